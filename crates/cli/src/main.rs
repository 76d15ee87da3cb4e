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

mod check;
mod claims;
mod commands;
mod decompose;
mod embeddings;
mod extremes;
mod input;
mod localize;
mod scan;
mod scan_eval;
mod target;
mod vis;

// The allocator of every binary of the workspace (see Cargo.toml).
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

use clap::{Parser, Subcommand};
use std::path::PathBuf;
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
    Demo {
        /// Folder for the output files.
        #[arg(long, default_value = "target/wai-demo")]
        out: PathBuf,
    },
    /// Generate a map: a thesis family (`--family`) or a random kind (`--random`).
    Gen(commands::GenArgs),
    /// Validate a map and print n, r, area, orthogonality and scale.
    Info {
        /// Map file (JSON map format or GeoJSON); `-` reads standard input.
        map: PathBuf,
        /// Print JSON instead of text.
        #[arg(long)]
        json: bool,
        #[command(flatten)]
        format: input::FormatArg,
    },
    /// The visibility polygon V_p of a viewpoint (edge kinds, blocking
    /// vertices) and its skeleton V*_p (origin, labels, kernel).
    Vis {
        /// Map file (JSON map format or GeoJSON); `-` reads standard input.
        map: PathBuf,
        /// The viewpoint `x,y`, exact numbers in the map's units (e.g. `3/2,0.25`).
        #[arg(long, allow_hyphen_values = true)]
        at: String,
        /// Print JSON instead of text.
        #[arg(long)]
        json: bool,
        /// Also draw V_p, its spurious edges and the skeleton into this SVG file.
        #[arg(long)]
        svg: Option<PathBuf>,
        #[command(flatten)]
        format: input::FormatArg,
    },
    /// The visibility cell decomposition: rays, cells, skeletons and
    /// equivalence classes, with their counts (thesis sec. 3.6).
    Decompose {
        /// Map file (JSON map format or GeoJSON); `-` reads standard input.
        map: PathBuf,
        /// Print JSON instead of text.
        #[arg(long)]
        json: bool,
        /// Draw the cells coloured by class into this SVG file.
        #[arg(long)]
        svg: Option<PathBuf>,
        /// With --svg: highlight this class (an index printed by --json).
        #[arg(long)]
        class: Option<usize>,
        /// Skip the memory estimate made before the work starts.
        #[arg(long)]
        force: bool,
        #[command(flatten)]
        format: input::FormatArg,
    },
    /// The embeddings of each skeleton (Def 3.11): origin, witnesses and
    /// validity (Def 4.1), candidate and valid candidate edges; the
    /// overlapping valid pairs of one skeleton and whether their witnesses
    /// see each other, decided exactly (Theorem 4.2).
    Embeddings {
        /// Map file (JSON map format or GeoJSON); `-` reads standard input.
        map: PathBuf,
        /// Only this class (an index printed by `wai decompose --json`).
        #[arg(long)]
        class: Option<usize>,
        /// Print JSON instead of text.
        #[arg(long)]
        json: bool,
        /// Draw the embedded skeletons, kernels, witnesses and candidate
        /// edges of one class (--class, else the one with the most valid
        /// embeddings) into this SVG file.
        #[arg(long)]
        svg: Option<PathBuf>,
        #[command(flatten)]
        format: input::FormatArg,
    },
    /// Preprocess a map for localization (Alg 3.14): decompose it and
    /// overlay each class's cells, then save the structure (versioned JSON)
    /// for `wai localize`.
    Preprocess {
        /// Map file (JSON map format or GeoJSON); `-` reads standard input.
        map: PathBuf,
        /// Output file.
        #[arg(short, long)]
        out: PathBuf,
        #[command(flatten)]
        format: input::FormatArg,
    },
    /// Every position where a robot can be, given what it sees (Alg 3.13):
    /// a visibility polygon relative to the robot (--polygon), or the one
    /// simulated at a map point (--at). Prints each position with the map
    /// vertex its skeleton origin lands on, or says why there is none.
    Localize {
        /// A map file (preprocessed now) or a file written by `wai preprocess`.
        map: PathBuf,
        /// Simulate the view at `x,y` (exact numbers in the map's units).
        #[arg(long, allow_hyphen_values = true)]
        at: Option<String>,
        /// A JSON file with the polygon: an array of [x, y] pairs (or an
        /// object with "vertices"), exact numbers in the map's units,
        /// relative to the robot, counter-clockwise.
        #[arg(long)]
        polygon: Option<PathBuf>,
        /// Print JSON: {"answers": [{"position": [x, y], "origin_vertex": i}], "class": k}
        /// (and "reason" when there is no answer).
        #[arg(long)]
        json: bool,
        /// Draw the map, the polygon at every answer and the answers into this SVG file.
        #[arg(long)]
        svg: Option<PathBuf>,
        #[command(flatten)]
        format: input::FormatArg,
    },
    /// Search for the maps that push one chapter 5 ratio highest: seeded
    /// hill climbing over map mutations from the thesis families and random
    /// maps, ratios measured exactly; writes the best maps to
    /// counterexamples/ (or --out) and prints what the starts reach.
    SearchExtremes(extremes::Args),
    /// Hunt for counterexamples: every claim checker (or the CLAIM ids
    /// given) over a stream of generated maps, the corpus or files, for a
    /// count or a time budget; prints per claim the instances examined, the
    /// violations and the largest ratio, shrinks each counterexample and
    /// writes it to counterexamples/ with its replay command. Exits 1 on a
    /// counterexample.
    Check(check::Args),
    /// Simulate a laser scan of a map from a pose (thesis sec. 6.1): beams
    /// at equal angles, Gaussian range noise, a range cutoff and unknown
    /// obstacles, seeded; writes the angles and ranges as JSON.
    Scan(scan::Args),
    /// Localize a laser scan in a map (thesis ch. 6): the cells ranked by
    /// the polar coordinate metric, the best refined by point-to-line ICP,
    /// and the set of poses that match as well (every look-alike place).
    LocalizeScan(scan_eval::LocalizeArgs),
    /// The evaluation protocol of issue 12: seeded poses on each map,
    /// simulated scans under each condition, success rates, answer sets,
    /// times and error CDF plots (SVG), with peers on the same scans.
    Eval(scan_eval::EvalArgs),
    /// Every claim of the registry with its kind, its checker and what the
    /// last recorded run (lemmas/last-run.json) found: instances examined,
    /// violations, known failures, the largest ratio.
    Claims(claims::Args),
    /// Draw a map as SVG, reflex vertices marked.
    Render {
        /// Map file (JSON map format or GeoJSON); `-` reads standard input.
        map: PathBuf,
        /// Output SVG file; standard output if absent.
        #[arg(long)]
        out: Option<PathBuf>,
        /// Number the vertices.
        #[arg(long)]
        labels: bool,
        /// Pixels along the longer side.
        #[arg(long, default_value_t = 800)]
        size: u32,
        #[command(flatten)]
        format: input::FormatArg,
    },
}

/// The progress bar of long commands (on standard error): elapsed time, a
/// bar of `len` steps, a message.
pub fn progress_bar(len: u64) -> indicatif::ProgressBar {
    let bar = indicatif::ProgressBar::new(len);
    bar.set_style(
        indicatif::ProgressStyle::with_template("{elapsed_precise} [{bar:30}] {msg}")
            .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
    );
    bar
}

/// A failure with its exit code.
#[derive(Debug)]
pub struct Failure {
    pub code: u8,
    pub message: String,
}

impl Failure {
    pub fn invalid(message: impl Into<String>) -> Self {
        Failure {
            code: 1,
            message: message.into(),
        }
    }
    pub fn usage(message: impl Into<String>) -> Self {
        Failure {
            code: 2,
            message: message.into(),
        }
    }
    pub fn io(message: impl Into<String>) -> Self {
        Failure {
            code: 3,
            message: message.into(),
        }
    }
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Demo { out } => commands::demo(&out),
        Command::Gen(args) => commands::gen(&args),
        Command::Info { map, json, format } => commands::info(&map, json, format.format),
        Command::Vis {
            map,
            at,
            json,
            svg,
            format,
        } => vis::vis(&map, &at, json, svg.as_deref(), format.format),
        Command::Decompose {
            map,
            json,
            svg,
            class,
            force,
            format,
        } => decompose::decompose(
            &map,
            &decompose::Options {
                json,
                svg: svg.as_deref(),
                class,
                force,
            },
            format.format,
        ),
        Command::Embeddings {
            map,
            class,
            json,
            svg,
            format,
        } => embeddings::embeddings(
            &map,
            &embeddings::Options {
                class,
                json,
                svg: svg.as_deref(),
            },
            format.format,
        ),
        Command::Preprocess { map, out, format } => localize::preprocess(&map, &out, format.format),
        Command::Localize {
            map,
            at,
            polygon,
            json,
            svg,
            format,
        } => localize::localize(
            &map,
            &localize::Options {
                at: at.as_deref(),
                polygon: polygon.as_deref(),
                json,
                svg: svg.as_deref(),
            },
            format.format,
        ),
        Command::SearchExtremes(args) => extremes::search_extremes(&args),
        Command::Check(args) => check::check(&args),
        Command::Scan(args) => scan::scan(&args),
        Command::LocalizeScan(args) => scan_eval::localize_scan(&args),
        Command::Eval(args) => scan_eval::eval(&args),
        Command::Claims(args) => claims::claims(&args),
        Command::Render {
            map,
            out,
            labels,
            size,
            format,
        } => commands::render(&map, out.as_deref(), labels, size, format.format),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(f) => {
            eprintln!("error: {}", f.message);
            ExitCode::from(f.code)
        }
    }
}
