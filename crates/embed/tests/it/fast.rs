//! The integer paths of the ring-against-ring computations agree with the
//! GMP rational ones: on every pair of embedded skeleton polygons of
//! decomposed maps (the rings the chapter 4 claims meet: shared vertices,
//! collinear edges, touching corners), on the maps' own rings against
//! translated and mirrored copies, and on each artificial edge against
//! the other polygon.

use crate::common::maps;
use rug::Rational;
use wai_cells::Decomposition;
use wai_embed::intersection::{
    edges_meet, edges_meet_rational, pieces_inside, pieces_inside_rational, FAST_BITS,
};
use wai_embed::{interiors_overlap, interiors_overlap_rational, Embedder, Intersection};
use wai_exact::QPoint;
use wai_visibility::VisibilityIndex;

/// Both paths on one pair of rings, and each edge of each against the
/// other.
fn agree(p: &[QPoint], q: &[QPoint]) {
    let (x, y) = (Intersection::of(p, q), Intersection::of_rational(p, q));
    assert_eq!(x.cycles, y.cycles, "{p:?} ∩ {q:?}");
    assert_eq!(x.components(), y.components());
    assert_eq!(interiors_overlap(p, q), interiors_overlap_rational(p, q));
    for i in 0..p.len() {
        for j in 0..q.len() {
            let e = (&p[i], &p[(i + 1) % p.len()]);
            let f = (&q[j], &q[(j + 1) % q.len()]);
            assert_eq!(edges_meet(e, f), edges_meet_rational(e, f), "{e:?} {f:?}");
        }
    }
    for (r, s) in [(p, q), (q, p)] {
        for i in 0..r.len() {
            let (a, b) = (&r[i], &r[(i + 1) % r.len()]);
            assert_eq!(
                pieces_inside(a, b, s),
                pieces_inside_rational(a, b, s),
                "{a}–{b} in {s:?}"
            );
        }
    }
}

fn ring(m: &wai_map::Map, vertices: &[usize]) -> Vec<QPoint> {
    vertices
        .iter()
        .map(|&v| QPoint::from(m.vertices()[v]))
        .collect()
}

#[test]
fn integer_and_rational_paths_agree_on_skeleton_polygons() {
    let mut pairs = 0;
    for m in maps(12, 2) {
        let d = Decomposition::new(&m);
        let index = VisibilityIndex::new(&m);
        let embedder = Embedder::new(&index);
        let rings: Vec<Vec<QPoint>> = d
            .skeletons()
            .iter()
            .flat_map(|key| embedder.embeddings(key))
            .map(|h| ring(&m, &h.vertices))
            .collect();
        // Every pair would be slow in GMP; a stride keeps pairs of one
        // skeleton and of different ones.
        for (i, p) in rings.iter().enumerate() {
            for q in rings.iter().skip(i).step_by(7) {
                agree(p, q);
                pairs += 1;
            }
        }
    }
    assert!(pairs > 1000, "{pairs} pairs");
}

#[test]
fn integer_and_rational_paths_agree_on_moved_maps() {
    let shift = |r: &[QPoint], dx: i64, dy: i64| -> Vec<QPoint> {
        r.iter()
            .map(|p| QPoint::new(Rational::from(&p.x + dx), Rational::from(&p.y + dy)))
            .collect()
    };
    for m in maps(10, 2) {
        let r: Vec<QPoint> = m.vertices().iter().map(|&p| QPoint::from(p)).collect();
        for (dx, dy) in [(0, 0), (1, 0), (0, 2), (3, -1), (-2, -2)] {
            agree(&r, &shift(&r, dx, dy));
        }
    }
}

#[test]
fn rings_past_the_bound_take_the_rational_path() {
    // A square at the bound: the integer path declines it, and the
    // results are the rational ones.
    let big = 1i64 << FAST_BITS;
    let pt = |x: i64, y: i64| QPoint::new(Rational::from(x), Rational::from(y));
    let p = vec![pt(0, 0), pt(big, 0), pt(big, big), pt(0, big)];
    let q = vec![pt(1, 1), pt(3, 1), pt(3, 3), pt(1, 3)];
    agree(&p, &q);
    assert_eq!(Intersection::of(&p, &q).components(), 1);
    // Rational vertices too.
    let half = vec![
        QPoint::new(Rational::from((1, 2)), Rational::new()),
        pt(2, 0),
        pt(2, 2),
    ];
    agree(&half, &q);
}

#[test]
fn open_hulls_meet_agrees_with_the_pieces() {
    use wai_embed::piece::{open_hulls_meet, Piece};
    use wai_exact::Point;
    // Small coordinates on a 5 × 5 grid: many shared points, collinear
    // sets and touching hulls.
    let mut state = 0x2545_f491_4f6c_dd1du64;
    let mut next = |m: u64| {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state % m) as i128
    };
    let piece = |s: &[Point]| -> Option<Piece> {
        let h = wai_exact::convex_hull(s.iter().map(|&p| QPoint::from(p)).collect());
        match h.len() {
            0 | 1 => None,
            2 => Some(Piece::Segment(h[0].clone(), h[1].clone())),
            _ => Some(Piece::Polygon(h)),
        }
    };
    let mut checked = 0;
    for _ in 0..4000 {
        let mut set =
            |k: usize| -> Vec<Point> { (0..k).map(|_| Point::new(next(5), next(5))).collect() };
        let (p, q) = (set(2 + (checked % 3)), set(2 + (checked / 3 % 3)));
        let (Some(a), Some(b)) = (piece(&p), piece(&q)) else {
            continue;
        };
        assert_eq!(open_hulls_meet(&p, &q), Some(a.meets(&b)), "{p:?} {q:?}");
        checked += 1;
    }
    assert!(checked > 2000, "{checked}");
}
