//! The visibility cell decomposition as one value: rays, arrangement, the
//! skeleton of every cell of every dimension (Def 3.9) and the equivalence
//! classes of cells (Def 3.10); the boundary assignment (sec. 3.6) when
//! asked for.

use crate::arrangement::{Arrangement, EdgeId, FaceId, HalfEdgeId, VertexId};
use crate::assignment::BoundaryAssignment;
use crate::eye::{Eye, PointRef};
use crate::fx::HashChains;
use crate::incremental::{line_views, Compact, EdgeLines, LowerSkeleton, Walked, Walker};
use crate::rays::{visibility_rays, VisibilityRay};
use rayon::prelude::*;
use rug::Integer;
use std::cmp::Ordering;
use std::sync::OnceLock;
use wai_exact::RatPoint;
use wai_map::Map;
use wai_visibility::{SkeletonKey, VisibilityIndex};

/// Marks the outer face in the face → cell position table.
const NOT_A_CELL: usize = usize::MAX;

/// The visibility cell decomposition of a map (Def 3.8) with the skeleton
/// of each cell (Def 3.9) and its equivalence classes (Def 3.10).
///
/// Built in one pass: [`visibility_rays`], [`Arrangement::new`], then for
/// every cell its skeleton, found by walking the arrangement from one
/// visibility query (sec. 3.9.2: crossing an edge on a ray line changes the
/// visibility of the map vertices on that line only; see the `incremental`
/// module).
/// Cells with equal skeletons (equal canonical [`SkeletonKey`]s) form a
/// class. Skeletons are compared in map terms, up to translation, exactly
/// and without building their keys; the keys
/// ([`Decomposition::skeletons`]) and the cells' exact interior points
/// ([`Decomposition::representative`]) are built when first asked for.
///
/// # Cells of every dimension
/// The decomposition has open cells of dimension 2 (the faces, "cells" in
/// the thesis's sense and in the names below), 1 (the arrangement edges on
/// rays) and 0 (the arrangement vertices inside the map): see
/// [`LowerCell`]. A lower-dimensional cell with the skeleton of an adjacent
/// 2-cell, in the same embedding, is absorbed by it; the others are cells
/// of their own and join the class of their skeleton
/// ([`Decomposition::class_lower_cells`]). This replaces the sec. 3.6
/// boundary assignment, which cannot give every boundary point a cell with
/// its skeleton (claim A3.6, `counterexamples/T3.3b-doorway-1d-cell.json`);
/// the assignment is still computed and reported by the arrangement, when
/// first asked for ([`Decomposition::assignment`], [`Counts::conflicts`]).
///
/// # Edge cases
/// - The skeleton of a cell is computed at one point (an interior point of
///   a 2-cell, the midpoint of a 1-cell); T3.3b says every point of the
///   cell has the same skeleton. The T3.3b checker compares the skeletons
///   this walk gives with fresh visibility queries at points of every cell.
/// - Counts follow the arrangement: a cell's size is the number of
///   arrangement vertices on its boundary, including vertices where the
///   boundary goes straight on (a ray ending in the middle of a map edge
///   splits it for both incident cells). See
///   [`Decomposition::total_complexity`].
/// - Classes are ordered by their first cell, cells by face id: both orders
///   are deterministic for a given map.
///
/// ```
/// use wai_cells::Decomposition;
/// use wai_exact::Point;
/// use wai_map::Map;
/// // The L room: 5 cells, each seeing a different set of map vertices, so
/// // 5 classes of one cell each.
/// let ring = [(0, 0), (4, 0), (4, 2), (2, 2), (2, 4), (0, 4)];
/// let map = Map::from_ring(ring.iter().map(|&(x, y)| Point::new(x, y)).collect()).unwrap().0;
/// let d = Decomposition::new(&map);
/// assert_eq!(d.cells().len(), 5);
/// assert_eq!(d.total_complexity(), 2 * d.cells().iter().map(|&c| d.cell_size(c)).sum::<usize>());
/// let c = d.counts();
/// assert_eq!((c.n, c.r, c.cells, c.classes), (6, 1, 5, 5));
/// let sq = d.cells()[0]; // (0, 0), (2, 0), (2, 2), (0, 2): sees all 6 vertices
/// assert_eq!(d.skeletons()[d.skeleton_of(sq)].offsets.len(), 6);
/// ```
///
/// # Panics
/// If the visibility code fails at a representative point (an interior
/// point of the map, so only on a bug in `wai_visibility`).
#[derive(Clone, Debug)]
pub struct Decomposition<'m> {
    map: &'m Map,
    arrangement: Arrangement,
    cells: Vec<FaceId>,
    /// Face id → position in `cells` (NOT_A_CELL for the outer face).
    position: Vec<usize>,
    /// By cell position.
    sizes: Vec<usize>,
    /// By cell position: three non-collinear boundary vertices, whose
    /// centroid is the representative.
    corners: Vec<[VertexId; 3]>,
    /// By cell position: the representatives, built when first asked for.
    representatives: OnceLock<Vec<RatPoint>>,
    /// By cell position: index into `skeletons`.
    skeleton_index: Vec<usize>,
    /// By cell position: the map vertex that is the skeleton's origin v0.
    origins: Vec<usize>,
    /// By class: the compact skeleton of one of its cells.
    class_skeletons: Vec<Compact>,
    /// The keys of `class_skeletons`, built when first asked for.
    skeletons: OnceLock<Vec<SkeletonKey>>,
    classes: Vec<Vec<FaceId>>,
    class_complexity: Vec<usize>,
    /// The 1-cells (ray edges), then the 0-cells (interior vertices).
    lower: Vec<LowerCell>,
    /// By class: indices into `lower` of its kept lower-dimensional cells.
    class_lower: Vec<Vec<usize>>,
}

/// A cell of dimension 1 or 0: where it lies in the arrangement.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum LowerSite {
    /// The open arrangement edge `e`, which lies on visibility rays.
    Edge(EdgeId),
    /// The arrangement vertex `v`, in the interior of the map.
    Vertex(VertexId),
}

/// A cell of dimension 1 or 0 of the decomposition (DESIGN "Degenerate
/// cases", claims T3.3b and A3.6): an open edge of the arrangement on
/// visibility rays, or an arrangement vertex inside the map, with its own
/// skeleton.
///
/// It is **absorbed** by an adjacent 2-cell whose skeleton, in the same
/// embedding (the same origin map vertex), is its own: then its points
/// belong to that 2-cell, as the sec. 3.6 rule intends where it works.
/// Otherwise it is **kept**, a cell of its own in the class of its skeleton.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LowerCell {
    pub site: LowerSite,
    /// Its skeleton's index in [`Decomposition::skeletons`] (= its class).
    pub class: usize,
    /// The map vertex that is its skeleton's origin v0: with `class`, the
    /// skeleton in its embedding.
    pub origin: usize,
    /// The adjacent 2-cell that absorbs it, if any.
    pub absorbed_by: Option<FaceId>,
}

impl LowerCell {
    /// 1 for an edge, 0 for a vertex.
    pub fn dimension(&self) -> u8 {
        match self.site {
            LowerSite::Edge(_) => 1,
            LowerSite::Vertex(_) => 0,
        }
    }
}

/// Cells of one dimension: those that are cells of their own and those
/// an adjacent 2-cell absorbs.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct KeptAbsorbed {
    pub kept: usize,
    pub absorbed: usize,
}

/// The counts the snapshots keep and the sweep plots, from
/// [`Decomposition::counts`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Counts {
    /// Map vertices.
    pub n: usize,
    /// Reflex map vertices.
    pub r: usize,
    /// Visibility rays (Def 3.8), before merging collinear ones.
    pub rays: usize,
    /// Cells: bounded faces of the arrangement.
    pub cells: usize,
    /// N (Thm 3.9): total vertices and edges of all cells; see
    /// [`Decomposition::total_complexity`].
    pub total_complexity: usize,
    /// Equivalence classes (Def 3.10): distinct skeletons of the cells of
    /// every dimension (a kept 1- or 0-cell may have a skeleton no 2-cell
    /// has).
    pub classes: usize,
    /// max |EC| over the classes (Def 3.10, Thm 3.10, Thm 5.17), counting
    /// the 2-cells as the thesis does.
    pub max_class_complexity: usize,
    /// Vertices of the arrangement.
    pub vertices: usize,
    /// Edges of the arrangement.
    pub edges: usize,
    /// Boundary pieces two rays assign to different cells (sec. 3.6).
    pub conflicts: usize,
    /// 1-cells (arrangement edges on rays), kept and absorbed.
    pub one_cells: KeptAbsorbed,
    /// 0-cells (arrangement vertices inside the map), kept and absorbed.
    pub zero_cells: KeptAbsorbed,
}

impl<'m> Decomposition<'m> {
    /// Rays, arrangement, the skeleton of every cell (Def 3.9) and the
    /// equivalence classes (Def 3.10).
    pub fn new(map: &'m Map) -> Decomposition<'m> {
        Decomposition::with_progress(map, &mut |_, _| {})
    }

    /// Same as [`Decomposition::new`], reporting progress over the cells of
    /// every dimension (2-cells first, then 1- and 0-cells):
    /// `progress(done_cells, total_cells)` is called once before the first
    /// skeleton (with `done_cells = 0`), about every 1% of the cells, and
    /// once at the end (with `done_cells = total_cells`).
    pub fn with_progress(
        map: &'m Map,
        progress: &mut dyn FnMut(usize, usize),
    ) -> Decomposition<'m> {
        Decomposition::from_rays(map, visibility_rays(map), progress)
    }

    /// Same as [`Decomposition::with_progress`], from the rays of `map`
    /// (`visibility_rays(map)`) computed already, e.g. for a size estimate.
    pub fn from_rays(
        map: &'m Map,
        rays: Vec<VisibilityRay>,
        progress: &mut dyn FnMut(usize, usize),
    ) -> Decomposition<'m> {
        // The lines of the ray groups for the walk, beside the arrangement.
        let (arrangement, line_views) =
            Arrangement::from_rays_beside(map, rays, |groups, rays| line_views(map, groups, rays));
        let cells: Vec<FaceId> = arrangement.cells().collect();
        let total = cells.len();
        let mut position = vec![NOT_A_CELL; arrangement.face_count()];
        for (i, &f) in cells.iter().enumerate() {
            position[f] = i;
        }
        let index = VisibilityIndex::new(map);
        let lines = EdgeLines::new(map);
        // The walker's topology is mostly sequential: beside it, each
        // cell's size and three corners for its interior point.
        let (walker, shapes) = rayon::join(
            || Walker::new(map, &arrangement, &index, &lines, line_views),
            || {
                cells
                    .par_iter()
                    .map_init(Vec::new, |hs, &f| {
                        hs.clear();
                        hs.extend(arrangement.face_cycle(f));
                        (hs.len(), interior_corners(&arrangement, hs))
                    })
                    .collect::<Vec<(usize, [VertexId; 3])>>()
            },
        );
        // Progress counts the cells of every dimension.
        let all = total + walker.lower_count();
        progress(0, all);
        let step = (all / 100).max(1);

        let (sizes, cell_corners): (Vec<usize>, Vec<[VertexId; 3]>) = shapes.into_iter().unzip();
        let mut corners: Vec<Option<[VertexId; 3]>> = vec![None; arrangement.face_count()];
        for (&f, &c) in cells.iter().zip(&cell_corners) {
            corners[f] = Some(c);
        }
        let Walked {
            faces: walked,
            hashes: face_hashes,
            early,
        } = walker.walk(&corners, &mut |done| {
            if done.is_multiple_of(step) && done < all {
                progress(done, all);
            }
        });
        let skeleton = |i: usize| walked[cells[i]].get().expect("every cell is walked");
        let mut table = ClassTable::new(map, &lines);
        let hashes: Vec<u64> = cells.iter().map(|&f| face_hashes[f]).collect();
        let first = first_alike(&hashes, |i, j| {
            skeleton(i).same_skeleton(skeleton(j), map, &lines)
        });
        let mut skeleton_index = Vec::with_capacity(total);
        for (i, &f) in cells.iter().enumerate() {
            let class = if first[i] == i {
                table.push(Rep::Face(f), hashes[i])
            } else {
                skeleton_index[first[i]]
            };
            table.classes[class].push(f);
            table.complexity[class] += 2 * sizes[i];
            skeleton_index.push(class);
        }
        let origins: Vec<usize> = (0..total)
            .into_par_iter()
            .map(|i| skeleton(i).origin())
            .collect();

        // Cells of dimension 1 and 0, each with its skeleton, absorbed by an
        // adjacent 2-cell with the same skeleton in the same embedding.
        // Resolved in parallel where no new class is needed.
        let resolve = |site: LowerSite, faces: &[FaceId], sk: LowerSkeleton| {
            let cell = |f: FaceId, origin: usize| LowerCell {
                site,
                class: skeleton_index[position[f]],
                origin,
                absorbed_by: Some(f),
            };
            match sk {
                LowerSkeleton::Face(f) => Resolved::Cell(cell(f, origins[position[f]])),
                LowerSkeleton::Own(sk) => {
                    // Equal compact skeletons are equal skeletons in the
                    // same embedding, and need no class lookup.
                    match faces
                        .iter()
                        .find(|&&f| walked[f].get().is_some_and(|w| *w == sk))
                    {
                        Some(&f) => Resolved::Cell(cell(f, sk.origin())),
                        None => Resolved::Own(site, faces.to_vec(), sk),
                    }
                }
            }
        };
        let mut lower: Vec<LowerCell> = Vec::with_capacity(walker.lower_count());
        walker.lower(&walked, &early, resolve, &mut |block| {
            for r in block {
                let c = match r {
                    Resolved::Cell(c) => c,
                    Resolved::Own(site, faces, sk) => {
                        let origin = sk.origin();
                        let class = table.intern(&sk, Rep::Own(sk.clone()), &walked);
                        // Collinear map edges make the converse need the
                        // class.
                        let absorbed_by = faces.iter().copied().find(|&f| {
                            position[f] != NOT_A_CELL
                                && skeleton_index[position[f]] == class
                                && origins[position[f]] == origin
                        });
                        LowerCell {
                            site,
                            class,
                            origin,
                            absorbed_by,
                        }
                    }
                };
                if c.absorbed_by.is_none() {
                    table.lower[c.class].push(lower.len());
                }
                lower.push(c);
                let done = total + lower.len();
                if done.is_multiple_of(step) && done < all {
                    progress(done, all);
                }
            }
        });
        drop(walker);
        let mut walked = walked;
        let class_skeletons = table
            .skeletons
            .into_iter()
            .map(|r| match r {
                Rep::Face(f) => walked[f].take().expect("every cell is walked"),
                Rep::Own(c) => c,
            })
            .collect();
        drop(walked);
        progress(all, all);

        Decomposition {
            map,
            arrangement,
            cells,
            position,
            sizes,
            corners: cell_corners,
            representatives: OnceLock::new(),
            skeleton_index,
            origins,
            class_skeletons,
            skeletons: OnceLock::new(),
            classes: table.classes,
            class_complexity: table.complexity,
            lower,
            class_lower: table.lower,
        }
    }

    pub fn map(&self) -> &'m Map {
        self.map
    }

    /// The visibility rays (Def 3.8) the arrangement was built from.
    pub fn rays(&self) -> &[VisibilityRay] {
        self.arrangement.rays()
    }

    pub fn arrangement(&self) -> &Arrangement {
        &self.arrangement
    }

    /// The boundary assignment of sec. 3.6.
    pub fn assignment(&self) -> &BoundaryAssignment {
        self.arrangement.assignment()
    }

    /// The cells: the bounded faces of the arrangement, in face id order.
    pub fn cells(&self) -> &[FaceId] {
        &self.cells
    }

    /// The position of `cell` in [`Decomposition::cells`].
    ///
    /// # Panics
    /// If `cell` is the outer face or not a face.
    fn pos(&self, cell: FaceId) -> usize {
        match self.position.get(cell) {
            Some(&i) if i != NOT_A_CELL => i,
            _ => panic!("face {cell} is not a cell"),
        }
    }

    /// The number of vertices (= number of edges) of the boundary of
    /// `cell`: arrangement vertices, including those where the boundary
    /// goes straight on.
    pub fn cell_size(&self, cell: FaceId) -> usize {
        self.sizes[self.pos(cell)]
    }

    /// N (Thm 3.9, sec. 3.9): the total complexity of all cells, the sum
    /// over the cells of their vertices plus their edges, i.e. twice the
    /// sum of [`Decomposition::cell_size`]. A vertex or edge shared by
    /// several cells counts once per cell (as in N = Σ |EC_{V*}|).
    pub fn total_complexity(&self) -> usize {
        2 * self.sizes.iter().sum::<usize>()
    }

    /// An exact point in the interior of `cell`: the centroid of three
    /// non-collinear vertices of its boundary (the first two and the first
    /// one after them not on their line). Interior because the cell is
    /// convex (Thm 3.3 (1), checked by the arrangement's sanity check).
    pub fn representative(&self, cell: FaceId) -> &RatPoint {
        let all = self.representatives.get_or_init(|| {
            self.corners
                .iter()
                .map(|c| centroid(&self.arrangement, *c))
                .collect()
        });
        &all[self.pos(cell)]
    }

    /// The index of `cell`'s skeleton (Def 3.9) in
    /// [`Decomposition::skeletons`], which is also its class's index in
    /// [`Decomposition::classes`].
    pub fn skeleton_of(&self, cell: FaceId) -> usize {
        self.skeleton_index[self.pos(cell)]
    }

    /// The map vertex that is the origin v0 of `cell`'s skeleton: with
    /// [`Decomposition::skeleton_of`], the skeleton in its embedding.
    pub fn origin_of(&self, cell: FaceId) -> usize {
        self.origins[self.pos(cell)]
    }

    /// The distinct skeleton keys, one per class, in class order. Built
    /// on the first call (classes are told apart without them).
    pub fn skeletons(&self) -> &[SkeletonKey] {
        self.skeletons.get_or_init(|| {
            self.class_skeletons
                .iter()
                .map(|c| c.key(self.map))
                .collect()
        })
    }

    /// The key of class `class`'s skeleton, built alone (see
    /// [`Decomposition::skeletons`] for all of them).
    pub fn skeleton_key(&self, class: usize) -> SkeletonKey {
        match self.skeletons.get() {
            Some(keys) => keys[class].clone(),
            None => self.class_skeletons[class].key(self.map),
        }
    }

    /// An exact point of a 1- or 0-cell: the edge's midpoint, or the
    /// vertex (where its skeleton was computed).
    pub fn lower_representative(&self, cell: &LowerCell) -> RatPoint {
        let arr = &self.arrangement;
        match cell.site {
            LowerSite::Edge(e) => RatPoint::midpoint(
                arr.point(arr.half_edge(2 * e).origin),
                arr.point(arr.dest(2 * e)),
            ),
            LowerSite::Vertex(v) => arr.point(v).clone(),
        }
    }

    /// The equivalence classes (Def 3.10): `classes()[i]` are the 2-cells
    /// (ascending) whose skeleton is `skeletons()[i]`. Classes with a 2-cell
    /// come first, ordered by their first 2-cell; then the classes of kept
    /// lower-dimensional cells only, whose list here is empty (their cells
    /// are in [`Decomposition::class_lower_cells`]).
    pub fn classes(&self) -> &[Vec<FaceId>] {
        &self.classes
    }

    /// |EC| of class `class` (Def 3.10): the total number of vertices and
    /// edges of its cells, with the convention of
    /// [`Decomposition::total_complexity`].
    pub fn class_complexity(&self, class: usize) -> usize {
        self.class_complexity[class]
    }

    /// The largest |EC| (0 for a map without cells, which cannot occur).
    pub fn max_class_complexity(&self) -> usize {
        self.class_complexity.iter().copied().max().unwrap_or(0)
    }

    /// The cells of dimension 1 (first, by edge id) and 0 (then, by vertex
    /// id), kept or absorbed; see [`LowerCell`].
    pub fn lower_cells(&self) -> &[LowerCell] {
        &self.lower
    }

    /// The kept cells of dimension 1 and 0 of class `class` (indices into
    /// [`Decomposition::lower_cells`]). A class may have kept
    /// lower-dimensional cells and no 2-cell: the skeleton of a doorway's
    /// segment, say, which no 2-cell has.
    pub fn class_lower_cells(&self, class: usize) -> &[usize] {
        &self.class_lower[class]
    }

    pub fn counts(&self) -> Counts {
        let tally = |dim: u8| {
            let mut t = KeptAbsorbed::default();
            for c in self.lower.iter().filter(|c| c.dimension() == dim) {
                if c.absorbed_by.is_some() {
                    t.absorbed += 1;
                } else {
                    t.kept += 1;
                }
            }
            t
        };
        Counts {
            n: self.map.n(),
            r: self.map.r(),
            rays: self.rays().len(),
            cells: self.cells.len(),
            total_complexity: self.total_complexity(),
            classes: self.classes.len(),
            max_class_complexity: self.max_class_complexity(),
            vertices: self.arrangement.vertex_count(),
            edges: self.arrangement.edge_count(),
            conflicts: self.arrangement.conflicts().len(),
            one_cells: tally(1),
            zero_cells: tally(0),
        }
    }
}

/// The classes as they are found: one row per distinct skeleton, in the
/// order first seen. Skeletons are compared as compact skeletons up to
/// translation ([`Compact::same_skeleton`]), which is comparing keys
/// without building them.
struct ClassTable<'a> {
    map: &'a Map,
    lines: &'a EdgeLines,
    /// Classes by the hash of their skeleton (equal hashes are told apart
    /// by comparing skeletons).
    by_hash: HashChains,
    /// By class: the compact skeleton of its first cell.
    skeletons: Vec<Rep>,
    /// By class: its 2-cells.
    classes: Vec<Vec<FaceId>>,
    /// By class: |EC| of its 2-cells.
    complexity: Vec<usize>,
    /// By class: its kept lower-dimensional cells.
    lower: Vec<Vec<usize>>,
    /// By class: the hash of its skeleton.
    hashes: Vec<u64>,
    /// The classes below this one are filed in `by_hash`.
    filed: usize,
}

impl<'a> ClassTable<'a> {
    fn new(map: &'a Map, lines: &'a EdgeLines) -> ClassTable<'a> {
        ClassTable {
            map,
            lines,
            by_hash: HashChains::default(),
            skeletons: Vec::new(),
            classes: Vec::new(),
            complexity: Vec::new(),
            lower: Vec::new(),
            hashes: Vec::new(),
            filed: 0,
        }
    }

    /// A new class, skeleton `rep` with class hash `h`, known to differ
    /// from all others; not yet filed for [`ClassTable::intern`].
    fn push(&mut self, rep: Rep, h: u64) -> usize {
        self.skeletons.push(rep);
        self.classes.push(Vec::new());
        self.complexity.push(0);
        self.lower.push(Vec::new());
        self.hashes.push(h);
        self.skeletons.len() - 1
    }

    /// The class of skeleton `sk`, a new empty one (with `rep`, which is
    /// `sk`) if it was not seen before. `walked`: the 2-cells' skeletons.
    fn intern(&mut self, sk: &Compact, rep: Rep, walked: &[OnceLock<Compact>]) -> usize {
        // Classes pushed unfiled (those of the 2-cells) are filed when
        // first needed: most maps need none.
        for c in self.filed..self.skeletons.len() {
            self.by_hash.find_or_file(self.hashes[c], c, |_| false);
        }
        let h = sk.class_hash(self.lines);
        let c = self.skeletons.len();
        let (skeletons, map, lines) = (&self.skeletons, self.map, self.lines);
        let same = |at: usize| skeletons[at].get(walked).same_skeleton(sk, map, lines);
        let class = match self.by_hash.find_or_file(h, c, same) {
            Some(at) => at,
            None => self.push(rep, h),
        };
        self.filed = self.skeletons.len();
        class
    }
}

/// By position: the first position whose value is alike, for `alike` an
/// equivalence that implies equal `hashes`. Found in parallel: positions
/// sorted by hash, each run of equal hashes split into classes.
fn first_alike(hashes: &[u64], alike: impl Fn(usize, usize) -> bool + Sync) -> Vec<usize> {
    let mut order: Vec<(u64, usize)> = hashes.iter().copied().zip(0..).collect();
    order.par_sort_unstable();
    let mut first: Vec<usize> = (0..hashes.len()).collect();
    // Runs of equal hashes; a run of one is its own first.
    let mut runs: Vec<&[(u64, usize)]> = Vec::new();
    let mut rest = &order[..];
    while let Some(&(h, _)) = rest.first() {
        let len = rest.iter().take_while(|&&(g, _)| g == h).count();
        let (run, tail) = rest.split_at(len);
        if len > 1 {
            runs.push(run);
        }
        rest = tail;
    }
    let found: Vec<Vec<(usize, usize)>> = runs
        .par_iter()
        .map(|run| {
            // Ascending positions: each is alike to an earlier first one
            // or is a first one itself.
            let mut firsts: Vec<usize> = Vec::new();
            run.iter()
                .map(|&(_, i)| {
                    let f = firsts
                        .iter()
                        .copied()
                        .find(|&f| alike(f, i))
                        .unwrap_or_else(|| {
                            firsts.push(i);
                            i
                        });
                    (i, f)
                })
                .collect()
        })
        .collect();
    for (i, f) in found.into_iter().flatten() {
        first[i] = f;
    }
    first
}

/// A 1- or 0-cell as resolved in parallel: done, or with a skeleton no
/// adjacent 2-cell has in the same embedding, whose class is to be found.
enum Resolved {
    Cell(LowerCell),
    Own(LowerSite, Vec<FaceId>, Compact),
}

/// A class's skeleton while the classes are found: a 2-cell's (in the
/// walk's results, not copied) or a lower cell's own.
enum Rep {
    Face(FaceId),
    Own(Compact),
}

impl Rep {
    fn get<'a>(&'a self, walked: &'a [OnceLock<Compact>]) -> &'a Compact {
        match self {
            Rep::Face(f) => walked[*f].get().expect("every cell is walked"),
            Rep::Own(c) => c,
        }
    }
}

/// Three non-collinear vertices of a convex face with boundary cycle
/// `hs`, whose centroid is an interior point: the ends of two consecutive
/// boundary edges that turn (their directions are not parallel), so no
/// orientation test on rational points is needed.
pub(crate) fn interior_corners(arr: &Arrangement, hs: &[HalfEdgeId]) -> [VertexId; 3] {
    let k = hs.len();
    let i = (0..k)
        .find(|&i| {
            arr.direction(hs[i])
                .cross_sign(arr.direction(hs[(i + 1) % k]))
                != Ordering::Equal
        })
        .expect("a cell has three non-collinear vertices");
    let at = |j: usize| arr.half_edge(hs[j % k]).origin;
    [at(i), at(i + 1), at(i + 2)]
}

/// The centroid of the points of three arrangement vertices.
pub(crate) fn centroid(arr: &Arrangement, c: [VertexId; 3]) -> RatPoint {
    centroid3(arr.pt(c[0]), arr.pt(c[1]), arr.pt(c[2]))
}

/// `(a + b + c) / 3`, exactly (through `i128` when it fits).
fn centroid3(a: PointRef<'_>, b: PointRef<'_>, c: PointRef<'_>) -> RatPoint {
    match Eye::centroid(a, b, c) {
        Eye::Small { x, y, w } => RatPoint::from_i128(x, y, w).expect("w > 0"),
        Eye::Big { .. } => centroid3_gmp(&a.exact(), &b.exact(), &c.exact()),
    }
}

/// [`centroid3`] on GMP integers.
pub(crate) fn centroid3_gmp(a: &RatPoint, b: &RatPoint, c: &RatPoint) -> RatPoint {
    let (aw, bw, cw) = (a.hw(), b.hw(), c.hw());
    let bc = Integer::from(bw * cw);
    let ac = Integer::from(aw * cw);
    let ab = Integer::from(aw * bw);
    let x = Integer::from(a.hx() * &bc) + Integer::from(b.hx() * &ac) + Integer::from(c.hx() * &ab);
    let y = Integer::from(a.hy() * &bc) + Integer::from(b.hy() * &ac) + Integer::from(c.hy() * &ab);
    let w = Integer::from(aw * &bc) * 3u32;
    RatPoint::new(x, y, w).expect("positive denominators")
}

#[cfg(test)]
mod tests {
    use super::{centroid3, centroid3_gmp};
    use crate::eye::PointRef;
    use rug::Integer;
    use wai_exact::RatPoint;

    /// The `i128` path and the GMP path agree, across the `i128` limits.
    #[test]
    fn centroid_paths_agree() {
        let big = |v: i128| Integer::from(v);
        let p = |x: i128, y: i128, w: i128| RatPoint::new(big(x), big(y), big(w)).unwrap();
        let huge = 1i128 << 100;
        let cases = [
            [p(0, 0, 1), p(3, 0, 1), p(0, 3, 1)],
            [p(1, 2, 3), p(-5, 7, 11), p(13, -17, 19)],
            [p(huge, 1, 3), p(-huge, huge, 7), p(1, -huge, 1 << 40)],
            [
                p(i128::MAX, 0, 1),
                p(i128::MIN + 1, 5, 1),
                p(0, i128::MAX, 2),
            ],
        ];
        for [a, b, c] in &cases {
            let fast = centroid3(PointRef::new(a), PointRef::new(b), PointRef::new(c));
            assert_eq!(fast, centroid3_gmp(a, b, c), "{a} {b} {c}");
        }
    }
}
