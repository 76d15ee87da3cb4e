//! Claim T5.12 (Theorem 5.12): a skeleton has O(r) multiple candidate
//! edges (Def 5.4). Measured: the ratio max |C_mult| / r over the classes
//! of every map.
//!
//! The thesis proves it under Assumption 5.10 (sec. 5.4.4); the ratio is
//! measured on every map regardless.
//!
//! ## Trust
//! Exact counts: C_{i,j} from the witness views of [`wai_study::Study`] over
//! the valid embeddings of each class's skeleton. A bound is never
//! decided by one map ([`Report::hold_to`]): a ratio above the ceiling
//! is reported as a map worth a look.

use serde_json::json;
use wai_embed::CandidateSets;
use wai_study::Study;

use crate::framework::{over, Ceiling, Checker, Report};

const ID: &str = "T5.12";

/// The checker. The ceiling is far above every ratio seen: 1/2 (2
/// multiple candidate edges, r = 4, on `convex-niches` k = 1) over 1,501
/// maps — the stress corpus (901) and 300 each of `bottled_niches` and
/// `repeated_niches`, whose overlapping embeddings have several valid
/// candidate edges per artificial edge — and 4/5 (n = 15, r = 5) found by
/// a 10-minute `wai search-extremes --ratio cmult`
/// (`counterexamples/T5.12-extreme-*`).
pub const CHECKER: Checker = Checker::new(ID, check_study).with_ceiling(Ceiling(4, 1));

/// max |C_mult| / r against the ceiling.
fn check_study(study: &Study<'_>) -> Report {
    check_classes(&CHECKER, study.map(), study.candidate_sets())
}

/// The check on the candidate sets of every class, by `checker` (this
/// claim's, or one with a planted ceiling): the ratio max |C_mult| / r
/// (r at least 1), and the largest |C_mult| as a count.
pub fn check_classes(checker: &Checker, map: &wai_map::Map, classes: &[CandidateSets]) -> Report {
    let (class, mult) = classes
        .iter()
        .enumerate()
        .map(|(k, c)| (k, c.multiple.len()))
        .max_by_key(|&(k, m)| (m, std::cmp::Reverse(k)))
        .unwrap_or((0, 0));
    let mut report = checker.bound_report(Some((
        over(mult, map.r() as u128),
        json!({"class": class, "multiple": mult, "r": map.r()}),
    )));
    report.count("largest_multiple", mult as u64);
    report
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn measures_on_a_map_with_multiple_candidate_edges() {
        let map = wai_gen::family("convex-niches", &[3]).unwrap();
        let study = Study::new(&map);
        let report = check_classes(&CHECKER, &map, study.candidate_sets());
        assert_eq!((report.examined, report.violations.len()), (1, 0));
        let ratio = report.largest.expect("a ratio").ratio;
        assert!(ratio > 0, "the layout has multiple candidate edges");
    }

    #[test]
    fn planted_excess_is_reported() {
        // 2r + 1 multiple candidate edges on a map with r reflex vertices,
        // against a ceiling of 2.
        let map = wai_gen::family("corridor-niches", &[1]).unwrap();
        let edges: Vec<usize> = (0..=2 * map.r()).collect();
        let c = CandidateSets::from_sets(vec![0], vec![0], vec![vec![edges]]);
        let planted = CHECKER.with_ceiling(Ceiling(2, 1));
        let report = planted.judge(check_classes(&planted, &map, &[c]));
        assert_eq!(report.violations.len(), 1);
        assert!(report.largest.expect("a ratio").ratio > 2);
    }
}
