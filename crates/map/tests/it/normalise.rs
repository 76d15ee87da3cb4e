use crate::ring;
use wai_map::{validate_all, Map};

#[test]
fn counter_clockwise_input_is_kept() {
    let (map, norm) = Map::from_ring(ring(&[(0, 0), (4, 0), (4, 3), (0, 3)])).unwrap();
    assert!(norm.is_identity());
    assert_eq!(map.vertices(), ring(&[(0, 0), (4, 0), (4, 3), (0, 3)]));
    assert_eq!((map.n(), map.r()), (4, 0));
    assert!(map.is_orthogonal());
    assert_eq!(map.area_twice(), 24);
}

#[test]
fn clockwise_input_is_reversed_keeping_its_first_vertex() {
    let (map, norm) = Map::from_ring(ring(&[(0, 0), (0, 3), (4, 3), (4, 0)])).unwrap();
    assert!(norm.reversed);
    assert_eq!(map.vertices(), ring(&[(0, 0), (4, 0), (4, 3), (0, 3)]));
}

#[test]
fn straight_vertices_are_removed() {
    // (2, 0), (4, 2) and (0, 0)... only the 180° ones: (2, 0), (4, 2), (0, 1).
    let input = ring(&[(0, 0), (2, 0), (4, 0), (4, 2), (4, 4), (0, 4), (0, 1)]);
    let (map, norm) = Map::from_ring(input).unwrap();
    assert_eq!(norm.removed_collinear, vec![1, 3, 6]);
    assert_eq!(map.vertices(), ring(&[(0, 0), (4, 0), (4, 4), (0, 4)]));
}

#[test]
fn straight_first_vertex_and_chains_are_removed() {
    // Vertex 0 is straight, and so is a chain of three on the top edge.
    let input = ring(&[
        (2, 0),
        (4, 0),
        (4, 4),
        (3, 4),
        (2, 4),
        (1, 4),
        (0, 4),
        (0, 0),
    ]);
    let (map, norm) = Map::from_ring(input).unwrap();
    assert_eq!(norm.removed_collinear, vec![0, 3, 4, 5]);
    assert_eq!(map.n(), 4);
}

#[test]
fn reflex_vertices_of_an_l_shape() {
    let (map, _) = Map::from_ring(ring(&[(0, 0), (4, 0), (4, 2), (2, 2), (2, 4), (0, 4)])).unwrap();
    assert_eq!(map.reflex_vertices(), &[3]);
    assert!(map.is_reflex(3) && !map.is_reflex(2));
}

#[test]
fn scale_is_reduced_to_the_least() {
    let (map, _) = Map::from_scaled_ring(ring(&[(0, 0), (4, 0), (0, 6)]), 2.into()).unwrap();
    assert_eq!(*map.scale(), 1);
    assert_eq!(map.vertices(), ring(&[(0, 0), (2, 0), (0, 3)]));
}

#[test]
fn validate_all_agrees_with_from_ring_on_small_rings() {
    // Every ring of 4 points of a 3x3 grid, valid or not.
    let grid: Vec<(i128, i128)> = (0..3).flat_map(|x| (0..3).map(move |y| (x, y))).collect();
    let mut valid = 0;
    for a in &grid {
        for b in &grid {
            for c in &grid {
                for d in &grid {
                    let r = ring(&[*a, *b, *c, *d]);
                    let errors = validate_all(&r);
                    assert_eq!(errors.is_empty(), Map::from_ring(r).is_ok());
                    valid += usize::from(errors.is_empty());
                }
            }
        }
    }
    assert!(valid > 100, "only {valid} valid rings");
}

/// Enlarging by a power of two equals validating the enlarged ring (which
/// needs no normalisation), keeps names, and refuses a coordinate beyond
/// the bound with its vertex.
#[test]
fn scaled_up_equals_the_validated_enlarged_ring() {
    // An L with a reflex vertex and a negative coordinate.
    let ring = ring(&[(0, 0), (6, 0), (6, 2), (2, 2), (2, 5), (-3, 5)]);
    let (map, _) = Map::from_ring(ring.clone()).unwrap();
    let map = map.with_name("l");
    for bits in [0, 1, 31, 60, 96] {
        let big = map.scaled_up(bits).unwrap();
        let enlarged = ring
            .iter()
            .map(|p| wai_exact::Point::new(p.x << bits, p.y << bits))
            .collect();
        let (want, norm) = Map::from_ring(enlarged).unwrap();
        assert!(norm.is_identity());
        assert_eq!(big, want.with_name("l"), "2^{bits}");
        assert_eq!(big.reflex_vertices(), map.reflex_vertices());
    }
    // 6 needs 3 bits: 3 + 98 > 100.
    let err = map.scaled_up(98).unwrap_err().to_string();
    assert!(
        err.contains("vertex 1") && err.contains("101 bits"),
        "{err}"
    );
}
