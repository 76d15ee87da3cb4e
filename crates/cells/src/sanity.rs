//! Layered sanity checks of an [`Arrangement`] (STYLE 4): topology first,
//! then geometry.

use crate::arrangement::{
    along, area_twice_rat, bbox, boxes_meet, meeting_pairs, on_closed_segment, Arrangement, Support,
};
use rug::Rational;
use wai_exact::{orientation_rat, Orientation, RatPoint};

impl Arrangement {
    /// Check every invariant; the error names the first that fails.
    ///
    /// Topology: twin(twin(h)) = h, next and prev inverse, origin(twin(h))
    /// = origin(next(h)), one face around each cycle, each face's cycle and
    /// each vertex's fan complete, Euler's V − E + F = 2 (the arrangement is
    /// connected: every ray starts at a map vertex).
    ///
    /// Geometry: every edge lies on its support (a map edge, or every ray
    /// covering it) in the support's direction; the outer face runs along
    /// map edges with area −area(M); every cell is a convex polygon
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
    pub fn check_geometry(&self) -> Result<(), String> {
        let mv = self.map.vertices();
        let n = mv.len();
        let map_pt = |i: usize| RatPoint::from(mv[i % n]);
        let points = self.points();
        // Edges on their supports, in the support's direction.
        for (e, geom) in self.edges.iter().enumerate() {
            let (a, b) = (self.half_edges[2 * e].origin, self.dest(2 * e));
            let (pa, pb) = (&points[a], &points[b]);
            if a == b || pa == pb {
                return Err(format!("edge {e}: zero length"));
            }
            let d = self.direction(2 * e);
            if along(d, pa) >= along(d, pb) {
                return Err(format!("edge {e}: against its support's direction"));
            }
            match geom.support {
                Support::MapEdge(i) => {
                    let (p, q) = (map_pt(i), map_pt(i + 1));
                    if !on_closed_segment(&p, &q, pa) || !on_closed_segment(&p, &q, pb) {
                        return Err(format!("edge {e}: off map edge {i}"));
                    }
                }
                Support::Rays(g) => {
                    if self.edge_rays(e).is_empty() {
                        return Err(format!("edge {e}: on group {g} but covered by no ray"));
                    }
                    for &r in self.edge_rays(e) {
                        let ray = &self.rays[r];
                        let s = map_pt(ray.anchor);
                        if !self.groups[g].rays.contains(&r)
                            || !on_closed_segment(&s, &ray.end.point, pa)
                            || !on_closed_segment(&s, &ray.end.point, pb)
                        {
                            return Err(format!("edge {e}: not covered by ray {r}"));
                        }
                    }
                }
            }
        }
        // The outer face: map edges only, area −area(M).
        let outer = self.outer_face();
        let outer_hs = self.face_half_edges(outer);
        if let Some(h) = outer_hs
            .iter()
            .find(|&&h| !matches!(self.edges[h / 2].support, Support::MapEdge(_)))
        {
            return Err(format!("outer face: half-edge {h} is not on a map edge"));
        }
        let map_area = Rational::from(self.map.area_twice());
        let ring: Vec<&RatPoint> = self
            .face_vertices(outer)
            .into_iter()
            .map(|v| &points[v])
            .collect();
        if area_twice_rat(&ring) != -map_area.clone() {
            return Err("outer face: area is not −area(M)".to_string());
        }
        // Cells: convex, counter-clockwise, positive area; areas sum up.
        let mut total = Rational::new();
        for f in self.cells() {
            let vs = self.face_vertices(f);
            let mut sorted = vs.clone();
            sorted.sort_unstable();
            sorted.dedup();
            if sorted.len() != vs.len() {
                return Err(format!("face {f}: a vertex repeats on its boundary"));
            }
            let ring: Vec<&RatPoint> = vs.iter().map(|&v| &points[v]).collect();
            let k = ring.len();
            for i in 0..k {
                let (a, b, c) = (ring[i], ring[(i + 1) % k], ring[(i + 2) % k]);
                let turn = orientation_rat(a, b, c);
                let ok = turn == Orientation::CounterClockwise
                    || (turn == Orientation::Collinear && on_closed_segment(a, c, b));
                if !ok {
                    return Err(format!(
                        "face {f}: not convex (turn at vertex {})",
                        vs[(i + 1) % k]
                    ));
                }
                for (j, p) in ring.iter().enumerate() {
                    if orientation_rat(a, b, p) == Orientation::Clockwise {
                        return Err(format!(
                            "face {f}: not convex (vertex {} right of its edge {} → {})",
                            vs[j],
                            vs[i],
                            vs[(i + 1) % k]
                        ));
                    }
                }
            }
            let area = area_twice_rat(&ring);
            if area <= 0 {
                return Err(format!("face {f}: area {area} ≤ 0"));
            }
            total += area;
        }
        if total != map_area {
            return Err(format!(
                "cells' areas sum to {total}, not area(M) {map_area}"
            ));
        }
        self.check_no_crossings()
    }

    /// No vertex in an edge's relative interior; no two edges cross or
    /// overlap. Candidates by integer bounding boxes, sorted by x.
    fn check_no_crossings(&self) -> Result<(), String> {
        let points = self.points();
        let ends = |e: usize| (self.half_edges[2 * e].origin, self.dest(2 * e));
        let eboxes: Vec<[i128; 4]> = (0..self.edges.len())
            .map(|e| {
                let (a, b) = ends(e);
                bbox([&points[a], &points[b]])
            })
            .collect();
        let vboxes: Vec<[i128; 4]> = points.iter().map(|p| bbox([p])).collect();
        // A point's box is at most 1 wide: sort by xmin and scan from
        // xmin ≥ eb[0] − 1 while xmin ≤ eb[2].
        let mut vorder: Vec<usize> = (0..points.len()).collect();
        vorder.sort_by_key(|&v| vboxes[v][0]);
        for (e, eb) in eboxes.iter().enumerate() {
            let (a, b) = ends(e);
            let from = vorder.partition_point(|&v| vboxes[v][0] < eb[0] - 1);
            for &v in &vorder[from..] {
                if vboxes[v][0] > eb[2] {
                    break;
                }
                if v == a || v == b || !boxes_meet(&vboxes[v], eb) {
                    continue;
                }
                if on_closed_segment(&points[a], &points[b], &points[v]) {
                    return Err(format!("vertex {v} lies in the interior of edge {e}"));
                }
            }
        }
        let bad = meeting_pairs(&eboxes, |e, f| {
            let why = self.edges_meet_badly(ends(e), ends(f))?;
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
        (a, b): (usize, usize),
        (c, d): (usize, usize),
    ) -> Option<&'static str> {
        let p = |v: usize| &self.points()[v];
        let shared = [a, b].iter().filter(|x| **x == c || **x == d).count();
        match shared {
            2 => Some("are the same segment"),
            1 => {
                let w = if a == c || a == d { a } else { b };
                let x = if w == a { b } else { a };
                let y = if w == c { d } else { c };
                // Overlap iff x and y lie on one ray from w.
                (orientation_rat(p(w), p(x), p(y)) == Orientation::Collinear
                    && !on_closed_segment(p(x), p(y), p(w)))
                .then_some("overlap")
            }
            _ => {
                let o = |u: usize, v: usize, t: usize| orientation_rat(p(u), p(v), p(t));
                let (o1, o2, o3, o4) = (o(a, b, c), o(a, b, d), o(c, d, a), o(c, d, b));
                let apart = |s: Orientation, t: Orientation| s == t && s != Orientation::Collinear;
                if apart(o1, o2) || apart(o3, o4) {
                    return None;
                }
                if [o1, o2, o3, o4]
                    .iter()
                    .all(|&s| s == Orientation::Collinear)
                {
                    let overlap = on_closed_segment(p(a), p(b), p(c))
                        || on_closed_segment(p(a), p(b), p(d))
                        || on_closed_segment(p(c), p(d), p(a));
                    return overlap.then_some("overlap");
                }
                Some("cross")
            }
        }
    }
}
