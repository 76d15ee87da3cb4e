//! The per-map pipeline that the claim checkers read.
//!
//! A [`Study`] holds one map and every structure of the thesis computed
//! about it so far: the visibility index, the visibility cell decomposition
//! (Defs 3.8–3.10), the embeddings of every class's skeleton (Def 3.11) with
//! their kernels, witnesses (Def 4.1), views and valid candidate edges, the
//! overlapping pairs of chapter 4 with their verdicts, the candidate sets,
//! gaps and interweavement graphs of chapter 5, Def 5.2's classification
//! of cell edges, and the localizer's preprocessing (Alg 3.14). Each structure is built the first time something asks for
//! it, once, and then shared by every reader of the study.
//!
//! - [`study`]: [`Study`] and the records it hands out ([`OverlappingPair`],
//!   [`EmbeddingPair`], [`CellEdges`], [`GapStructure`], [`Embedded`]).
//! - [`sample`]: the viewpoints the chapter 3 claims are examined at, and
//!   Def 3.4 read off a polygon's geometry.
//! - [`wedge_counts`]: kernel and wedge edges per class and embedding.
//! - [`edge_pairs`]: pairs of map edges that are candidate edges of
//!   different artificial edges (the premise of sec. 5.5).
//! - [`family`]: whether a map is a member of a thesis family.
//! - [`preprocessing`]: the size of Alg 3.14's overlays, counted from the
//!   decomposition.
//! - [`profile`]: the time each stage took ([`StageTimes`]).
//!
//! **Invariant:** a study never changes a structure once built; readers get
//! shared references. **Invariant:** no floating point (the workspace denies
//! `clippy::float_arithmetic`); time is measured in `Duration`s.

pub mod edge_pairs;
pub mod family;
#[cfg(test)]
mod pipeline_tests;
pub mod preprocessing;
pub mod profile;
pub mod sample;
pub mod study;
pub mod wedge_counts;

pub use profile::{Stage, StageTimes};
pub use study::{
    fresh_skeleton, CellEdges, Embedded, EmbeddingPair, FreshSkeleton, GapStructure,
    OverlappingPair, SkeletonPair, Study, TouchingPair, Views, CROSS_SKELETON_MAX_N,
};
