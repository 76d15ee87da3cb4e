//! `sees` (thesis sec. 2.2: the closed segment meets the boundary at most in
//! its endpoints; grazing a vertex blocks): data-driven cases, laws, and a
//! differential test against a naive reference written here.
//!
//! The naive reference scales the polygon and both points by twice the
//! common denominator, so that the points and their midpoint are integer,
//! and asks `classify_segments` about the segment against every edge: any
//! common point other than the two endpoints blocks.

use crate::common::{config, pt, ring};
use proptest::prelude::*;
use rug::Integer;
use std::mem::discriminant;
use wai_exact::{
    classify_segments, convex_hull, locate, sees, Containment, Point, QPoint, RatPoint, Segment,
    SegmentIntersection as X, Sight,
};

use Sight::{EndpointOutside, Exterior, Visible};

/// A point as `(x, y, w)`, meaning `(x / w, y / w)`, `w > 0`.
type Q = (i128, i128, i128);

fn rq(p: Q) -> RatPoint {
    crate::common::rat(p.0, p.1, p.2)
}

fn blocked(edge: usize) -> Sight {
    Sight::Blocked { edge }
}

fn int(v: &Integer) -> i128 {
    v.to_i128().expect("small test coordinates")
}

/// The naive reference. With `grazing_blocks = false` it is a planted
/// mutant that lets a sightline pass through a polygon vertex.
fn naive(ring: &[Point], p: &RatPoint, q: &RatPoint, grazing_blocks: bool) -> Sight {
    let l = int(&(Integer::from(p.hw().lcm_ref(q.hw())) * 2u32));
    let up = |r: &RatPoint| {
        let k = l / int(r.hw());
        pt(int(r.hx()) * k, int(r.hy()) * k)
    };
    let (pp, qq) = (up(p), up(q));
    let scaled: Vec<Point> = ring.iter().map(|v| pt(v.x * l, v.y * l)).collect();
    let (lp, lq) = (locate(&scaled, pp), locate(&scaled, qq));
    if lp == Containment::Outside || lq == Containment::Outside {
        return EndpointOutside;
    }
    let Some(pq) = Segment::new(pp, qq) else {
        return Visible;
    };
    for i in 0..scaled.len() {
        let Some(e) = Segment::new(scaled[i], scaled[(i + 1) % scaled.len()]) else {
            continue;
        };
        match classify_segments(&pq, &e) {
            X::None => {}
            X::Touching { at } if at == pp || at == qq => {}
            X::Touching { at } if !grazing_blocks && (at == e.a() || at == e.b()) => {}
            _ => return blocked(i),
        }
    }
    if lp == Containment::Inside || lq == Containment::Inside {
        return Visible;
    }
    let mid = pt((pp.x + qq.x) / 2, (pp.y + qq.y) / 2);
    if locate(&scaled, mid) == Containment::Inside {
        Visible
    } else {
        Exterior
    }
}

/// The maps of the plane under which the answer, edge index included, must
/// not change (they keep the ring order).
/// A named map of the plane, on points and on rational points.
type PlaneMap = (&'static str, fn(Point) -> Point, fn(Q) -> Q);

const MAPS: [PlaneMap; 4] = [
    ("rotate", |p| pt(-p.y, p.x), |(x, y, w)| (-y, x, w)),
    ("reflect", |p| pt(p.x, -p.y), |(x, y, w)| (x, -y, w)),
    (
        "translate",
        |p| pt(p.x - 5, p.y + 9),
        |(x, y, w)| (x - 5 * w, y + 9 * w, w),
    ),
    (
        "far",
        |p| pt(p.x + (1 << 70), p.y + (1 << 61)),
        |(x, y, w)| (x + (w << 70), y + (w << 61), w),
    ),
];

/// `sees(ring, p, q) == expect`; the naive reference agrees; the answer is
/// symmetric in `p` and `q`, invariant under [`MAPS`], and its kind is
/// invariant under a cyclic shift and a reversal of the ring.
fn check(vs: &[(i128, i128)], p: Q, q: Q, expect: Sight) {
    let r = ring(vs);
    let (a, b) = (rq(p), rq(q));
    let what = format!("{vs:?}: {a} to {b}");
    assert_eq!(sees(&r, &a, &b), expect, "sees, {what}");
    assert_eq!(naive(&r, &a, &b, true), expect, "naive, {what}");
    assert_eq!(sees(&r, &b, &a), expect, "symmetry, {what}");
    for (name, f, g) in MAPS {
        let m: Vec<Point> = r.iter().map(|&v| f(v)).collect();
        assert_eq!(sees(&m, &rq(g(p)), &rq(g(q))), expect, "{name}, {what}");
    }
    for shift in 0..r.len() {
        let mut s = r.clone();
        s.rotate_left(shift);
        for reverse in [false, true] {
            if reverse {
                s.reverse();
            }
            let got = sees(&s, &a, &b);
            assert_eq!(
                discriminant(&got),
                discriminant(&expect),
                "shift {shift}, reversed {reverse}, {what}"
            );
        }
    }
}

const L: &[(i128, i128)] = &[(0, 0), (4, 0), (4, 2), (2, 2), (2, 4), (0, 4)];
const U: &[(i128, i128)] = &[
    (0, 0),
    (6, 0),
    (6, 4),
    (4, 4),
    (4, 2),
    (2, 2),
    (2, 4),
    (0, 4),
];
const COMB: &[(i128, i128)] = &[
    (0, 0),
    (7, 0),
    (7, 3),
    (6, 3),
    (6, 1),
    (5, 1),
    (5, 3),
    (4, 3),
    (4, 1),
    (3, 1),
    (3, 3),
    (2, 3),
    (2, 1),
    (1, 1),
    (1, 3),
    (0, 3),
];
const W: &[(i128, i128)] = &[(0, 0), (6, 0), (6, 4), (4, 2), (3, 4), (2, 2), (0, 4)];

#[test]
fn l_shape() {
    check(L, (1, 3, 1), (1, 1, 1), Visible);
    check(L, (1, 3, 1), (3, 1, 1), blocked(2)); // grazes the reflex vertex (2, 2)
    check(L, (0, 4, 1), (4, 0, 1), blocked(2)); // grazes it from vertex to vertex
    check(L, (0, 0, 1), (4, 0, 1), blocked(0)); // along an edge
    check(L, (4, 2, 1), (2, 4, 1), Exterior);
    check(L, (1, 1, 1), (5, 5, 1), EndpointOutside);
    check(L, (3, 3, 1), (1, 1, 1), EndpointOutside);
    // Viewpoints on the boundary.
    check(L, (0, 1, 1), (3, 1, 1), Visible);
    check(L, (0, 1, 1), (4, 1, 1), Visible);
    check(L, (2, 3, 1), (0, 0, 1), Visible);
    check(L, (0, 0, 1), (4, 2, 1), Visible);
    check(L, (0, 0, 1), (2, 2, 1), Visible);
    check(L, (0, 0, 1), (2, 4, 1), Visible);
    check(L, (0, 3, 2), (4, 3, 2), Visible); // (0, 3/2) to (2, 3/2)
    check(L, (0, 3, 2), (8, 3, 2), Visible); // (0, 3/2) to (4, 3/2)
                                             // Rational viewpoints.
    check(L, (1, 7, 2), (7, 1, 2), blocked(2)); // x + y = 4 through (2, 2)
    check(L, (1, 1, 2), (7, 3, 2), Visible);
    check(L, (1, 4, 2), (5, 4, 2), blocked(2)); // along y = 2 past (2, 2)
    check(L, (1, 1, 3), (5, 5, 3), Visible);
    check(L, (1, 7, 2), (5, 1, 3), Visible); // (1/2, 7/2) to (5/3, 1/3)
                                             // A point sees itself.
    check(L, (1, 1, 1), (1, 1, 1), Visible);
    check(L, (0, 0, 1), (0, 0, 1), Visible);
    check(L, (5, 5, 1), (5, 5, 1), EndpointOutside);
}

#[test]
fn u_shape() {
    check(U, (2, 4, 1), (4, 4, 1), Exterior); // the tips
    check(U, (2, 3, 1), (4, 3, 1), Exterior); // across the notch
    check(U, (1, 2, 1), (3, 2, 2), Visible); // collinear with an edge, apart from it
    check(U, (1, 2, 1), (2, 2, 1), Visible); // ends at the reflex vertex
    check(U, (1, 2, 1), (3, 2, 1), blocked(4)); // through (2, 2), then along the edge
    check(U, (1, 2, 1), (5, 2, 1), blocked(3));
    check(U, (1, 3, 1), (5, 3, 1), blocked(3));
    check(U, (1, 3, 1), (5, 1, 1), blocked(4));
    check(U, (1, 3, 1), (3, 1, 1), blocked(4)); // grazes (2, 2)
    check(U, (1, 1, 1), (5, 1, 1), Visible);
    check(U, (0, 2, 1), (6, 2, 1), blocked(3));
    check(U, (0, 1, 1), (6, 1, 1), Visible);
}

#[test]
fn comb() {
    check(COMB, (1, 5, 2), (1, 1, 2), Visible);
    check(COMB, (1, 5, 2), (13, 1, 2), blocked(4)); // across four teeth
    check(COMB, (1, 2, 2), (13, 2, 2), blocked(3)); // through (6, 1), along the gap bottoms
    check(COMB, (0, 1, 2), (14, 1, 2), Visible); // along the base
    check(COMB, (1, 3, 1), (2, 3, 1), Exterior); // tip to tip over a gap
    check(COMB, (1, 3, 1), (6, 3, 1), blocked(5));
    check(COMB, (1, 5, 2), (5, 5, 2), blocked(11));
    check(COMB, (1, 1, 2), (11, 5, 4), blocked(11)); // grazes the reflex (2, 1)
    check(COMB, (1, 1, 2), (22, 7, 8), Visible); // passes just below it
    check(COMB, (3, 5, 2), (3, 1, 2), EndpointOutside);
}

#[test]
fn w_shape() {
    check(W, (1, 2, 1), (5, 2, 1), blocked(2)); // through both reflex vertices
    check(W, (1, 1, 1), (5, 1, 1), Visible);
    check(W, (0, 4, 1), (6, 4, 1), blocked(3)); // through the spike (3, 4)
    check(W, (0, 4, 1), (3, 4, 1), Exterior);
    check(W, (1, 3, 1), (3, 3, 1), blocked(4)); // from the boundary, across an edge
    check(W, (1, 3, 1), (2, 3, 1), EndpointOutside);
    check(W, (1, 3, 1), (5, 6, 2), Exterior); // across the notch at y = 3
    check(W, (3, 3, 1), (3, 0, 1), Visible);
}

// ---------------------------------------------------------------------------
// Properties.

/// The convex hull of `ps`, counter-clockwise, without collinear vertices
/// (the crate's [`convex_hull`], on integer points).
fn hull(ps: Vec<Point>) -> Vec<Point> {
    convex_hull(ps.into_iter().map(QPoint::from).collect())
        .iter()
        .map(|q| q.to_point().expect("a hull vertex is an input point"))
        .collect()
}

/// A strictly positive combination of the vertices: an interior point of a
/// convex polygon with nonempty interior.
fn combination(vs: &[Point], ws: &[i128]) -> RatPoint {
    let (mut x, mut y, mut w) = (0, 0, 0);
    for (v, k) in vs.iter().zip(ws.iter().cycle()) {
        x += k * v.x;
        y += k * v.y;
        w += k;
    }
    crate::common::rat(x, y, w)
}

/// A rational point near the bounding box of `vs`, often a vertex or the
/// midpoint of an edge.
fn point_near(vs: &'static [(i128, i128)]) -> impl Strategy<Value = Q> {
    let (x0, x1) = (
        vs.iter().map(|v| v.0).min().unwrap() - 1,
        vs.iter().map(|v| v.0).max().unwrap() + 1,
    );
    let (y0, y1) = (
        vs.iter().map(|v| v.1).min().unwrap() - 1,
        vs.iter().map(|v| v.1).max().unwrap() + 1,
    );
    let n = vs.len();
    prop_oneof![
        3 => (1i128..=3).prop_flat_map(move |w| (x0 * w..=x1 * w, y0 * w..=y1 * w, Just(w))),
        1 => (0..n).prop_map(move |i| (vs[i].0, vs[i].1, 1)),
        1 => (0..n).prop_map(move |i| {
            let (a, b) = (vs[i], vs[(i + 1) % n]);
            (a.0 + b.0, a.1 + b.1, 2)
        }),
    ]
}

fn any_polygon() -> impl Strategy<Value = &'static [(i128, i128)]> {
    prop::sample::select(vec![L, U, COMB, W])
}

proptest! {
    #![proptest_config(config(2000))]

    /// In a convex polygon every two interior points see each other, and a
    /// vertex sees every interior point.
    #[test]
    fn convex_interior_points_see_each_other(
        ps in prop::collection::vec((-20i128..=20, -20i128..=20), 3..12),
        w1 in prop::collection::vec(1i128..=5, 1..6),
        w2 in prop::collection::vec(1i128..=5, 1..6),
        k in 0usize..12,
    ) {
        let h = hull(ps.into_iter().map(|(x, y)| pt(x, y)).collect());
        prop_assume!(h.len() >= 3);
        let (a, b) = (combination(&h, &w1), combination(&h, &w2));
        prop_assert_eq!(sees(&h, &a, &b), Visible);
        prop_assert_eq!(naive(&h, &a, &b, true), Visible);
        let v = RatPoint::from(h[k % h.len()]);
        prop_assert_eq!(sees(&h, &v, &a), Visible);
    }

    /// `sees` is symmetric and agrees with the naive reference, edge index
    /// included, on rational points of small polygons.
    #[test]
    fn symmetric_and_agrees_with_naive(
        (vs, p, q) in any_polygon().prop_flat_map(|vs| (Just(vs), point_near(vs), point_near(vs)))
    ) {
        let r = ring(vs);
        let (a, b) = (rq(p), rq(q));
        let got = sees(&r, &a, &b);
        prop_assert_eq!(got, sees(&r, &b, &a));
        prop_assert_eq!(got.is_visible(), sees(&r, &b, &a).is_visible());
        prop_assert_eq!(got, naive(&r, &a, &b, true));
    }
}

/// Every pair of points of the half-integer grid around `vs`: `sees` agrees
/// with the naive reference and is symmetric. Returns the count of each
/// answer (Visible, Blocked, Exterior, EndpointOutside) and the number of
/// pairs on which the grazing mutant disagrees.
fn grid_pairs(vs: &[(i128, i128)]) -> ([usize; 4], usize) {
    let r = ring(vs);
    let (x0, x1) = (
        vs.iter().map(|v| v.0).min().unwrap(),
        vs.iter().map(|v| v.0).max().unwrap(),
    );
    let (y0, y1) = (
        vs.iter().map(|v| v.1).min().unwrap(),
        vs.iter().map(|v| v.1).max().unwrap(),
    );
    let pts: Vec<RatPoint> = (2 * x0 - 1..=2 * x1 + 1)
        .flat_map(|x| (2 * y0 - 1..=2 * y1 + 1).map(move |y| crate::common::rat(x, y, 2)))
        .collect();
    let (mut counts, mut mutant_differs) = ([0usize; 4], 0);
    for (i, a) in pts.iter().enumerate() {
        for b in &pts[i..] {
            let got = sees(&r, a, b);
            assert_eq!(got, naive(&r, a, b, true), "{vs:?}: {a} to {b}");
            assert_eq!(got, sees(&r, b, a), "symmetry, {vs:?}: {a} to {b}");
            counts[match got {
                Visible => 0,
                Sight::Blocked { .. } => 1,
                Exterior => 2,
                EndpointOutside => 3,
            }] += 1;
            mutant_differs += usize::from(naive(&r, a, b, false) != got);
        }
    }
    (counts, mutant_differs)
}

/// Exhaustive on the half-integer grids of the L, the U, the W and the comb: every
/// answer occurs (the comparison is not vacuous), and the planted mutant
/// that lets a sightline graze a vertex is caught.
#[test]
fn half_grid_exhaustive() {
    for vs in [L, U, W, COMB] {
        let (counts, mutant_differs) = grid_pairs(vs);
        assert!(counts.iter().all(|&c| c > 0), "{vs:?}: {counts:?}");
        assert!(
            mutant_differs > 0,
            "{vs:?}: the grazing mutant went unnoticed"
        );
    }
}
