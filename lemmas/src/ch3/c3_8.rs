//! Claim C3.8 (Corollary 3.8): a localization query has at most r answers
//! — at most r points of the map have a given visibility polygon.
//!
//! The query is the visibility polygon V_p of one point p of every cell of
//! every dimension; its answers are the points q with V_q = V_p + (q − p)
//! (Def 3.2). For a map with no reflex vertex (convex, outside the thesis's
//! assumption) the bound read is max(r, 1), as for Lemma 3.7.
//!
//! ## Trust
//! Exhaustive over the cells of every dimension, one point each (the
//! decomposition's: each 2-cell's representative, each 1-cell's midpoint,
//! each 0-cell's vertex, as claim L3.5 takes them), exact. The answers are
//! counted by their definition, not by the skeleton: for each embedding h
//! of the cell's skeleton other than its own (origin o' ≠ v0), the
//! translate q = p + (o' − v0) is an answer iff it lies inside the map and
//! V_q, computed afresh, has exactly the vertices of V_p translated. No
//! answer is missed: an answer q has V*_q = V*_p translated (Def 3.7 reads
//! only V), so its origin is a map vertex where V*_p embeds (Lemma 3.4's
//! embedding), and the embeddings of [`wai_study::Study`] are all of Def
//! 3.11's (every map vertex tried as h(v0)). A translate q whose skeleton,
//! read off the expansion ([`Study::fresh_skeletons`]), is not p's (also
//! read afresh) translated is no answer and its V_q is not built (Def 3.7 reads only the
//! polygon and the viewpoint: equal polygons, translated with their
//! viewpoints, have equal skeletons); every answer counted has had its V_q
//! compared with V_p translated, vertex by vertex. p itself is always an
//! answer. V_p and the translates are computed only for skeletons with
//! more than one embedding; with one, p is the only answer.
//!
//! ## Cases
//! Each query by its number A of answers: **one answer**, **several
//! answers** (2 ≤ A < r) and **r answers** (A = r ≥ 2: the bound reached,
//! approached with the progress A / r). Counts: `translates` (translates
//! inside the map, whose skeleton or V_q was compared) and `kernel but no
//! answer` (those whose V_q differs: points of another embedding that see
//! something else, Remark 3.4).

use serde_json::json;
use wai_exact::{Containment, Point, RatPoint};
use wai_study::sample::{self, translate};
use wai_study::Study;
use wai_visibility::VisibilityPolygon;

use super::l3_5::{cell_points, CellPoint};
use crate::framework::{over, Case, Checker, Report, Violation};

const ID: &str = "C3.8";

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study).with_cases(&[
    Case {
        name: ONE,
        what: "a query (V_p of a cell's point) with one answer, p itself",
    },
    Case {
        name: SEVERAL,
        what: "a query with 2 <= A < r answers",
    },
    Case {
        name: REACHED,
        what: "a query with A = r >= 2 answers: the bound of Corollary 3.8 reached",
    },
]);

/// Case: one answer.
pub const ONE: &str = "one answer";
/// Case: several answers, fewer than r.
pub const SEVERAL: &str = "several answers";
/// Case: r ≥ 2 answers.
pub const REACHED: &str = "r answers";

/// Checks C3.8 on one point of every cell of a map.
fn check_study(study: &Study<'_>) -> Report {
    check_points(study, &cell_points(study), study.map().r())
}

/// Whether two visibility polygons have the same vertices (both start at
/// their lexicographically least vertex, which a translation keeps).
fn same_vertices(a: &VisibilityPolygon, b: &[RatPoint]) -> bool {
    a.len() == b.len() && a.vertices().iter().zip(b).all(|(v, q)| v.point == *q)
}

/// The check proper on `points`, with the bound max(`r`, 1).
pub fn check_points(study: &Study<'_>, points: &[CellPoint], r: usize) -> Report {
    let map = study.map();
    let index = study.index();
    let v = map.vertices();
    let mut report = Report::new(ID);
    let bound = r.max(1);
    for p in points {
        let hs = &study.embeddings()[p.class];
        let mut answers = vec![p.point.clone()];
        if hs.len() > 1 {
            let mut vp: Option<VisibilityPolygon> = None;
            let o = v[p.origin];
            for h in hs.iter().filter(|h| h.embedding.origin != p.origin) {
                let t = v[h.embedding.origin];
                let (dx, dy) = (t.x - o.x, t.y - o.y);
                let q = translate(&p.point, dx, dy);
                if map.locate(&q) != Containment::Inside {
                    continue;
                }
                report.count("translates", 1);
                // V*_q other than V*_p translated by t: V_q is not V_p + t
                // (Def 3.7 reads only V_q and q's position). Both fresh.
                let own = study.fresh_skeletons(&[p.point.clone(), q.clone()]);
                if let (Ok(sp), Ok(sq)) = (&*own[0], &*own[1]) {
                    let moved = v[sp.origin()];
                    let same_skeleton = v[sq.origin()] == Point::new(moved.x + dx, moved.y + dy)
                        && sq.key(map) == sp.key(map);
                    if !same_skeleton {
                        report.count("kernel but no answer", 1);
                        continue;
                    }
                }
                let vp = vp.get_or_insert_with(|| {
                    index
                        .visibility_polygon(&p.point)
                        .expect("a cell's point lies inside the map")
                });
                let vq = index
                    .visibility_polygon(&q)
                    .expect("an interior point has a visibility polygon");
                let moved: Vec<RatPoint> = vp
                    .vertices()
                    .iter()
                    .map(|x| translate(&x.point, dx, dy))
                    .collect();
                if same_vertices(&vq, &moved) {
                    answers.push(q);
                } else {
                    report.count("kernel but no answer", 1);
                }
            }
        }
        let a = answers.len();
        report.hit(match a {
            1 => ONE,
            _ if a >= r => REACHED,
            _ => SEVERAL,
        });
        if r >= 2 {
            report.progress_toward(REACHED, over(a, r as u128));
        }
        report.record((a > bound).then(|| {
            Violation::with_data(
                format!(
                    "map {}: the view of {} has {a} answers, more than max(r, 1) = {bound}",
                    sample::map_name(map),
                    p.point
                ),
                json!({
                    "map": sample::map_name(map),
                    "point": p.point.to_string(),
                    "point_file_units": sample::point_json(map, &p.point),
                    "class": p.class,
                    "r": r,
                    "answers": answers.iter().map(ToString::to_string).collect::<Vec<_>>(),
                }),
            )
        }));
    }
    report
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_corridor_of_niches_answers_up_to_k_times() {
        let map = wai_gen::family("corridor-niches", &[3]).unwrap();
        let study = Study::new(&map);
        let r = CHECKER.run(&study);
        let d = study.decomposition();
        assert_eq!(r.examined as usize, d.cells().len() + d.lower_cells().len());
        assert!(r.violations.is_empty(), "{:?}", r.violations);
        // Deep in a niche the view repeats in all three niches: 3 of r = 6.
        assert!(
            r.cases.get(SEVERAL).is_some_and(|&k| k > 0),
            "{:?}",
            r.cases
        );
        assert_eq!(r.toward.get(REACHED), Some(&rug::Rational::from((1, 2))));
        assert!(r.counts.get("translates").is_some_and(|&k| k > 0));
    }

    #[test]
    fn a_bound_below_the_answers_is_reported() {
        // The same points against a bound of 2: the niche views have 3.
        let map = wai_gen::family("corridor-niches", &[3]).unwrap();
        let study = Study::new(&map);
        let r = check_points(&study, &cell_points(&study), 2);
        assert!(!r.violations.is_empty());
        let v = &r.violations[0];
        assert_eq!(v.data["answers"].as_array().map(Vec::len), Some(3));
        assert!(v.what.contains("3 answers"), "{}", v.what);
    }
}
