//! Claim L5.8 (Lemma 5.8): the interweavement graph (Def 5.9) has no
//! cycle.
//!
//! ## Trust
//! Exact, on every class whose graph has a special node (an instance
//! each): the graph of [`wai_study::GapStructure`], built from the
//! overlapping pairs of valid embeddings and the interweaved gap chains,
//! searched for a cycle by depth-first search. Counts: `special_nodes`,
//! `edges`.
//!
//! ## Cases
//! A graph is bipartite and simple, so a cycle needs two special nodes in
//! one component: graphs whose components have one special node each
//! ([`STARS`]: acyclic by construction) and graphs with a component of
//! several ([`TREES`]: where the lemma has content, with the most special
//! nodes of a component as progress toward it); and graphs with both
//! kinds of special node, overlap classes and interweavements
//! ([`MIXED`], as Example 5.2).

use rug::Rational;
use serde_json::json;
use wai_embed::Interweavement;

use super::over_gap_classes;
use crate::framework::{Case, Checker, Report, Violation};
use wai_study::Study;

const ID: &str = "L5.8";

/// Every component has one special node.
pub const STARS: &str = "stars";
/// Some component has two or more special nodes.
pub const TREES: &str = "trees";
/// Special nodes of both kinds.
pub const MIXED: &str = "mixed kinds";

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study)
    .outer_ring_only("gap chains run along the boundary from one candidate edge to the next (Def 5.4): boundary order on one ring").with_cases(&[
    Case {
        name: STARS,
        what: "an interweavement graph whose components have one special node each (no \
               cycle is possible)",
    },
    Case {
        name: TREES,
        what: "an interweavement graph with two or more special nodes in one component: a \
               cycle of interweaved or overlapping embeddings could close (Lemma 5.8)",
    },
    Case {
        name: MIXED,
        what: "an interweavement graph with an overlap class (Def 5.7) and an interweavement \
               (Def 5.8), as Example 5.2",
    },
]);

/// Checks L5.8 on every class.
fn check_study(study: &Study<'_>) -> Report {
    over_gap_classes(study, ID, |g, _| check_graph(&g.graph))
}

/// L5.8 on one graph (nothing examined when it has no special node).
pub fn check_graph(g: &Interweavement) -> Report {
    let mut report = Report::new(ID);
    if g.special_nodes() == 0 {
        return report;
    }
    report.count("special_nodes", g.special_nodes() as u64);
    report.count("edges", g.edges.len() as u64);
    let most = g.components().iter().map(|c| c.1).max().unwrap_or(0);
    if most >= 2 {
        report.hit(TREES);
    } else {
        report.hit(STARS);
        report.progress_toward(TREES, Rational::from(most));
    }
    if !g.overlap_classes.is_empty() && !g.interweave_classes.is_empty() {
        report.hit(MIXED);
    }
    report.record(g.cycle().map(|cycle| {
        Violation::with_data(
            format!(
                "the interweavement graph has a cycle of {} nodes",
                cycle.len()
            ),
            json!({
                "cycle": cycle.iter().map(|x| format!("{x:?}")).collect::<Vec<_>>(),
                "overlap_classes": g.overlap_classes,
                "interweave_classes": g.interweave_classes,
            }),
        )
    }));
    report
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn planted_circle_of_interweavements_is_reported() {
        let iw = [((0, 0), (1, 0)), ((1, 1), (2, 1)), ((2, 2), (0, 2))];
        let report = check_graph(&Interweavement::new(3, &[], &iw));
        assert_eq!((report.examined, report.violations.len()), (1, 1));
        let report = check_graph(&Interweavement::new(3, &[], &iw[..2]));
        assert_eq!((report.examined, report.violations.len()), (1, 0));
        assert_eq!(report.cases[TREES], 1);
        let report = check_graph(&Interweavement::new(3, &[(1, 2)], &iw[..1]));
        assert_eq!(report.cases[TREES], 1);
        assert_eq!(report.cases[MIXED], 1);
        let report = check_graph(&Interweavement::new(3, &[], &iw[..1]));
        assert_eq!(report.cases[STARS], 1);
        // No special node: nothing to examine.
        assert_eq!(check_graph(&Interweavement::new(3, &[], &[])).examined, 0);
    }
}
