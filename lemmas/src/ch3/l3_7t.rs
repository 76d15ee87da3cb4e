//! Claim L3.7t (Lemma 3.7, tightness; Fig 3.12): a corridor with k niches
//! (family `corridor-niches`) gives one skeleton k embeddings, all valid,
//! with r linear in k — so the bound r of Lemma 3.7 is reached up to a
//! constant factor.
//!
//! ## Trust
//! Exact, on the family's maps only (recognised by their vertices,
//! [`wai_study::family::parameter_of`], k ≤ 8): the most embeddings of one
//! skeleton among all embeddings of [`wai_study::Study`] (every map vertex
//! tried as h(v0)), and their witness regions. Count `largest`: the sum
//! over the maps examined of that most.

use serde_json::json;

use crate::framework::{Checker, Report, Violation};
use wai_study::family::parameter_of;
use wai_study::Study;

const ID: &str = "L3.7t";

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study);
const FAMILY: &str = "corridor-niches";

/// Checks L3.7t on the maps of family `corridor-niches`.
fn check_study(study: &Study<'_>) -> Report {
    match parameter_of(study.map(), FAMILY) {
        Some(k) => check_niches(study, k as usize),
        None => Report::new(ID),
    }
}

/// The check proper: the skeleton with the most embeddings has `expected`
/// of them, all valid.
pub fn check_niches(study: &Study<'_>, expected: usize) -> Report {
    let mut report = Report::new(ID);
    let (class, most) = study
        .embeddings()
        .iter()
        .enumerate()
        .map(|(c, all)| (c, all.len()))
        .max_by_key(|&(c, k)| (k, std::cmp::Reverse(c)))
        .unwrap_or((0, 0));
    let valid = study
        .witnesses()
        .get(class)
        .map_or(0, |ws| ws.iter().filter(|w| w.is_valid()).count());
    report.count("largest", most as u64);
    report.record((most != expected || valid != most).then(|| {
        Violation::with_data(
            format!(
                "the corridor of {expected} niches gives one skeleton at most {most} embeddings ({valid} valid), not {expected}"
            ),
            json!({ "expected": expected, "most": most, "valid": valid, "class": class }),
        )
    }));
    report
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_corridor_reaches_k() {
        for k in 1..=4u32 {
            let map = wai_gen::family(FAMILY, &[k]).unwrap();
            let report = CHECKER.run(&Study::new(&map));
            assert_eq!(report.examined, 1);
            assert!(
                report.violations.is_empty(),
                "k = {k}: {:?}",
                report.violations
            );
        }
    }

    #[test]
    fn planted_shortfall_is_reported() {
        let map = wai_gen::family(FAMILY, &[2]).unwrap();
        let report = check_niches(&Study::new(&map), 3);
        assert_eq!(report.violations.len(), 1);
    }
}
