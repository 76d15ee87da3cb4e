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
    CHECKER.counts_report(study, measure)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::framework::checker::counts_tests::{planted_excess_reported, ratio_on};

    #[test]
    fn measures_and_passes_on_a_family() {
        // max |EC| = 20, n = 12, r = 4 (the snapshot counts).
        let ratio = ratio_on(&CHECKER, "corridor-niches", 2);
        assert_eq!(ratio, Rational::from((20, 12 + 16)));
    }

    #[test]
    fn planted_excess_is_reported() {
        planted_excess_reported(&CHECKER, measure, |counts| {
            counts.max_class_complexity = 100 * (counts.n + counts.r * counts.r);
        });
    }
}
