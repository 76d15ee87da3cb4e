#![allow(
    clippy::float_arithmetic,
    reason = "elapsed seconds for the progress line"
)]
//! The stress run: every claim that has a checker, over many seeded random
//! and orthogonal maps (n ≤ 30).
//!
//! `cargo run --release -p wai-lemmas --bin stress -- [--maps N] [--start S]`
//!
//! Map i is `wai_gen::random(kind, n, seed = S + i)` with the kind cycling
//! through every random kind and n cycling through 8..=30. Prints progress,
//! then per claim the instances examined and the violations; the known
//! failures of the sec. 3.6 rule (claim A3.6: 1-cells such as
//! `counterexamples/T3.3b-doorway-1d-cell.json`, and 0-cells) are counted
//! apart, by kind. Exits 1 on any other violation, printing the map as JSON
//! to replay it.

use std::collections::BTreeMap;
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

usage: stress [--maps N] [--start S]
  --maps N    how many maps (default 10000)
  --start S   the first seed (default 0)
  -h, --help  this text

Prints per claim the instances examined; exits 1 on a violation other than
the known failures of the sec. 3.6 rule (claim A3.6).";

fn main() {
    let args: Vec<String> = std::env::args().collect();
    if args.iter().any(|a| a == "-h" || a == "--help") {
        println!("{USAGE}");
        return;
    }
    let total = arg(&args, "--maps", 10_000);
    let start = arg(&args, "--start", 0);
    let checkers: Vec<Box<dyn Checker>> = CLAIMS
        .iter()
        .filter_map(|c| match c.status {
            Status::Checker(make) => Some(make()),
            Status::NoCheckerYet => None,
        })
        .collect();
    let refs: Vec<&dyn Checker> = checkers.iter().map(AsRef::as_ref).collect();
    let kinds = wai_gen::RANDOM_KINDS;
    let mut examined: BTreeMap<&'static str, u64> = BTreeMap::new();
    let mut conflicts: BTreeMap<String, u64> = BTreeMap::new();
    let mut others = 0u64;
    let batch = 100u64;
    let t = std::time::Instant::now();
    let mut i = 0u64;
    while i < total {
        let maps: Vec<wai_map::Map> = (i..(i + batch).min(total))
            .map(|j| {
                let kind = &kinds[(j % kinds.len() as u64) as usize];
                let n = (8 + (j / kinds.len() as u64) % 23) as usize;
                let n = n.clamp(kind.min_n, kind.max_n);
                let seed = start + j;
                wai_gen::random(kind.id, n, seed)
                    .expect("sizes within the kind's range")
                    .with_name(format!("{} n={n} seed={seed}", kind.id))
            })
            .collect();
        let summary = run(&refs, &maps);
        for tally in &summary.tallies {
            *examined.entry(tally.claim).or_default() += tally.examined;
        }
        for v in summary.violations() {
            let kind = v.violation.data["kind"].as_str().unwrap_or("");
            if v.claim == "A3.6" && wai_lemmas::a3_6::is_known_failure(&v.violation.data) {
                *conflicts.entry(kind.to_owned()).or_default() += 1;
            } else {
                others += 1;
                if others <= 5 {
                    println!("VIOLATION {}: {}", v.claim, v.violation.what);
                    println!("{}", v.map_json);
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
    println!(
        "stress: {total} maps (seeds {start}..{}), {:.1} s",
        start + total,
        t.elapsed().as_secs_f64()
    );
    for (claim, count) in &examined {
        println!("  {claim:<6} examined {count}");
    }
    for id in examined.iter().filter(|(_, &c)| c == 0).map(|(id, _)| id) {
        println!("  {id}: examined nothing in this run — NOT TESTED");
    }
    println!("  A3.6 known failures of the sec. 3.6 rule (1-cells, 0-cells; not counted below):");
    for (what, count) in &conflicts {
        println!("    {what}: {count}");
    }
    println!("  other violations: {others}");
    if others > 0 {
        std::process::exit(1);
    }
}
