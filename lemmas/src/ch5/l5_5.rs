//! Claim L5.5 (Lemma 5.5): two gaps that are nested or interweaved
//! (Def 5.6) belong to different embeddings.
//!
//! ## Trust
//! Exact, on every class with a valid embedding: the gaps of the sets
//! C_{i,j} as boundary chains ([`wai_embed::gaps`], whose module doc says
//! how "part of the chain" is read), every two chains of different pairs
//! of map edges compared. Each nested or interweaved pair is one instance
//! (`examined`), counted by case ([`NESTED`], [`INTERWEAVED`]: the
//! lemma's two premises); counts `chains` (all gap chains) and
//! `chains_through_own_set` (a chain passing another edge of its own set,
//! which the reading of Def 5.5 excludes; 0 on the stress corpus).

use serde_json::json;
use wai_embed::{CandidateSets, GapRelation};

use crate::framework::{Case, Checker, Report, Violation};
use wai_study::GapStructure;

use super::over_gap_classes;
use wai_study::Study;

const ID: &str = "L5.5";

/// Two gaps, one nested into the other.
pub const NESTED: &str = "nested";
/// Two interweaved gaps.
pub const INTERWEAVED: &str = "interweaved";

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study)
    .outer_ring_only("gap chains run along the boundary from one candidate edge to the next (Def 5.4): boundary order on one ring").with_cases(&[
    Case {
        name: NESTED,
        what: "two gaps of which one is nested into the other (Def 5.6)",
    },
    Case {
        name: INTERWEAVED,
        what: "two interweaved gaps (Def 5.6)",
    },
]);

/// Checks L5.5 on every class.
fn check_study(study: &Study<'_>) -> Report {
    over_gap_classes(study, ID, check_class)
}

/// L5.5 on one class: its gap structure and its sets C_{i,j}.
pub fn check_class(g: &GapStructure, c: &CandidateSets) -> Report {
    let mut report = Report::new(ID);
    report.count("chains", g.chains.len() as u64);
    for ch in &g.chains {
        if ch.holds_own_set(&c.sets[ch.j][ch.i]) {
            report.count("chains_through_own_set", 1);
        }
    }
    for &(a, b, rel) in &g.related {
        let (x, y) = (&g.chains[a], &g.chains[b]);
        report.hit(if rel == GapRelation::Interweaved {
            INTERWEAVED
        } else {
            NESTED
        });
        report.record((x.j == y.j).then(|| {
            Violation::with_data(
                format!(
                    "gaps ({}, {}) of artificial edge {} and ({}, {}) of artificial edge {} are {rel:?} in one embedding {}",
                    x.s, x.e, x.i, y.s, y.e, y.i, c.embeddings[x.j]
                ),
                json!({
                    "embedding": c.embeddings[x.j],
                    "first": {"s": x.s, "e": x.e, "artificial": c.artificial[x.i]},
                    "second": {"s": y.s, "e": y.e, "artificial": c.artificial[y.i]},
                    "relation": format!("{rel:?}"),
                }),
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
    fn planted_interweaved_gaps_of_one_embedding_are_reported() {
        // One embedding, two artificial edges whose gaps (1, 6) and (4, 9)
        // interweave on a boundary of 20 edges.
        let c = CandidateSets::from_sets(
            vec![0, 1],
            vec![0, 1],
            vec![vec![vec![1, 6], vec![4, 9]], vec![vec![], vec![]]],
        );
        let chains = vec![GapChain::new(1, 6, 0, 0, 20), GapChain::new(4, 9, 0, 1, 20)];
        let g = GapStructure::new(chains.clone(), vec![], 2);
        let report = check_class(&g, &c);
        assert_eq!((report.examined, report.violations.len()), (1, 1));
        assert_eq!(report.cases[INTERWEAVED], 1);
        // In different embeddings they may.
        let moved = vec![chains[0], GapChain::new(4, 9, 1, 1, 20)];
        let report = check_class(&GapStructure::new(moved, vec![], 2), &c);
        assert_eq!((report.examined, report.violations.len()), (1, 0));
    }

    #[test]
    fn holds_on_maps_with_multiple_candidate_edges() {
        let mut chains = 0;
        for seed in 0..4 {
            let map = wai_gen::bottled_niches(seed);
            let report = CHECKER.check_map(&map);
            assert!(report.violations.is_empty(), "{:?}", report.violations);
            assert_eq!(report.counts.get("chains_through_own_set"), None);
            chains += report.counts.get("chains").copied().unwrap_or(0);
        }
        assert!(chains > 0);
    }
}
