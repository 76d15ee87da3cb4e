//! Claim T5.16 (Theorem 5.16): an equivalence class has O(r²) wedge edges.
//! Measured: the ratio max W / r² over the classes of every map.
//!
//! ## Trust
//! Exact counts from the classification of every cell edge (Def 5.2,
//! `wai_embed::wedge`); an edge on both a kernel and a wedge line counts as
//! a wedge edge. A bound is never decided by one map (see
//! [`crate::ratio`]).

use serde_json::json;

use crate::framework::{over, Ceiling, Checker, Report};
use wai_study::Study;

const ID: &str = "T5.16";

/// The checker. The ceiling is 8× the largest ratio seen: 2 (random-simple-2opt n = 8,
/// where r is small) over the 1,502 maps of [`super::l5_1::ceiling`].
pub const CHECKER: Checker = Checker::new(ID, check_study)
    .outer_ring_only(super::OWN_ORIGIN)
    .with_ceiling(Ceiling(16, 1));

/// The largest ratio over the map's instances.
fn check_study(study: &Study<'_>) -> Report {
    let map = study.map();
    let r2 = (map.r() as u128).pow(2);
    let largest = study
        .edge_counts()
        .iter()
        .enumerate()
        .filter(|(_, c)| c.kernel + c.wedge > 0)
        .map(|(k, c)| (over(c.wedge, r2), json!({ "class": k, "wedge": c.wedge })))
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
