//! What the visibility checkers examine: sampled viewpoints, their exact
//! visibility polygons, and Def 3.4 read off a polygon's geometry.
//!
//! The checkers of chapter 3 (L3.1a–c, D3.5, T3.2) examine these.
//!
//! # Sampling
//! The claims L3.1a–c, D3.5 and T3.2 speak about every viewpoint of the map,
//! a continuum; [`viewpoints`] picks a finite, deterministic set of interior
//! viewpoints of every degenerate kind the thesis's decomposition produces,
//! plus generic ones (the same kinds as the visibility crate's tests):
//! - the viewpoints the thesis figure draws, when the map is a recognised
//!   thesis family (`corridor-niches`, `overlap-fan`, `convex-niches`; the
//!   map is regenerated from its name and compared vertex by vertex, so the
//!   name is only a hint),
//! - midpoints of vertex pairs (on a line through two map vertices),
//! - meeting points of two lines through vertex pairs,
//! - points on the extension of a map edge beyond its end,
//! - points of a rational grid (generic positions),
//!
//! taken round robin from the kinds so that a small `limit` still mixes them.
//! Each V_p is then computed exactly by the production algorithm
//! ([`wai_visibility::VisibilityIndex`]) and examined exactly.
//!
//! # Edge cases
//! A viewpoint is kept only if it lies strictly inside the map (the thesis
//! assumes p not on the boundary, sec. 3.4); duplicates are dropped.

use std::cmp::Ordering;

use rug::{Integer, Rational};
use serde_json::{json, Value};
use wai_cells::{Arrangement, Support};
use wai_exact::{
    construct_intersection, orientation_rat, Containment, Line, Orientation, Point, RatPoint,
};
use wai_map::{format_exact, Map};
use wai_visibility::{VisibilityIndex, VisibilityPolygon};

/// Viewpoints per map that the chapter 3 checkers examine by default.
pub const VIEWPOINTS: usize = 10;

/// At most `limit` interior viewpoints of `map`, deterministic (see the
/// module documentation for the kinds).
///
/// ```
/// use wai_exact::{locate_rat, Containment};
/// let map = wai_gen::family("corridor-niches", &[3]).unwrap();
/// let views = wai_study::sample::viewpoints(&map, 10);
/// assert_eq!(views.len(), 10);
/// // The thesis's own viewpoints come first: (5 + 4i, -3), deep in niche i.
/// assert_eq!(views[0].to_string(), "(5, -3)");
/// assert!(views.iter().all(|p| locate_rat(map.vertices(), p) == Containment::Inside));
/// ```
pub fn viewpoints(map: &Map, limit: usize) -> Vec<RatPoint> {
    let v = map.vertices();
    let n = v.len();
    let mut out: Vec<RatPoint> = Vec::new();
    let keep = |q: RatPoint, out: &mut Vec<RatPoint>| {
        if out.len() < limit && !out.contains(&q) && map.locate(&q) == Containment::Inside {
            out.push(q);
        }
    };
    // The family's own viewpoints, at most half of the budget (and 2).
    for q in family_viewpoints(map).into_iter().take((limit / 2).max(2)) {
        keep(q, &mut out);
    }
    // Midpoints of vertex pairs, in a scrambled order.
    let pairs: Vec<(usize, usize)> = (0..n)
        .flat_map(|i| ((i + 2)..n).map(move |j| (i, j)))
        .collect();
    let midpoints = scrambled(pairs.len())
        .map(move |k| pairs[k])
        .map(|(i, j)| RatPoint::midpoint(&v[i].into(), &v[j].into()));
    // Meeting points of lines through vertex pairs (a sample of 40 lines).
    let lines: Vec<Line> = (0..n)
        .flat_map(|i| (0..n).filter(move |&j| j != i).map(move |j| (i, j)))
        .step_by(3)
        .filter_map(|(i, j)| Line::new(v[i], v[j]))
        .take(40)
        .collect();
    let line_pairs: Vec<(usize, usize)> = (0..lines.len())
        .flat_map(|a| ((a + 1)..lines.len()).map(move |b| (a, b)))
        .collect();
    let meetings = scrambled(line_pairs.len())
        .filter_map(|k| construct_intersection(&lines[line_pairs[k].0], &lines[line_pairs[k].1]));
    // Points on the extensions of map edges: v_i + (v_i − v_{i−1}) / 3.
    let extensions = (0..n).map(|i| {
        let (a, b) = (v[map.prev(i)], v[i]);
        RatPoint::new(
            Integer::from(b.x) * 4 - a.x,
            Integer::from(b.y) * 4 - a.y,
            Integer::from(3),
        )
        .expect("3 != 0")
    });
    // A rational grid: (lo + (hi − lo)·i/8 + 1/56, lo + (hi − lo)·j/8 + 2/56).
    let (lo, hi) = map.bounding_box();
    let grid = (1..8i128).flat_map(move |i| {
        (1..8i128).map(move |j| {
            let x = Integer::from(lo.x) * 8 + Integer::from(hi.x - lo.x) * i;
            let y = Integer::from(lo.y) * 8 + Integer::from(hi.y - lo.y) * j;
            RatPoint::new(x * 7 + 1, y * 7 + 2, Integer::from(56)).expect("56 != 0")
        })
    });
    let mut kinds: Vec<Box<dyn Iterator<Item = RatPoint> + '_>> = vec![
        Box::new(midpoints),
        Box::new(meetings),
        Box::new(extensions),
        Box::new(grid),
    ];
    // Round robin; a kind whose next candidate is rejected keeps its turn
    // until it yields a kept point or runs dry.
    while out.len() < limit && !kinds.is_empty() {
        kinds.retain_mut(|kind| {
            let before = out.len();
            for q in kind.by_ref() {
                keep(q, &mut out);
                if out.len() > before || out.len() >= limit {
                    return true;
                }
            }
            false
        });
    }
    out
}

/// The indices `0..len` in a fixed scrambled order: `k·s mod len` for a
/// step `s ≈ 0.618·len` coprime with `len`.
fn scrambled(len: usize) -> impl Iterator<Item = usize> {
    let coprime = |a: usize, b: usize| {
        let (mut a, mut b) = (a, b);
        while b != 0 {
            (a, b) = (b, a % b);
        }
        a == 1
    };
    let step = (len * 618 / 1000..len.max(1))
        .find(|&s| s > 0 && coprime(s, len))
        .unwrap_or(1);
    (0..len).map(move |k| (k * step) % len)
}

/// The viewpoints the thesis figure draws, if `map` is a thesis family map
/// (recognised by its name `id/params` and confirmed by regenerating it);
/// otherwise none.
///
/// ```
/// let map = wai_gen::family("corridor-niches", &[2]).unwrap();
/// assert_eq!(wai_study::sample::family_viewpoints(&map).len(), 2);
/// let renamed = map.clone().with_name("corridor-niches/k=3");
/// assert!(wai_study::sample::family_viewpoints(&renamed).is_empty());
/// ```
pub fn family_viewpoints(map: &Map) -> Vec<RatPoint> {
    let Some((id, params)) = map.name().and_then(|s| s.split_once('/')) else {
        return Vec::new();
    };
    let values: Option<Vec<u32>> = params
        .split(',')
        .map(|kv| kv.split_once('=').and_then(|(_, x)| x.parse().ok()))
        .collect();
    let Some(values) = values else {
        return Vec::new();
    };
    let points: Vec<Point> = match (id, values.as_slice()) {
        ("corridor-niches", &[k]) => wai_gen::corridor_niches_viewpoints(k),
        ("overlap-fan", &[z]) => wai_gen::overlap_fan_viewpoints(z),
        ("convex-niches", &[fan, views]) => wai_gen::convex_niches_viewpoints(fan, views),
        _ => return Vec::new(),
    };
    let same = wai_gen::family(id, &values)
        .is_ok_and(|m| m.vertices() == map.vertices() && *map.scale() == 1);
    if !same {
        return Vec::new();
    }
    points.into_iter().map(RatPoint::from).collect()
}

/// V_p of each of [`viewpoints`]`(map, limit)`, by the production algorithm.
///
/// # Panics
/// If the production algorithm rejects an interior viewpoint (a bug of
/// `wai-visibility`, not a claim violation).
pub fn visibility_polygons(map: &Map, limit: usize) -> Vec<VisibilityPolygon> {
    visibility_polygons_with(map, &VisibilityIndex::new(map), limit)
}

/// As [`visibility_polygons`], through an index already built.
pub fn visibility_polygons_with(
    map: &Map,
    index: &VisibilityIndex<'_>,
    limit: usize,
) -> Vec<VisibilityPolygon> {
    viewpoints(map, limit)
        .iter()
        .map(|p| {
            index.visibility_polygon(p).unwrap_or_else(|e| {
                panic!(
                    "V_p of the interior viewpoint {p} of map {}: {e}",
                    map_name(map)
                )
            })
        })
        .collect()
}

/// The map's name, or `"unnamed"`.
pub fn map_name(map: &Map) -> &str {
    map.name().unwrap_or("unnamed")
}

/// A point as `["x", "y"]` of exact strings in the units of the map's file
/// (the `viewpoints` format of `counterexamples/`).
pub fn point_json(map: &Map, q: &RatPoint) -> Value {
    let unit = |c: &Integer| format_exact(&Rational::from((c.clone(), q.hw() * map.scale())));
    json!([unit(q.hx()), unit(q.hy())])
}

/// The replay data every violation of a V_p starts with: the map's name,
/// the viewpoint in file units and in the map's integer frame, and V_p's
/// vertices (integer frame). Checkers add their indices to it.
pub fn replay(map: &Map, vp: &VisibilityPolygon) -> serde_json::Map<String, Value> {
    let mut m = serde_json::Map::new();
    m.insert("map".into(), json!(map_name(map)));
    m.insert("viewpoint".into(), point_json(map, vp.viewpoint()));
    m.insert("viewpoint_scaled".into(), json!(vp.viewpoint().to_string()));
    m.insert(
        "vp".into(),
        json!(vp
            .vertices()
            .iter()
            .map(|v| v.point.to_string())
            .collect::<Vec<_>>()),
    );
    m
}

/// `q + (dx, dy)`.
pub fn translate(q: &RatPoint, dx: i128, dy: i128) -> RatPoint {
    RatPoint::new(
        Integer::from(q.hw() * dx) + q.hx(),
        Integer::from(q.hw() * dy) + q.hy(),
        q.hw().clone(),
    )
    .expect("the denominator is positive")
}

/// Def 3.4: edge `i` of V_p (from vertex `i` to `i + 1`) is spurious iff it
/// is collinear with the viewpoint — read off the geometry, not off the
/// stored kind.
pub fn edge_collinear_with_viewpoint(vp: &VisibilityPolygon, i: usize) -> bool {
    let v = vp.vertices();
    let n = v.len();
    orientation_rat(&v[i].point, &v[(i + 1) % n].point, vp.viewpoint()) == Orientation::Collinear
}

/// Def 3.4: vertex `i` of V_p is spurious iff it lies on a spurious edge
/// (u, v_i) whose other endpoint u is closer to the viewpoint — read off the
/// geometry, not off the stored flag.
pub fn vertex_spurious_by_def(vp: &VisibilityPolygon, i: usize) -> bool {
    let v = vp.vertices();
    let n = v.len();
    let p = vp.viewpoint();
    let (before, after) = ((i + n - 1) % n, (i + 1) % n);
    (edge_collinear_with_viewpoint(vp, before) && closer(p, &v[before].point, &v[i].point))
        || (edge_collinear_with_viewpoint(vp, i) && closer(p, &v[after].point, &v[i].point))
}

/// Whether `a` is strictly closer to `p` than `b` is (exact squared
/// distances).
///
/// With homogeneous coordinates, `|a − p|² = |a·wp − p·wa|² / (wa·wp)²`, so
/// the comparison is `|a·wp − p·wa|²·wb² < |b·wp − p·wb|²·wa²` in integers
/// (the common factor wp² dropped); in `i128` when every value fits
/// (checked), else in GMP.
pub fn closer(p: &RatPoint, a: &RatPoint, b: &RatPoint) -> bool {
    let small = || -> Option<bool> {
        let t = |q: &RatPoint| Some([q.hx().to_i128()?, q.hy().to_i128()?, q.hw().to_i128()?]);
        let (p, a, b) = (t(p)?, t(a)?, t(b)?);
        let sq = |q: [i128; 3], w_other: i128| -> Option<i128> {
            let ux = q[0]
                .checked_mul(p[2])?
                .checked_sub(p[0].checked_mul(q[2])?)?;
            let uy = q[1]
                .checked_mul(p[2])?
                .checked_sub(p[1].checked_mul(q[2])?)?;
            let d = ux.checked_mul(ux)?.checked_add(uy.checked_mul(uy)?)?;
            d.checked_mul(w_other.checked_mul(w_other)?)
        };
        Some(sq(a, b[2])? < sq(b, a[2])?)
    };
    if let Some(c) = small() {
        return c;
    }
    let sq = |q: &RatPoint, w_other: &Integer| -> Integer {
        let ux = Integer::from(q.hx() * p.hw()) - Integer::from(p.hx() * q.hw());
        let uy = Integer::from(q.hy() * p.hw()) - Integer::from(p.hy() * q.hw());
        (Integer::from(&ux * &ux) + Integer::from(&uy * &uy)) * Integer::from(w_other * w_other)
    };
    sq(a, b.hw()) < sq(b, a.hw())
}

fn coords(q: &RatPoint) -> (Rational, Rational) {
    (
        Rational::from((q.hx().clone(), q.hw().clone())),
        Rational::from((q.hy().clone(), q.hw().clone())),
    )
}

/// The rational with the least denominator (then the least numerator in
/// absolute value) strictly between `a` and `b` (`a < b`): the
/// Stern–Brocot search by continued fractions, exact.
///
/// ```
/// use rug::Rational;
/// let q = |n: i64, d: i64| Rational::from((n, d));
/// assert_eq!(wai_study::sample::simplest_between(&q(1, 3), &q(2, 3)), q(1, 2));
/// assert_eq!(wai_study::sample::simplest_between(&q(-7, 2), &q(5, 1)), q(0, 1));
/// assert_eq!(wai_study::sample::simplest_between(&q(3, 10), &q(1, 3)), q(4, 13));
/// ```
pub fn simplest_between(a: &Rational, b: &Rational) -> Rational {
    simplest::<Rational>(a, b).expect("GMP does not overflow")
}

/// Exact rationals for the simple-point searches, in GMP ([`Rational`])
/// or in `i128` ([`Frac`]); an operation answers `None` only when an
/// `i128` would overflow.
trait Q: Clone + Sized {
    fn int(v: i128) -> Self;
    fn add(&self, o: &Self) -> Option<Self>;
    fn sub(&self, o: &Self) -> Option<Self>;
    fn mul(&self, o: &Self) -> Option<Self>;
    /// `self / o`, `o ≠ 0`.
    fn div(&self, o: &Self) -> Option<Self>;
    fn cmp(&self, o: &Self) -> Option<Ordering>;
    fn floor(&self) -> Option<Self>;
    fn is_zero(&self) -> bool;
    /// The point `(x, y)`.
    fn point(x: &Self, y: &Self) -> Option<RatPoint>;
    /// The coordinates of `p`.
    fn of(p: &RatPoint) -> Option<(Self, Self)>;
    /// [`simplest`] of `a < b`.
    fn simplest_in(a: &Self, b: &Self) -> Option<Self> {
        simplest(a, b)
    }
    /// The ordinate at `x` of the line through `a` and `b` (not vertical),
    /// when a representation has a shortcut for it; `None` to have it
    /// computed step by step.
    fn line_y(_a: &RatPoint, _b: &RatPoint, _x: &Self) -> Option<Self> {
        None
    }
}

impl Q for Rational {
    fn int(v: i128) -> Self {
        Rational::from(v)
    }
    fn add(&self, o: &Self) -> Option<Self> {
        Some(Rational::from(self + o))
    }
    fn sub(&self, o: &Self) -> Option<Self> {
        Some(Rational::from(self - o))
    }
    fn mul(&self, o: &Self) -> Option<Self> {
        Some(Rational::from(self * o))
    }
    fn div(&self, o: &Self) -> Option<Self> {
        Some(Rational::from(self / o))
    }
    fn cmp(&self, o: &Self) -> Option<Ordering> {
        Some(Ord::cmp(self, o))
    }
    fn floor(&self) -> Option<Self> {
        Some(Rational::from(self.floor_ref()))
    }
    fn is_zero(&self) -> bool {
        *self == 0
    }
    fn point(x: &Self, y: &Self) -> Option<RatPoint> {
        let w = Integer::from(x.denom() * y.denom());
        let hx = Integer::from(x.numer() * y.denom());
        let hy = Integer::from(y.numer() * x.denom());
        RatPoint::new(hx, hy, w)
    }
    fn of(p: &RatPoint) -> Option<(Self, Self)> {
        Some(coords(p))
    }
}

/// `n / d` with `d > 0` in lowest terms, in `i128`; every operation is
/// checked, so a result is exact or absent.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Frac {
    n: i128,
    d: i128,
}

impl Frac {
    /// `n / d` in lowest terms with `d > 0`; `None` if `d = 0` or a
    /// negation overflows. Reduced by [`RatPoint::lowest_terms_i128`] (a
    /// binary gcd, in 64 bits when the values fit), which keeps exactly
    /// these terms: `(n, 0, d)` has the gcd of `n` and `d`.
    fn new(n: i128, d: i128) -> Option<Frac> {
        let [n, _, d] = RatPoint::lowest_terms_i128(n, 0, d)?;
        Some(Frac { n, d })
    }
}

impl Q for Frac {
    fn int(v: i128) -> Self {
        Frac { n: v, d: 1 }
    }
    fn add(&self, o: &Self) -> Option<Self> {
        let n = self
            .n
            .checked_mul(o.d)?
            .checked_add(o.n.checked_mul(self.d)?)?;
        Frac::new(n, self.d.checked_mul(o.d)?)
    }
    fn sub(&self, o: &Self) -> Option<Self> {
        let n = self
            .n
            .checked_mul(o.d)?
            .checked_sub(o.n.checked_mul(self.d)?)?;
        Frac::new(n, self.d.checked_mul(o.d)?)
    }
    fn mul(&self, o: &Self) -> Option<Self> {
        Frac::new(self.n.checked_mul(o.n)?, self.d.checked_mul(o.d)?)
    }
    fn div(&self, o: &Self) -> Option<Self> {
        Frac::new(self.n.checked_mul(o.d)?, self.d.checked_mul(o.n)?)
    }
    fn cmp(&self, o: &Self) -> Option<Ordering> {
        Some(self.n.checked_mul(o.d)?.cmp(&o.n.checked_mul(self.d)?))
    }
    fn floor(&self) -> Option<Self> {
        Some(Frac::int(self.n.div_euclid(self.d)))
    }
    fn is_zero(&self) -> bool {
        self.n == 0
    }
    fn point(x: &Self, y: &Self) -> Option<RatPoint> {
        RatPoint::from_i128(
            x.n.checked_mul(y.d)?,
            y.n.checked_mul(x.d)?,
            x.d.checked_mul(y.d)?,
        )
    }
    fn simplest_in(a: &Self, b: &Self) -> Option<Self> {
        simplest_frac(a, b)
    }
    /// The line through `a = (ax, ay, aw)` and `b` is `l·(X, Y, W) = 0`
    /// with `l = a × b`, so the ordinate at `x = n / d` is
    /// `−(l0·n + l2·d) / (l1·d)` (`l1 = aw·bx − ax·bw ≠ 0` as the line is
    /// not vertical): one reduction instead of one per step. Checked, so
    /// `None` (then step by step) on overflow.
    fn line_y(a: &RatPoint, b: &RatPoint, x: &Self) -> Option<Self> {
        let [ax, ay, aw] = [a.hx().to_i128()?, a.hy().to_i128()?, a.hw().to_i128()?];
        let [bx, by, bw] = [b.hx().to_i128()?, b.hy().to_i128()?, b.hw().to_i128()?];
        let l0 = ay.checked_mul(bw)?.checked_sub(aw.checked_mul(by)?)?;
        let l1 = aw.checked_mul(bx)?.checked_sub(ax.checked_mul(bw)?)?;
        let l2 = ax.checked_mul(by)?.checked_sub(ay.checked_mul(bx)?)?;
        let num = l0.checked_mul(x.n)?.checked_add(l2.checked_mul(x.d)?)?;
        let den = l1.checked_mul(x.d)?;
        Frac::new(num.checked_neg()?, den)
    }
    fn of(p: &RatPoint) -> Option<(Self, Self)> {
        let w = p.hw().to_i128()?;
        Some((
            Frac::new(p.hx().to_i128()?, w)?,
            Frac::new(p.hy().to_i128()?, w)?,
        ))
    }
}

/// [`simplest_between`] in any [`Q`]; `None` on `i128` overflow.
fn simplest<T: Q>(a: &T, b: &T) -> Option<T> {
    let one = T::int(1);
    let f = a.floor()?;
    // An integer strictly inside: the one nearest 0.
    let above = f.add(&one)?;
    if above.cmp(b)? == Ordering::Less {
        let below = b.floor()?;
        let below = if below.cmp(b)? == Ordering::Equal {
            below.sub(&one)?
        } else {
            below
        };
        let zero = T::int(0);
        return Some(if above.cmp(&zero)? == Ordering::Greater {
            above
        } else if below.cmp(&zero)? == Ordering::Less {
            below
        } else {
            zero
        });
    }
    // a and b in [f, f + 1]: f + 1 / (the simplest between 1/(b − f) and
    // 1/(a − f)), with 1/0 read as +∞.
    let (fa, fb) = (a.sub(&f)?, b.sub(&f)?);
    let hi_inv = one.div(&fb)?;
    let inner = if fa.is_zero() {
        hi_inv.floor()?.add(&one)?
    } else {
        simplest(&hi_inv, &one.div(&fa)?)?
    };
    f.add(&one.div(&inner)?)
}

/// [`simplest`] in [`Frac`] without reductions: every fraction it forms
/// is in lowest terms already. For `a = n/d` in lowest terms and an
/// integer `f`, `a − f = (n − f·d)/d` has `gcd(n − f·d, d) = gcd(n, d) =
/// 1`, its reciprocal likewise; and `f + 1/(p/q) = (f·p + q)/p` with
/// `gcd(f·p + q, p) = gcd(q, p) = 1`. The same steps as [`simplest`],
/// so the same value; `None` on `i128` overflow.
fn simplest_frac(a: &Frac, b: &Frac) -> Option<Frac> {
    let f = a.n.div_euclid(a.d);
    let above = f.checked_add(1)?;
    // above < b
    if above.checked_mul(b.d)? < b.n {
        let below = b.n.div_euclid(b.d);
        let below = if b.d == 1 { below - 1 } else { below };
        let v = if above > 0 {
            above
        } else if below < 0 {
            below
        } else {
            0
        };
        return Some(Frac::int(v));
    }
    // a − f = fa_n / a.d in [0, 1), b − f = fb_n / b.d in (0, 1].
    let fa_n = a.n.checked_sub(f.checked_mul(a.d)?)?;
    let fb_n = b.n.checked_sub(f.checked_mul(b.d)?)?;
    let hi_inv = Frac { n: b.d, d: fb_n };
    let inner = if fa_n == 0 {
        Frac::int(hi_inv.n.div_euclid(hi_inv.d).checked_add(1)?)
    } else {
        simplest_frac(&hi_inv, &Frac { n: a.d, d: fa_n })?
    };
    Some(Frac {
        n: f.checked_mul(inner.n)?.checked_add(inner.d)?,
        d: inner.n,
    })
}

/// Two points inside the open convex polygon `ring` (counter-clockwise,
/// positive area) with small denominators, so that queries at them stay on
/// the integer fast paths: x1 the simplest rational strictly inside the
/// polygon's x-range, y1 the simplest inside its vertical span at x1; x2
/// the simplest between x1 and the right end, y2 likewise. `None` if the
/// polygon has no interior (its x-range or a span is empty). Computed in
/// `i128` fractions, or in GMP where those overflow (the same points).
pub fn simple_interior_points(ring: &[RatPoint]) -> Option<[RatPoint; 2]> {
    let (p, q) = simple_interior_points_or_one(ring)?;
    Some([p, q?])
}

/// [`simple_interior_points`], with the first point alone (the same as
/// [`simple_interior_point`]) where the polygon has no second.
pub fn simple_interior_points_or_one(ring: &[RatPoint]) -> Option<(RatPoint, Option<RatPoint>)> {
    interior_points_in::<Frac>(ring, true).unwrap_or_else(|| {
        interior_points_in::<Rational>(ring, true).expect("GMP does not overflow")
    })
}

/// The first point of [`simple_interior_points`] alone.
pub fn simple_interior_point(ring: &[RatPoint]) -> Option<RatPoint> {
    interior_points_in::<Frac>(ring, false)
        .unwrap_or_else(|| {
            interior_points_in::<Rational>(ring, false).expect("GMP does not overflow")
        })
        .map(|(p, _)| p)
}

/// [`simple_interior_points_or_one`] in `T` (the second point only if
/// `both`): `None` on overflow, `Some(None)` if the polygon has no
/// interior.
#[allow(clippy::type_complexity)]
fn interior_points_in<T: Q>(
    ring: &[RatPoint],
    both: bool,
) -> Option<Option<(RatPoint, Option<RatPoint>)>> {
    let pts: Vec<(T, T)> = ring.iter().map(T::of).collect::<Option<_>>()?;
    let k = pts.len();
    if k == 0 {
        return Some(None);
    }
    let (mut lo, mut hi) = (pts[0].0.clone(), pts[0].0.clone());
    for p in &pts[1..] {
        if p.0.cmp(&lo)? == Ordering::Less {
            lo = p.0.clone();
        }
        if p.0.cmp(&hi)? == Ordering::Greater {
            hi = p.0.clone();
        }
    }
    if lo.cmp(&hi)? != Ordering::Less {
        return Some(None);
    }
    // The open vertical span of the polygon at x (strictly inside x-range).
    let span = |x: &T| -> Option<Option<(T, T)>> {
        let mut span: Option<(T, T)> = None;
        for i in 0..k {
            let (a, b) = (&pts[i], &pts[(i + 1) % k]);
            let (l, r) = if a.0.cmp(&b.0)? != Ordering::Greater {
                (a, b)
            } else {
                (b, a)
            };
            let inside = l.0.cmp(x)? != Ordering::Greater && x.cmp(&r.0)? != Ordering::Greater;
            if !inside || l.0.cmp(&r.0)? == Ordering::Equal {
                continue;
            }
            let y = match T::line_y(&ring[i], &ring[(i + 1) % k], x) {
                Some(y) => y,
                None => {
                    let t = x.sub(&l.0)?.div(&r.0.sub(&l.0)?)?;
                    r.1.sub(&l.1)?.mul(&t)?.add(&l.1)?
                }
            };
            span = Some(match span {
                None => (y.clone(), y),
                Some((ylo, yhi)) => {
                    let ylo = if y.cmp(&ylo)? == Ordering::Less {
                        y.clone()
                    } else {
                        ylo
                    };
                    let yhi = if y.cmp(&yhi)? == Ordering::Greater {
                        y
                    } else {
                        yhi
                    };
                    (ylo, yhi)
                }
            });
        }
        Some(span.filter(|(ylo, yhi)| ylo.cmp(yhi) == Some(Ordering::Less)))
    };
    let at = |x: &T| -> Option<Option<RatPoint>> {
        let Some((ylo, yhi)) = span(x)? else {
            return Some(None);
        };
        Some(Some(T::point(x, &T::simplest_in(&ylo, &yhi)?)?))
    };
    let x1 = T::simplest_in(&lo, &hi)?;
    let Some(p1) = at(&x1)? else {
        return Some(None);
    };
    if !both {
        return Some(Some((p1, None)));
    }
    let x2 = T::simplest_in(&x1, &hi)?;
    Some(Some((p1, at(&x2)?)))
}

/// Three points of the open segment from `a` to `b` (distinct points on
/// the line through the integer points `on.0` and `on.1`) with small
/// denominators, in order from `a`: the simplest point inside it (by the
/// coordinate that varies, then the line), and the simplest on each side
/// of that one. Computed in `i128` fractions, or in GMP where those
/// overflow (the same points).
pub fn simple_segment_points(a: &RatPoint, b: &RatPoint, on: (Point, Point)) -> [RatPoint; 3] {
    let v = segment_points_in::<Frac>(a, b, on, true).unwrap_or_else(|| {
        segment_points_in::<Rational>(a, b, on, true).expect("GMP does not overflow")
    });
    [v[0].clone(), v[1].clone(), v[2].clone()]
}

/// The middle point of [`simple_segment_points`] alone.
pub fn simple_segment_point(a: &RatPoint, b: &RatPoint, on: (Point, Point)) -> RatPoint {
    segment_points_in::<Frac>(a, b, on, false)
        .unwrap_or_else(|| {
            segment_points_in::<Rational>(a, b, on, false).expect("GMP does not overflow")
        })
        .swap_remove(0)
}

/// [`simple_segment_points`] in `T` (only the middle one unless `all`):
/// `None` on overflow.
fn segment_points_in<T: Q>(
    a: &RatPoint,
    b: &RatPoint,
    on: (Point, Point),
    all: bool,
) -> Option<Vec<RatPoint>> {
    let (pa, pb) = (T::of(a)?, T::of(b)?);
    let (p, q) = on;
    let vertical = pa.0.cmp(&pb.0)? == Ordering::Equal;
    // The varying coordinate u and the other as a function of it.
    let (ua, ub) = if vertical {
        (&pa.1, &pb.1)
    } else {
        (&pa.0, &pb.0)
    };
    let slope = if vertical {
        None
    } else {
        Some(T::int(q.y.checked_sub(p.y)?).div(&T::int(q.x.checked_sub(p.x)?))?)
    };
    let point = |u: &T| -> Option<RatPoint> {
        match &slope {
            None => T::point(&pa.0, u),
            Some(m) => {
                let y = u.sub(&T::int(p.x))?.mul(m)?.add(&T::int(p.y))?;
                T::point(u, &y)
            }
        }
    };
    let increasing = ua.cmp(ub)? == Ordering::Less;
    let (lo, hi) = if increasing { (ua, ub) } else { (ub, ua) };
    let mid = T::simplest_in(lo, hi)?;
    if !all {
        return Some(vec![point(&mid)?]);
    }
    let (first, last) = (T::simplest_in(lo, &mid)?, T::simplest_in(&mid, hi)?);
    let (near_a, near_b) = if increasing {
        (first, last)
    } else {
        (last, first)
    };
    Some(vec![point(&near_a)?, point(&mid)?, point(&near_b)?])
}

/// The ends of arrangement edge `e` and two integer points of its line
/// (of its first ray, or of its map edge).
pub fn arrangement_edge_line(
    arr: &Arrangement,
    e: usize,
) -> (&RatPoint, &RatPoint, (Point, Point)) {
    let (a, b) = (
        arr.point(arr.half_edge(2 * e).origin),
        arr.point(arr.dest(2 * e)),
    );
    let line = match arr.edge_rays(e).first() {
        Some(&r) => (arr.rays()[r].line.a(), arr.rays()[r].line.b()),
        None => {
            // A map edge: its own end points.
            let Support::MapEdge(i) = arr.edge_support(e) else {
                unreachable!("an edge is on a map edge or covered by rays")
            };
            let v = arr.map().vertices();
            (v[i], v[(i + 1) % v.len()])
        }
    };
    (a, b, line)
}

/// Whether vertex `i` of V_p is reflex in V_p (a clockwise turn).
pub fn reflex_in_vp(vp: &VisibilityPolygon, i: usize) -> bool {
    let v = vp.vertices();
    let n = v.len();
    orientation_rat(
        &v[(i + n - 1) % n].point,
        &v[i].point,
        &v[(i + 1) % n].point,
    ) == Orientation::Clockwise
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn viewpoints_are_interior_distinct_and_mixed() {
        let map = wai_gen::random("special-orthogonal", 16, 3).unwrap();
        let views = viewpoints(&map, 12);
        assert_eq!(views.len(), 12);
        for (k, p) in views.iter().enumerate() {
            assert_eq!(map.locate(p), Containment::Inside);
            assert!(!views[..k].contains(p));
        }
        // The grid kind contributes (denominator a multiple of 56's factor 7).
        assert!(views.iter().any(|p| Integer::from(p.hw() % 7u32) == 0));
        // And not everything is a midpoint of two integer points.
        assert!(views.iter().any(|p| *p.hw() > 2));
    }

    #[test]
    fn simplest_between_is_inside_and_simplest() {
        let q = |n: i64, d: i64| Rational::from((n, d));
        for (a, b) in [
            (q(0, 1), q(1, 1)),
            (q(-1, 1), q(0, 1)),
            (q(-5, 3), q(-4, 3)),
            (q(1, 1000), q(1, 999)),
            (q(355, 113), q(22, 7)),
            (q(7, 1), q(9, 1)),
            (q(-9, 1), q(-7, 1)),
        ] {
            let s = simplest_between(&a, &b);
            assert!(a < s && s < b, "{a} {s} {b}");
            // No smaller denominator fits: brute force.
            for d in 1..s.denom().to_u32().unwrap() {
                let d = Rational::from(d);
                let lo = Rational::from(&a * &d).floor() + 1u32;
                assert!(Rational::from(&lo / &d) >= b, "{a} {b}: {lo}/{d} fits");
            }
        }
    }

    /// The `i128` fractions and GMP give the same points wherever the
    /// former answer, and decline past their range.
    #[test]
    fn fractions_and_gmp_agree() {
        let r = |x: i128, y: i128, w: i128| RatPoint::from_i128(x, y, w).unwrap();
        let mut small = 0;
        for scale in [1i128, 1 << 20, 1 << 40, 1 << 60] {
            let ring = [
                r(0, 0, 1),
                r(1000 * scale, scale, 1000),
                r(scale, 1000 * scale, 999),
            ];
            let big = interior_points_in::<Rational>(&ring, true).unwrap();
            if let Some(f) = interior_points_in::<Frac>(&ring, true) {
                assert_eq!(f, big);
                small += 1;
            }
            let (a, b) = (r(3 * scale, scale, 7), r(6 * scale, 2 * scale, 5));
            let on = (Point::new(0, 0), Point::new(3, 1));
            let big = segment_points_in::<Rational>(&a, &b, on, true).unwrap();
            if let Some(f) = segment_points_in::<Frac>(&a, &b, on, true) {
                assert_eq!(f, big);
            }
        }
        assert!(small >= 2, "{small}");
        let q = |n: i128, d: i128| (Frac::new(n, d).unwrap(), Rational::from((n, d)));
        for ((fa, ra), (fb, rb)) in [
            (q(1, 3), q(2, 3)),
            (q(-7, 2), q(5, 1)),
            (q(3, 10), q(1, 3)),
            (q(-5, 3), q(-4, 3)),
            (q(1, 1000), q(1, 999)),
            (q(355, 113), q(22, 7)),
            (q(-9, 1), q(-7, 1)),
        ] {
            let f = simplest(&fa, &fb).unwrap();
            let g = simplest_between(&ra, &rb);
            assert_eq!(Rational::from((f.n, f.d)), g);
            assert_eq!(simplest_frac(&fa, &fb), Some(f));
        }
    }

    /// The reduction-free [`simplest_frac`] and [`Frac::line_y`] against
    /// GMP on many pseudo-random fractions, small and near the `i128`
    /// range (where they may decline, never differ).
    #[test]
    fn shortcuts_agree_with_gmp() {
        let mut state = 0x9e37_79b9_7f4a_7c15_u64;
        let mut next = |bits: u32| -> i128 {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            let v = i128::from(state >> 1) ^ (i128::from(state) << 40);
            v % (1i128 << bits)
        };
        let mut answered = 0;
        for round in 0..20_000 {
            let bits = [8, 20, 40, 62, 100][round % 5];
            let (n1, d1) = (next(bits), next(bits).abs() + 1);
            let (n2, d2) = (next(bits), next(bits).abs() + 1);
            let (a, b) = (Rational::from((n1, d1)), Rational::from((n2, d2)));
            if a != b {
                let (lo, hi) = if a < b { (a, b) } else { (b, a) };
                let want = simplest::<Rational>(&lo, &hi).unwrap();
                let (fl, fh) = (
                    Frac::new(lo.numer().to_i128().unwrap(), lo.denom().to_i128().unwrap()),
                    Frac::new(hi.numer().to_i128().unwrap(), hi.denom().to_i128().unwrap()),
                );
                if let Some(f) = simplest_frac(&fl.unwrap(), &fh.unwrap()) {
                    assert_eq!(Rational::from((f.n, f.d)), want);
                    answered += 1;
                }
            }
            let p = |x: i128, y: i128, w: i128| RatPoint::from_i128(x, y, w.abs() + 1).unwrap();
            let (pa, pb) = (
                p(next(bits), next(bits), next(bits)),
                p(next(bits), next(bits), next(bits)),
            );
            let (ca, cb) = (coords(&pa), coords(&pb));
            if ca.0 == cb.0 {
                continue;
            }
            let x = Frac::new(next(bits), next(bits).abs() + 1).unwrap();
            let rx = Rational::from((x.n, x.d));
            let want = Rational::from(&cb.1 - &ca.1) * (rx - &ca.0) / Rational::from(&cb.0 - &ca.0)
                + &ca.1;
            if let Some(y) = Frac::line_y(&pa, &pb, &x) {
                assert_eq!(Rational::from((y.n, y.d)), want);
                answered += 1;
            }
        }
        assert!(answered > 10_000, "{answered}");
    }

    #[test]
    fn simple_points_lie_inside() {
        let r = |x: i64, y: i64, w: i64| {
            RatPoint::new(Integer::from(x), Integer::from(y), Integer::from(w)).unwrap()
        };
        // A thin triangle.
        let ring = [r(0, 0, 1), r(1000, 1, 1000), r(1, 1000, 999)];
        let [p, q] = simple_interior_points(&ring).unwrap();
        for x in [&p, &q] {
            let inside = (0..3).all(|i| {
                orientation_rat(&ring[i], &ring[(i + 1) % 3], x) == Orientation::CounterClockwise
            });
            assert!(inside, "{x}");
        }
        assert_ne!(p, q);
        // A segment on the line through (0, 0) and (3, 1).
        let (a, b) = (r(3, 1, 7), r(6, 2, 5));
        let pts = simple_segment_points(&a, &b, (Point::new(0, 0), Point::new(3, 1)));
        let line = (
            RatPoint::from(Point::new(0, 0)),
            RatPoint::from(Point::new(3, 1)),
        );
        for x in &pts {
            assert_eq!(orientation_rat(&line.0, &line.1, x), Orientation::Collinear);
        }
        let xs: Vec<Rational> = pts.iter().map(|p| coords(p).0).collect();
        assert!(coords(&a).0 < xs[0] && xs[0] < xs[1] && xs[1] < xs[2] && xs[2] < coords(&b).0);
        // Vertical, from top to bottom.
        let pts = simple_segment_points(
            &r(2, 9, 1),
            &r(2, 1, 1),
            (Point::new(2, 0), Point::new(2, 5)),
        );
        let ys: Vec<Rational> = pts.iter().map(|p| coords(p).1).collect();
        assert!(ys[0] > ys[1] && ys[1] > ys[2], "{ys:?}");
        assert_eq!(pts[1], r(2, 2, 1));
    }

    #[test]
    fn closer_agrees_with_rational_distances() {
        let squared = |a: &RatPoint, b: &RatPoint| {
            let ((ax, ay), (bx, by)) = (coords(a), coords(b));
            let (dx, dy) = (ax - bx, ay - by);
            Rational::from(&dx * &dx) + Rational::from(&dy * &dy)
        };
        let r = |x: i128, y: i128, w: i128| RatPoint::from_i128(x, y, w).unwrap();
        let big = |x: i128, y: i128, w: i128| {
            let s = Integer::from(1) << 80u32;
            RatPoint::new(
                Integer::from(x) * &s,
                Integer::from(y) * &s,
                Integer::from(w) * &s + 1u32,
            )
            .unwrap()
        };
        let pts = [
            r(0, 0, 1),
            r(3, 4, 1),
            r(-5, 0, 1),
            r(7, 9, 3),
            r(1, 1, 1000),
            big(3, 4, 1),
            big(5, 0, 1),
            big(-1, 2, 7),
        ];
        for p in &pts {
            for a in &pts {
                for b in &pts {
                    assert_eq!(
                        closer(p, a, b),
                        squared(p, a) < squared(p, b),
                        "{p} {a} {b}"
                    );
                }
            }
        }
    }

    #[test]
    fn scrambled_is_a_permutation() {
        for len in [0, 1, 2, 5, 10, 36, 97] {
            let mut seen: Vec<usize> = scrambled(len).collect();
            seen.sort_unstable();
            assert_eq!(seen, (0..len).collect::<Vec<_>>(), "{len}");
        }
    }

    #[test]
    fn family_viewpoints_need_the_family_map() {
        let map = wai_gen::family("overlap-fan", &[1]).unwrap();
        assert_eq!(family_viewpoints(&map).len(), 3);
        let other = wai_gen::family("convex-niches", &[2]).unwrap();
        assert_eq!(family_viewpoints(&other).len(), 2);
        let plain = wai_gen::random("random-orthogonal", 10, 0).unwrap();
        assert!(family_viewpoints(&plain).is_empty());
    }
}
