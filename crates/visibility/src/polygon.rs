//! The visibility polygon V_p and its classification (Defs 3.4–3.6).

use wai_exact::RatPoint;

/// Where a vertex of V_p lies on the boundary of the map.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum OnMap {
    /// At map vertex `i`.
    Vertex(usize),
    /// In the interior of map edge `i` (from vertex `i` to `i + 1`).
    Edge(usize),
}

/// A vertex of V_p.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct VisVertex {
    pub point: RatPoint,
    pub on_map: OnMap,
    /// Def 3.4: the farther endpoint of a spurious edge.
    pub spurious: bool,
}

/// The kind of an edge of V_p (Defs 3.4 and 3.5).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum EdgeKind {
    /// Collinear with the viewpoint (Def 3.4).
    Spurious,
    /// Non-spurious, both endpoints non-spurious.
    Full,
    /// Non-spurious, exactly one endpoint spurious.
    Half,
    /// Non-spurious, both endpoints spurious.
    Partial,
}

/// An edge of V_p, from vertex `i` to vertex `i + 1`.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct VisEdge {
    pub kind: EdgeKind,
    /// The map edge a non-spurious edge lies on. `None` for spurious edges,
    /// which lie on a ray from the viewpoint (possibly along a map edge
    /// collinear with the viewpoint, the case noted after Def 3.4).
    pub map_edge: Option<usize>,
    /// Def 3.6: for a half or partial edge, the V_p indices of its blocking
    /// vertices — the near endpoints of the spurious edges adjacent to its
    /// spurious endpoints — in boundary order. Empty for full and spurious
    /// edges.
    pub blocking: Vec<usize>,
}

/// The visibility polygon V_p of a viewpoint p: the closure of the set of
/// points of the map that p sees, counter-clockwise, with no 180° vertex.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct VisibilityPolygon {
    pub(crate) viewpoint: RatPoint,
    pub(crate) vertices: Vec<VisVertex>,
    pub(crate) edges: Vec<VisEdge>,
}

impl VisibilityPolygon {
    pub fn viewpoint(&self) -> &RatPoint {
        &self.viewpoint
    }
    pub fn vertices(&self) -> &[VisVertex] {
        &self.vertices
    }
    /// Edge `i` runs from vertex `i` to vertex `i + 1 (mod len)`.
    pub fn edges(&self) -> &[VisEdge] {
        &self.edges
    }
    pub fn len(&self) -> usize {
        self.vertices.len()
    }
    pub fn is_empty(&self) -> bool {
        self.vertices.is_empty()
    }
    /// The vertex points, in order.
    pub fn points(&self) -> Vec<RatPoint> {
        self.vertices.iter().map(|v| v.point.clone()).collect()
    }
    /// Assemble a polygon from parts, for tests that plant broken
    /// structures in checkers. Library code builds polygons only through the
    /// visibility algorithms.
    pub fn from_parts(viewpoint: RatPoint, vertices: Vec<VisVertex>, edges: Vec<VisEdge>) -> Self {
        assert_eq!(vertices.len(), edges.len(), "one edge after each vertex");
        VisibilityPolygon {
            viewpoint,
            vertices,
            edges,
        }
    }
}

/// Why no visibility polygon is computed.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum VisibilityError {
    #[error("the viewpoint {0} lies outside the map")]
    Outside(RatPoint),
    #[error("the viewpoint {0} lies on the boundary of the map; only interior viewpoints are supported (the thesis assumes p not on the boundary, sec. 3.4)")]
    OnBoundary(RatPoint),
}
