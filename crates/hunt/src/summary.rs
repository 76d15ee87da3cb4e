//! Checkers over maps: [`run`] sums the reports of every checker on every
//! map per claim into a [`Summary`], attaching the violating map to each
//! violation so it can be replayed and stored in `counterexamples/`, and
//! times each study stage and each checker ([`Profile`]).
//!
//! # Edge cases
//!
//! A claim whose total stays 0 over a whole run was not tested by that run;
//! [`Summary::untested`] names it, and so does the summary's `Display`
//! (CLAIMS.md, "What a checker reports").

use std::borrow::Borrow;
use std::collections::BTreeMap;
use std::fmt;
use std::time::{Duration, Instant};

use wai_lemmas::{Checker, Largest, Violation};
use wai_map::Map;
use wai_study::{StageTimes, Study};

/// A violation as the driver saw it: which claim, on which map.
#[derive(Debug, Clone, PartialEq)]
pub struct FoundViolation {
    /// The claim broken.
    pub claim: &'static str,
    /// Whether it is one of the checker's known failures
    /// ([`Checker::known`]), counted apart rather than a counterexample.
    pub known: bool,
    /// The position of the map in the stream given to [`run`], from 0.
    pub map_index: usize,
    /// The map's name, if it has one.
    pub map_name: Option<String>,
    /// The map in the format of `counterexamples/` (`wai_map::json`).
    pub map_json: String,
    /// What the checker reported.
    pub violation: Violation,
}

impl FoundViolation {
    /// True if this is a known failure, counted apart.
    pub fn is_known_failure(&self) -> bool {
        self.known
    }
}

/// The totals of one claim over a run.
#[derive(Debug, Clone, PartialEq)]
pub struct ClaimTally {
    /// The claim's id.
    pub claim: &'static str,
    /// Instances examined over all maps.
    pub examined: u64,
    /// Every violation found.
    pub violations: Vec<FoundViolation>,
    /// Instances per case of the claim ([`wai_lemmas::Report::cases`]),
    /// summed; every declared case is present, hit or not.
    pub cases: BTreeMap<&'static str, u64>,
    /// The checkers' further counts ([`wai_lemmas::Report::counts`]), summed.
    pub counts: BTreeMap<&'static str, u64>,
    /// The largest ratio of the run ([`wai_lemmas::Report::largest`]) and
    /// its map.
    pub largest: Option<FoundLargest>,
}

impl ClaimTally {
    /// The tally of `checker`'s claim before any map: every declared case
    /// at 0.
    pub fn new(checker: &Checker) -> Self {
        ClaimTally {
            claim: checker.id,
            examined: 0,
            violations: Vec::new(),
            cases: checker.cases.iter().map(|c| (c.name, 0)).collect(),
            counts: BTreeMap::new(),
            largest: None,
        }
    }

    /// True if `ratio`, reached on map `index`, beats the tally's largest
    /// so far: a larger ratio, or the same on an earlier map (so the run's
    /// largest does not depend on the order maps finish in).
    fn beaten_by(&self, ratio: &rug::Rational, index: usize) -> bool {
        self.largest.as_ref().is_none_or(|l| {
            *ratio > l.largest.ratio || (*ratio == l.largest.ratio && index < l.map_index)
        })
    }

    /// The violations that are not known failures.
    pub fn counterexamples(&self) -> impl Iterator<Item = &FoundViolation> {
        self.violations.iter().filter(|v| !v.known)
    }

    /// The declared cases no instance hit.
    pub fn cases_never_hit(&self) -> Vec<&'static str> {
        self.cases
            .iter()
            .filter(|(_, &k)| k == 0)
            .map(|(c, _)| *c)
            .collect()
    }
}

/// The largest ratio of a claim over a run, with its map.
#[derive(Debug, Clone, PartialEq)]
pub struct FoundLargest {
    pub largest: Largest,
    pub map_index: usize,
    pub map_name: Option<String>,
    /// The map in the format of `counterexamples/`, to replay it.
    pub map_json: String,
}

/// The outcome of [`run`].
#[derive(Debug, Clone, PartialEq)]
pub struct Summary {
    /// Maps the run went through.
    pub maps: usize,
    /// One tally per claim that some checker of the run covers, in the order
    /// the checkers were given.
    pub tallies: Vec<ClaimTally>,
}

/// Where a run's time went: each study stage's own time (summed over the
/// maps) and each checker's own time (its wall time minus the stages it
/// caused to be built).
#[derive(Debug, Clone, Default)]
pub struct Profile {
    /// Maps profiled.
    pub maps: u64,
    /// By stage, its own time and builds.
    pub stages: StageTimes,
    /// By claim, its checker's own time.
    pub checkers: BTreeMap<&'static str, Duration>,
}

impl Profile {
    /// Adds another profile to this one.
    pub fn absorb(&mut self, other: &Profile) {
        self.maps += other.maps;
        self.stages.absorb(&other.stages);
        for (claim, t) in &other.checkers {
            *self.checkers.entry(claim).or_default() += *t;
        }
    }

    /// Stages and checkers by own time, longest first: (`"stage NAME"` or
    /// `"checker ID"`, time).
    pub fn ranked(&self) -> Vec<(String, Duration)> {
        let mut rows: Vec<(String, Duration)> = self
            .stages
            .stages
            .iter()
            .map(|(s, (t, _))| (format!("stage {s}"), *t))
            .chain(
                self.checkers
                    .iter()
                    .map(|(c, t)| (format!("checker {c}"), *t)),
            )
            .collect();
        rows.sort_by(|a, b| b.1.cmp(&a.1).then_with(|| a.0.cmp(&b.0)));
        rows
    }

    /// The total own time of stages and checkers.
    pub fn total(&self) -> Duration {
        self.stages.total() + self.checkers.values().sum::<Duration>()
    }
}

impl Summary {
    /// The summary of a run of `checkers` before any map.
    pub fn empty(checkers: &[Checker]) -> Summary {
        let mut tallies: Vec<ClaimTally> = Vec::new();
        for c in checkers {
            assert!(
                wai_lemmas::claim(c.id).is_some(),
                "checker id {:?} is not a claim of CLAIMS",
                c.id
            );
            if !tallies.iter().any(|t| t.claim == c.id) {
                tallies.push(ClaimTally::new(c));
            }
        }
        Summary { maps: 0, tallies }
    }

    /// The tally of `claim`, if a checker of the run covers it.
    pub fn tally(&self, claim: &str) -> Option<&ClaimTally> {
        self.tallies.iter().find(|t| t.claim == claim)
    }

    /// Claims that had checkers in this run but whose examined count stayed
    /// 0: the run did not test them.
    pub fn untested(&self) -> Vec<&'static str> {
        self.tallies
            .iter()
            .filter(|t| t.examined == 0)
            .map(|t| t.claim)
            .collect()
    }

    /// Claims of [`wai_lemmas::CLAIMS`] that no checker of this run covers,
    /// in catalogue order.
    pub fn not_run(&self) -> Vec<&'static str> {
        wai_lemmas::CLAIMS
            .iter()
            .map(|c| c.id)
            .filter(|id| self.tally(id).is_none())
            .collect()
    }

    /// Every violation of the run, claim by claim.
    pub fn violations(&self) -> impl Iterator<Item = &FoundViolation> {
        self.tallies.iter().flat_map(|t| t.violations.iter())
    }

    /// The violations that are not known failures.
    pub fn counterexamples(&self) -> impl Iterator<Item = &FoundViolation> {
        self.violations().filter(|v| !v.known)
    }

    /// Adds the summary of a later part of the same run, whose maps start at
    /// index `first` of the whole stream: totals are summed, violations and
    /// largest ratios keep their maps with indices shifted by `first`.
    /// Tallies of claims new to `self` are appended.
    pub fn absorb(&mut self, other: Summary, first: usize) {
        self.maps += other.maps;
        for t in other.tallies {
            let mine = match self.tallies.iter().position(|m| m.claim == t.claim) {
                Some(k) => &mut self.tallies[k],
                None => {
                    self.tallies.push(ClaimTally {
                        examined: 0,
                        violations: Vec::new(),
                        cases: t.cases.keys().map(|c| (*c, 0)).collect(),
                        counts: BTreeMap::new(),
                        largest: None,
                        ..t.clone()
                    });
                    self.tallies.last_mut().expect("just pushed")
                }
            };
            mine.examined += t.examined;
            for (name, by) in t.cases {
                *mine.cases.entry(name).or_default() += by;
            }
            for (name, by) in t.counts {
                *mine.counts.entry(name).or_default() += by;
            }
            mine.violations
                .extend(t.violations.into_iter().map(|mut v| {
                    v.map_index += first;
                    v
                }));
            if let Some(mut l) = t.largest {
                l.map_index += first;
                if mine.beaten_by(&l.largest.ratio, l.map_index) {
                    mine.largest = Some(l);
                }
            }
        }
    }

    /// Puts every tally's violations in stream order (stable among one
    /// map's), as a search that absorbs maps as they finish must.
    pub fn sort_by_map(&mut self) {
        for t in &mut self.tallies {
            t.violations.sort_by_key(|v| v.map_index);
        }
    }

    /// True if no checker reported a violation. Says nothing about coverage:
    /// see [`Summary::untested`] and [`Summary::not_run`].
    pub fn is_clean(&self) -> bool {
        self.violations().next().is_none()
    }
}

impl fmt::Display for Summary {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(f, "{} maps", self.maps)?;
        for t in &self.tallies {
            write!(
                f,
                "{}: examined {}, violations {}",
                t.claim,
                t.examined,
                t.violations.len()
            )?;
            if !t.counts.is_empty() {
                let counts: Vec<String> =
                    t.counts.iter().map(|(k, v)| format!("{k} {v}")).collect();
                write!(f, " ({})", counts.join(", "))?;
            }
            writeln!(f)?;
        }
        for v in self.violations() {
            writeln!(
                f,
                "VIOLATION {} on map #{} ({}): {}",
                v.claim,
                v.map_index,
                v.map_name.as_deref().unwrap_or("unnamed"),
                v.violation.what
            )?;
        }
        let untested = self.untested();
        if !untested.is_empty() {
            writeln!(
                f,
                "not tested by this run (0 examined): {}",
                untested.join(", ")
            )?;
        }
        let not_run = self.not_run();
        if !not_run.is_empty() {
            writeln!(f, "no checker in this run: {}", not_run.join(", "))?;
        }
        Ok(())
    }
}

/// Runs every checker on every map and sums the reports per claim. A
/// checker that panics on a map reports it as a violation of its claim
/// ([`crate::caught`]), and the run goes on.
pub fn run<M: Borrow<Map>>(checkers: &[Checker], maps: impl IntoIterator<Item = M>) -> Summary {
    run_profiled(checkers, maps).0
}

/// [`run`], with where the time went.
pub fn run_profiled<M: Borrow<Map>>(
    checkers: &[Checker],
    maps: impl IntoIterator<Item = M>,
) -> (Summary, Profile) {
    let mut summary = Summary::empty(checkers);
    let mut profile = Profile::default();
    for (map_index, map) in maps.into_iter().enumerate() {
        let map = map.borrow();
        summary.maps += 1;
        profile.maps += 1;
        let study = Study::new(map);
        let mut map_json: Option<String> = None;
        let mut json = || {
            map_json
                .get_or_insert_with(|| wai_map::json::to_json(map))
                .clone()
        };
        for checker in checkers {
            let (start, stages_before) = (Instant::now(), study.stage_total());
            let report = crate::caught::run_caught(checker, &study);
            let own = start
                .elapsed()
                .saturating_sub(study.stage_total() - stages_before);
            *profile.checkers.entry(checker.id).or_default() += own;
            let tally = summary
                .tallies
                .iter_mut()
                .find(|t| t.claim == checker.id)
                .expect("every checker's claim has a tally");
            tally.examined += report.examined;
            for (name, by) in &report.cases {
                *tally.cases.entry(name).or_default() += by;
            }
            for (name, by) in &report.counts {
                *tally.counts.entry(name).or_default() += by;
            }
            if let Some(l) = report.largest {
                if tally.beaten_by(&l.ratio, map_index) {
                    tally.largest = Some(FoundLargest {
                        largest: l,
                        map_index,
                        map_name: map.name().map(str::to_owned),
                        map_json: json(),
                    });
                }
            }
            for violation in report.violations {
                tally.violations.push(FoundViolation {
                    claim: checker.id,
                    known: checker.is_known(&violation),
                    map_index,
                    map_name: map.name().map(str::to_owned),
                    map_json: json(),
                    violation,
                });
            }
        }
        profile.stages.absorb(&study.stage_times());
    }
    (summary, profile)
}

#[cfg(test)]
mod tests {
    use super::*;
    use wai_exact::Point;
    use wai_lemmas::{Case, Report};

    fn map(ring: &[(i128, i128)]) -> Map {
        let ring = ring.iter().map(|&(x, y)| Point::new(x, y)).collect();
        Map::from_ring(ring).expect("test map is valid").0
    }

    fn triangle() -> Map {
        map(&[(0, 0), (4, 0), (0, 4)])
    }

    fn square() -> Map {
        map(&[(0, 0), (4, 0), (4, 4), (0, 4)])
    }

    /// Planted: examines one instance per map and "finds" a violation on
    /// every triangle; counts the triangles as a case.
    const HATES_TRIANGLES: Checker = Checker::new("T4.2", |study| {
        let mut report = Report::new("T4.2");
        let broken = study.map().n() == 3;
        if broken {
            report.hit("triangle");
        }
        report.record(broken.then(|| {
            Violation::with_data(
                "planted: a triangle",
                serde_json::json!({ "n": study.map().n() }),
            )
        }));
        report
    })
    .with_cases(&[
        Case {
            name: "triangle",
            what: "a map of three vertices",
        },
        Case {
            name: "never",
            what: "nothing",
        },
    ]);

    /// Planted: never finds anything to examine.
    const FINDS_NOTHING: Checker = Checker::new("L4.6", |_| Report::new("L4.6"));

    /// Planted: a second checker of T4.2 that examines two instances per map.
    const COUNTS_TWO: Checker = Checker::new("T4.2", |_| {
        let mut report = Report::new("T4.2");
        report.record(None);
        report.record(None);
        report
    });

    #[test]
    fn planted_violation_is_reported_with_its_map_and_case() {
        let maps = [triangle(), square()];
        let summary = run(&[HATES_TRIANGLES, FINDS_NOTHING], &maps);
        assert_eq!(summary.maps, 2);
        let t = summary.tally("T4.2").expect("T4.2 ran");
        assert_eq!(t.examined, 2);
        assert_eq!(t.violations.len(), 1);
        assert_eq!(t.cases.get("triangle"), Some(&1));
        assert_eq!(t.cases_never_hit(), vec!["never"]);
        let v = &t.violations[0];
        assert_eq!(v.claim, "T4.2");
        assert!(!v.known);
        assert_eq!(v.map_index, 0);
        assert_eq!(v.violation.what, "planted: a triangle");
        assert_eq!(v.violation.data, serde_json::json!({ "n": 3 }));
        assert_eq!(v.map_json, wai_map::json::to_json(&maps[0]));
        assert!(!summary.is_clean());
        assert_eq!(summary.violations().count(), 1);
        let text = summary.to_string();
        assert!(text.contains("VIOLATION T4.2 on map #0"), "{text}");
    }

    #[test]
    fn zero_examined_claims_are_named_untested() {
        let summary = run(&[HATES_TRIANGLES, FINDS_NOTHING], [square()]);
        assert!(summary.is_clean());
        assert_eq!(summary.tally("L4.6").map(|t| t.examined), Some(0));
        assert_eq!(summary.untested(), vec!["L4.6"]);
        let text = summary.to_string();
        assert!(
            text.contains("not tested by this run (0 examined): L4.6"),
            "{text}"
        );
    }

    #[test]
    fn an_empty_map_stream_tests_nothing() {
        let summary = run(&[HATES_TRIANGLES, FINDS_NOTHING], std::iter::empty::<Map>());
        assert_eq!(summary.maps, 0);
        assert_eq!(summary.untested(), vec!["T4.2", "L4.6"]);
        assert!(summary.is_clean());
    }

    #[test]
    fn checkers_of_one_claim_are_summed() {
        let summary = run(&[HATES_TRIANGLES, COUNTS_TWO], [triangle(), square()]);
        assert_eq!(summary.tallies.len(), 1);
        assert_eq!(summary.tally("T4.2").map(|t| t.examined), Some(2 + 4));
        assert_eq!(summary.violations().count(), 1);
    }

    #[test]
    fn claims_without_a_checker_in_the_run_are_named() {
        let summary = run(&[FINDS_NOTHING], [square()]);
        let not_run = summary.not_run();
        assert_eq!(not_run.len(), wai_lemmas::CLAIMS.len() - 1);
        assert!(!not_run.contains(&"L4.6"));
        assert!(not_run.contains(&"T4.2"));
        assert!(summary
            .to_string()
            .contains("no checker in this run: L3.1a, "));
    }

    #[test]
    #[should_panic(expected = "not a claim of CLAIMS")]
    fn a_checker_with_an_unknown_id_is_a_bug() {
        run(&[Checker::new("X9.9", |_| Report::new("X9.9"))], [square()]);
    }

    /// The one violation a checker bug leaves on a run over the square: a
    /// caught panic ([`crate::caught`]), a counterexample with its map.
    fn caught_bug(checker: Checker) -> String {
        let summary = run(&[checker], [square()]);
        let found: Vec<&FoundViolation> = summary.counterexamples().collect();
        assert_eq!(found.len(), 1, "{summary}");
        assert!(crate::caught::is_panic(&found[0].violation));
        assert!(!found[0].map_json.is_empty());
        found[0].violation.what.clone()
    }

    #[test]
    fn a_report_for_another_claim_is_a_bug() {
        let what = caught_bug(Checker::new("T4.2", |_| Report::new("T4.3")));
        assert!(what.contains("returned a report for T4.3"), "{what}");
    }

    #[test]
    fn violations_without_examined_instances_are_a_bug() {
        let planted = Checker::new("T4.2", |_| {
            let mut report = Report::new("T4.2");
            report.violations.push(Violation::new("planted"));
            report
        });
        let what = caught_bug(planted);
        assert!(what.contains("examined only 0"), "{what}");
    }

    #[test]
    fn an_undeclared_case_is_a_bug() {
        let planted = Checker::new("T4.2", |_| {
            let mut report = Report::new("T4.2");
            report.hit("made up");
            report
        });
        let what = caught_bug(planted);
        assert!(what.contains("does not declare"), "{what}");
    }

    #[test]
    fn known_failures_are_marked() {
        let data = serde_json::json!({ "kind": wai_lemmas::ch3::a3_6::FAILS_ON_1_CELL });
        let planted = Checker {
            check: |_| {
                let mut report = Report::new("A3.6");
                report.record(Some(Violation::with_data(
                    "planted",
                    serde_json::json!({ "kind": wai_lemmas::ch3::a3_6::FAILS_ON_1_CELL }),
                )));
                report.record(Some(Violation::with_data(
                    "planted",
                    serde_json::json!({ "kind": "wrong-cell" }),
                )));
                report
            },
            ..wai_lemmas::ch3::a3_6::CHECKER
        };
        let summary = run(&[planted], [square()]);
        let t = summary.tally("A3.6").unwrap();
        assert_eq!(t.violations.len(), 2);
        assert!(t.violations[0].known && t.violations[0].violation.data == data);
        assert_eq!(t.counterexamples().count(), 1);
    }

    #[test]
    fn the_largest_ratio_of_a_run_is_kept_with_its_map() {
        // T5.17's max |EC| / (n + r²): 2 on a convex map (one cell of
        // complexity 2n), less on an L-shaped one.
        let l = map(&[(0, 0), (6, 0), (6, 2), (2, 2), (2, 6), (0, 6)]).with_name("L");
        let sq = square().with_name("square");
        let summary = run(&[wai_lemmas::ch5::t5_17::CHECKER], [l, sq]);
        let found = summary.tally("T5.17").and_then(|t| t.largest.as_ref());
        let found = found.expect("T5.17 measures a ratio");
        assert_eq!(found.largest.ratio, 2);
        assert_eq!(
            (found.map_index, found.map_name.as_deref()),
            (1, Some("square"))
        );
        assert!(found.map_json.contains("\"outer\""), "{}", found.map_json);
    }

    #[test]
    fn a_profile_charges_stages_and_checkers() {
        let (_, profile) = run_profiled(
            &[
                wai_lemmas::ch5::t5_17::CHECKER,
                wai_lemmas::ch3::t3_3a::CHECKER,
            ],
            [triangle(), square()],
        );
        assert_eq!(profile.maps, 2);
        assert_eq!(profile.stages.stages["decomposition"].1, 2);
        assert!(profile.checkers.contains_key("T3.3a"));
        assert!(profile.total() >= profile.stages.total());
    }
}
