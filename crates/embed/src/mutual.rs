//! Whether some point of one region sees some point of another (sec. 2.2
//! visibility), decided exactly and completely for regions made of
//! relatively open convex pieces (cells of the decomposition) inside the
//! map — the test behind Theorem 4.2, which speaks of *all* witnesses.
//!
//! Two independent methods, which must agree:
//! - [`Sightlines::by_lines`] searches the space of lines. A line carries
//!   a sight line between pieces A and B iff the closed stretch of it
//!   between A and B misses the map's boundary (A and B lie in the open
//!   map). Which lines do is decided by the order of a finite point set E
//!   (the pieces' vertices and the reflex map vertices in their convex
//!   hull)
//!   across the line, so one line per cell of the arrangement of E's dual
//!   lines is tested: a direction strictly between any two consecutive
//!   directions of E's point pairs, and in it an offset strictly between
//!   any two consecutive projections of E.
//! - [`Sightlines::by_points`] cuts A by the lines through two points of
//!   E' (B's vertices and the reflex map vertices in the hull) into parts
//!   whose points all see B or all do not, and from one point of each part
//!   sweeps the directions towards E', testing one ray strictly between any
//!   two consecutive ones.
//!
//! Both rely on visibility being open: the pairs of points that see each
//! other form an open subset of A × B (the boundary is closed, the pieces'
//! points interior), so if there is one, there is one in general position,
//! which the strict in-between samples find. Every "visible" answer comes
//! with two exact points, re-checked by [`Map::sees`]. Maps with holes are
//! handled alike (see [`Sightlines::new`]).

use crate::piece::{offsets_between, projection, segments_meet, Bounds, Parallel, Piece, Span};
use rug::{Integer, Rational};
use std::cmp::Ordering;
use wai_exact::{convex_hull, turn, Point, QPoint};
use wai_map::Map;

/// The verdict of a mutual-visibility test.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Mutual {
    /// `from` (of the first region) sees `to` (of the second), re-checked
    /// with [`wai_exact::sees`].
    Visible { from: QPoint, to: QPoint },
    /// No point of one sees a point of the other; `tested` sight lines
    /// (lines or rays) were examined to decide it.
    Invisible { tested: u64 },
}

impl Mutual {
    pub fn is_visible(&self) -> bool {
        matches!(self, Mutual::Visible { .. })
    }
}

/// A map prepared for sight-line tests.
#[derive(Debug)]
pub struct Sightlines<'m> {
    map: &'m Map,
    /// By vertex: the vertex after it along its ring (edge i runs from
    /// vertex i to `next[i]`).
    next: Vec<usize>,
    points: Vec<QPoint>,
    reflex: Vec<bool>,
    /// By map edge: its line as homogeneous integer coefficients (the
    /// cross product of its ends), positive on its left (the inside).
    lines: Vec<[Integer; 3]>,
}

/// `(x, y, w)` with `w > 0` for a rational point.
fn homogeneous(p: &QPoint) -> [Integer; 3] {
    let (xd, yd) = (p.x.denom(), p.y.denom());
    [
        Integer::from(p.x.numer() * yd),
        Integer::from(p.y.numer() * xd),
        Integer::from(xd * yd),
    ]
}

/// The line through two homogeneous points (`w > 0`): `p × q`, whose dot
/// product with a point `r` (`w > 0`) has the sign of the turn p → q → r.
fn line_through(p: &[Integer; 3], q: &[Integer; 3]) -> [Integer; 3] {
    [
        Integer::from(&p[1] * &q[2]) - Integer::from(&p[2] * &q[1]),
        Integer::from(&p[2] * &q[0]) - Integer::from(&p[0] * &q[2]),
        Integer::from(&p[0] * &q[1]) - Integer::from(&p[1] * &q[0]),
    ]
}

fn side_of(l: &[Integer; 3], r: &[Integer; 3]) -> Ordering {
    (Integer::from(&l[0] * &r[0]) + Integer::from(&l[1] * &r[1]) + Integer::from(&l[2] * &r[2]))
        .cmp0()
}

/// Directions `d` with `d.y > 0` or `d.y = 0, d.x > 0`: each line once.
pub(crate) fn upper(d: QPoint) -> QPoint {
    if d.upper_half() {
        d
    } else {
        d.neg()
    }
}

/// The axis directions, added to every set of critical directions so that
/// consecutive ones are less than a quarter turn apart and their sum lies
/// strictly between them.
pub(crate) fn axes() -> [QPoint; 4] {
    let v = |x: i32, y: i32| QPoint::new(Rational::from(x), Rational::from(y));
    [v(1, 0), v(0, 1), v(-1, 0), v(0, -1)]
}

/// Sorted, deduplicated by angle; consecutive pairs (cyclically) give
/// the directions strictly between them as sums.
pub(crate) fn between(mut dirs: Vec<QPoint>) -> Vec<QPoint> {
    dirs.sort_by(QPoint::compare_angle);
    dirs.dedup_by(|a, b| a.compare_angle(b) == Ordering::Equal);
    (0..dirs.len())
        .map(|i| dirs[i].add(&dirs[(i + 1) % dirs.len()]))
        .collect()
}

/// A closed cone of directions from `lo` counter-clockwise to `hi`, less
/// than a half turn wide.
struct Cone {
    lo: QPoint,
    hi: QPoint,
}

impl Cone {
    fn holds(&self, d: &QPoint) -> bool {
        self.lo.cross_sign(d) != Ordering::Less && d.cross_sign(&self.hi) != Ordering::Less
    }

    /// Whether the line of direction `d` has a direction in the cone.
    fn holds_line(&self, d: &QPoint) -> bool {
        self.holds(d) || self.holds(&QPoint::new(Rational::from(-&d.x), Rational::from(-&d.y)))
    }
}

/// The smallest cone holding every vector of `vs`, if they all lie in an
/// open half-plane (else `None`: every direction may matter). Grown one
/// vector at a time: a vector that cannot extend the cone on either side
/// within a half turn proves the vectors span a half turn or more.
fn cone(vs: impl IntoIterator<Item = QPoint>) -> Option<Cone> {
    let mut vs = vs.into_iter();
    let first = vs.next()?;
    if first.is_zero() {
        return None;
    }
    let mut c = Cone {
        lo: first.clone(),
        hi: first,
    };
    for v in vs {
        if v.is_zero() {
            return None;
        }
        if c.holds(&v) {
            continue;
        }
        let left = |u: &QPoint, w: &QPoint| u.cross_sign(w) == Ordering::Greater;
        if left(&c.hi, &v) && left(&c.lo, &v) {
            c.hi = v;
        } else if left(&v, &c.lo) && left(&v, &c.hi) {
            c.lo = v;
        } else {
            return None;
        }
    }
    Some(c)
}

/// Whether `p` lies in the closed convex hull `h` (as [`convex_hull`]
/// returns it).
fn in_hull(h: &[QPoint], p: &QPoint) -> bool {
    match h.len() {
        0 => false,
        1 => h[0] == *p,
        2 => segments_meet(&h[0], &h[1], p, p),
        _ => (0..h.len()).all(|i| turn(&h[i], &h[(i + 1) % h.len()], p) != Ordering::Less),
    }
}

/// Whether the closed segment `ab` meets the closed convex hull `h`.
fn segment_meets_hull(h: &[QPoint], a: &QPoint, b: &QPoint) -> bool {
    if in_hull(h, a) || in_hull(h, b) {
        return true;
    }
    match h.len() {
        0 => false,
        1 => segments_meet(a, b, &h[0], &h[0]),
        _ => (0..h.len()).any(|i| segments_meet(a, b, &h[i], &h[(i + 1) % h.len()])),
    }
}

impl<'m> Sightlines<'m> {
    pub fn new(map: &'m Map) -> Sightlines<'m> {
        // Holes (thesis sec. 6.4) change nothing in the argument: a sight
        // line starts or stops meeting a hole as the line passes a vertex
        // of the hole that is convex in it, which is a reflex vertex of the
        // free space and so in E; the edges near a hull are those of every
        // ring.
        let ring = map.vertices();
        let next: Vec<usize> = (0..ring.len()).map(|i| map.next(i)).collect();
        let reflex = {
            let mut f = vec![false; ring.len()];
            for &r in map.reflex_vertices() {
                f[r] = true;
            }
            f
        };
        let n = ring.len();
        let one = || Integer::from(1);
        let lines = (0..n)
            .map(|i| {
                let h = |p: Point| [Integer::from(p.x), Integer::from(p.y), one()];
                line_through(&h(ring[i]), &h(ring[next[i]]))
            })
            .collect();
        Sightlines {
            map,
            next,
            points: ring.iter().map(|&p| QPoint::from(p)).collect(),
            reflex,
            lines,
        }
    }

    fn edge(&self, i: usize) -> (&QPoint, &QPoint) {
        (&self.points[i], &self.points[self.next[i]])
    }

    /// The map edges that meet the closed hull `h`.
    fn edges_near(&self, h: &[QPoint]) -> Vec<usize> {
        let b = Bounds::of(h);
        (0..self.points.len())
            .filter(|&i| {
                let (p, q) = self.edge(i);
                b.meets(p, q) && segment_meets_hull(h, p, q)
            })
            .collect()
    }

    /// The reflex map vertices in the closed hull `h`.
    fn reflex_in(&self, h: &[QPoint]) -> Vec<QPoint> {
        let b = Bounds::of(h);
        (0..self.points.len())
            .filter(|&i| {
                self.reflex[i]
                    && b.meets(&self.points[i], &self.points[i])
                    && in_hull(h, &self.points[i])
            })
            .map(|i| self.points[i].clone())
            .collect()
    }

    /// Whether the closed segment `ab` misses every edge of `edges`.
    ///
    /// The four orientations of each test are signs of integer dot
    /// products: `ab` in homogeneous integers (a common denominator), its
    /// line `a × b`, and each map edge's line from its integer ends. Only
    /// a test with a zero sign (an end on the other's line) takes the
    /// rational path.
    fn clear(&self, edges: &[usize], a: &QPoint, b: &QPoint) -> bool {
        let (ha, hb) = (homogeneous(a), homogeneous(b));
        let l = line_through(&ha, &hb);
        edges.iter().all(|&i| {
            let ring = self.map.vertices();
            let (c, d) = (ring[i], ring[self.next[i]]);
            let side = |p: Point| {
                side_of(
                    &l,
                    &[Integer::from(p.x), Integer::from(p.y), Integer::from(1)],
                )
            };
            let (o1, o2) = (side(c), side(d));
            if o1 != Ordering::Equal && o1 == o2 {
                return true;
            }
            let m = &self.lines[i];
            let (o3, o4) = (side_of(m, &ha), side_of(m, &hb));
            if o3 != Ordering::Equal && o3 == o4 {
                return true;
            }
            if [o1, o2, o3, o4].contains(&Ordering::Equal) {
                let (c, d) = self.edge(i);
                return !segments_meet(a, b, c, d);
            }
            false
        })
    }

    /// The certificate, re-checked by the reference predicate.
    fn certify(&self, from: QPoint, to: QPoint) -> Mutual {
        assert!(
            self.map
                .sees(&from.to_rat_point(), &to.to_rat_point())
                .is_visible(),
            "a sight line found between {from} and {to} is blocked: a bug in the mutual-visibility search"
        );
        Mutual::Visible { from, to }
    }

    /// Does some point of a piece of `a` see some point of a piece of `b`?
    /// By the search over lines (see the module doc).
    pub fn regions_by_lines(&self, a: &[Piece], b: &[Piece]) -> Mutual {
        all_pairs(a, b, |p, q| self.by_lines(p, q))
    }

    /// As [`Sightlines::regions_by_lines`], by the cuts and sweeps from
    /// points.
    pub fn regions_by_points(&self, a: &[Piece], b: &[Piece]) -> Mutual {
        all_pairs(a, b, |p, q| self.by_points(p, q))
    }

    /// One pair of pieces, by the search over lines.
    pub fn by_lines(&self, a: &Piece, b: &Piece) -> Mutual {
        let (va, vb) = (a.vertices(), b.vertices());
        let h = convex_hull(va.iter().chain(&vb).cloned().collect());
        let edges = self.edges_near(&h);
        if let (Piece::Point(p), Piece::Point(q)) = (a, b) {
            return if self.clear(&edges, p, q) {
                self.certify(p.clone(), q.clone())
            } else {
                Mutual::Invisible { tested: 1 }
            };
        }
        // Both on one line (collinear segments, a point on a segment's
        // line): that line is the only one meeting both.
        if h.len() == 2 {
            return self.on_line(&edges, a, b, &h[0], &h[1].sub(&h[0]));
        }
        // E: the pieces' vertices and the reflex map vertices in the hull.
        // A convex map vertex is no event: a stretch passing near it on
        // either side is blocked (it crosses both edges at the vertex, or
        // runs outside the map).
        let mut e: Vec<QPoint> = va.iter().chain(&vb).cloned().collect();
        e.extend(self.reflex_in(&h));
        e.sort();
        e.dedup();
        // A point piece fixes the line through it: only the directions from
        // it to E matter; otherwise those of all pairs of E.
        let fixed = match (a, b) {
            (Piece::Point(p), _) | (_, Piece::Point(p)) => Some(p.clone()),
            _ => None,
        };
        // Only directions of lines that can meet both pieces matter: those
        // of the vectors from A to B, a cone when the pieces are apart.
        let cone = cone(va.iter().flat_map(|x| vb.iter().map(move |y| y.sub(x))));
        let mut dirs: Vec<QPoint> = axes().to_vec();
        for (i, x) in e.iter().enumerate() {
            for y in &e[i + 1..] {
                if fixed.as_ref().is_some_and(|f| f != x && f != y) {
                    continue;
                }
                let d = upper(y.sub(x));
                if cone.as_ref().is_none_or(|c| c.holds_line(&d)) {
                    dirs.push(d);
                }
            }
        }
        // Lines, not rays: half the circle.
        let tests: Vec<QPoint> = between(dirs)
            .into_iter()
            .filter(QPoint::upper_half)
            .collect();
        let mut tested = 0;
        for d in tests {
            let n = d.perp();
            let ((alo, ahi), (blo, bhi)) = (projection(&n, &va), projection(&n, &vb));
            let offsets: Vec<Rational> = if let Some(f) = &fixed {
                let u = n.dot(f);
                let other = if matches!(a, Piece::Point(_)) {
                    (&blo, &bhi)
                } else {
                    (&alo, &ahi)
                };
                if *other.0 < u && u < *other.1 {
                    vec![u]
                } else {
                    Vec::new()
                }
            } else {
                let (lo, hi) = (alo.max(blo), ahi.min(bhi));
                if lo >= hi {
                    continue;
                }
                offsets_between(&e, &n, lo, hi)
            };
            let (pa, pb) = (Parallel::new(a, &d), Parallel::new(b, &d));
            for u in offsets {
                tested += 1;
                let seen = self.stretch(&edges, a, b, pa.span(&u), pb.span(&u), &pa.base(&u), &d);
                if seen.is_visible() {
                    return seen;
                }
            }
        }
        Mutual::Invisible { tested }
    }

    /// Whether the line `p0 + t·d` carries a sight line from `a` to `b`:
    /// it meets both, and the closed stretch between them misses the
    /// boundary edges `edges` (the pieces lie in the open map).
    fn on_line(&self, edges: &[usize], a: &Piece, b: &Piece, p0: &QPoint, d: &QPoint) -> Mutual {
        self.stretch(edges, a, b, a.span(p0, d), b.span(p0, d), p0, d)
    }

    /// [`Sightlines::on_line`] with the pieces' spans on the line given.
    #[allow(clippy::too_many_arguments)]
    fn stretch(
        &self,
        edges: &[usize],
        a: &Piece,
        b: &Piece,
        sa: Option<Span>,
        sb: Option<Span>,
        p0: &QPoint,
        d: &QPoint,
    ) -> Mutual {
        let (Some(sa), Some(sb)) = (sa, sb) else {
            return Mutual::Invisible { tested: 1 };
        };
        let ((alo, ahi), (blo, bhi)) = (sa.ends(), sb.ends());
        let gap = if ahi <= blo {
            (ahi, blo)
        } else if bhi <= alo {
            (bhi, alo)
        } else {
            panic!("pieces {a:?} and {b:?} overlap on a line: they are not disjoint cells");
        };
        if self.clear(edges, &p0.along(d, gap.0), &p0.along(d, gap.1)) {
            self.certify(p0.along(d, &sa.inner()), p0.along(d, &sb.inner()))
        } else {
            Mutual::Invisible { tested: 1 }
        }
    }

    /// One pair of pieces, by cutting `a` and sweeping from points.
    pub fn by_points(&self, a: &Piece, b: &Piece) -> Mutual {
        let h = convex_hull(a.vertices().into_iter().chain(b.vertices()).collect());
        let mut e: Vec<QPoint> = b.vertices();
        e.extend(self.reflex_in(&h));
        e.sort();
        e.dedup();
        let mut parts = vec![a.clone()];
        for (i, x) in e.iter().enumerate() {
            for y in &e[i + 1..] {
                parts = parts
                    .into_iter()
                    .flat_map(|p| match p.split(x, y) {
                        Some((l, r)) => vec![l, r],
                        None => vec![p],
                    })
                    .collect();
            }
        }
        let edges = self.edges_near(&h);
        let reflex = self.reflex_in(&h);
        let mut tested = 0;
        for part in parts {
            match self.sweep(&part.inner_point(), b, &edges, &reflex) {
                Mutual::Invisible { tested: t } => tested += t,
                seen => return seen,
            }
        }
        Mutual::Invisible { tested }
    }

    /// Does the point `w` (in the open map) see some point of `b`? Rays
    /// from `w` strictly between consecutive directions towards `b`'s
    /// vertices and the reflex map vertices in the hull.
    pub fn from_point(&self, w: &QPoint, b: &Piece) -> Mutual {
        let h = convex_hull(b.vertices().into_iter().chain([w.clone()]).collect());
        self.sweep(w, b, &self.edges_near(&h), &self.reflex_in(&h))
    }

    /// [`Sightlines::from_point`] with the map edges and reflex vertices
    /// of a hull that contains `w` and `b` (more than needed is harmless:
    /// more directions are tested).
    fn sweep(&self, w: &QPoint, b: &Piece, edges: &[usize], reflex: &[QPoint]) -> Mutual {
        let h = convex_hull(b.vertices().into_iter().chain([w.clone()]).collect());
        if let Piece::Point(q) = b {
            return if self.clear(edges, w, q) {
                self.certify(w.clone(), q.clone())
            } else {
                Mutual::Invisible { tested: 1 }
            };
        }
        if h.len() == 2 {
            // `w` on the line of segment `b`: only along it.
            return self.on_line(edges, &Piece::Point(w.clone()), b, w, &h[1].sub(&h[0]));
        }
        let mut dirs: Vec<QPoint> = axes().to_vec();
        dirs.extend(b.vertices().iter().map(|p| p.sub(w)));
        dirs.extend(reflex.iter().map(|p| p.sub(w)));
        dirs.retain(|d| !d.is_zero());
        let mut tested = 0;
        for d in between(dirs) {
            let Some(span) = b.span(w, &d) else { continue };
            let (tin, tout) = span.ends();
            if *tout <= 0 {
                continue;
            }
            // `w` may lie on the closure of `b` (a 1-cell on a 2-cell's side).
            let tin = tin.clone().max(Rational::new());
            let tin = &tin;
            tested += 1;
            // The nearest boundary point along the ray.
            let hit = edges
                .iter()
                .filter_map(|&i| {
                    let (c, e) = self.edge(i);
                    ray_hit(w, &d, c, e)
                })
                .min();
            let beyond = match &hit {
                None => true,
                Some(t) => t > tin,
            };
            if beyond {
                let far = match &hit {
                    Some(t) if t < tout => t.clone(),
                    _ => tout.clone(),
                };
                let t = match span {
                    Span::At(t) => t,
                    Span::Open(..) => Rational::from(tin + &far) / 2u32,
                };
                return self.certify(w.clone(), w.along(&d, &t));
            }
        }
        Mutual::Invisible { tested }
    }
}

/// `test` on every pair of a piece of `a` and one of `b`: the first
/// "visible", or "invisible" with the sight lines of all tests summed.
fn all_pairs(a: &[Piece], b: &[Piece], test: impl Fn(&Piece, &Piece) -> Mutual) -> Mutual {
    let mut tested = 0;
    for p in a {
        for q in b {
            match test(p, q) {
                Mutual::Invisible { tested: t } => tested += t,
                seen => return seen,
            }
        }
    }
    Mutual::Invisible { tested }
}

/// The least `t > 0` at which the ray `w + t·d` meets the closed segment
/// `ce`, if any.
fn ray_hit(w: &QPoint, d: &QPoint, c: &QPoint, e: &QPoint) -> Option<Rational> {
    let f = e.sub(c);
    let den = d.cross(&f);
    let r = c.sub(w);
    if den == 0 {
        if r.cross_sign(d) != Ordering::Equal {
            return None;
        }
        let dd = d.dot(d);
        let (tc, te) = (r.dot(d) / &dd, e.sub(w).dot(d) / dd);
        let lo = tc.min(te);
        return (lo > 0).then_some(lo);
    }
    // w + t·d = c + s·f: t = (r × f)/(d × f), s = (r × d)/(d × f).
    let t = r.cross(&f) / &den;
    let s = r.cross(d) / den;
    (t > 0 && (0..=1).contains(&s)).then_some(t)
}
