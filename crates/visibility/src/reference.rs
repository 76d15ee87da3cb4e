//! The reference algorithm for V_p: exact, simple, O(n²).
//!
//! It defines what the production algorithms must compute. Sort the map
//! vertices by their direction from p; between two consecutive directions
//! no vertex is in view, so one map edge is nearest along every ray of the
//! open angular interval — found by testing every edge against a ray
//! strictly inside it. At each vertex direction the boundary of V_p jumps
//! along the ray from the nearest edge before to the nearest edge after (a
//! spurious edge, Def 3.4), or passes a corner where the two meet, or goes
//! straight on when they are the same edge. Maps with holes are read the
//! same way: a hole's edges are edges, and the outer ring surrounds p.

use crate::assemble::assemble;
use crate::polygon::{VisibilityError, VisibilityPolygon};
use rug::Integer;
use std::cmp::Ordering;
use wai_exact::{BigVector, Containment, RatPoint};
use wai_map::Map;

/// The map seen from p, translated to p and scaled by p's denominator so
/// that every coordinate is an integer.
struct Frame {
    /// `W·v_i − (X, Y)` for every map vertex `v_i`, with `p = (X, Y) / W`.
    rel: Vec<BigVector>,
    /// The vertex after each along its ring.
    next: Vec<usize>,
}

/// A fraction `num / den` with `den != 0`: the parameter of a point on a
/// ray from p.
#[derive(Clone, Debug)]
struct Param {
    num: Integer,
    den: Integer,
}

impl Param {
    fn cmp(&self, other: &Param) -> Ordering {
        let lhs = Integer::from(&self.num * &other.den);
        let rhs = Integer::from(&other.num * &self.den);
        let ord = lhs.cmp(&rhs);
        if (self.den < 0) != (other.den < 0) {
            ord.reverse()
        } else {
            ord
        }
    }
}

impl Frame {
    fn new(map: &Map, p: &RatPoint) -> Frame {
        let rel = map
            .vertices()
            .iter()
            .map(|&v| BigVector::toward(p, v))
            .collect();
        let next = (0..map.n()).map(|i| map.next(i)).collect();
        Frame { rel, next }
    }

    fn edge(&self, i: usize) -> (&BigVector, &BigVector) {
        (&self.rel[i], &self.rel[self.next[i]])
    }

    /// Where the ray in direction `d` meets the line of edge `i`:
    /// the parameter `s` with the point at `s·d`. `None` if parallel.
    fn hit_line(&self, d: &BigVector, i: usize) -> Option<Param> {
        let (a, b) = self.edge(i);
        let den = d.cross(&b.sub(a));
        (den != 0).then(|| Param {
            num: a.cross(b),
            den,
        })
    }

    /// Whether the ray in direction `r` crosses edge `i` in its interior, in
    /// front of p, given that no vertex lies on the ray.
    fn proper_hit(&self, r: &BigVector, i: usize) -> Option<Param> {
        let (a, b) = self.edge(i);
        let (sa, sb) = (r.cross_sign(a), r.cross_sign(b));
        let straddles = matches!(
            (sa, sb),
            (Ordering::Less, Ordering::Greater) | (Ordering::Greater, Ordering::Less)
        );
        if !straddles {
            return None;
        }
        let s = self.hit_line(r, i)?;
        (s.num.cmp0() == s.den.cmp0()).then_some(s)
    }

    /// The edge nearest to p along the ray in direction `r`.
    fn nearest(&self, r: &BigVector) -> Option<usize> {
        let mut best: Option<(usize, Param)> = None;
        for i in 0..self.rel.len() {
            if let Some(s) = self.proper_hit(r, i) {
                if best
                    .as_ref()
                    .is_none_or(|(_, b)| s.cmp(b) == Ordering::Less)
                {
                    best = Some((i, s));
                }
            }
        }
        best.map(|(i, _)| i)
    }
}

/// V_p of an interior point p of `map`, by the reference algorithm.
pub fn visibility_polygon(map: &Map, p: &RatPoint) -> Result<VisibilityPolygon, VisibilityError> {
    match map.locate(p) {
        Containment::Inside => {}
        Containment::OnBoundary => return Err(VisibilityError::OnBoundary(p.clone())),
        Containment::Outside => return Err(VisibilityError::Outside(p.clone())),
    }
    let frame = Frame::new(map, p);
    // Distinct vertex directions, counter-clockwise, each with one vertex.
    let mut order: Vec<usize> = (0..map.n()).collect();
    order.sort_by(|&i, &j| frame.rel[i].compare_angle(&frame.rel[j]));
    let mut dirs: Vec<usize> = Vec::new();
    for &i in &order {
        let new = dirs
            .last()
            .is_none_or(|&last| frame.rel[last].compare_angle(&frame.rel[i]) != Ordering::Equal);
        if new {
            dirs.push(i);
        }
    }
    let g = dirs.len();
    // The nearest edge on the open interval after each direction. For an
    // interior p consecutive directions are less than π apart, so their sum
    // lies strictly between them.
    let leaves: Vec<(usize, usize)> = (0..g)
        .map(|k| {
            let (a, b) = (&frame.rel[dirs[k]], &frame.rel[dirs[(k + 1) % g]]);
            debug_assert!(
                a.cross_sign(b) == Ordering::Greater,
                "gap of π or more around an interior point"
            );
            let r = a.add(b);
            let edge = frame
                .nearest(&r)
                .expect("every ray from an interior point leaves the map");
            (dirs[k], edge)
        })
        .collect();
    let coord_bits = map
        .vertices()
        .iter()
        .map(|v| v.magnitude_bits())
        .max()
        .unwrap_or(0);
    Ok(assemble(map, p, coord_bits, &leaves))
}
