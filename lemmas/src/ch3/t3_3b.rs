//! Claim T3.3b (Theorem 3.3(2), restated for cells of every dimension):
//! every point of the map's interior has the skeleton of the cell that
//! contains it, where the decomposition's cells are the open faces (2-cells),
//! the open edges inside M (1-cells) and the vertices inside M (0-cells) of
//! the arrangement of map edges and visibility rays. A lower-dimensional
//! cell whose skeleton equals an adjacent 2-cell's is absorbed by it; that is
//! a naming, not a further claim, so the statement to check is that each
//! open face and each open edge has one skeleton on all its points (a vertex
//! is a single point).
//!
//! The thesis states part (2) for 2-cells with the boundary assignment of
//! sec. 3.6; that reading is false where opposite collinear rays cover a
//! segment or rays cross with no common side
//! (`counterexamples/T3.3b-doorway-1d-cell.json`), and the rule is now claim
//! A3.6, checked by [`super::a3_6`].
//!
//! ## Trust
//! Exhaustive over cells, sampled within each cell; every comparison is
//! exact. The cells and their skeletons are the production
//! [`wai_cells::Decomposition`]'s, which computes skeletons by walking the
//! arrangement from one query (sec. 3.9.2); every sample's skeleton is
//! computed afresh by a visibility query
//! ([`wai_visibility::VisibilityIndex::skeleton_at`]: Def 3.7 read off the
//! triangular expansion, tested equal to [`wai_visibility::Skeleton::of`]
//! on V_p) and compared with its cell's, one instance per cell:
//! - a 2-cell: two interior points, chosen with small denominators
//!   ([`wai_study::sample::simple_interior_points`]) so that the queries
//!   stay on the integer fast paths;
//! - a 1-cell (an arrangement edge on a ray; edges on ∂M are not interior):
//!   three points of it, likewise ([`wai_study::sample::simple_segment_points`]);
//! - a 0-cell (an arrangement vertex off ∂M): the vertex.
//!
//! The queries are the study's ([`Study::fresh_skeletons`]), shared with
//! A3.6, which asks for many of the same points.
//!
//! So the checker also tests the walk against fresh queries on every cell.
//! Two skeletons are equal when their origins v0 (map points) and their
//! canonical keys are: the same skeleton in the same embedding. The proof of
//! Thm 3.3 (a segment inside one convex cell that no ray crosses) makes every
//! point of an open face or open edge equivalent to the sampled ones.
//! **Not covered:** points of ∂M (the thesis assumes viewpoints off ∂M).
//!
//! ## Cases
//! The cells by dimension: **2-cell** (an open face), **1-cell** (an open
//! arrangement edge on a ray whose skeleton no adjacent 2-cell shares), and
//! **0-cell** (an arrangement vertex inside M whose skeleton no incident
//! 2-cell shares).

use serde_json::{json, Value};
use wai_cells::{Arrangement, LowerSite};
use wai_exact::RatPoint;
use wai_map::Map;
use wai_study::FreshSkeleton;
use wai_visibility::SkeletonKey;

use crate::framework::{Case, Checker, Report, Violation};
use wai_study::sample;
use wai_study::Study;

const ID: &str = "T3.3b";

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study).with_cases(&[
    Case {
        name: CELL_2,
        what: "a 2-cell: an open face of the arrangement (Thm 3.3 (2))",
    },
    Case {
        name: CELL_1,
        what: "a 1-cell: an open arrangement edge on a ray with a skeleton of its own \
               (counterexamples/T3.3b-doorway-1d-cell.json)",
    },
    Case {
        name: CELL_0,
        what: "a 0-cell: an arrangement vertex inside M with a skeleton of its own",
    },
]);

/// Case: a 2-cell.
pub const CELL_2: &str = "2-cell";
/// Case: a 1-cell.
pub const CELL_1: &str = "1-cell";
/// Case: a 0-cell.
pub const CELL_0: &str = "0-cell";

/// The `data["kind"]` of a violation: a point with a skeleton other than
/// its cell's.
pub const SKELETON_DIFFERS: &str = "skeleton-differs";
/// The `data["kind"]` of a point whose V_p or V*_p cannot be built.
pub const NO_SKELETON: &str = "no-skeleton";

/// Checks T3.3b on every cell of every dimension of a map.
fn check_study(study: &Study<'_>) -> Report {
    let map = study.map();
    let name = sample::map_name(map);
    let mut report = Report::new(ID);
    if let Err(e) = study.arrangement_sanity() {
        report.record(Some(Violation::with_data(
            format!("map {name}: the arrangement fails its sanity check: {e}"),
            json!({"map": name, "kind": NO_SKELETON, "sanity_check": e}),
        )));
        return report;
    }
    // The cells' skeletons as the decomposition computes them (by its
    // walk, sec. 3.9.2): every sample is checked against them.
    let d = study.decomposition();
    let arr = d.arrangement();
    for f in arr.cells() {
        report.hit(CELL_2);
        let points = study.cell_sample_points(f);
        if points.len() < 2 {
            let ring: Vec<RatPoint> = arr.face_points(f);
            report.record(Some(Violation::with_data(
                format!("map {name}, cell {f}: no interior point"),
                json!({"map": name, "kind": NO_SKELETON, "cell": f,
                       "cell_vertices": ring.iter().map(ToString::to_string).collect::<Vec<_>>()}),
            )));
            continue;
        }
        let claimed = (d.origin_of(f), &d.skeletons()[d.skeleton_of(f)]);
        report.absorb(check_cell_points(study, Cell::Face(f), claimed, &points));
    }
    for c in d.lower_cells() {
        let claimed = (c.origin, &d.skeletons()[c.class]);
        let (cell, points) = match c.site {
            LowerSite::Edge(e) => {
                report.hit(CELL_1);
                (Cell::Edge(e), study.edge_sample_points(e).to_vec())
            }
            LowerSite::Vertex(v) => {
                report.hit(CELL_0);
                (Cell::Vertex(v), vec![arr.point(v).clone()])
            }
        };
        report.absorb(check_cell_points(study, cell, claimed, &points));
    }
    report
}

/// Three points of the open arrangement edge `e` on a ray, with small
/// denominators ([`sample::simple_segment_points`]): the middle one is
/// the simplest point of the edge ([`edge_point`]).
pub fn edge_points(arr: &Arrangement, e: usize) -> [RatPoint; 3] {
    let (a, b, line) = sample::arrangement_edge_line(arr, e);
    sample::simple_segment_points(a, b, line)
}

/// The simplest point of the open arrangement edge `e`: the middle one of
/// [`edge_points`].
pub fn edge_point(arr: &Arrangement, e: usize) -> RatPoint {
    let (a, b, line) = sample::arrangement_edge_line(arr, e);
    sample::simple_segment_point(a, b, line)
}

/// A cell of the decomposition, by dimension.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Cell {
    /// The open face (2-cell).
    Face(usize),
    /// The open arrangement edge (1-cell).
    Edge(usize),
    /// The arrangement vertex (0-cell).
    Vertex(usize),
}

impl Cell {
    fn describe(&self) -> String {
        match self {
            Cell::Face(f) => format!("2-cell (face) {f}"),
            Cell::Edge(e) => format!("1-cell (edge) {e}"),
            Cell::Vertex(v) => format!("0-cell (vertex) {v}"),
        }
    }
}

/// A skeleton for a violation's data: its origin (map point), vertex
/// offsets and number of artificial edges.
pub fn skeleton_json(map: &Map, origin: usize, key: &SkeletonKey) -> Value {
    let o = map.vertices()[origin];
    json!({
        "origin": [o.x.to_string(), o.y.to_string()],
        "offsets": key.offsets.iter().map(|(x, y)| [x.to_string(), y.to_string()]).collect::<Vec<_>>(),
        "artificial_edges": key.labels.iter().filter(|l| l.is_some()).count(),
    })
}

/// A fresh skeleton for a violation's data.
pub fn fresh_json(map: &Map, s: &FreshSkeleton) -> Value {
    match s {
        Ok(sk) => skeleton_json(map, sk.origin(), &sk.key(map)),
        Err(e) => json!({"error": e}),
    }
}

/// T3.3b on one cell: the cell is one instance, violated if the skeleton
/// of some point of `points` (computed afresh: [`Study::fresh_skeletons`])
/// is not `claimed` — the cell's skeleton `key` with its origin at map
/// vertex `claimed.0` — or cannot be built. A violation names the map, the
/// cell, the point (exact) and both skeletons.
pub fn check_cell_points(
    study: &Study<'_>,
    cell: Cell,
    claimed: (usize, &SkeletonKey),
    points: &[RatPoint],
) -> Report {
    let map = study.map();
    let name = sample::map_name(map);
    let mut report = Report::new(ID);
    let fresh = study.fresh_skeletons(points);
    let bad = points.iter().zip(&fresh).find(|(_, at)| match &***at {
        Ok(sk) => !sk.is(map, claimed.0, claimed.1),
        Err(_) => true,
    });
    report.record(bad.map(|(p, at)| {
        let kind = if at.is_err() {
            NO_SKELETON
        } else {
            SKELETON_DIFFERS
        };
        Violation::with_data(
            format!(
                "map {name}, {}: the point {p} has {}",
                cell.describe(),
                if kind == NO_SKELETON {
                    "no skeleton"
                } else {
                    "another skeleton than its cell's"
                }
            ),
            json!({
                "kind": kind,
                "map": name,
                "cell": cell.describe(),
                "point": p.to_string(),
                "point_file_units": sample::point_json(map, p),
                "skeleton": fresh_json(map, at),
                "cell_skeleton": skeleton_json(map, claimed.0, claimed.1),
            }),
        )
    }));
    report
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fixtures;
    use wai_study::fresh_skeleton;

    #[test]
    fn a_family_map_passes() {
        let map = wai_gen::family("corridor-niches", &[2]).unwrap();
        let r = CHECKER.run(&Study::new(&map));
        assert!(r.violations.is_empty(), "{:?}", r.violations);
        let case = |c: &str| r.cases.get(c).copied().unwrap_or(0);
        assert!(
            case(CELL_2) > 5 && case(CELL_1) > 0 && case(CELL_0) > 0,
            "{:?}",
            r.cases
        );
        assert_eq!(r.examined, case(CELL_2) + case(CELL_1) + case(CELL_0));
    }

    #[test]
    fn the_l_room_passes() {
        let r = CHECKER.run(&Study::new(&fixtures::l_room().0));
        assert!(r.violations.is_empty(), "{:?}", r.violations);
        assert_eq!(r.cases.get(CELL_2), Some(&5));
        assert!(
            r.cases.get(CELL_1).is_some_and(|&k| k >= 4),
            "{:?}",
            r.cases
        );
    }

    /// The doorway's segment breaks the sec. 3.6 reading (A3.6) but is a
    /// 1-cell with one skeleton: the restated claim holds there.
    #[test]
    fn the_doorway_passes_with_its_1_cell() {
        let s_tetromino = fixtures::s_tetromino();
        let a = crate::ch3::a3_6::CHECKER.run(&Study::new(&s_tetromino));
        assert!(a
            .cases
            .get(crate::ch3::a3_6::FAILS_1)
            .is_some_and(|&k| k > 0));
        let r = CHECKER.run(&Study::new(&s_tetromino));
        assert!(r.violations.is_empty(), "{:?}", r.violations);
        assert!(r.cases.get(CELL_1).is_some_and(|&k| k > 0), "{:?}", r.cases);
    }

    /// The cells of a map and two interior points of each.
    fn cells_of(study: &Study<'_>) -> Vec<(usize, [RatPoint; 2])> {
        let arr = study.arrangement();
        arr.cells()
            .map(|f| {
                let ring: Vec<RatPoint> = arr.face_points(f);
                (f, sample::simple_interior_points(&ring).unwrap())
            })
            .collect()
    }

    #[test]
    fn an_altered_cell_skeleton_is_reported() {
        let map = fixtures::l_room().0;
        let study = Study::new(&map);
        let cells = cells_of(&study);
        let (f, pts) = &cells[0];
        let sk = fresh_skeleton(study.index(), &pts[0]).unwrap();
        let key = sk.key(&map);
        let r = check_cell_points(&study, Cell::Face(*f), (sk.origin(), &key), &pts[1..]);
        assert_eq!((r.examined, r.violations.len()), (1, 0));
        let mut altered = key.clone();
        altered.offsets[0].0 += 1;
        let r = check_cell_points(&study, Cell::Face(*f), (sk.origin(), &altered), &pts[1..]);
        assert_eq!((r.examined, r.violations.len()), (1, 1));
        assert_eq!(r.violations[0].data["kind"], SKELETON_DIFFERS);
        assert_eq!(r.violations[0].data["cell"], Cell::Face(*f).describe());
    }

    #[test]
    fn a_point_of_another_cell_is_reported() {
        let map = fixtures::l_room().0;
        let study = Study::new(&map);
        let cells = cells_of(&study);
        let sk = fresh_skeleton(study.index(), &cells[0].1[0]).unwrap();
        let key = sk.key(&map);
        // Some other cell of the L room has another skeleton.
        let strangers: usize = cells[1..]
            .iter()
            .map(|(_, pts)| {
                check_cell_points(
                    &study,
                    Cell::Face(cells[0].0),
                    (sk.origin(), &key),
                    &pts[..1],
                )
                .violations
                .len()
            })
            .sum();
        assert!(strangers > 0);
        // A point outside the map has no skeleton.
        let outside = [RatPoint::from(wai_exact::Point::new(3, 3))];
        let r = check_cell_points(&study, Cell::Vertex(99), (sk.origin(), &key), &outside);
        assert_eq!(r.violations.len(), 1);
        assert_eq!(r.violations[0].data["kind"], NO_SKELETON);
    }
}
