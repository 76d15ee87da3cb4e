//! One test per error kind, asserting the error and where it is.

use crate::ring;
use rug::Rational;
use wai_map::json::from_json;
use wai_map::{validate_all, IntersectionKind, Map, MapError, NumberError, Position};

fn pos(x: (i64, i64), y: (i64, i64)) -> Position {
    Position {
        x: Rational::from(x),
        y: Rational::from(y),
    }
}

fn errors_of(json: &str) -> Vec<MapError> {
    from_json(json.as_bytes()).unwrap_err().0
}

#[test]
fn empty_input() {
    assert_eq!(errors_of(""), vec![MapError::Empty]);
    assert_eq!(errors_of(" \n\t"), vec![MapError::Empty]);
}

#[test]
fn binary_input() {
    let e = from_json(&[b'{', 0xff, 0xfe, 0x00]).unwrap_err().0;
    assert_eq!(e, vec![MapError::NotUtf8 { offset: 1 }]);
}

#[test]
fn malformed_json_has_line_and_column() {
    let e = errors_of("{\"outer\": [\n  [\"0\", \"0\"],\n  [\"1\" \"0\"]\n]}");
    match &e[..] {
        [MapError::Syntax { line, column, .. }] => assert_eq!((*line, *column), (3, 8)),
        other => panic!("unexpected {other:?}"),
    }
}

#[test]
fn structure_errors_name_the_path() {
    assert_eq!(
        errors_of("[1, 2]"),
        vec![MapError::Structure {
            path: "$".into(),
            message: "expected an object with an \"outer\" ring".into()
        }]
    );
    assert!(
        matches!(&errors_of("{\"name\": \"x\"}")[..], [MapError::Structure { path, .. }] if path == "$")
    );
    assert!(matches!(
        &errors_of("{\"outer\": [[\"0\", \"0\"], [\"1\"], [\"0\", \"1\"]]}")[..],
        [MapError::Structure { path, .. }] if path == "outer[1]"
    ));
    assert!(matches!(
        &errors_of("{\"outer\": [[\"0\", \"0\"], [\"1\", null], [\"0\", \"1\"]]}")[..],
        [MapError::Structure { path, .. }] if path == "outer[1][1]"
    ));
}

#[test]
fn every_bad_number_is_reported_with_its_path() {
    let e = errors_of(r#"{"outer": [["0", "NaN"], ["1e3", "0"], ["1/0", "1"], [1.5e2, "2"]]}"#);
    let got: Vec<(String, NumberError)> = e
        .into_iter()
        .map(|e| match e {
            MapError::BadNumber { path, reason, .. } => (path, reason),
            other => panic!("unexpected {other:?}"),
        })
        .collect();
    assert_eq!(
        got,
        vec![
            ("outer[0][1]".into(), NumberError::NotFinite),
            ("outer[1][0]".into(), NumberError::Exponent),
            ("outer[2][0]".into(), NumberError::ZeroDenominator),
            ("outer[3][0]".into(), NumberError::Exponent),
        ]
    );
}

#[test]
fn absurdly_large_coordinates() {
    let big = format!("1{}", "0".repeat(40));
    let e = errors_of(&format!(
        r#"{{"outer": [["0", "0"], ["{big}", "0"], ["0", "1"]]}}"#
    ));
    assert!(matches!(
        &e[..],
        [MapError::CoordinateTooLarge { path, bits: 133, max: 100 }] if path == "outer[1][0]"
    ));
    // Small values with a common denominator too large to scale to 100 bits.
    let e = errors_of(
        r#"{"outer": [["1/3", "0"], ["1", "1/1267650600228229401496703205376"], ["0", "1"]]}"#,
    );
    assert!(
        !e.is_empty()
            && e.iter()
                .all(|e| matches!(e, MapError::CoordinateTooLarge { .. })),
        "{e:?}"
    );
}

#[test]
fn a_stage_without_holes_names_itself() {
    let map = from_json(
        br#"{"outer": [["0","0"],["9","0"],["0","9"]], "holes": [[["1","1"],["1","2"],["2","1"]]]}"#,
    )
    .unwrap()
    .map;
    let e = map.require_no_holes("the visibility skeleton").unwrap_err();
    assert_eq!(
        e.to_string(),
        "the visibility skeleton does not support maps with holes yet: the map has 1 hole(s)"
    );
}

#[test]
fn fewer_than_three_distinct_vertices() {
    assert_eq!(
        validate_all(&ring(&[(0, 0), (1, 1)])),
        vec![MapError::TooFewVertices { found: 2 }]
    );
    assert_eq!(
        validate_all(&ring(&[(0, 0), (1, 1), (0, 0)])),
        vec![MapError::TooFewVertices { found: 2 }]
    );
    assert_eq!(
        errors_of(r#"{"outer": []}"#),
        vec![MapError::TooFewVertices { found: 0 }]
    );
}

#[test]
fn repeated_vertices() {
    let e = validate_all(&ring(&[(0, 0), (4, 0), (4, 4), (4, 0), (0, 4)]));
    assert_eq!(
        e[0],
        MapError::RepeatedVertex {
            first: 1,
            second: 3,
            at: pos((4, 1), (0, 1)),
            closing: false
        }
    );
    // A closed ring (first vertex repeated at the end) says how to fix it.
    let e = errors_of(r#"{"outer": [["0","0"],["1","0"],["0","1"],["0","0"]]}"#);
    assert_eq!(
        e,
        vec![MapError::RepeatedVertex {
            first: 0,
            second: 3,
            at: pos((0, 1), (0, 1)),
            closing: true
        }]
    );
    assert!(e[0].to_string().contains("rings are open"));
}

#[test]
fn self_intersection_names_both_edges_and_the_point() {
    // A bow tie: edges 0 and 2 cross at (1, 1/2) — in input units, from a scaled file.
    let e = errors_of(r#"{"outer": [["0","0"],["1","1"],["1","0"],["0","1"]]}"#);
    assert_eq!(
        e,
        vec![MapError::SelfIntersection {
            edge_a: 0,
            edge_b: 2,
            kind: IntersectionKind::Crossing,
            at: pos((1, 2), (1, 2))
        }]
    );
    assert_eq!(
        e[0].to_string(),
        "the map is not simple: edges 0 and 2 cross at (0.5, 0.5)"
    );
}

#[test]
fn touching_itself_at_a_vertex() {
    // Vertex 4 = (2, 0) lies on edge 0 from (0, 0) to (4, 0).
    let e = validate_all(&ring(&[
        (0, 0),
        (4, 0),
        (4, 4),
        (3, 4),
        (2, 0),
        (1, 4),
        (0, 4),
    ]));
    assert_eq!(
        e,
        vec![
            MapError::SelfIntersection {
                edge_a: 0,
                edge_b: 3,
                kind: IntersectionKind::Touching,
                at: pos((2, 1), (0, 1))
            },
            MapError::SelfIntersection {
                edge_a: 0,
                edge_b: 4,
                kind: IntersectionKind::Touching,
                at: pos((2, 1), (0, 1))
            },
        ]
    );
}

#[test]
fn edges_folding_back_overlap() {
    // A spike: (4, 0) -> (6, 0) -> (5, 0) runs back along itself.
    let e = validate_all(&ring(&[(0, 0), (6, 0), (5, 0), (5, 3), (0, 3)]));
    assert!(
        e.contains(&MapError::SelfIntersection {
            edge_a: 0,
            edge_b: 1,
            kind: IntersectionKind::Overlap,
            at: pos((5, 1), (0, 1))
        }),
        "{e:?}"
    );
}

#[test]
fn all_vertices_on_one_line() {
    assert_eq!(
        validate_all(&ring(&[(0, 0), (1, 1), (3, 3), (2, 2)])),
        vec![MapError::ZeroArea { n: 4 }]
    );
    assert_eq!(
        errors_of(r#"{"outer": [["0","0"],["1","0"],["2","0"]]}"#),
        vec![MapError::ZeroArea { n: 3 }]
    );
}

#[test]
fn validate_all_reports_every_problem() {
    // Two separate crossings and a repeated vertex in one ring.
    let e = validate_all(&ring(&[
        (0, 0),
        (2, 2),
        (2, 0),
        (0, 2),
        (0, 5),
        (2, 7),
        (2, 5),
        (0, 7),
        (-3, 7),
        (-3, 0),
        (2, 2),
    ]));
    let crossings = e
        .iter()
        .filter(|e| {
            matches!(
                e,
                MapError::SelfIntersection {
                    kind: IntersectionKind::Crossing,
                    ..
                }
            )
        })
        .count();
    let repeats = e
        .iter()
        .filter(|e| matches!(e, MapError::RepeatedVertex { .. }))
        .count();
    assert!(crossings >= 2 && repeats == 1, "{e:?}");
}

#[test]
fn from_ring_rejects_what_validate_all_reports() {
    let bad = ring(&[(0, 0), (1, 1), (1, 0), (0, 1)]);
    assert_eq!(
        Map::from_ring(bad.clone()).unwrap_err().0,
        validate_all(&bad)
    );
}

#[test]
fn validate_all_checks_the_coordinate_bound() {
    // Found by the `ring` fuzz target: validate_all must refuse what from_ring refuses.
    let big = 1i128 << 112;
    let r = vec![
        wai_exact::Point::new(-big, -big),
        wai_exact::Point::new(45 * big, -big),
        wai_exact::Point::new(0, 0),
    ];
    let e = validate_all(&r);
    assert!(
        matches!(&e[..], [MapError::CoordinateTooLarge { path: a, bits: 113, max: 100 }, MapError::CoordinateTooLarge { path: b, .. }] if a == "vertex 0" && b == "vertex 1"),
        "{e:?}"
    );
    assert_eq!(Map::from_ring(r).unwrap_err().0, e);
}
