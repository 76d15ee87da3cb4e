//! The fast products against GMP.

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::Integer;
use wai_localize::fast::{cmp_products, mul_wide};

fn gmp(a: i128, b: i128, c: i128, d: i128) -> std::cmp::Ordering {
    (Integer::from(a) * b - Integer::from(c) * d).cmp0()
}

#[test]
fn products_compare_exactly_on_random_and_extreme_inputs() {
    let extremes = [
        0,
        1,
        -1,
        i128::MAX,
        i128::MIN,
        i128::MIN + 1,
        1 << 64,
        (1 << 64) - 1,
        -(1 << 100),
        u64::MAX as i128 * 3,
    ];
    for &a in &extremes {
        for &b in &extremes {
            for &c in &extremes {
                for &d in &extremes {
                    assert_eq!(cmp_products(a, b, c, d), gmp(a, b, c, d), "{a} {b} {c} {d}");
                }
            }
        }
    }
    let mut rng = ChaCha8Rng::seed_from_u64(3);
    for _ in 0..200_000 {
        let bits: u32 = rng.random_range(1..=127);
        let mut r = || {
            let v: i128 = rng.random::<i128>() >> (128 - bits);
            v
        };
        let (a, b, c, d) = (r(), r(), r(), r());
        assert_eq!(cmp_products(a, b, c, d), gmp(a, b, c, d), "{a} {b} {c} {d}");
        // Equal products.
        assert_eq!(cmp_products(a, b, b, a), std::cmp::Ordering::Equal);
    }
    let (hi, lo) = mul_wide(u128::MAX, u128::MAX);
    let full = Integer::from(u128::MAX) * u128::MAX;
    assert_eq!((Integer::from(hi) << 128u32) + lo, full);
}

#[test]
fn exact_division_by_multiplication_equals_the_remainder_test() {
    use wai_localize::fast::ExactDivisor;
    let mut rng = ChaCha8Rng::seed_from_u64(5);
    let mut divisors: Vec<u64> = (1..=64).collect();
    divisors.extend([u64::MAX, 1 << 63, (1 << 63) - 1, 3 << 40, 1_000_000_007]);
    for _ in 0..200 {
        let bits = rng.random_range(0..64);
        divisors.push(rng.random_range(1..=u64::MAX >> bits));
    }
    let mut checked = 0;
    for &d in &divisors {
        let div = ExactDivisor::new(d).unwrap();
        let mut ns: Vec<i64> = vec![0, 1, -1, i64::MAX, i64::MIN, i64::MIN + 1];
        for _ in 0..200 {
            let q: i64 = rng.random_range(-(1 << 40)..(1 << 40));
            if let Some(n) = q.checked_mul(d as i64).filter(|_| d <= i64::MAX as u64) {
                ns.push(n);
                ns.push(n.wrapping_add(1));
            }
            ns.push(rng.random());
        }
        for n in ns {
            let want = (i128::from(n) % i128::from(d) == 0).then(|| i128::from(n) / i128::from(d));
            assert_eq!(div.divide(n), want, "{n} / {d}");
            checked += 1;
        }
    }
    assert!(ExactDivisor::new(0).is_none());
    assert!(checked > 50_000);
}
