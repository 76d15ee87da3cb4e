//! Claim T5.17 (Theorem 5.17, the main theorem of chapter 5): the cells of
//! an equivalence class and their total complexity are O(n + r²). Measured:
//! the ratio max |EC| / (n + r²) on every map.
//!
//! ## Trust
//! Exact counts on every map examined (the decomposition of `wai-cells`,
//! whose arrangement is sanity-checked in its tests); a bound is never
//! decided by one map ([`Report::hold_to`]). The growth exponent comes from
//! the scaling sweep (max |EC| against n + r²).

use rug::Rational;
use serde_json::json;
use wai_cells::Counts;
use wai_study::Study;

use crate::framework::{over, Ceiling, Checker, Report};

const ID: &str = "T5.17";

/// The checker. The ceiling is far above every ratio seen: the largest
/// seen is 2, on every convex map (one cell of complexity 2n over n + 0),
/// over 968 generated, family, polyomino and r2v maps.
pub const CHECKER: Checker = Checker::new(ID, check_study).with_ceiling(Ceiling(8, 1));

/// max |EC| / (n + r²).
pub fn measure(c: &Counts) -> Rational {
    over(c.max_class_complexity, c.n as u128 + (c.r as u128).pow(2))
}

/// The ratio on the decomposition's counts.
fn check_study(study: &Study<'_>) -> Report {
    let c = study.decomposition().counts();
    CHECKER.bound_report(Some((
        measure(&c),
        json!({"n": c.n, "r": c.r, "max_class_complexity": c.max_class_complexity}),
    )))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn measures_and_passes_on_a_family() {
        let map = wai_gen::family("corridor-niches", &[2]).unwrap();
        let report = CHECKER.check_map(&map);
        assert_eq!((report.examined, report.violations.len()), (1, 0));
        // max |EC| = 20, n = 12, r = 4 (the snapshot counts).
        let largest = report.largest.expect("a ratio");
        assert_eq!(largest.ratio, Rational::from((20, 12 + 16)));
    }

    #[test]
    fn planted_excess_is_reported() {
        let map = wai_gen::family("corridor-niches", &[1]).unwrap();
        let mut counts = wai_cells::Decomposition::new(&map).counts();
        counts.max_class_complexity = 100 * (counts.n + counts.r * counts.r);
        let report = CHECKER.judge(CHECKER.bound_report(Some((measure(&counts), json!({})))));
        assert_eq!(report.violations.len(), 1);
        assert!(report.violations[0].what.contains("above the ceiling"));
    }
}
