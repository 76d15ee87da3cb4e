//! Checkers, their reports, and the driver that runs a set of checkers over a
//! stream of maps.
//!
//! A [`Checker`] checks one claim of [`crate::CLAIMS`] on one map and returns
//! a [`Report`]: how many instances it examined (cells, pairs of embeddings,
//! triples of candidate edges…) and every [`Violation`] it found. [`run`]
//! sums the reports per claim into a [`Summary`], attaching the violating
//! map to each violation so it can be replayed and stored in
//! `counterexamples/`.
//!
//! # Edge cases
//!
//! A checker that finds nothing to examine on a map reports `examined == 0`.
//! A claim whose total stays 0 over a whole run was not tested by that run;
//! [`Summary::untested`] names it, and so does the summary's `Display`
//! (CLAIMS.md, "What a checker reports"; STYLE.md 6).

use std::borrow::Borrow;
use std::collections::BTreeMap;
use std::fmt;

use wai_map::Map;

use crate::Study;

/// One failed instance of a claim, with the data needed to replay it.
#[derive(Debug, Clone, PartialEq)]
pub struct Violation {
    /// What failed, as a sentence ("witnesses (3, 1) and (5, 2) see each
    /// other").
    pub what: String,
    /// The instance as data: skeleton, embeddings, witness points… — exact
    /// numbers written as strings. The driver adds the map itself.
    pub data: serde_json::Value,
}

impl Violation {
    /// A violation with no data beyond its description.
    pub fn new(what: impl Into<String>) -> Self {
        Violation {
            what: what.into(),
            data: serde_json::Value::Null,
        }
    }

    /// A violation with replay data.
    pub fn with_data(what: impl Into<String>, data: serde_json::Value) -> Self {
        Violation {
            what: what.into(),
            data,
        }
    }
}

/// What a checker found on one map.
#[derive(Debug, Clone, PartialEq)]
pub struct Report {
    /// The claim's id in [`crate::CLAIMS`]; must equal the checker's
    /// [`Checker::id`].
    pub claim: &'static str,
    /// Instances of the claim examined on this map (0 if the map has none).
    pub examined: u64,
    /// The examined instances that broke the claim; never more than
    /// `examined`.
    pub violations: Vec<Violation>,
    /// Further named counts a checker keeps beside `examined` (how many
    /// verdicts a second method cross-checked, how many instances met a
    /// stronger premise…); the driver sums them by name.
    pub counts: BTreeMap<&'static str, u64>,
    /// The largest ratio measured on this map, for claims that measure
    /// one (bounds; exact claims with a natural ratio such as k/6), with
    /// where it was reached; the driver keeps the run's largest and its map.
    pub largest: Option<Largest>,
}

/// A measured ratio and where on the map it was reached.
#[derive(Debug, Clone, PartialEq)]
pub struct Largest {
    pub ratio: rug::Rational,
    pub at: serde_json::Value,
}

impl Report {
    /// An empty report for `claim`: nothing examined yet.
    pub fn new(claim: &'static str) -> Self {
        Report {
            claim,
            examined: 0,
            violations: Vec::new(),
            counts: BTreeMap::new(),
            largest: None,
        }
    }

    /// Keeps `ratio` (reached `at`) if it is the largest so far.
    pub fn measure(&mut self, ratio: rug::Rational, at: serde_json::Value) {
        if self.largest.as_ref().is_none_or(|l| ratio > l.ratio) {
            self.largest = Some(Largest { ratio, at });
        }
    }

    /// Adds `by` to the named count `name`.
    pub fn count(&mut self, name: &'static str, by: u64) {
        *self.counts.entry(name).or_default() += by;
    }

    /// Counts one examined instance, which holds if `violation` is `None`.
    pub fn record(&mut self, violation: Option<Violation>) {
        self.examined += 1;
        self.violations.extend(violation);
    }

    /// Adds `key: value` to the data of every violation found so far (the
    /// instance they belong to: a pair of embeddings, a class…), and to
    /// where the largest ratio was reached.
    pub fn tag(&mut self, key: &str, value: serde_json::Value) {
        for v in &mut self.violations {
            v.data[key] = value.clone();
        }
        if let Some(l) = &mut self.largest {
            if l.at.is_object() {
                l.at[key] = value.clone();
            }
        }
    }

    /// The violations that are not known failures
    /// ([`crate::is_known_failure`]): the counterexamples among them.
    pub fn counterexamples(&self) -> impl Iterator<Item = &Violation> {
        self.violations
            .iter()
            .filter(|v| !crate::is_known_failure(self.claim, &v.data))
    }

    /// Adds another report of the same claim to this one.
    pub fn absorb(&mut self, other: Report) {
        debug_assert_eq!(self.claim, other.claim, "reports of one claim");
        self.examined += other.examined;
        self.violations.extend(other.violations);
        for (name, by) in other.counts {
            self.count(name, by);
        }
        if let Some(l) = other.largest {
            self.measure(l.ratio, l.at);
        }
    }
}

/// A checker of one claim.
///
/// **Invariant:** `check` never mutates what it checks and is deterministic.
pub trait Checker {
    /// The id of the claim in [`crate::CLAIMS`] (`"T4.2"`).
    fn id(&self) -> &'static str;
    /// Checks the claim on every instance the study's map offers, reading
    /// the structures the study builds once per map.
    fn check_study(&self, study: &Study<'_>) -> Report;

    /// Checks the claim on `map` alone (a study of its own).
    fn check(&self, map: &Map) -> Report {
        self.check_study(&Study::new(map))
    }
}

/// A violation as the driver saw it: which claim, on which map.
#[derive(Debug, Clone, PartialEq)]
pub struct FoundViolation {
    /// The claim broken.
    pub claim: &'static str,
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
    /// True if this is a known failure ([`crate::is_known_failure`]),
    /// counted apart rather than a counterexample.
    pub fn is_known_failure(&self) -> bool {
        crate::is_known_failure(self.claim, &self.violation.data)
    }
}

/// The totals of one claim over a run.
#[derive(Debug, Clone, PartialEq)]
pub struct ClaimTally {
    /// The claim's id.
    pub claim: &'static str,
    /// Instances examined over all maps (and all checkers of this claim).
    pub examined: u64,
    /// Every violation found.
    pub violations: Vec<FoundViolation>,
    /// The checkers' further counts ([`Report::counts`]), summed.
    pub counts: BTreeMap<&'static str, u64>,
    /// The largest ratio of the run ([`Report::largest`]) and its map.
    pub largest: Option<FoundLargest>,
}

impl ClaimTally {
    /// The tally of `claim` before any map.
    fn new(claim: &'static str) -> Self {
        ClaimTally {
            claim,
            examined: 0,
            violations: Vec::new(),
            counts: BTreeMap::new(),
            largest: None,
        }
    }

    /// True if `ratio` is larger than the tally's largest so far (the only
    /// rule by which a run's largest ratio is replaced).
    fn beaten_by(&self, ratio: &rug::Rational) -> bool {
        self.largest
            .as_ref()
            .is_none_or(|l| *ratio > l.largest.ratio)
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

impl Summary {
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

    /// Claims of [`crate::CLAIMS`] that no checker of this run covers, in
    /// catalogue order.
    pub fn not_run(&self) -> Vec<&'static str> {
        crate::CLAIMS
            .iter()
            .map(|c| c.id)
            .filter(|id| self.tally(id).is_none())
            .collect()
    }

    /// Every violation of the run, claim by claim.
    pub fn violations(&self) -> impl Iterator<Item = &FoundViolation> {
        self.tallies.iter().flat_map(|t| t.violations.iter())
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
                    self.tallies.push(ClaimTally::new(t.claim));
                    self.tallies.last_mut().expect("just pushed")
                }
            };
            mine.examined += t.examined;
            for (name, by) in t.counts {
                *mine.counts.entry(name).or_default() += by;
            }
            mine.violations
                .extend(t.violations.into_iter().map(|mut v| {
                    v.map_index += first;
                    v
                }));
            if let Some(mut l) = t.largest {
                if mine.beaten_by(&l.largest.ratio) {
                    l.map_index += first;
                    mine.largest = Some(l);
                }
            }
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

/// Runs every checker on every map and sums the reports per claim.
///
/// # Panics
///
/// On a checker bug, never on a claim violation: a checker whose id is not in
/// [`crate::CLAIMS`], a report whose `claim` differs from its checker's id,
/// or a report with more violations than instances examined.
pub fn run<M: Borrow<Map>>(
    checkers: &[&dyn Checker],
    maps: impl IntoIterator<Item = M>,
) -> Summary {
    let mut tallies: Vec<ClaimTally> = Vec::new();
    for checker in checkers {
        let id = checker.id();
        assert!(
            crate::claim(id).is_some(),
            "checker id {id:?} is not a claim of CLAIMS"
        );
        if !tallies.iter().any(|t| t.claim == id) {
            tallies.push(ClaimTally::new(id));
        }
    }
    let mut count = 0;
    for (map_index, map) in maps.into_iter().enumerate() {
        let map = map.borrow();
        count += 1;
        let study = Study::new(map);
        for checker in checkers {
            let id = checker.id();
            let report = checker.check_study(&study);
            assert_eq!(
                report.claim, id,
                "checker {id} returned a report for {}",
                report.claim
            );
            assert!(
                report.violations.len() as u64 <= report.examined,
                "checker {id} reported {} violations but examined only {} instances",
                report.violations.len(),
                report.examined
            );
            let tally = tallies
                .iter_mut()
                .find(|t| t.claim == id)
                .expect("every checker's claim has a tally");
            tally.examined += report.examined;
            for (name, by) in &report.counts {
                *tally.counts.entry(name).or_default() += by;
            }
            if let Some(l) = report.largest {
                if tally.beaten_by(&l.ratio) {
                    tally.largest = Some(FoundLargest {
                        largest: l,
                        map_index,
                        map_name: map.name().map(str::to_owned),
                        map_json: wai_map::json::to_json(map),
                    });
                }
            }
            if !report.violations.is_empty() {
                let map_json = wai_map::json::to_json(map);
                tally
                    .violations
                    .extend(
                        report
                            .violations
                            .into_iter()
                            .map(|violation| FoundViolation {
                                claim: id,
                                map_index,
                                map_name: map.name().map(str::to_owned),
                                map_json: map_json.clone(),
                                violation,
                            }),
                    );
            }
        }
    }
    Summary {
        maps: count,
        tallies,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use wai_exact::Point;

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
    /// every triangle.
    struct HatesTriangles;
    impl Checker for HatesTriangles {
        fn id(&self) -> &'static str {
            "T4.2"
        }
        fn check_study(&self, study: &Study<'_>) -> Report {
            let mut report = Report::new(self.id());
            let broken = study.map().n() == 3;
            report.record(broken.then(|| {
                Violation::with_data(
                    "planted: a triangle",
                    serde_json::json!({ "n": study.map().n() }),
                )
            }));
            report
        }
    }

    /// Planted: never finds anything to examine.
    struct FindsNothing;
    impl Checker for FindsNothing {
        fn id(&self) -> &'static str {
            "L4.6"
        }
        fn check_study(&self, _study: &Study<'_>) -> Report {
            Report::new(self.id())
        }
    }

    /// Planted: a second checker of T4.2 that examines two instances per map.
    struct CountsTwo;
    impl Checker for CountsTwo {
        fn id(&self) -> &'static str {
            "T4.2"
        }
        fn check_study(&self, _study: &Study<'_>) -> Report {
            let mut report = Report::new(self.id());
            report.record(None);
            report.record(None);
            report
        }
    }

    #[test]
    fn planted_violation_is_reported_with_its_map() {
        let maps = [triangle(), square()];
        let summary = run(&[&HatesTriangles, &FindsNothing], &maps);
        assert_eq!(summary.maps, 2);
        let t = summary.tally("T4.2").expect("T4.2 ran");
        assert_eq!(t.examined, 2);
        assert_eq!(t.violations.len(), 1);
        let v = &t.violations[0];
        assert_eq!(v.claim, "T4.2");
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
        let summary = run(&[&HatesTriangles, &FindsNothing], [square()]);
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
        let summary = run(&[&HatesTriangles, &FindsNothing], std::iter::empty::<Map>());
        assert_eq!(summary.maps, 0);
        assert_eq!(summary.untested(), vec!["T4.2", "L4.6"]);
        assert!(summary.is_clean());
    }

    #[test]
    fn checkers_of_one_claim_are_summed() {
        let summary = run(&[&HatesTriangles, &CountsTwo], [triangle(), square()]);
        assert_eq!(summary.tallies.len(), 1);
        assert_eq!(summary.tally("T4.2").map(|t| t.examined), Some(2 + 4));
        assert_eq!(summary.violations().count(), 1);
    }

    #[test]
    fn claims_without_a_checker_in_the_run_are_named() {
        let summary = run(&[&FindsNothing], [square()]);
        let not_run = summary.not_run();
        assert_eq!(not_run.len(), crate::CLAIMS.len() - 1);
        assert!(!not_run.contains(&"L4.6"));
        assert!(not_run.contains(&"T4.2"));
        assert!(summary
            .to_string()
            .contains("no checker in this run: L3.1a, "));
    }

    struct Unknown;
    impl Checker for Unknown {
        fn id(&self) -> &'static str {
            "X9.9"
        }
        fn check_study(&self, _study: &Study<'_>) -> Report {
            Report::new(self.id())
        }
    }

    #[test]
    #[should_panic(expected = "not a claim of CLAIMS")]
    fn a_checker_with_an_unknown_id_is_a_bug() {
        run(&[&Unknown], [square()]);
    }

    struct Mislabelled;
    impl Checker for Mislabelled {
        fn id(&self) -> &'static str {
            "T4.2"
        }
        fn check_study(&self, _study: &Study<'_>) -> Report {
            Report::new("T4.3")
        }
    }

    #[test]
    #[should_panic(expected = "returned a report for T4.3")]
    fn a_report_for_another_claim_is_a_bug() {
        run(&[&Mislabelled], [square()]);
    }

    struct ViolatesUnexamined;
    impl Checker for ViolatesUnexamined {
        fn id(&self) -> &'static str {
            "T4.2"
        }
        fn check_study(&self, _study: &Study<'_>) -> Report {
            Report {
                claim: "T4.2",
                examined: 0,
                violations: vec![Violation::new("planted")],
                counts: BTreeMap::new(),
                largest: None,
            }
        }
    }

    #[test]
    #[should_panic(expected = "examined only 0")]
    fn violations_without_examined_instances_are_a_bug() {
        run(&[&ViolatesUnexamined], [square()]);
    }

    #[test]
    fn the_largest_ratio_of_a_run_is_kept_with_its_map() {
        // T5.17's max |EC| / (n + r²): 2 on a convex map (one cell of
        // complexity 2n), less on an L-shaped one.
        let l = map(&[(0, 0), (6, 0), (6, 2), (2, 2), (2, 6), (0, 6)]).with_name("L");
        let sq = square().with_name("square");
        let summary = run(&[&crate::t5_17::CHECKER], [l, sq]);
        let found = summary.tally("T5.17").and_then(|t| t.largest.as_ref());
        let found = found.expect("T5.17 measures a ratio");
        assert_eq!(found.largest.ratio, 2);
        assert_eq!(
            (found.map_index, found.map_name.as_deref()),
            (1, Some("square"))
        );
        assert!(found.map_json.contains("\"outer\""), "{}", found.map_json);
    }
}
