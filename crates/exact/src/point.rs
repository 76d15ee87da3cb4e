//! Points: integer input points and exact rational (homogeneous) points.

use crate::intersection::mul_checked as mul;
use rug::Integer;
use serde::{Deserialize, Serialize};
use std::fmt;

/// The largest supported magnitude of an input coordinate, in bits:
/// every coordinate `c` of a [`Point`] satisfies `|c| < 2^MAX_COORD_BITS`.
///
/// It covers every map of `data/datasets` (the largest, AGPLIB's dyadic
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

    /// [`RatPoint::new`] from `i128` values, reduced in `i128` (GMP only
    /// if a sign change overflows); `None` if `w == 0`.
    pub fn from_i128(x: i128, y: i128, w: i128) -> Option<Self> {
        if w == 0 {
            return None;
        }
        match RatPoint::lowest_terms_i128(x, y, w) {
            Some([x, y, w]) => Some(RatPoint {
                x: Integer::from(x),
                y: Integer::from(y),
                w: Integer::from(w),
            }),
            None => RatPoint::new(Integer::from(x), Integer::from(y), Integer::from(w)),
        }
    }

    /// `(x, y, w)` divided by their gcd and made `w > 0`: the homogeneous
    /// coordinates a [`RatPoint`] keeps. `None` if `w = 0` or the result
    /// does not fit an `i128`.
    pub fn lowest_terms_i128(x: i128, y: i128, w: i128) -> Option<[i128; 3]> {
        if w == 0 {
            return None;
        }
        if let (Ok(x), Ok(y), Ok(w)) = (i64::try_from(x), i64::try_from(y), i64::try_from(w)) {
            // The same in 64 bits, whose divisions are several times faster.
            let mut g = gcd_u64(w.unsigned_abs(), x.unsigned_abs());
            if g != 1 {
                g = gcd_u64(g, y.unsigned_abs());
            }
            let (x, y, w) = match i64::try_from(g) {
                Ok(1) => (x, y, w),
                Ok(g) => (x / g, y / g, w / g),
                // g = 2^63 divides w: |w| = 2^63 and x, y are 0 or ±2^63.
                Err(_) => (x.signum(), y.signum(), w.signum()),
            };
            let s = if w < 0 { -1 } else { 1 };
            return Some([i128::from(x) * s, i128::from(y) * s, i128::from(w) * s]);
        }
        // From w, the smallest as a rule, and no division when the first
        // gcd is already 1 (most crossings of rays).
        let mut g = gcd_u128(w.unsigned_abs(), x.unsigned_abs());
        if g != 1 {
            g = gcd_u128(g, y.unsigned_abs());
        }
        // g ≥ 1 divides |w| ≤ 2^127, so the quotients fit unless g = 1 and
        // a value is i128::MIN, which only a negation below can hit.
        let (x, y, w) = if g == 1 {
            (x, y, w)
        } else {
            let g = i128::try_from(g).ok()?;
            (x / g, y / g, w / g)
        };
        if w < 0 {
            Some([x.checked_neg()?, y.checked_neg()?, w.checked_neg()?])
        } else {
            Some([x, y, w])
        }
    }

    /// The point `(x, y)`, over the least common denominator.
    pub fn from_rationals(x: rug::Rational, y: rug::Rational) -> Self {
        let (xn, xd) = x.into_numer_denom();
        let (yn, yd) = y.into_numer_denom();
        let w = Integer::from(xd.lcm_ref(&yd));
        let hx = xn * Integer::from(w.div_exact_ref(&xd));
        let hy = yn * Integer::from(w.div_exact_ref(&yd));
        RatPoint::new(hx, hy, w).expect("denominators are positive")
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
        // Checked i128 first (exact: overflow takes the GMP path).
        let small = |v: &Integer| v.to_i128();
        let fast = || -> Option<RatPoint> {
            let (ax, ay, aw) = (small(&a.x)?, small(&a.y)?, small(&a.w)?);
            let (bx, by, bw) = (small(&b.x)?, small(&b.y)?, small(&b.w)?);
            let x = mul(ax, bw)?.checked_add(mul(bx, aw)?)?;
            let y = mul(ay, bw)?.checked_add(mul(by, aw)?)?;
            let w = mul(aw, bw)?.checked_mul(2)?;
            RatPoint::from_i128(x, y, w)
        };
        if let Some(m) = fast() {
            return m;
        }
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

/// Binary gcd (Stein) on one unsigned type: shifts and subtractions, no
/// division.
macro_rules! binary_gcd {
    ($name:ident, $t:ty) => {
        fn $name(mut x: $t, mut y: $t) -> $t {
            if x == 0 {
                return y;
            }
            if y == 0 {
                return x;
            }
            let shift = (x | y).trailing_zeros();
            x >>= x.trailing_zeros();
            loop {
                y >>= y.trailing_zeros();
                if x > y {
                    std::mem::swap(&mut x, &mut y);
                }
                y -= x;
                if y == 0 {
                    return x << shift;
                }
            }
        }
    };
}

binary_gcd!(gcd_u64, u64);
binary_gcd!(gcd_u128_wide, u128);

/// The gcd of two `u128` (`gcd(0, 0) = 0`), on 64 bits when both fit.
pub fn gcd_u128(x: u128, y: u128) -> u128 {
    match (u64::try_from(x), u64::try_from(y)) {
        (Ok(a), Ok(b)) => u128::from(gcd_u64(a, b)),
        _ => gcd_u128_wide(x, y),
    }
}
