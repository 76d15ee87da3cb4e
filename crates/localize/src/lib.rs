//! The exact reference localizer (thesis sec. 3.8, Algorithms 3.13 and
//! 3.14): given a map and what an ideal range sensor with a compass sees —
//! a visibility polygon V with the robot at its origin — every position
//! where the robot can be (the answer set A, Def 3.2), each with the
//! embedding that gives it.
//!
//! Maps with holes (sec. 6.4) are localized too, and checked against both
//! oracles; the one-shot query ([`oracle::one_shot`]) then also asks that
//! no hole lie inside the placed polygon (∂P ⊆ M gives P ⊆ M only without
//! holes).
//!
//! - [`RobotView`]: V checked to be a visibility polygon (star-shaped from
//!   the robot, winding once) and its skeleton V* computed from V alone.
//! - [`Localizer`]: the preprocessing (one overlay per equivalence class of
//!   its cells of every dimension, translated to the skeleton origin, with
//!   slab point location) and the query.
//! - [`oracle`]: an independent brute force and Guibas et al.'s one-shot
//!   query (with [`ray_exits`], its directional sweep) to compare with.
//! - [`file`]: save and load a preprocessed map (versioned JSON).

pub mod fast;
pub mod file;
mod localizer;
pub mod oracle;
pub mod overlay;
pub mod ray_exits;
mod view;

pub use localizer::{Answer, Localizer, Nowhere, Placement};
pub use overlay::CellSite;
pub use view::{NoSkeleton, RobotView, ViewError, ViewSkeleton};

use std::cmp::Ordering;
use wai_exact::RatPoint;

/// Points ordered by x, then y (exactly).
pub fn cmp_points(a: &RatPoint, b: &RatPoint) -> Ordering {
    use rug::Integer;
    let x = (Integer::from(a.hx() * b.hw()) - Integer::from(b.hx() * a.hw())).cmp0();
    x.then_with(|| (Integer::from(a.hy() * b.hw()) - Integer::from(b.hy() * a.hw())).cmp0())
}

/// `z` as an `i128` below 2^126 in magnitude (so that negation,
/// `unsigned_abs` and the products of [`fast`] are safe), if it is one.
pub(crate) fn small_i128(z: &rug::Integer) -> Option<i128> {
    z.to_i128().filter(|c| c.unsigned_abs() < 1u128 << 126)
}

/// A rational point as a homogeneous `i128` triple, each coordinate
/// [`small_i128`], if it is one.
pub(crate) fn small_triple(p: &RatPoint) -> Option<[i128; 3]> {
    Some([
        small_i128(p.hx())?,
        small_i128(p.hy())?,
        small_i128(p.hw())?,
    ])
}

/// p + o for an integer point o (`sign` 1) or p − o (`sign` −1), exactly.
pub(crate) fn shifted(p: &RatPoint, o: wai_exact::Point, sign: i128) -> RatPoint {
    use rug::Integer;
    let w = p.hw();
    RatPoint::new(
        p.hx() + Integer::from(w * (sign * o.x)),
        p.hy() + Integer::from(w * (sign * o.y)),
        w.clone(),
    )
    .expect("w > 0")
}
