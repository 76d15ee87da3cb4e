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
//!
//! ## Cases
//! A pair with no spurious edge is counted as **no spurious edge**; a pair
//! with one by what the other edge is (Defs 3.4, 3.5, read off the
//! geometry): **beside full** (at its near end, the blocking vertex),
//! **beside half** and **beside partial** (at its far end, the spurious
//! vertex, or at the near end when the blocking vertex is itself the
//! non-spurious end of a half edge).

use serde_json::json;
use wai_map::Map;
use wai_visibility::{EdgeKind, VisibilityPolygon};

use super::d3_5::kind_by_def;
use crate::framework::{Case, Checker, Report, Violation};
use wai_study::sample::{self, edge_collinear_with_viewpoint};
use wai_study::Study;

const ID: &str = "L3.1b";

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study).with_cases(&[
    Case {
        name: NONE,
        what: "two adjacent edges of V_p, neither spurious",
    },
    Case {
        name: BESIDE_FULL,
        what: "a spurious edge beside a full edge (Def 3.5)",
    },
    Case {
        name: BESIDE_HALF,
        what: "a spurious edge beside a half edge (Def 3.5)",
    },
    Case {
        name: BESIDE_PARTIAL,
        what: "a spurious edge beside a partial edge (Def 3.5)",
    },
]);

/// Case: a pair of adjacent edges with no spurious edge.
pub const NONE: &str = "no spurious edge";
/// Case: a spurious edge next to a full edge.
pub const BESIDE_FULL: &str = "beside full";
/// Case: a spurious edge next to a half edge.
pub const BESIDE_HALF: &str = "beside half";
/// Case: a spurious edge next to a partial edge.
pub const BESIDE_PARTIAL: &str = "beside partial";

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
        let beside = |e: usize| match kind_by_def(vp, e) {
            EdgeKind::Full => Some(BESIDE_FULL),
            EdgeKind::Half => Some(BESIDE_HALF),
            EdgeKind::Partial => Some(BESIDE_PARTIAL),
            EdgeKind::Spurious => None,
        };
        let case = match (spurious(i), spurious(j)) {
            (false, false) => Some(NONE),
            (true, true) => None,
            (true, false) => beside(j),
            (false, true) => beside(i),
        };
        if let Some(case) = case {
            report.hit(case);
        }
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
        // The doorway's partial edge has a spurious edge on each side.
        assert_eq!(r.cases.get(BESIDE_PARTIAL), Some(&2));
        assert_eq!(r.cases.values().sum::<u64>(), r.examined);
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
