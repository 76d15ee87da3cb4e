//! From the nearest edge on each angular interval to the boundary of V_p.
//!
//! Both algorithms end here: given, counter-clockwise around p, the
//! direction (a map vertex) where each angular interval starts and the map
//! edge nearest to p on the open interval, the boundary of V_p is fixed. At
//! each interval start the boundary jumps along the ray from the edge before
//! to the edge after (a spurious edge, Def 3.4), or turns at the corner
//! where the two meet, or runs straight on when they are the same edge.

use crate::classify::{classify, Along, RawVertex};
use crate::polygon::{OnMap, VisibilityPolygon};
use rug::Integer;
use std::cmp::Ordering;
use wai_exact::RatPoint;
use wai_map::Map;

/// A point `p + (num / den)·(v − p)` on the ray from p through vertex v.
struct RayPoint {
    point: RatPoint,
    num: Integer,
    den: Integer,
}

/// Where the ray from p through map vertex `through` meets the line of map
/// edge `edge`, or `None` if they are parallel.
fn ray_meets_edge_line(map: &Map, p: &RatPoint, through: usize, edge: usize) -> Option<RayPoint> {
    let v = map.vertices();
    let w = p.hw();
    let rel = |i: usize| {
        (
            Integer::from(w * v[i].x) - p.hx(),
            Integer::from(w * v[i].y) - p.hy(),
        )
    };
    let cross = |a: &(Integer, Integer), b: &(Integer, Integer)| {
        Integer::from(&a.0 * &b.1) - Integer::from(&a.1 * &b.0)
    };
    let d = rel(through);
    let (a, b) = (rel(edge), rel((edge + 1) % map.n()));
    let e = (Integer::from(&b.0 - &a.0), Integer::from(&b.1 - &a.1));
    let den = cross(&d, &e);
    if den == 0 {
        return None;
    }
    let num = cross(&a, &b);
    let x = Integer::from(p.hx() * &den) + Integer::from(&num * &d.0);
    let y = Integer::from(p.hy() * &den) + Integer::from(&num * &d.1);
    let point = RatPoint::new(x, y, Integer::from(w * &den)).expect("den != 0");
    Some(RayPoint { point, num, den })
}

fn farther(a: &RayPoint, b: &RayPoint) -> bool {
    let ord = Integer::from(&a.num * &b.den).cmp(&Integer::from(&b.num * &a.den));
    let ord = if (a.den < 0) != (b.den < 0) {
        ord.reverse()
    } else {
        ord
    };
    ord == Ordering::Greater
}

/// Locate `q`, a point of the closed map edge `e`, on the map boundary.
fn on_edge(map: &Map, e: usize, q: &RatPoint) -> OnMap {
    for v in [e, (e + 1) % map.n()] {
        if q.to_point() == Some(map.vertices()[v]) {
            return OnMap::Vertex(v);
        }
    }
    OnMap::Edge(e)
}

/// Build V_p from `leaves`: for each angular interval, counter-clockwise,
/// the map vertex whose direction starts it and the nearest map edge on it.
pub(crate) fn assemble(map: &Map, p: &RatPoint, leaves: &[(usize, usize)]) -> VisibilityPolygon {
    let g = leaves.len();
    let mut raw = Vec::new();
    for k in 0..g {
        let (before, (dir, after)) = (leaves[(k + g - 1) % g].1, leaves[k]);
        if before == after {
            continue;
        }
        let a = ray_meets_edge_line(map, p, dir, before).expect("the limit of hits is finite");
        let b = ray_meets_edge_line(map, p, dir, after).expect("the limit of hits is finite");
        if a.point == b.point {
            raw.push(RawVertex {
                on_map: on_edge(map, after, &b.point),
                point: b.point,
                far_end_of_ray: false,
                after: Along::MapEdge(after),
            });
        } else {
            let a_far = farther(&a, &b);
            raw.push(RawVertex {
                on_map: on_edge(map, before, &a.point),
                point: a.point,
                far_end_of_ray: a_far,
                after: Along::Ray,
            });
            raw.push(RawVertex {
                on_map: on_edge(map, after, &b.point),
                point: b.point,
                far_end_of_ray: !a_far,
                after: Along::MapEdge(after),
            });
        }
    }
    classify(p.clone(), raw)
}
