//! `wai`: the workspace's one binary.
//!
//! Subcommands: `demo` (the main job on the built-in default map), `gen`
//! (generate a map of a thesis family or a random kind), `info` (validate a
//! map and print its numbers), `vis` (V_p and V*_p of a viewpoint),
//! `decompose` (the visibility cell decomposition), `embeddings` (the
//! embeddings of each skeleton, witnesses, overlaps), `preprocess` and
//! `localize` (the exact reference localizer), `render` (draw a map as SVG),
//! `search-extremes` (a seeded local search for the maps that push a
//! chapter 5 ratio highest), `check` (every claim checker over a stream of
//! maps, shrinking what breaks a claim), `claims` (the claims registry with
//! the last recorded run), `scan` (a simulated noisy laser scan), `localize-scan` (localize a scan)
//! and `eval` (the scan localizer's evaluation protocol).
//!
//! Exit codes: 0 success; 1 the map is invalid; 2 bad usage; 3 the file
//! could not be read or written. Errors say what and where, never panic.
//! A closed pipe on standard output ends a command quietly with 141
//! (`wai_output`).

#[macro_use]
extern crate wai_output;

mod budget;
mod check;
mod check_target;
mod claims;
mod decompose;
mod demo;
mod embeddings;
mod eval;
mod eval_log;
mod failure;
mod gen;
mod import_grid;
mod info;
mod input;
mod localize;
mod localize_scan;
mod map_from_log;
mod merge;
mod options;
mod output;
mod preprocess;
mod render;
mod scan;
mod scan_maps;
mod search_extremes;
mod vis;

pub(crate) use failure::{progress_bar, Failure};

// The allocator of every binary of the workspace (see Cargo.toml).
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

use clap::{Parser, Subcommand};
use std::process::ExitCode;

#[derive(Parser, Debug)]
#[command(
    name = "wai",
    version,
    about = "Where am I? Exact visibility and localization in polygonal maps"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Run the main job on the built-in default map (an office floor):
    /// validate it, print its numbers and write its JSON and SVG.
    Demo(demo::Args),
    /// Generate a map: a thesis family (`--family`) or a random kind (`--random`).
    Gen(gen::Args),
    /// Validate a map and print n, r, holes, area, orthogonality and scale.
    Info(info::Args),
    /// Trace an occupancy grid (ROS map_server: a YAML file and its PGM
    /// image) into a map with holes, in metres in the grid's frame.
    ImportGrid(import_grid::Args),
    /// Build a map with holes from a laser log's scans (CARMEN FLASER /
    /// ROBOTLASER1, plain or .gz) through an occupancy grid.
    MapFromLog(map_from_log::Args),
    /// Localize a laser log's scans globally against a map built from the
    /// log's other scans, with and without a compass, beside a peer: success
    /// rates, answer sets, times and the error CDF.
    EvalLog(eval_log::Args),
    /// The visibility polygon V_p of a viewpoint (edge kinds, blocking
    /// vertices) and its skeleton V*_p (origin, labels, kernel).
    Vis(vis::Args),
    /// The visibility cell decomposition: rays, cells, skeletons and
    /// equivalence classes, with their counts (thesis sec. 3.6).
    Decompose(decompose::Args),
    /// The embeddings of each skeleton (Def 3.11): origin, witnesses and
    /// validity (Def 4.1), candidate and valid candidate edges; the
    /// overlapping valid pairs of one skeleton and whether their witnesses
    /// see each other, decided exactly (Theorem 4.2).
    Embeddings(embeddings::Args),
    /// Preprocess a map for localization (Alg 3.14): decompose it and
    /// overlay each class's cells, then save the structure (versioned JSON)
    /// for `wai localize`.
    Preprocess(preprocess::Args),
    /// Every position where a robot can be, given what it sees (Alg 3.13):
    /// a visibility polygon relative to the robot (--polygon), or the one
    /// simulated at a map point (--at). Prints each position with the map
    /// vertex its skeleton origin lands on, or says why there is none.
    Localize(localize::Args),
    /// Search for the maps that push one chapter 5 ratio highest: seeded
    /// hill climbing over map mutations from the thesis families and random
    /// maps, ratios measured exactly; writes the best maps to
    /// counterexamples/ (or --out) and prints what the starts reach.
    SearchExtremes(search_extremes::Args),
    /// Hunt for counterexamples: every claim checker (or the CLAIM ids
    /// given) over a stream of generated maps, the corpus or files, for a
    /// count or a time budget; prints per claim the instances examined, the
    /// violations and the largest ratio, shrinks each counterexample and
    /// writes it to counterexamples/ with its replay command. Exits 1 on a
    /// counterexample.
    Check(check::Args),
    /// Merge the records of a sharded run (`wai check --shard I/N
    /// --record …`) into the record of the whole run: examined,
    /// violations, cases and maps summed, the largest ratios kept with
    /// their maps. Refuses records of different commits or runs and shards
    /// merged twice; names missing shards and marks such a merge partial
    /// (exit 1).
    Merge(merge::Args),
    /// Simulate a laser scan of a map from a pose (thesis sec. 6.1): beams
    /// at equal angles, Gaussian range noise, a range cutoff and unknown
    /// obstacles, seeded; writes the angles and ranges as JSON.
    Scan(scan::Args),
    /// Localize a laser scan in a map (thesis ch. 6): the cells ranked by
    /// the polar coordinate metric, the best refined by point-to-line ICP,
    /// and the set of poses that match as well (every look-alike place).
    LocalizeScan(localize_scan::Args),
    /// The scan localizer's evaluation protocol: seeded poses on each map,
    /// simulated scans under each condition, success rates, answer sets,
    /// times and error CDF plots (SVG), with peers on the same scans.
    Eval(eval::Args),
    /// Every claim of the registry with its kind, its checker and what the
    /// last recorded run (lemmas/last-run.json) found: instances examined,
    /// violations, known failures, the largest ratio.
    Claims(claims::Args),
    /// Draw a map as SVG, reflex vertices marked.
    Render(render::Args),
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Demo(args) => demo::run(&args),
        Command::Gen(args) => gen::run(&args),
        Command::Info(args) => info::run(&args),
        Command::ImportGrid(args) => import_grid::run(&args),
        Command::MapFromLog(args) => map_from_log::run(&args),
        Command::EvalLog(args) => eval_log::run(&args),
        Command::Vis(args) => vis::run(&args),
        Command::Decompose(args) => decompose::run(&args),
        Command::Embeddings(args) => embeddings::run(&args),
        Command::Preprocess(args) => preprocess::run(&args),
        Command::Localize(args) => localize::run(&args),
        Command::SearchExtremes(args) => search_extremes::run(&args),
        Command::Check(args) => check::run(&args),
        Command::Merge(args) => merge::run(&args),
        Command::Scan(args) => scan::run(&args),
        Command::LocalizeScan(args) => localize_scan::run(&args),
        Command::Eval(args) => eval::run(&args),
        Command::Claims(args) => claims::run(&args),
        Command::Render(args) => render::run(&args),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(f) => {
            eprintln!("error: {}", f.message);
            ExitCode::from(f.code)
        }
    }
}
