//! Every map of `data/datasets` is read: those without holes exactly; the
//! families with holes exactly where their values fit, else rounded to the
//! grid of 2^-60, which moves what it must and nothing else.

use rug::{Integer, Rational};
use serde_json::Value;
use std::path::PathBuf;
use wai_map::json::{from_json, from_json_with, ReadOptions};
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

/// The exact value of a coordinate of `map`.
fn value(map: &wai_map::Map, c: i128) -> Rational {
    Rational::from((Integer::from(c), map.scale().clone()))
}

/// Read every map of a family with holes and compare it with the file's
/// text and meta; returns how many needed the grid.
fn check_holes(sub: &str, expected_files: usize) -> usize {
    let files = map_files(sub);
    assert_eq!(files.len(), expected_files, "{sub}");
    let grid = ReadOptions {
        grid_bits: Some(60),
    };
    let half_step = Rational::from((1, Integer::from(1) << 61));
    let mut rounded = 0;
    for path in files {
        let shown = path.display();
        let bytes = std::fs::read(&path).unwrap();
        let raw: Value = serde_json::from_slice(&bytes).unwrap();
        let meta = &raw["meta"];
        let loaded = match from_json(&bytes) {
            Ok(exact) => exact,
            Err(e) => {
                // Only the size of the exact values stops the exact reading.
                assert!(
                    e.iter()
                        .all(|e| matches!(e, MapError::CoordinateTooLarge { .. })),
                    "{shown}: {e}"
                );
                rounded += 1;
                from_json_with(&bytes, &grid).unwrap_or_else(|e| panic!("{shown}: {e}"))
            }
        };
        let (map, norm) = (&loaded.map, &loaded.normalisation);
        assert!(!norm.reversed && norm.reversed_holes.is_empty(), "{shown}");
        let removed = norm.removed_collinear.len() + norm.removed_collinear_holes.len();
        assert_eq!(
            removed as u64,
            meta["collinear_consecutive"].as_u64().unwrap(),
            "{shown}"
        );
        assert_eq!(
            (map.n() + removed) as u64,
            meta["vertices_total"].as_u64().unwrap(),
            "{shown}"
        );
        assert_eq!(
            map.hole_count() as u64,
            meta["holes"].as_u64().unwrap(),
            "{shown}"
        );
        assert_eq!(
            map.r() as u64,
            meta["reflex_total"].as_u64().unwrap(),
            "{shown}"
        );
        assert_eq!(
            map.is_orthogonal(),
            meta["orthogonal"].as_bool().unwrap(),
            "{shown}"
        );
        // Every vertex kept equals the source's value, or is its nearest
        // grid point when the grid was used.
        let mut rings = vec![raw["outer"].as_array().unwrap().clone()];
        rings.extend(
            raw["holes"]
                .as_array()
                .unwrap()
                .iter()
                .map(|h| h.as_array().unwrap().clone()),
        );
        let mut moved = 0;
        for (k, src) in rings.iter().enumerate() {
            let removed: Vec<usize> = if k == 0 {
                norm.removed_collinear.clone()
            } else {
                norm.removed_collinear_holes
                    .iter()
                    .filter(|(h, _)| *h == k - 1)
                    .map(|&(_, i)| i)
                    .collect()
            };
            let kept = src
                .iter()
                .enumerate()
                .filter(|(i, _)| !removed.contains(i))
                .map(|(_, v)| v);
            for (p, v) in map.ring(k).iter().zip(kept) {
                for (c, s) in [(p.x, &v[0]), (p.y, &v[1])] {
                    let want = parse_exact(s.as_str().unwrap()).unwrap();
                    let got = value(map, c);
                    if got != want {
                        assert!(norm.rounded.is_some(), "{shown}: {got} != {want}");
                        assert!(Rational::from(&got - &want).abs() <= half_step, "{shown}");
                        moved += 1;
                    }
                }
            }
        }
        if let Some(r) = &norm.rounded {
            assert!(r.largest <= half_step && r.moved >= moved, "{shown}: {r:?}");
        }
        if sub.contains("simple-holes") {
            // One subnormal double where 0 was meant: the only value moved.
            assert_eq!(moved, 1, "{shown}");
        }
    }
    rounded
}

#[test]
fn agplib_simple_with_holes() {
    // Each file holds one subnormal double (about 1e-310, denominator
    // 2^1074): no exact reading fits, and the grid moves that value only.
    assert_eq!(check_holes("agplib/simple-holes", 20), 20);
}

#[test]
fn agplib_orthogonal_with_holes() {
    // Rationals with denominators up to 2^124 over the map: 3 of 16 fit.
    assert_eq!(check_holes("agplib/ortho-holes", 16), 13);
}
