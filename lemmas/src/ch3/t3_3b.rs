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
//! computed afresh by [`wai_visibility::VisibilityIndex`] and
//! [`wai_visibility::Skeleton::of`] and compared with its cell's, one
//! instance per cell:
//! - a 2-cell: two interior points (the centroid of a strict corner and its
//!   neighbours, and the point a quarter of the way from it to the opposite
//!   vertex);
//! - a 1-cell (an arrangement edge on a ray; edges on ∂M are not interior):
//!   the points at 1/4, 1/2 and 3/4 of it;
//! - a 0-cell (an arrangement vertex off ∂M): the vertex.
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
use wai_cells::LowerSite;
use wai_exact::{orientation_rat, Orientation, Point, RatPoint};
use wai_map::Map;
use wai_visibility::{Skeleton, SkeletonKey, VisibilityIndex};

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
    let arr = study.arrangement();
    let name = sample::map_name(map);
    let mut report = Report::new(ID);
    if let Err(e) = arr.sanity_check() {
        report.record(Some(Violation::with_data(
            format!("map {name}: the arrangement fails its sanity check: {e}"),
            json!({"map": name, "kind": NO_SKELETON, "sanity_check": e}),
        )));
        return report;
    }
    let index = study.index();
    // The cells' skeletons as the decomposition computes them (by its
    // walk, sec. 3.9.2): every sample is checked against them.
    let d = study.decomposition();
    let embedded = |origin: usize, class: usize| -> Result<Embedded, String> {
        Ok((map.vertices()[origin], d.skeletons()[class].clone()))
    };
    let arr = d.arrangement();
    for f in arr.cells() {
        let ring: Vec<RatPoint> = arr.face_points(f);
        report.hit(CELL_2);
        let Some(points) = interior_points(&ring) else {
            report.record(Some(Violation::with_data(
                format!("map {name}, cell {f}: no strict corner, no interior point"),
                json!({"map": name, "kind": NO_SKELETON, "cell": f,
                       "cell_vertices": ring.iter().map(ToString::to_string).collect::<Vec<_>>()}),
            )));
            continue;
        };
        let claimed = embedded(d.origin_of(f), d.skeleton_of(f));
        report.absorb(check_cell_points(
            map,
            index,
            Cell::Face(f),
            &claimed,
            &points,
        ));
    }
    for c in d.lower_cells() {
        let claimed = embedded(c.origin, c.class);
        let (cell, points) = match c.site {
            LowerSite::Edge(e) => {
                report.hit(CELL_1);
                let (a, b) = (
                    arr.point(arr.half_edge(2 * e).origin),
                    arr.point(arr.dest(2 * e)),
                );
                let mid = RatPoint::midpoint(a, b);
                let points = vec![
                    RatPoint::midpoint(a, &mid),
                    mid.clone(),
                    RatPoint::midpoint(&mid, b),
                ];
                (Cell::Edge(e), points)
            }
            LowerSite::Vertex(v) => {
                report.hit(CELL_0);
                (Cell::Vertex(v), vec![arr.point(v).clone()])
            }
        };
        report.absorb(check_cell_points(map, index, cell, &claimed, &points));
    }
    report
}

/// A skeleton in its embedding: the origin v0 (a map point) and the key.
pub type Embedded = (Point, SkeletonKey);

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

/// V*_p at `p` in its embedding, or why it cannot be built.
pub fn skeleton_at(index: &VisibilityIndex<'_>, p: &RatPoint) -> Result<Embedded, String> {
    let vp = index
        .visibility_polygon(p)
        .map_err(|e| format!("V_p: {e}"))?;
    let sk = Skeleton::of(index.map(), &vp).map_err(|e| format!("V*_p: {e}"))?;
    Ok((sk.origin(), sk.key()))
}

pub fn embedded_json(s: &Result<Embedded, String>) -> Value {
    match s {
        Ok((o, key)) => json!({
            "origin": [o.x.to_string(), o.y.to_string()],
            "offsets": key.offsets.iter().map(|(x, y)| [x.to_string(), y.to_string()]).collect::<Vec<_>>(),
            "artificial_edges": key.labels.iter().filter(|l| l.is_some()).count(),
        }),
        Err(e) => json!({"error": e}),
    }
}

/// `Σ w_i p_i / Σ w_i`, exactly.
fn combine(parts: &[(&RatPoint, u32)]) -> RatPoint {
    use rug::Integer;
    let mut w = Integer::from(1);
    for (p, _) in parts {
        w *= p.hw();
    }
    let total: u32 = parts.iter().map(|&(_, k)| k).sum();
    let (mut x, mut y) = (Integer::new(), Integer::new());
    for &(p, k) in parts {
        let scale = Integer::from(&w / p.hw()) * k;
        x += Integer::from(p.hx() * &scale);
        y += Integer::from(p.hy() * &scale);
    }
    RatPoint::new(x, y, w * total).expect("a positive denominator")
}

/// Two interior points of a convex cell with vertices `ring`
/// (counter-clockwise): the centroid of a strict corner and its two
/// neighbours, and the point a quarter of the way from it to the vertex
/// opposite the corner. `None` if no three consecutive vertices turn.
pub fn interior_points(ring: &[RatPoint]) -> Option<[RatPoint; 2]> {
    let k = ring.len();
    let i = (0..k).find(|&i| {
        orientation_rat(&ring[(i + k - 1) % k], &ring[i], &ring[(i + 1) % k])
            == Orientation::CounterClockwise
    })?;
    let c = combine(&[
        (&ring[(i + k - 1) % k], 1),
        (&ring[i], 1),
        (&ring[(i + 1) % k], 1),
    ]);
    let q = combine(&[(&c, 3), (&ring[(i + k / 2) % k], 1)]);
    Some([c, q])
}

/// T3.3b on one cell: the cell is one instance, violated if the skeleton
/// of some point of `points` (computed afresh through `index`) differs from
/// `claimed`, the cell's skeleton, or if a skeleton cannot be built. A violation names the map, the cell, the point (exact,
/// and in file units) and both skeletons.
pub fn check_cell_points(
    map: &Map,
    index: &VisibilityIndex<'_>,
    cell: Cell,
    claimed: &Result<Embedded, String>,
    points: &[RatPoint],
) -> Report {
    let name = sample::map_name(map);
    let mut report = Report::new(ID);
    let bad = std::iter::once(None)
        .chain(points.iter().map(Some))
        .find_map(|p| {
            let at = match p {
                None if claimed.is_err() => claimed.clone(),
                None => return None,
                Some(p) => skeleton_at(index, p),
            };
            (at.is_err() || at != *claimed).then_some((p, at))
        });
    report.record(bad.map(|(p, at)| {
        let kind = if at.is_err() || claimed.is_err() {
            NO_SKELETON
        } else {
            SKELETON_DIFFERS
        };
        let p = p.map_or("the cell".to_owned(), ToString::to_string);
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
                "point": p,
                "skeleton": embedded_json(&at),
                "cell_skeleton": embedded_json(claimed),
            }),
        )
    }));
    report
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fixtures;

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

    /// The L room's cells and two interior points of each.
    fn cells_of(map: &Map) -> (VisibilityIndex<'_>, Vec<(usize, [RatPoint; 2])>) {
        let arr = wai_cells::Arrangement::new(map, &wai_cells::visibility_rays(map));
        let cells = arr
            .cells()
            .map(|f| {
                let ring: Vec<RatPoint> = arr.face_points(f);
                (f, interior_points(&ring).unwrap())
            })
            .collect();
        (VisibilityIndex::new(map), cells)
    }

    #[test]
    fn an_altered_cell_skeleton_is_reported() {
        let map = fixtures::l_room().0;
        let (index, cells) = cells_of(&map);
        let (f, pts) = &cells[0];
        let claimed = skeleton_at(&index, &pts[0]);
        let r = check_cell_points(&map, &index, Cell::Face(*f), &claimed, &pts[1..]);
        assert_eq!((r.examined, r.violations.len()), (1, 0));
        let (o, mut key) = claimed.unwrap();
        key.offsets[0].0 += 1;
        let r = check_cell_points(&map, &index, Cell::Face(*f), &Ok((o, key)), &pts[1..]);
        assert_eq!((r.examined, r.violations.len()), (1, 1));
        assert_eq!(r.violations[0].data["kind"], SKELETON_DIFFERS);
        assert_eq!(r.violations[0].data["cell"], Cell::Face(*f).describe());
    }

    #[test]
    fn a_point_of_another_cell_is_reported() {
        let map = fixtures::l_room().0;
        let (index, cells) = cells_of(&map);
        let claimed = skeleton_at(&index, &cells[0].1[0]);
        // Some other cell of the L room has another skeleton.
        let strangers: usize = cells[1..]
            .iter()
            .map(|(_, pts)| {
                check_cell_points(&map, &index, Cell::Face(cells[0].0), &claimed, &pts[..1])
                    .violations
                    .len()
            })
            .sum();
        assert!(strangers > 0);
        // A point outside the map has no skeleton.
        let outside = [RatPoint::from(Point::new(3, 3))];
        let r = check_cell_points(&map, &index, Cell::Vertex(99), &claimed, &outside);
        assert_eq!(r.violations.len(), 1);
        assert_eq!(r.violations[0].data["kind"], NO_SKELETON);
    }

    #[test]
    fn interior_points_are_strictly_inside() {
        let ring: Vec<RatPoint> = [(0, 0), (3, 0), (6, 0), (6, 3), (0, 3)]
            .iter()
            .map(|&(x, y)| RatPoint::from(Point::new(x, y)))
            .collect();
        let [a, b] = interior_points(&ring).unwrap();
        assert_ne!(a, b);
        let box_ring: Vec<Point> = [(0, 0), (6, 0), (6, 3), (0, 3)]
            .iter()
            .map(|&(x, y)| Point::new(x, y))
            .collect();
        for p in [a, b] {
            assert_eq!(
                wai_exact::locate_rat(&box_ring, &p),
                wai_exact::Containment::Inside
            );
        }
    }
}
