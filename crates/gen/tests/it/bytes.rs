//! `wai_gen::bytes`: maps from bytes are valid, small, deterministic, of
//! every shape, orthogonal where their shape says so, and no byte string
//! makes the builder panic.

use crate::common::check_valid;
use arbitrary::Unstructured;
use proptest::prelude::*;
use rand::{RngCore, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::collections::BTreeMap;
use wai_gen::bytes::{map_from_bytes, map_from_seed, shaped_map_from_bytes, Shape, SHAPES};

/// The bytes `map_from_seed` reads for `seed`.
fn seed_bytes(seed: u64) -> Vec<u8> {
    let mut bytes = vec![0u8; wai_gen::bytes::SEED_BYTES];
    ChaCha8Rng::seed_from_u64(seed).fill_bytes(&mut bytes);
    bytes
}

#[test]
fn every_shape_is_reached_and_every_map_is_valid() {
    let mut reached: BTreeMap<Shape, usize> = BTreeMap::new();
    for seed in 0..400 {
        let bytes = seed_bytes(seed);
        let (shape, map) = shaped_map_from_bytes(&mut Unstructured::new(&bytes)).unwrap();
        check_valid(&map);
        let name = map.name().unwrap();
        assert!(
            name.starts_with(&format!("bytes/{} ", shape.id())),
            "{shape:?}: {name}"
        );
        assert!(
            map.n() <= wai_gen::bytes::MAX_VERTICES + 2,
            "{name}: n = {}",
            map.n()
        );
        if shape.is_orthogonal() {
            assert!(map.is_orthogonal(), "{name}");
        }
        // map_from_seed is the same map, with the seed in its name.
        let again = map_from_seed(seed);
        assert_eq!(again.vertices(), map.vertices(), "{name}");
        assert_eq!(again.name().unwrap(), format!("{name} seed={seed}"));
        *reached.entry(shape).or_default() += 1;
    }
    for shape in SHAPES {
        assert!(
            reached.get(shape).copied().unwrap_or(0) >= 3,
            "{shape:?} reached {reached:?}"
        );
    }
}

#[test]
fn maps_are_a_function_of_the_bytes() {
    for seed in 0..100 {
        let bytes = seed_bytes(seed);
        let a = map_from_bytes(&mut Unstructured::new(&bytes)).unwrap();
        let b = map_from_bytes(&mut Unstructured::new(&bytes)).unwrap();
        assert_eq!(a, b);
        assert_eq!(a.name(), b.name());
    }
    // Different seeds give different maps, mostly.
    let distinct: std::collections::BTreeSet<Vec<(i128, i128)>> = (0..50)
        .map(|s| {
            map_from_seed(s)
                .vertices()
                .iter()
                .map(|p| (p.x, p.y))
                .collect()
        })
        .collect();
    assert!(distinct.len() > 40, "{}", distinct.len());
}

#[test]
fn short_and_empty_inputs_give_maps() {
    for len in 0..24 {
        for fill in [0u8, 1, 0x7f, 0xff] {
            let bytes = vec![fill; len];
            let map = map_from_bytes(&mut Unstructured::new(&bytes)).unwrap();
            check_valid(&map);
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 400, ..ProptestConfig::default() })]

    /// No byte string panics the builder, and what it builds is valid.
    #[test]
    fn arbitrary_bytes_never_panic(bytes in proptest::collection::vec(any::<u8>(), 0..300)) {
        if let Ok((shape, map)) = shaped_map_from_bytes(&mut Unstructured::new(&bytes)) {
            check_valid(&map);
            prop_assert!(!shape.is_orthogonal() || map.is_orthogonal());
        }
    }
}
