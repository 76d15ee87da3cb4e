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
//!
//! ## Cases
//! Each instance is [`K4`] (a pair with 2 ≤ k < 4 gives progress k toward
//! it). The proof's general case, all k embeddings pairwise overlapping,
//! is [`ALL_OVERLAP`]; each two of them that do not overlap are the
//! proof's one exception when the artificial edge of e in one and that of
//! f in the other meet at a map vertex v ([`EXCEPTION`], Fig 5.14), and
//! [`APART`] otherwise; three pairwise non-overlapping ones are
//! [`THREE_APART`] (Fig 5.15).

use rug::Rational;
use serde_json::json;

use crate::framework::{Case, Checker, Report, Violation};
use wai_study::GapStructure;
use wai_study::Study;

const ID: &str = "L5.14";

/// A pair shared by k ≥ 4 embeddings: an instance.
pub const K4: &str = "k≥4";
/// The k embeddings pairwise overlap.
pub const ALL_OVERLAP: &str = "all overlap";
/// Two of them do not overlap, their windows to e and f meeting at a map
/// vertex: the proof's exception (Fig 5.14).
pub const EXCEPTION: &str = "exception";
/// Two of them do not overlap, their windows not meeting.
pub const APART: &str = "apart";
/// Three of them pairwise do not overlap (Fig 5.15).
pub const THREE_APART: &str = "three apart";

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study)
    .outer_ring_only("gap chains run along the boundary from one candidate edge to the next (Def 5.4): boundary order on one ring").with_cases(&[
    Case {
        name: K4,
        what: "map edges e, f candidate edges of different artificial edges in k ≥ 4 \
               embeddings (Lemma 5.14's premise)",
    },
    Case {
        name: ALL_OVERLAP,
        what: "k ≥ 4 embeddings sharing the pair that pairwise overlap (the proof's general \
               case: each overlaps h_{j_l} and h_{j_r})",
    },
    Case {
        name: EXCEPTION,
        what: "two of the k embeddings that do not overlap, the artificial edge of e in one and \
               that of f in the other meeting at a map vertex v (the one exception, Fig 5.14)",
    },
    Case {
        name: APART,
        what: "two of the k embeddings that do not overlap, with no such common vertex",
    },
    Case {
        name: THREE_APART,
        what: "three of the k embeddings that pairwise do not overlap (Fig 5.15)",
    },
]);

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
        let hs = &study.embeddings()[class];
        for ((e, f), shared) in study.edge_pairs()[class].iter() {
            if e > f {
                continue; // the premise is symmetric in e and f
            }
            if shared.len() < 2 {
                // One embedding (each gives a pair once): nothing to count.
                largest = largest.max(shared.len());
                continue;
            }
            let mut js: Vec<usize> = shared.iter().map(|s| s.j).collect();
            js.dedup();
            largest = largest.max(js.len());
            // By j: the map vertices at the ends of the artificial edges
            // through which it sees e and f.
            let ends = |j: usize, i: usize| {
                let v = &hs[c.embeddings[j]].embedding.vertices;
                let a = c.artificial[i];
                [v[a], v[(a + 1) % v.len()]]
            };
            let windows = |j: usize| {
                let s = shared.iter().find(|s| s.j == j).expect("listed");
                (ends(j, s.i), ends(j, s.i_tilde))
            };
            let meet = |j1: usize, j2: usize| {
                let (e1, f1) = windows(j1);
                let (e2, f2) = windows(j2);
                e1.iter().any(|x| f2.contains(x)) || f1.iter().any(|x| e2.contains(x))
            };
            let mut one = check_pair(&js, g, meet);
            if !one.violations.is_empty() {
                one.tag("class", || json!(class));
                one.tag("edges", || json!([e, f]));
                one.tag("embeddings", || {
                    json!(js.iter().map(|&j| c.embeddings[j]).collect::<Vec<_>>())
                });
            }
            report.absorb(one);
        }
    }
    report.count("largest_k", largest as u64);
    report
}

/// L5.14 for one pair of map edges shared by the embeddings at positions
/// `js` (nothing examined when fewer than 4); `meet(j1, j2)` tells whether
/// the artificial edge of e in one and that of f in the other share a map
/// vertex.
pub fn check_pair(js: &[usize], g: &GapStructure, meet: impl Fn(usize, usize) -> bool) -> Report {
    let mut report = Report::new(ID);
    let k = js.len();
    if k >= 2 {
        report.count("pairs_k_ge_2", 1);
    }
    if k < 4 {
        if k >= 2 {
            report.progress_toward(K4, Rational::from(k));
        }
        return report;
    }
    report.hit(K4);
    let clique = largest_clique(js, |a, b| g.overlap(a, b));
    if clique.len() == k {
        report.hit(ALL_OVERLAP);
    }
    for (x, &a) in js.iter().enumerate() {
        for &b in &js[x + 1..] {
            if !g.overlap(a, b) {
                report.hit(if meet(a, b) { EXCEPTION } else { APART });
            }
        }
    }
    let apart = |a: usize, b: usize| !g.overlap(a, b);
    let three = js.iter().enumerate().any(|(x, &a)| {
        js[x + 1..].iter().enumerate().any(|(y, &b)| {
            apart(a, b)
                && js[x + 1 + y + 1..]
                    .iter()
                    .any(|&c| apart(a, c) && apart(b, c))
        })
    });
    if three {
        report.hit(THREE_APART);
    }
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
        let never = |_: usize, _: usize| false;
        let report = check_pair(&js, &apart, never);
        assert_eq!((report.examined, report.violations.len()), (1, 1));
        assert_eq!(report.cases[THREE_APART], 1);
        // 21 pairs, 2 of them overlapping.
        assert_eq!(report.cases[APART], 19);
        let triangle = GapStructure::new(vec![], vec![(0, 1), (1, 2), (0, 2)], 7);
        assert!(check_pair(&js, &triangle, never).violations.is_empty());
        // Three embeddings: no instance, progress 3 toward k ≥ 4.
        let report = check_pair(&js[..3], &apart, never);
        assert_eq!(report.examined, 0);
        assert_eq!(report.toward[K4], 3);
        // Four pairwise overlapping; then one pair apart meeting at v.
        let all: Vec<(usize, usize)> = (0..4)
            .flat_map(|a| (a + 1..4).map(move |b| (a, b)))
            .collect();
        let report = check_pair(&js[..4], &GapStructure::new(vec![], all.clone(), 4), never);
        assert_eq!((report.cases[K4], report.cases[ALL_OVERLAP]), (1, 1));
        let but_one: Vec<(usize, usize)> = all.into_iter().filter(|&p| p != (1, 2)).collect();
        let g = GapStructure::new(vec![], but_one, 4);
        let report = check_pair(&js[..4], &g, |a, b| (a, b) == (1, 2));
        assert_eq!(report.cases[EXCEPTION], 1);
        assert!(!report.cases.contains_key(ALL_OVERLAP));
    }
}
