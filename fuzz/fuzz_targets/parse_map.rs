//! Arbitrary bytes into the two map readers.
//!
//! Laws: neither reader panics; a map either reads back from `to_json` equal
//! to itself, needing no further normalisation, and `to_json` is a fixed
//! point (writing the re-read map gives the same text).
#![no_main]

use libfuzzer_sys::fuzz_target;
use wai_map::json::{from_json, to_json};
use wai_map::{geojson::from_geojson, Loaded, MapErrors};

fn round_trip(reader: &str, loaded: Result<Loaded, MapErrors>) {
    let Ok(loaded) = loaded else { return };
    let text = to_json(&loaded.map);
    let again = match from_json(text.as_bytes()) {
        Ok(again) => again,
        Err(e) => panic!("{reader}: to_json wrote a map from_json rejects: {e}\n{text}"),
    };
    assert_eq!(
        again.map, loaded.map,
        "{reader}: round trip changed the map\n{text}"
    );
    assert!(
        again.normalisation.is_identity(),
        "{reader}: a written map needed normalising again: {:?}\n{text}",
        again.normalisation
    );
    assert_eq!(
        to_json(&again.map),
        text,
        "{reader}: to_json is not a fixed point"
    );
}

fuzz_target!(|bytes: &[u8]| {
    round_trip("json", from_json(bytes));
    round_trip("geojson", from_geojson(bytes));
});
