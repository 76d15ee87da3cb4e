//! Claim L4.6 (Lemma 4.6): two overlapping valid embeddings (skeletons may
//! differ) intersect in one connected polygon.
//!
//! ## Trust
//! Exact, on the overlapping pairs of [`wai_study::Study::embedding_pairs`]
//! (all pairs of one skeleton; of different skeletons on small maps, see
//! [`wai_study::CROSS_SKELETON_MAX_N`]): the boundary of the
//! intersection is traced exactly ([`wai_embed::Intersection`]) and its
//! counter-clockwise cycles — one per component — counted.

use serde_json::json;
use wai_embed::Intersection;

use crate::framework::{Checker, Report, Violation};
use wai_study::Study;

const ID: &str = "L4.6";

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study);

/// Checks L4.6 on every overlapping pair in scope.
fn check_study(study: &Study<'_>) -> Report {
    let mut report = Report::new(ID);
    for pair in study.embedding_pairs() {
        let Some(x) = study.intersection(pair) else {
            continue;
        };
        if !pair.same_skeleton() {
            report.count("different skeletons", 1);
        }
        report.record(check(x).map(|mut v| {
            v.data["pair"] = json!([pair.first, pair.second]);
            v
        }));
    }
    report
}

/// One intersection: a single component.
pub fn check(x: &Intersection) -> Option<Violation> {
    let k = x.components();
    (k != 1).then(|| {
        Violation::with_data(
            format!("two overlapping valid embeddings intersect in {k} regions"),
            json!({ "components": k }),
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn holds_on_the_funnel_figure() {
        let map = wai_gen::repeated_niches(195);
        let report = CHECKER.run(&Study::new(&map));
        assert!(report.examined > 0);
        assert!(report.violations.is_empty(), "{:?}", report.violations);
    }

    #[test]
    fn planted_two_regions_are_reported() {
        let ring = wai_embed::piece::ints;
        let u = ring(&wai_embed::piece::U_RING);
        let bar = ring(&[(-1, 3), (7, 3), (7, 5), (-1, 5)]);
        let v = check(&Intersection::of(&u, &bar)).expect("two regions");
        assert!(v.what.contains("in 2 regions"));
    }
}
