//! Claim L3.1a (Lemma 3.1(1)): a reflex vertex of a visibility polygon V_p
//! is never spurious.
//!
//! A vertex of V_p is spurious (Def 3.4) if it is the far endpoint of an
//! edge of V_p collinear with p. The lemma says that where V_p turns
//! clockwise, the vertex is a point the robot can certify to be a map
//! vertex.
//!
//! ## Trust
//! Sampled viewpoints, exact polygons. For each map the checker takes
//! [`wai_study::sample::viewpoints`] (degenerate and generic interior points,
//! [`wai_study::sample::VIEWPOINTS`] of them), computes each V_p with the
//! production algorithm, and examines **every** reflex vertex of every
//! such V_p (a clockwise turn, decided exactly). A reflex vertex violates
//! the claim if V_p flags it spurious *or* Def 3.4, read off the geometry
//! (an adjacent edge collinear with p whose other endpoint is closer to p),
//! makes it spurious — so the verdict does not rest on the stored flags
//! alone. What is not covered: viewpoints outside the sample.
//!
//! ## Cases
//! A reflex vertex of V_p has two edges of V_p; Lemma 3.1(2) leaves two
//! configurations, counted apart: **blocking vertex** (one edge is
//! spurious, the vertex its near end: the reflex map vertex that hides what
//! lies behind it, Def 3.6) and **map corner** (neither is: a reflex map
//! vertex whose two map edges p sees).

use serde_json::json;
use wai_map::Map;
use wai_visibility::VisibilityPolygon;

use crate::framework::{Case, Checker, Report, Violation};
use wai_study::sample::{
    self, edge_collinear_with_viewpoint, reflex_in_vp, vertex_spurious_by_def,
};
use wai_study::Study;

const ID: &str = "L3.1a";

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study).with_cases(&[
    Case {
        name: BLOCKING,
        what: "a reflex vertex of V_p beside a spurious edge, its near end: a blocking \
               vertex (Def 3.6)",
    },
    Case {
        name: CORNER,
        what: "a reflex vertex of V_p between two non-spurious edges: a reflex map vertex \
               whose two map edges p sees",
    },
]);

/// Case: a reflex vertex of V_p beside a spurious edge.
pub const BLOCKING: &str = "blocking vertex";
/// Case: a reflex vertex of V_p between two non-spurious edges.
pub const CORNER: &str = "map corner";

/// Checks L3.1a on the sampled viewpoints of a map.
fn check_study(study: &Study<'_>) -> Report {
    super::over_sampled_polygons(ID, study, check_polygon)
}

/// L3.1a on one V_p of `map`: every reflex vertex is one instance.
pub fn check_polygon(map: &Map, vp: &VisibilityPolygon) -> Report {
    let mut report = Report::new(ID);
    for i in 0..vp.len() {
        if !reflex_in_vp(vp, i) {
            continue;
        }
        let n = vp.len();
        let beside_spurious = edge_collinear_with_viewpoint(vp, (i + n - 1) % n)
            || edge_collinear_with_viewpoint(vp, i);
        report.hit(if beside_spurious { BLOCKING } else { CORNER });
        let flagged = vp.vertices()[i].spurious;
        let by_def = vertex_spurious_by_def(vp, i);
        report.record((flagged || by_def).then(|| {
            let mut data = sample::replay(map, vp);
            data.insert("vertex".into(), json!(i));
            data.insert("point".into(), json!(vp.vertices()[i].point.to_string()));
            data.insert("flagged_spurious".into(), json!(flagged));
            data.insert("spurious_by_def_3_4".into(), json!(by_def));
            Violation::with_data(
                format!(
                    "map {}, viewpoint {}: reflex vertex {i} {} of V_p is spurious \
                     (flag {flagged}, Def 3.4 {by_def})",
                    sample::map_name(map),
                    vp.viewpoint(),
                    vp.vertices()[i].point
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
    use crate::fixtures::l_room;
    use wai_exact::{Point, RatPoint};

    #[test]
    fn a_correct_polygon_passes() {
        let (map, vp) = l_room();
        let r = check_polygon(&map, &vp);
        assert_eq!(r.examined, 1);
        assert!(r.violations.is_empty(), "{:?}", r.violations);
        // (2, 2) blocks the view of the east wing from (1, 3).
        assert_eq!(r.cases.get(BLOCKING), Some(&1));
        let r = CHECKER.check_map(&map);
        assert!(r.examined > 0);
        assert!(r.violations.is_empty(), "{:?}", r.violations);
    }

    #[test]
    fn a_reflex_vertex_flagged_spurious_is_reported() {
        let (map, vp) = l_room();
        let mut vertices = vp.vertices().to_vec();
        assert_eq!(vertices[2].point, RatPoint::from(Point::new(2, 2)));
        vertices[2].spurious = true;
        let broken =
            VisibilityPolygon::from_parts(vp.viewpoint().clone(), vertices, vp.edges().to_vec());
        let r = check_polygon(&map, &broken);
        assert_eq!(r.violations.len(), 1);
        let v = &r.violations[0];
        assert!(
            v.what.contains("L-room") && v.what.contains("(1, 3)"),
            "{}",
            v.what
        );
        assert_eq!(v.data["map"], "L-room");
        assert_eq!(v.data["vertex"], 2);
        assert_eq!(v.data["viewpoint"], json!(["1", "3"]));
    }

    #[test]
    fn a_reflex_vertex_spurious_by_geometry_is_reported() {
        // Keep V_p but put the viewpoint at (6, −2), on the line of the V_p
        // edge (4, 0)–(2, 2) beyond (4, 0): that edge is then collinear with
        // p and its far end is the reflex vertex (2, 2), spurious by Def 3.4
        // although no flag says so.
        let (map, vp) = l_room();
        let moved = VisibilityPolygon::from_parts(
            RatPoint::from(Point::new(6, -2)),
            vp.vertices().to_vec(),
            vp.edges().to_vec(),
        );
        let r = check_polygon(&map, &moved);
        assert_eq!(r.violations.len(), 1, "{:?}", r.violations);
        assert_eq!(r.violations[0].data["spurious_by_def_3_4"], true);
    }
}
