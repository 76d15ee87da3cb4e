//! Exact planar geometry for the whole workspace (thesis ch. 2).
//!
//! Every geometric decision of the workspace is made here, exactly. Input
//! points are [`Point`]s with integer coordinates (maps scale decimal and
//! rational input to integers; see `wai-map`). Every other point the thesis
//! needs is the meeting point of two [`Line`]s through input points, kept as
//! a homogeneous [`RatPoint`] or, better, never constructed at all: the
//! predicates of [`intersection`] decide its position from the defining
//! lines.
//!
//! The vector vocabulary every crate shares lives in the `vector` module:
//! [`Vector`] (an `i128` difference of input points), [`BigVector`] (GMP
//! integer directions), [`QPoint`] (an affine rational point or vector for
//! constructions), their cross and dot products and angular order, [`turn`]
//! on three [`QPoint`]s and one [`convex_hull`].
//!
//! Predicates return enums ([`Orientation`], [`Side`], [`Containment`],
//! [`SegmentIntersection`], [`Sight`]); constructions return new exact
//! values. Each predicate on input points has a machine-integer fast path
//! whose bound is stated next to it (`*_FAST_BITS`) and derived in an
//! `Implementation note`; inputs beyond the bound go to GMP through `rug`.
//! The GMP versions are public in [`reference`] so tests can compare the two.
//!
//! # Invariant
//! No floating point is read or written by this crate.

mod intersection;
mod line;
mod point;
mod polygon;
mod predicates;
pub mod reference;
mod segment;
mod vector;
mod visibility;

pub use intersection::{
    compare_intersections_along, construct_intersection, construct_intersection_i128, mul_checked,
    mul_wide, side_of_intersection, INTERSECTION_FAST_BITS,
};
pub use line::Line;
pub use point::{gcd_u128, Point, RatPoint, MAX_COORD_BITS};
pub use polygon::{locate, locate_rat, signed_area_twice, Containment};
pub use predicates::{
    compare_along, orientation, orientation_rat, side_of_line, side_of_line_rat, Orientation, Side,
    ORIENTATION_FAST_BITS,
};
pub use segment::{classify_segments, Segment, SegmentIntersection};
pub use vector::{
    convex_hull, det3_sign_i128, turn, BigVector, QPoint, Vector, HOMOGENEOUS_FAST_BITS,
    VECTOR_FAST_BITS,
};
pub use visibility::{sees, sees_among, Sight};
