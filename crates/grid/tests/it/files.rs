//! The `map_server` pair on disk: read, traced, refused when bad.

use std::path::PathBuf;
use wai_grid::pgm::to_pgm;
use wai_grid::{import, GridError, ImportOptions};

fn dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("wai-grid-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

const YAML: &str = "image: room.pgm\nresolution: 0.05\norigin: [-1.0, -2.0, 0.0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n";

#[test]
fn a_pair_on_disk_is_imported_with_its_name_and_source() {
    let d = dir("pair");
    let img = crate::image(&["#####", "#...#", "#.#.#", "#...#", "#####"]);
    std::fs::write(d.join("room.pgm"), to_pgm(&img)).unwrap();
    std::fs::write(d.join("lab.yaml"), YAML).unwrap();
    let got = import(&d.join("lab.yaml"), &ImportOptions::default()).unwrap();
    assert_eq!(got.map.name(), Some("lab"));
    assert_eq!(
        got.map.source(),
        Some("occupancy grid room.pgm (5 × 5 cells of 0.05 m, origin (-1, -2))")
    );
    assert_eq!((got.map.n(), got.map.hole_count()), (8, 1));
    // Too many cells for the limit: refused before the pixels are read.
    let small = ImportOptions {
        max_cells: 20,
        ..ImportOptions::default()
    };
    let e = import(&d.join("lab.yaml"), &small).unwrap_err();
    assert!(matches!(e, GridError::TooLarge { cells: 25, .. }), "{e}");
    assert!(e.to_string().contains("--max-cells"), "{e}");
    // A missing image names the file.
    std::fs::write(d.join("gone.yaml"), YAML.replace("room.pgm", "gone.pgm")).unwrap();
    let e = import(&d.join("gone.yaml"), &ImportOptions::default()).unwrap_err();
    assert!(e.to_string().contains("gone.pgm"), "{e}");
    let e = import(&d.join("absent.yaml"), &ImportOptions::default()).unwrap_err();
    assert!(e.to_string().contains("absent.yaml"), "{e}");
    std::fs::remove_dir_all(&d).unwrap();
}
