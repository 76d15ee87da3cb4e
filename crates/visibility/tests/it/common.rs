//! Maps and viewpoints shared by the tests.

use rug::Integer;
use wai_exact::{construct_intersection, locate_rat, Containment, Line, Point, RatPoint};
use wai_map::Map;

pub fn map(pts: &[(i128, i128)]) -> Map {
    let ring = pts.iter().map(|&(x, y)| Point::new(x, y)).collect();
    Map::from_ring(ring).expect("test maps are valid").0
}

pub fn rat(x: i64, y: i64, w: i64) -> RatPoint {
    RatPoint::new(Integer::from(x), Integer::from(y), Integer::from(w)).unwrap()
}

pub fn pt(x: i128, y: i128) -> RatPoint {
    RatPoint::from(Point::new(x, y))
}

/// Interior viewpoints of every degenerate kind the thesis's decomposition
/// produces, plus generic ones: midpoints of vertex pairs (on a line
/// through two vertices), meeting points of two such lines, points on the
/// extension of a map edge, and points of a fine rational grid.
pub fn viewpoints(map: &Map, limit: usize) -> Vec<RatPoint> {
    let v = map.vertices();
    let n = v.len();
    let inside = |q: &RatPoint| locate_rat(v, q) == Containment::Inside;
    let mut out: Vec<RatPoint> = Vec::new();
    let push = |q: RatPoint, out: &mut Vec<RatPoint>| {
        if inside(&q) && !out.contains(&q) && out.len() < limit {
            out.push(q);
        }
    };
    // Midpoints of vertex pairs.
    for i in 0..n {
        for j in (i + 2)..n {
            push(RatPoint::midpoint(&v[i].into(), &v[j].into()), &mut out);
        }
    }
    // Meeting points of lines through vertex pairs (a sample).
    let lines: Vec<Line> = (0..n)
        .flat_map(|i| (0..n).filter(move |&j| j != i).map(move |j| (i, j)))
        .step_by(3)
        .filter_map(|(i, j)| Line::new(v[i], v[j]))
        .take(40)
        .collect();
    for a in 0..lines.len() {
        for b in (a + 1)..lines.len() {
            if let Some(q) = construct_intersection(&lines[a], &lines[b]) {
                push(q, &mut out);
            }
        }
    }
    // Points on the extensions of map edges: v_i + t (v_i − v_{i−1}) for t = 1/3.
    for i in 0..n {
        let (a, b) = (v[(i + n - 1) % n], v[i]);
        let q = RatPoint::new(
            Integer::from(3 * b.x + (b.x - a.x)),
            Integer::from(3 * b.y + (b.y - a.y)),
            Integer::from(3),
        )
        .unwrap();
        push(q, &mut out);
    }
    // A rational grid.
    let (lo, hi) = map.bounding_box();
    for i in 1..8i128 {
        for j in 1..8i128 {
            let x = Integer::from(lo.x) * 8 + (hi.x - lo.x) * i;
            let y = Integer::from(lo.y) * 8 + (hi.y - lo.y) * j;
            push(
                RatPoint::new(x * 7 + 1, y * 7 + 2, Integer::from(56)).unwrap(),
                &mut out,
            );
        }
    }
    out
}
