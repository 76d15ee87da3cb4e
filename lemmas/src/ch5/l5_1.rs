//! Claim L5.1 (Lemma 5.1): an equivalence class has O(n + r² + W) kernel
//! edges, W its wedge edges. Measured: the ratio max K / (n + r² + W) over
//! the classes of every map.
//!
//! ## Trust
//! Exact counts from the classification of every cell edge (Def 5.2,
//! `wai_embed::wedge`); an edge on both kinds of line counts for both. A
//! bound is never decided by one map ([`Report::hold_to`]).

use serde_json::json;

use crate::framework::{over, Ceiling, Checker, Report};
use wai_study::Study;

const ID: &str = "L5.1";

/// The checker. The ceiling is 4× the largest ratio seen: 1 (an R2V floor plan) over
/// 1,502 maps — the stress corpus (901), 150 each of `bottled_niches` and
/// `repeated_niches`, and 300 random maps of every kind with n from 8 to
/// 30.
pub const CHECKER: Checker = Checker::new(ID, check_study)
    .outer_ring_only(super::OWN_ORIGIN)
    .with_ceiling(Ceiling(4, 1));

/// The largest ratio over the map's instances.
fn check_study(study: &Study<'_>) -> Report {
    let map = study.map();
    let (n, r) = (map.n() as u128, map.r() as u128);
    let largest = study
        .edge_counts()
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
    CHECKER.bound_report(largest)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn measures_and_can_fail() {
        super::super::tests::assert_measures_and_can_fail(&CHECKER);
    }
}
