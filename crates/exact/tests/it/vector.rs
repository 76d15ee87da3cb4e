//! The vector vocabulary (`Vector`, `BigVector`, `QPoint`, `turn`,
//! `convex_hull`) against plain GMP computations written here, at and
//! beyond each fast path's bound, and its laws.

use crate::common::{config, rat};
use proptest::prelude::*;
use rug::{Integer, Rational};
use std::cmp::Ordering;
use wai_exact::{
    convex_hull, det3_sign_i128, orientation, orientation_rat, turn, BigVector, Orientation, Point,
    QPoint, RatPoint, Vector, HOMOGENEOUS_FAST_BITS, VECTOR_FAST_BITS,
};

// ---------------------------------------------------------------------------
// Plain GMP answers, written without the crate's arithmetic.

fn big_cross(u: (i128, i128), v: (i128, i128)) -> Integer {
    Integer::from(u.0) * v.1 - Integer::from(u.1) * v.0
}

fn big_dot(u: (i128, i128), v: (i128, i128)) -> Integer {
    Integer::from(u.0) * v.0 + Integer::from(u.1) * v.1
}

/// `(b − a) × (c − a)` in `rug::Rational`: the computation `turn` replaces.
fn rational_turn(a: &QPoint, b: &QPoint, c: &QPoint) -> Ordering {
    let (ux, uy) = (Rational::from(&b.x - &a.x), Rational::from(&b.y - &a.y));
    let (vx, vy) = (Rational::from(&c.x - &a.x), Rational::from(&c.y - &a.y));
    (ux * vy - uy * vx).cmp0()
}

/// The angular order from the positive x axis by the angle's quadrant and
/// a rational slope comparison, independent of `compare_angle`.
fn angle_key(x: &Rational, y: &Rational) -> (u8, Rational) {
    // Quadrants 0..4 counter-clockwise from angle 0, each half-open; within
    // one, the angle grows with t = y/x (or −x/y).
    let zero = Rational::new();
    match (x.cmp(&zero), y.cmp(&zero)) {
        (Ordering::Greater, Ordering::Equal | Ordering::Greater) => (0, Rational::from(y / x)),
        (Ordering::Less | Ordering::Equal, Ordering::Greater) => (1, Rational::from(-x) / y),
        (Ordering::Less, Ordering::Less | Ordering::Equal) => (2, Rational::from(y / x)),
        (Ordering::Greater | Ordering::Equal, Ordering::Less) => (3, Rational::from(-x) / y),
        (Ordering::Equal, Ordering::Equal) => panic!("zero direction"),
    }
}

// ---------------------------------------------------------------------------
// Strategies.

/// `i128` values of every size: small, at `VECTOR_FAST_BITS`, the extremes.
fn any_component() -> impl Strategy<Value = i128> + Clone {
    let m = (1i128 << VECTOR_FAST_BITS) - 1;
    prop_oneof![
        3 => -1000i128..=1000,
        2 => Just(m),
        2 => Just(-m),
        1 => Just(m + 1),
        1 => Just(-m - 1),
        1 => Just(i128::MAX),
        1 => Just(i128::MIN),
        1 => Just(i128::MIN + 1),
        3 => -m..=m,
        3 => any::<i128>(),
    ]
}

fn vector() -> impl Strategy<Value = Vector> + Clone {
    (any_component(), any_component()).prop_map(|(x, y)| Vector::new(x, y))
}

/// Rationals whose numerators and denominators are below `2^bits`, with
/// a bias towards shared denominators and the extremes.
fn rational(bits: u32) -> impl Strategy<Value = Rational> + Clone {
    let m = (1i128 << bits) - 1;
    let num = prop_oneof![2 => Just(m), 2 => Just(-m), 1 => Just(0i128), 5 => -m..=m];
    let den = prop_oneof![3 => Just(1i128), 2 => Just(m), 1 => Just(2i128), 4 => 1..=m];
    (num, den).prop_map(|(n, d)| Rational::from((n, d)))
}

fn qpoint(bits: u32) -> impl Strategy<Value = QPoint> + Clone {
    (rational(bits), rational(bits)).prop_map(|(x, y)| QPoint::new(x, y))
}

/// Points with one denominator for both coordinates (as `RatPoint`s give),
/// at `bits`.
fn qpoint_shared(bits: u32) -> impl Strategy<Value = QPoint> + Clone {
    let m = (1i128 << bits) - 1;
    (-m..=m, -m..=m, 1..=m).prop_map(|(x, y, w)| QPoint::from(&rat(x, y, w)))
}

/// Collinear triples `a, a + s·d, a + t·d` with rational `s`, `t`.
fn collinear(bits: u32) -> impl Strategy<Value = [QPoint; 3]> {
    (qpoint(bits), qpoint(bits), rational(8), rational(8))
        .prop_map(|(a, d, s, t)| [a.clone(), a.along(&d, &s), a.along(&d, &t)])
}

/// Rational points whose homogeneous numerators straddle the `i64` range
/// of `RatPoint::cross_sign`'s fast path.
fn ratpoint() -> impl Strategy<Value = RatPoint> {
    let num = prop_oneof![
        2 => -1000i128..=1000,
        1 => Just(i128::from(i64::MIN)),
        1 => Just(i128::from(i64::MAX)),
        1 => Just(i128::from(i64::MAX) + 1),
        2 => any::<i64>().prop_map(i128::from),
        2 => -(1i128 << 100)..=1i128 << 100,
    ];
    (num.clone(), num, 1i128..=1 << 40).prop_map(|(x, y, w)| rat(x, y, w))
}

const H: u32 = HOMOGENEOUS_FAST_BITS;

/// The determinant of three rows in GMP integers.
fn big_det3(a: [i128; 3], b: [i128; 3], c: [i128; 3]) -> Integer {
    let z = |v: i128| Integer::from(v);
    let minor = |i: usize, j: usize| z(b[i]) * c[j] - z(b[j]) * c[i];
    z(a[0]) * minor(1, 2) - z(a[1]) * minor(0, 2) + z(a[2]) * minor(0, 1)
}

/// An entry of a homogeneous row: small, at the unchecked path's bound
/// (`2^H − 1`, `2^H`) or far beyond it, either sign.
fn entry() -> impl Strategy<Value = i128> {
    let edge = (1i128 << H) - 1;
    prop_oneof![
        3 => -50i128..=50,
        2 => Just(edge),
        2 => Just(-edge),
        1 => Just(edge + 1),
        2 => -(1i128 << H)..=1i128 << H,
        1 => -(1i128 << 62)..=1i128 << 62,
    ]
}

fn check_turn(a: &QPoint, b: &QPoint, c: &QPoint) {
    let t = turn(a, b, c);
    assert_eq!(t, rational_turn(a, b, c), "{a} {b} {c}");
    // orientation_rat on the same points, through the homogeneous form.
    let (ra, rb, rc) = (a.to_rat_point(), b.to_rat_point(), c.to_rat_point());
    assert_eq!(orientation_rat(&ra, &rb, &rc).sign(), t, "{a} {b} {c}");
    // The cross sign of the two differences.
    assert_eq!(b.sub(a).cross_sign(&c.sub(a)), t, "{a} {b} {c}");
}

proptest! {
    #![proptest_config(config(3000))]

    #[test]
    fn vector_signs_equal_gmp(u in vector(), v in vector()) {
        let (p, q) = ((u.x, u.y), (v.x, v.y));
        prop_assert_eq!(u.cross_sign(v), big_cross(p, q).cmp0());
        prop_assert_eq!(u.dot_sign(v), big_dot(p, q).cmp0());
        let (bu, bv) = (u.to_big(), v.to_big());
        prop_assert_eq!(bu.cross(&bv), big_cross(p, q));
        prop_assert_eq!(bu.dot(&bv), big_dot(p, q));
        prop_assert_eq!(bu.cross_sign(&bv), big_cross(p, q).cmp0());
        prop_assert_eq!(bu.dot_sign(&bv), big_dot(p, q).cmp0());
        let narrow = |w: Vector| w.x.unsigned_abs() < 1 << VECTOR_FAST_BITS
            && w.y.unsigned_abs() < 1 << VECTOR_FAST_BITS;
        if narrow(u) && narrow(v) {
            prop_assert_eq!(Integer::from(u.cross(v)), big_cross(p, q));
            prop_assert_eq!(Integer::from(u.dot(v)), big_dot(p, q));
        }
    }

    #[test]
    fn det3_signs_equal_gmp(
        a in prop::array::uniform3(entry()),
        b in prop::array::uniform3(entry()),
        c in prop::array::uniform3(entry()),
    ) {
        // Unchecked below the bound, checked above: either the GMP sign or
        // `None` (an overflow), never a wrong sign.
        match det3_sign_i128(a, b, c) {
            Some(s) => prop_assert_eq!(s, big_det3(a, b, c).cmp0()),
            None => prop_assert!(a.iter().chain(&b).chain(&c).any(|v| v.unsigned_abs() >= 1 << H)),
        }
    }

    #[test]
    fn angle_orders_agree_with_slopes(u in vector(), v in vector()) {
        prop_assume!(!u.is_zero() && !v.is_zero());
        let key = |w: Vector| angle_key(&Rational::from(w.x), &Rational::from(w.y));
        let expect = key(u).cmp(&key(v));
        prop_assert_eq!(u.compare_angle(v), expect);
        prop_assert_eq!(u.to_big().compare_angle(&v.to_big()), expect);
        prop_assert_eq!(QPoint::from(u).compare_angle(&QPoint::from(v)), expect);
    }

    // turn: small rationals, at the homogeneous bound, at the integer
    // (orientation) bound, beyond both, and on collinear triples.
    #[test]
    fn turn_small(a in qpoint(6), b in qpoint(6), c in qpoint(6)) {
        check_turn(&a, &b, &c);
    }
    #[test]
    fn turn_at_homogeneous_bound(a in qpoint_shared(H), b in qpoint_shared(H), c in qpoint_shared(H)) {
        check_turn(&a, &b, &c);
    }
    #[test]
    fn turn_at_split_bound(a in qpoint(H / 2), b in qpoint(H / 2), c in qpoint(H / 2)) {
        check_turn(&a, &b, &c);
    }
    #[test]
    fn turn_beyond(a in qpoint(H + 1), b in qpoint(70), c in qpoint(H)) {
        check_turn(&a, &b, &c);
    }
    #[test]
    fn turn_integers(a in qpoint_shared(62), b in qpoint_shared(62), c in qpoint_shared(62)) {
        let int = |p: &QPoint| QPoint::new(p.x.numer().clone().into(), p.y.numer().clone().into());
        check_turn(&int(&a), &int(&b), &int(&c));
    }
    #[test]
    fn turn_collinear(t in collinear(20)) {
        prop_assert_eq!(turn(&t[0], &t[1], &t[2]), Ordering::Equal);
        check_turn(&t[0], &t[1], &t[2]);
    }
    #[test]
    fn turn_collinear_at_bound(t in collinear(H)) {
        prop_assert_eq!(turn(&t[0], &t[1], &t[2]), Ordering::Equal);
    }

    #[test]
    fn turn_laws(a in qpoint(12), b in qpoint(12), c in qpoint(12), d in qpoint(12)) {
        let t = turn(&a, &b, &c);
        prop_assert_eq!(turn(&b, &a, &c), t.reverse(), "swap");
        prop_assert_eq!(turn(&b, &c, &a), t, "cyclic");
        let tr = |p: &QPoint| p.add(&d);
        prop_assert_eq!(turn(&tr(&a), &tr(&b), &tr(&c)), t, "translation");
        let r = |p: &QPoint| p.perp();
        prop_assert_eq!(turn(&r(&a), &r(&b), &r(&c)), t, "rotation");
        let m = |p: &QPoint| QPoint::new(p.x.clone(), Rational::from(-&p.y));
        prop_assert_eq!(turn(&m(&a), &m(&b), &m(&c)), t.reverse(), "reflection");
        prop_assert_eq!(turn(&a, &a, &c), Ordering::Equal);
    }

    #[test]
    fn orientation_rat_at_bound(a in qpoint_shared(H), b in qpoint_shared(H), c in qpoint_shared(H)) {
        let (ra, rb, rc) = (a.to_rat_point(), b.to_rat_point(), c.to_rat_point());
        let plain = rational_turn(&a, &b, &c);
        prop_assert_eq!(orientation_rat(&ra, &rb, &rc), Orientation::from_sign(plain));
    }

    // RatPoint as a position vector, against its affine coordinates, with
    // numerators around the i64 edge of the fast path.
    #[test]
    fn ratpoint_vector_ops_equal_rationals(a in ratpoint(), b in ratpoint()) {
        let (qa, qb) = (QPoint::from(&a), QPoint::from(&b));
        prop_assert_eq!(a.cross_sign(&b), qa.cross(&qb).cmp0());
        prop_assert_eq!(a.dot_sign(&b), qa.dot(&qb).cmp0());
        prop_assert_eq!(QPoint::from(&a.sub(&b)), qa.sub(&qb));
        prop_assert_eq!(QPoint::from(&a.neg()), qa.neg());
        if !qa.is_zero() && !qb.is_zero() {
            prop_assert_eq!(a.compare_angle(&b), qa.compare_angle(&qb));
        }
    }

    #[test]
    fn qpoint_conversions_round_trip(x in -1000i128..=1000, y in -1000i128..=1000, w in 1i128..=50) {
        let r = rat(x, y, w);
        let q = QPoint::from(&r);
        prop_assert_eq!(q.to_rat_point(), r.clone());
        prop_assert_eq!(RatPoint::from(&q), r.clone());
        prop_assert_eq!(q.to_point(), r.to_point());
        prop_assert_eq!(q.to_string(), r.to_string());
    }

}

proptest! {
    #![proptest_config(config(500))]

    #[test]
    fn hull_is_convex_and_holds_every_point(pts in prop::collection::vec(qpoint(3), 0..16)) {
        let h = convex_hull(pts.clone());
        prop_assert_eq!(&h, &reference_hull(&pts));
        if h.len() >= 3 {
            for i in 0..h.len() {
                let (a, b) = (&h[i], &h[(i + 1) % h.len()]);
                prop_assert_eq!(turn(a, b, &h[(i + 2) % h.len()]), Ordering::Greater);
                for p in &pts {
                    prop_assert_ne!(turn(a, b, p), Ordering::Less);
                }
            }
        }
    }
}

/// The hull by brute force: the ends of the hull's edges — pairs `(a, b)`
/// with every point left of the line `ab` or on the closed segment — in
/// counter-clockwise order from the least point (by angle around it).
fn reference_hull(pts: &[QPoint]) -> Vec<QPoint> {
    let mut ps = pts.to_vec();
    ps.sort();
    ps.dedup();
    if ps.len() < 3 {
        return ps;
    }
    let on_segment = |p: &QPoint, a: &QPoint, b: &QPoint| p.sub(a).dot(&p.sub(b)) <= 0;
    let edge = |a: &QPoint, b: &QPoint| {
        ps.iter().all(|p| match rational_turn(a, b, p) {
            Ordering::Greater => true,
            Ordering::Equal => on_segment(p, a, b),
            Ordering::Less => false,
        })
    };
    let mut extreme: Vec<QPoint> = ps
        .iter()
        .filter(|a| ps.iter().any(|b| b != *a && edge(a, b)))
        .cloned()
        .collect();
    if extreme.len() < 3 {
        return extreme;
    }
    // Counter-clockwise around the least point (first after sorting).
    let o = extreme[0].clone();
    let mut rest = extreme.split_off(1);
    rest.sort_by(|p, q| rational_turn(&o, q, p));
    let mut h = vec![o];
    h.extend(rest);
    h
}

#[test]
fn hull_cases() {
    fn check(input: &[(i64, i64)], expect: &[(i64, i64)]) {
        let q = |v: &[(i64, i64)]| -> Vec<QPoint> {
            v.iter()
                .map(|&(x, y)| QPoint::new(x.into(), y.into()))
                .collect()
        };
        assert_eq!(convex_hull(q(input)), q(expect), "{input:?}");
    }
    check(&[], &[]);
    check(&[(1, 1)], &[(1, 1)]);
    check(&[(1, 1), (1, 1), (1, 1)], &[(1, 1)]);
    check(&[(2, 0), (0, 0)], &[(0, 0), (2, 0)]);
    check(&[(0, 0), (1, 1), (2, 2), (3, 3)], &[(0, 0), (3, 3)]);
    check(
        &[(0, 0), (4, 0), (4, 4), (0, 4), (2, 2), (2, 0), (4, 2)],
        &[(0, 0), (4, 0), (4, 4), (0, 4)],
    );
    // Clockwise input comes out counter-clockwise.
    check(&[(0, 0), (0, 3), (3, 0)], &[(0, 0), (3, 0), (0, 3)]);
}

#[test]
fn point_difference_is_a_vector() {
    let (a, b) = (Point::new(3, -2), Point::new(-1, 5));
    assert_eq!(b - a, Vector::new(-4, 7));
    assert_eq!(Vector::between(a, b), Some(Vector::new(-4, 7)));
    let far = Point::new(i128::MAX, 0);
    assert_eq!(Vector::between(Point::new(-1, 0), far), None);
    assert_eq!(
        BigVector::between(Point::new(-1, 0), far),
        BigVector::new(Integer::from(i128::MAX) + 1, Integer::new())
    );
    // The direction from a rational point to a vertex, scaled by W.
    let p = rat(1, 1, 2);
    assert_eq!(
        BigVector::toward(&p, Point::new(1, 0)),
        BigVector::new(Integer::from(1), Integer::from(-1))
    );
}

/// Past `VECTOR_FAST_BITS` the values refuse instead of wrapping; the signs
/// stay exact.
#[test]
#[should_panic(expected = "beyond 2^63")]
fn cross_refuses_beyond_its_bound() {
    let big = Vector::new(1 << VECTOR_FAST_BITS, 1);
    assert_eq!(big.cross_sign(big), Ordering::Equal);
    let _ = big.cross(big);
}

#[test]
fn orientation_sign_round_trips() {
    for o in [
        Orientation::CounterClockwise,
        Orientation::Collinear,
        Orientation::Clockwise,
    ] {
        assert_eq!(Orientation::from_sign(o.sign()), o);
    }
    let p = |x, y| Point::new(x, y);
    assert_eq!(
        orientation(p(0, 0), p(1, 0), p(0, 1)).sign(),
        Ordering::Greater
    );
}
