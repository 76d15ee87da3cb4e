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
//! ## Trust
//! Exact, on every edge of every 2-cell of the decomposition
//! ([`wai_study::Study::cell_edges`], `wai_embed::wedge`): collinearity with a
//! kernel edge's line or with a wedge's bounding line (through an end of
//! the embedded artificial edge and an end of the candidate edge, the other
//! ends on one side), decided by exact orientation. Counts: `kernel`,
//! `wedge` and `both` (edges the thesis's partition would put in one class
//! only).

use serde_json::json;
use wai_embed::wedge::{occluding_vertex, CellEdgeKind};

use crate::framework::{Checker, Known, Report, Violation};
use wai_study::CellEdges;
use wai_study::Study;

const ID: &str = "O5.3";

/// The checker of this claim, with its known failure.
pub const CHECKER: Checker = Checker::new(ID, check_study).with_known(&[Known {
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
    check_classes_with(study.cell_edges(), explain)
}

/// `data["kind"]` of a violation whose edge lies on the line through an
/// end of an embedded artificial edge and a hidden map vertex that is on no
/// candidate edge (`wai_embed::wedge::occluding_vertex`): the known gap in
/// Observation 5.3's case 2b (`counterexamples/O5.3-hidden-vertex.json`).
pub const HIDDEN_VERTEX: &str = "hidden vertex";

/// Every edge of every cell, by class, with no explanation of a violation.
pub fn check_classes(classes: &[Vec<CellEdges>]) -> Report {
    check_classes_with(classes, |_, _, _| None)
}

/// Every edge of every cell, by class; `explain(class, cell, edge)` finds
/// the (artificial edge, hidden vertex) of a known failure.
pub fn check_classes_with(
    classes: &[Vec<CellEdges>],
    explain: impl Fn(usize, &CellEdges, usize) -> Option<(usize, usize)>,
) -> Report {
    let mut report = Report::new(ID);
    for (class, cells) in classes.iter().enumerate() {
        for c in cells {
            for (k, kind) in c.kinds.iter().enumerate() {
                report.record((*kind == CellEdgeKind::Neither).then(|| {
                    let why = explain(class, c, k);
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
                }));
                match kind {
                    CellEdgeKind::Kernel => report.count("kernel", 1),
                    CellEdgeKind::Wedge => report.count("wedge", 1),
                    CellEdgeKind::Both => report.count("both", 1),
                    CellEdgeKind::Neither => {}
                }
            }
        }
    }
    report
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
            assert!(
                report.counts.get("wedge").copied().unwrap_or(0) > 0,
                "{:?}",
                report.counts
            );
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
