//! Claim L5.4 (Lemma 5.4): the number of gaps (Def 5.5) of a skeleton and
//! its number |C_mult| of multiple candidate edges (Def 5.4) are within a
//! factor 2 of each other.
//!
//! Every multiple candidate edge ends a gap of a set C_{i,j} with more than
//! one element, so |C_mult| ≤ 2·gaps always; the thesis reads the other
//! direction "directly" off the definition, but a gap is a pair of edges
//! consecutive in *some* C_{i,j}, and different embeddings may pair one
//! edge with different neighbours. Both directions are checked.
//!
//! ## Trust
//! Exact, on every class with a valid embedding: C_{i,j} from the witness
//! views of [`wai_study::Study`], ordered along their line; gaps counted as
//! distinct pairs of map edges. Counts: `gaps` and `multiple` summed over
//! the classes examined.
//!
//! ## Cases
//! On the classes with a gap, which side is larger: |C_mult| > gaps
//! ([`MORE_MULTIPLE`], the direction |C_mult| ≤ 2·gaps has content), equal
//! ([`EQUAL`]), or gaps > |C_mult| ([`MORE_GAPS`], the direction the thesis
//! reads off the definition has content: an edge paired with different
//! neighbours in different sets), with the largest gaps / |C_mult| as
//! progress toward it.

use rug::Rational;
use serde_json::json;
use wai_embed::CandidateSets;

use crate::framework::{Case, Checker, Report, Violation};
use wai_study::Study;

const ID: &str = "L5.4";

/// A class with more multiple candidate edges than gaps.
pub const MORE_MULTIPLE: &str = "more multiple";
/// A class with as many gaps as multiple candidate edges.
pub const EQUAL: &str = "equal";
/// A class with more gaps than multiple candidate edges.
pub const MORE_GAPS: &str = "more gaps";

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study).with_cases(&[
    Case {
        name: MORE_MULTIPLE,
        what: "a skeleton with a gap and |C_mult| > gaps: a set C_{i,j} of three or more edges \
               (the direction |C_mult| ≤ 2·gaps of Lemma 5.4 has content)",
    },
    Case {
        name: EQUAL,
        what: "a skeleton with a gap and as many gaps as multiple candidate edges",
    },
    Case {
        name: MORE_GAPS,
        what: "a skeleton with more gaps (Def 5.5) than multiple candidate edges: an edge \
               consecutive with different edges in different sets C_{i,j} (the direction \
               gaps ≤ 2·|C_mult| of Lemma 5.4 has content)",
    },
]);

/// Checks L5.4 on every class with a valid embedding.
fn check_study(study: &Study<'_>) -> Report {
    check_classes(study.candidate_sets())
}

/// |C_mult| ≤ 2·gaps and gaps ≤ 2·|C_mult| on one class.
pub fn check_class(c: &CandidateSets) -> Option<Violation> {
    let (gaps, mult) = (c.gaps.len(), c.multiple.len());
    (mult > 2 * gaps || gaps > 2 * mult).then(|| {
        Violation::with_data(
            format!("{gaps} gaps and {mult} multiple candidate edges: not within a factor 2"),
            json!({
                "gaps": c.gaps.keys().collect::<Vec<_>>(),
                "multiple": c.multiple,
                "sets": c.sets,
            }),
        )
    })
}

/// Every class with a valid embedding.
pub fn check_classes(classes: &[CandidateSets]) -> Report {
    let mut report = Report::new(ID);
    for (class, c) in classes.iter().enumerate() {
        if c.t() == 0 {
            continue;
        }
        report.record(super::tagged(check_class(c), "class", || json!(class)));
        report.count("gaps", c.gaps.len() as u64);
        report.count("multiple", c.multiple.len() as u64);
        let (gaps, mult) = (c.gaps.len(), c.multiple.len());
        if gaps > 0 {
            report.hit(match gaps.cmp(&mult) {
                std::cmp::Ordering::Less => MORE_MULTIPLE,
                std::cmp::Ordering::Equal => EQUAL,
                std::cmp::Ordering::Greater => MORE_GAPS,
            });
            if gaps <= mult {
                report.progress_toward(MORE_GAPS, Rational::from((gaps, mult)));
            }
        }
    }
    report
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn holds_on_a_map_with_multiple_candidate_edges() {
        let map = wai_gen::family("convex-niches", &[3]).unwrap();
        let report = CHECKER.run(&Study::new(&map));
        assert!(report.examined > 0);
        assert!(report.violations.is_empty(), "{:?}", report.violations);
        // Its largest class: 4 multiple candidate edges, 3 gaps.
        assert!(report.counts["multiple"] >= 4 && report.counts["gaps"] >= 3);
        assert!(
            report.cases.contains_key(MORE_MULTIPLE),
            "{:?}",
            report.cases
        );
    }

    #[test]
    fn planted_pairs_of_every_two_edges_are_reported() {
        // Six edges on one line, every two of them the whole C_{1,j} of an
        // embedding: 15 gaps against 6 multiple candidate edges.
        let mut sets = Vec::new();
        for a in 0..6 {
            for b in a + 1..6 {
                sets.push(vec![vec![a, b]]);
            }
        }
        let c = CandidateSets::from_sets(vec![0], (0..sets.len()).collect(), sets);
        let report = check_classes(&[c]);
        assert_eq!((report.examined, report.violations.len()), (1, 1));
        assert_eq!(report.cases[MORE_GAPS], 1);
        // Three edges, one set: 2 gaps, 3 multiple edges, within 2.
        let c = CandidateSets::from_sets(vec![0], vec![0], vec![vec![vec![1, 2, 3]]]);
        assert!(check_classes(&[c]).violations.is_empty());
    }
}
