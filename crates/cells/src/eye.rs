//! Exact signs for the incremental skeletons: directions from a rational
//! viewpoint and angular order around a map vertex.
//!
//! Every product is tried in `i128` with checked arithmetic and redone on
//! GMP integers when it overflows, so no bit bound is assumed: the fast
//! path is exact by construction, not by a proof about magnitudes.

use rug::Integer;
use std::borrow::Cow;
use std::cmp::Ordering;
use wai_exact::{Orientation, Point, RatPoint};

pub(crate) use wai_exact::mul_checked as mul;

/// A direction with integer coordinates, small or large.
#[derive(Clone, Debug)]
pub(crate) enum Dir {
    Small(i128, i128),
    Big(Integer, Integer),
}

impl Dir {
    fn from_integers(x: Integer, y: Integer) -> Dir {
        match (x.to_i128(), y.to_i128()) {
            (Some(a), Some(b)) => Dir::Small(a, b),
            _ => Dir::Big(x, y),
        }
    }

    fn big(&self) -> (Integer, Integer) {
        match self {
            Dir::Small(a, b) => (Integer::from(*a), Integer::from(*b)),
            Dir::Big(a, b) => (a.clone(), b.clone()),
        }
    }

    /// The sign of `self × other` (`Greater`: other is counter-clockwise).
    pub(crate) fn cross(&self, other: &Dir) -> Ordering {
        if let (Dir::Small(a, b), Dir::Small(c, d)) = (self, other) {
            if let (Some(p), Some(q)) = (mul(*a, *d), mul(*b, *c)) {
                return p.cmp(&q);
            }
        }
        let ((a, b), (c, d)) = (self.big(), other.big());
        (a * d).cmp(&(b * c))
    }

    /// The sign of `self · other`.
    pub(crate) fn dot(&self, other: &Dir) -> Ordering {
        if let (Dir::Small(a, b), Dir::Small(c, d)) = (self, other) {
            if let (Some(p), Some(q)) = (mul(*a, *c), mul(*b, *d)) {
                // p + q > 0  <=>  p > -q (no overflow: -q of a product of
                // two i128 that did not overflow can only fail at i128::MIN).
                if let Some(nq) = q.checked_neg() {
                    return p.cmp(&nq);
                }
            }
        }
        let ((a, b), (c, d)) = (self.big(), other.big());
        (a * c + b * d).cmp0()
    }
}

/// The direction from `a` to `b`.
pub(crate) fn dir(a: Point, b: Point) -> Dir {
    match (b.x.checked_sub(a.x), b.y.checked_sub(a.y)) {
        (Some(x), Some(y)) => Dir::Small(x, y),
        _ => Dir::Big(Integer::from(b.x) - a.x, Integer::from(b.y) - a.y),
    }
}

/// Counter-clockwise angular order of directions, starting at `base`
/// (angle 0) and going round once: `Less` if `u` comes before `v`.
pub(crate) fn angle_cmp(base: &Dir, u: &Dir, v: &Dir) -> Ordering {
    let half = |w: &Dir| match base.cross(w) {
        Ordering::Greater => 0,
        Ordering::Equal if base.dot(w) == Ordering::Greater => 0,
        _ => 1,
    };
    half(u).cmp(&half(v)).then_with(|| v.cross(u))
}

/// A rational point: its homogeneous coordinates as `i128`s when they
/// fit, else its exact point (the arrangement keeps one or the other, so
/// each point is converted once and most never become GMP integers).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Pt<'a> {
    pub(crate) small: Option<[i128; 3]>,
    /// `Some` at least when `small` is `None`.
    pub(crate) big: Option<&'a RatPoint>,
}

impl<'a> Pt<'a> {
    #[cfg(test)]
    pub(crate) fn new(p: &'a RatPoint) -> Pt<'a> {
        Pt {
            small: small_of(p),
            big: Some(p),
        }
    }

    /// The exact point, built from the `i128`s if it is not at hand (the
    /// slow paths, after an overflow).
    pub(crate) fn exact(&self) -> Cow<'a, RatPoint> {
        match (self.big, self.small) {
            (Some(p), _) => Cow::Borrowed(p),
            (None, Some([x, y, w])) => {
                Cow::Owned(RatPoint::from_i128(x, y, w).expect("a point has w > 0"))
            }
            (None, None) => unreachable!("a point is small or at hand"),
        }
    }
}

/// The homogeneous coordinates of `p` as `i128`s, if they fit.
pub(crate) fn small_of(p: &RatPoint) -> Option<[i128; 3]> {
    Some([p.hx().to_i128()?, p.hy().to_i128()?, p.hw().to_i128()?])
}

/// A rational viewpoint q = (X, Y) / W, for signs against map vertices
/// (any W > 0: not necessarily in lowest terms).
#[derive(Debug)]
pub(crate) enum Eye {
    Small { x: i128, y: i128, w: i128 },
    Big { x: Integer, y: Integer, w: Integer },
}

impl Eye {
    pub(crate) fn new(q: &RatPoint) -> Eye {
        match (q.hx().to_i128(), q.hy().to_i128(), q.hw().to_i128()) {
            (Some(x), Some(y), Some(w)) => Eye::Small { x, y, w },
            _ => Eye::Big {
                x: q.hx().clone(),
                y: q.hy().clone(),
                w: q.hw().clone(),
            },
        }
    }

    /// The point `p` itself.
    pub(crate) fn at(p: Pt<'_>) -> Eye {
        match p.small {
            Some([x, y, w]) => Eye::Small { x, y, w },
            None => Eye::new(&p.exact()),
        }
    }

    /// The midpoint of `a` and `b`, without reducing it (checked `i128`
    /// first, GMP on overflow).
    pub(crate) fn midpoint(a: Pt<'_>, b: Pt<'_>) -> Eye {
        let fast = || -> Option<Eye> {
            let ([ax, ay, aw], [bx, by, bw]) = (a.small?, b.small?);
            Some(Eye::Small {
                x: mul(ax, bw)?.checked_add(mul(bx, aw)?)?,
                y: mul(ay, bw)?.checked_add(mul(by, aw)?)?,
                w: mul(aw, bw)?.checked_mul(2)?,
            })
        };
        fast().unwrap_or_else(|| Eye::new(&RatPoint::midpoint(&a.exact(), &b.exact())))
    }

    /// The centroid of `a`, `b` and `c`, without reducing it (checked
    /// `i128` first, GMP on overflow).
    pub(crate) fn centroid(a: Pt<'_>, b: Pt<'_>, c: Pt<'_>) -> Eye {
        let fast = || -> Option<Eye> {
            let ([ax, ay, aw], [bx, by, bw], [cx, cy, cw]) = (a.small?, b.small?, c.small?);
            let (bc, ac, ab) = (mul(bw, cw)?, mul(aw, cw)?, mul(aw, bw)?);
            let sum = |u: i128, v: i128, w: i128| -> Option<i128> {
                mul(u, bc)?
                    .checked_add(mul(v, ac)?)?
                    .checked_add(mul(w, ab)?)
            };
            Some(Eye::Small {
                x: sum(ax, bx, cx)?,
                y: sum(ay, by, cy)?,
                w: mul(aw, bc)?.checked_mul(3)?,
            })
        };
        fast().unwrap_or_else(|| {
            Eye::new(&crate::decomposition::centroid3_gmp(
                &a.exact(),
                &b.exact(),
                &c.exact(),
            ))
        })
    }

    /// The homogeneous coordinates `[x, y, w]` of q when each is below
    /// `2^NARROW_BITS` in magnitude ([`crate::small::EdgeTurns::left`]).
    #[inline]
    pub(crate) fn narrow(&self) -> Option<[i128; 3]> {
        let fits = |c: i128| c.unsigned_abs() < 1 << crate::small::NARROW_BITS;
        match self {
            Eye::Small { x, y, w } if fits(*x) && fits(*y) && fits(*w) => Some([*x, *y, *w]),
            _ => None,
        }
    }

    /// The direction from q to the map vertex `a`, scaled by W > 0.
    pub(crate) fn toward(&self, a: Point) -> Dir {
        match self {
            Eye::Small { x, y, w } => {
                let dx = mul(*w, a.x).and_then(|p| p.checked_sub(*x));
                let dy = mul(*w, a.y).and_then(|p| p.checked_sub(*y));
                match (dx, dy) {
                    (Some(dx), Some(dy)) => Dir::Small(dx, dy),
                    _ => Dir::from_integers(
                        Integer::from(*w) * a.x - *x,
                        Integer::from(*w) * a.y - *y,
                    ),
                }
            }
            Eye::Big { x, y, w } => {
                Dir::from_integers(Integer::from(w * a.x) - x, Integer::from(w * a.y) - y)
            }
        }
    }

    /// The orientation of `(a, b, q)`.
    pub(crate) fn orientation(&self, a: Point, b: Point) -> Orientation {
        // (b − a) × (q − a) = −(b − a) × toward(a) / W.
        match dir(a, b).cross(&self.toward(a)) {
            Ordering::Less => Orientation::CounterClockwise,
            Ordering::Equal => Orientation::Collinear,
            Ordering::Greater => Orientation::Clockwise,
        }
    }
}
