//! Claim L5.2 (Lemma 5.2): the wedge edges of the cells in one embedding
//! h_j number O(r + (Σ_i (c_{i,j} − 1))² − Σ_i (c_{i,j} − 1)²). Measured:
//! the ratio W_j over that expression, its maximum over the valid
//! embeddings of every class of a map.
//!
//! ## Trust
//! Exact counts: W_j from the classification of every cell edge (Def 5.2)
//! of the cells whose origin is h_j(v0), c_{i,j} from
//! [`wai_study::Study::candidate_sets`]. A bound is never decided by one map
//! ([`Report::hold_to`]).

use serde_json::json;

use crate::framework::{over, Ceiling, Checker, Report};
use wai_study::Study;

const ID: &str = "L5.2";

/// The checker. The ceiling is 8× the largest ratio seen: 2 (random-simple-2opt n = 11)
/// over the 1,502 maps of [`super::l5_1::ceiling`].
pub const CHECKER: Checker = Checker::new(ID, check_study)
    .outer_ring_only(super::OWN_ORIGIN)
    .with_ceiling(Ceiling(16, 1));

/// r + (Σ (c − 1))² − Σ (c − 1)² for the c_{i,j} of one embedding.
pub fn bound(r: usize, cs: &[usize]) -> u128 {
    let excess: Vec<u128> = cs.iter().map(|&c| c.saturating_sub(1) as u128).collect();
    let sum: u128 = excess.iter().sum();
    let squares: u128 = excess.iter().map(|x| x * x).sum();
    r as u128 + sum * sum - squares
}

/// The largest ratio over the map's instances.
fn check_study(study: &Study<'_>) -> Report {
    let map = study.map();
    let sets = study.candidate_sets();
    // The largest W_j / bound so far, as (W_j, bound ≥ 1), compared by
    // cross multiplication (u128: W_j is a count of edges, the bound below
    // 2^64 for any map that fits in memory), with where it was reached.
    let mut largest: Option<((u128, u128), serde_json::Value)> = None;
    for (class, c) in study.edge_counts().iter().enumerate() {
        for (&j, &w) in &c.wedge_by_embedding {
            let Some(pos) = sets[class].embeddings.iter().position(|&e| e == j) else {
                continue; // cells lie in valid embeddings only
            };
            let cij = || {
                sets[class].sets[pos]
                    .iter()
                    .map(Vec::len)
                    .collect::<Vec<usize>>()
            };
            let b = bound(map.r(), &cij());
            let (w, d) = (w as u128, b.max(1));
            if largest.as_ref().is_none_or(|((lw, ld), _)| w * ld > lw * d) {
                let at = json!({ "class": class, "embedding": j, "wedge": w, "c": cij(), "bound": b.to_string() });
                largest = Some(((w, d), at));
            }
        }
    }
    CHECKER.bound_report(largest.map(|((w, d), at)| (over(w as usize, d), at)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_bound_of_the_lemma() {
        // c = (3, 2, 1): excesses 2, 1, 0; (2 + 1)² − (4 + 1) = 4; plus r.
        assert_eq!(bound(5, &[3, 2, 1]), 9);
        assert_eq!(bound(0, &[1, 1]), 0);
    }

    #[test]
    fn measures_and_can_fail() {
        super::super::tests::assert_measures_and_can_fail(&CHECKER);
    }
}
