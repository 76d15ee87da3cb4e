//! Integration tests of the localizer.

mod agree;
mod fast;
mod file;
mod view;
