//! Claim A3.6 (sec. 3.6, the boundary assignment): a point of a visibility
//! ray belongs to the cell on the side where the ray's anchor obstructs the
//! view of the vertex the ray emanates from, and then has that cell's
//! skeleton.
//!
//! The thesis states the rule just before Thm 3.3 and the theorem's part
//! (2) relies on it. It is **known to be false** in two configurations,
//! which is why T3.3b was restated for cells of every dimension
//! (`shared/CLAIMS.md`, DESIGN "Degenerate cases that matter"):
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
//! skeleton is computed afresh by [`wai_visibility::VisibilityIndex`] and
//! [`wai_visibility::Skeleton::of`]. Instances: the midpoint of every
//! arrangement edge on a ray (one instance per edge), every arrangement
//! vertex interior to the map. The skeleton of a 2-cell is taken at one
//! interior point (T3.3b checks that it is the skeleton of the whole open
//! cell). **Not covered:** points of ∂M (the thesis assumes viewpoints off
//! the boundary).

use serde_json::{json, Value};
use wai_cells::{Arrangement, Conflict, FaceId, Support};
use wai_exact::RatPoint;
use wai_map::Map;
use wai_visibility::VisibilityIndex;

use super::t3_3b::{embedded_json, interior_points, skeleton_at, Embedded};
use crate::framework::{Checker, Known, Report, Violation};
use wai_study::sample;
use wai_study::Study;

const ID: &str = "A3.6";

/// The checker of this claim, with its two known failures.
pub const CHECKER: Checker = Checker::new(ID, check_study).with_known(&[
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

/// How the examined pieces of one map (or a run) came out.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Tally {
    /// Ray edges examined.
    pub edges: u64,
    /// Interior vertices examined.
    pub vertices: u64,
    /// Pieces with the skeleton of their assigned cell.
    pub holds: u64,
    /// Edges with the skeleton of no adjacent 2-cell.
    pub fails_on_1_cell: u64,
    /// Vertices with the skeleton of no incident 2-cell.
    pub fails_on_0_cell: u64,
    /// Pieces with an adjacent 2-cell's skeleton, not the assigned one's.
    pub wrong_cell: u64,
    /// Pieces or cells without a skeleton.
    pub no_skeleton: u64,
    /// Pieces the assignment reports as a [`Conflict`].
    pub conflicts: u64,
}

/// Checks A3.6 on every ray piece and ray vertex of a map.
fn check_study(study: &Study<'_>) -> Report {
    check_with_tally(study).0
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
    at: &Result<Embedded, String>,
    owner: Option<&Result<Embedded, String>>,
    adjacent: &[&Result<Embedded, String>],
    lower_dim_kind: &'static str,
) -> Option<&'static str> {
    if at.is_err() || owner.is_some_and(|o| o.is_err()) || adjacent.iter().any(|a| a.is_err()) {
        return Some(NO_SKELETON);
    }
    match owner {
        Some(o) if o == at => None,
        Some(_) if adjacent.contains(&at) => Some(WRONG_CELL),
        _ => Some(lower_dim_kind),
    }
}

/// [`Checker::check`] with the tally of outcomes.
pub fn check_with_tally(study: &Study<'_>) -> (Report, Tally) {
    check_arrangement(study.map(), study.arrangement(), study.index(), None)
}

/// The check on a built arrangement. `plant` replaces the skeleton of
/// one cell, for the planted-violation test.
fn check_arrangement(
    map: &Map,
    arr: &Arrangement,
    index: &VisibilityIndex<'_>,
    plant: Option<(FaceId, Embedded)>,
) -> (Report, Tally) {
    let name = sample::map_name(map);
    let mut report = Report::new(ID);
    let mut tally = Tally::default();
    // The skeleton of each cell, at an interior point.
    let mut cell: Vec<Result<Embedded, String>> =
        vec![Err("the outer face".into()); arr.face_count()];
    for f in arr.cells() {
        let ring: Vec<RatPoint> = arr.face_points(f);
        cell[f] = match interior_points(&ring) {
            Some([p, _]) => skeleton_at(index, &p),
            None => Err(format!("cell {f} has no strict corner")),
        };
    }
    if let Some((f, e)) = plant {
        cell[f] = Ok(e);
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
        let p = RatPoint::midpoint(arr.point(a), arr.point(b));
        let (f0, f1) = (arr.half_edge(2 * e).face, arr.half_edge(2 * e + 1).face);
        let owner = arr.owner_of_edge(e);
        let at = skeleton_at(index, &p);
        let conflict = conflict_here.is_some();
        tally.edges += 1;
        tally.conflicts += u64::from(conflict);
        // Rays pointing both ways along the edge with opposite sides
        // (a doorway): the rule has no answer, whatever the skeleton.
        let both_ways = conflict_here == Some(true);
        let v = verdict(
            &at,
            (!both_ways).then_some(&cell[owner]),
            &[&cell[f0], &cell[f1]],
            FAILS_ON_1_CELL,
        );
        count(&mut tally, v);
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
                    "matches_adjacent_cell": at.is_ok() && (cell[f0] == at || cell[f1] == at),
                    "skeleton": embedded_json(&at),
                    "owner_skeleton": embedded_json(&cell[owner]),
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
        let at = skeleton_at(index, &p);
        let adjacent: Vec<&Result<Embedded, String>> = incident.iter().map(|&f| &cell[f]).collect();
        tally.vertices += 1;
        tally.conflicts += u64::from(owner.is_none());
        let verdict = verdict(&at, owner.map(|f| &cell[f]), &adjacent, FAILS_ON_0_CELL);
        count(&mut tally, verdict);
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
                    "matches_incident_cell": adjacent.iter().any(|a| at.is_ok() && **a == at),
                    "skeleton": embedded_json(&at),
                }),
            )
        }));
    }
    (report, tally)
}

fn count(t: &mut Tally, v: Option<&str>) {
    match v {
        None => t.holds += 1,
        Some(FAILS_ON_1_CELL) => t.fails_on_1_cell += 1,
        Some(FAILS_ON_0_CELL) => t.fails_on_0_cell += 1,
        Some(WRONG_CELL) => t.wrong_cell += 1,
        Some(_) => t.no_skeleton += 1,
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

    #[test]
    fn the_rule_holds_in_the_l_room() {
        let (r, t) = check_with_tally(&Study::new(&fixtures::l_room().0));
        assert!(r.violations.is_empty(), "{:?}", r.violations);
        assert_eq!(r.examined, t.edges + t.vertices);
        assert!(t.edges >= 4 && t.holds == r.examined, "{t:?}");
    }

    /// The known failure: the doorway's segment is a 1-cell.
    #[test]
    fn the_doorway_fails_on_a_1_cell() {
        let (r, t) = check_with_tally(&Study::new(&fixtures::s_tetromino()));
        assert!(t.fails_on_1_cell >= 1, "{t:?}");
        assert_eq!((t.wrong_cell, t.no_skeleton), (0, 0), "{t:?}");
        assert!(r.violations.iter().all(|v| CHECKER.is_known(v)));
    }

    /// A planted wrong skeleton for one cell makes the pieces it owns fail.
    #[test]
    fn a_planted_cell_skeleton_is_reported() {
        let map = fixtures::l_room().0;
        let arr = Arrangement::new(&map, &wai_cells::visibility_rays(&map));
        let index = VisibilityIndex::new(&map);
        let f = (0..arr.edge_count())
            .find(|&e| matches!(arr.edge_support(e), Support::Rays(_)))
            .map(|e| arr.owner_of_edge(e))
            .unwrap();
        let ring: Vec<RatPoint> = arr.face_points(f);
        let (o, mut key) = skeleton_at(&index, &interior_points(&ring).unwrap()[0]).unwrap();
        key.offsets[0].0 += 1;
        let (r, t) = check_arrangement(&map, &arr, &index, Some((f, (o, key))));
        assert!(!r.violations.is_empty());
        assert!(
            t.fails_on_1_cell + t.fails_on_0_cell + t.wrong_cell > 0,
            "{t:?}"
        );
    }
}
