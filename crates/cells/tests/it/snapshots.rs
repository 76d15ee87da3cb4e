//! Snapshot counts of the decomposition: n, r, rays, cells, total
//! complexity N, classes, max |EC|, assignment conflicts and the 1- and
//! 0-cells kept/absorbed for each thesis
//! family at small parameters, seeded random and orthogonal maps, and maps
//! of `data/datasets` (AGPLIB's dyadic coordinates exercise the GMP path).
//! A change in a count must be explained in the commit that changes the
//! snapshot.

use std::fmt::Write;
use wai_cells::Decomposition;
use wai_map::Map;

fn row(out: &mut String, name: &str, map: &Map) {
    let c = Decomposition::new(map).counts();
    writeln!(
        out,
        "{name:<44} n={:<3} r={:<3} rays={:<5} cells={:<6} N={:<7} classes={:<6} max|EC|={:<5} conflicts={:<3} 1-cells={}/{} 0-cells={}/{}",
        c.n, c.r, c.rays, c.cells, c.total_complexity, c.classes, c.max_class_complexity, c.conflicts,
        c.one_cells.kept, c.one_cells.absorbed, c.zero_cells.kept, c.zero_cells.absorbed
    )
    .unwrap();
}

#[test]
fn family_counts() {
    let mut out = String::new();
    for f in wai_gen::FAMILIES {
        for k in 1..=3u32 {
            let map = match wai_gen::family(f.id, &[k]) {
                Ok(map) => map,
                // comb-convex-chain needs a chain of at least 2 vertices.
                Err(wai_gen::GenError::ParamTooSmall { .. }) => continue,
                Err(e) => panic!("{}: {e}", f.id),
            };
            if map.n() <= 60 {
                row(&mut out, &format!("{} k={k}", f.id), &map);
            }
        }
    }
    insta::assert_snapshot!(out);
}

#[test]
fn random_counts() {
    let mut out = String::new();
    for kind in [
        "random-simple-star",
        "random-simple-2opt",
        "random-orthogonal",
        "special-orthogonal",
        "special-comb",
        "special-chamfer",
    ] {
        for (n, seed) in [(12, 1), (24, 2)] {
            row(
                &mut out,
                &format!("{kind} n={n} seed={seed}"),
                &wai_gen::random(kind, n, seed).unwrap(),
            );
        }
    }
    insta::assert_snapshot!(out);
}

#[test]
fn dataset_counts() {
    let root = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../data/datasets");
    assert!(
        root.is_dir(),
        "{} is missing: the tests read the repository's data/datasets",
        root.display()
    );
    let mut out = String::new();
    for file in [
        "agplib/simple/randsimple-20-1.json",
        "agplib/ortho/random-20-1.json",
        "agplib/ortho/random-40-1.json",
        "agplib/vonkoch/randvon-20-1.json",
        "r2v/r2v-00_30_fc54c50d7cd00465eeb0eb7de905_0001.json",
        "r2v/r2v-00_36_9c123784498b3312b995399ad578_0004.json",
        "r2v/r2v-01_96_f7fd06b0def79fe6c82632bd29ea_0001.json",
        "westport/westport-house-floor-gf.json",
    ] {
        let bytes = std::fs::read(root.join(file)).unwrap_or_else(|e| panic!("{file}: {e}"));
        let map = wai_map::json::from_json(&bytes).unwrap().map;
        row(&mut out, file, &map);
    }
    insta::assert_snapshot!(out);
}
