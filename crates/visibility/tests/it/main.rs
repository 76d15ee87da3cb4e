//! Tests of wai-visibility: hand-checked polygons, laws on generated maps
//! with degenerate viewpoints, skeleton encoding and reconstruction.

mod cases;
mod common;
mod holes;
mod laws;
mod map_skeleton;
mod production;
