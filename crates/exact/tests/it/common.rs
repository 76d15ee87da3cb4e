//! Short constructors, seeded test configurations and GMP helpers written
//! here, independently of the crate, for the other test modules.

use proptest::test_runner::{Config, RngSeed};
use quickcheck::{Gen, QuickCheck};
use rug::{Integer, Rational};
use wai_exact::{Line, Point, RatPoint};

/// One seed for every randomised test, so that runs are reproducible.
pub const SEED: u64 = 0x5741_4921;

/// A proptest configuration with a fixed seed and `cases` cases.
pub fn config(cases: u32) -> Config {
    Config {
        cases,
        rng_seed: RngSeed::Fixed(SEED),
        ..Config::default()
    }
}

/// A quickcheck runner with a fixed seed that must pass `tests` cases.
pub fn qc(tests: u64) -> QuickCheck {
    QuickCheck::new()
        .rng(Gen::from_size_and_seed(100, SEED))
        .tests(tests)
        .max_tests(tests * 20)
        .min_tests_passed(tests)
}

pub fn pt(x: i128, y: i128) -> Point {
    Point::new(x, y)
}

/// The line from `a` to `b`; panics if they coincide.
pub fn ln(a: Point, b: Point) -> Line {
    Line::new(a, b).expect("distinct points")
}

/// The rational point `(x / w, y / w)`.
pub fn rat(x: i128, y: i128, w: i128) -> RatPoint {
    RatPoint::new(Integer::from(x), Integer::from(y), Integer::from(w)).expect("w != 0")
}

pub fn ring(vs: &[(i128, i128)]) -> Vec<Point> {
    vs.iter().map(|&(x, y)| pt(x, y)).collect()
}

/// The affine coordinates of a rational point.
pub fn coords(p: &RatPoint) -> (Rational, Rational) {
    (
        Rational::from((p.hx().clone(), p.hw().clone())),
        Rational::from((p.hy().clone(), p.hw().clone())),
    )
}

fn q(v: i128) -> Rational {
    Rational::from(v)
}

/// The meeting point of two lines by Cramer's rule on `A x + B y = C`, in
/// `rug::Rational`; `None` if parallel. Independent of
/// `wai_exact::construct_intersection`.
pub fn meet(l1: &Line, l2: &Line) -> Option<(Rational, Rational)> {
    let eq = |l: &Line| {
        let (a, b) = (l.a(), l.b());
        let ca = q(b.y) - q(a.y);
        let cb = q(a.x) - q(b.x);
        let cc = &ca * q(a.x) + &cb * q(a.y);
        (ca, cb, cc)
    };
    let ((a1, b1, c1), (a2, b2, c2)) = (eq(l1), eq(l2));
    let det = Rational::from(&a1 * &b2) - Rational::from(&a2 * &b1);
    if det == 0 {
        return None;
    }
    let x = (Rational::from(&c1 * &b2) - Rational::from(&c2 * &b1)) / &det;
    let y = (Rational::from(&a1 * &c2) - Rational::from(&a2 * &c1)) / &det;
    Some((x, y))
}

/// The sign of `(b - a) × (p - a)` for the line `ab`, in `rug::Rational`:
/// `Greater` is left.
pub fn cross_sign(l: &Line, p: &(Rational, Rational)) -> std::cmp::Ordering {
    let (a, b) = (l.a(), l.b());
    let (dx, dy) = (q(b.x) - q(a.x), q(b.y) - q(a.y));
    let (px, py) = (&p.0 - q(a.x), &p.1 - q(a.y));
    (dx * py - dy * px).cmp0()
}

/// The sign of `(v - u) · d` for the direction `d` of `l`: `Greater` when `v`
/// comes after `u` along `l`.
pub fn dot_sign(
    l: &Line,
    u: &(Rational, Rational),
    v: &(Rational, Rational),
) -> std::cmp::Ordering {
    let (a, b) = (l.a(), l.b());
    let (dx, dy) = (q(b.x) - q(a.x), q(b.y) - q(a.y));
    let ex = Rational::from(&v.0 - &u.0);
    let ey = Rational::from(&v.1 - &u.1);
    (ex * dx + ey * dy).cmp0()
}
