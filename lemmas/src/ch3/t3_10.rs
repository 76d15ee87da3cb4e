//! Claim T3.10 (Theorem 3.10, Guibas et al.): an equivalence class
//! has complexity |EC| = O(n²) (superseded by T5.17). Measured: the
//! ratio max |EC| / n² on every map.
//!
//! ## Trust
//! Exact counts on every map examined (the decomposition of `wai-cells`,
//! whose arrangement is sanity-checked in its tests); a bound is never
//! decided by one map ([`Report::hold_to`]). The growth exponent comes from
//! the scaling sweep (max |EC| against n + r²).

use rug::Rational;
use wai_cells::Counts;
use wai_study::Study;

use crate::framework::{over, Ceiling, Checker, Report};

const ID: &str = "T3.10";

/// The checker. The ceiling is far above every ratio seen: the largest
/// seen is 2/3, on a triangle (one cell, 2n = 6 over n² = 9), over 968
/// generated, family, polyomino and r2v maps.
pub const CHECKER: Checker = Checker::new(ID, check_study).with_ceiling(Ceiling(4, 1));

/// max |EC| / n².
pub fn measure(c: &Counts) -> Rational {
    over(c.max_class_complexity, (c.n as u128).pow(2))
}

/// The ratio on the decomposition's counts.
fn check_study(study: &Study<'_>) -> Report {
    CHECKER.counts_report(study, measure)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::framework::checker::counts_tests::{planted_excess_reported, ratio_on};

    #[test]
    fn measures_and_passes_on_a_family() {
        // max |EC| = 20, n = 12 (the snapshot counts).
        let ratio = ratio_on(&CHECKER, "corridor-niches", 2);
        assert_eq!(ratio, Rational::from((20, 12 * 12)));
    }

    #[test]
    fn planted_excess_is_reported() {
        planted_excess_reported(&CHECKER, measure, |counts| {
            counts.max_class_complexity = 5 * counts.n * counts.n;
        });
    }
}
