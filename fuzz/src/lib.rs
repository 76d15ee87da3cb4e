//! What the fuzz targets share: the claims check of one chapter on a map
//! built from bytes, with the planted bug of `WAI_PLANT` swapped in, and
//! the replay file written before a violation panics.
//!
//! The maps come from [`wai_gen::bytes::map_from_bytes`]: valid by
//! construction and small, so every checker runs on every input; a target
//! never returns early on an invalid map.
//!
//! # Invariant
//! A target panics only where a law or a claim fails: never on input it
//! cannot use (the byte stream always makes a map).

use std::path::PathBuf;
use std::sync::OnceLock;

use arbitrary::Unstructured;
use wai_hunt::FoundViolation;
use wai_lemmas::{planted, Checker};
use wai_map::Map;

/// mimalloc for Rust's allocations, and (its `override` feature, set in
/// `fuzz/Cargo.toml`) for GMP's, which otherwise go through glibc's
/// malloc: a `RatPoint` holds three GMP integers, and the claims' exact
/// arithmetic spent a fifth of its time allocating them.
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

/// Runs `f` on [`wai_hunt::own_thread_pool`], built on libFuzzer's
/// thread at the first input. libFuzzer runs one input at a time (parallel
/// fuzzing is `-jobs`/`-workers`, one process each), always on that thread.
pub fn inline<R: Send>(f: impl FnOnce() -> R + Send) -> R {
    static POOL: OnceLock<Option<rayon::ThreadPool>> = OnceLock::new();
    let pool = POOL.get_or_init(wai_hunt::own_thread_pool);
    match pool {
        Some(pool) => pool.install(f),
        None => f(),
    }
}

/// The map of the fuzz input, or `None` if the bytes make none
/// (`map_from_bytes` reads missing bytes as zeros, so this is rare).
pub fn map_of(data: &[u8]) -> Option<(Map, Unstructured<'_>)> {
    let mut u = Unstructured::new(data);
    let map = wai_gen::bytes::map_from_bytes(&mut u).ok()?;
    Some((map, u))
}

/// The planted bug named by the environment variable `WAI_PLANT` (one of
/// [`planted::PLANTED`]), read once; `None` when it is unset or empty.
///
/// # Panics
/// If `WAI_PLANT` names no planted bug: a misspelt name must not make a
/// fuzz run that silently tests nothing planted.
pub fn planted_name() -> Option<&'static str> {
    static PLANT: OnceLock<Option<&'static str>> = OnceLock::new();
    *PLANT.get_or_init(|| {
        let name = std::env::var("WAI_PLANT").ok().filter(|s| !s.is_empty())?;
        match planted::PLANTED.iter().find(|p| p.name == name) {
            Some(p) => Some(p.name),
            None => panic!(
                "WAI_PLANT={name:?} is not a planted bug (known: {:?})",
                planted::names()
            ),
        }
    })
}

/// The checkers of every claim of `chapter`, with the planted checker of
/// `WAI_PLANT` instead of the real one of its claim when its claim is of
/// this chapter.
pub fn checkers(chapter: u8) -> Vec<Checker> {
    let of_chapter = wai_lemmas::checkers_of_chapter(chapter).into_iter();
    planted::swap_in(of_chapter, planted_name().and_then(planted::checker)).collect()
}

/// Runs every checker of `chapter` (see [`checkers`]) on the map of
/// `data`.
///
/// # Panics
/// On a violation that is not one of its checker's known failures, after
/// writing its replay file
/// ([`write_replay`]); the message names the claim, what broke, the map
/// and the replay command.
pub fn check_claims(chapter: u8, data: &[u8]) {
    let Some((map, _)) = map_of(data) else { return };
    let summary = inline(|| wai_hunt::run(&checkers(chapter), [&map]));
    let Some(v) = summary.counterexamples().next() else {
        return;
    };
    let target = format!("claims_ch{chapter}");
    let replay = match write_replay(v, &target) {
        Ok(path) => path.display().to_string(),
        Err(e) => format!("(could not write the replay file: {e})"),
    };
    panic!(
        "claim {} violated on map {:?}: {}\n\
         replay file: {replay}\n\
         replay with: wai check --replay {replay}\n\
         (cargo run --release -p wai-cli -- check --replay {replay}){planted}",
        v.claim,
        v.map_name.as_deref().unwrap_or("unnamed"),
        v.violation.what,
        planted = planted_name()
            .map(|n| format!("\nthe planted bug {n} (WAI_PLANT) was running"))
            .unwrap_or_default(),
    );
}

/// The directory of replay files: `fuzz/artifacts/replay/`.
pub fn replay_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("artifacts/replay")
}

/// The replay file of a violation, in the format of `counterexamples/`
/// (its README, written by [`wai_hunt::counterexample::file_text`]): the
/// map with `claim`, `kind: "violation"`, a `note` saying it is not known
/// yet whether the thesis or our code is wrong, a `source` naming the
/// target, and the checker's data under `meta`.
pub fn replay_json(v: &FoundViolation, target: &str) -> String {
    let map = wai_map::json::from_json(v.map_json.as_bytes())
        .unwrap_or_else(|e| panic!("FoundViolation::map_json reads back: {e}"))
        .map;
    let map_name = v.map_name.as_deref().unwrap_or("unnamed");
    // `check.planted` is where `wai check --replay` looks for the planted
    // bug to run instead of the claim's checker.
    let meta = serde_json::json!({
        "what": v.violation.what,
        "data": v.violation.data,
        "check": { "planted": planted_name(), "target": target },
    });
    wai_hunt::counterexample::file_text(
        &map,
        map_name,
        &format!("cargo fuzz target {target}, map {map_name}"),
        v.claim,
        "violation",
        &format!(
            "Found by the fuzz target {target}: {}. Whether the thesis or our code \
             is wrong is not known yet.",
            v.violation.what
        ),
        &meta,
    )
}

/// Writes [`replay_json`] to [`replay_dir`]`/<claim>-<hash>.json`, the hash
/// of the file's text, and returns its path.
pub fn write_replay(v: &FoundViolation, target: &str) -> std::io::Result<PathBuf> {
    use std::hash::{Hash, Hasher};
    let text = replay_json(v, target);
    // SipHash with fixed keys: the same file gets the same name.
    let mut h = std::collections::hash_map::DefaultHasher::new();
    text.hash(&mut h);
    let dir = replay_dir();
    std::fs::create_dir_all(&dir)?;
    let path = dir.join(format!("{}-{:016x}.json", v.claim, h.finish()));
    std::fs::write(&path, text)?;
    Ok(path)
}

/// A random map with holes from bytes: the kind (`orthogonal-pillars` or
/// `simple-holes`, the random kinds of [`wai_gen::HOLED_KINDS`]; the
/// layout-based kinds are too slow to fuzz), n in 6..=17, 1 to 3 holes, and
/// a seed from the next eight bytes.
pub fn holed_map_of(data: &[u8]) -> Option<Map> {
    let mut u = Unstructured::new(data);
    let kind = ["orthogonal-pillars", "simple-holes"][usize::from(u.arbitrary::<u8>().ok()? % 2)];
    let n = 6 + usize::from(u.arbitrary::<u8>().ok()? % 12);
    let holes = 1 + usize::from(u.arbitrary::<u8>().ok()? % 3);
    let seed = u.arbitrary::<u64>().unwrap_or(0);
    wai_gen::random_with_holes(kind, n, holes, seed).ok()
}

/// The `holes` target: every claim checker on a map with holes (thesis sec.
/// 6.4). The claims assume a map without holes, so their violations there
/// are findings (`wai check --maps holes` reports them), not failures; the
/// law is that no checker panics and that a checker which walks one ring
/// ([`wai_lemmas::Rings::Outer`]) examines nothing.
///
/// # Panics
/// On a checker's panic, after writing its replay file.
pub fn check_holes(data: &[u8]) {
    let Some(map) = holed_map_of(data) else {
        return;
    };
    let all: Vec<Checker> = wai_lemmas::checkers().collect();
    let summary = inline(|| wai_hunt::run(&all, [&map]));
    for c in all.iter().filter(|c| !c.examines(&map)) {
        let tally = summary.tallies.iter().find(|t| t.claim == c.id);
        assert!(
            tally.is_none_or(|t| t.examined == 0),
            "{} walks one ring but examined {:?} instances on the holed map {:?}",
            c.id,
            tally.map(|t| t.examined),
            map.name()
        );
    }
    let Some(v) = summary
        .counterexamples()
        .find(|v| v.violation.data["kind"] == "panic")
    else {
        return;
    };
    let replay = match write_replay(v, "holes") {
        Ok(path) => path.display().to_string(),
        Err(e) => format!("(could not write the replay file: {e})"),
    };
    panic!(
        "the checker of {} panicked on the holed map {:?}: {}\nreplay file: {replay}\nreplay with: wai check --replay {replay}",
        v.claim,
        v.map_name.as_deref().unwrap_or("unnamed"),
        v.violation.what,
    );
}
