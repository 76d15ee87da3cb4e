//! Claim T5.15 (Theorem 5.15): if e is a valid candidate edge and f a valid
//! *multiple* candidate edge of different artificial edges in each of k
//! embeddings of one skeleton, then k ≤ 6. Eq. (5.9) turns it into the
//! O(|C_mult|²) count of wedge-edge pairs behind Theorem 5.16.
//!
//! "Multiple" is read as in the proof and in eq. (5.9): f shares its set
//! C_{ĩ,j} with another candidate edge in that embedding
//! ([`wai_study::edge_pairs::Shared::f_multiple`]), not merely somewhere.
//!
//! ## Trust
//! Exact, on every class with a valid embedding: the sets C_{i,j} of
//! [`wai_study::Study::candidate_sets`]; every ordered pair (e, f) of map edges
//! with at least one such embedding is one instance (`examined`), its k
//! the number of embeddings. Counts: `pairs_k_ge_2` (instances with
//! k ≥ 2, where the theorem has content), `largest_k` (the largest k per
//! map, summed over maps by the driver) and `premise_embeddings` (per map,
//! the most valid embeddings of one skeleton with an artificial edge of two
//! or more valid candidate edges beside another artificial edge: an upper
//! bound on k, and the guide of a search for large k).
//!
//! ## Cases
//! The value of k of each instance, `k=1` to `k=6` ([`K_CASES`]); the
//! proof's argument (three overlapping embeddings, from Lemma 5.14) has
//! content from k = 3 on. For each value never reached on a map, the
//! largest k below it is the progress toward it.

use rug::Rational;
use serde_json::json;
use wai_embed::CandidateSets;

use crate::framework::{Case, Checker, Report, Violation};
use wai_study::edge_pairs::{shared_embeddings, SharedPairs};
use wai_study::Study;

const ID: &str = "T5.15";

/// The theorem's bound on k.
pub const BOUND: usize = 6;

/// The case of each k from 1 to [`BOUND`], by k − 1.
pub const K_CASES: [&str; BOUND] = ["k=1", "k=2", "k=3", "k=4", "k=5", "k=6"];

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study).with_cases(&[
    Case {
        name: K_CASES[0],
        what: "e a valid candidate edge and f a valid multiple candidate edge of another \
               artificial edge in one embedding (Theorem 5.15, k = 1)",
    },
    Case {
        name: K_CASES[1],
        what: "the pair (e, f) so in k = 2 embeddings",
    },
    Case {
        name: K_CASES[2],
        what: "the pair (e, f) so in k = 3 embeddings (from here on Lemma 5.14 and the \
               proof's three overlapping embeddings have content)",
    },
    Case {
        name: K_CASES[3],
        what: "the pair (e, f) so in k = 4 embeddings",
    },
    Case {
        name: K_CASES[4],
        what: "the pair (e, f) so in k = 5 embeddings",
    },
    Case {
        name: K_CASES[5],
        what: "the pair (e, f) so in k = 6 embeddings: the theorem's bound reached",
    },
]);

/// Checks T5.15 on every class with a valid embedding.
fn check_study(study: &Study<'_>) -> Report {
    let mut report = Report::new(ID);
    let mut largest = 0;
    let classes = study.candidate_sets().iter().zip(study.edge_pairs());
    for (class, (c, pairs)) in classes.enumerate() {
        let (mut one, k) = check_pairs(c, pairs, BOUND);
        one.tag("class", || json!(class));
        report.absorb(one);
        largest = largest.max(k);
    }
    report.count("largest_k", largest as u64);
    let premise = study.candidate_sets().iter().map(premise_embeddings).max();
    report.count("premise_embeddings", premise.unwrap_or(0) as u64);
    report
}

/// The valid embeddings of one skeleton with an artificial edge of two or
/// more valid candidate edges beside another artificial edge (so that some
/// pair (e, f) could count them): an upper bound on k.
pub fn premise_embeddings(c: &CandidateSets) -> usize {
    c.sets
        .iter()
        .filter(|by_edge| by_edge.len() >= 2 && by_edge.iter().any(|set| set.len() >= 2))
        .count()
}

/// For each ordered pair (e, f): the embeddings (positions j in
/// [`CandidateSets::embeddings`]) where e is a candidate edge of one
/// artificial edge and f a multiple candidate edge of another.
pub fn k_of_pairs(c: &CandidateSets) -> Vec<((usize, usize), Vec<usize>)> {
    k_of_shared(&shared_embeddings(c))
}

/// [`k_of_pairs`] from the class's shared pairs
/// ([`wai_study::Study::edge_pairs`]).
pub fn k_of_shared(pairs: &SharedPairs) -> Vec<((usize, usize), Vec<usize>)> {
    pairs
        .iter()
        .map(|(pair, shared)| {
            let js: Vec<usize> = shared
                .iter()
                .filter(|s| s.f_multiple)
                .map(|s| s.j)
                .collect();
            (pair, js)
        })
        .filter(|(_, js)| !js.is_empty())
        .collect()
}

/// One class against a bound on k: the report and the largest k.
pub fn check_class(c: &CandidateSets, bound: usize) -> (Report, usize) {
    check_pairs(c, &shared_embeddings(c), bound)
}

/// [`check_class`] on the class's shared pairs `pairs`
/// ([`wai_study::Study::edge_pairs`]).
pub fn check_pairs(c: &CandidateSets, pairs: &SharedPairs, bound: usize) -> (Report, usize) {
    let mut report = Report::new(ID);
    let mut largest = 0;
    for ((e, f), js) in k_of_shared(pairs) {
        let k = js.len();
        largest = largest.max(k);
        if let Some(case) = k.checked_sub(1).and_then(|x| K_CASES.get(x)) {
            report.hit(case);
        }
        if k >= 2 {
            report.count("pairs_k_ge_2", 1);
        }
        let embeddings = || js.iter().map(|&j| c.embeddings[j]).collect::<Vec<usize>>();
        super::measure_lazily(
            &mut report,
            rug::Rational::from((k, BOUND)),
            || json!({"e": e, "f": f, "k": k, "embeddings": embeddings()}),
        );
        report.record((k > bound).then(|| {
            let embeddings = embeddings();
            Violation::with_data(
                format!(
                    "map edges {e} and {f}: a candidate edge and a multiple candidate edge of different artificial edges in {k} embeddings, above {bound}"
                ),
                json!({ "e": e, "f": f, "k": k, "embeddings": embeddings }),
            )
        }));
    }
    for (x, case) in K_CASES.iter().enumerate() {
        let best = k_below(&report, x + 1);
        if !report.cases.contains_key(case) && best > 0 {
            report.progress_toward(case, Rational::from(best));
        }
    }
    (report, largest)
}

/// The largest k below `want` that an instance of `report` hit.
fn k_below(report: &Report, want: usize) -> usize {
    (1..want)
        .rev()
        .find(|&k| report.cases.contains_key(K_CASES[k - 1]))
        .unwrap_or(0)
}

/// The largest k of Theorem 5.15 over the classes of a map (0 when no
/// pair qualifies): the quantity `wai search-extremes --ratio k` climbs.
pub fn largest_k(study: &Study<'_>) -> usize {
    study
        .edge_pairs()
        .iter()
        .flat_map(k_of_shared)
        .map(|(_, js)| js.len())
        .max()
        .unwrap_or(0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn holds_and_measures_on_maps_with_multiple_candidate_edges() {
        let mut examined = 0;
        let mut largest = 0;
        for seed in 0..6 {
            let map = wai_gen::bottled_niches(seed);
            let study = Study::new(&map);
            let report = CHECKER.run(&study);
            assert!(report.violations.is_empty(), "{:?}", report.violations);
            examined += report.examined;
            largest = largest.max(largest_k(&study));
        }
        assert!(
            examined > 0 && largest >= 1,
            "{examined} pairs, k ≤ {largest}"
        );
    }

    #[test]
    fn planted_seven_embeddings_are_reported() {
        // Seven embeddings, each with e = 1 on a_0 and f = 2 sharing a_1
        // with edge 3: k = 7 for (1, 2) and (1, 3).
        let sets = vec![vec![vec![1], vec![2, 3]]; 7];
        let c = CandidateSets::from_sets(vec![0, 1], (0..7).collect(), sets);
        let (report, largest) = check_class(&c, BOUND);
        assert_eq!(largest, 7);
        assert_eq!(report.violations.len(), 2);
        // k = 7 is no case; nothing below it either.
        assert!(report.cases.is_empty() && report.toward.is_empty());
        // (2, 1) and (3, 1): f = 1 is single in its set, no instance.
        assert_eq!(report.examined, 2);
        // Six embeddings: within the bound.
        let sets = vec![vec![vec![1], vec![2, 3]]; 6];
        let c = CandidateSets::from_sets(vec![0, 1], (0..6).collect(), sets);
        let report = check_class(&c, BOUND).0;
        assert!(report.violations.is_empty());
        assert_eq!(report.cases["k=6"], 2);
        // Two embeddings: k = 2 for (1, 2), (1, 3); k = 3..6 never reached,
        // 2 the progress toward each.
        let sets = vec![vec![vec![1], vec![2, 3]]; 2];
        let c = CandidateSets::from_sets(vec![0, 1], (0..2).collect(), sets);
        let report = check_class(&c, BOUND).0;
        assert_eq!(report.cases["k=2"], 2);
        assert_eq!(report.toward["k=3"], 2);
        assert_eq!(report.toward["k=6"], 2);
        assert!(!report.toward.contains_key("k=1"));
    }
}
