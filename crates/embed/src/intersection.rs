//! The intersection of two embedded skeleton polygons (sec. 4.4): its
//! boundary as cycles of maximal edges, each edge's supporting edges in the
//! two polygons, its type (Lemma 4.7), and the crossings of artificial
//! edges behind Lemmas 4.5, 4.8 and 4.9 — exactly, with rationals.

mod fast;

pub use fast::FAST_BITS;

/// A ring as small integer points ([`FAST_BITS`]), if it is one.
pub(crate) fn fast_ring(r: &[QPoint]) -> Option<Vec<[i64; 2]>> {
    fast::small_ring(r)
}

/// Whether the interiors of two small integer rings overlap
/// ([`crate::interiors_overlap`]'s test after its box test).
pub(crate) fn fast_overlaps(p: &[[i64; 2]], q: &[[i64; 2]]) -> bool {
    fast::one_side_overlaps(p, q) || fast::one_side_overlaps(q, p)
}

use crate::piece::{segment_cuts, segments_meet};
use crate::witness::{locate, Locus};
use rug::Rational;
use std::cmp::Ordering;
use std::collections::HashSet;
use wai_exact::{Point, QPoint};

/// An embedded skeleton polygon h(V◇): its vertices counter-clockwise and,
/// by edge (from vertex i to i + 1), whether the edge is artificial.
///
/// The ring is converted to small integer points ([`FAST_BITS`]) once,
/// when it is made: the ring tests below (intersections, crossings of
/// artificial edges, pieces inside, overlaps) run on the integer form
/// whenever both rings have one, and a study asks them of the same rings
/// thousands of times.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SkeletonRing {
    pub ring: Vec<QPoint>,
    pub artificial: Vec<bool>,
    /// `ring` as small integer points, if every vertex is one.
    small: Option<Vec<fast::I>>,
    /// The bounding box `[x_lo, y_lo, x_hi, y_hi]` of `small`.
    small_box: [i64; 4],
}

impl SkeletonRing {
    /// From map points and the skeleton key's labels (`Some` = artificial).
    pub fn new(points: &[Point], artificial: Vec<bool>) -> SkeletonRing {
        let ring = points.iter().map(|&p| QPoint::from(p)).collect();
        let small = points
            .iter()
            .map(|p| Some([fast::small_int(p.x)?, fast::small_int(p.y)?]))
            .collect();
        SkeletonRing::with_small(ring, artificial, small)
    }

    /// From rational points and, by edge, whether it is artificial.
    pub fn from_ring(ring: Vec<QPoint>, artificial: Vec<bool>) -> SkeletonRing {
        let small = fast::small_ring(&ring);
        SkeletonRing::with_small(ring, artificial, small)
    }

    /// From the ring, its labels and its small integer form, if any.
    fn with_small(
        ring: Vec<QPoint>,
        artificial: Vec<bool>,
        small: Option<Vec<fast::I>>,
    ) -> SkeletonRing {
        let mut small_box = [i64::MAX, i64::MAX, i64::MIN, i64::MIN];
        for v in small.iter().flatten() {
            small_box = [
                small_box[0].min(v[0]),
                small_box[1].min(v[1]),
                small_box[2].max(v[0]),
                small_box[3].max(v[1]),
            ];
        }
        SkeletonRing {
            ring,
            artificial,
            small,
            small_box,
        }
    }

    pub fn edge(&self, i: usize) -> (&QPoint, &QPoint) {
        (&self.ring[i], &self.ring[(i + 1) % self.ring.len()])
    }

    /// The artificial edges.
    pub fn artificial_edges(&self) -> impl Iterator<Item = usize> + '_ {
        (0..self.ring.len()).filter(|&i| self.artificial[i])
    }

    /// Both rings in small integer points, if both have them.
    fn both_small<'a>(&'a self, o: &'a SkeletonRing) -> Option<(&'a [fast::I], &'a [fast::I])> {
        Some((self.small.as_deref()?, o.small.as_deref()?))
    }

    /// Whether the closed bounding boxes of two non-empty rings share a
    /// point ([`crate::Bounds::meets_box`] of their boxes).
    pub fn boxes_meet(&self, o: &SkeletonRing) -> bool {
        if self.both_small(o).is_some() && !self.ring.is_empty() && !o.ring.is_empty() {
            let (a, b) = (self.small_box, o.small_box);
            return !(a[2] < b[0] || b[2] < a[0] || a[3] < b[1] || b[3] < a[1]);
        }
        crate::Bounds::of(&self.ring).meets_box(&crate::Bounds::of(&o.ring))
    }

    /// [`crate::interiors_overlap`] of the two rings.
    pub fn interiors_overlap(&self, o: &SkeletonRing) -> bool {
        match self.both_small(o) {
            Some((p, q)) if !p.is_empty() && !q.is_empty() => {
                // The same box test as `interiors_overlap`: boxes sharing
                // no interior point.
                let (a, b) = (self.small_box, o.small_box);
                if a[2] <= b[0] || b[2] <= a[0] || a[3] <= b[1] || b[3] <= a[1] {
                    return false;
                }
                fast_overlaps(p, q)
            }
            _ => crate::interiors_overlap(&self.ring, &o.ring),
        }
    }

    /// Whether edge `i` of this ring and edge `j` of `o` meet other than
    /// in a common end ([`edges_meet`]).
    pub fn edges_meet(&self, i: usize, o: &SkeletonRing, j: usize) -> bool {
        match self.both_small(o) {
            Some((p, q)) => fast::edges_meet(
                [p[i], p[fast::next(i, p.len())]],
                [q[j], q[fast::next(j, q.len())]],
            ),
            None => edges_meet_rational(self.edge(i), o.edge(j)),
        }
    }

    /// Whether the boundaries of the two rings share a point.
    pub fn boundaries_meet(&self, o: &SkeletonRing) -> bool {
        let Some((p, q)) = self.both_small(o) else {
            let (p, q) = (&self.ring, &o.ring);
            let (np, nq) = (p.len(), q.len());
            return (0..np).any(|i| {
                (0..nq).any(|j| segments_meet(&p[i], &p[(i + 1) % np], &q[j], &q[(j + 1) % nq]))
            });
        };
        let (np, nq) = (p.len(), q.len());
        (0..np).any(|i| {
            let (a, b) = (p[i], p[fast::next(i, np)]);
            (0..nq).any(|j| fast::segments_meet(a, b, q[j], q[fast::next(j, nq)]))
        })
    }

    /// [`pieces_inside`] of edge `i` of this ring in the polygon `o`.
    pub fn edge_pieces_inside(&self, i: usize, o: &SkeletonRing) -> usize {
        match self.both_small(o) {
            Some((p, q)) => fast::pieces_inside(p[i], p[fast::next(i, p.len())], q),
            None => {
                let (a, b) = self.edge(i);
                pieces_inside_rational(a, b, &o.ring)
            }
        }
    }
}

/// Whether two closed segments meet other than in an end common to both.
pub fn edges_meet(a: (&QPoint, &QPoint), b: (&QPoint, &QPoint)) -> bool {
    if let (Some(a0), Some(a1), Some(b0), Some(b1)) = (
        fast::small(a.0),
        fast::small(a.1),
        fast::small(b.0),
        fast::small(b.1),
    ) {
        return fast::edges_meet([a0, a1], [b0, b1]);
    }
    edges_meet_rational(a, b)
}

/// [`edges_meet`] in GMP rationals.
pub fn edges_meet_rational(a: (&QPoint, &QPoint), b: (&QPoint, &QPoint)) -> bool {
    if !segments_meet(a.0, a.1, b.0, b.1) {
        return false;
    }
    let shared: Vec<&QPoint> = [a.0, a.1]
        .into_iter()
        .filter(|p| *p == b.0 || *p == b.1)
        .collect();
    if shared.is_empty() {
        return true;
    }
    // They share an end: do they meet anywhere else? Only if collinear and
    // overlapping beyond it.
    let da = a.1.sub(a.0);
    let db = b.1.sub(b.0);
    if da.cross_sign(&db) != Ordering::Equal {
        return false;
    }
    // Collinear with a common end: overlap beyond it iff they point the
    // same way from it.
    let x = shared[0];
    let away = |s: (&QPoint, &QPoint)| if s.0 == x { s.1.sub(x) } else { s.0.sub(x) };
    away(a).dot(&away(b)) > 0
}

/// The artificial edges of `other` that `ring`'s edge `i` meets (other
/// than in a common end).
pub fn artificial_crossings(ring: &SkeletonRing, i: usize, other: &SkeletonRing) -> Vec<usize> {
    other
        .artificial_edges()
        .filter(|&j| ring.edges_meet(i, other, j))
        .collect()
}

/// How many connected pieces (intervals, possibly single points) the
/// closed segment `ab` has inside the closed polygon `q`.
pub fn pieces_inside(a: &QPoint, b: &QPoint, q: &[QPoint]) -> usize {
    if let (Some(a), Some(b), Some(q)) = (fast::small(a), fast::small(b), fast::small_ring(q)) {
        return fast::pieces_inside(a, b, &q);
    }
    pieces_inside_rational(a, b, q)
}

/// [`pieces_inside`] in GMP rationals: the path for points beyond
/// [`FAST_BITS`], and the reference of the integer one.
pub fn pieces_inside_rational(a: &QPoint, b: &QPoint, q: &[QPoint]) -> usize {
    let mut cuts = vec![Rational::new(), Rational::from(1)];
    for j in 0..q.len() {
        cuts.extend(segment_cuts(a, b, &q[j], &q[(j + 1) % q.len()]));
    }
    cuts.sort();
    cuts.dedup();
    let d = b.sub(a);
    let inside = |t: &Rational| !matches!(locate(q, &a.along(&d, t)), Locus::Outside);
    // Alternate cut points and open stretches between them; count runs.
    let mut runs = 0;
    let mut previous = false;
    for (k, t) in cuts.iter().enumerate() {
        let at = inside(t);
        if at && !previous {
            runs += 1;
        }
        previous = at;
        if let Some(next) = cuts.get(k + 1) {
            let mid = Rational::from(t + next) / 2u32;
            let between = inside(&mid);
            if between && !previous {
                runs += 1;
            }
            previous = between;
        }
    }
    runs
}

/// An edge of the boundary of P ∩ Q — between two consecutive points that
/// are vertices of P or Q or crossings of their boundaries — directed with
/// the intersection on its left, and the edges of P and Q it lies on.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct BoundaryEdge {
    pub from: QPoint,
    pub to: QPoint,
    pub on_p: Option<usize>,
    pub on_q: Option<usize>,
}

/// The type of an edge of the intersection polygon (Lemma 4.7).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum EdgeType {
    /// A full edge in both embeddings.
    Full,
    /// An artificial edge in both, between the same two points.
    CommonArtificial,
    /// An artificial edge of one lying inside the other.
    ArtificialInside,
    /// Part of an artificial edge meeting exactly one artificial edge of
    /// the other, one end a map vertex.
    OneCrossing,
    /// Part of an artificial edge meeting exactly two artificial edges of
    /// the other, no end a map vertex.
    TwoCrossings,
}

impl EdgeType {
    /// The thesis's number, 1 to 5.
    pub fn number(self) -> u8 {
        match self {
            EdgeType::Full => 1,
            EdgeType::CommonArtificial => 2,
            EdgeType::ArtificialInside => 3,
            EdgeType::OneCrossing => 4,
            EdgeType::TwoCrossings => 5,
        }
    }
}

/// P ∩ Q for two embedded skeleton polygons.
#[derive(Clone, Debug)]
pub struct Intersection {
    /// The boundary's cycles of edges; a counter-clockwise
    /// cycle bounds a component of the intersection from outside, a
    /// clockwise one a hole.
    pub cycles: Vec<Vec<BoundaryEdge>>,
    /// The counter-clockwise cycles, counted once.
    components: usize,
}

/// A directed boundary piece before merging.
#[derive(Clone, Debug)]
struct Stretch {
    from: QPoint,
    to: QPoint,
    on_p: Option<usize>,
    on_q: Option<usize>,
}

/// The pieces of `p`'s edges on the boundary of the intersection with `q`:
/// cut where `q`'s boundary meets them, kept if the side on their left is
/// inside `q` (midpoint strictly inside, or on an edge of `q` running the
/// same way — then recorded on both). `shared`: keep the pieces along
/// `q`'s edges (only for one of the two polygons, so they count once).
fn boundary_pieces(p: &[QPoint], q: &[QPoint], p_is_first: bool, shared: bool) -> Vec<Stretch> {
    let mut out = Vec::new();
    for i in 0..p.len() {
        let (a, b) = (&p[i], &p[(i + 1) % p.len()]);
        let d = b.sub(a);
        let mut cuts = vec![Rational::new(), Rational::from(1)];
        for j in 0..q.len() {
            cuts.extend(segment_cuts(a, b, &q[j], &q[(j + 1) % q.len()]));
        }
        cuts.sort();
        cuts.dedup();
        for w in cuts.windows(2) {
            let mid = a.along(&d, &(Rational::from(&w[0] + &w[1]) / 2u32));
            let other = match locate(q, &mid) {
                Locus::Inside => None,
                Locus::Outside => continue,
                Locus::OnEdge(j) => {
                    let (c, e) = (&q[j], &q[(j + 1) % q.len()]);
                    if !shared || d.dot(&e.sub(c)) <= 0 {
                        continue;
                    }
                    Some(j)
                }
            };
            let (on_p, on_q) = if p_is_first {
                (Some(i), other)
            } else {
                (other, Some(i))
            };
            out.push(Stretch {
                from: a.along(&d, &w[0]),
                to: a.along(&d, &w[1]),
                on_p,
                on_q,
            });
        }
    }
    out
}

/// Clockwise angle order from direction `r`: directions just clockwise of
/// `r` first, `r` itself last.
fn clockwise_from(r: &QPoint, u: &QPoint, v: &QPoint) -> Ordering {
    let half = |w: &QPoint| {
        let c = r.cross_sign(w);
        // 0: strictly clockwise of r within a half turn (or opposite r);
        // 1: counter-clockwise of r, or r itself.
        u8::from(!(c == Ordering::Less || (c == Ordering::Equal && r.dot(w) < 0)))
    };
    half(u).cmp(&half(v)).then_with(|| v.cross_sign(u))
}

impl Intersection {
    /// The boundary of P ∩ Q (closed polygons, counter-clockwise, simple).
    /// Empty if the interiors do not meet. Polygons whose vertices are
    /// integer points below [`FAST_BITS`] (map vertices) take an integer
    /// path, the others [`Intersection::of_rational`]; the two agree.
    pub fn of(p: &[QPoint], q: &[QPoint]) -> Intersection {
        match (fast::small_ring(p), fast::small_ring(q)) {
            (Some(p), Some(q)) => fast::intersection(&p, &q),
            _ => Intersection::of_rational(p, q),
        }
    }

    /// [`Intersection::of`] of two skeleton rings, on their integer forms
    /// when both have one.
    pub fn of_rings(p: &SkeletonRing, q: &SkeletonRing) -> Intersection {
        match p.both_small(q) {
            Some((p, q)) => fast::intersection(p, q),
            None => Intersection::of_rational(&p.ring, &q.ring),
        }
    }

    /// [`Intersection::of`] in GMP rationals.
    pub fn of_rational(p: &[QPoint], q: &[QPoint]) -> Intersection {
        let mut pieces = boundary_pieces(p, q, true, true);
        pieces.extend(boundary_pieces(q, p, false, false));
        // Chain: at each end, of the pieces leaving it, take the first
        // clockwise from the way back, so that touching components stay
        // apart.
        let mut used = vec![false; pieces.len()];
        let mut cycles = Vec::new();
        for start in 0..pieces.len() {
            if used[start] {
                continue;
            }
            let mut cycle: Vec<Stretch> = Vec::new();
            let mut k = start;
            loop {
                used[k] = true;
                cycle.push(pieces[k].clone());
                let here = &pieces[k].to;
                let back = pieces[k].from.sub(here);
                let next = (0..pieces.len())
                    .filter(|&m| !used[m] || m == start)
                    .filter(|&m| pieces[m].from == *here)
                    .min_by(|&x, &y| {
                        clockwise_from(&back, &pieces[x].to.sub(here), &pieces[y].to.sub(here))
                    });
                match next {
                    Some(m) if m == start => break,
                    Some(m) => k = m,
                    None => break,
                }
            }
            cycles.push(edges_of(cycle));
        }
        Intersection::from_cycles(cycles)
    }

    /// From the boundary's cycles and how many of them run
    /// counter-clockwise.
    fn with_components(cycles: Vec<Vec<BoundaryEdge>>, components: usize) -> Intersection {
        Intersection { cycles, components }
    }

    /// From the boundary's cycles, counting the counter-clockwise ones.
    fn from_cycles(cycles: Vec<Vec<BoundaryEdge>>) -> Intersection {
        let components = cycles
            .iter()
            .filter(|c| {
                let area = c
                    .iter()
                    .fold(Rational::new(), |s, e| s + e.from.cross(&e.to));
                area > 0
            })
            .count();
        Intersection { cycles, components }
    }

    /// Connected components of the intersection: its counter-clockwise
    /// boundary cycles.
    pub fn components(&self) -> usize {
        self.components
    }
}

/// A cycle's pieces as edges. They are not merged where they continue
/// each other in a straight line: every such junction is a vertex of P or
/// Q (a map vertex), and the thesis's intersection polygon keeps those
/// (Fig 4.1 (a) has five collinear edges in a row; Lemma 4.7's proof).
fn edges_of(cycle: Vec<Stretch>) -> Vec<BoundaryEdge> {
    cycle
        .into_iter()
        .map(|s| BoundaryEdge {
            from: s.from,
            to: s.to,
            on_p: s.on_p,
            on_q: s.on_q,
        })
        .collect()
}

/// Lemma 4.7's type of boundary edge `e` of P ∩ Q, or `None` if it is of
/// none of the five. `map_vertices`: the map's vertices.
pub fn edge_type(
    e: &BoundaryEdge,
    p: &SkeletonRing,
    q: &SkeletonRing,
    map_vertices: &HashSet<QPoint>,
) -> Option<EdgeType> {
    let same = |x: (&QPoint, &QPoint)| {
        (x.0 == &e.from && x.1 == &e.to) || (x.0 == &e.to && x.1 == &e.from)
    };
    let full_p = e.on_p.filter(|&i| !p.artificial[i]);
    let full_q = e.on_q.filter(|&j| !q.artificial[j]);
    if full_p.is_some() || full_q.is_some() {
        return match (full_p, full_q) {
            (Some(i), Some(j)) if same(p.edge(i)) && same(q.edge(j)) => Some(EdgeType::Full),
            _ => None,
        };
    }
    if let (Some(i), Some(j)) = (e.on_p, e.on_q) {
        if same(p.edge(i)) && same(q.edge(j)) {
            return Some(EdgeType::CommonArtificial);
        }
    }
    // On an artificial edge of one, X, against the other, Y.
    let (x, i, y) = match (e.on_p, e.on_q) {
        (Some(i), None) => (p, i, q),
        (None, Some(j)) => (q, j, p),
        (Some(i), Some(_)) => (p, i, q),
        (None, None) => return None,
    };
    let alone = e.on_p.is_none() || e.on_q.is_none();
    if alone && same(x.edge(i)) {
        return Some(EdgeType::ArtificialInside);
    }
    let ends = [&e.from, &e.to]
        .into_iter()
        .filter(|v| map_vertices.contains(v))
        .count();
    let crossings = artificial_crossings(x, i, y).len();
    match (ends, crossings) {
        (1, 1) => Some(EdgeType::OneCrossing),
        (0, 2) => Some(EdgeType::TwoCrossings),
        _ => None,
    }
}

/// Left-right classification of Def 4.2: artificial edge `a` of one
/// embedding, seen from its witness `w`, against the line of an artificial
/// edge `b` of the other. `Some(true)` for LR (w and a's left end on the
/// same side of b), `Some(false)` for RL, `None` if a point lies on the
/// line or the ends are not told apart.
pub fn left_right(w: &QPoint, a: (&QPoint, &QPoint), b: (&QPoint, &QPoint)) -> Option<bool> {
    use wai_exact::turn;
    // The left end, viewed from w: the one counter-clockwise of the other.
    let (left, right) = match turn(w, a.0, a.1) {
        Ordering::Greater => (a.1, a.0),
        Ordering::Less => (a.0, a.1),
        Ordering::Equal => return None,
    };
    let side = |x: &QPoint| turn(b.0, b.1, x);
    let sw = side(w);
    if sw == Ordering::Equal {
        return None;
    }
    match (side(left) == sw, side(right) == sw) {
        (true, false) => Some(true),
        (false, true) => Some(false),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::piece::{ints as ring, U_RING as U};

    #[test]
    fn two_squares_one_square_of_intersection() {
        let p = ring(&[(0, 0), (4, 0), (4, 4), (0, 4)]);
        let q = ring(&[(2, 2), (6, 2), (6, 6), (2, 6)]);
        let x = Intersection::of(&p, &q);
        assert_eq!(x.components(), 1);
        assert_eq!(x.cycles[0].len(), 4);
        // A vertex of one on an edge of the other splits the edge there.
        let r = ring(&[(0, 2), (2, 2), (2, 6), (0, 6)]);
        assert_eq!(Intersection::of(&p, &r).cycles[0].len(), 4);
        let s = ring(&[(-2, 2), (4, 2), (4, 6), (-2, 6)]);
        let x = Intersection::of(&p, &s);
        assert_eq!(x.components(), 1);
        assert_eq!(x.cycles[0].len(), 4);
    }

    #[test]
    fn a_comb_and_a_bar_meet_in_two_components() {
        // A U shape and a bar across both of its arms.
        let u = ring(&U);
        let bar = ring(&[(-1, 3), (7, 3), (7, 5), (-1, 5)]);
        let x = Intersection::of(&u, &bar);
        assert_eq!(x.components(), 2);
        // Touching along an edge only: nothing.
        let beside = ring(&[(6, 0), (8, 0), (8, 2), (6, 2)]);
        assert_eq!(Intersection::of(&u, &beside).components(), 0);
    }

    /// The ring tests on the rings' cached integer form agree with the
    /// same tests on their rational points, on rings that share vertices,
    /// run along each other's edges, touch in corners and cross.
    #[test]
    fn ring_tests_on_the_integer_form_agree_with_rationals() {
        let shapes: Vec<Vec<(i64, i64)>> = vec![
            vec![(0, 0), (4, 0), (4, 4), (0, 4)],
            U.to_vec(),
            vec![(-1, 3), (7, 3), (7, 5), (-1, 5)],
            vec![(0, 0), (5, 1), (2, 4)],
            vec![(3, -1), (5, 1), (1, 5), (-1, 3)],
        ];
        let shifts = [(0, 0), (2, 2), (4, 0), (1, 3), (-3, 1), (6, 6)];
        let mut rings = Vec::new();
        for shape in &shapes {
            for &(dx, dy) in &shifts {
                let moved: Vec<(i64, i64)> = shape.iter().map(|&(x, y)| (x + dx, y + dy)).collect();
                let n = moved.len();
                rings.push(SkeletonRing::from_ring(ring(&moved), vec![true; n]));
            }
        }
        let rational = |r: &SkeletonRing| SkeletonRing {
            small: None,
            ..r.clone()
        };
        for p in &rings {
            assert!(p.small.is_some());
            for q in &rings {
                let (rp, rq) = (rational(p), rational(q));
                let (x, y) = (
                    Intersection::of_rings(p, q),
                    Intersection::of_rings(&rp, &rq),
                );
                assert_eq!(x.cycles, y.cycles);
                assert_eq!(x.components(), y.components());
                assert_eq!(p.boxes_meet(q), rp.boxes_meet(&rq));
                assert_eq!(
                    p.interiors_overlap(q),
                    crate::interiors_overlap_rational(&p.ring, &q.ring)
                );
                assert_eq!(p.boundaries_meet(q), rp.boundaries_meet(&rq));
                for i in 0..p.ring.len() {
                    assert_eq!(p.edge_pieces_inside(i, q), rp.edge_pieces_inside(i, &rq));
                    for j in 0..q.ring.len() {
                        assert_eq!(p.edges_meet(i, q, j), rp.edges_meet(i, &rq, j));
                    }
                }
            }
        }
    }

    /// The integer intersection equals the rational one on generated maps
    /// laid over each other at small offsets: collinear edges, shared
    /// vertices, corners on edges and proper crossings.
    #[test]
    fn integer_intersections_equal_rational_ones_on_generated_maps() {
        let rings: Vec<Vec<QPoint>> = (0..24)
            .map(|seed| {
                wai_gen::bytes::map_from_seed(seed)
                    .vertices()
                    .iter()
                    .map(|&p| QPoint::from(p))
                    .collect()
            })
            .collect();
        let shifted = |r: &[QPoint], dx: i64, dy: i64| -> Vec<QPoint> {
            r.iter()
                .map(|p| QPoint::new(Rational::from(&p.x + dx), Rational::from(&p.y + dy)))
                .collect()
        };
        let (mut compared, mut overlapping) = (0, 0);
        for (k, p) in rings.iter().enumerate() {
            for q in &rings[k..] {
                for (dx, dy) in [(0, 0), (1, 0), (0, 1), (2, 1), (-1, 3)] {
                    let q = shifted(q, dx, dy);
                    let (x, y) = (Intersection::of(p, &q), Intersection::of_rational(p, &q));
                    assert_eq!(
                        x.cycles, y.cycles,
                        "seed ring {k} against a ring shifted by ({dx}, {dy})"
                    );
                    assert_eq!(x.components(), y.components());
                    compared += 1;
                    overlapping += usize::from(x.components() > 0);
                }
            }
        }
        assert_eq!(compared, 5 * 24 * 25 / 2);
        assert!(
            overlapping > compared / 2,
            "{overlapping} of {compared} overlap"
        );
    }

    #[test]
    fn pieces_of_a_segment_inside_a_polygon() {
        let u = ring(&U);
        let pt = crate::piece::int;
        assert_eq!(pieces_inside(&pt(-1, 4), &pt(7, 4), &u), 2);
        assert_eq!(pieces_inside(&pt(-1, 1), &pt(7, 1), &u), 1);
        assert_eq!(pieces_inside(&pt(-1, 8), &pt(7, 8), &u), 0);
        // Touching the inner corner (2, 2) from above: one point.
        assert_eq!(pieces_inside(&pt(1, 3), &pt(3, 1), &u), 1);
    }

    #[test]
    fn meeting_edges_exclude_a_shared_end() {
        let pt = |x: i64, y: i64| QPoint::new(Rational::from(x), Rational::from(y));
        let (a, b, c) = (pt(0, 0), pt(2, 0), pt(2, 2));
        assert!(!edges_meet((&a, &b), (&b, &c)));
        assert!(edges_meet((&a, &b), (&pt(1, -1), &pt(1, 1))));
        // Collinear, sharing an end and overlapping beyond it.
        assert!(edges_meet((&a, &b), (&a, &pt(1, 0))));
        assert!(!edges_meet((&a, &b), (&b, &pt(3, 0))));
    }

    #[test]
    fn left_right_follows_def_4_2() {
        let pt = |x: i64, y: i64| QPoint::new(Rational::from(x), Rational::from(y));
        // w below, a horizontal above it from (-2, 2) to (2, 2): its left
        // end seen from w is (-2, 2).
        let w = pt(0, 0);
        let (a0, a1) = (pt(-2, 2), pt(2, 2));
        // b crosses a near its right end, running up and to the right: w
        // and the left end are on the same side → LR.
        assert_eq!(
            left_right(&w, (&a0, &a1), (&pt(1, 0), &pt(2, 4))),
            Some(true)
        );
        assert_eq!(
            left_right(&w, (&a0, &a1), (&pt(-1, 0), &pt(-2, 4))),
            Some(false)
        );
    }
}
