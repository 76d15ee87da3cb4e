//! Claim L3.1c (Lemma 3.1(3)): a non-spurious edge e of V_p, lying on the
//! map edge e', is the only portion of e' that p sees.
//!
//! So a map edge shows up in V_p at most once, and everything of it outside
//! e is hidden from p.
//!
//! ## Trust
//! Sampled viewpoints; each V_p is checked exactly. For each map the
//! checker reads V_p of [`wai_study::sample::viewpoints`] (the study's,
//! production algorithm) and examines **every** non-spurious edge e (not
//! collinear with p, Def 3.4, decided exactly) of every such V_p:
//! 1. e lies on the closed map edge e' that V_p names, in e''s direction;
//! 2. no other non-spurious edge of V_p names e' or has its midpoint on e';
//! 3. the part of e' that p sees is exactly e, up to e's two endpoints
//!    (which are visible or not by the grazing convention of sec. 2.2). This
//!    is decided exactly, not sampled, in one pass over the map edges: each
//!    other map edge f (closed, so grazing its ends blocks) hides from p one
//!    interval of directions of e' — the directions f and e' share, if f
//!    lies in front of e' there (disjoint segments keep their order over
//!    the directions they share; a neighbour of e' blocks nothing at their
//!    common vertex), or the one direction of f if p is on f's line and f
//!    reaches nearer than e' — and the points of e' that p sees are those
//!    no interval covers. Every decision is an exact orientation of map
//!    vertices, V_p's vertices and p; the intervals are compared by the
//!    order of their directions around p. A violation is located (a point
//!    of e' seen or hidden wrongly) by the former method: cut e' where the
//!    lines through p and the map vertices meet it, and test every cut and
//!    piece midpoint with [`Map::sees`]; a test compares the two
//!    methods on degenerate and generic maps, true and wrong edges.
//!
//! What is not covered: viewpoints outside the sample.
//!
//! ## Cases
//! Each non-spurious edge by its kind (Def 3.5, read off the geometry):
//! **full** (e is all of e'), **half**, **partial** (e a proper part of
//! e', the rest hidden); and, counted besides, **collinear edges**: e' has
//! another map edge on its line (the case Remark 3.2 calls the source of
//! the problem's complexity, where the lemma says which one p sees).

use rug::{Integer, Rational};
use serde_json::json;
use std::cmp::Ordering;

use wai_exact::{
    det3_sign_i128, orientation, orientation_rat, side_of_line_rat, Orientation, Point, RatPoint,
    Side,
};
use wai_map::Map;
use wai_visibility::{EdgeKind, VisibilityPolygon};

use super::d3_5::kind_by_def;
use crate::framework::{Case, Checker, Report, Violation};
use wai_study::sample::{self, edge_collinear_with_viewpoint};
use wai_study::Study;

const ID: &str = "L3.1c";

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study).with_cases(&[
    Case {
        name: FULL,
        what: "a full edge of V_p (Def 3.5): all of its map edge",
    },
    Case {
        name: HALF,
        what: "a half edge of V_p (Def 3.5): a proper part of its map edge, one end spurious",
    },
    Case {
        name: PARTIAL,
        what: "a partial edge of V_p (Def 3.5): a proper part of its map edge, both ends \
               spurious",
    },
    Case {
        name: COLLINEAR,
        what: "a non-spurious edge whose map edge has another map edge on its line \
               (Remark 3.2)",
    },
]);

/// Case: a full edge.
pub const FULL: &str = "full";
/// Case: a half edge.
pub const HALF: &str = "half";
/// Case: a partial edge.
pub const PARTIAL: &str = "partial";
/// Case: the map edge has another map edge on its line.
pub const COLLINEAR: &str = "collinear edges";

/// Checks L3.1c on the sampled viewpoints of a map.
fn check_study(study: &Study<'_>) -> Report {
    super::over_sampled_polygons(ID, study, check_polygon)
}

/// L3.1c on one V_p of `map`: every non-spurious edge is one instance.
pub fn check_polygon(map: &Map, vp: &VisibilityPolygon) -> Report {
    let mut report = Report::new(ID);
    let pts: Vec<RatPoint> = map.vertices().iter().map(|&x| RatPoint::from(x)).collect();
    let turns = Turns::new(map, vp.viewpoint(), &pts);
    let edges = VpEdges::new(vp);
    for i in 0..vp.len() {
        if edges.collinear[i] {
            continue;
        }
        match kind_by_def(vp, i) {
            EdgeKind::Full => report.hit(FULL),
            EdgeKind::Half => report.hit(HALF),
            EdgeKind::Partial => report.hit(PARTIAL),
            EdgeKind::Spurious => {}
        }
        if vp.edges()[i]
            .map_edge
            .is_some_and(|k| k < map.n() && has_collinear_edge(map, k))
        {
            report.hit(COLLINEAR);
        }
        let problem = check_edge(map, &pts, &turns, vp, &edges, i);
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

/// Whether some other map edge lies on the line of map edge `k`.
fn has_collinear_edge(map: &Map, k: usize) -> bool {
    let (a, b) = (map.vertices()[k], map.vertices()[map.next(k)]);
    (0..map.n()).filter(|&j| j != k).any(|j| {
        let (c, d) = (map.vertices()[j], map.vertices()[map.next(j)]);
        orientation(a, b, c) == Orientation::Collinear
            && orientation(a, b, d) == Orientation::Collinear
    })
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
    /// `a` and `b` as given.
    ends: (Point, Point),
}

impl EdgeLine {
    fn new(a: Point, b: Point) -> EdgeLine {
        EdgeLine {
            a: (Rational::from(a.x), Rational::from(a.y)),
            d: (Rational::from(b.x - a.x), Rational::from(b.y - a.y)),
            ends: (a, b),
        }
    }

    /// λ of a point known to lie on the line: for `q = (X, Y) / W`,
    /// `((X − W·ax)·dx + (Y − W·ay)·dy) / (W·|d|²)`, in checked `i128`
    /// arithmetic when every value fits (exact: an overflow takes GMP).
    fn param(&self, q: &RatPoint) -> Rational {
        let small = || -> Option<(i128, i128)> {
            let (a, b) = self.ends;
            let (ax, ay) = (a.x, a.y);
            let (dx, dy) = (b.x.checked_sub(a.x)?, b.y.checked_sub(a.y)?);
            let (x, y, w) = (q.hx().to_i128()?, q.hy().to_i128()?, q.hw().to_i128()?);
            let ux = x.checked_sub(w.checked_mul(ax)?)?;
            let uy = y.checked_sub(w.checked_mul(ay)?)?;
            let dot = ux.checked_mul(dx)?.checked_add(uy.checked_mul(dy)?)?;
            let len2 = dx.checked_mul(dx)?.checked_add(dy.checked_mul(dy)?)?;
            Some((dot, w.checked_mul(len2)?))
        };
        if let Some((num, den)) = small() {
            return Rational::from((num, den));
        }
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

/// What [`check_edge`] reads of V_p's edges and vertices for every edge it
/// checks, computed once per polygon.
struct VpEdges {
    /// By edge: whether it is collinear with the viewpoint
    /// ([`edge_collinear_with_viewpoint`]).
    collinear: Vec<bool>,
    /// By vertex: its homogeneous coordinates `(X, Y, W)` if they fit an
    /// `i128`, for [`det3_sign_i128`].
    rows: Vec<Option<[i128; 3]>>,
}

impl VpEdges {
    fn new(vp: &VisibilityPolygon) -> VpEdges {
        VpEdges {
            collinear: (0..vp.len())
                .map(|i| edge_collinear_with_viewpoint(vp, i))
                .collect(),
            rows: vp.vertices().iter().map(|x| row(&x.point)).collect(),
        }
    }

    /// The orientation of map points `a`, `b` (as `pts` rows) and V_p's
    /// vertex `j`: the exact determinant in `i128` when it fits
    /// ([`det3_sign_i128`] checks every product), else GMP.
    fn orientation(
        &self,
        (a, ra): (&RatPoint, Option<[i128; 3]>),
        (b, rb): (&RatPoint, Option<[i128; 3]>),
        vp: &VisibilityPolygon,
        j: usize,
    ) -> Orientation {
        if let (Some(ra), Some(rb), Some(rj)) = (ra, rb, self.rows[j]) {
            if let Some(s) = det3_sign_i128(ra, rb, rj) {
                return Orientation::from_sign(s);
            }
        }
        orientation_rat(a, b, &vp.vertices()[j].point)
    }
}

/// The homogeneous coordinates of a rational point, if they fit an `i128`.
fn row(q: &RatPoint) -> Option<[i128; 3]> {
    Some([q.hx().to_i128()?, q.hy().to_i128()?, q.hw().to_i128()?])
}

/// The problem with non-spurious edge `i`, if any: a sentence and data.
fn check_edge(
    map: &Map,
    pts: &[RatPoint],
    turns: &Turns<'_>,
    vp: &VisibilityPolygon,
    edges: &VpEdges,
    i: usize,
) -> Option<(String, serde_json::Value)> {
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
    let (ea, eb) = (&pts[k], &pts[map.next(k)]);
    let (ea, eb) = ((ea, row(ea)), (eb, row(eb)));
    for j in (0..n).filter(|&j| j != i && !edges.collinear[j]) {
        let named = vp.edges()[j].map_edge == Some(k);
        // Both ends strictly on one side of e''s line: the midpoint too.
        let (oa, ob) = (
            edges.orientation(ea, eb, vp, j),
            edges.orientation(ea, eb, vp, (j + 1) % n),
        );
        let off_line = oa == ob && oa != Orientation::Collinear;
        let on = !off_line && {
            let mid = RatPoint::midpoint(&v[j].point, &v[(j + 1) % n].point);
            side_of_line_rat(&seg.line(), &mid) == Side::On && {
                let l = line.param(&mid);
                zero <= l && l <= one
            }
        };
        if named || on {
            return Some((
                format!("non-spurious edge {j} of V_p also lies on map edge {k}"),
                json!({"other_edge": j, "other_names_it": named}),
            ));
        }
    }
    // 3. p sees exactly open e of e', decided by the blocked intervals;
    //    a violation is located by probing with `sees`.
    if visible_part_is(map, turns, k, s, t) {
        return None;
    }
    Some(
        locate_by_cut_points(map, vp, k, &line, &ls, &lt).unwrap_or_else(|| {
            (
                format!(
                    "the part of map edge {k} that p sees is not the edge (blocked intervals), \
                 though no probe of the cut points shows where"
                ),
                json!({"probes_agree": false}),
            )
        }),
    )
}

/// Where visibility from p along map edge `k` differs from "exactly open
/// e", e = (`ls`, `lt`) in the parameters of `line`: cut e' at the lines
/// through p and each map vertex (between two consecutive cuts the nearest
/// map edge in every direction is fixed) and at e's endpoints, and test
/// every cut and the midpoint of every piece with [`Map::sees`].
/// `None` if every probe agrees. O(n) probes of O(n) each: used only to
/// locate a violation, and as the reference the interval method is tested
/// against.
fn locate_by_cut_points(
    map: &Map,
    vp: &VisibilityPolygon,
    k: usize,
    line: &EdgeLine,
    ls: &Rational,
    lt: &Rational,
) -> Option<(String, serde_json::Value)> {
    let (zero, one) = (Rational::new(), Rational::from(1));
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
        if l == *ls || l == *lt {
            continue; // e's endpoints: visible or not by the grazing rule
        }
        let want = *ls < l && l < *lt;
        let x = line.point(&l);
        let sight = map.sees(vp.viewpoint(), &x);
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

/// A direction from the viewpoint p: through map vertex `V(i)` or through
/// the exact point `P(q)`.
#[derive(Clone, Copy)]
enum D<'a> {
    V(usize),
    P(&'a RatPoint),
}

/// Turns around the viewpoint p = (X, Y) / W.
///
/// Implementation note: when `|X|, |Y| < 2^61` and `W·|v| < 2^61` for every
/// map vertex v (the bound of `wai_visibility`'s fast path), the
/// directions `W·v − (X, Y)` are below 2^62 per coordinate and the cross
/// product of two is below 2^125: exact in `i128`. They are computed once
/// per polygon; turns involving another point (V_p's vertices on e') take
/// [`orientation_rat`].
struct Turns<'a> {
    p: &'a RatPoint,
    pts: &'a [RatPoint],
    dirs: Option<Vec<(i128, i128)>>,
}

impl<'a> Turns<'a> {
    fn new(map: &Map, p: &'a RatPoint, pts: &'a [RatPoint]) -> Turns<'a> {
        const FAST: u32 = 61;
        let bits = map
            .vertices()
            .iter()
            .map(Point::magnitude_bits)
            .max()
            .unwrap_or(0);
        let fits = p.hx().significant_bits() <= FAST
            && p.hy().significant_bits() <= FAST
            && p.hw().significant_bits() + bits <= FAST;
        let dirs = fits.then(|| {
            let (x, y, w) = (
                p.hx().to_i128().expect("fits"),
                p.hy().to_i128().expect("fits"),
                p.hw().to_i128().expect("fits"),
            );
            map.vertices()
                .iter()
                .map(|v| (w * v.x - x, w * v.y - y))
                .collect()
        });
        Turns { p, pts, dirs }
    }

    fn point(&self, d: D<'a>) -> &'a RatPoint {
        match d {
            D::V(i) => &self.pts[i],
            D::P(q) => q,
        }
    }

    /// The orientation of (p, x, y).
    fn turn(&self, x: D<'a>, y: D<'a>) -> Orientation {
        if let (Some(dirs), D::V(i), D::V(j)) = (&self.dirs, x, y) {
            let (u, w) = (dirs[i], dirs[j]);
            return match (u.0 * w.1 - u.1 * w.0).cmp(&0) {
                Ordering::Greater => Orientation::CounterClockwise,
                Ordering::Less => Orientation::Clockwise,
                Ordering::Equal => Orientation::Collinear,
            };
        }
        orientation_rat(self.p, self.point(x), self.point(y))
    }
}

/// Directions from a viewpoint p inside the closed cone of a map edge
/// e' = (A, B) (p not on its line), ordered from A's to B's.
struct Cone<'a> {
    turns: &'a Turns<'a>,
    a: D<'a>,
    b: D<'a>,
    /// The turn from A to B around p.
    sense: Orientation,
}

impl<'a> Cone<'a> {
    /// The order of the directions of `x` and `y` (both in the cone).
    fn cmp(&self, x: D<'a>, y: D<'a>) -> Ordering {
        match self.turns.turn(x, y) {
            Orientation::Collinear => Ordering::Equal,
            o if o == self.sense => Ordering::Less,
            _ => Ordering::Greater,
        }
    }

    /// Whether the direction of `x` lies in the closed cone from `lo` to
    /// `hi` (turning in the cone's sense, less than half a turn).
    fn within(&self, lo: D<'a>, hi: D<'a>, x: D<'a>) -> bool {
        let ok = |o: Orientation| o == self.sense || o == Orientation::Collinear;
        ok(self.turns.turn(lo, x)) && ok(self.turns.turn(x, hi))
    }

    /// Whether the direction of `x` lies in the cone of e'.
    fn holds(&self, x: D<'a>) -> bool {
        self.within(self.a, self.b, x)
    }
}

/// An end of a blocked interval: a point whose direction from p bounds it,
/// and whether the direction itself is blocked.
#[derive(Clone, Copy)]
struct End<'a> {
    at: D<'a>,
    closed: bool,
}

/// The directions of e' in which a map edge hides e' from p (the points x
/// of e' whose segment px meets the edge elsewhere than at x).
#[derive(Clone, Copy)]
struct Blocked<'a> {
    lo: End<'a>,
    hi: End<'a>,
}

/// Whether the closed directions covered by `blocked` include every
/// direction of the cone from `from` to `to` (each end counted if its flag
/// says so).
fn covers<'a>(cone: &Cone<'a>, blocked: &[Blocked<'a>], from: End<'a>, to: End<'a>) -> bool {
    // Everything before `reach.at` is covered; `reach.at` itself iff closed.
    let mut reach = End {
        at: from.at,
        closed: !from.closed,
    };
    let done = |reach: End<'a>| match cone.cmp(reach.at, to.at) {
        Ordering::Greater => true,
        Ordering::Equal => reach.closed || !to.closed,
        Ordering::Less => false,
    };
    for j in blocked {
        if done(reach) {
            return true;
        }
        let gap = match cone.cmp(j.lo.at, reach.at) {
            Ordering::Greater => true,
            Ordering::Equal => !reach.closed && !j.lo.closed,
            Ordering::Less => false,
        };
        if gap {
            return false;
        }
        let further = match cone.cmp(j.hi.at, reach.at) {
            Ordering::Greater => true,
            Ordering::Equal => j.hi.closed && !reach.closed,
            Ordering::Less => false,
        };
        if further {
            reach = j.hi;
        }
    }
    done(reach)
}

/// Lemma 3.1(3) decided in one pass over the map edges: the points of map
/// edge `k` that the viewpoint `p` sees are exactly those of the open
/// segment (`s`, `t`), e's endpoints (on map edge k, in its direction)
/// aside. p must not lie on the line of edge k. `turns` are around p.
///
/// Every other map edge f (a closed segment) hides from p the points x of
/// e' whose segment px meets f elsewhere than at x (sec. 2.2: grazing a
/// vertex blocks). Those x form one interval of directions from p: the
/// directions common to f and e' if f lies in front of e' there (two
/// disjoint segments keep their order across the directions they share;
/// an edge sharing an endpoint of e' keeps it beyond that endpoint's
/// direction, which it does not block), or the one direction of f if p is
/// on f's line and f reaches nearer than e' in it. The part of e' that p
/// sees is what no interval covers.
fn visible_part_is(map: &Map, turns: &Turns<'_>, k: usize, s: &RatPoint, t: &RatPoint) -> bool {
    let v = map.vertices();
    let n = map.n();
    let (ia, ib) = (k, map.next(k));
    let (a, b) = (D::V(ia), D::V(ib));
    let sense = turns.turn(a, b);
    let cone = Cone { turns, a, b, sense };
    // Which side of e''s line p lies on (the orientation of (A, B, p), the
    // cone's sense); a point strictly there is in front.
    let p_side = sense;
    let in_front = |x: usize| orientation(v[ia], v[ib], v[x]) == p_side;
    let mut blocked: Vec<Blocked<'_>> = Vec::new();
    for j in (0..n).filter(|&j| j != k) {
        let (ic, id) = (j, map.next(j));
        let turn = turns.turn(D::V(ic), D::V(id));
        if turn == Orientation::Collinear {
            // p on f's line, off f: f is seen edge-on, in one direction.
            if cone.holds(D::V(ic)) && (in_front(ic) || in_front(id)) {
                let end = End {
                    at: D::V(ic),
                    closed: true,
                };
                blocked.push(Blocked { lo: end, hi: end });
            }
            continue;
        }
        let (first, second) = if turn == sense { (ic, id) } else { (id, ic) };
        let (f0, f1) = (D::V(first), D::V(second));
        let lo = if cone.holds(f0) {
            first
        } else if cone.within(f0, f1, a) {
            ia
        } else {
            continue;
        };
        let hi = if cone.holds(f1) {
            second
        } else if cone.within(f0, f1, b) {
            ib
        } else {
            continue;
        };
        // f shares an endpoint with e' (a neighbour of edge k): it does
        // not block that endpoint's direction, and is tested beyond it.
        let shared = [ia, ib].into_iter().find(|&x| x == ic || x == id);
        let probe = match shared {
            Some(x) if x == lo => hi,
            Some(_) => lo,
            None => lo,
        };
        if shared.is_some() && cone.cmp(D::V(lo), D::V(hi)) == Ordering::Equal {
            continue;
        }
        // In front at the probe direction: an endpoint of f nearer than
        // e', or an endpoint of e' behind f's line (p's side of f's line
        // is the orientation of (C, D, p), which is `turn`).
        let front = if probe == first || probe == second {
            in_front(probe)
        } else {
            let e_side = orientation(v[ic], v[id], v[probe]);
            e_side != turn && e_side != Orientation::Collinear
        };
        if front {
            blocked.push(Blocked {
                lo: End {
                    at: D::V(lo),
                    closed: shared != Some(lo),
                },
                hi: End {
                    at: D::V(hi),
                    closed: shared != Some(hi),
                },
            });
        }
    }
    let (s, t) = (D::P(s), D::P(t));
    // Nothing blocks a direction strictly between s and t.
    let meets_e = |j: &Blocked<'_>| match cone.cmp(j.lo.at, j.hi.at) {
        Ordering::Equal => {
            cone.cmp(s, j.lo.at) == Ordering::Less && cone.cmp(j.lo.at, t) == Ordering::Less
        }
        _ => cone.cmp(j.lo.at, t) == Ordering::Less && cone.cmp(s, j.hi.at) == Ordering::Less,
    };
    if blocked.iter().any(meets_e) {
        return false;
    }
    // Everything before s and after t is blocked.
    blocked.sort_by(|x, y| {
        cone.cmp(x.lo.at, y.lo.at)
            .then_with(|| y.lo.closed.cmp(&x.lo.closed))
    });
    let end = |at, closed| End { at, closed };
    covers(&cone, &blocked, end(a, true), end(s, false))
        && covers(&cone, &blocked, end(t, false), end(b, true))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fixtures::l_room;
    use wai_visibility::{EdgeKind, OnMap, VisEdge, VisVertex, VisibilityIndex};

    /// What a hole does to the lemma (thesis sec. 6.4): a pillar in front
    /// of a wall splits the part of the wall that p sees in two, two
    /// non-spurious edges of V_p on one map edge. The checker, which sees
    /// and locates against every ring, reports it; the lemma needs a map
    /// without holes.
    #[test]
    fn a_pillar_splits_the_wall_that_p_sees() {
        let pt = |x, y| Point::new(x, y);
        let (map, _) = Map::from_rings(
            vec![pt(0, 0), pt(10, 0), pt(10, 10), pt(0, 10)],
            vec![vec![pt(4, 4), pt(4, 6), pt(6, 6), pt(6, 4)]],
        )
        .expect("a room with a pillar");
        assert!(CHECKER.examines(&map));
        let p = RatPoint::from(pt(5, 1));
        let vp = VisibilityIndex::new(&map).visibility_polygon(&p).unwrap();
        let report = check_polygon(&map, &vp);
        assert!(report.examined > 0);
        assert!(
            report
                .violations
                .iter()
                .any(|v| v.what.contains("also lies on map edge 2")),
            "{:?}",
            report.violations
        );
    }

    proptest::proptest! {
        /// λ by the checked `i128` formula is the rational one, for points
        /// of the line with any denominator, near and beyond `i128`.
        #[test]
        fn param_agrees_with_rationals(
            a in (-(1i128 << 100) + 1..1 << 100, -(1i128 << 100) + 1..1 << 100),
            d in (-1000i128..1000, -1000i128..1000),
            k in -(1i128 << 70)..1 << 70,
            m in 1i128..1 << 60,
        ) {
            proptest::prop_assume!(d != (0, 0));
            let (a, b) = (Point::new(a.0, a.1), Point::new(a.0 + d.0, a.1 + d.1));
            let line = EdgeLine::new(a, b);
            // a + (k / m)·d
            let q = RatPoint::new(
                Integer::from(a.x) * m + Integer::from(k) * d.0,
                Integer::from(a.y) * m + Integer::from(k) * d.1,
                Integer::from(m),
            )
            .unwrap();
            proptest::prop_assert_eq!(line.param(&q), Rational::from((k, m)));
        }
    }

    fn at(x: i128, y: i128) -> RatPoint {
        RatPoint::from(Point::new(x, y))
    }

    #[test]
    fn a_correct_polygon_passes() {
        let (map, vp) = l_room();
        let r = check_polygon(&map, &vp);
        assert_eq!(r.examined, 4);
        assert!(r.violations.is_empty(), "{:?}", r.violations);
        assert_eq!(r.cases.get(FULL), Some(&3));
        assert_eq!(r.cases.get(HALF), Some(&1));
        let r = CHECKER.check_map(&map);
        assert!(r.examined > 0);
        assert!(r.violations.is_empty(), "{:?}", r.violations);
    }

    /// The interval method against the cut points probed with `sees`, on
    /// every non-spurious edge of V_p for degenerate and generic maps and
    /// viewpoints, with e's true endpoints and with wrong ones (the whole
    /// map edge, and e's ends swapped for the map edge's ends one at a
    /// time), so both verdicts are compared.
    #[test]
    fn the_interval_method_agrees_with_the_cut_points() {
        let mut maps: Vec<Map> = Vec::new();
        for kind in [
            "special-orthogonal",
            "special-comb",
            "special-chamfer",
            "random-orthogonal",
            "random-simple-star",
        ] {
            for seed in 0..6 {
                maps.push(wai_gen::random(kind, 14, seed).unwrap());
            }
        }
        maps.extend(wai_gen::exhaustive_polyomino_maps(
            5,
            wai_gen::Symmetry::Free,
        ));
        for id in ["corridor-niches", "comb-convex-chain", "overlap-fan"] {
            maps.push(wai_gen::family(id, &[2]).unwrap());
        }
        maps.push(crate::fixtures::doorway().0);
        // Pillars and holes: the intervals and the probes over every ring.
        for kind in ["orthogonal-pillars", "simple-holes"] {
            for seed in 0..4 {
                maps.push(wai_gen::random_with_holes(kind, 10, 2, seed).unwrap());
            }
        }
        let (mut compared, mut hidden) = (0, 0);
        for map in &maps {
            let index = VisibilityIndex::new(map);
            let pts: Vec<RatPoint> = map.vertices().iter().map(|&x| RatPoint::from(x)).collect();
            for p in wai_study::sample::viewpoints(map, 12) {
                let vp = index.visibility_polygon(&p).unwrap();
                let n = vp.len();
                for i in (0..n).filter(|&i| !edge_collinear_with_viewpoint(&vp, i)) {
                    let k = vp.edges()[i].map_edge.unwrap();
                    let line = EdgeLine::new(map.edge(k).a(), map.edge(k).b());
                    let (a, b) = (
                        RatPoint::from(map.edge(k).a()),
                        RatPoint::from(map.edge(k).b()),
                    );
                    let (s, t) = (&vp.vertices()[i].point, &vp.vertices()[(i + 1) % n].point);
                    for (s, t) in [(s, t), (&a, &b), (&a, t), (s, &b)] {
                        let (ls, lt) = (line.param(s), line.param(t));
                        let fast = visible_part_is(map, &Turns::new(map, &p, &pts), k, s, t);
                        let slow = locate_by_cut_points(map, &vp, k, &line, &ls, &lt).is_none();
                        assert_eq!(
                            fast,
                            slow,
                            "map {:?}, p = {p}, edge {k}, e = {s}..{t}",
                            map.vertices()
                        );
                        compared += 1;
                        hidden += u32::from(!fast);
                    }
                }
            }
        }
        assert!(compared > 5000 && hidden > 500, "{compared} {hidden}");
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
