//! Exact comparisons of products of `i128`s without GMP: the query's fast
//! path.
//!
//! Implementation note: a product of two `i128`s has at most 254 bits of
//! magnitude, so it is computed exactly as a 256-bit magnitude (two `u128`
//! halves, schoolbook on 64-bit limbs: every partial product of two 64-bit
//! limbs fits a `u128`, and the middle column sums three values below 2^64
//! each, below 2^66) with a sign. Comparing two such products is then
//! exact for every input, with no bound to check. Sums of products that
//! are needed elsewhere use `checked_*` and fall back to GMP on overflow.
//! `tests/it/fast.rs` compares every function with GMP on random and
//! extreme inputs.

use std::cmp::Ordering;

const LOW: u128 = (1u128 << 64) - 1;

/// The 256-bit product of two `u128`s, as (high, low) halves.
pub fn mul_wide(x: u128, y: u128) -> (u128, u128) {
    let (x1, x0) = (x >> 64, x & LOW);
    let (y1, y0) = (y >> 64, y & LOW);
    let p00 = x0 * y0;
    let p01 = x0 * y1;
    let p10 = x1 * y0;
    let p11 = x1 * y1;
    let mid = (p00 >> 64) + (p01 & LOW) + (p10 & LOW);
    let lo = (p00 & LOW) | (mid << 64);
    let hi = p11 + (p01 >> 64) + (p10 >> 64) + (mid >> 64);
    (hi, lo)
}

/// The sign of a·b − c·d, exactly, for any `i128`s.
#[inline]
pub fn cmp_products(a: i128, b: i128, c: i128, d: i128) -> Ordering {
    // In i64 each product is below 2^126 and the difference fits; the
    // products of sign-extended i64s are single widening multiplications.
    if let (Ok(a), Ok(b), Ok(c), Ok(d)) = (
        i64::try_from(a),
        i64::try_from(b),
        i64::try_from(c),
        i64::try_from(d),
    ) {
        return (i128::from(a) * i128::from(b)).cmp(&(i128::from(c) * i128::from(d)));
    }
    let sign = |x: i128, y: i128| x.signum() * y.signum();
    let (s1, s2) = (sign(a, b), sign(c, d));
    if s1 != s2 {
        return s1.cmp(&s2);
    }
    if s1 == 0 {
        return Ordering::Equal;
    }
    let m1 = mul_wide(a.unsigned_abs(), b.unsigned_abs());
    let m2 = mul_wide(c.unsigned_abs(), d.unsigned_abs());
    if s1 > 0 {
        m1.cmp(&m2)
    } else {
        m2.cmp(&m1)
    }
}

/// a·b − c·d if it fits an `i128`.
#[inline]
pub fn det2(a: i128, b: i128, c: i128, d: i128) -> Option<i128> {
    // In i64 each product is below 2^126 and the difference fits: single
    // widening multiplications, without the overflow checks (a library
    // call for `i128`).
    if let (Ok(a), Ok(b), Ok(c), Ok(d)) = (
        i64::try_from(a),
        i64::try_from(b),
        i64::try_from(c),
        i64::try_from(d),
    ) {
        return Some(i128::from(a) * i128::from(b) - i128::from(c) * i128::from(d));
    }
    a.checked_mul(b)?.checked_sub(c.checked_mul(d)?)
}
