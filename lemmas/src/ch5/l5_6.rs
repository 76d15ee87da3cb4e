//! Claim L5.6 (Lemma 5.6): the embeddings of two interweaved gaps
//! (Def 5.6) do not overlap.
//!
//! ## Trust
//! Exact, on every class with a valid embedding: the interweaved pairs of
//! gap chains of different embeddings ([`wai_study::GapStructure`]),
//! each an instance, against whether the two embedded skeleton polygons'
//! interiors overlap (`wai_embed::interiors_overlap`, the relation of
//! Theorem 4.2 and Def 5.7). Interweaved gaps of one embedding are
//! L5.5's violations and not examined here (`same_embedding`).
//!
//! ## Cases
//! Whether the two gaps belong to the same artificial edge of V* in their
//! two embeddings ([`SAME_EDGE`]) or to different ones ([`OTHER_EDGES`]:
//! Example 5.2 notes that interweaved embeddings' artificial edges need
//! not be identical).

use serde_json::json;

use crate::framework::{Case, Checker, Report, Violation};
use wai_study::GapStructure;

use super::over_gap_classes;
use wai_study::Study;

const ID: &str = "L5.6";

/// Interweaved gaps of the same artificial edge in their embeddings.
pub const SAME_EDGE: &str = "same artificial edge";
/// Interweaved gaps of different artificial edges.
pub const OTHER_EDGES: &str = "different artificial edges";

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study)
    .outer_ring_only("gap chains run along the boundary from one candidate edge to the next (Def 5.4): boundary order on one ring").with_cases(&[
    Case {
        name: SAME_EDGE,
        what: "interweaved gaps of two embeddings h1(a), h2(a) of one artificial edge a",
    },
    Case {
        name: OTHER_EDGES,
        what: "interweaved gaps of different artificial edges h1(a1), h2(a2), a1 ≠ a2 \
               (as E^iw_2 of Example 5.2)",
    },
]);

/// Checks L5.6 on every class.
fn check_study(study: &Study<'_>) -> Report {
    over_gap_classes(study, ID, |g, _| check_class(g))
}

/// L5.6 on one class's gap structure; violations name the embeddings by
/// their positions `j1`, `j2` in the class's valid embeddings (the
/// driver's `embeddings` tag lists them).
pub fn check_class(g: &GapStructure) -> Report {
    let mut report = Report::new(ID);
    let all = g
        .related
        .iter()
        .filter(|r| r.2 == wai_embed::GapRelation::Interweaved);
    for &(a, b, _) in all {
        let (x, y) = (&g.chains[a], &g.chains[b]);
        if x.j == y.j {
            report.count("same_embedding", 1);
            continue;
        }
        report.hit(if x.i == y.i { SAME_EDGE } else { OTHER_EDGES });
        report.record(g.overlap(x.j, y.j).then(|| {
            Violation::with_data(
                format!(
                    "gaps ({}, {}) and ({}, {}) are interweaved, and their embeddings overlap",
                    x.s, x.e, y.s, y.e
                ),
                json!({"j1": x.j, "j2": y.j, "first": [x.s, x.e], "second": [y.s, y.e]}),
            )
        }));
    }
    report
}

#[cfg(test)]
mod tests {
    use super::*;
    use wai_embed::GapChain;

    #[test]
    fn planted_overlap_of_interweaved_embeddings_is_reported() {
        let chains = vec![GapChain::new(1, 6, 0, 0, 20), GapChain::new(4, 9, 1, 0, 20)];
        let report = check_class(&GapStructure::new(chains.clone(), vec![(0, 1)], 2));
        assert_eq!((report.examined, report.violations.len()), (1, 1));
        assert_eq!(report.cases[SAME_EDGE], 1);
        let report = check_class(&GapStructure::new(chains, vec![], 2));
        assert_eq!((report.examined, report.violations.len()), (1, 0));
    }
}
