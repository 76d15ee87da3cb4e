//! Lemma 4.1's construction, family `overlap-fan`: the skeleton of the
//! south-niche viewpoints has 2z + 1 embeddings, all valid, all sharing an
//! interior point, while r grows as 12z + 4 — a snapshot of the counts.

use std::fmt::Write;
use wai_cells::Decomposition;
use wai_embed::{common_interior_point, witness_regions, Embedder};
use wai_exact::{QPoint, RatPoint};
use wai_visibility::{Skeleton, VisibilityIndex};

#[test]
fn fan_counts() {
    let mut out = String::from("z n r embeddings valid sharing_a_point\n");
    for z in 0..=3u32 {
        let map = wai_gen::family("overlap-fan", &[z]).unwrap();
        let index = VisibilityIndex::new(&map);
        let p = RatPoint::from(wai_gen::overlap_fan_viewpoints(z)[0]);
        let key = Skeleton::of(&map, &index.visibility_polygon(&p).unwrap())
            .unwrap()
            .key();
        let d = Decomposition::new(&map);
        let class = d.skeletons().iter().position(|k| *k == key).unwrap();
        let hs = Embedder::new(&index).embeddings(&key);
        let origins: Vec<usize> = hs.iter().map(|h| h.origin).collect();
        let ws = witness_regions(&d, class, &origins);
        let valid: Vec<Vec<QPoint>> = hs
            .iter()
            .zip(&ws)
            .filter(|(_, w)| w.is_valid())
            .map(|(h, _)| h.polygon(&map).into_iter().map(QPoint::from).collect())
            .collect();
        let sharing = common_interior_point(&valid).is_some();
        writeln!(
            out,
            "{z} {} {} {} {} {sharing}",
            map.n(),
            map.r(),
            hs.len(),
            valid.len()
        )
        .unwrap();
        assert_eq!(valid.len(), 2 * z as usize + 1);
        assert!(sharing);
    }
    insta::assert_snapshot!(out);
}
