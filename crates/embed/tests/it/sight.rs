//! What a map vertex sees of a map edge, on hand-drawn maps.

use rug::Rational;
use wai_embed::EdgeSight;
use wai_exact::Point;
use wai_map::Map;
use wai_visibility::VisibilityIndex;

fn map(pts: &[(i128, i128)]) -> Map {
    Map::from_ring(pts.iter().map(|&(x, y)| Point::new(x, y)).collect())
        .unwrap()
        .0
}

fn sight(m: &Map, y: usize, e: usize) -> EdgeSight {
    EdgeSight::of(m, &VisibilityIndex::new(m).vertex_view(y), y, e)
}

fn q(a: i64, b: i64) -> Rational {
    Rational::from((a, b))
}

/// The L room; vertex 3 = (2, 2) is reflex.
fn l_room() -> Map {
    map(&[(0, 0), (4, 0), (4, 2), (2, 2), (2, 4), (0, 4)])
}

#[test]
fn a_corner_sees_the_opposite_walls_whole_but_not_its_own() {
    let m = l_room();
    // (0, 0) sees the top wall 4 → 5 ((2, 4) to (0, 4)) but for its far
    // end (0, 4): the segment to it runs along the wall 5 → 0.
    let s = sight(&m, 0, 4);
    for t in [q(0, 1), q(1, 2), q(99, 100)] {
        assert!(s.contains(&t), "{t}");
    }
    assert!(!s.contains(&q(1, 1)));
    // Of its own edge 0 → 1 it sees only itself.
    let own = sight(&m, 0, 0);
    assert!(own.contains(&q(0, 1)));
    assert!(!own.contains(&q(1, 2)) && !own.contains(&q(1, 1)));
}

#[test]
fn the_reflex_corner_blocks_part_of_an_edge() {
    let m = l_room();
    // From (4, 0) (vertex 1), the wall 4 → 5 from (2, 4) to (0, 4): the
    // line from (4, 0) through the reflex vertex (2, 2) meets it at (0, 4),
    // its far end, so nothing of it is seen but... the segment to (0, 4)
    // grazes (2, 2): blocked. The wall is hidden whole.
    let s = sight(&m, 1, 4);
    assert!(s.is_empty(), "{s:?}");
    // From (4, 2) (vertex 2), the wall 5 → 0 from (0, 4) to (0, 0): the
    // line through (2, 2) meets x = 0 at y = 2, halfway: the lower half is
    // seen (open at y = 2), and the end (0, 0).
    let s = sight(&m, 2, 5);
    assert!(s.contains(&q(3, 4)) && s.contains(&q(1, 1)));
    assert!(
        !s.contains(&q(1, 2)),
        "the point on the grazing line is blocked"
    );
    assert!(!s.contains(&q(1, 4)) && !s.contains(&q(0, 1)));
}

#[test]
fn meets_needs_a_common_point() {
    let m = l_room();
    // Vertices 0 and 2 both see the lower half of the wall 5 → 0.
    assert!(sight(&m, 0, 5).meets(&sight(&m, 2, 5)));
    // Vertex 1 sees nothing of the wall 4 → 5; nobody meets it there.
    assert!(!sight(&m, 1, 4).meets(&sight(&m, 0, 4)));
}

/// Against the brute-force `wai_exact::sees` (an independent O(n) test of
/// sec. 2.2): on random maps of every kind and the families, for every map
/// vertex and every map edge, the positions where the sight changes, the
/// midpoints between them and a grid of 16 positions are seen exactly when
/// `sees` says so.
#[test]
fn agrees_with_sees_on_every_vertex_and_edge() {
    use wai_exact::{sees, RatPoint, Sight};
    let maps = crate::common::maps(16, 2);
    let mut examined = 0usize;
    for m in &maps {
        let v = m.vertices();
        let n = v.len();
        let index = VisibilityIndex::new(m);
        for y in 0..n {
            let view = index.vertex_view(y);
            for e in 0..n {
                let s = EdgeSight::of(m, &view, y, e);
                let (a, b) = (v[e], v[(e + 1) % n]);
                let point = |t: &Rational| {
                    let (num, den) = (t.numer().clone(), t.denom().clone());
                    let x = rug::Integer::from(a.x) * &den + (rug::Integer::from(b.x) - a.x) * &num;
                    let yy =
                        rug::Integer::from(a.y) * &den + (rug::Integer::from(b.y) - a.y) * &num;
                    RatPoint::new(x, yy, den).unwrap()
                };
                let mut ts: Vec<Rational> = (0..=16).map(|i| q(i, 16)).collect();
                ts.extend(s.breakpoints());
                ts.sort();
                ts.dedup();
                let mids: Vec<Rational> =
                    ts.windows(2).map(|w| (w[0].clone() + &w[1]) / 2).collect();
                ts.extend(mids);
                for t in &ts {
                    let want = sees(v, &RatPoint::from(v[y]), &point(t)) == Sight::Visible;
                    assert_eq!(
                        s.contains(t),
                        want,
                        "{:?}: vertex {y}, edge {e}, t = {t}",
                        m.name()
                    );
                    examined += 1;
                }
            }
        }
    }
    assert!(examined > 100_000, "examined {examined}");
}
