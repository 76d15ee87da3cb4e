//! Claim T3.9b (Theorem 3.9): the cells of the visibility cell
//! decomposition and their total complexity N are O(n²r). Measured: the
//! ratio N / (n²·max(r, 1)) on every map.
//!
//! ## Trust
//! Exact counts on every map examined (the decomposition of `wai-cells`,
//! whose arrangement is sanity-checked in its tests); a bound is never
//! decided by one map: see [`crate::ratio`]. The growth exponent comes from
//! the scaling sweep (family `comb-convex-chain`, claim T3.9c).

use rug::Rational;
use wai_cells::Counts;

use crate::driver::Checker;
use crate::ratio::{over, BoundChecker};

const ID: &str = "T3.9b";

/// The ceiling, far above every ratio seen: the largest seen is 1, on the S
/// tetromino (n = 6, r = 1, N = 36), over 968 generated, family, polyomino
/// and r2v maps.
pub fn ceiling() -> Rational {
    Rational::from(4)
}

/// N / (n²·max(r, 1)).
pub fn measure(c: &Counts) -> Rational {
    over(
        c.total_complexity,
        (c.n as u128).pow(2) * (c.r as u128).max(1),
    )
}

/// The checker: this claim's ratio against its ceiling.
pub const CHECKER: BoundChecker = BoundChecker {
    id: ID,
    measure,
    ceiling,
};

/// The registry's constructor.
pub fn checker() -> Box<dyn Checker> {
    Box::new(CHECKER)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ratio::check_counts;

    #[test]
    fn measures_and_passes_on_a_family() {
        let map = wai_gen::family("corridor-niches", &[2]).unwrap();
        let (report, m) = CHECKER.check_with_ratio(&crate::Study::new(&map));
        assert_eq!((report.examined, report.violations.len()), (1, 0));
        // N = 124, n = 12, r = 4 (the snapshot counts).
        assert_eq!(m.ratio, Rational::from((124, 12 * 12 * 4)));
    }

    #[test]
    fn planted_excess_is_reported() {
        let map = wai_gen::family("corridor-niches", &[1]).unwrap();
        let mut counts = wai_cells::Decomposition::new(&map).counts();
        counts.total_complexity = 5 * counts.n * counts.n * counts.r;
        let (report, _) = check_counts(ID, &map, &counts, &ceiling(), measure);
        assert_eq!(report.violations.len(), 1);
        assert!(report.violations[0].what.contains("above the ceiling"));
    }
}
