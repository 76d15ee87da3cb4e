//! Integration tests of the localizer.

mod agree;
mod fast;
mod file;
mod ray_exits;
mod view;
