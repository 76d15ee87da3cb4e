#![allow(
    clippy::float_arithmetic,
    reason = "elapsed seconds for the progress line"
)]
//! The stress run: every claim that has a checker, over many seeded random
//! and orthogonal maps (n ≤ 30).
//!
//! `cargo run --release -p wai-lemmas --bin stress -- [--maps N] [--start S]
//! [--repeated | --bottles | --interweave]`, `-- --files MAP...` or
//! `-- --corpus`
//!
//! Map i is `wai_gen::random(kind, n, seed = S + i)` with the kind cycling
//! through every random kind and n cycling through 8..=30; with
//! `--repeated` it is `wai_gen::repeated_niches(S + i)` instead, maps whose
//! repeated funnels and niches give overlapping embeddings of one skeleton
//! (the chapter 4 claims examine nothing on most random maps), and with
//! `--bottles` it is `wai_gen::bottled_niches(S + i)`, whose overlapping
//! embeddings have artificial edges with several valid candidate edges
//! that cross (Fig 4.31: Theorem 4.19, Corollary 4.20), and with
//! `--interweave` it cycles through `wai_gen::interweaved_gaps`,
//! `wai_gen::shared_niches` and `wai_gen::shared_spiked_niches` (S + i),
//! whose gaps are interweaved and nested (Fig 5.5: L5.5–L5.9) and whose
//! pairs of candidate edges are shared by several embeddings (Figs
//! 5.13–5.16: L5.13, L5.14, T5.15). With `--files`
//! the maps are the given map files. With `--corpus`
//! the maps are instead the fixed corpus of issue 7's acceptance: every free
//! polyomino of up to 8 cells, every thesis family at parameters 1 to 6,
//! every map of `shared/datasets` that the cells tests decompose (R2V,
//! Westport, AGPLIB up to 60 vertices) and the maps of `counterexamples/`.
//! Prints progress,
//! then per claim the instances examined and the violations; the known
//! failures of the sec. 3.6 rule (claim A3.6: 1-cells such as
//! `counterexamples/T3.3b-doorway-1d-cell.json`, and 0-cells) are counted
//! apart, by kind. Exits 1 on any other violation, printing the map as JSON
//! to replay it.

// The allocator of every binary of the workspace (see Cargo.toml).
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

use rayon::prelude::*;
use std::collections::BTreeMap;
use wai_lemmas::corpus::{corpus_maps, read_map};
use wai_lemmas::{run, Checker, Status, CLAIMS};

fn arg(args: &[String], name: &str, default: u64) -> u64 {
    args.iter()
        .position(|a| a == name)
        .and_then(|i| args.get(i + 1))
        .map_or(default, |v| {
            v.parse()
                .unwrap_or_else(|_| panic!("{name} takes a number"))
        })
}

const USAGE: &str = "\
stress: every claim checker over seeded random maps (n from 8 to 30, every random kind)

usage: stress [--maps N] [--start S] [--repeated | --bottles | --interweave] [--claims L]
       stress --corpus [--claims L]
       stress --files MAP... [--claims L]
  --maps N    how many maps (default 10000)
  --start S   the first seed (default 0)
  --repeated  the maps are wai_gen::repeated_niches(S + i): repeated funnels
              and niches, with overlapping embeddings (chapter 4)
  --bottles   the maps are wai_gen::bottled_niches(S + i): rooms under
              bottled niches, whose artificial edges have several valid
              candidate edges that cross (Fig 4.31; T4.19, C4.20)
  --interweave  map i is wai_gen::interweaved_gaps, shared_niches or
              shared_spiked_niches(S + i) by i mod 3: interweaved and nested
              gaps (Fig 5.5; L5.5-L5.9), candidate edges shared by several
              embeddings (Figs 5.13-5.16; L5.13, L5.14, T5.15)
  --claims L  only the checkers of the comma-separated claim ids L
  --corpus    instead: all free polyominoes up to 8 cells, the families at
              parameters 1..=6, the dataset maps (needs ../shared/datasets)
              and the maps of counterexamples/
  --files     instead: the map files that follow (JSON map format)
  --largest D write, per claim that measures a ratio, the map of its
              largest ratio to D/<claim>-largest.json (replayable with
              --files)
  -h, --help  this text

Prints per claim the instances examined; exits 1 on a violation other than
the known failures of the sec. 3.6 rule (claim A3.6).";

/// Says what is wrong and exits 2.
fn fail(what: &str) -> ! {
    eprintln!("stress: {what}");
    std::process::exit(2);
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    if args.iter().any(|a| a == "-h" || a == "--help") {
        println!("{USAGE}");
        return;
    }
    let corpus = args.iter().any(|a| a == "--corpus");
    let repeated = args.iter().any(|a| a == "--repeated");
    let bottles = args.iter().any(|a| a == "--bottles");
    let interweave = args.iter().any(|a| a == "--interweave");
    let start = arg(&args, "--start", 0);
    let largest_dir: Option<String> =
        args.iter()
            .position(|a| a == "--largest")
            .map(|i| match args.get(i + 1) {
                Some(d) if !d.starts_with("--") => d.clone(),
                _ => fail("--largest wants a directory"),
            });
    let files: Vec<&String> = args
        .iter()
        .skip_while(|a| *a != "--files")
        .skip(1)
        .take_while(|a| !a.starts_with("--"))
        .collect();
    let all: Vec<wai_map::Map> = if !files.is_empty() {
        files
            .iter()
            .map(|f| {
                let map = read_map(std::path::Path::new(f)).unwrap_or_else(|e| {
                    eprintln!("stress: {e}");
                    std::process::exit(2);
                });
                let name = map.name().map_or_else(|| (*f).clone(), str::to_owned);
                map.with_name(name)
            })
            .collect()
    } else if corpus {
        corpus_maps().unwrap_or_else(|e| {
            eprintln!("stress: {e}");
            std::process::exit(2);
        })
    } else if repeated {
        (0..arg(&args, "--maps", 10_000))
            .map(|j| wai_gen::repeated_niches(start + j))
            .collect()
    } else if bottles {
        (0..arg(&args, "--maps", 10_000))
            .map(|j| wai_gen::bottled_niches(start + j))
            .collect()
    } else if interweave {
        let layouts = [
            wai_gen::interweaved_gaps,
            wai_gen::shared_niches,
            wai_gen::shared_spiked_niches,
        ];
        (0..arg(&args, "--maps", 10_000))
            .map(|j| layouts[(j % 3) as usize](start + j))
            .collect()
    } else {
        let kinds = wai_gen::RANDOM_KINDS;
        (0..arg(&args, "--maps", 10_000))
            .map(|j| {
                let kind = &kinds[(j % kinds.len() as u64) as usize];
                let n = (8 + (j / kinds.len() as u64) % 23) as usize;
                let n = n.clamp(kind.min_n, kind.max_n);
                let seed = start + j;
                wai_gen::random(kind.id, n, seed)
                    .expect("sizes within the kind's range")
                    .with_name(format!("{} n={n} seed={seed}", kind.id))
            })
            .collect()
    };
    let total = all.len() as u64;
    // --claims ID,ID,…: only those claims' checkers.
    let only: Option<Vec<String>> = args
        .iter()
        .position(|a| a == "--claims")
        .and_then(|i| args.get(i + 1))
        .map(|v| v.split(',').map(str::to_owned).collect());
    if let Some(ids) = &only {
        for id in ids {
            match wai_lemmas::claim(id) {
                Some(c) if matches!(c.status, Status::Checker(_)) => {}
                Some(_) => {
                    eprintln!("stress: claim {id} has no checker yet");
                    std::process::exit(2);
                }
                None => {
                    eprintln!("stress: no claim {id} in the registry");
                    std::process::exit(2);
                }
            }
        }
    }
    let make_checkers = || -> Vec<Box<dyn Checker>> {
        CLAIMS
            .iter()
            .filter(|c| {
                only.as_ref()
                    .is_none_or(|ids| ids.iter().any(|i| i == c.id))
            })
            .filter_map(|c| match c.status {
                Status::Checker(make) => Some(make()),
                Status::NoCheckerYet => None,
            })
            .collect()
    };
    let mut examined: BTreeMap<&'static str, u64> = BTreeMap::new();
    let mut counts: BTreeMap<(&'static str, &'static str), u64> = BTreeMap::new();
    // Maps on which each claim examined something.
    let mut maps_with: BTreeMap<&'static str, u64> = BTreeMap::new();
    // The largest ratio of each claim that measures one, and its map.
    let mut largest: BTreeMap<&'static str, wai_lemmas::FoundLargest> = BTreeMap::new();
    let mut conflicts: BTreeMap<String, u64> = BTreeMap::new();
    let mut others = 0u64;
    let batch = 100u64;
    let t = std::time::Instant::now();
    let mut i = 0u64;
    while i < total {
        let maps = &all[i as usize..(i + batch).min(total) as usize];
        // One map per task: the checkers are cheap to make and a study is
        // per map.
        let summaries: Vec<wai_lemmas::Summary> = maps
            .par_iter()
            .map(|m| {
                let checkers = make_checkers();
                let refs: Vec<&dyn Checker> = checkers.iter().map(AsRef::as_ref).collect();
                run(&refs, [m])
            })
            .collect();
        for summary in &summaries {
            for tally in &summary.tallies {
                *examined.entry(tally.claim).or_default() += tally.examined;
                *maps_with.entry(tally.claim).or_default() += u64::from(tally.examined > 0);
                for (name, by) in &tally.counts {
                    *counts.entry((tally.claim, name)).or_default() += by;
                }
                if let Some(l) = &tally.largest {
                    if largest
                        .get(tally.claim)
                        .is_none_or(|best| l.largest.ratio > best.largest.ratio)
                    {
                        largest.insert(tally.claim, l.clone());
                    }
                }
            }
            for v in summary.violations() {
                let kind = v.violation.data["kind"].as_str().unwrap_or("");
                if wai_lemmas::is_known_failure(v.claim, &v.violation.data) {
                    *conflicts.entry(format!("{} {kind}", v.claim)).or_default() += 1;
                } else {
                    others += 1;
                    if others <= 5 {
                        println!(
                            "VIOLATION {} on {}: {}",
                            v.claim,
                            v.map_name.as_deref().unwrap_or("unnamed"),
                            v.violation.what
                        );
                        println!("{}", v.violation.data);
                        println!("{}", v.map_json);
                    }
                }
            }
        }
        i = (i + batch).min(total);
        eprint!(
            "\rstress: {i}/{total} maps, {:.0} s",
            t.elapsed().as_secs_f64()
        );
    }
    eprintln!();
    if !files.is_empty() {
        println!(
            "stress: {total} map files, {:.1} s",
            t.elapsed().as_secs_f64()
        );
    } else if corpus {
        println!(
            "stress: the corpus, {total} maps (polyominoes <= 8, families, datasets, counterexamples), {:.1} s",
            t.elapsed().as_secs_f64()
        );
    } else {
        println!(
            "stress: {total} {}maps (seeds {start}..{}), {:.1} s",
            if repeated {
                "repeated-niches "
            } else if bottles {
                "bottled-niches "
            } else if interweave {
                "interweave (gaps, shared niches) "
            } else {
                ""
            },
            start + total,
            t.elapsed().as_secs_f64()
        );
    }
    for (claim, count) in &examined {
        print!(
            "  {claim:<6} examined {count} (on {} maps)",
            maps_with.get(claim).copied().unwrap_or(0)
        );
        let extra: Vec<String> = counts
            .iter()
            .filter(|((c, _), _)| c == claim)
            .map(|((_, name), by)| format!("{name} {by}"))
            .collect();
        if !extra.is_empty() {
            print!("; {}", extra.join(", "));
        }
        if let Some(l) = largest.get(claim) {
            print!(
                "; largest ratio {} (≈ {:.4}) on {} at {}",
                l.largest.ratio,
                l.largest.ratio.to_f64(),
                l.map_name.as_deref().unwrap_or("an unnamed map"),
                l.largest.at
            );
        }
        println!();
    }
    if let Some(dir) = &largest_dir {
        std::fs::create_dir_all(dir).unwrap_or_else(|e| fail(&format!("{dir}: {e}")));
        for (claim, l) in &largest {
            let path = format!("{dir}/{claim}-largest.json");
            std::fs::write(&path, &l.map_json).unwrap_or_else(|e| fail(&format!("{path}: {e}")));
        }
        println!("  the map of each largest ratio: {dir}/<claim>-largest.json");
    }
    for id in examined.iter().filter(|(_, &c)| c == 0).map(|(id, _)| id) {
        println!("  {id}: examined nothing in this run — NOT TESTED");
    }
    println!("  known failures (A3.6: the sec. 3.6 rule on 1- and 0-cells; O5.3: edges on rays from hidden vertices), not counted below:");
    for (what, count) in &conflicts {
        println!("    {what}: {count}");
    }
    println!("  other violations: {others}");
    if others > 0 {
        std::process::exit(1);
    }
}
