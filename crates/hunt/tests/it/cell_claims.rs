//! The visibility cell decomposition checkers (T3.3a, T3.3b, A3.6, T3.9a)
//! over generated maps, the thesis families, all free polyominoes up to 5
//! cells and the R2V floor plans: every claim examined, no violation of
//! T3.3a, T3.3b (restated for cells of every dimension) or T3.9a, and no
//! A3.6 violation other than its two known failures (a 1-cell, a 0-cell,
//! which its checker declares), which are printed with their counts.
//!
//! `cargo test -p wai-hunt --test it cell_claims -- --nocapture` prints
//! the summaries.

use std::collections::BTreeMap;
use std::path::PathBuf;

use wai_hunt::{run, FoundViolation};
use wai_lemmas::ch3::{a3_6, t3_3a, t3_3b, t3_9a};
use wai_map::Map;

const R2V: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../../data/datasets/r2v");

/// R2V maps in the sample: every `R2V_STEP`-th file in name order (1: all
/// 300; the whole set runs in a few seconds).
const R2V_STEP: usize = 1;

fn generated() -> Vec<Map> {
    let mut maps = Vec::new();
    for kind in wai_gen::RANDOM_KINDS {
        for n in [kind.min_n.max(8), 16, 24] {
            for seed in 0..2 {
                maps.push(wai_gen::random(kind.id, n, seed).expect("n within range"));
            }
        }
    }
    maps
}

fn families() -> Vec<Map> {
    let mut maps = Vec::new();
    for f in wai_gen::FAMILIES {
        let before = maps.len();
        for k in 1..=2 {
            // comb-convex-chain needs chain >= 2: its k = 1 is rejected.
            if let Ok(m) = wai_gen::family(f.id, &[k]) {
                maps.push(m);
            }
        }
        assert!(maps.len() > before, "family {} gave no map", f.id);
    }
    maps
}

fn r2v_sample() -> Vec<Map> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(R2V)
        .unwrap_or_else(|e| panic!("cannot read {R2V} ({e}): the run needs data/datasets"))
        .map(|e| e.expect("directory entry").path())
        .filter(|p| p.extension().is_some_and(|x| x == "json") && !p.ends_with("index.json"))
        .collect();
    files.sort();
    assert_eq!(files.len(), 300, "the R2V set has 300 maps");
    files
        .iter()
        .step_by(R2V_STEP)
        .map(|f| {
            let bytes = std::fs::read(f).expect("readable");
            let loaded =
                wai_map::json::from_json(&bytes).unwrap_or_else(|e| panic!("{}: {e}", f.display()));
            let name = f
                .file_stem()
                .expect("a file")
                .to_string_lossy()
                .into_owned();
            loaded.map.with_name(name)
        })
        .collect()
}

/// A known failure of the sec. 3.6 rule (A3.6): a 1-cell or a 0-cell.
fn is_known(v: &FoundViolation) -> bool {
    v.claim == "A3.6" && v.known
}

#[test]
fn cell_decomposition_claims_hold_everywhere() {
    let checkers = [
        t3_3a::CHECKER,
        t3_3b::CHECKER,
        a3_6::CHECKER,
        t3_9a::CHECKER,
        wai_lemmas::ch3::t3_9b::CHECKER,
        wai_lemmas::ch3::t3_10::CHECKER,
        wai_lemmas::ch5::t5_17::CHECKER,
    ];
    let mut failures = Vec::new();
    for (set, maps) in [
        ("generated", generated()),
        ("families", families()),
        (
            "polyominoes<=5",
            wai_gen::exhaustive_polyomino_maps(5, wai_gen::Symmetry::Free).collect(),
        ),
        ("r2v", r2v_sample()),
    ] {
        let start = std::time::Instant::now();
        let summary = run(&checkers, &maps);
        // The known failures of the sec. 3.6 rule, by kind.
        let mut conflicts: BTreeMap<String, usize> = BTreeMap::new();
        for v in summary.violations().filter(|v| is_known(v)) {
            let key = v.violation.data["kind"].as_str().unwrap_or("?").to_owned();
            *conflicts.entry(key).or_default() += 1;
        }
        let ray_max = summary
            .tally("T3.9a")
            .and_then(|t| t.largest.as_ref())
            .map_or_else(|| "none".to_owned(), |l| l.largest.ratio.to_string());
        println!(
            "== {set} ({} maps, {:.1?}):\n{}   T3.9a: the fullest ray holds {} of 2n interior \
             vertices\n   A3.6 known failures: {conflicts:?}",
            maps.len(),
            start.elapsed(),
            summary
                .to_string()
                .lines()
                .filter(|l| !l.starts_with("VIOLATION A3.6") || !l.contains("fails-on-"))
                .map(|l| format!("{l}\n"))
                .collect::<String>(),
            ray_max,
        );
        for id in ["T3.3a", "T3.3b", "A3.6", "T3.9a"] {
            let tally = summary.tally(id).expect("every checker has a tally");
            if tally.examined == 0 {
                failures.push(format!("{set}: {id} examined nothing"));
            }
        }
        failures.extend(summary.violations().filter(|v| !is_known(v)).map(|v| {
            format!(
                "{set}: {} on {}: {}\n{}",
                v.claim,
                v.map_name.as_deref().unwrap_or("unnamed"),
                v.violation.what,
                v.violation.data
            )
        }));
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
