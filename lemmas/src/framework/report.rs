//! What a checker found on one map: the [`Report`].
//!
//! A report counts the instances of its claim that were examined (cells,
//! pairs of embeddings, triples of candidate edges…), keeps every
//! [`Violation`] with the data needed to replay it, counts instances per
//! named case of the claim's proof ([`crate::framework::Case`]), keeps
//! further named counts, and, for claims that measure a ratio, the largest
//! one with where it was reached ([`Largest`]).
//!
//! # Edge cases
//!
//! A checker that finds nothing to examine on a map reports `examined ==
//! 0`. A claim whose total stays 0 over a whole run was not tested by that
//! run, and the run must say so (CLAIMS.md, "What a checker reports").

use std::collections::BTreeMap;

use rug::Rational;
use serde_json::json;

/// One failed instance of a claim, with the data needed to replay it.
#[derive(Debug, Clone, PartialEq)]
pub struct Violation {
    /// What failed, as a sentence ("witnesses (3, 1) and (5, 2) see each
    /// other").
    pub what: String,
    /// The instance as data: skeleton, embeddings, witness points… — exact
    /// numbers written as strings. A known failure names itself in
    /// `data["kind"]` ([`crate::framework::Known`]).
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

    /// The kind it names in `data["kind"]`, if any.
    pub fn kind(&self) -> Option<&str> {
        self.data["kind"].as_str()
    }
}

/// A measured ratio and where on the map it was reached.
#[derive(Debug, Clone, PartialEq)]
pub struct Largest {
    pub ratio: Rational,
    pub at: serde_json::Value,
}

/// What a checker found on one map.
#[derive(Debug, Clone, PartialEq)]
pub struct Report {
    /// The claim's id in the registry; equal to its checker's id.
    pub claim: &'static str,
    /// Instances of the claim examined on this map (0 if the map has none).
    pub examined: u64,
    /// The examined instances that broke the claim; never more than
    /// `examined`.
    pub violations: Vec<Violation>,
    /// Instances by case of the claim's proof (only the cases hit; the
    /// checker declares them all).
    pub cases: BTreeMap<&'static str, u64>,
    /// For cases a map may come close to without hitting (a threshold such
    /// as "k ≥ 3"), the largest progress toward each measured on this map
    /// (k itself): the guide of a search that targets the case.
    pub toward: BTreeMap<&'static str, Rational>,
    /// Further named counts a checker keeps beside `examined` (how many
    /// verdicts a second method cross-checked, how many instances met a
    /// stronger premise…); summed by name over a run.
    pub counts: BTreeMap<&'static str, u64>,
    /// The largest ratio measured on this map, for claims that measure
    /// one (bounds; exact claims with a natural ratio such as k/6), with
    /// where it was reached.
    pub largest: Option<Largest>,
}

impl Report {
    /// An empty report for `claim`: nothing examined yet.
    pub fn new(claim: &'static str) -> Self {
        Report {
            claim,
            examined: 0,
            violations: Vec::new(),
            cases: BTreeMap::new(),
            toward: BTreeMap::new(),
            counts: BTreeMap::new(),
            largest: None,
        }
    }

    /// Counts one examined instance, which holds if `violation` is `None`.
    pub fn record(&mut self, violation: Option<Violation>) {
        self.examined += 1;
        self.violations.extend(violation);
    }

    /// Counts one instance of case `case` of the claim (a name the checker
    /// declares in its [`crate::framework::Checker::cases`]).
    pub fn hit(&mut self, case: &'static str) {
        *self.cases.entry(case).or_default() += 1;
    }

    /// Keeps `progress` toward case `case` if it is the largest so far
    /// (see [`Report::toward`]).
    pub fn progress_toward(&mut self, case: &'static str, progress: Rational) {
        match self.toward.get_mut(case) {
            Some(p) if *p >= progress => {}
            Some(p) => *p = progress,
            None => {
                self.toward.insert(case, progress);
            }
        }
    }

    /// Adds `by` to the named count `name`.
    pub fn count(&mut self, name: &'static str, by: u64) {
        *self.counts.entry(name).or_default() += by;
    }

    /// Keeps `ratio` (reached `at`) if it is the largest so far.
    pub fn measure(&mut self, ratio: Rational, at: serde_json::Value) {
        if self.largest.as_ref().is_none_or(|l| ratio > l.ratio) {
            self.largest = Some(Largest { ratio, at });
        }
    }

    /// A bound claim's verdict on this report: if its largest ratio lies
    /// above `ceiling` — a constant far above every ratio seen, so that a
    /// value above it is a bug of ours or a map worth a look (an asymptotic
    /// bound is never refuted by one map) — a violation with the ratio and
    /// where it was reached. The one mechanism of every bound
    /// ([`crate::framework::Checker::run`] applies it).
    pub fn hold_to(&mut self, ceiling: &Rational) {
        let Some(l) = &self.largest else { return };
        if l.ratio <= *ceiling {
            return;
        }
        let what = format!(
            "{}: ratio {} (≈ {:.4}) above the ceiling {ceiling}",
            self.claim,
            l.ratio,
            l.ratio.to_f64()
        );
        let data = json!({
            "ratio": l.ratio.to_string(),
            "ceiling": ceiling.to_string(),
            "at": l.at.clone(),
        });
        self.violations.push(Violation::with_data(what, data));
    }

    /// Adds `key: value` to the data of every violation found so far (the
    /// instance they belong to: a pair of embeddings, a class…), and to
    /// where the largest ratio was reached. `value` is built only if there
    /// is such a place: most instances have none, and they are many.
    pub fn tag(&mut self, key: &str, value: impl FnOnce() -> serde_json::Value) {
        let wanted =
            !self.violations.is_empty() || self.largest.as_ref().is_some_and(|l| l.at.is_object());
        if !wanted {
            return;
        }
        let value = value();
        for v in &mut self.violations {
            v.data[key] = value.clone();
        }
        if let Some(l) = &mut self.largest {
            if l.at.is_object() {
                l.at[key] = value.clone();
            }
        }
    }

    /// Adds another report of the same claim to this one.
    pub fn absorb(&mut self, other: Report) {
        debug_assert_eq!(self.claim, other.claim, "reports of one claim");
        self.examined += other.examined;
        self.violations.extend(other.violations);
        for (name, by) in other.cases {
            *self.cases.entry(name).or_default() += by;
        }
        for (case, progress) in other.toward {
            self.progress_toward(case, progress);
        }
        for (name, by) in other.counts {
            self.count(name, by);
        }
        if let Some(l) = other.largest {
            self.measure(l.ratio, l.at);
        }
    }
}

/// `a / b` as an exact ratio, with `b` at least 1.
pub fn over(a: usize, b: u128) -> Rational {
    Rational::from((rug::Integer::from(a), rug::Integer::from(b.max(1))))
}
