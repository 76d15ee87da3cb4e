//! Claim L5.1 (Lemma 5.1): an equivalence class has O(n + r² + W) kernel
//! edges, W its wedge edges. Measured: the ratio max K / (n + r² + W) over
//! the classes of every map.
//!
//! ## Trust
//! Exact counts from the classification of every cell edge (Def 5.2,
//! `wai_embed::wedge`); an edge on both kinds of line counts for both. A
//! bound is never decided by one map (see [`crate::ratio`]).

use rug::Rational;
use serde_json::json;

use crate::driver::{Checker, Report};
use crate::wedge_counts::{counts, ratio, ratio_report};
use crate::Study;

const ID: &str = "L5.1";

/// The ceiling, 4× the largest ratio seen: 1 (an R2V floor plan) over
/// 1,502 maps — the stress corpus (901), 150 each of `bottled_niches` and
/// `repeated_niches`, and 300 random maps of every kind with n from 8 to
/// 30.
pub fn ceiling() -> Rational {
    Rational::from(4)
}

/// Checks L5.1.
#[derive(Debug, Clone, Copy, Default)]
pub struct KernelEdges;

/// The registry's constructor.
pub fn checker() -> Box<dyn Checker> {
    Box::new(KernelEdges)
}

/// The report and the ratio.
pub fn check_with_ratio(study: &Study<'_>, ceiling: &Rational) -> (Report, Rational) {
    let map = study.map();
    let (n, r) = (map.n() as u128, map.r() as u128);
    let largest = counts(study.cell_edges())
        .iter()
        .enumerate()
        .filter(|(_, c)| c.kernel + c.wedge > 0)
        .map(|(k, c)| {
            (
                ratio(c.kernel, n + r * r + c.wedge as u128),
                json!({ "class": k, "kernel": c.kernel, "wedge": c.wedge }),
            )
        })
        .max_by(|a, b| a.0.cmp(&b.0));
    ratio_report(ID, map, largest, ceiling)
}

impl Checker for KernelEdges {
    fn id(&self) -> &'static str {
        ID
    }
    fn check_study(&self, study: &Study<'_>) -> Report {
        check_with_ratio(study, &ceiling()).0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn measures_and_fails_against_a_low_ceiling() {
        let map = wai_gen::family("convex-niches", &[2]).unwrap();
        let study = Study::new(&map);
        let (report, ratio) = check_with_ratio(&study, &ceiling());
        assert_eq!((report.examined, report.violations.len()), (1, 0));
        assert!(ratio > 0);
        let (report, _) = check_with_ratio(&study, &(ratio.clone() / 2));
        assert_eq!(report.violations.len(), 1);
        assert!(report.violations[0].what.contains("above the ceiling"));
    }
}
