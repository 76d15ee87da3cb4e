//! The visibility cell decomposition (thesis sec. 3.6, Def 3.8, Thm 3.3).
//!
//! This crate is the `cells` stage of the pipeline: map → visibility rays →
//! exact arrangement of map edges and rays → cells of dimension 2, 1 and 0
//! → the skeleton of each cell (Def 3.9) → equivalence classes of cells
//! (Def 3.10). The boundary assignment of sec. 3.6 is computed beside it,
//! when asked for.
//!
//! Maps with holes (sec. 6.4) are decomposed too: rays from the reflex
//! vertices of the free space (hole vertices convex as vertices of their
//! hole among them), the holes' interiors faces of the arrangement but not
//! cells ([`Arrangement::is_cell`]), and each cell's skeleton by a query at
//! its point instead of the walk of sec. 3.9.2, whose update assumes one
//! ring.
//!
//! Its principal type is [`Decomposition`]: all of these stages for one
//! map, with the cells in face order, an exact interior point of each, the
//! index of its skeleton, the classes with their complexity |EC|, and the
//! [`Counts`] (n, r, rays, cells, N, classes, max |EC|) that chapter 3's
//! bounds are about.
//!
//! [`Arrangement`] is the half-edge structure of the map edges and all rays
//! (topology by indices, exact geometry attached by index; collinear rays
//! merged; any number of rays through one point give one vertex), with a
//! layered `sanity_check`. [`BoundaryAssignment`] gives every edge and
//! vertex of the arrangement its cell by the rule of sec. 3.6 and reports
//! every [`Conflict`] where rays on one piece disagree.
//!
//! [`VisibilityRay`] (Def 3.8) is the directed segment
//! inside the map on the line through a vertex `v` and a reflex vertex
//! `v_r` that `v` is visible from or adjacent to, starting at `v_r`, moving
//! away from `v` and ending on the map boundary, with its side (left or
//! right: where the anchor's map edges lie, which is the side the boundary
//! assignment of sec. 3.6 gives the ray's points to). [`visibility_rays`]
//! computes all of them exactly; its `# Edge cases` section states the
//! conventions for rays that would leave the map at once, graze map
//! vertices, run along collinear map edges or end at a vertex.
//! [`group_by_line`] groups rays by their supporting line ([`LineKey`]) for
//! the arrangement, which merges overlapping rays.
//!
//! # Invariant
//! No floating point is read or written: every decision is a `wai_exact`
//! predicate on integer map vertices or, for maps whose coordinates are
//! below 2^30, the same sign computed in `i64`/`i128` with its bound proven
//! where it is used (the `small` module; the scaling tests compare both
//! paths), and every constructed point is an exact
//! [`wai_exact::RatPoint`].

mod arrangement;
mod assignment;
mod decomposition;
mod estimate;
mod eye;
mod fx;
mod incremental;
mod line_view;
mod rays;
mod sanity;
mod small;

pub use arrangement::{
    Arrangement, EdgeGeometry, EdgeId, Face, FaceId, HalfEdge, HalfEdgeId, RayGroup, Support,
    Vertex, VertexId,
};
pub use assignment::{BoundaryAssignment, Conflict};
pub use decomposition::{Counts, Decomposition, KeptAbsorbed, LowerCell, LowerSite};
pub use estimate::vertex_bound;
pub use rays::{group_by_line, visibility_rays, LineKey, RayEnd, RaySide, VisibilityRay};
pub use wai_visibility::OnMap;
