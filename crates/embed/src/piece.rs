//! Relatively open convex pieces of the plane — the cells of the
//! decomposition of dimension 0, 1 and 2 — and where a line meets them,
//! exactly (GMP rationals).

use rug::Rational;
use std::cmp::Ordering;
use wai_exact::{Point, RatPoint};

/// A point with rational coordinates, in affine form.
#[derive(Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Pt {
    pub x: Rational,
    pub y: Rational,
}

impl Pt {
    pub fn new(x: Rational, y: Rational) -> Pt {
        Pt { x, y }
    }

    pub fn sub(&self, o: &Pt) -> Pt {
        Pt::new(
            Rational::from(&self.x - &o.x),
            Rational::from(&self.y - &o.y),
        )
    }

    pub fn add(&self, o: &Pt) -> Pt {
        Pt::new(
            Rational::from(&self.x + &o.x),
            Rational::from(&self.y + &o.y),
        )
    }

    pub fn scale(&self, t: &Rational) -> Pt {
        Pt::new(Rational::from(&self.x * t), Rational::from(&self.y * t))
    }

    /// `p + t·d`.
    pub fn along(&self, d: &Pt, t: &Rational) -> Pt {
        self.add(&d.scale(t))
    }

    /// The vector turned a quarter counter-clockwise.
    pub fn perp(&self) -> Pt {
        Pt::new(Rational::from(-&self.y), self.x.clone())
    }

    pub fn is_zero(&self) -> bool {
        self.x == 0 && self.y == 0
    }

    pub fn to_rat_point(&self) -> RatPoint {
        // x = a/b, y = c/d → (a·d, c·b, b·d).
        let (a, b) = (self.x.numer(), self.x.denom());
        let (c, d) = (self.y.numer(), self.y.denom());
        RatPoint::new(
            rug::Integer::from(a * d),
            rug::Integer::from(c * b),
            rug::Integer::from(b * d),
        )
        .expect("denominators are positive")
    }
}

impl From<&RatPoint> for Pt {
    fn from(p: &RatPoint) -> Pt {
        Pt::new(
            Rational::from((p.hx().clone(), p.hw().clone())),
            Rational::from((p.hy().clone(), p.hw().clone())),
        )
    }
}

impl From<Point> for Pt {
    fn from(p: Point) -> Pt {
        Pt::new(Rational::from(p.x), Rational::from(p.y))
    }
}

impl std::fmt::Display for Pt {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "({}, {})", self.x, self.y)
    }
}

/// `u × w`.
pub fn cross(u: &Pt, w: &Pt) -> Rational {
    Rational::from(&u.x * &w.y) - Rational::from(&u.y * &w.x)
}

/// `u · w`.
pub fn dot(u: &Pt, w: &Pt) -> Rational {
    Rational::from(&u.x * &w.x) + Rational::from(&u.y * &w.y)
}

/// The sign of `(b − a) × (c − a)`: `Greater` for a left turn.
pub fn turn(a: &Pt, b: &Pt, c: &Pt) -> Ordering {
    // Integer points below 2^62 (map vertices, skeleton polygons): the
    // differences fit 63 bits and their products an i128, exactly.
    let small = |q: &Rational| -> Option<i128> {
        if *q.denom() != 1 {
            return None;
        }
        q.numer()
            .to_i64()
            .filter(|v| v.unsigned_abs() < 1 << 62)
            .map(i128::from)
    };
    let fast = || -> Option<Ordering> {
        let (ax, ay) = (small(&a.x)?, small(&a.y)?);
        let (bx, by) = (small(&b.x)?, small(&b.y)?);
        let (cx, cy) = (small(&c.x)?, small(&c.y)?);
        Some(((bx - ax) * (cy - ay) - (by - ay) * (cx - ax)).cmp(&0))
    };
    fast().unwrap_or_else(|| cross(&b.sub(a), &c.sub(a)).cmp0())
}

/// Whether the closed segments `ab` and `cd` share a point.
pub fn segments_meet(a: &Pt, b: &Pt, c: &Pt, d: &Pt) -> bool {
    // Boxes first: comparisons only, no arithmetic.
    let apart = |f: fn(&Pt) -> &Rational| {
        let (lo1, hi1) = if f(a) <= f(b) {
            (f(a), f(b))
        } else {
            (f(b), f(a))
        };
        let (lo2, hi2) = if f(c) <= f(d) {
            (f(c), f(d))
        } else {
            (f(d), f(c))
        };
        hi1 < lo2 || hi2 < lo1
    };
    if apart(|p| &p.x) || apart(|p| &p.y) {
        return false;
    }
    let (o1, o2) = (turn(a, b, c), turn(a, b, d));
    let (o3, o4) = (turn(c, d, a), turn(c, d, b));
    let within = |p: &Pt, q: &Pt, x: &Pt| {
        let box1 = |u: &Rational, v: &Rational, w: &Rational| u.min(v) <= w && w <= u.max(v);
        box1(&p.x, &q.x, &x.x) && box1(&p.y, &q.y, &x.y)
    };
    use Ordering::Equal;
    if o1 != Equal && o2 != Equal && o3 != Equal && o4 != Equal {
        return o1 != o2 && o3 != o4;
    }
    // An end on the other's line: where the lines meet (or overlap), so
    // the segments share a point iff such an end lies on the other.
    (o1 == Equal && within(a, b, c))
        || (o2 == Equal && within(a, b, d))
        || (o3 == Equal && within(c, d, a))
        || (o4 == Equal && within(c, d, b))
}

/// The parameters `t ∈ [0, 1]` of the points `a + t·(b − a)` where the
/// closed segment `ce` meets `ab`: its crossing point, or, when the two
/// overlap along a line, the ends of `ce` that lie on `ab`.
pub fn segment_cuts(a: &Pt, b: &Pt, c: &Pt, e: &Pt) -> Vec<Rational> {
    if !segments_meet(a, b, c, e) {
        return Vec::new();
    }
    let d = b.sub(a);
    let f = e.sub(c);
    let den = cross(&d, &f);
    if den == 0 {
        let dd = dot(&d, &d);
        return [c, e]
            .into_iter()
            .map(|x| dot(&x.sub(a), &d) / &dd)
            .filter(|t| *t >= 0 && *t <= 1)
            .collect();
    }
    // a + t·d = c + s·f: t = ((c − a) × f)/(d × f).
    vec![cross(&c.sub(a), &f) / den]
}

/// The convex hull of `pts`, counter-clockwise, collinear points dropped.
pub fn convex_hull(pts: Vec<Pt>) -> Vec<Pt> {
    crate::mutual::hull(pts)
}

/// The parameters `t` with `α + t·β > 0` for every `(α, β)` given, an open
/// interval (the constraints of a bounded open convex polygon), if any.
fn open_span(constraints: impl Iterator<Item = (Rational, Rational)>) -> Option<Span> {
    let mut lo: Option<Rational> = None;
    let mut hi: Option<Rational> = None;
    for (alpha, beta) in constraints {
        match beta.cmp0() {
            Ordering::Equal if alpha <= 0 => return None,
            Ordering::Equal => {}
            Ordering::Greater => {
                let t = -alpha / beta;
                if lo.as_ref().is_none_or(|l| t > *l) {
                    lo = Some(t);
                }
            }
            Ordering::Less => {
                let t = -alpha / beta;
                if hi.as_ref().is_none_or(|h| t < *h) {
                    hi = Some(t);
                }
            }
        }
    }
    match (lo, hi) {
        (Some(lo), Some(hi)) if lo < hi => Some(Span::Open(lo, hi)),
        _ => None,
    }
}

/// Points with small integer coordinates (for tests and figures).
pub fn ints(pts: &[(i64, i64)]) -> Vec<Pt> {
    pts.iter()
        .map(|&(x, y)| Pt::new(Rational::from(x), Rational::from(y)))
        .collect()
}

/// The closed axis-parallel box around some points: a cheap first test
/// before the exact ones.
#[derive(Clone, Debug)]
pub struct Bounds {
    pub lo: (Rational, Rational),
    pub hi: (Rational, Rational),
}

impl Bounds {
    pub fn of(pts: &[Pt]) -> Bounds {
        let min = |f: fn(&Pt) -> &Rational| pts.iter().map(f).min().cloned().unwrap_or_default();
        let max = |f: fn(&Pt) -> &Rational| pts.iter().map(f).max().cloned().unwrap_or_default();
        Bounds {
            lo: (min(|p| &p.x), min(|p| &p.y)),
            hi: (max(|p| &p.x), max(|p| &p.y)),
        }
    }

    /// Whether two closed boxes share a point.
    pub fn meets_box(&self, o: &Bounds) -> bool {
        !(self.hi.0 < o.lo.0 || o.hi.0 < self.lo.0 || self.hi.1 < o.lo.1 || o.hi.1 < self.lo.1)
    }

    /// False only if the closed segment `ab` surely misses the box.
    pub fn meets(&self, a: &Pt, b: &Pt) -> bool {
        let (xl, xh) = if a.x <= b.x {
            (&a.x, &b.x)
        } else {
            (&b.x, &a.x)
        };
        let (yl, yh) = if a.y <= b.y {
            (&a.y, &b.y)
        } else {
            (&b.y, &a.y)
        };
        !(*xh < self.lo.0 || *xl > self.hi.0 || *yh < self.lo.1 || *yl > self.hi.1)
    }
}

/// The least and greatest of `n · v` over `vertices`.
pub fn projection(n: &Pt, vertices: &[Pt]) -> (Rational, Rational) {
    let proj: Vec<Rational> = vertices.iter().map(|v| dot(n, v)).collect();
    (
        proj.iter().min().cloned().unwrap_or_default(),
        proj.iter().max().cloned().unwrap_or_default(),
    )
}

/// Offsets strictly between `lo` and `hi` and between any two consecutive
/// projections `n · p` of the points `e` that fall between them: one per
/// open slab of parallel lines of normal `n`.
pub fn offsets_between(e: &[Pt], n: &Pt, lo: Rational, hi: Rational) -> Vec<Rational> {
    let mut cuts: Vec<Rational> = e
        .iter()
        .map(|p| dot(n, p))
        .filter(|u| lo < *u && *u < hi)
        .collect();
    cuts.push(lo);
    cuts.push(hi);
    cuts.sort();
    cuts.dedup();
    cuts.windows(2)
        .map(|w| Rational::from(&w[0] + &w[1]) / 2u32)
        .collect()
}

/// A relatively open convex piece of the plane: a cell of dimension 0, 1
/// or 2 (its points; the boundary of a segment or polygon excluded).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Piece {
    Point(Pt),
    /// The open segment between two distinct points.
    Segment(Pt, Pt),
    /// The interior of a convex polygon, counter-clockwise, with positive
    /// area (vertices where the boundary goes straight on allowed).
    Polygon(Vec<Pt>),
}

/// Where a line `p0 + t·d` meets a piece: the parameters `t` of its points.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Span {
    /// Exactly `t`.
    At(Rational),
    /// The open interval `(lo, hi)`, `lo < hi`.
    Open(Rational, Rational),
}

impl Span {
    /// The least and greatest parameter of its closure.
    pub fn ends(&self) -> (&Rational, &Rational) {
        match self {
            Span::At(t) => (t, t),
            Span::Open(lo, hi) => (lo, hi),
        }
    }

    /// A parameter of the span itself.
    pub fn inner(&self) -> Rational {
        match self {
            Span::At(t) => t.clone(),
            Span::Open(lo, hi) => Rational::from(lo + hi) / 2u32,
        }
    }
}

impl Piece {
    /// The piece's vertices (its closure's extreme points and any
    /// straight-on polygon vertices).
    pub fn vertices(&self) -> Vec<Pt> {
        match self {
            Piece::Point(p) => vec![p.clone()],
            Piece::Segment(a, b) => vec![a.clone(), b.clone()],
            Piece::Polygon(v) => v.clone(),
        }
    }

    /// 0, 1 or 2.
    pub fn dimension(&self) -> u8 {
        match self {
            Piece::Point(_) => 0,
            Piece::Segment(..) => 1,
            Piece::Polygon(_) => 2,
        }
    }

    /// A point of the piece: the point, the segment's midpoint, the
    /// polygon's vertex centroid (inside: the polygon is convex).
    pub fn inner_point(&self) -> Pt {
        match self {
            Piece::Point(p) => p.clone(),
            Piece::Segment(a, b) => a.add(b).scale(&Rational::from((1, 2))),
            Piece::Polygon(v) => {
                let mut s = Pt::new(Rational::new(), Rational::new());
                for p in v {
                    s = s.add(p);
                }
                s.scale(&Rational::from((1, v.len())))
            }
        }
    }

    /// Where the line `p0 + t·d` (`d ≠ 0`) meets the piece, if it does.
    pub fn span(&self, p0: &Pt, d: &Pt) -> Option<Span> {
        match self {
            Piece::Point(c) => {
                let r = c.sub(p0);
                (cross(&r, d) == 0).then(|| Span::At(dot(&r, d) / dot(d, d)))
            }
            Piece::Segment(a, b) => {
                let e = b.sub(a);
                let r = p0.sub(a);
                let den = cross(&e, d);
                if den == 0 {
                    if cross(&r, d) != 0 {
                        return None;
                    }
                    let dd = dot(d, d);
                    let ta = dot(&a.sub(p0), d) / &dd;
                    let tb = dot(&b.sub(p0), d) / dd;
                    let (lo, hi) = if ta < tb { (ta, tb) } else { (tb, ta) };
                    return Some(Span::Open(lo, hi));
                }
                // p0 + t·d = a + s·e: s = (r × d)/(e × d), t = (r × e)/(e × d).
                let s = cross(&r, d) / &den;
                (s > 0 && s < 1).then(|| Span::At(cross(&r, &e) / den))
            }
            Piece::Polygon(v) => {
                // Inside: left of every edge a→b, (b − a) × (p0 + t·d − a) > 0,
                // i.e. α + t·β > 0.
                open_span((0..v.len()).map(|i| {
                    let (a, b) = (&v[i], &v[(i + 1) % v.len()]);
                    let e = b.sub(a);
                    (cross(&e, &p0.sub(a)), cross(&e, d))
                }))
            }
        }
    }

    /// The two pieces into which the line through `a` and `b` cuts this
    /// one, if it crosses its relative interior; otherwise `None`. The
    /// points on the line itself are left out (they form a piece of lower
    /// dimension, which the caller needs only when it matters).
    pub fn split(&self, a: &Pt, b: &Pt) -> Option<(Piece, Piece)> {
        let side = |p: &Pt| turn(a, b, p);
        match self {
            Piece::Point(_) => None,
            Piece::Segment(p, q) => {
                let (sp, sq) = (side(p), side(q));
                if sp == Ordering::Equal || sq == Ordering::Equal || sp == sq {
                    return None;
                }
                let x = line_cut(p, q, a, b);
                Some((
                    Piece::Segment(p.clone(), x.clone()),
                    Piece::Segment(x, q.clone()),
                ))
            }
            Piece::Polygon(v) => {
                let sides: Vec<Ordering> = v.iter().map(side).collect();
                let left = sides.contains(&Ordering::Greater);
                let right = sides.contains(&Ordering::Less);
                if !(left && right) {
                    return None;
                }
                let (mut l, mut r) = (Vec::new(), Vec::new());
                for i in 0..v.len() {
                    let j = (i + 1) % v.len();
                    match sides[i] {
                        Ordering::Greater => l.push(v[i].clone()),
                        Ordering::Less => r.push(v[i].clone()),
                        Ordering::Equal => {
                            l.push(v[i].clone());
                            r.push(v[i].clone());
                        }
                    }
                    let crosses = (sides[i] == Ordering::Greater && sides[j] == Ordering::Less)
                        || (sides[i] == Ordering::Less && sides[j] == Ordering::Greater);
                    if crosses {
                        let x = line_cut(&v[i], &v[j], a, b);
                        l.push(x.clone());
                        r.push(x);
                    }
                }
                Some((Piece::Polygon(l), Piece::Polygon(r)))
            }
        }
    }

    /// Whether `x` is a point of the piece.
    pub fn contains(&self, x: &Pt) -> bool {
        match self {
            Piece::Point(p) => p == x,
            Piece::Segment(a, b) => {
                turn(a, b, x) == Ordering::Equal && dot(&a.sub(x), &b.sub(x)) < 0
            }
            Piece::Polygon(v) => {
                (0..v.len()).all(|i| turn(&v[i], &v[(i + 1) % v.len()], x) == Ordering::Greater)
            }
        }
    }

    /// A point that this piece and `o` share, if they share one. Exact and
    /// complete: each piece is relatively open and convex.
    pub fn common_point(&self, o: &Piece) -> Option<Pt> {
        match (self, o) {
            (Piece::Point(p), _) => o.contains(p).then(|| p.clone()),
            (_, Piece::Point(p)) => self.contains(p).then(|| p.clone()),
            (Piece::Segment(a, b), _) => segment_common(a, b, o),
            (_, Piece::Segment(a, b)) => segment_common(a, b, self),
            // Both convex: clip one by the inner side of each edge of the
            // other; what is left, if anything, is their intersection.
            (Piece::Polygon(_), Piece::Polygon(q)) => {
                let mut left = self.clone();
                for i in 0..q.len() {
                    left = left.clip(&q[i], &q[(i + 1) % q.len()], Ordering::Greater)?;
                }
                Some(left.inner_point())
            }
        }
    }

    /// Whether this piece and `o` share a point.
    pub fn meets(&self, o: &Piece) -> bool {
        self.common_point(o).is_some()
    }

    /// The part of the piece strictly on side `side` (`Greater`: left) of
    /// the line through `a` and `b`, if any.
    pub fn clip(&self, a: &Pt, b: &Pt, side: Ordering) -> Option<Piece> {
        debug_assert_ne!(side, Ordering::Equal);
        if let Some((l, r)) = self.split(a, b) {
            return Some(if side == Ordering::Greater { l } else { r });
        }
        // Not cut: wholly on one side (or, below dimension 2, on the line).
        (turn(a, b, &self.inner_point()) == side).then(|| self.clone())
    }
}

/// A point of the open segment `ab` in the piece `o`, if any.
fn segment_common(a: &Pt, b: &Pt, o: &Piece) -> Option<Pt> {
    let d = b.sub(a);
    let t = match o.span(a, &d)? {
        Span::At(t) => (t > 0 && t < 1).then_some(t)?,
        Span::Open(lo, hi) => {
            let (zero, one) = (Rational::new(), Rational::from(1));
            let lo = if lo > zero { lo } else { zero };
            let hi = if hi < one { hi } else { one };
            (lo < hi).then(|| Rational::from(&lo + &hi) / 2u32)?
        }
    };
    Some(a.along(&d, &t))
}

/// A piece prepared for the parallel lines of one direction `d`: the line
/// of offset `u` is `p0(u) + t·d` with `p0(u) = u·n/(n·n)`, `n` the normal
/// `d` turned a quarter counter-clockwise. For a polygon, each edge's
/// constraint `α + t·β > 0` of [`Piece::span`] is kept as
/// `α = u·k − c`, so a span costs a few operations per edge.
#[derive(Debug)]
pub struct Parallel<'p> {
    piece: &'p Piece,
    d: Pt,
    n: Pt,
    nn: Rational,
    /// Polygons only: by edge `(k, c, β)`.
    edges: Vec<(Rational, Rational, Rational)>,
}

impl<'p> Parallel<'p> {
    pub fn new(piece: &'p Piece, d: &Pt) -> Parallel<'p> {
        let n = d.perp();
        let nn = dot(&n, &n);
        let edges = match piece {
            Piece::Polygon(v) => (0..v.len())
                .map(|i| {
                    let (a, b) = (&v[i], &v[(i + 1) % v.len()]);
                    let e = b.sub(a);
                    (cross(&e, &n) / &nn, cross(&e, a), cross(&e, d))
                })
                .collect(),
            _ => Vec::new(),
        };
        Parallel {
            piece,
            d: d.clone(),
            n,
            nn,
            edges,
        }
    }

    /// The base point `p0(u)` of the line of offset `u`.
    pub fn base(&self, u: &Rational) -> Pt {
        self.n.scale(&Rational::from(u / &self.nn))
    }

    /// [`Piece::span`] of the line of offset `u`.
    pub fn span(&self, u: &Rational) -> Option<Span> {
        if !matches!(self.piece, Piece::Polygon(_)) {
            return self.piece.span(&self.base(u), &self.d);
        }
        open_span(
            self.edges
                .iter()
                .map(|(k, c, beta)| (Rational::from(u * k) - c, beta.clone())),
        )
    }
}

/// One point of each part into which `lines` (each through two distinct
/// points) cut `pieces`: across a part no point crosses a line, so
/// whatever depends only on sides of those lines is the same at all its
/// points. Points on a line are left out (see [`Piece::split`]).
pub fn part_points(pieces: &[Piece], lines: &[(Pt, Pt)]) -> Vec<Pt> {
    let mut parts: Vec<Piece> = pieces.to_vec();
    for (a, b) in lines {
        parts = parts
            .into_iter()
            .flat_map(|p| match p.split(a, b) {
                Some((l, r)) => vec![l, r],
                None => vec![p],
            })
            .collect();
    }
    parts.iter().map(Piece::inner_point).collect()
}

/// Where segment `pq` meets the line through `a` and `b` (they cross).
/// Where the line through `p` and `q` meets the line through `a` and `b`
/// (which must not be parallel).
pub(crate) fn line_cut(p: &Pt, q: &Pt, a: &Pt, b: &Pt) -> Pt {
    let e = b.sub(a);
    let cp = cross(&e, &p.sub(a));
    let cq = cross(&e, &q.sub(a));
    let s = &cp / Rational::from(&cp - &cq);
    p.along(&q.sub(p), &s)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pt(x: i64, y: i64) -> Pt {
        ints(&[(x, y)]).remove(0)
    }

    #[test]
    fn spans_of_a_square_a_segment_and_a_point() {
        let sq = Piece::Polygon(vec![pt(0, 0), pt(2, 0), pt(2, 2), pt(0, 2)]);
        let (p0, d) = (pt(-1, 1), pt(1, 0));
        assert_eq!(
            sq.span(&p0, &d),
            Some(Span::Open(Rational::from(1), Rational::from(3)))
        );
        // Along an edge: the open square misses it.
        assert_eq!(sq.span(&pt(-1, 0), &d), None);
        let seg = Piece::Segment(pt(1, -1), pt(1, 1));
        assert_eq!(seg.span(&pt(0, 0), &d), Some(Span::At(Rational::from(1))));
        // Through an end of the open segment: no point.
        assert_eq!(seg.span(&pt(0, 1), &d), None);
        assert_eq!(
            Piece::Point(pt(3, 0)).span(&pt(1, 0), &pt(2, 0)),
            Some(Span::At(Rational::from(1)))
        );
    }

    #[test]
    fn parallel_spans_equal_direct_spans() {
        let hexagon = Piece::Polygon(vec![
            pt(0, 0),
            pt(4, -1),
            pt(7, 2),
            pt(6, 5),
            pt(2, 6),
            pt(-1, 3),
        ]);
        for d in [pt(1, 0), pt(2, 3), pt(-1, 4), pt(5, -2)] {
            let par = Parallel::new(&hexagon, &d);
            for u in -40..=40 {
                let u = Rational::from((u, 3));
                assert_eq!(
                    par.span(&u),
                    hexagon.span(&par.base(&u), &d),
                    "d = {d}, u = {u}"
                );
            }
        }
    }

    #[test]
    fn split_cuts_only_through_the_inside() {
        let sq = Piece::Polygon(vec![pt(0, 0), pt(2, 0), pt(2, 2), pt(0, 2)]);
        let (l, r) = sq.split(&pt(1, -5), &pt(1, 5)).unwrap();
        assert_eq!(l.vertices().len(), 4);
        assert_eq!(r.vertices().len(), 4);
        // Along an edge or through a corner only: no cut.
        assert!(sq.split(&pt(0, -5), &pt(0, 5)).is_none());
        assert!(sq.split(&pt(-1, 1), &pt(1, -1)).is_none());
        // Through two opposite corners: triangles.
        let (l, _) = sq.split(&pt(0, 0), &pt(2, 2)).unwrap();
        assert_eq!(l.vertices().len(), 3);
    }

    #[test]
    fn closed_segments_meet_at_ends_and_along() {
        assert!(segments_meet(&pt(0, 0), &pt(2, 0), &pt(2, 0), &pt(3, 1)));
        assert!(segments_meet(&pt(0, 0), &pt(2, 0), &pt(1, 0), &pt(3, 0)));
        assert!(segments_meet(&pt(0, 0), &pt(2, 2), &pt(0, 2), &pt(2, 0)));
        assert!(segments_meet(&pt(0, 0), &pt(2, 0), &pt(1, -1), &pt(1, 0)));
        assert!(!segments_meet(&pt(0, 0), &pt(2, 0), &pt(3, 0), &pt(4, 0)));
        assert!(!segments_meet(&pt(0, 0), &pt(2, 0), &pt(1, 1), &pt(2, 1)));
    }
}
