//! Validation of a ring of integer points as a simple polygon.

use crate::error::{IntersectionKind, MapError, Position};
use rug::{Integer, Rational};
use std::collections::HashMap;
use wai_exact::{
    classify_segments, construct_intersection, orientation, Orientation, Point, RatPoint, Segment,
    SegmentIntersection,
};

/// Every problem of `ring` as the boundary of a map (coordinates in input
/// units, scale 1); empty if and only if [`crate::Map::from_ring`] accepts it.
///
/// Checks, in order: every coordinate below `2^MAX_COORD_BITS`; at least 3
/// distinct vertices; no repeated vertex; not
/// all on one line; no two edges meeting except consecutive edges at their
/// common vertex (a vertex touching another edge, crossing edges and edges
/// folding back onto each other are all reported, each pair once).
pub fn validate_all(ring: &[Point]) -> Vec<MapError> {
    validate_scaled(ring, &Integer::from(1))
}

pub(crate) fn position(p: Point, scale: &Integer) -> Position {
    Position {
        x: Rational::from((Integer::from(p.x), scale.clone())),
        y: Rational::from((Integer::from(p.y), scale.clone())),
    }
}

fn rat_position(p: &RatPoint, scale: &Integer) -> Position {
    let den = Integer::from(p.hw() * scale);
    Position {
        x: Rational::from((p.hx().clone(), den.clone())),
        y: Rational::from((p.hy().clone(), den)),
    }
}

pub(crate) fn validate_scaled(ring: &[Point], scale: &Integer) -> Vec<MapError> {
    // Coordinates beyond the supported size make every later check moot.
    let too_large: Vec<MapError> = ring
        .iter()
        .enumerate()
        .filter(|(_, p)| !p.is_supported())
        .map(|(i, p)| MapError::CoordinateTooLarge {
            path: format!("vertex {i}"),
            bits: u64::from(p.magnitude_bits()),
            max: wai_exact::MAX_COORD_BITS,
        })
        .collect();
    if !too_large.is_empty() {
        return too_large;
    }
    let mut errors = Vec::new();
    let mut first_at: HashMap<Point, usize> = HashMap::new();
    for (i, &p) in ring.iter().enumerate() {
        if let Some(&first) = first_at.get(&p) {
            errors.push(MapError::RepeatedVertex {
                first,
                second: i,
                at: position(p, scale),
                closing: first == 0 && i + 1 == ring.len(),
            });
        } else {
            first_at.insert(p, i);
        }
    }
    if first_at.len() < 3 {
        return vec![MapError::TooFewVertices {
            found: first_at.len(),
        }];
    }
    let a = ring[0];
    let Some(&b) = ring.iter().find(|&&p| p != a) else {
        unreachable!("three distinct vertices")
    };
    if ring
        .iter()
        .all(|&p| orientation(a, b, p) == Orientation::Collinear)
    {
        errors.push(MapError::ZeroArea { n: ring.len() });
        return errors;
    }
    // With repeated vertices, check the ring without its zero-length edges
    // and do not report again the touching at a repeated point.
    let repeated: Vec<Point> = errors
        .iter()
        .filter_map(|e| match e {
            MapError::RepeatedVertex { second, .. } => Some(ring[*second]),
            _ => None,
        })
        .collect();
    let edges: Vec<(usize, Segment)> = (0..ring.len())
        .filter_map(|i| Segment::new(ring[i], ring[(i + 1) % ring.len()]).map(|s| (i, s)))
        .collect();
    for (ia, ib, kind, at) in intersecting_pairs(&edges) {
        if let SegmentIntersection::Touching { at: p } = at {
            if repeated.contains(&p) {
                continue;
            }
        }
        let at = match at {
            SegmentIntersection::Touching { at } => position(at, scale),
            SegmentIntersection::Overlap { start, .. } => position(start, scale),
            _ => {
                let (sa, sb) = (edges[ia].1, edges[ib].1);
                let p = construct_intersection(&sa.line(), &sb.line())
                    .expect("crossing segments are not parallel");
                rat_position(&p, scale)
            }
        };
        errors.push(MapError::SelfIntersection {
            edge_a: edges[ia].0,
            edge_b: edges[ib].0,
            kind,
            at,
        });
    }
    errors
}

/// Pairs of edges (indices into `edges`) that meet where they must not,
/// found by a sweep over the edges' x-extents: O(n log n + k) for maps
/// whose edges are short compared with the map, O(n²) at worst.
fn intersecting_pairs(
    edges: &[(usize, Segment)],
) -> Vec<(usize, usize, IntersectionKind, SegmentIntersection)> {
    let m = edges.len();
    let xmin = |s: &Segment| s.a().x.min(s.b().x);
    let xmax = |s: &Segment| s.a().x.max(s.b().x);
    let mut order: Vec<usize> = (0..m).collect();
    order.sort_by_key(|&k| xmin(&edges[k].1));
    let mut found = Vec::new();
    for (pos, &i) in order.iter().enumerate() {
        let si = &edges[i].1;
        for &j in &order[pos + 1..] {
            let sj = &edges[j].1;
            if xmin(sj) > xmax(si) {
                break;
            }
            let (lo, hi) = (i.min(j), i.max(j));
            let adjacent = hi == lo + 1 || (lo == 0 && hi == m - 1);
            let hit = classify_segments(&edges[lo].1, &edges[hi].1);
            let kind = match hit {
                SegmentIntersection::None => continue,
                // Consecutive edges meet at their common vertex; anything
                // more is a fold.
                SegmentIntersection::Touching { .. } if adjacent && m > 2 => continue,
                SegmentIntersection::Crossing => IntersectionKind::Crossing,
                SegmentIntersection::Touching { .. } => IntersectionKind::Touching,
                SegmentIntersection::Overlap { .. } => IntersectionKind::Overlap,
            };
            found.push((lo, hi, kind, hit));
        }
    }
    found.sort_by_key(|&(a, b, _, _)| (a, b));
    found
}
