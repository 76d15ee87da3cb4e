//! The localizer against the brute-force oracle on many queries: over the stress corpus (polyominoes, families, datasets,
//! counterexamples) and seeded random and chapter 4 layout maps, views from
//! viewpoints in cells of every dimension (points on rays, 1- and 0-cells)
//! and random points; each answer must equal the brute force's and the
//! one-shot oracle's, contain
//! the viewpoint, and come with V's skeleton equal to the map-side one.
//!
//! `cargo run --release -p wai-benches --bin localize_agree -- [--random N]
//! [--cells K] [--points P] [--max-n N]`
//!
//! Prints progress, then the number of queries by kind of viewpoint and the
//! distribution of A (the number of answers). Exits 1 on the first
//! disagreement, printing the map as JSON and the viewpoint.

// The allocator of every binary of the workspace (see Cargo.toml).
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

use rayon::prelude::*;
use std::collections::BTreeMap;
use std::sync::atomic::{AtomicUsize, Ordering};
use wai_cells::Decomposition;
use wai_exact::RatPoint;
use wai_localize::{oracle, Localizer};
use wai_map::Map;
use wai_visibility::VisibilityIndex;

const USAGE: &str = "\
localize_agree: the exact localizer against the brute-force and one-shot oracles

usage: localize_agree [--random N] [--cells K] [--points P] [--max-n N]
  --random N  seeded random maps beyond the corpus (default 2000): every
              random kind, n from 8 to 40, and the chapter 4 layouts
  --cells K   viewpoints from at most K cells of every dimension per map,
              evenly spaced (default 200)
  --points P  random viewpoints per map (default 20)
  --max-n N   skip maps with more vertices (default 400)
";

fn arg(args: &[String], name: &str, default: usize) -> usize {
    args.iter()
        .position(|a| a == name)
        .and_then(|i| args.get(i + 1))
        .map_or(default, |v| {
            v.parse().unwrap_or_else(|_| {
                eprintln!("{name} takes a number\n{USAGE}");
                std::process::exit(2)
            })
        })
}

/// What one map's queries found.
#[derive(Default)]
struct Tally {
    queries: usize,
    by_kind: [usize; 4],
    answers: BTreeMap<usize, usize>,
    one_shot_sweeps: usize,
}

/// The viewpoints of a map: kind 0 = 2-cell, 1 = 1-cell, 2 = 0-cell,
/// 3 = random.
fn viewpoints(
    d: &Decomposition<'_>,
    cells: usize,
    points: usize,
    seed: u64,
) -> Vec<(u8, RatPoint)> {
    let mut out = Vec::new();
    let every = |len: usize| (len / cells.max(1)).max(1);
    let step = every(d.cells().len());
    out.extend(
        d.cells()
            .iter()
            .step_by(step)
            .map(|&c| (0, d.representative(c).clone())),
    );
    let step = every(d.lower_cells().len());
    out.extend(
        d.lower_cells()
            .iter()
            .step_by(step)
            .map(|c| (2 - c.dimension(), d.lower_representative(c))),
    );
    out.extend(
        wai_benches::viewpoints::small_denominator_points(d.map(), points, seed)
            .into_iter()
            .map(|p| (3, p)),
    );
    out
}

fn check(map: &Map, cells: usize, points: usize, seed: u64) -> Result<Tally, String> {
    let d = Decomposition::new(map);
    let loc = Localizer::from_decomposition(&d);
    let index = VisibilityIndex::new(map);
    let mut t = Tally::default();
    for (kind, p) in viewpoints(&d, cells, points, seed) {
        let c = oracle::cross_check(&loc, &index, &p).map_err(|e| {
            format!(
                "{}: at {p}: {e}\n{}",
                map.name().unwrap_or("map"),
                wai_map::json::to_json(map)
            )
        })?;
        let positions = c.answer.placements.len();
        t.one_shot_sweeps += c.one_shot_sweeps;
        t.queries += 1;
        t.by_kind[kind as usize] += 1;
        *t.answers.entry(positions).or_default() += 1;
    }
    Ok(t)
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.iter().any(|a| a == "--help" || a == "-h") {
        wai_output::out!("{USAGE}");
        return;
    }
    let random = arg(&args, "--random", 2000);
    let cells = arg(&args, "--cells", 200);
    let points = arg(&args, "--points", 20);
    let max_n = arg(&args, "--max-n", 400);
    let mut maps = wai_hunt::corpus::corpus_maps().unwrap_or_else(|e| {
        eprintln!("error: {e}");
        std::process::exit(1)
    });
    let kinds = wai_gen::RANDOM_KINDS;
    for i in 0..random {
        let seed = i as u64;
        let map = if i % 5 == 4 {
            let id = wai_gen::LAYOUTS[i / 5 % wai_gen::LAYOUTS.len()].id;
            wai_gen::layout(id, seed).map(|m| m.with_name(format!("{id} seed {seed}")))
        } else {
            let kind = kinds[i % kinds.len()].id;
            let n = 8 + i % 33;
            wai_gen::random(kind, n, seed).map(|m| m.with_name(format!("{kind} n={n} seed {seed}")))
        };
        maps.push(map.unwrap_or_else(|e| {
            eprintln!("error: generating map {i}: {e}");
            std::process::exit(1)
        }));
    }
    let skipped = maps.iter().filter(|m| m.n() > max_n).count();
    maps.retain(|m| m.n() <= max_n);
    let done = AtomicUsize::new(0);
    let total = maps.len();
    let start = std::time::Instant::now();
    let results: Vec<Result<Tally, String>> = maps
        .par_iter()
        .enumerate()
        .map(|(i, m)| {
            let r = check(m, cells, points, i as u64);
            let k = done.fetch_add(1, Ordering::Relaxed) + 1;
            if k.is_multiple_of(100) || k == total {
                eprintln!("{k}/{total} maps, {} s", start.elapsed().as_secs());
            }
            r
        })
        .collect();
    let mut sum = Tally::default();
    for r in results {
        match r {
            Ok(t) => {
                sum.queries += t.queries;
                sum.one_shot_sweeps += t.one_shot_sweeps;
                for k in 0..4 {
                    sum.by_kind[k] += t.by_kind[k];
                }
                for (a, c) in t.answers {
                    *sum.answers.entry(a).or_default() += c;
                }
            }
            Err(e) => {
                eprintln!("DISAGREEMENT: {e}");
                std::process::exit(1);
            }
        }
    }
    wai_output::outln!(
        "{total} maps ({skipped} over {max_n} vertices skipped), {} queries: the localizer, the brute force and the one-shot oracle agree on all",
        sum.queries
    );
    wai_output::outln!(
        "one-shot: {} directional sweeps of ray exits (one per spurious-edge direction of a view that reached test 4)",
        sum.one_shot_sweeps
    );
    wai_output::outln!(
        "viewpoints: {} in 2-cells, {} on 1-cells, {} on 0-cells, {} random",
        sum.by_kind[0],
        sum.by_kind[1],
        sum.by_kind[2],
        sum.by_kind[3]
    );
    let dist: Vec<String> = sum
        .answers
        .iter()
        .map(|(a, c)| format!("A={a}: {c}"))
        .collect();
    wai_output::outln!("answers: {}", dist.join(", "));
    wai_output::outln!("{} s", start.elapsed().as_secs());
}
