//! Every map of `data/datasets/r2v` and `westport`, and the AGPLIB maps of
//! up to 60 vertices (dyadic and rational coordinates: the exact path),
//! decompose exactly: the arrangement passes its sanity checks, every
//! cell has a skeleton, and the skeletons the walk gives (sec. 3.9.2) are
//! those of fresh visibility queries on every cell of every dimension.

use std::path::PathBuf;
use wai_cells::Decomposition;

fn maps_in(sub: &str, max_n: usize) -> Vec<(String, wai_map::Map)> {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../data/datasets")
        .join(sub);
    assert!(
        dir.is_dir(),
        "{} is missing: the tests read the repository's data/datasets",
        dir.display()
    );
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "json") && !p.ends_with("index.json"))
        .collect();
    files.sort();
    files
        .into_iter()
        .map(|f| {
            let map = wai_map::json::from_json(&std::fs::read(&f).unwrap())
                .unwrap()
                .map;
            (f.file_name().unwrap().to_string_lossy().into_owned(), map)
        })
        .filter(|(_, m)| m.n() <= max_n)
        .collect()
}

fn check(sub: &str, max_n: usize, expect_maps: usize) {
    let maps = maps_in(sub, max_n);
    assert_eq!(maps.len(), expect_maps, "{sub}");
    let mut cells = 0;
    for (name, map) in &maps {
        let d = Decomposition::new(map);
        d.arrangement()
            .sanity_check()
            .unwrap_or_else(|e| panic!("{sub}/{name}: {e}"));
        crate::incremental::compare(map)
            .unwrap_or_else(|e| panic!("{sub}/{name}: the walk and the query differ: {e}"));
        let c = d.counts();
        assert_eq!(
            d.classes().iter().map(Vec::len).sum::<usize>(),
            c.cells,
            "{name}"
        );
        cells += c.cells;
    }
    assert!(cells > maps.len(), "{sub}: {cells} cells");
}

#[test]
fn r2v_maps_decompose() {
    check("r2v", usize::MAX, 300);
}

#[test]
fn westport_maps_decompose() {
    check("westport", usize::MAX, 7);
}

#[test]
fn agplib_maps_up_to_60_vertices_decompose() {
    check("agplib/simple", 60, 12);
    check("agplib/ortho", 60, 12);
    check("agplib/vonkoch", 60, 12);
}
