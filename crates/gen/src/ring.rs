//! Rings (vertex cycles) and their conversion into [`Map`]s.
//!
//! Every generator of this crate builds a ring that is valid by
//! construction — simple, counter-clockwise, without two collinear
//! consecutive edges — and hands it to [`into_map`], which insists that
//! [`Map::from_ring`] accepts it unchanged. A rejection there is a bug of
//! the generator, never of its caller, so it panics with the ring.

use std::cmp::Ordering;
use wai_exact::{classify_segments, orientation, Orientation, Point, Segment, SegmentIntersection};
use wai_map::Map;

/// Builds the map of a ring that is valid by construction.
///
/// # Panics
/// If `Map::from_ring` rejects the ring or has to normalise it (reverse it
/// or drop a 180° vertex): the generator that built it is wrong.
pub(crate) fn into_map(ring: Vec<Point>, name: impl Into<String>) -> Map {
    debug_assert_eq!(ring_problem(&ring), None, "{ring:?}");
    let copy = ring.clone();
    match Map::from_ring(ring) {
        Ok((map, norm)) => {
            assert!(
                norm.is_identity(),
                "generator emitted a ring that needed normalisation ({norm:?}): {copy:?}"
            );
            map.with_name(name)
        }
        Err(e) => panic!("generator emitted an invalid ring ({e}): {copy:?}"),
    }
}

/// The first reason why `ring` is not a valid map ring (simple,
/// counter-clockwise, no repeated vertex, no 180° vertex), or `None`.
///
/// An independent O(n²) check, used in debug builds on every generated ring
/// and by the tests as a second opinion next to `wai_map::validate_all`.
pub fn ring_problem(ring: &[Point]) -> Option<String> {
    let n = ring.len();
    if n < 3 {
        return Some(format!("only {n} vertices"));
    }
    for i in 0..n {
        let (a, b, c) = (ring[i], ring[(i + 1) % n], ring[(i + 2) % n]);
        if a == b {
            return Some(format!("vertex {i} repeats at {a}"));
        }
        if orientation(a, b, c) == Orientation::Collinear {
            return Some(format!(
                "vertex {} at {b} is collinear with its neighbours",
                (i + 1) % n
            ));
        }
    }
    let seg = |i: usize| Segment::new(ring[i], ring[(i + 1) % n]).expect("distinct endpoints");
    for i in 0..n {
        for j in i + 1..n {
            let x = classify_segments(&seg(i), &seg(j));
            let adjacent_at = if j == i + 1 {
                Some(ring[j])
            } else if i == 0 && j == n - 1 {
                Some(ring[0])
            } else {
                None
            };
            let ok = match (x, adjacent_at) {
                (SegmentIntersection::None, None) => true,
                (SegmentIntersection::Touching { at }, Some(v)) => at == v,
                _ => false,
            };
            if !ok {
                return Some(format!("edges {i} and {j} meet: {x:?}"));
            }
        }
    }
    if wai_exact::signed_area_twice(ring).cmp0() != Ordering::Greater {
        return Some("not counter-clockwise".into());
    }
    None
}

/// Removes the vertices where the ring goes straight on (180° vertices) and
/// repeated consecutive vertices; used on orthogonal boundaries traced from
/// unit edges.
pub(crate) fn drop_straight(ring: &[Point]) -> Vec<Point> {
    let n = ring.len();
    let mut out: Vec<Point> = Vec::with_capacity(n);
    for i in 0..n {
        let (a, b, c) = (ring[(i + n - 1) % n], ring[i], ring[(i + 1) % n]);
        if orientation(a, b, c) != Orientation::Collinear {
            out.push(b);
        }
    }
    out
}

/// Reverses the ring if it is clockwise.
pub(crate) fn make_ccw(mut ring: Vec<Point>) -> Vec<Point> {
    if wai_exact::signed_area_twice(&ring).cmp0() == Ordering::Less {
        ring.reverse();
    }
    ring
}

/// Number of reflex vertices of a counter-clockwise ring.
pub fn reflex_count(ring: &[Point]) -> usize {
    let n = ring.len();
    (0..n)
        .filter(|&i| {
            orientation(ring[(i + n - 1) % n], ring[i], ring[(i + 1) % n]) == Orientation::Clockwise
        })
        .count()
}
