//! Claim D3.5 (Definitions 3.5 and 3.6, and the observations after them):
//! every non-spurious edge of V_p is exactly one of full, half or partial;
//! every spurious vertex of a half edge lies on a spurious edge (whose near
//! endpoint is the half edge's blocking vertex); and every blocking vertex
//! is a reflex vertex of the map M.
//!
//! ## Trust
//! Sampled viewpoints, exact polygons. For each map the checker computes
//! V_p with the production algorithm for [`wai_study::sample::viewpoints`] and
//! examines, in every such V_p, exactly and without sampling:
//! - **every edge**: its kind must be the one Defs 3.4 and 3.5 give it from
//!   the geometry — spurious iff collinear with p; otherwise full, half or
//!   partial by how many endpoints are spurious by Def 3.4 (the far end of
//!   an adjacent edge collinear with p) — and the stored vertex flags and
//!   blocking list must agree with it;
//! - **every spurious endpoint of a half or partial edge** (Def 3.6 treats
//!   partial edges "analogously"): its other edge must be spurious, stored
//!   and by geometry, with this vertex as its far end;
//! - **every blocking vertex** (the near end of that spurious edge, per half
//!   or partial edge): it must be a vertex of the map, located there, not
//!   spurious, reflex in M, and listed in the edge's `blocking`.
//!
//! The checker trusts no stored field it can recompute. What is not
//! covered: viewpoints outside the sample.
//!
//! ## Cases
//! Each edge by the kind its geometry gives: **spurious**, **full**,
//! **half**, **partial**; among the spurious ones, **along a map edge**
//! (the spurious edge runs along a map edge collinear with p, which p
//! cannot certify: the leftmost spurious edge of Fig 3.3); each blocking
//! vertex by its edge: **blocks a half edge**, **blocks a partial edge**
//! (Def 3.6: one, resp. two per edge).

use serde_json::json;
use wai_exact::{orientation_rat, Orientation, RatPoint};
use wai_map::Map;
use wai_visibility::{EdgeKind, OnMap, VisibilityPolygon};

use crate::framework::{Case, Checker, Report, Violation};
use wai_study::sample::{self, closer, edge_collinear_with_viewpoint, vertex_spurious_by_def};
use wai_study::Study;

const ID: &str = "D3.5";

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study).with_cases(&[
    Case {
        name: SPURIOUS,
        what: "a spurious edge of V_p (Def 3.4: collinear with p)",
    },
    Case {
        name: FULL,
        what: "a full edge (Def 3.5: both ends non-spurious)",
    },
    Case {
        name: HALF,
        what: "a half edge (Def 3.5: one end spurious)",
    },
    Case {
        name: PARTIAL,
        what: "a partial edge (Def 3.5: both ends spurious)",
    },
    Case {
        name: ALONG_MAP_EDGE,
        what: "a spurious edge running along a map edge collinear with p (Fig 3.3, after \
               Def 3.4)",
    },
    Case {
        name: BLOCKS_HALF,
        what: "the blocking vertex of a half edge (Def 3.6)",
    },
    Case {
        name: BLOCKS_PARTIAL,
        what: "one of the two blocking vertices of a partial edge (Def 3.6)",
    },
]);

/// Case: a spurious edge.
pub const SPURIOUS: &str = "spurious";
/// Case: a full edge.
pub const FULL: &str = "full";
/// Case: a half edge.
pub const HALF: &str = "half";
/// Case: a partial edge.
pub const PARTIAL: &str = "partial";
/// Case: a spurious edge along a map edge.
pub const ALONG_MAP_EDGE: &str = "along a map edge";
/// Case: a blocking vertex of a half edge.
pub const BLOCKS_HALF: &str = "blocks a half edge";
/// Case: a blocking vertex of a partial edge.
pub const BLOCKS_PARTIAL: &str = "blocks a partial edge";

/// Whether spurious edge `i` of V_p runs along a map edge: its near end is
/// a map vertex one of whose neighbours lies on the edge's ray from p,
/// beyond it.
fn along_map_edge(map: &Map, vp: &VisibilityPolygon, i: usize) -> bool {
    let n = vp.len();
    let v = vp.vertices();
    let p = vp.viewpoint();
    let (a, b) = (&v[i].point, &v[(i + 1) % n].point);
    let near = if closer(p, a, b) { i } else { (i + 1) % n };
    let OnMap::Vertex(m) = v[near].on_map else {
        return false;
    };
    if m >= map.n() {
        return false;
    }
    let u = &v[near].point;
    [map.next(m), map.prev(m)]
        .into_iter()
        .map(|k| RatPoint::from(map.vertices()[k]))
        .any(|w| orientation_rat(p, u, &w) == Orientation::Collinear && closer(p, u, &w))
}

/// Checks D3.5 on the sampled viewpoints of a map.
fn check_study(study: &Study<'_>) -> Report {
    super::over_sampled_polygons(ID, study, check_polygon)
}

/// The kind Defs 3.4 and 3.5 give edge `i` of V_p, from geometry alone.
pub fn kind_by_def(vp: &VisibilityPolygon, i: usize) -> EdgeKind {
    if edge_collinear_with_viewpoint(vp, i) {
        return EdgeKind::Spurious;
    }
    let j = (i + 1) % vp.len();
    match (vertex_spurious_by_def(vp, i), vertex_spurious_by_def(vp, j)) {
        (false, false) => EdgeKind::Full,
        (true, true) => EdgeKind::Partial,
        _ => EdgeKind::Half,
    }
}

/// D3.5 on one V_p of `map`: every edge, every spurious endpoint of a half
/// or partial edge and every blocking vertex is one instance.
pub fn check_polygon(map: &Map, vp: &VisibilityPolygon) -> Report {
    let mut report = Report::new(ID);
    let n = vp.len();
    let v = vp.vertices();
    let p = vp.viewpoint();
    let violation = |what: String, extra: serde_json::Value| {
        let mut data = sample::replay(map, vp);
        data.insert("instance".into(), extra);
        Violation::with_data(
            format!(
                "map {}, viewpoint {}: {what}",
                sample::map_name(map),
                vp.viewpoint()
            ),
            data.into(),
        )
    };
    for i in 0..n {
        let j = (i + 1) % n;
        let edge = &vp.edges()[i];
        let want = kind_by_def(vp, i);
        // The spurious endpoints of a non-spurious edge and, for each, the
        // index of the other end of its spurious edge (the blocking vertex).
        let ends: Vec<(usize, usize, usize)> = if want == EdgeKind::Spurious {
            Vec::new()
        } else {
            [(i, (i + n - 1) % n, (i + n - 1) % n), (j, j, (j + 1) % n)]
                .into_iter()
                .filter(|&(x, _, _)| vertex_spurious_by_def(vp, x))
                .collect()
        };
        let want_blocking: Vec<usize> = ends.iter().map(|&(_, _, u)| u).collect();
        report.hit(match want {
            EdgeKind::Spurious => SPURIOUS,
            EdgeKind::Full => FULL,
            EdgeKind::Half => HALF,
            EdgeKind::Partial => PARTIAL,
        });
        if want == EdgeKind::Spurious && along_map_edge(map, vp, i) {
            report.hit(ALONG_MAP_EDGE);
        }
        // Every edge: one kind, the one its geometry gives.
        let flags_ok = [i, j]
            .iter()
            .all(|&x| v[x].spurious == vertex_spurious_by_def(vp, x));
        let ok = edge.kind == want
            && flags_ok
            && edge.blocking == want_blocking
            && (want == EdgeKind::Spurious) == edge.map_edge.is_none();
        report.record((!ok).then(|| {
            violation(
                format!(
                    "edge {i} of V_p is stored as {:?} (blocking {:?}, map edge {:?}), \
                     Defs 3.4-3.6 make it {want:?} (blocking {want_blocking:?}){}",
                    edge.kind,
                    edge.blocking,
                    edge.map_edge,
                    if flags_ok {
                        ""
                    } else {
                        "; an endpoint's spurious flag disagrees with Def 3.4"
                    }
                ),
                json!({"edge": i, "stored": format!("{:?}", edge.kind),
                       "by_def": format!("{want:?}"), "stored_blocking": edge.blocking,
                       "blocking_by_def": want_blocking, "flags_agree": flags_ok}),
            )
        }));
        for &(x, s, u) in &ends {
            // Every spurious endpoint x of a half or partial edge lies on the
            // spurious edge s, as its far end, with near end u.
            let on_spurious = edge_collinear_with_viewpoint(vp, s)
                && vp.edges()[s].kind == EdgeKind::Spurious
                && closer(p, &v[u].point, &v[x].point);
            report.record((!on_spurious).then(|| {
                violation(
                    format!(
                        "spurious vertex {x} {} of {:?} edge {i} is not the far end of a \
                         spurious edge {s}",
                        v[x].point, want
                    ),
                    json!({"edge": i, "vertex": x, "spurious_edge": s,
                           "stored_kind_of_it": format!("{:?}", vp.edges()[s].kind)}),
                )
            }));
            // Its blocking vertex u is a reflex vertex of M (after Def 3.6).
            report.hit(if want == EdgeKind::Half {
                BLOCKS_HALF
            } else {
                BLOCKS_PARTIAL
            });
            let at_map_vertex = match v[u].on_map {
                OnMap::Vertex(m) if m < map.n() => {
                    (v[u].point.to_point() == Some(map.vertices()[m])).then_some(m)
                }
                _ => None,
            };
            let ok = at_map_vertex.is_some_and(|m| map.is_reflex(m))
                && !vertex_spurious_by_def(vp, u)
                && edge.blocking.contains(&u);
            report.record((!ok).then(|| {
                violation(
                    format!(
                        "blocking vertex {u} {} of {want:?} edge {i} is not a non-spurious \
                         reflex map vertex listed by the edge (map vertex {at_map_vertex:?}, \
                         located {:?})",
                        v[u].point, v[u].on_map
                    ),
                    json!({"edge": i, "blocking_vertex": u, "map_vertex": at_map_vertex,
                           "reflex_in_map": at_map_vertex.map(|m| map.is_reflex(m)),
                           "listed": edge.blocking.contains(&u)}),
                )
            }));
        }
    }
    report
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fixtures::doorway;

    #[test]
    fn a_correct_polygon_passes() {
        let (map, vp) = doorway();
        let r = check_polygon(&map, &vp);
        // Every edge, plus two spurious ends and two blocking vertices per
        // spurious edge pair around the partial edge.
        assert!(r.examined >= vp.len() as u64 + 4, "{}", r.examined);
        assert!(r.violations.is_empty(), "{:?}", r.violations);
        assert_eq!(r.cases.get(PARTIAL), Some(&1));
        assert_eq!(r.cases.get(BLOCKS_PARTIAL), Some(&2));
        let edges = [SPURIOUS, FULL, HALF, PARTIAL].map(|c| r.cases.get(c).copied().unwrap_or(0));
        assert_eq!(edges.iter().sum::<u64>(), vp.len() as u64);
        let r = CHECKER.check_map(&map);
        assert!(r.examined > 0);
        assert!(r.violations.is_empty(), "{:?}", r.violations);
    }

    #[test]
    fn a_spurious_edge_along_a_map_edge_is_counted() {
        // From (2, 1) in the L room the wall (2, 2)–(2, 4) lies on the ray
        // from p through the reflex vertex (2, 2): V_p's spurious edge from
        // (2, 2) to (2, 4) runs along it, and p cannot certify it.
        let pts = [(0, 0), (4, 0), (4, 2), (2, 2), (2, 4), (0, 4)];
        let map = Map::from_ring(
            pts.iter()
                .map(|&(x, y)| wai_exact::Point::new(x, y))
                .collect(),
        )
        .unwrap()
        .0;
        let vp = wai_visibility::VisibilityIndex::new(&map)
            .visibility_polygon(&RatPoint::from(wai_exact::Point::new(2, 1)))
            .unwrap();
        let r = check_polygon(&map, &vp);
        assert!(r.violations.is_empty(), "{:?}", r.violations);
        assert_eq!(r.cases.get(ALONG_MAP_EDGE), Some(&1), "{:?}", r.cases);
    }

    #[test]
    fn a_wrong_edge_kind_is_reported() {
        let (map, vp) = doorway();
        let mut edges = vp.edges().to_vec();
        let i = (0..vp.len())
            .find(|&i| edges[i].kind == EdgeKind::Partial)
            .expect("a partial edge");
        edges[i].kind = EdgeKind::Half;
        let broken =
            VisibilityPolygon::from_parts(vp.viewpoint().clone(), vp.vertices().to_vec(), edges);
        let r = check_polygon(&map, &broken);
        assert_eq!(r.violations.len(), 1, "{:?}", r.violations);
        let v = &r.violations[0];
        assert_eq!(v.data["map"], "doorway");
        assert_eq!(v.data["viewpoint"], json!(["3", "1"]));
        assert_eq!(v.data["instance"]["edge"], i);
        assert_eq!(v.data["instance"]["by_def"], "Partial");
    }

    #[test]
    fn a_convex_blocking_vertex_is_reported() {
        // Claim the partial edge's first blocking vertex sits at a convex
        // map vertex: relocate it to map vertex 0 = (0, 0).
        let (map, vp) = doorway();
        let i = (0..vp.len())
            .find(|&i| vp.edges()[i].kind == EdgeKind::Partial)
            .expect("a partial edge");
        let u = vp.edges()[i].blocking[0];
        let mut vertices = vp.vertices().to_vec();
        vertices[u].on_map = OnMap::Vertex(0);
        let broken =
            VisibilityPolygon::from_parts(vp.viewpoint().clone(), vertices, vp.edges().to_vec());
        let r = check_polygon(&map, &broken);
        assert_eq!(r.violations.len(), 1, "{:?}", r.violations);
        assert_eq!(r.violations[0].data["instance"]["blocking_vertex"], u);
    }
}
