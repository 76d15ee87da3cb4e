//! The chapter 5 layouts of `wai_gen` reach what the stress corpus never
//! does — gaps that are interweaved and nested (Def 5.6, Example 5.1,
//! Fig 5.5) and pairs of map edges that are candidate edges of different
//! artificial edges in several embeddings (Figs 5.13–5.16) — and the
//! checkers of L5.5–L5.9, L5.13, L5.14 and T5.15 examine them and find
//! nothing wrong.

use std::collections::BTreeMap;

use wai_embed::GapRelation;
use wai_exact::{Point, RatPoint};
use wai_lemmas::Report;
use wai_study::Study;
use wai_visibility::{Skeleton, SkeletonKey};

/// The reports of the claims `ids` on one study of `study`'s map, by id;
/// fails on any violation.
fn check(study: &Study<'_>, ids: &[&str]) -> BTreeMap<String, Report> {
    let mut out = BTreeMap::new();
    for id in ids {
        let checker =
            wai_lemmas::checker(id).unwrap_or_else(|| panic!("claim {id} has no checker"));
        let report = checker.run(study);
        assert!(
            report.violations.is_empty(),
            "{id} on {:?}: {:?}",
            study.map().name(),
            report.violations
        );
        out.insert((*id).to_owned(), report);
    }
    out
}

fn count(report: &Report, name: &str) -> u64 {
    report.counts.get(name).copied().unwrap_or(0)
}

fn case(report: &Report, name: &str) -> u64 {
    report.cases.get(name).copied().unwrap_or(0)
}

/// The class of the common skeleton of `points` (which must be equal).
fn class_of(study: &Study<'_>, points: &[Point]) -> usize {
    let keys: Vec<SkeletonKey> = points
        .iter()
        .map(|&p| {
            let vp = study
                .index()
                .visibility_polygon(&RatPoint::from(p))
                .unwrap();
            Skeleton::of(study.map(), &vp).unwrap().key()
        })
        .collect();
    assert!(
        keys.windows(2).all(|w| w[0] == w[1]),
        "{:?}: the viewpoints' skeletons differ",
        study.map().name()
    );
    study
        .decomposition()
        .skeletons()
        .iter()
        .position(|k| *k == keys[0])
        .expect("the skeleton is a class")
}

#[test]
fn interweaved_gaps_are_interweaved_and_nested_and_the_lemmas_hold() {
    for seed in 0..4 {
        let map = wai_gen::interweaved_gaps(seed);
        let study = Study::new(&map);
        let r = check(&study, &["L5.5", "L5.6", "L5.7", "L5.8", "L5.9"]);
        assert!(case(&r["L5.5"], "interweaved") > 0, "seed {seed}");
        assert!(case(&r["L5.5"], "nested") > 0, "seed {seed}");
        for id in ["L5.6", "L5.7", "L5.8", "L5.9"] {
            assert!(r[id].examined > 0, "seed {seed}: {id} examined nothing");
        }
        // As the module doc of `wai_gen::interweave` says: the witnesses of
        // the two rooms share a skeleton, with two valid embeddings that
        // do not overlap, and its gaps are both interweaved and nested.
        let class = class_of(&study, &wai_gen::PinholeLayout::of_seed(seed).viewpoints());
        let g = &study.gap_structures()[class];
        assert_eq!(study.candidate_sets()[class].t(), 2, "seed {seed}");
        assert!(g.overlapping.is_empty(), "seed {seed}");
        let relations: Vec<GapRelation> = g.related.iter().map(|r| r.2).collect();
        assert!(relations.contains(&GapRelation::Interweaved), "seed {seed}");
        assert!(relations.iter().any(|r| r.is_nested()), "seed {seed}");
        assert_eq!(g.graph.interweave_classes.len(), 1, "seed {seed}");
    }
}

#[test]
fn shared_niches_share_pairs_in_four_embeddings_and_the_lemmas_hold() {
    // Seeds 0 and 3 see two bottles on either side (k = 4), the smallest
    // maps; seeds with `view` 3 reach k = 6 (and `SharedLayout::plain`
    // with `view` 4 or 5, k = 8 or 10).
    for seed in [0, 3] {
        let layout = wai_gen::SharedLayout::of_seed(seed);
        assert_eq!(layout.view, 2);
        let map = wai_gen::shared_niches(seed);
        let study = Study::new(&map);
        let r = check(&study, &["L5.13", "L5.14", "T5.15"]);
        assert!(r["L5.13"].examined > 0, "seed {seed}");
        assert!(r["L5.14"].examined > 0, "seed {seed}");
        assert_eq!(count(&r["L5.14"], "largest_k"), 4, "seed {seed}");
        assert!(case(&r["L5.14"], "k≥4") > 0, "seed {seed}");
        // The rooms' witnesses share a skeleton with one valid embedding
        // per room.
        let class = class_of(&study, &layout.viewpoints());
        assert_eq!(
            study.candidate_sets()[class].t() as i128,
            layout.rooms,
            "seed {seed}"
        );
    }
}

#[test]
fn spiked_niches_share_a_multiple_candidate_edge_and_theorem_5_15_holds() {
    for seed in [0, 2] {
        let layout = wai_gen::SharedLayout::spiked_of_seed(seed);
        let map = wai_gen::shared_spiked_niches(seed);
        let study = Study::new(&map);
        let r = check(&study, &["L5.13", "L5.14", "T5.15"]);
        assert!(count(&r["T5.15"], "pairs_k_ge_2") > 0, "seed {seed}");
        assert_eq!(count(&r["T5.15"], "largest_k"), 2, "seed {seed}");
        assert!(case(&r["T5.15"], "k=2") > 0, "seed {seed}");
        let class = class_of(&study, &layout.viewpoints());
        let c = &study.candidate_sets()[class];
        assert_eq!(c.t() as i128, layout.rooms, "seed {seed}");
        // In every embedding, the three necks' sets hold two back pieces
        // each (the two sides of a spike); the view's two half edges on
        // the ceiling one edge each.
        for by_edge in &c.sets {
            let mut sizes: Vec<usize> = by_edge.iter().map(Vec::len).collect();
            sizes.sort_unstable();
            assert_eq!(sizes, [1, 1, 2, 2, 2], "seed {seed}: {:?}", c.sets);
        }
    }
}
