//! Exact signs for the incremental skeletons: directions from a rational
//! viewpoint and angular order around a map vertex.
//!
//! Every product is tried in `i128` with checked arithmetic and redone on
//! GMP integers when it overflows, so no bit bound is assumed: the fast
//! path is exact by construction, not by a proof about magnitudes.

use rug::Integer;
use std::borrow::Cow;
use std::cmp::Ordering;
use wai_exact::{BigVector, Orientation, Point, RatPoint, Vector};

pub(crate) use wai_exact::mul_checked as mul;

/// A direction with integer coordinates, small or large: the shared
/// [`Vector`] while it fits an `i128`, else a [`BigVector`].
#[derive(Clone, Debug)]
pub(crate) enum Dir {
    Small(Vector),
    Big(BigVector),
}

impl Dir {
    fn from_integers(x: Integer, y: Integer) -> Dir {
        let big = BigVector::new(x, y);
        match big.to_small() {
            Some(v) => Dir::Small(v),
            None => Dir::Big(big),
        }
    }

    fn big(&self) -> Cow<'_, BigVector> {
        match self {
            Dir::Small(v) => Cow::Owned(v.to_big()),
            Dir::Big(v) => Cow::Borrowed(v),
        }
    }

    /// The sign of `self × other` (`Greater`: other is counter-clockwise).
    pub(crate) fn cross_sign(&self, other: &Dir) -> Ordering {
        match (self, other) {
            (Dir::Small(u), Dir::Small(v)) => u.cross_sign(*v),
            _ => self.big().cross_sign(&other.big()),
        }
    }

    /// The sign of `self · other`.
    pub(crate) fn dot_sign(&self, other: &Dir) -> Ordering {
        match (self, other) {
            (Dir::Small(u), Dir::Small(v)) => u.dot_sign(*v),
            _ => self.big().dot_sign(&other.big()),
        }
    }
}

/// The direction from `a` to `b`.
pub(crate) fn dir(a: Point, b: Point) -> Dir {
    match Vector::between(a, b) {
        Some(v) => Dir::Small(v),
        None => Dir::Big(BigVector::between(a, b)),
    }
}

/// Counter-clockwise angular order of directions, starting at `base`
/// (angle 0) and going round once: `Less` if `u` comes before `v`.
pub(crate) fn angle_cmp(base: &Dir, u: &Dir, v: &Dir) -> Ordering {
    let half = |w: &Dir| match base.cross_sign(w) {
        Ordering::Greater => 0,
        Ordering::Equal if base.dot_sign(w) == Ordering::Greater => 0,
        _ => 1,
    };
    half(u).cmp(&half(v)).then_with(|| v.cross_sign(u))
}

/// An arrangement point as the arrangement stores it: its homogeneous
/// coordinates as `i128`s when they fit, else a reference to its exact
/// [`RatPoint`] (the arrangement keeps one or the other, so each point is
/// converted once and most never become GMP integers). A view of storage,
/// not a point type of its own: its arithmetic is [`Eye`]'s and
/// `wai_exact`'s.
#[derive(Clone, Copy, Debug)]
pub(crate) struct PointRef<'a> {
    pub(crate) small: Option<[i128; 3]>,
    /// `Some` at least when `small` is `None`.
    pub(crate) big: Option<&'a RatPoint>,
}

impl<'a> PointRef<'a> {
    #[cfg(test)]
    pub(crate) fn new(p: &'a RatPoint) -> PointRef<'a> {
        PointRef {
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
    pub(crate) fn at(p: PointRef<'_>) -> Eye {
        match p.small {
            Some([x, y, w]) => Eye::Small { x, y, w },
            None => Eye::new(&p.exact()),
        }
    }

    /// The midpoint of `a` and `b`, without reducing it (checked `i128`
    /// first, GMP on overflow).
    pub(crate) fn midpoint(a: PointRef<'_>, b: PointRef<'_>) -> Eye {
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
    pub(crate) fn centroid(a: PointRef<'_>, b: PointRef<'_>, c: PointRef<'_>) -> Eye {
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
                    (Some(dx), Some(dy)) => Dir::Small(Vector::new(dx, dy)),
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
        match dir(a, b).cross_sign(&self.toward(a)) {
            Ordering::Less => Orientation::CounterClockwise,
            Ordering::Equal => Orientation::Collinear,
            Ordering::Greater => Orientation::Clockwise,
        }
    }
}
