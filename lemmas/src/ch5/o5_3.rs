//! Claim O5.3 (Observation 5.3): every edge of every cell of an
//! equivalence class is a kernel edge (on the boundary of its embedding's
//! kernel) or a wedge edge (on the boundary of a visibility wedge of one of
//! its embedding's valid candidate edges), Defs 5.1 and 5.2.
//!
//! **Known to be false** (a gap in the thesis's case 2b): an edge on the
//! ray from a map vertex u through v_r, an end of an embedded artificial
//! edge, where u is hidden from the cell and on no candidate edge, is
//! neither. It happens on an 8-vertex C-shaped polyomino (the extension of
//! the hidden notch wall below the reflex corner,
//! `counterexamples/O5.3-hidden-vertex.json`) and on the thesis's own
//! Fig 5.4 construction (`convex-niches` k = 2: the ray from the south
//! niche's corner through a mouth corner). Such violations carry
//! `data["kind"]` = [`HIDDEN_VERTEX`] and are counted apart by the stress
//! run; any other edge on neither is a violation.
//!
//! ## Cases
//! The observation's argument, by the segment an edge lies on: case 1, a
//! map edge ([`MAP_EDGE`]: a kernel edge); case 2a, a ray whose far vertex
//! is visible from the cell ([`KERNEL_RAY`]: on an edge of ker V*); case
//! 2b, a ray that makes a hidden vertex visible ([`WEDGE`]: a wedge's
//! bounding ray). An edge on a ray that lies on a kernel line and a wedge
//! line at once is [`BOTH`] (the thesis's classification is a partition;
//! Def 5.2's two kinds are not disjoint), and the known gap of case 2b is
//! [`HIDDEN_VERTEX`].
//!
//! ## Trust
//! Exact, on every edge of every 2-cell of the decomposition
//! ([`wai_study::Study::cell_edges`], `wai_embed::wedge`): collinearity with a
//! kernel edge's line or with a wedge's bounding line (through an end of
//! the embedded artificial edge and an end of the candidate edge, the other
//! ends on one side), decided by exact orientation; whether an edge lies on
//! a map edge or a ray is the arrangement's record of its supporting
//! segment.

use serde_json::json;
use wai_cells::Support;
use wai_embed::wedge::{occluding_vertex, CellEdgeKind};

use crate::framework::{Case, Checker, Known, Report, Violation};
use wai_study::CellEdges;
use wai_study::Study;

const ID: &str = "O5.3";

/// Case 1 of the argument: an edge on a map edge.
pub const MAP_EDGE: &str = "map edge";
/// Case 2a: an edge on a ray, on the kernel's boundary only.
pub const KERNEL_RAY: &str = "kernel ray";
/// Case 2b: an edge on a wedge's bounding ray only.
pub const WEDGE: &str = "wedge";
/// An edge on a ray that is a kernel edge and a wedge edge at once.
pub const BOTH: &str = "both";

/// The checker of this claim, with its cases and its known failure.
pub const CHECKER: Checker = Checker::new(ID, check_study)
    .outer_ring_only(super::OWN_ORIGIN)
    .with_cases(&[
        Case {
            name: MAP_EDGE,
            what: "an edge on a map edge: a kernel edge (Observation 5.3, case 1)",
        },
        Case {
            name: KERNEL_RAY,
            what: "an edge on a visibility ray v_r u with u visible from the cell: on an edge \
                   of ker V*, a kernel edge (Observation 5.3, case 2a)",
        },
        Case {
            name: WEDGE,
            what: "an edge on a bounding ray of a visibility wedge (Def 5.1) and on no kernel \
                   line: a wedge edge (Observation 5.3, case 2b)",
        },
        Case {
            name: BOTH,
            what: "an edge on a ray that lies on the boundary of the embedded kernel and of a \
                   visibility wedge at once (Def 5.2's kinds are not disjoint)",
        },
        Case {
            name: HIDDEN_VERTEX,
            what: "an edge on neither: on the line through an end of an embedded artificial \
                   edge and a hidden map vertex on no candidate edge (the known gap of case 2b)",
        },
    ])
    .with_known(&[Known {
        kind: HIDDEN_VERTEX,
        what: "an edge on the line through an end of an embedded artificial edge and a hidden \
               map vertex on no candidate edge: the gap in the observation's case 2b \
               (counterexamples/O5.3-hidden-vertex.json)",
    }]);

/// Checks O5.3 on every cell edge.
fn check_study(study: &Study<'_>) -> Report {
    let map = study.map();
    let arr = study.arrangement();
    let explain = |class: usize, c: &CellEdges, k: usize| {
        let pts = arr.face_points(c.cell);
        let (x, y) = (&pts[k], &pts[(k + 1) % pts.len()]);
        let h = &study.embeddings()[class][c.embedding].embedding;
        occluding_vertex(map, h, study.valid_candidates(class, c.embedding), x, y)
    };
    let on_map_edge = |c: &CellEdges| -> Vec<bool> {
        arr.face_cycle(c.cell)
            .map(|h| matches!(arr.edge_support(h / 2), Support::MapEdge(_)))
            .collect()
    };
    check_classes_with(study.cell_edges(), on_map_edge, explain)
}

/// `data["kind"]` of a violation whose edge lies on the line through an
/// end of an embedded artificial edge and a hidden map vertex that is on no
/// candidate edge (`wai_embed::wedge::occluding_vertex`): the known gap in
/// Observation 5.3's case 2b (`counterexamples/O5.3-hidden-vertex.json`).
pub const HIDDEN_VERTEX: &str = "hidden vertex";

/// Every edge of every cell, by class, all taken to lie on rays, with no
/// explanation of a violation.
pub fn check_classes(classes: &[Vec<CellEdges>]) -> Report {
    check_classes_with(classes, |c| vec![false; c.kinds.len()], |_, _, _| None)
}

/// Every edge of every cell, by class; `on_map_edge(cell)` tells, by edge,
/// whether it lies on a map edge; `explain(class, cell, edge)` finds the
/// (artificial edge, hidden vertex) of a known failure.
pub fn check_classes_with(
    classes: &[Vec<CellEdges>],
    on_map_edge: impl Fn(&CellEdges) -> Vec<bool>,
    explain: impl Fn(usize, &CellEdges, usize) -> Option<(usize, usize)>,
) -> Report {
    let mut report = Report::new(ID);
    for (class, cells) in classes.iter().enumerate() {
        for c in cells {
            let map_edge = on_map_edge(c);
            for (k, kind) in c.kinds.iter().enumerate() {
                let case = match (kind, map_edge[k]) {
                    (CellEdgeKind::Kernel | CellEdgeKind::Both, true) => MAP_EDGE,
                    (CellEdgeKind::Kernel, false) => KERNEL_RAY,
                    (CellEdgeKind::Wedge, _) => WEDGE,
                    (CellEdgeKind::Both, false) => BOTH,
                    (CellEdgeKind::Neither, _) => {
                        report.record(Some(neither(class, c, k, explain(class, c, k))));
                        if report.violations.last().and_then(Violation::kind) == Some(HIDDEN_VERTEX)
                        {
                            report.hit(HIDDEN_VERTEX);
                        }
                        continue;
                    }
                };
                report.record(None);
                report.hit(case);
            }
        }
    }
    report
}

/// The violation of edge `k` of cell `c` (class `class`), on neither kind
/// of line; `why` the (artificial edge, hidden vertex) of the known gap.
fn neither(class: usize, c: &CellEdges, k: usize, why: Option<(usize, usize)>) -> Violation {
    let what = match why {
        Some((i, u)) => format!(
            "{HIDDEN_VERTEX}: edge {k} of cell {} (class {class}, embedding {}) lies on the line through an end of artificial edge {i} and map vertex {u}, which is hidden and on no candidate edge: neither a kernel edge nor a wedge edge",
            c.cell, c.embedding
        ),
        None => format!(
            "edge {k} of cell {} (class {class}, embedding {}) is neither a kernel edge nor a wedge edge",
            c.cell, c.embedding
        ),
    };
    Violation::with_data(
        what,
        json!({
            "kind": if why.is_some() { HIDDEN_VERTEX } else { "neither" },
            "class": class, "cell": c.cell, "embedding": c.embedding, "edge": k,
            "artificial_edge": why.map(|w| w.0), "hidden_vertex": why.map(|w| w.1),
        }),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn holds_but_for_hidden_vertices_on_maps_with_several_candidate_edges() {
        for map in [
            wai_gen::family("convex-niches", &[2]).unwrap(),
            wai_gen::family("corridor-niches", &[3]).unwrap(),
            wai_gen::random("random-orthogonal", 20, 3).unwrap(),
        ] {
            let report = CHECKER.run(&Study::new(&map));
            assert!(report.examined > 0);
            let other: Vec<_> = report
                .violations
                .iter()
                .filter(|v| !CHECKER.is_known(v))
                .collect();
            assert!(other.is_empty(), "{:?}", other);
            for case in [MAP_EDGE, KERNEL_RAY, WEDGE] {
                assert!(
                    report.cases.get(case).copied().unwrap_or(0) > 0,
                    "{case}: {:?}",
                    report.cases
                );
            }
        }
    }

    #[test]
    fn the_c_shaped_polyomino_has_the_known_gap() {
        // The notch wall (1,1)-(1,2), extended below the reflex corner
        // (1,1), bounds the triangle (1,0), (3/2,0), (1,1); from there
        // (1,2) is hidden and on no candidate edge. (The file
        // counterexamples/O5.3-hidden-vertex.json stores this map.)
        let ring = [
            (0, 0),
            (2, 0),
            (2, 1),
            (1, 1),
            (1, 2),
            (2, 2),
            (2, 3),
            (0, 3),
        ]
        .map(|(x, y)| wai_exact::Point::new(x, y))
        .to_vec();
        let map = wai_map::Map::from_ring(ring).unwrap().0;
        let report = CHECKER.run(&Study::new(&map));
        assert!(!report.violations.is_empty());
        assert!(report.violations.iter().all(|v| CHECKER.is_known(v)));
        assert_eq!(report.cases[HIDDEN_VERTEX], report.violations.len() as u64);
        // Hidden: (1,2) below the notch, and (1,1) above it, symmetrically.
        assert!(report
            .violations
            .iter()
            .all(|v| v.data["hidden_vertex"] == 4 || v.data["hidden_vertex"] == 3));
    }

    #[test]
    fn planted_stray_edge_is_reported() {
        let map = wai_gen::family("convex-niches", &[1]).unwrap();
        let study = Study::new(&map);
        let mut classes: Vec<Vec<CellEdges>> = study.cell_edges().to_vec();
        classes[0][0].kinds[0] = CellEdgeKind::Neither;
        let report = check_classes(&classes);
        assert_eq!(report.violations.len(), 1);
        assert!(report.violations[0].what.contains("neither"));
    }
}
