//! Laws of the predicates and of `RatPoint`, with exact equality.
//!
//! Orientation is antisymmetric under a swap, invariant under a cyclic
//! shift, integer translation, 90° rotation and positive scaling, and flips
//! under reflection; the line predicates obey the matching laws. Inputs mix
//! small coordinates with ones that the transformation pushes across the
//! fast-path bound, so each law also relates the `i128` and GMP paths.

use crate::common::{config, ln, pt, qc, rat};
use proptest::prelude::*;
use quickcheck::TestResult;
use rug::{Integer, Rational};
use std::cmp::Ordering;
use std::collections::hash_map::DefaultHasher;
use std::hash::{Hash, Hasher};
use wai_exact::{
    compare_along, compare_intersections_along, orientation, side_of_intersection, Line,
    Orientation, Point, RatPoint, Side, INTERSECTION_FAST_BITS, ORIENTATION_FAST_BITS,
};

fn translate(p: Point, t: Point) -> Point {
    pt(p.x + t.x, p.y + t.y)
}
fn rot90(p: Point) -> Point {
    pt(-p.y, p.x)
}
fn reflect(p: Point) -> Point {
    pt(p.x, -p.y)
}
fn scale(p: Point, k: i128) -> Point {
    pt(p.x * k, p.y * k)
}
fn map_line(l: &Line, f: impl Fn(Point) -> Point) -> Line {
    ln(f(l.a()), f(l.b()))
}

fn flip(s: Side) -> Side {
    match s {
        Side::Left => Side::Right,
        Side::On => Side::On,
        Side::Right => Side::Left,
    }
}

/// Coordinates below `2^(bits - 1)`: small ones and ones near the top, so
/// that a translation by another such value may cross `2^bits`.
fn coord(bits: u32) -> impl Strategy<Value = i128> + Clone {
    let top = 1i128 << (bits - 1);
    prop_oneof![-16i128..=16, -top..=top, Just(top), Just(-top)]
}

fn point(bits: u32) -> impl Strategy<Value = Point> + Clone {
    (coord(bits), coord(bits)).prop_map(|(x, y)| pt(x, y))
}

fn line(bits: u32) -> impl Strategy<Value = Line> + Clone {
    (point(bits), point(bits)).prop_filter_map("distinct", |(a, b)| Line::new(a, b))
}

const O: u32 = ORIENTATION_FAST_BITS;
const I: u32 = INTERSECTION_FAST_BITS;

proptest! {
    #![proptest_config(config(1000))]

    #[test]
    fn orientation_laws(a in point(O), b in point(O), c in point(O), t in point(O), k in 1i128..=1 << 20) {
        let o = orientation(a, b, c);
        prop_assert_eq!(orientation(b, a, c), o.reverse(), "swap");
        prop_assert_eq!(orientation(a, c, b), o.reverse(), "swap");
        prop_assert_eq!(orientation(b, c, a), o, "cyclic");
        prop_assert_eq!(orientation(c, a, b), o, "cyclic");
        let tr = |p| translate(p, t);
        prop_assert_eq!(orientation(tr(a), tr(b), tr(c)), o, "translation");
        prop_assert_eq!(orientation(rot90(a), rot90(b), rot90(c)), o, "rotation");
        prop_assert_eq!(orientation(reflect(a), reflect(b), reflect(c)), o.reverse(), "reflection");
        let sc = |p| scale(p, k);
        prop_assert_eq!(orientation(sc(a), sc(b), sc(c)), o, "scaling");
        // The degenerate triples.
        prop_assert_eq!(orientation(a, a, c), Orientation::Collinear);
        prop_assert_eq!(orientation(a, b, a), Orientation::Collinear);
    }

    #[test]
    fn compare_along_laws(l in line(O), p in point(O), q in point(O), t in point(O)) {
        let c = compare_along(&l, p, q);
        prop_assert_eq!(compare_along(&l, q, p), c.reverse(), "swap");
        prop_assert_eq!(compare_along(&l.reversed(), p, q), c.reverse(), "reversed line");
        prop_assert_eq!(compare_along(&l, p, p), Ordering::Equal);
        let tr = |x| translate(x, t);
        prop_assert_eq!(compare_along(&map_line(&l, tr), tr(p), tr(q)), c, "translation");
        prop_assert_eq!(compare_along(&map_line(&l, rot90), rot90(p), rot90(q)), c, "rotation");
        prop_assert_eq!(compare_along(&map_line(&l, reflect), reflect(p), reflect(q)), c, "reflection");
    }

    #[test]
    fn side_of_intersection_laws(l3 in line(I), l1 in line(I), l2 in line(I), t in point(I)) {
        let s = side_of_intersection(&l3, &l1, &l2);
        prop_assert_eq!(side_of_intersection(&l3, &l2, &l1), s, "swap the meeting lines");
        prop_assert_eq!(side_of_intersection(&l3, &l1.reversed(), &l2), s, "direction of l1");
        prop_assert_eq!(side_of_intersection(&l3.reversed(), &l1, &l2), s.map(flip), "reversed l3");
        let tr = |x| translate(x, t);
        let (m3, m1, m2) = (map_line(&l3, tr), map_line(&l1, tr), map_line(&l2, tr));
        prop_assert_eq!(side_of_intersection(&m3, &m1, &m2), s, "translation");
        let (m3, m1, m2) = (map_line(&l3, rot90), map_line(&l1, rot90), map_line(&l2, rot90));
        prop_assert_eq!(side_of_intersection(&m3, &m1, &m2), s, "rotation");
        let (m3, m1, m2) = (map_line(&l3, reflect), map_line(&l1, reflect), map_line(&l2, reflect));
        prop_assert_eq!(side_of_intersection(&m3, &m1, &m2), s.map(flip), "reflection");
    }

    #[test]
    fn compare_intersections_along_laws(l0 in line(I), l1 in line(I), l2 in line(I), t in point(I)) {
        let c = compare_intersections_along(&l0, &l1, &l2);
        prop_assert_eq!(compare_intersections_along(&l0, &l2, &l1), c.map(Ordering::reverse), "swap");
        prop_assert_eq!(compare_intersections_along(&l0.reversed(), &l1, &l2), c.map(Ordering::reverse), "reversed l0");
        prop_assert_eq!(compare_intersections_along(&l0, &l1.reversed(), &l2.reversed()), c, "direction of l1, l2");
        let tr = |x| translate(x, t);
        let (m0, m1, m2) = (map_line(&l0, tr), map_line(&l1, tr), map_line(&l2, tr));
        prop_assert_eq!(compare_intersections_along(&m0, &m1, &m2), c, "translation");
        let (m0, m1, m2) = (map_line(&l0, rot90), map_line(&l1, rot90), map_line(&l2, rot90));
        prop_assert_eq!(compare_intersections_along(&m0, &m1, &m2), c, "rotation");
        let (m0, m1, m2) = (map_line(&l0, reflect), map_line(&l1, reflect), map_line(&l2, reflect));
        prop_assert_eq!(compare_intersections_along(&m0, &m1, &m2), c, "reflection");
        if c.is_some() {
            prop_assert_eq!(compare_intersections_along(&l0, &l1, &l1), Some(Ordering::Equal));
        }
    }
}

/// The orientation laws once more with quickcheck, on full-range `i128`
/// points shifted into `±2^100` (every path: fast, GMP, mixed).
#[test]
fn quickcheck_orientation_laws() {
    fn law(a: (i128, i128), b: (i128, i128), c: (i128, i128), t: (i128, i128)) -> TestResult {
        let clamp = |v: i128| v >> 27;
        let p = |v: (i128, i128)| pt(clamp(v.0), clamp(v.1));
        let (a, b, c, t) = (p(a), p(b), p(c), p(t));
        let o = orientation(a, b, c);
        let tr = |x| translate(x, t);
        let ok = orientation(b, a, c) == o.reverse()
            && orientation(b, c, a) == o
            && orientation(tr(a), tr(b), tr(c)) == o
            && orientation(rot90(a), rot90(b), rot90(c)) == o
            && orientation(reflect(a), reflect(b), reflect(c)) == o.reverse();
        TestResult::from_bool(ok)
    }
    qc(2000).quickcheck(law as fn(_, _, _, _) -> TestResult);
}

// ---------------------------------------------------------------------------
// RatPoint: canonical form and Display.

fn hash(p: &RatPoint) -> u64 {
    let mut h = DefaultHasher::new();
    p.hash(&mut h);
    h.finish()
}

#[test]
fn ratpoint_canonical_cases() {
    fn check(input: (i128, i128, i128), expect: (i128, i128, i128)) {
        let p = rat(input.0, input.1, input.2);
        let got = (p.hx().clone(), p.hy().clone(), p.hw().clone());
        let want = (
            Integer::from(expect.0),
            Integer::from(expect.1),
            Integer::from(expect.2),
        );
        assert_eq!(got, want, "{input:?}");
        let e = rat(expect.0, expect.1, expect.2);
        assert_eq!(p, e);
        assert_eq!(hash(&p), hash(&e));
    }
    check((2, 4, 2), (1, 2, 1));
    check((1, 2, 1), (1, 2, 1));
    check((-2, 4, -2), (1, -2, 1));
    check((3, 6, 9), (1, 2, 3));
    check((3, 5, -7), (-3, -5, 7));
    check((0, 0, 5), (0, 0, 1));
    check((0, 0, -5), (0, 0, 1));
    check((0, 6, 4), (0, 3, 2));
    check((6, 10, 4), (3, 5, 2));
    check((i128::MAX, i128::MAX, i128::MAX), (1, 1, 1));
    check((i128::MIN, 0, i128::MIN), (1, 0, 1));
    assert!(RatPoint::new(Integer::from(1), Integer::from(2), Integer::new()).is_none());
    assert_eq!(rat(2, 4, 2).to_point(), Some(pt(1, 2)));
    assert_eq!(rat(1, 4, 2).to_point(), None);
    assert_eq!(RatPoint::from(pt(-3, 7)), rat(-6, 14, 2));
}

#[test]
fn ratpoint_display_cases() {
    fn check(input: (i128, i128, i128), expect: &str) {
        assert_eq!(
            rat(input.0, input.1, input.2).to_string(),
            expect,
            "{input:?}"
        );
    }
    check((1, 3, 2), "(1/2, 3/2)");
    check((3, -2, 2), "(3/2, -1)");
    check((2, 4, 2), "(1, 2)");
    check((0, 0, 7), "(0, 0)");
    check((-1, 4, -6), "(1/6, -2/3)");
    check((5, 10, 15), "(1/3, 2/3)");
    check((1, 0, -3), "(-1/3, 0)");
    check(
        (i128::MAX, 1, 2),
        "(170141183460469231731687303715884105727/2, 1/2)",
    );
}

proptest! {
    #![proptest_config(config(1000))]

    /// Equal values give equal structs: scaling the homogeneous triple by
    /// any nonzero integer changes nothing; the stored form is canonical.
    #[test]
    fn ratpoint_canonical_law(x in -1000i128..=1000, y in -1000i128..=1000, w in -50i128..=50, k in -1000i128..=1000) {
        prop_assume!(w != 0 && k != 0);
        let p = rat(x, y, w);
        let s = rat(k * x, k * y, k * w);
        prop_assert_eq!(&p, &s);
        prop_assert_eq!(hash(&p), hash(&s));
        prop_assert!(*p.hw() > 0);
        let g = Integer::from(p.hx().gcd_ref(p.hy())).gcd(p.hw());
        prop_assert_eq!(g, 1);
        // The value is kept: x / w == hx / hw.
        prop_assert_eq!(Rational::from((x, w)), Rational::from((p.hx().clone(), p.hw().clone())));
        prop_assert_eq!(Rational::from((y, w)), Rational::from((p.hy().clone(), p.hw().clone())));
    }

    /// Display prints each coordinate in lowest terms and reads back exactly.
    #[test]
    fn ratpoint_display_roundtrip(x in any::<i64>(), y in any::<i64>(), w in any::<i64>()) {
        prop_assume!(w != 0);
        let p = rat(x.into(), y.into(), w.into());
        let s = p.to_string();
        let inner = s.strip_prefix('(').and_then(|s| s.strip_suffix(')')).expect("parenthesised");
        let (sx, sy) = inner.split_once(", ").expect("two coordinates");
        let (rx, ry): (Rational, Rational) = (sx.parse().expect("x"), sy.parse().expect("y"));
        prop_assert_eq!(rx, Rational::from((x, w)));
        prop_assert_eq!(ry, Rational::from((y, w)));
        for part in [sx, sy] {
            // An integer prints without a denominator; a fraction's is above 1.
            if let Some((_, den)) = part.split_once('/') {
                prop_assert!(den.parse::<Integer>().expect("denominator") > 1);
            }
        }
    }

    #[test]
    fn midpoint_laws(p in (-99i128..=99, -99i128..=99, 1i128..=9), q in (-99i128..=99, -99i128..=99, 1i128..=9)) {
        let (p, q) = (rat(p.0, p.1, p.2), rat(q.0, q.1, q.2));
        let m = RatPoint::midpoint(&p, &q);
        prop_assert_eq!(&m, &RatPoint::midpoint(&q, &p));
        prop_assert_eq!(RatPoint::midpoint(&p, &p), p.clone());
        // m - p == q - m, exactly.
        let c = |r: &RatPoint| crate::common::coords(r);
        let ((mx, my), (px, py), (qx, qy)) = (c(&m), c(&p), c(&q));
        prop_assert_eq!(Rational::from(&mx - &px), qx - mx);
        prop_assert_eq!(Rational::from(&my - &py), qy - my);
    }
}

/// `RatPoint::from_rationals` keeps both coordinates exactly, over their
/// least common denominator.
#[test]
fn rat_point_from_rationals_is_exact() {
    use rug::{Integer, Rational};
    let p = wai_exact::RatPoint::from_rationals(Rational::from((3, 4)), Rational::from((-5, 6)));
    assert_eq!(
        (p.hx(), p.hy(), p.hw()),
        (&Integer::from(9), &Integer::from(-10), &Integer::from(12))
    );
    let q = wai_exact::RatPoint::from_rationals(Rational::from(2), Rational::from((1, 2)));
    assert_eq!(
        q,
        wai_exact::RatPoint::new(4.into(), 1.into(), 2.into()).unwrap()
    );
}
