//! Claim L3.1b (Lemma 3.1(2)): no two spurious edges of a visibility
//! polygon V_p are adjacent.
//!
//! A spurious edge (Def 3.4) lies on a ray from p; between two of them the
//! boundary of V_p always runs along a piece of a map edge that p sees.
//!
//! ## Trust
//! Sampled viewpoints, exact polygons. For each map the checker computes
//! V_p with the production algorithm for [`wai_study::sample::viewpoints`] and
//! examines **every** pair of adjacent edges of every such V_p (edges `i`
//! and `i + 1`, cyclically, so as many pairs as edges). An edge counts as
//! spurious if V_p classifies it so *or* it is collinear with p (Def 3.4,
//! decided exactly), so the verdict does not rest on the stored kinds
//! alone. What is not covered: viewpoints outside the sample.

use serde_json::json;
use wai_map::Map;
use wai_visibility::{EdgeKind, VisibilityPolygon};

use crate::framework::{Checker, Report, Violation};
use wai_study::sample::{self, edge_collinear_with_viewpoint};
use wai_study::Study;

const ID: &str = "L3.1b";

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study);

/// Checks L3.1b on the sampled viewpoints of a map.
fn check_study(study: &Study<'_>) -> Report {
    super::over_sampled_polygons(ID, study, check_polygon)
}

/// L3.1b on one V_p of `map`: every pair of adjacent edges is one instance.
pub fn check_polygon(map: &Map, vp: &VisibilityPolygon) -> Report {
    let mut report = Report::new(ID);
    let n = vp.len();
    let spurious =
        |i: usize| vp.edges()[i].kind == EdgeKind::Spurious || edge_collinear_with_viewpoint(vp, i);
    for i in 0..n {
        let j = (i + 1) % n;
        report.record((spurious(i) && spurious(j)).then(|| {
            let mut data = sample::replay(map, vp);
            data.insert("edges".into(), json!([i, j]));
            data.insert(
                "kinds".into(),
                json!([
                    format!("{:?}", vp.edges()[i].kind),
                    format!("{:?}", vp.edges()[j].kind)
                ]),
            );
            data.insert("shared_vertex".into(), json!(j));
            Violation::with_data(
                format!(
                    "map {}, viewpoint {}: edges {i} and {j} of V_p are both spurious and meet \
                     at vertex {j} {}",
                    sample::map_name(map),
                    vp.viewpoint(),
                    vp.vertices()[j].point
                ),
                data.into(),
            )
        }));
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
        assert_eq!(r.examined, vp.len() as u64);
        assert!(r.violations.is_empty(), "{:?}", r.violations);
        let r = CHECKER.check_map(&map);
        assert!(r.examined > 0);
        assert!(r.violations.is_empty(), "{:?}", r.violations);
    }

    #[test]
    fn two_adjacent_spurious_edges_are_reported() {
        let (map, vp) = doorway();
        let n = vp.len();
        let mut edges = vp.edges().to_vec();
        // The partial edge and the spurious edge after it.
        let i = (0..n)
            .find(|&i| edges[i].kind == EdgeKind::Partial)
            .expect("a partial edge");
        assert_eq!(edges[(i + 1) % n].kind, EdgeKind::Spurious);
        edges[i].kind = EdgeKind::Spurious;
        edges[i].map_edge = None;
        edges[i].blocking.clear();
        let broken =
            VisibilityPolygon::from_parts(vp.viewpoint().clone(), vp.vertices().to_vec(), edges);
        let r = check_polygon(&map, &broken);
        // The pairs (i − 1, i) and (i, i + 1).
        assert_eq!(r.violations.len(), 2, "{:?}", r.violations);
        for v in &r.violations {
            assert_eq!(v.data["map"], "doorway");
            assert_eq!(v.data["viewpoint"], json!(["3", "1"]));
        }
        for pair in [[(i + n - 1) % n, i], [i, (i + 1) % n]] {
            assert!(
                r.violations.iter().any(|v| v.data["edges"] == json!(pair)),
                "{pair:?} not reported"
            );
        }
    }
}
