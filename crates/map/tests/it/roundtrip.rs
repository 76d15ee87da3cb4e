use crate::ring;
use proptest::prelude::*;
use wai_map::json::{from_json, to_json};
use wai_map::Map;

fn round_trip(map: &Map) {
    let text = to_json(map);
    let back = from_json(text.as_bytes()).unwrap_or_else(|e| panic!("{e}\n{text}"));
    assert!(back.normalisation.is_identity());
    assert_eq!(&back.map, map, "{text}");
    assert_eq!(to_json(&back.map), text);
}

#[test]
fn exact_decimals_and_fractions_survive() {
    let text =
        r#"{"name": "mixed", "outer": [["0.1", "0"], ["7/3", "0"], [2, "1.25"], ["-1/7", "3"]]}"#;
    let loaded = from_json(text.as_bytes()).unwrap();
    assert_eq!(*loaded.map.scale(), 420); // lcm(10, 3, 4, 7)
    let written = to_json(&loaded.map);
    assert!(
        written.contains(r#"["0.1", "0"]"#) && written.contains(r#"["7/3", "0"]"#),
        "{written}"
    );
    assert!(
        written.contains(r#"["-1/7", "3"]"#) && written.contains(r#"["2", "1.25"]"#),
        "{written}"
    );
    round_trip(&loaded.map);
}

#[test]
fn names_and_sources_survive() {
    let (map, _) = Map::from_ring(ring(&[(0, 0), (5, 0), (0, 5)])).unwrap();
    round_trip(&map.with_name("tri \"quoted\"").with_source("hand"));
}

#[test]
fn json_numbers_are_read_exactly() {
    let text = r#"{"outer": [[0, 0], [0.1, 0], [0.1, 0.30000000000000004]]}"#;
    let m = from_json(text.as_bytes()).unwrap().map;
    // The least common denominator of 1/10 and 30000000000000004/10^17.
    assert_eq!(
        *m.scale(),
        rug::Integer::from(25) * rug::Integer::from(rug::Integer::u_pow_u(10, 15))
    );
    round_trip(&m);
}

proptest! {
    #[test]
    fn random_scaled_triangles_round_trip(
        a in -1000i128..1000, b in -1000i128..1000, c in 1i128..1000, d in 1i128..1000, s in 1u32..5000
    ) {
        // A triangle with a positive area, in units of 1/s.
        if let Ok((m, _)) = Map::from_scaled_ring(ring(&[(a, b), (a + c, b), (a, b + d)]), s.into()) {
            round_trip(&m);
        }
    }
}

#[test]
fn stated_units_are_read_and_written_back() {
    use wai_map::Units;
    let text = br#"{"units": "scale:0.01", "outer": [["0", "0"], ["400", "0"], ["400", "300"], ["0", "300"]]}"#;
    let map = from_json(text).expect("a map").map;
    assert_eq!(
        map.units(),
        Some(&Units::Scale(rug::Rational::from((1, 100))))
    );
    let back = from_json(to_json(&map).as_bytes()).expect("a map").map;
    assert_eq!(back, map);
    assert!(to_json(&map).contains(r#""units": "scale:0.01""#));
    // Without the field: none stated.
    let plain = br#"{"outer": [["0", "0"], ["4", "0"], ["4", "3"]]}"#;
    assert_eq!(from_json(plain).expect("a map").map.units(), None);
    // A bad value is an error at "units".
    let bad = br#"{"units": "feet", "outer": [["0", "0"], ["4", "0"], ["4", "3"]]}"#;
    let err = from_json(bad).unwrap_err().to_string();
    assert!(err.contains("units") && err.contains("scale:K"), "{err}");
}

#[test]
fn a_map_looks_lonlat_only_when_small_and_in_range() {
    let map = |ring: &str| {
        from_json(format!(r#"{{"outer": {ring}}}"#).as_bytes())
            .expect("a map")
            .map
    };
    assert!(map(r#"[["8", "47"], ["8.001", "47"], ["8.001", "47.001"]]"#).looks_lonlat());
    // Too wide a span, or beyond ±90 in y: planar.
    assert!(!map(r#"[["8", "47"], ["8.2", "47"], ["8.2", "47.2"]]"#).looks_lonlat());
    assert!(!map(r#"[["8", "95"], ["8.001", "95"], ["8.001", "95.001"]]"#).looks_lonlat());
}
