//! The figures of `counterexamples/` show what their notes say: each test
//! rebuilds the configuration from the stored map and its viewpoints.

use std::path::Path;

use serde_json::Value;
use wai_embed::{interiors_overlap, Mutual, Pt};
use wai_exact::{orientation, Orientation, RatPoint};
use wai_lemmas::Study;
use wai_map::{json::from_json, Map};
use wai_visibility::{Skeleton, SkeletonKey};

use crate::counterexamples::{viewpoint, DIR};

/// The map of `file` and its viewpoints.
fn load(file: &str) -> (Map, Vec<RatPoint>) {
    let path = Path::new(DIR).join(file);
    let bytes = std::fs::read(&path).unwrap_or_else(|e| panic!("{file}: {e}"));
    let map = from_json(&bytes).expect("valid").map;
    let value: Value = serde_json::from_slice(&bytes).unwrap();
    let points = value["viewpoints"]
        .as_array()
        .map(|a| a.iter().map(|v| viewpoint(&map, v, &path)).collect())
        .unwrap_or_default();
    (map, points)
}

/// The skeleton of each viewpoint (all must be equal) and its class.
fn common_skeleton(study: &Study<'_>, points: &[RatPoint]) -> (SkeletonKey, usize) {
    let keys: Vec<SkeletonKey> = points
        .iter()
        .map(|p| {
            let vp = study.index().visibility_polygon(p).unwrap();
            Skeleton::of(study.map(), &vp).unwrap().key()
        })
        .collect();
    assert!(
        keys.windows(2).all(|w| w[0] == w[1]),
        "the viewpoints' skeletons differ"
    );
    let class = study
        .decomposition()
        .skeletons()
        .iter()
        .position(|k| *k == keys[0])
        .expect("the skeleton is a class");
    (keys[0].clone(), class)
}

#[test]
fn fig_3_12_one_skeleton_three_valid_embeddings() {
    let (map, points) = load("L3.7t-fig-3-12d.json");
    let study = Study::new(&map);
    let (_, class) = common_skeleton(&study, &points);
    assert_eq!(study.embeddings()[class].len(), 3);
    assert!(study.witnesses()[class].iter().all(|w| w.is_valid()));
}

#[test]
fn fig_3_10_an_embedding_without_witness() {
    let (map, points) = load("R3.4-short-candidate.json");
    let study = Study::new(&map);
    let (key, class) = common_skeleton(&study, &points);
    let all = &study.embeddings()[class];
    let ws = &study.witnesses()[class];
    assert_eq!(all.len(), 2);
    let v = map.vertices();
    let east = all
        .iter()
        .position(|h| v[h.embedding.origin] == wai_exact::Point::new(20, -4))
        .expect("an embedding at the east niche");
    assert!(
        ws[1 - east].is_valid(),
        "the west niche's viewpoint is a witness"
    );
    assert!(!ws[east].is_valid(), "the east embedding has a witness");
    // Its only candidate edge, the pillar's bottom, is shorter than the
    // artificial edge.
    let h = &all[east].embedding;
    let i = key.labels.iter().position(Option::is_some).unwrap();
    assert_eq!(h.candidates[i].len(), 1);
    let e = h.candidates[i][0];
    let length = |a: wai_exact::Point, b: wai_exact::Point| (a.x - b.x).abs() + (a.y - b.y).abs();
    let k = h.vertices.len();
    assert!(
        length(v[e], v[(e + 1) % map.n()]) < length(v[h.vertices[i]], v[h.vertices[(i + 1) % k]])
    );
}

#[test]
fn figs_4_1_and_4_2_overlapping_kernels_and_crossing_artificial_edges() {
    let (map, points) = load("E4.1-funnels-kernels-overlap.json");
    let study = Study::new(&map);
    let (key, class) = common_skeleton(&study, &points);
    let all = &study.embeddings()[class];
    assert_eq!(all.len(), 2);
    assert!(study.witnesses()[class].iter().all(|w| w.is_valid()));
    let ring = |i: usize| -> Vec<Pt> {
        all[i]
            .embedding
            .polygon(&map)
            .into_iter()
            .map(Pt::from)
            .collect()
    };
    let kernel = |i: usize| -> Vec<Pt> { all[i].kernel.vertices().iter().map(Pt::from).collect() };
    assert!(interiors_overlap(&ring(0), &ring(1)));
    assert!(interiors_overlap(&kernel(0), &kernel(1)));
    // Fig 4.2: an artificial edge of one strictly crosses one of the other.
    let (p, q) = (
        all[0].embedding.polygon(&map),
        all[1].embedding.polygon(&map),
    );
    let k = p.len();
    let artificial: Vec<usize> = (0..k).filter(|&i| key.labels[i].is_some()).collect();
    let strict = artificial.iter().any(|&a| {
        artificial.iter().any(|&b| {
            let (s, t) = ((p[a], p[(a + 1) % k]), (q[b], q[(b + 1) % k]));
            let o = [
                orientation(s.0, s.1, t.0),
                orientation(s.0, s.1, t.1),
                orientation(t.0, t.1, s.0),
                orientation(t.0, t.1, s.1),
            ];
            !o.contains(&Orientation::Collinear) && o[0] != o[1] && o[2] != o[3]
        })
    });
    assert!(strict, "no strictly crossing artificial edges");
    // Theorems 4.2 and 4.3: the witnesses do not see each other, by both
    // methods.
    let pair = study
        .overlapping_pairs()
        .iter()
        .find(|p| p.class == class)
        .expect("the pair overlaps");
    assert!(pair.kernels_overlap);
    assert!(matches!(pair.sight, Mutual::Invisible { .. }));
    let ws = &study.witnesses()[class];
    assert!(!study
        .sightlines()
        .regions_by_points(&ws[0].pieces(), &ws[1].pieces())
        .is_visible());
    // Example 4.4 (2): candidate edges of the two embeddings cross (Def
    // 4.4), shown by two lines of sight that meet.
    let k = study
        .overlapping_pairs()
        .iter()
        .position(|p| p.class == class)
        .expect("the pair overlaps");
    let (va, vb) = (
        study.valid_candidates(class, pair.a),
        study.valid_candidates(class, pair.b),
    );
    let mut crossing = 0;
    for (i, ci) in va.iter().enumerate() {
        for (j, cj) in vb.iter().enumerate() {
            for &c in ci {
                for &d in cj {
                    crossing += usize::from(study.crosses(k, (i, c), (j, d)).is_some());
                }
            }
        }
    }
    assert!(crossing > 0, "no crossing candidate edges");
}

#[test]
fn lemma_4_17_corollary_fails_for_def_3_11_candidate_edges_only() {
    let (map, points) = load("L4.17-shared-candidate-edge.json");
    let study = Study::new(&map);
    let (_, class) = common_skeleton(&study, &points);
    let all = &study.embeddings()[class];
    assert_eq!(all.len(), 1);
    let h = &all[0].embedding;
    let shared = |sets: &[Vec<usize>]| -> usize {
        (0..sets.len())
            .flat_map(|a| (a + 1..sets.len()).map(move |b| (a, b)))
            .map(|(a, b)| sets[a].iter().filter(|e| sets[b].contains(e)).count())
            .sum()
    };
    // Two map edges are Def 3.11 candidates of both artificial edges …
    assert_eq!(shared(&h.candidates), 2);
    // … but valid candidates of one each.
    assert_eq!(shared(study.valid_candidates(class, 0)), 0);
    let report = wai_lemmas::l4_17::checker().check_study(&study);
    assert!(report.violations.is_empty(), "{:?}", report.violations);
    assert!(report.counts["shared_def_3_11"] > 0);
}

#[test]
fn fig_4_16_four_type_5_edges_and_no_map_vertex() {
    use std::collections::HashSet;
    use wai_embed::intersection::EdgeType;
    let (map, points) = load("E4.10-four-type-5.json");
    let study = Study::new(&map);
    let (_, class) = common_skeleton(&study, &points);
    assert_eq!(study.embeddings()[class].len(), 2);
    assert!(study.witnesses()[class].iter().all(|w| w.is_valid()));
    let pair = study
        .embedding_pairs()
        .iter()
        .find(|p| p.first.0 == class && p.second.0 == class)
        .expect("the two embeddings are a pair");
    let x = study.intersection(pair).expect("they overlap");
    let rings = study.skeleton_rings();
    let vertices: HashSet<Pt> = map.vertices().iter().map(|&p| Pt::from(p)).collect();
    let types = wai_lemmas::l4_7::types(x, &rings[class][0], &rings[class][1], &vertices);
    assert_eq!(types, vec![Some(EdgeType::TwoCrossings); 4]);
    assert!(x
        .cycles
        .iter()
        .flatten()
        .all(|e| !vertices.contains(&e.from)));
    let overlapping = study
        .overlapping_pairs()
        .iter()
        .find(|p| p.class == class)
        .unwrap();
    assert!(!overlapping.sight.is_visible());
}
