//! Tests of wai-cells: hand-checked maps with every degeneracy of Def 3.8,
//! laws of visibility rays on generated maps (against a brute-force
//! enumeration with `wai_exact::sees`), invariance under rigid motions, and
//! the decomposition with skeletons and classes (hand-derived classes,
//! Lemma 3.7, consistency laws).

mod arrangement;
mod common;
mod datasets;
mod decomposition;
mod hand;
mod holes;
mod incremental;
mod laws;
mod snapshots;
