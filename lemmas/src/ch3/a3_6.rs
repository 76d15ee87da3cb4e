//! Claim A3.6 (sec. 3.6, the boundary assignment): a point of a visibility
//! ray belongs to the cell on the side where the ray's anchor obstructs the
//! view of the vertex the ray emanates from, and then has that cell's
//! skeleton.
//!
//! The thesis states the rule just before Thm 3.3 and the theorem's part
//! (2) relies on it. It is **known to be false** in two configurations,
//! which is why T3.3b was restated for cells of every dimension
//! (`data/CLAIMS.md`):
//! - opposite collinear rays covering one segment (a doorway between
//!   collinear walls, `counterexamples/T3.3b-doorway-1d-cell.json`): the
//!   segment's points see neither anchor's hidden vertex, so their skeleton
//!   is no adjacent 2-cell's — a 1-cell of its own;
//! - rays crossing with no common side: the crossing point is hidden from
//!   the vertices of every ray through it — a 0-cell of its own.
//!
//! The checker therefore sorts every examined piece into one of: the rule
//! **holds** (the point has its assigned cell's skeleton); it **fails on a
//! 1-cell** or **fails on a 0-cell** (the known failures: the point's
//! skeleton is that of no adjacent 2-cell, so no assignment could be right;
//! or rays covering an edge point both ways with opposite sides, or the
//! rays through a vertex have no common side, so the rule gives the piece
//! no cell — `data["matches_adjacent_cell"]` / `["matches_incident_cell"]`
//! say whether some adjacent 2-cell has its skeleton all the same); or it fails in some **other** way
//! (the rule chose a cell, and the point has another adjacent 2-cell's
//! skeleton). Every failure is a
//! violation — the claim is exact and false — with `data["kind"]` one of
//! [`FAILS_ON_1_CELL`], [`FAILS_ON_0_CELL`], [`WRONG_CELL`] or
//! [`NO_SKELETON`]; only the last two are unexplained.
//!
//! ## Trust
//! Exhaustive over pieces, one exact point per piece. The decomposition is
//! the production one ([`wai_cells::visibility_rays`],
//! [`wai_cells::Arrangement::new`] and its
//! [`wai_cells::BoundaryAssignment`], which implements the rule, with the
//! nearest-anchor reading where collinear rays point one way); every
//! skeleton is computed afresh by a visibility query (the study's
//! [`Study::fresh_skeletons`], shared with T3.3b). Instances: one point
//! of every arrangement edge on a ray (the simplest rational point of the
//! open edge, [`super::t3_3b::edge_points`]; one instance per edge), every
//! arrangement vertex interior to the map. The skeleton of a 2-cell is
//! taken at one interior point (T3.3b checks that it is the skeleton of the
//! whole open cell). Skeletons are compared in map terms
//! ([`wai_visibility::MapSkeleton::same`]: same vertices and edge kinds,
//! artificial edges on one line). **Not covered:** points of ∂M (the thesis assumes viewpoints off
//! the boundary).
//!
//! ## Cases
//! Where the rule holds, by the part of it that decided: **one ray** (an
//! edge covered by one ray: its anchor's side), **collinear rays** (an edge
//! covered by several rays pointing one way: the nearest anchor behind it),
//! **vertex** (an interior vertex: the cell on the assigned side of every
//! ray through it); where it fails: **fails on 1-cell**, **fails on 0-cell**
//! (the known failures) and **wrong cell** (unexplained). Counts: `ray
//! edges` and `interior vertices` examined, `conflicts` (pieces the
//! assignment reports as a [`Conflict`]), `no skeleton`.

use serde_json::{json, Value};
use wai_cells::{Arrangement, Conflict, FaceId, Support};
use wai_exact::RatPoint;
use wai_map::Map;
use wai_visibility::MapSkeleton;

use std::rc::Rc;

use super::t3_3b::fresh_json;
use crate::framework::{Case, Checker, Known, Report, Violation};
use wai_study::sample;
use wai_study::FreshSkeleton;
use wai_study::Study;

const ID: &str = "A3.6";

/// The checker of this claim, with its two known failures.
pub const CHECKER: Checker = Checker::new(ID, check_study)
    .with_cases(&[
        Case {
            name: ONE_RAY,
            what: "the rule holds on an edge covered by one ray (its anchor's side, sec. 3.6)",
        },
        Case {
            name: COLLINEAR_RAYS,
            what: "the rule holds on an edge covered by collinear rays pointing one way (the \
                   nearest anchor behind it decides)",
        },
        Case {
            name: VERTEX,
            what: "the rule holds at an interior vertex (the cell on the assigned side of \
                   every ray through it)",
        },
        Case {
            name: FAILS_1,
            what: "an edge with the skeleton of no adjacent 2-cell, or rays pointing both ways \
                   along it: a 1-cell (known failure)",
        },
        Case {
            name: FAILS_0,
            what: "an interior vertex with the skeleton of no incident 2-cell, or rays with no \
                   common side: a 0-cell (known failure)",
        },
        Case {
            name: WRONG,
            what: "a piece with an adjacent 2-cell's skeleton that the rule did not choose",
        },
    ])
    .with_known(&[
        Known {
            kind: FAILS_ON_1_CELL,
            what: "a ray edge whose skeleton is no adjacent 2-cell's: a one-dimensional cell \
               (opposite collinear rays, counterexamples/T3.3b-doorway-1d-cell.json)",
        },
        Known {
            kind: FAILS_ON_0_CELL,
            what: "an interior vertex whose skeleton is no incident 2-cell's: a zero-dimensional \
               cell (rays crossing with no common side)",
        },
    ]);

/// `data["kind"]`: an edge whose skeleton is no adjacent 2-cell's (the
/// known failure: a one-dimensional cell).
pub const FAILS_ON_1_CELL: &str = "fails-on-1-cell";
/// `data["kind"]`: an interior vertex whose skeleton is no incident
/// 2-cell's (the known failure: a zero-dimensional cell).
pub const FAILS_ON_0_CELL: &str = "fails-on-0-cell";
/// `data["kind"]`: a piece with the skeleton of an adjacent 2-cell that the
/// rule did not choose (unexplained: a bug or a new finding).
pub const WRONG_CELL: &str = "wrong-cell";
/// `data["kind"]`: a point or cell whose skeleton cannot be built.
pub const NO_SKELETON: &str = "no-skeleton";

/// Case: the rule holds on an edge of one ray.
pub const ONE_RAY: &str = "one ray";
/// Case: the rule holds on an edge of collinear rays pointing one way.
pub const COLLINEAR_RAYS: &str = "collinear rays";
/// Case: the rule holds at an interior vertex.
pub const VERTEX: &str = "vertex";
/// Case: the known failure on a 1-cell.
pub const FAILS_1: &str = "fails on 1-cell";
/// Case: the known failure on a 0-cell.
pub const FAILS_0: &str = "fails on 0-cell";
/// Case: a piece given the wrong adjacent cell.
pub const WRONG: &str = "wrong cell";

/// Checks A3.6 on every ray piece and ray vertex of a map.
fn check_study(study: &Study<'_>) -> Report {
    check_arrangement(study, None)
}

/// The verdict on one piece, from its skeleton, its assigned cell's (`None`:
/// the rule gives it no cell) and those of the adjacent 2-cells.
///
/// A piece the rule gives no cell (rays through a vertex with no common
/// side) fails on a lower-dimensional cell whatever its skeleton: the rule
/// itself has no answer there. A piece given a cell whose skeleton it lacks
/// fails on a lower-dimensional cell if no adjacent 2-cell has its skeleton,
/// and is a [`WRONG_CELL`] otherwise.
fn verdict(
    map: &Map,
    at: &FreshSkeleton,
    owner: Option<&FreshSkeleton>,
    adjacent: &[&FreshSkeleton],
    lower_dim_kind: &'static str,
) -> Option<&'static str> {
    let Ok(at) = at else {
        return Some(NO_SKELETON);
    };
    if owner.is_some_and(|o| o.is_err()) || adjacent.iter().any(|a| a.is_err()) {
        return Some(NO_SKELETON);
    }
    let same = |s: &FreshSkeleton| s.as_ref().is_ok_and(|s| s.same(map, at));
    match owner {
        Some(o) if same(o) => None,
        Some(_) if adjacent.iter().any(|a| same(a)) => Some(WRONG_CELL),
        _ => Some(lower_dim_kind),
    }
}

/// Whether two fresh skeletons are one skeleton in one embedding.
fn same_skeleton(map: &Map, a: &FreshSkeleton, b: &FreshSkeleton) -> bool {
    matches!((a, b), (Ok(a), Ok(b)) if a.same(map, b))
}

/// The check on a built arrangement. `plant` replaces the skeleton of
/// one cell, for the planted-violation test.
fn check_arrangement(study: &Study<'_>, plant: Option<(FaceId, MapSkeleton)>) -> Report {
    let (map, arr) = (study.map(), study.arrangement());
    let at = |p: &RatPoint| -> Rc<FreshSkeleton> {
        Rc::clone(&study.fresh_skeletons(std::slice::from_ref(p))[0])
    };
    let name = sample::map_name(map);
    let mut report = Report::new(ID);
    // The skeleton of each cell, at an interior point.
    let outer: Rc<FreshSkeleton> = Rc::new(Err("the outer face".into()));
    let mut cell: Vec<Rc<FreshSkeleton>> = vec![outer; arr.face_count()];
    for f in arr.cells() {
        // T3.3b's sample points of the cell (the first, the same as
        // `sample::simple_interior_point`), shared through the study.
        cell[f] = match study.cell_sample_points(f).first() {
            Some(p) => at(p),
            None => Rc::new(Err(format!("cell {f} has no interior point"))),
        };
    }
    if let Some((f, e)) = plant {
        cell[f] = Rc::new(Ok(e));
    }
    // Per edge: whether the rule reports a conflict there, and whether
    // its rays point both ways (a doorway), where the rule has no answer.
    let mut conflict_at: Vec<Option<bool>> = vec![None; arr.edge_count()];
    for c in arr.conflicts() {
        if let Conflict::Edge {
            edge, both_ways, ..
        } = c
        {
            conflict_at[*edge] = Some(*both_ways);
        }
    }
    for (e, &conflict_here) in conflict_at.iter().enumerate() {
        if !matches!(arr.edge_support(e), Support::Rays(_)) {
            continue;
        }
        let (a, b) = (arr.half_edge(2 * e).origin, arr.dest(2 * e));
        let p = study.edge_sample_point(e);
        let (f0, f1) = (arr.half_edge(2 * e).face, arr.half_edge(2 * e + 1).face);
        let owner = arr.owner_of_edge(e);
        let at = at(&p);
        let conflict = conflict_here.is_some();
        report.count("ray edges", 1);
        report.count("conflicts", u64::from(conflict));
        // Rays pointing both ways along the edge with opposite sides
        // (a doorway): the rule has no answer, whatever the skeleton.
        let both_ways = conflict_here == Some(true);
        let v = verdict(
            map,
            &at,
            (!both_ways).then_some(&*cell[owner]),
            &[&*cell[f0], &*cell[f1]],
            FAILS_ON_1_CELL,
        );
        let holds = if arr.edge_rays(e).len() > 1 {
            COLLINEAR_RAYS
        } else {
            ONE_RAY
        };
        count(&mut report, v, holds);
        report.record(v.map(|kind| {
            Violation::with_data(
                format!(
                    "{kind}: map {name}, edge {e} ({p}): the rule assigns it to cell \
                     {owner}, whose skeleton it does not have"
                ),
                json!({
                    "kind": kind, "map": name, "edge": e, "point": p.to_string(),
                    "point_file_units": sample::point_json(map, &p),
                    "edge_ends": [arr.point(a).to_string(), arr.point(b).to_string()],
                    "rays": rays_json(arr, arr.edge_rays(e)),
                    "conflict": conflict, "rays_point_both_ways": both_ways,
                    "owner": owner, "cells": [f0, f1],
                    "matches_adjacent_cell": same_skeleton(map, &at, &cell[f0])
                        || same_skeleton(map, &at, &cell[f1]),
                    "skeleton": fresh_json(map, &at),
                    "owner_skeleton": fresh_json(map, &cell[owner]),
                }),
            )
        }));
    }
    for v in 0..arr.vertex_count() {
        if arr.is_on_map_boundary(v) {
            continue;
        }
        let p = arr.point(v).clone();
        let incident = arr.faces_around(v);
        let owner = arr.owner_of_vertex(v);
        let at = at(&p);
        let adjacent: Vec<&FreshSkeleton> = incident.iter().map(|&f| &*cell[f]).collect();
        report.count("interior vertices", 1);
        report.count("conflicts", u64::from(owner.is_none()));
        let verdict = verdict(
            map,
            &at,
            owner.map(|f| &*cell[f]),
            &adjacent,
            FAILS_ON_0_CELL,
        );
        count(&mut report, verdict, VERTEX);
        report.record(verdict.map(|kind| {
            Violation::with_data(
                format!(
                    "{kind}: map {name}, vertex {v} ({p}): the rule assigns it to {}, \
                     whose skeleton it does not have",
                    owner.map_or("no cell".into(), |f| format!("cell {f}"))
                ),
                json!({
                    "kind": kind, "map": name, "vertex": v, "point": p.to_string(),
                    "point_file_units": sample::point_json(map, &p),
                    "owner": owner, "cells": incident,
                    "matches_incident_cell": adjacent.iter().any(|a| same_skeleton(map, &at, a)),
                    "skeleton": fresh_json(map, &at),
                }),
            )
        }));
    }
    report
}

/// Counts a verdict: `holds` is the case of a piece where the rule holds.
fn count(report: &mut Report, v: Option<&str>, holds: &'static str) {
    match v {
        None => report.hit(holds),
        Some(FAILS_ON_1_CELL) => report.hit(FAILS_1),
        Some(FAILS_ON_0_CELL) => report.hit(FAILS_0),
        Some(WRONG_CELL) => report.hit(WRONG),
        Some(_) => report.count("no skeleton", 1),
    }
}

fn rays_json(arr: &Arrangement, rays: &[usize]) -> Vec<Value> {
    rays.iter()
        .map(|&r| {
            let ray = &arr.rays()[r];
            json!({"ray": r, "anchor": ray.anchor, "from": ray.from,
                   "side": format!("{:?}", ray.side)})
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fixtures;

    fn case(r: &Report, c: &str) -> u64 {
        r.cases.get(c).copied().unwrap_or(0)
    }

    #[test]
    fn the_rule_holds_in_the_l_room() {
        let r = CHECKER.run(&Study::new(&fixtures::l_room().0));
        assert!(r.violations.is_empty(), "{:?}", r.violations);
        let count = |c: &str| r.counts.get(c).copied().unwrap_or(0);
        let (edges, vertices) = (count("ray edges"), count("interior vertices"));
        assert_eq!(r.examined, edges + vertices);
        let holds = case(&r, ONE_RAY) + case(&r, COLLINEAR_RAYS) + case(&r, VERTEX);
        assert!(edges >= 4 && holds == r.examined, "{:?}", r.cases);
    }

    /// The known failure: the doorway's segment is a 1-cell.
    #[test]
    fn the_doorway_fails_on_a_1_cell() {
        let r = CHECKER.run(&Study::new(&fixtures::s_tetromino()));
        assert!(case(&r, FAILS_1) >= 1, "{:?}", r.cases);
        assert_eq!(case(&r, WRONG), 0, "{:?}", r.cases);
        assert!(!r.counts.contains_key("no skeleton"), "{:?}", r.counts);
        assert!(r.violations.iter().all(|v| CHECKER.is_known(v)));
    }

    /// A planted wrong skeleton for one cell makes the pieces it owns fail.
    #[test]
    fn a_planted_cell_skeleton_is_reported() {
        let map = fixtures::l_room().0;
        let study = Study::new(&map);
        let arr = study.arrangement();
        let f = (0..arr.edge_count())
            .find(|&e| matches!(arr.edge_support(e), Support::Rays(_)))
            .map(|e| arr.owner_of_edge(e))
            .unwrap();
        let ring: Vec<RatPoint> = arr.face_points(f);
        let p = sample::simple_interior_point(&ring).unwrap();
        let mut sk = wai_study::fresh_skeleton(study.index(), &p).unwrap();
        // Another skeleton: one more vertex.
        sk.vertices.push(sk.vertices[0]);
        sk.edges.push(sk.edges[0]);
        let r = check_arrangement(&study, Some((f, sk)));
        assert!(!r.violations.is_empty());
        assert!(
            case(&r, FAILS_1) + case(&r, FAILS_0) + case(&r, WRONG) > 0,
            "{:?}",
            r.cases
        );
    }
}
