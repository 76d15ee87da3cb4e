//! The bit bounds of the fast paths, recomputed with GMP.
//!
//! Each fast predicate is written once below, generically over [`Arith`], as
//! the exact sequence of `i128` operations the crate performs. It is then
//! evaluated in three number models:
//!
//! - [`Interval`]: every coordinate ranges over `[-(2^B - 1), 2^B - 1]`.
//!   Interval arithmetic treats every occurrence of a coordinate as
//!   independent, exactly as the `Implementation note` derivations do, so its
//!   peak is a rigorous upper bound on every intermediate value. It must stay
//!   below `2^127`.
//! - [`Exact`] on every adversarial input whose coordinates are `±(2^B - 1)`
//!   (all `2^k` sign patterns): the largest intermediate actually reached, a
//!   lower bound on the true worst case. The slack between the two is
//!   asserted, so that the derivations are documented by a test.
//! - [`Checked`] (`i128` with `checked_*`): at `B + 1` bits some adversarial
//!   input overflows, so the bound cannot be raised by one bit; at `B` bits
//!   none does.

use rug::Integer;
use wai_exact::{
    HOMOGENEOUS_FAST_BITS, INTERSECTION_FAST_BITS, ORIENTATION_FAST_BITS, VECTOR_FAST_BITS,
};

/// The arithmetic of one fast path.
trait Arith: Clone {
    fn sub(&self, o: &Self) -> Self;
    fn add(&self, o: &Self) -> Self;
    fn mul(&self, o: &Self) -> Self;
}

/// An exact value that remembers the largest magnitude of itself and of
/// every intermediate it was computed from.
#[derive(Clone, Debug)]
struct Exact {
    v: Integer,
    peak: Integer,
}

impl Exact {
    fn new(v: Integer) -> Self {
        let peak = Integer::from(v.abs_ref());
        Exact { v, peak }
    }
    fn op(&self, o: &Self, v: Integer) -> Self {
        let abs = Integer::from(v.abs_ref());
        let peak = abs.max(self.peak.clone()).max(o.peak.clone());
        Exact { v, peak }
    }
}

impl Arith for Exact {
    fn sub(&self, o: &Self) -> Self {
        self.op(o, Integer::from(&self.v - &o.v))
    }
    fn add(&self, o: &Self) -> Self {
        self.op(o, Integer::from(&self.v + &o.v))
    }
    fn mul(&self, o: &Self) -> Self {
        self.op(o, Integer::from(&self.v * &o.v))
    }
}

/// A closed integer interval with the peak magnitude of its computation.
#[derive(Clone, Debug)]
struct Interval {
    lo: Integer,
    hi: Integer,
    peak: Integer,
}

impl Interval {
    fn coordinate(m: &Integer) -> Self {
        Interval {
            lo: Integer::from(-m),
            hi: m.clone(),
            peak: m.clone(),
        }
    }
    fn op(&self, o: &Self, lo: Integer, hi: Integer) -> Self {
        let mag = Integer::from(lo.abs_ref()).max(Integer::from(hi.abs_ref()));
        let peak = mag.max(self.peak.clone()).max(o.peak.clone());
        Interval { lo, hi, peak }
    }
}

impl Arith for Interval {
    fn sub(&self, o: &Self) -> Self {
        self.op(
            o,
            Integer::from(&self.lo - &o.hi),
            Integer::from(&self.hi - &o.lo),
        )
    }
    fn add(&self, o: &Self) -> Self {
        self.op(
            o,
            Integer::from(&self.lo + &o.lo),
            Integer::from(&self.hi + &o.hi),
        )
    }
    fn mul(&self, o: &Self) -> Self {
        let ps = [
            Integer::from(&self.lo * &o.lo),
            Integer::from(&self.lo * &o.hi),
            Integer::from(&self.hi * &o.lo),
            Integer::from(&self.hi * &o.hi),
        ];
        let lo = ps.iter().min().expect("four products").clone();
        let hi = ps.iter().max().expect("four products").clone();
        self.op(o, lo, hi)
    }
}

/// `i128` arithmetic that records overflow instead of wrapping or panicking.
#[derive(Clone, Copy, Debug)]
struct Checked(Option<i128>);

impl Checked {
    fn lift(&self, o: &Self, f: fn(i128, i128) -> Option<i128>) -> Self {
        Checked(self.0.zip(o.0).and_then(|(a, b)| f(a, b)))
    }
}

impl Arith for Checked {
    fn sub(&self, o: &Self) -> Self {
        self.lift(o, i128::checked_sub)
    }
    fn add(&self, o: &Self) -> Self {
        self.lift(o, i128::checked_add)
    }
    fn mul(&self, o: &Self) -> Self {
        self.lift(o, i128::checked_mul)
    }
}

fn cross<N: Arith>(ux: &N, uy: &N, vx: &N, vy: &N) -> N {
    ux.mul(vy).sub(&uy.mul(vx))
}

/// `orientation(a, b, c)` as in `predicates.rs`: `c = [ax, ay, bx, by, cx, cy]`.
fn orientation<N: Arith>(c: &[N]) -> N {
    let [ax, ay, bx, by, cx, cy] = c else {
        panic!("6 coordinates")
    };
    bx.sub(ax)
        .mul(&cy.sub(ay))
        .sub(&by.sub(ay).mul(&cx.sub(ax)))
}

/// `compare_along(l = ab, p, q)` as in `predicates.rs`.
fn compare_along<N: Arith>(c: &[N]) -> N {
    let [ax, ay, bx, by, px, py, qx, qy] = c else {
        panic!("8 coordinates")
    };
    qx.sub(px)
        .mul(&bx.sub(ax))
        .add(&qy.sub(py).mul(&by.sub(ay)))
}

/// `Vector::cross(u, v)` as in `vector.rs`: `c = [ux, uy, vx, vy]`.
fn vector_cross<N: Arith>(c: &[N]) -> N {
    let [ux, uy, vx, vy] = c else {
        panic!("4 components")
    };
    cross(ux, uy, vx, vy)
}

/// `Vector::dot(u, v)` as in `vector.rs`.
fn vector_dot<N: Arith>(c: &[N]) -> N {
    let [ux, uy, vx, vy] = c else {
        panic!("4 components")
    };
    ux.mul(vx).add(&uy.mul(vy))
}

/// The homogeneous determinant of `det3_sign_small` in `vector.rs` (the
/// fast path of `turn` and `orientation_rat`): rows `(X, Y, W)` of `a`,
/// `b`, `c`.
fn homogeneous_orientation<N: Arith>(c: &[N]) -> N {
    let [a0, a1, a2, b0, b1, b2, c0, c1, c2] = c else {
        panic!("9 entries")
    };
    let m0 = b1.mul(c2).sub(&b2.mul(c1));
    let m1 = b0.mul(c2).sub(&b2.mul(c0));
    let m2 = b0.mul(c1).sub(&b1.mul(c0));
    a0.mul(&m0).sub(&a1.mul(&m1)).add(&a2.mul(&m2))
}

/// The six points of three lines, as `(ax, ay, bx, by)` per line.
type Lines<'a, N> = [(&'a N, &'a N, &'a N, &'a N); 3];

fn lines<N: Arith>(c: &[N]) -> Lines<'_, N> {
    let [a1x, a1y, b1x, b1y, a2x, a2y, b2x, b2y, a3x, a3y, b3x, b3y] = c else {
        panic!("12 coordinates")
    };
    [
        (a1x, a1y, b1x, b1y),
        (a2x, a2y, b2x, b2y),
        (a3x, a3y, b3x, b3y),
    ]
}

/// `side_of_intersection(l3, l1, l2)` as in `intersection.rs`; the
/// coordinates are those of `l1`, `l2`, `l3`.
fn side_of_intersection<N: Arith>(c: &[N]) -> N {
    let [(a1x, a1y, b1x, b1y), (a2x, a2y, b2x, b2y), (a3x, a3y, b3x, b3y)] = lines(c);
    let (d1x, d1y) = (b1x.sub(a1x), b1y.sub(a1y));
    let (d2x, d2y) = (b2x.sub(a2x), b2y.sub(a2y));
    let (d3x, d3y) = (b3x.sub(a3x), b3y.sub(a3y));
    let den = cross(&d1x, &d1y, &d2x, &d2y);
    let num = cross(&a2x.sub(a1x), &a2y.sub(a1y), &d2x, &d2y);
    let first = cross(&d3x, &d3y, &a1x.sub(a3x), &a1y.sub(a3y)).mul(&den);
    first.add(&num.mul(&cross(&d3x, &d3y, &d1x, &d1y)))
}

/// `compare_intersections_along(l0, l1, l2)` as in `intersection.rs`; the
/// coordinates are those of `l0`, `l1`, `l2`.
fn compare_intersections_along<N: Arith>(c: &[N]) -> N {
    let [(a0x, a0y, b0x, b0y), (a1x, a1y, b1x, b1y), (a2x, a2y, b2x, b2y)] = lines(c);
    let (d0x, d0y) = (b0x.sub(a0x), b0y.sub(a0y));
    let (d1x, d1y) = (b1x.sub(a1x), b1y.sub(a1y));
    let (d2x, d2y) = (b2x.sub(a2x), b2y.sub(a2y));
    let e1 = cross(&d0x, &d0y, &d1x, &d1y);
    let e2 = cross(&d0x, &d0y, &d2x, &d2y);
    let n1 = cross(&a1x.sub(a0x), &a1y.sub(a0y), &d1x, &d1y);
    let n2 = cross(&a2x.sub(a0x), &a2y.sub(a0y), &d2x, &d2y);
    n1.mul(&e2).sub(&n2.mul(&e1))
}

/// A fast path: its formula, its number of coordinates and its bound.
#[derive(Clone, Copy)]
struct FastPath {
    name: &'static str,
    arity: usize,
    bits: u32,
    exact: fn(&[Exact]) -> Exact,
    interval: fn(&[Interval]) -> Interval,
    checked: fn(&[Checked]) -> Checked,
}

fn fast_paths() -> [FastPath; 7] {
    [
        FastPath {
            name: "vector_cross",
            arity: 4,
            bits: VECTOR_FAST_BITS,
            exact: vector_cross,
            interval: vector_cross,
            checked: vector_cross,
        },
        FastPath {
            name: "vector_dot",
            arity: 4,
            bits: VECTOR_FAST_BITS,
            exact: vector_dot,
            interval: vector_dot,
            checked: vector_dot,
        },
        FastPath {
            name: "homogeneous_orientation",
            arity: 9,
            bits: HOMOGENEOUS_FAST_BITS,
            exact: homogeneous_orientation,
            interval: homogeneous_orientation,
            checked: homogeneous_orientation,
        },
        FastPath {
            name: "orientation",
            arity: 6,
            bits: ORIENTATION_FAST_BITS,
            exact: orientation,
            interval: orientation,
            checked: orientation,
        },
        FastPath {
            name: "compare_along",
            arity: 8,
            bits: ORIENTATION_FAST_BITS,
            exact: compare_along,
            interval: compare_along,
            checked: compare_along,
        },
        FastPath {
            name: "side_of_intersection",
            arity: 12,
            bits: INTERSECTION_FAST_BITS,
            exact: side_of_intersection,
            interval: side_of_intersection,
            checked: side_of_intersection,
        },
        FastPath {
            name: "compare_intersections_along",
            arity: 12,
            bits: INTERSECTION_FAST_BITS,
            exact: compare_intersections_along,
            interval: compare_intersections_along,
            checked: compare_intersections_along,
        },
    ]
}

/// The largest coordinate magnitude the fast path with bound `bits` accepts.
fn max_coord(bits: u32) -> Integer {
    (Integer::from(1) << bits) - 1u32
}

/// `i128::MAX = 2^127 - 1` as a GMP integer.
fn i128_max() -> Integer {
    Integer::from(i128::MAX)
}

/// Every input with all coordinates `±m`, as sign patterns `0..2^arity`.
fn corners(arity: usize, m: &Integer) -> impl Iterator<Item = Vec<Integer>> + '_ {
    (0u32..1 << arity).map(move |mask| {
        (0..arity)
            .map(|i| {
                if mask >> i & 1 == 1 {
                    m.clone()
                } else {
                    Integer::from(-m)
                }
            })
            .collect()
    })
}

/// The rigorous (interval) peak magnitude at `bits`.
fn interval_peak(f: &FastPath, bits: u32) -> Integer {
    let m = max_coord(bits);
    let c = vec![Interval::coordinate(&m); f.arity];
    (f.interval)(&c).peak
}

/// The largest intermediate magnitude reached on the corner inputs at `bits`.
fn corner_peak(f: &FastPath, bits: u32) -> Integer {
    let m = max_coord(bits);
    corners(f.arity, &m)
        .map(|c| {
            let c: Vec<Exact> = c.into_iter().map(Exact::new).collect();
            (f.exact)(&c).peak
        })
        .max()
        .expect("at least one corner")
}

/// The corner inputs at `bits` on which the `i128` evaluation overflows.
fn corner_overflows(f: &FastPath, bits: u32) -> usize {
    let m = max_coord(bits);
    corners(f.arity, &m)
        .filter(|c| {
            let c: Vec<Checked> = c.iter().map(|v| Checked(v.to_i128())).collect();
            (f.checked)(&c).0.is_none()
        })
        .count()
}

#[test]
fn every_fast_path_fits_i128_at_its_bound() {
    for f in fast_paths() {
        let peak = interval_peak(&f, f.bits);
        assert!(
            peak <= i128_max(),
            "{}: interval peak {} bits at B = {} exceeds i128",
            f.name,
            peak.significant_bits(),
            f.bits
        );
        assert_eq!(corner_overflows(&f, f.bits), 0, "{}", f.name);
    }
}

#[test]
fn every_fast_path_overflows_one_bit_beyond_its_bound() {
    for f in fast_paths() {
        let peak = corner_peak(&f, f.bits + 1);
        assert!(
            peak > i128_max(),
            "{}: at B + 1 = {} the corner peak has only {} bits; the bound is loose",
            f.name,
            f.bits + 1,
            peak.significant_bits()
        );
        assert!(
            corner_overflows(&f, f.bits + 1) > 0,
            "{}: no i128 overflow at B + 1",
            f.name
        );
    }
}

/// The stated derivations, as bit lengths of the peak magnitude at the bound:
/// the interval (proven) peak and the peak reached on the corner inputs. The
/// true worst case lies between them; `127 - interval bits` is the proven
/// headroom.
#[test]
fn slack_of_each_bound_is_as_derived() {
    fn check(name: &str, expect_interval_bits: u32, expect_corner_bits: u32) {
        let f = fast_paths()
            .into_iter()
            .find(|f| f.name == name)
            .expect("known fast path");
        let (iv, co) = (interval_peak(&f, f.bits), corner_peak(&f, f.bits));
        assert!(
            co <= iv,
            "{name}: the corner peak exceeds the interval bound"
        );
        assert_eq!(
            (iv.significant_bits(), co.significant_bits()),
            (expect_interval_bits, expect_corner_bits),
            "{name}: (interval, corner) peak bits"
        );
    }
    // orientation: differences <= 2^63 - 2, products <= (2^63 - 2)^2 < 2^126
    // (reached), their difference < 2^127 by the derivation. The final
    // determinant is twice a triangle area in a square of side 2^63 - 2, so
    // it never exceeds a single product: the corner peak stays at 126 bits.
    check("orientation", 127, 126);
    // compare_along: four independent differences, so the sum of the two
    // products 2 (2^63 - 2)^2 = 2^127 - 2^66 + 8 is reached: the bound is
    // tight.
    check("compare_along", 127, 127);
    // The 2^(4B + 7) of the intersection note: cross products of two
    // independent differences reach 2 (2^31 - 2)^2 < 2^63; the corner inputs
    // reach 125 bits, one or two below the proven 127.
    check("side_of_intersection", 127, 125);
    check("compare_intersections_along", 127, 125);
    // Vector::cross and Vector::dot: components below 2^63, products below
    // 2^126, their sum or difference reaches 2 (2^63 - 1)^2 < 2^127: tight.
    check("vector_cross", 127, 127);
    check("vector_dot", 127, 127);
    // The homogeneous determinant at B = 41: minors below 2^83, terms below
    // 2^124, the sum of three below 3 · 2^124 < 2^126 (proven); the corner
    // inputs reach 125 bits.
    check("homogeneous_orientation", 126, 125);
}

/// The derivation of each note, number by number: differences, cross
/// products and products of cross products at `B = 30`, and the orientation
/// note at `B = 62`.
#[test]
fn note_numbers_recomputed() {
    let two = |e: u32| Integer::from(1) << e;
    // Orientation note: |d| <= 2^63 - 2, |d d'| < 2^126, sum < 2^127.
    let m = max_coord(ORIENTATION_FAST_BITS);
    let d = Integer::from(&m * 2u32);
    assert_eq!(d, two(63) - 2u32);
    let prod = Integer::from(&d * &d);
    assert!(prod < two(126));
    assert!(Integer::from(&prod * 2u32) < two(127));
    // Intersection note: |d| < 2^(B + 1), |cross| < 2^(2B + 3), product
    // < 2^(4B + 6), sum < 2^(4B + 7) = 2^127.
    let b = INTERSECTION_FAST_BITS;
    let m = max_coord(b);
    let d = Integer::from(&m * 2u32);
    assert!(d < two(b + 1));
    let cr = Integer::from(&d * &d) * 2u32;
    assert!(cr < two(2 * b + 3));
    let prod = Integer::from(&cr * &cr);
    assert!(prod < two(4 * b + 6));
    assert!(Integer::from(&prod * 2u32) < two(4 * b + 7));
    assert_eq!(4 * b + 7, 127);
}

/// A planted violation: the checker must reject a bound one bit too large.
#[test]
fn interval_checker_rejects_a_bound_too_large() {
    for f in fast_paths() {
        assert!(interval_peak(&f, f.bits + 1) > i128_max(), "{}", f.name);
    }
}
