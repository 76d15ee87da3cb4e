//! `wai check --target CLAIM:CASE`: a seeded hill climb toward a map that
//! hits a case of a claim's proof (`wai_hunt::target`). The map found is
//! stored as a figure with the command that reproduces the search.

use std::path::PathBuf;
use std::time::Duration;

use rug::Rational;
use serde_json::json;
use wai_gen::mutate::Limits;
use wai_hunt::climb::{self, Config, Starts};
use wai_hunt::target::Target;

use crate::Failure;

/// Evaluations when neither --evals nor --budget is given.
const DEFAULT_EVALS: u64 = 2000;

/// The search of `--target spec`: at most `evals` evaluations (default
/// [`DEFAULT_EVALS`] without a budget) or `budget`, from `seed`; a map found
/// is stored in `out` (default `counterexamples/`).
pub fn run(
    spec: &str,
    evals: Option<u64>,
    budget: Option<Duration>,
    seed: u64,
    out: Option<&std::path::Path>,
) -> Result<(), Failure> {
    let target = Target::parse(spec).map_err(Failure::usage)?;
    let evals = match (evals, budget) {
        (None, None) => Some(DEFAULT_EVALS),
        (e, _) => e,
    };
    let limits = Limits {
        max_n: 40,
        ..Limits::default()
    };
    let mut starts = climb::start_maps(Starts::Both, seed, &limits);
    for layout in wai_gen::LAYOUTS {
        for s in 0..4 {
            if let Ok(m) = wai_gen::layout(layout.id, seed.wrapping_add(s)) {
                starts.push((format!("{} seed={}", layout.id, seed + s), m));
            }
        }
    }
    let config = Config {
        seed,
        evals,
        budget,
        limits,
        pool: 8,
        keep: 1,
        stall: 200,
        min_r: 1,
        goal: Some(Rational::from(1)),
    };
    let bar = crate::progress_bar(evals.unwrap_or(0));
    let outcome = climb::search(&starts, &config, &|m| target.evaluate(m), &mut |s| {
        bar.set_position(s.evaluations);
        if let Some(b) = s.best {
            bar.set_message(format!(
                "best {} hits, guide {}",
                b.eval.value, b.eval.guide
            ));
        }
    });
    bar.finish_and_clear();
    let effort = format!(
        "{} evaluations in {} s from {} start maps (thesis families, layouts, random maps; seed {})",
        outcome.evaluations,
        outcome.elapsed.as_secs(),
        outcome.starts.len(),
        seed
    );
    let Some(best) = outcome.best.first() else {
        outln!(
            "wai check --target {}: no map evaluated ({effort})",
            target.name()
        );
        return Ok(());
    };
    if best.eval.value == 0 {
        outln!(
            "wai check --target {}: not hit. {effort}. Closest: {} (n = {}, from {}), {}",
            target.name(),
            best.eval.detail,
            best.map.n(),
            best.start,
            target.case.what
        );
        return Ok(());
    }
    let out = out.map_or_else(|| PathBuf::from("counterexamples"), PathBuf::from);
    std::fs::create_dir_all(&out).map_err(|e| Failure::io(format!("{}: {e}", out.display())))?;
    let slug: String = target
        .case
        .name
        .chars()
        .map(|c| if c.is_ascii_alphanumeric() { c } else { '-' })
        .collect();
    let stem = format!("{}-case-{slug}", target.checker.id);
    let path = out.join(format!("{stem}.json"));
    let reproduce = format!(
        "wai check --target {} --seed {} --evals {}",
        target.name(),
        seed,
        best.at
    );
    let note = format!(
        "A map that hits case \"{}\" of {} ({}): {} instance(s). Found by a hill climb from {} \
         after {} mutation(s), evaluation {} of the search. Reproduce: `{reproduce}`.",
        target.case.name,
        target.checker.id,
        target.case.what,
        best.eval.value,
        best.start,
        best.mutations,
        best.at
    );
    let meta = json!({"target": {
        "case": target.case.name,
        "hits": best.eval.detail,
        "start": best.start,
        "mutations": best.mutations,
        "evaluation": best.at,
        "reproduce": reproduce,
    }});
    let text = wai_hunt::counterexample::file_text(
        &best.map,
        &stem,
        &format!("found by `{reproduce}`"),
        target.checker.id,
        "figure",
        &note,
        &meta,
    );
    std::fs::write(&path, text).map_err(|e| Failure::io(format!("{}: {e}", path.display())))?;
    outln!(
        "wai check --target {}: hit, {} instance(s) on a map of n = {}, r = {}; {effort}\n  stored: {}\n  reproduce: {reproduce}",
        target.name(),
        best.eval.value,
        best.map.n(),
        best.map.r(),
        path.display()
    );
    Ok(())
}
