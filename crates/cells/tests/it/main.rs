//! Tests of wai-cells: hand-checked maps with every degeneracy of Def 3.8,
//! laws of visibility rays on generated maps (against a brute-force
//! enumeration with `wai_exact::sees`), and invariance under rigid motions.

mod arrangement;
mod common;
mod hand;
mod laws;
