//! Integration tests of `wai-exact`, linked once as one binary (STYLE.md 11).
//!
//! - `bounds`: the `Implementation note` bit bounds recomputed with GMP.
//! - `differential`: every fast predicate against `wai_exact::reference` and
//!   against an independent `rug::Rational` construction (STYLE.md 3, 9).
//! - `laws`: exact symmetry laws of the predicates and of `RatPoint` (STYLE.md 7).
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
