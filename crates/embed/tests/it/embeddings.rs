//! Def 3.11 on decomposed maps: the identity embedding of Lemma 3.4 exists
//! for every cell, with the cell's own map edges among the candidates;
//! Lemma 3.7's bound; the corridor of niches; broken keys embed nowhere.

use crate::common::maps;
use std::collections::BTreeSet;
use wai_cells::Decomposition;
use wai_embed::{embeddings, Embedder};
use wai_visibility::{LineLabel, Skeleton, SkeletonEdge, SkeletonKey, VisibilityIndex};

/// Lemma 3.4: the skeleton of every cell embeds at the cell's own origin,
/// placing each vertex on the map vertex it came from, and each artificial
/// edge's own map edge (Def 3.7 (3), (4)) is one of its candidate edges.
/// Every embedding found also satisfies Lemma 3.7 (at most r of them).
#[test]
fn every_cell_embeds_at_its_own_origin() {
    let mut examined = 0;
    for m in maps(18, 3) {
        let d = Decomposition::new(&m);
        let index = VisibilityIndex::new(&m);
        let embedder = Embedder::new(&index);
        for &c in d.cells() {
            let vp = index.visibility_polygon(d.representative(c)).unwrap();
            let sk = Skeleton::of(&m, &vp).unwrap();
            let key = &d.skeletons()[d.skeleton_of(c)];
            assert_eq!(&sk.key(), key, "{:?}", m.name());
            let h = embedder
                .embedding_at(key, d.origin_of(c))
                .unwrap_or_else(|| panic!("{:?}: cell {c} does not embed at its origin", m.name()));
            assert_eq!(h.vertices, sk.map_vertices(), "{:?}", m.name());
            for (i, e) in sk.edges().iter().enumerate() {
                if let SkeletonEdge::Artificial { map_edge, .. } = e {
                    assert!(
                        h.candidates[i].contains(map_edge),
                        "{:?}: cell {c}, edge {i}: {map_edge} not among {:?}",
                        m.name(),
                        h.candidates[i]
                    );
                }
            }
            examined += 1;
        }
        for key in d.skeletons() {
            let all = embedder.embeddings(key);
            assert!(
                all.len() <= m.reflex_vertices().len().max(1),
                "{:?}: Lemma 3.7",
                m.name()
            );
        }
    }
    assert!(examined > 1000, "examined {examined} cells");
}

/// Lemma 3.7's tight example: the skeleton of the cells deep in the niches
/// of `corridor-niches` embeds once per niche.
#[test]
fn corridor_niches_embed_once_per_niche() {
    for k in 1..=4 {
        let m = wai_gen::family("corridor-niches", &[k]).unwrap();
        let d = Decomposition::new(&m);
        let most = d
            .skeletons()
            .iter()
            .map(|key| embeddings(&m, key).len())
            .max()
            .unwrap();
        assert_eq!(most, k as usize, "k = {k}");
    }
}

/// Planted: a key whose label is moved off every map line, or whose
/// vertex is moved off every map vertex, embeds nowhere; the unbroken key
/// embeds.
#[test]
fn broken_keys_embed_nowhere() {
    let m = wai_gen::random("random-orthogonal", 20, 1).unwrap();
    let d = Decomposition::new(&m);
    let key = d
        .skeletons()
        .iter()
        .find(|k| k.labels.iter().any(Option::is_some))
        .expect("a skeleton with an artificial edge")
        .clone();
    assert!(!embeddings(&m, &key).is_empty());
    let mut moved = key.clone();
    let i = moved.labels.iter().position(Option::is_some).unwrap();
    let l = moved.labels[i].clone().unwrap();
    moved.labels[i] = Some(LineLabel {
        c: l.c + 1_000_000_007,
        ..l
    });
    assert!(embeddings(&m, &moved).is_empty());
    let mut shifted: SkeletonKey = key.clone();
    shifted.offsets[1].0 += 1_000_003;
    assert!(embeddings(&m, &shifted).is_empty());
    // Condition 2: making an artificial edge full breaks it too.
    let mut full = key;
    full.labels[i] = None;
    let origins: BTreeSet<usize> = embeddings(&m, &full).iter().map(|h| h.origin).collect();
    assert!(origins.is_empty(), "{origins:?}");
}

/// What a hole does to Def 3.11 (thesis sec. 6.4): from a cell beside a
/// pillar, an outer edge is seen in two parts, either side of the pillar's
/// shadow, so the skeleton has both of its ends but not the edge between
/// them as a full edge, and two artificial edges on its line. Condition 2
/// (full edges are exactly the map edges among the images) then rules out
/// the placement at the cell's own origin, and Lemma 3.5 (every point lies
/// in the kernel of one embedding of its skeleton) needs the map without
/// holes.
#[test]
fn a_pillar_leaves_a_skeleton_without_an_embedding_at_its_own_origin() {
    let pt = |x, y| wai_exact::Point::new(x, y);
    let (map, _) = wai_map::Map::from_rings(
        vec![pt(22, 0), pt(24, 10), pt(0, 5)],
        vec![vec![pt(20, 6), pt(20, 9), pt(23, 9), pt(23, 6)]],
    )
    .expect("a triangle with a pillar");
    let d = Decomposition::new(&map);
    let mut without = 0;
    for (class, key) in d.skeletons().iter().enumerate() {
        let origin = d.origin_of(d.classes()[class][0]);
        if embeddings(&map, key).iter().any(|h| h.origin == origin) {
            continue;
        }
        without += 1;
        let o = map.vertices()[origin];
        let k = key.offsets.len();
        let image = |i: usize| {
            let (dx, dy) = key.offsets[i];
            let p = pt(o.x + dx, o.y + dy);
            map.vertices()
                .iter()
                .position(|&v| v == p)
                .expect("a map vertex")
        };
        let images: Vec<usize> = (0..k).map(image).collect();
        // A map edge between two images that is not a full skeleton edge.
        let split = (0..k).any(|i| {
            (0..k).any(|j| {
                images[j] == map.next(images[i]) && !(j == (i + 1) % k && key.labels[i].is_none())
            })
        });
        assert!(split, "class {class}: condition 2 holds at the origin");
        // Two artificial edges on one line: one map edge seen in two parts.
        let labels: Vec<_> = key.labels.iter().flatten().collect();
        assert!(
            (0..labels.len()).any(|a| (a + 1..labels.len()).any(|b| labels[a] == labels[b])),
            "class {class}: {key:?}"
        );
    }
    assert!(without > 0, "every skeleton embeds at its own origin");
}
