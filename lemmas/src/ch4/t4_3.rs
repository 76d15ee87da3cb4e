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

use super::t4_2::{check_pairs, CROSS_CHECK_MAX_N};
use crate::framework::{Checker, Report};
use wai_study::Study;

const ID: &str = "T4.3";

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study);

/// Checks T4.3 on every pair of valid embeddings of one skeleton whose
/// kernels overlap.
fn check_study(study: &Study<'_>) -> Report {
    let cross = (study.map().n() <= CROSS_CHECK_MAX_N).then(|| study.sightlines());
    check_pairs(
        ID,
        study
            .overlapping_pairs()
            .iter()
            .filter(|p| p.kernels_overlap),
        study.embeddings(),
        study.witnesses(),
        cross,
    )
}
