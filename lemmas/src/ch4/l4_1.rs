//! Claim L4.1 (Lemma 4.1, tightness): Ω(r) embeddings of one skeleton can
//! all overlap in one point. The construction of the proof is the family
//! `overlap-fan` (x = 2z + 1 south niches, y = 4z + 1 north niches): the
//! skeleton of the south-niche viewpoints has 2z + 1 valid embeddings,
//! while r grows linearly in z.
//!
//! ## Trust
//! Exact, on the family's maps only (recognised by their vertices,
//! [`wai_study::family::parameter_of`], z ≤ 8): the embeddings and witnesses
//! of [`wai_study::Study`], and a common interior point of all the valid
//! embeddings' skeleton polygons found by the exact slab search of
//! [`wai_embed::common_interior_point`]. A family map on which no skeleton
//! reaches 2z + 1 such embeddings is a violation (of the construction as
//! we built it). Counts: `largest` sums, over the maps examined, the most
//! valid embeddings of one skeleton sharing an interior point.
//!
//! ## Cases
//! The family member examined: "z=0", "z=1", "z=2" or "z≥3" (the
//! construction's parameter; z = 0 is a single south niche, so the
//! overlap of 2z + 1 embeddings needs z ≥ 1 to say anything).

use serde_json::json;
use wai_embed::common_interior_point;
use wai_exact::QPoint;

use crate::framework::{Case, Checker, Report, Violation};
use wai_study::family::parameter_of;
use wai_study::Study;

const ID: &str = "L4.1";

/// The family members by z, the last for every z ≥ 3.
const MEMBERS: [&str; 4] = ["z=0", "z=1", "z=2", "z≥3"];

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study).with_cases(&[
    Case {
        name: MEMBERS[0],
        what: "the construction with z = 0: one south niche, one north niche",
    },
    Case {
        name: MEMBERS[1],
        what: "z = 1: 3 south and 5 north niches, 3 embeddings sharing a point",
    },
    Case {
        name: MEMBERS[2],
        what: "z = 2: 5 south and 9 north niches, 5 embeddings sharing a point",
    },
    Case {
        name: MEMBERS[3],
        what: "z ≥ 3: 2z + 1 ≥ 7 embeddings sharing a point",
    },
]);
const FAMILY: &str = "overlap-fan";

/// Checks L4.1 on the maps of family `overlap-fan`.
fn check_study(study: &Study<'_>) -> Report {
    match parameter_of(study.map(), FAMILY) {
        Some(z) => {
            let mut report = check_fan(study, 2 * z as usize + 1);
            report.hit(MEMBERS[(z as usize).min(3)]);
            report
        }
        None => Report::new(ID),
    }
}

/// The most valid embeddings of one skeleton whose skeleton polygons share
/// an interior point (a skeleton counts only if all its valid embeddings
/// do), with the class and the point.
pub fn largest_common_overlap(study: &Study<'_>) -> Option<(usize, usize, QPoint)> {
    let map = study.map();
    let mut best: Option<(usize, usize, QPoint)> = None;
    for (class, all) in study.embeddings().iter().enumerate() {
        let ws = &study.witnesses()[class];
        let rings: Vec<Vec<QPoint>> = all
            .iter()
            .zip(ws)
            .filter(|(_, w)| w.is_valid())
            .map(|(h, _)| {
                h.embedding
                    .polygon(map)
                    .into_iter()
                    .map(QPoint::from)
                    .collect()
            })
            .collect();
        if rings.is_empty() || best.as_ref().is_some_and(|b| b.1 >= rings.len()) {
            continue;
        }
        if let Some(p) = common_interior_point(&rings) {
            best = Some((class, rings.len(), p));
        }
    }
    best
}

/// The check proper: some skeleton has `expected` valid embeddings all
/// sharing an interior point.
pub fn check_fan(study: &Study<'_>, expected: usize) -> Report {
    let mut report = Report::new(ID);
    let found = largest_common_overlap(study);
    let largest = found.as_ref().map_or(0, |f| f.1);
    report.count("largest", largest as u64);
    report.record((largest != expected).then(|| {
        Violation::with_data(
            format!(
                "the overlap fan has at most {largest} valid embeddings of one skeleton sharing an interior point, not 2z + 1 = {expected}"
            ),
            json!({
                "expected": expected,
                "largest": largest,
                "class": found.as_ref().map(|f| f.0),
                "point": found.as_ref().map(|f| f.2.to_string()),
            }),
        )
    }));
    report
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_fan_reaches_2z_plus_1() {
        for z in 0..=2u32 {
            let map = wai_gen::family(FAMILY, &[z]).unwrap();
            let report = CHECKER.run(&Study::new(&map));
            assert_eq!(report.examined, 1);
            assert!(
                report.violations.is_empty(),
                "z = {z}: {:?}",
                report.violations
            );
        }
        // Other maps are not the construction: nothing examined.
        let map = wai_gen::family("corridor-niches", &[3]).unwrap();
        assert_eq!(CHECKER.run(&Study::new(&map)).examined, 0);
    }

    #[test]
    fn planted_shortfall_is_reported() {
        // The z = 1 fan checked against the count of z = 2.
        let map = wai_gen::family(FAMILY, &[1]).unwrap();
        let report = check_fan(&Study::new(&map), 5);
        assert_eq!(report.violations.len(), 1);
        assert!(report.violations[0].what.contains("at most 3"));
    }
}
