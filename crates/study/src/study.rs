//! One study per map: the structures the checkers read, each built the
//! first time a checker asks for it and then shared by every checker of a
//! run on that map.
//!
//! map → visibility index → decomposition (rays, arrangement, the skeleton
//! of every cell of every dimension, classes) → sampled visibility
//! polygons; → the embeddings of every class's skeleton (Def 3.11) with
//! their candidate edges and kernels. Later chapters add their structures
//! here, so a stress run builds each once per map.

use std::cell::{OnceCell, RefCell};
use std::collections::{BTreeMap, HashMap, HashSet};
use std::rc::Rc;

use rustc_hash::FxHashMap;
use wai_cells::{Arrangement, Decomposition, VisibilityRay};
use wai_embed::intersection::{edge_type, EdgeType};
use wai_embed::wedge::{classify_by_lines, embedding_wedge_lines, CellEdgeKind};
use wai_embed::{
    crossing, gap_chains, kernels_overlap, sight_fans, witness_regions, witness_views_by_rule,
    CandidateSets, Crossing, EmbeddedEdge, Embedder, Embedding, GapChain, GapRelation,
    Intersection, Interweavement, Mutual, SightFan, Sightlines, SkeletonRing, Witnesses,
};
use wai_exact::QPoint;
use wai_exact::RatPoint;
use wai_localize::Localizer;
use wai_map::Map;
use wai_visibility::{ConvexRegion, MapSkeleton, VisibilityIndex, VisibilityPolygon};

use crate::profile::{StageTimes, Timer};
use crate::sample;

/// A map and what has been computed about it so far.
pub struct Study<'m> {
    map: &'m Map,
    index: OnceCell<VisibilityIndex<'m>>,
    decomposition: OnceCell<Decomposition<'m>>,
    /// The arrangement's sanity check, run once.
    sanity: OnceCell<Result<(), String>>,
    /// V*_p computed afresh, by the point p asked for.
    fresh: RefCell<FxHashMap<RatPoint, Rc<FreshSkeleton>>>,
    /// By sample limit: V_p of [`sample::viewpoints`]`(map, limit)`.
    polygons: RefCell<BTreeMap<usize, Rc<Vec<VisibilityPolygon>>>>,
    /// By class of the decomposition: its skeleton's embeddings.
    embeddings: OnceCell<Vec<Vec<Embedded>>>,
    /// By class, by embedding: the witness regions (Def 4.1).
    witnesses: OnceCell<Vec<Vec<Witnesses>>>,
    /// By class, by embedding: the witness regions' pieces
    /// ([`Witnesses::pieces`]), copied out once.
    witness_pieces: OnceCell<Vec<Vec<Vec<wai_embed::Piece>>>>,
    sightlines: OnceCell<Sightlines<'m>>,
    /// Every pair of valid embeddings of one skeleton whose skeleton
    /// polygons overlap, with the verdict on their witnesses.
    overlapping: OnceCell<Vec<OverlappingPair>>,
    /// Every pair of valid embeddings of one skeleton whose skeleton
    /// polygons intersect without overlapping, with the same verdict.
    touching: OnceCell<Vec<TouchingPair>>,
    /// By class and embedding: h(V◇) with its artificial edges marked.
    rings: OnceCell<Vec<Vec<SkeletonRing>>>,
    /// The pairs of valid embeddings the sec. 4.4 checkers examine.
    pairs: OnceCell<Vec<EmbeddingPair>>,
    /// By class: its pairs of valid embeddings whose polygons' boxes meet,
    /// with whether their interiors overlap.
    skeleton_pairs: OnceCell<Vec<Vec<SkeletonPair>>>,
    /// By class, embedding and witness cell, by skeleton edge: the map
    /// edge seen through it (`wai_embed::witness_views`).
    views: OnceCell<Vec<Vec<Views>>>,
    /// By class and embedding: the valid candidate edges, read off `views`.
    valid: OnceCell<Vec<Vec<Vec<Vec<usize>>>>>,
    /// By class: C_{i,j} over its valid embeddings (Defs 5.4, 5.5).
    candidate_sets: OnceCell<Vec<CandidateSets>>,
    /// By class, by cell: its edges as Def 5.2 classifies them.
    cell_edges: OnceCell<Vec<Vec<CellEdges>>>,
    /// By class: its gaps as boundary chains and the interweavement graph.
    gaps: OnceCell<Vec<GapStructure>>,
    /// By class: the pairs of map edges shared by its embeddings (sec. 5.5).
    edge_pairs: OnceCell<Vec<crate::edge_pairs::SharedPairs>>,
    /// By class: its kernel and wedge edges counted (Def 5.2).
    edge_counts: OnceCell<Vec<crate::wedge_counts::EdgeCounts>>,
    /// The localizer's preprocessing (Alg 3.14): one overlay per class.
    localizer: OnceCell<Localizer>,
    /// The trapezoids of those overlays, counted without building them.
    preprocessing_size: OnceCell<usize>,
    /// By class and embedding: the sight fans of its witness cells, each
    /// embedding's built when first asked for.
    fans: OnceCell<Vec<Vec<OnceCell<Vec<SightFan>>>>>,
    /// Def 4.4, decided so far: by (overlapping pair, (artificial edge,
    /// candidate edge) of its first embedding, of its second).
    crossings: RefCell<HashMap<CrossingKey, Option<Crossing>>>,
    /// The map's vertices as rational points.
    map_points: OnceCell<HashSet<QPoint>>,
    /// The time each stage took.
    timer: Timer,
    /// Sample points of arrangement faces, by face
    /// ([`Study::cell_sample_points`]).
    cell_samples: RefCell<FxHashMap<usize, Rc<Vec<RatPoint>>>>,
    /// Sample points of arrangement edges, by edge
    /// ([`Study::edge_sample_points`]).
    edge_samples: RefCell<FxHashMap<usize, Rc<[RatPoint; 3]>>>,
    /// Middle sample points of arrangement edges, by edge
    /// ([`Study::edge_sample_point`]).
    edge_middles: RefCell<FxHashMap<usize, RatPoint>>,
}

/// V*_p of a point p computed afresh (a visibility query and Def 3.7, not
/// the decomposition's walk), in map terms (its embedding included); or
/// why it cannot be built.
pub type FreshSkeleton = Result<MapSkeleton, String>;

/// (index in [`Study::overlapping_pairs`], (artificial edge, candidate
/// edge) of the pair's embedding `a`, the same of `b`).
type CrossingKey = (usize, (usize, usize), (usize, usize));

/// By witness cell, by skeleton edge: the map edge seen through it.
pub type Views = Vec<Vec<Option<usize>>>;

/// Maps of at most this many vertices have the sec. 4.4 claims (L4.5 to
/// C4.10, which allow different skeletons) checked on pairs of valid
/// embeddings of different skeletons too; larger maps on pairs of one
/// skeleton only (a map of 52 vertices has about 190,000 overlapping pairs
/// of different skeletons).
pub const CROSS_SKELETON_MAX_N: usize = 14;

/// Two valid embeddings, (class, index in [`Study::embeddings`]) each, whose
/// skeleton polygons' bounding boxes meet: whether their interiors
/// overlap, and their intersection, traced when first asked for
/// ([`Study::intersection`]).
#[derive(Debug, Clone)]
pub struct EmbeddingPair {
    pub first: (usize, usize),
    pub second: (usize, usize),
    overlap: bool,
    intersection: OnceCell<Intersection>,
    /// By edge of the intersection's cycles: its type (Lemma 4.7).
    types: OnceCell<Vec<Option<EdgeType>>>,
}

impl EmbeddingPair {
    pub fn same_skeleton(&self) -> bool {
        self.first.0 == self.second.0
    }

    pub fn overlap(&self) -> bool {
        self.overlap
    }
}

/// Two valid embeddings of one class, by index in [`Study::embeddings`],
/// `a < b`, whose skeleton polygons' bounding boxes meet, and whether the
/// polygons' interiors overlap (`wai_embed::interiors_overlap`, on the
/// rings' integer form: [`SkeletonRing::interiors_overlap`]).
pub type SkeletonPair = (usize, usize, bool);

/// Two different valid embeddings of one skeleton whose embedded skeleton
/// polygons overlap (the premise of Theorem 4.2), by class and position in
/// [`Study::embeddings`], `a < b`.
#[derive(Debug, Clone)]
pub struct OverlappingPair {
    pub class: usize,
    pub a: usize,
    pub b: usize,
    /// Its index in [`Study::embedding_pairs`].
    pub pair: usize,
    /// Whether the embedded kernels overlap too (Theorem 4.3's premise).
    pub kernels_overlap: bool,
    /// Whether a witness of one sees a witness of the other, by
    /// [`Sightlines::regions_by_lines`].
    pub sight: Mutual,
}

/// Two different valid embeddings of one skeleton whose embedded skeleton
/// polygons intersect but do not overlap (sec. 4.6): their boundaries
/// share a point, their interiors none. By class and position in
/// [`Study::embeddings`], `a < b`.
#[derive(Debug, Clone)]
pub struct TouchingPair {
    pub class: usize,
    pub a: usize,
    pub b: usize,
    /// Its index in [`Study::embedding_pairs`].
    pub pair: usize,
    /// Whether a witness of one sees a witness of the other, by
    /// [`Sightlines::regions_by_lines`].
    pub sight: Mutual,
}

/// The edges of one 2-cell of a class, classified by Def 5.2 in the
/// embedding the cell lies in.
#[derive(Debug, Clone)]
pub struct CellEdges {
    pub cell: wai_cells::FaceId,
    /// Its embedding: the index in [`Study::embeddings`] of the class.
    pub embedding: usize,
    /// By edge of the cell (from vertex k to k + 1 of its face points).
    pub kinds: Vec<CellEdgeKind>,
}

/// The gaps of one class's skeleton (Def 5.5) as boundary chains, the
/// pairs of them Def 5.6 relates, which valid embeddings overlap, and the
/// interweavement graph (Def 5.9) they make. Embeddings are named by their
/// position j in the class's [`CandidateSets::embeddings`].
#[derive(Debug, Clone, Default)]
pub struct GapStructure {
    /// One chain per (gap, set C_{i,j} it is consecutive in).
    pub chains: Vec<GapChain>,
    /// (a, b, relation) for chains a < b of different pairs of map edges
    /// that are nested or interweaved.
    pub related: Vec<(usize, usize, GapRelation)>,
    /// The pairs j1 < j2 of valid embeddings whose skeleton polygons'
    /// interiors overlap (Def 5.7's relation).
    pub overlapping: Vec<(usize, usize)>,
    pub graph: Interweavement,
}

impl GapStructure {
    /// From the chains of a class's gaps, the overlapping pairs of its `t`
    /// valid embeddings: relates every two chains of different pairs of
    /// map edges and builds the graph.
    pub fn new(chains: Vec<GapChain>, overlapping: Vec<(usize, usize)>, t: usize) -> GapStructure {
        let mut related = Vec::new();
        for a in 0..chains.len() {
            for b in a + 1..chains.len() {
                if chains[a].same_edges(&chains[b]) {
                    continue;
                }
                let rel = chains[a].relation(&chains[b]);
                if rel != GapRelation::Apart {
                    related.push((a, b, rel));
                }
            }
        }
        let mut g = GapStructure {
            chains,
            related,
            overlapping,
            graph: Interweavement::default(),
        };
        g.graph = Interweavement::new(t, &g.overlapping, &g.interweaved());
        g
    }

    /// The interweaved pairs ((j1, i1), (j2, i2)) of different embeddings.
    pub fn interweaved(&self) -> Vec<(EmbeddedEdge, EmbeddedEdge)> {
        self.related
            .iter()
            .filter(|r| r.2 == GapRelation::Interweaved)
            .map(|&(a, b, _)| (&self.chains[a], &self.chains[b]))
            .filter(|(g, h)| g.j != h.j)
            .map(|(g, h)| ((g.j, g.i), (h.j, h.i)))
            .collect()
    }

    /// Whether valid embeddings j1 and j2 overlap.
    pub fn overlap(&self, j1: usize, j2: usize) -> bool {
        self.overlapping.contains(&(j1.min(j2), j1.max(j2)))
    }
}

/// An embedding of a class's skeleton (Def 3.11) and its kernel
/// h(ker V*) (Def 3.12), in map coordinates; the kernel computed when
/// first asked for (most embeddings' kernels are never read).
#[derive(Debug, Clone)]
pub struct Embedded {
    pub embedding: Embedding,
    /// h(V◇) as map points.
    polygon: Vec<wai_exact::Point>,
    kernel: OnceCell<ConvexRegion>,
}

impl Embedded {
    /// `embedding` in `map`.
    pub fn new(embedding: Embedding, map: &Map) -> Embedded {
        Embedded {
            polygon: embedding.polygon(map),
            embedding,
            kernel: OnceCell::new(),
        }
    }

    /// h(V◇) as map points.
    pub fn polygon(&self) -> &[wai_exact::Point] {
        &self.polygon
    }

    /// The embedded kernel h(ker V*), the kernel of h(V◇).
    pub fn kernel(&self) -> &ConvexRegion {
        self.kernel
            .get_or_init(|| wai_visibility::kernel_of_ring(&self.polygon))
    }
}

impl<'m> Study<'m> {
    /// A study of `map` with nothing computed yet.
    pub fn new(map: &'m Map) -> Study<'m> {
        Study {
            map,
            index: OnceCell::new(),
            decomposition: OnceCell::new(),
            sanity: OnceCell::new(),
            fresh: RefCell::new(FxHashMap::default()),
            polygons: RefCell::new(BTreeMap::new()),
            embeddings: OnceCell::new(),
            witnesses: OnceCell::new(),
            witness_pieces: OnceCell::new(),
            sightlines: OnceCell::new(),
            overlapping: OnceCell::new(),
            touching: OnceCell::new(),
            rings: OnceCell::new(),
            pairs: OnceCell::new(),
            skeleton_pairs: OnceCell::new(),
            views: OnceCell::new(),
            valid: OnceCell::new(),
            candidate_sets: OnceCell::new(),
            cell_edges: OnceCell::new(),
            gaps: OnceCell::new(),
            edge_pairs: OnceCell::new(),
            edge_counts: OnceCell::new(),
            fans: OnceCell::new(),
            localizer: OnceCell::new(),
            preprocessing_size: OnceCell::new(),
            crossings: RefCell::new(HashMap::new()),
            map_points: OnceCell::new(),
            timer: Timer::default(),
            cell_samples: RefCell::default(),
            edge_samples: RefCell::default(),
            edge_middles: RefCell::default(),
        }
    }

    /// A study of a map whose decomposition is built already (with a
    /// progress bar, say).
    pub fn from_decomposition(decomposition: Decomposition<'m>) -> Study<'m> {
        let study = Study::new(decomposition.map());
        let _ = study.decomposition.set(decomposition);
        study
    }

    pub fn map(&self) -> &'m Map {
        self.map
    }

    /// The own time of each stage built so far ([`crate::profile`]).
    pub fn stage_times(&self) -> StageTimes {
        self.timer.times()
    }

    /// The time spent building stages so far: a reader's own time is its
    /// wall time minus this total's growth while it ran.
    pub fn stage_total(&self) -> std::time::Duration {
        self.timer.total()
    }

    /// The production visibility index of the map.
    pub fn index(&self) -> &VisibilityIndex<'m> {
        self.index
            .get_or_init(|| self.timer.stage("index", || VisibilityIndex::new(self.map)))
    }

    /// The visibility cell decomposition (Def 3.8) with its cells of every
    /// dimension, their skeletons and classes.
    pub fn decomposition(&self) -> &Decomposition<'m> {
        self.decomposition.get_or_init(|| {
            self.timer
                .stage("decomposition", || Decomposition::new(self.map))
        })
    }

    /// The arrangement's layered sanity check (topology, then geometry:
    /// `Arrangement::sanity_check`), run once: the verdict every checker
    /// that reads the cells as faces of the true arrangement rests on.
    pub fn arrangement_sanity(&self) -> &Result<(), String> {
        self.sanity.get_or_init(|| {
            let arr = self.arrangement();
            self.timer.stage("sanity check", || arr.sanity_check())
        })
    }

    /// V*_p of each of `points`, computed afresh by the study's visibility
    /// index ([`VisibilityIndex::skeleton_at`]), each point once per study
    /// (the cell checkers T3.3b and A3.6 sample many of the same points).
    pub fn fresh_skeletons(&self, points: &[RatPoint]) -> Vec<Rc<FreshSkeleton>> {
        let index = self.index();
        self.timer.stage("fresh skeletons", || {
            points
                .iter()
                .map(|p| {
                    if let Some(s) = self.fresh.borrow().get(p) {
                        return Rc::clone(s);
                    }
                    let s = Rc::new(fresh_skeleton(index, p));
                    self.fresh.borrow_mut().insert(p.clone(), Rc::clone(&s));
                    s
                })
                .collect()
        })
    }

    /// [`sample::simple_interior_points_or_one`] of arrangement face `f`,
    /// once per face per study (T3.3b and A3.6 sample the same points):
    /// both points, the first alone, or none if the face has no interior.
    pub fn cell_sample_points(&self, f: usize) -> Rc<Vec<RatPoint>> {
        if let Some(s) = self.cell_samples.borrow().get(&f) {
            return Rc::clone(s);
        }
        let ring = self.arrangement().face_points(f);
        let s = Rc::new(match sample::simple_interior_points_or_one(&ring) {
            None => vec![],
            Some((p, None)) => vec![p],
            Some((p, Some(q))) => vec![p, q],
        });
        self.cell_samples.borrow_mut().insert(f, Rc::clone(&s));
        s
    }

    /// [`sample::simple_segment_points`] of arrangement edge `e` (on the
    /// line of [`sample::arrangement_edge_line`]), once per edge per study.
    pub fn edge_sample_points(&self, e: usize) -> Rc<[RatPoint; 3]> {
        if let Some(s) = self.edge_samples.borrow().get(&e) {
            return Rc::clone(s);
        }
        let (a, b, line) = sample::arrangement_edge_line(self.arrangement(), e);
        let s = Rc::new(sample::simple_segment_points(a, b, line));
        self.edge_samples.borrow_mut().insert(e, Rc::clone(&s));
        s
    }

    /// The middle one of [`Study::edge_sample_points`]
    /// ([`sample::simple_segment_point`]), once per edge per study.
    pub fn edge_sample_point(&self, e: usize) -> RatPoint {
        if let Some(s) = self.edge_samples.borrow().get(&e) {
            return s[1].clone();
        }
        if let Some(p) = self.edge_middles.borrow().get(&e) {
            return p.clone();
        }
        let (a, b, line) = sample::arrangement_edge_line(self.arrangement(), e);
        let p = sample::simple_segment_point(a, b, line);
        self.edge_middles.borrow_mut().insert(e, p.clone());
        p
    }

    /// The decomposition's arrangement of map edges and rays.
    pub fn arrangement(&self) -> &Arrangement {
        self.decomposition().arrangement()
    }

    /// The visibility rays (Def 3.8).
    pub fn rays(&self) -> &[VisibilityRay] {
        self.decomposition().rays()
    }

    /// By class of the decomposition (its index in
    /// [`Decomposition::skeletons`]): every embedding of its skeleton in
    /// the map, by ascending h(v0), with its kernel.
    pub fn embeddings(&self) -> &[Vec<Embedded>] {
        self.embeddings.get_or_init(|| {
            self.timer.stage("embeddings", || {
                let embedder = Embedder::new(self.index());
                self.decomposition()
                    .skeletons()
                    .iter()
                    .map(|key| {
                        embedder
                            .embeddings(key)
                            .into_iter()
                            .map(|embedding| Embedded::new(embedding, self.map))
                            .collect()
                    })
                    .collect()
            })
        })
    }

    /// By class and embedding (as [`Study::embeddings`]): the witness
    /// region (Def 4.1), the class's cells at the embedding's own v0.
    pub fn witnesses(&self) -> &[Vec<Witnesses>] {
        self.witnesses.get_or_init(|| {
            self.timer.stage("witnesses", || {
                let d = self.decomposition();
                self.embeddings()
                    .iter()
                    .enumerate()
                    .map(|(class, all)| {
                        let origins: Vec<usize> = all.iter().map(|h| h.embedding.origin).collect();
                        witness_regions(d, class, &origins)
                    })
                    .collect()
            })
        })
    }

    /// The pieces of the witness region of embedding `i` of class `class`
    /// ([`Witnesses::pieces`] of [`Study::witnesses`]), made once for all
    /// the checkers that read them.
    pub fn witness_pieces(&self, class: usize, i: usize) -> &[wai_embed::Piece] {
        &self.witness_pieces.get_or_init(|| {
            self.witnesses()
                .iter()
                .map(|ws| ws.iter().map(Witnesses::pieces).collect())
                .collect()
        })[class][i]
    }

    /// The map prepared for exact mutual-visibility tests of regions.
    pub fn sightlines(&self) -> &Sightlines<'m> {
        self.sightlines
            .get_or_init(|| self.timer.stage("sightlines", || Sightlines::new(self.map)))
    }

    /// Every pair of different valid embeddings of one skeleton whose
    /// skeleton polygons overlap, with whether their kernels overlap and
    /// whether their witnesses see each other.
    pub fn overlapping_pairs(&self) -> &[OverlappingPair] {
        self.overlapping.get_or_init(|| {
            self.timer.stage("overlapping pairs", || {
                let embeddings = self.embeddings();
                self.embedding_pairs()
                    .iter()
                    .enumerate()
                    .filter(|(_, p)| p.same_skeleton() && p.overlap())
                    .map(|(pair, p)| {
                        let (class, a, b) = (p.first.0, p.first.1, p.second.1);
                        let kernels_overlap = kernels_overlap(
                            embeddings[class][a].kernel(),
                            embeddings[class][b].kernel(),
                        );
                        let sight = self.sightlines().regions_by_lines(
                            self.witness_pieces(class, a),
                            self.witness_pieces(class, b),
                        );
                        OverlappingPair {
                            class,
                            a,
                            b,
                            pair,
                            kernels_overlap,
                            sight,
                        }
                    })
                    .collect()
            })
        })
    }

    /// Every pair of different valid embeddings of one skeleton whose
    /// skeleton polygons intersect without overlapping (sec. 4.6), with
    /// whether their witnesses see each other.
    pub fn touching_pairs(&self) -> &[TouchingPair] {
        self.touching.get_or_init(|| {
            self.timer.stage("touching pairs", || {
                let rings = self.skeleton_rings();
                self.embedding_pairs()
                    .iter()
                    .enumerate()
                    .filter(|(_, p)| p.same_skeleton() && !p.overlap())
                    .filter(|(_, p)| {
                        rings[p.first.0][p.first.1].boundaries_meet(&rings[p.second.0][p.second.1])
                    })
                    .map(|(pair, p)| {
                        let (class, a, b) = (p.first.0, p.first.1, p.second.1);
                        let sight = self.sightlines().regions_by_lines(
                            self.witness_pieces(class, a),
                            self.witness_pieces(class, b),
                        );
                        TouchingPair {
                            class,
                            a,
                            b,
                            pair,
                            sight,
                        }
                    })
                    .collect()
            })
        })
    }

    /// The intersection of the skeleton polygons of `pair` (one of
    /// [`Study::embedding_pairs`]), if their interiors overlap; traced once.
    pub fn intersection<'s>(&'s self, pair: &'s EmbeddingPair) -> Option<&'s Intersection> {
        if !pair.overlap {
            return None;
        }
        let rings = self.skeleton_rings();
        Some(pair.intersection.get_or_init(|| {
            self.timer.stage("intersections", || {
                let (p, q) = (
                    &rings[pair.first.0][pair.first.1],
                    &rings[pair.second.0][pair.second.1],
                );
                Intersection::of_rings(p, q)
            })
        }))
    }

    /// The edge types (Lemma 4.7, [`wai_embed::intersection::edge_type`])
    /// of the intersection of `pair`'s skeleton polygons, edge by edge of
    /// its cycles, if their interiors overlap; classified once.
    pub fn intersection_types<'s>(
        &'s self,
        pair: &'s EmbeddingPair,
    ) -> Option<&'s [Option<EdgeType>]> {
        let x = self.intersection(pair)?;
        Some(pair.types.get_or_init(|| {
            let rings = self.skeleton_rings();
            let vertices = self.map_points.get_or_init(|| {
                self.map
                    .vertices()
                    .iter()
                    .map(|&p| QPoint::from(p))
                    .collect()
            });
            self.timer.stage("intersection types", || {
                let (p, q) = (
                    &rings[pair.first.0][pair.first.1],
                    &rings[pair.second.0][pair.second.1],
                );
                x.cycles
                    .iter()
                    .flatten()
                    .map(|e| edge_type(e, p, q, vertices))
                    .collect()
            })
        }))
    }

    /// By class and embedding: the embedded skeleton polygon h(V◇) with its
    /// artificial edges marked, for the valid embeddings (Def 4.1), the
    /// only ones the chapter 4 claims compare; the ring of an embedding
    /// without witness is empty.
    pub fn skeleton_rings(&self) -> &[Vec<SkeletonRing>] {
        self.rings.get_or_init(|| {
            let witnesses = self.witnesses();
            self.timer.stage("skeleton rings", || {
                let keys = self.decomposition().skeletons();
                self.embeddings()
                    .iter()
                    .zip(witnesses)
                    .enumerate()
                    .map(|(class, (all, ws))| {
                        let artificial: Vec<bool> =
                            keys[class].labels.iter().map(Option::is_some).collect();
                        all.iter()
                            .zip(ws)
                            .map(|(h, w)| {
                                if !w.is_valid() {
                                    return SkeletonRing::new(&[], Vec::new());
                                }
                                SkeletonRing::new(h.polygon(), artificial.clone())
                            })
                            .collect()
                    })
                    .collect()
            })
        })
    }

    /// The pairs of valid embeddings the sec. 4.4 claims examine: of one
    /// skeleton always, of different skeletons on maps of at most
    /// [`CROSS_SKELETON_MAX_N`] vertices; those whose polygons' bounding
    /// boxes meet, and whether their interiors overlap.
    pub fn embedding_pairs(&self) -> &[EmbeddingPair] {
        self.pairs.get_or_init(|| {
            self.timer.stage("embedding pairs", || {
                let rings = self.skeleton_rings();
                let valid: Vec<(usize, usize)> = self
                    .witnesses()
                    .iter()
                    .enumerate()
                    .flat_map(|(c, ws)| {
                        ws.iter()
                            .enumerate()
                            .filter(|(_, w)| w.is_valid())
                            .map(move |(i, _)| (c, i))
                    })
                    .collect();
                let cross = self.map.n() <= CROSS_SKELETON_MAX_N;
                let same = self.skeleton_pairs();
                let ring = |k: usize| &rings[valid[k].0][valid[k].1];
                let mut out = Vec::new();
                for a in 0..valid.len() {
                    for b in a + 1..valid.len() {
                        let one_class = valid[a].0 == valid[b].0;
                        if !one_class && !cross {
                            continue;
                        }
                        if !ring(a).boxes_meet(ring(b)) {
                            continue;
                        }
                        // A pair of one class: its verdict is the class's.
                        let overlap = if one_class {
                            let of_class = &same[valid[a].0];
                            let at = of_class
                                .binary_search_by_key(&(valid[a].1, valid[b].1), |&(x, y, _)| {
                                    (x, y)
                                })
                                .expect("a pair of one class whose boxes meet");
                            of_class[at].2
                        } else {
                            ring(a).interiors_overlap(ring(b))
                        };
                        out.push(EmbeddingPair {
                            first: valid[a],
                            second: valid[b],
                            overlap,
                            intersection: OnceCell::new(),
                            types: OnceCell::new(),
                        });
                    }
                }
                out
            })
        })
    }

    /// By class: the pairs a < b of its valid embeddings whose skeleton
    /// polygons' bounding boxes meet, with whether their interiors overlap
    /// (Def 5.7's relation; [`Study::embedding_pairs`] takes its pairs of
    /// one skeleton from here).
    pub fn skeleton_pairs(&self) -> &[Vec<SkeletonPair>] {
        self.skeleton_pairs.get_or_init(|| {
            let witnesses = self.witnesses();
            let embeddings = self.embeddings();
            let keys = self.decomposition().skeletons();
            self.timer.stage("skeleton pairs", || {
                // The study's skeleton rings if made already (the chapter 4
                // claims make them first), else this class's valid ones
                // made here: the same rings, h(V◇) of [`Study::embeddings`].
                let built = self.rings.get();
                witnesses
                    .iter()
                    .zip(embeddings)
                    .enumerate()
                    .map(|(class, (ws, hs))| {
                        let valid: Vec<usize> =
                            (0..ws.len()).filter(|&i| ws[i].is_valid()).collect();
                        if valid.len() < 2 {
                            return Vec::new();
                        }
                        let own: Vec<SkeletonRing> = match built {
                            Some(_) => Vec::new(),
                            None => {
                                let artificial: Vec<bool> =
                                    keys[class].labels.iter().map(Option::is_some).collect();
                                valid
                                    .iter()
                                    .map(|&i| {
                                        SkeletonRing::new(hs[i].polygon(), artificial.clone())
                                    })
                                    .collect()
                            }
                        };
                        let ring = |x: usize| match built {
                            Some(r) => &r[class][valid[x]],
                            None => &own[x],
                        };
                        let mut out = Vec::new();
                        for x in 0..valid.len() {
                            for y in x + 1..valid.len() {
                                if ring(x).boxes_meet(ring(y)) {
                                    let overlap = ring(x).interiors_overlap(ring(y));
                                    out.push((valid[x], valid[y], overlap));
                                }
                            }
                        }
                        out
                    })
                    .collect()
            })
        })
    }

    /// By class, embedding and witness cell: the map edge seen through
    /// each skeleton edge (`None` for full edges) from the cell's
    /// representative point: for a 2-cell by the rule the decomposition's
    /// walk computes skeletons by (`wai_embed::witness_views_by_rule`: two
    /// orientations, else a look-up in the view from the artificial edge's
    /// first vertex), for a 1- or 0-cell from V_w of a visibility query.
    /// That the point's skeleton is the embedding's is the decomposition's
    /// (claims T3.3b and L3.5 check it on every cell).
    pub fn views(&self) -> &[Vec<Views>] {
        self.views.get_or_init(|| {
            let witnesses = self.witnesses();
            let index = self.index();
            self.timer.stage("views", || {
                // The view from each map vertex, computed when first needed.
                let vertex_views: Vec<OnceCell<Vec<(usize, usize)>>> =
                    (0..self.map.n()).map(|_| OnceCell::new()).collect();
                let view = |x: usize| -> &[(usize, usize)] {
                    vertex_views[x].get_or_init(|| index.vertex_view(x))
                };
                self.embeddings()
                    .iter()
                    .zip(witnesses)
                    .map(|(hs, ws)| {
                        hs.iter()
                            .zip(ws)
                            .map(|(h, w)| witness_views_by_rule(index, view, &h.embedding, w))
                            .collect()
                    })
                    .collect()
            })
        })
    }

    /// Of embedding `i` of class `class`: one sight fan per witness cell
    /// and artificial edge (Def 4.4's lines of sight,
    /// `wai_embed::SightFan`); built when first asked for, as most
    /// embeddings' fans are never needed (building all of them costs more
    /// than every other chapter 4 structure together).
    pub fn fans(&self, class: usize, i: usize) -> &[SightFan] {
        let slots = self.fans.get_or_init(|| {
            self.embeddings()
                .iter()
                .map(|hs| hs.iter().map(|_| OnceCell::new()).collect())
                .collect()
        });
        slots[class][i].get_or_init(|| {
            self.timer.stage("sight fans", || {
                sight_fans(
                    self.map,
                    &self.embeddings()[class][i].embedding,
                    &self.witnesses()[class][i],
                    &self.views()[class][i],
                )
            })
        })
    }

    /// Def 4.4 on pair `pair` of [`Study::overlapping_pairs`]: whether
    /// candidate edge `first.1` of artificial edge `first.0` (a skeleton
    /// edge's index) in the pair's embedding `a` crosses candidate edge
    /// `second.1` of `second.0` in embedding `b`, with two lines of sight
    /// that show it. Exact over whole witness regions
    /// (`wai_embed::crossing`, each witness cell's fan against each);
    /// decided once.
    pub fn crosses(
        &self,
        pair: usize,
        first: (usize, usize),
        second: (usize, usize),
    ) -> Option<Crossing> {
        let key = (pair, first, second);
        if let Some(x) = self.crossings.borrow().get(&key) {
            return x.clone();
        }
        let p = &self.overlapping_pairs()[pair];
        let map = self.map;
        let found = self.timer.stage("crossings", || {
            (first.1 != second.1)
                .then(|| {
                    self.fans_seeing(p.class, p.a, first)
                        .flat_map(|f| self.fans_seeing(p.class, p.b, second).map(move |g| (f, g)))
                        .find_map(|(f, g)| crossing(map, f, g, false))
                })
                .flatten()
        });
        self.crossings.borrow_mut().insert(key, found.clone());
        found
    }

    /// The fans of embedding `i` of class `class` (as [`Study::fans`])
    /// whose witness cells see candidate edge `key.1` through artificial
    /// edge `key.0`.
    pub fn fans_seeing(
        &self,
        class: usize,
        i: usize,
        (a, c): (usize, usize),
    ) -> impl Iterator<Item = &SightFan> + '_ {
        self.fans(class, i)
            .iter()
            .filter(move |f| f.artificial == a && f.edge == c)
    }

    /// By class and embedding: the valid candidate edges (Def 4.1) of
    /// each skeleton edge (empty for full edges), read off the witness
    /// views once.
    pub fn valid_candidates(&self, class: usize, embedding: usize) -> &[Vec<usize>] {
        &self.valid.get_or_init(|| {
            self.timer.stage("valid candidates", || {
                self.embeddings()
                    .iter()
                    .zip(self.views())
                    .map(|(hs, views)| {
                        hs.iter()
                            .zip(views)
                            .map(|(h, v)| {
                                wai_embed::valid_from_views(h.embedding.vertices.len(), v)
                            })
                            .collect()
                    })
                    .collect()
            })
        })[class][embedding]
    }

    /// By class: the sets C_{i,j} of valid candidate edges over the valid
    /// embeddings of its skeleton, with its single and multiple candidate
    /// edges (Def 5.4) and gaps (Def 5.5).
    pub fn candidate_sets(&self) -> &[CandidateSets] {
        self.candidate_sets.get_or_init(|| {
            self.timer.stage("candidate sets", || {
                let keys = self.decomposition().skeletons();
                (0..keys.len())
                    .map(|class| {
                        let artificial: Vec<usize> = keys[class]
                            .labels
                            .iter()
                            .enumerate()
                            .filter_map(|(i, l)| l.as_ref().map(|_| i))
                            .collect();
                        let valid: Vec<(usize, Vec<Vec<usize>>)> = self.witnesses()[class]
                            .iter()
                            .enumerate()
                            .filter(|(_, w)| w.is_valid())
                            .map(|(j, _)| (j, self.valid_candidates(class, j).to_vec()))
                            .collect();
                        CandidateSets::new(self.map, artificial, valid)
                    })
                    .collect()
            })
        })
    }

    /// By class: the gaps as boundary chains, the nested and interweaved
    /// pairs (Def 5.6), and the interweavement graph (Defs 5.7–5.9).
    pub fn gap_structures(&self) -> &[GapStructure] {
        self.gaps.get_or_init(|| {
            self.timer.stage("gap structures", || {
                let sets = self.candidate_sets();
                let mut overlapping: Vec<Vec<(usize, usize)>> = vec![Vec::new(); sets.len()];
                for (class, pairs) in self.skeleton_pairs().iter().enumerate() {
                    for &(a, b, overlap) in pairs {
                        if overlap {
                            let j =
                                |i: usize| sets[class].embeddings.binary_search(&i).expect("valid");
                            overlapping[class].push((j(a), j(b)));
                        }
                    }
                }
                sets.iter()
                    .zip(overlapping)
                    .map(|(c, overlapping)| {
                        GapStructure::new(gap_chains(self.map, &c.sets), overlapping, c.t())
                    })
                    .collect()
            })
        })
    }

    /// By class: every ordered pair (e, f) of map edges that are valid
    /// candidate edges of different artificial edges in some valid
    /// embedding, with those embeddings (the premise of Lemmas 5.13, 5.14
    /// and Theorem 5.15; [`crate::edge_pairs::shared_embeddings`]).
    pub fn edge_pairs(&self) -> &[crate::edge_pairs::SharedPairs] {
        self.edge_pairs.get_or_init(|| {
            let sets = self.candidate_sets();
            self.timer.stage("edge pairs", || {
                sets.iter()
                    .map(crate::edge_pairs::shared_embeddings)
                    .collect()
            })
        })
    }

    /// By class, by 2-cell: the cell's edges as kernel or wedge edges
    /// (Def 5.2) of the embedding it lies in (the one whose origin is the
    /// cell's skeleton origin), the wedges those of its valid candidate
    /// edges. Each edge is classified by its supporting line, in integers
    /// (`wai_embed::wedge::classify_by_lines`, which relies on the cell
    /// lying in its embedding's kernel, Observation 3.13); the tests
    /// compare it with `classify_cell_edges`, which reads the kernel's
    /// edges and the cell's exact points.
    pub fn cell_edges(&self) -> &[Vec<CellEdges>] {
        self.cell_edges.get_or_init(|| {
            self.timer.stage("cell edges", || {
                let d = self.decomposition();
                let arr = self.arrangement();
                // By arrangement edge: two map points on its line.
                let supports: Vec<(wai_exact::Point, wai_exact::Point)> = (0..arr.edge_count())
                    .map(|e| crate::preprocessing::support_points(arr, e))
                    .collect();
                d.classes()
                    .iter()
                    .enumerate()
                    .map(|(class, cells)| {
                        let hs = &self.embeddings()[class];
                        let mut lines: BTreeMap<usize, Vec<(wai_exact::Point, wai_exact::Point)>> =
                            BTreeMap::new();
                        cells
                            .iter()
                            .map(|&f| {
                                let o = d.origin_of(f);
                                let j = hs
                                    .iter()
                                    .position(|h| h.embedding.origin == o)
                                    .expect("a cell's skeleton is embedded at its own origin");
                                let lines = lines.entry(j).or_insert_with(|| {
                                    embedding_wedge_lines(
                                        self.map,
                                        &hs[j].embedding,
                                        self.valid_candidates(class, j),
                                    )
                                });
                                let kinds = classify_by_lines(
                                    hs[j].polygon(),
                                    lines,
                                    arr.face_cycle(f).map(|h| supports[h / 2]),
                                );
                                CellEdges {
                                    cell: f,
                                    embedding: j,
                                    kinds,
                                }
                            })
                            .collect()
                    })
                    .collect()
            })
        })
    }

    /// By class: its kernel edges K and wedge edges W, and W by embedding
    /// ([`crate::wedge_counts::counts`] of [`Study::cell_edges`]), which
    /// the bounds L5.1, L5.2 and T5.16 read.
    pub fn edge_counts(&self) -> &[crate::wedge_counts::EdgeCounts] {
        self.edge_counts.get_or_init(|| {
            let cells = self.cell_edges();
            self.timer
                .stage("edge counts", || crate::wedge_counts::counts(cells))
        })
    }

    /// The map preprocessed for localization by Alg 3.14 from the study's
    /// decomposition (steps 17–26: per class, its cells of every dimension
    /// translated to their embedding's origin and overlaid, with slab point
    /// location; `wai_localize::Localizer::from_decomposition`).
    pub fn localizer(&self) -> &Localizer {
        self.localizer.get_or_init(|| {
            let d = self.decomposition();
            self.timer
                .stage("localizer", || Localizer::from_decomposition(d))
        })
    }

    /// The size of Alg 3.14's preprocessing: the trapezoids of the
    /// overlays of every class, as [`Study::localizer`] would build them
    /// (`Localizer::trapezoids`), counted from the decomposition in `i128`
    /// without building the overlays ([`crate::preprocessing`]); from the
    /// localizer itself when a number does not fit.
    pub fn preprocessing_size(&self) -> usize {
        *self.preprocessing_size.get_or_init(|| {
            let d = self.decomposition();
            self.timer
                .stage("preprocessing size", || crate::preprocessing::trapezoids(d))
                .unwrap_or_else(|| self.localizer().trapezoids())
        })
    }

    /// V_p of each of [`sample::viewpoints`]`(map, limit)`, by the
    /// production algorithm.
    pub fn sampled_polygons(&self, limit: usize) -> Rc<Vec<VisibilityPolygon>> {
        if let Some(v) = self.polygons.borrow().get(&limit) {
            return Rc::clone(v);
        }
        let v = Rc::new(self.timer.stage("sampled polygons", || {
            sample::visibility_polygons_with(self.map, self.index(), limit)
        }));
        self.polygons.borrow_mut().insert(limit, Rc::clone(&v));
        v
    }
}

/// V*_p at `p` in map terms, or why it cannot be built.
pub fn fresh_skeleton(index: &VisibilityIndex<'_>, p: &RatPoint) -> FreshSkeleton {
    index.skeleton_at(p).map_err(|e| e.to_string())
}

impl std::fmt::Debug for Study<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Study")
            .field("map", &sample::map_name(self.map))
            .field("index", &self.index.get().is_some())
            .field("decomposition", &self.decomposition.get().is_some())
            .field(
                "sampled",
                &self.polygons.borrow().keys().collect::<Vec<_>>(),
            )
            .finish()
    }
}

impl<'m> From<&'m Map> for Study<'m> {
    fn from(map: &'m Map) -> Self {
        Study::new(map)
    }
}
