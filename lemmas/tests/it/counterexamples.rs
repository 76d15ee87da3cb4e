//! Every map of `counterexamples/` loads, and its extra fields are sound.
//!
//! The format is the map format of `data/datasets/README.md` plus the
//! top-level fields `claim`, `kind`, `note` and optional `viewpoints`
//! (`counterexamples/README.md`).

use std::path::{Path, PathBuf};

use serde_json::Value;
use wai_exact::{locate_rat, Containment, RatPoint};
use wai_lemmas::claim;
use wai_map::{json::from_json, parse_exact, Map};

pub(crate) const DIR: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../counterexamples");

fn json_files() -> Vec<PathBuf> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(DIR)
        .unwrap_or_else(|e| panic!("cannot read {DIR}: {e}"))
        .map(|e| e.expect("directory entry").path())
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .collect();
    files.sort();
    files
}

/// A viewpoint `[x, y]` of exact strings, scaled like the map's vertices.
pub(crate) fn viewpoint(map: &Map, v: &Value, file: &Path) -> RatPoint {
    let coords: Vec<&str> = v
        .as_array()
        .filter(|a| a.len() == 2)
        .and_then(|a| a.iter().map(Value::as_str).collect())
        .unwrap_or_else(|| panic!("{}: viewpoint {v} is not [\"x\", \"y\"]", file.display()));
    let [x, y] = [coords[0], coords[1]].map(|s| {
        parse_exact(s).unwrap_or_else(|e| panic!("{}: viewpoint {v}: {e}", file.display()))
            * map.scale()
    });
    // Homogeneous (x_num·y_den, y_num·x_den, x_den·y_den).
    RatPoint::new(
        x.numer().clone() * y.denom(),
        y.numer().clone() * x.denom(),
        x.denom().clone() * y.denom(),
    )
    .expect("the denominators are positive")
}

/// Loads one file and checks its extra fields; returns the claim id.
fn check(file: &Path) -> String {
    let name = file
        .file_name()
        .expect("a file")
        .to_string_lossy()
        .into_owned();
    let bytes = std::fs::read(file).expect("readable");
    let loaded = from_json(&bytes).unwrap_or_else(|e| panic!("{name}: not a valid map: {e}"));
    let value: Value = serde_json::from_slice(&bytes).expect("from_json accepted it");

    let id = value["claim"]
        .as_str()
        .unwrap_or_else(|| panic!("{name}: no string field \"claim\""));
    assert!(claim(id).is_some(), "{name}: claim {id:?} is not in CLAIMS");
    assert!(
        name.starts_with(&format!("{id}-")) && name.len() > id.len() + 1 + ".json".len(),
        "{name}: the file name must be <claim-id>-<short-name>.json with claim {id}"
    );
    let kind = value["kind"].as_str();
    assert!(
        matches!(kind, Some("figure" | "violation")),
        "{name}: kind must be \"figure\" or \"violation\", is {}",
        value["kind"]
    );
    let note = value["note"].as_str().unwrap_or("");
    assert!(!note.trim().is_empty(), "{name}: empty or missing \"note\"");
    if kind == Some("violation") {
        assert!(
            note.contains("thesis") || note.contains("our code") || note.contains("not known yet"),
            "{name}: a violation's note must say whether the thesis or our code was wrong \
             (or that it is not known yet)"
        );
    }

    match &value["viewpoints"] {
        Value::Null => {}
        Value::Array(points) => {
            assert!(!points.is_empty(), "{name}: \"viewpoints\" is empty");
            for v in points {
                let p = viewpoint(&loaded.map, v, file);
                assert_ne!(
                    locate_rat(loaded.map.vertices(), &p),
                    Containment::Outside,
                    "{name}: viewpoint {v} is outside the map"
                );
            }
        }
        other => panic!("{name}: \"viewpoints\" must be a list, is {other}"),
    }
    id.to_owned()
}

#[test]
fn every_counterexample_loads_with_sound_extra_fields() {
    let files = json_files();
    let claims: Vec<String> = files.iter().map(|f| check(f)).collect();
    println!("{} counterexample files: {claims:?}", files.len());
    assert!(!files.is_empty(), "no *.json in {DIR}: nothing was loaded");
}

#[test]
fn the_corridor_of_fig_3_12_has_three_south_niches() {
    let file = Path::new(DIR).join("L3.7t-fig-3-12d.json");
    let bytes = std::fs::read(&file).expect("the Fig 3.12(d) map is stored");
    let map = from_json(&bytes).expect("valid").map;
    // 3 south niches and 2 north niches, two reflex vertices at each mouth.
    assert_eq!((map.n(), map.r()), (24, 10));
}
