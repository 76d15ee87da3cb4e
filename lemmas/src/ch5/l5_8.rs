//! Claim L5.8 (Lemma 5.8): the interweavement graph (Def 5.9) has no
//! cycle.
//!
//! ## Trust
//! Exact, on every class whose graph has a special node (an instance
//! each): the graph of [`wai_study::GapStructure`], built from the
//! overlapping pairs of valid embeddings and the interweaved gap chains,
//! searched for a cycle by depth-first search. Counts: `special_nodes`,
//! `edges`.

use serde_json::json;
use wai_embed::Interweavement;

use super::over_gap_classes;
use crate::framework::{Checker, Report, Violation};
use wai_study::Study;

const ID: &str = "L5.8";

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study);

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
        // No special node: nothing to examine.
        assert_eq!(check_graph(&Interweavement::new(3, &[], &[])).examined, 0);
    }
}
