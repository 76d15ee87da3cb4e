//! Claim T5.17 (Theorem 5.17, the main theorem of chapter 5): the cells of
//! an equivalence class and their total complexity are O(n + r²). Measured: the
//! ratio max |EC| / (n + r²) on every map.
//!
//! ## Trust
//! Exact counts on every map examined (the decomposition of `wai-cells`,
//! whose arrangement is sanity-checked in its tests); a bound is never
//! decided by one map: see [`crate::ratio`]. The growth exponent comes from
//! the scaling sweep (max |EC| against n + r²).

use rug::Rational;
use wai_cells::Counts;

use crate::driver::Checker;
use crate::ratio::{over, BoundChecker};

const ID: &str = "T5.17";

/// The ceiling, far above every ratio seen: the largest seen is 2, on every
/// convex map (one cell of complexity 2n over n + 0), over 968 generated,
/// family, polyomino and r2v maps.
pub fn ceiling() -> Rational {
    Rational::from(8)
}

/// max |EC| / (n + r²).
pub fn measure(c: &Counts) -> Rational {
    over(c.max_class_complexity, c.n as u128 + (c.r as u128).pow(2))
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
        // max |EC| = 20, n = 12, r = 4 (the snapshot counts).
        assert_eq!(m.ratio, Rational::from((20, 12 + 16)));
    }

    #[test]
    fn planted_excess_is_reported() {
        let map = wai_gen::family("corridor-niches", &[1]).unwrap();
        let mut counts = wai_cells::Decomposition::new(&map).counts();
        counts.max_class_complexity = 100 * (counts.n + counts.r * counts.r);
        let (report, _) = check_counts(ID, &map, &counts, &ceiling(), measure);
        assert_eq!(report.violations.len(), 1);
        assert!(report.violations[0].what.contains("above the ceiling"));
    }
}
