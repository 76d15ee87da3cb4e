//! Claim T3.9a (Theorem 3.9, the counting step of its proof): at most 2n
//! vertices of the visibility cell decomposition lie on any one visibility
//! ray, n the number of map vertices.
//!
//! The proof's argument: walking along a ray, each decomposition vertex met
//! is a change in the visibility of some map vertex, and in a simple
//! polygon a vertex that disappears from view never reappears, so each map
//! vertex contributes at most two changes. The proof counts the vertices
//! in the interior of the map (the ray's own end on ∂M is counted
//! separately, one per ray); so do we.
//!
//! ## Trust
//! Exhaustive over the rays of each map, exact. The checker builds the
//! decomposition with the production code ([`wai_cells::visibility_rays`],
//! [`wai_cells::Arrangement::new`]) and examines **every** ray: the
//! decomposition vertices on it are the endpoints of the arrangement edges
//! the ray covers (the arrangement records, per edge, every ray whose closed
//! segment contains it — collinear rays merged); of those, the vertices in
//! the interior of the map are counted (the anchor, the end and grazed map
//! vertices lie on ∂M). Each counted vertex is also tested to lie on the
//! ray's closed segment (an exact orientation and a betweenness test), so
//! a wrongly recorded cover is a violation, not a silent miscount. The
//! verdict rests on the arrangement containing every crossing of two rays
//! (its `sanity_check` — run first; a failure is a violation — and the
//! `wai-cells` tests against brute force) and on the rays being all rays of
//! Def 3.8.
//!
//! ## Cases
//! The proof's counting step: at a decomposition vertex on ray r, every
//! other ray x through it (emanating from map vertex u, anchored at v_r)
//! is a change in the visibility of u for a walk along r — u **comes into
//! sight** (the walk leaves the side of x where v_r hides u) or
//! **disappears** (it enters that side). Rays collinear with r are not
//! crossed. The ratio measured is the most vertices on one ray over 2n.

use std::collections::BTreeSet;

use rug::{Integer, Rational};
use serde_json::json;
use wai_cells::{Arrangement, RaySide, VisibilityRay};
use wai_exact::{orientation_rat, Orientation, Point, RatPoint};

use crate::framework::{over, Case, Checker, Report, Violation};
use wai_study::sample;
use wai_study::Study;

const ID: &str = "T3.9a";

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study).with_cases(&[
    Case {
        name: APPEARS,
        what: "a ray crossed at a decomposition vertex where the vertex it emanates from \
               comes into sight (Thm 3.9's counting step)",
    },
    Case {
        name: DISAPPEARS,
        what: "a ray crossed at a decomposition vertex where the vertex it emanates from \
               disappears from view (Thm 3.9's counting step)",
    },
]);

/// Case: a map vertex comes into sight along a ray.
pub const APPEARS: &str = "comes into sight";
/// Case: a map vertex disappears from view along a ray.
pub const DISAPPEARS: &str = "disappears";

/// Checks T3.9a on every ray of a map.
fn check_study(study: &Study<'_>) -> Report {
    check_with_n(study, None)
}

/// The sign of `(b − a) × (d − c)`, exactly.
fn cross_sign(a: Point, b: Point, c: Point, d: Point) -> std::cmp::Ordering {
    let (ux, uy) = (Integer::from(b.x) - a.x, Integer::from(b.y) - a.y);
    let (vx, vy) = (Integer::from(d.x) - c.x, Integer::from(d.y) - c.y);
    (ux * &vy - uy * &vx).cmp0()
}

/// Walking along `r` across `x` (not collinear with it): whether the
/// vertex `x` emanates from comes into sight (`true`) or disappears.
fn comes_into_sight(r: &VisibilityRay, x: &VisibilityRay) -> bool {
    // r's direction points to the left of x: the walk goes from x's right
    // side to its left side.
    let to_left =
        cross_sign(x.source(), x.start(), r.source(), r.start()) == std::cmp::Ordering::Greater;
    let into_shadow = match x.side {
        RaySide::Left => to_left,
        RaySide::Right => !to_left,
    };
    !into_shadow
}

/// The rays through arrangement vertex `v` (on an edge incident to it).
fn rays_through(arr: &Arrangement, v: usize) -> BTreeSet<usize> {
    arr.outgoing(v)
        .into_iter()
        .flat_map(|h| arr.edge_rays(h / 2).iter().copied())
        .collect()
}

/// The check. `n` is the n of the bound 2n: `None` (the claim) for the
/// map's number of vertices; planted-violation tests set it artificially
/// small. The largest ratio (vertices on one ray) / 2n is measured.
pub fn check_with_n(study: &Study<'_>, n: Option<usize>) -> Report {
    let map = study.map();
    let rays = study.rays();
    let arr = study.arrangement();
    let name = sample::map_name(map);
    let mut report = Report::new(ID);
    let n = n.unwrap_or(map.n());
    if let Err(e) = study.arrangement_sanity() {
        report.record(Some(Violation::with_data(
            format!("map {name}: the arrangement fails its sanity check: {e}"),
            json!({"map": name, "sanity_check": e}),
        )));
        return report;
    }
    // The interior vertices on each ray: endpoints of the edges it covers.
    let mut on_ray: Vec<BTreeSet<usize>> = vec![BTreeSet::new(); rays.len()];
    for e in 0..arr.edge_count() {
        let (a, b) = (arr.half_edge(2 * e).origin, arr.half_edge(2 * e + 1).origin);
        for &r in arr.edge_rays(e) {
            for v in [a, b] {
                if !arr.is_on_map_boundary(v) {
                    on_ray[r].insert(v);
                }
            }
        }
    }
    for (r, ray) in rays.iter().enumerate() {
        let start = RatPoint::from(ray.start());
        let points: Vec<RatPoint> = on_ray[r].iter().map(|&v| arr.point(v).clone()).collect();
        let off: Vec<String> = points
            .iter()
            .filter(|p| !on_closed_segment(&start, &ray.end.point, p))
            .map(ToString::to_string)
            .collect();
        for &v in &on_ray[r] {
            for x in rays_through(arr, v) {
                let other = &rays[x];
                if wai_exact::orientation(ray.source(), ray.start(), other.source())
                    == Orientation::Collinear
                    && wai_exact::orientation(ray.source(), ray.start(), other.start())
                        == Orientation::Collinear
                {
                    continue;
                }
                report.hit(if comes_into_sight(ray, other) {
                    APPEARS
                } else {
                    DISAPPEARS
                });
            }
        }
        report.measure(
            over(points.len(), 2 * n as u128),
            json!({"ray": r, "count": points.len(), "n": n}),
        );
        let mut v = check_ray(name, n, r, &points);
        if !off.is_empty() && v.is_none() {
            v = Some(Violation::with_data(
                format!(
                    "map {name}, ray {r}: the arrangement puts vertices {} on the ray, \
                     which are not on its segment",
                    off.join(", ")
                ),
                json!({"map": name, "ray": r, "off_segment": off}),
            ));
        }
        if let Some(v) = v.as_mut() {
            v.data["anchor"] = json!(ray.anchor);
            v.data["from"] = json!(ray.from);
            v.data["start"] = json!(start.to_string());
            v.data["end"] = json!(ray.end.point.to_string());
        }
        report.record(v);
    }
    report
}

/// T3.9a on one ray: `points` are the decomposition vertices in the
/// interior of the map on ray `ray` of map `map_name`, which has `n`
/// vertices. One instance; a violation if there are more than 2n, with
/// the map, the ray and every vertex as an exact point.
pub fn check_ray(map_name: &str, n: usize, ray: usize, points: &[RatPoint]) -> Option<Violation> {
    (points.len() > 2 * n).then(|| {
        Violation::with_data(
            format!(
                "map {map_name}, ray {ray}: {} decomposition vertices on the ray, more than 2n = {}",
                points.len(),
                2 * n
            ),
            json!({
                "map": map_name,
                "ray": ray,
                "n": n,
                "count": points.len(),
                "vertices": points.iter().map(ToString::to_string).collect::<Vec<_>>(),
            }),
        )
    })
}

/// Whether `p` lies on the closed segment `ab`, exactly.
fn on_closed_segment(a: &RatPoint, b: &RatPoint, p: &RatPoint) -> bool {
    if orientation_rat(a, b, p) != Orientation::Collinear {
        return false;
    }
    let c = |q: &RatPoint| {
        (
            Rational::from((q.hx().clone(), q.hw().clone())),
            Rational::from((q.hy().clone(), q.hw().clone())),
        )
    };
    let (a, b, p) = (c(a), c(b), c(p));
    let along = Rational::from(&a.0 - &p.0) * Rational::from(&b.0 - &p.0)
        + Rational::from(&a.1 - &p.1) * Rational::from(&b.1 - &p.1);
    along <= 0
}

#[cfg(test)]
mod tests {
    use super::*;
    use wai_exact::Point;

    #[test]
    fn the_comb_family_passes() {
        let map = wai_gen::family("comb-convex-chain", &[3]).unwrap();
        let study = Study::new(&map);
        let r = CHECKER.run(&study);
        assert!(r.violations.is_empty(), "{:?}", r.violations);
        assert_eq!(r.examined as usize, study.rays().len());
        assert!(r.examined > 10, "{}", r.examined);
        let most = r.largest.expect("a ratio").ratio;
        assert!(most > 0 && most <= 1, "{most}");
        // Both kinds of change occur along the rays.
        assert!(
            r.cases.get(APPEARS).is_some_and(|&k| k > 0),
            "{:?}",
            r.cases
        );
        assert!(
            r.cases.get(DISAPPEARS).is_some_and(|&k| k > 0),
            "{:?}",
            r.cases
        );
    }

    /// The case of each crossing agrees with `sees`: the vertex a crossing
    /// ray emanates from is visible from the midpoint of r's arrangement
    /// edge after the crossing and not before it ("comes into sight"), or
    /// the other way round.
    #[test]
    fn the_cases_follow_the_visibility_of_the_crossing_rays_vertex() {
        let (mut appears, mut disappears) = (0, 0);
        for map in [
            wai_gen::family("comb-convex-chain", &[3]).unwrap(),
            wai_gen::family("corridor-niches", &[2]).unwrap(),
            wai_gen::random("random-simple-star", 12, 4).unwrap(),
        ] {
            let study = Study::new(&map);
            let (arr, rays) = (study.arrangement(), study.rays());
            for (r, ray) in rays.iter().enumerate() {
                let start = RatPoint::from(ray.start());
                // r's edges, ordered from the anchor, as (near end, far end).
                let mut edges: Vec<(usize, usize)> = (0..arr.edge_count())
                    .filter(|&e| arr.edge_rays(e).contains(&r))
                    .map(|e| {
                        let (a, b) = (arr.half_edge(2 * e).origin, arr.dest(2 * e));
                        let a_first = on_closed_segment(&start, arr.point(b), arr.point(a));
                        if a_first {
                            (a, b)
                        } else {
                            (b, a)
                        }
                    })
                    .collect();
                edges.sort_by(|x, y| {
                    let near = on_closed_segment(&start, arr.point(y.0), arr.point(x.0));
                    if x.0 == y.0 {
                        std::cmp::Ordering::Equal
                    } else if near {
                        std::cmp::Ordering::Less
                    } else {
                        std::cmp::Ordering::Greater
                    }
                });
                for w in edges.windows(2) {
                    let v = w[0].1;
                    assert_eq!(v, w[1].0, "r's edges are consecutive");
                    let mid =
                        |(a, b): (usize, usize)| RatPoint::midpoint(arr.point(a), arr.point(b));
                    let (before, after) = (mid(w[0]), mid(w[1]));
                    for x in rays_through(arr, v) {
                        let other = &rays[x];
                        let collinear = |q| {
                            wai_exact::orientation(ray.source(), ray.start(), q)
                                == Orientation::Collinear
                        };
                        if collinear(other.source()) && collinear(other.start()) {
                            continue;
                        }
                        let u = RatPoint::from(map.vertices()[other.from]);
                        let sees = |q: &RatPoint| map.sees(q, &u).is_visible();
                        if comes_into_sight(ray, other) {
                            assert!(
                                !sees(&before) && sees(&after),
                                "ray {r} at {}",
                                arr.point(v)
                            );
                            appears += 1;
                        } else {
                            assert!(
                                sees(&before) && !sees(&after),
                                "ray {r} at {}",
                                arr.point(v)
                            );
                            disappears += 1;
                        }
                    }
                }
            }
        }
        assert!(appears > 0 && disappears > 0, "{appears} {disappears}");
    }

    #[test]
    fn too_many_vertices_are_reported() {
        let pts: Vec<RatPoint> = (1..=5).map(|x| RatPoint::from(Point::new(x, 0))).collect();
        assert!(check_ray("planted", 3, 0, &pts).is_none());
        let v = check_ray("planted", 2, 4, &pts).expect("5 > 2·2");
        assert_eq!(v.data["ray"], 4);
        assert_eq!(v.data["count"], 5);
        assert_eq!(v.data["vertices"][4], "(5, 0)");
    }

    #[test]
    fn a_real_ray_breaks_an_artificially_small_bound() {
        // The full pipeline against 2n with n = 1: every ray with more
        // than 2 interior vertices is reported, with its vertices.
        let map = wai_gen::family("comb-convex-chain", &[3]).unwrap();
        let r = check_with_n(&Study::new(&map), Some(1));
        assert!(r.largest.expect("a ratio").ratio > 1);
        assert!(!r.violations.is_empty());
        let v = &r.violations[0];
        assert_eq!(v.data["n"], 1);
        assert!(v.data["count"].as_u64().unwrap() > 2);
        assert_eq!(v.data["map"], "comb-convex-chain/niches=3,chain=3");
        assert!(v.data["start"].is_string() && v.data["end"].is_string());
    }

    #[test]
    fn on_closed_segment_is_exact() {
        let p = |x, y| RatPoint::from(Point::new(x, y));
        assert!(on_closed_segment(&p(0, 0), &p(4, 2), &p(2, 1)));
        assert!(on_closed_segment(&p(0, 0), &p(4, 2), &p(4, 2)));
        assert!(!on_closed_segment(&p(0, 0), &p(4, 2), &p(6, 3)));
        assert!(!on_closed_segment(&p(0, 0), &p(4, 2), &p(2, 2)));
    }
}
