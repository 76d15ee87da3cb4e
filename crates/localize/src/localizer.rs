//! The preprocessed localizer (Alg 3.14) and its query (Alg 3.13).

use crate::overlay::{CellSite, ClassOverlay, Item, Shape};
use crate::shifted;
use crate::view::{NoSkeleton, RobotView};
use rustc_hash::FxHashMap;
use wai_cells::{Decomposition, LowerSite};
use wai_exact::RatPoint;
use wai_map::Map;
use wai_visibility::SkeletonKey;

/// One position where the robot can be (an element of the answer set A,
/// Def 3.2), with the embedding that gives it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Placement {
    /// The robot's position, in map units.
    pub position: RatPoint,
    /// The map vertex that is the image of the skeleton origin v0: the
    /// embedding h, a translation by this vertex minus v0.
    pub origin_vertex: usize,
    /// The cell of the decomposition the position lies in.
    pub cell: CellSite,
}

/// Why the answer set is empty.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum Nowhere {
    #[error("no skeleton can be formed from the polygon: {0}")]
    NoSkeleton(#[from] NoSkeleton),
    #[error("no cell of the map has the polygon's skeleton (no equivalence class matches)")]
    NoClass,
    #[error("the skeleton matches class {0}, but the robot's position relative to v0 lies in no cell of the class")]
    NoCell(usize),
}

/// The answer to a query: every placement (ascending by origin vertex), or
/// none and why.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Answer {
    pub class: Option<usize>,
    pub placements: Vec<Placement>,
    pub nowhere: Option<Nowhere>,
}

impl Answer {
    fn nowhere(class: Option<usize>, why: Nowhere) -> Answer {
        Answer {
            class,
            placements: Vec::new(),
            nowhere: Some(why),
        }
    }

    /// The positions alone, ascending.
    pub fn positions(&self) -> Vec<RatPoint> {
        let mut p: Vec<RatPoint> = self.placements.iter().map(|a| a.position.clone()).collect();
        p.sort_by(crate::cmp_points);
        p
    }
}

/// A map preprocessed for localization (Alg 3.14): a map from skeleton
/// keys to classes, and per class the overlay of its cells.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Localizer {
    pub(crate) map: Map,
    pub(crate) keys: Vec<SkeletonKey>,
    pub(crate) by_key: FxHashMap<SkeletonKey, usize>,
    pub(crate) overlays: Vec<ClassOverlay>,
}

impl Localizer {
    /// Preprocess `map`: decompose it, then overlay each class.
    pub fn new(map: &Map) -> Localizer {
        Localizer::from_decomposition(&Decomposition::new(map))
    }

    /// Overlay the classes of a decomposition (Alg 3.14 steps 18–23): each
    /// cell of every dimension translated by minus its origin vertex.
    pub fn from_decomposition(d: &Decomposition<'_>) -> Localizer {
        let map = d.map();
        let arr = d.arrangement();
        let keys = d.skeletons().to_vec();
        let mut items: Vec<Vec<Item>> = vec![Vec::new(); keys.len()];
        for (k, cells) in d.classes().iter().enumerate() {
            for &f in cells {
                let o = d.origin_of(f);
                let ov = map.vertices()[o];
                items[k].push(Item {
                    origin: o,
                    site: CellSite::Face(f),
                    shape: Shape::Polygon(
                        arr.face_points(f)
                            .iter()
                            .map(|p| shifted(p, ov, -1))
                            .collect(),
                    ),
                });
            }
        }
        for (i, c) in d.lower_cells().iter().enumerate() {
            let ov = map.vertices()[c.origin];
            let shape = match c.site {
                LowerSite::Edge(e) => Shape::Segment(
                    shifted(arr.point(arr.half_edge(2 * e).origin), ov, -1),
                    shifted(arr.point(arr.dest(2 * e)), ov, -1),
                ),
                LowerSite::Vertex(v) => Shape::Point(shifted(arr.point(v), ov, -1)),
            };
            items[c.class].push(Item {
                origin: c.origin,
                site: CellSite::Lower(i),
                shape,
            });
        }
        let overlays = items.into_iter().map(ClassOverlay::new).collect();
        Localizer::assemble(map.clone(), keys, overlays)
    }

    pub(crate) fn assemble(map: Map, keys: Vec<SkeletonKey>, overlays: Vec<ClassOverlay>) -> Self {
        let by_key = keys
            .iter()
            .cloned()
            .enumerate()
            .map(|(i, k)| (k, i))
            .collect();
        Localizer {
            map,
            keys,
            by_key,
            overlays,
        }
    }

    pub fn map(&self) -> &Map {
        &self.map
    }

    /// The number of classes (Def 3.10).
    pub fn classes(&self) -> usize {
        self.keys.len()
    }

    /// Cells of every dimension placed in the overlays.
    pub fn cells(&self) -> usize {
        self.overlays.iter().map(|o| o.items.len()).sum()
    }

    /// Trapezoids over all overlays: the size of the point location.
    pub fn trapezoids(&self) -> usize {
        self.overlays.iter().map(ClassOverlay::trapezoids).sum()
    }

    /// The overlay of class `k`.
    pub fn overlay(&self, k: usize) -> &ClassOverlay {
        &self.overlays[k]
    }

    /// The class of a skeleton key, if any cell has that skeleton.
    pub fn class_of(&self, key: &SkeletonKey) -> Option<usize> {
        self.by_key.get(key).copied()
    }

    /// Alg 3.13: skeleton of V, its class, the robot's position relative
    /// to v0 located in the class's overlay, and the placements.
    pub fn localize(&self, v: &RobotView) -> Answer {
        let sk = match v.skeleton() {
            Ok(s) => s,
            Err(e) => return Answer::nowhere(None, e.into()),
        };
        let Some(k) = self.class_of(&sk.key) else {
            return Answer::nowhere(None, Nowhere::NoClass);
        };
        // No check that V is what the skeleton and the robot's position
        // rebuild (Thm 3.2) is needed: in a checked V every spurious vertex
        // lies on the ray through its blocking vertex and on the line of
        // its half or partial edge, which is where `reconstruct` puts it
        // (the tests assert the equality on every view they make). So a
        // point of a cell of this class sees exactly V (Cor 3.6).
        let overlay = &self.overlays[k];
        let hits = overlay.locate(&sk.robot);
        if hits.is_empty() {
            return Answer::nowhere(Some(k), Nowhere::NoCell(k));
        }
        let mut placements: Vec<Placement> = hits
            .iter()
            .map(|&i| {
                let it = &overlay.items[i as usize];
                Placement {
                    position: shifted(&sk.robot, self.map.vertices()[it.origin], 1),
                    origin_vertex: it.origin,
                    cell: it.site,
                }
            })
            .collect();
        placements.sort_by_key(|p| p.origin_vertex);
        Answer {
            class: Some(k),
            placements,
            nowhere: None,
        }
    }
}
