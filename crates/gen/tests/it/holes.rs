//! Random maps with holes: valid, deterministic, and holed as asked.

use wai_gen::{random_with_holes, HOLED_KINDS};

#[test]
fn holed_maps_are_valid_deterministic_and_have_their_holes() {
    for kind in HOLED_KINDS {
        let mut full = 0;
        let mut total = 0;
        for seed in 0..30 {
            for n in [8, 24, 60] {
                let map = random_with_holes(kind.id, n, 6, seed).unwrap();
                let again = random_with_holes(kind.id, n, 6, seed).unwrap();
                assert_eq!(map, again, "{} n={n} seed={seed}", kind.id);
                // Valid as a file would be: read back equal.
                let back = wai_map::json::from_json(wai_map::json::to_json(&map).as_bytes())
                    .unwrap()
                    .map;
                assert_eq!(back.vertices(), map.vertices());
                assert!(map.hole_count() <= 6);
                if kind.id == "orthogonal-pillars" {
                    assert!(map.is_orthogonal());
                    // Every pillar corner is reflex in the free space.
                    let hole_reflex = map
                        .reflex_vertices()
                        .iter()
                        .filter(|&&i| map.ring_of(i) > 0)
                        .count();
                    assert_eq!(hole_reflex, 4 * map.hole_count());
                }
                full += usize::from(map.hole_count() == 6);
                total += 1;
            }
        }
        assert!(
            full * 2 >= total,
            "{}: {full} of {total} maps got every hole",
            kind.id
        );
    }
    assert!(random_with_holes("no-such-kind", 10, 1, 0).is_err());
    assert!(random_with_holes("simple-holes", 2, 1, 0).is_err());
}
