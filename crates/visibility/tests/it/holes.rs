//! The triangulation of maps with holes: bridges, then ear clipping, checked
//! on random holed maps, the AGPLIB maps with holes and grid-traced rooms.

use wai_map::json::{from_json_with, ReadOptions};
use wai_map::Map;
use wai_visibility::bridged_ring;
use wai_visibility::Triangulation;

fn check(map: &Map, what: &str) {
    let ring = bridged_ring(map);
    // Every vertex once, the two ends of each bridge twice.
    assert_eq!(ring.len(), map.n() + 2 * map.hole_count(), "{what}");
    let t = Triangulation::new(map);
    t.sanity_check(map)
        .unwrap_or_else(|e| panic!("{what}: {e}"));
}

#[test]
fn random_maps_with_holes() {
    let mut maps = 0;
    for kind in wai_gen::HOLED_KINDS {
        for seed in 0..60 {
            for (n, h) in [(6, 1), (12, 3), (24, 8), (60, 15)] {
                let map = wai_gen::random_with_holes(kind.id, n, h, seed).unwrap();
                check(&map, &format!("{} n={n} h={h} seed={seed}", kind.id));
                maps += 1;
            }
        }
    }
    assert_eq!(maps, 480);
}

#[test]
fn pillars_in_line_with_each_other_and_the_walls() {
    // Rays from each pillar's rightmost corner run along the next pillar's
    // edges and through the walls' corners: every tie at once.
    let text = r#"{"outer": [["0","0"],["20","0"],["20","4"],["14","4"],["14","8"],["20","8"],["20","12"],["0","12"]],
        "holes": [[["2","2"],["2","4"],["4","4"],["4","2"]],
                  [["6","2"],["6","4"],["8","4"],["8","2"]],
                  [["10","2"],["10","4"],["12","4"],["12","2"]],
                  [["6","6"],["6","8"],["8","8"],["8","6"]],
                  [["10","8"],["10","10"],["12","10"],["12","8"]],
                  [["2","8"],["2","10"],["4","10"],["4","8"]]]}"#;
    let map = wai_map::json::from_json(text.as_bytes()).unwrap().map;
    check(&map, "aligned pillars");
}

#[test]
fn agplib_maps_with_holes() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../data/datasets/agplib");
    let mut maps = 0;
    for family in ["simple-holes", "ortho-holes"] {
        let mut files: Vec<_> = std::fs::read_dir(dir.join(family))
            .unwrap()
            .map(|e| e.unwrap().path())
            .filter(|p| p.extension().is_some_and(|e| e == "json"))
            .collect();
        files.sort();
        for f in files {
            let bytes = std::fs::read(&f).unwrap();
            let map = from_json_with(
                &bytes,
                &ReadOptions {
                    grid_bits: Some(60),
                },
            )
            .unwrap()
            .map;
            check(&map, &f.display().to_string());
            maps += 1;
        }
    }
    assert_eq!(maps, 36);
}
