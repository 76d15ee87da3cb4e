//! Claim T3.9b (Theorem 3.9): the cells of the visibility cell
//! decomposition and their total complexity N are O(n²r). Measured: the
//! ratio N / (n²·max(r, 1)) on every map.
//!
//! ## Trust
//! Exact counts on every map examined (the decomposition of `wai-cells`,
//! whose arrangement is sanity-checked in its tests); a bound is never
//! decided by one map ([`Report::hold_to`]). The growth exponent comes from
//! the scaling sweep (family `comb-convex-chain`, claim T3.9c).

use rug::Rational;
use wai_cells::Counts;
use wai_study::Study;

use crate::framework::{over, Ceiling, Checker, Report};

const ID: &str = "T3.9b";

/// The checker. The ceiling is far above every ratio seen: the largest
/// seen is 1, on the S tetromino (n = 6, r = 1, N = 36), over 968
/// generated, family, polyomino and r2v maps.
pub const CHECKER: Checker = Checker::new(ID, check_study).with_ceiling(Ceiling(4, 1));

/// N / (n²·max(r, 1)).
pub fn measure(c: &Counts) -> Rational {
    over(
        c.total_complexity,
        (c.n as u128).pow(2) * (c.r as u128).max(1),
    )
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
        // N = 124, n = 12, r = 4 (the snapshot counts).
        let ratio = ratio_on(&CHECKER, "corridor-niches", 2);
        assert_eq!(ratio, Rational::from((124, 12 * 12 * 4)));
    }

    #[test]
    fn planted_excess_is_reported() {
        planted_excess_reported(&CHECKER, measure, |counts| {
            counts.total_complexity = 5 * counts.n * counts.n * counts.r;
        });
    }
}
