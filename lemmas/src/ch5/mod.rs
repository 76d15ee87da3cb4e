//! The checkers of chapter 5's claims (the complexity of an equivalence
//! class), one module per claim id, and what several of them share.

pub mod c5_18;
pub mod l5_1;
pub mod l5_13;
pub mod l5_14;
pub mod l5_2;
pub mod l5_3;
pub mod l5_4;
pub mod l5_5;
pub mod l5_6;
pub mod l5_7;
pub mod l5_8;
pub mod l5_9;
pub mod o5_3;
pub mod t5_12;
pub mod t5_15;
pub mod t5_16;
pub mod t5_17;
pub mod t5_17t;

/// Why the checkers that read each cell's embedding at the cell's own
/// origin examine nothing on a map with holes ([`crate::Rings::Outer`]).
pub(crate) const OWN_ORIGIN: &str = "they read each cell's embedding at its own origin, which \
     Def 3.11 does not give on a map with holes: a hole can split the part of a map edge that a \
     cell sees in two (L3.1c fails there), and condition 2 then rules the placement out";

use wai_embed::CandidateSets;
use wai_study::{GapStructure, Study};

use crate::framework::Report;

/// Runs `check` on every class's gap structure and sets C_{i,j}, tags each
/// violation with its class and the class's valid embeddings (indices in
/// [`Study::embeddings`], by position j), and sums the reports (L5.5–L5.9).
pub fn over_gap_classes(
    study: &Study<'_>,
    id: &'static str,
    check: impl Fn(&GapStructure, &CandidateSets) -> Report,
) -> Report {
    let mut report = Report::new(id);
    let classes = study.gap_structures().iter().zip(study.candidate_sets());
    for (class, (g, c)) in classes.enumerate() {
        let mut one = check(g, c);
        if !one.violations.is_empty() {
            one.tag("class", || serde_json::json!(class));
            one.tag("embeddings", || serde_json::json!(c.embeddings));
        }
        report.absorb(one);
    }
    report
}

/// Keeps `ratio` as the report's largest if it is ([`Report::measure`]),
/// building the data of where it was reached, `at()`, only then.
pub fn measure_lazily(
    report: &mut Report,
    ratio: rug::Rational,
    at: impl FnOnce() -> serde_json::Value,
) {
    if report.largest.as_ref().is_none_or(|l| ratio > l.ratio) {
        report.measure(ratio, at());
    }
}

/// `violation` with `key: value` in its data ([`Report::tag`] for one).
pub fn tagged(
    violation: Option<crate::framework::Violation>,
    key: &str,
    value: impl FnOnce() -> serde_json::Value,
) -> Option<crate::framework::Violation> {
    violation.map(|mut v| {
        v.data[key] = value();
        v
    })
}

#[cfg(test)]
pub(crate) mod tests {
    use crate::framework::{Ceiling, Checker};

    /// The test every bound on Def 5.2's counts passes: on `convex-niches`
    /// k = 2 it examines the map once with a positive ratio under its
    /// ceiling, and reports a violation under a ceiling below that ratio.
    pub(crate) fn assert_measures_and_can_fail(checker: &Checker) {
        let map = wai_gen::family("convex-niches", &[2]).unwrap();
        let report = checker.check_map(&map);
        let id = checker.id;
        assert_eq!((report.examined, report.violations.len()), (1, 0), "{id}");
        let ratio = report.largest.expect("a ratio").ratio;
        assert!(ratio > 0, "{id}");
        let low = checker.with_ceiling(Ceiling(1, 1_000_000_000));
        assert!(ratio > low.ceiling().unwrap(), "{id}");
        let report = low.check_map(&map);
        assert_eq!(report.violations.len(), 1, "{id}");
        assert!(report.violations[0].what.contains("above the ceiling"));
    }
}
