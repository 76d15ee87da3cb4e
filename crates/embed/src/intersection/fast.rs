//! The ring-against-ring computations of this module on polygons whose
//! vertices are small integer points (map vertices, below
//! [`FAST_BITS`]): the same algorithms as the rational ones of
//! [`super`] and [`crate::witness`], in `i64` and `i128` with no
//! allocation but the output's.
//!
//! A point on an edge `a → b` is `a + t·(b − a)` with `t = n/d` exact; a
//! point where a test is made is kept homogeneous, `(X, Y, W)` with
//! `W > 0`; an output point is that triple reduced (coprime entries), so
//! equal points have equal triples.
//!
//! Implementation note: with every coordinate `|c| < 2^29`
//! ([`FAST_BITS`]):
//! - a difference of two vertices has `|Δ| < 2^30`, a cross or dot
//!   product of two differences `< 2·2^60 = 2^61`: both are `i64`;
//! - a cut parameter `t = n/d` on a segment has `0 ≤ n ≤ d < 2^61` (`d` a
//!   cross product `(b − a) × (e − c)` or a squared length `(b − a)·(b −
//!   a)`, `n` the matching product with `c − a`), so comparing two, `n1·d2`
//!   against `n2·d1`, stays below `2^122` (`i128`);
//! - a test parameter is a cut or the mediant `(n0 + n1)/(d0 + d1)` of two
//!   consecutive cuts (strictly between them), `N ≤ D < 2^62` (`i64`); its
//!   point `X = a_x·D + N·Δ_x` has `|X| < 2^91 + 2^92 < 2^93`, `W = D <
//!   2^62`;
//! - locating it against an edge `c → e` takes `Y − c_y·W` (`< 2^94`) and
//!   the orientation `(e − c) × (X − c_x·W, Y − c_y·W)`, two products
//!   below `2^30·2^94 = 2^124` and their difference below `2^125`;
//! - an output point (a cut, `N = n`, `D = d`) has `|X| < 2^92`.
//!
//! Everything stays below `2^63` where it is an `i64` and below `2^127`
//! where it is an `i128`; `fast_bits_bound_holds` recomputes the worst
//! case, and the differential tests compare every result with the
//! rational path. Products are taken with [`mul`], [`wai_exact::mul_wide`]
//! (64 × 64 → 128 bits, one machine multiplication) and [`mul128`], all
//! wrapping, so
//! exact below the bound: fuzzing builds check every checked product for
//! overflow, which the bound makes redundant.

use super::{BoundaryEdge, Intersection};
use rug::Rational;
use std::cmp::Ordering;
use wai_exact::{mul_wide as wide, QPoint};

/// Ring vertices with `|x|, |y| < 2^FAST_BITS` take the integer path.
pub const FAST_BITS: u32 = 29;

/// A small integer point.
pub(crate) type I = [i64; 2];

/// The ring as small integer points, if every vertex is one.
pub(crate) fn small_ring(r: &[QPoint]) -> Option<Vec<I>> {
    r.iter().map(small).collect()
}

/// An integer coordinate as a small one ([`FAST_BITS`]), if it is one.
pub(crate) fn small_int(v: i128) -> Option<i64> {
    i64::try_from(v)
        .ok()
        .filter(|v| v.unsigned_abs() < 1u64 << FAST_BITS)
}

/// The point as a small integer point, if it is one.
pub(crate) fn small(p: &QPoint) -> Option<I> {
    let c = |q: &Rational| -> Option<i64> {
        if *q.denom() != 1 {
            return None;
        }
        q.numer()
            .to_i64()
            .filter(|v| v.unsigned_abs() < 1u64 << FAST_BITS)
    };
    Some([c(&p.x)?, c(&p.y)?])
}

/// A difference of two small points (`|Δ| < 2^30`).
type D = [i64; 2];

fn sub(a: I, b: I) -> D {
    [a[0] - b[0], a[1] - b[1]]
}

/// `a·b`, exact below the module's bound (`< 2^61` for the products of
/// two differences).
#[inline]
fn mul(a: i64, b: i64) -> i64 {
    a.wrapping_mul(b)
}

/// `a·b` for an `i128` below the module's bound, exact.
#[inline]
fn mul128(a: i128, b: i64) -> i128 {
    a.wrapping_mul(i128::from(b))
}

fn cross(u: D, v: D) -> i64 {
    mul(u[0], v[1]) - mul(u[1], v[0])
}

fn dot(u: D, v: D) -> i64 {
    mul(u[0], v[0]) + mul(u[1], v[1])
}

/// The index after `j` around a ring of `n` (no division: this runs
/// once per edge pair).
#[inline]
pub(crate) fn next(j: usize, n: usize) -> usize {
    if j + 1 == n {
        0
    } else {
        j + 1
    }
}

/// The sign of `(b − a) × (c − a)`.
fn turn(a: I, b: I, c: I) -> Ordering {
    cross(sub(b, a), sub(c, a)).cmp(&0)
}

/// `lo ≤ x ≤ hi` for `x` between the two.
fn between(u: i64, v: i64, x: i64) -> bool {
    u.min(v) <= x && x <= u.max(v)
}

/// [`crate::piece::segments_meet`] on small points.
pub(crate) fn segments_meet(a: I, b: I, c: I, d: I) -> bool {
    for k in 0..2 {
        if a[k].max(b[k]) < c[k].min(d[k]) || c[k].max(d[k]) < a[k].min(b[k]) {
            return false;
        }
    }
    let (o1, o2) = (turn(a, b, c), turn(a, b, d));
    let (o3, o4) = (turn(c, d, a), turn(c, d, b));
    let within = |p: I, q: I, x: I| between(p[0], q[0], x[0]) && between(p[1], q[1], x[1]);
    use Ordering::Equal;
    if o1 != Equal && o2 != Equal && o3 != Equal && o4 != Equal {
        return o1 != o2 && o3 != o4;
    }
    (o1 == Equal && within(a, b, c))
        || (o2 == Equal && within(a, b, d))
        || (o3 == Equal && within(c, d, a))
        || (o4 == Equal && within(c, d, b))
}

/// [`super::edges_meet`] on small points: the closed segments meet other
/// than in an end common to both.
pub(crate) fn edges_meet(a: [I; 2], b: [I; 2]) -> bool {
    if !segments_meet(a[0], a[1], b[0], b[1]) {
        return false;
    }
    let Some(&x) = a.iter().find(|p| b.contains(p)) else {
        return true;
    };
    // A common end: they meet elsewhere only if collinear and pointing the
    // same way from it.
    let (da, db) = (sub(a[1], a[0]), sub(b[1], b[0]));
    if cross(da, db) != 0 {
        return false;
    }
    let away = |s: [I; 2]| {
        if s[0] == x {
            sub(s[1], x)
        } else {
            sub(s[0], x)
        }
    };
    dot(away(a), away(b)) > 0
}

/// A parameter `n/d` on a segment, `d > 0`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Frac {
    n: i64,
    d: i64,
}

impl Frac {
    const ZERO: Frac = Frac { n: 0, d: 1 };
    const ONE: Frac = Frac { n: 1, d: 1 };

    fn cmp(self, o: Frac) -> Ordering {
        wide(self.n, o.d).cmp(&wide(o.n, self.d))
    }

    /// Strictly between `self` and `o` (`self < o`).
    fn mediant(self, o: Frac) -> Frac {
        Frac {
            n: self.n + o.n,
            d: self.d + o.d,
        }
    }

    #[cfg(test)]
    fn to_rational(self) -> Rational {
        Rational::from((self.n, self.d))
    }
}

/// [`crate::piece::segment_cuts`] on small points, pushed onto `out`.
#[cfg(test)]
fn segment_cuts(a: I, b: I, c: I, e: I, out: &mut Vec<Frac>) {
    if !segments_meet(a, b, c, e) {
        return;
    }
    segment_cuts_in_box(a, b, c, e, out);
}

/// [`segment_cuts`] for segments whose closed boxes are known to meet
/// (the box test of [`segments_meet`] already passed).
///
/// It reuses the orientations of the meeting test for the crossing: with
/// `d = b − a`, `f = e − c`, `s_a = f × (a − c)` and `s_b = f × (b − c)`
/// (the orientations of `a` and `b` against `c → e`), `d × f = s_a − s_b`
/// and `(c − a) × f = s_a`, so the cut of a proper crossing is
/// `s_a / (s_a − s_b)` — the same fraction as before, with no further
/// product (`|s_a|, |s_b| < 2^61`, their difference below `2^62`).
fn segment_cuts_in_box(a: I, b: I, c: I, e: I, out: &mut Vec<Frac>) {
    let d = sub(b, a);
    let f = sub(e, c);
    let s_a = cross(f, sub(a, c));
    let s_b = cross(f, sub(b, c));
    let (o1, o2) = (cross(d, sub(c, a)).cmp(&0), cross(d, sub(e, a)).cmp(&0));
    let (o3, o4) = (s_a.cmp(&0), s_b.cmp(&0));
    use Ordering::Equal;
    let meet = if o1 != Equal && o2 != Equal && o3 != Equal && o4 != Equal {
        o1 != o2 && o3 != o4
    } else {
        let within = |p: I, q: I, x: I| between(p[0], q[0], x[0]) && between(p[1], q[1], x[1]);
        (o1 == Equal && within(a, b, c))
            || (o2 == Equal && within(a, b, e))
            || (o3 == Equal && within(c, e, a))
            || (o4 == Equal && within(c, e, b))
    };
    if !meet {
        return;
    }
    let den = s_a - s_b;
    if den == 0 {
        let dd = dot(d, d);
        for x in [c, e] {
            let n = dot(sub(x, a), d);
            if (0..=dd).contains(&n) {
                out.push(Frac { n, d: dd });
            }
        }
        return;
    }
    let num = s_a;
    let (n, d) = if den < 0 { (-num, -den) } else { (num, den) };
    out.push(Frac { n, d });
}

/// The cuts of `a → b` by the boundary of `q`, with 0 and 1, sorted,
/// without repeats.
fn cuts(a: I, b: I, q: &[I]) -> Vec<Frac> {
    let mut out = Vec::with_capacity(8);
    cuts_into(a, b, q, &mut out);
    out
}

/// [`cuts`] into `out` (cleared first), so that a caller cutting many
/// edges reuses one buffer.
fn cuts_into(a: I, b: I, q: &[I], out: &mut Vec<Frac>) {
    out.clear();
    out.extend([Frac::ZERO, Frac::ONE]);
    // The box of `ab`: an edge of `q` entirely beyond it on one side
    // cannot meet it, and is skipped before the orientation tests (the
    // same first test `segments_meet` makes). Each vertex of `q` gets an
    // outcode, one bit per side of the box it lies beyond, computed once:
    // an edge lies beyond one side exactly when its ends' codes share a
    // bit.
    let (xl, xh) = (a[0].min(b[0]), a[0].max(b[0]));
    let (yl, yh) = (a[1].min(b[1]), a[1].max(b[1]));
    let code = |v: I| {
        u8::from(v[0] < xl)
            | u8::from(v[0] > xh) << 1
            | u8::from(v[1] < yl) << 2
            | u8::from(v[1] > yh) << 3
    };
    let n = q.len();
    let Some(&first) = q.first() else { return };
    let mut from = code(first);
    for j in 0..n {
        let e = q[next(j, n)];
        let to = code(e);
        if from & to == 0 {
            segment_cuts_in_box(a, b, q[j], e, out);
        }
        from = to;
    }
    if out.len() > 2 {
        out.sort_by(|x, y| x.cmp(*y));
        out.dedup_by(|x, y| x.cmp(*y) == Ordering::Equal);
    }
}

/// The point `a + t·(b − a)`, homogeneous `(X, Y, W)`, `W > 0`.
fn at(a: I, b: I, t: Frac) -> [i128; 3] {
    let d = sub(b, a);
    [
        wide(a[0], t.d) + wide(t.n, d[0]),
        wide(a[1], t.d) + wide(t.n, d[1]),
        i128::from(t.d),
    ]
}

/// The same point reduced: coprime entries, `W > 0`.
fn reduced(p: [i128; 3]) -> [i128; 3] {
    if p[2] == 1 {
        return p; // an end of the edge: already coprime
    }
    // W first: it is the smallest entry, and often coprime to X already.
    let mut g = gcd(p[2].unsigned_abs(), p[0].unsigned_abs());
    if g > 1 {
        g = gcd(g, p[1].unsigned_abs());
    }
    let g = g.max(1) as i128;
    [p[0] / g, p[1] / g, p[2] / g]
}

/// Euclid's gcd; once both values fit in 64 bits (after at most a few
/// wide steps: a reduced point's `W` is below `2^62`) it continues with
/// 64-bit remainders, which the machine divides directly — the same
/// sequence of remainders, so the same result.
fn gcd(mut a: u128, mut b: u128) -> u128 {
    while b != 0 {
        if let (Ok(x), Ok(y)) = (u64::try_from(a), u64::try_from(b)) {
            return u128::from(gcd64(x, y));
        }
        (a, b) = (b, a % b);
    }
    a
}

fn gcd64(mut a: u64, mut b: u64) -> u64 {
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}

/// A reduced homogeneous point as a rational point.
fn qpoint(p: [i128; 3]) -> QPoint {
    QPoint::new(Rational::from((p[0], p[2])), Rational::from((p[1], p[2])))
}

/// Where a point lies against a polygon ([`crate::witness::locate`]).
pub(crate) enum Locus {
    Inside,
    Outside,
    OnEdge(usize),
}

/// [`crate::witness::locate`] of the homogeneous point `x` on the small
/// ring `q`: the same edges in the same order, the same half-open rule.
fn locate(q: &[I], x: [i128; 3]) -> Locus {
    let n = q.len();
    if n == 0 {
        return Locus::Outside;
    }
    let w = i64::try_from(x[2]).expect("W below 2^62");
    // The sign of v − Y for an integer v, Y = X_y / W: with Y's floor `yq`
    // (a point of a small segment: |Y| < 2^29) and whether Y is whole,
    // v − Y has the sign of v − yq, but for v = yq below a fraction. Each
    // vertex's sign is found once and carried to the next edge.
    let wide_w = i128::from(w);
    let yq = i64::try_from(x[1].div_euclid(wide_w)).expect("a small ordinate");
    let whole = x[1].rem_euclid(wide_w) == 0;
    let side = |v: i64| match v.cmp(&yq) {
        Ordering::Equal if !whole => Ordering::Less,
        o => o,
    };
    let mut inside = false;
    let mut ay = side(q[0][1]);
    for j in 0..n {
        let (a, b) = (q[j], q[next(j, q.len())]);
        // Signs of a_y − Y and b_y − Y.
        let by = side(b[1]);
        let ay = std::mem::replace(&mut ay, by);
        if (ay == Ordering::Less && by == Ordering::Less)
            || (ay == Ordering::Greater && by == Ordering::Greater)
        {
            continue;
        }
        let e = sub(b, a);
        let r = [x[0] - wide(a[0], w), x[1] - wide(a[1], w)];
        let t = (mul128(r[1], e[0]) - mul128(r[0], e[1])).cmp(&0);
        let within = |k: usize| {
            let (lo, hi) = (a[k].min(b[k]), a[k].max(b[k]));
            wide(lo, w) <= x[k] && x[k] <= wide(hi, w)
        };
        if t == Ordering::Equal && within(0) && within(1) {
            return Locus::OnEdge(j);
        }
        if (ay == Ordering::Greater) != (by == Ordering::Greater) {
            let up = b[1] > a[1];
            if (up && t == Ordering::Greater) || (!up && t == Ordering::Less) {
                inside = !inside;
            }
        }
    }
    if inside {
        Locus::Inside
    } else {
        Locus::Outside
    }
}

/// The bounding box of a ring.
struct Bounds {
    lo: I,
    hi: I,
}

impl Bounds {
    fn of(q: &[I]) -> Bounds {
        let (mut lo, mut hi) = ([i64::MAX; 2], [i64::MIN; 2]);
        for v in q {
            for k in 0..2 {
                lo[k] = lo[k].min(v[k]);
                hi[k] = hi[k].max(v[k]);
            }
        }
        Bounds { lo, hi }
    }

    /// Whether the closed segment `ab` lies strictly outside the box on
    /// one side (so it has no point in or on the ring).
    fn misses(&self, a: I, b: I) -> bool {
        (0..2).any(|k| a[k].max(b[k]) < self.lo[k] || a[k].min(b[k]) > self.hi[k])
    }
}

/// A directed boundary piece: reduced ends, the direction of its edge.
#[derive(Clone, Debug)]
struct Stretch {
    from: [i128; 3],
    to: [i128; 3],
    dir: D,
    /// `from × to`, twice the signed area it adds to its cycle's: with
    /// `from = a + t0·d` and `to = a + t1·d` on the edge `a → a + d`, it
    /// is `(t1 − t0)·(a × d)`.
    area: Area,
    on_p: Option<usize>,
    on_q: Option<usize>,
}

/// [`super`]'s `boundary_pieces` on small rings.
fn boundary_pieces(p: &[I], q: &[I], p_is_first: bool, shared: bool, out: &mut Vec<Stretch>) {
    let bounds = Bounds::of(q);
    let mut cuts = Vec::with_capacity(8);
    for i in 0..p.len() {
        let (a, b) = (p[i], p[next(i, p.len())]);
        if bounds.misses(a, b) {
            continue; // outside q's box: every piece would be outside q
        }
        let d = sub(b, a);
        cuts_into(a, b, q, &mut cuts);
        // The reduced end of the last kept stretch, by cut index: the next
        // stretch starts at the same cut.
        let mut last_end: Option<(usize, [i128; 3])> = None;
        for (k, w) in cuts.windows(2).enumerate() {
            let other = match locate(q, at(a, b, w[0].mediant(w[1]))) {
                Locus::Inside => None,
                Locus::Outside => continue,
                Locus::OnEdge(j) => {
                    let f = sub(q[next(j, q.len())], q[j]);
                    if !shared || dot(d, f) <= 0 {
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
            let from = match last_end {
                Some((cut, point)) if cut == k => point,
                _ => reduced(at(a, b, w[0])),
            };
            let to = reduced(at(a, b, w[1]));
            last_end = Some((k + 1, to));
            out.push(Stretch {
                from,
                to,
                dir: d,
                area: Area::of(w[0], w[1], cross(a, d)),
                on_p,
                on_q,
            });
        }
    }
}

/// `(t1 − t0)·c` for two cut parameters and an integer `c = a × d`
/// (`|c| < 2^29·2^30·2 = 2^60`): the integer itself when both parameters
/// are whole (`d = 1`: the ends of the edge), else the fraction
/// `(n1·d0 − n0·d1)·c / (d0·d1)` with numerator and denominator each
/// below `2^122` (as `0 ≤ n ≤ d < 2^61`, the module's note) before the
/// factor `c`, which is applied in GMP.
#[derive(Clone, Debug)]
enum Area {
    Whole(i128),
    Part { n: i128, d: i128, c: i64 },
}

impl Area {
    fn of(t0: Frac, t1: Frac, c: i64) -> Area {
        if t0.d == 1 && t1.d == 1 {
            return Area::Whole(wide(t1.n - t0.n, c));
        }
        Area::Part {
            n: wide(t1.n, t0.d) - wide(t0.n, t1.d),
            d: wide(t0.d, t1.d),
            c,
        }
    }
}

/// Whether a cycle of stretches runs counter-clockwise: the sign of the
/// sum of their [`Area`]s. The whole terms are summed in `i128` (each
/// below `2^61` in size, a cycle has far fewer than `2^60` of them), the
/// others in GMP rationals, only when there are any.
fn counter_clockwise<'a>(cycle: impl Iterator<Item = &'a Stretch>) -> bool {
    let mut whole: i128 = 0;
    let mut part: Option<Rational> = None;
    for s in cycle {
        match s.area {
            Area::Whole(v) => whole += v,
            Area::Part { n, d, c } => {
                let mut r = Rational::from((n, d));
                r *= c;
                *part.get_or_insert_with(Rational::new) += r;
            }
        }
    }
    match part {
        None => whole > 0,
        Some(mut r) => {
            r += whole;
            r > 0
        }
    }
}

/// [`super`]'s clockwise order from `r` on integer directions.
fn clockwise_from(r: D, u: D, v: D) -> Ordering {
    let half = |w: D| {
        let c = cross(r, w);
        u8::from(!(c < 0 || (c == 0 && dot(r, w) < 0)))
    };
    half(u).cmp(&half(v)).then_with(|| cross(v, u).cmp(&0))
}

/// [`Intersection::of`] on small rings.
pub(crate) fn intersection(p: &[I], q: &[I]) -> Intersection {
    let mut pieces = Vec::new();
    boundary_pieces(p, q, true, true, &mut pieces);
    boundary_pieces(q, p, false, false, &mut pieces);
    // The pieces by their start (then by index): the pieces leaving a
    // point are one run of this order, found by binary search. Reduced
    // ends are canonical, so equal points have equal triples.
    let mut by_from: Vec<usize> = (0..pieces.len()).collect();
    by_from.sort_unstable_by(|&x, &y| pieces[x].from.cmp(&pieces[y].from).then(x.cmp(&y)));
    let leaving = |here: &[i128; 3]| {
        let lo = by_from.partition_point(|&m| pieces[m].from < *here);
        let len = by_from[lo..].partition_point(|&m| pieces[m].from <= *here);
        &by_from[lo..lo + len]
    };
    let mut used = vec![false; pieces.len()];
    let mut cycles = Vec::new();
    let mut components = 0;
    for start in 0..pieces.len() {
        if used[start] {
            continue;
        }
        let mut cycle: Vec<usize> = Vec::new();
        let mut k = start;
        loop {
            used[k] = true;
            cycle.push(k);
            let here = pieces[k].to;
            let back = [-pieces[k].dir[0], -pieces[k].dir[1]];
            let next = leaving(&here)
                .iter()
                .copied()
                .filter(|&m| !used[m] || m == start)
                .min_by(|&x, &y| clockwise_from(back, pieces[x].dir, pieces[y].dir));
            match next {
                Some(m) if m == start => break,
                Some(m) => k = m,
                None => break,
            }
        }
        if counter_clockwise(cycle.iter().map(|&k| &pieces[k])) {
            components += 1;
        }
        cycles.push(
            cycle
                .into_iter()
                .map(|k| {
                    let s = &pieces[k];
                    BoundaryEdge {
                        from: qpoint(s.from),
                        to: qpoint(s.to),
                        on_p: s.on_p,
                        on_q: s.on_q,
                    }
                })
                .collect(),
        );
    }
    Intersection::with_components(cycles, components)
}

/// [`crate::witness::interiors_overlap`]'s test of the edges of `p`
/// against `q` on small rings.
pub(crate) fn one_side_overlaps(p: &[I], q: &[I]) -> bool {
    let bounds = Bounds::of(q);
    let mut cuts = Vec::with_capacity(8);
    for i in 0..p.len() {
        let (a, b) = (p[i], p[next(i, p.len())]);
        if bounds.misses(a, b) {
            continue;
        }
        let d = sub(b, a);
        cuts_into(a, b, q, &mut cuts);
        for w in cuts.windows(2) {
            match locate(q, at(a, b, w[0].mediant(w[1]))) {
                Locus::Inside => return true,
                Locus::Outside => {}
                Locus::OnEdge(j) => {
                    if dot(d, sub(q[next(j, q.len())], q[j])) > 0 {
                        return true;
                    }
                }
            }
        }
    }
    false
}

/// [`super::pieces_inside`] on small points.
pub(crate) fn pieces_inside(a: I, b: I, q: &[I]) -> usize {
    let cuts = cuts(a, b, q);
    let inside = |t: Frac| !matches!(locate(q, at(a, b, t)), Locus::Outside);
    let mut runs = 0;
    let mut previous = false;
    for (k, &t) in cuts.iter().enumerate() {
        let here = inside(t);
        if here && !previous {
            runs += 1;
        }
        previous = here;
        if let Some(&next) = cuts.get(k + 1) {
            let between = inside(t.mediant(next));
            if between && !previous {
                runs += 1;
            }
            previous = between;
        }
    }
    runs
}

/// The cut parameters of `a → b` by `q`'s boundary as rationals (for
/// tests against the rational path).
#[cfg(test)]
pub(crate) fn cut_rationals(a: I, b: I, q: &[I]) -> Vec<Rational> {
    cuts(a, b, q).into_iter().map(Frac::to_rational).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use rug::Integer;

    #[test]
    fn cuts_equal_the_rational_cuts() {
        let q: Vec<I> = vec![
            [0, 0],
            [6, 0],
            [6, 6],
            [4, 6],
            [4, 2],
            [2, 2],
            [2, 6],
            [0, 6],
        ];
        let qq: Vec<QPoint> = q
            .iter()
            .map(|v| QPoint::new(Rational::from(v[0]), Rational::from(v[1])))
            .collect();
        let pt = |v: I| QPoint::new(Rational::from(v[0]), Rational::from(v[1]));
        for (a, b) in [
            ([-1, 4], [7, 4]),
            ([-1, 1], [7, 1]),
            ([1, 3], [3, 1]),
            ([0, 0], [6, 0]),
            ([2, 2], [4, 2]),
            ([3, -1], [3, 7]),
        ] {
            let mut want = vec![Rational::new(), Rational::from(1)];
            for j in 0..qq.len() {
                want.extend(crate::piece::segment_cuts(
                    &pt(a),
                    &pt(b),
                    &qq[j],
                    &qq[(j + 1) % qq.len()],
                ));
            }
            want.sort();
            want.dedup();
            assert_eq!(cut_rationals(a, b, &q), want, "{a:?}–{b:?}");
        }
    }

    /// The cuts taken from the meeting test's orientations equal the
    /// rational cuts on every pair of segments between points of a small
    /// grid: crossing, touching, collinear, overlapping and apart.
    #[test]
    fn segment_cuts_equal_the_rational_segment_cuts() {
        let grid: Vec<I> = (0..4)
            .flat_map(|x| (0..4).map(move |y| [x * 3 - 2, y * 2 - 3]))
            .collect();
        let pt = |v: I| QPoint::new(Rational::from(v[0]), Rational::from(v[1]));
        let segments: Vec<(I, I)> = grid
            .iter()
            .flat_map(|&a| grid.iter().map(move |&b| (a, b)))
            .filter(|(a, b)| a != b)
            .collect();
        for &(a, b) in &segments {
            for &(c, e) in &segments {
                let mut fast = Vec::new();
                segment_cuts(a, b, c, e, &mut fast);
                let fast: Vec<Rational> = fast.into_iter().map(Frac::to_rational).collect();
                let want = crate::piece::segment_cuts(&pt(a), &pt(b), &pt(c), &pt(e));
                assert_eq!(fast, want, "{a:?}–{b:?} against {c:?}–{e:?}");
            }
        }
    }

    /// The mixed-width gcd equals plain Euclid on wide and narrow values.
    #[test]
    fn gcd_equals_wide_euclid() {
        let wide = |mut a: u128, mut b: u128| {
            while b != 0 {
                (a, b) = (b, a % b);
            }
            a
        };
        let values: [u128; 8] = [
            0,
            1,
            6,
            (1 << 61) - 1,
            (1 << 62) * 3,
            ((1 << 61) - 1) * 12,
            (1u128 << 92) - 7,
            ((1u128 << 40) + 3) * ((1u128 << 50) + 9),
        ];
        for &a in &values {
            for &b in &values {
                assert_eq!(gcd(a, b), wide(a, b), "{a} {b}");
            }
        }
    }

    #[test]
    fn fast_bits_bound_holds() {
        // The worst cases of the implementation note, in GMP integers.
        let two = |k: u32| Integer::from(1) << k;
        let c = two(FAST_BITS); // |coordinate| < c
        let delta = Integer::from(&c * 2u32); // |Δ| < 2c
        let prod = Integer::from(&delta * &delta) * 2u32; // cross, dot: i64
        assert!(prod <= two(61) && prod < two(63));
        let cut_d = prod.clone(); // 0 ≤ n ≤ d < prod
        assert!(Integer::from(&cut_d * &cut_d) < two(127));
        let big_d = Integer::from(&cut_d * 2u32); // mediant: i64
        assert!(big_d < two(63));
        let x = Integer::from(&c * &big_d) + Integer::from(&big_d * &delta);
        let y_off: Integer = &x + Integer::from(&c * &big_d);
        let orient = Integer::from(&delta * &y_off) * 2u32;
        assert!(orient < two(127), "{orient}");
        assert!(x < two(93));
        // An area term: `a × d` in i64, the part fractions in i128.
        assert!(Integer::from(&c * &delta) * 2u32 < two(63));
    }
}
