//! Every map of `data/datasets` that has no holes is read exactly; the
//! families with holes give the clear "not supported yet" error.

use rug::{Integer, Rational};
use serde_json::Value;
use std::path::PathBuf;
use wai_map::json::from_json;
use wai_map::{parse_exact, MapError};

fn dataset_dir(sub: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../data/datasets")
        .join(sub);
    assert!(
        dir.is_dir(),
        "dataset folder {} is missing: the tests read the repository's data/datasets",
        dir.display()
    );
    dir
}

fn map_files(sub: &str) -> Vec<PathBuf> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(dataset_dir(sub))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "json") && !p.ends_with("index.json"))
        .collect();
    files.sort();
    files
}

/// Read every map of `sub` and compare it with the file's own text and meta.
fn check_exact(sub: &str, expected_files: usize) {
    let files = map_files(sub);
    assert_eq!(files.len(), expected_files, "{sub}");
    for path in files {
        let bytes = std::fs::read(&path).unwrap();
        let loaded = from_json(&bytes).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        let raw: Value = serde_json::from_slice(&bytes).unwrap();
        let meta = &raw["meta"];
        let (map, norm) = (&loaded.map, &loaded.normalisation);
        assert!(norm.is_identity(), "{}: {norm:?}", path.display());
        assert_eq!(
            map.n() as u64,
            meta["vertices_outer"].as_u64().unwrap(),
            "{}",
            path.display()
        );
        assert_eq!(
            map.r() as u64,
            meta["reflex_outer"].as_u64().unwrap(),
            "{}",
            path.display()
        );
        assert_eq!(
            map.is_orthogonal(),
            meta["orthogonal"].as_bool().unwrap(),
            "{}",
            path.display()
        );
        // Every vertex equals the source's exact value.
        let outer = raw["outer"].as_array().unwrap();
        for (p, src) in map.vertices().iter().zip(outer) {
            for (c, s) in [(p.x, &src[0]), (p.y, &src[1])] {
                let want = parse_exact(s.as_str().unwrap()).unwrap();
                let got = Rational::from((Integer::from(c), map.scale().clone()));
                assert_eq!(got, want, "{}", path.display());
            }
        }
    }
}

#[test]
fn agplib_simple() {
    check_exact("agplib/simple", 44);
}

#[test]
fn agplib_ortho() {
    check_exact("agplib/ortho", 44);
}

#[test]
fn agplib_vonkoch() {
    check_exact("agplib/vonkoch", 44);
}

#[test]
fn r2v() {
    check_exact("r2v", 300);
}

#[test]
fn westport() {
    check_exact("westport", 7);
}

#[test]
fn holes_families_give_the_clear_error() {
    for sub in ["agplib/simple-holes", "agplib/ortho-holes"] {
        let files = map_files(sub);
        assert!(!files.is_empty());
        for path in files {
            let e = from_json(&std::fs::read(&path).unwrap()).unwrap_err();
            assert!(
                matches!(e.0[..], [MapError::HolesNotSupported { count }] if count > 0),
                "{}: {e}",
                path.display()
            );
        }
    }
}
