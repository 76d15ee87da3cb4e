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
//!
//! ## Cases
//! The four parts, each counted on what it speaks of: part 1 per special
//! node, part 2 per embedding node with an edge to an overlap class, part
//! 3 per tree (a component with an edge), part 4 per graph; and a graph
//! meeting part 4 with equality, edges = 2 × embedding nodes
//! ([`PART_4_TIGHT`], the count of part 4's induction reached).

use serde_json::json;
use wai_embed::{Interweavement, Node};

use super::over_gap_classes;
use crate::framework::{Case, Checker, Report, Violation};
use wai_study::Study;

const ID: &str = "L5.9";

/// Part 1, per special node.
pub const PART_1: &str = "part 1";
/// Part 2, per embedding node in an overlap class.
pub const PART_2: &str = "part 2";
/// Part 3, per tree.
pub const PART_3: &str = "part 3";
/// Part 4, per graph.
pub const PART_4: &str = "part 4";
/// Part 4 with equality.
pub const PART_4_TIGHT: &str = "part 4 tight";

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study)
    .outer_ring_only("gap chains run along the boundary from one candidate edge to the next (Def 5.4): boundary order on one ring").with_cases(&[
    Case {
        name: PART_1,
        what: "a special node (its degree is at least 2: Lemma 5.9 (1))",
    },
    Case {
        name: PART_2,
        what: "an embedding node with an edge to an overlap class (it has only one: \
               Lemma 5.9 (2))",
    },
    Case {
        name: PART_3,
        what: "a tree of the interweavement graph (its leaves are embedding nodes: \
               Lemma 5.9 (3))",
    },
    Case {
        name: PART_4,
        what: "an interweavement graph with a special node (edges ≤ 2 × embedding nodes: \
               Lemma 5.9 (4))",
    },
    Case {
        name: PART_4_TIGHT,
        what: "an interweavement graph with exactly twice as many edges as embedding nodes",
    },
]);

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
    for _ in 0..g.special_nodes() {
        report.hit(PART_1);
    }
    let in_overlap: std::collections::BTreeSet<usize> =
        g.overlap_classes.iter().flatten().copied().collect();
    for _ in &in_overlap {
        report.hit(PART_2);
    }
    for _ in g.components() {
        report.hit(PART_3);
    }
    report.hit(PART_4);
    if g.edges.len() == 2 * g.embeddings {
        report.hit(PART_4_TIGHT);
    }
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
        // Two special nodes, embeddings 0 and 1 in the overlap class, one
        // tree, one graph.
        let cases = |r: &Report, c: &str| r.cases.get(c).copied().unwrap_or(0);
        assert_eq!(
            [PART_1, PART_2, PART_3, PART_4, PART_4_TIGHT].map(|c| cases(&report, c)),
            [2, 2, 1, 1, 0]
        );
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
