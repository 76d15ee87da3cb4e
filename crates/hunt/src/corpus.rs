//! The fixed corpus of maps that `wai check --maps corpus` runs: the maps
//! of `counterexamples/` (the figures of the example claims, the stored
//! violations), every thesis family at parameters 1 to 6, the maps of
//! `data/datasets` that the cells tests decompose (R2V, Westport, AGPLIB
//! up to 60 vertices) and every free polyomino of up to 8 cells — in that
//! order, so that a run cut short by a budget has seen the rarest first.

/// The fixed corpus: the maps of `counterexamples/` (a stored violation is
/// reported again), the families at parameters 1..=6, the dataset maps and
/// the free polyominoes up to 8 cells. An error if a folder is missing
/// (the run must not pass on less than it says).
pub fn corpus_maps() -> Result<Vec<wai_map::Map>, String> {
    // The figures and violations of `counterexamples/`: some chapter 4
    // configurations (Figs 4.1, 4.2, 4.31) occur in none of the others.
    let repo = crate::repository::root()?;
    let stored = repo.join("counterexamples");
    let mut maps = maps_in(&stored, "counterexamples", usize::MAX)?;
    for f in wai_gen::FAMILIES {
        let before = maps.len();
        maps.extend((1..=6).filter_map(|k| {
            wai_gen::family(f.id, &[k])
                .ok()
                .map(|m| m.with_name(format!("{} k={k}", f.id)))
        }));
        if maps.len() == before {
            return Err(format!("family {} gave no map at parameters 1..=6", f.id));
        }
    }
    let root = repo.join("data/datasets");
    for (sub, max_n) in [
        ("r2v", usize::MAX),
        ("westport", usize::MAX),
        ("agplib/simple", 60),
        ("agplib/ortho", 60),
        ("agplib/vonkoch", 60),
    ] {
        let dir = root.join(sub);
        if !dir.is_dir() {
            return Err(format!(
                "{}: no such directory (the corpus reads the repository's data/datasets)",
                dir.display()
            ));
        }
        maps.extend(maps_in(&dir, sub, max_n)?);
    }
    maps.extend(
        wai_gen::exhaustive_polyomino_maps(8, wai_gen::Symmetry::Free)
            .enumerate()
            .map(|(i, m)| m.with_name(format!("polyomino #{i}"))),
    );
    Ok(maps)
}

/// The maps of the `*.json` files of `dir` (but `index.json`) with at most
/// `max_n` vertices, in file name order, named `label/FILE`.
pub fn maps_in(
    dir: &std::path::Path,
    label: &str,
    max_n: usize,
) -> Result<Vec<wai_map::Map>, String> {
    let mut files: Vec<std::path::PathBuf> = std::fs::read_dir(dir)
        .map_err(|e| format!("{}: {e}", dir.display()))?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "json") && !p.ends_with("index.json"))
        .collect();
    files.sort();
    let mut maps = Vec::new();
    for f in files {
        let map = read_map(&f)?;
        if map.n() <= max_n {
            let name = format!(
                "{label}/{}",
                f.file_name().unwrap_or_default().to_string_lossy()
            );
            maps.push(map.with_name(name));
        }
    }
    Ok(maps)
}

/// The map of a file in the JSON map format; errors name the file. A
/// sealed counterexample file must still match its digest
/// ([`crate::counterexample::verify`]); a map with holes is refused (the
/// claims of chapters 3–5 assume none).
pub fn read_map(f: &std::path::Path) -> Result<wai_map::Map, String> {
    let bytes = std::fs::read(f).map_err(|e| format!("{}: {e}", f.display()))?;
    crate::counterexample::verify(&bytes).map_err(|e| format!("{}: {e}", f.display()))?;
    let map = wai_map::json::from_json(&bytes)
        .map(|loaded| loaded.map)
        .map_err(|e| format!("{}: {e}", f.display()))?;
    map.require_no_holes("the claim checkers")
        .map_err(|e| format!("{}: {e}", f.display()))?;
    Ok(map)
}
