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
