//! Seeded hill climbing over map mutations (`wai_gen::mutate`) that
//! maximises an exact score read off the checkers' reports: a chapter 5
//! ratio (`wai search-extremes`, [`crate::extremes`]) or the instances of
//! a proof case never hit (`wai check --target`, [`crate::target`]).
//!
//! A pool of climbers starts from the best of the start maps (thesis
//! families and random maps); each round one climber, in turn, proposes a
//! valid mutant of its map, which is evaluated and replaces it if its ratio
//! is at least as large (equal ratios let the climber drift across
//! plateaus). A climber that has not improved for a while restarts, from a
//! copy of the best map so far or from the next start. The best distinct
//! maps seen are kept, larger ratio first, then fewer vertices, then the
//! earlier found.
//!
//! Everything is a function of the seed and the number of evaluations: one
//! random number generator (`ChaCha8Rng`) drives every choice, evaluations
//! are deterministic (the decomposition gives the same result for any
//! number of threads), and the stopping rule is checked only between
//! evaluations. A run stopped by time after N evaluations is therefore
//! reproduced by `--evals N`.
//!
//! Ratios are exact `Rational`s; floats appear only in printed decimals.

use std::collections::BTreeSet;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::time::{Duration, Instant};

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::Rational;
use serde_json::Value;
use wai_gen::mutate::{mutate, Limits};
use wai_map::Map;

/// A ratio measured on a map, and what it was measured on.
#[derive(Clone, Debug, PartialEq)]
pub struct Evaluation {
    pub value: Rational,
    /// A second, exact score that orders maps of equal `value` for the
    /// climbers (0 where the ratio has none): a slope on the plateaus of an
    /// integer count such as k.
    pub guide: Rational,
    pub detail: Value,
}

impl Evaluation {
    /// An evaluation without a guide.
    pub fn of(value: Rational, detail: Value) -> Evaluation {
        Evaluation {
            value,
            guide: Rational::new(),
            detail,
        }
    }

    /// `(value, guide)`, the climbers' order.
    fn score(&self) -> (&Rational, &Rational) {
        (&self.value, &self.guide)
    }
}

/// Where the search starts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Starts {
    /// Random maps of every kind of `wai_gen::RANDOM_KINDS`.
    Random,
    /// The thesis families (`wai_gen::FAMILIES`) at every parameter that
    /// fits the vertex cap.
    Families,
    /// Both: the families first.
    Both,
}

impl Starts {
    /// Every choice, with the name the command line uses.
    pub const ALL: [(Starts, &'static str); 3] = [
        (Starts::Random, "random"),
        (Starts::Families, "families"),
        (Starts::Both, "both"),
    ];

    /// The choice named `name`.
    pub fn named(name: &str) -> Option<Starts> {
        Starts::ALL
            .iter()
            .find(|(_, n)| *n == name)
            .map(|(s, _)| *s)
    }
}

/// The start maps, named, each within `limits` (n ≤ max_n).
pub fn start_maps(which: Starts, seed: u64, limits: &Limits) -> Vec<(String, Map)> {
    let mut out = Vec::new();
    let fits = |m: &Map| m.n() <= limits.max_n && m.n() >= limits.min_n;
    if matches!(which, Starts::Families | Starts::Both) {
        // Every family of wai_gen::FAMILIES at every parameter list of one
        // or two values that it accepts and that fits, each map once; n
        // grows with each parameter, so a loop stops at the first map
        // above the cap.
        let mut seen: BTreeSet<Vec<wai_exact::Point>> = BTreeSet::new();
        let mut push = |name: String, map: Result<Map, wai_gen::GenError>| -> bool {
            match map {
                Ok(m) if m.n() > limits.max_n => true,
                Ok(m) => {
                    if fits(&m) && seen.insert(m.vertices().to_vec()) {
                        out.push((name, m));
                    }
                    false
                }
                Err(_) => false,
            }
        };
        for family in wai_gen::FAMILIES {
            for k in 0..=64u32 {
                let id = family.id;
                if push(format!("{id} {k}"), wai_gen::family(id, &[k])) {
                    break;
                }
            }
            for a in 0..=8u32 {
                for b in 0..=8u32 {
                    let id = family.id;
                    if push(format!("{id} {a},{b}"), wai_gen::family(id, &[a, b])) {
                        break;
                    }
                }
            }
        }
        for layout in wai_gen::LAYOUTS {
            for s in 0..4 {
                push(
                    format!("{} seed={s}", layout.id),
                    wai_gen::layout(layout.id, s),
                );
            }
        }
    }
    if matches!(which, Starts::Random | Starts::Both) {
        let mut rng = ChaCha8Rng::seed_from_u64(seed ^ 0x5eed_5eed);
        let sizes: Vec<usize> = [8, 12, 16, 24, 32]
            .into_iter()
            .filter(|&n| n <= limits.max_n)
            .collect();
        for kind in wai_gen::RANDOM_KINDS {
            for &n in &sizes {
                let s: u64 = rng.random();
                if let Ok(m) = wai_gen::random(kind.id, n, s) {
                    if fits(&m) {
                        out.push((format!("{} n={n} seed={s}", kind.id), m));
                    }
                }
            }
        }
    }
    out
}

/// How a search runs.
#[derive(Clone, Debug)]
pub struct Config {
    pub seed: u64,
    /// Stop after this many evaluations (starts included).
    pub evals: Option<u64>,
    /// Stop once this much time has passed.
    pub budget: Option<Duration>,
    pub limits: Limits,
    /// Climbers.
    pub pool: usize,
    /// Best distinct maps kept.
    pub keep: usize,
    /// A climber restarts after this many of its evaluations without an
    /// improvement.
    pub stall: u64,
    /// Maps (starts and mutants) with fewer reflex vertices are not
    /// evaluated.
    pub min_r: usize,
    /// Stop as soon as a map reaches this value.
    pub goal: Option<Rational>,
}

/// A map with its evaluation and its history.
#[derive(Clone, Debug)]
pub struct Found {
    pub map: Map,
    pub eval: Evaluation,
    /// The start it descends from.
    pub start: String,
    /// Accepted mutations since that start.
    pub mutations: usize,
    /// The evaluation (1-based, starts included) that measured it.
    pub at: u64,
}

impl Found {
    /// Larger value first, then larger guide, then fewer vertices, then
    /// found earlier.
    fn rank(&self) -> (std::cmp::Reverse<(&Rational, &Rational)>, usize, u64) {
        (std::cmp::Reverse(self.eval.score()), self.map.n(), self.at)
    }
}

/// A start map's ratio.
#[derive(Clone, Debug)]
pub struct StartResult {
    pub name: String,
    pub n: usize,
    pub r: usize,
    /// `None` if the evaluation panicked.
    pub value: Option<Rational>,
}

/// What the search reports as it goes.
#[derive(Clone, Debug)]
pub struct Status<'a> {
    pub elapsed: Duration,
    pub evaluations: u64,
    pub best: Option<&'a Found>,
}

/// The result of a search.
#[derive(Clone, Debug, Default)]
pub struct Outcome {
    /// The best distinct maps, best first (at most `keep`).
    pub best: Vec<Found>,
    pub starts: Vec<StartResult>,
    pub evaluations: u64,
    /// Climber steps that improved the climber's ratio.
    pub improvements: u64,
    /// Mutation proposals refused (invalid or outside the limits).
    pub refused: u64,
    /// Mutants not evaluated for having fewer than `min_r` reflex vertices.
    pub too_few_reflex: u64,
    /// Maps on which an evaluation panicked (a bug: the map is valid).
    pub panicked: Vec<Map>,
    /// Time spent in evaluations, and in all.
    pub evaluating: Duration,
    pub elapsed: Duration,
}

/// One climber of the pool.
struct Climber {
    current: Found,
    stalled: u64,
}

/// Keeps the best `keep` distinct maps.
fn offer(best: &mut Vec<Found>, keep: usize, found: &Found) {
    if best
        .iter()
        .any(|b| b.map.vertices() == found.map.vertices())
    {
        return;
    }
    let pos = best
        .iter()
        .position(|b| found.rank() < b.rank())
        .unwrap_or(best.len());
    if pos < keep {
        best.insert(pos, found.clone());
        best.truncate(keep);
    }
}

/// Evaluate, catching a panic (a bug of ours on a valid map) as `None`.
fn guarded(evaluate: &dyn Fn(&Map) -> Evaluation, map: &Map) -> Option<Evaluation> {
    catch_unwind(AssertUnwindSafe(|| evaluate(map))).ok()
}

/// Rounds without an evaluation after which [`search`] gives up.
const BARREN_ROUNDS: u32 = 100_000;

/// Runs the search from `starts` (in order), maximising `evaluate`.
pub fn search(
    starts: &[(String, Map)],
    config: &Config,
    evaluate: &dyn Fn(&Map) -> Evaluation,
    progress: &mut dyn FnMut(&Status<'_>),
) -> Outcome {
    let clock = Instant::now();
    let mut rng = ChaCha8Rng::seed_from_u64(config.seed);
    let mut out = Outcome::default();
    let stop = |evaluations: u64, best: Option<&Found>| {
        config.evals.is_some_and(|n| evaluations >= n)
            || config.budget.is_some_and(|b| clock.elapsed() >= b)
            || config
                .goal
                .as_ref()
                .is_some_and(|g| best.is_some_and(|f| f.eval.value >= *g))
    };
    let timed = |map: &Map, out: &mut Outcome| {
        let t = Instant::now();
        let e = guarded(evaluate, map);
        out.evaluating += t.elapsed();
        out.evaluations += 1;
        if e.is_none() {
            out.panicked.push(map.clone());
        }
        e
    };
    let mut ranked: Vec<Found> = Vec::new();
    for (name, map) in starts {
        if stop(out.evaluations, out.best.first()) {
            break;
        }
        if map.r() < config.min_r {
            continue;
        }
        let e = timed(map, &mut out);
        out.starts.push(StartResult {
            name: name.clone(),
            n: map.n(),
            r: map.r(),
            value: e.as_ref().map(|e| e.value.clone()),
        });
        if let Some(eval) = e {
            let f = Found {
                map: map.clone(),
                eval,
                start: name.clone(),
                mutations: 0,
                at: out.evaluations,
            };
            offer(&mut out.best, config.keep, &f);
            ranked.push(f);
        }
        progress(&Status {
            elapsed: clock.elapsed(),
            evaluations: out.evaluations,
            best: out.best.first(),
        });
    }
    ranked.sort_by(|a, b| a.rank().cmp(&b.rank()));
    let mut climbers: Vec<Climber> = ranked
        .iter()
        .take(config.pool.max(1))
        .map(|f| Climber {
            current: f.clone(),
            stalled: 0,
        })
        .collect();
    let mut next_start = climbers.len() % ranked.len().max(1);
    let mut turn = 0usize;
    let mut idle = 0u32;
    // Rounds since the last evaluation: a search that can no longer make
    // an evaluable mutant (every proposal refused) ends rather than spin.
    let mut barren = 0u32;
    while !climbers.is_empty() && !stop(out.evaluations, out.best.first()) && barren < BARREN_ROUNDS
    {
        let c = turn % climbers.len();
        turn += 1;
        barren += 1;
        let parent = &climbers[c].current;
        let mutant = mutate(&parent.map, &config.limits, &mut rng);
        let restart;
        match mutant {
            None => restart = true,
            Some(m) => {
                out.refused += m.refused as u64;
                if m.map.r() < config.min_r {
                    out.too_few_reflex += 1;
                    idle += 1;
                    // A climber that keeps proposing maps below min_r
                    // without evaluating anything is restarted.
                    restart = idle > 1000;
                } else {
                    idle = 0;
                    barren = 0;
                    if let Some(eval) = timed(&m.map, &mut out) {
                        let child = Found {
                            map: m.map,
                            eval,
                            start: parent.start.clone(),
                            mutations: parent.mutations + 1,
                            at: out.evaluations,
                        };
                        offer(&mut out.best, config.keep, &child);
                        let climber = &mut climbers[c];
                        match child.eval.score().cmp(&climber.current.eval.score()) {
                            std::cmp::Ordering::Greater => {
                                out.improvements += 1;
                                climber.current = child;
                                climber.stalled = 0;
                            }
                            std::cmp::Ordering::Equal => {
                                climber.current = child;
                                climber.stalled += 1;
                            }
                            std::cmp::Ordering::Less => climber.stalled += 1,
                        }
                    } else {
                        climbers[c].stalled += 1;
                    }
                    restart = climbers[c].stalled >= config.stall;
                    progress(&Status {
                        elapsed: clock.elapsed(),
                        evaluations: out.evaluations,
                        best: out.best.first(),
                    });
                }
            }
        }
        if restart {
            idle = 0;
            let from = if rng.random_bool(0.5) || ranked.is_empty() {
                out.best[0].clone()
            } else {
                let f = ranked[next_start].clone();
                next_start = (next_start + 1) % ranked.len();
                f
            };
            climbers[c] = Climber {
                current: from,
                stalled: 0,
            };
        }
    }
    out.elapsed = clock.elapsed();
    out
}

/// Parses a duration: `90`, `90s`, `10m`, `1h30m`, `2h` (whole seconds,
/// minutes and hours).
pub fn parse_duration(text: &str) -> Result<Duration, String> {
    let bad = || format!("{text:?} is not a duration (e.g. 90s, 10m, 1h30m)");
    let t = text.trim();
    if t.is_empty() {
        return Err(bad());
    }
    if let Ok(s) = t.parse::<u64>() {
        return Ok(Duration::from_secs(s));
    }
    let mut total: u64 = 0;
    let mut digits = String::new();
    for ch in t.chars() {
        if ch.is_ascii_digit() {
            digits.push(ch);
            continue;
        }
        let unit = match ch {
            's' => 1,
            'm' => 60,
            'h' => 3600,
            _ => return Err(bad()),
        };
        let v: u64 = digits.parse().map_err(|_| bad())?;
        total = v
            .checked_mul(unit)
            .and_then(|x| total.checked_add(x))
            .ok_or_else(bad)?;
        digits.clear();
    }
    if !digits.is_empty() {
        return Err(bad());
    }
    Ok(Duration::from_secs(total))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn config(seed: u64, evals: u64) -> Config {
        Config {
            seed,
            evals: Some(evals),
            budget: None,
            limits: Limits {
                max_n: 20,
                ..Limits::default()
            },
            pool: 3,
            keep: 2,
            stall: 10,
            min_r: 0,
            goal: None,
        }
    }

    /// A cheap stand-in for a ratio: r / n.
    fn reflex_share(map: &Map) -> Evaluation {
        Evaluation::of(
            Rational::from((map.r() as u64, map.n() as u64)),
            Value::Null,
        )
    }

    fn starts() -> Vec<(String, Map)> {
        start_maps(Starts::Both, 3, &config(0, 0).limits)
            .into_iter()
            .step_by(5)
            .collect()
    }

    fn summary(o: &Outcome) -> Vec<(Vec<wai_exact::Point>, Rational, u64)> {
        o.best
            .iter()
            .map(|f| (f.map.vertices().to_vec(), f.eval.value.clone(), f.at))
            .collect()
    }

    #[test]
    fn same_seed_and_evaluations_give_the_same_best_maps() {
        let s = starts();
        let run = |seed| search(&s, &config(seed, 300), &reflex_share, &mut |_| {});
        let (a, b) = (run(1), run(1));
        assert_eq!(a.evaluations, 300);
        assert_eq!(summary(&a), summary(&b));
        assert_eq!((a.refused, a.improvements), (b.refused, b.improvements));
        // The search improves on its starts.
        let start_best = a
            .starts
            .iter()
            .filter_map(|s| s.value.clone())
            .max()
            .unwrap();
        assert!(a.best[0].eval.value > start_best, "{:?}", a.best[0].eval);
        assert_eq!(a.best.len(), 2);
        assert!(a.best[0].eval.value >= a.best[1].eval.value);
        assert_ne!(summary(&run(2)), summary(&a));
    }

    #[test]
    fn every_best_map_is_valid_and_within_the_limits() {
        let s = starts();
        let c = config(4, 200);
        let o = search(&s, &c, &reflex_share, &mut |_| {});
        for f in &o.best {
            assert!(wai_map::validate_all(f.map.vertices()).is_empty());
            assert!(f.map.n() <= c.limits.max_n);
            assert_eq!(f.eval, reflex_share(&f.map));
        }
    }

    #[test]
    fn a_goal_stops_the_search_at_the_first_map_reaching_it() {
        let s = starts();
        let mut c = config(4, 5000);
        c.goal = Some(Rational::from((1, 2)));
        let o = search(&s, &c, &reflex_share, &mut |_| {});
        assert!(o.best[0].eval.value >= Rational::from((1, 2)));
        assert!(o.evaluations < 5000, "{}", o.evaluations);
    }

    #[test]
    fn the_evaluation_budget_counts_the_starts() {
        let s = starts();
        let o = search(&s, &config(0, 2), &reflex_share, &mut |_| {});
        assert_eq!((o.evaluations, o.starts.len()), (2, 2));
    }

    #[test]
    fn starts_below_min_r_are_not_evaluated() {
        let s = starts();
        let mut c = config(0, 50);
        c.min_r = 1000;
        let o = search(&s, &c, &reflex_share, &mut |_| {});
        assert_eq!((o.evaluations, o.starts.len(), o.best.len()), (0, 0, 0));
        // With min_r 3 every evaluated map, start or mutant, has r >= 3.
        c.min_r = 3;
        c.keep = 50;
        let o = search(&s, &c, &reflex_share, &mut |_| {});
        assert!(o.starts.iter().all(|s| s.r >= 3) && !o.starts.is_empty());
        assert!(o.best.iter().all(|f| f.map.r() >= 3));
    }

    #[test]
    fn a_panicking_evaluation_is_caught() {
        let s = starts();
        let o = search(
            &s[..1],
            &config(0, 3),
            &|_: &Map| -> Evaluation { panic!("planted") },
            &mut |_| {},
        );
        assert_eq!(o.evaluations, 1);
        assert_eq!(o.panicked.len(), 1);
        assert!(o.best.is_empty());
    }

    #[test]
    fn the_start_maps_fit_the_cap() {
        let limits = Limits::default();
        let both = start_maps(Starts::Both, 0, &limits);
        assert!(both.iter().all(|(_, m)| m.n() <= limits.max_n));
        let families = start_maps(Starts::Families, 0, &limits);
        for id in [
            "corridor-niches",
            "comb-convex-chain",
            "overlap-fan",
            "convex-niches",
        ] {
            assert!(
                families.iter().any(|(name, _)| name.starts_with(id)),
                "{id}"
            );
        }
        let random = start_maps(Starts::Random, 0, &limits);
        assert_eq!(both.len(), families.len() + random.len());
        assert_eq!(
            start_maps(Starts::Random, 0, &limits)
                .iter()
                .map(|(_, m)| m.clone())
                .collect::<Vec<_>>(),
            random.iter().map(|(_, m)| m.clone()).collect::<Vec<_>>()
        );
    }

    #[test]
    fn durations() {
        assert_eq!(parse_duration("10m"), Ok(Duration::from_secs(600)));
        assert_eq!(parse_duration("90"), Ok(Duration::from_secs(90)));
        assert_eq!(parse_duration("1h30m"), Ok(Duration::from_secs(5400)));
        assert_eq!(parse_duration("45s"), Ok(Duration::from_secs(45)));
        for bad in ["", "m", "10x", "1.5m", "10m5"] {
            assert!(parse_duration(bad).is_err(), "{bad}");
        }
    }
}
