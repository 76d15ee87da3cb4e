//! Claim L5.9 (Lemma 5.9): in the interweavement graph (Def 5.9)
//! 1. every special node has degree ≥ 2;
//! 2. every embedding node has at most one edge to an overlap class;
//! 3. the graph is a forest whose leaves are embedding nodes;
//! 4. it has at most twice as many edges as embedding nodes.
//!
//! ## Trust
//! Exact, on every class whose graph has a special node (an instance
//! each, all four parts checked): the graph of
//! [`wai_study::GapStructure`]. Parts 1 and 2 follow from the
//! definitions as built ([`wai_embed::Interweavement::new`]), so on maps
//! they test the construction; parts 3 and 4 carry Lemma 5.8's content.
//! Counts: `embedding_nodes` (t summed), `edges`.

use serde_json::json;
use wai_embed::{Interweavement, Node};

use super::over_gap_classes;
use crate::framework::{Checker, Report, Violation};
use wai_study::Study;

const ID: &str = "L5.9";

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study);

/// Checks L5.9 on every class.
fn check_study(study: &Study<'_>) -> Report {
    over_gap_classes(study, ID, |g, _| check_graph(&g.graph))
}

/// The parts of L5.9 that fail on `g`, as sentences.
pub fn failures(g: &Interweavement) -> Vec<String> {
    let mut out = Vec::new();
    let degrees = g.degrees();
    for (node, &d) in &degrees {
        let special = !matches!(node, Node::Embedding(_));
        if special && d < 2 {
            out.push(format!("(1) special node {node:?} has degree {d}"));
        }
        if d == 1 && special {
            out.push(format!("(3) leaf {node:?} is a special node"));
        }
    }
    for j in 0..g.embeddings {
        let to_overlap = g
            .edges
            .iter()
            .filter(|(a, b)| *a == Node::Embedding(j) && matches!(b, Node::Overlap(_)))
            .count();
        if to_overlap > 1 {
            out.push(format!(
                "(2) embedding {j} has {to_overlap} edges to overlap classes"
            ));
        }
    }
    if let Some(cycle) = g.cycle() {
        out.push(format!("(3) not a forest: a cycle through {:?}", cycle));
    }
    if g.edges.len() > 2 * g.embeddings {
        out.push(format!(
            "(4) {} edges, more than twice the {} embedding nodes",
            g.edges.len(),
            g.embeddings
        ));
    }
    out
}

/// L5.9 on one graph (nothing examined when it has no special node).
pub fn check_graph(g: &Interweavement) -> Report {
    let mut report = Report::new(ID);
    if g.special_nodes() == 0 {
        return report;
    }
    report.count("embedding_nodes", g.embeddings as u64);
    report.count("edges", g.edges.len() as u64);
    let failed = failures(g);
    report.record((!failed.is_empty()).then(|| {
        Violation::with_data(
            failed.join("; "),
            json!({
                "failures": failed,
                "edges": g.edges.iter().map(|e| format!("{e:?}")).collect::<Vec<_>>(),
            }),
        )
    }));
    report
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn planted_broken_graphs_are_reported() {
        let good = Interweavement::new(3, &[(0, 1)], &[((1, 0), (2, 0))]);
        let report = check_graph(&good);
        assert_eq!((report.examined, report.violations.len()), (1, 0));
        // A special node with one edge: parts 1 and 3.
        let mut lonely = good.clone();
        lonely.interweave_classes.push(vec![(0, 4), (0, 5)]);
        lonely
            .edges
            .insert((Node::Embedding(0), Node::Interweave(1)));
        let f = failures(&lonely);
        assert!(f.iter().any(|s| s.starts_with("(1)")) && f.iter().any(|s| s.starts_with("(3)")));
        // An embedding in two overlap classes: part 2.
        let mut twice = good.clone();
        twice.overlap_classes.push(vec![0, 2]);
        twice.edges.insert((Node::Embedding(0), Node::Overlap(1)));
        twice.edges.insert((Node::Embedding(2), Node::Overlap(1)));
        assert!(failures(&twice).iter().any(|s| s.starts_with("(2)")));
        // A cycle: part 3, and a dense one breaks part 4.
        let iw = [((0, 0), (1, 0)), ((1, 1), (2, 1)), ((2, 2), (0, 2))];
        let cyc = Interweavement::new(3, &[(0, 1), (1, 2)], &iw);
        let f = failures(&cyc);
        assert!(f.iter().any(|s| s.starts_with("(3)")), "{f:?}");
        assert!(f.iter().any(|s| s.starts_with("(4)")), "{f:?}");
        assert_eq!(check_graph(&cyc).violations.len(), 1);
    }
}
