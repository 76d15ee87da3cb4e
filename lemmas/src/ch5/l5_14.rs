//! Claim L5.14 (Lemma 5.14): if map edges e and f are valid candidate
//! edges of different artificial edges in each of k ≥ 4 embeddings of one
//! skeleton, at least ⌈k/3⌉ of those embeddings pairwise overlap.
//!
//! ## Trust
//! Exact, on every class with a valid embedding: the embeddings of each
//! pair {e, f} from the sets C_{i,j} ([`wai_study::edge_pairs`]); each pair
//! with k ≥ 4 is an instance, and the largest set of its embeddings that
//! pairwise overlap (skeleton polygons' interiors, as Theorem 4.2 and
//! Def 5.7 use) is found by exhaustive clique search and compared with
//! ⌈k/3⌉. Counts: `pairs_k_ge_2`, `largest_k` (per map, summed).

use serde_json::json;

use crate::framework::{Checker, Report, Violation};
use wai_study::edge_pairs::shared_embeddings;
use wai_study::GapStructure;
use wai_study::Study;

const ID: &str = "L5.14";

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study);

/// Checks L5.14 on every class.
fn check_study(study: &Study<'_>) -> Report {
    let mut report = Report::new(ID);
    let mut largest = 0;
    for (class, (c, g)) in study
        .candidate_sets()
        .iter()
        .zip(study.gap_structures())
        .enumerate()
    {
        for ((e, f), shared) in shared_embeddings(c) {
            if e > f {
                continue; // the premise is symmetric in e and f
            }
            let mut js: Vec<usize> = shared.iter().map(|s| s.j).collect();
            js.dedup();
            largest = largest.max(js.len());
            let mut one = check_pair(&js, g);
            one.tag("class", json!(class));
            one.tag("edges", json!([e, f]));
            one.tag(
                "embeddings",
                json!(js.iter().map(|&j| c.embeddings[j]).collect::<Vec<_>>()),
            );
            report.absorb(one);
        }
    }
    report.count("largest_k", largest as u64);
    report
}

/// L5.14 for one pair of map edges shared by the embeddings at positions
/// `js` (nothing examined when fewer than 4).
pub fn check_pair(js: &[usize], g: &GapStructure) -> Report {
    let mut report = Report::new(ID);
    let k = js.len();
    if k >= 2 {
        report.count("pairs_k_ge_2", 1);
    }
    if k < 4 {
        return report;
    }
    let clique = largest_clique(js, |a, b| g.overlap(a, b));
    let need = k.div_ceil(3);
    report.record((clique.len() < need).then(|| {
        Violation::with_data(
            format!(
                "{k} embeddings share the pair, but at most {} of them pairwise overlap (need ⌈k/3⌉ = {need})",
                clique.len()
            ),
            json!({"k": k, "largest_overlapping": clique, "need": need}),
        )
    }));
    report
}

/// A largest subset of `nodes` whose members are pairwise `adjacent`
/// (Bron–Kerbosch with pivoting; k is small).
pub fn largest_clique(nodes: &[usize], adjacent: impl Fn(usize, usize) -> bool) -> Vec<usize> {
    fn grow(
        r: &mut Vec<usize>,
        mut p: Vec<usize>,
        mut x: Vec<usize>,
        adj: &dyn Fn(usize, usize) -> bool,
        best: &mut Vec<usize>,
    ) {
        if p.is_empty() && x.is_empty() {
            if r.len() > best.len() {
                *best = r.clone();
            }
            return;
        }
        if r.len() + p.len() <= best.len() {
            return;
        }
        let pivot = *p.iter().chain(&x).next().expect("nonempty");
        let candidates: Vec<usize> = p
            .iter()
            .copied()
            .filter(|&v| v == pivot || !adj(v, pivot))
            .collect();
        for v in candidates {
            r.push(v);
            let np = p.iter().copied().filter(|&u| u != v && adj(u, v)).collect();
            let nx = x.iter().copied().filter(|&u| adj(u, v)).collect();
            grow(r, np, nx, adj, best);
            r.pop();
            p.retain(|&u| u != v);
            x.push(v);
        }
    }
    let mut best = Vec::new();
    grow(
        &mut Vec::new(),
        nodes.to_vec(),
        Vec::new(),
        &adjacent,
        &mut best,
    );
    best.sort_unstable();
    best
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cliques() {
        let edges = [(0, 1), (1, 2), (0, 2), (2, 3), (3, 4)];
        let adj = |a: usize, b: usize| edges.contains(&(a.min(b), a.max(b)));
        assert_eq!(largest_clique(&[0, 1, 2, 3, 4], adj), vec![0, 1, 2]);
        assert_eq!(largest_clique(&[3, 4], adj), vec![3, 4]);
        assert_eq!(largest_clique(&[0, 4], adj).len(), 1);
    }

    #[test]
    fn planted_pairwise_apart_embeddings_are_reported() {
        // Seven embeddings sharing the pair: ⌈7/3⌉ = 3 must overlap.
        let js: Vec<usize> = (0..7).collect();
        let apart = GapStructure::new(vec![], vec![(0, 1), (2, 3)], 7);
        let report = check_pair(&js, &apart);
        assert_eq!((report.examined, report.violations.len()), (1, 1));
        let triangle = GapStructure::new(vec![], vec![(0, 1), (1, 2), (0, 2)], 7);
        assert!(check_pair(&js, &triangle).violations.is_empty());
        // Three embeddings: no instance.
        assert_eq!(check_pair(&js[..3], &apart).examined, 0);
    }
}
