//! The part of a map edge that a map vertex sees (sec. 2.2), exactly.

use rug::Rational;
use std::cmp::Ordering;
use wai_exact::{BigVector, Point};
use wai_map::Map;

/// The points of map edge `e` (from `v[e]` to `v[e + 1]`) that map vertex
/// `y` sees, as positions `t ∈ [0, 1]` along the edge: open intervals, and
/// single points (an end of the edge that `y` sees, or `y` itself).
///
/// `y` sees a point x when the closed segment yx meets the boundary only in
/// y and x and runs through the map (sec. 2.2); a point sees itself. From
/// the view of `y` ([`wai_visibility::VisibilityIndex::vertex_view`]: the
/// open angular sectors of its interior angle, each with the map edge it
/// reaches first), `y` sees the points of `e` inside the open sectors that
/// reach `e`; in the direction of a vertex that bounds a sector the view
/// stops at that vertex (grazing blocks, sec. 2.2), so of `e` it sees there
/// only that vertex, if it is an end of `e`. Along its own edges `y` sees
/// nothing but itself (the segment lies on the boundary).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct EdgeSight {
    /// Open intervals `(lo, hi)`, `lo < hi`.
    open: Vec<(Rational, Rational)>,
    /// Single points.
    points: Vec<Rational>,
}

/// `a − b` in GMP integers.
fn diff(a: Point, b: Point) -> BigVector {
    BigVector::between(b, a)
}

impl EdgeSight {
    /// What map vertex `y` sees of map edge `e`; `view` is the view of `y`
    /// (`VisibilityIndex::vertex_view(y)`).
    pub fn of(map: &Map, view: &[(usize, usize)], y: usize, e: usize) -> EdgeSight {
        let v = map.vertices();
        let (e0, e1) = (e, map.next(e));
        let f = diff(v[e1], v[e0]);
        // Where the ray from y in direction d meets the line of e, as a
        // position along e: y + s·d = e0 + t·f gives
        // t = (y − e0) × d / (f × d).
        let at = |d: BigVector| -> Rational {
            let num = diff(v[y], v[e0]).cross(&d);
            let den = f.cross(&d);
            assert!(
                den != 0,
                "a sector that reaches edge {e} is not parallel to it at its ends"
            );
            Rational::from((num, den))
        };
        let mut open = Vec::new();
        for (i, &(lo, reached)) in view.iter().enumerate() {
            if reached != e {
                continue;
            }
            let hi = view.get(i + 1).map_or(map.prev(y), |s| s.0);
            let (a, b) = (at(diff(v[lo], v[y])), at(diff(v[hi], v[y])));
            let (a, b) = if a <= b { (a, b) } else { (b, a) };
            // Every ray of the open sector meets e, so its ends meet the
            // closed edge; clamped all the same.
            let (a, b) = (a.max(Rational::from(0)), b.min(Rational::from(1)));
            if a < b {
                open.push((a, b));
            }
        }
        let mut points = Vec::new();
        let seen_vertex = |u: usize| u != map.next(y) && view.iter().any(|&(lo, _)| lo == u);
        for (u, t) in [(e0, 0), (e1, 1)] {
            if u == y || seen_vertex(u) {
                points.push(Rational::from(t));
            }
        }
        EdgeSight { open, points }
    }

    /// The positions where what is seen changes: the ends of the open
    /// intervals and the single points, ascending.
    pub fn breakpoints(&self) -> Vec<Rational> {
        let mut all: Vec<Rational> = self
            .open
            .iter()
            .flat_map(|(a, b)| [a.clone(), b.clone()])
            .chain(self.points.iter().cloned())
            .collect();
        all.sort();
        all.dedup();
        all
    }

    /// Whether no point of the edge is seen.
    pub fn is_empty(&self) -> bool {
        self.open.is_empty() && self.points.is_empty()
    }

    /// Whether the position `t` is seen.
    pub fn contains(&self, t: &Rational) -> bool {
        self.points.iter().any(|p| p == t) || self.open.iter().any(|(a, b)| a < t && t < b)
    }

    /// Whether some point is seen in both: open intervals that overlap, or
    /// a single point of one that the other sees.
    pub fn meets(&self, other: &EdgeSight) -> bool {
        let overlap = |(a, b): &(Rational, Rational), (c, d): &(Rational, Rational)| {
            a.max(c).cmp(b.min(d)) == Ordering::Less
        };
        self.open
            .iter()
            .any(|i| other.open.iter().any(|j| overlap(i, j)))
            || self.points.iter().any(|p| other.contains(p))
            || other.points.iter().any(|p| self.contains(p))
    }
}
