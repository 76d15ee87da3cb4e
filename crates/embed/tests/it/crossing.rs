//! Def 4.4's lines of sight (`SightFan`): the union computed as pieces
//! against lines of sight sampled exactly, and certified crossings.

use rug::Rational;
use wai_embed::piece::ints;
use wai_embed::{crossing, Piece, SightFan};
use wai_exact::{turn, Point, QPoint};

/// A room [0, 10]², a passage x ∈ [4, 6] up to y = 11 and a chamber
/// [1, 9] × [11, 14] above it; the passage's top (6, 11)→(4, 11) is the
/// window, the chamber's ceiling (9, 14)→(1, 14) (map edge 7) what the
/// room sees through it.
fn room() -> Vec<Point> {
    [
        (0, 0),
        (10, 0),
        (10, 10),
        (6, 10),
        (6, 11),
        (9, 11),
        (9, 14),
        (1, 14),
        (1, 11),
        (4, 11),
        (4, 10),
        (0, 10),
    ]
    .iter()
    .map(|&(x, y)| Point::new(x, y))
    .collect()
}

fn q(n: i64, d: i64) -> Rational {
    Rational::from((n, d))
}

fn fan_of(cell: Piece) -> SightFan {
    let w = ints(&[(6, 11), (4, 11), (9, 14), (1, 14)]);
    SightFan::new(
        &cell,
        0,
        0,
        (w[0].clone(), w[1].clone()),
        7,
        (w[2].clone(), w[3].clone()),
    )
}

fn square(x0: i64, y0: i64) -> Piece {
    Piece::Polygon(ints(&[
        (x0, y0),
        (x0 + 1, y0),
        (x0 + 1, y0 + 1),
        (x0, y0 + 1),
    ]))
}

#[test]
fn the_pieces_hold_every_sampled_line_of_sight_and_nothing_else() {
    let fan = fan_of(square(4, 2));
    let (v1, v2) = (
        QPoint::new(q(6, 1), q(11, 1)),
        QPoint::new(q(4, 1), q(11, 1)),
    );
    let ceiling = |w: &QPoint, through: &QPoint| {
        // Where the line from w through `through` meets y = 14.
        let t = (q(14, 1) - &w.y) / (through.y.clone() - &w.y);
        w.along(&through.sub(w), &t)
    };
    let mut sampled = 0;
    for i in 1..8 {
        for j in 1..8 {
            let w = QPoint::new(q(4 * 8 + i, 8), q(2 * 8 + j, 8));
            let (s1, s2) = (ceiling(&w, &v1), ceiling(&w, &v2));
            for k in 1..6 {
                let p = s1.along(&s2.sub(&s1), &q(k, 6));
                for t in [q(0, 1), q(1, 9), q(1, 2), q(9, 10), q(1, 1)] {
                    let x = w.along(&p.sub(&w), &t);
                    assert!(fan.pieces().any(|piece| piece.contains(&x)), "{x} missing");
                    sampled += 1;
                }
            }
        }
    }
    assert_eq!(sampled, 7 * 7 * 5 * 5);
    // Beside the view: the chamber's corner, the passage's wall, a point
    // of the room below the cell, and the ceiling beyond the rays.
    for (x, y) in [(3, 26), (2, 27), (12, 20), (9, 3), (4, 28)] {
        let x = QPoint::new(q(x, 2), q(y, 2));
        assert!(
            !fan.pieces().any(|piece| piece.contains(&x)),
            "{x} included"
        );
    }
    // From a single point, the rays through the window's ends graze it:
    // not lines of sight through it.
    let w = QPoint::new(q(5, 1), q(3, 1));
    let point = fan_of(Piece::Point(w.clone()));
    let on_ray = w.along(&ceiling(&w, &v1).sub(&w), &q(99, 100));
    assert!(!point.pieces().any(|piece| piece.contains(&on_ray)));
    let mid = v1.add(&v2).scale(&q(1, 2));
    let inside = w.along(&ceiling(&w, &mid).sub(&w), &q(99, 100));
    assert!(point.pieces().any(|piece| piece.contains(&inside)));
}

#[test]
fn lines_of_sight_from_two_cells_cross_and_are_certified() {
    let ring = wai_map::Map::from_ring(room()).expect("a valid room").0;
    let (left, right) = (fan_of(square(1, 1)), fan_of(square(8, 1)));
    let x = crossing(&ring, &left, &right, false).expect("they cross");
    // The certificate's segments meet at `at`, each from its cell.
    assert!(square(1, 1).contains(&x.first.0));
    assert!(square(8, 1).contains(&x.second.0));
    let behind = crossing(&ring, &left, &right, true).expect("behind the window too");
    assert_eq!(
        turn(&left.v1, &left.v2, &behind.at),
        std::cmp::Ordering::Less
    );
    // A fan meets itself, a point cell's fan too.
    let point = fan_of(Piece::Point(QPoint::new(q(5, 1), q(5, 1))));
    assert!(crossing(&ring, &point, &left, false).is_some());
}

#[test]
fn fans_through_windows_far_apart_do_not_meet() {
    // The same room mirrored far to the east: disjoint boxes.
    let far = {
        let w = ints(&[(106, 11), (104, 11), (109, 14), (101, 14)]);
        SightFan::new(
            &square(104, 2),
            0,
            0,
            (w[0].clone(), w[1].clone()),
            7,
            (w[2].clone(), w[3].clone()),
        )
    };
    assert!(fan_of(square(4, 2)).meets(&far, false).is_none());
}
