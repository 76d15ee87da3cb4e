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
