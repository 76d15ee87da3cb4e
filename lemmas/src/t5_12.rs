//! Claim T5.12 (Theorem 5.12): a skeleton has O(r) multiple candidate
//! edges (Def 5.4). Measured: the ratio max |C_mult| / r over the classes
//! of every map.
//!
//! The thesis proves it under Assumption 5.10 (sec. 5.4.4); the ratio is
//! measured on every map regardless.
//!
//! ## Trust
//! Exact counts: C_{i,j} from the witness views of [`crate::Study`] over
//! the valid embeddings of each class's skeleton. A bound is never
//! decided by one map (see [`crate::ratio`]): a ratio above the ceiling
//! is reported as a map worth a look.

use rug::Rational;
use serde_json::json;
use wai_embed::CandidateSets;

use crate::driver::{Checker, Report, Violation};
use crate::ratio::over;
use crate::{sample, Study};

const ID: &str = "T5.12";

/// The ceiling, far above every ratio seen: 1/2 (2 multiple candidate
/// edges, r = 4, on `convex-niches` k = 1) over 1,501 maps — the stress
/// corpus (901) and 300 each of `bottled_niches` and `repeated_niches`,
/// whose overlapping embeddings have several valid candidate edges per
/// artificial edge — and 4/5 (n = 15, r = 5) found by a 10-minute
/// `wai search-extremes --ratio cmult` (`counterexamples/T5.12-extreme-*`).
pub fn ceiling() -> Rational {
    Rational::from(4)
}

/// Checks T5.12: max |C_mult| / r against [`ceiling`].
#[derive(Debug, Clone, Copy, Default)]
pub struct MultipleCandidates;

/// The registry's constructor.
pub fn checker() -> Box<dyn Checker> {
    Box::new(MultipleCandidates)
}

impl Checker for MultipleCandidates {
    fn id(&self) -> &'static str {
        ID
    }

    fn check_study(&self, study: &Study<'_>) -> Report {
        check_with_ratio(study.map(), study.candidate_sets(), &ceiling()).0
    }
}

/// The report and the ratio max |C_mult| / r (r at least 1).
pub fn check_with_ratio(
    map: &wai_map::Map,
    classes: &[CandidateSets],
    ceiling: &Rational,
) -> (Report, Rational) {
    let (class, mult) = classes
        .iter()
        .enumerate()
        .map(|(k, c)| (k, c.multiple.len()))
        .max_by_key(|&(k, m)| (m, std::cmp::Reverse(k)))
        .unwrap_or((0, 0));
    let ratio = over(mult, map.r() as u128);
    let mut report = Report::new(ID);
    report.record((ratio > *ceiling).then(|| {
        Violation::with_data(
            format!(
                "{ID}: map {}: {mult} multiple candidate edges for one skeleton, r = {}: ratio {ratio} above the ceiling {ceiling}",
                sample::map_name(map),
                map.r()
            ),
            json!({
                "map": sample::map_name(map),
                "class": class,
                "multiple": mult,
                "r": map.r(),
                "ratio": ratio.to_string(),
                "ceiling": ceiling.to_string(),
            }),
        )
    }));
    report.count("largest_multiple", mult as u64);
    report.measure(
        ratio.clone(),
        json!({"class": class, "multiple": mult, "r": map.r()}),
    );
    (report, ratio)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn measures_on_a_map_with_multiple_candidate_edges() {
        let map = wai_gen::family("convex-niches", &[3]).unwrap();
        let study = Study::new(&map);
        let (report, ratio) = check_with_ratio(&map, study.candidate_sets(), &ceiling());
        assert_eq!((report.examined, report.violations.len()), (1, 0));
        assert!(ratio > 0, "the layout has multiple candidate edges");
    }

    #[test]
    fn planted_excess_is_reported() {
        // 2r + 1 multiple candidate edges on a map with r reflex vertices,
        // against a ceiling of 2.
        let map = wai_gen::family("corridor-niches", &[1]).unwrap();
        let edges: Vec<usize> = (0..=2 * map.r()).collect();
        let c = CandidateSets::from_sets(vec![0], vec![0], vec![vec![edges]]);
        let (report, ratio) = check_with_ratio(&map, &[c], &Rational::from(2));
        assert_eq!(report.violations.len(), 1);
        assert!(ratio > 2);
    }
}
