//! What a search keeps: each counterexample shrunk ([`crate::shrink`]) and
//! written to `counterexamples/` with the command that replays it, and the
//! replay of a stored file.

use std::path::{Path, PathBuf};

use serde_json::{json, Value};
use wai_lemmas::{Checker, Report};
use wai_map::Map;

use crate::search::{still_violated, Outcome};

/// How counterexamples are stored.
#[derive(Debug, Clone)]
pub struct StoreOptions {
    /// Store as found, without shrinking.
    pub no_shrink: bool,
    /// At most this many candidate maps checked while shrinking one.
    pub shrink_tries: usize,
    /// The run's seed (part of the file name).
    pub seed: u64,
    /// The planted bug the run used, if any.
    pub planted: Option<String>,
    /// The command line of the run.
    pub command: String,
}

/// One counterexample written to a file.
#[derive(Debug, Clone)]
pub struct Stored {
    pub claim: &'static str,
    /// The map it was found on (its name, or `map #i`).
    pub found_on: String,
    /// The vertices of that map.
    pub from_n: usize,
    /// The map stored (shrunk unless asked not to).
    pub map: Map,
    /// Shrinking moves accepted.
    pub steps: usize,
    /// The violation on the stored map.
    pub what: String,
    pub path: PathBuf,
}

impl Stored {
    /// The command that replays it.
    pub fn replay(&self) -> String {
        format!("wai check --replay {}", self.path.display())
    }

    /// As JSON, for `wai check --json`.
    pub fn json(&self) -> Value {
        json!({
            "claim": self.claim,
            "found_on": self.found_on,
            "n_found": self.from_n,
            "n": self.map.n(),
            "r": self.map.r(),
            "shrink_steps": self.steps,
            "what": self.what,
            "file": self.path.display().to_string(),
            "replay": self.replay(),
        })
    }
}

/// Per claim with a counterexample in `outcome`: the one on the smallest
/// map, shrunk (unless `options.no_shrink`) by the claim's checker among
/// `checkers` and written to `out`. `progress` hears of each shrink before
/// it starts.
pub fn store_counterexamples(
    outcome: &Outcome,
    checkers: &[Checker],
    options: &StoreOptions,
    out: &Path,
    progress: &mut dyn FnMut(&str),
) -> Result<Vec<Stored>, String> {
    let mut stored = Vec::new();
    let counterexamples = outcome.counterexamples();
    for checker in checkers {
        let claim = checker.id;
        let Some(first) = counterexamples
            .iter()
            .copied()
            .filter(|v| v.claim == claim)
            .min_by_key(|v| (v.map_json.len(), v.map_index))
        else {
            continue;
        };
        let found = wai_map::json::from_json(first.map_json.as_bytes())
            .map_err(|e| format!("the violating map does not read back: {e}"))?
            .map;
        let shrunk = if options.no_shrink {
            None
        } else {
            progress(&format!(
                "shrinking the {claim} counterexample on {} (n = {})",
                first.map_name.as_deref().unwrap_or("an unnamed map"),
                found.n()
            ));
            Some(crate::shrink::shrink(
                &found,
                |m| still_violated(checker, m),
                options.shrink_tries,
            ))
        };
        let (map, steps) = match &shrunk {
            Some(s) => (s.map.clone(), s.steps),
            None => (found.clone(), 0),
        };
        // The violation as reported on the stored map.
        let report = crate::caught::check_map_caught(checker, &map);
        let violation = checker
            .counterexamples(&report)
            .next()
            .unwrap_or(&first.violation)
            .clone();
        std::fs::create_dir_all(out).map_err(|e| format!("{}: {e}", out.display()))?;
        let stem = format!("{claim}-check-seed{}-map{}", options.seed, first.map_index);
        let s = Stored {
            claim,
            found_on: first
                .map_name
                .clone()
                .unwrap_or_else(|| format!("map #{}", first.map_index)),
            from_n: found.n(),
            map,
            steps,
            what: violation.what.clone(),
            path: out.join(format!("{stem}.json")),
        };
        let meta = json!({"check": {
            "command": options.command,
            "found_on": s.found_on,
            "map_index": first.map_index,
            "n_found": s.from_n,
            "shrink_steps": steps,
            "shrink_tries": shrunk.as_ref().map(|s| s.tries),
            "planted": options.planted,
            "violation": violation.data,
            "replay": s.replay(),
        }});
        let note = format!(
            "A violation of {claim} found by `wai check` on {} (n = {}) and shrunk to n = {}, \
             r = {} in {steps} steps: {}. Whether the thesis or our code is wrong is not known \
             yet.{} Replay: `{}`.",
            s.found_on,
            s.from_n,
            s.map.n(),
            s.map.r(),
            s.what,
            if options.planted.is_some() {
                " (Planted bug: the checker was wrong on purpose.)"
            } else {
                ""
            },
            s.replay()
        );
        let text = crate::counterexample::file_text(
            &s.map,
            &stem,
            &format!("found by `{}`", options.command),
            claim,
            "violation",
            &note,
            &meta,
        );
        crate::record::write_whole(&s.path, text.as_bytes())
            .map_err(|e| format!("{}: {e}", s.path.display()))?;
        stored.push(s);
    }
    Ok(stored)
}

/// Writes, per claim of `outcome` that measured a ratio, the map of its
/// largest ratio to `dir/<claim>-largest.json`.
pub fn write_largest(outcome: &Outcome, dir: &Path) -> Result<(), String> {
    std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    for t in &outcome.summary.tallies {
        if let Some(l) = &t.largest {
            let path = dir.join(format!("{}-largest.json", t.claim));
            crate::record::write_whole(&path, l.map_json.as_bytes())
                .map_err(|e| format!("{}: {e}", path.display()))?;
        }
    }
    Ok(())
}

/// The checker a stored counterexample file names: its planted bug
/// (`planted`, else the file's `meta.check.planted`) or its claim's.
pub fn replay_checker(file: &Value, planted: Option<&str>) -> Result<Checker, String> {
    let claim = file["claim"]
        .as_str()
        .ok_or("no \"claim\" field (the format of counterexamples/README.md)")?;
    let planted = planted.or_else(|| file["meta"]["check"]["planted"].as_str());
    match planted {
        Some(name) => {
            wai_lemmas::planted::checker(name).ok_or_else(|| format!("unknown planted bug {name}"))
        }
        None => match wai_lemmas::claim(claim) {
            Some(c) => c
                .checker
                .ok_or_else(|| format!("claim {claim} has no checker yet")),
            None => Err(format!("claim {claim} is not in the registry")),
        },
    }
}

/// A replay's verdict: the report, and how many of its violations are
/// counterexamples (not known failures; a panic is one).
pub fn replay(checker: &Checker, map: &Map) -> (Report, usize) {
    let report = crate::caught::check_map_caught(checker, map);
    let open = checker.counterexamples(&report).count();
    (report, open)
}
