//! Incremental skeletons (thesis sec. 3.9.2): the skeleton of every cell of
//! every dimension from one visibility query, by walking the arrangement.
//!
//! # The model
//! The skeleton V*_q of a viewpoint q (Def 3.7) is fixed by
//! - **Vis(q)**, the map vertices q sees strictly (the open segment lies in
//!   the interior of the map): exactly the non-spurious vertices of V_q, in
//!   boundary order, which is map index order;
//! - for each pair x → y of consecutive ones with y ≠ x + 1, the one map
//!   edge V_q sees partly between them (the artificial edge's line):
//!   1. edge x, if q sees it from its interior side (orientation
//!      (x, x + 1, q) counter-clockwise): V_q leaves x along it;
//!   2. else edge y − 1, if q sees that one from its interior side;
//!   3. else the edge that the ray from q through x meets beyond x: V_q
//!      leaves x on a window. It is looked up in the view from x
//!      ([`VisibilityIndex::vertex_view`]) at the direction x − q, taken
//!      just counter-clockwise of it (V_q continues counter-clockwise
//!      after the window), which settles rays through further vertices;
//! - the origin: the leftmost, then lowest, vertex of Vis(q) that is reflex
//!   in V_q, which for a vertex q sees strictly is being reflex in the map.
//!
//! # The walk
//! Vis is computed by one query in the first 2-cell, then carried across
//! arrangement edges: the region that sees a map vertex v is bounded by
//! lines through v, so crossing an edge on line L changes Vis only for the
//! map vertices on L, and [`LineView::seen_from`] recomputes those by
//! walking along L. A 1-cell on L sees what its 2-cells see off L and, on
//! L, the nearest vertex each way; a 0-cell the same for each of its lines.
//!
//! The result is tested against a fresh query for every cell of every
//! dimension of the test maps, and the T3.3b checker compares the two on
//! every cell of every stress map.

use crate::arrangement::{Arrangement, FaceId, RayGroup, Support, VertexId};
use crate::decomposition::LowerSite;
use crate::eye::{angle_cmp, dir, mul, Eye};
use crate::line_view::{Beside, LineView};
use crate::rays::{LineKey, VisibilityRay};
use crate::small::{EdgeTurns, SmallCoords};
use rayon::prelude::*;
use rug::Integer;
use std::sync::atomic::{AtomicU32, AtomicU64, AtomicUsize, Ordering as AtomicOrdering};
use std::sync::OnceLock;
use wai_exact::{Line, Orientation, Point, RatPoint};
use wai_map::Map;
use wai_visibility::{LineLabel, Skeleton, SkeletonEdge, SkeletonKey, VisibilityIndex};

/// A skeleton in map terms: Vis (the map vertices seen, ascending map
/// ids), for each consecutive pair of Vis (cyclically) the edge between
/// them, and where in Vis the origin sits; the skeleton's vertices are Vis
/// rotated to start at the origin. (On one ring, ascending ids are the
/// skeleton's counter-clockwise order; on a map with holes they are not,
/// and Vis is kept in the skeleton's order from the origin instead, with
/// the origin first: [`Walker::walk`].) An edge is [`FULL`] or the map edge an
/// artificial edge lies on. Equal compact skeletons are equal skeletons in
/// the same embedding; the converse fails only where an artificial edge's
/// line holds several collinear map edges, which
/// [`Compact::same_skeleton`] settles.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct Compact {
    /// Vis, then the edges (one allocation): `edges[i]` runs from `vis[i]`
    /// to `vis[i + 1]` (cyclically).
    data: Box<[u32]>,
    /// The origin is `vis[shift]`.
    shift: u32,
}

/// A skeleton edge that is a full map edge, not an artificial one.
const FULL: u32 = u32::MAX;

impl Compact {
    /// Vis: the map vertices seen, ascending.
    fn vis(&self) -> &[u32] {
        &self.data[..self.data.len() / 2]
    }

    /// By gap of Vis, its edge: [`FULL`] or the map edge.
    fn edges(&self) -> &[u32] {
        &self.data[self.data.len() / 2..]
    }

    fn edges_mut(&mut self) -> &mut [u32] {
        let k = self.data.len() / 2;
        &mut self.data[k..]
    }

    /// The origin map vertex.
    pub(crate) fn origin(&self) -> usize {
        self.vis()[self.shift as usize] as usize
    }

    /// The skeleton's vertices and edges in order from the origin: map
    /// vertex ids, and `None` (full) or the map edge of an artificial edge.
    fn rotated(&self) -> impl Iterator<Item = (u32, Option<u32>)> + '_ {
        let s = self.shift as usize;
        let (vis, edges) = (self.vis(), self.edges());
        let pair = move |i: usize| (vis[i], (edges[i] != FULL).then_some(edges[i]));
        (s..vis.len()).chain(0..s).map(pair)
    }

    /// The canonical key (as [`Skeleton::key`] would give it).
    pub(crate) fn key(&self, map: &Map) -> SkeletonKey {
        let v = map.vertices();
        let o = v[self.origin()];
        let (offsets, labels) = self
            .rotated()
            .map(|(u, e)| {
                let p = v[u as usize];
                let label = e.map(|e| {
                    let e = e as usize;
                    LineLabel::through(v[e], v[map.next(e)], o)
                });
                ((p.x - o.x, p.y - o.y), label)
            })
            .unzip();
        SkeletonKey { offsets, labels }
    }
}

/// An integer that is usually small: normalised, so equal values are
/// equal and hash alike whichever way they were computed.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
enum Wide {
    Small(i128),
    Big(Integer),
}

impl Wide {
    fn of(x: Integer) -> Wide {
        match x.to_i128() {
            Some(v) => Wide::Small(v),
            None => Wide::Big(x),
        }
    }
}

/// The lines of the map's edges in a form that translates cheaply, for
/// telling skeletons apart without building their [`SkeletonKey`]s: each
/// line's [`LineKey`] a·x + b·y = c, unique for the line, as the key's
/// [`LineLabel`] is (that one is also reduced by the gcd with c).
pub(crate) struct EdgeLines {
    /// By map edge: (a, b, c), c also as an `i128` if it fits.
    by_edge: Vec<(i128, i128, Integer, Option<i128>)>,
    /// By map edge, for hashing: (a, b, c) modulo 2^64, and a mix of a
    /// and b.
    wrapping: Vec<[u64; 4]>,
    /// By map vertex, for hashing: its coordinates modulo 2^64.
    coords: Vec<[u64; 2]>,
    /// Powers of an odd constant, two per map vertex: the weights of the
    /// words of [`Compact::class_hash`] by position.
    powers: Vec<u64>,
}

/// The word of a full edge in [`Compact::class_hash`].
const FULL_WORD: u64 = 0x2545_f491_4f6c_dd1d;

impl EdgeLines {
    pub(crate) fn new(map: &Map) -> EdgeLines {
        let v = map.vertices();
        let by_edge: Vec<(i128, i128, Integer, Option<i128>)> = (0..v.len())
            .map(|i| {
                let line = Line::new(v[i], v[map.next(i)]).expect("distinct vertices");
                let key = LineKey::of(&line);
                let c = key.c().clone();
                let small = c.to_i128();
                (key.a(), key.b(), c, small)
            })
            .collect();
        let wrapping = by_edge
            .iter()
            .map(|(a, b, c, _)| {
                // Truncation is reduction modulo 2^64.
                let (a, b) = (*a as u64, *b as u64);
                let mix = a.wrapping_mul(0x9e37_79b9_7f4a_7c15) ^ b.rotate_left(32);
                [a, b, c.to_u64_wrapping(), mix]
            })
            .collect();
        // Truncation is reduction modulo 2^64.
        let coords = v.iter().map(|p| [p.x as u64, p.y as u64]).collect();
        let powers = std::iter::successors(Some(0x9e37_79b9_7f4a_7c15u64), |&p| {
            Some(p.wrapping_mul(0x9e37_79b9_7f4a_7c15))
        })
        .take(2 * v.len())
        .collect();
        EdgeLines {
            by_edge,
            wrapping,
            coords,
            powers,
        }
    }

    /// A hash of edge e's line relative to a point o, given as `(ox, oy)`
    /// modulo 2^64: (a, b, c − a·o.x − b·o.y) modulo 2^64, mixed into one
    /// value. Arithmetic modulo 2^64 is a ring homomorphism, so equal lines
    /// give equal values however large.
    fn relative_wrapping(&self, e: u32, ox: u64, oy: u64) -> u64 {
        let [a, b, c, mix] = self.wrapping[e as usize];
        let c = c
            .wrapping_sub(a.wrapping_mul(ox))
            .wrapping_sub(b.wrapping_mul(oy));
        c ^ mix
    }

    /// Edge e's line relative to `o`: (a, b, c − a·o.x − b·o.y).
    fn relative(&self, e: u32, o: Point) -> (i128, i128, Wide) {
        let (a, b, c, small) = &self.by_edge[e as usize];
        let fast = small.and_then(|c| c.checked_sub(mul(*a, o.x)?)?.checked_sub(mul(*b, o.y)?));
        let c = match fast {
            Some(c) => Wide::Small(c),
            None => Wide::of((c - Integer::from(*a) * o.x) - Integer::from(*b) * o.y),
        };
        (*a, *b, c)
    }
}

impl Compact {
    /// A hash of the skeleton up to translation: equal for compact
    /// skeletons whose keys are equal ([`Compact::same_skeleton`]).
    ///
    /// One word per vertex (its offset from the origin) and per edge (its
    /// line relative to the origin, or a constant for a full edge), all
    /// modulo 2^64, each times its own power of an odd constant, summed and
    /// mixed: the products are independent, so they overlap in the
    /// pipeline where a chained hash would wait on each step. The hash only
    /// sorts skeletons into buckets; [`Compact::same_skeleton`] decides.
    pub(crate) fn class_hash(&self, lines: &EdgeLines) -> u64 {
        let (vis, edges) = (self.vis(), self.edges());
        let (k, s) = (vis.len(), self.shift as usize);
        let c = &lines.coords;
        let [ox, oy] = c[vis[s] as usize];
        let (before, after) = lines.powers[..2 * k].split_at(2 * (k - s));
        let step = |acc: u64, (u, e, p): (&u32, &u32, &[u64])| {
            let [x, y] = c[*u as usize];
            let w = x.wrapping_sub(ox) ^ y.wrapping_sub(oy).rotate_left(32);
            let f = if *e == FULL {
                FULL_WORD
            } else {
                lines.relative_wrapping(*e, ox, oy)
            };
            acc.wrapping_add(w.wrapping_mul(p[0]))
                .wrapping_add(f.wrapping_mul(p[1]))
        };
        let zip = |vis: &'_ [u32], edges: &'_ [u32], pow: &'_ [u64]| {
            let pairs = vis.iter().zip(edges).zip(pow.chunks_exact(2));
            pairs.map(|((u, e), p)| (u, e, p)).fold(0u64, step)
        };
        let acc = (k as u64)
            .wrapping_add(zip(&vis[s..], &edges[s..], before))
            .wrapping_add(zip(&vis[..s], &edges[..s], after));
        // MurmurHash3's finaliser: every bit of the sum reaches the high
        // and the low bits, which the class table's buckets use.
        let h = (acc ^ (acc >> 33)).wrapping_mul(0xff51_afd7_ed55_8ccd);
        let h = (h ^ (h >> 33)).wrapping_mul(0xc4ce_b9fe_1a85_ec53);
        h ^ (h >> 33)
    }

    /// Whether two compact skeletons are one skeleton, i.e. have equal
    /// keys: the same vertex offsets from their origins, and artificial
    /// edges on the same lines relative to them.
    pub(crate) fn same_skeleton(&self, other: &Compact, map: &Map, lines: &EdgeLines) -> bool {
        let v = map.vertices();
        let (o, p) = (v[self.origin()], v[other.origin()]);
        self.data.len() == other.data.len()
            && self.rotated().zip(other.rotated()).all(|((x, e), (y, f))| {
                let (x, y) = (v[x as usize], v[y as usize]);
                x.x - o.x == y.x - p.x
                    && x.y - o.y == y.y - p.y
                    && match (e, f) {
                        (None, None) => true,
                        (Some(e), Some(f)) => lines.relative(e, o) == lines.relative(f, p),
                        _ => false,
                    }
            })
    }
}

/// The skeleton of a 1- or 0-cell.
#[derive(Debug)]
pub(crate) enum LowerSkeleton {
    /// That of the adjacent 2-cell, in the same embedding: the compact
    /// skeletons are equal.
    Face(FaceId),
    /// Its own, which may still equal an adjacent 2-cell's.
    Own(Compact),
}

/// The skeletons of all cells of an arrangement, by walking it. Shared
/// by reference: its only state after construction is a cache filled
/// once per map vertex.
pub(crate) struct Walker<'a> {
    map: &'a Map,
    /// For the class hashes of the 2-cells, taken while they are at hand.
    edge_lines: &'a EdgeLines,
    arr: &'a Arrangement,
    index: &'a VisibilityIndex<'a>,
    /// By ray group.
    lines: Vec<LineView>,
    topo: Topology,
    /// By map vertex: the view from it, computed when first needed.
    views: Vec<OnceLock<Vec<(usize, usize)>>>,
    /// By map vertex: reflex in the map.
    reflex: Vec<bool>,
    /// By map edge, for maps on the `i64` paths: [`EdgeTurns`].
    turns: Option<EdgeTurns>,
    /// The cells in the order the walk splits into parts
    /// ([`breadth_first`]).
    order: Vec<FaceId>,
}

/// The line of each ray group, in the arrangement's order of groups
/// (built beside the arrangement: [`Arrangement::from_rays_beside`]).
pub(crate) fn line_views(map: &Map, groups: &[RayGroup], rays: &[VisibilityRay]) -> Vec<LineView> {
    let small = SmallCoords::of(map);
    groups
        .par_iter()
        .map(|g| LineView::new(map, small.as_ref(), rays[g.rays[0]].from, g.dir))
        .collect()
}

/// No ray group, no lower cell, no skeleton found early.
const NONE: u32 = u32::MAX;

/// The arrangement as the walk reads it: its topology in 32-bit ids (12
/// bytes a half-edge against the arrangement's 40, so that more of it
/// stays in cache), each edge's line and slot, and the lower cells. Twins
/// are `h ^ 1`.
struct Topology {
    /// By half-edge: the next on its face's boundary, its origin, its face.
    half: Vec<[u32; 3]>,
    /// By face: a half-edge of its boundary.
    outer: Vec<u32>,
    /// By edge: its ray group and its slot on the group's line
    /// ([`LineView::slot`]), [`NONE`] for map edges; its index in `sites`
    /// ([`NONE`] for map edges).
    edge: Vec<[u32; 3]>,
    /// By vertex: its index in `sites` ([`NONE`] on the map boundary), its
    /// number of outgoing half-edges (= corners of faces), and the first of
    /// them in the arrangement's counter-clockwise order
    /// ([`Arrangement::outgoing`]).
    vertex: Vec<[u32; 3]>,
    /// The 1-cells (edges on rays, by id), then the 0-cells (vertices off
    /// the map boundary, by id).
    sites: Vec<LowerSite>,
}

impl Topology {
    fn new(arr: &Arrangement, lines: &[LineView]) -> Topology {
        let id = |i: usize| u32::try_from(i).expect("fewer than 2^32 arrangement elements");
        let half: Vec<[u32; 3]> = (0..arr.half_edge_count())
            .into_par_iter()
            .map(|h| {
                let he = arr.half_edge(h);
                debug_assert_eq!(he.twin, h ^ 1, "twins are paired");
                [id(he.next), id(he.origin), id(he.face)]
            })
            .collect();
        let outer = (0..arr.face_count())
            .map(|f| id(arr.face(f).outer))
            .collect();
        // The edges on rays come group by group, each group's in order
        // along its line (half-edge 2e forward), so their slots are found
        // by one pass along each line.
        let mut runs: Vec<(usize, std::ops::Range<usize>)> = Vec::new();
        for e in 0..arr.edge_count() {
            if let Support::Rays(g) = arr.edge_support(e) {
                match runs.last_mut() {
                    Some((h, r)) if *h == g && r.end == e => r.end = e + 1,
                    _ => runs.push((g, e..e + 1)),
                }
            }
        }
        let slots: Vec<(usize, usize, usize)> = runs
            .par_iter()
            .flat_map_iter(|(g, r)| {
                let l = &lines[*g];
                let mut slot = 0;
                r.clone().map(move |e| {
                    let (a, b) = (arr.half_edge(2 * e).origin, arr.dest(2 * e));
                    slot = l.slot_from(&l.position_of(arr.pt(a)), slot);
                    debug_assert_eq!(slot, l.slot(&l.position_of(arr.pt(a))));
                    debug_assert_eq!(
                        slot,
                        l.slot_before(&l.position_of(arr.pt(b))),
                        "an event strictly inside arrangement edge {e}"
                    );
                    (e, *g, slot)
                })
            })
            .collect();
        let mut edge: Vec<[u32; 3]> = vec![[NONE; 3]; arr.edge_count()];
        for (e, g, slot) in slots {
            edge[e] = [id(g), id(slot), NONE];
        }
        let sites: Vec<LowerSite> = (0..arr.edge_count())
            .filter(|&e| edge[e][0] != NONE)
            .map(LowerSite::Edge)
            .chain(
                (0..arr.vertex_count())
                    .filter(|&v| !arr.is_on_map_boundary(v))
                    .map(LowerSite::Vertex),
            )
            .collect();
        let mut vertex: Vec<[u32; 3]> = (0..arr.vertex_count())
            .map(|v| [NONE, 0, id(arr.vertex(v).out)])
            .collect();
        for (i, &site) in sites.iter().enumerate() {
            match site {
                LowerSite::Edge(e) => edge[e][2] = id(i),
                LowerSite::Vertex(v) => vertex[v][0] = id(i),
            }
        }
        for h in &half {
            vertex[h[1] as usize][1] += 1;
        }
        Topology {
            half,
            outer,
            edge,
            vertex,
            sites,
        }
    }

    /// The half-edges of face `f`'s boundary.
    fn cycle(&self, f: FaceId) -> impl Iterator<Item = usize> + '_ {
        let start = self.outer[f];
        let mut h = Some(start);
        std::iter::from_fn(move || {
            let cur = h?;
            let next = self.half[cur as usize][0];
            h = (next != start).then_some(next);
            Some(cur as usize)
        })
    }

    fn origin(&self, h: usize) -> usize {
        self.half[h][1] as usize
    }

    /// The outgoing half-edges of vertex `v` counter-clockwise, from the
    /// arrangement's first ([`Arrangement::outgoing`]'s order), into `out`.
    /// Turning by `next` of the twin goes clockwise, so the turn is
    /// collected and its tail reversed.
    fn outgoing(&self, v: VertexId, out: &mut Vec<usize>) {
        out.clear();
        let first = self.vertex[v][2] as usize;
        out.push(first);
        let mut h = self.half[first ^ 1][0] as usize;
        while h != first {
            out.push(h);
            h = self.half[h ^ 1][0] as usize;
        }
        out[1..].reverse();
    }

    fn face(&self, h: usize) -> FaceId {
        self.half[h][2] as usize
    }

    /// Edge e's ray group and slot on its line, `None` for a map edge.
    fn line(&self, e: usize) -> Option<(usize, u32)> {
        let [g, slot, _] = self.edge[e];
        (g != NONE).then_some((g as usize, slot))
    }
}

/// The skeletons of the lower cells found during the walk (those whose
/// 2-cells were all walked in one part), by index in the walker's sites.
pub(crate) struct Early {
    /// By site: the 2-cell whose skeleton it has, or [`NONE`].
    face: Vec<u32>,
    /// By ascending site: its own skeleton.
    own: Vec<(u32, Compact)>,
}

impl<'a> Walker<'a> {
    /// The walker over `arr`, whose ray groups' lines are `lines`
    /// ([`line_views`]).
    pub(crate) fn new(
        map: &'a Map,
        arr: &'a Arrangement,
        index: &'a VisibilityIndex<'a>,
        edge_lines: &'a EdgeLines,
        lines: Vec<LineView>,
    ) -> Self {
        debug_assert_eq!(lines.len(), arr.ray_groups().len(), "a line per ray group");
        // The order reads the arrangement itself, beside the topology.
        let (topo, order) = rayon::join(|| Topology::new(arr, &lines), || breadth_first(arr));
        let n = map.vertices().len();
        Walker {
            order,
            map,
            edge_lines,
            arr,
            index,
            lines,
            topo,
            views: (0..n).map(|_| OnceLock::new()).collect(),
            reflex: (0..n).map(|i| map.is_reflex(i)).collect(),
            turns: SmallCoords::of(map).map(|c| c.edge_turns()),
        }
    }

    /// The number of 1- and 0-cells.
    pub(crate) fn lower_count(&self) -> usize {
        self.topo.sites.len()
    }

    /// Walk the 2-cells: `corners[f]` are three vertices of face `f` whose
    /// centroid is inside it (`None` for the outer face); the result is
    /// the skeleton of each cell by face id. `progress(done)` is called
    /// on the caller's thread as 2-cells are done.
    ///
    /// The cells are split into one part per thread (consecutive stretches
    /// of a breadth-first order, so a part is few connected pieces), each
    /// walked on its own from one query per piece. The skeleton of a cell
    /// does not depend on which neighbour it was reached from, so the
    /// result is the same for any number of threads.
    pub(crate) fn walk(
        &self,
        corners: &[Option<[VertexId; 3]>],
        progress: &mut dyn FnMut(usize),
    ) -> Walked {
        if self.map.has_holes() {
            return self.walk_by_queries(corners, progress);
        }
        let arr = self.arr;
        let order = &self.order;
        let parts = rayon::current_num_threads()
            .min(order.len() / MIN_PART)
            .max(1);
        let mut part_of = vec![u32::MAX; arr.face_count()];
        let size = order.len().div_ceil(parts);
        for (i, &f) in order.iter().enumerate() {
            part_of[f] = (i / size) as u32;
        }
        let done = AtomicUsize::new(0);
        // One table for all parts: each part writes its own faces and
        // sites, and reads only those.
        let shared = Shared {
            faces: (0..arr.face_count()).map(|_| OnceLock::new()).collect(),
            hashes: (0..arr.face_count()).map(|_| AtomicU64::new(0)).collect(),
            early_face: (0..self.topo.sites.len())
                .map(|_| AtomicU32::new(NONE))
                .collect(),
        };
        // Parts 1.. on the pool's threads, part 0 here, reporting progress.
        let others: Vec<OnceLock<Vec<(u32, Compact)>>> =
            (1..parts).map(|_| OnceLock::new()).collect();
        let range = |p: usize| &order[p * size..((p + 1) * size).min(order.len())];
        let (part_of, done, sh) = (&part_of, &done, &shared);
        let first = rayon::in_place_scope(|scope| {
            for (p, slot) in (1..parts).zip(&others) {
                scope.spawn(move |_| {
                    let own = self.walk_part(range(p), p as u32, part_of, corners, sh, &mut || {
                        done.fetch_add(1, AtomicOrdering::Relaxed);
                    });
                    slot.set(own).expect("each part is walked once");
                });
            }
            self.walk_part(range(0), 0, part_of, corners, sh, &mut || {
                progress(done.fetch_add(1, AtomicOrdering::Relaxed) + 1);
            })
        });
        let mut own = first;
        for other in others {
            own.extend(other.into_inner().expect("walked"));
        }
        own.sort_unstable_by_key(|&(i, _)| i);
        progress(done.load(AtomicOrdering::Relaxed));
        let Shared {
            faces,
            hashes,
            early_face,
        } = shared;
        Walked {
            faces,
            hashes: hashes.into_iter().map(AtomicU64::into_inner).collect(),
            early: Early {
                face: early_face.into_iter().map(AtomicU32::into_inner).collect(),
                own,
            },
        }
    }

    /// Walk the cells of part `part` (`part_of`, by face), starting from
    /// those of `order` not yet reached, into `shared`: the skeleton and
    /// class hash of each, by face id; and the skeleton of each lower cell
    /// whose 2-cells are all in the part, by site, found when the last of
    /// them is walked (while its skeleton is at hand, not in a later pass):
    /// those with a 2-cell's skeleton in `shared`, those with their own
    /// returned.
    ///
    /// Depth first: a cell is walked right after the cell it was reached
    /// from, whose skeleton it starts from, so that one is still in cache.
    fn walk_part(
        &self,
        order: &[FaceId],
        part: u32,
        part_of: &[u32],
        corners: &[Option<[VertexId; 3]>],
        shared: &Shared,
        progress: &mut dyn FnMut(),
    ) -> Vec<(u32, Compact)> {
        let arr = self.arr;
        let faces = &shared.faces;
        // By face: reached (in this part's faces only).
        let mut queued = vec![false; arr.face_count()];
        // Faces to walk (a stack), each with the walked face it was reached
        // from and the line crossed (group, slot, side of the face), if any.
        let mut stack: Vec<(FaceId, Option<Crossed>)> = Vec::new();
        let mut own: Vec<(u32, Compact)> = Vec::new();
        let mut scratch = Scratch::default();
        // Vis of the cell at hand, and what it sees on the line crossed.
        let (mut here, mut seen): (Vec<u32>, Vec<u32>) = (Vec::new(), Vec::new());
        // By vertex off the map boundary: its corners in walked 2-cells.
        let mut corners_walked = vec![0u32; arr.vertex_count()];
        for &start in order {
            if part_of[start] != part || queued[start] {
                continue;
            }
            queued[start] = true;
            stack.push((start, None));
            while let Some((f, from)) = stack.pop() {
                let c = corners[f].expect("a cell");
                let eye = Eye::centroid(arr.pt(c[0]), arr.pt(c[1]), arr.pt(c[2]));
                let sk = match from {
                    Some((p, g, slot, side)) => {
                        let parent = faces[p].get().expect("walked");
                        let bufs = (&mut here, &mut seen);
                        self.across(parent.vis(), &[(g, slot)], Some(side), bufs);
                        self.compact_across(&here, &eye, parent, g)
                    }
                    None => {
                        self.compact(&self.queried(&crate::decomposition::centroid(arr, c)), &eye)
                    }
                };
                for h in self.topo.cycle(f) {
                    let Some((g, slot)) = self.topo.line(h / 2) else {
                        continue;
                    };
                    let t = h ^ 1;
                    let other = self.topo.face(t);
                    if !arr.is_cell(other) || part_of[other] != part || queued[other] {
                        continue;
                    }
                    // Half-edge 2e runs along the group's direction, its
                    // face on the left.
                    let side = if t.is_multiple_of(2) {
                        Beside::Left
                    } else {
                        Beside::Right
                    };
                    queued[other] = true;
                    stack.push((other, Some((f, g, slot, side))));
                }
                shared.hashes[f].store(sk.class_hash(self.edge_lines), AtomicOrdering::Relaxed);
                if faces[f].set(sk).is_err() {
                    unreachable!("each face is walked once");
                }
                // The lower cells whose 2-cells are all walked now (all in
                // this part).
                let topo = &self.topo;
                for h in topo.cycle(f) {
                    let mut found = |i: u32, site: LowerSite| match self.lower_cell(
                        site,
                        faces,
                        &mut scratch,
                    ) {
                        LowerSkeleton::Face(g) => shared.early_face[i as usize].store(
                            u32::try_from(g).expect("fewer than 2^32 faces"),
                            AtomicOrdering::Relaxed,
                        ),
                        LowerSkeleton::Own(c) => own.push((i, c)),
                    };
                    let v = topo.origin(h);
                    let [site, degree, _] = topo.vertex[v];
                    if site != NONE {
                        corners_walked[v] += 1;
                        if corners_walked[v] == degree {
                            found(site, LowerSite::Vertex(v));
                        }
                    }
                    let e = h / 2;
                    let site = topo.edge[e][2];
                    if site != NONE {
                        let other = topo.face(h ^ 1);
                        if other != f && part_of[other] == part && faces[other].get().is_some() {
                            found(site, LowerSite::Edge(e));
                        }
                    }
                }
                progress();
            }
        }
        own
    }

    /// After [`Walker::walk`] (`walked`, `early`): the skeleton of every
    /// 1-cell (edge on a ray) by edge id, then of every 0-cell (vertex off
    /// the map boundary) by vertex id: found in the walk, or else computed
    /// here. Each is handed to `resolve` in parallel, with the 2-cells next
    /// to it (left empty for a [`LowerSkeleton::Face`] found in the walk,
    /// which names its 2-cell); `sink` receives the results a block at a
    /// time, in that order, on the caller's thread.
    pub(crate) fn lower<T: Send>(
        &self,
        walked: &[OnceLock<Compact>],
        early: &Early,
        resolve: impl Fn(LowerSite, &[FaceId], LowerSkeleton) -> T + Sync,
        sink: &mut dyn FnMut(Vec<T>),
    ) {
        for (b, block) in self.topo.sites.chunks(LOWER_BLOCK).enumerate() {
            sink(
                block
                    .par_iter()
                    .enumerate()
                    .map_init(Scratch::default, |scratch, (j, &site)| {
                        let i = b * LOWER_BLOCK + j;
                        if early.face[i] != NONE {
                            let f = early.face[i] as usize;
                            return resolve(site, &[], LowerSkeleton::Face(f));
                        }
                        let own = early
                            .own
                            .binary_search_by_key(&(i as u32), |&(at, _)| at)
                            .ok();
                        let sk = match own {
                            Some(o) => {
                                self.faces_of(site, scratch);
                                LowerSkeleton::Own(early.own[o].1.clone())
                            }
                            None => self.lower_cell(site, walked, scratch),
                        };
                        resolve(site, &scratch.faces, sk)
                    })
                    .collect(),
            );
        }
    }

    /// The skeleton of a lower cell, with the 2-cells next to it left in
    /// `scratch.faces` (in the order of [`Walker::faces_of`]). `walked`
    /// holds the skeletons of those 2-cells at least.
    fn lower_cell(
        &self,
        site: LowerSite,
        walked: &[OnceLock<Compact>],
        scratch: &mut Scratch,
    ) -> LowerSkeleton {
        self.faces_of(site, scratch);
        if self.map.has_holes() {
            let arr = self.arr;
            let q = match site {
                LowerSite::Edge(e) => {
                    let a = arr.point(arr.half_edge(2 * e).origin);
                    RatPoint::midpoint(a, arr.point(arr.dest(2 * e)))
                }
                LowerSite::Vertex(v) => arr.point(v).clone(),
            };
            return LowerSkeleton::Own(self.queried_skeleton(&q));
        }
        let mut lines = std::mem::take(&mut scratch.lines);
        let mut sides = std::mem::take(&mut scratch.sides);
        lines.clear();
        sides.clear();
        match site {
            LowerSite::Edge(e) => {
                lines.push(self.topo.line(e).expect("1-cells lie on rays"));
                // Half-edge 2e runs along the line, its face on the left.
                sides.extend([Beside::Left, Beside::Right]);
            }
            LowerSite::Vertex(_) => {
                let out = &scratch.out;
                lines.extend(out.iter().filter_map(|&h| self.topo.line(h / 2)));
                // The vertex is no event of a line through it, so it shares
                // the slot of the line's edges next to it.
                lines.sort_unstable();
                lines.dedup_by_key(|l| l.0);
                // The face of out[i] fills the corner from out[i] to the
                // next counter-clockwise. Counter-clockwise from the
                // half-edge along a line's direction to the one against
                // it, the corners lie left of the line, the others right.
                // The vertex is off the map boundary and rays start and
                // end on it, so both half-edges exist.
                let k = out.len();
                sides.resize(k * lines.len(), Beside::Right);
                for (j, &(g, _)) in lines.iter().enumerate() {
                    let along = |forward: bool| {
                        out.iter()
                            .position(|&h| {
                                h % 2 == usize::from(!forward)
                                    && self.topo.line(h / 2).is_some_and(|(l, _)| l == g)
                            })
                            .expect("a line through an interior vertex runs both ways")
                    };
                    let (from, to) = (along(true), along(false));
                    let mut i = from;
                    while i != to {
                        sides[i * lines.len() + j] = Beside::Left;
                        i = next(i, k);
                    }
                }
            }
        }
        let sk = self.lower_skeleton(site, walked, &lines, &sides, scratch);
        scratch.lines = lines;
        scratch.sides = sides;
        sk
    }

    /// The 2-cells next to a lower cell into `scratch.faces`: an edge's
    /// left then right face; a vertex's faces counter-clockwise, one per
    /// outgoing half-edge (left in `scratch.out`).
    fn faces_of(&self, site: LowerSite, scratch: &mut Scratch) {
        scratch.faces.clear();
        match site {
            LowerSite::Edge(e) => scratch
                .faces
                .extend([self.topo.face(2 * e), self.topo.face(2 * e + 1)]),
            LowerSite::Vertex(v) => {
                self.topo.outgoing(v, &mut scratch.out);
                let faces = scratch.out.iter().map(|&h| self.topo.face(h));
                scratch.faces.extend(faces);
            }
        }
    }

    /// Vis at a point q on the lines `lines` (ray group and q's slot on
    /// it), or beside the one line on side `beside`, from Vis of a 2-cell
    /// next to q: unchanged off the lines, recomputed on them.
    fn across(
        &self,
        base: &[u32],
        lines: &[(usize, u32)],
        beside: Option<Beside>,
        (out, seen): (&mut Vec<u32>, &mut Vec<u32>),
    ) {
        out.clear();
        if let [(g, slot)] = lines {
            // One line: base minus its vertices, with those seen on it, all
            // ascending. The vertices seen are some of the line's vertices,
            // and off the line Vis is unchanged: base is copied in stretches
            // between the line's vertices, each taken if seen now.
            let line = &self.lines[*g];
            let on = line.vertices();
            seen.clear();
            line.seen_in(*slot as usize, beside, seen);
            seen.sort_unstable();
            seen.dedup();
            let (mut from, mut m) = (0, 0);
            for &u in on {
                let at = from + base[from..].partition_point(|&b| b < u);
                out.extend_from_slice(&base[from..at]);
                from = if base.get(at) == Some(&u) { at + 1 } else { at };
                if seen.get(m) == Some(&u) {
                    out.push(u);
                    m += 1;
                }
            }
            out.extend_from_slice(&base[from..]);
            assert_eq!(m, seen.len(), "the vertices seen on a line lie on it");
            return;
        }
        out.extend(
            base.iter()
                .copied()
                .filter(|&u| lines.iter().all(|&(g, _)| !self.lines[g].contains(u))),
        );
        for &(g, slot) in lines {
            self.lines[g].seen_in(slot as usize, beside, out);
        }
        out.sort_unstable();
        out.dedup();
    }

    /// On a map with holes, the skeleton of every 2-cell by a query at its
    /// point: Vis in ascending ids is boundary order only on a single ring
    /// (sec. 3.9.2's update walks a simple polygon), so the walk of
    /// [`Walker::walk`] is for maps without holes. No lower cell is found
    /// early; [`Walker::lower`] queries each.
    fn walk_by_queries(
        &self,
        corners: &[Option<[VertexId; 3]>],
        progress: &mut dyn FnMut(usize),
    ) -> Walked {
        let arr = self.arr;
        let faces: Vec<OnceLock<Compact>> =
            (0..arr.face_count()).map(|_| OnceLock::new()).collect();
        let hashes: Vec<AtomicU64> = (0..arr.face_count()).map(|_| AtomicU64::new(0)).collect();
        let done = AtomicUsize::new(0);
        for block in self.order.chunks(LOWER_BLOCK) {
            block.par_iter().for_each(|&f| {
                let c = corners[f].expect("a cell");
                let sk = self.queried_skeleton(&crate::decomposition::centroid(arr, c));
                hashes[f].store(sk.class_hash(self.edge_lines), AtomicOrdering::Relaxed);
                if faces[f].set(sk).is_err() {
                    unreachable!("each face is queried once");
                }
                done.fetch_add(1, AtomicOrdering::Relaxed);
            });
            progress(done.load(AtomicOrdering::Relaxed));
        }
        Walked {
            faces,
            hashes: hashes.into_iter().map(AtomicU64::into_inner).collect(),
            early: Early {
                face: vec![NONE; self.topo.sites.len()],
                own: Vec::new(),
            },
        }
    }

    /// The compact skeleton at `q` by a query, in the skeleton's own order
    /// (counter-clockwise from its origin, which is first): for maps with
    /// holes, where [`Compact`]'s Vis is in this order rather than
    /// ascending.
    fn queried_skeleton(&self, q: &RatPoint) -> Compact {
        let vp = self
            .index
            .visibility_polygon(q)
            .unwrap_or_else(|e| panic!("no visibility polygon at the cell point {q}: {e}"));
        let sk = Skeleton::of(self.map, &vp).unwrap_or_else(|e| panic!("no skeleton at {q}: {e}"));
        let vis = sk.map_vertices().iter().map(|&m| m as u32);
        let edges = sk.edges().iter().map(|e| match e {
            SkeletonEdge::Full { .. } => FULL,
            SkeletonEdge::Artificial { map_edge, .. } => *map_edge as u32,
        });
        Compact {
            data: vis.chain(edges).collect(),
            shift: 0,
        }
    }

    /// Vis at a 2-cell's point by a query: the skeleton's map vertices.
    fn queried(&self, q: &RatPoint) -> Vec<u32> {
        let vp = self
            .index
            .visibility_polygon(q)
            .unwrap_or_else(|e| panic!("no visibility polygon at the cell point {q}: {e}"));
        let sk = Skeleton::of(self.map, &vp).unwrap_or_else(|e| panic!("no skeleton at {q}: {e}"));
        let mut vs: Vec<u32> = sk.map_vertices().iter().map(|&m| m as u32).collect();
        vs.sort_unstable();
        vs
    }

    /// The compact skeleton of q from Vis(q) (ascending map ids).
    fn compact(&self, vis: &[u32], eye: &Eye) -> Compact {
        let k = vis.len();
        assert!(k > 0, "a point of the interior sees a map vertex ({eye:?})");
        let mut data = Vec::with_capacity(2 * k);
        data.extend_from_slice(vis);
        data.extend((0..k).map(|s| self.gap(vis[s] as usize, vis[next(s, k)] as usize, k, eye)));
        self.with_origin(data)
    }

    /// [`Walker::compact`] for a 2-cell reached from the 2-cell `parent`
    /// across ray group `g`: the artificial edge of a gap x → y with
    /// neither end on the line, consecutive in both Vis, is the parent's.
    /// Every test of [`Walker::gap`] for it changes sign only on a line
    /// through x or y (the line of edge x or of edge y − 1, or a line from
    /// x through a vertex it sees), and between the two cells only the
    /// line of `g` is crossed.
    fn compact_across(&self, vis: &[u32], eye: &Eye, parent: &Compact, g: usize) -> Compact {
        let (pvis, pedges) = (parent.vis(), parent.edges());
        let (k, pk) = (vis.len(), pvis.len());
        if k < 2 || pk < 2 {
            return self.compact(vis, eye);
        }
        // Off the line both Vis are one list, so the kept gaps come in runs
        // that are runs of the parent's gaps: copied whole. A run from x
        // ends before a vertex of the line, or where the two lists part.
        let on = self.lines[g].vertices();
        let on_line = |x: u32| on.binary_search(&x).is_ok();
        let mut data: Vec<u32> = Vec::with_capacity(2 * k);
        data.extend_from_slice(vis);
        // `m`: the first vertex of the line above x; `j`: x in the parent.
        let (mut s, mut j, mut m) = (0, 0, 0);
        while s < k {
            let x = vis[s];
            while m < on.len() && on[m] <= x {
                m += 1;
            }
            if m > 0 && on[m - 1] == x {
                data.push(self.gap(x as usize, vis[next(s, k)] as usize, k, eye));
                s += 1;
                continue;
            }
            while pvis[j] < x {
                j += 1;
            }
            // Gaps s, s + 1, ... while the next vertices agree and are off
            // the line (all below the line's next vertex).
            let bound = on.get(m).copied().unwrap_or(u32::MAX);
            let below = vis[s + 1..].partition_point(|&u| u < bound);
            let most = below.min(pk - j - 1);
            let r = common_prefix(&vis[s + 1..s + 1 + most], &pvis[j + 1..j + 1 + most]);
            data.extend_from_slice(&pedges[j..j + r]);
            s += r;
            j += r;
            // The gap after the run: the last of Vis (to the first), or to
            // a vertex of the line, or where the lists part.
            let (x, y) = (vis[s], vis[next(s, k)]);
            let kept = !on_line(y) && pvis[next(j, pk)] == y;
            data.push(if kept {
                pedges[j]
            } else {
                self.gap(x as usize, y as usize, k, eye)
            });
            s += 1;
        }
        // The origin: off the line Vis did not change, so a reflex parent
        // origin off it stays first unless a reflex vertex of the line now
        // seen comes before it.
        let po = parent.origin() as u32;
        if self.reflex[po as usize] && !self.lines[g].contains(po) {
            let v = self.map.vertices();
            let at = |u: u32| (v[u as usize].x, v[u as usize].y);
            let mut best = po;
            for &u in on {
                if self.reflex[u as usize] && at(u) < at(best) && vis.binary_search(&u).is_ok() {
                    best = u;
                }
            }
            let shift = vis.binary_search(&best).expect("the origin is seen");
            return Compact {
                data: data.into_boxed_slice(),
                shift: u32::try_from(shift).expect("fewer than 2^32 vertices"),
            };
        }
        self.with_origin(data)
    }

    /// The compact skeleton from Vis and its edges in Vis order (`data`),
    /// with the origin: the leftmost, then lowest, of the reflex vertices
    /// seen, else of all seen.
    fn with_origin(&self, data: Vec<u32>) -> Compact {
        let v = self.map.vertices();
        let vis = &data[..data.len() / 2];
        let k = vis.len();
        let pick = |pool: &mut dyn Iterator<Item = usize>| {
            pool.min_by_key(|&s| {
                let p: Point = v[vis[s] as usize];
                (p.x, p.y)
            })
        };
        let o = pick(&mut (0..k).filter(|&s| self.reflex[vis[s] as usize]))
            .or_else(|| pick(&mut (0..k)))
            .expect("k > 0");
        Compact {
            data: data.into_boxed_slice(),
            shift: u32::try_from(o).expect("fewer than 2^32 vertices"),
        }
    }

    /// The skeleton edge from x to the next vertex y that q sees (`k` of
    /// them): [`FULL`], else the map edge the artificial edge lies on
    /// (cases 1–3 of the module documentation).
    fn gap(&self, x: usize, y: usize, k: usize, eye: &Eye) -> u32 {
        let v = self.map.vertices();
        let n = v.len();
        // Whether q lies left of map edge e.
        let left_of = |e: usize| match self.turns.as_ref().zip(eye.narrow()) {
            Some((turns, q)) => turns.left(e, q),
            None => eye.orientation(v[e], v[self.map.next(e)]) == Orientation::CounterClockwise,
        };
        let e = if y == next(x, n) && k > 1 {
            return FULL;
        } else if left_of(x) {
            x
        } else if left_of(back(y, 1, n)) {
            back(y, 1, n)
        } else {
            self.beyond(x, eye)
        };
        e as u32
    }

    /// The point of a lower cell where its skeleton is computed: the
    /// midpoint of an edge, the vertex itself.
    fn site_eye(&self, site: LowerSite) -> Eye {
        let arr = self.arr;
        match site {
            LowerSite::Edge(e) => {
                Eye::midpoint(arr.pt(arr.half_edge(2 * e).origin), arr.pt(arr.dest(2 * e)))
            }
            LowerSite::Vertex(v) => Eye::at(arr.pt(v)),
        }
    }

    /// The skeleton at the point q of a lower cell on `lines` that sees
    /// what 2-cell `f` (skeleton `face`) sees: the same vertices and
    /// origin, and the same artificial edges except at some gaps x → y with
    /// an end on the lines, which are tested again at q.
    ///
    /// A test of [`Walker::gap`] has the same sign at q as in the open
    /// 2-cell unless q lies on the test's line, and such a line is a ray
    /// line through q, hence one of `lines`: the line of edge x (q sees x,
    /// so q lies on its extension beyond x, a ray from x), that of edge
    /// y − 1 (a ray from y along it), or a line from x through a vertex x
    /// sees (the ray from x beyond it). So a gap is tested again only if x
    /// lies on one of the lines, or y and y − 1 lie on one. A vertex of Vis
    /// on a line through q is the nearest one that way: one of `near`.
    ///
    /// `at`: where each of `near` sits in f's Vis.
    #[allow(clippy::too_many_arguments)]
    fn relabel(
        &self,
        f: FaceId,
        face: &Compact,
        near: &[u32],
        at: &[usize],
        site: LowerSite,
        lines: &[(usize, u32)],
        touched: &mut Vec<usize>,
    ) -> LowerSkeleton {
        let v = self.map.vertices();
        let n = v.len();
        let along = |a: usize, b: usize| {
            lines.iter().any(|&(g, _)| {
                let l = &self.lines[g];
                l.passes(v[a]) && l.passes(v[b])
            })
        };
        // The gaps at the vertices of the lines that f sees (those the cell
        // sees on them, `near`), before and after each in Vis.
        let (vis, edges) = (face.vis(), face.edges());
        let k = vis.len();
        touched.clear();
        for &j in at {
            touched.extend([j, back(j, 1, k)]);
        }
        touched.sort_unstable();
        touched.dedup();
        let mut eye: Option<Eye> = None;
        let mut own: Option<Compact> = None;
        for &s in touched.iter() {
            let (x, y) = (vis[s] as usize, vis[next(s, k)] as usize);
            if edges[s] == FULL || !(near.contains(&(x as u32)) || along(back(y, 1, n), y)) {
                continue;
            }
            let eye = eye.get_or_insert_with(|| self.site_eye(site));
            let e = self.gap(x, y, k, eye);
            if e != edges[s] {
                own.get_or_insert_with(|| face.clone()).edges_mut()[s] = e;
            }
        }
        match own {
            Some(c) => LowerSkeleton::Own(c),
            None => LowerSkeleton::Face(f),
        }
    }

    /// The skeleton of a 1- or 0-cell on `lines` (ray group and the cell's
    /// slot on it), next to the 2-cells `scratch.faces` (all cells), each
    /// on sides `sides[i * lines.len()..]` of the lines.
    ///
    /// Off its lines the cell sees what its 2-cells see, so its Vis equals
    /// Vis of 2-cell f exactly when the vertices f sees on the lines are
    /// those the cell sees on them, the nearest each way: when from f's
    /// side of each line the view along it stops at them
    /// ([`LineView::sees_past`]). Then f's skeleton is relabelled;
    /// otherwise Vis is built and its skeleton computed.
    fn lower_skeleton(
        &self,
        site: LowerSite,
        walked: &[OnceLock<Compact>],
        lines: &[(usize, u32)],
        sides: &[Beside],
        scratch: &mut Scratch,
    ) -> LowerSkeleton {
        let Scratch {
            near,
            at,
            touched,
            faces,
            ..
        } = scratch;
        near.clear();
        for &(g, slot) in lines {
            self.lines[g].seen_in(slot as usize, None, near);
        }
        near.sort_unstable();
        near.dedup();
        let mut same = None;
        for (i, &f) in faces.iter().enumerate() {
            let Some(sk) = walked[f].get() else {
                continue;
            };
            let side = &sides[i * lines.len()..(i + 1) * lines.len()];
            // (That f sees the near vertices is the T3.3b checker's to
            // test; here it only may not panic.)
            if lines
                .iter()
                .zip(side)
                .any(|(&(g, slot), &b)| self.lines[g].sees_past(slot as usize, b))
            {
                continue;
            }
            at.clear();
            for u in near.iter() {
                match sk.vis().binary_search(u) {
                    Ok(j) => at.push(j),
                    Err(_) => break,
                }
            }
            if at.len() == near.len() {
                same = Some((f, sk));
                break;
            }
        }
        match same {
            Some((f, sk)) => self.relabel(f, sk, near, at, site, lines, touched),
            None => {
                let base = walked[faces[0]]
                    .get()
                    .expect("the cells next to a lower cell are walked");
                let mut seen = Vec::new();
                self.across(base.vis(), lines, None, (&mut seen, &mut Vec::new()));
                LowerSkeleton::Own(self.compact(&seen, &self.site_eye(site)))
            }
        }
    }

    /// The map edge the ray from q through x meets beyond x, taken just
    /// counter-clockwise of the ray.
    fn beyond(&self, x: usize, eye: &Eye) -> usize {
        let view = self.views[x].get_or_init(|| self.index.vertex_view(x));
        let v = self.map.vertices();
        // x − q, scaled by W > 0: the opposite of the direction to x.
        let d = eye.toward(v[x]);
        let base = dir(v[x], v[view[0].0]);
        let at = view.partition_point(|&(lo, _)| {
            angle_cmp(&base, &dir(v[x], v[lo]), &d) != std::cmp::Ordering::Greater
        });
        assert!(
            at > 0,
            "the ray from {eye:?} through map vertex {x} does not enter the map beyond it"
        );
        view[at - 1].1
    }
}

/// The cells in breadth-first order across ray edges, from each cell
/// not yet reached (the interior of the map is connected and cells
/// meet across ray edges, so the first one reaches all).
fn breadth_first(arr: &Arrangement) -> Vec<FaceId> {
    let mut seen = vec![false; arr.face_count()];
    let mut order = Vec::with_capacity(arr.face_count());
    for start in arr.cells() {
        if seen[start] {
            continue;
        }
        seen[start] = true;
        let mut i = order.len();
        order.push(start);
        while i < order.len() {
            let f = order[i];
            i += 1;
            for h in arr.face_cycle(f) {
                if let Support::Rays(_) = arr.edge_support(h / 2) {
                    let other = arr.half_edge(h ^ 1).face;
                    if arr.is_cell(other) && !seen[other] {
                        seen[other] = true;
                        order.push(other);
                    }
                }
            }
        }
    }
    order
}

/// How the walk reached a 2-cell: from a walked 2-cell, across a ray
/// group's line in a slot, onto a side of it.
type Crossed = (FaceId, usize, u32, Beside);

/// Cells per part of the walk, at least.
const MIN_PART: usize = 256;

/// What the parts of the walk write, each to its own faces and sites:
/// by face, the skeleton and class hash; by site, the 2-cell whose
/// skeleton a lower cell found in the walk has.
struct Shared {
    faces: Vec<OnceLock<Compact>>,
    hashes: Vec<AtomicU64>,
    early_face: Vec<AtomicU32>,
}

/// The walk's results: by face, the skeleton and its class hash
/// ([`Compact::class_hash`]); the lower cells' skeletons found on the way.
pub(crate) struct Walked {
    pub(crate) faces: Vec<OnceLock<Compact>>,
    pub(crate) hashes: Vec<u64>,
    pub(crate) early: Early,
}

/// Lower cells computed in parallel between two calls of the sink.
const LOWER_BLOCK: usize = 1 << 13;

/// Buffers reused from lower cell to lower cell.
#[derive(Default)]
struct Scratch {
    /// The vertices seen on the cell's lines, and where each sits in a
    /// 2-cell's Vis.
    near: Vec<u32>,
    at: Vec<usize>,
    /// Gaps of a 2-cell's skeleton to test again.
    touched: Vec<usize>,
    /// The 2-cells next to the cell ([`Walker::faces_of`]).
    faces: Vec<FaceId>,
    /// A vertex's outgoing half-edges.
    out: Vec<usize>,
    /// The cell's lines and slots, and each face's side of each line.
    lines: Vec<(usize, u32)>,
    sides: Vec<Beside>,
}

/// The length of the longest common prefix of `a` and `b` (equally long),
/// compared eight at a time first.
fn common_prefix(a: &[u32], b: &[u32]) -> usize {
    let mut i = 0;
    for (x, y) in a.chunks_exact(8).zip(b.chunks_exact(8)) {
        if x != y {
            break;
        }
        i += 8;
    }
    i + a[i..]
        .iter()
        .zip(&b[i..])
        .take_while(|(x, y)| x == y)
        .count()
}

/// `(i + 1) mod k` for `i < k`, without a division (hot loops).
#[inline]
pub(crate) fn next(i: usize, k: usize) -> usize {
    if i + 1 == k {
        0
    } else {
        i + 1
    }
}

/// `(i − d) mod k` for `i, d < k`, without a division.
#[inline]
fn back(i: usize, d: usize, k: usize) -> usize {
    if i >= d {
        i - d
    } else {
        i + k - d
    }
}
