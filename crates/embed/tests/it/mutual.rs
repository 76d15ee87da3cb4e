//! Mutual visibility of cells: the search over lines and the cuts and
//! sweeps from points agree with each other on cells of every dimension of
//! random, orthogonal and family maps, and with sampled sight lines: a
//! sampled pair of points that see each other is never missed.

use crate::common::maps;
use rug::Rational;
use wai_cells::Decomposition;
use wai_embed::{piece_of, CellRef, Mutual, Piece, Sightlines};
use wai_exact::{sees, QPoint};

/// A few points of a piece: its inner point and, for a polygon, convex
/// combinations of its vertices with small positive weights.
fn samples(p: &Piece) -> Vec<QPoint> {
    let mut out = vec![p.inner_point()];
    let v = p.vertices();
    if let Piece::Segment(a, b) = p {
        for (i, j) in [(1, 4), (3, 4)] {
            out.push(a.along(&b.sub(a), &Rational::from((i, j))));
        }
    }
    if v.len() >= 3 {
        for s in 0..6usize {
            let weights: Vec<u32> = (0..v.len())
                .map(|i| 1 + ((i * 7 + s * 3) % 5) as u32)
                .collect();
            let total: u32 = weights.iter().sum();
            let mut q = QPoint::new(Rational::new(), Rational::new());
            for (p, w) in v.iter().zip(&weights) {
                q = q.add(&p.scale(&Rational::from((*w, total))));
            }
            out.push(q);
        }
    }
    out
}

#[test]
fn both_methods_agree_and_never_miss_a_sampled_sight_line() {
    let (mut pairs, mut visible, mut sampled_visible) = (0, 0, 0);
    for m in maps(14, 2) {
        let d = Decomposition::new(&m);
        let sl = Sightlines::new(&m);
        let mut cells: Vec<CellRef> = d.cells().iter().map(|&f| CellRef::Face(f)).collect();
        cells.extend((0..d.lower_cells().len()).map(CellRef::Lower));
        let k = cells.len();
        for s in 0..25usize {
            let (i, j) = ((s * 7919) % k, (s * 104_729 + 17) % k);
            if i == j {
                continue;
            }
            let (a, b) = (piece_of(&d, cells[i]), piece_of(&d, cells[j]));
            let x = sl.by_lines(&a, &b);
            let y = sl.by_points(&a, &b);
            assert_eq!(
                x.is_visible(),
                y.is_visible(),
                "{:?}: cells {:?} and {:?}: {x:?} vs {y:?}",
                m.name(),
                cells[i],
                cells[j]
            );
            let seen = samples(&a).iter().any(|p| {
                samples(&b)
                    .iter()
                    .any(|q| sees(m.vertices(), &p.to_rat_point(), &q.to_rat_point()).is_visible())
            });
            if seen {
                sampled_visible += 1;
                assert!(
                    x.is_visible(),
                    "{:?}: a sampled sight line was missed",
                    m.name()
                );
            }
            if let Mutual::Visible { from, to } = &x {
                assert!(sees(m.vertices(), &from.to_rat_point(), &to.to_rat_point()).is_visible());
                visible += 1;
            }
            pairs += 1;
        }
    }
    // Both verdicts occur often, and sampling finds most visible pairs.
    assert!(pairs > 400, "{pairs} pairs");
    assert!(
        visible > pairs / 4 && visible < pairs,
        "{visible} of {pairs} visible"
    );
    assert!(
        sampled_visible > visible / 2,
        "{sampled_visible} sampled of {visible}"
    );
}

/// The boundary cases of the sight rule, on an L-shaped room: a sight line
/// grazing the reflex vertex is blocked, so two cells that see each other
/// only through that vertex do not see each other; a point on a segment's
/// line sees it along the line.
#[test]
fn grazing_blocks_and_collinear_pieces_are_handled() {
    use wai_exact::Point;
    let ring: Vec<Point> = [(0, 0), (4, 0), (4, 2), (2, 2), (2, 4), (0, 4)]
        .map(|(x, y)| Point::new(x, y))
        .to_vec();
    let m = wai_map::Map::from_ring(ring).unwrap().0;
    let sl = Sightlines::new(&m);
    let pt = |x: i64, y: i64| QPoint::new(Rational::from(x), Rational::from(y));
    let q = |x: i64, y: i64, d: i64| QPoint::new(Rational::from((x, d)), Rational::from((y, d)));
    // Two triangles beyond the diagonal x + y = 4 through the reflex
    // vertex (2, 2), their tips on it: every segment between them passes
    // at or beyond the vertex.
    let north = Piece::Polygon(vec![pt(1, 3), q(3, 6, 2), q(3, 7, 2)]);
    let east = Piece::Polygon(vec![pt(3, 1), q(7, 3, 2), q(6, 3, 2)]);
    assert!(!sl.by_lines(&north, &east).is_visible());
    assert!(!sl.by_points(&north, &east).is_visible());
    // Moved a quarter towards the corner, they see each other.
    let north = Piece::Polygon(vec![q(3, 11, 4), q(5, 11, 4), q(5, 13, 4)]);
    let east = Piece::Polygon(vec![q(11, 3, 4), q(13, 5, 4), q(11, 5, 4)]);
    assert!(sl.by_lines(&north, &east).is_visible());
    assert!(sl.by_points(&north, &east).is_visible());
    // Collinear pieces: only their common line can carry a sight line.
    let west = Piece::Point(q(1, 2, 2));
    let along = Piece::Segment(q(3, 2, 2), q(7, 2, 2));
    assert!(sl.by_lines(&west, &along).is_visible());
    assert!(sl.by_points(&west, &along).is_visible());
    // On x + y = 4 through the reflex vertex: grazing blocks.
    let before = Piece::Point(q(3, 5, 2));
    let after = Piece::Segment(q(5, 3, 2), q(7, 1, 2));
    assert!(!sl.by_lines(&before, &after).is_visible());
    assert!(!sl.by_points(&before, &after).is_visible());
}
