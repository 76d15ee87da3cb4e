//! The counterexample search behind `wai check`: checkers over a stream of
//! maps ([`crate::stream`]), in parallel, for a number of maps or a time
//! budget.
//!
//! [`search`] runs every checker on every map, one map per task, and merges
//! the per-map summaries in map order, so a run of `--count N` gives the
//! same summary whatever the number of threads. With a budget, the maps
//! reached depend on the machine; the summary says how many.
//!
//! Violations that are known failures stay in the summary, reduced to their
//! kind and without their map, but are not counterexamples;
//! [`Outcome::counterexamples`] leaves them out.

use std::time::{Duration, Instant};

use rayon::prelude::*;
use wai_lemmas::Checker;
use wai_map::Map;

use crate::stream::Stream;
use crate::summary::{run_profiled, FoundViolation, Profile, Summary};

/// How long a search runs.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Limit {
    /// This many maps (fewer if a fixed stream ends first).
    Count(u64),
    /// Until this much time has passed (and the batch under way is done).
    Budget(Duration),
}

/// What [`search`] found.
#[derive(Debug, Clone)]
pub struct Outcome {
    /// Every checker's totals over the maps, map indices in stream order.
    pub summary: Summary,
    /// Maps per kind, in order of first appearance.
    pub map_kinds: Vec<(String, u64)>,
    pub elapsed: Duration,
    /// Where the time went, summed over every worker (so it can exceed
    /// `elapsed` on several threads).
    pub profile: Profile,
}

impl Outcome {
    /// The violations that are not known failures.
    pub fn counterexamples(&self) -> Vec<&FoundViolation> {
        self.summary.counterexamples().collect()
    }
}

/// Runs `checkers` over `stream` until `limit`, `batch` maps at a time in
/// parallel (rayon's pool: set its threads before calling), calling
/// `progress(maps done, elapsed)` after each batch. With `stop_early`, stops
/// after the first batch with a counterexample.
pub fn search(
    checkers: &[Checker],
    stream: &Stream,
    limit: Limit,
    batch: u64,
    stop_early: bool,
    progress: &(dyn Fn(u64, Duration) + Sync),
) -> Outcome {
    let start = Instant::now();
    let end = match (limit, stream.len()) {
        (Limit::Count(n), Some(len)) => n.min(len),
        (Limit::Count(n), None) => n,
        (Limit::Budget(_), Some(len)) => len,
        (Limit::Budget(_), None) => u64::MAX,
    };
    let mut summary = Summary::empty(checkers);
    let mut profile = Profile::default();
    let mut map_kinds: Vec<(String, u64)> = Vec::new();
    let mut i = 0u64;
    while i < end {
        if let Limit::Budget(budget) = limit {
            if start.elapsed() >= budget {
                break;
            }
        }
        let upto = (i + batch.max(1)).min(end);
        let results: Vec<(String, Summary, Profile)> = (i..upto)
            .into_par_iter()
            .map(|j| {
                let (kind, map) = stream.map(j).expect("j is below the stream's length");
                let (one, p) = run_profiled(checkers, [&map]);
                (kind, light(one), p)
            })
            .collect();
        // Only this batch's maps are new: the earlier ones were looked at.
        let found = results
            .iter()
            .any(|(_, one, _)| one.counterexamples().next().is_some());
        for (offset, (kind, one, p)) in results.into_iter().enumerate() {
            profile.absorb(&p);
            match map_kinds.iter_mut().find(|(k, _)| *k == kind) {
                Some((_, count)) => *count += 1,
                None => map_kinds.push((kind, 1)),
            }
            summary.absorb(one, i as usize + offset);
        }
        i = upto;
        progress(i, start.elapsed());
        if stop_early && found {
            break;
        }
    }
    Outcome {
        summary,
        map_kinds,
        elapsed: start.elapsed(),
        profile,
    }
}

/// `summary` with its known failures reduced to their kind: a long run
/// meets hundreds of thousands (O5.3's hidden vertices), which are counted,
/// not replayed, so they need not each carry the map.
fn light(mut summary: Summary) -> Summary {
    for t in &mut summary.tallies {
        for v in &mut t.violations {
            if v.known {
                v.violation.data = serde_json::json!({ "kind": v.violation.data["kind"] });
                v.map_json = String::new();
            }
        }
    }
    summary
}

/// True if `checker` reports a violation on `map` that is not a known
/// failure: the predicate [`crate::shrink::shrink`] keeps.
pub fn still_violated(checker: &Checker, map: &Map) -> bool {
    let report = checker.check_map(map);
    let found = checker.counterexamples(&report).next().is_some();
    found
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::stream::parse_kinds;

    #[test]
    fn a_count_gives_the_same_summary_in_any_batch_size() {
        let stream = Stream::Generated {
            kinds: parse_kinds("random-orthogonal:6-10,random-simple-star:5-9").unwrap(),
            seed: 3,
        };
        let checkers = [
            wai_lemmas::ch3::t3_3a::CHECKER,
            wai_lemmas::ch5::t5_17::CHECKER,
        ];
        let a = search(&checkers, &stream, Limit::Count(12), 1, false, &|_, _| {});
        let b = search(&checkers, &stream, Limit::Count(12), 5, false, &|_, _| {});
        assert_eq!(a.summary, b.summary);
        assert_eq!(a.summary.maps, 12);
        assert_eq!(
            a.map_kinds,
            vec![
                ("random-orthogonal".to_owned(), 6),
                ("random-simple-star".to_owned(), 6)
            ]
        );
    }

    #[test]
    fn the_planted_bug_is_found_and_stops_early() {
        let stream = Stream::Generated {
            kinds: parse_kinds("random-orthogonal:6-12").unwrap(),
            seed: 0,
        };
        let checkers = [wai_lemmas::planted::SHIFTED_LABELS];
        let out = search(&checkers, &stream, Limit::Count(100), 4, true, &|_, _| {});
        assert!(!out.counterexamples().is_empty());
        assert!(out.summary.maps <= 8, "{}", out.summary.maps);
        let v = out.counterexamples()[0];
        let map = wai_map::json::from_json(v.map_json.as_bytes()).unwrap().map;
        assert!(still_violated(&wai_lemmas::planted::SHIFTED_LABELS, &map));
    }
}
