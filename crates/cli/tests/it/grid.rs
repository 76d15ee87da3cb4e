//! `wai import-grid`: an occupancy grid on disk to a map `wai info` reads.

use crate::{text, wai};

/// A 10 × 8 grid at 5 cm: a room with a 2 × 2 pillar and a one-cell speck,
/// written as `map_saver` writes it (P5, 254 free, 0 occupied, 205 unknown).
fn write_grid(dir: &std::path::Path, yaml: &str) {
    let rows = [
        "##########",
        "#........#",
        "#.##.....#",
        "#.##...#.#",
        "#........#",
        "#....??..#",
        "#........#",
        "##########",
    ];
    let mut pgm = b"P5\n# CREATOR: map_saver.cpp 0.050 m/pix\n10 8\n255\n".to_vec();
    for row in rows {
        pgm.extend(row.bytes().map(|b| match b {
            b'.' => 254u8,
            b'#' => 0,
            _ => 205,
        }));
    }
    std::fs::write(dir.join("lab.pgm"), pgm).unwrap();
    std::fs::write(dir.join("lab.yaml"), yaml).unwrap();
}

#[test]
fn a_grid_becomes_a_map_with_holes_in_metres() {
    let dir = std::env::temp_dir().join(format!("wai-import-grid-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    write_grid(
        &dir,
        "image: lab.pgm\nresolution: 0.050000\norigin: [-2.000000, -1.000000, 0.000000]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n",
    );
    let yaml = dir.join("lab.yaml");
    let out = dir.join("lab.json");
    let run = wai(
        &[
            "import-grid",
            yaml.to_str().unwrap(),
            "--min-hole-area",
            "0.003",
            "--out",
            out.to_str().unwrap(),
        ],
        b"",
    );
    let err = text(&run.stderr);
    assert!(run.status.success(), "{err}");
    assert!(err.contains("10 × 8 cells of 0.05 m"), "{err}");
    assert!(
        err.contains("1 enclosed obstacle(s) below 0.003 m² filled (1 cells)"),
        "{err}"
    );
    assert!(err.contains("2 hole(s), in metres"), "{err}");
    let info = wai(&["info", out.to_str().unwrap(), "--json"], b"");
    assert!(info.status.success(), "{}", text(&info.stderr));
    let v: serde_json::Value = serde_json::from_slice(&info.stdout).unwrap();
    assert_eq!(v["holes"], 2, "{v}");
    // 8 × 6 interior cells less the pillar (4) and the unknown pair (2),
    // of 1/400 m² each.
    assert_eq!(v["area"], "0.105", "{v}");
    assert_eq!(v["bounding_box"][0][0], "-1.95", "{v}");
    // It decomposes, pillars and all.
    let dec = wai(&["decompose", out.to_str().unwrap()], b"");
    assert!(dec.status.success(), "{}", text(&dec.stderr));
    assert!(
        text(&dec.stdout).contains("cells:"),
        "{}",
        text(&dec.stdout)
    );
    // A point in an obstacle, and bad metadata.
    let bad = wai(
        &["import-grid", yaml.to_str().unwrap(), "--at=-1.85,-0.75"],
        b"",
    );
    assert_eq!(bad.status.code(), Some(1));
    assert!(
        text(&bad.stderr).contains("which is not free"),
        "{}",
        text(&bad.stderr)
    );
    write_grid(
        &dir,
        "image: lab.pgm\nresolution: -0.05\norigin: [0, 0, 0]\noccupied_thresh: 0.65\nfree_thresh: 0.196\n",
    );
    let bad = wai(&["import-grid", yaml.to_str().unwrap()], b"");
    assert_eq!(bad.status.code(), Some(1));
    assert!(text(&bad.stderr).contains("resolution: -1/20 metres per cell: must be above 0"));
    write_grid(
        &dir,
        "image: lab.pgm\nresolution: 0.05\norigin: [0, 0, 0]\noccupied_thresh: 0.25\nfree_thresh: 0.65\n",
    );
    let bad = wai(&["import-grid", yaml.to_str().unwrap()], b"");
    assert!(text(&bad.stderr).contains("the thresholds are out of order"));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_map_from_the_intel_log_and_its_grid() {
    let log = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../data/datasets/laser/intel-corrected.log.gz");
    let dir = std::env::temp_dir().join(format!("wai-map-from-log-{}", std::process::id()));
    let out = dir.join("intel.json");
    let run = wai(
        &[
            "map-from-log",
            log.to_str().unwrap(),
            "--scans",
            "even",
            "--out",
            out.to_str().unwrap(),
            "--grid-out",
            dir.join("intel-grid").to_str().unwrap(),
        ],
        b"",
    );
    let err = text(&run.stderr);
    assert!(run.status.success(), "{err}");
    assert!(err.contains("455 scans of 910"), "{err}");
    // The map reads back, with holes, and so does the grid it came from.
    let info = wai(&["info", out.to_str().unwrap(), "--json"], b"");
    assert!(info.status.success(), "{}", text(&info.stderr));
    let v: serde_json::Value = serde_json::from_slice(&info.stdout).unwrap();
    assert!(v["holes"].as_u64().unwrap() > 0, "{v}");
    let again = wai(
        &[
            "import-grid",
            dir.join("intel-grid.yaml").to_str().unwrap(),
            "--min-hole-area",
            "0.05",
        ],
        b"",
    );
    assert!(again.status.success(), "{}", text(&again.stderr));
    let traced: serde_json::Value = serde_json::from_slice(&again.stdout).unwrap();
    let first: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&out).unwrap()).unwrap();
    // The pair written is the grid the map was traced from.
    assert!(traced["outer"] == first["outer"] && traced["holes"] == first["holes"]);
    let bad = wai(
        &[
            "map-from-log",
            dir.join("intel-grid.yaml").to_str().unwrap(),
        ],
        b"",
    );
    assert_eq!(bad.status.code(), Some(1));
    assert!(
        text(&bad.stderr).contains("no laser scan"),
        "{}",
        text(&bad.stderr)
    );
    std::fs::remove_dir_all(&dir).unwrap();
}
