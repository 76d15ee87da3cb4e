//! The exact arrangement of the map edges and the visibility rays (Def 3.8)
//! as a half-edge structure.
//!
//! Topology apart from geometry: [`Vertex`], [`HalfEdge`] and
//! [`Face`] hold indices only; each vertex's exact point, each edge's
//! supporting segment ([`Support`]) and the rays covering it are attached
//! by index.

use crate::assignment::{assign, BoundaryAssignment, Conflict};
use crate::eye::{mul, small_of, Eye, PointRef};
use crate::fx::HashChains;
use crate::rays::{group_by_line, LineKey, VisibilityRay};
use crate::small::{SmallCoords, Span};
use rayon::prelude::*;
use rug::{Integer, Rational};
use std::cmp::Ordering;
use std::sync::OnceLock;
use wai_exact::{
    construct_intersection, construct_intersection_i128, gcd_u128, orientation, orientation_rat,
    Line, Orientation, RatPoint, Vector,
};
use wai_map::Map;
use wai_visibility::OnMap;

/// Index of a vertex of an [`Arrangement`]; map vertex `i` is vertex `i`.
pub type VertexId = usize;
/// Index of a half-edge; the two halves of edge `e` are `2e` and `2e + 1`.
pub type HalfEdgeId = usize;
/// Index of an (undirected) edge: half-edges `2e` and `2e + 1`.
pub type EdgeId = usize;
/// Index of a face; [`Arrangement::outer_face`] is the exterior of the map.
pub type FaceId = usize;

/// Topology of a vertex: one outgoing half-edge.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Vertex {
    pub out: HalfEdgeId,
}

/// Topology of a half-edge. Its face lies to its left; `next` continues
/// the boundary of that face counter-clockwise (clockwise for the outer
/// face, which lies outside the map).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct HalfEdge {
    pub origin: VertexId,
    pub twin: HalfEdgeId,
    pub next: HalfEdgeId,
    pub prev: HalfEdgeId,
    pub face: FaceId,
}

/// Topology of a face: one half-edge of its (only) boundary cycle.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Face {
    pub outer: HalfEdgeId,
}

/// The segment an edge lies on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Support {
    /// Map edge `i` (from map vertex `i` to `i + 1`).
    MapEdge(usize),
    /// Ray group `g` (see [`Arrangement::ray_group`]): rays on one line.
    Rays(usize),
}

/// The visibility rays on one line, merged (edge case (c) of
/// [`crate::visibility_rays`]).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RayGroup {
    /// The line.
    pub key: LineKey,
    /// Indices into the rays, ascending.
    pub rays: Vec<usize>,
    /// The group's direction: the primitive integer direction of its first
    /// ray. Half-edge `2e` of each of its edges points this way.
    pub dir: Vector,
}

/// Geometry of an edge, by index.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct EdgeGeometry {
    pub support: Support,
    /// Where in the arrangement's list of edge rays
    /// ([`Arrangement::edge_rays`]) the rays (indices into the rays) whose
    /// closed segment contains the edge are; empty for map edges.
    pub rays: std::ops::Range<usize>,
}

/// The exact arrangement of the map edges and all visibility rays: the
/// visibility cell decomposition of Def 3.8, with the boundary assignment
/// of sec. 3.6 ([`Arrangement::owner_of_edge`],
/// [`Arrangement::owner_of_vertex`]).
///
/// Face [`Arrangement::outer_face`] (always 0) is the exterior of the map;
/// on a map with `h` holes, faces `1..=h` are the holes' interiors
/// ([`Arrangement::hole_face`]); every other face is a visibility cell
/// (Thm 3.3: convex; [`Arrangement::cells`], [`Arrangement::is_cell`]).
///
/// With holes the arrangement is still connected, so every face has one
/// boundary cycle: take a connected set of holes that touches no ray to
/// the rest, and a vertex `v` of its convex hull extreme in some direction
/// `w`. `v` is convex as a vertex of its hole, hence reflex in the free
/// space, and the ray extending the hole edge that arrives at `v` has a
/// direction `d` with `w·d > 0`: it leaves the hull at once, never comes
/// back, and ends on the outer ring or another hole — a contradiction.
///
/// # Edge cases
/// - Any number of rays through one point give one vertex (points are
///   deduplicated by exact equality).
/// - Collinear rays are merged per line ([`RayGroup`]): an edge on a line
///   lists every ray covering it ([`Arrangement::edge_rays`]).
/// - A vertex splits every segment through it: a ray end in an edge's
///   relative interior splits that map edge, a grazed map vertex splits the
///   ray through it.
///
/// ```
/// use wai_cells::{visibility_rays, Arrangement};
/// use wai_exact::Point;
/// use wai_map::Map;
/// // The L room: 4 rays from the reflex corner (2, 2) cut it into 5 cells.
/// let ring = [(0, 0), (4, 0), (4, 2), (2, 2), (2, 4), (0, 4)];
/// let map = Map::from_ring(ring.iter().map(|&(x, y)| Point::new(x, y)).collect()).unwrap().0;
/// let rays = visibility_rays(&map);
/// let arr = Arrangement::new(&map, &rays);
/// arr.sanity_check().unwrap();
/// assert_eq!((arr.vertex_count(), arr.edge_count(), arr.face_count()), (8, 12, 6));
/// ```
///
/// # Complexity
/// Intersections are found by testing every pair of rays on different
/// lines (an integer bounding-box filter, then an exact construction): `O(R²)`
/// for `R` rays, plus `O(k log k)` per supporting segment with `k` points.
/// Fine for `R` up to a few thousand; a sweep is a later task.
#[derive(Clone, Debug)]
pub struct Arrangement {
    // Topology.
    pub(crate) vertices: Vec<Vertex>,
    pub(crate) half_edges: Vec<HalfEdge>,
    pub(crate) faces: Vec<Face>,
    // Geometry, by index.
    /// By vertex: its point's homogeneous coordinates as `i128`s, if they
    /// fit (the fast paths start from these).
    pub(crate) small: Vec<Option<[i128; 3]>>,
    /// The points whose coordinates do not fit, by ascending vertex.
    pub(crate) big: BigPoints,
    /// By vertex: its exact point, built when first asked for.
    pub(crate) points: OnceLock<Vec<RatPoint>>,
    pub(crate) on_boundary: Vec<bool>,
    pub(crate) edges: Vec<EdgeGeometry>,
    /// The rays of the edges on rays, edge after edge
    /// ([`EdgeGeometry::rays`]).
    pub(crate) ray_list: Vec<usize>,
    /// By edge: the primitive direction of half-edge 2e.
    pub(crate) dirs: Vec<Vector>,
    pub(crate) groups: Vec<RayGroup>,
    pub(crate) map: Map,
    pub(crate) rays: Vec<VisibilityRay>,
    /// Sec. 3.6, computed when first asked for: the decomposition does not
    /// need it (its lower cells carry their own skeletons), claim A3.6's
    /// checker and the counts do.
    assignment: OnceLock<BoundaryAssignment>,
}

/// The primitive integer direction of `line`.
pub(crate) fn primitive_dir(line: &Line) -> Vector {
    let d = line.b() - line.a();
    let g = gcd_u128(d.x.unsigned_abs(), d.y.unsigned_abs());
    let g = i128::try_from(g).expect("a coordinate difference fits an i128");
    Vector::new(d.x / g, d.y / g)
}

/// A direction strictly inside the corner that runs counter-clockwise from
/// direction `d` to direction `d2` (consecutive edges around a vertex): the
/// sum of the two, negated for a reflex corner, or `d` turned left for a
/// straight one. Primitive directions are below 2^101, so the sums fit.
pub(crate) fn inside_corner(d: Vector, d2: Vector) -> Vector {
    match d.cross_sign(d2) {
        Ordering::Greater => d + d2,
        Ordering::Less => -(d + d2),
        Ordering::Equal => Vector::new(-d.y, d.x),
    }
}

/// `d · p` for a rational point, exactly.
pub(crate) fn along(d: Vector, p: &RatPoint) -> Rational {
    let num = Integer::from(p.hx() * d.x) + Integer::from(p.hy() * d.y);
    Rational::from((num, p.hw().clone()))
}

/// `f(i, j)` for every pair of boxes `[x0, y0, x1, y1]` that meet
/// (closed), in parallel: boxes in order of their left sides, each against
/// those after it until one starts right of its right side. The `Some`
/// results, in that order.
///
/// When every coordinate fits an `i64` (every map below 2^61, so nearly
/// always) the scan compares `i64` copies of the boxes: the same order and
/// the same comparisons, at half the width.
pub(crate) fn meeting_pairs<T: Send>(
    boxes: &[[i128; 4]],
    f: impl Fn(usize, usize) -> Option<T> + Sync,
) -> Vec<T> {
    let mut order: Vec<usize> = (0..boxes.len()).collect();
    order.sort_by_key(|&i| boxes[i][0]);
    let narrow = |b: &[i128; 4]| -> Option<[i64; 4]> {
        Some([
            i64::try_from(b[0]).ok()?,
            i64::try_from(b[1]).ok()?,
            i64::try_from(b[2]).ok()?,
            i64::try_from(b[3]).ok()?,
        ])
    };
    // The boxes in that order, side by side: the scans read them in turn.
    match order
        .iter()
        .map(|&i| narrow(&boxes[i]))
        .collect::<Option<Vec<_>>>()
    {
        Some(sorted) => scan_pairs::<i64, T>(&order, &sorted, &f),
        None => {
            let sorted: Vec<[i128; 4]> = order.iter().map(|&i| boxes[i]).collect();
            scan_pairs::<i128, T>(&order, &sorted, &f)
        }
    }
}

/// The scan of [`meeting_pairs`] over its boxes `sorted` by left side
/// (`order`: their indices).
fn scan_pairs<C: Ord + Copy + Sync, T: Send>(
    order: &[usize],
    sorted: &[[C; 4]],
    f: &(impl Fn(usize, usize) -> Option<T> + Sync),
) -> Vec<T> {
    order
        .par_iter()
        .enumerate()
        .with_min_len(16)
        .flat_map_iter(|(k, &i)| {
            let b = &sorted[k];
            sorted[k + 1..]
                .iter()
                .zip(&order[k + 1..])
                .take_while(move |(c, _)| c[0] <= b[2])
                .filter(move |(c, _)| c[1] <= b[3] && b[1] <= c[3])
                .filter_map(move |(_, &j)| f(i, j))
        })
        .collect()
}

/// Integer bounding box `(xmin, ymin, xmax, ymax)` of rational points
/// (floors and ceilings).
pub(crate) fn bbox<'a>(pts: impl IntoIterator<Item = &'a RatPoint>) -> [i128; 4] {
    let mut b = [i128::MAX, i128::MAX, i128::MIN, i128::MIN];
    for p in pts {
        if let Some([x0, y0, x1, y1]) = small_box(p) {
            b = [b[0].min(x0), b[1].min(y0), b[2].max(x1), b[3].max(y1)];
            continue;
        }
        let fl = |c: &Integer| {
            let (q, _) = c.clone().div_rem_floor(p.hw().clone());
            q.to_i128().expect("map coordinates fit an i128")
        };
        let ce = |c: &Integer| {
            let (q, _) = c.clone().div_rem_ceil(p.hw().clone());
            q.to_i128().expect("map coordinates fit an i128")
        };
        b[0] = b[0].min(fl(p.hx()));
        b[1] = b[1].min(fl(p.hy()));
        b[2] = b[2].max(ce(p.hx()));
        b[3] = b[3].max(ce(p.hy()));
    }
    b
}

/// The integer box of one point whose homogeneous coordinates fit an
/// `i128` (w > 0): floors by `div_euclid`, which rounds down for a
/// positive divisor, and ceilings as minus the floor of the negation.
/// `None` if they do not fit (or a negation would overflow).
fn small_box(p: &RatPoint) -> Option<[i128; 4]> {
    let [x, y, w] = small_of(p)?;
    let (nx, ny) = (x.checked_neg()?, y.checked_neg()?);
    if w == 1 {
        return Some([x, y, x, y]);
    }
    Some([
        x.div_euclid(w),
        y.div_euclid(w),
        -nx.div_euclid(w),
        -ny.div_euclid(w),
    ])
}

pub(crate) fn boxes_meet(a: &[i128; 4], b: &[i128; 4]) -> bool {
    a[0] <= b[2] && b[0] <= a[2] && a[1] <= b[3] && b[1] <= a[3]
}

/// The arrangement's points, each stored once: found again by their
/// `i128` coordinates, or for larger ones by hash and exact equality.
struct Points {
    /// By point: the exact point; `None` for crossings whose coordinates
    /// fit, built in parallel at the end ([`Points::finish`]).
    points: Vec<Option<RatPoint>>,
    /// By point: its homogeneous coordinates as `i128`s, if they fit.
    small: Vec<Option<[i128; 3]>>,
    /// The points whose coordinates fit, by them.
    by_small: SmallTable,
    /// The others, by hash.
    by_hash: HashChains,
}

/// The ids of points whose coordinates fit, by those coordinates: open
/// addressing with linear probing, each slot 8 bytes (the id + 1, 0 when
/// empty, and the high half of the hash), so that the table of a large
/// arrangement stays small enough to be cache-friendly; the coordinates
/// themselves are read from the points' table.
#[derive(Default)]
struct SmallTable {
    slots: Vec<(u32, u32)>,
    len: usize,
}

impl SmallTable {
    fn hash(t: &[i128; 3]) -> u64 {
        let mut h = crate::fx::FxHasher::default();
        for &c in t {
            std::hash::Hasher::write_i128(&mut h, c);
        }
        std::hash::Hasher::finish(&h)
    }

    /// The id filed under `t`, or else `new`, filed now. `small` holds
    /// the coordinates of every id filed.
    fn find_or_file(
        &mut self,
        t: [i128; 3],
        new: VertexId,
        small: &[Option<[i128; 3]>],
    ) -> VertexId {
        if 2 * (self.len + 1) > self.slots.len() {
            self.reserve(2 * self.len + 16, small);
        }
        let h = SmallTable::hash(&t);
        let tag = (h >> 32) as u32;
        let mask = self.slots.len() - 1;
        let mut i = h as usize & mask;
        loop {
            let (g, id) = self.slots[i];
            if id == 0 {
                let id = u32::try_from(new + 1).expect("fewer than 2^32 points");
                self.slots[i] = (tag, id);
                self.len += 1;
                return new;
            }
            if g == tag && small[id as usize - 1] == Some(t) {
                return id as usize - 1;
            }
            i = (i + 1) & mask;
        }
    }

    /// Room for `n` points in all, at most half the slots full.
    fn reserve(&mut self, n: usize, small: &[Option<[i128; 3]>]) {
        let size = (2 * n).next_power_of_two();
        if size <= self.slots.len() {
            return;
        }
        let old = std::mem::replace(&mut self.slots, vec![(0, 0); size]);
        let mask = size - 1;
        for (g, id) in old.into_iter().filter(|&(_, id)| id != 0) {
            let t = small[id as usize - 1].expect("filed points fit");
            let mut i = SmallTable::hash(&t) as usize & mask;
            while self.slots[i].1 != 0 {
                i = (i + 1) & mask;
            }
            self.slots[i] = (g, id);
        }
    }
}

/// The first half of [`Arrangement::assemble`]'s work: the points so far,
/// the group of each ray, its end, each group's points so far, and the
/// pairs of rays (on different lines) that meet, with their points.
struct Found {
    pts: Points,
    group_of: Vec<usize>,
    ends: Vec<VertexId>,
    on_line: Vec<Vec<VertexId>>,
    crossings: Vec<(usize, usize, Meet)>,
}

/// A point as the pairs of rays construct it.
enum Meet {
    /// Its homogeneous coordinates in lowest terms, `w > 0`.
    Small([i128; 3]),
    /// Its exact point, built with GMP.
    Big(RatPoint),
}

impl Points {
    fn new() -> Points {
        Points {
            points: Vec::new(),
            small: Vec::new(),
            by_small: SmallTable::default(),
            by_hash: HashChains::default(),
        }
    }

    fn intern(&mut self, p: RatPoint) -> VertexId {
        match small_of(&p) {
            Some(t) => self.intern_small(t, Some(p)),
            None => self.intern_big(p),
        }
    }

    fn intern_meet(&mut self, m: Meet) -> VertexId {
        match m {
            Meet::Small(t) => self.intern_small(t, None),
            // GMP may have built a point whose coordinates fit.
            Meet::Big(p) => self.intern(p),
        }
    }

    /// A point whose coordinates in lowest terms `t` fit, and the exact
    /// point if it is at hand.
    fn intern_small(&mut self, t: [i128; 3], exact: Option<RatPoint>) -> VertexId {
        let new = self.points.len();
        let id = self.by_small.find_or_file(t, new, &self.small);
        if id == new {
            self.push(exact, Some(t));
        }
        id
    }

    /// The exact point of an interned point that was given as one.
    fn exact(&self, i: VertexId) -> &RatPoint {
        self.points[i].as_ref().expect("interned as an exact point")
    }

    /// By id, the `i128` coordinates; by ascending id, the exact points of
    /// the others.
    fn finish(self) -> (Vec<Option<[i128; 3]>>, BigPoints) {
        let big = self
            .points
            .into_iter()
            .zip(&self.small)
            .enumerate()
            .filter_map(|(i, (p, t))| match t {
                Some(_) => None,
                None => Some((i, p.expect("points that do not fit are given exactly"))),
            })
            .collect();
        (self.small, big)
    }

    /// A point whose coordinates do not fit.
    fn intern_big(&mut self, p: RatPoint) -> VertexId {
        use std::hash::BuildHasher;
        let h = std::hash::BuildHasherDefault::<crate::fx::FxHasher>::default().hash_one(&p);
        let new = self.points.len();
        let points = &self.points;
        if let Some(at) = self
            .by_hash
            .find_or_file(h, new, |at| points[at].as_ref() == Some(&p))
        {
            return at;
        }
        self.push(Some(p), None);
        new
    }

    /// Room for `more` points.
    fn reserve(&mut self, more: usize) {
        self.points.reserve(more);
        self.small.reserve(more);
        self.by_small.reserve(self.small.len() + more, &self.small);
    }

    fn push(&mut self, p: Option<RatPoint>, small: Option<[i128; 3]>) {
        self.points.push(p);
        self.small.push(small);
    }

    fn ray_end(&mut self, r: &VisibilityRay) -> VertexId {
        match r.end.on_map {
            OnMap::Vertex(i) => i,
            OnMap::Edge(_) => self.intern(r.end.point.clone()),
        }
    }
}

/// A position along a line, `d · p` as a fraction: `i128` numerator and
/// (positive) denominator when they fit, else a GMP rational. Compared
/// exactly either way.
#[derive(Clone, Debug)]
pub(crate) enum Along {
    Small(i128, i128),
    Big(Rational),
}

impl Along {
    pub(crate) fn of(d: Vector, p: PointRef<'_>) -> Along {
        let fast = || -> Option<Along> {
            let [x, y, w] = p.small?;
            let num = mul(x, d.x)?.checked_add(mul(y, d.y)?)?;
            Some(Along::Small(num, w))
        };
        fast().unwrap_or_else(|| Along::Big(along(d, &p.exact())))
    }

    /// A rational, small if it fits.
    pub(crate) fn from_rational(r: Rational) -> Along {
        match (r.numer().to_i128(), r.denom().to_i128()) {
            (Some(n), Some(w)) => Along::Small(n, w),
            _ => Along::Big(r),
        }
    }

    pub(crate) fn big(&self) -> Rational {
        match self {
            Along::Small(n, w) => Rational::from((*n, *w)),
            Along::Big(r) => r.clone(),
        }
    }

    /// Exact comparison (denominators are positive).
    pub(crate) fn cmp(&self, other: &Along) -> Ordering {
        if let (Along::Small(a, w), Along::Small(b, v)) = (self, other) {
            if let (Some(x), Some(y)) = (mul(*a, *v), mul(*b, *w)) {
                return x.cmp(&y);
            }
        }
        self.big().cmp(&other.big())
    }
}

/// Sort point ids by `d · p` and drop duplicates.
fn sort_along<'a>(d: Vector, ids: &mut Vec<VertexId>, pt: impl Fn(VertexId) -> PointRef<'a>) {
    ids.sort_unstable();
    ids.dedup();
    let mut keyed: Vec<(Along, VertexId)> = ids.iter().map(|&i| (Along::of(d, pt(i)), i)).collect();
    keyed.sort_by(|a, b| a.0.cmp(&b.0).then(a.1.cmp(&b.1)));
    *ids = keyed.into_iter().map(|(_, i)| i).collect();
}

impl Arrangement {
    /// The arrangement of the edges of `map` and the visibility rays
    /// `rays` (normally [`crate::visibility_rays`]`(map)`; any subset gives
    /// a valid subdivision, though its faces need not be convex).
    pub fn new(map: &Map, rays: &[VisibilityRay]) -> Arrangement {
        Arrangement::from_rays(map, rays.to_vec())
    }

    /// Same as [`Arrangement::new`], keeping `rays` without copying them.
    pub fn from_rays(map: &Map, rays: Vec<VisibilityRay>) -> Arrangement {
        Arrangement::from_rays_beside(map, rays, |_, _| ()).0
    }

    /// [`Arrangement::from_rays`], and `beside(groups, rays)` run at the
    /// same time (on another thread when one is free: much of the
    /// construction is sequential).
    pub(crate) fn from_rays_beside<T: Send>(
        map: &Map,
        rays: Vec<VisibilityRay>,
        beside: impl FnOnce(&[RayGroup], &[VisibilityRay]) -> T + Send,
    ) -> (Arrangement, T) {
        // Groups and their directions.
        let groups: Vec<RayGroup> = group_by_line(&rays)
            .into_iter()
            .map(|(key, rs)| {
                let dir = primitive_dir(&rays[rs[0]].line);
                RayGroup { key, rays: rs, dir }
            })
            .collect();
        let (mut arr, t) = Arrangement::assemble(map, &rays, &groups, beside);
        arr.groups = groups;
        arr.rays = rays;
        (arr, t)
    }

    /// The arrangement of the map and `rays` in ray groups `groups`, but
    /// for those two (left empty); and `beside(groups, rays)`, run beside
    /// its sequential second half ([`Arrangement::link`]) once the pairs of
    /// rays that meet are found.
    fn assemble<T: Send>(
        map: &Map,
        rays: &[VisibilityRay],
        groups: &[RayGroup],
        beside: impl FnOnce(&[RayGroup], &[VisibilityRay]) -> T + Send,
    ) -> (Arrangement, T) {
        let v = map.vertices();
        let mut pts = Points::new();
        for &p in v {
            pts.intern(RatPoint::from(p));
        }
        // The ray ends, and each group's points.
        let mut group_of = vec![0; rays.len()];
        for (g, grp) in groups.iter().enumerate() {
            for &r in &grp.rays {
                group_of[r] = g;
            }
        }
        let ends: Vec<VertexId> = rays.iter().map(|r| pts.ray_end(r)).collect();
        let on_line: Vec<Vec<VertexId>> = groups
            .iter()
            .map(|grp| {
                let mut ids = Vec::new();
                for &r in &grp.rays {
                    ids.push(rays[r].anchor);
                    ids.extend(rays[r].grazed.iter().copied());
                    ids.push(ends[r]);
                }
                ids
            })
            .collect();
        // Pairwise intersections of rays on different lines.
        let boxes: Vec<[i128; 4]> = rays
            .iter()
            .zip(&ends)
            .map(|(r, &e)| bbox([pts.exact(r.anchor), pts.exact(e)]))
            .collect();
        // Closed segments on different lines meet iff neither has both
        // endpoints strictly on one side of the other's line: exact signs
        // (each ray a [`Span`] on the `i64` path of `crate::small`, else
        // orientations with the ends through `Eye`'s checked i128 path),
        // and the point is constructed only for pairs that meet. Pairs are
        // visited in order of their boxes' left sides, stopping once a box
        // starts right of the current one.
        let spans: Option<Vec<Span>> =
            SmallCoords::of(map).map(|c| rays.iter().map(|r| c.span(r)).collect());
        let eyes: Vec<Eye> = match spans {
            Some(_) => Vec::new(),
            None => ends.iter().map(|&e| Eye::new(pts.exact(e))).collect(),
        };
        let apart = |i: usize, j: usize| match &spans {
            Some(s) => s[i].apart_from(&s[j]),
            None => {
                let (a, b) = (rays[j].line.a(), rays[j].line.b());
                let sa = orientation(a, b, rays[i].start());
                let se = eyes[i].orientation(a, b);
                sa == se && sa != Orientation::Collinear
            }
        };
        let crossings = meeting_pairs(&boxes, |i, j| {
            if group_of[i] == group_of[j] || apart(i, j) || apart(j, i) {
                return None;
            }
            let (l1, l2) = (&rays[i].line, &rays[j].line);
            // None for parallel lines.
            let x = match construct_intersection_i128(l1, l2) {
                Some(t) => Meet::Small(t?),
                None => Meet::Big(construct_intersection(l1, l2)?),
            };
            Some((i, j, x))
        });
        let found = Found {
            pts,
            group_of,
            ends,
            on_line,
            crossings,
        };
        rayon::join(
            || Arrangement::link(map, rays, groups, found),
            || beside(groups, rays),
        )
    }

    /// The second half of [`Arrangement::assemble`]: every point stored
    /// once, the edges along each line and map edge, the half-edges
    /// linked around each vertex, the faces traced.
    fn link(map: &Map, rays: &[VisibilityRay], groups: &[RayGroup], found: Found) -> Arrangement {
        let v = map.vertices();
        let n = v.len();
        let Found {
            mut pts,
            group_of,
            ends,
            mut on_line,
            crossings,
        } = found;
        pts.reserve(crossings.len());
        let mut more = vec![0usize; groups.len()];
        for &(i, j, _) in &crossings {
            more[group_of[i]] += 1;
            more[group_of[j]] += 1;
        }
        for (ids, more) in on_line.iter_mut().zip(more) {
            ids.reserve_exact(more);
        }
        for (i, j, x) in crossings {
            let id = pts.intern_meet(x);
            on_line[group_of[i]].push(id);
            on_line[group_of[j]].push(id);
        }
        // Points on map edges: the ends of rays in their relative interior.
        let mut on_edge: Vec<Vec<VertexId>> = (0..n).map(|i| vec![i, map.next(i)]).collect();
        for (r, &e) in rays.iter().zip(&ends) {
            if let OnMap::Edge(i) = r.end.on_map {
                on_edge[i].push(e);
            }
        }
        let (small, big) = pts.finish();
        let nv = small.len();
        let pt = |v: VertexId| PointRef {
            small: small[v],
            big: big_point(&small, &big, v),
        };
        let mut on_boundary = vec![false; nv];
        // Edges: map edges first, then ray groups.
        let most = on_edge.iter().chain(&on_line).map(Vec::len).sum::<usize>();
        let mut edges: Vec<EdgeGeometry> = Vec::with_capacity(most);
        let mut ends_of: Vec<(VertexId, VertexId)> = Vec::with_capacity(most);
        let mut dir_of: Vec<Vector> = Vec::with_capacity(most);
        let edge_dirs: Vec<Vector> = (0..n)
            .map(|i| primitive_dir(&Line::new(v[i], v[map.next(i)]).expect("distinct")))
            .collect();
        on_edge
            .par_iter_mut()
            .zip(&edge_dirs)
            .for_each(|(ids, &d)| sort_along(d, ids, pt));
        on_line
            .par_iter_mut()
            .zip(groups)
            .for_each(|(ids, g)| sort_along(g.dir, ids, pt));
        // By ring, the edge of the first piece of its first map edge.
        let mut ring_first_piece = Vec::with_capacity(map.hole_count() + 1);
        for (i, ids) in on_edge.iter().enumerate() {
            let d = edge_dirs[i];
            let ring = ring_first_piece.len();
            if ring <= map.hole_count() && map.ring_range(ring).start == i {
                ring_first_piece.push(edges.len());
            }
            for w in ids.windows(2) {
                on_boundary[w[0]] = true;
                on_boundary[w[1]] = true;
                edges.push(EdgeGeometry {
                    support: Support::MapEdge(i),
                    rays: 0..0,
                });
                ends_of.push((w[0], w[1]));
                dir_of.push(d);
            }
        }
        // By point: its place on the line at hand.
        let mut pos = vec![0; nv];
        let mut ray_list: Vec<usize> = Vec::with_capacity(2 * rays.len());
        for (g, ids) in on_line.iter().enumerate() {
            let d = groups[g].dir;
            for (k, &i) in ids.iter().enumerate() {
                pos[i] = k;
            }
            // Each ray's stretch of the line, as places.
            let spans: Vec<(usize, usize, usize)> = groups[g]
                .rays
                .iter()
                .map(|&r| {
                    let (a, b) = (pos[rays[r].anchor], pos[ends[r]]);
                    (a.min(b), a.max(b), r)
                })
                .collect();
            for k in 0..ids.len().saturating_sub(1) {
                let start = ray_list.len();
                ray_list.extend(
                    spans
                        .iter()
                        .filter(|&&(lo, hi, _)| lo <= k && k < hi)
                        .map(|&(_, _, r)| r),
                );
                if ray_list.len() == start {
                    continue;
                }
                edges.push(EdgeGeometry {
                    support: Support::Rays(g),
                    rays: start..ray_list.len(),
                });
                ends_of.push((ids[k], ids[k + 1]));
                dir_of.push(d);
            }
        }
        // Half-edges 2e (along the support's direction) and 2e + 1.
        let mut half_edges: Vec<HalfEdge> = Vec::with_capacity(2 * edges.len());
        // By vertex, its outgoing half-edges: `out[start[v]..start[v + 1]]`.
        let mut start = vec![0usize; nv + 1];
        for &(a, b) in &ends_of {
            start[a + 1] += 1;
            start[b + 1] += 1;
        }
        for v in 0..nv {
            start[v + 1] += start[v];
        }
        let mut fill = start.clone();
        let mut out: Vec<HalfEdgeId> = vec![0; 2 * ends_of.len()];
        for (e, &(a, b)) in ends_of.iter().enumerate() {
            for (h, o) in [(2 * e, a), (2 * e + 1, b)] {
                half_edges.push(HalfEdge {
                    origin: o,
                    twin: h ^ 1,
                    next: usize::MAX,
                    prev: usize::MAX,
                    face: usize::MAX,
                });
                out[fill[o]] = h;
                fill[o] += 1;
            }
        }
        drop(fill);
        let hdir = |h: HalfEdgeId| {
            let d = dir_of[h / 2];
            if h.is_multiple_of(2) {
                d
            } else {
                -d
            }
        };
        let mut around: Vec<&mut [HalfEdgeId]> = Vec::with_capacity(nv);
        let mut rest = &mut out[..];
        for v in 0..nv {
            let (o, tail) = std::mem::take(&mut rest).split_at_mut(start[v + 1] - start[v]);
            around.push(o);
            rest = tail;
        }
        around
            .par_iter_mut()
            .for_each(|o| o.sort_by(|&x, &y| hdir(x).compare_angle(hdir(y))));
        drop(around);
        let mut vertices = Vec::with_capacity(nv);
        for v in 0..nv {
            let o = &out[start[v]..start[v + 1]];
            let k = o.len();
            for i in 0..k {
                let h = o[i] ^ 1;
                let nx = o[(i + k - 1) % k];
                half_edges[h].next = nx;
                half_edges[nx].prev = h;
            }
            vertices.push(Vertex {
                out: *o.first().expect("every vertex lies on a segment"),
            });
        }
        // Faces; the first traced is the exterior, left of the reverse of
        // the first piece of map edge 0 (the map is counter-clockwise),
        // then the holes' interiors, left of the reverse of each hole's
        // first piece (holes are clockwise), then the cells.
        let mut faces = Vec::new();
        let reversed = ring_first_piece.iter().map(|&e| 2 * e + 1);
        for start in reversed.chain(0..half_edges.len()) {
            if half_edges[start].face != usize::MAX {
                continue;
            }
            let f = faces.len();
            faces.push(Face { outer: start });
            let mut h = start;
            while half_edges[h].face == usize::MAX {
                half_edges[h].face = f;
                h = half_edges[h].next;
            }
        }
        Arrangement {
            vertices,
            half_edges,
            faces,
            small,
            big,
            points: OnceLock::new(),
            on_boundary,
            edges,
            ray_list,
            dirs: dir_of,
            groups: Vec::new(),
            map: map.clone(),
            rays: Vec::new(),
            assignment: OnceLock::new(),
        }
    }

    /// The exterior of the map (always face 0).
    pub fn outer_face(&self) -> FaceId {
        0
    }
    /// The interior of hole `k` (0-based): face `1 + k`.
    pub fn hole_face(&self, k: usize) -> FaceId {
        assert!(
            k < self.map.hole_count(),
            "hole {k} of {}",
            self.map.hole_count()
        );
        1 + k
    }
    /// Whether face `f` is a visibility cell: neither the exterior nor a
    /// hole's interior.
    pub fn is_cell(&self, f: FaceId) -> bool {
        f > self.map.hole_count()
    }
    pub fn vertex_count(&self) -> usize {
        self.vertices.len()
    }
    pub fn half_edge_count(&self) -> usize {
        self.half_edges.len()
    }
    pub fn edge_count(&self) -> usize {
        self.edges.len()
    }
    /// Faces including the outer face.
    pub fn face_count(&self) -> usize {
        self.faces.len()
    }
    /// The faces of the free space: the visibility cells (every bounded
    /// face but the holes' interiors, which come first).
    pub fn cells(&self) -> impl Iterator<Item = FaceId> {
        1 + self.map.hole_count()..self.faces.len()
    }
    pub fn vertex(&self, v: VertexId) -> &Vertex {
        &self.vertices[v]
    }
    pub fn half_edge(&self, h: HalfEdgeId) -> &HalfEdge {
        &self.half_edges[h]
    }
    pub fn face(&self, f: FaceId) -> &Face {
        &self.faces[f]
    }
    /// The exact point of vertex `v`.
    pub fn point(&self, v: VertexId) -> &RatPoint {
        &self.points()[v]
    }
    /// The exact points of the vertices, by id (built on the first call:
    /// the decomposition itself needs only their `i128` coordinates).
    pub fn points(&self) -> &[RatPoint] {
        self.points.get_or_init(|| {
            (0..self.small.len())
                .into_par_iter()
                .map(|v| self.pt(v).exact().into_owned())
                .collect()
        })
    }
    /// The point of vertex `v`: its `i128` coordinates, or its exact point.
    pub(crate) fn pt(&self, v: VertexId) -> PointRef<'_> {
        PointRef {
            small: self.small[v],
            big: big_point(&self.small, &self.big, v),
        }
    }
    /// Whether vertex `v` lies on the map boundary.
    pub fn is_on_map_boundary(&self, v: VertexId) -> bool {
        self.on_boundary[v]
    }
    /// The destination of half-edge `h`.
    pub fn dest(&self, h: HalfEdgeId) -> VertexId {
        self.half_edges[self.half_edges[h].twin].origin
    }
    /// The supporting segment of edge `e`.
    pub fn edge_support(&self, e: EdgeId) -> Support {
        self.edges[e].support
    }
    /// The rays (indices into the rays) covering edge `e`.
    pub fn edge_rays(&self, e: EdgeId) -> &[usize] {
        &self.ray_list[self.edges[e].rays.clone()]
    }
    /// Ray group `g`.
    pub fn ray_group(&self, g: usize) -> &RayGroup {
        &self.groups[g]
    }
    pub fn ray_groups(&self) -> &[RayGroup] {
        &self.groups
    }
    /// The rays the arrangement was built from.
    pub fn rays(&self) -> &[VisibilityRay] {
        &self.rays
    }
    pub fn map(&self) -> &Map {
        &self.map
    }
    /// The primitive integer direction of half-edge `h`.
    pub fn direction(&self, h: HalfEdgeId) -> Vector {
        let d = self.dirs[h / 2];
        if h.is_multiple_of(2) {
            d
        } else {
            -d
        }
    }
    /// The half-edges of the boundary cycle of face `f`, from its `outer`,
    /// without collecting them.
    pub fn face_cycle(&self, f: FaceId) -> impl Iterator<Item = HalfEdgeId> + '_ {
        let start = self.faces[f].outer;
        let mut h = Some(start);
        std::iter::from_fn(move || {
            let cur = h?;
            let next = self.half_edges[cur].next;
            h = (next != start).then_some(next);
            Some(cur)
        })
    }

    /// The half-edges of the boundary cycle of face `f`, from its `outer`.
    pub fn face_half_edges(&self, f: FaceId) -> Vec<HalfEdgeId> {
        let start = self.faces[f].outer;
        let mut out = Vec::with_capacity(8);
        out.push(start);
        let mut h = self.half_edges[start].next;
        while h != start && out.len() <= self.half_edges.len() {
            out.push(h);
            h = self.half_edges[h].next;
        }
        out
    }
    /// The vertices of face `f` in boundary order (counter-clockwise for a
    /// cell).
    pub fn face_vertices(&self, f: FaceId) -> Vec<VertexId> {
        self.face_half_edges(f)
            .into_iter()
            .map(|h| self.half_edges[h].origin)
            .collect()
    }
    /// The exact points of the vertices of face `f`, in boundary order.
    pub fn face_points(&self, f: FaceId) -> Vec<RatPoint> {
        self.face_vertices(f)
            .into_iter()
            .map(|v| self.point(v).clone())
            .collect()
    }
    /// The half-edges leaving `v`, counter-clockwise.
    pub fn outgoing(&self, v: VertexId) -> Vec<HalfEdgeId> {
        let mut out = Vec::with_capacity(8);
        self.outgoing_into(v, &mut out);
        out
    }

    /// [`Arrangement::outgoing`] into `out` (cleared first), for callers
    /// that reuse one buffer over many vertices.
    pub(crate) fn outgoing_into(&self, v: VertexId, out: &mut Vec<HalfEdgeId>) {
        out.clear();
        let start = self.vertices[v].out;
        out.push(start);
        let mut h = self.half_edges[self.half_edges[start].prev].twin;
        while h != start && out.len() <= self.half_edges.len() {
            out.push(h);
            h = self.half_edges[self.half_edges[h].prev].twin;
        }
    }

    /// The faces around vertex `v`: the face of each outgoing half-edge,
    /// counter-clockwise (a face meeting `v` in two corners appears twice).
    pub fn faces_around(&self, v: VertexId) -> Vec<FaceId> {
        self.outgoing(v)
            .into_iter()
            .map(|h| self.half_edges[h].face)
            .collect()
    }

    /// Sec. 3.6: the cell that owns the points of edge `e`'s relative
    /// interior. See [`BoundaryAssignment`] for the rule.
    pub fn owner_of_edge(&self, e: EdgeId) -> FaceId {
        self.assignment().edge_owner[e]
    }
    /// Sec. 3.6: the cell that owns vertex `v`; `None` when the rays
    /// through it assign it to no common cell (a [`Conflict::Vertex`]).
    pub fn owner_of_vertex(&self, v: VertexId) -> Option<FaceId> {
        self.assignment().vertex_owner[v]
    }
    /// Every boundary piece that two rays assign to different cells.
    pub fn conflicts(&self) -> &[Conflict] {
        &self.assignment().conflicts
    }
    /// The boundary assignment of sec. 3.6, computed on the first call.
    pub fn assignment(&self) -> &BoundaryAssignment {
        self.assignment.get_or_init(|| assign(self))
    }

    /// Planted violations for tests: point half-edge `h`'s twin at `t`.
    #[doc(hidden)]
    pub fn corrupt_twin_for_tests(&mut self, h: HalfEdgeId, t: HalfEdgeId) {
        self.half_edges[h].twin = t;
    }
    /// Planted violations for tests: move vertex `v` to `p`.
    #[doc(hidden)]
    pub fn corrupt_point_for_tests(&mut self, v: VertexId, p: RatPoint) {
        self.big.retain(|&(u, _)| u != v);
        self.small[v] = small_of(&p);
        if self.small[v].is_none() {
            let at = self.big.partition_point(|&(u, _)| u < v);
            self.big.insert(at, (v, p));
        }
        self.points = OnceLock::new();
    }
}

/// Exact points by ascending vertex id: those whose coordinates do not fit
/// an `i128`.
type BigPoints = Vec<(VertexId, RatPoint)>;

/// The exact point of vertex `v` among `big` (ascending ids), when its
/// coordinates do not fit (`small[v]` is `None`).
fn big_point<'a>(
    small: &[Option<[i128; 3]>],
    big: &'a [(VertexId, RatPoint)],
    v: VertexId,
) -> Option<&'a RatPoint> {
    if small[v].is_some() {
        return None;
    }
    let at = big
        .binary_search_by_key(&v, |&(u, _)| u)
        .expect("a point that does not fit is kept exactly");
    Some(&big[at].1)
}

/// Twice the signed area of a ring of rational points, exactly.
pub(crate) fn area_twice_rat(ring: &[&RatPoint]) -> Rational {
    let mut s = Rational::new();
    for (i, p) in ring.iter().enumerate() {
        let q = ring[(i + 1) % ring.len()];
        let num = Integer::from(p.hx() * q.hy()) - Integer::from(p.hy() * q.hx());
        s += Rational::from((num, Integer::from(p.hw() * q.hw())));
    }
    s
}

/// Whether `p` lies on the closed segment `ab` (exactly).
pub(crate) fn on_closed_segment(a: &RatPoint, b: &RatPoint, p: &RatPoint) -> bool {
    if orientation_rat(a, b, p) != Orientation::Collinear {
        return false;
    }
    let d = |u: &RatPoint, w: &RatPoint| {
        (
            Rational::from((u.hx().clone(), u.hw().clone()))
                - Rational::from((w.hx().clone(), w.hw().clone())),
            Rational::from((u.hy().clone(), u.hw().clone()))
                - Rational::from((w.hy().clone(), w.hw().clone())),
        )
    };
    let (ux, uy) = d(p, a);
    let (vx, vy) = d(p, b);
    ux * vx + uy * vy <= 0
}

#[cfg(test)]
mod tests {
    use super::{bbox, small_box};
    use rug::Integer;
    use wai_exact::RatPoint;

    /// The `i128` box of a point equals the GMP floors and ceilings.
    #[test]
    fn small_boxes_equal_gmp_boxes() {
        let mut rng = 0x2545_f491_4f6c_dd1du64;
        let mut next = |bits: u32| {
            rng ^= rng << 13;
            rng ^= rng >> 7;
            rng ^= rng << 17;
            let v = (rng >> (64 - bits)) as i128;
            if rng & 1 == 0 {
                v
            } else {
                -v
            }
        };
        for bits in [1u32, 3, 20, 62] {
            for _ in 0..2000 {
                let w = next(bits.min(40)).abs().max(1);
                let (x, y) = (next(bits) << 60, next(bits));
                let p =
                    RatPoint::new(Integer::from(x), Integer::from(y), Integer::from(w)).unwrap();
                let fl = |c: &Integer| {
                    let (q, _) = c.clone().div_rem_floor(p.hw().clone());
                    q.to_i128().unwrap()
                };
                let ce = |c: &Integer| {
                    let (q, _) = c.clone().div_rem_ceil(p.hw().clone());
                    q.to_i128().unwrap()
                };
                let want = [fl(p.hx()), fl(p.hy()), ce(p.hx()), ce(p.hy())];
                assert_eq!(small_box(&p).unwrap(), want, "{p}");
                assert_eq!(bbox([&p]), want);
            }
        }
    }
}
