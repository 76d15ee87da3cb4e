//! Integration tests of the localizer.

mod agree;
mod view;
