//! Random simple polygons by two independent methods: star-shaped rings by
//! an exact angular sort, and 2-opt untangling of a random tour.
//!
//! No decision reads a float: angles are compared with [`orientation`]
//! around the centre, crossings are classified by
//! [`wai_exact::classify_segments`].

use crate::ring::make_ccw;
use rand::Rng;
use rand_chacha::ChaCha8Rng;
use std::cmp::Ordering;
use wai_exact::{classify_segments, orientation, Orientation, Point, Segment, SegmentIntersection};

const ORIGIN: Point = Point::new(0, 0);

/// The exact angular order of vectors around the origin, starting at the
/// positive x-axis and turning counter-clockwise.
pub(crate) fn angular_cmp(a: Point, b: Point) -> Ordering {
    // Upper half-plane (angle in [0, π)) first.
    let half = |p: Point| u8::from(!(p.y > 0 || (p.y == 0 && p.x > 0)));
    half(a)
        .cmp(&half(b))
        .then_with(|| match orientation(ORIGIN, a, b) {
            Orientation::CounterClockwise => Ordering::Less,
            Orientation::Clockwise => Ordering::Greater,
            Orientation::Collinear => Ordering::Equal,
        })
}

/// A random star-shaped polygon with exactly `n ≥ 3` vertices with
/// coordinates in `[-range, range]`, its kernel containing the origin in its
/// interior.
///
/// Points are drawn uniformly from the lattice box, no two on one ray from
/// the origin, sorted by [`angular_cmp`]; a draw is kept when every
/// consecutive pair turns by less than 180° around the origin (so the
/// origin lies strictly left of every edge) and no three consecutive
/// vertices are collinear. `range` must leave room for `n` rays
/// (`range ≥ n` suffices; callers use more).
pub(crate) fn star_ring(n: usize, range: i128, rng: &mut ChaCha8Rng) -> Vec<Point> {
    assert!(n >= 3 && range >= 2);
    loop {
        let mut pts: Vec<Point> = Vec::with_capacity(n);
        while pts.len() < n {
            let p = Point::new(
                rng.random_range(-range..=range),
                rng.random_range(-range..=range),
            );
            if p == ORIGIN || pts.iter().any(|&q| angular_cmp(p, q) == Ordering::Equal) {
                continue;
            }
            pts.push(p);
        }
        pts.sort_by(|&a, &b| angular_cmp(a, b));
        let ok = (0..n).all(|i| {
            let (a, b, c) = (pts[i], pts[(i + 1) % n], pts[(i + 2) % n]);
            orientation(ORIGIN, a, b) == Orientation::CounterClockwise
                && orientation(a, b, c) != Orientation::Collinear
        });
        if ok {
            return pts;
        }
    }
}

/// `n` distinct random lattice points of `[0, range]²`, no three collinear.
fn general_position_points(n: usize, range: i128, rng: &mut ChaCha8Rng) -> Vec<Point> {
    let mut pts: Vec<Point> = Vec::with_capacity(n);
    while pts.len() < n {
        let p = Point::new(rng.random_range(0..=range), rng.random_range(0..=range));
        let bad = pts.iter().enumerate().any(|(i, &a)| {
            a == p
                || pts[i + 1..]
                    .iter()
                    .any(|&b| orientation(a, b, p) == Orientation::Collinear)
        });
        if !bad {
            pts.push(p);
        }
    }
    pts
}

/// A random simple polygon with exactly `n ≥ 3` vertices in `[0, range]²`
/// by 2-opt untangling: random points in general position (no three
/// collinear) in random order; while two edges cross, reverse the path
/// between them. Every move strictly shortens the tour (the triangle
/// inequality is strict for points in general position), so the loop ends,
/// with a simple polygon whose consecutive edges are never collinear.
pub(crate) fn two_opt_ring(n: usize, range: i128, rng: &mut ChaCha8Rng) -> Vec<Point> {
    assert!(n >= 3);
    // The points come in random order already.
    let mut p = general_position_points(n, range, rng);
    let seg = |p: &[Point], i: usize| Segment::new(p[i], p[(i + 1) % n]).expect("distinct points");
    'untangle: loop {
        for i in 0..n {
            for j in i + 2..n {
                if i == 0 && j == n - 1 {
                    continue; // adjacent through the closing edge
                }
                if classify_segments(&seg(&p, i), &seg(&p, j)) != SegmentIntersection::None {
                    // General position: any meeting of non-adjacent edges is
                    // a proper crossing. Edges (i, i+1) and (j, j+1) become
                    // (i, j) and (i+1, j+1).
                    p[i + 1..=j].reverse();
                    continue 'untangle;
                }
            }
        }
        break;
    }
    make_ccw(p)
}
