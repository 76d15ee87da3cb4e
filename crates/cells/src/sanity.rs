//! Layered sanity checks of an [`Arrangement`]: topology first,
//! then geometry.

use crate::arrangement::{
    along, area_twice_rat, bbox, boxes_meet, meeting_pairs, on_closed_segment, Arrangement, Support,
};
use crate::eye::small_of;
use rug::Rational;
use std::cmp::Ordering;
use wai_exact::{orientation_rat, signed_area_twice, Orientation, Point, RatPoint, Vector};

impl Arrangement {
    /// Check every invariant; the error names the first that fails.
    ///
    /// Topology: twin(twin(h)) = h, next and prev inverse, origin(twin(h))
    /// = origin(next(h)), one face around each cycle, each face's cycle and
    /// each vertex's fan complete, Euler's V − E + F = 2 (the arrangement is
    /// connected: every ray starts at a map vertex, and with holes the
    /// holes' interiors count among the faces; see [`Arrangement`] for why
    /// rays join every hole to the outer ring).
    ///
    /// Geometry: every edge lies on its support (a map edge, or every ray
    /// covering it) in the support's direction; the outer face and each
    /// hole's interior run along map edges, with their ring's area reversed;
    /// every cell is a convex polygon
    /// (Thm 3.3a), counter-clockwise with positive area; the cells' areas sum
    /// to area(M) exactly; no vertex lies in an edge's relative interior; no
    /// two edges cross or overlap.
    pub fn sanity_check(&self) -> Result<(), String> {
        self.check_topology()?;
        self.check_geometry()
    }

    /// The topological layer of [`Arrangement::sanity_check`].
    pub fn check_topology(&self) -> Result<(), String> {
        let (nh, nv, nf) = (self.half_edges.len(), self.vertices.len(), self.faces.len());
        if nh != 2 * self.edges.len() {
            return Err(format!("{nh} half-edges for {} edges", self.edges.len()));
        }
        let np = self.points().len();
        if np != nv {
            return Err(format!("{np} points for {nv} vertices"));
        }
        for (h, he) in self.half_edges.iter().enumerate() {
            if he.twin >= nh || he.next >= nh || he.prev >= nh || he.origin >= nv || he.face >= nf {
                return Err(format!("half-edge {h}: index out of range: {he:?}"));
            }
            if he.twin == h || self.half_edges[he.twin].twin != h {
                return Err(format!("half-edge {h}: twin(twin(h)) != h"));
            }
            if he.twin / 2 != h / 2 {
                return Err(format!("half-edge {h}: twin {} on another edge", he.twin));
            }
            if self.half_edges[he.next].prev != h || self.half_edges[he.prev].next != h {
                return Err(format!("half-edge {h}: next and prev not inverse"));
            }
            if self.half_edges[he.next].origin != self.half_edges[he.twin].origin {
                return Err(format!("half-edge {h}: next does not start at its end"));
            }
            if self.half_edges[he.next].face != he.face {
                return Err(format!("half-edge {h}: next lies on another face"));
            }
        }
        for (v, vx) in self.vertices.iter().enumerate() {
            if vx.out >= nh || self.half_edges[vx.out].origin != v {
                return Err(format!("vertex {v}: out half-edge does not leave it"));
            }
        }
        let mut per_face = vec![0usize; nf];
        let mut per_vertex = vec![0usize; nv];
        for he in &self.half_edges {
            per_face[he.face] += 1;
            per_vertex[he.origin] += 1;
        }
        for (f, face) in self.faces.iter().enumerate() {
            if face.outer >= nh || self.half_edges[face.outer].face != f {
                return Err(format!("face {f}: outer half-edge not on it"));
            }
            let cycle = self.face_half_edges(f).len();
            if cycle != per_face[f] {
                return Err(format!(
                    "face {f}: cycle of {cycle} half-edges, {} on the face",
                    per_face[f]
                ));
            }
        }
        for (v, &count) in per_vertex.iter().enumerate() {
            if self.outgoing(v).len() != count {
                return Err(format!("vertex {v}: fan incomplete"));
            }
        }
        let euler = nv as i64 - self.edges.len() as i64 + nf as i64;
        if euler != 2 {
            return Err(format!(
                "Euler: V − E + F = {nv} − {} + {nf} = {euler} ≠ 2",
                self.edges.len()
            ));
        }
        Ok(())
    }

    /// The geometric layer of [`Arrangement::sanity_check`] (assumes the
    /// topology is sound).
    ///
    /// Every predicate is exact: on the points' `i128` homogeneous
    /// coordinates with checked products, on GMP where a product would
    /// overflow ([`Geo`]).
    pub fn check_geometry(&self) -> Result<(), String> {
        let mv = self.map.vertices();
        let geo = Geo::new(self);
        let map_pt = |i: usize| Pt::Map(mv[i]);
        // Edges on their supports, in the support's direction.
        for (e, geom) in self.edges.iter().enumerate() {
            let (a, b) = (self.half_edges[2 * e].origin, self.dest(2 * e));
            let (pa, pb) = (Pt::Vertex(a), Pt::Vertex(b));
            if a == b || geo.equal(pa, pb) {
                return Err(format!("edge {e}: zero length"));
            }
            let d = self.direction(2 * e);
            if geo.along(d, pa, pb) != Ordering::Less {
                return Err(format!("edge {e}: against its support's direction"));
            }
            match geom.support {
                Support::MapEdge(i) => {
                    let (p, q) = (map_pt(i), map_pt(self.map.next(i)));
                    let l = geo.map_lines[i];
                    if !geo.on_segment(l, p, q, a) || !geo.on_segment(l, p, q, b) {
                        return Err(format!("edge {e}: off map edge {i}"));
                    }
                }
                Support::Rays(g) => {
                    if self.edge_rays(e).is_empty() {
                        return Err(format!("edge {e}: on group {g} but covered by no ray"));
                    }
                    for &r in self.edge_rays(e) {
                        let ray = &self.rays[r];
                        let (s, t) = (map_pt(ray.anchor), Pt::Ray(r));
                        let l = geo.ray_lines[r];
                        if !self.groups[g].rays.contains(&r)
                            || !geo.on_segment(l, s, t, a)
                            || !geo.on_segment(l, s, t, b)
                        {
                            return Err(format!("edge {e}: not covered by ray {r}"));
                        }
                    }
                }
            }
        }
        // The outer face and each hole's interior: map edges only, with the
        // signed area of the ring they run along reversed (−area of the
        // outer ring, +area of the hole).
        let points = self.points();
        let not_cells = std::iter::once(("outer face".to_string(), self.outer_face(), 0)).chain(
            (0..self.map.hole_count()).map(|k| (format!("hole {k}"), self.hole_face(k), k + 1)),
        );
        for (name, face, ring) in not_cells {
            if let Some(h) = self
                .face_half_edges(face)
                .iter()
                .find(|&&h| !matches!(self.edges[h / 2].support, Support::MapEdge(_)))
            {
                return Err(format!("{name}: half-edge {h} is not on a map edge"));
            }
            let want = -Rational::from(signed_area_twice(self.map.ring(ring)));
            let cycle: Vec<&RatPoint> = self
                .face_vertices(face)
                .into_iter()
                .map(|v| &points[v])
                .collect();
            if area_twice_rat(&cycle) != want {
                return Err(format!("{name}: area is not that of its ring, reversed"));
            }
        }
        // Cells: convex, counter-clockwise, positive area. (That their
        // areas sum to area(M) needs no test: every half-edge lies on one
        // face and its twin runs the other way, so the signed areas of all
        // faces sum to 0, and the cells' to the outer ring's area minus the
        // holes'.)
        for f in self.cells() {
            let hs = self.face_half_edges(f);
            let vs: Vec<usize> = hs.iter().map(|&h| self.half_edges[h].origin).collect();
            let mut sorted = vs.clone();
            sorted.sort_unstable();
            sorted.dedup();
            if sorted.len() != vs.len() {
                return Err(format!("face {f}: a vertex repeats on its boundary"));
            }
            let k = vs.len();
            let at = |i: usize| Pt::Vertex(vs[i % k]);
            let mut strict = false;
            for i in 0..k {
                // a → b is half-edge hs[i]: its line decides the turns.
                let (a, b, c) = (at(i), at(i + 1), at(i + 2));
                let turn = geo.turn(hs[i], vs[(i + 2) % k]);
                strict |= turn == Orientation::CounterClockwise;
                let ok = turn == Orientation::CounterClockwise
                    || (turn == Orientation::Collinear && geo.on_closed_segment(a, c, b));
                if !ok {
                    return Err(format!(
                        "face {f}: not convex (turn at vertex {})",
                        vs[(i + 1) % k]
                    ));
                }
                for j in 0..k {
                    if geo.turn(hs[i], vs[j]) == Orientation::Clockwise {
                        return Err(format!(
                            "face {f}: not convex (vertex {} right of its edge {} → {})",
                            vs[j],
                            vs[i],
                            vs[(i + 1) % k]
                        ));
                    }
                }
            }
            // Convex and counter-clockwise (every vertex left of or on every
            // edge): the area is positive iff some turn is strict.
            if !strict {
                return Err(format!("face {f}: area 0"));
            }
        }
        self.check_no_crossings(&geo)
    }

    /// No vertex in an edge's relative interior; no two edges cross or
    /// overlap. Candidates by integer bounding boxes, sorted by x.
    fn check_no_crossings(&self, geo: &Geo<'_>) -> Result<(), String> {
        let ends = |e: usize| (self.half_edges[2 * e].origin, self.dest(2 * e));
        let vboxes: Vec<[i128; 4]> = (0..self.vertices.len()).map(|v| geo.bbox(v)).collect();
        let eboxes: Vec<[i128; 4]> = (0..self.edges.len())
            .map(|e| {
                let (a, b) = ends(e);
                let (p, q) = (&vboxes[a], &vboxes[b]);
                [
                    p[0].min(q[0]),
                    p[1].min(q[1]),
                    p[2].max(q[2]),
                    p[3].max(q[3]),
                ]
            })
            .collect();
        // A point's box is at most 1 wide: sort by xmin and scan from
        // xmin ≥ eb[0] − 1 while xmin ≤ eb[2].
        let mut vorder: Vec<usize> = (0..vboxes.len()).collect();
        vorder.sort_by_key(|&v| vboxes[v][0]);
        // The boxes in that order, side by side: the scans read them in turn.
        let vsorted: Vec<[i128; 4]> = vorder.iter().map(|&v| vboxes[v]).collect();
        for (e, eb) in eboxes.iter().enumerate() {
            let (a, b) = ends(e);
            let from = vsorted.partition_point(|vb| vb[0] < eb[0] - 1);
            for (vb, &v) in vsorted[from..].iter().zip(&vorder[from..]) {
                if vb[0] > eb[2] {
                    break;
                }
                if v == a || v == b || !boxes_meet(vb, eb) {
                    continue;
                }
                if geo.side(e, v) == Orientation::Collinear
                    && geo.on_closed_segment(Pt::Vertex(a), Pt::Vertex(b), Pt::Vertex(v))
                {
                    return Err(format!("vertex {v} lies in the interior of edge {e}"));
                }
            }
        }
        let bad = meeting_pairs(&eboxes, |e, f| {
            let why = self.edges_meet_badly(geo, (e, ends(e)), (f, ends(f)))?;
            Some(format!("edges {e} and {f} {why}"))
        });
        match bad.into_iter().next() {
            Some(why) => Err(why),
            None => Ok(()),
        }
    }

    /// Whether two edges meet other than in one shared end point.
    fn edges_meet_badly(
        &self,
        geo: &Geo<'_>,
        (e, (a, b)): (usize, (usize, usize)),
        (f, (c, d)): (usize, (usize, usize)),
    ) -> Option<&'static str> {
        let p = Pt::Vertex;
        let shared = [a, b].iter().filter(|x| **x == c || **x == d).count();
        match shared {
            2 => Some("are the same segment"),
            1 => {
                let w = if a == c || a == d { a } else { b };
                let x = if w == a { b } else { a };
                let y = if w == c { d } else { c };
                // Overlap iff x and y lie on one ray from w. (w, x, y)
                // are collinear iff y lies on the line of edge e (w, x).
                (geo.side(e, y) == Orientation::Collinear && !geo.between(x, y, w))
                    .then_some("overlap")
            }
            _ => {
                let apart = |s: Orientation, t: Orientation| s == t && s != Orientation::Collinear;
                // Most pairs that meet in their boxes are told apart by the
                // first line alone: its two tests before the other two.
                // (The orientation of (a, b, t) is the side of edge e's line
                // t lies on.)
                let (o1, o2) = (geo.side(e, c), geo.side(e, d));
                if apart(o1, o2) {
                    return None;
                }
                let (o3, o4) = (geo.side(f, a), geo.side(f, b));
                if apart(o3, o4) {
                    return None;
                }
                if [o1, o2, o3, o4]
                    .iter()
                    .all(|&s| s == Orientation::Collinear)
                {
                    let overlap = geo.on_closed_segment(p(a), p(b), p(c))
                        || geo.on_closed_segment(p(a), p(b), p(d))
                        || geo.on_closed_segment(p(c), p(d), p(a));
                    return overlap.then_some("overlap");
                }
                Some("cross")
            }
        }
    }
}

/// A point the sanity check asks about: an arrangement vertex, a map
/// vertex, or a ray's end.
#[derive(Clone, Copy)]
enum Pt {
    Vertex(usize),
    Map(Point),
    /// The end of ray `r`.
    Ray(usize),
}

/// The sanity check's predicates: on `i128` homogeneous coordinates with
/// every product checked, falling back to the GMP predicates of
/// `wai_exact` and `crate::arrangement` when a value does not fit (so the
/// answers are exact either way; a test compares the two paths).
///
/// The orientation of `(a, b, t)` for an edge `a → b` is asked of many
/// points `t` (the convexity of each cell, the pairs of edges that may
/// cross): it is the sign of `det(a; b; t) = (a × b) · t` for the
/// homogeneous triples, so each edge's line `a × b` is built once
/// ([`Geo::side`]).
struct Geo<'a> {
    arr: &'a Arrangement,
    /// By edge: the line `a × b` through its ends, if built without
    /// overflow, and the bits of its largest coefficient.
    lines: Vec<Option<([i128; 3], u32)>>,
    /// By vertex: the bits of its largest homogeneous coordinate, if they
    /// fit an `i128`.
    bits: Vec<Option<u32>>,
    /// By map edge: its line, as `lines`.
    map_lines: Vec<Option<([i128; 3], u32)>>,
    /// By ray: its end's homogeneous coordinates, if they fit.
    ray_ends: Vec<Option<[i128; 3]>>,
    /// By ray: the line from its anchor to its end, as `lines`.
    ray_lines: Vec<Option<([i128; 3], u32)>>,
}

/// The line through two points as [`Geo`] keeps it: coefficients and the
/// bits of the largest.
fn line_with_bits(a: Option<[i128; 3]>, b: Option<[i128; 3]>) -> Option<([i128; 3], u32)> {
    let l = line_through(a?, b?)?;
    Some((l, l.iter().map(|&c| magnitude_bits(c)).max().unwrap_or(0)))
}

/// Bits of `|v|`: `|v| < 2^magnitude_bits(v)`.
fn magnitude_bits(v: i128) -> u32 {
    128 - v.unsigned_abs().leading_zeros()
}

/// The cross product `a × b` of two homogeneous triples: the line through
/// the two points (`(a × b) · t = 0` iff t is on it). `None` on overflow.
fn line_through(a: [i128; 3], b: [i128; 3]) -> Option<[i128; 3]> {
    let minor = |i: usize, j: usize| a[i].checked_mul(b[j])?.checked_sub(a[j].checked_mul(b[i])?);
    Some([minor(1, 2)?, minor(2, 0)?, minor(0, 1)?])
}

impl<'a> Geo<'a> {
    fn new(arr: &'a Arrangement) -> Geo<'a> {
        let bits: Vec<Option<u32>> = arr
            .small
            .iter()
            .map(|t| t.map(|t| t.iter().map(|&c| magnitude_bits(c)).max().unwrap_or(0)))
            .collect();
        let lines = (0..arr.edges.len())
            .map(|e| {
                let (a, b) = (arr.half_edges[2 * e].origin, arr.dest(2 * e));
                line_with_bits(arr.small[a], arr.small[b])
            })
            .collect();
        let mv = arr.map.vertices();
        let map_pt = |i: usize| Some([mv[i].x, mv[i].y, 1]);
        let map_lines = (0..mv.len())
            .map(|i| line_with_bits(map_pt(i), map_pt(arr.map.next(i))))
            .collect();
        let ray_ends: Vec<Option<[i128; 3]>> =
            arr.rays.iter().map(|r| small_of(&r.end.point)).collect();
        let ray_lines = arr
            .rays
            .iter()
            .zip(&ray_ends)
            .map(|(r, &t)| line_with_bits(map_pt(r.anchor), t))
            .collect();
        Geo {
            arr,
            lines,
            bits,
            map_lines,
            ray_ends,
            ray_lines,
        }
    }

    /// The sign of `l · v` for the line `l` (coefficients below `2^lb`) and
    /// vertex `v`, if the bound of [`Geo::side`] holds.
    fn line_side(&self, l: Option<([i128; 3], u32)>, v: usize) -> Option<Orientation> {
        let ((l, lb), pb) = (l?, self.bits[v]?);
        if lb + pb + 2 > 127 {
            return None;
        }
        let p = self.arr.small[v].expect("bits are of small points");
        let s = if lb < 64 && pb < 64 {
            // Every entry is an i64 value: 64 × 64 → 128-bit products.
            let w = |a: i128, b: i128| wai_exact::mul_wide(a as i64, b as i64);
            w(l[0], p[0])
                .wrapping_add(w(l[1], p[1]))
                .wrapping_add(w(l[2], p[2]))
        } else {
            l[0].wrapping_mul(p[0])
                .wrapping_add(l[1].wrapping_mul(p[1]))
                .wrapping_add(l[2].wrapping_mul(p[2]))
        };
        Some(match s.cmp(&0) {
            Ordering::Greater => Orientation::CounterClockwise,
            Ordering::Less => Orientation::Clockwise,
            Ordering::Equal => Orientation::Collinear,
        })
    }

    /// Whether vertex `v` lies on the closed segment from `a` to `b`, whose
    /// line `a × b` is `l` when built: [`Geo::on_closed_segment`], with the
    /// orientation read off the line.
    fn on_segment(&self, l: Option<([i128; 3], u32)>, a: Pt, b: Pt, v: usize) -> bool {
        match self.line_side(l, v) {
            Some(Orientation::Collinear) => {}
            Some(_) => return false,
            None => return self.on_closed_segment(a, b, Pt::Vertex(v)),
        }
        if let (Some(sa), Some(sb), Some(p)) = (self.small(a), self.small(b), self.arr.small[v]) {
            if let Some(s) = toward_dot_sign(p, sa, sb) {
                return s != Ordering::Greater;
            }
        }
        on_closed_segment(&self.exact(a), &self.exact(b), &self.exact(Pt::Vertex(v)))
    }

    /// The orientation of `(a, b, v)` for edge `e` from `a` to `b` and
    /// vertex `v`: the sign of `(a × b) · v`.
    ///
    /// Implementation note: with the line's coefficients below `2^lb` and
    /// the point's below `2^pb`, each of the three products is below
    /// `2^(lb + pb)` and their sum below `2^(lb + pb + 2)`: when that is at
    /// most `2^127` nothing overflows and the wrapping operations are
    /// exact. Otherwise, as [`Geo::orientation`].
    fn side(&self, e: usize, v: usize) -> Orientation {
        if let Some(o) = self.line_side(self.lines[e], v) {
            return o;
        }
        let (a, b) = (self.arr.half_edges[2 * e].origin, self.arr.dest(2 * e));
        self.orientation(Pt::Vertex(a), Pt::Vertex(b), Pt::Vertex(v))
    }

    /// Whether vertex `w` lies on the closed segment from vertex `x` to
    /// vertex `y`, the three being collinear: [`Geo::on_closed_segment`]
    /// without its orientation test.
    fn between(&self, x: usize, y: usize, w: usize) -> bool {
        let s = &self.arr.small;
        if let (Some(a), Some(b), Some(p)) = (s[x], s[y], s[w]) {
            if let Some(s) = toward_dot_sign(p, a, b) {
                return s != Ordering::Greater;
            }
        }
        let pt = |v: usize| &self.arr.points()[v];
        on_closed_segment(pt(x), pt(y), pt(w))
    }

    /// The orientation of `(origin(h), dest(h), v)` for half-edge `h`.
    fn turn(&self, h: usize, v: usize) -> Orientation {
        let o = self.side(h / 2, v);
        if h.is_multiple_of(2) {
            o
        } else {
            match o {
                Orientation::CounterClockwise => Orientation::Clockwise,
                Orientation::Clockwise => Orientation::CounterClockwise,
                Orientation::Collinear => Orientation::Collinear,
            }
        }
    }

    fn small(&self, p: Pt) -> Option<[i128; 3]> {
        match p {
            Pt::Vertex(v) => self.arr.small[v],
            Pt::Map(q) => Some([q.x, q.y, 1]),
            Pt::Ray(r) => self.ray_ends[r],
        }
    }

    fn exact<'b>(&'b self, p: Pt) -> std::borrow::Cow<'b, RatPoint> {
        match p {
            Pt::Vertex(v) => std::borrow::Cow::Borrowed(&self.arr.points()[v]),
            Pt::Map(q) => std::borrow::Cow::Owned(RatPoint::from(q)),
            Pt::Ray(r) => std::borrow::Cow::Borrowed(&self.arr.rays[r].end.point),
        }
    }

    fn equal(&self, a: Pt, b: Pt) -> bool {
        match (self.small(a), self.small(b)) {
            // Both in lowest terms with w > 0: equal points, equal triples.
            (Some(x), Some(y)) => x == y,
            _ => self.exact(a) == self.exact(b),
        }
    }

    fn orientation(&self, a: Pt, b: Pt, c: Pt) -> Orientation {
        if let (Some(a), Some(b), Some(c)) = (self.small(a), self.small(b), self.small(c)) {
            if let Some(o) = orientation_small(a, b, c) {
                return o;
            }
        }
        orientation_rat(&self.exact(a), &self.exact(b), &self.exact(c))
    }

    /// Whether `p` lies on the closed segment `ab`.
    fn on_closed_segment(&self, a: Pt, b: Pt, p: Pt) -> bool {
        if self.orientation(a, b, p) != Orientation::Collinear {
            return false;
        }
        if let (Some(a), Some(b), Some(p)) = (self.small(a), self.small(b), self.small(p)) {
            if let Some(s) = toward_dot_sign(p, a, b) {
                return s != Ordering::Greater;
            }
        }
        on_closed_segment(&self.exact(a), &self.exact(b), &self.exact(p))
    }

    /// The order of `a` and `b` along the direction `d`.
    fn along(&self, d: Vector, a: Pt, b: Pt) -> Ordering {
        if let (Some([ax, ay, aw]), Some([bx, by, bw])) = (self.small(a), self.small(b)) {
            // d·a − d·b has the sign of d·(a·bw − b·aw) (aw, bw > 0).
            let s = || -> Option<i128> {
                let ux = ax.checked_mul(bw)?.checked_sub(bx.checked_mul(aw)?)?;
                let uy = ay.checked_mul(bw)?.checked_sub(by.checked_mul(aw)?)?;
                d.x.checked_mul(ux)?.checked_add(d.y.checked_mul(uy)?)
            };
            if let Some(s) = s() {
                return s.cmp(&0);
            }
        }
        along(d, &self.exact(a)).cmp(&along(d, &self.exact(b)))
    }

    /// An integer box around vertex `v` (floors and ceilings).
    fn bbox(&self, v: usize) -> [i128; 4] {
        match self.arr.small[v] {
            Some([x, y, w]) => {
                let fl = |c: i128| c.div_euclid(w);
                let ce = |c: i128| -(-c).div_euclid(w);
                [fl(x), fl(y), ce(x), ce(y)]
            }
            None => bbox([&self.arr.points()[v]]),
        }
    }
}

/// The orientation of three points `[x, y, w]` (w > 0): the sign of the
/// 3×3 determinant of their rows (`wai_exact::det3_sign_i128`: unchecked
/// below its proven bound, checked above); `None` on overflow.
fn orientation_small(a: [i128; 3], b: [i128; 3], c: [i128; 3]) -> Option<Orientation> {
    Some(match wai_exact::det3_sign_i128(a, b, c)? {
        Ordering::Greater => Orientation::CounterClockwise,
        Ordering::Less => Orientation::Clockwise,
        Ordering::Equal => Orientation::Collinear,
    })
}

/// The sign of (a − p)·(b − p) for points `[x, y, w]` (w > 0), in checked
/// `i128`; `None` on overflow.
fn toward_dot_sign(p: [i128; 3], a: [i128; 3], b: [i128; 3]) -> Option<Ordering> {
    // (a − p) ∝ (ax·pw − px·aw, ay·pw − py·aw), scaled by aw·pw > 0.
    let rel = |q: [i128; 3]| -> Option<(i128, i128)> {
        Some((
            q[0].checked_mul(p[2])?
                .checked_sub(p[0].checked_mul(q[2])?)?,
            q[1].checked_mul(p[2])?
                .checked_sub(p[1].checked_mul(q[2])?)?,
        ))
    };
    let (u, v) = (rel(a)?, rel(b)?);
    Some(
        u.0.checked_mul(v.0)?
            .checked_add(u.1.checked_mul(v.1)?)?
            .cmp(&0),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The `i128` predicates agree with `wai_exact`'s on points of every
    /// size, and decline past their range.
    #[test]
    fn small_predicates_agree_with_gmp() {
        let mut rng = 0x2545_f491_4f6c_dd1du64;
        let mut next = |bits: u32| {
            rng ^= rng << 13;
            rng ^= rng >> 7;
            rng ^= rng << 17;
            let v = (rng % (1u64 << bits.min(63))) as i128;
            if rng & 1 == 0 {
                v
            } else {
                -v
            }
        };
        let (mut small, mut declined) = (0, 0);
        for bits in [2u32, 8, 20, 30, 40, 45, 62] {
            for _ in 0..400 {
                let mut pt = || {
                    let w = next(bits).abs().max(1);
                    let p = RatPoint::from_i128(next(bits), next(bits), w).unwrap();
                    (small_of(&p).unwrap(), p)
                };
                let (a, b, c) = (pt(), pt(), pt());
                // Collinear triples too: c on the line through a and b.
                let mid = RatPoint::midpoint(&a.1, &b.1);
                let m = (small_of(&mid).unwrap_or([0, 0, 1]), mid);
                for (x, y, z) in [(&a, &b, &c), (&a, &b, &m)] {
                    match orientation_small(x.0, y.0, z.0) {
                        Some(o) => {
                            assert_eq!(o, orientation_rat(&x.1, &y.1, &z.1));
                            small += 1;
                        }
                        None => declined += 1,
                    }
                }
                if let Some(s) = toward_dot_sign(m.0, a.0, b.0) {
                    assert_eq!(s != Ordering::Greater, on_closed_segment(&a.1, &b.1, &m.1));
                }
            }
        }
        assert!(small > 1000 && declined > 100, "{small} {declined}");
    }

    /// The side of a vertex against an edge's line built once equals the
    /// orientation of the three points, on arrangements small and scaled
    /// past the `i128` lines.
    #[test]
    fn sides_of_edge_lines_agree_with_orientations() {
        use crate::rays::visibility_rays;
        let (mut fast, mut all) = (0, 0);
        for kind in wai_gen::RANDOM_KINDS {
            for seed in 0..2 {
                let map = wai_gen::random(kind.id, kind.min_n.max(8) + 2, seed).unwrap();
                for shift in [0u32, 31, 50] {
                    let map = map.scaled_up(shift).unwrap();
                    let arr = Arrangement::new(&map, &visibility_rays(&map));
                    let geo = Geo::new(&arr);
                    for e in 0..arr.edge_count() {
                        let (a, b) = (arr.half_edges[2 * e].origin, arr.dest(2 * e));
                        fast += usize::from(geo.lines[e].is_some());
                        for v in 0..arr.vertex_count() {
                            let want = geo.orientation(Pt::Vertex(a), Pt::Vertex(b), Pt::Vertex(v));
                            assert_eq!(geo.side(e, v), want, "edge {e}, vertex {v}");
                            all += 1;
                        }
                    }
                    let mv = map.vertices();
                    for v in 0..arr.vertex_count() {
                        for i in 0..mv.len() {
                            let (p, q) = (Pt::Map(mv[i]), Pt::Map(mv[map.next(i)]));
                            let want = geo.on_closed_segment(p, q, Pt::Vertex(v));
                            assert_eq!(geo.on_segment(geo.map_lines[i], p, q, v), want);
                        }
                        for (r, ray) in arr.rays.iter().enumerate() {
                            let (s, t) = (Pt::Map(mv[ray.anchor]), Pt::Ray(r));
                            let want = geo.on_closed_segment(s, t, Pt::Vertex(v));
                            assert_eq!(geo.on_segment(geo.ray_lines[r], s, t, v), want);
                        }
                    }
                }
            }
        }
        assert!(fast > 100 && all > 10_000, "{fast} lines, {all} sides");
    }
}
