//! Validation of rings of integer points as a map: a simple polygon, and
//! holes inside it that meet nothing.

use crate::error::{IntersectionKind, MapError, Position, Ring};
use rug::{Integer, Rational};
use std::collections::HashMap;
use wai_exact::{
    classify_segments, construct_intersection, locate, orientation, Containment, Orientation,
    Point, RatPoint, Segment, SegmentIntersection,
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

/// Every problem of `outer` and `holes` as a map with holes (coordinates in
/// input units, scale 1); empty if and only if [`crate::Map::from_rings`]
/// accepts them.
///
/// Each ring is checked as [`validate_all`] checks one (a hole's problems
/// come as [`MapError::InHole`]); then, if every ring is valid, that no two
/// rings meet ([`MapError::RingsMeet`]: crossing, touching or overlapping
/// edges, a shared vertex), that every hole lies inside the outer ring
/// ([`MapError::HoleOutside`]) and that no hole lies inside another
/// ([`MapError::HoleInHole`]).
pub fn validate_rings(outer: &[Point], holes: &[Vec<Point>]) -> Vec<MapError> {
    validate_scaled_rings(outer, holes, &Integer::from(1))
}

pub(crate) fn validate_scaled_rings(
    outer: &[Point],
    holes: &[Vec<Point>],
    scale: &Integer,
) -> Vec<MapError> {
    let mut errors = validate_scaled(outer, scale);
    for (k, hole) in holes.iter().enumerate() {
        errors.extend(
            validate_scaled(hole, scale)
                .into_iter()
                .map(|error| MapError::InHole {
                    hole: k,
                    error: Box::new(error),
                }),
        );
    }
    if !errors.is_empty() || holes.is_empty() {
        return errors;
    }
    // Every edge of every ring, named by its ring and input position.
    let rings: Vec<(Ring, &[Point])> = std::iter::once((Ring::Outer, outer))
        .chain(
            holes
                .iter()
                .enumerate()
                .map(|(k, h)| (Ring::Hole(k), h.as_slice())),
        )
        .collect();
    let edges: Vec<(Ring, usize, Segment)> = rings
        .iter()
        .flat_map(|&(ring, pts)| {
            (0..pts.len()).map(move |i| {
                let s = Segment::new(pts[i], pts[(i + 1) % pts.len()]).expect("a valid ring");
                (ring, i, s)
            })
        })
        .collect();
    let segments: Vec<Segment> = edges.iter().map(|e| e.2).collect();
    let mut meetings = Vec::new();
    sweep_pairs(&segments, |a, b| {
        let (ea, eb) = (&edges[a], &edges[b]);
        if ea.0 == eb.0 {
            return;
        }
        let hit = classify_segments(&ea.2, &eb.2);
        let (kind, at) = match hit {
            SegmentIntersection::None => return,
            SegmentIntersection::Crossing => {
                let p = construct_intersection(&ea.2.line(), &eb.2.line())
                    .expect("crossing segments are not parallel");
                (IntersectionKind::Crossing, rat_position(&p, scale))
            }
            SegmentIntersection::Touching { at } => {
                (IntersectionKind::Touching, position(at, scale))
            }
            SegmentIntersection::Overlap { start, .. } => {
                (IntersectionKind::Overlap, position(start, scale))
            }
        };
        let (first, second) = if (ea.0, ea.1) <= (eb.0, eb.1) {
            (ea, eb)
        } else {
            (eb, ea)
        };
        meetings.push(MapError::RingsMeet {
            ring_a: first.0,
            edge_a: first.1,
            ring_b: second.0,
            edge_b: second.1,
            kind,
            at,
        });
    });
    if !meetings.is_empty() {
        meetings.sort_by_key(|e| match e {
            MapError::RingsMeet {
                ring_a,
                edge_a,
                ring_b,
                edge_b,
                ..
            } => (*ring_a, *edge_a, *ring_b, *edge_b),
            _ => unreachable!("only meetings"),
        });
        return meetings;
    }
    // No two rings meet, so each hole lies wholly inside or wholly outside
    // any other ring, and one vertex decides which.
    let bbox = |pts: &[Point]| {
        let xs = pts.iter().map(|p| p.x);
        let ys = pts.iter().map(|p| p.y);
        (
            xs.clone().min().unwrap_or(0),
            ys.clone().min().unwrap_or(0),
            xs.max().unwrap_or(0),
            ys.max().unwrap_or(0),
        )
    };
    let boxes: Vec<_> = holes.iter().map(|h| bbox(h)).collect();
    let inside = |p: Point, k: usize| {
        let (x0, y0, x1, y1) = boxes[k];
        (x0..=x1).contains(&p.x)
            && (y0..=y1).contains(&p.y)
            && locate(&holes[k], p) == Containment::Inside
    };
    for (k, hole) in holes.iter().enumerate() {
        if locate(outer, hole[0]) != Containment::Inside {
            errors.push(MapError::HoleOutside {
                hole: k,
                at: position(hole[0], scale),
            });
            continue;
        }
        if let Some(j) = (0..holes.len()).find(|&j| j != k && inside(hole[0], j)) {
            errors.push(MapError::HoleInHole { inner: k, outer: j });
        }
    }
    errors
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
    let segments: Vec<Segment> = edges.iter().map(|e| e.1).collect();
    let mut found = Vec::new();
    sweep_pairs(&segments, |i, j| {
        let (lo, hi) = (i.min(j), i.max(j));
        let adjacent = hi == lo + 1 || (lo == 0 && hi == m - 1);
        let hit = classify_segments(&edges[lo].1, &edges[hi].1);
        let kind = match hit {
            SegmentIntersection::None => return,
            // Consecutive edges meet at their common vertex; anything
            // more is a fold.
            SegmentIntersection::Touching { .. } if adjacent && m > 2 => return,
            SegmentIntersection::Crossing => IntersectionKind::Crossing,
            SegmentIntersection::Touching { .. } => IntersectionKind::Touching,
            SegmentIntersection::Overlap { .. } => IntersectionKind::Overlap,
        };
        found.push((lo, hi, kind, hit));
    });
    found.sort_by_key(|&(a, b, _, _)| (a, b));
    found
}

/// Every pair of `segments` (indices) whose x-extents overlap, each once,
/// found by a sweep: O(m log m + k) for segments short compared with their
/// spread, O(m²) at worst.
fn sweep_pairs(segments: &[Segment], mut visit: impl FnMut(usize, usize)) {
    let xmin = |s: &Segment| s.a().x.min(s.b().x);
    let xmax = |s: &Segment| s.a().x.max(s.b().x);
    let mut order: Vec<usize> = (0..segments.len()).collect();
    order.sort_by_key(|&k| xmin(&segments[k]));
    for (pos, &i) in order.iter().enumerate() {
        let si = &segments[i];
        for &j in &order[pos + 1..] {
            if xmin(&segments[j]) > xmax(si) {
                break;
            }
            visit(i, j);
        }
    }
}
