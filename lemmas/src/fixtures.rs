//! Maps and visibility polygons shared by the checkers' unit tests.

use wai_exact::{Point, RatPoint};
use wai_study::Study;

use crate::framework::Checker;
use wai_map::Map;
use wai_visibility::{VisibilityIndex, VisibilityPolygon};

/// The map of `ring`, named `name`, and V_p of the integer point `p`.
pub(crate) fn seen_from(
    ring: &[(i128, i128)],
    name: &str,
    p: (i128, i128),
) -> (Map, VisibilityPolygon) {
    let ring = ring.iter().map(|&(x, y)| Point::new(x, y)).collect();
    let map = Map::from_ring(ring).unwrap().0.with_name(name);
    let vp = VisibilityIndex::new(&map)
        .visibility_polygon(&RatPoint::from(Point::new(p.0, p.1)))
        .unwrap();
    (map, vp)
}

/// The L-shaped room seen from (1, 3): V_p = (0,0) (4,0) (2,2) (2,4)
/// (0,4), reflex at (2, 2); edge 0 is a half edge on map edge 0 whose
/// far end (4, 0) is spurious.
pub(crate) fn l_room() -> (Map, VisibilityPolygon) {
    seen_from(
        &[(0, 0), (4, 0), (4, 2), (2, 2), (2, 4), (0, 4)],
        "L-room",
        (1, 3),
    )
}

/// The S tetromino of `counterexamples/T3.3b-doorway-1d-cell.json`:
/// opposite collinear rays cover the segment (1, 1)–(1, 2), a 1-cell.
pub(crate) fn s_tetromino() -> Map {
    let ring = [
        (0, 0),
        (1, 0),
        (1, 1),
        (2, 1),
        (2, 3),
        (1, 3),
        (1, 2),
        (0, 2),
    ];
    let ring = ring.iter().map(|&(x, y)| Point::new(x, y)).collect();
    Map::from_ring(ring).unwrap().0.with_name("s-tetromino")
}

/// A room with a door in its north wall leading to a corridor, seen from
/// (3, 1): V_p has a partial edge between two spurious edges, and half
/// edges.
pub(crate) fn doorway() -> (Map, VisibilityPolygon) {
    let ring = [
        (0, 0),
        (6, 0),
        (6, 4),
        (4, 4),
        (4, 5),
        (10, 5),
        (10, 8),
        (-4, 8),
        (-4, 5),
        (2, 5),
        (2, 4),
        (0, 4),
    ];
    seen_from(&ring, "doorway", (3, 1))
}

/// `checker` finds no violation on the layout maps `layout(seed)` of
/// `seeds`, and examines something over them.
pub(crate) fn holds_on(checker: &Checker, layout: fn(u64) -> Map, seeds: &[u64]) {
    let mut examined = 0;
    for &seed in seeds {
        let map = layout(seed);
        let report = checker.run(&Study::new(&map));
        examined += report.examined;
        assert!(report.violations.is_empty(), "{:?}", report.violations);
    }
    assert!(examined > 0, "{}: nothing examined", checker.id);
}
