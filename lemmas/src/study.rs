//! One study per map: the structures the checkers read, each built the
//! first time a checker asks for it and then shared by every checker of a
//! run on that map (issue 7, "one study per map").
//!
//! map → visibility index → decomposition (rays, arrangement, the skeleton
//! of every cell of every dimension, classes) → sampled visibility
//! polygons; → the embeddings of every class's skeleton (Def 3.11) with
//! their candidate edges and kernels. Later chapters add their structures
//! here, so a stress run builds each once per map.

use std::cell::{OnceCell, RefCell};
use std::collections::BTreeMap;
use std::rc::Rc;

use wai_cells::{Arrangement, Decomposition, VisibilityRay};
use wai_embed::{Embedder, Embedding};
use wai_map::Map;
use wai_visibility::{ConvexRegion, VisibilityIndex, VisibilityPolygon};

use crate::sample;

/// A map and what has been computed about it so far.
pub struct Study<'m> {
    map: &'m Map,
    index: OnceCell<VisibilityIndex<'m>>,
    decomposition: OnceCell<Decomposition<'m>>,
    /// By sample limit: V_p of [`sample::viewpoints`]`(map, limit)`.
    polygons: RefCell<BTreeMap<usize, Rc<Vec<VisibilityPolygon>>>>,
    /// By class of the decomposition: its skeleton's embeddings.
    embeddings: OnceCell<Vec<Vec<Embedded>>>,
}

/// An embedding of a class's skeleton (Def 3.11) and its kernel
/// h(ker V*) (Def 3.12), in map coordinates.
#[derive(Debug, Clone)]
pub struct Embedded {
    pub embedding: Embedding,
    pub kernel: ConvexRegion,
}

impl<'m> Study<'m> {
    /// A study of `map` with nothing computed yet.
    pub fn new(map: &'m Map) -> Study<'m> {
        Study {
            map,
            index: OnceCell::new(),
            decomposition: OnceCell::new(),
            polygons: RefCell::new(BTreeMap::new()),
            embeddings: OnceCell::new(),
        }
    }

    pub fn map(&self) -> &'m Map {
        self.map
    }

    /// The production visibility index of the map.
    pub fn index(&self) -> &VisibilityIndex<'m> {
        self.index.get_or_init(|| VisibilityIndex::new(self.map))
    }

    /// The visibility cell decomposition (Def 3.8) with its cells of every
    /// dimension, their skeletons and classes.
    pub fn decomposition(&self) -> &Decomposition<'m> {
        self.decomposition
            .get_or_init(|| Decomposition::new(self.map))
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
            let embedder = Embedder::new(self.index());
            self.decomposition()
                .skeletons()
                .iter()
                .map(|key| {
                    embedder
                        .embeddings(key)
                        .into_iter()
                        .map(|embedding| Embedded {
                            kernel: embedding.kernel(self.map),
                            embedding,
                        })
                        .collect()
                })
                .collect()
        })
    }

    /// V_p of each of [`sample::viewpoints`]`(map, limit)`, by the
    /// production algorithm.
    pub fn sampled_polygons(&self, limit: usize) -> Rc<Vec<VisibilityPolygon>> {
        if let Some(v) = self.polygons.borrow().get(&limit) {
            return Rc::clone(v);
        }
        let v = Rc::new(sample::visibility_polygons_with(
            self.map,
            self.index(),
            limit,
        ));
        self.polygons.borrow_mut().insert(limit, Rc::clone(&v));
        v
    }
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
