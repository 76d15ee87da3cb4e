//! Viewpoints for the differential tests of the fast query paths: the
//! midpoints of vertex pairs and a rational grid, kept where inside.

use rug::Integer;
use wai_exact::{Containment, RatPoint};
use wai_map::Map;

/// Midpoints of non-adjacent vertex pairs, and the grid of `steps − 1` by
/// `steps − 1` points over the bounding box shifted by `(1, 2)/(steps·spread)`
/// off its lines, so most points lie on no line through two vertices; only
/// those inside `map`.
pub(crate) fn interior_points(map: &Map, steps: i128, spread: i128) -> Vec<RatPoint> {
    let v = map.vertices();
    let mut out: Vec<RatPoint> = Vec::new();
    for i in 0..v.len() {
        for j in i + 2..v.len() {
            out.push(RatPoint::midpoint(&v[i].into(), &v[j].into()));
        }
    }
    let (lo, hi) = map.bounding_box();
    for i in 1..steps {
        for j in 1..steps {
            let x = Integer::from(lo.x) * steps + (hi.x - lo.x) * i;
            let y = Integer::from(lo.y) * steps + (hi.y - lo.y) * j;
            let w = Integer::from(steps * spread);
            out.push(RatPoint::new(x * spread + 1, y * spread + 2, w).unwrap());
        }
    }
    out.retain(|q| map.locate(q) == Containment::Inside);
    out
}
