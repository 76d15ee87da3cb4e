//! Claim T3.3b (Theorem 3.3(2)): all points of a visibility cell have the
//! same visibility skeleton — the points of its interior, and the boundary
//! points (on visibility rays) that the assignment rule of sec. 3.6 gives
//! it: a point on the ray emanating from v and anchored at v_r belongs to
//! the cell on the side where v_r's obstruction lies, where v is hidden.
//!
//! ## Trust
//! Exhaustive over cells and their assigned boundary pieces, sampled within
//! each piece; every comparison is exact. The checker builds the
//! decomposition with the production code ([`wai_cells::visibility_rays`],
//! [`wai_cells::Arrangement::new`], its [`wai_cells::BoundaryAssignment`])
//! and, for **every** cell, computes V*_p independently — V_p by
//! [`wai_visibility::VisibilityIndex`], then [`wai_visibility::Skeleton::of`]
//! — at exact points, each one instance:
//! - two interior points: the centroid of three consecutive vertices of a
//!   strict corner (the cell's skeleton, the reference), and the point a
//!   quarter of the way from it to the opposite vertex;
//! - the midpoint of every edge the assignment gives the cell that lies on
//!   a ray;
//! - every arrangement vertex the assignment gives the cell that is
//!   interior to the map.
//!
//! Two skeletons are equal when their origins v0 (map points) and their
//! canonical keys are: the same skeleton in the same embedding. A point
//! whose V_p or V*_p cannot be built is a violation.
//!
//! **Not covered:** boundary pieces on ∂M (map edges, ray ends, anchors,
//! grazed map vertices): the thesis assumes viewpoints off ∂M and
//! `wai-visibility` does not support them. Within an edge only the midpoint
//! is examined; the theorem's proof (a segment inside a convex cell that no
//! ray crosses) makes every point of an edge's relative interior equivalent.
//!
//! **Assignment conflicts** ([`wai_cells::Conflict`]): where collinear rays
//! covering one edge assign it to different sides, or the rays through a
//! vertex leave it to no common cell, the rule of sec. 3.6 does not give
//! the piece a cell. Such pieces are examined too (same points: the edge's
//! midpoint, the vertex) and **every one** is reported as a violation of
//! the separate kind `assignment-conflict` (`data["kind"]`), saying whether
//! the point's skeleton matches the owner chosen by `wai-cells`, the cell
//! on the other side, both or neither — so a run shows them. Ordinary
//! violations have `data["kind"] == "skeleton-differs"` (or
//! `"no-skeleton"`).

use serde_json::{json, Value};
use wai_cells::{visibility_rays, Arrangement, Conflict, FaceId, Support};
use wai_exact::{orientation_rat, Orientation, Point, RatPoint};
use wai_map::Map;
use wai_visibility::{Skeleton, SkeletonKey, VisibilityIndex};

use crate::driver::{Checker, Report, Violation};
use crate::sample;

const ID: &str = "T3.3b";

/// The `data["kind"]` of a violation on a piece two rays assign to
/// different cells.
pub const ASSIGNMENT_CONFLICT: &str = "assignment-conflict";
/// The `data["kind"]` of an ordinary violation: a point with a skeleton
/// other than its cell's.
pub const SKELETON_DIFFERS: &str = "skeleton-differs";
/// The `data["kind"]` of a point whose V_p or V*_p cannot be built.
pub const NO_SKELETON: &str = "no-skeleton";

/// Checks T3.3b on every cell of a map.
#[derive(Debug, Clone, Copy, Default)]
pub struct SameSkeleton;

/// The registry's constructor.
pub fn checker() -> Box<dyn Checker> {
    Box::new(SameSkeleton)
}

/// What one map contributed, beyond the report.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Stats {
    /// Cells examined.
    pub cells: u64,
    /// Interior points examined.
    pub interior: u64,
    /// Midpoints of assigned ray edges examined.
    pub edges: u64,
    /// Assigned interior vertices examined.
    pub vertices: u64,
    /// Conflicting edges examined, by what the midpoint's skeleton matched.
    pub conflict_edges: ConflictTally,
    /// Conflicting vertices examined (interior to the map), by match.
    pub conflict_vertices: ConflictTally,
}

/// How often a conflicting piece's skeleton matched the chosen owner only,
/// the other side only, both, or neither.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ConflictTally {
    pub owner: u64,
    pub other: u64,
    pub both: u64,
    pub neither: u64,
    /// Conflicting vertices on ∂M (not examinable).
    pub on_boundary: u64,
}

impl ConflictTally {
    fn add(&mut self, m: &str) {
        match m {
            "owner" => self.owner += 1,
            "other" => self.other += 1,
            "both" => self.both += 1,
            "on-boundary" => self.on_boundary += 1,
            _ => self.neither += 1,
        }
    }
}

impl Checker for SameSkeleton {
    fn id(&self) -> &'static str {
        ID
    }

    fn check(&self, map: &Map) -> Report {
        self.check_with_stats(map).0
    }
}

/// A skeleton in its embedding: the origin v0 (a map point) and the key.
pub type Embedded = (Point, SkeletonKey);

/// Where an examined point lies in its cell.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Site {
    /// In the cell's interior.
    Interior,
    /// The midpoint of edge `e`, assigned to the cell.
    Edge(usize),
    /// Vertex `v`, assigned to the cell.
    Vertex(usize),
}

impl Site {
    fn describe(&self) -> String {
        match self {
            Site::Interior => "interior point".into(),
            Site::Edge(e) => format!("midpoint of edge {e}"),
            Site::Vertex(v) => format!("vertex {v}"),
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

fn embedded_json(s: &Result<Embedded, String>) -> Value {
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

impl SameSkeleton {
    /// [`Checker::check`] with the counts of each kind of point.
    pub fn check_with_stats(&self, map: &Map) -> (Report, Stats) {
        let arr = Arrangement::new(map, &visibility_rays(map));
        let name = sample::map_name(map);
        let mut report = Report::new(ID);
        let mut stats = Stats::default();
        if let Err(e) = arr.sanity_check() {
            report.record(Some(Violation::with_data(
                format!("map {name}: the arrangement fails its sanity check: {e}"),
                json!({"map": name, "kind": NO_SKELETON, "sanity_check": e}),
            )));
            return (report, stats);
        }
        let index = VisibilityIndex::new(map);
        let conflicted: Vec<usize> = arr
            .conflicts()
            .iter()
            .filter_map(|c| match c {
                Conflict::Edge { edge, .. } => Some(*edge),
                Conflict::Vertex { .. } => None,
            })
            .collect();
        // The skeleton of each cell, at its first interior point.
        let mut cell_skeleton: Vec<Option<Result<Embedded, String>>> = vec![None; arr.face_count()];
        for f in arr.cells() {
            let ring: Vec<RatPoint> = arr
                .face_vertices(f)
                .into_iter()
                .map(|v| arr.point(v).clone())
                .collect();
            let mut points: Vec<(Site, RatPoint)> = Vec::new();
            match interior_points(&ring) {
                Some([a, b]) => {
                    points.push((Site::Interior, a));
                    points.push((Site::Interior, b));
                }
                None => {
                    report.record(Some(Violation::with_data(
                        format!("map {name}, cell {f}: no strict corner, no interior point"),
                        json!({"map": name, "kind": NO_SKELETON, "cell": f,
                               "cell_vertices": ring.iter().map(ToString::to_string).collect::<Vec<_>>()}),
                    )));
                    continue;
                }
            }
            for h in arr.face_half_edges(f) {
                let e = h / 2;
                if matches!(arr.edge_support(e), Support::Rays(_))
                    && arr.owner_of_edge(e) == f
                    && !conflicted.contains(&e)
                {
                    let (a, b) = (arr.half_edge(h).origin, arr.dest(h));
                    points.push((
                        Site::Edge(e),
                        RatPoint::midpoint(arr.point(a), arr.point(b)),
                    ));
                }
                let v = arr.half_edge(h).origin;
                if arr.owner_of_vertex(v) == Some(f) && !arr.is_on_map_boundary(v) {
                    points.push((Site::Vertex(v), arr.point(v).clone()));
                }
            }
            let claimed = skeleton_at(&index, &points[0].1);
            stats.cells += 1;
            for (site, _) in &points {
                match site {
                    Site::Interior => stats.interior += 1,
                    Site::Edge(_) => stats.edges += 1,
                    Site::Vertex(_) => stats.vertices += 1,
                }
            }
            let r = check_cell_points(map, &index, f, &claimed, &points);
            report.examined += r.examined;
            report.violations.extend(r.violations);
            cell_skeleton[f] = Some(claimed);
        }
        // The conflicts: examined, and every one reported.
        let cell_of = |f: FaceId| cell_skeleton.get(f).cloned().flatten();
        for c in arr.conflicts() {
            match c {
                Conflict::Edge {
                    edge,
                    left,
                    right,
                    owner,
                } => {
                    let (f0, f1) = (
                        arr.half_edge(2 * edge).face,
                        arr.half_edge(2 * edge + 1).face,
                    );
                    let other = if *owner == f0 { f1 } else { f0 };
                    let (a, b) = (arr.half_edge(2 * edge).origin, arr.dest(2 * edge));
                    let p = RatPoint::midpoint(arr.point(a), arr.point(b));
                    let at = skeleton_at(&index, &p);
                    let m = matches(&at, cell_of(*owner).as_ref(), cell_of(other).as_ref());
                    stats.conflict_edges.add(m);
                    // Whether the rays covering the edge point both ways
                    // along it (a "doorway" between two anchors) or one way
                    // (one ray runs on through another's anchor).
                    let d = arr.direction(2 * edge);
                    let forward = |r: usize| {
                        let ray = &arr.rays()[r];
                        let (a, b) = (ray.source(), ray.start());
                        (b.x - a.x) * d.0 + (b.y - a.y) * d.1 > 0
                    };
                    let both_ways = left.iter().chain(right).any(|&r| forward(r))
                        && left.iter().chain(right).any(|&r| !forward(r));
                    let describe = |rs: &[usize]| {
                        rs.iter()
                            .map(|&r| {
                                let ray = &arr.rays()[r];
                                json!({"ray": r, "anchor": ray.anchor, "from": ray.from,
                                       "side": format!("{:?}", ray.side)})
                            })
                            .collect::<Vec<_>>()
                    };
                    report.record(Some(Violation::with_data(
                        format!(
                            "{ASSIGNMENT_CONFLICT}: map {name}, edge {edge} ({p}): rays assign it \
                             to both sides; its skeleton matches {m} (owner cell {owner}, other \
                             cell {other})"
                        ),
                        json!({
                            "kind": ASSIGNMENT_CONFLICT,
                            "map": name,
                            "edge": edge,
                            "point": p.to_string(),
                            "point_file_units": sample::point_json(map, &p),
                            "edge_ends": [arr.point(a).to_string(), arr.point(b).to_string()],
                            "rays_left": describe(left),
                            "rays_right": describe(right),
                            "owner": owner,
                            "other": other,
                            "matches": m,
                            "rays_point_both_ways": both_ways,
                            "skeleton": embedded_json(&at),
                            "owner_skeleton": cell_of(*owner).as_ref().map(embedded_json),
                            "other_skeleton": cell_of(other).as_ref().map(embedded_json),
                        }),
                    )));
                }
                Conflict::Vertex { vertex, rays } => {
                    let p = arr.point(*vertex).clone();
                    let cells: Vec<FaceId> = arr
                        .outgoing(*vertex)
                        .into_iter()
                        .map(|h| arr.half_edge(h).face)
                        .filter(|&f| f != arr.outer_face())
                        .collect();
                    let (m, matching) = if arr.is_on_map_boundary(*vertex) {
                        ("on-boundary", Vec::new())
                    } else {
                        let at = skeleton_at(&index, &p);
                        let matching: Vec<FaceId> = cells
                            .iter()
                            .copied()
                            .filter(|&f| at.is_ok() && cell_of(f) == Some(at.clone()))
                            .collect();
                        (
                            if matching.is_empty() {
                                "neither"
                            } else {
                                "an incident cell"
                            },
                            matching,
                        )
                    };
                    stats.conflict_vertices.add(m);
                    report.record(Some(Violation::with_data(
                        format!(
                            "{ASSIGNMENT_CONFLICT}: map {name}, vertex {vertex} ({p}): the rays \
                             through it leave it to no cell; its skeleton matches {m} {matching:?}"
                        ),
                        json!({
                            "kind": ASSIGNMENT_CONFLICT,
                            "map": name,
                            "vertex": vertex,
                            "point": p.to_string(),
                            "rays": rays,
                            "incident_cells": cells,
                            "matching_cells": matching,
                            "matches": m,
                        }),
                    )));
                }
            }
        }
        (report, stats)
    }
}

/// Which of the two cells' skeletons the skeleton `at` equals.
fn matches(
    at: &Result<Embedded, String>,
    owner: Option<&Result<Embedded, String>>,
    other: Option<&Result<Embedded, String>>,
) -> &'static str {
    let eq = |c: Option<&Result<Embedded, String>>| at.is_ok() && c == Some(at);
    match (eq(owner), eq(other)) {
        (true, true) => "both",
        (true, false) => "owner",
        (false, true) => "other",
        (false, false) => "neither",
    }
}

/// T3.3b on the examined points of cell `cell` of `map`: each point is one
/// instance, violated if its skeleton (computed afresh through `index`)
/// differs from `claimed`, the cell's skeleton, or cannot be built. A
/// violation names the map, the cell, the point (exact, and in file units)
/// and both skeletons.
pub fn check_cell_points(
    map: &Map,
    index: &VisibilityIndex<'_>,
    cell: usize,
    claimed: &Result<Embedded, String>,
    points: &[(Site, RatPoint)],
) -> Report {
    let name = sample::map_name(map);
    let mut report = Report::new(ID);
    for (site, p) in points {
        let at = skeleton_at(index, p);
        let ok = claimed.is_ok() && at == *claimed;
        report.record((!ok).then(|| {
            let kind = if at.is_err() || claimed.is_err() {
                NO_SKELETON
            } else {
                SKELETON_DIFFERS
            };
            Violation::with_data(
                format!(
                    "map {name}, cell {cell}: the {} {p} has {}",
                    site.describe(),
                    if kind == NO_SKELETON {
                        "no skeleton"
                    } else {
                        "another skeleton than the cell"
                    }
                ),
                json!({
                    "kind": kind,
                    "map": name,
                    "cell": cell,
                    "site": site.describe(),
                    "point": p.to_string(),
                    "point_file_units": sample::point_json(map, p),
                    "skeleton": embedded_json(&at),
                    "cell_skeleton": embedded_json(claimed),
                }),
            )
        }));
    }
    report
}

#[cfg(test)]
mod tests {
    use super::*;

    fn l_room() -> Map {
        let pts = [(0, 0), (4, 0), (4, 2), (2, 2), (2, 4), (0, 4)];
        Map::from_ring(pts.iter().map(|&(x, y)| Point::new(x, y)).collect())
            .unwrap()
            .0
    }

    #[test]
    fn a_family_map_passes() {
        let map = wai_gen::family("corridor-niches", &[2]).unwrap();
        let (r, stats) = SameSkeleton.check_with_stats(&map);
        assert!(r.violations.is_empty(), "{:?}", r.violations);
        assert!(
            stats.cells > 5 && stats.edges > 0 && stats.vertices > 0,
            "{stats:?}"
        );
        assert_eq!(r.examined, stats.interior + stats.edges + stats.vertices);
    }

    #[test]
    fn the_l_room_passes() {
        let (r, stats) = SameSkeleton.check_with_stats(&l_room());
        assert!(r.violations.is_empty(), "{:?}", r.violations);
        assert_eq!(stats.cells, 5);
        assert!(stats.edges >= 4, "{stats:?}");
    }

    /// The L room's cells, their rings, and the skeleton of each.
    fn cells_of(map: &Map) -> (VisibilityIndex<'_>, Vec<(usize, [RatPoint; 2])>) {
        let arr = Arrangement::new(map, &visibility_rays(map));
        let cells = arr
            .cells()
            .map(|f| {
                let ring: Vec<RatPoint> = arr
                    .face_vertices(f)
                    .into_iter()
                    .map(|v| arr.point(v).clone())
                    .collect();
                (f, interior_points(&ring).unwrap())
            })
            .collect();
        (VisibilityIndex::new(map), cells)
    }

    #[test]
    fn an_altered_cell_skeleton_is_reported() {
        let map = l_room();
        let (index, cells) = cells_of(&map);
        let (f, pts) = &cells[0];
        let points: Vec<(Site, RatPoint)> =
            pts.iter().map(|p| (Site::Interior, p.clone())).collect();
        let claimed = skeleton_at(&index, &pts[0]);
        let r = check_cell_points(&map, &index, *f, &claimed, &points);
        assert_eq!((r.examined, r.violations.len()), (2, 0));
        let (o, mut key) = claimed.unwrap();
        key.offsets[0].0 += 1;
        let r = check_cell_points(&map, &index, *f, &Ok((o, key)), &points);
        assert_eq!((r.examined, r.violations.len()), (2, 2));
        assert_eq!(r.violations[0].data["kind"], SKELETON_DIFFERS);
        assert_eq!(r.violations[0].data["cell"], *f);
    }

    #[test]
    fn a_point_of_another_cell_is_reported() {
        let map = l_room();
        let (index, cells) = cells_of(&map);
        let claimed = skeleton_at(&index, &cells[0].1[0]);
        // Some other cell of the L room has another skeleton.
        let strangers: usize = cells[1..]
            .iter()
            .map(|(_, pts)| {
                let points = vec![(Site::Interior, pts[0].clone())];
                check_cell_points(&map, &index, cells[0].0, &claimed, &points)
                    .violations
                    .len()
            })
            .sum();
        assert!(strangers > 0);
        // A point outside the map has no skeleton.
        let outside = vec![(Site::Vertex(99), RatPoint::from(Point::new(3, 3)))];
        let r = check_cell_points(&map, &index, cells[0].0, &claimed, &outside);
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
