//! Claim L4.7 (Lemma 4.7): every edge of the intersection polygon of two
//! overlapping valid embeddings is of type 1 (a full edge of both), 2 (an
//! artificial edge of both, between the same points), 3 (an artificial
//! edge of one inside the other), 4 (part of an artificial edge meeting
//! exactly one artificial edge of the other, one end a map vertex) or 5
//! (meeting exactly two, no end a map vertex).
//!
//! ## Trust
//! Exact, on the overlapping pairs of [`wai_study::Study::embedding_pairs`]
//! whose intersection is one region (L4.6 checks that): every maximal edge
//! of its traced boundary is classified by
//! [`wai_embed::intersection::edge_type`]; an edge of no type is a
//! violation.
//!
//! ## Cases
//! The five types of the lemma, "type 1" to "type 5", one instance per
//! edge of an intersection polygon.

use serde_json::json;
use std::collections::HashSet;
use wai_embed::intersection::{edge_type, EdgeType};
use wai_embed::{Intersection, SkeletonRing};
use wai_exact::QPoint;

use crate::framework::{Case, Checker, Report, Violation};
use wai_study::EmbeddingPair;
use wai_study::Study;

const ID: &str = "L4.7";

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study).with_cases(&[
    Case {
        name: NAMES[0],
        what: "a full edge of both embeddings, seen from both witnesses (Lemma 4.7, type 1)",
    },
    Case {
        name: NAMES[1],
        what: "an artificial edge of both, between the same two points (type 2)",
    },
    Case {
        name: NAMES[2],
        what: "an artificial edge of one inside the other (type 3)",
    },
    Case {
        name: NAMES[3],
        what: "part of an artificial edge meeting exactly one artificial edge of the other, one end a map vertex (type 4)",
    },
    Case {
        name: NAMES[4],
        what: "part of an artificial edge meeting exactly two artificial edges of the other, no end a map vertex (type 5)",
    },
]);

const NAMES: [&str; 5] = ["type 1", "type 2", "type 3", "type 4", "type 5"];

/// Checks L4.7 on every edge of every intersection polygon in scope.
fn check_study(study: &Study<'_>) -> Report {
    let mut report = Report::new(ID);
    for (pair, x, types) in classified_pairs(study) {
        let mut r = check_types(x, types);
        r.tag("pair", || json!([pair.first, pair.second]));
        report.absorb(r);
    }
    report
}

/// The overlapping pairs of [`Study::embedding_pairs`] whose intersection
/// is one region, with its edges' types (shared with C4.10 and E4.10;
/// classified once, [`Study::intersection_types`]).
pub fn classified_pairs<'s>(
    study: &'s Study<'_>,
) -> Vec<(&'s EmbeddingPair, &'s Intersection, &'s [Option<EdgeType>])> {
    study
        .embedding_pairs()
        .iter()
        .filter_map(|pair| {
            let x = study.intersection(pair).filter(|x| x.components() == 1)?;
            Some((pair, x, study.intersection_types(pair)?))
        })
        .collect()
}

/// The edges of one intersection polygon, classified.
pub fn types(
    x: &Intersection,
    p: &SkeletonRing,
    q: &SkeletonRing,
    vertices: &HashSet<QPoint>,
) -> Vec<Option<EdgeType>> {
    x.cycles
        .iter()
        .flatten()
        .map(|e| edge_type(e, p, q, vertices))
        .collect()
}

/// Every edge of one intersection polygon has a type.
pub fn check(
    x: &Intersection,
    p: &SkeletonRing,
    q: &SkeletonRing,
    vertices: &HashSet<QPoint>,
) -> Report {
    check_types(x, &types(x, p, q, vertices))
}

/// The edges of `x` with their `types`: each must have one.
fn check_types(x: &Intersection, types: &[Option<EdgeType>]) -> Report {
    let mut report = Report::new(ID);
    for (e, t) in x.cycles.iter().flatten().zip(types) {
        if let Some(t) = t {
            report.hit(NAMES[usize::from(t.number()) - 1]);
        }
        report.record(t.is_none().then(|| {
            Violation::with_data(
                format!(
                    "edge {}–{} of the intersection polygon is of none of the five types",
                    e.from, e.to
                ),
                json!({
                    "edge": [e.from.to_string(), e.to.to_string()],
                    "on_first": e.on_p,
                    "on_second": e.on_q,
                }),
            )
        }));
    }
    report
}

#[cfg(test)]
mod tests {
    use super::*;
    use wai_exact::Point;

    #[test]
    fn holds_on_the_funnel_figure() {
        let map = wai_gen::repeated_niches(195);
        let report = CHECKER.run(&Study::new(&map));
        assert!(report.examined > 0);
        assert!(report.violations.is_empty(), "{:?}", report.violations);
    }

    #[test]
    fn planted_full_edge_inside_the_other_is_reported() {
        // Two squares overlapping in a corner, every edge full: the
        // intersection's edges lie on full edges of one only.
        let pts = |v: &[(i128, i128)]| v.iter().map(|&(x, y)| Point::new(x, y)).collect::<Vec<_>>();
        let p = SkeletonRing::new(&pts(&[(0, 0), (4, 0), (4, 4), (0, 4)]), vec![false; 4]);
        let q = SkeletonRing::new(&pts(&[(2, 2), (6, 2), (6, 6), (2, 6)]), vec![false; 4]);
        let x = Intersection::of(&p.ring, &q.ring);
        let report = check(&x, &p, &q, &HashSet::new());
        assert_eq!(report.examined, 4);
        assert_eq!(report.violations.len(), 4);
    }
}
