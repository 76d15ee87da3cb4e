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
use crate::ratio::over;
use crate::wedge_counts::{counts, ratio_report, EdgeBound};
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
    let (n, r) = (map.n() as u128, map.r() as u128);
    let largest = counts(study.cell_edges())
        .iter()
        .enumerate()
        .filter(|(_, c)| c.kernel + c.wedge > 0)
        .map(|(k, c)| {
            (
                over(c.kernel, n + r * r + c.wedge as u128),
                json!({ "class": k, "kernel": c.kernel, "wedge": c.wedge }),
            )
        })
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
