//! Claim L3.1c (Lemma 3.1(3)): a non-spurious edge e of V_p, lying on the
//! map edge e', is the only portion of e' that p sees.
//!
//! So a map edge shows up in V_p at most once, and everything of it outside
//! e is hidden from p.
//!
//! ## Trust
//! Sampled viewpoints; each V_p is checked exactly. For each map the
//! checker computes V_p with the production algorithm for
//! [`wai_study::sample::viewpoints`] and examines **every** non-spurious edge e
//! (not collinear with p, Def 3.4, decided exactly) of every such V_p:
//! 1. e lies on the closed map edge e' that V_p names, in e''s direction;
//! 2. no other non-spurious edge of V_p names e' or has its midpoint on e';
//! 3. the part of e' that p sees is exactly e, up to e's two endpoints
//!    (which are visible or not by the grazing convention of sec. 2.2). This
//!    is decided exactly, not sampled: along e', visibility from p can only
//!    change where e' meets a line through p and a map vertex (between two
//!    consecutive such directions the nearest map edge is fixed, the premise
//!    of the reference algorithm). So the checker cuts e' at those meeting
//!    points and at e's endpoints, and tests with [`wai_exact::sees`] every
//!    cut point and the midpoint of every piece: open e must be visible, the
//!    rest of e' invisible.
//!
//! What is not covered: viewpoints outside the sample.

use rug::{Integer, Rational};
use serde_json::json;
use wai_exact::{sees, side_of_line_rat, Point, RatPoint, Side};
use wai_map::Map;
use wai_visibility::VisibilityPolygon;

use crate::framework::{Checker, Report, Violation};
use wai_study::sample::{self, edge_collinear_with_viewpoint};
use wai_study::Study;

const ID: &str = "L3.1c";

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study);

/// Checks L3.1c on the sampled viewpoints of a map.
fn check_study(study: &Study<'_>) -> Report {
    super::over_sampled_polygons(ID, study, check_polygon)
}

/// L3.1c on one V_p of `map`: every non-spurious edge is one instance.
pub fn check_polygon(map: &Map, vp: &VisibilityPolygon) -> Report {
    let mut report = Report::new(ID);
    for i in 0..vp.len() {
        if edge_collinear_with_viewpoint(vp, i) {
            continue;
        }
        let problem = check_edge(map, vp, i);
        report.record(problem.map(|(what, extra)| {
            let mut data = sample::replay(map, vp);
            data.insert("edge".into(), json!(i));
            data.insert("map_edge".into(), json!(vp.edges()[i].map_edge));
            data.insert("problem".into(), extra);
            Violation::with_data(
                format!(
                    "map {}, viewpoint {}: non-spurious edge {i} of V_p ({} – {}): {what}",
                    sample::map_name(map),
                    vp.viewpoint(),
                    vp.vertices()[i].point,
                    vp.vertices()[(i + 1) % vp.len()].point,
                ),
                data.into(),
            )
        }));
    }
    report
}

/// `(x, y)` of a rational point as rationals.
fn coords(q: &RatPoint) -> (Rational, Rational) {
    (
        Rational::from((q.hx().clone(), q.hw().clone())),
        Rational::from((q.hy().clone(), q.hw().clone())),
    )
}

/// Points of the line through the map edge from `a` to `b`, by their
/// parameter λ (the point `a + λ(b − a)`).
struct EdgeLine {
    a: (Rational, Rational),
    d: (Rational, Rational),
}

impl EdgeLine {
    fn new(a: Point, b: Point) -> EdgeLine {
        EdgeLine {
            a: (Rational::from(a.x), Rational::from(a.y)),
            d: (Rational::from(b.x - a.x), Rational::from(b.y - a.y)),
        }
    }

    /// λ of a point known to lie on the line.
    fn param(&self, q: &RatPoint) -> Rational {
        let (x, y) = coords(q);
        let (ux, uy) = (x - &self.a.0, y - &self.a.1);
        let dot = ux * &self.d.0 + uy * &self.d.1;
        let len2 = Rational::from(&self.d.0 * &self.d.0) + Rational::from(&self.d.1 * &self.d.1);
        dot / len2
    }

    /// The point of parameter λ.
    fn point(&self, l: &Rational) -> RatPoint {
        let x = Rational::from(&self.d.0 * l) + &self.a.0;
        let y = Rational::from(&self.d.1 * l) + &self.a.1;
        let w = Integer::from(x.denom()).lcm(y.denom());
        let hx = x.numer() * Integer::from(&w / x.denom());
        let hy = y.numer() * Integer::from(&w / y.denom());
        RatPoint::new(hx, hy, w).expect("positive denominator")
    }

    /// λ where the line through `p` and `v` meets this line, if they cross.
    fn meet(&self, p: &(Rational, Rational), v: Point) -> Option<Rational> {
        let w = (Rational::from(v.x) - &p.0, Rational::from(v.y) - &p.1);
        let cross = |a: &(Rational, Rational), b: &(Rational, Rational)| {
            Rational::from(&a.0 * &b.1) - Rational::from(&a.1 * &b.0)
        };
        let den = cross(&w, &self.d);
        if den == 0 {
            return None;
        }
        let ap = (
            Rational::from(&self.a.0 - &p.0),
            Rational::from(&self.a.1 - &p.1),
        );
        Some(-cross(&w, &ap) / den)
    }
}

/// The problem with non-spurious edge `i`, if any: a sentence and data.
fn check_edge(map: &Map, vp: &VisibilityPolygon, i: usize) -> Option<(String, serde_json::Value)> {
    let n = vp.len();
    let v = vp.vertices();
    let Some(k) = vp.edges()[i].map_edge else {
        return Some((
            "it names no map edge".into(),
            json!({"kind": format!("{:?}", vp.edges()[i].kind)}),
        ));
    };
    if k >= map.n() {
        return Some((format!("map edge {k} does not exist"), json!({})));
    }
    let seg = map.edge(k);
    let line = EdgeLine::new(seg.a(), seg.b());
    let (s, t) = (&v[i].point, &v[(i + 1) % n].point);
    // 1. e lies on the closed segment e', in its direction.
    for q in [s, t] {
        if side_of_line_rat(&seg.line(), q) != Side::On {
            return Some((
                format!("endpoint {q} is not on the line of map edge {k}"),
                json!({"point": q.to_string()}),
            ));
        }
    }
    let (ls, lt) = (line.param(s), line.param(t));
    let (zero, one) = (Rational::new(), Rational::from(1));
    if ls < zero || lt > one || ls >= lt {
        return Some((
            format!(
                "it is not a piece of map edge {k} in its direction (parameters {ls} and {lt})"
            ),
            json!({"parameters": [ls.to_string(), lt.to_string()]}),
        ));
    }
    // 2. No other non-spurious edge on e'.
    for j in (0..n).filter(|&j| j != i && !edge_collinear_with_viewpoint(vp, j)) {
        let mid = RatPoint::midpoint(&v[j].point, &v[(j + 1) % n].point);
        let named = vp.edges()[j].map_edge == Some(k);
        let on = side_of_line_rat(&seg.line(), &mid) == Side::On && {
            let l = line.param(&mid);
            zero <= l && l <= one
        };
        if named || on {
            return Some((
                format!("non-spurious edge {j} of V_p also lies on map edge {k}"),
                json!({"other_edge": j, "other_names_it": named}),
            ));
        }
    }
    // 3. p sees exactly open e of e': cut e' where visibility may change.
    let p = coords(vp.viewpoint());
    let mut cuts: Vec<Rational> = vec![zero.clone(), one.clone(), ls.clone(), lt.clone()];
    cuts.extend(
        map.vertices()
            .iter()
            .filter_map(|&u| line.meet(&p, u))
            .filter(|l| zero < *l && *l < one),
    );
    cuts.sort();
    cuts.dedup();
    let mut probes: Vec<Rational> = Vec::with_capacity(2 * cuts.len());
    for w in cuts.windows(2) {
        probes.push(w[0].clone());
        probes.push(Rational::from(&w[0] + &w[1]) / 2u32);
    }
    probes.extend(cuts.last().cloned());
    for l in probes {
        if l == ls || l == lt {
            continue; // e's endpoints: visible or not by the grazing rule
        }
        let want = ls < l && l < lt;
        let x = line.point(&l);
        let sight = sees(map.vertices(), vp.viewpoint(), &x);
        if sight.is_visible() != want {
            let what = if want {
                format!("p does not see its point {x} ({sight:?})")
            } else {
                format!("p sees the point {x} of map edge {k} outside it")
            };
            return Some((
                what,
                json!({"point": x.to_string(), "point_file_units": sample::point_json(map, &x),
                       "sight": format!("{sight:?}"), "should_see": want}),
            ));
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fixtures::l_room;
    use wai_visibility::{EdgeKind, OnMap, VisEdge, VisVertex, VisibilityIndex};

    fn at(x: i128, y: i128) -> RatPoint {
        RatPoint::from(Point::new(x, y))
    }

    #[test]
    fn a_correct_polygon_passes() {
        let (map, vp) = l_room();
        let r = check_polygon(&map, &vp);
        assert_eq!(r.examined, 4);
        assert!(r.violations.is_empty(), "{:?}", r.violations);
        let r = CHECKER.check_map(&map);
        assert!(r.examined > 0);
        assert!(r.violations.is_empty(), "{:?}", r.violations);
    }

    #[test]
    fn a_second_edge_on_the_same_map_edge_is_reported() {
        // Split the full edge (2, 4) → (0, 4) at (1, 4): two V_p edges on
        // map edge 4, each of which claims to be all p sees of it.
        let (map, vp) = l_room();
        let mut vertices = vp.vertices().to_vec();
        let mut edges = vp.edges().to_vec();
        assert_eq!(vertices[3].point, at(2, 4));
        assert_eq!(edges[3].map_edge, Some(4));
        vertices.insert(
            4,
            VisVertex {
                point: at(1, 4),
                on_map: OnMap::Edge(4),
                spurious: false,
            },
        );
        edges.insert(
            4,
            VisEdge {
                kind: EdgeKind::Full,
                map_edge: Some(4),
                blocking: Vec::new(),
            },
        );
        let broken = VisibilityPolygon::from_parts(vp.viewpoint().clone(), vertices, edges);
        let r = check_polygon(&map, &broken);
        assert_eq!(r.examined, 5);
        assert_eq!(r.violations.len(), 2, "{:?}", r.violations);
        for v in &r.violations {
            assert_eq!(v.data["map"], "L-room");
            assert_eq!(v.data["viewpoint"], json!(["1", "3"]));
            assert_eq!(v.data["map_edge"], 4);
            assert!(v.what.contains("also lies on map edge 4"), "{}", v.what);
        }
    }

    #[test]
    fn a_visible_point_outside_the_edge_is_reported() {
        // Shorten the half edge (0, 0) → (4, 0) to end at (3, 0): p still
        // sees (7/2, 0) beyond it. The ring is inconsistent elsewhere, but
        // only edge 0's claim is at stake.
        let (map, vp) = l_room();
        let mut vertices = vp.vertices().to_vec();
        vertices[1].point = at(3, 0);
        vertices[1].on_map = OnMap::Edge(0);
        let broken =
            VisibilityPolygon::from_parts(vp.viewpoint().clone(), vertices, vp.edges().to_vec());
        let r = check_polygon(&map, &broken);
        let v = r
            .violations
            .iter()
            .find(|v| v.data["edge"] == 0)
            .expect("edge 0 is reported");
        assert_eq!(v.data["problem"]["should_see"], false, "{}", v.what);
        assert!(v.what.contains("outside it"), "{}", v.what);
    }

    #[test]
    fn an_invisible_point_inside_the_edge_is_reported() {
        // Give the viewpoint (1, 3) the V_p of (3, 1): it claims that
        // (1, 3) sees the east wall x = 4, hidden behind the reflex corner
        // (2, 2).
        let (map, vp) = l_room();
        let elsewhere = VisibilityIndex::new(&map)
            .visibility_polygon(&at(3, 1))
            .unwrap();
        let broken = VisibilityPolygon::from_parts(
            vp.viewpoint().clone(),
            elsewhere.vertices().to_vec(),
            elsewhere.edges().to_vec(),
        );
        let r = check_polygon(&map, &broken);
        assert!(
            r.violations
                .iter()
                .any(|v| v.data["problem"]["should_see"] == true),
            "{:?}",
            r.violations
        );
    }
}
