//! The sweep that finds self-intersections agrees with the all-pairs test.

use proptest::prelude::*;
use wai_exact::{classify_segments, Point, Segment, SegmentIntersection};
use wai_map::{validate_all, MapError};

/// Every pair of edges that meet where they must not, by brute force.
fn naive_pairs(ring: &[Point]) -> Vec<(usize, usize)> {
    let edges: Vec<(usize, Segment)> = (0..ring.len())
        .filter_map(|i| Segment::new(ring[i], ring[(i + 1) % ring.len()]).map(|s| (i, s)))
        .collect();
    let m = edges.len();
    let mut out = Vec::new();
    for a in 0..m {
        for b in a + 1..m {
            let adjacent = b == a + 1 || (a == 0 && b == m - 1);
            match classify_segments(&edges[a].1, &edges[b].1) {
                SegmentIntersection::None => {}
                SegmentIntersection::Touching { .. } if adjacent => {}
                _ => out.push((edges[a].0, edges[b].0)),
            }
        }
    }
    out
}

fn reported_pairs(ring: &[Point]) -> Option<Vec<(usize, usize)>> {
    let errors = validate_all(ring);
    if errors
        .iter()
        .any(|e| !matches!(e, MapError::SelfIntersection { .. }))
    {
        return None; // repeated vertices or zero area: other rules apply
    }
    Some(
        errors
            .iter()
            .map(|e| match e {
                MapError::SelfIntersection { edge_a, edge_b, .. } => (*edge_a, *edge_b),
                _ => unreachable!(),
            })
            .collect(),
    )
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(3000))]
    /// Random rings on a small grid: many crossings, touchings and overlaps.
    #[test]
    fn sweep_finds_exactly_the_naive_pairs(pts in prop::collection::vec((0i128..6, 0i128..6), 3..12)) {
        let ring: Vec<Point> = pts.iter().map(|&(x, y)| Point::new(x, y)).collect();
        if let Some(got) = reported_pairs(&ring) {
            prop_assert_eq!(got, naive_pairs(&ring));
        }
    }
}
