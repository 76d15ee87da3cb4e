//! Def 3.11: the embeddings of a skeleton in a map, and the candidate
//! edges of their artificial edges.

use crate::sight::EdgeSight;
use rustc_hash::FxHashMap as HashMap;
use std::sync::{Mutex, OnceLock};
use wai_exact::Point;
use wai_map::Map;
use wai_visibility::{kernel_of_ring, ConvexRegion, LineLabel, SkeletonKey, VisibilityIndex};

/// An embedding h of a skeleton V* in the map (Def 3.11): where each
/// vertex of V* lands, and the candidate edges of each artificial edge.
///
/// h is a translation, fixed by the image of the origin v0 (the proof of
/// Lemma 3.7): `h(p) = p + h(v0)` in the skeleton's coordinates, whose
/// origin is v0.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Embedding {
    /// The map vertex h(v0).
    pub origin: usize,
    /// By skeleton vertex, in the key's order (counter-clockwise from
    /// v0): the map vertex h(v).
    pub vertices: Vec<usize>,
    /// By skeleton edge (from vertex i to i + 1): for an artificial edge,
    /// its candidate edges in h (map edge ids, ascending: never empty);
    /// for a full edge, empty.
    pub candidates: Vec<Vec<usize>>,
}

impl Embedding {
    /// The embedded skeleton polygon h(V◇): the map points of its
    /// vertices, counter-clockwise from h(v0).
    pub fn polygon(&self, map: &Map) -> Vec<Point> {
        self.vertices.iter().map(|&m| map.vertices()[m]).collect()
    }

    /// The embedded kernel h(ker V*) (Def 3.12): the kernel of h(V◇),
    /// which h, a translation, carries from ker V*.
    pub fn kernel(&self, map: &Map) -> ConvexRegion {
        kernel_of_ring(&self.polygon(map))
    }
}

/// Finds the embeddings of skeletons in one map: the map's vertices by
/// position, its edges by line, and the view from each map vertex,
/// computed when first needed from the map's visibility index (shared
/// with whoever built it).
#[derive(Debug)]
pub struct Embedder<'a> {
    map: &'a Map,
    index: &'a VisibilityIndex<'a>,
    /// Map vertex by position.
    at: HashMap<Point, usize>,
    /// Map edges by their line, labelled relative to (0, 0).
    on_line: HashMap<LineLabel, Vec<usize>>,
    /// By map vertex: `VisibilityIndex::vertex_view`.
    views: Vec<OnceLock<Vec<(usize, usize)>>>,
    /// Condition 3's test, by (map vertex a, map vertex b, map edge e):
    /// whether a and b both see a point of e. Neighbouring cells' skeletons
    /// share most artificial edges, so most classes ask again what another
    /// asked.
    seen_by_both: Mutex<HashMap<(usize, usize, usize), bool>>,
    /// What map vertex y sees of map edge e, by (y, e), computed once.
    sights: Mutex<HashMap<(usize, usize), EdgeSight>>,
}

/// The embeddings of skeleton `key` in `map` (Def 3.11), by ascending
/// map vertex h(v0). See [`Embedder::embeddings`].
pub fn embeddings(map: &Map, key: &SkeletonKey) -> Vec<Embedding> {
    Embedder::new(&VisibilityIndex::new(map)).embeddings(key)
}

impl<'a> Embedder<'a> {
    /// The embedder of the map of `index`.
    pub fn new(index: &'a VisibilityIndex<'a>) -> Embedder<'a> {
        let map = index.map();
        let v = map.vertices();
        let n = v.len();
        let mut on_line: HashMap<LineLabel, Vec<usize>> = HashMap::default();
        let zero = Point::new(0, 0);
        for e in 0..n {
            let label = LineLabel::through(v[e], v[map.next(e)], zero);
            on_line.entry(label).or_default().push(e);
        }
        Embedder {
            map,
            index,
            at: v.iter().enumerate().map(|(i, &p)| (p, i)).collect(),
            on_line,
            views: (0..n).map(|_| OnceLock::new()).collect(),
            seen_by_both: Mutex::new(HashMap::default()),
            sights: Mutex::new(HashMap::default()),
        }
    }

    /// Every embedding of `key`, by ascending h(v0): one per map vertex at
    /// which conditions 1–3 of Def 3.11 hold.
    ///
    /// # Edge cases
    /// - Every map vertex is tried as h(v0), reflex or not: Def 3.11 does
    ///   not ask for a reflex one (Lemma 3.7's bound r is for the claim's
    ///   checker to confirm).
    /// - Condition 2 is an "if and only if": a map edge between the images
    ///   of two skeleton vertices that are not joined by a full edge rules
    ///   the placement out.
    pub fn embeddings(&self, key: &SkeletonKey) -> Vec<Embedding> {
        (0..self.map.n())
            .filter_map(|o| self.embedding_at(key, o))
            .collect()
    }

    /// The embedding of `key` with h(v0) at map vertex `origin`, if
    /// conditions 1–3 of Def 3.11 hold there.
    pub fn embedding_at(&self, key: &SkeletonKey, origin: usize) -> Option<Embedding> {
        let map = self.map;
        let v = map.vertices();
        let o = v[origin];
        let k = key.offsets.len();
        let lands = |&(dx, dy): &(i128, i128)| {
            let p = Point::new(o.x.checked_add(dx)?, o.y.checked_add(dy)?);
            self.at.get(&p).copied()
        };
        // 1. Each vertex lands on a map vertex (a translation is injective);
        // the last vertex first, as most origins fail there at once.
        lands(key.offsets.last()?)?;
        let vertices: Vec<usize> = key.offsets.iter().map(lands).collect::<Option<_>>()?;
        // 2. Full edges are exactly the map edges among the images (a
        // skeleton has few vertices: a linear search finds an image).
        let image = |m: usize| vertices.iter().position(|&v| v == m);
        let full = |i: usize| key.labels[i].is_none();
        for i in 0..k {
            let j = (i + 1) % k;
            let adjacent =
                vertices[j] == map.next(vertices[i]) || vertices[i] == map.next(vertices[j]);
            if full(i) != adjacent {
                return None;
            }
            for m in [map.next(vertices[i]), map.prev(vertices[i])] {
                if let Some(j) = image(m) {
                    let joined = (j == (i + 1) % k && full(i)) || (i == (j + 1) % k && full(j));
                    if !joined {
                        return None;
                    }
                }
            }
        }
        // 3. Each artificial edge has a candidate edge.
        let mut candidates = vec![Vec::new(); k];
        for i in 0..k {
            let Some(label) = &key.labels[i] else {
                continue;
            };
            let (a, b) = (vertices[i], vertices[(i + 1) % k]);
            candidates[i] = self.candidates(label, o, a, b);
            if candidates[i].is_empty() {
                return None;
            }
        }
        Some(Embedding {
            origin,
            vertices,
            candidates,
        })
    }

    /// The map edges on the line `label` (relative to `o`) with a point
    /// that map vertices `a` and `b` both see, ascending.
    fn candidates(&self, label: &LineLabel, o: Point, a: usize, b: usize) -> Vec<usize> {
        // The same line relative to (0, 0): a·x + b·y = c + a·o.x + b·o.y,
        // still in lowest terms (the gcd of a and b divides the change).
        let absolute = LineLabel {
            a: label.a.clone(),
            b: label.b.clone(),
            c: label.c.clone() + &label.a * o.x + &label.b * o.y,
        };
        let Some(edges) = self.on_line.get(&absolute) else {
            return Vec::new();
        };
        edges
            .iter()
            .copied()
            .filter(|&e| self.both_see(a, b, e))
            .collect()
    }

    /// Whether map vertices `a` and `b` both see a point of map edge `e`
    /// (decided once per triple).
    fn both_see(&self, a: usize, b: usize, e: usize) -> bool {
        let key = (a, b, e);
        if let Some(&known) = self
            .seen_by_both
            .lock()
            .expect("no panic holding it")
            .get(&key)
        {
            return known;
        }
        let both = {
            let mut sights = self.sights.lock().expect("no panic holding it");
            for y in [a, b] {
                sights
                    .entry((y, e))
                    .or_insert_with(|| EdgeSight::of(self.map, self.view(y), y, e));
            }
            sights[&(a, e)].meets(&sights[&(b, e)])
        };
        self.seen_by_both
            .lock()
            .expect("no panic holding it")
            .insert(key, both);
        both
    }

    /// The view from map vertex `y`.
    fn view(&self, y: usize) -> &[(usize, usize)] {
        self.views[y].get_or_init(|| self.index.vertex_view(y))
    }
}
