//! Embeddings of visibility skeletons (thesis sec. 3.7, Def 3.11).
//!
//! A skeleton V* fits the map wherever its vertices, translated so that
//! its origin v0 lands on a map vertex, are map vertices (condition 1), its
//! full edges are exactly the map edges among them (condition 2), and each
//! artificial edge has a **candidate edge**: a map edge on the translated
//! label line with a point that both ends of the artificial edge see
//! (condition 3). [`embeddings`] finds every such placement of a
//! [`wai_visibility::SkeletonKey`] in a map, exactly.
//!
//! Maps with holes (sec. 6.4) are embedded too: map edges and neighbours
//! follow each vertex's ring ([`wai_map::Map::next`]), and so does the
//! mutual-visibility test of Theorem 4.2 (module `mutual`). Gap chains
//! (module `gaps`) and [`Chord`] still take the boundary as one ring.
//!
//! Seeing follows sec. 2.2 as the rest of the workspace reads it: two
//! points see each other when the closed segment between them meets the
//! boundary only at its ends and runs through the map; a point sees itself.
//! [`EdgeSight`] is the part of a map edge a map vertex sees.
//!
//! # Invariant
//! No floating point: positions along edges are GMP rationals, every sign
//! an exact integer predicate.

mod candidate_sets;
mod crossing;
mod embedding;
pub mod gaps;
pub mod intersection;
pub mod interweavement;
mod mutual;
mod overlay;
pub mod piece;
mod sight;
mod transversal;
mod views;
pub mod wedge;
mod witness;

pub use candidate_sets::CandidateSets;
pub use crossing::{crossing, Chord, Crossing, SightFan};
pub use embedding::{embeddings, Embedder, Embedding};
pub use gaps::{gap_chains, GapChain, GapRelation};
pub use intersection::{EdgeType, Intersection, SkeletonRing};
pub use interweavement::{EmbeddedEdge, Interweavement, Node};
pub use mutual::{Mutual, Sightlines};
pub use overlay::common_interior_point;
pub use piece::{Bounds, Piece};
pub use sight::EdgeSight;
pub use transversal::transversal;
pub use views::witness_views_by_rule;
pub use witness::{
    interiors_overlap, interiors_overlap_rational, kernels_overlap, overlapping_valid_pairs,
    piece_of, segment_meets_polygon, sight_fans, valid_candidate_edges, valid_from_views,
    witness_regions, witness_views, CellRef, WitnessCell, Witnesses,
};
