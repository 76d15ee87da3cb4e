//! Claim T4.3 (Theorem 4.3): two different valid embeddings of the same
//! skeleton whose embedded **kernels** overlap have mutually invisible
//! witnesses — Theorem 4.2 under a stronger premise, proved first in the
//! thesis.
//!
//! ## Trust
//! As [`super::t4_2`], on the overlapping pairs whose kernels h(ker V*)
//! and h'(ker V*) overlap too (exact half-plane intersections, interior
//! overlap tested exactly and completely). A kernel lies in its skeleton
//! polygon, so these pairs are among T4.2's; the verdicts are the same
//! computation, reported under this claim's id.
//!
//! ## Cases
//! The proof's line l runs through a point x of both kernels' interiors,
//! parallel to t: [`super::t4_2::proof_lines`] restricted to the offsets
//! of lines that cross the kernels' common interior
//! ([`super::t4_2::common_range`]). Each pair hits the case of the order
//! of the eight ends of a, a', b, b' (sec. 4.3's cases 1–3; "order 4" the
//! proof shows impossible here, "other order" none of the four), or "no
//! line l" if such a line does not leave the intersection through
//! artificial edges of h and h' (the proof shows it always does).
//! Generated maps rarely have overlapping kernels (the thesis met 1 in
//! 2,230 overlapping pairs); `counterexamples/E4.1-*.json` have them.

use super::t4_2::CROSS_CHECK_MAX_N;
use super::t4_2::{check_pairs, common_range, hit_orders, proof_lines, ORDER_CASES};
use crate::framework::{Checker, Report};
use wai_exact::QPoint;
use wai_study::Study;

const ID: &str = "T4.3";

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study).with_cases(&ORDER_CASES);

/// Checks T4.3 on every pair of valid embeddings of one skeleton whose
/// kernels overlap.
fn check_study(study: &Study<'_>) -> Report {
    let cross = (study.map().n() <= CROSS_CHECK_MAX_N).then(|| study.sightlines());
    let mut report = Report::new(ID);
    let map = study.map().vertices();
    for pair in study
        .overlapping_pairs()
        .iter()
        .filter(|p| p.kernels_overlap)
    {
        report.absorb(check_pairs(
            ID,
            [pair].into_iter(),
            study.embeddings(),
            study.witnesses(),
            cross,
        ));
        let all = &study.embeddings()[pair.class];
        let (h, h2) = (&all[pair.a], &all[pair.b]);
        let t = QPoint::from(map[h2.embedding.origin]).sub(&QPoint::from(map[h.embedding.origin]));
        let ring = |k: &wai_visibility::ConvexRegion| -> Vec<QPoint> {
            k.vertices().iter().map(QPoint::from).collect()
        };
        let within = common_range(&ring(h.kernel()), &ring(h2.kernel()), &t.perp());
        let cases = match within {
            Some(range) => proof_lines(study, pair, Some(range)),
            None => Vec::new(),
        };
        hit_orders(&mut report, &cases);
    }
    report
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_funnels_of_figs_4_1_and_4_2_are_order_2() {
        // The common artificial edges across the ceiling niches: the ends
        // above l of b' and a are equal or swapped (sec. 4.3, case 2).
        for fig in [super::super::e4_1::fig_4_1(), super::super::e4_1::fig_4_2()] {
            let report = CHECKER.check_map(&fig.map);
            assert_eq!(report.examined, 1);
            assert!(report.violations.is_empty(), "{:?}", report.violations);
            assert_eq!(
                report.cases.get("order 2"),
                Some(&1),
                "{}: {:?}",
                fig.file,
                report.cases
            );
            assert_eq!(report.cases.len(), 1, "{:?}", report.cases);
        }
    }
}
