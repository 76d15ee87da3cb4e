//! Maps with holes (thesis sec. 2.1): reading, normalisation, the ring
//! structure, and one test per way a hole can be wrong, with where.

use crate::ring;
use rug::Rational;
use wai_map::json::{from_json, from_json_with, to_json, ReadOptions};
use wai_map::{validate_rings, IntersectionKind, Map, MapError, Position, Ring};

/// The square [0, 12]² with the given holes.
fn with_holes(holes: Vec<Vec<(i128, i128)>>) -> Result<Map, Vec<MapError>> {
    let outer = ring(&[(0, 0), (12, 0), (12, 12), (0, 12)]);
    let holes = holes.iter().map(|h| ring(h)).collect();
    Map::from_rings(outer, holes)
        .map(|(m, _)| m)
        .map_err(|e| e.0)
}

fn at(x: i64, y: i64) -> Position {
    Position {
        x: Rational::from(x),
        y: Rational::from(y),
    }
}

#[test]
fn rings_are_numbered_outer_first_and_walked_with_free_space_on_the_left() {
    // A counter-clockwise square hole is made clockwise, keeping vertex 0.
    let (map, norm) = Map::from_rings(
        ring(&[(0, 0), (12, 0), (12, 12), (0, 12)]),
        vec![
            ring(&[(2, 2), (4, 2), (4, 4), (2, 4)]),
            ring(&[(6, 6), (6, 8), (7, 8), (8, 8), (8, 6)]),
        ],
    )
    .unwrap();
    assert_eq!(norm.reversed_holes, vec![0]);
    assert_eq!(norm.removed_collinear_holes, vec![(1, 2)]);
    assert!(!norm.is_identity());
    assert_eq!((map.n(), map.hole_count()), (12, 2));
    assert_eq!(map.outer(), ring(&[(0, 0), (12, 0), (12, 12), (0, 12)]));
    assert_eq!(map.ring(1), ring(&[(2, 2), (2, 4), (4, 4), (4, 2)]));
    assert_eq!(map.ring(2), ring(&[(6, 6), (6, 8), (8, 8), (8, 6)]));
    assert_eq!(map.holes().count(), 2);
    assert_eq!(
        (
            map.ring_of(3),
            map.ring_of(4),
            map.ring_of(7),
            map.ring_of(8)
        ),
        (0, 1, 1, 2)
    );
    assert_eq!(
        (map.next(3), map.next(7), map.prev(4), map.prev(8)),
        (0, 4, 7, 11)
    );
    // The edges of a hole close on the hole.
    assert_eq!(map.edge(7).b(), map.vertices()[4]);
    assert_eq!(map.edges().count(), 12);
    // Every corner of a square hole is reflex in the free space.
    assert_eq!(map.reflex_vertices(), &[4, 5, 6, 7, 8, 9, 10, 11]);
    assert_eq!(map.r(), 8);
    // 144 less two holes of 4.
    assert_eq!(map.area_twice(), 2 * (144 - 4 - 4));
    assert!(map.is_orthogonal() && map.has_holes());
    assert!(map.require_no_holes("x").is_err());
}

#[test]
fn a_map_with_holes_survives_the_file_format() {
    let map = with_holes(vec![
        vec![(2, 2), (2, 4), (4, 4), (4, 2)],
        vec![(6, 6), (7, 9), (9, 6)],
    ])
    .unwrap()
    .with_name("pillars");
    let text = to_json(&map);
    let back = from_json(text.as_bytes()).unwrap();
    assert!(back.normalisation.is_identity(), "{text}");
    assert_eq!(back.map, map);
    assert_eq!(to_json(&back.map), text);
    // The digest follows the holes and tells them apart from the ring.
    let fewer = with_holes(vec![vec![(2, 2), (2, 4), (4, 4), (4, 2)]]).unwrap();
    let none = with_holes(vec![]).unwrap();
    assert_ne!(map.digest(), fewer.digest());
    assert_ne!(fewer.digest(), none.digest());
}

#[test]
fn hole_errors_are_located() {
    let e = |holes| with_holes(holes).unwrap_err();
    // A hole crossing the outer ring.
    assert_eq!(
        e(vec![vec![(10, 10), (10, 14), (11, 11)]]),
        vec![
            MapError::RingsMeet {
                ring_a: Ring::Outer,
                edge_a: 2,
                ring_b: Ring::Hole(0),
                edge_b: 0,
                kind: IntersectionKind::Crossing,
                at: at(10, 12),
            },
            MapError::RingsMeet {
                ring_a: Ring::Outer,
                edge_a: 2,
                ring_b: Ring::Hole(0),
                edge_b: 1,
                kind: IntersectionKind::Crossing,
                at: Position {
                    x: Rational::from((32, 3)),
                    y: Rational::from(12),
                },
            },
        ]
    );
    // A hole touching the outer ring with a vertex.
    assert!(matches!(
        &e(vec![vec![(6, 0), (5, 3), (7, 3)]])[..],
        [MapError::RingsMeet { ring_a: Ring::Outer, edge_a: 0, ring_b: Ring::Hole(0), kind: IntersectionKind::Touching, at, .. }, ..] if *at == at_point(6, 0)
    ));
    // Two holes sharing a vertex, and two holes along each other.
    assert!(matches!(
        &e(vec![
            vec![(2, 2), (2, 4), (4, 4)],
            vec![(4, 4), (6, 6), (6, 4)]
        ])[..],
        [
            MapError::RingsMeet {
                ring_a: Ring::Hole(0),
                ring_b: Ring::Hole(1),
                kind: IntersectionKind::Touching,
                ..
            },
            ..
        ]
    ));
    assert!(e(vec![
        vec![(2, 2), (2, 4), (4, 4), (4, 2)],
        vec![(4, 2), (4, 4), (6, 4), (6, 2)]
    ])
    .iter()
    .any(|x| matches!(
        x,
        MapError::RingsMeet {
            kind: IntersectionKind::Overlap,
            ..
        }
    )));
    // Outside the outer ring, and inside another hole.
    assert_eq!(
        e(vec![vec![(20, 20), (20, 22), (22, 22)]]),
        vec![MapError::HoleOutside {
            hole: 0,
            at: at(20, 20)
        }]
    );
    assert_eq!(
        e(vec![
            vec![(1, 1), (1, 11), (11, 11), (11, 1)],
            vec![(4, 4), (4, 6), (6, 6)]
        ]),
        vec![MapError::HoleInHole { inner: 1, outer: 0 }]
    );
    // Degenerate holes: two vertices, a line, a bow tie.
    assert_eq!(
        e(vec![vec![(2, 2), (3, 3)]]),
        vec![MapError::InHole {
            hole: 0,
            error: Box::new(MapError::TooFewVertices { found: 2 })
        }]
    );
    assert_eq!(
        e(vec![vec![(2, 2), (3, 3), (4, 4)]]),
        vec![MapError::InHole {
            hole: 0,
            error: Box::new(MapError::ZeroArea { n: 3 })
        }]
    );
    let bow = e(vec![vec![(2, 2), (4, 4), (4, 2), (2, 4)]]);
    assert!(
        matches!(&bow[..], [MapError::InHole { hole: 0, error }] if matches!(**error, MapError::SelfIntersection { kind: IntersectionKind::Crossing, .. })),
        "{bow:?}"
    );
    assert_eq!(
        bow[0].to_string(),
        "hole 0: the map is not simple: edges 0 and 2 cross at (3, 3)"
    );
    // validate_rings says the same as the constructor.
    assert_eq!(
        validate_rings(
            &ring(&[(0, 0), (12, 0), (12, 12), (0, 12)]),
            &[ring(&[(2, 2), (4, 4), (4, 2), (2, 4)])]
        ),
        bow
    );
}

fn at_point(x: i64, y: i64) -> Position {
    at(x, y)
}

#[test]
fn messages_name_rings_and_edges() {
    let e = with_holes(vec![vec![(6, 0), (5, 3), (7, 3)]]).unwrap_err();
    assert_eq!(
        e[0].to_string(),
        "the outer ring and hole 0 meet: the outer ring's edge 0 and hole 0's edge 0 touch at (6, 0)"
    );
    let e = with_holes(vec![vec![(20, 20), (20, 22), (22, 22)]]).unwrap_err();
    assert_eq!(
        e[0].to_string(),
        "hole 0 lies outside the outer ring (its vertex 0 is at (20, 20))"
    );
}

#[test]
fn a_bad_number_in_a_hole_is_located_in_the_file() {
    let e = from_json(
        br#"{"outer": [["0","0"],["9","0"],["0","9"]], "holes": [[["1","1"],["1e0","2"],["2","1"]]]}"#,
    )
    .unwrap_err();
    assert!(
        matches!(&e.0[..], [MapError::BadNumber { path, .. }] if path == "holes[0][1][0]"),
        "{e}"
    );
    let e = from_json(br#"{"outer": [["0","0"],["9","0"],["0","9"]], "holes": [["1","1"]]}"#)
        .unwrap_err();
    assert!(
        matches!(&e.0[..], [MapError::Structure { path, .. }, ..] if path == "holes[0][0]"),
        "{e}"
    );
    let e = from_json(br#"{"outer": [["0","0"],["9","0"],["0","9"]], "holes": 3}"#).unwrap_err();
    assert!(matches!(&e.0[..], [MapError::Structure { path, .. }] if path == "holes"));
}

#[test]
fn rounding_to_a_grid_moves_only_what_is_off_it_and_says_so() {
    let text = br#"{"outer": [["0","0"],["1/3","0"],["1/3","1"],["0","1"]], "holes": [[["1/10","1/4"],["1/10","1/2"],["1/5","1/2"]]]}"#;
    let exact = from_json(text).unwrap();
    assert!(exact.normalisation.rounded.is_none());
    let grid = from_json_with(text, &ReadOptions { grid_bits: Some(8) }).unwrap();
    let r = grid.normalisation.rounded.clone().unwrap();
    // 1/3 (twice), 1/10 (twice) and 1/5 are off the grid; 0, 1, 1/4, 1/2
    // are on it.
    assert_eq!((r.bits, r.moved), (8, 5));
    assert!(r.largest > 0 && r.largest <= Rational::from((1, 512)));
    assert_eq!(*grid.map.scale(), 256);
    assert!(!grid.normalisation.is_identity());
    // Equal coordinates stay equal: the map stays orthogonal where it was.
    assert_eq!(grid.map.outer()[1].x, grid.map.outer()[2].x);
    // A grid finer than any coordinate can hold is refused.
    let e = from_json_with(
        text,
        &ReadOptions {
            grid_bits: Some(200),
        },
    )
    .unwrap_err();
    assert!(
        e.to_string().contains("finer than the finest supported"),
        "{e}"
    );
}
