//! The one validity check every generated map goes through.

use wai_exact::Point;
use wai_gen::ring_problem;
use wai_map::{validate_all, Map};

/// A generated map is valid three times over: `Map::from_ring` accepts its
/// ring unchanged, `validate_all` finds nothing, and the independent
/// `ring_problem` of this crate agrees.
pub fn check_valid(map: &Map) {
    let ring: Vec<Point> = map.vertices().to_vec();
    let (again, norm) = Map::from_ring(ring.clone())
        .unwrap_or_else(|e| panic!("{:?}: rejected: {e}: {ring:?}", map.name()));
    assert!(norm.is_identity(), "{:?}: normalised {norm:?}", map.name());
    assert_eq!(again.vertices(), map.vertices());
    let errors = validate_all(&ring);
    assert!(errors.is_empty(), "{:?}: {errors:?}", map.name());
    assert_eq!(ring_problem(&ring), None, "{:?}", map.name());
    assert_eq!(wai_gen::reflex_count(&ring), map.r());
}
