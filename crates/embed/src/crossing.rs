//! Def 4.4: crossing candidate edges, decided exactly over whole witness
//! regions.
//!
//! # The lines of sight of one witness cell through one artificial edge
//! Let h(a) = (v1, v2) be an embedded artificial edge, h(V◇) on its left,
//! and w a witness of h in the cell C. V_w has skeleton V*, so behind h(a)
//! it has a pocket: the triangle cut off by the rays from w through v1 and
//! v2, closed by the partial (or half) edge, which lies on one map edge c,
//! the same for every point of C ([`crate::witness_views`]). So w sees
//! through h(a) exactly the open interval (s1(w), s2(w)) of c between the
//! two rays, and nothing is in the way. Lines grazing v1 or v2 do not pass
//! *through* h(a) (nor do they see, by the rule of sec. 2.2). The union
//! U(C, a) of the lines of sight [w, p], w ∈ C, p ∈ c, through h(a) is
//! therefore
//!
//! ```text
//! C ∪ int conv(C̄ ∪ h(a)) ∪ h(a)° ∪ B° ∪ (t1, t2)
//! ```
//!
//! - before h(a): a point lies on an open segment from a point of C to a
//!   point of h(a)° iff it is in C or inside the hull;
//! - behind h(a): a point x lies on such a line iff the open wedge from x
//!   through h(a) meets C, iff C meets both open half-planes bounded by the
//!   lines x v1 and x v2 on the wedge's side (C is connected and the two
//!   closed outer parts are disjoint). The limits are the lines through v1
//!   and through v2 and the vertices u of C̄ whose rays u→v1, u→v2 reach
//!   farthest out on c's line, at t1 and t2 (a ray's end on a line is
//!   monotone along a segment, so the extremes are at vertices). B is the
//!   polygon v2, v1, t1, t2, a triangle when h(a) ends on c's line;
//! - on c's line: the union of the intervals (s1(w), s2(w)), which is
//!   (t1, t2) as C is relatively open.
//!
//! Each part is a relatively open convex [`Piece`], so whether two such
//! unions share a point is decided exactly and completely piece by piece.
//!
//! # Certificates
//! A shared point x comes with a witness and a point of the candidate
//! edge on each side whose line of sight passes through x, found from x
//! (a point of C in the wedge that reaches x), and re-checked: the segment
//! sees (`wai_exact::sees`), crosses h(a)° and ends on c. A failed
//! re-check panics: it would be a bug in the region above.

use std::cmp::Ordering;

use rug::Rational;
use wai_exact::{convex_hull, turn, QPoint};
use wai_map::Map;

use crate::piece::{line_cut, segments_meet, Bounds, Piece};

/// The lines of sight from one witness cell through one embedded
/// artificial edge to the candidate edge the cell sees (module doc).
#[derive(Clone, Debug)]
pub struct SightFan {
    /// The witness cell's index in its [`crate::Witnesses`].
    pub cell: usize,
    /// The artificial edge: its index among the skeleton's edges.
    pub artificial: usize,
    /// The map edge seen through it.
    pub edge: usize,
    /// h(a), counter-clockwise along h(V◇).
    pub v1: QPoint,
    pub v2: QPoint,
    /// The candidate edge's ends.
    c: (QPoint, QPoint),
    /// The witness cell.
    witnesses: Piece,
    /// The parts in h(V◇): the open hull, h(a)°, and the cell unless it
    /// is a 2-cell (inside the hull).
    pub inside: Vec<Piece>,
    /// The parts behind h(a): B° and (t1, t2).
    pub beyond: Vec<Piece>,
    /// The box of each part, `beyond` then `inside`.
    boxes: Vec<Bounds>,
    bounds: Bounds,
}

/// Two lines of sight that meet (Def 4.4), each from a witness `w` to a
/// point `p` of its candidate edge, and a point `at` they share.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Crossing {
    pub at: QPoint,
    pub first: (QPoint, QPoint),
    pub second: (QPoint, QPoint),
}

/// The end on c's line (`ray_end`) of the ray from a corner through `v`
/// of least (`first`) or greatest `along`, over the corners whose rays are
/// not parallel to `c_dir`: the points compared one by one.
fn extreme_by_points(
    corners: &[QPoint],
    v: &QPoint,
    first: bool,
    c_dir: &QPoint,
    ray_end: &impl Fn(&QPoint, &QPoint) -> QPoint,
    along: &impl Fn(&QPoint) -> Rational,
) -> QPoint {
    let ends = corners
        .iter()
        .filter(|u| v.sub(u).cross_sign(c_dir) != Ordering::Equal)
        .map(|u| ray_end(u, v));
    let best = if first {
        ends.min_by_key(|p| along(p))
    } else {
        ends.max_by_key(|p| along(p))
    };
    best.expect("a cell has a vertex")
}

/// [`extreme_by_points`] when `rising`, the sign of `c_dir · dir`, is not
/// zero: the corner of least or greatest parameter s on c's line
/// (`c.0 + s·c.1`), ordered as `along` is, and the end of its ray only.
fn extreme_by_parameter(
    corners: &[QPoint],
    v: &QPoint,
    first: bool,
    (c0, c_dir): (&QPoint, &QPoint),
    rising: Ordering,
    ray_end: &impl Fn(&QPoint, &QPoint) -> QPoint,
) -> QPoint {
    let vc = v.sub(c0);
    // A corner whose ray runs parallel to c's line is skipped: the cell's
    // other rays all reach c, so its limit is no extreme.
    let mut best: Option<(Rational, &QPoint)> = None;
    for u in corners {
        let w = u.sub(v);
        let den = c_dir.cross(&w);
        if den == 0 {
            continue;
        }
        let s = vc.cross(&w) / den;
        // The least `along` when `first`, else the greatest.
        let better = best.as_ref().is_none_or(|(b, _)| {
            let o = s.cmp(b);
            let o = if rising == Ordering::Less {
                o.reverse()
            } else {
                o
            };
            if first {
                o == Ordering::Less
            } else {
                o == Ordering::Greater
            }
        });
        if better {
            best = Some((s, u));
        }
    }
    let (_, u) = best.expect("a cell has a vertex");
    ray_end(u, v)
}

impl SightFan {
    /// The lines of sight from the witness cell `witnesses` (index `cell`)
    /// through the artificial edge `artificial`, from `v1` to `v2`
    /// counter-clockwise along h(V◇), to the map edge `edge` from `c0` to
    /// `c1`, which the cell sees through it.
    ///
    /// # Panics
    /// If the cell is not strictly inside the edge's line, or a ray from
    /// it through `v1` or `v2` does not reach the edge (neither can happen
    /// for a witness, whose V_w has the pocket of the module doc).
    pub fn new(
        witnesses: &Piece,
        cell: usize,
        artificial: usize,
        (v1, v2): (QPoint, QPoint),
        edge: usize,
        (c0, c1): (QPoint, QPoint),
    ) -> SightFan {
        let corners = witnesses.vertices();
        let w0 = witnesses.inner_point();
        // The cell is inside h(a)'s line; its closure may touch the line
        // (a cell along a wall that h(a) continues).
        assert!(
            turn(&v1, &v2, &w0) == Ordering::Greater
                && corners.iter().all(|u| turn(&v1, &v2, u) != Ordering::Less),
            "witness cell {cell} is not inside artificial edge {v1}–{v2}"
        );
        let ray_end = |u: &QPoint, v: &QPoint| line_cut(u, v, &c0, &c1);
        // Along c's line, from the s1 side to the s2 side.
        let origin = ray_end(&w0, &v1);
        let dir = ray_end(&w0, &v2).sub(&origin);
        let along = |p: &QPoint| p.sub(&origin).dot(&dir);
        let c_dir = c1.sub(&c0);
        // The ray from a corner u through v meets c's line at c0 + s·c_dir
        // with s = ((v − c0) × (u − v)) / (c_dir × (u − v)); `along` is
        // (s − s_origin)·(c_dir · dir), so when c_dir · dir ≠ 0 the extreme
        // corner is the one of least or greatest s, found without the
        // points, and corners of equal s reach the same point.
        let rising = c_dir.dot(&dir).cmp0();
        let extreme = |v: &QPoint, first: bool| -> QPoint {
            if rising == Ordering::Equal {
                return extreme_by_points(&corners, v, first, &c_dir, &ray_end, &along);
            }
            extreme_by_parameter(&corners, v, first, (&c0, &c_dir), rising, &ray_end)
        };
        let (t1, t2) = (extreme(&v1, true), extreme(&v2, false));
        for t in [&t1, &t2] {
            assert!(
                segments_meet(t, t, &c0, &c1),
                "witness cell {cell} sees past map edge {edge} through {v1}–{v2}"
            );
        }
        // Largest parts first (a shared point is found sooner); a 2-cell
        // lies inside the open hull, so it is not a part of its own.
        let mut all = corners.clone();
        all.extend([v1.clone(), v2.clone()]);
        let mut inside = vec![Piece::Polygon(convex_hull(all))];
        inside.push(Piece::Segment(v1.clone(), v2.clone()));
        if witnesses.dimension() < 2 {
            inside.push(witnesses.clone());
        }
        let mut beyond = Vec::new();
        let b = convex_hull(vec![v2.clone(), v1.clone(), t1.clone(), t2.clone()]);
        if b.len() >= 3 {
            beyond.push(Piece::Polygon(b));
        }
        if t1 != t2 {
            beyond.push(Piece::Segment(t1, t2));
        }
        let points: Vec<QPoint> = inside
            .iter()
            .chain(&beyond)
            .flat_map(Piece::vertices)
            .collect();
        let boxes = beyond
            .iter()
            .chain(&inside)
            .map(|p| Bounds::of(&p.vertices()))
            .collect();
        SightFan {
            boxes,
            cell,
            artificial,
            edge,
            v1,
            v2,
            c: (c0, c1),
            witnesses: witnesses.clone(),
            inside,
            beyond,
            bounds: Bounds::of(&points),
        }
    }

    /// Every part of the union of the lines of sight.
    pub fn pieces(&self) -> impl Iterator<Item = &Piece> {
        self.beyond.iter().chain(&self.inside)
    }

    /// A point shared by a line of sight of this fan and one of `other`:
    /// of any part, or (`beyond_only`) of the parts behind the artificial
    /// edges only.
    pub fn meets(&self, other: &SightFan, beyond_only: bool) -> Option<QPoint> {
        if !self.bounds.meets_box(&other.bounds) {
            return None;
        }
        let k = |f: &SightFan| {
            if beyond_only {
                f.beyond.len()
            } else {
                f.boxes.len()
            }
        };
        let (mine, theirs) = (k(self), k(other));
        for (p, bp) in self.pieces().zip(&self.boxes).take(mine) {
            for (q, bq) in other.pieces().zip(&other.boxes).take(theirs) {
                if bp.meets_box(bq) {
                    if let Some(x) = p.common_point(q) {
                        return Some(x);
                    }
                }
            }
        }
        None
    }

    /// The witness cell the lines of sight start from.
    pub fn witness_piece(&self) -> &Piece {
        &self.witnesses
    }

    /// Whether every line of sight of the fan meets the closed segment
    /// [a, b] (Lemma 5.13's "crosses h(a)"): `Some(true)` when shown for all
    /// of them, `Some(false)` with a line of sight that misses it, `None`
    /// when neither test settles it.
    ///
    /// Every line of sight is [w, q] ∪ [q, p] with w in the cell, q on the
    /// open window h(a) and p on (t1, t2). All of them meet [a, b] if it is
    /// the window or holds it on its line; or if the line ab strictly
    /// separates the window from (t1, t2) (or the cell from the window) and
    /// cuts the hull of the two inside [a, b] — that hull holds every
    /// part behind (before) the window, and its cut by the line is spanned
    /// by the cuts of the segments between their vertices. A miss is
    /// looked for on the lines from the cell's inner point through the
    /// window at 1/4, 1/2 and 3/4, each a line of sight (module doc).
    pub fn lines_meet_segment(&self, a: &QPoint, b: &QPoint) -> Option<bool> {
        let (v1, v2) = (&self.v1, &self.v2);
        let on_ab = |z: &QPoint| segments_meet(z, z, a, b);
        if turn(a, b, v1) == Ordering::Equal
            && turn(a, b, v2) == Ordering::Equal
            && on_ab(v1)
            && on_ab(v2)
        {
            return Some(true);
        }
        let side = |z: &QPoint| turn(a, b, z);
        // Whether the line ab strictly separates the open convex sets with
        // closures spanned by `p` and `q` (`p_in`, `q_in` inner points) and
        // cuts their hull inside [a, b].
        let cuts_inside = |p: &[QPoint], p_in: &QPoint, q: &[QPoint], q_in: &QPoint| -> bool {
            let sp = side(p_in);
            if sp == Ordering::Equal || side(q_in) != sp.reverse() {
                return false;
            }
            if p.iter().any(|z| side(z) == sp.reverse()) || q.iter().any(|z| side(z) == sp) {
                return false;
            }
            p.iter().all(|u| {
                q.iter().all(|t| {
                    let x = match (side(u), side(t)) {
                        (Ordering::Equal, _) => u.clone(),
                        (_, Ordering::Equal) => t.clone(),
                        _ => line_cut(u, t, a, b),
                    };
                    on_ab(&x)
                })
            })
        };
        let window = [v1.clone(), v2.clone()];
        let mid = v1.add(v2).scale(&Rational::from((1, 2)));
        // (t1, t2): the segment part behind the window, if it has one.
        let landing: Vec<QPoint> = self
            .beyond
            .iter()
            .find(|x| matches!(x, Piece::Segment(..)))
            .map(Piece::vertices)
            .unwrap_or_default();
        let cell = self.witnesses.vertices();
        let w0 = self.witnesses.inner_point();
        if cuts_inside(&cell, &w0, &window, &mid) {
            return Some(true);
        }
        if let [t1, t2] = &landing[..] {
            let t_in = t1.add(t2).scale(&Rational::from((1, 2)));
            if cuts_inside(&window, &mid, &landing, &t_in) {
                return Some(true);
            }
        }
        for k in [1u32, 2, 3] {
            let q = v1.along(&v2.sub(v1), &Rational::from((k, 4)));
            let p = line_cut(&w0, &q, &self.c.0, &self.c.1);
            if !segments_meet(&w0, &p, a, b) {
                return Some(false);
            }
        }
        None
    }

    /// A witness `w` of the cell and a point `p` of the candidate edge
    /// whose line of sight through h(a) passes through `x`, a point of the
    /// fan. Re-checked against `map` (every ring).
    ///
    /// # Panics
    /// If no such line is found or it fails the re-check (a bug).
    pub fn sight_through(&self, map: &Map, x: &QPoint) -> (QPoint, QPoint) {
        let (v1, v2) = (&self.v1, &self.v2);
        let to_c = |w: &QPoint, through: &QPoint| line_cut(w, through, &self.c.0, &self.c.1);
        let on_c_line = turn(&self.c.0, &self.c.1, x) == Ordering::Equal;
        let (w, p) = if self.witnesses.contains(x) {
            let mid = v1.add(v2).scale(&Rational::from((1, 2)));
            (x.clone(), to_c(x, &mid))
        } else {
            let w = match turn(v1, v2, x) {
                Ordering::Equal => Some(self.witnesses.inner_point()),
                // Before h(a): w behind x, in the wedge opposite h(a).
                Ordering::Greater => self
                    .witnesses
                    .clip(x, v1, turn(x, v1, v2).reverse())
                    .and_then(|c| c.clip(x, v2, turn(x, v2, v1).reverse()))
                    .map(|c| c.inner_point()),
                // Behind h(a): w in the wedge from x through h(a).
                Ordering::Less => self
                    .witnesses
                    .clip(x, v1, turn(x, v1, v2))
                    .and_then(|c| c.clip(x, v2, turn(x, v2, v1)))
                    .map(|c| c.inner_point()),
            };
            let w = w.unwrap_or_else(|| panic!("no witness's line of sight reaches {x}"));
            let p = if on_c_line { x.clone() } else { to_c(&w, x) };
            (w, p)
        };
        self.recheck(map, x, &w, &p);
        (w, p)
    }

    fn recheck(&self, map: &Map, x: &QPoint, w: &QPoint, p: &QPoint) {
        let (v1, v2) = (&self.v1, &self.v2);
        let through = turn(v1, v2, w) == Ordering::Greater
            && turn(v1, v2, p) == Ordering::Less
            && turn(w, p, v1) == turn(w, p, v2).reverse()
            && turn(w, p, v1) != Ordering::Equal;
        let ok = self.witnesses.contains(w)
            && through
            && segments_meet(p, p, &self.c.0, &self.c.1)
            && segments_meet(x, x, w, p)
            && map.sees(&w.to_rat_point(), &p.to_rat_point()).is_visible();
        assert!(
            ok,
            "the line of sight {w}–{p} through {v1}–{v2} found for {x} fails its re-check: a bug in the sight fans"
        );
    }
}

/// An embedded artificial edge [x, y] between two map vertices whose
/// relative interior runs through the map's interior: a chord, which cuts
/// the map into two parts (the boundary arc from x forward to y, closed by
/// the chord, and the rest).
///
/// Lines of sight meet the boundary only at their ends (sec. 2.2), so one
/// meets the chord iff its ends lie in different parts: this decides
/// whether *all* lines of sight of a fan cross it, exactly, where
/// [`SightFan::lines_meet_segment`]'s hull tests may not.
#[derive(Debug, Clone)]
pub struct Chord {
    x: QPoint,
    y: QPoint,
    /// Vertex indices of x and y, and n.
    ix: usize,
    iy: usize,
    n: usize,
    /// The part of the arc from x to y: its vertices, x first.
    part: Vec<QPoint>,
}

impl Chord {
    /// The chord [x, y] of `ring`, if x and y are distinct map vertices and
    /// no other boundary point lies on the segment.
    pub fn new(ring: &[QPoint], x: &QPoint, y: &QPoint) -> Option<Chord> {
        let n = ring.len();
        let ix = ring.iter().position(|v| v == x)?;
        let iy = ring.iter().position(|v| v == y)?;
        // Equal or adjacent vertices: no chord (a map edge is boundary).
        if ix == iy || (ix + 1) % n == iy || (iy + 1) % n == ix {
            return None;
        }
        for k in 0..n {
            let (a, b) = (&ring[k], &ring[(k + 1) % n]);
            // An edge that touches the open chord: a vertex on it, or a
            // crossing (edges at x or y touch it only there).
            let at_ends = |v: &QPoint| v == x || v == y;
            if !at_ends(a) && segments_meet(a, a, x, y) {
                return None;
            }
            if !at_ends(a) && !at_ends(b) && segments_meet(a, b, x, y) {
                return None;
            }
        }
        let len = (iy + n - ix) % n;
        let part = (0..=len).map(|k| ring[(ix + k) % n].clone()).collect();
        Some(Chord {
            x: x.clone(),
            y: y.clone(),
            ix,
            iy,
            n,
            part,
        })
    }

    /// Whether map edge `e` (from vertex e to e + 1) lies on the arc from x
    /// to y.
    fn edge_in_part(&self, e: usize) -> bool {
        (e + self.n - self.ix) % self.n < (self.iy + self.n - self.ix) % self.n
    }

    /// Whether a point off the chord and off the boundary lies in the part
    /// of the arc from x to y (crossing parity of a rightward ray).
    fn point_in_part(&self, z: &QPoint) -> bool {
        let m = self.part.len();
        let mut inside = false;
        for k in 0..m {
            let (a, b) = (&self.part[k], &self.part[(k + 1) % m]);
            if (a.y > z.y) != (b.y > z.y) {
                // The edge crosses the horizontal line through z; is the
                // crossing right of z? Its sign against the edge's direction.
                let t = turn(a, b, z);
                if (b.y > a.y) == (t == Ordering::Greater) {
                    inside = !inside;
                }
            }
        }
        inside
    }

    /// Whether every line of sight of `fan` meets the chord: `Some(true)`
    /// if its witness cell and its candidate edge lie in different parts,
    /// `Some(false)` if some of its witnesses lie in the edge's part.
    pub fn crossed_by(&self, fan: &SightFan) -> Option<bool> {
        let cell = fan.witness_piece();
        let chord = Piece::Segment(self.x.clone(), self.y.clone());
        let edge_side = self.edge_in_part(fan.edge);
        if cell.meets(&chord) {
            let corners = cell.vertices();
            if corners
                .iter()
                .all(|v| turn(&self.x, &self.y, v) == Ordering::Equal)
            {
                // Along the chord's line: on it (every line starts on the
                // chord) or partly beyond an end (left open).
                return corners
                    .iter()
                    .all(|v| segments_meet(v, v, &self.x, &self.y))
                    .then_some(true);
            }
            // Witnesses on both sides of the chord near it, so some in the
            // edge's part: their lines of sight stay there.
            return Some(false);
        }
        Some(self.point_in_part(&cell.inner_point()) != edge_side)
    }
}

/// Def 4.4 for two fans: a pair of lines of sight, one of each, that meet
/// (anywhere, or behind both artificial edges with `beyond_only`),
/// certified against `map` (every ring).
pub fn crossing(map: &Map, f: &SightFan, g: &SightFan, beyond_only: bool) -> Option<Crossing> {
    let at = f.meets(g, beyond_only)?;
    Some(Crossing {
        first: f.sight_through(map, &at),
        second: g.sight_through(map, &at),
        at,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::piece::int as pt;

    /// The extreme ray end by parameter is the one found by comparing the
    /// points, for lines of either direction, either `along` sense, and
    /// corners with ties and rays parallel to the line.
    #[test]
    fn extreme_by_parameter_is_extreme_by_points() {
        let corners: Vec<Vec<QPoint>> = vec![
            vec![pt(0, 1), pt(2, 1), pt(2, 3), pt(0, 3)],
            vec![pt(1, 1), pt(3, 2), pt(1, 4)],
            vec![pt(0, 2), pt(4, 2)],
            vec![pt(-1, 1), pt(1, 3), pt(3, 5), pt(0, 2)],
            vec![pt(2, 2)],
        ];
        let lines = [
            (pt(-10, 10), pt(10, 10)),
            (pt(10, 10), pt(-10, 10)),
            (pt(-10, 8), pt(10, 12)),
            (pt(5, 20), pt(-3, 9)),
        ];
        let mut compared = 0;
        for (c0, c1) in &lines {
            let ray_end = |u: &QPoint, v: &QPoint| line_cut(u, v, c0, c1);
            let c_dir = c1.sub(c0);
            for (o0, o1) in [(pt(-1, 0), pt(1, 0)), (pt(1, 0), pt(-1, 0))] {
                let (origin, end) = (ray_end(&pt(0, -2), &o0), ray_end(&pt(0, -2), &o1));
                let dir = end.sub(&origin);
                let along = |p: &QPoint| p.sub(&origin).dot(&dir);
                let rising = c_dir.dot(&dir).cmp0();
                assert_ne!(rising, Ordering::Equal);
                for cs in &corners {
                    for v in [pt(1, 6), pt(-2, 6), pt(3, 7), pt(0, 5)] {
                        if cs
                            .iter()
                            .all(|u| v.sub(u).cross_sign(&c_dir) == Ordering::Equal)
                        {
                            continue;
                        }
                        for first in [true, false] {
                            assert_eq!(
                                extreme_by_parameter(cs, &v, first, (c0, &c_dir), rising, &ray_end),
                                extreme_by_points(cs, &v, first, &c_dir, &ray_end, &along),
                            );
                            compared += 1;
                        }
                    }
                }
            }
        }
        assert!(compared > 100, "{compared}");
    }
}
