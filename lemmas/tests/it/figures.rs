//! The figures of `counterexamples/` show what their notes say: each test
//! rebuilds the configuration from the stored map and its viewpoints.

use std::path::Path;

use serde_json::Value;
use wai_embed::{interiors_overlap, Mutual};
use wai_exact::{QPoint, RatPoint};
use wai_lemmas::ch4::{e4_1, e4_10, e4_28};
use wai_map::{json::from_json, Map};
use wai_study::Study;
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

/// The embedded skeleton polygon h(V◇) of `h`.
fn skeleton_ring(map: &Map, h: &wai_study::Embedded) -> Vec<QPoint> {
    h.embedding
        .polygon(map)
        .into_iter()
        .map(QPoint::from)
        .collect()
}

/// The embedded kernel h(ker V*) of `h`.
fn kernel_ring(h: &wai_study::Embedded) -> Vec<QPoint> {
    h.kernel().vertices().iter().map(QPoint::from).collect()
}

#[test]
fn fig_4_1_overlapping_kernels_with_artificial_edges_that_share_vertices() {
    let (map, points) = load("E4.1-fig-4-1-adjacent-funnels.json");
    let study = Study::new(&map);
    let (key, class) = common_skeleton(&study, &points);
    let all = &study.embeddings()[class];
    assert_eq!(all.len(), 2);
    assert!(study.witnesses()[class].iter().all(|w| w.is_valid()));
    let pair = study
        .overlapping_pairs()
        .iter()
        .find(|p| p.class == class)
        .expect("the skeleton polygons overlap");
    assert!(pair.kernels_overlap);
    // E4.1's checker recognises the stored figure and finds its
    // configuration: artificial edges meeting only in vertices, the
    // northern ones on the same pairs of map vertices.
    let report = e4_1::CHECKER.run(&study);
    assert!(report.violations.is_empty(), "{:?}", report.violations);
    assert_eq!(report.counts["figures"], 1);
    let r = e4_1::relations(&study, class, 0, 1);
    assert!(r.vertices_only() && r.same_vertices >= 2, "{r:?}");
    // The two from the ceiling to the floor meet in the vertex between
    // the funnels.
    let floor = map
        .vertices()
        .iter()
        .position(|v| *v == wai_exact::Point::new(35, 0))
        .expect("the vertex between the funnels");
    let touching = |h: &wai_study::Embedded| {
        let v = &h.embedding.vertices;
        (0..v.len())
            .filter(|&a| key.labels[a].is_some())
            .any(|a| v[a] == floor || v[(a + 1) % v.len()] == floor)
    };
    assert!(touching(&all[0]) && touching(&all[1]));
    // Theorems 4.2 and 4.3: the witnesses do not see each other.
    assert!(matches!(pair.sight, Mutual::Invisible { .. }));
    let ws = &study.witnesses()[class];
    assert!(!study
        .sightlines()
        .regions_by_points(&ws[0].pieces(), &ws[1].pieces())
        .is_visible());
}

#[test]
fn fig_4_2_overlapping_kernels_and_crossing_artificial_edges() {
    let (map, points) = load("E4.1-funnels-kernels-overlap.json");
    let study = Study::new(&map);
    let (_, class) = common_skeleton(&study, &points);
    let all = &study.embeddings()[class];
    assert_eq!(all.len(), 2);
    assert!(study.witnesses()[class].iter().all(|w| w.is_valid()));
    let ring = |i: usize| skeleton_ring(&map, &all[i]);
    let kernel = |i: usize| kernel_ring(&all[i]);
    assert!(interiors_overlap(&ring(0), &ring(1)));
    assert!(interiors_overlap(&kernel(0), &kernel(1)));
    // Fig 4.2: an artificial edge of one strictly crosses one of the
    // other, as E4.1's checker finds on the stored figure.
    let report = e4_1::CHECKER.run(&study);
    assert!(report.violations.is_empty(), "{:?}", report.violations);
    assert_eq!(report.counts["figures"], 1);
    assert!(report.cases["strictly crossing"] >= 1);
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
    let report = wai_lemmas::ch4::l4_17::CHECKER.run(&study);
    assert!(report.violations.is_empty(), "{:?}", report.violations);
    assert!(report.counts["shared_def_3_11"] > 0);
}

#[test]
fn fig_4_16_four_type_5_edges_and_no_map_vertex() {
    let (map, points) = load("E4.10-four-type-5.json");
    let study = Study::new(&map);
    let (_, class) = common_skeleton(&study, &points);
    assert_eq!(study.embeddings()[class].len(), 2);
    assert!(study.witnesses()[class].iter().all(|w| w.is_valid()));
    // E4.10's checker recognises the stored figure and finds four type-5
    // edges and no map vertex on the intersection of the viewpoints'
    // embeddings.
    let report = e4_10::CHECKER.run(&study);
    assert!(report.violations.is_empty(), "{:?}", report.violations);
    assert_eq!(report.counts["figures"], 1);
    assert!(report.cases["Fig 4.16"] >= 1);
    // Theorem 4.2 holds for them.
    let overlapping = study
        .overlapping_pairs()
        .iter()
        .find(|p| p.class == class)
        .unwrap();
    assert!(!overlapping.sight.is_visible());
}

#[test]
fn fig_4_31_candidate_edges_of_two_rooms_cross_in_one_neck() {
    use wai_lemmas::ch4::{c4_20, t4_19};
    let (map, points) = load("T4.19-fig-4-31-bottles.json");
    // The stored map is the generator's, with its viewpoints.
    assert_eq!(map.vertices(), wai_gen::bottled_niches(0).vertices());
    let layout = wai_gen::BottleLayout::of_seed(0);
    assert_eq!(
        points,
        layout
            .viewpoints()
            .iter()
            .map(|p| RatPoint::from(*p))
            .collect::<Vec<_>>()
    );
    let study = Study::new(&map);
    let (key, class) = common_skeleton(&study, &points);
    let all = &study.embeddings()[class];
    assert_eq!(all.len(), 2, "one embedding per room");
    assert!(study.witnesses()[class].iter().all(|w| w.is_valid()));
    let pair = study
        .overlapping_pairs()
        .iter()
        .position(|p| p.class == class)
        .expect("the rooms' embeddings overlap");
    let p = &study.overlapping_pairs()[pair];
    assert!(matches!(p.sight, Mutual::Invisible { .. }));
    // Three artificial edges (across the necks) with two valid candidate
    // edges each, in each embedding.
    for i in [p.a, p.b] {
        let valid = study.valid_candidates(class, i);
        assert_eq!(valid.iter().filter(|c| c.len() == 2).count(), 3);
        assert!(valid.iter().all(|c| c.len() <= 2));
    }
    // The neck above the first room is an artificial edge of both
    // embeddings (a of h, a' of h'); its candidate edges of h cross those
    // of h' pairwise, in the order of Corollary 4.20.
    let n = map.n();
    let ends = |i: usize, a: usize| {
        let v = &all[i].embedding.vertices;
        let mut e = [v[a], v[(a + 1) % v.len()]];
        e.sort_unstable();
        e
    };
    let artificial: Vec<usize> = (0..key.labels.len())
        .filter(|&a| key.labels[a].is_some())
        .collect();
    let (ca, cb) = (
        t4_19::ordered_candidates(&study, class, p.a),
        t4_19::ordered_candidates(&study, class, p.b),
    );
    let mut shared = 0;
    for &a in &artificial {
        for &b in &artificial {
            if ends(p.a, a) != ends(p.b, b) || ca[a].len() != 2 || cb[b].len() != 2 {
                continue;
            }
            shared += 1;
            for &c in &ca[a] {
                for &d in &cb[b] {
                    let x = study.crosses(pair, (a, c), (b, d));
                    assert!(x.is_some(), "{c} and {d} do not cross");
                }
            }
            let (c, d) = ([ca[a][0], ca[a][1]], [cb[b][0], cb[b][1]]);
            assert!(c4_20::check(n, c, d).is_none());
            for &e in &d {
                assert!(!t4_19::between(n, c[0], c[1], e));
            }
        }
    }
    assert_eq!(shared, 2, "the two necks between the rooms");
    // The checkers examine these triples and quadruples and find nothing.
    let t = t4_19::CHECKER.run(&study);
    assert!(t.violations.is_empty(), "{:?}", t.violations);
    assert!(t.counts["crosses_both"] > 0);
    let q = c4_20::CHECKER.run(&study);
    assert!(q.violations.is_empty(), "{:?}", q.violations);
    assert!(q.counts["mutually_crossing"] > 0);
}

#[test]
fn fig_4_28_intersecting_embeddings_whose_witnesses_see_each_other() {
    use std::collections::BTreeSet;
    use wai_exact::sees;
    let (map, points) = load("E4.28-intersecting-hexagons.json");
    let study = Study::new(&map);
    let (key, class) = common_skeleton(&study, &points);
    let all = &study.embeddings()[class];
    assert_eq!(all.len(), 2);
    let ws = &study.witnesses()[class];
    assert!(ws.iter().all(|w| w.is_valid()));
    let ring = |i: usize| skeleton_ring(&map, &all[i]);
    let kernel = |i: usize| kernel_ring(&all[i]);
    // Each skeleton polygon is convex, its own kernel.
    for i in 0..2 {
        let (r, k) = (ring(i), kernel(i));
        assert_eq!(
            r.iter().collect::<BTreeSet<_>>(),
            k.iter().collect::<BTreeSet<_>>()
        );
    }
    // The embeddings intersect but do not overlap: they share exactly one
    // segment, an artificial edge of both.
    assert!(!interiors_overlap(&ring(0), &ring(1)));
    assert!(!interiors_overlap(&kernel(0), &kernel(1)));
    assert!(study.overlapping_pairs().iter().all(|p| p.class != class));
    let artificial = |i: usize| -> BTreeSet<[usize; 2]> {
        let v = &all[i].embedding.vertices;
        (0..v.len())
            .filter(|&a| key.labels[a].is_some())
            .map(|a| {
                let mut e = [v[a], v[(a + 1) % v.len()]];
                e.sort_unstable();
                e
            })
            .collect()
    };
    assert_eq!(artificial(0).intersection(&artificial(1)).count(), 1);
    // The exact test over the whole witness regions says visible, by both
    // methods, with certificates that re-check.
    let (a, b) = (ws[0].pieces(), ws[1].pieces());
    for sight in [
        study.sightlines().regions_by_lines(&a, &b),
        study.sightlines().regions_by_points(&a, &b),
    ] {
        match sight {
            Mutual::Visible { from, to } => {
                assert!(sees(map.vertices(), &from.to_rat_point(), &to.to_rat_point()).is_visible())
            }
            Mutual::Invisible { .. } => panic!("the witnesses of Fig 4.28 see each other"),
        }
    }
    // So do the two stored viewpoints.
    assert!(sees(map.vertices(), &points[0], &points[1]).is_visible());
    // E4.28's checker recognises the stored figure and finds the pair.
    let report = e4_28::CHECKER.run(&study);
    assert!(report.violations.is_empty(), "{:?}", report.violations);
    assert_eq!(report.counts["figures"], 1);
    assert!(report.cases["visible"] >= 1);
}
