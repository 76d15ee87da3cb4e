//! Claim T5.16 (Theorem 5.16): an equivalence class has O(r²) wedge edges.
//! Measured: the ratio max W / r² over the classes of every map.
//!
//! ## Trust
//! Exact counts from the classification of every cell edge (Def 5.2,
//! `wai_embed::wedge`); an edge on both a kernel and a wedge line counts as
//! a wedge edge. A bound is never decided by one map (see
//! [`crate::ratio`]).

use rug::Rational;
use serde_json::json;

use crate::driver::{Checker, Report};
use crate::ratio::over;
use crate::wedge_counts::{counts, ratio_report, EdgeBound};
use crate::Study;

const ID: &str = "T5.16";

/// The ceiling, 8× the largest ratio seen: 2 (random-simple-2opt n = 8,
/// where r is small) over the 1,502 maps of [`crate::l5_1::ceiling`].
pub fn ceiling() -> Rational {
    Rational::from(16)
}

/// Checks T5.16.
pub const CHECKER: EdgeBound = EdgeBound {
    id: ID,
    check_with_ratio,
    ceiling,
};

/// The registry's constructor.
pub fn checker() -> Box<dyn Checker> {
    Box::new(CHECKER)
}

/// The report and the ratio.
pub fn check_with_ratio(study: &Study<'_>, ceiling: &Rational) -> (Report, Rational) {
    let map = study.map();
    let r2 = (map.r() as u128).pow(2);
    let largest = counts(study.cell_edges())
        .iter()
        .enumerate()
        .filter(|(_, c)| c.kernel + c.wedge > 0)
        .map(|(k, c)| (over(c.wedge, r2), json!({ "class": k, "wedge": c.wedge })))
        .max_by(|a, b| a.0.cmp(&b.0));
    ratio_report(ID, map, largest, ceiling)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn measures_and_can_fail() {
        crate::wedge_counts::assert_measures_and_can_fail(&CHECKER);
    }
}
