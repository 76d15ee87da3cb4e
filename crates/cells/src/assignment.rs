//! The boundary assignment of sec. 3.6: which cell owns each point of a
//! visibility ray, so that every point of the map belongs to exactly one
//! cell.

use crate::arrangement::{
    inside_corner, primitive_dir, Arrangement, EdgeGeometry, EdgeId, FaceId, Support, VertexId,
};
use crate::rays::RaySide;
use rayon::prelude::*;
use std::cmp::Ordering;
use wai_exact::Vector;

/// A boundary piece that two rays assign to different cells (reported,
/// never hidden).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Conflict {
    /// The rays covering `edge` disagree: `left` assign it to the face of
    /// half-edge `2 · edge`, `right` to the face of `2 · edge + 1`
    /// (indices into the rays). `owner` is the default chosen: the choice
    /// of the nearest anchor's ray, or of the lowest index when the rays
    /// point both ways (see [`BoundaryAssignment`]). `both_ways`: the rays
    /// point both ways along the edge (a doorway between two anchors), so
    /// the rule has no answer and `owner` is only a default.
    Edge {
        edge: EdgeId,
        left: Vec<usize>,
        right: Vec<usize>,
        owner: FaceId,
        both_ways: bool,
    },
    /// No cell around `vertex` lies on the assigned side of every ray
    /// through it (`rays`: those with the vertex in their relative
    /// interior).
    Vertex { vertex: VertexId, rays: Vec<usize> },
}

/// Sec. 3.6, applied to every edge and vertex of an [`Arrangement`].
///
/// # Edge cases
/// - **Edges on rays** (the thesis's rule): a point on the visibility ray
///   emanating from v and anchored at v_r belongs to the cell on the side
///   where the obstruction determined by the anchor lies — the ray's
///   [`RaySide`] — so that v is not visible from it. An edge covered by
///   several collinear rays gets the side of each; if they differ, the edge
///   is a [`Conflict::Edge`]. If they all point the same way along the edge
///   (one runs on through another's anchor), the ray whose anchor is
///   nearest behind the edge decides: the last obstruction passed, which is
///   the one that hides its vertex from the points beyond. If they point both
///   ways (a doorway between two anchors on one line), no side is right —
///   the edge's points have a skeleton of their own, a one-dimensional cell
///   (`counterexamples/T3.3b-doorway-1d-cell.json`) — and the lowest ray
///   index decides.
/// - **Edges on the map boundary**: the thesis assumes viewpoints off ∂M;
///   so that every point of the closed map has a cell, such an edge belongs
///   to its one incident cell.
/// - **Vertices** (our rule; the thesis does not state one): a vertex
///   belongs to the incident cell that lies on the assigned side of every
///   ray through the vertex (a ray with the vertex in its relative
///   interior: rays starting or ending at a vertex do not constrain it —
///   the anchor's own rays point to both sides of it). This is the edge
///   rule applied to the vertex as a point of each ray through it: v is
///   hidden from it by every anchor that hides v from the ray's own
///   points. An interior vertex lies
///   on at least two lines, whose open half-planes through it meet in at
///   most one cell; if they meet in none the vertex is a
///   [`Conflict::Vertex`] and has no owner. When several cells qualify
///   (only on the map boundary, or when few rays pass through), the first
///   counter-clockwise after the exterior (on the boundary) or from the
///   vertex's `out` half-edge wins.
///
/// ```
/// use wai_cells::{visibility_rays, Arrangement};
/// use wai_exact::Point;
/// use wai_map::Map;
/// // The L room: no two rays overlap, so there is no conflict.
/// let ring = [(0, 0), (4, 0), (4, 2), (2, 2), (2, 4), (0, 4)];
/// let map = Map::from_ring(ring.iter().map(|&(x, y)| Point::new(x, y)).collect()).unwrap().0;
/// let arr = Arrangement::new(&map, &visibility_rays(&map));
/// assert!(arr.conflicts().is_empty());
/// assert!((0..arr.vertex_count()).all(|v| arr.owner_of_vertex(v).is_some()));
/// ```
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct BoundaryAssignment {
    pub(crate) edge_owner: Vec<FaceId>,
    pub(crate) vertex_owner: Vec<Option<FaceId>>,
    pub(crate) conflicts: Vec<Conflict>,
}

impl BoundaryAssignment {
    /// The owner of each edge, by edge index.
    pub fn edge_owners(&self) -> &[FaceId] {
        &self.edge_owner
    }
    /// The owner of each vertex, by vertex index.
    pub fn vertex_owners(&self) -> &[Option<FaceId>] {
        &self.vertex_owner
    }
    pub fn conflicts(&self) -> &[Conflict] {
        &self.conflicts
    }
}

/// If every ray in `rays` points the same way along the edge's line (by
/// `forward`, per ray), the one whose anchor is nearest behind the edge:
/// the last obstruction the rays pass before reaching it. `None` if the
/// rays point both ways.
fn nearest_anchor_ray(arr: &Arrangement, rays: &[usize], forward: &[bool]) -> Option<usize> {
    let first = *rays.first()?;
    if rays.iter().any(|&r| forward[r] != forward[first]) {
        return None;
    }
    // All rays share the supporting line and direction: compare anchors
    // along it; the greatest comes last before the edge.
    let line = arr.rays[first].line;
    rays.iter().copied().max_by(|&a, &b| {
        let (pa, pb) = (arr.rays[a].start(), arr.rays[b].start());
        wai_exact::compare_along(&line, pa, pb).then(b.cmp(&a))
    })
}

pub(crate) fn assign(arr: &Arrangement) -> BoundaryAssignment {
    // By ray: its primitive direction, and whether it points along its
    // group's direction.
    let ray_dir: Vec<Vector> = arr.rays.iter().map(|r| primitive_dir(&r.line)).collect();
    let mut forward = vec![false; arr.rays.len()];
    for g in &arr.groups {
        for &r in &g.rays {
            forward[r] = ray_dir[r].dot_sign(g.dir) == Ordering::Greater;
        }
    }
    // Each edge and each vertex on its own (in parallel), in index order.
    let by_edge: Vec<(FaceId, Option<Conflict>)> = arr
        .edges
        .par_iter()
        .enumerate()
        .map(|(e, geom)| edge_owner(arr, e, geom, &forward))
        .collect();
    let by_vertex: Vec<(Option<FaceId>, Option<Conflict>)> = (0..arr.vertices.len())
        .into_par_iter()
        .map_init(VertexScratch::default, |s, v| {
            vertex_owner(arr, v, &ray_dir, s)
        })
        .collect();
    let mut conflicts = Vec::new();
    let mut edge_owner = Vec::with_capacity(by_edge.len());
    for (owner, conflict) in by_edge {
        edge_owner.push(owner);
        conflicts.extend(conflict);
    }
    let mut vertex_owner = Vec::with_capacity(by_vertex.len());
    for (owner, conflict) in by_vertex {
        vertex_owner.push(owner);
        conflicts.extend(conflict);
    }
    BoundaryAssignment {
        edge_owner,
        vertex_owner,
        conflicts,
    }
}

/// The cell that owns edge `e` (sec. 3.6), and the conflict if rays on
/// both sides cover it.
fn edge_owner(
    arr: &Arrangement,
    e: usize,
    geom: &EdgeGeometry,
    forward: &[bool],
) -> (FaceId, Option<Conflict>) {
    let (f0, f1) = (arr.half_edges[2 * e].face, arr.half_edges[2 * e + 1].face);
    match geom.support {
        Support::MapEdge(_) => (if arr.is_cell(f0) { f0 } else { f1 }, None),
        Support::Rays(_) => {
            let rays = arr.edge_rays(e);
            // Half-edge 2e points along `dir`; its face is on its left.
            let to_left = |r: usize| (arr.rays[r].side == RaySide::Left) == forward[r];
            // The first ray assigning the edge to each side (the lists of
            // a conflict are built only when there is one).
            let left0 = rays.iter().copied().find(|&r| to_left(r));
            let right0 = rays.iter().copied().find(|&r| !to_left(r));
            let nearest = nearest_anchor_ray(arr, rays, forward);
            let owner = match nearest {
                // One way along the edge: the last obstruction passed
                // decides (its anchor is nearest behind the edge).
                Some(r) if to_left(r) => f0,
                Some(_) => f1,
                // Both ways (a doorway between two anchors): no side is
                // right (a one-dimensional cell); the lowest index
                // decides, and the conflict is reported.
                None => match (left0, right0) {
                    (_, None) => f0,
                    (Some(l), Some(r)) if l < r => f0,
                    _ => f1,
                },
            };
            let conflict = (left0.is_some() && right0.is_some()).then(|| {
                let (left, right) = rays.iter().partition(|&&r| to_left(r));
                Conflict::Edge {
                    edge: e,
                    left,
                    right,
                    owner,
                    both_ways: nearest.is_none(),
                }
            });
            (owner, conflict)
        }
    }
}

/// The working lists of [`vertex_owner`], reused from vertex to vertex.
#[derive(Default)]
struct VertexScratch {
    out: Vec<usize>,
    through: Vec<usize>,
    seen: Vec<usize>,
}

/// The cell that owns vertex `v` (sec. 3.6): the first cell around `v`,
/// counter-clockwise after the exterior, that lies on the ray's side
/// ([`crate::VisibilityRay::side`]) of every ray through `v`; `None` and
/// the conflict if none does.
fn vertex_owner(
    arr: &Arrangement,
    v: usize,
    ray_dir: &[Vector],
    scratch: &mut VertexScratch,
) -> (Option<FaceId>, Option<Conflict>) {
    let VertexScratch { out, through, seen } = scratch;
    arr.outgoing_into(v, out);
    // Rays through v: those covering two edges at v.
    through.clear();
    seen.clear();
    for &h in out.iter() {
        for &r in arr.edge_rays(h / 2) {
            if seen.contains(&r) {
                through.push(r);
            } else {
                seen.push(r);
            }
        }
    }
    through.sort_unstable();
    // The cells around v, counter-clockwise, starting after the exterior
    // (or the hole) if v is on it.
    let k = out.len();
    let start = (0..k)
        .find(|&i| !arr.is_cell(arr.half_edges[out[i]].face))
        .map_or(0, |i| i + 1);
    for i in (0..k).map(|i| (start + i) % k) {
        let f = arr.half_edges[out[i]].face;
        if !arr.is_cell(f) {
            continue;
        }
        let w = inside_corner(arr.direction(out[i]), arr.direction(out[(i + 1) % k]));
        let fits = through.iter().all(|&r| {
            let side = match ray_dir[r].cross_sign(w) {
                Ordering::Greater => Some(RaySide::Left),
                Ordering::Less => Some(RaySide::Right),
                Ordering::Equal => None,
            };
            side == Some(arr.rays[r].side)
        });
        if fits {
            return (Some(f), None);
        }
    }
    let conflict = Conflict::Vertex {
        vertex: v,
        rays: through.clone(),
    };
    (None, Some(conflict))
}
