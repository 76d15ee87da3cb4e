//! The size of an arrangement before it is built, from predicates only.

use crate::arrangement::{bbox, meeting_pairs};
use crate::rays::{LineKey, VisibilityRay};
use wai_exact::{side_of_intersection, side_of_line, Line, Point, Side};
use wai_map::Map;
use wai_visibility::OnMap;

/// An upper bound on the vertices of [`crate::Arrangement::new`]`(map,
/// rays)`: the map vertices, the ray ends in the relative interior of map
/// edges, and one vertex per pair of rays on different lines that cross in
/// the relative interiors of both.
///
/// No intersection point is constructed: whether two segments on
/// non-parallel lines meet is decided by the sides of each one's end points
/// relative to the other's line, and an end in the relative interior of map
/// edge `k` is the meeting point of the ray's line and edge `k`'s line, whose
/// side is [`side_of_intersection`] (the `i128` fast path below
/// `2^INTERSECTION_FAST_BITS`). Pairs are filtered by integer bounding
/// boxes first.
///
/// # Edge cases
/// Several pairs of rays through one point count once each (three or more
/// lines crossing, a grazed map vertex that two rays pass), and collinear
/// rays (merged by the arrangement) meet nothing here: the bound is exact
/// on maps without such points and exceeds the count by their
/// multiplicity otherwise.
///
/// ```
/// use wai_cells::{visibility_rays, vertex_bound, Arrangement};
/// use wai_exact::Point;
/// use wai_map::Map;
/// let ring = [(0, 0), (4, 0), (4, 2), (2, 2), (2, 4), (0, 4)];
/// let map = Map::from_ring(ring.iter().map(|&(x, y)| Point::new(x, y)).collect()).unwrap().0;
/// let rays = visibility_rays(&map);
/// assert_eq!(vertex_bound(&map, &rays), Arrangement::new(&map, &rays).vertex_count() as u64);
/// ```
pub fn vertex_bound(map: &Map, rays: &[VisibilityRay]) -> u64 {
    let v = map.vertices();
    let ends: Vec<End> = rays
        .iter()
        .map(|r| match r.end.on_map {
            OnMap::Vertex(i) => End::Vertex(v[i]),
            OnMap::Edge(k) => End::OnEdge(Line::new(v[k], v[map.next(k)]).expect("distinct")),
        })
        .collect();
    let keys: Vec<LineKey> = rays.iter().map(|r| LineKey::of(&r.line)).collect();
    let boxes: Vec<[i128; 4]> = rays
        .iter()
        .map(|r| {
            // The start is a map vertex: its box is the point itself.
            let (s, e) = (r.start(), bbox([&r.end.point]));
            [e[0].min(s.x), e[1].min(s.y), e[2].max(s.x), e[3].max(s.y)]
        })
        .collect();
    let crossing = meeting_pairs(&boxes, |i, j| {
        (keys[i] != keys[j]
            && straddles(&rays[i].line, &rays[j], &ends[j])
            && straddles(&rays[j].line, &rays[i], &ends[i]))
        .then_some(())
    });
    let on_edges = rays
        .iter()
        .filter(|r| matches!(r.end.on_map, OnMap::Edge(_)))
        .count();
    (v.len() + on_edges + crossing.len()) as u64
}

/// An end of a ray: a map vertex, or the meeting point of the ray's line
/// and a map edge's line.
enum End {
    Vertex(Point),
    OnEdge(Line),
}

/// Whether `ray` (ending at `end`) crosses `line` in its relative interior:
/// its ends lie strictly on opposite sides. A meeting at an end of either
/// ray is at a map vertex or at a ray end inside a map edge, both counted
/// already.
fn straddles(line: &Line, ray: &VisibilityRay, end: &End) -> bool {
    let s = side_of_line(line, ray.start());
    let e = match end {
        End::Vertex(p) => side_of_line(line, *p),
        // The ray crosses edge `k` there, so the two lines are not parallel.
        End::OnEdge(edge) => side_of_intersection(line, &ray.line, edge)
            .expect("a ray ending inside an edge is not parallel to it"),
    };
    matches!(
        (s, e),
        (Side::Left, Side::Right) | (Side::Right, Side::Left)
    )
}
