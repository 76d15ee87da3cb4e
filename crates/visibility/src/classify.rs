//! From the raw boundary of V_p to its classification (Defs 3.4–3.6).

use crate::polygon::{EdgeKind, OnMap, VisEdge, VisVertex, VisibilityPolygon};
use wai_exact::RatPoint;

/// What the boundary of V_p runs along after a vertex.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Along {
    /// A ray from the viewpoint: a spurious edge.
    Ray,
    /// Map edge `i`.
    MapEdge(usize),
}

/// A vertex of V_p before classification.
#[derive(Clone, Debug)]
pub(crate) struct RawVertex {
    pub point: RatPoint,
    pub on_map: OnMap,
    /// For the two endpoints of a ray edge: whether this one is the farther.
    pub far_end_of_ray: bool,
    pub after: Along,
}

/// Classify the boundary `raw` of V_p (counter-clockwise, each vertex with
/// what the boundary runs along after it).
///
/// The vertex list starts at the lexicographically least vertex (least x,
/// then least y), so every algorithm yields the same sequence.
pub(crate) fn classify(viewpoint: RatPoint, mut raw: Vec<RawVertex>) -> VisibilityPolygon {
    let n = raw.len();
    if let Some(start) = (0..n).min_by(|&i, &j| lexicographic(&raw[i].point, &raw[j].point)) {
        raw.rotate_left(start);
    }
    let vertices: Vec<VisVertex> = raw
        .iter()
        .map(|r| VisVertex {
            point: r.point.clone(),
            on_map: r.on_map,
            spurious: r.far_end_of_ray,
        })
        .collect();
    let edges = (0..n)
        .map(|i| {
            let j = (i + 1) % n;
            match raw[i].after {
                Along::Ray => VisEdge {
                    kind: EdgeKind::Spurious,
                    map_edge: None,
                    blocking: Vec::new(),
                },
                Along::MapEdge(e) => {
                    let (si, sj) = (vertices[i].spurious, vertices[j].spurious);
                    let kind = match (si, sj) {
                        (false, false) => EdgeKind::Full,
                        (true, true) => EdgeKind::Partial,
                        _ => EdgeKind::Half,
                    };
                    // Def 3.6: the spurious endpoint's other edge is the
                    // spurious edge; its near endpoint blocks.
                    let mut blocking = Vec::new();
                    if si {
                        blocking.push((i + n - 1) % n);
                    }
                    if sj {
                        blocking.push((j + 1) % n);
                    }
                    VisEdge {
                        kind,
                        map_edge: Some(e),
                        blocking,
                    }
                }
            }
        })
        .collect();
    VisibilityPolygon {
        viewpoint,
        vertices,
        edges,
    }
}

/// Compare exact points by x, then y.
pub(crate) fn lexicographic(a: &RatPoint, b: &RatPoint) -> std::cmp::Ordering {
    use rug::Integer;
    let c = |x: &Integer, wx: &Integer, y: &Integer, wy: &Integer| {
        Integer::from(x * wy).cmp(&Integer::from(y * wx))
    };
    c(a.hx(), a.hw(), b.hx(), b.hw()).then_with(|| c(a.hy(), a.hw(), b.hy(), b.hw()))
}
