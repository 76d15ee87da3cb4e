//! Visibility polygons and visibility skeletons, exactly (thesis sec.
//! 3.4–3.5, Defs 3.4–3.7 and 3.12, Thm 3.2).
//!
//! The principal types are [`VisibilityPolygon`] — V_p with every edge
//! classified as spurious (Def 3.4), full, half or partial (Def 3.5), every
//! vertex located on the map and every half or partial edge given its
//! blocking vertices (Def 3.6) — and [`Skeleton`] — V*_p (Def 3.7) with its
//! canonical, hashable [`SkeletonKey`], its skeleton polygon V◇ and its
//! kernel (Def 3.12), and the reconstruction of V_p from V*_p and the
//! viewpoint (the constructive direction of Thm 3.2).
//!
//! Maps with holes are read throughout (thesis sec. 2.1, 6.4): the
//! triangulation joins each hole to the outer ring by a bridge, the
//! expansion and the reference walk every ring's edges, and V_p — a star
//! polygon, never holed — and V*_p are built as for a map without holes.
//!
//! [`reference::visibility_polygon`] is the simple angular algorithm that
//! defines what V_p is; every other algorithm is tested against it.
//!
//! # Invariant
//! Every decision is exact: vertices of V_p are [`wai_exact::RatPoint`]s and
//! no floating point is used.

mod assemble;
mod classify;
mod expansion;
mod kernel;
mod locate;
mod map_skeleton;
mod polygon;
pub mod reference;
mod skeleton;
#[cfg(test)]
mod test_points;
mod triangulation;

pub use expansion::VisibilityIndex;
pub use kernel::{kernel_of_ring, ConvexRegion};
pub use map_skeleton::{MapSkeleton, SkeletonAtError};
pub use polygon::{EdgeKind, OnMap, VisEdge, VisVertex, VisibilityError, VisibilityPolygon};
pub use skeleton::{reconstruct, LineLabel, Skeleton, SkeletonEdge, SkeletonError, SkeletonKey};
pub use triangulation::{bridged_ring, Across, Triangulation};
