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

use std::collections::BTreeSet;

use rug::Rational;
use serde_json::json;
use wai_exact::{orientation_rat, Orientation, RatPoint};

use crate::framework::{Checker, Report, Violation};
use wai_study::sample;
use wai_study::Study;

const ID: &str = "T3.9a";

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study);

/// What one map contributed, beyond the report.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Stats {
    /// Rays examined.
    pub rays: u64,
    /// The most interior decomposition vertices on one ray.
    pub max_on_ray: u64,
    /// The map's n (the bound is 2n).
    pub n: u64,
}

/// Checks T3.9a on every ray of a map.
fn check_study(study: &Study<'_>) -> Report {
    check_with_stats(study, None).0
}

/// The check with the largest count met. `n` is the n of the bound 2n:
/// `None` (the claim) for the map's number of vertices; planted-violation
/// tests set it artificially small.
pub fn check_with_stats(study: &Study<'_>, n: Option<usize>) -> (Report, Stats) {
    let map = study.map();
    let rays = study.rays();
    let arr = study.arrangement();
    let name = sample::map_name(map);
    let mut report = Report::new(ID);
    let n = n.unwrap_or(map.n());
    let mut stats = Stats {
        n: n as u64,
        ..Stats::default()
    };
    if let Err(e) = arr.sanity_check() {
        report.record(Some(Violation::with_data(
            format!("map {name}: the arrangement fails its sanity check: {e}"),
            json!({"map": name, "sanity_check": e}),
        )));
        return (report, stats);
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
        stats.rays += 1;
        stats.max_on_ray = stats.max_on_ray.max(points.len() as u64);
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
    (report, stats)
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
        let (r, stats) = check_with_stats(&Study::new(&map), None);
        assert!(r.violations.is_empty(), "{:?}", r.violations);
        assert_eq!(r.examined, stats.rays);
        assert!(stats.rays > 10 && stats.max_on_ray > 0, "{stats:?}");
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
        let (r, stats) = check_with_stats(&Study::new(&map), Some(1));
        assert!(stats.max_on_ray > 2, "{stats:?}");
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
