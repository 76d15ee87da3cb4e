//! Points: integer input points and exact rational (homogeneous) points.

use rug::Integer;
use serde::{Deserialize, Serialize};
use std::fmt;

/// The largest supported magnitude of an input coordinate, in bits:
/// every coordinate `c` of a [`Point`] satisfies `|c| < 2^MAX_COORD_BITS`.
///
/// It covers every map of `shared/datasets` (the largest, AGPLIB's dyadic
/// random simple polygons scaled to integers, need 70 bits) with room to
/// spare, and keeps every coordinate difference inside an `i128`. Maps
/// enforce it on input; the predicates stay exact for any `i128`.
pub const MAX_COORD_BITS: u32 = 100;

/// An input point: integer coordinates, `|x|, |y| < 2^MAX_COORD_BITS`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub struct Point {
    pub x: i128,
    pub y: i128,
}

impl Point {
    pub const fn new(x: i128, y: i128) -> Self {
        Point { x, y }
    }

    /// Whether both coordinates are within [`MAX_COORD_BITS`].
    pub fn is_supported(&self) -> bool {
        fits_bits(self.x, MAX_COORD_BITS) && fits_bits(self.y, MAX_COORD_BITS)
    }

    /// The bits needed for the larger of `|x|` and `|y|`.
    pub fn magnitude_bits(&self) -> u32 {
        bits(self.x).max(bits(self.y))
    }
}

impl fmt::Display for Point {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "({}, {})", self.x, self.y)
    }
}

/// Bits of `|v|`: the least `b` with `|v| < 2^b`.
pub(crate) fn bits(v: i128) -> u32 {
    128 - v.unsigned_abs().leading_zeros()
}

/// Whether `|v| < 2^b`.
#[inline]
pub(crate) fn fits_bits(v: i128, b: u32) -> bool {
    v.unsigned_abs() < (1u128 << b)
}

/// An exact rational point in homogeneous form `(x / w, y / w)`.
///
/// Canonical: `w > 0` and `gcd(x, y, w) = 1`, so equal points have equal
/// fields and `Eq`/`Hash` are exact.
#[derive(Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct RatPoint {
    x: Integer,
    y: Integer,
    w: Integer,
}

impl RatPoint {
    /// `(x / w, y / w)`; `None` if `w = 0` (a point at infinity).
    pub fn new(x: Integer, y: Integer, w: Integer) -> Option<Self> {
        if w == 0 {
            return None;
        }
        let mut p = RatPoint { x, y, w };
        if p.w < 0 {
            p.x = -p.x;
            p.y = -p.y;
            p.w = -p.w;
        }
        let g = Integer::from(p.x.gcd_ref(&p.y)).gcd(&p.w);
        if g != 1 {
            p.x /= &g;
            p.y /= &g;
            p.w /= &g;
        }
        Some(p)
    }

    pub fn from_point(p: Point) -> Self {
        RatPoint {
            x: Integer::from(p.x),
            y: Integer::from(p.y),
            w: Integer::from(1),
        }
    }

    /// The homogeneous numerator of x.
    pub fn hx(&self) -> &Integer {
        &self.x
    }
    /// The homogeneous numerator of y.
    pub fn hy(&self) -> &Integer {
        &self.y
    }
    /// The common denominator, always positive.
    pub fn hw(&self) -> &Integer {
        &self.w
    }

    /// The integer point, if both coordinates are integers in `i128`.
    pub fn to_point(&self) -> Option<Point> {
        if self.w != 1 {
            return None;
        }
        Some(Point::new(self.x.to_i128()?, self.y.to_i128()?))
    }

    /// The midpoint of `a` and `b`, exactly.
    pub fn midpoint(a: &RatPoint, b: &RatPoint) -> RatPoint {
        let x = Integer::from(&a.x * &b.w) + Integer::from(&b.x * &a.w);
        let y = Integer::from(&a.y * &b.w) + Integer::from(&b.y * &a.w);
        let w = Integer::from(&a.w * &b.w) * 2u32;
        RatPoint::new(x, y, w).expect("product of positive denominators is positive")
    }
}

impl From<Point> for RatPoint {
    fn from(p: Point) -> Self {
        RatPoint::from_point(p)
    }
}

impl fmt::Display for RatPoint {
    /// Coordinates as exact fractions in lowest terms: `(3/2, -1)`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let show = |n: &Integer| {
            let q = rug::Rational::from((n.clone(), self.w.clone()));
            if *q.denom() == 1 {
                q.numer().to_string()
            } else {
                format!("{}/{}", q.numer(), q.denom())
            }
        };
        write!(f, "({}, {})", show(&self.x), show(&self.y))
    }
}
