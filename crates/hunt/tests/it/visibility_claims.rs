//! The chapter 3 visibility checkers (L3.1a, L3.1b, L3.1c, D3.5, T3.2) over
//! generated maps, the thesis families, all free polyominoes up to 6 cells
//! and the R2V floor plans: no violation, and every claim examined.
//!
//! `cargo test -p wai-hunt --test it visibility_claims -- --nocapture`
//! prints the summary with the examined counts.

use std::path::PathBuf;

use wai_hunt::run;
use wai_lemmas::ch3::t3_2;
use wai_lemmas::ch3::{d3_5, l3_1a, l3_1b, l3_1c};
use wai_lemmas::{Checker, Report};
use wai_map::Map;
use wai_study::Study;
use wai_visibility::VisibilityPolygon;

/// Viewpoints per map (more than the checkers' default).
const VIEWPOINTS: usize = 12;

/// The per-polygon check `check` of claim `id` on [`VIEWPOINTS`] sampled
/// viewpoints.
fn sampled(
    id: &'static str,
    study: &Study<'_>,
    check: fn(&Map, &VisibilityPolygon) -> Report,
) -> Report {
    let mut report = Report::new(id);
    for vp in study.sampled_polygons(VIEWPOINTS).iter() {
        report.absorb(check(study.map(), vp));
    }
    report
}

const R2V: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../../data/datasets/r2v");

fn generated() -> Vec<Map> {
    let mut maps = Vec::new();
    for kind in wai_gen::RANDOM_KINDS {
        for n in [kind.min_n.max(8), 20, 36] {
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
        for k in 1..=3 {
            // comb-convex-chain needs chain >= 2: its k = 1 is rejected.
            if let Ok(m) = wai_gen::family(f.id, &[k]) {
                maps.push(m);
            }
        }
        assert!(
            maps.len() >= before + 2,
            "family {} gave too few maps",
            f.id
        );
    }
    maps
}

fn r2v() -> Vec<Map> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(R2V)
        .unwrap_or_else(|e| panic!("cannot read {R2V} ({e}): the run needs data/datasets"))
        .map(|e| e.expect("directory entry").path())
        .filter(|p| p.extension().is_some_and(|x| x == "json") && !p.ends_with("index.json"))
        .collect();
    files.sort();
    let maps: Vec<Map> = files
        .iter()
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
        .collect();
    assert_eq!(maps.len(), 300, "the R2V set has 300 maps");
    maps
}

#[test]
fn chapter_3_visibility_claims_hold_everywhere() {
    let checkers = [
        Checker {
            check: |s| sampled("L3.1a", s, l3_1a::check_polygon),
            ..l3_1a::CHECKER
        },
        Checker {
            check: |s| sampled("L3.1b", s, l3_1b::check_polygon),
            ..l3_1b::CHECKER
        },
        Checker {
            check: |s| sampled("L3.1c", s, l3_1c::check_polygon),
            ..l3_1c::CHECKER
        },
        Checker {
            check: |s| sampled("D3.5", s, d3_5::check_polygon),
            ..d3_5::CHECKER
        },
        Checker {
            check: |s| t3_2::check_viewpoints(s, VIEWPOINTS),
            ..t3_2::CHECKER
        },
    ];
    let ids: Vec<&str> = checkers.iter().map(|c| c.id).collect();
    let mut failures = Vec::new();
    for (set, maps) in [
        ("generated", generated()),
        ("families", families()),
        (
            "polyominoes<=6",
            wai_gen::exhaustive_polyomino_maps(6, wai_gen::Symmetry::Free).collect(),
        ),
        ("r2v", r2v()),
    ] {
        let summary = run(&checkers, &maps);
        // T3.2 across embeddings: how often the premise held.
        let t32 = summary.tally("T3.2").expect("T3.2 ran");
        let case = |c: &str| t32.cases.get(c).copied().unwrap_or(0);
        println!(
            "== {set}: {summary}   T3.2: {} viewpoints rebuilt; {} translated into another \
             embedding met in the sample, {} onto another reflex vertex; {} of the translates \
             with the same skeleton\n",
            case(t3_2::REBUILD),
            case(t3_2::ACROSS),
            case(t3_2::TRANSLATE),
            case(t3_2::IF)
        );
        if set == "families" {
            assert!(
                case(t3_2::IF) > 0,
                "no pair of viewpoints in different embeddings of one skeleton"
            );
        }
        for id in &ids {
            let tally = summary.tally(id).expect("every checker has a tally");
            if tally.examined == 0 {
                failures.push(format!("{set}: {id} examined nothing"));
            }
        }
        failures.extend(summary.violations().map(|v| {
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
