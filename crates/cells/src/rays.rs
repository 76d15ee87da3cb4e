//! Visibility rays (Def 3.8), exactly.

use crate::small::SmallCoords;
use rayon::prelude::*;
use rug::Integer;
use std::cmp::Ordering;
use std::collections::BTreeMap;
use wai_exact::{
    compare_along, compare_intersections_along, construct_intersection, gcd_u128, orientation,
    Line, Orientation, Point, RatPoint, Side,
};
use wai_map::Map;
use wai_visibility::{OnMap, VisibilityIndex};

/// Def 3.8: a **left** or **right** ray, according to whether the map
/// edges incident to the anchor lie to the left or to the right of the
/// directed ray.
///
/// By the boundary assignment of sec. 3.6 the points of the ray belong to
/// the cells on this side: there the anchor obstructs the view of the
/// vertex the ray emanates from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum RaySide {
    Left,
    Right,
}

impl RaySide {
    /// The other side (the side after reflecting the map).
    pub fn flipped(self) -> RaySide {
        match self {
            RaySide::Left => RaySide::Right,
            RaySide::Right => RaySide::Left,
        }
    }

    /// As a [`Side`] of the ray's directed line.
    pub fn as_side(self) -> Side {
        match self {
            RaySide::Left => Side::Left,
            RaySide::Right => Side::Right,
        }
    }
}

/// Where a visibility ray ends: an exact point of the map boundary.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct RayEnd {
    /// The end point, exact (an integer point when `on_map` is a vertex).
    pub point: RatPoint,
    /// At map vertex `i`, or in the relative interior of map edge `i`.
    pub on_map: OnMap,
}

/// Def 3.8: the visibility ray emanating from map vertex `from` (v) and
/// anchored at the reflex map vertex `anchor` (v_r).
///
/// It is the segment from `v_r` to [`VisibilityRay::end`] on the line
/// through `v` and `v_r`, moving away from `v`. Its relative interior lies
/// in the interior of the map except at the `grazed` vertices (see
/// [`visibility_rays`] for every convention).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct VisibilityRay {
    /// The reflex map vertex v_r the ray starts at.
    pub anchor: usize,
    /// The map vertex v the ray emanates from (visible from or adjacent to
    /// the anchor).
    pub from: usize,
    /// Where the anchor's incident map edges lie.
    pub side: RaySide,
    /// The supporting line, `Line::new(v, v_r)`: through the two map
    /// vertices, directed from `v` towards `v_r`, which is the ray's
    /// direction. We keep the two input points rather than `v_r` and the
    /// derived point `2 v_r − v`, so every predicate on the ray stays within
    /// the bounds of `wai_exact` for lines through input points (the ray is
    /// the part of the line beyond `v_r`, see [`VisibilityRay::start`]).
    pub line: Line,
    /// The exact end point on the map boundary.
    pub end: RayEnd,
    /// Map vertices in the ray's relative interior, in order from the
    /// anchor: reflex vertices whose two incident edges lie strictly on one
    /// side of the line. The ray passes through them.
    pub grazed: Vec<usize>,
}

impl VisibilityRay {
    /// The start point: the anchor v_r (the second point of `line`).
    pub fn start(&self) -> Point {
        self.line.b()
    }

    /// The point v the ray emanates from (the first point of `line`).
    pub fn source(&self) -> Point {
        self.line.a()
    }
}

/// The canonical key of an undirected line through two integer points:
/// `a·x + b·y = c` with `gcd(a, b) = 1` and `(a, b)` lexicographically
/// positive (`a > 0`, or `a = 0` and `b > 0`). Equal lines have equal keys,
/// whatever two points and direction define them.
#[derive(Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct LineKey {
    a: i128,
    b: i128,
    c: Integer,
}

impl LineKey {
    /// The key of the line through `line.a()` and `line.b()`.
    ///
    /// Coordinates below `2^MAX_COORD_BITS = 2^100` give `|a|, |b| < 2^101`,
    /// which fit an `i128`; `c` can reach `2^202` and is a GMP integer.
    pub fn of(line: &Line) -> LineKey {
        let (p, q) = (line.a(), line.b());
        let (mut a, mut b) = (q.y - p.y, p.x - q.x);
        let g = gcd_u128(a.unsigned_abs(), b.unsigned_abs());
        let g = i128::try_from(g).expect("a coordinate difference fits an i128");
        a /= g;
        b /= g;
        if a < 0 || (a == 0 && b < 0) {
            a = -a;
            b = -b;
        }
        let c = Integer::from(a) * p.x + Integer::from(b) * p.y;
        LineKey { a, b, c }
    }

    /// The coefficient of x.
    pub fn a(&self) -> i128 {
        self.a
    }

    /// The coefficient of y.
    pub fn b(&self) -> i128 {
        self.b
    }

    /// The constant: points of the line satisfy `a·x + b·y = c`.
    pub fn c(&self) -> &Integer {
        &self.c
    }

    /// Whether the integer point `p` lies on the line.
    pub fn contains(&self, p: Point) -> bool {
        Integer::from(self.a) * p.x + Integer::from(self.b) * p.y == self.c
    }
}

/// Edge case (c): the rays grouped by supporting line, for the arrangement
/// to merge rays that overlap.
///
/// Keys are [`LineKey`]s (undirected: rays on one line may point either
/// way); each group lists indices into `rays`, ascending. Groups with one
/// ray are included.
pub fn group_by_line(rays: &[VisibilityRay]) -> BTreeMap<LineKey, Vec<usize>> {
    let mut groups: BTreeMap<LineKey, Vec<usize>> = BTreeMap::new();
    for (i, r) in rays.iter().enumerate() {
        groups.entry(LineKey::of(&r.line)).or_default().push(i);
    }
    groups
}

/// Def 3.8: every visibility ray of `map`, ordered by anchor, then by the
/// vertex it emanates from.
///
/// For every reflex vertex v_r and every vertex v that is adjacent to v_r
/// or visible from it (sec. 2.2: the closed segment meets the boundary only
/// in v and v_r, and runs through the map), the ray is the maximal segment
/// on the line through v and v_r that starts at v_r, moves away from v and
/// whose relative interior lies in the interior of the map, except at
/// grazed vertices.
///
/// # Edge cases
///
/// (a) **No ray when the line leaves the map at v_r.** The exterior angle
/// at a reflex vertex is a convex cone `E` of less than 180°, spanned by
/// the directions to its two neighbours. The ray exists exactly when its
/// direction `d = v_r − v` lies outside the closed cone `E`; otherwise the
/// segment in the map from v_r in direction `d` has length zero and is
/// skipped. For an adjacent v this never happens: `d` extends an incident
/// edge, and at a reflex vertex both extensions point into the interior.
/// For a visible v it happens when v lies in the opposite cone `v_r − E`:
/// the view from v passes v_r on the outside of the corner, where nothing
/// is obstructed. On the boundary of `E` the direction runs along an
/// incident edge (v, v_r and a neighbour of v_r are collinear, v_r between):
/// that "ray" would lie on the boundary, which holds no viewpoint, so it
/// is skipped too.
///
/// (b) **Grazing continues; exiting or running along an edge ends.** At a
/// map vertex u on the ray beyond v_r:
/// - both incident edges strictly on one side of the line: u is *grazed*.
///   The small wedge between them excludes both directions of the line,
///   and the ray arrives from the interior, so it continues into the
///   interior; the map lies on both sides of the ray before and after u,
///   so the ray still separates cells there. u is recorded in
///   [`VisibilityRay::grazed`].
/// - incident edges strictly on opposite sides: the line crosses the
///   boundary at u; the ray ends at u.
/// - an incident edge on the line: the ray ends at u, the first point where
///   it touches that edge. (The edge lies ahead: the part behind u is in the
///   interior.) Beyond u the line runs along the boundary, which holds no
///   viewpoint (the thesis assumes viewpoints off ∂M) and is already a map
///   edge of the arrangement. Where the line re-enters the interior at the
///   far end w' of the collinear edge, w' is reflex (the interior wedge at
///   w' contains the continuation), so the edge-extension ray emanating
///   from the edge's other end and anchored at w' lies on the same line and
///   covers the continuation: stopping loses no separating segment.
///
/// A crossing of an edge's relative interior ends the ray there.
///
/// (c) **Collinear rays are all kept.** When v, v_r and v_r' are collinear,
/// the ray from v anchored at v_r may graze v_r' and overlap the ray from
/// v_r anchored at v_r'. Both are returned; [`group_by_line`] groups them
/// for the arrangement, which merges overlaps.
///
/// (d) **Ends at a vertex.** An end at map vertex i is reported as
/// `OnMap::Vertex(i)` with the integer point, never as the end of an edge.
///
/// ```
/// use wai_cells::{visibility_rays, OnMap, RaySide, VisibilityRay};
/// use wai_exact::{Point, RatPoint};
/// use wai_map::Map;
/// let map = |pts: &[(i128, i128)]| {
///     Map::from_ring(pts.iter().map(|&(x, y)| Point::new(x, y)).collect()).unwrap().0
/// };
/// let ray = |rays: &[VisibilityRay], anchor: usize, from: usize| {
///     rays.iter().find(|r| (r.anchor, r.from) == (anchor, from)).cloned()
/// };
/// // An L room; vertex 3 = (2, 2) is reflex.
/// let l = map(&[(0, 0), (4, 0), (4, 2), (2, 2), (2, 4), (0, 4)]);
/// let rays = visibility_rays(&l);
/// assert_eq!(rays.len(), 4);
/// // (a) (0, 0) sees (2, 2), but the line leaves the room there: no ray.
/// assert!(ray(&rays, 3, 0).is_none());
/// // (d) from (4, 0) through (2, 2) to the corner (0, 4), vertex 5.
/// let r = ray(&rays, 3, 1).unwrap();
/// assert_eq!((r.end.on_map, r.side), (OnMap::Vertex(5), RaySide::Right));
///
/// // (b) A corridor over one niche [4, 6] × [-4, 0]: the extension of the
/// // wall y = 0 crosses the niche's mouth and ends at (6, 0), where the
/// // wall resumes; the reverse direction runs along the wall: no ray.
/// let c = map(&[(0, 0), (4, 0), (4, -4), (6, -4), (6, 0), (10, 0), (10, 4), (0, 4)]);
/// let rays = visibility_rays(&c);
/// assert_eq!(rays.len(), 8);
/// assert_eq!(ray(&rays, 1, 0).unwrap().end.on_map, OnMap::Vertex(4));
/// assert!(ray(&rays, 1, 4).is_none());
///
/// // (b), (c) Three blocks hang from the ceiling of a 12 × 12 room; their
/// // lower-left corners (2, 6), (4, 4), (6, 2) lie on x + y = 8. The ray
/// // from (2, 6) anchored at (4, 4) grazes (6, 2) and ends on the floor.
/// let g = map(&[
///     (0, 0), (12, 0), (12, 12), (7, 12), (7, 2), (6, 2), (6, 12), (5, 12),
///     (5, 4), (4, 4), (4, 12), (3, 12), (3, 6), (2, 6), (2, 12), (0, 12),
/// ]);
/// let rays = visibility_rays(&g);
/// let r = ray(&rays, 9, 13).unwrap();
/// assert_eq!(r.grazed, vec![5]);
/// assert_eq!(r.end.point, RatPoint::from(Point::new(8, 0)));
/// assert_eq!(r.end.on_map, OnMap::Edge(0));
/// // (c) The ray from (4, 4) anchored at (6, 2) overlaps it; both are kept.
/// assert!(ray(&rays, 5, 9).is_some());
/// ```
///
/// # Complexity
/// One visibility query per reflex vertex
/// ([`VisibilityIndex::vertex_view`], triangular expansion) names the
/// vertices it sees; then `O(n)` predicates per such pair (the exact
/// visibility check and the shot): `O(n · R)` for `R` rays instead of a scan
/// of all `r · n` pairs. Orientations take the `i128` fast path below
/// `2^ORIENTATION_FAST_BITS`, the comparisons of crossings along the ray
/// below `2^INTERSECTION_FAST_BITS`; GMP beyond, and to construct end
/// points in the relative interior of edges. A 76-vertex map with 54
/// reflex vertices takes well under a millisecond (release build).
pub fn visibility_rays(map: &Map) -> Vec<VisibilityRay> {
    let v = map.vertices();
    let n = v.len();
    let index = VisibilityIndex::new(map);
    let small = SmallCoords::of(map);
    let at = Vertices {
        v,
        map,
        small: small.as_ref(),
    };
    // Each reflex vertex's rays on their own (in parallel), in order.
    let by_vertex: Vec<Vec<VisibilityRay>> = map
        .reflex_vertices()
        .par_iter()
        .map_init(
            || vec![Side::On; n],
            |sides, &a| rays_from(at, &index, sides, a),
        )
        .collect();
    by_vertex.concat()
}

/// The map's vertices, with their `i64` coordinates when they fit
/// ([`crate::small`]).
#[derive(Clone, Copy)]
struct Vertices<'a> {
    v: &'a [Point],
    /// For the rings: edge `k` runs from `k` to `map.next(k)`.
    map: &'a Map,
    small: Option<&'a SmallCoords>,
}

impl Vertices<'_> {
    /// The vertex after `k` along its ring.
    #[inline]
    fn next(&self, k: usize) -> usize {
        self.map.next(k)
    }

    /// The vertex before `k` along its ring.
    #[inline]
    fn prev(&self, k: usize) -> usize {
        self.map.prev(k)
    }

    /// The orientation of vertices `(a, b, c)`: exact either way.
    #[inline]
    fn orientation(&self, a: usize, b: usize, c: usize) -> Orientation {
        match self.small {
            Some(s) => s.orientation(a, b, c),
            None => orientation(self.v[a], self.v[b], self.v[c]),
        }
    }

    /// `sides[k]`: the side of vertex `k` of the line directed from vertex
    /// `j` to vertex `a`, for every `k`.
    fn sides(&self, j: usize, a: usize, sides: &mut [Side]) {
        match self.small {
            Some(s) => s.sides(j, a, sides),
            None => {
                for (side, &c) in sides.iter_mut().zip(self.v) {
                    *side = orientation(self.v[j], self.v[a], c).into();
                }
            }
        }
    }

    /// The order along `line` (directed from vertex `j` to vertex `a`) of
    /// its meeting points with edges `k` and `b` (`Less`: edge `k`'s comes
    /// first), both crossing it.
    fn compare_crossings(
        &self,
        line: &Line,
        (j, a): (usize, usize),
        k: usize,
        b: usize,
    ) -> Ordering {
        match self.small {
            Some(s) => s.compare_crossings((j, a), k, b),
            None => {
                let edge = |k: usize| {
                    Line::new(self.v[k], self.v[self.next(k)]).expect("map vertices are distinct")
                };
                compare_intersections_along(line, &edge(k), &edge(b))
                    .expect("crossing edges are not parallel to the ray")
            }
        }
    }
}

/// The visibility rays from reflex vertex `a` (`sides`: a buffer of one
/// entry per map vertex).
fn rays_from(
    at: Vertices<'_>,
    index: &VisibilityIndex,
    sides: &mut [Side],
    a: usize,
) -> Vec<VisibilityRay> {
    let v = at.v;
    let mut rays = Vec::new();
    let (prev, next) = (at.prev(a), at.next(a));
    // The candidates: the vertices v_r sees (its own visibility
    // polygon, one query) and its neighbours. Each is still checked
    // below, so the query only narrows the search.
    let mut candidates: Vec<usize> = index.vertex_view(a).iter().map(|&(lo, _)| lo).collect();
    candidates.extend([prev, next]);
    candidates.sort_unstable();
    candidates.dedup();
    for j in candidates.into_iter().filter(|&j| j != a) {
        // Implementation note: with e1 = v_prev − v_r, e2 = v_next − v_r
        // (cross(e1, e2) > 0 at a reflex vertex of a CCW ring), a
        // direction u is in the closed exterior cone E iff
        // cross(e1, u) ≥ 0 and cross(u, e2) ≥ 0. For u = v_r − v these
        // are o1 ≠ CCW and o2 ≠ CW; for u = v − v_r they are o1 ≠ CW and
        // o2 ≠ CCW.
        let o1 = at.orientation(a, prev, j);
        let o2 = at.orientation(a, next, j);
        use Orientation::{Clockwise as Cw, CounterClockwise as Ccw};
        if o1 != Ccw && o2 != Cw {
            continue; // (a): the ray's direction leaves the map at v_r
        }
        let adjacent = j == prev || j == next;
        if !adjacent && o1 != Cw && o2 != Ccw {
            // The segment from v_r towards v leaves the map at once. If
            // it passes this test and its open part misses the boundary
            // (checked next), it lies in the interior: this local test
            // is what `sees` decides with a midpoint in that case.
            continue;
        }
        let line = Line::new(v[j], v[a]).expect("map vertices are distinct");
        at.sides(j, a, sides);
        if !adjacent && !visible(at, &line, sides, a, j) {
            continue; // v is not visible from v_r
        }
        rays.push(shoot(at, line, sides, a, j));
    }
    rays
}

fn opposite(s: Side, t: Side) -> bool {
    matches!(
        (s, t),
        (Side::Left, Side::Right) | (Side::Right, Side::Left)
    )
}

/// Whether the open segment between vertices `j` and `a` misses the
/// boundary, given the side of every vertex of the line through them
/// (`sides`).
fn visible(at: Vertices<'_>, line: &Line, sides: &[Side], a: usize, j: usize) -> bool {
    let v = at.v;
    let n = v.len();
    // A vertex strictly between blocks (grazing blocks, sec. 2.2); this also
    // covers every map edge collinear with the segment that overlaps it.
    let between = |k: usize| {
        k != a
            && k != j
            && compare_along(line, v[j], v[k]) == Ordering::Less
            && compare_along(line, v[k], v[a]) == Ordering::Less
    };
    // Edge k0 → k1 with endpoints strictly on opposite sides crosses the
    // open segment iff v[j] and v[a] lie strictly on opposite sides of it.
    let crosses = |k0: usize, k1: usize| {
        opposite(sides[k0], sides[k1])
            && opposite(
                at.orientation(k0, k1, j).into(),
                at.orientation(k0, k1, a).into(),
            )
    };
    !(0..n).any(|k| (sides[k] == Side::On && between(k)) || crosses(k, at.next(k)))
}

/// For an edge `p → q` whose endpoints lie strictly on opposite sides of a
/// directed line `L` (`q` on side `side_q`), and a point `u` of `L`: whether
/// `u` comes before the meeting point `X` of `L` and the edge.
///
/// Implementation note: `g(x) = cross(q − p, x − p)` is affine along `L`
/// with slope `cross(q − p, d)`, which is positive exactly when `q` is to
/// the right of `L`; `g(X) = 0`, so `u` precedes `X` iff `g(u)` and the
/// slope have opposite signs. `g(u) ≠ 0`: else `u` would be `X`, a map
/// vertex in the relative interior of an edge.
fn before_crossing(at: Vertices<'_>, p: usize, q: usize, side_q: Side, u: usize) -> bool {
    (at.orientation(p, q, u) == Orientation::Clockwise) == (side_q == Side::Right)
}

/// Shoot the ray from `v[a]` along `line` (directed from `v[j]` to `v[a]`).
fn shoot(at: Vertices<'_>, line: Line, sides: &[Side], a: usize, j: usize) -> VisibilityRay {
    let v = at.v;
    let n = v.len();
    let edge_line = |k: usize| Line::new(v[k], v[at.next(k)]).expect("map vertices are distinct");
    // The nearest crossing of an edge's relative interior beyond v_r.
    let mut nearest: Option<usize> = None;
    for k in 0..n {
        let k1 = at.next(k);
        if !opposite(sides[k], sides[k1]) || !before_crossing(at, k, k1, sides[k1], a) {
            continue;
        }
        let closer = match nearest {
            None => true,
            Some(b) => at.compare_crossings(&line, (j, a), k, b) == Ordering::Less,
        };
        if closer {
            nearest = Some(k);
        }
    }
    // The map vertices on the ray beyond v_r and before that crossing.
    let mut on_ray: Vec<usize> = Vec::new();
    for (u, &s) in sides.iter().enumerate() {
        if s == Side::On
            && compare_along(&line, v[a], v[u]) == Ordering::Less
            && nearest.is_none_or(|k| before_crossing(at, k, at.next(k), sides[at.next(k)], u))
        {
            on_ray.push(u);
        }
    }
    on_ray.sort_by(|&x, &y| compare_along(&line, v[x], v[y]));
    let mut grazed = Vec::new();
    let mut end = None;
    for u in on_ray {
        let (sp, sn) = (sides[at.prev(u)], sides[at.next(u)]);
        if sp != Side::On && sp == sn {
            grazed.push(u); // (b) grazing: the ray continues
        } else {
            // (b) exit through u, or an incident edge on the line ahead.
            end = Some(RayEnd {
                point: RatPoint::from(v[u]),
                on_map: OnMap::Vertex(u),
            });
            break;
        }
    }
    let end = end.unwrap_or_else(|| {
        let k = nearest.expect("a ray inside a bounded polygon meets its boundary");
        RayEnd {
            point: construct_intersection(&line, &edge_line(k))
                .expect("crossing edges are not parallel to the ray"),
            on_map: OnMap::Edge(k),
        }
    });
    let (prev, next) = (at.prev(a), at.next(a));
    let side = match (sides[prev], sides[next]) {
        (Side::Left, Side::Left | Side::On) | (Side::On, Side::Left) => RaySide::Left,
        (Side::Right, Side::Right | Side::On) | (Side::On, Side::Right) => RaySide::Right,
        other => unreachable!("the anchor's edges lie on one side of a ray: {other:?}"),
    };
    VisibilityRay {
        anchor: a,
        from: j,
        side,
        line,
        end,
        grazed,
    }
}
