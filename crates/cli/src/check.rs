#![allow(
    clippy::float_arithmetic,
    reason = "approximate decimals of exact ratios, for people"
)]
//! `wai check`: the claim checkers over a stream of maps, hunting for
//! counterexamples. The engine is `wai_hunt` (the search, the shrinking and
//! storing of counterexamples, the climb toward a proof case); this module
//! reads the command line, shows progress and prints.
//!
//! Exit codes: 0 no counterexample (known failures, counted apart, do not
//! count); 1 a counterexample was found (or, with `--replay`, the stored
//! one still breaks its claim); 2 bad usage; 3 a file could not be read or
//! written.

use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use serde_json::Value;
use wai_hunt::record::RunRecord;
use wai_hunt::shard::{ShardRun, Shards};
use wai_hunt::store::{StoreOptions, Stored};
use wai_hunt::{Limit, Outcome, Shard, Stream};
use wai_lemmas::Checker;

use crate::Failure;

#[derive(clap::Args, Debug)]
pub struct Args {
    /// Claim ids to check (e.g. T4.2 L5.13 or T4.2,L5.13); default every
    /// claim that has a checker.
    #[arg(value_delimiter = ',')]
    pub claims: Vec<String>,
    /// Only the claims of these chapters (comma-separated: 3,4,5).
    #[arg(long, value_delimiter = ',')]
    pub chapter: Vec<u8>,
    /// The maps: comma-separated KIND[:a-b] — a random kind (n from a to b,
    /// default 8-30), a layout, `family` (every thesis family, parameter a
    /// to b, default 1-4), or the groups `random`, `layouts` and `all` —
    /// and `corpus` (polyominoes up to 8 cells, the families at 1..6, the
    /// datasets, counterexamples/), which may precede generated kinds
    /// (`corpus,all`: the corpus first). Map i of the generated part has
    /// seed S + i. With --budget every kind (and the corpus) gets an equal
    /// share of the time. The kinds with holes (`orthogonal-pillars`,
    /// `simple-holes`, n default 6-20, 1 to 3 holes; `repeated-niches-pillars`
    /// and `kernel-funnels-pillars`, chapter 4's layouts with pillars; the
    /// group `holes`) are outside `all`: the claims assume a map without
    /// holes, and such a run shows what holes do to them; checkers that
    /// walk one ring examine nothing there.
    #[arg(long, default_value = "all")]
    pub maps: String,
    /// Instead of --maps: these map files.
    #[arg(long, num_args = 1.., value_name = "MAP")]
    pub files: Vec<PathBuf>,
    /// Stop after this many maps (default 1000 without --budget).
    #[arg(long, value_parser = crate::options::count_u64, allow_negative_numbers = true)]
    pub count: Option<u64>,
    /// Stop after this much wall-clock time: 90s, 10m, 1h30m.
    #[arg(long)]
    pub budget: Option<String>,
    /// Map i of a generated stream has seed S + i.
    #[arg(long, default_value_t = 0, value_parser = crate::options::count_u64, allow_negative_numbers = true)]
    pub seed: u64,
    /// Run shard I of N (from 0): the maps of the run with the same other
    /// arguments whose position is I modulo N (with --budget, in each kind,
    /// for budget / N), so that N shards see each map once. With --record,
    /// the record says which shard it is, for `wai merge`.
    #[arg(long, value_name = "I/N", value_parser = parse_shard)]
    pub shard: Option<Shard>,
    /// Worker threads (default: one per core).
    #[arg(long, value_parser = crate::options::positive_count, allow_negative_numbers = true)]
    pub threads: Option<usize>,
    /// Print the run as JSON (the record's keys, and the counterexamples).
    #[arg(long)]
    pub json: bool,
    /// Also write the run record to this file (the claims dashboard reads
    /// lemmas/last-run.json).
    #[arg(long)]
    pub record: Option<PathBuf>,
    /// Folder for shrunk counterexamples (default counterexamples/, or
    /// target/wai-check-planted with --plant).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Do not shrink counterexamples; store them as found.
    #[arg(long)]
    pub no_shrink: bool,
    /// At most this many candidate maps checked while shrinking one
    /// counterexample.
    #[arg(long, default_value_t = 3000, value_parser = crate::options::count, allow_negative_numbers = true)]
    pub shrink_tries: usize,
    /// Stop taking maps once a counterexample is found.
    #[arg(long)]
    pub first: bool,
    /// Write, per claim that measures a ratio, the map of its largest
    /// ratio to DIR/<claim>-largest.json.
    #[arg(long, value_name = "DIR")]
    pub largest: Option<PathBuf>,
    /// Run a planted bug (wai_lemmas::planted) in place of the real checker
    /// of its claim, to see the search find and shrink it.
    #[arg(long)]
    pub plant: Option<String>,
    /// Re-run the claim of a stored counterexample file on its map instead.
    #[arg(long, value_name = "FILE", conflicts_with_all = ["files", "count", "budget", "shard"])]
    pub replay: Option<PathBuf>,
    /// Print where the time went: each study stage's and each checker's own
    /// time, longest first (with --json, a "profile" object).
    #[arg(long)]
    pub profile: bool,
    /// Instead of a run: climb toward a map that hits case CASE of claim
    /// CLAIM (`wai claims` lists each claim's cases and which were never
    /// hit), for --evals evaluations or --budget; a map found is stored as
    /// a figure in --out (default counterexamples/).
    #[arg(long, value_name = "CLAIM:CASE", conflicts_with_all = ["files", "replay", "plant", "shard"])]
    pub target: Option<String>,
    /// With --target: stop after this many evaluations (default 2000
    /// without --budget).
    #[arg(long, requires = "target", value_parser = crate::options::count_u64, allow_negative_numbers = true)]
    pub evals: Option<u64>,
}

fn parse_shard(s: &str) -> Result<Shard, String> {
    s.parse()
}

/// The checkers of the run, planted bug in place.
fn checkers(args: &Args) -> Result<Vec<Checker>, Failure> {
    for id in &args.claims {
        match wai_lemmas::claim(id) {
            Some(c) if c.checker.is_some() => {}
            Some(_) => return Err(Failure::usage(format!("claim {id} has no checker yet"))),
            None => {
                return Err(Failure::usage(format!(
                    "no claim {id} in the registry (wai claims lists them)"
                )))
            }
        }
    }
    if let Some(ch) = args.chapter.iter().find(|c| !(3..=5).contains(*c)) {
        return Err(Failure::usage(format!(
            "--chapter {ch}: the claims are in chapters 3, 4 and 5"
        )));
    }
    let plant = match &args.plant {
        None => None,
        Some(name) => Some(wai_lemmas::planted::checker(name).ok_or_else(|| {
            Failure::usage(format!(
                "--plant {name}: the planted bugs are {}",
                wai_lemmas::planted::names().join(", ")
            ))
        })?),
    };
    let selected = wai_lemmas::checkers()
        .filter(|c| args.claims.is_empty() || args.claims.iter().any(|i| i == c.id))
        .filter(|c| {
            args.chapter.is_empty()
                || wai_lemmas::chapter_of(c.id).is_some_and(|ch| args.chapter.contains(&ch))
        });
    let chosen: Vec<Checker> = wai_lemmas::planted::swap_in(selected, plant).collect();
    if chosen.is_empty() {
        return Err(Failure::usage("no checker is selected"));
    }
    if let Some(p) = plant {
        if !chosen.iter().any(|c| c.id == p.id) {
            return Err(Failure::usage(format!(
                "--plant replaces the checker of {}, which is not selected",
                p.id
            )));
        }
    }
    Ok(chosen)
}

/// The kind of a fixed stream's map, from its name: a dataset's folder, a
/// family's id, `polyomino`, `counterexamples`.
fn kind_of_name(name: &str) -> String {
    let cut = name.find([' ', '/']).unwrap_or(name.len());
    name[..cut].to_owned()
}

fn stream(args: &Args) -> Result<Stream, Failure> {
    if !args.files.is_empty() {
        let mut maps = Vec::new();
        for f in &args.files {
            let map = crate::input::load_with_holes(f, crate::input::Format::Auto)?.map;
            let name = map
                .name()
                .map_or_else(|| f.display().to_string(), str::to_owned);
            maps.push(("files".to_owned(), map.with_name(name)));
        }
        return Ok(Stream::Fixed(maps));
    }
    // `corpus` among the kinds: the fixed corpus first, then the rest.
    let parts: Vec<&str> = args.maps.split(',').map(str::trim).collect();
    let with_corpus = parts.contains(&"corpus");
    let rest: Vec<&str> = parts.into_iter().filter(|p| *p != "corpus").collect();
    let fixed = if with_corpus {
        let maps = wai_hunt::corpus::corpus_maps().map_err(Failure::io)?;
        maps.into_iter()
            .map(|m| (kind_of_name(m.name().unwrap_or("corpus")), m))
            .collect()
    } else {
        Vec::new()
    };
    if rest.iter().all(|p| p.is_empty()) {
        return Ok(Stream::Fixed(fixed));
    }
    let kinds = wai_hunt::parse_kinds(&rest.join(",")).map_err(Failure::usage)?;
    Ok(if with_corpus {
        Stream::Mixed {
            fixed,
            kinds,
            seed: args.seed,
        }
    } else {
        Stream::Generated {
            kinds,
            seed: args.seed,
        }
    })
}

/// The run as a command, the same in every shard of it: the arguments
/// that choose the maps and the checkers, the limit made explicit, without
/// --shard, --threads and the options that only say where output goes.
fn run_arguments(args: &Args, limit: Limit) -> String {
    let mut words = vec!["wai check".to_owned()];
    if !args.claims.is_empty() {
        words.push(args.claims.join(","));
    }
    if !args.chapter.is_empty() {
        let ch: Vec<String> = args.chapter.iter().map(u8::to_string).collect();
        words.push(format!("--chapter {}", ch.join(",")));
    }
    if args.files.is_empty() {
        words.push(format!("--maps {}", args.maps));
    } else {
        let files: Vec<String> = args.files.iter().map(|f| f.display().to_string()).collect();
        words.push(format!("--files {}", files.join(" ")));
    }
    match limit {
        Limit::Count(n) => words.push(format!("--count {n}")),
        Limit::Budget(_) => words.push(format!(
            "--budget {}",
            args.budget.as_deref().unwrap_or_default()
        )),
    }
    // Not --threads: a resource, like where output goes (the nodes of a
    // cluster differ), and with a count the maps do not depend on it.
    words.push(format!("--seed {}", args.seed));
    if let Some(p) = &args.plant {
        words.push(format!("--plant {p}"));
    }
    if args.first {
        words.push("--first".to_owned());
    }
    words.join(" ")
}

/// The command line of this run, for records and notes.
fn command_line() -> String {
    let mut words = vec!["wai".to_owned()];
    words.extend(std::env::args().skip(1));
    words.join(" ")
}

/// Progress on standard error: a bar on a terminal, else a line every 30 s.
struct Progress {
    bar: indicatif::ProgressBar,
    terminal: bool,
    last_line: std::sync::Mutex<Instant>,
    total: Option<u64>,
}

impl Progress {
    fn new(total: Option<u64>, budget: Option<Duration>) -> Progress {
        let len = total.or(budget.map(|b| b.as_secs().max(1))).unwrap_or(0);
        let bar = crate::progress_bar(len);
        Progress {
            bar,
            terminal: std::io::stderr().is_terminal(),
            last_line: std::sync::Mutex::new(Instant::now()),
            total,
        }
    }

    fn update(&self, done: u64, elapsed: Duration) {
        let msg = match self.total {
            Some(t) => format!("{done}/{t} maps"),
            None => format!("{done} maps"),
        };
        if self.terminal {
            self.bar.set_position(if self.total.is_some() {
                done
            } else {
                elapsed.as_secs()
            });
            self.bar.set_message(msg);
        } else if let Ok(mut last) = self.last_line.lock() {
            if last.elapsed() >= Duration::from_secs(30) {
                *last = Instant::now();
                eprintln!("[{:>5} s] wai check: {msg}", elapsed.as_secs());
            }
        }
    }
}

pub fn run(args: &Args) -> Result<(), Failure> {
    if let Some(file) = &args.replay {
        return replay(args, file);
    }
    let budget = args
        .budget
        .as_deref()
        .map(wai_hunt::climb::parse_duration)
        .transpose()
        .map_err(|e| Failure::usage(format!("--budget: {e}")))?;
    if let Some(target) = &args.target {
        return crate::check_target::run(
            target,
            args.evals,
            budget,
            args.seed,
            args.out.as_deref(),
        );
    }
    let checkers = checkers(args)?;
    let stream = stream(args)?;
    if stream.is_empty() {
        return Err(Failure::usage("the stream has no map"));
    }
    let limit = match (args.count, budget) {
        (Some(_), Some(_)) => return Err(Failure::usage("give --count or --budget, not both")),
        (Some(n), None) => Limit::Count(n),
        (None, Some(b)) => Limit::Budget(b),
        (None, None) => Limit::Count(stream.len().unwrap_or(1000)),
    };
    if let Some(t) = args.threads {
        if t == 0 {
            return Err(Failure::usage("--threads must be positive"));
        }
        // Fails only if the pool was built already, which it was not.
        let _ = rayon::ThreadPoolBuilder::new()
            .num_threads(t)
            .build_global();
    }
    let threads = rayon::current_num_threads() as u64;
    let shard = args.shard.unwrap_or(Shard::WHOLE);
    let total = match limit {
        Limit::Count(n) => {
            let run = stream.len().map_or(n, |len| n.min(len));
            // The shard's positions i, i + N, … below the run's count.
            Some(run.saturating_sub(shard.index).div_ceil(shard.count))
        }
        Limit::Budget(_) => None,
    };
    // The checkout's commit when the run starts: the code that ran.
    let commit = wai_hunt::provenance::commit();
    let started = wai_hunt::provenance::utc_timestamp();
    let progress = Progress::new(total, budget.map(|b| b / shard.count.max(1) as u32));
    let outcome = wai_hunt::search(
        &checkers,
        &stream,
        limit,
        shard,
        args.first,
        &|done, elapsed| progress.update(done, elapsed),
    );
    progress.bar.finish_and_clear();
    let out_dir = args.out.clone().unwrap_or_else(|| {
        PathBuf::from(if args.plant.is_some() {
            "target/wai-check-planted"
        } else {
            "counterexamples"
        })
    });
    let options = StoreOptions {
        no_shrink: args.no_shrink,
        shrink_tries: args.shrink_tries,
        seed: args.seed,
        planted: args.plant.clone(),
        command: command_line(),
    };
    let stored = wai_hunt::store::store_counterexamples(
        &outcome,
        &checkers,
        &options,
        &out_dir,
        &mut |what| eprintln!("wai check: {what}"),
    )
    .map_err(Failure::io)?;
    if let Some(dir) = &args.largest {
        wai_hunt::store::write_largest(&outcome, dir).map_err(Failure::io)?;
    }
    let mut record = record(&outcome, commit);
    if let Some(shard) = args.shard {
        record.shards = Some(Shards {
            count: shard.count,
            run: run_arguments(args, limit),
            present: vec![ShardRun {
                index: shard.index,
                maps: record.maps,
                seconds: record.seconds,
                started,
                ended: wai_hunt::provenance::utc_timestamp(),
                binary: wai_hunt::provenance::binary_digest(),
                counterexamples: stored
                    .iter()
                    .map(|s| s.path.display().to_string())
                    .collect(),
            }],
        });
    }
    if let Some(path) = &args.record {
        record.write(path).map_err(Failure::io)?;
    }
    if args.json {
        let mut all = record.to_json();
        all["counterexamples"] = Value::from(stored.iter().map(Stored::json).collect::<Vec<_>>());
        if args.profile {
            all["profile"] = profile_json(&outcome);
        }
        outln!(
            "{}",
            serde_json::to_string_pretty(&all).expect("plain JSON values")
        );
    } else {
        out!(
            "{}",
            text_summary(args, &outcome, &record, threads, &stored)
        );
        if args.profile {
            out!("{}", profile_text(&outcome));
        }
    }
    let found = outcome.counterexamples().len();
    if found == 0 {
        Ok(())
    } else {
        Err(Failure {
            code: 1,
            message: format!(
                "{} counterexample(s) found; stored in {}",
                found,
                out_dir.display()
            ),
        })
    }
}

/// Where the time went, as text: stages and checkers by own time.
fn profile_text(outcome: &Outcome) -> String {
    use std::fmt::Write;
    let p = &outcome.profile;
    let total = p.total().as_secs_f64().max(1e-9);
    let maps = p.maps.max(1) as f64;
    let mut s = format!(
        "profile: {} maps, {:.1} s of work ({:.2} ms a map) over {:.1} s of wall time\n  {:<28} {:>10} {:>7} {:>12}\n",
        p.maps,
        total,
        1000.0 * total / maps,
        outcome.elapsed.as_secs_f64(),
        "stage or checker",
        "seconds",
        "share",
        "ms a map"
    );
    for (name, t) in p.ranked() {
        let secs = t.as_secs_f64();
        let _ = writeln!(
            s,
            "  {name:<28} {secs:>10.3} {:>6.1}% {:>12.3}",
            100.0 * secs / total,
            1000.0 * secs / maps
        );
    }
    s
}

/// Where the time went, as JSON: seconds by stage and by checker.
fn profile_json(outcome: &Outcome) -> Value {
    let p = &outcome.profile;
    let stages: serde_json::Map<String, Value> = p
        .stages
        .stages
        .iter()
        .map(|(s, (t, builds))| {
            (
                (*s).to_owned(),
                serde_json::json!({"seconds": t.as_secs_f64(), "builds": builds}),
            )
        })
        .collect();
    let checkers: serde_json::Map<String, Value> = p
        .checkers
        .iter()
        .map(|(c, t)| ((*c).to_owned(), serde_json::json!(t.as_secs_f64())))
        .collect();
    serde_json::json!({
        "maps": p.maps,
        "wall_seconds": outcome.elapsed.as_secs_f64(),
        "work_seconds": p.total().as_secs_f64(),
        "stages": stages,
        "checkers": checkers,
    })
}

/// The run as a record (the claims dashboard reads one); `commit` as
/// taken when the run started.
fn record(outcome: &Outcome, commit: String) -> RunRecord {
    RunRecord::from_summary(
        &outcome.summary,
        command_line(),
        commit,
        wai_hunt::provenance::utc_date(),
        outcome.elapsed.as_secs(),
        outcome.map_kinds.clone(),
    )
}

fn text_summary(
    args: &Args,
    outcome: &Outcome,
    record: &RunRecord,
    threads: u64,
    stored: &[Stored],
) -> String {
    use std::fmt::Write;
    let mut s = String::new();
    let kinds: Vec<String> = outcome
        .map_kinds
        .iter()
        .map(|k| format!("{} {}", k.kind, k.maps))
        .collect();
    let _ = writeln!(
        s,
        "wai check{}: {} maps in {} s on {threads} threads, seed {} ({})",
        args.shard
            .map_or(String::new(), |sh| format!(" shard {sh}")),
        outcome.summary.maps,
        outcome.elapsed.as_secs(),
        args.seed,
        kinds.join(", ")
    );
    if let Some(p) = &args.plant {
        let _ = writeln!(s, "  PLANTED BUG {p}: its checker replaced the real one");
    }
    let _ = writeln!(
        s,
        "  {:<7} {:>14} {:>10} {:>8}  largest ratio",
        "claim", "examined", "violations", "known"
    );
    for c in &record.claims {
        let largest = c.max_ratio.as_ref().map_or(String::new(), |r| {
            format!(
                "{r} ≈ {:.4} on {}",
                r.to_f64(),
                c.max_ratio_map.as_deref().unwrap_or("an unnamed map")
            )
        });
        let _ = writeln!(
            s,
            "  {:<7} {:>14} {:>10} {:>8}  {largest}",
            c.id, c.examined, c.violations, c.known_failures
        );
    }
    let untested = outcome.summary.untested();
    if !untested.is_empty() {
        let _ = writeln!(
            s,
            "  examined nothing, NOT TESTED by this run: {}",
            untested.join(", ")
        );
    }
    let with_holes = !args.files.is_empty()
        || wai_hunt::parse_kinds(&args.maps).is_ok_and(|kinds| {
            kinds
                .iter()
                .any(|k| matches!(k.kind, wai_hunt::MapKind::Holed(_)))
        });
    if with_holes {
        let one_ring: Vec<&str> = wai_lemmas::checkers()
            .filter(|c| matches!(c.rings, wai_lemmas::Rings::Outer(_)))
            .map(|c| c.id)
            .collect();
        let _ = writeln!(
            s,
            "  checkers that walk one ring, run on the maps without holes only: {}",
            one_ring.join(", ")
        );
    }
    for v in outcome.counterexamples().iter().take(5) {
        let _ = writeln!(
            s,
            "  VIOLATION {} on {}: {}",
            v.claim,
            v.map_name.as_deref().unwrap_or("an unnamed map"),
            v.violation.what
        );
    }
    for st in stored {
        let _ = writeln!(
            s,
            "  {} counterexample shrunk from n = {} to n = {} in {} steps: {}\n    replay: {}",
            st.claim,
            st.from_n,
            st.map.n(),
            st.steps,
            st.path.display(),
            st.replay()
        );
    }
    s
}

/// `--replay FILE`: the file's claim (or its planted bug) on its map.
fn replay(args: &Args, file: &Path) -> Result<(), Failure> {
    let bytes = std::fs::read(file).map_err(|e| Failure::io(format!("{}: {e}", file.display())))?;
    let value: Value = serde_json::from_slice(&bytes)
        .map_err(|e| Failure::invalid(format!("{}: not JSON: {e}", file.display())))?;
    wai_hunt::counterexample::verify(&bytes)
        .map_err(|e| Failure::invalid(format!("{}: refused: {e}", file.display())))?;
    let checker = wai_hunt::store::replay_checker(&value, args.plant.as_deref())
        .map_err(|e| Failure::invalid(format!("{}: {e}", file.display())))?;
    let claim = checker.id;
    let planted = args.plant.clone().or_else(|| {
        value["meta"]["check"]["planted"]
            .as_str()
            .map(str::to_owned)
    });
    let map = crate::input::load_with_holes(file, crate::input::Format::Auto)?.map;
    let (report, open) = wai_hunt::store::replay(&checker, &map);
    outln!(
        "wai check --replay {}: {claim}{} on {} (n = {}, r = {}): examined {}, violations {}, known failures {}",
        file.display(),
        planted.map_or(String::new(), |p| format!(" (planted bug {p})")),
        map.name().unwrap_or("the map"),
        map.n(),
        map.r(),
        report.examined,
        open,
        report.violations.len() - open
    );
    for v in checker.counterexamples(&report).take(5) {
        outln!("  VIOLATION: {}", v.what);
    }
    if open == 0 {
        outln!("  {claim} holds on this map");
        Ok(())
    } else {
        Err(Failure {
            code: 1,
            message: format!("{claim} is still violated on {}", file.display()),
        })
    }
}
