//! Claim L3.5 (Lemma 3.5, with Lemma 3.4): a point with skeleton V* lies in
//! the kernel of exactly one embedding of V*, and (Lemma 3.4) that is the
//! embedding placing V*'s origin on the point's own v0.
//!
//! ## Trust
//! Exhaustive over the cells of every dimension, one point each, exact. The
//! points are the decomposition's: each 2-cell's interior representative,
//! each 1-cell's midpoint, each 0-cell's vertex, with the skeleton and v0
//! the decomposition gives them (the walk, which claim T3.3b tests against
//! fresh queries on every cell). The embeddings are all those of
//! Def 3.11 ([`wai_embed::Embedder`]: every map vertex tried as h(v0),
//! conditions 1–3 exact, the candidate edges' sight tested against
//! `wai_exact::sees` in its own tests); each kernel is the exact half-plane
//! intersection of the embedded skeleton polygon, and "lies in" is closed
//! (a point of a ray may lie on a kernel's boundary).
//!
//! ## Cases
//! **one embedding** (the skeleton embeds once: existence, Lemma 3.4, is
//! what is tested) and **several embeddings** (the uniqueness of the
//! proof: the point must lie in no other embedding's kernel, though
//! kernels of one skeleton may overlap, Example 4.1).

use serde_json::json;
use wai_exact::{Containment, RatPoint};

use crate::framework::{Case, Checker, Report, Violation};
use wai_study::Embedded;
use wai_study::Study;

const ID: &str = "L3.5";

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study).with_cases(&[
    Case {
        name: ONE,
        what: "a point whose skeleton has one embedding (Lemma 3.4's existence)",
    },
    Case {
        name: SEVERAL,
        what: "a point whose skeleton has several embeddings (Lemma 3.5's uniqueness)",
    },
]);

/// Case: the point's skeleton has one embedding.
pub const ONE: &str = "one embedding";
/// Case: the point's skeleton has several embeddings.
pub const SEVERAL: &str = "several embeddings";

/// A point of a cell: where it is, its skeleton's class and its v0.
#[derive(Debug, Clone)]
pub struct CellPoint {
    pub point: RatPoint,
    pub class: usize,
    pub origin: usize,
}

/// Checks L3.5 on every cell of a map.
fn check_study(study: &Study<'_>) -> Report {
    check_points(&cell_points(study), study.embeddings())
}

/// One point of every cell of every dimension.
pub fn cell_points(study: &Study<'_>) -> Vec<CellPoint> {
    let d = study.decomposition();
    let arr = d.arrangement();
    let mut points: Vec<CellPoint> = d
        .cells()
        .iter()
        .map(|&c| CellPoint {
            point: d.representative(c).clone(),
            class: d.skeleton_of(c),
            origin: d.origin_of(c),
        })
        .collect();
    for l in d.lower_cells() {
        let point = match l.site {
            wai_cells::LowerSite::Vertex(v) => arr.point(v).clone(),
            wai_cells::LowerSite::Edge(e) => {
                let h = arr.half_edge(2 * e);
                RatPoint::midpoint(arr.point(h.origin), arr.point(arr.dest(2 * e)))
            }
        };
        points.push(CellPoint {
            point,
            class: l.class,
            origin: l.origin,
        });
    }
    points
}

/// The check proper: each point lies in the kernel of exactly one
/// embedding of its class, the one at its own v0. `by_class`: the
/// embeddings of each class.
pub fn check_points(points: &[CellPoint], by_class: &[Vec<Embedded>]) -> Report {
    let mut report = Report::new(ID);
    for p in points {
        report.examined += 1;
        report.hit(if by_class[p.class].len() > 1 {
            SEVERAL
        } else {
            ONE
        });
        let hits: Vec<usize> = by_class[p.class]
            .iter()
            .filter(|h| h.kernel().locate(&p.point) != Containment::Outside)
            .map(|h| h.embedding.origin)
            .collect();
        let what = match hits.as_slice() {
            [o] if *o == p.origin => continue,
            [o] => format!(
                "the point {} lies in the kernel of the embedding at map vertex {o} only, not in that at its own v0 {}",
                p.point, p.origin
            ),
            [] => format!("the point {} lies in the kernel of no embedding of its skeleton", p.point),
            _ => format!(
                "the point {} lies in the kernels of {} embeddings of its skeleton",
                p.point,
                hits.len()
            ),
        };
        report.violations.push(Violation::with_data(
            what,
            json!({
                "point": p.point.to_string(),
                "class": p.class,
                "origin": p.origin,
                "embeddings_containing_it": hits,
            }),
        ));
    }
    report
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn holds_on_a_corridor_of_niches() {
        let map = wai_gen::family("corridor-niches", &[3]).unwrap();
        let study = Study::new(&map);
        let report = CHECKER.run(&study);
        let d = study.decomposition();
        assert_eq!(
            report.examined as usize,
            d.cells().len() + d.lower_cells().len()
        );
        assert!(report.violations.is_empty(), "{:?}", report.violations);
        // The niche cells' skeleton embeds in all three niches.
        assert!(report.cases.get(SEVERAL).is_some_and(|&k| k > 0));
    }

    #[test]
    fn planted_second_embedding_is_reported() {
        let map = wai_gen::family("corridor-niches", &[2]).unwrap();
        let study = Study::new(&map);
        let points = cell_points(&study);
        let mut by_class = study.embeddings().to_vec();
        // Every class's first embedding twice: its points are in two kernels.
        let c = points[0].class;
        let twin = by_class[c][0].clone();
        by_class[c].push(twin);
        let report = check_points(&points, &by_class);
        assert!(!report.violations.is_empty());
        assert!(
            report.violations[0].what.contains("kernels of 2"),
            "{}",
            report.violations[0].what
        );
        // And with no embeddings at all, the point is in none.
        by_class[c].clear();
        let report = check_points(&points, &by_class);
        assert!(report
            .violations
            .iter()
            .any(|v| v.what.contains("no embedding")));
    }
}
