//! Exact angular order of integer vectors around the origin.

use rug::Integer;
use std::cmp::Ordering;

/// A direction from the viewpoint, as an integer vector (never zero).
pub(crate) type Dir = (Integer, Integer);

pub(crate) fn cross(a: &Dir, b: &Dir) -> Integer {
    Integer::from(&a.0 * &b.1) - Integer::from(&a.1 * &b.0)
}

/// 0 for angles in [0, π), 1 for [π, 2π).
fn half(d: &Dir) -> u8 {
    if d.1 > 0 || (d.1 == 0 && d.0 > 0) {
        0
    } else {
        1
    }
}

/// Counter-clockwise order of directions starting at angle 0 (the positive
/// x axis); vectors with the same direction compare equal.
pub(crate) fn compare_angle(a: &Dir, b: &Dir) -> Ordering {
    // Within one half-plane, a comes first when b is to its left.
    half(a).cmp(&half(b)).then_with(|| cross(b, a).cmp0())
}
