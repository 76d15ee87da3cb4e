//! V*_p in map terms (Def 3.7), read straight off the triangular expansion
//! when the viewpoint's coordinates are small: the many skeletons a checker
//! compares (one per sampled point of every cell) without building V_p's
//! spurious vertices as exact points.

use crate::assemble::fits_fast;
use crate::polygon::VisibilityError;
use crate::skeleton::{LineLabel, Skeleton, SkeletonEdge, SkeletonError, SkeletonKey};
use rug::Integer;
use std::cmp::Ordering;
use wai_exact::{orientation, Orientation, Point, RatPoint, Vector};
use wai_map::Map;

/// A skeleton V*_p in map terms: the map vertex of each skeleton vertex,
/// counter-clockwise from the canonical origin v0 (Def 3.7 (6), as
/// [`Skeleton`] chooses it), and for each edge from vertex i to i + 1 the
/// map edge under it — the full edge itself, or the half or partial edge an
/// artificial edge replaces (Def 3.7 (2)–(4)).
///
/// Two points have equal skeletons in the same embedding (equal
/// [`SkeletonKey`]s and origins) iff their map skeletons have the same
/// vertices and kinds of edges and each artificial edge's map edge lies on
/// the same line ([`MapSkeleton::same`]): the label is that line (Def 3.7
/// (5)), and collinear map edges give equal labels (Fig 3.5).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct MapSkeleton {
    /// By skeleton vertex: its map vertex, from v0.
    pub vertices: Vec<usize>,
    /// By skeleton edge: the map edge under it, and whether the edge is
    /// artificial.
    pub edges: Vec<(usize, bool)>,
}

/// Why V*_p could not be formed at a point.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum SkeletonAtError {
    #[error("V_p: {0}")]
    Visibility(#[from] VisibilityError),
    #[error("V*_p: {0}")]
    Skeleton(#[from] SkeletonError),
}

impl MapSkeleton {
    /// The map terms of a skeleton.
    pub fn of(sk: &Skeleton) -> MapSkeleton {
        MapSkeleton {
            vertices: sk.map_vertices().to_vec(),
            edges: sk
                .edges()
                .iter()
                .map(|e| match e {
                    SkeletonEdge::Full { map_edge } => (*map_edge, false),
                    SkeletonEdge::Artificial { map_edge, .. } => (*map_edge, true),
                })
                .collect(),
        }
    }

    /// The map vertex of the origin v0.
    pub fn origin(&self) -> usize {
        self.vertices[0]
    }

    /// The canonical key (as [`Skeleton::key`]).
    pub fn key(&self, map: &Map) -> SkeletonKey {
        let v = map.vertices();
        let o = v[self.origin()];
        SkeletonKey {
            offsets: self
                .vertices
                .iter()
                .map(|&m| (v[m].x - o.x, v[m].y - o.y))
                .collect(),
            labels: self
                .edges
                .iter()
                .map(|&(e, artificial)| {
                    artificial.then(|| LineLabel::through(v[e], v[map.next(e)], o))
                })
                .collect(),
        }
    }

    /// Whether `self` and `other` are one skeleton in one embedding: equal
    /// keys and origins.
    pub fn same(&self, map: &Map, other: &MapSkeleton) -> bool {
        if self.vertices != other.vertices || self.edges.len() != other.edges.len() {
            return false;
        }
        let v = map.vertices();
        self.edges
            .iter()
            .zip(&other.edges)
            .all(|(&(e, ae), &(f, af))| {
                ae == af
                    && (e == f
                        || (ae
                            && orientation(v[e], v[map.next(e)], v[f]) == Orientation::Collinear
                            && orientation(v[e], v[map.next(e)], v[map.next(f)])
                                == Orientation::Collinear))
            })
    }

    /// Whether `self` is the skeleton `key` with its origin at map vertex
    /// `origin`.
    pub fn is(&self, map: &Map, origin: usize, key: &SkeletonKey) -> bool {
        let v = map.vertices();
        if self.origin() != origin
            || self.vertices.len() != key.offsets.len()
            || self.edges.len() != key.labels.len()
        {
            return false;
        }
        let o = v[origin];
        let rel = |m: usize| (v[m].x - o.x, v[m].y - o.y);
        self.vertices
            .iter()
            .zip(&key.offsets)
            .all(|(&m, &off)| rel(m) == off)
            && self
                .edges
                .iter()
                .zip(&key.labels)
                .all(|(&(e, artificial), label)| match label {
                    None => !artificial,
                    Some(l) => artificial && on_label(l, rel(e), rel(map.next(e))),
                })
    }
}

/// `i + 1` modulo `n`, for `i < n` (without a division).
#[inline]
fn succ(i: usize, n: usize) -> usize {
    if i + 1 == n {
        0
    } else {
        i + 1
    }
}

/// `i − 1` modulo `n`, for `i < n` (without a division).
#[inline]
fn pred(i: usize, n: usize) -> usize {
    if i == 0 {
        n - 1
    } else {
        i - 1
    }
}

/// Whether the points `s` and `t` (relative to the origin) lie on `l`:
/// `a·x + b·y = c`, in `i128` when the products cannot overflow.
fn on_label(l: &LineLabel, s: (i128, i128), t: (i128, i128)) -> bool {
    let small = |c: &Integer| c.to_i128().filter(|c| c.unsigned_abs() < 1 << 62);
    let fits = |c: i128| c.unsigned_abs() < 1 << 62;
    match (small(&l.a), small(&l.b), small(&l.c)) {
        (Some(a), Some(b), Some(c)) => [s, t].into_iter().all(|(x, y)| {
            if fits(x) && fits(y) {
                // |a·x|, |b·y| < 2^124 and |c| < 2^62: the sum fits.
                a * x + b * y == c
            } else {
                l.contains(x, y)
            }
        }),
        _ => l.contains(s.0, s.1) && l.contains(t.0, t.1),
    }
}

/// What the boundary of V_p runs along after a vertex.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Along {
    Ray,
    MapEdge(usize),
}

/// A vertex of V_p: the map vertex of a non-spurious one.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Vertex {
    At(usize),
    Spurious,
}

/// The working lists of [`from_leaves`], kept between queries so that a
/// query allocates only the skeleton it returns.
#[derive(Default)]
pub(crate) struct SkeletonScratch {
    boundary: Vec<(Vertex, Along)>,
    kept: Vec<(usize, usize)>,
}

/// V*_p from the expansion's `leaves` (as [`crate::assemble`] reads them)
/// without building V_p's points, if `p` fits the fast path and every
/// boundary direction meets the configuration below; `None` otherwise
/// (the caller builds V_p and [`Skeleton::of`] instead).
///
/// At the direction of map vertex d that starts a leaf, with map edge
/// `before` nearest just before it and `after` just after: if d is an end
/// of both, V_p turns at d (a non-spurious vertex). If d is an end of one
/// only, the other edge's line meets the ray from p through d at
/// `p + t·(d − p)`, t = num / den in `i128` (the bound of
/// [`fits_fast`]); t > 1 makes d the near, non-spurious end of a spurious
/// edge whose far end is that meeting point. Any other configuration
/// (neither edge at d, or t ≤ 1) falls back.
///
/// A non-spurious vertex is reflex in V_p — what the canonical origin asks
/// — iff it is the near end of a spurious edge (the boundary comes back
/// toward p along the map edge: the interior angle exceeds 180°, the map
/// edge not being collinear with p, as no V_p edge along a map edge is), or
/// it lies between its own two map edges (m − 1 and m) and is reflex in the
/// map. Other configurations fall back. Tests compare every skeleton with
/// [`Skeleton::of`] on V_p.
///
/// `reflex`: by map vertex, whether it is reflex in the map.
pub(crate) fn from_leaves(
    map: &Map,
    reflex: &[bool],
    p: &RatPoint,
    coord_bits: u32,
    leaves: &[(usize, usize)],
    scratch: &mut SkeletonScratch,
) -> Option<Result<MapSkeleton, SkeletonError>> {
    if !fits_fast(p, coord_bits) {
        return None;
    }
    let (x, y, w) = (p.hx().to_i64()?, p.hy().to_i64()?, p.hw().to_i64()?);
    let v = map.vertices();
    // Within the bound of `fits_fast`: W, X, Y and the map coordinates fit
    // an `i64` (|W·v| < 2^61), W·v is a widening product, directions are
    // below 2^62, an edge vector below 2^63, cross products below 2^126.
    let c = |a: i128, b: i64| i128::from(w) * i128::from(a as i64) - i128::from(b);
    let rel = |i: usize| Vector::new(c(v[i].x, x), c(v[i].y, y));
    // Whether the line of map edge `e` meets the ray from p through vertex
    // `d` beyond d (t > 1), before it (`Less`) or at it.
    let beyond = |d: usize, e: usize| -> Option<Ordering> {
        let (dv, ra, rb) = (rel(d), rel(e), rel(map.next(e)));
        let den = dv.cross(Vector::new(rb.x - ra.x, rb.y - ra.y));
        if den == 0 {
            return None;
        }
        let num = ra.cross(rb);
        Some(if den > 0 {
            num.cmp(&den)
        } else {
            den.cmp(&num)
        })
    };
    let g = leaves.len();
    let SkeletonScratch { boundary, kept } = scratch;
    boundary.clear();
    for k in 0..g {
        let (before, (d, after)) = (leaves[pred(k, g)].1, leaves[k]);
        if before == after {
            continue;
        }
        let ends_at = |e: usize| d == e || d == map.next(e);
        match (ends_at(before), ends_at(after)) {
            (true, true) => boundary.push((Vertex::At(d), Along::MapEdge(after))),
            (true, false) => {
                if beyond(d, after)? != Ordering::Greater {
                    return None;
                }
                boundary.push((Vertex::At(d), Along::Ray));
                boundary.push((Vertex::Spurious, Along::MapEdge(after)));
            }
            (false, true) => {
                if beyond(d, before)? != Ordering::Greater {
                    return None;
                }
                boundary.push((Vertex::Spurious, Along::Ray));
                boundary.push((Vertex::At(d), Along::MapEdge(after)));
            }
            (false, false) => return None,
        }
    }
    let m = boundary.len();
    kept.clear();
    kept.extend(
        boundary
            .iter()
            .enumerate()
            .filter_map(|(i, (vx, _))| match vx {
                Vertex::At(mv) => Some((i, *mv)),
                Vertex::Spurious => None,
            }),
    );
    if kept.is_empty() {
        return None;
    }
    // The origin: the leftmost, then lowest, of the reflex ones, else of
    // all (positions in `kept`; vertices are distinct points, so the
    // first minimum is the only one).
    let at = |mv: usize| {
        let q: Point = v[mv];
        (q.x, q.y)
    };
    let (mut best_reflex, mut best): (Option<usize>, Option<usize>) = (None, None);
    for (s, &(i, mv)) in kept.iter().enumerate() {
        let (into, out) = (boundary[pred(i, m)].1, boundary[i].1);
        let is_reflex = match (into, out) {
            (Along::Ray, _) | (_, Along::Ray) => true,
            (Along::MapEdge(e1), Along::MapEdge(e2)) => {
                if e1 != map.prev(mv) || e2 != mv {
                    return None;
                }
                reflex[mv]
            }
        };
        let lower = |b: Option<usize>| b.is_none_or(|b| at(mv) < at(kept[b].1));
        if is_reflex && lower(best_reflex) {
            best_reflex = Some(s);
        }
        if lower(best) {
            best = Some(s);
        }
    }
    let start = best_reflex.or(best)?;
    let k = kept.len();
    // Skeleton vertex s is kept[(start + s) mod k].
    let at_s = |s: usize| {
        kept[if start + s >= k {
            start + s - k
        } else {
            start + s
        }]
    };
    let mut edges = Vec::with_capacity(k);
    for s in 0..k {
        let (i, _) = at_s(s);
        let (j, _) = at_s(succ(s, k));
        let mut solid = None;
        let mut count = 0;
        let mut len = 0;
        let mut e = i;
        loop {
            len += 1;
            if let Along::MapEdge(me) = boundary[e].1 {
                solid = Some(me);
                count += 1;
            }
            e = succ(e, m);
            if e == j {
                break;
            }
        }
        match (count, solid) {
            (1, Some(me)) => edges.push((me, len > 1)),
            _ => return None,
        }
    }
    Some(Ok(MapSkeleton {
        vertices: (0..k).map(|s| at_s(s).1).collect(),
        edges,
    }))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_points::interior_points;
    use crate::VisibilityIndex;

    /// The combinatorial reading agrees with the skeleton of V_p wherever
    /// it answers, and answers for nearly every point of small maps.
    #[test]
    fn the_fast_path_answers_and_agrees() {
        let (mut fast, mut all) = (0, 0);
        let mut maps = Vec::new();
        for kind in wai_gen::RANDOM_KINDS {
            for seed in 0..3 {
                maps.push(wai_gen::random(kind.id, kind.min_n.max(8) + 4, seed).unwrap());
            }
        }
        maps.extend(wai_gen::exhaustive_polyomino_maps(
            5,
            wai_gen::Symmetry::Free,
        ));
        for map in &maps {
            let index = VisibilityIndex::new(map);
            for p in interior_points(map, 6, 5) {
                let leaves = index.leaves_at(&p).unwrap();
                let vp = index.visibility_polygon(&p).unwrap();
                let want = Skeleton::of(map, &vp).map(|s| MapSkeleton::of(&s));
                all += 1;
                if let Some(got) = from_leaves(
                    map,
                    &index.reflex,
                    &p,
                    index.coord_bits(),
                    &leaves,
                    &mut SkeletonScratch::default(),
                ) {
                    fast += 1;
                    assert_eq!(got, want, "p = {p} in {:?}", map.vertices());
                }
            }
        }
        assert!(
            fast * 100 >= all * 95,
            "fast path on {fast} of {all} points"
        );
    }
}
