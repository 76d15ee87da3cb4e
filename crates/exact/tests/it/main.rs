//! Integration tests of `wai-exact`, linked once as one binary.
//!
//! - `bounds`: the `Implementation note` bit bounds recomputed with GMP.
//! - `differential`: every fast predicate against `wai_exact::reference` and
//!   against an independent `rug::Rational` construction.
//! - `laws`: exact symmetry laws of the predicates and of `RatPoint`.
//! - `vector`: the vector vocabulary (`Vector`, `BigVector`, `QPoint`,
//!   `turn`, `convex_hull`) against plain GMP computations, and its laws.
//! - `segments`, `polygon`, `visibility`: data-driven cases, one `check`
//!   helper per file, plus property and differential tests.

mod bounds;
mod common;
mod differential;
mod laws;
mod polygon;
mod segments;
mod vector;
mod visibility;
