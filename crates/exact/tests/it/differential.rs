//! Fast predicates against their GMP versions in `wai_exact::reference` and
//! against independent `rug::Rational` constructions.
//!
//! Four regimes of input: (a) small random coordinates, (b) coordinates at
//! the bound of the fast path (`±(2^B - 1)`, `±2^(B - 1)`, `0`, `±1` and
//! random values below `2^B`), (c) beyond the bound, up to `2^100` (routed to
//! GMP, checked against a rational construction), and (d) degenerate inputs
//! built to be degenerate: collinear triples `a + k d`, three lines through
//! one integer point, parallel lines.

use crate::common::{config, coords, cross_sign, dot_sign, ln, meet, pt, qc, rat};
use proptest::prelude::*;
use quickcheck::TestResult;
use rug::Integer;
use std::cmp::Ordering;
use wai_exact::{
    compare_along, compare_intersections_along, construct_intersection,
    construct_intersection_i128, orientation, reference, side_of_intersection, side_of_line_rat,
    signed_area_twice, Line, Orientation, Point, Side, INTERSECTION_FAST_BITS,
    ORIENTATION_FAST_BITS,
};

// ---------------------------------------------------------------------------
// The checks: each compares the fast predicate with every other answer.

fn check_orientation(a: Point, b: Point, c: Point) {
    let fast = orientation(a, b, c);
    assert_eq!(fast, reference::orientation(a, b, c), "{a} {b} {c}");
    // Independent: the sign of the triangle's doubled signed area.
    let area = Orientation::from_area(signed_area_twice(&[a, b, c]));
    assert_eq!(fast, area, "{a} {b} {c}");
}

fn check_compare_along(l: &Line, p: Point, q: Point) {
    let fast = compare_along(l, p, q);
    assert_eq!(fast, reference::compare_along(l, p, q), "{l:?} {p} {q}");
    let (pr, qr) = (rq(p), rq(q));
    assert_eq!(fast, dot_sign(l, &pr, &qr).reverse(), "{l:?} {p} {q}");
}

fn check_side_of_intersection(l3: &Line, l1: &Line, l2: &Line) {
    let fast = side_of_intersection(l3, l1, l2);
    assert_eq!(
        fast,
        reference::side_of_intersection(l3, l1, l2),
        "{l3:?} {l1:?} {l2:?}"
    );
    // Constructed with the crate, decided by side_of_line_rat.
    let built = construct_intersection(l1, l2).map(|i| side_of_line_rat(l3, &i));
    assert_eq!(fast, built, "{l3:?} {l1:?} {l2:?}");
    // Constructed by Cramer's rule in rug::Rational, decided by a cross product.
    let indep = meet(l1, l2).map(|i| side_from(cross_sign(l3, &i)));
    assert_eq!(fast, indep, "{l3:?} {l1:?} {l2:?}");
}

fn check_compare_intersections_along(l0: &Line, l1: &Line, l2: &Line) {
    let fast = compare_intersections_along(l0, l1, l2);
    assert_eq!(
        fast,
        reference::compare_intersections_along(l0, l1, l2),
        "{l0:?} {l1:?} {l2:?}"
    );
    let built = construct_intersection(l0, l1)
        .zip(construct_intersection(l0, l2))
        .map(|(i1, i2)| dot_sign(l0, &coords(&i1), &coords(&i2)).reverse());
    assert_eq!(fast, built, "{l0:?} {l1:?} {l2:?}");
    let indep = meet(l0, l1)
        .zip(meet(l0, l2))
        .map(|(i1, i2)| dot_sign(l0, &i1, &i2).reverse());
    assert_eq!(fast, indep, "{l0:?} {l1:?} {l2:?}");
}

trait FromArea {
    fn from_area(a: Integer) -> Self;
}

impl FromArea for Orientation {
    fn from_area(a: Integer) -> Self {
        match a.cmp0() {
            Ordering::Greater => Orientation::CounterClockwise,
            Ordering::Equal => Orientation::Collinear,
            Ordering::Less => Orientation::Clockwise,
        }
    }
}

fn side_from(o: Ordering) -> Side {
    match o {
        Ordering::Greater => Side::Left,
        Ordering::Equal => Side::On,
        Ordering::Less => Side::Right,
    }
}

fn rq(p: Point) -> (rug::Rational, rug::Rational) {
    (p.x.into(), p.y.into())
}

// ---------------------------------------------------------------------------
// proptest strategies.

/// Coordinates of magnitude below `2^bits`.
fn small(bits: u32) -> impl Strategy<Value = i128> + Clone {
    let m = (1i128 << bits) - 1;
    -m..=m
}

/// Coordinates at the bound `bits` of a fast path: the extremes, the
/// midpoint power, the tiny values, and uniform values below `2^bits`.
fn at_bound(bits: u32) -> impl Strategy<Value = i128> + Clone {
    let m = (1i128 << bits) - 1;
    let h = 1i128 << (bits - 1);
    prop_oneof![
        2 => Just(m),
        2 => Just(-m),
        1 => Just(h),
        1 => Just(-h),
        1 => Just(0),
        1 => Just(1),
        1 => Just(-1),
        3 => -m..=m,
    ]
}

/// Coordinates at and beyond the bound `bits`, up to `2^100`: the first
/// values past the bound, powers of two up to `2^100` and uniform values.
fn beyond(bits: u32) -> impl Strategy<Value = i128> + Clone {
    let b = 1i128 << bits;
    let top = 1i128 << 100;
    prop_oneof![
        1 => Just(b),
        1 => Just(-b),
        1 => Just(b + 1),
        1 => Just(-b - 1),
        1 => Just(top),
        1 => Just(-top),
        2 => (bits..=100u32).prop_map(|e| 1i128 << e),
        2 => at_bound(bits),
        4 => -top..=top,
    ]
}

fn point<S: Strategy<Value = i128> + Clone>(c: S) -> impl Strategy<Value = Point> + Clone {
    (c.clone(), c).prop_map(|(x, y)| pt(x, y))
}

fn line<S: Strategy<Value = i128> + Clone>(c: S) -> impl Strategy<Value = Line> + Clone {
    (point(c.clone()), point(c)).prop_filter_map("distinct endpoints", |(a, b)| Line::new(a, b))
}

const O: u32 = ORIENTATION_FAST_BITS;
const I: u32 = INTERSECTION_FAST_BITS;

proptest! {
    #![proptest_config(config(5000))]

    // (a) small coordinates.
    #[test]
    fn orientation_small(a in point(small(8)), b in point(small(8)), c in point(small(8))) {
        check_orientation(a, b, c);
    }
    #[test]
    fn compare_along_small(l in line(small(8)), p in point(small(8)), q in point(small(8))) {
        check_compare_along(&l, p, q);
    }
    #[test]
    fn side_of_intersection_small(l3 in line(small(4)), l1 in line(small(4)), l2 in line(small(4))) {
        check_side_of_intersection(&l3, &l1, &l2);
    }
    #[test]
    fn compare_intersections_along_small(l0 in line(small(4)), l1 in line(small(4)), l2 in line(small(4))) {
        check_compare_intersections_along(&l0, &l1, &l2);
    }

    // (b) at the bound.
    #[test]
    fn orientation_at_bound(a in point(at_bound(O)), b in point(at_bound(O)), c in point(at_bound(O))) {
        check_orientation(a, b, c);
    }
    #[test]
    fn compare_along_at_bound(l in line(at_bound(O)), p in point(at_bound(O)), q in point(at_bound(O))) {
        check_compare_along(&l, p, q);
    }
    #[test]
    fn side_of_intersection_at_bound(l3 in line(at_bound(I)), l1 in line(at_bound(I)), l2 in line(at_bound(I))) {
        check_side_of_intersection(&l3, &l1, &l2);
    }
    #[test]
    fn compare_intersections_along_at_bound(l0 in line(at_bound(I)), l1 in line(at_bound(I)), l2 in line(at_bound(I))) {
        check_compare_intersections_along(&l0, &l1, &l2);
    }

    // (c) beyond the bound.
    #[test]
    fn orientation_beyond(a in point(beyond(O)), b in point(beyond(O)), c in point(beyond(O))) {
        check_orientation(a, b, c);
    }
    #[test]
    fn compare_along_beyond(l in line(beyond(O)), p in point(beyond(O)), q in point(beyond(O))) {
        check_compare_along(&l, p, q);
    }
    #[test]
    fn side_of_intersection_beyond(l3 in line(beyond(I)), l1 in line(beyond(I)), l2 in line(beyond(I))) {
        check_side_of_intersection(&l3, &l1, &l2);
    }
    #[test]
    fn compare_intersections_along_beyond(l0 in line(beyond(I)), l1 in line(beyond(I)), l2 in line(beyond(I))) {
        check_compare_intersections_along(&l0, &l1, &l2);
    }
}

// ---------------------------------------------------------------------------
// (d) degenerate inputs, built to be degenerate.

/// `a + k d`, or `None` on `i128` overflow.
fn along(a: Point, k: i128, d: Point) -> Option<Point> {
    Some(pt(
        a.x.checked_add(k.checked_mul(d.x)?)?,
        a.y.checked_add(k.checked_mul(d.y)?)?,
    ))
}

/// A base point in any regime, so that degenerate inputs also straddle the
/// bounds.
fn base(bits: u32) -> impl Strategy<Value = i128> + Clone {
    prop_oneof![small(8), at_bound(bits), beyond(bits)]
}

/// A nonzero direction with small coordinates.
fn direction() -> impl Strategy<Value = Point> + Clone {
    point(small(6)).prop_filter("nonzero", |d| *d != pt(0, 0))
}

/// A line through `c` with direction `d`: the points `c + s d`, `c + t d`.
fn line_through(c: Point, d: Point, s: i128, t: i128) -> Option<Line> {
    Line::new(along(c, s, d)?, along(c, t, d)?)
}

proptest! {
    #![proptest_config(config(1000))]

    #[test]
    fn collinear_triples(a in point(base(O)), d in direction(), k in prop::array::uniform3(-1000i128..=1000)) {
        let [p, q, r] = k.map(|k| along(a, k, d));
        let (Some(p), Some(q), Some(r)) = (p, q, r) else { return Ok(()) };
        check_orientation(p, q, r);
        prop_assert_eq!(orientation(p, q, r), Orientation::Collinear);
        prop_assert_eq!(orientation(r, p, q), Orientation::Collinear);
        // Along the line from a to a + d, the points come in the order of k.
        let l = ln(a, along(a, 1, d).expect("small"));
        check_compare_along(&l, p, q);
        prop_assert_eq!(compare_along(&l, p, q), k[0].cmp(&k[1]));
    }

    #[test]
    fn three_lines_through_one_point(
        c in point(base(I)),
        d in prop::array::uniform3(direction()),
        s in prop::array::uniform3(-50i128..=50),
        t in prop::array::uniform3(-50i128..=50),
    ) {
        let ls: Vec<Option<Line>> = (0..3).map(|i| line_through(c, d[i], s[i], t[i])).collect();
        let (Some(l1), Some(l2), Some(l3)) = (ls[0], ls[1], ls[2]) else { return Ok(()) };
        check_side_of_intersection(&l3, &l1, &l2);
        check_compare_intersections_along(&l3, &l1, &l2);
        let parallel = |a: Point, b: Point| a.x * b.y == a.y * b.x;
        let expect = (!parallel(d[0], d[1])).then_some(Side::On);
        prop_assert_eq!(side_of_intersection(&l3, &l1, &l2), expect);
        // l1 and l2 meet l3 in the same point c, unless one is parallel to it.
        let expect = (!parallel(d[2], d[0]) && !parallel(d[2], d[1])).then_some(Ordering::Equal);
        prop_assert_eq!(compare_intersections_along(&l3, &l1, &l2), expect);
        if let Some(i) = construct_intersection(&l1, &l2) {
            prop_assert_eq!(i.to_point(), Some(c));
        }
    }

    #[test]
    fn parallel_lines_give_none(
        l1 in line(base(I)),
        a2 in point(base(I)),
        k in (-20i128..=20).prop_filter("nonzero", |k| *k != 0),
        l3 in line(base(I)),
    ) {
        let d1 = pt(l1.b().x - l1.a().x, l1.b().y - l1.a().y);
        let Some(b2) = along(a2, k, d1) else { return Ok(()) };
        let l2 = ln(a2, b2);
        check_side_of_intersection(&l3, &l1, &l2);
        prop_assert_eq!(side_of_intersection(&l3, &l1, &l2), None);
        prop_assert_eq!(side_of_intersection(&l3, &l1, &l1), None);
        // l0 parallel to the first or the second line.
        check_compare_intersections_along(&l1, &l2, &l3);
        prop_assert_eq!(compare_intersections_along(&l1, &l2, &l3), None);
        prop_assert_eq!(compare_intersections_along(&l1, &l3, &l2), None);
        prop_assert!(construct_intersection(&l1, &l2).is_none());
    }
}

// ---------------------------------------------------------------------------
// The same differential checks with quickcheck: raw i128 values shaped into
// each regime by a selector byte.

/// Shape a raw `i128` into a coordinate of the regime `bits` chosen by
/// `sel`: special values at the bound, or uniform below `2^bits`, or (with
/// `wide`) uniform up to `2^100`.
fn shape(sel: u8, raw: i128, bits: u32, wide: bool) -> i128 {
    let m = (1i128 << bits) - 1;
    let uniform = |top: i128| raw.rem_euclid(2 * top + 1) - top;
    match sel % 12 {
        0 => m,
        1 => -m,
        2 => 1 << (bits - 1),
        3 => 0,
        4 => 1,
        5 => -1,
        6 if wide => m + 1,
        7 if wide => -m - 1,
        8 | 9 if wide => uniform(1 << 100),
        _ => uniform(m),
    }
}

fn shaped<const N: usize>(raw: [(u8, i128); N], bits: u32, wide: bool) -> [i128; N] {
    raw.map(|(s, r)| shape(s, r, bits, wide))
}

fn qc_line(x: &[i128]) -> Option<Line> {
    Line::new(pt(x[0], x[1]), pt(x[2], x[3]))
}

fn qc_orientation(raw: [(u8, i128); 6], bits: u32, wide: bool) -> TestResult {
    let c = shaped(raw, bits, wide);
    check_orientation(pt(c[0], c[1]), pt(c[2], c[3]), pt(c[4], c[5]));
    TestResult::passed()
}

fn qc_compare_along(raw: [(u8, i128); 8], bits: u32, wide: bool) -> TestResult {
    let c = shaped(raw, bits, wide);
    let Some(l) = qc_line(&c[..4]) else {
        return TestResult::discard();
    };
    check_compare_along(&l, pt(c[4], c[5]), pt(c[6], c[7]));
    TestResult::passed()
}

fn qc_three_lines(raw: [(u8, i128); 12], bits: u32, wide: bool) -> TestResult {
    let c = shaped(raw, bits, wide);
    let (Some(l0), Some(l1), Some(l2)) = (qc_line(&c[..4]), qc_line(&c[4..8]), qc_line(&c[8..]))
    else {
        return TestResult::discard();
    };
    check_side_of_intersection(&l0, &l1, &l2);
    check_compare_intersections_along(&l0, &l1, &l2);
    TestResult::passed()
}

#[test]
fn quickcheck_orientation_and_compare_along() {
    fn at_bound(raw: [(u8, i128); 6]) -> TestResult {
        qc_orientation(raw, O, false)
    }
    fn beyond(raw: [(u8, i128); 6]) -> TestResult {
        qc_orientation(raw, O, true)
    }
    fn small(raw: [(u8, i128); 6]) -> TestResult {
        qc_orientation(raw, 6, false)
    }
    fn along_at_bound(raw: [(u8, i128); 8]) -> TestResult {
        qc_compare_along(raw, O, false)
    }
    fn along_beyond(raw: [(u8, i128); 8]) -> TestResult {
        qc_compare_along(raw, O, true)
    }
    type P6 = fn([(u8, i128); 6]) -> TestResult;
    type P8 = fn([(u8, i128); 8]) -> TestResult;
    qc(2000).quickcheck(at_bound as P6);
    qc(2000).quickcheck(beyond as P6);
    qc(2000).quickcheck(small as P6);
    qc(2000).quickcheck(along_at_bound as P8);
    qc(2000).quickcheck(along_beyond as P8);
}

#[test]
fn quickcheck_intersection_predicates() {
    fn small(raw: [(u8, i128); 12]) -> TestResult {
        qc_three_lines(raw, 3, false)
    }
    fn at_bound(raw: [(u8, i128); 12]) -> TestResult {
        qc_three_lines(raw, I, false)
    }
    fn beyond(raw: [(u8, i128); 12]) -> TestResult {
        qc_three_lines(raw, I, true)
    }
    type P12 = fn([(u8, i128); 12]) -> TestResult;
    qc(2000).quickcheck(small as P12);
    qc(2000).quickcheck(at_bound as P12);
    qc(2000).quickcheck(beyond as P12);
}

/// Full-range `i128` coordinates (quickcheck's own `i128`, which includes
/// `i128::MIN` and `i128::MAX`): the predicates stay exact for any `i128`.
#[test]
fn quickcheck_full_i128_range() {
    fn orient(a: (i128, i128), b: (i128, i128), c: (i128, i128)) -> TestResult {
        check_orientation(pt(a.0, a.1), pt(b.0, b.1), pt(c.0, c.1));
        TestResult::passed()
    }
    fn lines(p: [i128; 12]) -> TestResult {
        qc_three_lines(p.map(|v| (11, v)), 126, false)
    }
    qc(1000).quickcheck(orient as fn(_, _, _) -> TestResult);
    // Selector 11 leaves the value uniform below 2^126 - 1, as wide as the
    // shaping allows; differences still fit i128 only for MAX_COORD_BITS.
    qc(300).quickcheck(lines as fn([i128; 12]) -> TestResult);
    qc(1000).quickcheck(side_rat as fn(_, _, _) -> TestResult);
}

/// `side_of_line_rat` on a line through any two `i128` points and a
/// non-integer point, against the rational cross product.
fn side_rat(a: (i128, i128), b: (i128, i128), p: (i128, i128, u8)) -> TestResult {
    let Some(l) = Line::new(pt(a.0, a.1), pt(b.0, b.1)) else {
        return TestResult::discard();
    };
    let w = i128::from(p.2 % 7) + 2;
    let p = rat(p.0, p.1, w);
    let got = side_of_line_rat(&l, &p);
    assert_eq!(got, side_from(cross_sign(&l, &coords(&p))), "{l:?} {p}");
    TestResult::passed()
}

/// Regression: `side_of_line_rat` subtracted endpoint coordinates in `i128`,
/// which overflows for a line from `(i128::MIN, 0)` to `(i128::MAX, 0)`.
#[test]
fn side_of_line_rat_extreme_line() {
    let l = ln(pt(i128::MIN, i128::MIN), pt(i128::MAX, i128::MAX));
    assert_eq!(side_of_line_rat(&l, &rat(1, 2, 3)), Side::Left);
    assert_eq!(side_of_line_rat(&l, &rat(2, 1, 3)), Side::Right);
    assert_eq!(side_of_line_rat(&l, &rat(1, 1, 3)), Side::On);
    assert_eq!(
        side_from(cross_sign(&l, &coords(&rat(1, 2, 3)))),
        Side::Left
    );
}

/// The fast path and GMP meet exactly at the bound: one unit more routes to
/// GMP, and both agree on inputs that straddle the threshold.
#[test]
fn threshold_straddling_cases() {
    let m = (1i128 << O) - 1;
    for (a, b, c) in [
        (pt(-m, -m), pt(m, m), pt(m, m - 1)),
        (pt(-m, -m), pt(m + 1, m + 1), pt(m, m)),
        (pt(-m, m), pt(m, -m), pt(-m, -m)),
        (pt(m, m), pt(-m, -m), pt(0, 0)),
        (pt(-m - 1, 0), pt(0, m + 1), pt(m + 1, 0)),
    ] {
        check_orientation(a, b, c);
    }
    let l = ln(pt(-m, -m), pt(m, m));
    check_compare_along(&l, pt(m, m), pt(-m, -m));
    check_compare_along(&l, pt(m + 1, -m - 1), pt(-m - 1, m + 1));
    let n = (1i128 << I) - 1;
    let (l1, l2, l3) = (
        ln(pt(-n, -n), pt(n, n)),
        ln(pt(-n, n), pt(n, -n)),
        ln(pt(-n, 0), pt(n, 1)),
    );
    check_side_of_intersection(&l3, &l1, &l2);
    check_compare_intersections_along(&l3, &l1, &l2);
    let l4 = ln(pt(-n - 1, 0), pt(n + 1, 1));
    check_side_of_intersection(&l4, &l1, &l2);
    check_compare_intersections_along(&l4, &l1, &l2);
}

// ---------------------------------------------------------------------------
// Constructions with a checked `i128` path: equal to the GMP formulas in
// every regime, including values where the checked path overflows.

fn any_i128() -> impl Strategy<Value = i128> + Clone {
    prop_oneof![
        small(8),
        at_bound(I),
        beyond(I),
        Just(i128::MIN),
        Just(i128::MAX),
        any::<i128>(),
    ]
}

/// The `i128` triple, when given, is the reference point's own homogeneous
/// coordinates; parallel lines are parallel for both.
fn check_construct_intersection_i128(l1: &Line, l2: &Line) {
    let reference = reference::construct_intersection(l1, l2);
    match construct_intersection_i128(l1, l2) {
        Some(Some([x, y, w])) => {
            let p = reference.expect("the lines meet");
            assert_eq!(
                (p.hx(), p.hy(), p.hw()),
                (&Integer::from(x), &Integer::from(y), &Integer::from(w)),
                "{l1:?} {l2:?}"
            );
        }
        Some(None) => assert!(reference.is_none(), "{l1:?} {l2:?}"),
        None => {}
    }
}

proptest! {
    #![proptest_config(config(3000))]

    #[test]
    fn construct_intersection_equals_reference(l1 in line(any_i128()), l2 in line(any_i128())) {
        prop_assert_eq!(construct_intersection(&l1, &l2), reference::construct_intersection(&l1, &l2));
    }

    #[test]
    fn construct_intersection_equals_reference_small(l1 in line(small(6)), l2 in line(small(6))) {
        prop_assert_eq!(construct_intersection(&l1, &l2), reference::construct_intersection(&l1, &l2));
    }

    #[test]
    fn construct_intersection_i128_equals_reference(l1 in line(any_i128()), l2 in line(any_i128())) {
        check_construct_intersection_i128(&l1, &l2);
    }

    #[test]
    fn construct_intersection_i128_equals_reference_small(l1 in line(small(6)), l2 in line(small(6))) {
        check_construct_intersection_i128(&l1, &l2);
    }

    /// The 64-bit path of lowest terms: values in `i64` with a common
    /// factor (so the gcd is rarely 1), and the extremes of `i64`.
    #[test]
    fn rat_point_from_i64_range_equals_new(
        t in prop::array::uniform3(prop_oneof![
            small(20),
            any::<i64>().prop_map(i128::from),
            Just(i128::from(i64::MIN)),
            Just(i128::from(i64::MAX)),
        ]),
        g in prop_oneof![Just(1i128), 2i128..1000, (0u32..40).prop_map(|s| 1i128 << s)],
    ) {
        let fit = |v: i128| {
            let m = v.checked_mul(g).unwrap_or(v);
            if i64::try_from(m).is_ok() { m } else { v }
        };
        let [x, y, w] = t.map(fit);
        let gmp = wai_exact::RatPoint::new(Integer::from(x), Integer::from(y), Integer::from(w));
        prop_assert_eq!(wai_exact::RatPoint::from_i128(x, y, w), gmp);
    }

    #[test]
    fn rat_point_from_i128_equals_new(x in any_i128(), y in any_i128(), w in any_i128()) {
        let gmp = wai_exact::RatPoint::new(Integer::from(x), Integer::from(y), Integer::from(w));
        prop_assert_eq!(wai_exact::RatPoint::from_i128(x, y, w), gmp);
    }

    #[test]
    fn midpoint_equals_rational_average(
        p in (any_i128(), any_i128(), any_i128()),
        q in (any_i128(), any_i128(), any_i128()),
    ) {
        let make = |(x, y, w): (i128, i128, i128)| wai_exact::RatPoint::from_i128(x, y, w);
        let (Some(p), Some(q)) = (make(p), make(q)) else { return Ok(()) };
        let m = wai_exact::RatPoint::midpoint(&p, &q);
        let ((mx, my), (px, py), (qx, qy)) = (coords(&m), coords(&p), coords(&q));
        prop_assert_eq!(mx * 2u32, px + qx);
        prop_assert_eq!(my * 2u32, py + qy);
    }
}

proptest! {
    #![proptest_config(config(5000))]

    /// The unchecked branch (both factors in `i64`) never differs from
    /// `checked_mul`, at the `i64` bounds included.
    #[test]
    fn mul_checked_equals_checked_mul(
        a in prop_oneof![any_i128(), Just(i128::from(i64::MIN)), Just(i128::from(i64::MAX)), any::<i64>().prop_map(i128::from)],
        b in prop_oneof![any_i128(), Just(i128::from(i64::MIN)), Just(i128::from(i64::MAX)), any::<i64>().prop_map(i128::from)],
    ) {
        prop_assert_eq!(wai_exact::mul_checked(a, b), a.checked_mul(b));
    }
}

proptest! {
    #![proptest_config(config(3000))]

    /// Both paths of the binary gcd (64 and 128 bits) equal GMP's gcd.
    #[test]
    fn gcd_u128_equals_gmp(
        x in prop_oneof![any::<u64>().prop_map(u128::from), any::<u128>(), Just(0u128), Just(u128::MAX)],
        y in prop_oneof![any::<u64>().prop_map(u128::from), any::<u128>(), Just(0u128), Just(u128::MAX)],
    ) {
        let gmp = Integer::from(x).gcd(&Integer::from(y));
        prop_assert_eq!(Integer::from(wai_exact::gcd_u128(x, y)), gmp);
    }
}
