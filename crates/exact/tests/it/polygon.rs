//! `locate` and `locate_rat`: data-driven cases (inside, on an edge, on a
//! vertex, outside; rays through vertices and along collinear horizontal
//! edges of orthogonal polygons; rational points), each checked against
//! `locate` on the polygon scaled by the point's denominator and under the
//! symmetries of the plane and of the ring.

use crate::common::{config, pt, rat, ring};
use proptest::prelude::*;
use rug::Integer;
use wai_exact::{locate, locate_rat, signed_area_twice, Containment, Point};

use Containment::{Inside, OnBoundary as On, Outside};

/// A point as `(x, y, w)`, meaning `(x / w, y / w)` with `w > 0`.
type Q = (i128, i128, i128);

/// The integer maps of the plane used as laws, on points and on rational
/// points `(x, y, w)`.
/// A named map of the plane, on points and on rational points.
type PlaneMap = (&'static str, fn(Point) -> Point, fn(Q) -> Q);

const MAPS: [PlaneMap; 5] = [
    ("identity", |p| p, |q| q),
    ("rotate", |p| pt(-p.y, p.x), |(x, y, w)| (-y, x, w)),
    ("reflect", |p| pt(p.x, -p.y), |(x, y, w)| (x, -y, w)),
    (
        "translate",
        |p| pt(p.x + 7, p.y - 3),
        |(x, y, w)| (x + 7 * w, y - 3 * w, w),
    ),
    (
        "far",
        |p| pt(p.x + (1 << 80), p.y - (1 << 62)),
        |(x, y, w)| (x + (w << 80), y - (w << 62), w),
    ),
];

/// `locate_rat(ring, p) == expect`, where the same answer must come from
/// `locate` on the ring scaled by `w` at the integer point `(x, y)`, for
/// every start vertex, both orientations and every map of [`MAPS`].
fn check(vs: &[(i128, i128)], p: Q, expect: Containment) {
    let base = ring(vs);
    assert!(p.2 > 0, "w > 0");
    for (name, f, g) in MAPS {
        let mapped: Vec<Point> = base.iter().map(|&v| f(v)).collect();
        let (x, y, w) = g(p);
        for shift in 0..mapped.len() {
            let mut r = mapped.clone();
            r.rotate_left(shift);
            for reverse in [false, true] {
                if reverse {
                    r.reverse();
                }
                let what = format!("{name}, shift {shift}, reversed {reverse}: {vs:?} at {p:?}");
                assert_eq!(locate_rat(&r, &rat(x, y, w)), expect, "locate_rat, {what}");
                let scaled: Vec<Point> = r.iter().map(|v| pt(v.x * w, v.y * w)).collect();
                assert_eq!(
                    locate(&scaled, pt(x, y)),
                    expect,
                    "locate scaled by w, {what}"
                );
                if w == 1 {
                    assert_eq!(locate(&r, pt(x, y)), expect, "locate, {what}");
                }
            }
        }
    }
}

const SQUARE: &[(i128, i128)] = &[(0, 0), (4, 0), (4, 4), (0, 4)];
const DIAMOND: &[(i128, i128)] = &[(0, 2), (2, 0), (4, 2), (2, 4)];
/// A square with a vertex in the middle of each side (collinear vertices).
const SQUARE8: &[(i128, i128)] = &[
    (0, 0),
    (2, 0),
    (4, 0),
    (4, 2),
    (4, 4),
    (2, 4),
    (0, 4),
    (0, 2),
];
const L: &[(i128, i128)] = &[(0, 0), (4, 0), (4, 2), (2, 2), (2, 4), (0, 4)];
/// Four teeth of width 1 on a base of height 1: the tops of the teeth lie on
/// y = 3, the bottoms of the gaps on y = 1.
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
/// Reflex vertices (2, 2), (4, 2) and spikes (0, 4), (3, 4), (6, 4) at
/// equal heights.
const W: &[(i128, i128)] = &[(0, 0), (6, 0), (6, 4), (4, 2), (3, 4), (2, 2), (0, 4)];

#[test]
fn square() {
    check(SQUARE, (1, 1, 1), Inside);
    check(SQUARE, (2, 0, 1), On);
    check(SQUARE, (4, 4, 1), On);
    check(SQUARE, (0, 0, 1), On);
    check(SQUARE, (5, 2, 1), Outside);
    check(SQUARE, (-1, 4, 1), Outside);
    check(SQUARE, (-1, 0, 1), Outside);
    check(SQUARE, (1, 3, 2), Inside);
    check(SQUARE, (7, 3, 2), Inside);
    check(SQUARE, (9, 3, 2), Outside);
    check(SQUARE, (8, 3, 2), On);
    check(SQUARE, (3999, 1, 1000), Inside);
    check(SQUARE, (4001, 1, 1000), Outside);
    check(SQUARE, (1, -1, 1000), Outside);
}

#[test]
fn rays_through_vertices() {
    check(DIAMOND, (1, 2, 1), Inside); // through (4, 2)
    check(DIAMOND, (-1, 2, 1), Outside); // through (0, 2) and (4, 2)
    check(DIAMOND, (5, 2, 1), Outside);
    check(DIAMOND, (2, 0, 1), On);
    check(DIAMOND, (1, 1, 1), On);
    check(DIAMOND, (1, 3, 2), On); // (1/2, 3/2) on x + y = 2
    check(DIAMOND, (1, 4, 2), Inside); // (1/2, 2)
    check(DIAMOND, (1, 2, 2), Outside); // (1/2, 1)
    check(DIAMOND, (2, 9, 2), Outside); // (1, 9/2)
    check(SQUARE8, (1, 2, 1), Inside);
    check(SQUARE8, (-1, 2, 1), Outside);
    check(SQUARE8, (-1, 0, 1), Outside);
    check(SQUARE8, (2, 0, 1), On);
    check(SQUARE8, (3, 0, 1), On);
    check(SQUARE8, (1, 4, 1), On);
    check(SQUARE8, (1, 8, 2), On);
    check(W, (1, 2, 1), Inside); // through the reflex vertices (2, 2), (4, 2)
    check(W, (3, 2, 1), Inside);
    check(W, (5, 2, 1), Inside);
    check(W, (2, 2, 1), On);
    check(W, (-1, 2, 1), Outside);
    check(W, (-1, 4, 1), Outside); // through the spikes (0, 4), (3, 4), (6, 4)
    check(W, (3, 4, 1), On);
    check(W, (6, 9, 2), Outside); // (3, 9/2)
    check(W, (3, 3, 1), Inside);
    check(W, (2, 3, 1), Outside);
    check(W, (7, 6, 2), On); // (7/2, 3) on the edge from (4, 2) to (3, 4)
    check(W, (1, 6, 2), Inside);
}

#[test]
fn orthogonal_polygons_with_collinear_edges() {
    check(L, (1, 3, 1), Inside);
    check(L, (3, 3, 1), Outside);
    check(L, (3, 2, 1), On);
    check(L, (-1, 2, 1), Outside); // along the edge from (4, 2) to (2, 2)
    check(L, (1, 2, 1), Inside); // through (2, 2), then along y = 2
    check(L, (1, 3, 2), Inside); // (1/2, 3/2)
    check(L, (5, 5, 2), Outside); // (5/2, 5/2)
    check(COMB, (-1, 3, 1), Outside); // along the four tops
    check(COMB, (-1, 1, 1), Outside); // along the three gap bottoms
    check(COMB, (-1, 0, 1), Outside); // along the bottom edge
    check(COMB, (1, 6, 2), On); // (1/2, 3)
    check(COMB, (3, 6, 2), Outside); // (3/2, 3), between two teeth
    check(COMB, (1, 2, 2), Inside); // (1/2, 1): ray along the gap bottoms
    check(COMB, (3, 2, 2), On); // (3/2, 1) on a gap bottom
    check(COMB, (3, 1, 2), Inside); // (3/2, 1/2)
    check(COMB, (3, 4, 2), Outside); // (3/2, 2)
    check(COMB, (5, 4, 2), Inside); // (5/2, 2)
    check(COMB, (7, 1, 1), On);
    check(COMB, (8, 1, 1), Outside);
    check(COMB, (1, 0, 2), On); // (1/2, 0)
    check(COMB, (13, 6, 2), On); // (13/2, 3)
    check(COMB, (13, 5, 2), Inside);
    check(COMB, (13, 7, 2), Outside);
}

#[test]
fn rings_are_counter_clockwise() {
    for vs in [SQUARE, DIAMOND, SQUARE8, L, COMB, W] {
        assert!(signed_area_twice(&ring(vs)) > Integer::new(), "{vs:?}");
    }
    // The signed area flips with the orientation.
    let mut r = ring(L);
    r.reverse();
    assert_eq!(signed_area_twice(&r), -24);
}

/// A rational point inside the bounding box of `vs`, widened by one, with a
/// small denominator so that it often lies on the lines of the edges.
fn point_near(vs: &'static [(i128, i128)]) -> impl Strategy<Value = Q> {
    let (x0, x1) = (
        vs.iter().map(|v| v.0).min().unwrap() - 1,
        vs.iter().map(|v| v.0).max().unwrap() + 1,
    );
    let (y0, y1) = (
        vs.iter().map(|v| v.1).min().unwrap() - 1,
        vs.iter().map(|v| v.1).max().unwrap() + 1,
    );
    (1i128..=4).prop_flat_map(move |w| (x0 * w..=x1 * w, y0 * w..=y1 * w, Just(w)))
}

fn any_polygon() -> impl Strategy<Value = &'static [(i128, i128)]> {
    prop::sample::select(vec![SQUARE, DIAMOND, SQUARE8, L, COMB, W])
}

proptest! {
    #![proptest_config(config(600))]

    /// Whatever the answer, it is the same for `locate` on the scaled ring
    /// and under every law of `check`.
    #[test]
    fn locate_rat_agrees_with_scaled_locate(
        (vs, p) in any_polygon().prop_flat_map(|vs| (Just(vs), point_near(vs)))
    ) {
        let expect = locate(&ring(vs).iter().map(|v| pt(v.x * p.2, v.y * p.2)).collect::<Vec<_>>(), pt(p.0, p.1));
        check(vs, p, expect);
    }
}

/// Exhaustive on the half-integer grid: every point of the comb's bounding
/// box, and each answer is reached (the test is not vacuous).
#[test]
fn comb_half_grid_counts() {
    let r = ring(COMB);
    let mut counts = [0usize; 3];
    for x in -2..=16 {
        for y in -2..=8 {
            let got = locate_rat(&r, &rat(x, y, 2));
            let scaled: Vec<Point> = r.iter().map(|v| pt(2 * v.x, 2 * v.y)).collect();
            assert_eq!(got, locate(&scaled, pt(x, y)), "({x}/2, {y}/2)");
            counts[got as usize] += 1;
        }
    }
    assert!(counts.iter().all(|&c| c > 0), "{counts:?}");
    assert_eq!(counts.iter().sum::<usize>(), 19 * 11);
}
