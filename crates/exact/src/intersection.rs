//! Meeting points of two lines through input points, and predicates on
//! them that never construct the point.
//!
//! The cell decomposition's vertices are such points (a visibility ray meets
//! a map edge or another ray). Deciding their position from the defining
//! lines keeps the degree of every predicate at 4 in the input coordinates.

use crate::line::Line;
use crate::point::{fits_bits, Point, RatPoint};
use crate::predicates::Side;
use crate::reference;
use crate::vector::Vector;
use std::cmp::Ordering;

/// Input coordinates below `2^INTERSECTION_FAST_BITS` in magnitude take the
/// `i128` fast path of [`side_of_intersection`] and
/// [`compare_intersections_along`].
///
/// Implementation note: write `d_i = b_i - a_i` for line `i` and
/// `×` for the cross product. With `|c| < 2^B` every difference is below
/// `2^(B+1)` and every cross product of two differences below
/// `2 · 2^(2B+2) = 2^(2B+3)`. Both predicates evaluate the sign of
/// `X·Y + Z·W` where each of `X, Y, Z, W` is such a cross product
/// (`side_of_intersection`: `(d3 × (a1 - a3))·(d1 × d2) + (d3 × d1)·((a2 - a1) × d2)`;
/// `compare_intersections_along`: `n1·e2 - n2·e1` with `n_k = (a_k - a0) × d_k`,
/// `e_k = d0 × d_k`). Each product is below `2^(4B+6)` and the sum below
/// `2^(4B+7)`, which fits an `i128` (`< 2^127`) for `B = 30`.
/// `tests/it/bounds.rs` recomputes this worst case with GMP.
pub const INTERSECTION_FAST_BITS: u32 = 30;

#[inline]
fn fast(ps: &[Point]) -> bool {
    ps.iter()
        .all(|p| fits_bits(p.x, INTERSECTION_FAST_BITS) && fits_bits(p.y, INTERSECTION_FAST_BITS))
}

/// `a · b` for two `i64` values: one 64 × 64 → 128-bit multiplication,
/// exact (the product is below `2^126`), with no overflow check to make —
/// fuzzing builds check every `i128` product through a library call.
#[inline]
pub fn mul_wide(a: i64, b: i64) -> i128 {
    i128::from(a).wrapping_mul(i128::from(b))
}

/// `a · b`, or `None` on overflow; factors that fit in `i64` skip the
/// (slow) overflow check, their product being below 2^126.
#[inline]
pub fn mul_checked(a: i128, b: i128) -> Option<i128> {
    if let (Ok(x), Ok(y)) = (i64::try_from(a), i64::try_from(b)) {
        Some(mul_wide(x, y))
    } else {
        a.checked_mul(b)
    }
}

/// The meeting point of `l1` and `l2`; `None` if they are parallel
/// (including equal).
pub fn construct_intersection(l1: &Line, l2: &Line) -> Option<RatPoint> {
    match construct_intersection_i128(l1, l2) {
        Some(Some([x, y, w])) => RatPoint::from_i128(x, y, w),
        Some(None) => None,
        None => reference::construct_intersection(l1, l2),
    }
}

/// [`construct_intersection`] in checked `i128` arithmetic, as the
/// homogeneous coordinates `[x, y, w]` of the meeting point in lowest
/// terms with `w > 0` (those of the [`RatPoint`], so equal points give
/// equal triples): `Some(None)` if the lines are parallel, `None` if a
/// product overflows or the result does not fit (then use
/// [`construct_intersection`]).
pub fn construct_intersection_i128(l1: &Line, l2: &Line) -> Option<Option<[i128; 3]>> {
    let (a1, b1, a2, b2) = (l1.a(), l1.b(), l2.a(), l2.b());
    let (d1x, d1y) = (b1.x.checked_sub(a1.x)?, b1.y.checked_sub(a1.y)?);
    let (d2x, d2y) = (b2.x.checked_sub(a2.x)?, b2.y.checked_sub(a2.y)?);
    let den = mul_checked(d1x, d2y)?.checked_sub(mul_checked(d1y, d2x)?)?;
    if den == 0 {
        return Some(None);
    }
    let (ex, ey) = (a2.x.checked_sub(a1.x)?, a2.y.checked_sub(a1.y)?);
    let num = mul_checked(ex, d2y)?.checked_sub(mul_checked(ey, d2x)?)?;
    let x = mul_checked(den, a1.x)?.checked_add(mul_checked(num, d1x)?)?;
    let y = mul_checked(den, a1.y)?.checked_add(mul_checked(num, d1y)?)?;
    Some(Some(RatPoint::lowest_terms_i128(x, y, den)?))
}

/// The side of the directed line `l3` on which the meeting point of `l1` and
/// `l2` lies, without constructing it; `None` if `l1 ∥ l2`.
///
/// # Edge cases
/// `Side::On` exactly when `l3` passes through the meeting point, as when
/// three visibility rays meet in one point.
/// ```
/// use wai_exact::{side_of_intersection, Line, Point, Side};
/// let l = |a: (i128, i128), b: (i128, i128)| Line::new(Point::new(a.0, a.1), Point::new(b.0, b.1)).unwrap();
/// let (h, v) = (l((0, 0), (4, 0)), l((2, -1), (2, 5)));
/// assert_eq!(side_of_intersection(&l((0, -2), (4, 2)), &h, &v), Some(Side::On));
/// assert_eq!(side_of_intersection(&l((3, 0), (3, 1)), &h, &v), Some(Side::Left));
/// assert_eq!(side_of_intersection(&h, &h, &l((0, 1), (4, 1))), None);
/// ```
pub fn side_of_intersection(l3: &Line, l1: &Line, l2: &Line) -> Option<Side> {
    let (a1, b1, a2, b2, a3, b3) = (l1.a(), l1.b(), l2.a(), l2.b(), l3.a(), l3.b());
    if !fast(&[a1, b1, a2, b2, a3, b3]) {
        return reference::side_of_intersection(l3, l1, l2);
    }
    // Differences below 2^31 and their cross products below 2^63: within
    // VECTOR_FAST_BITS, so `Vector::cross` is exact (the note above).
    let d = Vector::between_fast;
    let (d1, d2, d3) = (d(a1, b1), d(a2, b2), d(a3, b3));
    let den = d1.cross_fast(d2);
    if den == 0 {
        return None;
    }
    let num = d(a1, a2).cross_fast(d2);
    // I = a1 + (num/den) d1;  d3 × (I - a3) = [d3 × (a1 - a3) · den + num · (d3 × d1)] / den.
    let s = d3.cross_fast(d(a3, a1)) * den + num * d3.cross_fast(d1);
    Some(Side::from_sign(s.cmp(&0)).flip_if(den < 0))
}

/// The order along the directed line `l0` of its meeting points with `l1`
/// and with `l2` (`Less`: the meeting with `l1` comes first); `None` if `l0`
/// is parallel to `l1` or to `l2`.
pub fn compare_intersections_along(l0: &Line, l1: &Line, l2: &Line) -> Option<Ordering> {
    let (a0, b0, a1, b1, a2, b2) = (l0.a(), l0.b(), l1.a(), l1.b(), l2.a(), l2.b());
    if !fast(&[a0, b0, a1, b1, a2, b2]) {
        return reference::compare_intersections_along(l0, l1, l2);
    }
    // Within VECTOR_FAST_BITS, as in side_of_intersection.
    let d = Vector::between_fast;
    let (d0, d1, d2) = (d(a0, b0), d(a1, b1), d(a2, b2));
    let (e1, e2) = (d0.cross_fast(d1), d0.cross_fast(d2));
    if e1 == 0 || e2 == 0 {
        return None;
    }
    // t_k = n_k / e_k is the parameter of the meeting point on l0.
    let (n1, n2) = (d(a0, a1).cross_fast(d1), d(a0, a2).cross_fast(d2));
    let s = n1 * e2 - n2 * e1;
    let ord = s.cmp(&0);
    Some(if (e1 < 0) != (e2 < 0) {
        ord.reverse()
    } else {
        ord
    })
}

impl Side {
    pub(crate) fn flip_if(self, flip: bool) -> Side {
        match (self, flip) {
            (Side::Left, true) => Side::Right,
            (Side::Right, true) => Side::Left,
            (s, _) => s,
        }
    }
}
