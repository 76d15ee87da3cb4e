//! The exact vector vocabulary of the workspace: integer vectors in `i128`
//! ([`Vector`]) and in GMP integers ([`BigVector`]), the affine rational
//! point or vector [`QPoint`], their cross and dot products, the turn of
//! three [`QPoint`]s and their [`convex_hull`].
//!
//! Which to use:
//! - [`Vector`]: the difference of two input [`Point`]s (`b − a`), or any
//!   integer direction that fits an `i128`. Its signs ([`Vector::cross_sign`],
//!   [`Vector::dot_sign`], [`Vector::compare_angle`]) are exact for every
//!   `i128`; its values ([`Vector::cross`], [`Vector::dot`]) need components
//!   below `2^VECTOR_FAST_BITS` and panic rather than overflow beyond.
//! - [`BigVector`]: integer vectors of any size, such as the directions
//!   `W·v − (X, Y)` from a rational point `(X, Y)/W` to a map vertex `v`.
//! - [`QPoint`]: a point or a vector with rational coordinates in affine
//!   form, for constructions that add, scale and divide (clipping pieces,
//!   points along lines). [`RatPoint`] stays the canonical homogeneous form
//!   that is hashed and compared; the two convert both ways.
//!
//! Products are methods (`u.cross(&w)`, `u.dot(&w)`); predicates on three
//! points are functions ([`turn`] for [`QPoint`]s, [`crate::orientation`]
//! for [`Point`]s, [`crate::orientation_rat`] for [`RatPoint`]s).

use crate::intersection::mul_checked;
use crate::point::{Point, RatPoint};
use crate::predicates::ORIENTATION_FAST_BITS;
use rug::{Integer, Rational};
use std::borrow::Cow;
use std::cmp::Ordering;
use std::fmt;

/// Components below `2^VECTOR_FAST_BITS` in magnitude: [`Vector::cross`]
/// and [`Vector::dot`] are exact in `i128`.
///
/// Implementation note: with `|x|, |y| < 2^63` each product of two
/// components is below `2^126` and the sum or difference of two such
/// products below `2^127`, which an `i128` holds. The difference of two
/// points below `2^ORIENTATION_FAST_BITS = 2^62` is below `2^63`, so the
/// orientation fast path is a cross product of two such vectors.
pub const VECTOR_FAST_BITS: u32 = 63;

/// Whether both components are below `2^VECTOR_FAST_BITS` in magnitude.
#[inline]
fn narrow(x: i128, y: i128) -> bool {
    x.unsigned_abs() < 1 << VECTOR_FAST_BITS && y.unsigned_abs() < 1 << VECTOR_FAST_BITS
}

/// `x·y` for two values below `2^63` in magnitude (they are `i64`
/// values): [`crate::mul_wide`].
#[inline]
fn wide(x: i128, y: i128) -> i128 {
    debug_assert!(narrow(x, y));
    crate::mul_wide(x as i64, y as i64)
}

/// Whether a direction lies in the half-turn `[0, π)` measured
/// counter-clockwise from the positive x axis: `y > 0`, or `y = 0 < x`.
#[inline]
fn upper(x: Ordering, y: Ordering) -> bool {
    y == Ordering::Greater || (y == Ordering::Equal && x == Ordering::Greater)
}

/// The counter-clockwise angular order from the positive x axis, given the
/// half-turns of `u` and `v` and the sign of `u × v`.
#[inline]
fn angle_order(u_upper: bool, v_upper: bool, cross_uv: impl FnOnce() -> Ordering) -> Ordering {
    // Within one half-turn, u comes first when v is to its left.
    (!u_upper).cmp(&!v_upper).then_with(|| cross_uv().reverse())
}

// ---------------------------------------------------------------------------
// Vector: i128 components.

/// An integer vector with `i128` components: the difference of two input
/// [`Point`]s, or an integer direction.
///
/// The signs are exact for every `i128` (checked arithmetic, then GMP); the
/// values [`Vector::cross`] and [`Vector::dot`] are exact below
/// [`VECTOR_FAST_BITS`] and refuse (panic) beyond it, never wrap.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Vector {
    pub x: i128,
    pub y: i128,
}

impl Vector {
    /// The vector `(x, y)`.
    pub const fn new(x: i128, y: i128) -> Vector {
        Vector { x, y }
    }

    /// `to − from`, or `None` if a component overflows an `i128` (never for
    /// points below `2^MAX_COORD_BITS`).
    #[inline]
    pub fn between(from: Point, to: Point) -> Option<Vector> {
        Some(Vector::new(
            to.x.checked_sub(from.x)?,
            to.y.checked_sub(from.y)?,
        ))
    }

    /// `to − from` in plain `i128` arithmetic, for the fast paths whose
    /// stated bound keeps every difference inside an `i128` (no check in
    /// release builds: the bound is the proof).
    #[inline]
    pub(crate) fn between_fast(from: Point, to: Point) -> Vector {
        Vector::new(to.x - from.x, to.y - from.y)
    }

    /// Whether both components are zero.
    pub fn is_zero(self) -> bool {
        self.x == 0 && self.y == 0
    }

    /// The same vector in GMP integers.
    pub fn to_big(self) -> BigVector {
        BigVector::new(Integer::from(self.x), Integer::from(self.y))
    }

    /// `self × o`, exactly.
    ///
    /// # Panics
    /// If a component is `2^VECTOR_FAST_BITS` or more in magnitude, where
    /// the value may not fit an `i128`: use [`Vector::cross_sign`] or
    /// [`BigVector::cross`] there.
    #[inline]
    pub fn cross(self, o: Vector) -> i128 {
        assert!(
            narrow(self.x, self.y) && narrow(o.x, o.y),
            "{self} × {o} beyond 2^63"
        );
        self.cross_fast(o)
    }

    /// `self · o`, exactly.
    ///
    /// # Panics
    /// As [`Vector::cross`]; use [`Vector::dot_sign`] or [`BigVector::dot`]
    /// beyond the bound.
    #[inline]
    pub fn dot(self, o: Vector) -> i128 {
        assert!(
            narrow(self.x, self.y) && narrow(o.x, o.y),
            "{self} · {o} beyond 2^63"
        );
        self.dot_fast(o)
    }

    /// [`Vector::cross`] without the check, for the fast paths whose stated
    /// bound keeps the components below `2^VECTOR_FAST_BITS`.
    #[inline]
    pub(crate) fn cross_fast(self, o: Vector) -> i128 {
        debug_assert!(narrow(self.x, self.y) && narrow(o.x, o.y));
        // Below the bound nothing wraps (products < 2^126, difference
        // < 2^127); the wrapping operations only spare the overflow checks
        // of fuzzing builds, which the bound makes redundant. Components
        // below 2^63 are i64 values, so each product is one 64 × 64 →
        // 128-bit multiplication.
        wide(self.x, o.y).wrapping_sub(wide(self.y, o.x))
    }

    /// [`Vector::dot`] without the check, as [`Vector::cross_fast`].
    #[inline]
    pub(crate) fn dot_fast(self, o: Vector) -> i128 {
        debug_assert!(narrow(self.x, self.y) && narrow(o.x, o.y));
        // As in `cross_fast`: exact below the bound.
        wide(self.x, o.x).wrapping_add(wide(self.y, o.y))
    }

    /// The sign of `self × o` (`Greater`: `o` is counter-clockwise from
    /// `self`), exact for every `i128`.
    #[inline]
    pub fn cross_sign(self, o: Vector) -> Ordering {
        if narrow(self.x, self.y) && narrow(o.x, o.y) {
            return self.cross_fast(o).cmp(&0);
        }
        match (mul_checked(self.x, o.y), mul_checked(self.y, o.x)) {
            // p − q > 0 iff p > q: no subtraction needed.
            (Some(p), Some(q)) => p.cmp(&q),
            _ => self.to_big().cross_sign(&o.to_big()),
        }
    }

    /// The sign of `self · o`, exact for every `i128`.
    #[inline]
    pub fn dot_sign(self, o: Vector) -> Ordering {
        if narrow(self.x, self.y) && narrow(o.x, o.y) {
            return self.dot_fast(o).cmp(&0);
        }
        let fast = mul_checked(self.x, o.x).and_then(|p| p.checked_add(mul_checked(self.y, o.y)?));
        match fast {
            Some(d) => d.cmp(&0),
            None => self.to_big().dot_sign(&o.to_big()),
        }
    }

    /// Whether the direction lies in `[0, π)` counter-clockwise from the
    /// positive x axis (`y > 0`, or `y = 0 < x`).
    #[inline]
    pub fn upper_half(self) -> bool {
        upper(self.x.cmp(&0), self.y.cmp(&0))
    }

    /// The counter-clockwise angular order of nonzero directions, starting
    /// at the positive x axis (angle 0) and going round once; directions
    /// along one ray compare `Equal`.
    ///
    /// ```
    /// use wai_exact::Vector;
    /// use std::cmp::Ordering;
    /// let (east, north, south) = (Vector::new(1, 0), Vector::new(0, 1), Vector::new(0, -1));
    /// assert_eq!(east.compare_angle(north), Ordering::Less);
    /// assert_eq!(south.compare_angle(north), Ordering::Greater);
    /// assert_eq!(Vector::new(2, 2).compare_angle(Vector::new(5, 5)), Ordering::Equal);
    /// ```
    #[inline]
    pub fn compare_angle(self, o: Vector) -> Ordering {
        angle_order(self.upper_half(), o.upper_half(), || self.cross_sign(o))
    }
}

impl fmt::Display for Vector {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "({}, {})", self.x, self.y)
    }
}

impl std::ops::Add for Vector {
    type Output = Vector;

    /// `self + o`.
    ///
    /// # Panics
    /// If a component overflows an `i128` (never for vectors below
    /// `2^126`, such as differences of points below `2^MAX_COORD_BITS`).
    #[inline]
    fn add(self, o: Vector) -> Vector {
        let sum = || {
            Some(Vector::new(
                self.x.checked_add(o.x)?,
                self.y.checked_add(o.y)?,
            ))
        };
        sum().expect("a sum of vectors below 2^126")
    }
}

impl std::ops::Sub for Vector {
    type Output = Vector;

    /// `self − o`.
    ///
    /// # Panics
    /// If a component overflows an `i128`, as for `+`.
    #[inline]
    fn sub(self, o: Vector) -> Vector {
        let diff = || {
            Some(Vector::new(
                self.x.checked_sub(o.x)?,
                self.y.checked_sub(o.y)?,
            ))
        };
        diff().expect("a difference of vectors below 2^126")
    }
}

impl std::ops::Neg for Vector {
    type Output = Vector;

    /// `−self`.
    ///
    /// # Panics
    /// If a component is `i128::MIN`, whose negation an `i128` lacks.
    #[inline]
    fn neg(self) -> Vector {
        let neg = || Some(Vector::new(self.x.checked_neg()?, self.y.checked_neg()?));
        neg().expect("a vector above i128::MIN")
    }
}

impl std::ops::Sub for Point {
    type Output = Vector;

    /// `self − o` as a [`Vector`].
    ///
    /// # Panics
    /// If a component overflows an `i128`, which no two points below
    /// `2^MAX_COORD_BITS` (every map vertex) reach; use
    /// [`Vector::between`] for arbitrary `i128` points.
    #[inline]
    fn sub(self, o: Point) -> Vector {
        Vector::between(o, self).expect("a difference of points below 2^126")
    }
}

// ---------------------------------------------------------------------------
// BigVector: GMP integer components.

/// An integer vector with GMP components, for directions of any size.
#[derive(Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct BigVector {
    pub x: Integer,
    pub y: Integer,
}

impl BigVector {
    /// The vector `(x, y)`.
    pub fn new(x: Integer, y: Integer) -> BigVector {
        BigVector { x, y }
    }

    /// `to − from`, exactly.
    pub fn between(from: Point, to: Point) -> BigVector {
        BigVector::new(Integer::from(to.x) - from.x, Integer::from(to.y) - from.y)
    }

    /// The direction `W·v − (X, Y)` from the rational point `p = (X, Y)/W`
    /// to `v`, scaled by `p`'s denominator `W > 0` (same direction).
    pub fn toward(p: &RatPoint, v: Point) -> BigVector {
        BigVector::new(
            Integer::from(p.hw() * v.x) - p.hx(),
            Integer::from(p.hw() * v.y) - p.hy(),
        )
    }

    /// The vector in `i128`, if both components fit.
    pub fn to_small(&self) -> Option<Vector> {
        Some(Vector::new(self.x.to_i128()?, self.y.to_i128()?))
    }

    /// Whether both components are zero.
    pub fn is_zero(&self) -> bool {
        self.x.is_zero() && self.y.is_zero()
    }

    /// `self + o`.
    pub fn add(&self, o: &BigVector) -> BigVector {
        BigVector::new(Integer::from(&self.x + &o.x), Integer::from(&self.y + &o.y))
    }

    /// `self − o`.
    pub fn sub(&self, o: &BigVector) -> BigVector {
        BigVector::new(Integer::from(&self.x - &o.x), Integer::from(&self.y - &o.y))
    }

    /// `self × o`.
    pub fn cross(&self, o: &BigVector) -> Integer {
        Integer::from(&self.x * &o.y) - Integer::from(&self.y * &o.x)
    }

    /// `self · o`.
    pub fn dot(&self, o: &BigVector) -> Integer {
        Integer::from(&self.x * &o.x) + Integer::from(&self.y * &o.y)
    }

    /// The sign of `self × o` (`Greater`: `o` is counter-clockwise from
    /// `self`).
    pub fn cross_sign(&self, o: &BigVector) -> Ordering {
        Integer::from(&self.x * &o.y).cmp(&Integer::from(&self.y * &o.x))
    }

    /// The sign of `self · o`.
    pub fn dot_sign(&self, o: &BigVector) -> Ordering {
        self.dot(o).cmp0()
    }

    /// Whether the direction lies in `[0, π)` counter-clockwise from the
    /// positive x axis (`y > 0`, or `y = 0 < x`).
    pub fn upper_half(&self) -> bool {
        upper(self.x.cmp0(), self.y.cmp0())
    }

    /// The counter-clockwise angular order of nonzero directions from the
    /// positive x axis, as [`Vector::compare_angle`].
    pub fn compare_angle(&self, o: &BigVector) -> Ordering {
        angle_order(self.upper_half(), o.upper_half(), || self.cross_sign(o))
    }
}

impl From<Vector> for BigVector {
    fn from(v: Vector) -> BigVector {
        v.to_big()
    }
}

impl fmt::Display for BigVector {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "({}, {})", self.x, self.y)
    }
}

// ---------------------------------------------------------------------------
// QPoint: affine rational coordinates.

/// A point, or a vector (the difference of two points), with exact
/// rational coordinates in affine form.
///
/// For constructions: sums, scalings and points along lines stay exact and
/// each coordinate stays in lowest terms (GMP `mpq`). [`RatPoint`] is the
/// canonical homogeneous form for hashing and keys; [`QPoint::to_rat_point`]
/// and `QPoint::from(&RatPoint)` convert. The derived order is
/// lexicographic, by `x` then `y`.
#[derive(Clone, Debug, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct QPoint {
    pub x: Rational,
    pub y: Rational,
}

impl QPoint {
    /// The point `(x, y)`.
    pub fn new(x: Rational, y: Rational) -> QPoint {
        QPoint { x, y }
    }

    /// `self − o`.
    pub fn sub(&self, o: &QPoint) -> QPoint {
        QPoint::new(
            Rational::from(&self.x - &o.x),
            Rational::from(&self.y - &o.y),
        )
    }

    /// `self + o`.
    pub fn add(&self, o: &QPoint) -> QPoint {
        QPoint::new(
            Rational::from(&self.x + &o.x),
            Rational::from(&self.y + &o.y),
        )
    }

    /// `t · self`.
    pub fn scale(&self, t: &Rational) -> QPoint {
        QPoint::new(Rational::from(&self.x * t), Rational::from(&self.y * t))
    }

    /// `self + t·d`: the point at parameter `t` on the line through `self`
    /// with direction `d`.
    pub fn along(&self, d: &QPoint, t: &Rational) -> QPoint {
        self.add(&d.scale(t))
    }

    /// The vector turned a quarter counter-clockwise: `(−y, x)`.
    pub fn perp(&self) -> QPoint {
        QPoint::new(Rational::from(-&self.y), self.x.clone())
    }

    /// `−self`.
    pub fn neg(&self) -> QPoint {
        QPoint::new(Rational::from(-&self.x), Rational::from(-&self.y))
    }

    /// Whether both coordinates are zero.
    pub fn is_zero(&self) -> bool {
        self.x.is_zero() && self.y.is_zero()
    }

    /// `self × o`.
    pub fn cross(&self, o: &QPoint) -> Rational {
        Rational::from(&self.x * &o.y) - Rational::from(&self.y * &o.x)
    }

    /// `self · o`.
    pub fn dot(&self, o: &QPoint) -> Rational {
        Rational::from(&self.x * &o.x) + Rational::from(&self.y * &o.y)
    }

    /// The sign of `self × o` (`Greater`: `o` is counter-clockwise from
    /// `self`): [`turn`] of the origin, `self` and `o`, with its fast paths.
    pub fn cross_sign(&self, o: &QPoint) -> Ordering {
        if let (Some(u), Some(w)) = (homogeneous_small(self), homogeneous_small(o)) {
            // Implementation note: |X|, |Y|, W < 2^HOMOGENEOUS_FAST_BITS = 2^41,
            // so each product is below 2^82 and W_u·W_w > 0 keeps the sign.
            return wide(u[0], w[1]).cmp(&wide(u[1], w[0]));
        }
        Rational::from(&self.x * &o.y).cmp(&Rational::from(&self.y * &o.x))
    }

    /// Whether the direction lies in `[0, π)` counter-clockwise from the
    /// positive x axis (`y > 0`, or `y = 0 < x`).
    pub fn upper_half(&self) -> bool {
        upper(self.x.cmp0(), self.y.cmp0())
    }

    /// The counter-clockwise angular order of nonzero directions from the
    /// positive x axis, as [`Vector::compare_angle`].
    pub fn compare_angle(&self, o: &QPoint) -> Ordering {
        angle_order(self.upper_half(), o.upper_half(), || self.cross_sign(o))
    }

    /// The canonical homogeneous form of the point.
    pub fn to_rat_point(&self) -> RatPoint {
        // x = a/b, y = c/d → (a·d, c·b, b·d).
        let (a, b) = (self.x.numer(), self.x.denom());
        let (c, d) = (self.y.numer(), self.y.denom());
        RatPoint::new(
            Integer::from(a * d),
            Integer::from(c * b),
            Integer::from(b * d),
        )
        .expect("denominators are positive")
    }

    /// The integer point, if both coordinates are integers in `i128`
    /// (without allocating).
    #[inline]
    pub fn to_point(&self) -> Option<Point> {
        if *self.x.denom() != 1 || *self.y.denom() != 1 {
            return None;
        }
        Some(Point::new(
            self.x.numer().to_i128()?,
            self.y.numer().to_i128()?,
        ))
    }
}

impl From<Point> for QPoint {
    fn from(p: Point) -> QPoint {
        QPoint::new(Rational::from(p.x), Rational::from(p.y))
    }
}

impl From<&RatPoint> for QPoint {
    fn from(p: &RatPoint) -> QPoint {
        QPoint::new(
            Rational::from((p.hx().clone(), p.hw().clone())),
            Rational::from((p.hy().clone(), p.hw().clone())),
        )
    }
}

impl From<RatPoint> for QPoint {
    fn from(p: RatPoint) -> QPoint {
        QPoint::from(&p)
    }
}

impl From<&QPoint> for RatPoint {
    fn from(p: &QPoint) -> RatPoint {
        p.to_rat_point()
    }
}

impl From<Vector> for QPoint {
    fn from(v: Vector) -> QPoint {
        QPoint::new(Rational::from(v.x), Rational::from(v.y))
    }
}

impl fmt::Display for QPoint {
    /// Coordinates as exact fractions in lowest terms: `(3/2, -1)`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "({}, {})", self.x, self.y)
    }
}

// ---------------------------------------------------------------------------
// RatPoint as a position vector.

/// The products of two `i64` values as `i128`s: exact, each below `2^126`
/// in magnitude.
#[inline]
fn products(a: &Integer, b: &Integer, c: &Integer, d: &Integer) -> Option<(i128, i128)> {
    let f = |v: &Integer| v.to_i64().map(i128::from);
    Some((f(a)? * f(b)?, f(c)? * f(d)?))
}

/// A [`RatPoint`] read as its position vector (from the origin): the
/// vocabulary of [`QPoint`] on homogeneous coordinates, for code that keeps
/// its points canonical (the localizer's views relative to the robot).
impl RatPoint {
    /// `self − o`, in lowest terms.
    pub fn sub(&self, o: &RatPoint) -> RatPoint {
        let (aw, bw) = (self.hw(), o.hw());
        RatPoint::new(
            Integer::from(self.hx() * bw) - Integer::from(o.hx() * aw),
            Integer::from(self.hy() * bw) - Integer::from(o.hy() * aw),
            Integer::from(aw * bw),
        )
        .expect("positive denominators")
    }

    /// `−self`.
    pub fn neg(&self) -> RatPoint {
        RatPoint::new(
            Integer::from(-self.hx()),
            Integer::from(-self.hy()),
            self.hw().clone(),
        )
        .expect("w > 0")
    }

    /// The sign of `self × o` of the position vectors (`Greater`: `o` is
    /// counter-clockwise from `self` around the origin).
    ///
    /// Implementation note: the denominators are positive, so the sign is
    /// that of `X_a·Y_b − Y_a·X_b`, compared as two products; with the
    /// numerators in `i64` each product is below `2^126` and exact in
    /// `i128`, otherwise GMP.
    pub fn cross_sign(&self, o: &RatPoint) -> Ordering {
        if let Some((p, q)) = products(self.hx(), o.hy(), self.hy(), o.hx()) {
            return p.cmp(&q);
        }
        Integer::from(self.hx() * o.hy()).cmp(&Integer::from(self.hy() * o.hx()))
    }

    /// The sign of `self · o` of the position vectors (the same note as
    /// [`RatPoint::cross_sign`]: `p + q` is compared as `p` against `−q`,
    /// which no product of two `i64` overflows).
    pub fn dot_sign(&self, o: &RatPoint) -> Ordering {
        if let Some((p, q)) = products(self.hx(), o.hx(), self.hy(), o.hy()) {
            return p.cmp(&-q);
        }
        (Integer::from(self.hx() * o.hx()) + Integer::from(self.hy() * o.hy())).cmp0()
    }

    /// Whether the position vector lies in `[0, π)` counter-clockwise from
    /// the positive x axis (`y > 0`, or `y = 0 < x`).
    pub fn upper_half(&self) -> bool {
        upper(self.hx().cmp0(), self.hy().cmp0())
    }

    /// The counter-clockwise angular order of nonzero position vectors from
    /// the positive x axis, as [`Vector::compare_angle`].
    pub fn compare_angle(&self, o: &RatPoint) -> Ordering {
        angle_order(self.upper_half(), o.upper_half(), || self.cross_sign(o))
    }
}

// ---------------------------------------------------------------------------
// Predicates and the convex hull.

/// Homogeneous coordinates below `2^HOMOGENEOUS_FAST_BITS` in magnitude
/// take the `i128` fast path of [`turn`] and [`crate::orientation_rat`].
///
/// Implementation note: the orientation of three points `(X, Y, W)`,
/// `W > 0`, is the sign of the 3×3 determinant
/// `X_a·m_a − Y_a·m_b + W_a·m_c` of the rows, each 2×2 minor `m` a
/// difference of two products. With every entry below `2^41` a product is
/// below `2^82`, a minor below `2^83`, each term below `2^124` and the sum
/// of three below `3·2^124 < 2^126`, which an `i128` holds; at `2^42` the
/// sum overflows on some inputs. `tests/it/bounds.rs` recomputes both.
pub const HOMOGENEOUS_FAST_BITS: u32 = 41;

/// Whether `|v| < 2^HOMOGENEOUS_FAST_BITS`.
#[inline]
fn homogeneous_fits(v: i128) -> bool {
    v.unsigned_abs() < 1 << HOMOGENEOUS_FAST_BITS
}

/// The homogeneous triple `(X, Y, W)`, `W > 0`, of a rational point given
/// by the numerators and denominators of its coordinates, if each entry is
/// below `2^HOMOGENEOUS_FAST_BITS` (not necessarily in lowest terms).
#[inline]
fn homogeneous_small(p: &QPoint) -> Option<[i128; 3]> {
    let (nx, dx) = (p.x.numer().to_i64()?, p.x.denom().to_i64()?);
    let (ny, dy) = (p.y.numer().to_i64()?, p.y.denom().to_i64()?);
    let (nx, dx, ny, dy) = (
        i128::from(nx),
        i128::from(dx),
        i128::from(ny),
        i128::from(dy),
    );
    // Products of two i64 values are below 2^126: no overflow.
    let h = if dx == dy {
        [nx, ny, dx]
    } else {
        [nx * dy, ny * dx, dx * dy]
    };
    (homogeneous_fits(h[0]) && homogeneous_fits(h[1]) && homogeneous_fits(h[2])).then_some(h)
}

/// The sign of the determinant of three homogeneous rows with entries
/// below `2^HOMOGENEOUS_FAST_BITS` (see there for the bound).
#[inline]
pub(crate) fn det3_sign_small(a: [i128; 3], b: [i128; 3], c: [i128; 3]) -> Ordering {
    debug_assert!(a.iter().chain(&b).chain(&c).all(|&v| homogeneous_fits(v)));
    // Exact below the bound (minors < 2^83, terms < 2^124, sum < 2^126):
    // wrapping operations only spare fuzzing builds' redundant checks.
    // Every entry fits an i64 (below 2^41), so each minor's products are
    // 64 × 64 → 128-bit multiplications, one machine instruction each,
    // and each term multiplies an i128 by a sign-extended i64.
    let narrow = |v: [i128; 3]| v.map(|x| x as i64);
    let (a, b, c) = (narrow(a), narrow(b), narrow(c));
    let wide = crate::mul_wide;
    let term = |x: i64, minor: i128| minor.wrapping_mul(i128::from(x));
    let s = i128::wrapping_sub;
    let m0 = s(wide(b[1], c[2]), wide(b[2], c[1]));
    let m1 = s(wide(b[0], c[2]), wide(b[2], c[0]));
    let m2 = s(wide(b[0], c[1]), wide(b[1], c[0]));
    s(term(a[0], m0), term(a[1], m1))
        .wrapping_add(term(a[2], m2))
        .cmp(&0)
}

/// The sign of the determinant of three homogeneous rows `[x, y, w]` in
/// `i128`: through [`det3_sign_small`] when every entry is below
/// `2^HOMOGENEOUS_FAST_BITS`, else in checked arithmetic; `None` if that
/// overflows.
pub fn det3_sign_i128(a: [i128; 3], b: [i128; 3], c: [i128; 3]) -> Option<Ordering> {
    if a.iter().chain(&b).chain(&c).all(|&v| homogeneous_fits(v)) {
        return Some(det3_sign_small(a, b, c));
    }
    let m = |u: i128, v: i128| u.checked_mul(v);
    let minor = |i: usize, j: usize| m(b[i], c[j])?.checked_sub(m(b[j], c[i])?);
    let det = m(a[0], minor(1, 2)?)?
        .checked_sub(m(a[1], minor(0, 2)?)?)?
        .checked_add(m(a[2], minor(0, 1)?)?)?;
    Some(det.cmp(&0))
}

/// The homogeneous rows `(X, Y, W)` of a [`RatPoint`] in `i128`, if each
/// entry is below `2^HOMOGENEOUS_FAST_BITS`.
#[inline]
pub(crate) fn rat_point_small(p: &RatPoint) -> Option<[i128; 3]> {
    let h = [
        i128::from(p.hx().to_i64()?),
        i128::from(p.hy().to_i64()?),
        i128::from(p.hw().to_i64()?),
    ];
    (homogeneous_fits(h[0]) && homogeneous_fits(h[1]) && homogeneous_fits(h[2])).then_some(h)
}

/// The integer point of a [`QPoint`] whose coordinates are integers below
/// `2^ORIENTATION_FAST_BITS` in magnitude, read without allocating.
#[inline]
fn small_point(p: &QPoint) -> Option<Point> {
    let small = |q: &Rational| -> Option<i128> {
        if *q.denom() != 1 {
            return None;
        }
        let v = q.numer().to_i64()?;
        (v.unsigned_abs() < 1 << ORIENTATION_FAST_BITS).then_some(i128::from(v))
    };
    Some(Point::new(small(&p.x)?, small(&p.y)?))
}

/// The turn of `a → b → c`: the sign of `(b − a) × (c − a)`, `Greater` for
/// a left (counter-clockwise) turn, `Equal` when the three are collinear
/// (coincident points included). [`crate::Orientation::from_sign`] names it.
///
/// ```
/// use wai_exact::{turn, QPoint, Point};
/// use std::cmp::Ordering;
/// let p = |x, y| QPoint::from(Point::new(x, y));
/// assert_eq!(turn(&p(0, 0), &p(4, 0), &p(9, 1)), Ordering::Greater);
/// assert_eq!(turn(&p(0, 0), &p(4, 0), &p(-7, 0)), Ordering::Equal);
/// ```
///
/// Implementation note: three exact paths, the first that applies. Integer
/// points below `2^ORIENTATION_FAST_BITS` take [`crate::orientation`]'s
/// `i128` path (see its bound); points whose homogeneous triples are below
/// `2^HOMOGENEOUS_FAST_BITS` take a 3×3 determinant in `i128` (see there);
/// the rest the same determinant in GMP integers, which, unlike `mpq`
/// subtractions, reduces no fraction. No path allocates but the last.
#[inline]
pub fn turn(a: &QPoint, b: &QPoint, c: &QPoint) -> Ordering {
    if let (Some(a), Some(b), Some(c)) = (small_point(a), small_point(b), small_point(c)) {
        // Below 2^ORIENTATION_FAST_BITS: `orientation`'s fast path.
        let (u, v) = (Vector::between_fast(a, b), Vector::between_fast(a, c));
        return u.cross_fast(v).cmp(&0);
    }
    if let (Some(a), Some(b), Some(c)) = (
        homogeneous_small(a),
        homogeneous_small(b),
        homogeneous_small(c),
    ) {
        return det3_sign_small(a, b, c);
    }
    let (a, b, c) = (homogeneous_big(a), homogeneous_big(b), homogeneous_big(c));
    fn row<'a>(h: &'a [Cow<'_, Integer>; 3]) -> [&'a Integer; 3] {
        [&*h[0], &*h[1], &*h[2]]
    }
    det3_sign_big(row(&a), row(&b), row(&c))
}

/// The homogeneous triple `(X, Y, W)`, `W > 0`, of a rational point in GMP
/// integers (not necessarily in lowest terms), borrowed when both
/// coordinates have one denominator.
fn homogeneous_big(p: &QPoint) -> [Cow<'_, Integer>; 3] {
    let (xd, yd) = (p.x.denom(), p.y.denom());
    if xd == yd {
        return [
            Cow::Borrowed(p.x.numer()),
            Cow::Borrowed(p.y.numer()),
            Cow::Borrowed(xd),
        ];
    }
    [
        Cow::Owned(Integer::from(p.x.numer() * yd)),
        Cow::Owned(Integer::from(p.y.numer() * xd)),
        Cow::Owned(Integer::from(xd * yd)),
    ]
}

/// The sign of the determinant of three homogeneous rows in GMP integers.
pub(crate) fn det3_sign_big(a: [&Integer; 3], b: [&Integer; 3], c: [&Integer; 3]) -> Ordering {
    let minor = |i: usize, j: usize| Integer::from(b[i] * c[j]) - Integer::from(b[j] * c[i]);
    let (m0, m1, m2) = (minor(1, 2), minor(0, 2), minor(0, 1));
    (m0 * a[0] - m1 * a[1] + m2 * a[2]).cmp0()
}

/// The convex hull of `pts` (closed), counter-clockwise from its
/// lexicographically least point, collinear points dropped (Andrew's
/// monotone chain).
///
/// # Edge cases
/// Repeated points count once. Fewer than three distinct points, or all on
/// one line, give the distinct extreme points only: none, one, or the two
/// ends of the segment they span.
/// ```
/// use wai_exact::{convex_hull, Point, QPoint};
/// let p = |x, y| QPoint::from(Point::new(x, y));
/// let square = vec![p(0, 0), p(2, 2), p(1, 1), p(2, 0), p(0, 2), p(1, 0), p(2, 0)];
/// assert_eq!(convex_hull(square), vec![p(0, 0), p(2, 0), p(2, 2), p(0, 2)]);
/// assert_eq!(convex_hull(vec![p(3, 3), p(1, 1), p(2, 2)]), vec![p(1, 1), p(3, 3)]);
/// assert_eq!(convex_hull(vec![p(5, 5), p(5, 5)]), vec![p(5, 5)]);
/// ```
pub fn convex_hull(mut pts: Vec<QPoint>) -> Vec<QPoint> {
    pts.sort();
    pts.dedup();
    if pts.len() < 3 {
        return pts;
    }
    let chain = |pts: &mut dyn Iterator<Item = &QPoint>| {
        let mut h: Vec<QPoint> = Vec::new();
        for p in pts {
            while h.len() >= 2 && turn(&h[h.len() - 2], &h[h.len() - 1], p) != Ordering::Greater {
                h.pop();
            }
            h.push(p.clone());
        }
        // The last point starts the other chain.
        h.pop();
        h
    };
    let mut lower = chain(&mut pts.iter());
    lower.extend(chain(&mut pts.iter().rev()));
    lower
}
