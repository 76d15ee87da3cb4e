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
