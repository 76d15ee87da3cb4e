//! Claim E4.10 (Corollary 4.10, Figs 4.15 and 4.16): the bound of four
//! type-5 edges is reached — two overlapping valid embeddings, even of one
//! skeleton, whose intersection polygon has four type-5 edges and so no
//! map vertex at all.
//!
//! ## Trust
//! Exact, on the intersections and edge types of [`super::l4_7`] (the
//! boundary traced exactly, each edge classified by
//! [`wai_embed::intersection::edge_type`]). The stored figure
//! `counterexamples/E4.10-four-type-5.json` (`wai_gen::repeated_niches(114)`),
//! recognised by its vertices ([`super::Figure`]), must show it for its
//! viewpoints' skeleton: an intersection polygon of four edges, all of
//! type 5, none of whose vertices is a map vertex; otherwise a violation
//! (count `figures`). Elsewhere every intersection polygon L4.7
//! classifies is one instance, and the cases count the configuration
//! wherever it occurs; `progress toward` "four type 5" is the most type-5
//! edges of one polygon.

use std::collections::HashSet;

use rug::Rational;
use serde_json::json;
use wai_embed::intersection::EdgeType;
use wai_embed::Intersection;
use wai_exact::QPoint;
use wai_study::Study;

use super::l4_7::classified_pairs;
use super::{figure, Figure};
use crate::framework::{Case, Checker, Report, Violation};

const ID: &str = "E4.10";

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study).with_cases(&[
    Case {
        name: "four type 5",
        what: "an intersection polygon of two overlapping valid embeddings with four type-5 edges, the most Corollary 4.10 allows (Fig 4.15)",
    },
    Case {
        name: "no map vertex",
        what: "an intersection polygon none of whose vertices is a map vertex (Fig 4.16's remark)",
    },
    Case {
        name: "Fig 4.16",
        what: "both at once, for two embeddings of the same skeleton (Fig 4.16)",
    },
]);

figure!(
    /// Fig 4.16: `wai_gen::repeated_niches(114)`.
    fig_4_16,
    "E4.10-four-type-5.json"
);

/// What one intersection polygon shows: its type-5 edges, and whether any
/// of its vertices is a map vertex.
pub fn shape(
    x: &Intersection,
    types: &[Option<EdgeType>],
    vertices: &HashSet<QPoint>,
) -> (usize, bool) {
    let fives = types
        .iter()
        .filter(|t| **t == Some(EdgeType::TwoCrossings))
        .count();
    let map_vertex = x
        .cycles
        .iter()
        .flatten()
        .any(|e| vertices.contains(&e.from));
    (fives, map_vertex)
}

/// Checks E4.10: the stored figure shows Fig 4.16; every intersection
/// polygon is counted by configuration.
fn check_study(study: &Study<'_>) -> Report {
    let mut report = Report::new(ID);
    let vertices: HashSet<QPoint> = study
        .map()
        .vertices()
        .iter()
        .map(|&p| QPoint::from(p))
        .collect();
    let mut shown = Vec::new();
    for (pair, x, types) in classified_pairs(study) {
        report.record(None);
        let (fives, map_vertex) = shape(x, types, &vertices);
        report.progress_toward("four type 5", Rational::from(fives));
        if fives == 4 {
            report.hit("four type 5");
        }
        if !map_vertex {
            report.hit("no map vertex");
        }
        if fives == 4 && !map_vertex && types.len() == 4 && pair.same_skeleton() {
            report.hit("Fig 4.16");
            shown.push(pair.first.0);
        }
    }
    let fig = fig_4_16();
    if fig.is(study.map()) {
        report.count("figures", 1);
        report.record(figure_verdict(fig, fig.class(study), &shown));
    }
    report
}

/// The stored figure on its own map: the viewpoints' skeleton `class`
/// must be among the classes `shown` to have Fig 4.16's configuration.
pub fn figure_verdict(fig: &Figure, class: Option<usize>, shown: &[usize]) -> Option<Violation> {
    (!class.is_some_and(|c| shown.contains(&c))).then(|| {
        Violation::with_data(
            format!(
                "the stored figure {} no longer shows two embeddings of its viewpoints' skeleton whose intersection polygon has four type-5 edges and no map vertex",
                fig.file
            ),
            json!({ "file": fig.file, "class": class, "classes_shown": shown }),
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use wai_embed::piece::ints;
    use wai_embed::SkeletonRing;

    #[test]
    fn the_figure_shows_four_type_5_edges_and_no_map_vertex() {
        let report = CHECKER.check_map(&fig_4_16().map);
        assert!(report.violations.is_empty(), "{:?}", report.violations);
        assert_eq!(report.counts["figures"], 1);
        assert!(report.cases["Fig 4.16"] >= 1);
        assert_eq!(report.toward["four type 5"], 4);
    }

    #[test]
    fn planted_figure_without_its_configuration_is_reported() {
        let fig = fig_4_16();
        let study = Study::new(&fig.map);
        let class = fig.class(&study).expect("the viewpoints share a skeleton");
        assert!(figure_verdict(fig, Some(class), &[class]).is_none());
        let v = figure_verdict(fig, Some(class), &[class + 1]).expect("not shown");
        assert!(v.what.contains("no longer shows"));
        assert!(figure_verdict(fig, None, &[class]).is_some());
    }

    #[test]
    fn a_map_vertex_on_the_polygon_is_seen() {
        // Two squares overlapping in a corner square, every edge
        // artificial: the corner (2, 2) is a map vertex or not.
        let p = SkeletonRing::from_ring(ints(&[(0, 0), (4, 0), (4, 4), (0, 4)]), vec![true; 4]);
        let q = SkeletonRing::from_ring(ints(&[(2, 2), (6, 2), (6, 6), (2, 6)]), vec![true; 4]);
        let x = Intersection::of(&p.ring, &q.ring);
        let corner: HashSet<QPoint> = ints(&[(2, 2)]).into_iter().collect();
        let types = super::super::l4_7::types(&x, &p, &q, &corner);
        assert!(shape(&x, &types, &corner).1);
        assert!(!shape(&x, &types, &HashSet::new()).1);
    }
}
