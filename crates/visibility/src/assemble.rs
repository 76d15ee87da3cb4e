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
use wai_exact::{BigVector, RatPoint, Vector};
use wai_map::Map;

/// A point `p + (num / den)·(v − p)` on the ray from p through vertex v.
struct RayPoint {
    point: RatPoint,
    num: Integer,
    den: Integer,
}

/// Coordinates of directions from p fit the `i128` fast path: with
/// `p = (X, Y) / W`, `|X|, |Y| < 2^61` and `|W|·|v| < 2^61` for every map
/// vertex v (`coord_bits` bounds the map's coordinates).
///
/// Implementation note: then every direction `W·v − (X, Y)` is below
/// `2^62` per coordinate, an edge vector below `2^63`, and the cross
/// products `den = d × e` and `num = a × b` below `2^126`, which an `i128`
/// holds. The point itself, `(X·den + num·d) / (W·den)`, is built in GMP.
pub(crate) fn fits_fast(p: &RatPoint, coord_bits: u32) -> bool {
    const FAST: u32 = 61;
    p.hx().significant_bits() <= FAST
        && p.hy().significant_bits() <= FAST
        && p.hw().significant_bits() + coord_bits <= FAST
}

/// Where the ray from p through map vertex `through` meets the line of map
/// edge `edge`, or `None` if they are parallel.
fn ray_meets_edge_line(
    map: &Map,
    p: &RatPoint,
    fast: bool,
    through: usize,
    edge: usize,
) -> Option<RayPoint> {
    let v = map.vertices();
    let (a, b) = (edge, map.next(edge));
    let (num, den, d) = if fast {
        let (x, y, w) = (
            p.hx().to_i128().expect("fast"),
            p.hy().to_i128().expect("fast"),
            p.hw().to_i128().expect("fast"),
        );
        // Within VECTOR_FAST_BITS by `fits_fast`: directions below 2^62,
        // an edge vector below 2^63.
        let rel = |i: usize| Vector::new(w * v[i].x - x, w * v[i].y - y);
        let (d, ra, rb) = (rel(through), rel(a), rel(b));
        let den = d.cross(Vector::new(rb.x - ra.x, rb.y - ra.y));
        if den == 0 {
            return None;
        }
        (Integer::from(ra.cross(rb)), Integer::from(den), d.to_big())
    } else {
        let rel = |i: usize| BigVector::toward(p, v[i]);
        let (d, ra, rb) = (rel(through), rel(a), rel(b));
        let den = d.cross(&rb.sub(&ra));
        if den == 0 {
            return None;
        }
        (ra.cross(&rb), den, d)
    };
    let x = Integer::from(p.hx() * &den) + Integer::from(&num * &d.x);
    let y = Integer::from(p.hy() * &den) + Integer::from(&num * &d.y);
    let point = RatPoint::new(x, y, Integer::from(p.hw() * &den)).expect("den != 0");
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
    for v in [e, map.next(e)] {
        if q.to_point() == Some(map.vertices()[v]) {
            return OnMap::Vertex(v);
        }
    }
    OnMap::Edge(e)
}

/// Build V_p from `leaves`: for each angular interval, counter-clockwise,
/// the map vertex whose direction starts it and the nearest map edge on it.
pub(crate) fn assemble(
    map: &Map,
    p: &RatPoint,
    coord_bits: u32,
    leaves: &[(usize, usize)],
) -> VisibilityPolygon {
    let fast = fits_fast(p, coord_bits);
    let g = leaves.len();
    let mut raw = Vec::new();
    for k in 0..g {
        let (before, (dir, after)) = (leaves[(k + g - 1) % g].1, leaves[k]);
        if before == after {
            continue;
        }
        // The common case, a corner: consecutive edges meeting at the very
        // vertex that defines the direction. Both hits are that vertex.
        if after == map.next(before) && dir == after {
            raw.push(RawVertex {
                point: RatPoint::from(map.vertices()[dir]),
                on_map: OnMap::Vertex(dir),
                far_end_of_ray: false,
                after: Along::MapEdge(after),
            });
            continue;
        }
        let a =
            ray_meets_edge_line(map, p, fast, dir, before).expect("the limit of hits is finite");
        let b = ray_meets_edge_line(map, p, fast, dir, after).expect("the limit of hits is finite");
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
