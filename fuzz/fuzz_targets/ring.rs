//! Rings of points built from bytes: `validate_all` and `Map::from_ring`
//! must agree, and an accepted ring must give a map with the invariants of
//! `wai_map::Map`.
//!
//! Coordinates are small (an `i8` each) so that collinear points, repeated
//! vertices and touching edges are common, then scaled by `2^shift` and
//! translated so that large magnitudes, up to the whole `i128` range, are
//! covered too.
#![no_main]

use libfuzzer_sys::arbitrary::{self, Arbitrary};
use libfuzzer_sys::fuzz_target;
use wai_exact::{orientation, signed_area_twice, Orientation, Point};
use wai_map::{validate_all, Map};

#[derive(Debug)]
struct Ring {
    points: Vec<Point>,
}

impl<'a> Arbitrary<'a> for Ring {
    fn arbitrary(u: &mut arbitrary::Unstructured<'a>) -> arbitrary::Result<Self> {
        let shift = u.int_in_range(0u32..=120)?;
        // Mostly no translation; sometimes an arbitrary i128 offset.
        let offset: (i128, i128) = if u.ratio(1u8, 4)? {
            (u.arbitrary()?, u.arbitrary()?)
        } else {
            (0, 0)
        };
        let small: Vec<(i8, i8)> = u.arbitrary()?;
        let mut points = Vec::with_capacity(small.len());
        for (x, y) in small {
            let scale = 1i128 << shift; // |x| <= 2^7, so |x| * 2^120 <= 2^127
            let x = i128::from(x)
                .checked_mul(scale)
                .and_then(|x| x.checked_add(offset.0));
            let y = i128::from(y)
                .checked_mul(scale)
                .and_then(|y| y.checked_add(offset.1));
            match (x, y) {
                (Some(x), Some(y)) => points.push(Point::new(x, y)),
                _ => return Err(arbitrary::Error::IncorrectFormat),
            }
        }
        Ok(Ring { points })
    }
}

fuzz_target!(|ring: Ring| {
    let points = ring.points;
    let problems = validate_all(&points);
    let built = Map::from_ring(points.clone());
    // Beyond the supported size both must refuse, with that error (a
    // disagreement here was found by this target and fixed in wai-map).
    if points.iter().any(|p| !p.is_supported()) {
        assert!(problems
            .iter()
            .any(|e| matches!(e, wai_map::MapError::CoordinateTooLarge { .. })));
    }
    match &built {
        Ok(_) => assert!(
            problems.is_empty(),
            "from_ring accepted a ring validate_all rejects: {problems:?}\nring: {points:?}"
        ),
        Err(e) => assert!(
            !problems.is_empty(),
            "validate_all accepted a ring from_ring rejects: {e}\nring: {points:?}"
        ),
    }
    let Ok((map, norm)) = built else { return };
    let v = map.vertices();
    let n = v.len();
    assert_eq!(n, map.n());
    assert!(n >= 3, "a map with {n} vertices from {points:?}");
    assert_eq!(n + norm.removed_collinear.len(), points.len(), "{norm:?}");
    assert!(signed_area_twice(v) > 0, "map not counter-clockwise: {v:?}");
    let mut reflex = 0;
    for i in 0..n {
        match orientation(v[(i + n - 1) % n], v[i], v[(i + 1) % n]) {
            Orientation::Collinear => panic!("180° vertex {i} left in {v:?}"),
            Orientation::Clockwise => reflex += 1,
            Orientation::CounterClockwise => {}
        }
    }
    assert_eq!(reflex, map.r(), "reflex count of {v:?}");
    assert!(map.r() + 3 <= n, "r = {} with n = {n}", map.r());
});
