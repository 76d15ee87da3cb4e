//! Def 4.1 on decomposed maps: every cell of a class is a witness of
//! exactly one of its skeleton's embeddings; valid candidate edges are
//! candidate edges; the interior-overlap test on its boundary cases.

use crate::common::maps;
use wai_cells::Decomposition;
use wai_embed::{interiors_overlap, valid_candidate_edges, witness_regions, Embedder};
use wai_visibility::VisibilityIndex;

#[test]
fn every_cell_witnesses_one_embedding_and_valid_candidates_are_candidates() {
    let mut valid = 0;
    for m in maps(14, 2) {
        let d = Decomposition::new(&m);
        let index = VisibilityIndex::new(&m);
        let embedder = Embedder::new(&index);
        for (class, key) in d.skeletons().iter().enumerate() {
            let hs = embedder.embeddings(key);
            let origins: Vec<usize> = hs.iter().map(|h| h.origin).collect();
            let ws = witness_regions(&d, class, &origins);
            let cells: usize = ws.iter().map(|w| w.cells.len()).sum();
            assert_eq!(
                cells,
                d.classes()[class].len() + d.class_lower_cells(class).len(),
                "{:?}: class {class}",
                m.name()
            );
            for (h, w) in hs.iter().zip(&ws) {
                if !w.is_valid() {
                    continue;
                }
                valid += 1;
                let vc = valid_candidate_edges(&index, h, w);
                for (i, edges) in vc.iter().enumerate() {
                    assert!(edges.iter().all(|e| h.candidates[i].contains(e)));
                    // An artificial edge of a valid embedding has a valid
                    // candidate edge: its witnesses see one.
                    assert_eq!(edges.is_empty(), h.candidates[i].is_empty());
                }
            }
        }
    }
    assert!(valid > 500, "{valid} valid embeddings");
}

use wai_embed::piece::ints as ring;

#[test]
fn interiors_overlap_only_with_a_common_inner_point() {
    let sq = ring(&[(0, 0), (2, 0), (2, 2), (0, 2)]);
    let beside = ring(&[(2, 0), (4, 0), (4, 2), (2, 2)]);
    let corner = ring(&[(2, 2), (4, 2), (4, 4), (2, 4)]);
    let over = ring(&[(1, 1), (3, 1), (3, 3), (1, 3)]);
    let inner = ring(&[(1, 1), (2, 1), (1, 2)]);
    // Sharing an edge or a vertex only: they merely intersect.
    assert!(!interiors_overlap(&sq, &beside));
    assert!(!interiors_overlap(&sq, &corner));
    assert!(interiors_overlap(&sq, &over));
    assert!(interiors_overlap(&sq, &sq));
    // Nested, sharing two edges.
    assert!(interiors_overlap(&sq, &ring(&[(0, 0), (1, 0), (0, 1)])));
    assert!(interiors_overlap(&inner, &sq));
    // Star-shaped, not convex: a notch holds the other without overlap.
    let notched = ring(&[(0, 0), (6, 0), (6, 4), (4, 4), (3, 1), (2, 4), (0, 4)]);
    let in_notch = ring(&[(3, 2), (4, 5), (2, 5)]);
    assert!(!interiors_overlap(&notched, &in_notch));
    assert!(interiors_overlap(
        &notched,
        &ring(&[(3, 0), (4, 5), (2, 5)])
    ));
    // Crossing edges with no vertex inside the other: a cross.
    let bar = ring(&[(0, 1), (4, 1), (4, 2), (0, 2)]);
    let post = ring(&[(1, 0), (2, 0), (2, 4), (1, 4)]);
    assert!(interiors_overlap(&bar, &post));
}
