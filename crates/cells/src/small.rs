//! Exact `i64` paths for maps whose coordinates are all below
//! `2^SMALL_BITS` in magnitude, for the predicates that run once per
//! vertex and candidate ray (the rays) or per pair of rays (the
//! arrangement). Nothing here rounds: each bound is proven where it is
//! used, and maps beyond the bound take the general predicates of
//! `wai_exact` (the scaling law tests compare both paths).

use crate::rays::VisibilityRay;
use std::cmp::Ordering;
use wai_exact::{Orientation, Side, Vector};
use wai_map::Map;
use wai_visibility::OnMap;

/// The bound of the `i64` paths.
///
/// Implementation note: with `|c| < 2^30` every difference of coordinates
/// has `|d| < 2^31`, every product of two differences is below `2^62`, and
/// the sum or difference of two such products (a cross or dot product of
/// two differences) is below `2^63`, which an `i64` holds.
pub(crate) const SMALL_BITS: u32 = 30;

/// The map's vertex coordinates as `i64`s (all below `2^SMALL_BITS`), and
/// each vertex's successor along its ring (edge `k` runs from `k` to
/// `next[k]`; a map with holes has several rings).
pub(crate) struct SmallCoords(Vec<[i64; 2]>, Vec<u32>);

// The vector helpers below are the `i64` specialisation of
// `wai_exact::Vector` (whose `cross`/`dot` run in `i128`): on maps below
// `2^SMALL_BITS` these loops run once per vertex and candidate ray, and
// 64-bit products are several times cheaper than 128-bit ones. The tests
// at the end compare them with `wai_exact` at the bound.

/// `u − v`: below `2^31` for coordinates below `2^SMALL_BITS`.
#[inline]
fn sub(u: [i64; 2], v: [i64; 2]) -> [i64; 2] {
    [u[0] - v[0], u[1] - v[1]]
}

/// `u × v` for differences of coordinates: below `2^63`.
#[inline]
fn cross(u: [i64; 2], v: [i64; 2]) -> i64 {
    u[0] * v[1] - u[1] * v[0]
}

/// `u · v` for differences of coordinates: below `2^63`.
#[inline]
fn dot(u: [i64; 2], v: [i64; 2]) -> i64 {
    u[0] * v[0] + u[1] * v[1]
}

fn sign_side(x: i64) -> Side {
    match x.cmp(&0) {
        Ordering::Greater => Side::Left,
        Ordering::Less => Side::Right,
        Ordering::Equal => Side::On,
    }
}

impl SmallCoords {
    /// The coordinates of `map`'s vertices, if every one is below
    /// `2^SMALL_BITS`.
    pub(crate) fn of(map: &Map) -> Option<SmallCoords> {
        let v = map.vertices();
        let fits = |c: i128| c.unsigned_abs() < 1 << SMALL_BITS;
        v.iter().all(|p| fits(p.x) && fits(p.y)).then(|| {
            SmallCoords(
                v.iter().map(|p| [p.x as i64, p.y as i64]).collect(),
                (0..v.len()).map(|i| map.next(i) as u32).collect(),
            )
        })
    }

    /// The orientation of vertices `(a, b, c)`.
    #[inline]
    pub(crate) fn orientation(&self, a: usize, b: usize, c: usize) -> Orientation {
        let s = &self.0;
        match cross(sub(s[b], s[a]), sub(s[c], s[a])).cmp(&0) {
            Ordering::Greater => Orientation::CounterClockwise,
            Ordering::Less => Orientation::Clockwise,
            Ordering::Equal => Orientation::Collinear,
        }
    }

    /// `sides[k]`: the side of vertex `k` of the line directed from vertex
    /// `j` to vertex `a`, for every `k`.
    pub(crate) fn sides(&self, j: usize, a: usize, sides: &mut [Side]) {
        let s = &self.0;
        let (p, d) = (s[j], sub(s[a], s[j]));
        for (side, &c) in sides.iter_mut().zip(s) {
            *side = sign_side(cross(d, sub(c, p)));
        }
    }

    /// The order along the line directed from vertex `j` to vertex `a` of
    /// its meeting points with edges `k` and `b` (`Less`: edge `k`'s comes
    /// first), both crossing it (their ends strictly on opposite sides).
    ///
    /// Implementation note: the meeting with edge `k` (from `e`, direction
    /// `f`) is `v_j + t·d` with `t = cross(e − v_j, f) / cross(d, f)`, both
    /// below `2^63`; the fractions are compared by products below `2^126`
    /// in `i128`.
    pub(crate) fn compare_crossings(&self, (j, a): (usize, usize), k: usize, b: usize) -> Ordering {
        let s = &self.0;
        let (p, d) = (s[j], sub(s[a], s[j]));
        let t = |k: usize| {
            let (num, den) = self.crossing(p, d, k);
            (i128::from(num), i128::from(den))
        };
        let ((n1, e1), (n2, e2)) = (t(k), t(b));
        (n1 * e2).cmp(&(n2 * e1))
    }

    /// Where the line `p + t·d` meets the line of map edge `k` (from `e`,
    /// direction `f`): `t = cross(e − p, f) / cross(d, f)` as
    /// `(numerator, denominator)`, denominator positive, both below `2^63`
    /// for `p` a map vertex and `d` a difference of map vertices. The edge
    /// must not be parallel to `d`.
    fn crossing(&self, p: [i64; 2], d: [i64; 2], k: usize) -> (i64, i64) {
        let s = &self.0;
        let (e, f) = (s[k], sub(s[self.1[k] as usize], s[k]));
        let (num, den) = (cross(sub(e, p), f), cross(d, f));
        if den < 0 {
            (-num, -den)
        } else {
            (num, den)
        }
    }

    /// By map vertex, the sign of `d × (v − v_from)`: `Greater` left of the
    /// line through vertex `from` with direction `d`, a difference of
    /// coordinates or a divisor of one (below `2^31`).
    pub(crate) fn turns_from(&self, from: usize, d: Vector) -> Vec<Ordering> {
        let s = &self.0;
        let d = [
            i64::try_from(d.x).expect("a direction between small points"),
            i64::try_from(d.y).expect("a direction between small points"),
        ];
        s.iter()
            .map(|&c| cross(d, sub(c, s[from])).cmp(&0))
            .collect()
    }

    /// The map's edges as [`EdgeTurns`].
    pub(crate) fn edge_turns(&self) -> EdgeTurns {
        let s = &self.0;
        EdgeTurns(
            (0..s.len())
                .map(|i| {
                    let (a, d) = (s[i], sub(s[self.1[i] as usize], s[i]));
                    [d[0], d[1], cross(d, a)]
                })
                .collect(),
        )
    }

    /// Ray `r` as a [`Span`].
    pub(crate) fn span(&self, r: &VisibilityRay) -> Span {
        let s = &self.0;
        let a = s[r.anchor];
        let d = sub(a, s[r.from]);
        // The end a + (p/q)·d, q > 0.
        let (p, q) = match r.end.on_map {
            // On the line: the ratio of projections onto d.
            OnMap::Vertex(u) => (dot(sub(s[u], a), d), dot(d, d)),
            OnMap::Edge(k) => self.crossing(a, d, k),
        };
        Span { a, d, p, q }
    }
}

/// A visibility ray as the points `a + t·d`, `0 ≤ t ≤ p/q`: the anchor,
/// the direction from the vertex it emanates from, and the end's
/// parameter (`q > 0`), each part below `2^63`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Span {
    a: [i64; 2],
    d: [i64; 2],
    p: i64,
    q: i64,
}

impl Span {
    /// Whether this ray lies strictly on one side of the line of `other`
    /// (closed segments on different lines meet iff neither lies so).
    ///
    /// Implementation note: the side of `a + t·d` is the sign of
    /// `g(t) = cross(d', a − a') + t·cross(d', d)`, affine in t; the ray is
    /// apart iff `g(0)` and `q·g(p/q)` have one strict sign. `g(0)` and
    /// `cross(d', d)` are below `2^63` (differences of coordinates), so
    /// `q·g(p/q)`, a sum of two products below `2^126`, fits an `i128`.
    #[inline]
    pub(crate) fn apart_from(&self, other: &Span) -> bool {
        let g0 = cross(other.d, sub(self.a, other.a));
        let slope = cross(other.d, self.d);
        let g1 = i128::from(self.q) * i128::from(g0) + i128::from(self.p) * i128::from(slope);
        g0 != 0 && (g0 > 0) == (g1 > 0) && g1 != 0
    }
}

/// By map edge from `a` with direction `d`: `(d.x, d.y, d × a)`, the first
/// two below `2^31`, the last below `2^62` (a product of a difference and
/// a coordinate, each bound halved).
pub(crate) struct EdgeTurns(Vec<[i64; 3]>);

/// Rational points whose homogeneous coordinates are below this bound
/// take the `i128` path of [`EdgeTurns::left`].
pub(crate) const NARROW_BITS: u32 = 64;

impl EdgeTurns {
    /// Whether the point `q = (x/w, y/w)`, `w > 0`, lies strictly left of
    /// map edge `e`, for `|x|, |y|, |w| < 2^NARROW_BITS`.
    ///
    /// Implementation note: `w·((d × (q − a))) = d.x·y − d.y·x − w·(d × a)`;
    /// the first two products are below `2^95`, the last below `2^126`, so
    /// the sum is below `2^127` and fits an `i128`.
    #[inline]
    pub(crate) fn left(&self, e: usize, [x, y, w]: [i128; 3]) -> bool {
        let [dx, dy, c] = self.0[e];
        i128::from(dx) * y - i128::from(dy) * x - w * i128::from(c) > 0
    }
}

#[cfg(test)]
mod tests {
    use super::{cross, dot, sub, SmallCoords, SMALL_BITS};
    use proptest::prelude::*;
    use wai_exact::{orientation, Point, Vector};

    /// Coordinates at and below the bound: the extremes and uniform values.
    fn coord() -> impl Strategy<Value = i64> {
        let m = (1i64 << SMALL_BITS) - 1;
        prop_oneof![Just(m), Just(-m), Just(0), -m..=m, -20i64..=20]
    }

    fn point() -> impl Strategy<Value = [i64; 2]> {
        (coord(), coord()).prop_map(|(x, y)| [x, y])
    }

    fn vector(p: [i64; 2]) -> Vector {
        Vector::new(i128::from(p[0]), i128::from(p[1]))
    }

    proptest! {
        /// The `i64` helpers equal `wai_exact::Vector`'s products, and the
        /// `i64` orientation `wai_exact::orientation`, up to the bound.
        #[test]
        fn i64_paths_equal_wai_exact(a in point(), b in point(), c in point()) {
            let (u, v) = (sub(b, a), sub(c, a));
            let (bu, bv) = (vector(b) - vector(a), vector(c) - vector(a));
            prop_assert_eq!(i128::from(cross(u, v)), bu.cross(bv));
            prop_assert_eq!(i128::from(dot(u, v)), bu.dot(bv));
            let pt = |p: [i64; 2]| Point::new(i128::from(p[0]), i128::from(p[1]));
            // Three points, maybe collinear: no map, so built directly.
            let s = SmallCoords(vec![a, b, c], vec![1, 2, 0]);
            prop_assert_eq!(s.orientation(0, 1, 2), orientation(pt(a), pt(b), pt(c)));
            let turns = s.turns_from(0, bu);
            prop_assert_eq!(turns[2], bu.cross_sign(bv));
        }
    }
}
