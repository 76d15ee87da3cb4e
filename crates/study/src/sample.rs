//! What the visibility checkers examine: sampled viewpoints, their exact
//! visibility polygons, and Def 3.4 read off a polygon's geometry.
//!
//! The checkers of chapter 3 (L3.1a–c, D3.5, T3.2) examine these.
//!
//! # Sampling
//! The claims L3.1a–c, D3.5 and T3.2 speak about every viewpoint of the map,
//! a continuum; [`viewpoints`] picks a finite, deterministic set of interior
//! viewpoints of every degenerate kind the thesis's decomposition produces,
//! plus generic ones (the same kinds as the visibility crate's tests):
//! - the viewpoints the thesis figure draws, when the map is a recognised
//!   thesis family (`corridor-niches`, `overlap-fan`, `convex-niches`; the
//!   map is regenerated from its name and compared vertex by vertex, so the
//!   name is only a hint),
//! - midpoints of vertex pairs (on a line through two map vertices),
//! - meeting points of two lines through vertex pairs,
//! - points on the extension of a map edge beyond its end,
//! - points of a rational grid (generic positions),
//!
//! taken round robin from the kinds so that a small `limit` still mixes them.
//! Each V_p is then computed exactly by the production algorithm
//! ([`wai_visibility::VisibilityIndex`]) and examined exactly.
//!
//! # Edge cases
//! A viewpoint is kept only if it lies strictly inside the map (the thesis
//! assumes p not on the boundary, sec. 3.4); duplicates are dropped.

use rug::{Integer, Rational};
use serde_json::{json, Value};
use wai_exact::{
    construct_intersection, locate_rat, orientation_rat, Containment, Line, Orientation, Point,
    RatPoint,
};
use wai_map::{format_exact, Map};
use wai_visibility::{VisibilityIndex, VisibilityPolygon};

/// Viewpoints per map that the chapter 3 checkers examine by default.
pub const VIEWPOINTS: usize = 10;

/// At most `limit` interior viewpoints of `map`, deterministic (see the
/// module documentation for the kinds).
///
/// ```
/// use wai_exact::{locate_rat, Containment};
/// let map = wai_gen::family("corridor-niches", &[3]).unwrap();
/// let views = wai_study::sample::viewpoints(&map, 10);
/// assert_eq!(views.len(), 10);
/// // The thesis's own viewpoints come first: (5 + 4i, -3), deep in niche i.
/// assert_eq!(views[0].to_string(), "(5, -3)");
/// assert!(views.iter().all(|p| locate_rat(map.vertices(), p) == Containment::Inside));
/// ```
pub fn viewpoints(map: &Map, limit: usize) -> Vec<RatPoint> {
    let v = map.vertices();
    let n = v.len();
    let mut out: Vec<RatPoint> = Vec::new();
    let keep = |q: RatPoint, out: &mut Vec<RatPoint>| {
        if out.len() < limit && !out.contains(&q) && locate_rat(v, &q) == Containment::Inside {
            out.push(q);
        }
    };
    // The family's own viewpoints, at most half of the budget (and 2).
    for q in family_viewpoints(map).into_iter().take((limit / 2).max(2)) {
        keep(q, &mut out);
    }
    // Midpoints of vertex pairs, in a scrambled order.
    let pairs: Vec<(usize, usize)> = (0..n)
        .flat_map(|i| ((i + 2)..n).map(move |j| (i, j)))
        .collect();
    let midpoints = scrambled(pairs.len())
        .map(move |k| pairs[k])
        .map(|(i, j)| RatPoint::midpoint(&v[i].into(), &v[j].into()));
    // Meeting points of lines through vertex pairs (a sample of 40 lines).
    let lines: Vec<Line> = (0..n)
        .flat_map(|i| (0..n).filter(move |&j| j != i).map(move |j| (i, j)))
        .step_by(3)
        .filter_map(|(i, j)| Line::new(v[i], v[j]))
        .take(40)
        .collect();
    let line_pairs: Vec<(usize, usize)> = (0..lines.len())
        .flat_map(|a| ((a + 1)..lines.len()).map(move |b| (a, b)))
        .collect();
    let meetings = scrambled(line_pairs.len())
        .filter_map(|k| construct_intersection(&lines[line_pairs[k].0], &lines[line_pairs[k].1]));
    // Points on the extensions of map edges: v_i + (v_i − v_{i−1}) / 3.
    let extensions = (0..n).map(|i| {
        let (a, b) = (v[(i + n - 1) % n], v[i]);
        RatPoint::new(
            Integer::from(b.x) * 4 - a.x,
            Integer::from(b.y) * 4 - a.y,
            Integer::from(3),
        )
        .expect("3 != 0")
    });
    // A rational grid: (lo + (hi − lo)·i/8 + 1/56, lo + (hi − lo)·j/8 + 2/56).
    let (lo, hi) = map.bounding_box();
    let grid = (1..8i128).flat_map(move |i| {
        (1..8i128).map(move |j| {
            let x = Integer::from(lo.x) * 8 + Integer::from(hi.x - lo.x) * i;
            let y = Integer::from(lo.y) * 8 + Integer::from(hi.y - lo.y) * j;
            RatPoint::new(x * 7 + 1, y * 7 + 2, Integer::from(56)).expect("56 != 0")
        })
    });
    let mut kinds: Vec<Box<dyn Iterator<Item = RatPoint> + '_>> = vec![
        Box::new(midpoints),
        Box::new(meetings),
        Box::new(extensions),
        Box::new(grid),
    ];
    // Round robin; a kind whose next candidate is rejected keeps its turn
    // until it yields a kept point or runs dry.
    while out.len() < limit && !kinds.is_empty() {
        kinds.retain_mut(|kind| {
            let before = out.len();
            for q in kind.by_ref() {
                keep(q, &mut out);
                if out.len() > before || out.len() >= limit {
                    return true;
                }
            }
            false
        });
    }
    out
}

/// The indices `0..len` in a fixed scrambled order: `k·s mod len` for a
/// step `s ≈ 0.618·len` coprime with `len`.
fn scrambled(len: usize) -> impl Iterator<Item = usize> {
    let coprime = |a: usize, b: usize| {
        let (mut a, mut b) = (a, b);
        while b != 0 {
            (a, b) = (b, a % b);
        }
        a == 1
    };
    let step = (len * 618 / 1000..len.max(1))
        .find(|&s| s > 0 && coprime(s, len))
        .unwrap_or(1);
    (0..len).map(move |k| (k * step) % len)
}

/// The viewpoints the thesis figure draws, if `map` is a thesis family map
/// (recognised by its name `id/params` and confirmed by regenerating it);
/// otherwise none.
///
/// ```
/// let map = wai_gen::family("corridor-niches", &[2]).unwrap();
/// assert_eq!(wai_study::sample::family_viewpoints(&map).len(), 2);
/// let renamed = map.clone().with_name("corridor-niches/k=3");
/// assert!(wai_study::sample::family_viewpoints(&renamed).is_empty());
/// ```
pub fn family_viewpoints(map: &Map) -> Vec<RatPoint> {
    let Some((id, params)) = map.name().and_then(|s| s.split_once('/')) else {
        return Vec::new();
    };
    let values: Option<Vec<u32>> = params
        .split(',')
        .map(|kv| kv.split_once('=').and_then(|(_, x)| x.parse().ok()))
        .collect();
    let Some(values) = values else {
        return Vec::new();
    };
    let points: Vec<Point> = match (id, values.as_slice()) {
        ("corridor-niches", &[k]) => wai_gen::corridor_niches_viewpoints(k),
        ("overlap-fan", &[z]) => wai_gen::overlap_fan_viewpoints(z),
        ("convex-niches", &[fan, views]) => wai_gen::convex_niches_viewpoints(fan, views),
        _ => return Vec::new(),
    };
    let same = wai_gen::family(id, &values)
        .is_ok_and(|m| m.vertices() == map.vertices() && *map.scale() == 1);
    if !same {
        return Vec::new();
    }
    points.into_iter().map(RatPoint::from).collect()
}

/// V_p of each of [`viewpoints`]`(map, limit)`, by the production algorithm.
///
/// # Panics
/// If the production algorithm rejects an interior viewpoint (a bug of
/// `wai-visibility`, not a claim violation).
pub fn visibility_polygons(map: &Map, limit: usize) -> Vec<VisibilityPolygon> {
    visibility_polygons_with(map, &VisibilityIndex::new(map), limit)
}

/// As [`visibility_polygons`], through an index already built.
pub fn visibility_polygons_with(
    map: &Map,
    index: &VisibilityIndex<'_>,
    limit: usize,
) -> Vec<VisibilityPolygon> {
    viewpoints(map, limit)
        .iter()
        .map(|p| {
            index.visibility_polygon(p).unwrap_or_else(|e| {
                panic!(
                    "V_p of the interior viewpoint {p} of map {}: {e}",
                    map_name(map)
                )
            })
        })
        .collect()
}

/// The map's name, or `"unnamed"`.
pub fn map_name(map: &Map) -> &str {
    map.name().unwrap_or("unnamed")
}

/// A point as `["x", "y"]` of exact strings in the units of the map's file
/// (the `viewpoints` format of `counterexamples/`).
pub fn point_json(map: &Map, q: &RatPoint) -> Value {
    let unit = |c: &Integer| format_exact(&Rational::from((c.clone(), q.hw() * map.scale())));
    json!([unit(q.hx()), unit(q.hy())])
}

/// The replay data every violation of a V_p starts with: the map's name,
/// the viewpoint in file units and in the map's integer frame, and V_p's
/// vertices (integer frame). Checkers add their indices to it.
pub fn replay(map: &Map, vp: &VisibilityPolygon) -> serde_json::Map<String, Value> {
    let mut m = serde_json::Map::new();
    m.insert("map".into(), json!(map_name(map)));
    m.insert("viewpoint".into(), point_json(map, vp.viewpoint()));
    m.insert("viewpoint_scaled".into(), json!(vp.viewpoint().to_string()));
    m.insert(
        "vp".into(),
        json!(vp
            .vertices()
            .iter()
            .map(|v| v.point.to_string())
            .collect::<Vec<_>>()),
    );
    m
}

/// `q + (dx, dy)`.
pub fn translate(q: &RatPoint, dx: i128, dy: i128) -> RatPoint {
    RatPoint::new(
        Integer::from(q.hw() * dx) + q.hx(),
        Integer::from(q.hw() * dy) + q.hy(),
        q.hw().clone(),
    )
    .expect("the denominator is positive")
}

/// Def 3.4: edge `i` of V_p (from vertex `i` to `i + 1`) is spurious iff it
/// is collinear with the viewpoint — read off the geometry, not off the
/// stored kind.
pub fn edge_collinear_with_viewpoint(vp: &VisibilityPolygon, i: usize) -> bool {
    let v = vp.vertices();
    let n = v.len();
    orientation_rat(&v[i].point, &v[(i + 1) % n].point, vp.viewpoint()) == Orientation::Collinear
}

/// Def 3.4: vertex `i` of V_p is spurious iff it lies on a spurious edge
/// (u, v_i) whose other endpoint u is closer to the viewpoint — read off the
/// geometry, not off the stored flag.
pub fn vertex_spurious_by_def(vp: &VisibilityPolygon, i: usize) -> bool {
    let v = vp.vertices();
    let n = v.len();
    let p = vp.viewpoint();
    let (before, after) = ((i + n - 1) % n, (i + 1) % n);
    (edge_collinear_with_viewpoint(vp, before) && closer(p, &v[before].point, &v[i].point))
        || (edge_collinear_with_viewpoint(vp, i) && closer(p, &v[after].point, &v[i].point))
}

/// Whether `a` is strictly closer to `p` than `b` is (exact squared
/// distances).
pub fn closer(p: &RatPoint, a: &RatPoint, b: &RatPoint) -> bool {
    squared_distance(p, a) < squared_distance(p, b)
}

fn coords(q: &RatPoint) -> (Rational, Rational) {
    (
        Rational::from((q.hx().clone(), q.hw().clone())),
        Rational::from((q.hy().clone(), q.hw().clone())),
    )
}

fn squared_distance(a: &RatPoint, b: &RatPoint) -> Rational {
    let ((ax, ay), (bx, by)) = (coords(a), coords(b));
    let dx = ax - bx;
    let dy = ay - by;
    Rational::from(&dx * &dx) + Rational::from(&dy * &dy)
}

/// Whether vertex `i` of V_p is reflex in V_p (a clockwise turn).
pub fn reflex_in_vp(vp: &VisibilityPolygon, i: usize) -> bool {
    let v = vp.vertices();
    let n = v.len();
    orientation_rat(
        &v[(i + n - 1) % n].point,
        &v[i].point,
        &v[(i + 1) % n].point,
    ) == Orientation::Clockwise
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn viewpoints_are_interior_distinct_and_mixed() {
        let map = wai_gen::random("special-orthogonal", 16, 3).unwrap();
        let views = viewpoints(&map, 12);
        assert_eq!(views.len(), 12);
        for (k, p) in views.iter().enumerate() {
            assert_eq!(locate_rat(map.vertices(), p), Containment::Inside);
            assert!(!views[..k].contains(p));
        }
        // The grid kind contributes (denominator a multiple of 56's factor 7).
        assert!(views.iter().any(|p| Integer::from(p.hw() % 7u32) == 0));
        // And not everything is a midpoint of two integer points.
        assert!(views.iter().any(|p| *p.hw() > 2));
    }

    #[test]
    fn scrambled_is_a_permutation() {
        for len in [0, 1, 2, 5, 10, 36, 97] {
            let mut seen: Vec<usize> = scrambled(len).collect();
            seen.sort_unstable();
            assert_eq!(seen, (0..len).collect::<Vec<_>>(), "{len}");
        }
    }

    #[test]
    fn family_viewpoints_need_the_family_map() {
        let map = wai_gen::family("overlap-fan", &[1]).unwrap();
        assert_eq!(family_viewpoints(&map).len(), 3);
        let other = wai_gen::family("convex-niches", &[2]).unwrap();
        assert_eq!(family_viewpoints(&other).len(), 2);
        let plain = wai_gen::random("random-orthogonal", 10, 0).unwrap();
        assert!(family_viewpoints(&plain).is_empty());
    }
}
