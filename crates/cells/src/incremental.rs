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

use crate::arrangement::{Arrangement, FaceId, Support, VertexId};
use crate::decomposition::LowerSite;
use crate::eye::{angle_cmp, dir, Eye};
use crate::fx::FxHashMap;
use crate::line_view::{Beside, LineView};
use rug::Rational;
use std::collections::{HashMap, VecDeque};
use wai_exact::{Orientation, Point, RatPoint};
use wai_map::Map;
use wai_visibility::{LineLabel, Skeleton, SkeletonKey, VisibilityIndex};

/// A skeleton in map terms: its vertices (map vertex ids) from the origin,
/// and for each edge `None` (full) or the id of the line of the map edge an
/// artificial edge lies on. Equal compact skeletons are equal skeletons in
/// the same embedding; the converse holds too, since line ids identify
/// lines (collinear map edges share one).
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct Compact {
    pub(crate) vertices: Vec<u32>,
    pub(crate) lines: Vec<Option<u32>>,
    /// By edge: the map edge of an artificial edge (for the key's label).
    edges: Vec<Option<u32>>,
}

impl Compact {
    /// The origin map vertex.
    pub(crate) fn origin(&self) -> usize {
        self.vertices[0] as usize
    }

    /// The canonical key (as [`Skeleton::key`] would give it).
    pub(crate) fn key(&self, map: &Map) -> SkeletonKey {
        let v = map.vertices();
        let n = v.len();
        let o = v[self.origin()];
        SkeletonKey {
            offsets: self
                .vertices
                .iter()
                .map(|&u| {
                    let p = v[u as usize];
                    (p.x - o.x, p.y - o.y)
                })
                .collect(),
            labels: self
                .edges
                .iter()
                .map(|e| {
                    e.map(|e| {
                        let e = e as usize;
                        LineLabel::through(v[e], v[(e + 1) % n], o)
                    })
                })
                .collect(),
        }
    }
}

/// Receives each 1- or 0-cell: where it is, its point, the 2-cells next
/// to it and its skeleton.
pub(crate) type LowerSink<'s> = dyn FnMut(LowerSite, RatPoint, &[FaceId], Compact) + 's;

/// The skeletons of all cells of an arrangement, by walking it.
pub(crate) struct Walker<'a> {
    map: &'a Map,
    arr: &'a Arrangement,
    index: &'a VisibilityIndex<'a>,
    /// By ray group.
    lines: Vec<LineView>,
    /// By map edge: the id of its line.
    edge_line: Vec<u32>,
    /// Views from map vertices, computed when first needed.
    views: FxHashMap<usize, Vec<(usize, usize)>>,
    /// By map vertex: reflex in the map.
    reflex: Vec<bool>,
    /// By face id, after the walk: Vis of each cell (ascending map ids).
    vis: Vec<Option<Vec<u32>>>,
}

impl<'a> Walker<'a> {
    pub(crate) fn new(map: &'a Map, arr: &'a Arrangement, index: &'a VisibilityIndex<'a>) -> Self {
        let lines = arr
            .ray_groups()
            .iter()
            .map(|g| LineView::new(map, arr.rays()[g.rays[0]].source(), g.dir))
            .collect();
        let v = map.vertices();
        let n = v.len();
        let mut ids: HashMap<crate::rays::LineKey, u32> = HashMap::new();
        let edge_line = (0..n)
            .map(|i| {
                let l = wai_exact::Line::new(v[i], v[(i + 1) % n]).expect("distinct vertices");
                let k = crate::rays::LineKey::of(&l);
                let next = ids.len() as u32;
                *ids.entry(k).or_insert(next)
            })
            .collect();
        Walker {
            map,
            arr,
            index,
            lines,
            edge_line,
            views: FxHashMap::default(),
            vis: Vec::new(),
            reflex: (0..n).map(|i| map.is_reflex(i)).collect(),
        }
    }

    /// Walk the 2-cells: `reps[f]` is the representative point of face `f`
    /// (`None` for the outer face); the result is the skeleton of each cell
    /// by face id. `progress(done)` is called after each 2-cell.
    pub(crate) fn walk(
        &mut self,
        reps: &[Option<RatPoint>],
        progress: &mut dyn FnMut(usize),
    ) -> Vec<Option<Compact>> {
        let arr = self.arr;
        let nf = arr.face_count();
        let mut vis: Vec<Option<Vec<u32>>> = vec![None; nf];
        let mut faces: Vec<Option<Compact>> = vec![None; nf];
        let mut queue = VecDeque::new();
        let mut done = 0;
        // Every cell is reached from the first one: the interior of the
        // map is connected and cells meet across ray edges.
        for start in arr.cells() {
            if vis[start].is_some() {
                continue;
            }
            let rep = reps[start].as_ref().expect("cells have a point");
            vis[start] = Some(self.queried(rep));
            queue.push_back(start);
            while let Some(f) = queue.pop_front() {
                let here = vis[f].clone().expect("queued faces have Vis");
                faces[f] = Some(self.compact(&here, reps[f].as_ref().expect("a cell")));
                done += 1;
                progress(done);
                for h in arr.face_half_edges(f) {
                    let Support::Rays(g) = arr.edge_support(h / 2) else {
                        continue;
                    };
                    let t = arr.half_edge(h).twin;
                    let other = arr.half_edge(t).face;
                    if other == arr.outer_face() || vis[other].is_some() {
                        continue;
                    }
                    // Half-edge 2e runs along the group's direction, its
                    // face on the left.
                    let side = if t.is_multiple_of(2) {
                        Beside::Left
                    } else {
                        Beside::Right
                    };
                    let mid = RatPoint::midpoint(
                        arr.point(arr.half_edge(h).origin),
                        arr.point(arr.dest(h)),
                    );
                    vis[other] = Some(self.across(&here, &[g], &mid, Some(side)));
                    queue.push_back(other);
                }
            }
        }

        self.vis = vis;
        faces
    }

    /// After [`Walker::walk`]: the skeleton of every 1-cell (edge on a
    /// ray, at its midpoint) by edge id, then of every 0-cell (vertex off
    /// the map boundary) by vertex id, handed to `sink` one at a time with
    /// its point and the 2-cells next to it.
    pub(crate) fn lower(&mut self, walked: &[Option<Compact>], sink: &mut LowerSink<'_>) {
        let arr = self.arr;
        for e in 0..arr.edge_count() {
            let Support::Rays(g) = arr.edge_support(e) else {
                continue;
            };
            let f = arr.half_edge(2 * e).face;
            let mid = RatPoint::midpoint(
                arr.point(arr.half_edge(2 * e).origin),
                arr.point(arr.dest(2 * e)),
            );
            let faces = [f, arr.half_edge(2 * e + 1).face];
            let sk = self.lower_skeleton(&faces, walked, &[g], &mid);
            sink(LowerSite::Edge(e), mid, &faces, sk);
        }
        for v in 0..arr.vertex_count() {
            if arr.is_on_map_boundary(v) {
                continue;
            }
            let groups = self.lines_through(v);
            let p = arr.point(v).clone();
            let faces = arr.faces_around(v);
            let sk = self.lower_skeleton(&faces, walked, &groups, &p);
            sink(LowerSite::Vertex(v), p, &faces, sk);
        }
    }

    /// The ray groups through the interior vertex `v`.
    fn lines_through(&self, v: VertexId) -> Vec<usize> {
        let arr = self.arr;
        let out = arr.outgoing(v);
        let mut groups: Vec<usize> = out
            .iter()
            .filter_map(|&h| match arr.edge_support(h / 2) {
                Support::Rays(g) => Some(g),
                Support::MapEdge(_) => None,
            })
            .collect();
        groups.sort_unstable();
        groups.dedup();
        groups
    }

    /// Vis at q, on the lines `groups` (or beside the one line, on
    /// `beside`), from Vis of a 2-cell next to q: unchanged off the lines,
    /// recomputed on them.
    fn across(
        &self,
        base: &[u32],
        groups: &[usize],
        q: &RatPoint,
        beside: Option<Beside>,
    ) -> Vec<u32> {
        let mut out: Vec<u32> = base
            .iter()
            .copied()
            .filter(|&u| groups.iter().all(|&g| !self.lines[g].contains(u)))
            .collect();
        for &g in groups {
            let l = &self.lines[g];
            let t: Rational = l.position_of(q);
            l.seen_from(&t, beside, &mut out);
        }
        out.sort_unstable();
        out.dedup();
        out
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
    fn compact(&mut self, vis: &[u32], q: &RatPoint) -> Compact {
        let map = self.map;
        let v = map.vertices();
        let k = vis.len();
        assert!(k > 0, "a point of the interior sees a map vertex ({q})");
        let eye = Eye::new(q);
        let mut edges: Vec<Option<u32>> = Vec::with_capacity(k);
        for s in 0..k {
            let (x, y) = (vis[s] as usize, vis[(s + 1) % k] as usize);
            edges.push(self.gap(x, y, k, &eye, q));
        }
        // The origin: leftmost, then lowest, of the reflex vertices seen,
        // else of all seen.
        let pick = |pool: &mut dyn Iterator<Item = usize>| {
            pool.min_by_key(|&s| {
                let p: Point = v[vis[s] as usize];
                (p.x, p.y)
            })
        };
        let o = pick(&mut (0..k).filter(|&s| self.reflex[vis[s] as usize]))
            .or_else(|| pick(&mut (0..k)))
            .expect("k > 0");
        let mut vertices = vis.to_vec();
        vertices.rotate_left(o);
        edges.rotate_left(o);
        let lines = edges
            .iter()
            .map(|e| e.map(|e| self.edge_line[e as usize]))
            .collect();
        Compact {
            vertices,
            lines,
            edges,
        }
    }

    /// The skeleton edge from x to the next vertex y that q sees (`k` of
    /// them): `None` if full, else the map edge the artificial edge lies on
    /// (cases 1–3 of the module documentation).
    fn gap(&mut self, x: usize, y: usize, k: usize, eye: &Eye, q: &RatPoint) -> Option<u32> {
        let v = self.map.vertices();
        let n = v.len();
        let e = if y == (x + 1) % n && k > 1 {
            return None;
        } else if eye.orientation(v[x], v[(x + 1) % n]) == Orientation::CounterClockwise {
            x
        } else if eye.orientation(v[(y + n - 1) % n], v[y]) == Orientation::CounterClockwise {
            (y + n - 1) % n
        } else {
            self.beyond(x, eye, q)
        };
        Some(e as u32)
    }

    /// The skeleton at a point q of a 1- or 0-cell on the lines `groups`
    /// that sees what the 2-cell with skeleton `face` sees: the same
    /// vertices and origin, and the same artificial edges except where the
    /// gap's ends lie on one of the lines. Elsewhere every test of
    /// [`Walker::gap`] has the same sign at q as in the open 2-cell: a line
    /// through a vertex x that q sees, on which q lies, is a ray line
    /// through x (q on the extension of edge x, or on the line from a vertex
    /// x sees through x), and the only ray lines through q are `groups`.
    fn relabel(&mut self, face: &Compact, groups: &[usize], q: &RatPoint) -> Compact {
        let on = |u: u32| groups.iter().any(|&g| self.lines[g].contains(u));
        let k = face.vertices.len();
        let touched: Vec<usize> = (0..k)
            .filter(|&s| on(face.vertices[s]) || on(face.vertices[(s + 1) % k]))
            .collect();
        let mut out = face.clone();
        if touched.is_empty() {
            return out;
        }
        let eye = Eye::new(q);
        for s in touched {
            let (x, y) = (
                face.vertices[s] as usize,
                face.vertices[(s + 1) % k] as usize,
            );
            let e = self.gap(x, y, k, &eye, q);
            out.edges[s] = e;
            out.lines[s] = e.map(|e| self.edge_line[e as usize]);
        }
        out
    }

    /// The skeleton at q of a 1- or 0-cell on the lines `groups`, next to
    /// the 2-cells `faces` (all cells).
    ///
    /// Off its lines q sees what its 2-cells see, so Vis(q) equals Vis of
    /// 2-cell f exactly when the vertices f sees on the lines are those q
    /// sees on them (the nearest each way): a test on the few vertices of
    /// the lines, not on all of Vis. Then f's skeleton is relabelled;
    /// otherwise Vis(q) is built and its skeleton computed.
    fn lower_skeleton(
        &mut self,
        faces: &[FaceId],
        walked: &[Option<Compact>],
        groups: &[usize],
        q: &RatPoint,
    ) -> Compact {
        let mut near: Vec<u32> = Vec::new();
        for &g in groups {
            let l = &self.lines[g];
            l.seen_from(&l.position_of(q), None, &mut near);
        }
        near.sort_unstable();
        near.dedup();
        for &f in faces {
            if let (Some(vis), Some(sk)) = (&self.vis[f], &walked[f]) {
                let mut seen_on: Vec<u32> = groups
                    .iter()
                    .flat_map(|&g| self.lines[g].vertices())
                    .copied()
                    .filter(|u| vis.binary_search(u).is_ok())
                    .collect();
                seen_on.sort_unstable();
                if seen_on == near {
                    let sk = sk.clone();
                    return self.relabel(&sk, groups, q);
                }
            }
        }
        let base = self.vis[faces[0]]
            .take()
            .expect("the cells next to a lower cell are walked");
        let seen = self.across(&base, groups, q, None);
        self.vis[faces[0]] = Some(base);
        self.compact(&seen, q)
    }

    /// The map edge the ray from q through x meets beyond x, taken just
    /// counter-clockwise of the ray.
    fn beyond(&mut self, x: usize, eye: &Eye, q: &RatPoint) -> usize {
        let index = self.index;
        let view = self.views.entry(x).or_insert_with(|| index.vertex_view(x));
        let v = self.map.vertices();
        // x − q, scaled by W > 0: the opposite of the direction to x.
        let d = eye.toward(v[x]);
        let base = dir(v[x], v[view[0].0]);
        let at = view.partition_point(|&(lo, _)| {
            angle_cmp(&base, &dir(v[x], v[lo]), &d) != std::cmp::Ordering::Greater
        });
        assert!(
            at > 0,
            "the ray from {q} through map vertex {x} does not enter the map beyond it"
        );
        view[at - 1].1
    }
}
