//! The checker of one claim: a [`Checker`] value, declared once per claim
//! module as `pub const CHECKER`.
//!
//! A checker is data: its claim's id, the cases of the claim's proof whose
//! instances it counts ([`Case`]), the known failures it counts apart
//! ([`Known`]), the ceiling of a bound's ratio ([`Ceiling`]), and the
//! function that examines one study. [`Checker::run`] calls that function
//! and holds the report to the checker's declarations, so no claim module
//! repeats the bookkeeping.
//!
//! **Invariant:** `check` never mutates what it checks and is deterministic.

use rug::Rational;
use wai_cells::Counts;
use wai_map::Map;
use wai_study::Study;

use crate::framework::report::{Report, Violation};

/// A named case of a claim: a case of its proof, a type of a lemma (Lemma
/// 4.7's five edge types), a configuration of a theorem (Theorem 5.15's k,
/// kernels overlapping or not). The checker counts instances per case, so a
/// run shows which parts of the proof its maps exercised.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Case {
    /// The name counted in [`Report::cases`] (`"type 5"`, `"k=3"`).
    pub name: &'static str,
    /// What an instance of the case is, in the thesis's terms.
    pub what: &'static str,
}

/// A known failure: a violation of the claim as the thesis states it that is
/// understood, stored in `counterexamples/`, and counted apart from the
/// counterexamples. Its violations carry `data["kind"] == kind`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Known {
    /// The value of `data["kind"]`.
    pub kind: &'static str,
    /// What the failure is.
    pub what: &'static str,
}

/// The ceiling of a bound claim's ratio, `numerator / denominator`: far
/// above every ratio seen, so a ratio above it is reported.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Ceiling(pub u64, pub u64);

impl Ceiling {
    /// The ceiling as an exact rational.
    pub fn rational(self) -> Rational {
        Rational::from((self.0, self.1.max(1)))
    }
}

/// Which maps a checker's code can examine. The claims of chapters 3–5
/// assume a map without holes (thesis sec. 2.1); a run with holes (`wai
/// check --maps holes`) asks what the assumption does, and that needs
/// checkers whose own code is right on several rings.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Rings {
    /// Every ring: the checker walks rings by [`Map::next`] and
    /// [`Map::prev`], sees and locates against every ring, or reads only
    /// structures that do (visibility polygons, which are simple, the
    /// decomposition, the embeddings). Its verdict on a map with holes is
    /// the claim's.
    Every,
    /// The outer ring only: the checker's own arithmetic, or a structure
    /// it reads, takes the map as one ring (the reason says where). On a
    /// map with holes it examines nothing, so its silence is never read as
    /// the claim holding.
    Outer(&'static str),
}

/// The checker of one claim.
#[derive(Debug, Clone, Copy)]
pub struct Checker {
    /// The claim's id (`"T4.2"`).
    pub id: &'static str,
    /// The cases it counts; every case a report hits is one of them.
    pub cases: &'static [Case],
    /// The known failures it counts apart.
    pub known: &'static [Known],
    /// For a bound: the ceiling of its ratio.
    pub ceiling: Option<Ceiling>,
    /// The maps its code can examine.
    pub rings: Rings,
    /// Examines every instance the study's map offers.
    pub check: fn(&Study<'_>) -> Report,
}

impl Checker {
    /// A checker of claim `id` with no cases, known failures or ceiling.
    pub const fn new(id: &'static str, check: fn(&Study<'_>) -> Report) -> Checker {
        Checker {
            id,
            cases: &[],
            known: &[],
            ceiling: None,
            rings: Rings::Every,
            check,
        }
    }

    /// The same checker, declared to walk the outer ring only (`why`: where
    /// its arithmetic takes the map as one ring).
    pub const fn outer_ring_only(self, why: &'static str) -> Checker {
        Checker {
            rings: Rings::Outer(why),
            ..self
        }
    }

    /// True if the checker examines `map` (see [`Rings`]).
    pub fn examines(&self, map: &Map) -> bool {
        self.rings == Rings::Every || !map.has_holes()
    }

    /// The same checker counting `cases`.
    pub const fn with_cases(self, cases: &'static [Case]) -> Checker {
        Checker { cases, ..self }
    }

    /// The same checker counting `known` apart.
    pub const fn with_known(self, known: &'static [Known]) -> Checker {
        Checker { known, ..self }
    }

    /// The same checker as a bound with this ceiling.
    pub const fn with_ceiling(self, ceiling: Ceiling) -> Checker {
        Checker {
            ceiling: Some(ceiling),
            ..self
        }
    }

    /// The ceiling as a rational (a bound's; `None` for other claims).
    pub fn ceiling(&self) -> Option<Rational> {
        self.ceiling.map(Ceiling::rational)
    }

    /// A bound's report on one map: the largest ratio over the map's
    /// instances (`None`: the map has none to measure), one instance
    /// examined. [`Checker::run`] holds it to the ceiling.
    pub fn bound_report(&self, largest: Option<(Rational, serde_json::Value)>) -> Report {
        let mut report = Report::new(self.id);
        if let Some((ratio, at)) = largest {
            report.record(None);
            report.measure(ratio, at);
        }
        report
    }

    /// A bound on the decomposition's counts (Thm 3.9, Thm 3.10, Thm 5.17):
    /// the ratio `measure` gives the study's [`Counts`], at the counts that
    /// make it.
    pub fn counts_report(&self, study: &Study<'_>, measure: fn(&Counts) -> Rational) -> Report {
        let c = study.decomposition().counts();
        self.bound_report(Some((measure(&c), counts_json(&c))))
    }

    /// Holds `report` to the checker's declarations: a bound's largest
    /// ratio to its ceiling ([`Report::hold_to`]).
    ///
    /// # Panics
    ///
    /// On a checker bug (see [`Checker::run`]).
    pub fn judge(&self, mut report: Report) -> Report {
        if let Some(ceiling) = self.ceiling() {
            report.hold_to(&ceiling);
        }
        self.assert_consistent(&report);
        report
    }

    /// Checks the claim on the study's map.
    ///
    /// # Panics
    ///
    /// On a checker bug, never on a claim violation: a report for another
    /// claim, more violations than instances examined, or a case that the
    /// checker does not declare. A bound's report has at most one
    /// violation per map (its largest ratio above the ceiling), so a map
    /// with a ratio examined is enough.
    pub fn run(&self, study: &Study<'_>) -> Report {
        if !self.examines(study.map()) {
            return Report::new(self.id);
        }
        self.judge((self.check)(study))
    }

    /// Checks the claim on `map` alone (a study of its own).
    pub fn check_map(&self, map: &Map) -> Report {
        self.run(&Study::new(map))
    }

    /// True if `violation` is one of this checker's known failures.
    pub fn is_known(&self, violation: &Violation) -> bool {
        violation
            .kind()
            .is_some_and(|k| self.known.iter().any(|known| known.kind == k))
    }

    /// The violations of `report` that are not known failures: the
    /// counterexamples among them.
    pub fn counterexamples<'r>(&self, report: &'r Report) -> impl Iterator<Item = &'r Violation> {
        let me = *self;
        report.violations.iter().filter(move |v| !me.is_known(v))
    }

    fn assert_consistent(&self, report: &Report) {
        let id = self.id;
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
        for case in report.cases.keys().chain(report.toward.keys()) {
            assert!(
                self.cases.iter().any(|c| c.name == *case),
                "checker {id} counted case {case:?}, which it does not declare"
            );
        }
    }
}

/// The counts a ratio of [`Checker::counts_report`] is made of.
fn counts_json(c: &Counts) -> serde_json::Value {
    serde_json::json!({
        "n": c.n,
        "r": c.r,
        "cells": c.cells,
        "total_complexity": c.total_complexity,
        "max_class_complexity": c.max_class_complexity,
    })
}

/// The tests every bound on the decomposition's counts shares.
#[cfg(test)]
pub(crate) mod counts_tests {
    use super::*;

    /// The checker's largest ratio on `family` at `k`: one instance, no
    /// violation.
    pub fn ratio_on(checker: &Checker, family: &str, k: u32) -> Rational {
        let map = wai_gen::family(family, &[k]).unwrap();
        let report = checker.check_map(&map);
        assert_eq!((report.examined, report.violations.len()), (1, 0));
        report.largest.expect("a ratio").ratio
    }

    /// Counts of corridor-niches k = 1 changed by `plant` must be
    /// reported above the ceiling.
    pub fn planted_excess_reported(
        checker: &Checker,
        measure: fn(&Counts) -> Rational,
        plant: fn(&mut Counts),
    ) {
        let map = wai_gen::family("corridor-niches", &[1]).unwrap();
        let mut counts = wai_cells::Decomposition::new(&map).counts();
        plant(&mut counts);
        let report =
            checker.judge(checker.bound_report(Some((measure(&counts), counts_json(&counts)))));
        assert_eq!(report.violations.len(), 1);
        assert!(report.violations[0].what.contains("above the ceiling"));
    }
}

#[cfg(test)]
mod rings_tests {
    /// A checker declared to walk the outer ring examines nothing on a map
    /// with holes, so its silence there is never read as the claim holding;
    /// on a map without holes it runs as ever.
    #[test]
    fn a_one_ring_checker_examines_nothing_on_a_map_with_holes() {
        let c = crate::ch5::l5_13::CHECKER;
        let holed = wai_gen::random_with_holes("orthogonal-pillars", 8, 1, 1).unwrap();
        assert!(holed.has_holes() && !c.examines(&holed));
        assert_eq!(c.check_map(&holed).examined, 0);
        let plain = wai_gen::interweaved_gaps(0);
        assert!(c.examines(&plain));
        let every = crate::ch3::l3_1c::CHECKER;
        assert!(every.examines(&holed));
        assert!(every.check_map(&holed).examined > 0);
    }
}
