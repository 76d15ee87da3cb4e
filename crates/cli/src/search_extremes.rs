//! `wai search-extremes`: a seeded local search for the maps that push one
//! chapter 5 ratio highest; the engine is `wai_hunt::climb`, the ratios
//! are read off the checkers' reports (`wai_hunt::extremes`). Writes the best maps to `counterexamples/`
//! (kind `figure`, or `violation` for a k above Theorem 5.15's bound) and
//! prints a summary beside what the start maps reach.

use std::io::IsTerminal;
use std::path::PathBuf;
use std::time::{Duration, Instant};

use rug::Rational;
use serde_json::json;
use wai_gen::mutate::Limits;

use wai_hunt::climb::{self as search, Config, Found, Outcome, Starts, Status};
use wai_hunt::extremes::Ratio;

use crate::Failure;

/// `--ratio`: one of [`Ratio::ALL`] by id.
fn parse_ratio(text: &str) -> Result<Ratio, String> {
    Ratio::named(text).ok_or_else(|| {
        let ids: Vec<&str> = Ratio::ALL.iter().map(|r| r.id()).collect();
        format!("{text:?} is not a ratio; the ratios are {}", ids.join(", "))
    })
}

/// `--start`: one of [`Starts::ALL`] by name.
pub(crate) fn parse_starts(text: &str) -> Result<Starts, String> {
    Starts::named(text).ok_or_else(|| {
        let names: Vec<&str> = Starts::ALL.iter().map(|(_, n)| *n).collect();
        format!(
            "{text:?} is not a start; the starts are {}",
            names.join(", ")
        )
    })
}

#[derive(clap::Args, Debug)]
pub struct Args {
    /// The ratio to maximise: ec = max |EC| / (n + r²) (T5.17), cmult =
    /// max |C_mult| / r (T5.12), wedge = max W / r² (T5.16), k = Theorem
    /// 5.15's k.
    #[arg(long, value_parser = parse_ratio)]
    pub ratio: Ratio,
    /// Stop after this much wall-clock time: 90s, 10m, 1h30m (whole units).
    #[arg(long, required_unless_present = "evals")]
    pub budget: Option<String>,
    /// Stop after this many evaluations, the starts included (a run is a
    /// function of seed and evaluation count: this reproduces it).
    #[arg(long, value_parser = crate::options::count_u64, allow_negative_numbers = true)]
    pub evals: Option<u64>,
    /// Seed of every random choice (random starts, mutations, restarts).
    #[arg(long, default_value_t = 0, value_parser = crate::options::count_u64, allow_negative_numbers = true)]
    pub seed: u64,
    /// Start maps: random maps of every random kind, the thesis families,
    /// or both.
    #[arg(long, value_parser = parse_starts, default_value = "both")]
    pub start: Starts,
    /// Also start from this map file (repeatable; evaluated first). Its
    /// vertices must fit --max-n.
    #[arg(long = "from", value_name = "MAP")]
    pub from: Vec<PathBuf>,
    /// Folder for the best maps (the format of counterexamples/README.md).
    #[arg(long, default_value = "counterexamples")]
    pub out: PathBuf,
    /// At most this many vertices per map (keeps each evaluation affordable).
    #[arg(long, default_value_t = 40, value_parser = crate::options::count, allow_negative_numbers = true)]
    pub max_n: usize,
    /// Evaluate only maps with at least this many reflex vertices (the
    /// default 1 leaves out convex maps, whose one cell gives |EC| / n = 2).
    #[arg(long, default_value_t = 1, value_parser = crate::options::count, allow_negative_numbers = true)]
    pub min_r: usize,
    /// Climbers in the pool.
    #[arg(long, default_value_t = 8, value_parser = crate::options::positive_count, allow_negative_numbers = true)]
    pub pool: usize,
    /// How many of the best distinct maps to write.
    #[arg(long, default_value_t = 1, value_parser = crate::options::positive_count, allow_negative_numbers = true)]
    pub keep: usize,
    /// Restart a climber after this many of its evaluations without an
    /// improvement.
    #[arg(long, default_value_t = 200, value_parser = crate::options::count_u64, allow_negative_numbers = true)]
    pub stall: u64,
    /// Let orthogonal maps become non-orthogonal (by default they are
    /// mutated only by the operators that keep them orthogonal).
    #[arg(long)]
    pub free_angles: bool,
}

/// `≈ x.xxxxxx` of an exact ratio, for people.
fn approx(r: &Rational) -> String {
    format!("{:.6}", r.to_f64())
}

/// The command line that reproduces a run of `evaluations` evaluations.
fn command(args: &Args, evaluations: u64) -> String {
    let start = match args.start {
        Starts::Random => "random",
        Starts::Families => "families",
        Starts::Both => "both",
    };
    let mut c = format!(
        "wai search-extremes --ratio {} --evals {evaluations} --seed {} --start {start} --max-n {} --min-r {} --pool {} --keep {} --stall {}",
        args.ratio.id(),
        args.seed,
        args.max_n,
        args.min_r,
        args.pool,
        args.keep,
        args.stall,
    );
    if args.free_angles {
        c.push_str(" --free-angles");
    }
    for f in &args.from {
        c.push_str(&format!(" --from {}", f.display()));
    }
    c
}

/// Progress on standard error: a bar on a terminal, else a line every 30 s.
struct Progress {
    bar: indicatif::ProgressBar,
    terminal: bool,
    by_time: bool,
    last_line: Instant,
}

impl Progress {
    fn new(args: &Args, budget: Option<Duration>) -> Progress {
        let (len, by_time) = match (args.evals, budget) {
            (Some(n), _) => (n, false),
            (None, Some(b)) => (b.as_secs().max(1), true),
            (None, None) => (0, false),
        };
        let bar = crate::progress_bar(len);
        Progress {
            bar,
            terminal: std::io::stderr().is_terminal(),
            by_time,
            last_line: Instant::now(),
        }
    }

    fn update(&mut self, s: &Status<'_>) {
        let best = match s.best {
            Some(f) => format!(
                "best {} ≈ {} (n {}, r {})",
                f.eval.value,
                approx(&f.eval.value),
                f.map.n(),
                f.map.r()
            ),
            None => "no map evaluated yet".to_owned(),
        };
        let msg = format!("{} evaluations, {best}", s.evaluations);
        if self.terminal {
            self.bar.set_position(if self.by_time {
                s.elapsed.as_secs()
            } else {
                s.evaluations
            });
            self.bar.set_message(msg);
        } else if self.last_line.elapsed() >= Duration::from_secs(30) {
            self.last_line = Instant::now();
            eprintln!("[{:>5} s] {msg}", s.elapsed.as_secs());
        }
    }
}

pub fn run(args: &Args) -> Result<(), Failure> {
    let budget = args
        .budget
        .as_deref()
        .map(search::parse_duration)
        .transpose()
        .map_err(|e| Failure::usage(format!("--budget: {e}")))?;
    if budget.is_none() && args.evals.is_none() {
        return Err(Failure::usage("give --budget or --evals"));
    }
    if args.max_n < 4 {
        return Err(Failure::usage("--max-n must be at least 4"));
    }
    if args.pool == 0 || args.keep == 0 || args.stall == 0 {
        return Err(Failure::usage(
            "--pool, --keep and --stall must be positive",
        ));
    }
    let limits = Limits {
        max_n: args.max_n,
        keep_orthogonal: !args.free_angles,
        ..Limits::default()
    };
    let mut starts = Vec::new();
    for path in &args.from {
        let map = crate::input::load(path, crate::input::Format::Auto)?.map;
        if map.n() > limits.max_n {
            return Err(Failure::usage(format!(
                "--from {}: {} vertices, more than --max-n {}",
                path.display(),
                map.n(),
                limits.max_n
            )));
        }
        starts.push((format!("file {}", path.display()), map));
    }
    starts.extend(search::start_maps(args.start, args.seed, &limits));
    if starts.is_empty() {
        return Err(Failure::usage(format!(
            "no start map has at most {} vertices",
            args.max_n
        )));
    }
    let config = Config {
        seed: args.seed,
        evals: args.evals,
        budget,
        limits,
        pool: args.pool,
        keep: args.keep,
        stall: args.stall,
        min_r: args.min_r,
        goal: None,
    };
    let mut progress = Progress::new(args, budget);
    let ratio = args.ratio;
    let outcome = search::search(&starts, &config, &|m| ratio.evaluate(m), &mut |s| {
        progress.update(s)
    });
    progress.bar.finish_and_clear();
    let written = write_best(args, budget, &outcome)?;
    out!("{}", summary(args, &outcome, &written));
    Ok(())
}

/// The family (or random kind) of a start's name: its first word.
fn family_of(name: &str) -> &str {
    name.split(' ').next().unwrap_or(name)
}

/// Per family or random kind, its best start: (name, n, r, value).
fn best_starts(outcome: &Outcome) -> Vec<(String, usize, usize, Rational)> {
    let mut best: Vec<(String, usize, usize, Rational)> = Vec::new();
    for s in &outcome.starts {
        let Some(v) = &s.value else { continue };
        let fam = family_of(&s.name);
        match best.iter_mut().find(|b| family_of(&b.0) == fam) {
            Some(b) if (v, std::cmp::Reverse(s.n)) > (&b.3, std::cmp::Reverse(b.1)) => {
                *b = (s.name.clone(), s.n, s.r, v.clone());
            }
            Some(_) => {}
            None => best.push((s.name.clone(), s.n, s.r, v.clone())),
        }
    }
    best.sort_by(|a, b| b.3.cmp(&a.3).then(a.1.cmp(&b.1)));
    best
}

fn is_family(name: &str) -> bool {
    let fam = family_of(name);
    wai_gen::FAMILIES.iter().any(|f| f.id == fam) || wai_gen::LAYOUTS.iter().any(|l| l.id == fam)
}

/// Whether a value breaks the claim (only Theorem 5.15's k is an exact
/// statement a single map can break).
fn breaks(ratio: Ratio, value: &Rational) -> bool {
    ratio == Ratio::K && *value > ratio.ceiling()
}

fn note(args: &Args, f: &Found, outcome: &Outcome, rank: usize) -> String {
    let ratio = args.ratio;
    let v = &f.eval.value;
    let families = best_starts(outcome)
        .into_iter()
        .find(|b| is_family(&b.0))
        .map(|b| {
            format!(
                "the best thesis family start, {} (n = {}, r = {}), reaches {} ≈ {}",
                b.0,
                b.1,
                b.2,
                b.3,
                approx(&b.3)
            )
        })
        .unwrap_or_else(|| "no thesis family was among the starts".to_owned());
    let place = if rank == 1 {
        "the largest".to_owned()
    } else {
        format!("the {rank}th largest (distinct map)")
    };
    let verdict = if breaks(ratio, v) {
        format!(
            "The value k = {v} is above Theorem 5.15's bound {}: a violation found by search; whether the \
             thesis or our code is wrong is not known yet",
            wai_lemmas::ch5::t5_15::BOUND
        )
    } else if ratio == Ratio::K {
        format!(
            "The value k is within Theorem 5.15's bound {}: nothing here is a violation; neither the \
             thesis nor our code is wrong",
            wai_lemmas::ch5::t5_15::BOUND
        )
    } else {
        let side = if *v > ratio.ceiling() {
            "above"
        } else {
            "below"
        };
        format!(
            "The ratio is {side} the checker's ceiling {} (wai_lemmas::{}); an O(·) bound is \
             never decided by one map, so nothing here is a violation",
            ratio.ceiling(),
            ratio.claim().to_lowercase().replace('.', "_")
        )
    };
    format!(
        "An extreme map, not a figure of the thesis: {place} value of {} that the seeded local \
         search of `wai search-extremes` reached with seed {} in {} evaluations: {v} \
         ≈ {} on n = {}, r = {}, from the start {} after {} accepted mutations (evaluation {}). \
         For comparison, {families}. {verdict}. meta.search has the details and the command \
         that reproduces the run.",
        ratio.measure(),
        args.seed,
        outcome.evaluations,
        approx(v),
        f.map.n(),
        f.map.r(),
        f.start,
        f.mutations,
        f.at,
    )
}

fn file_name(args: &Args, rank: usize) -> String {
    let suffix = if rank == 1 {
        String::new()
    } else {
        format!("-{rank}")
    };
    format!(
        "{}-extreme-{}-seed{}{suffix}.json",
        args.ratio.claim(),
        args.ratio.id(),
        args.seed
    )
}

/// The file of one best map: the map format plus `claim`, `kind`, `note`
/// and `meta.search`.
fn file_text(
    args: &Args,
    budget: Option<Duration>,
    f: &Found,
    outcome: &Outcome,
    rank: usize,
) -> String {
    let map = &f.map;
    let kind = if breaks(args.ratio, &f.eval.value) {
        "violation"
    } else {
        "figure"
    };
    let cmd = command(args, outcome.evaluations);
    let name = format!("extreme-{}-seed{}-{rank}", args.ratio.id(), args.seed);
    let meta = json!({
        "search": {
            "ratio": args.ratio.id(),
            "measure": args.ratio.measure(),
            "value": f.eval.value.to_string(),
            "value_decimal": approx(&f.eval.value),
            "n": map.n(),
            "r": map.r(),
            "at": f.eval.detail,
            "seed": args.seed,
            "budget": args.budget,
            "budget_seconds": budget.map(|b| b.as_secs()),
            "evaluations": outcome.evaluations,
            "found_at_evaluation": f.at,
            "start": f.start,
            "mutations": f.mutations,
            "rank": rank,
            "command": cmd,
        }
    });
    wai_hunt::counterexample::file_text(
        map,
        &name,
        &format!("found by `{cmd}`"),
        args.ratio.claim(),
        kind,
        &note(args, f, outcome, rank),
        &meta,
    )
}

fn write_best(
    args: &Args,
    budget: Option<Duration>,
    outcome: &Outcome,
) -> Result<Vec<PathBuf>, Failure> {
    if outcome.best.is_empty() {
        return Ok(Vec::new());
    }
    std::fs::create_dir_all(&args.out)
        .map_err(|e| Failure::io(format!("{}: {e}", args.out.display())))?;
    let mut written = Vec::new();
    for (k, f) in outcome.best.iter().enumerate() {
        let path = args.out.join(file_name(args, k + 1));
        std::fs::write(&path, file_text(args, budget, f, outcome, k + 1))
            .map_err(|e| Failure::io(format!("{}: {e}", path.display())))?;
        written.push(path);
    }
    Ok(written)
}

fn summary(args: &Args, o: &Outcome, written: &[PathBuf]) -> String {
    use std::fmt::Write;
    let mut s = String::new();
    let per_eval = o
        .evaluating
        .as_micros()
        .checked_div(u128::from(o.evaluations))
        .unwrap_or(0);
    let _ = writeln!(
        s,
        "search-extremes: {} — seed {}, {} evaluations in {} s ({}.{:03} ms per evaluation), \
         {} improvements, {} mutation proposals refused",
        args.ratio.measure(),
        args.seed,
        o.evaluations,
        o.elapsed.as_secs(),
        per_eval / 1000,
        per_eval % 1000,
        o.improvements,
        o.refused
    );
    if o.too_few_reflex > 0 {
        let _ = writeln!(
            s,
            "  {} mutants with fewer than {} reflex vertices were not evaluated",
            o.too_few_reflex, args.min_r
        );
    }
    match o.best.first() {
        Some(f) => {
            let _ = writeln!(
                s,
                "best: {} ≈ {} on n = {}, r = {} (from {} after {} accepted mutations, evaluation {}; {})",
                f.eval.value,
                approx(&f.eval.value),
                f.map.n(),
                f.map.r(),
                f.start,
                f.mutations,
                f.at,
                f.eval.detail
            );
            if breaks(args.ratio, &f.eval.value) {
                let _ = writeln!(
                    s,
                    "  above Theorem 5.15's bound {}: a violation",
                    wai_lemmas::ch5::t5_15::BOUND
                );
            }
        }
        None => {
            let _ = writeln!(s, "best: none (no start map was evaluated)");
        }
    }
    let _ = writeln!(
        s,
        "starts ({} evaluated), the best of each family or random kind:",
        o.starts.len()
    );
    for (name, n, r, v) in best_starts(o) {
        let _ = writeln!(
            s,
            "  {v:>8} ≈ {}  n = {n:>2}, r = {r:>2}  {name}",
            approx(&v)
        );
    }
    if !o.panicked.is_empty() {
        let _ = writeln!(
            s,
            "{} evaluations panicked (a bug: the maps are valid); the first map:\n{}",
            o.panicked.len(),
            wai_map::json::to_json(&o.panicked[0])
        );
    }
    for p in written {
        let _ = writeln!(s, "wrote {}", p.display());
    }
    let _ = writeln!(s, "reproduce: {}", command(args, o.evaluations));
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The map of a written file.
    fn read_back(path: &std::path::Path) -> wai_map::Map {
        wai_map::json::from_json(&std::fs::read(path).unwrap())
            .unwrap()
            .map
    }

    #[test]
    fn a_written_file_is_a_loadable_figure() {
        let dir = std::env::temp_dir().join(format!("wai-extremes-unit-{}", std::process::id()));
        let args = Args {
            ratio: Ratio::Ec,
            budget: None,
            evals: Some(3),
            seed: 1,
            start: Starts::Families,
            from: Vec::new(),
            out: dir.clone(),
            max_n: 16,
            min_r: 0,
            pool: 2,
            keep: 2,
            stall: 5,
            free_angles: false,
        };
        run(&args).unwrap();
        let first = dir.join("T5.17-extreme-ec-seed1.json");
        let v: serde_json::Value = serde_json::from_slice(&std::fs::read(&first).unwrap()).unwrap();
        assert_eq!(
            (v["claim"].as_str(), v["kind"].as_str()),
            (Some("T5.17"), Some("figure"))
        );
        assert!(v["note"]
            .as_str()
            .unwrap()
            .contains("nothing here is a violation"));
        assert_eq!(v["meta"]["search"]["evaluations"], 3);
        let map = read_back(&first);
        assert!(map.n() <= 16);
        assert!(dir.join("T5.17-extreme-ec-seed1-2.json").exists());
        std::fs::remove_dir_all(dir).ok();
    }
}
