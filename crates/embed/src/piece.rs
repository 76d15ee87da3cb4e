//! Relatively open convex pieces of the plane — the cells of the
//! decomposition of dimension 0, 1 and 2 — and where a line meets them,
//! exactly, on [`wai_exact::QPoint`]s (GMP rationals).

use rug::Rational;
use std::cmp::Ordering;
use wai_exact::{turn, QPoint};

/// Whether the closed segments `ab` and `cd` share a point.
pub fn segments_meet(a: &QPoint, b: &QPoint, c: &QPoint, d: &QPoint) -> bool {
    // Boxes first: comparisons only, no arithmetic.
    let apart = |f: fn(&QPoint) -> &Rational| {
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
    let within = |p: &QPoint, q: &QPoint, x: &QPoint| {
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
pub fn segment_cuts(a: &QPoint, b: &QPoint, c: &QPoint, e: &QPoint) -> Vec<Rational> {
    if !segments_meet(a, b, c, e) {
        return Vec::new();
    }
    let d = b.sub(a);
    let f = e.sub(c);
    let den = d.cross(&f);
    if den == 0 {
        let dd = d.dot(&d);
        return [c, e]
            .into_iter()
            .map(|x| x.sub(a).dot(&d) / &dd)
            .filter(|t| *t >= 0 && *t <= 1)
            .collect();
    }
    // a + t·d = c + s·f: t = ((c − a) × f)/(d × f).
    vec![c.sub(a).cross(&f) / den]
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

/// Integer points below `2^HULL_FAST_BITS` in each coordinate take the
/// integer path of [`open_hulls_meet`].
///
/// Implementation note: a difference of two such points is below `2^41`;
/// a direction `u` is such a difference and its normal `(−u_y, u_x)` too;
/// a projection `n·p` of a point is below `2·2^41·2^40 = 2^82`, far
/// inside `i128`.
pub const HULL_FAST_BITS: u32 = 40;

/// Whether the relative interiors of the convex hulls of two integer point
/// sets share a point (each set spans a segment or a polygon, as the
/// pieces of [`Piece`] do), or `None` if a coordinate is not below
/// [`HULL_FAST_BITS`].
///
/// Exact and complete by proper separation (two convex sets have
/// disjoint relative interiors iff a line has one on each closed side and
/// not both on it): such a line can be taken parallel to an edge of one
/// hull, or, for two segments on one line, perpendicular to it; every
/// direction between two points of either set, and its normal, is tried.
pub fn open_hulls_meet(p: &[wai_exact::Point], q: &[wai_exact::Point]) -> Option<bool> {
    let limit = 1i128 << HULL_FAST_BITS;
    if p.iter()
        .chain(q)
        .any(|v| v.x.abs() >= limit || v.y.abs() >= limit)
    {
        return None;
    }
    let range = |s: &[wai_exact::Point], n: (i128, i128)| {
        let proj = s.iter().map(|v| n.0 * v.x + n.1 * v.y);
        let (mut lo, mut hi) = (i128::MAX, i128::MIN);
        for x in proj {
            lo = lo.min(x);
            hi = hi.max(x);
        }
        (lo, hi)
    };
    let separates = |n: (i128, i128)| {
        let ((plo, phi), (qlo, qhi)) = (range(p, n), range(q, n));
        let apart = phi <= qlo || qhi <= plo;
        let on_one_line = plo == phi && qlo == qhi && phi == qlo;
        apart && !on_one_line
    };
    for s in [p, q] {
        for (i, a) in s.iter().enumerate() {
            for b in &s[i + 1..] {
                let u = (b.x - a.x, b.y - a.y);
                if u == (0, 0) {
                    continue;
                }
                if separates((-u.1, u.0)) || separates(u) {
                    return Some(false);
                }
            }
        }
    }
    Some(true)
}

/// A point with small integer coordinates (for tests and figures).
pub fn int(x: i64, y: i64) -> QPoint {
    QPoint::new(Rational::from(x), Rational::from(y))
}

/// Points with small integer coordinates (for tests and figures).
pub fn ints(pts: &[(i64, i64)]) -> Vec<QPoint> {
    pts.iter().map(|&(x, y)| int(x, y)).collect()
}

/// A figure for tests, as [`ints`] takes it: a U, two arms of width 2
/// around a notch, open at the top. A bar across both arms meets it in
/// two regions.
pub const U_RING: [(i64, i64); 8] = [
    (0, 0),
    (6, 0),
    (6, 6),
    (4, 6),
    (4, 2),
    (2, 2),
    (2, 6),
    (0, 6),
];

/// The closed axis-parallel box around some points: a cheap first test
/// before the exact ones.
#[derive(Clone, Debug)]
pub struct Bounds {
    pub lo: (Rational, Rational),
    pub hi: (Rational, Rational),
}

impl Bounds {
    pub fn of(pts: &[QPoint]) -> Bounds {
        let min =
            |f: fn(&QPoint) -> &Rational| pts.iter().map(f).min().cloned().unwrap_or_default();
        let max =
            |f: fn(&QPoint) -> &Rational| pts.iter().map(f).max().cloned().unwrap_or_default();
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
    pub fn meets(&self, a: &QPoint, b: &QPoint) -> bool {
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
pub fn projection(n: &QPoint, vertices: &[QPoint]) -> (Rational, Rational) {
    let mut it = vertices.iter().map(|v| n.dot(v));
    let Some(first) = it.next() else {
        return (Rational::new(), Rational::new());
    };
    let (mut lo, mut hi) = (first.clone(), first);
    for x in it {
        if x < lo {
            lo = x;
        } else if x > hi {
            hi = x;
        }
    }
    (lo, hi)
}

/// Offsets strictly between `lo` and `hi` and between any two consecutive
/// projections `n · p` of the points `e` that fall between them: one per
/// open slab of parallel lines of normal `n`.
pub fn offsets_between(e: &[QPoint], n: &QPoint, lo: Rational, hi: Rational) -> Vec<Rational> {
    let mut cuts: Vec<Rational> = e
        .iter()
        .map(|p| n.dot(p))
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
    Point(QPoint),
    /// The open segment between two distinct points.
    Segment(QPoint, QPoint),
    /// The interior of a convex polygon, counter-clockwise, with positive
    /// area (vertices where the boundary goes straight on allowed).
    Polygon(Vec<QPoint>),
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
    pub fn vertices(&self) -> Vec<QPoint> {
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
    pub fn inner_point(&self) -> QPoint {
        match self {
            Piece::Point(p) => p.clone(),
            Piece::Segment(a, b) => a.add(b).scale(&Rational::from((1, 2))),
            Piece::Polygon(v) => {
                if let Some(mean) = small_mean(v) {
                    return mean;
                }
                // The vertices' mean, summed in place.
                let (mut x, mut y) = (Rational::new(), Rational::new());
                for p in v {
                    x += &p.x;
                    y += &p.y;
                }
                QPoint::new(x, y).scale(&Rational::from((1, v.len())))
            }
        }
    }

    /// Where the line `p0 + t·d` (`d ≠ 0`) meets the piece, if it does.
    pub fn span(&self, p0: &QPoint, d: &QPoint) -> Option<Span> {
        match self {
            Piece::Point(c) => {
                let r = c.sub(p0);
                (r.cross_sign(d) == Ordering::Equal).then(|| Span::At(r.dot(d) / d.dot(d)))
            }
            Piece::Segment(a, b) => {
                let e = b.sub(a);
                let r = p0.sub(a);
                let den = e.cross(d);
                if den == 0 {
                    if r.cross_sign(d) != Ordering::Equal {
                        return None;
                    }
                    let dd = d.dot(d);
                    let ta = a.sub(p0).dot(d) / &dd;
                    let tb = b.sub(p0).dot(d) / dd;
                    let (lo, hi) = if ta < tb { (ta, tb) } else { (tb, ta) };
                    return Some(Span::Open(lo, hi));
                }
                // p0 + t·d = a + s·e: s = (r × d)/(e × d), t = (r × e)/(e × d).
                let s = r.cross(d) / &den;
                (s > 0 && s < 1).then(|| Span::At(r.cross(&e) / den))
            }
            Piece::Polygon(v) => {
                // Inside: left of every edge a→b, (b − a) × (p0 + t·d − a) > 0,
                // i.e. α + t·β > 0.
                open_span((0..v.len()).map(|i| {
                    let (a, b) = (&v[i], &v[(i + 1) % v.len()]);
                    let e = b.sub(a);
                    (e.cross(&p0.sub(a)), e.cross(d))
                }))
            }
        }
    }

    /// The two pieces into which the line through `a` and `b` cuts this
    /// one, if it crosses its relative interior; otherwise `None`. The
    /// points on the line itself are left out (they form a piece of lower
    /// dimension, which the caller needs only when it matters).
    pub fn split(&self, a: &QPoint, b: &QPoint) -> Option<(Piece, Piece)> {
        let side = |p: &QPoint| turn(a, b, p);
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
    pub fn contains(&self, x: &QPoint) -> bool {
        match self {
            Piece::Point(p) => p == x,
            Piece::Segment(a, b) => turn(a, b, x) == Ordering::Equal && a.sub(x).dot(&b.sub(x)) < 0,
            Piece::Polygon(v) => {
                (0..v.len()).all(|i| turn(&v[i], &v[(i + 1) % v.len()], x) == Ordering::Greater)
            }
        }
    }

    /// A point that this piece and `o` share, if they share one. Exact and
    /// complete: each piece is relatively open and convex.
    pub fn common_point(&self, o: &Piece) -> Option<QPoint> {
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
    pub fn clip(&self, a: &QPoint, b: &QPoint, side: Ordering) -> Option<Piece> {
        debug_assert_ne!(side, Ordering::Equal);
        if let Some((l, r)) = self.split(a, b) {
            return Some(if side == Ordering::Greater { l } else { r });
        }
        // Not cut: wholly on one side (or, below dimension 2, on the line).
        (turn(a, b, &self.inner_point()) == side).then(|| self.clone())
    }
}

/// A point of the open segment `ab` in the piece `o`, if any.
fn segment_common(a: &QPoint, b: &QPoint, o: &Piece) -> Option<QPoint> {
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
    d: QPoint,
    n: QPoint,
    nn: Rational,
    /// Polygons only: by edge `(k, c, β)`.
    edges: Vec<(Rational, Rational, Rational)>,
}

impl<'p> Parallel<'p> {
    pub fn new(piece: &'p Piece, d: &QPoint) -> Parallel<'p> {
        let n = d.perp();
        let nn = n.dot(&n);
        let edges = match piece {
            Piece::Polygon(v) => (0..v.len())
                .map(|i| {
                    let (a, b) = (&v[i], &v[(i + 1) % v.len()]);
                    let e = b.sub(a);
                    (e.cross(&n) / &nn, e.cross(a), e.cross(d))
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
    pub fn base(&self, u: &Rational) -> QPoint {
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
pub fn part_points(pieces: &[Piece], lines: &[(QPoint, QPoint)]) -> Vec<QPoint> {
    let mut parts: Vec<Piece> = pieces.to_vec();
    let mut next = Vec::with_capacity(parts.len());
    for (a, b) in lines {
        for p in parts.drain(..) {
            match p.split(a, b) {
                Some((l, r)) => next.extend([l, r]),
                None => next.push(p),
            }
        }
        std::mem::swap(&mut parts, &mut next);
    }
    parts.iter().map(Piece::inner_point).collect()
}

/// The mean of the points in checked `i128` fractions kept in lowest
/// terms, if no step overflows (then the caller sums in GMP): the same
/// rational point, without a GMP operation per vertex.
fn small_mean(v: &[QPoint]) -> Option<QPoint> {
    /// `a/b + c/d` in lowest terms (`b, d > 0`, both in lowest terms).
    fn add((a, b): (i128, i128), (c, d): (i128, i128)) -> Option<(i128, i128)> {
        let g = gcd(b, d);
        let (b1, d1) = (b / g, d / g);
        let num = a.checked_mul(d1)?.checked_add(c.checked_mul(b1)?)?;
        let den = b.checked_mul(d1)?;
        let h = gcd(num.checked_abs()?, den);
        Some((num / h, den / h))
    }
    fn gcd(x: i128, y: i128) -> i128 {
        // Both non-negative and not both zero (a denominator is one).
        wai_exact::gcd_u128(x.unsigned_abs(), y.unsigned_abs()) as i128
    }
    let part = |q: &Rational| Some((q.numer().to_i128()?, q.denom().to_i128()?));
    let (mut x, mut y) = ((0, 1), (0, 1));
    for p in v {
        x = add(x, part(&p.x)?)?;
        y = add(y, part(&p.y)?)?;
    }
    let n = i128::try_from(v.len()).ok()?;
    let mean = |(num, den): (i128, i128)| -> Option<Rational> {
        Some(Rational::from((num, den.checked_mul(n)?)))
    };
    Some(QPoint::new(mean(x)?, mean(y)?))
}

/// Where segment `pq` meets the line through `a` and `b` (they cross).
/// Where the line through `p` and `q` meets the line through `a` and `b`
/// (which must not be parallel).
pub(crate) fn line_cut(p: &QPoint, q: &QPoint, a: &QPoint, b: &QPoint) -> QPoint {
    let e = b.sub(a);
    let cp = e.cross(&p.sub(a));
    let cq = e.cross(&q.sub(a));
    let s = &cp / Rational::from(&cp - &cq);
    p.along(&q.sub(p), &s)
}

#[cfg(test)]
mod tests {
    use super::int as pt;
    use super::*;

    /// The `i128` mean equals the GMP mean, on polygons of fractions of
    /// every size and on ones whose sums overflow (which fall back).
    #[test]
    fn small_means_equal_gmp_means() {
        let gmp = |v: &[QPoint]| {
            let (mut x, mut y) = (Rational::new(), Rational::new());
            for p in v {
                x += &p.x;
                y += &p.y;
            }
            QPoint::new(x, y).scale(&Rational::from((1, v.len())))
        };
        let q = |n: i128, d: i128| Rational::from((n, d));
        let mut seen = (0, 0);
        for k in 0..200i128 {
            // Every fifth polygon has 100-bit numerators and denominators,
            // every tenth 120-bit ones, whose sums leave the i128 range.
            let shift = match k % 10 {
                0 => 120,
                5 => 100,
                _ => 0,
            };
            let big = Rational::from(rug::Integer::from(1) << shift);
            let v: Vec<QPoint> = (0..3 + k % 5)
                .map(|i| {
                    QPoint::new(
                        q((i * 7 + k) - 11, 1 + (i * k) % 13) * &big,
                        q(k - i * 3, 1 + i + k % 7) / &big,
                    )
                })
                .collect();
            let want = gmp(&v);
            match small_mean(&v) {
                Some(m) => {
                    assert_eq!(m, want, "{v:?}");
                    seen.0 += 1;
                }
                None => seen.1 += 1,
            }
            assert_eq!(Piece::Polygon(v).inner_point(), want);
        }
        assert!(seen.0 > 100 && seen.1 > 10, "{seen:?}");
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
