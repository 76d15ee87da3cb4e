//! Orientation, side of a line and order along a line, for input points.

use crate::line::Line;
use crate::point::{fits_bits, Point, RatPoint};
use crate::reference;
use crate::vector::{
    det3_sign_big, det3_sign_small, rat_point_small, BigVector, Vector, HOMOGENEOUS_FAST_BITS,
};
use rug::Integer;
use std::cmp::Ordering;

/// The orientation of an ordered triple of points.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Orientation {
    /// A left turn: `c` is to the left of the directed line `ab`.
    CounterClockwise,
    /// The three points lie on one line (including coincident points).
    Collinear,
    /// A right turn.
    Clockwise,
}

impl Orientation {
    /// The orientation whose determinant has sign `s`: `Greater` is
    /// counter-clockwise (the convention of [`crate::turn`]).
    pub fn from_sign(s: Ordering) -> Self {
        match s {
            Ordering::Greater => Orientation::CounterClockwise,
            Ordering::Equal => Orientation::Collinear,
            Ordering::Less => Orientation::Clockwise,
        }
    }

    /// The sign of the determinant: `Greater` for counter-clockwise.
    pub fn sign(self) -> Ordering {
        match self {
            Orientation::CounterClockwise => Ordering::Greater,
            Orientation::Collinear => Ordering::Equal,
            Orientation::Clockwise => Ordering::Less,
        }
    }

    /// The orientation of the reversed triple.
    pub fn reverse(self) -> Self {
        match self {
            Orientation::CounterClockwise => Orientation::Clockwise,
            Orientation::Collinear => Orientation::Collinear,
            Orientation::Clockwise => Orientation::CounterClockwise,
        }
    }
}

/// The side of a directed line a point lies on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Side {
    Left,
    On,
    Right,
}

impl Side {
    pub(crate) fn from_sign(s: Ordering) -> Self {
        match s {
            Ordering::Greater => Side::Left,
            Ordering::Equal => Side::On,
            Ordering::Less => Side::Right,
        }
    }
}

impl From<Orientation> for Side {
    fn from(o: Orientation) -> Self {
        match o {
            Orientation::CounterClockwise => Side::Left,
            Orientation::Collinear => Side::On,
            Orientation::Clockwise => Side::Right,
        }
    }
}

/// Coordinates below `2^ORIENTATION_FAST_BITS` in magnitude take the `i128`
/// fast path of [`orientation`] and [`compare_along`].
///
/// Implementation note: with `|c| < 2^62` every difference of coordinates
/// has `|d| <= 2^63 - 2`, every product of two differences is below `2^126`
/// and the sum or difference of two such products is below `2^127`, which an
/// `i128` holds (its maximum is `2^127 - 1`). `tests/it/bounds.rs` recomputes
/// the worst case with GMP.
pub const ORIENTATION_FAST_BITS: u32 = 62;

#[inline]
fn fast(p: &Point) -> bool {
    fits_bits(p.x, ORIENTATION_FAST_BITS) && fits_bits(p.y, ORIENTATION_FAST_BITS)
}

/// The orientation of `(a, b, c)`: the sign of `(b - a) × (c - a)`.
///
/// # Edge cases
/// Coincident points are [`Orientation::Collinear`].
/// ```
/// use wai_exact::{orientation, Orientation, Point};
/// let (a, b) = (Point::new(0, 0), Point::new(4, 0));
/// assert_eq!(orientation(a, b, Point::new(9, 1)), Orientation::CounterClockwise);
/// assert_eq!(orientation(a, b, Point::new(-7, 0)), Orientation::Collinear);
/// assert_eq!(orientation(a, a, Point::new(1, 1)), Orientation::Collinear);
/// ```
#[inline]
pub fn orientation(a: Point, b: Point, c: Point) -> Orientation {
    if fast(&a) && fast(&b) && fast(&c) {
        // Differences below 2^63: within VECTOR_FAST_BITS.
        let d = Vector::between_fast;
        Orientation::from_sign(d(a, b).cross_fast(d(a, c)).cmp(&0))
    } else {
        reference::orientation(a, b, c)
    }
}

/// The side of the directed line `l` that `p` lies on.
#[inline]
pub fn side_of_line(l: &Line, p: Point) -> Side {
    orientation(l.a(), l.b(), p).into()
}

/// The order of `p` and `q` along the direction of `l` (`Less`: `p` comes
/// first). Points need not lie on `l`: they are compared by their orthogonal
/// projections onto it.
#[inline]
pub fn compare_along(l: &Line, p: Point, q: Point) -> Ordering {
    let (a, b) = (l.a(), l.b());
    if fast(&a) && fast(&b) && fast(&p) && fast(&q) {
        // Same bound as orientation: a sum of two products of differences.
        let d = Vector::between_fast;
        0.cmp(&d(p, q).dot_fast(d(a, b)))
    } else {
        reference::compare_along(l, p, q)
    }
}

/// The orientation of three rational points.
///
/// Implementation note: homogeneous rows `(X, Y, W)` with `W > 0`, so the
/// 3×3 determinant has the sign of the affine orientation determinant. It
/// is taken in `i128` when every entry is below
/// `2^HOMOGENEOUS_FAST_BITS` (the bound is derived there), else in GMP.
pub fn orientation_rat(a: &RatPoint, b: &RatPoint, c: &RatPoint) -> Orientation {
    if let (Some(a), Some(b), Some(c)) =
        (rat_point_small(a), rat_point_small(b), rat_point_small(c))
    {
        return Orientation::from_sign(det3_sign_small(a, b, c));
    }
    fn row(p: &RatPoint) -> [&Integer; 3] {
        [p.hx(), p.hy(), p.hw()]
    }
    Orientation::from_sign(det3_sign_big(row(a), row(b), row(c)))
}

/// The side of the directed line `l` that the rational point `p` lies on.
pub fn side_of_line_rat(l: &Line, p: &RatPoint) -> Side {
    if let Some(q) = p.to_point() {
        return side_of_line(l, q);
    }
    if let Some(p) = rat_point_small(p) {
        if let Some(s) = side_of_line_small(l.a(), l.b(), p) {
            return s;
        }
    }
    side_of_line_rat_big(l, p)
}

/// The homogeneous row `(x, y, 1)` of an input point, if both coordinates
/// are below `2^HOMOGENEOUS_FAST_BITS` in magnitude.
#[inline]
pub(crate) fn point_row_small(a: Point) -> Option<[i128; 3]> {
    let fits = |c: i128| c.unsigned_abs() < 1 << HOMOGENEOUS_FAST_BITS;
    (fits(a.x) && fits(a.y)).then_some([a.x, a.y, 1])
}

/// The side of the directed line through `a` and `b` that the point with
/// homogeneous row `p` (`W > 0`, entries below `2^HOMOGENEOUS_FAST_BITS`)
/// lies on, or `None` when `a` or `b` has a coordinate beyond that bound.
///
/// Implementation note: the sign of the determinant of the rows
/// `(a, 1)`, `(b, 1)`, `(X, Y, W)` is `W·((b − a) × (p − a))`, which has the
/// sign of the affine cross product as `W > 0`. Every entry is below
/// `2^HOMOGENEOUS_FAST_BITS`, so [`det3_sign_small`] is exact (its bound
/// is derived at [`HOMOGENEOUS_FAST_BITS`]).
#[inline]
pub(crate) fn side_of_line_small(a: Point, b: Point, p: [i128; 3]) -> Option<Side> {
    Some(Side::from_sign(det3_sign_small(
        point_row_small(a)?,
        point_row_small(b)?,
        p,
    )))
}

/// [`side_of_line_rat`] in GMP, for any point.
pub(crate) fn side_of_line_rat_big(l: &Line, p: &RatPoint) -> Side {
    let (a, b) = (l.a(), l.b());
    // sign((b - a) × (p - a)) with p = (X/W, Y/W), W > 0, scaled by W. The
    // differences are taken in GMP: in i128 they overflow beyond 2^126.
    let d = BigVector::between(a, b);
    let toward = BigVector::toward(p, a);
    // toward = W·a − (X, Y) = −W·(p − a).
    Side::from_sign(toward.cross_sign(&d))
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    const B: i128 = 1 << HOMOGENEOUS_FAST_BITS;

    /// Small values, values at the fast path's bound and values beyond it.
    fn coord() -> impl Strategy<Value = i128> {
        prop_oneof![-20i128..20, (-B + 1)..B, Just(B - 1), Just(-B + 1), Just(B)]
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(3000))]

        /// The `i128` path of `side_of_line_rat` decides as GMP does, the
        /// point off, near or on the line.
        #[test]
        fn side_of_line_small_agrees_with_gmp(
            a in (coord(), coord()),
            b in (coord(), coord()),
            p in (coord(), coord(), prop_oneof![1i128..20, 1..B, Just(B - 1), Just(B)]),
            on_line in prop::option::of((-9i128..9, 1i128..9)),
        ) {
            let (a, b) = (Point::new(a.0, a.1), Point::new(b.0, b.1));
            let Some(l) = Line::new(a, b) else { return Ok(()) };
            let (x, y, w) = match on_line {
                Some((k, m)) => (a.x * m + k * (b.x - a.x), a.y * m + k * (b.y - a.y), m),
                None => p,
            };
            let p = RatPoint::new(Integer::from(x), Integer::from(y), Integer::from(w))
                .expect("w > 0");
            let big = side_of_line_rat_big(&l, &p);
            if let Some(row) = rat_point_small(&p) {
                if let Some(small) = side_of_line_small(a, b, row) {
                    prop_assert_eq!(small, big);
                }
            }
            prop_assert_eq!(side_of_line_rat(&l, &p), big);
        }
    }
}
