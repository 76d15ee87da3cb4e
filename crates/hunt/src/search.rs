//! The counterexample search behind `wai check`: checkers over a stream of
//! maps ([`crate::stream`]), in parallel, for a number of maps or a time
//! budget.
//!
//! [`search`] runs every checker on every map, one map per task on rayon's
//! threads, each worker taking the next map as soon as it is done (no
//! batch waits for its slowest map). With a count, the maps are the first
//! N of the stream, and the summary is the same whatever the number of
//! threads. With a budget, every lane of the stream (each generated kind,
//! the fixed maps) gets an equal share of the time: a worker takes the next
//! map of the lane that has used the least time so far, so a kind whose maps
//! are slow does not starve the quick ones; each lane's maps are a prefix
//! of its part of the stream (the maps of the round-robin stream with the
//! same arguments), and a finite lane that runs out leaves its share to
//! the others. The maps a budget reaches depend on the machine; the
//! summary says how many of each kind.
//!
//! Violations that are known failures stay in the summary, reduced to their
//! kind and without their map, but are not counterexamples;
//! [`Outcome::counterexamples`] leaves them out.

use std::sync::mpsc;
use std::sync::Mutex;
use std::time::{Duration, Instant};

use wai_lemmas::Checker;
use wai_map::Map;

use crate::record::KindCount;
use crate::shard::Shard;
use crate::stream::{Lane, Stream};
use crate::summary::{run_profiled, FoundViolation, Profile, Summary};

/// How long a search runs.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Limit {
    /// The first this many maps of the stream (fewer if a fixed stream
    /// ends first).
    Count(u64),
    /// Until this much time has passed (the maps under way are finished),
    /// shared equally by the lanes of the stream.
    Budget(Duration),
}

/// What [`search`] found.
#[derive(Debug, Clone)]
pub struct Outcome {
    /// Every checker's totals over the maps; violations in stream order.
    pub summary: Summary,
    /// Maps per kind, in the order of their first map in the stream.
    pub map_kinds: Vec<KindCount>,
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

/// The scheduler's state: per lane, the next map, the time its finished
/// maps took and the start of each map under way.
struct Lanes {
    lanes: Vec<Lane>,
    next: Vec<u64>,
    used: Vec<Duration>,
    running: Vec<Vec<(u64, Instant)>>,
    stop: bool,
}

impl Lanes {
    /// The next map to check: (lane, stream index), from the lane that has
    /// used the least time — its finished maps and the maps under way so
    /// far, so a slow map in progress counts against its lane at once —
    /// and still has maps; `None` when every lane is done or the search
    /// stops.
    fn take(&mut self) -> Option<(usize, u64)> {
        if self.stop {
            return None;
        }
        let now = Instant::now();
        let spent = |l: usize| -> Duration {
            self.used[l]
                + self.running[l]
                    .iter()
                    .map(|(_, t)| now - *t)
                    .sum::<Duration>()
        };
        let lane = (0..self.lanes.len())
            .filter(|&l| self.lanes[l].index(self.next[l]).is_some())
            .min_by_key(|&l| (spent(l), l))?;
        let index = self.lanes[lane].index(self.next[lane])?;
        self.next[lane] += 1;
        self.running[lane].push((index, now));
        Some((lane, index))
    }

    /// Map `index` of lane `lane` is done.
    fn done(&mut self, lane: usize, index: u64) {
        let now = Instant::now();
        if let Some(k) = self.running[lane].iter().position(|(i, _)| *i == index) {
            let (_, began) = self.running[lane].swap_remove(k);
            self.used[lane] += now - began;
        }
    }
}

/// A rayon pool of one thread, the calling thread itself
/// (`use_current_thread`): inside it the decomposition's parallel loops
/// run inline instead of handing every loop of a small map to another
/// thread, and no map is handed to a pool thread and back. `None` if the
/// calling thread already belongs to a pool.
pub fn own_thread_pool() -> Option<rayon::ThreadPool> {
    rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .use_current_thread()
        .build()
        .ok()
}

/// Runs `checkers` over `stream` until `limit` on as many worker threads
/// as rayon's pool has (set the pool's size before calling), calling
/// `progress(maps done, elapsed)` as maps finish. With `stop_early`, stops
/// taking maps once a counterexample is found. `shard` takes its part of
/// the run ([`Shard::of_lane`] of each lane, a budget / N of the time);
/// [`Shard::WHOLE`] is the whole run.
pub fn search(
    checkers: &[Checker],
    stream: &Stream,
    limit: Limit,
    shard: Shard,
    stop_early: bool,
    progress: &(dyn Fn(u64, Duration) + Sync),
) -> Outcome {
    let start = Instant::now();
    let whole = match limit {
        Limit::Count(n) => vec![Lane {
            name: String::new(),
            start: 0,
            step: 1,
            len: Some(stream.len().map_or(n, |len| n.min(len))),
        }],
        Limit::Budget(_) => stream.lanes(),
    };
    let lanes: Vec<Lane> = whole.iter().map(|l| shard.of_lane(l)).collect();
    // A shard's share of the run's time.
    let budget = match limit {
        Limit::Budget(b) => Some(b / shard.count.clamp(1, u64::from(u32::MAX)) as u32),
        Limit::Count(_) => None,
    };
    // How many maps the run can take at most (`None`: endless lanes).
    let at_most: Option<u64> = lanes.iter().map(|l| l.len).sum();
    let state = Mutex::new(Lanes {
        next: vec![0; lanes.len()],
        used: vec![Duration::ZERO; lanes.len()],
        running: vec![Vec::new(); lanes.len()],
        lanes,
        stop: false,
    });
    let take = || {
        let mut s = state.lock().expect("no worker panics holding the lock");
        if budget.is_some_and(|b| start.elapsed() >= b) {
            s.stop = true;
        }
        s.take()
    };
    let mut summary = Summary::empty(checkers);
    let mut profile = Profile::default();
    // (kind, maps, the stream index of its first map).
    let mut per_kind: Vec<(String, u64, u64)> = Vec::new();
    let workers = rayon::current_num_threads().max(1);
    let few_maps = at_most.is_some_and(|n| n <= workers as u64);
    let (tx, rx) = mpsc::channel::<(u64, String, Summary, Profile)>();
    // Plain threads, not rayon tasks: the loop below blocks on the
    // channel, and inside a rayon scope it would hold one of the pool's
    // threads (all of them with --threads 1: a deadlock).
    std::thread::scope(|scope| {
        for _ in 0..workers {
            let tx = tx.clone();
            let take = &take;
            let state = &state;
            scope.spawn(move || {
                // Each worker runs its maps inside its own pool (the workers
                // already use every core, one map each). Not when there are
                // fewer maps than workers, which is where a large map's own
                // parallel loops use the idle cores.
                let inline = match few_maps {
                    true => None,
                    false => own_thread_pool(),
                };
                while let Some((lane, index)) = take() {
                    let (kind, map): (String, Map) =
                        stream.map(index).expect("lanes hold indices of the stream");
                    let (one, p) = match &inline {
                        Some(pool) => pool.install(|| run_profiled(checkers, [&map])),
                        None => run_profiled(checkers, [&map]),
                    };
                    // The worker that finds a counterexample stops the
                    // search itself: through the channel, the other
                    // workers could take several more quick maps first.
                    let found = stop_early && one.counterexamples().next().is_some();
                    {
                        let mut s = state.lock().expect("no worker panics holding the lock");
                        s.done(lane, index);
                        s.stop |= found;
                    }
                    if tx.send((index, kind, light(one), p)).is_err() {
                        break;
                    }
                }
            });
        }
        drop(tx);
        for (index, kind, one, p) in rx {
            profile.absorb(&p);
            match per_kind.iter_mut().find(|(k, _, _)| *k == kind) {
                Some((_, count, first)) => {
                    *count += 1;
                    *first = (*first).min(index);
                }
                None => per_kind.push((kind, 1, index)),
            }
            summary.absorb(one, index as usize);
            progress(summary.maps as u64, start.elapsed());
        }
    });
    summary.sort_by_map();
    // Kinds in the order of their first map in the stream.
    per_kind.sort_by_key(|(_, _, first)| *first);
    Outcome {
        summary,
        map_kinds: per_kind
            .into_iter()
            .map(|(kind, maps, first)| KindCount {
                kind,
                maps,
                first: Some(first),
            })
            .collect(),
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
/// failure (a panic counts): the predicate [`crate::shrink::shrink`] keeps.
pub fn still_violated(checker: &Checker, map: &Map) -> bool {
    let report = crate::caught::check_map_caught(checker, map);
    let found = checker.counterexamples(&report).next().is_some();
    found
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::stream::parse_kinds;

    #[test]
    fn a_count_gives_the_same_summary_on_any_number_of_threads() {
        let stream = Stream::Generated {
            kinds: parse_kinds("random-orthogonal:6-10,random-simple-star:5-9").unwrap(),
            seed: 3,
        };
        let checkers = [
            wai_lemmas::ch3::t3_3a::CHECKER,
            wai_lemmas::ch5::t5_17::CHECKER,
        ];
        // One thread: the collecting loop must not take the only worker.
        let a = rayon::ThreadPoolBuilder::new()
            .num_threads(1)
            .build()
            .unwrap()
            .install(|| {
                search(
                    &checkers,
                    &stream,
                    Limit::Count(12),
                    Shard::WHOLE,
                    false,
                    &|_, _| {},
                )
            });
        let b = rayon::ThreadPoolBuilder::new()
            .num_threads(3)
            .build()
            .unwrap()
            .install(|| {
                search(
                    &checkers,
                    &stream,
                    Limit::Count(12),
                    Shard::WHOLE,
                    false,
                    &|_, _| {},
                )
            });
        assert_eq!(a.summary, b.summary);
        assert_eq!(a.summary.maps, 12);
        assert_eq!(
            a.map_kinds,
            vec![
                KindCount {
                    first: Some(0),
                    ..KindCount::new("random-orthogonal", 6)
                },
                KindCount {
                    first: Some(1),
                    ..KindCount::new("random-simple-star", 6)
                },
            ]
        );
    }

    #[test]
    fn a_budget_shares_the_time_among_the_lanes() {
        // Layouts take tens of milliseconds a map, small random maps less:
        // with a budget both kinds progress, the quick one further, and
        // each kind's maps are the first of its lane.
        let stream = Stream::Generated {
            kinds: parse_kinds("repeated-niches,random-orthogonal:6-8").unwrap(),
            seed: 2,
        };
        let checkers = [
            wai_lemmas::ch5::t5_17::CHECKER,
            wai_lemmas::ch3::l3_7::CHECKER,
        ];
        let out = search(
            &checkers,
            &stream,
            Limit::Budget(Duration::from_millis(600)),
            Shard::WHOLE,
            false,
            &|_, _| {},
        );
        let count = |kind: &str| {
            out.map_kinds
                .iter()
                .find(|k| k.kind == kind)
                .map_or(0, |k| k.maps)
        };
        let (slow, quick) = (count("repeated-niches"), count("random-orthogonal"));
        assert!(slow >= 1 && quick > slow, "{:?}", out.map_kinds);
        assert_eq!(out.summary.maps as u64, slow + quick);
        // The same maps by count: lane 1's first `quick` maps are stream
        // indices 1, 3, 5, ...; re-checking them alone gives the same T5.17
        // examined count as the budgeted run's share of them.
        let t = out.summary.tally("T5.17").unwrap();
        assert_eq!(t.examined, slow + quick);
    }

    #[test]
    fn the_planted_bug_is_found_and_stops_early() {
        let stream = Stream::Generated {
            kinds: parse_kinds("random-orthogonal:6-12").unwrap(),
            seed: 0,
        };
        let checkers = [wai_lemmas::planted::SHIFTED_LABELS];
        let out = search(
            &checkers,
            &stream,
            Limit::Count(100),
            Shard::WHOLE,
            true,
            &|_, _| {},
        );
        assert!(!out.counterexamples().is_empty());
        assert!(out.summary.maps <= 8, "{}", out.summary.maps);
        let v = out.counterexamples()[0];
        let map = wai_map::json::from_json(v.map_json.as_bytes()).unwrap().map;
        assert!(still_violated(&wai_lemmas::planted::SHIFTED_LABELS, &map));
    }
}
