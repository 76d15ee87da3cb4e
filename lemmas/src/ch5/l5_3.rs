//! Claim L5.3 (Lemma 5.3, exact and tight): a skeleton has at most s·t
//! single candidate edges (Def 5.4), s its artificial edges and t its
//! valid embeddings, so O(min{n, r²}); and Ω(r²) is reached by the
//! construction of Fig 5.4 (family `convex-niches`, f = t = k: f·t
//! distinct single candidate edges).
//!
//! ## Trust
//! Exact, on every class with a valid embedding: C_{i,j} from the witness
//! views of [`wai_study::Study`] (Def 4.1), C_sing counted as a set of map
//! edges, compared with s·t and with n. The tight part runs on the
//! family's maps only (recognised by their vertices,
//! [`wai_study::family::parameter_of`]): some class must reach k² single
//! candidate edges. Counts: `single` sums |C_sing| over the classes
//! examined, `largest_single` the largest per map (the driver sums both
//! over maps).
//!
//! ## Cases
//! Which term of min{s·t, n} bounds a class ([`ST_BOUND`], [`N_BOUND`]);
//! a class with s, t ≥ 2 whose sets C_{i,j} are s·t distinct single edges,
//! reaching the proof's count ([`ST_REACHED`], the shape of Fig 5.4, with
//! the largest |C_sing| / (s·t) of such classes as progress toward it); and
//! the construction itself reaching k² ([`FIG_5_4`]).

use rug::Rational;
use serde_json::json;
use wai_embed::CandidateSets;

use crate::framework::{Case, Checker, Report, Violation};
use wai_study::family::parameter_of;
use wai_study::Study;

const ID: &str = "L5.3";

/// A class with s·t ≤ n: the proof's s·t (the O(r²) side) bounds it.
pub const ST_BOUND: &str = "s·t ≤ n";
/// A class with n < s·t: the trivial bound n is the smaller.
pub const N_BOUND: &str = "n < s·t";
/// A class with s, t ≥ 2 and |C_sing| = s·t.
pub const ST_REACHED: &str = "s·t reached";
/// The Fig 5.4 construction reaching k² single candidate edges.
pub const FIG_5_4: &str = "Fig 5.4";

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study).with_cases(&[
    Case {
        name: ST_BOUND,
        what: "a skeleton with s·t ≤ n: |C_sing| is bounded by the s·t sets C_{i,j} \
               (Lemma 5.3's proof, the O(r²) side by Lemma 3.7)",
    },
    Case {
        name: N_BOUND,
        what: "a skeleton with n < s·t: the trivial bound n on C_sing is the smaller",
    },
    Case {
        name: ST_REACHED,
        what: "a skeleton with s, t ≥ 2 whose s·t sets C_{i,j} are distinct single edges: \
               |C_sing| = s·t, the proof's count reached (the shape of Fig 5.4)",
    },
    Case {
        name: FIG_5_4,
        what: "the construction of Fig 5.4 (family convex-niches k) with k² single candidate \
               edges of one skeleton (Lemma 5.3's tightness)",
    },
]);
const FAMILY: &str = "convex-niches";

/// Checks L5.3 on every class, and its tightness on `convex-niches`.
fn check_study(study: &Study<'_>) -> Report {
    let tight = parameter_of(study.map(), FAMILY).map(|k| (k as usize).pow(2));
    check_classes(study.map().n(), study.candidate_sets(), tight)
}

/// The bound on one class: |C_sing| ≤ s·t and ≤ n.
pub fn check_class(n: usize, c: &CandidateSets) -> Option<Violation> {
    let single = c.all.len() - c.multiple.len();
    let bound = (c.s() * c.t()).min(n);
    (single > bound).then(|| {
        Violation::with_data(
            format!(
                "{single} single candidate edges, above min(s·t, n) = min({}·{}, {n})",
                c.s(),
                c.t()
            ),
            json!({
                "single": c.single(),
                "s": c.s(),
                "t": c.t(),
                "n": n,
                "sets": c.sets,
            }),
        )
    })
}

/// Every class with a valid embedding; with `tight = Some(k²)`, some
/// class must reach k² single candidate edges.
pub fn check_classes(n: usize, classes: &[CandidateSets], tight: Option<usize>) -> Report {
    let mut report = Report::new(ID);
    let mut largest = 0;
    for (class, c) in classes.iter().enumerate() {
        if c.t() == 0 {
            continue;
        }
        report.record(super::tagged(check_class(n, c), "class", || json!(class)));
        // C_mult ⊆ C_all (Def 5.4).
        let single = c.all.len() - c.multiple.len();
        let bound = (c.s() * c.t()).min(n);
        super::measure_lazily(
            &mut report,
            crate::framework::over(single, bound as u128),
            || json!({"single": single, "s": c.s(), "t": c.t(), "class": class}),
        );
        report.hit(if c.s() * c.t() <= n {
            ST_BOUND
        } else {
            N_BOUND
        });
        if c.s() >= 2 && c.t() >= 2 {
            if single == c.s() * c.t() {
                report.hit(ST_REACHED);
            } else {
                report.progress_toward(ST_REACHED, Rational::from((single, c.s() * c.t())));
            }
        }
        report.count("single", single as u64);
        largest = largest.max(single);
    }
    report.count("largest_single", largest as u64);
    if let Some(want) = tight {
        if largest >= want {
            report.hit(FIG_5_4);
        }
        report.record((largest < want).then(|| {
            Violation::with_data(
                format!(
                    "the convex-niches construction has at most {largest} single candidate edges for one skeleton, not k² = {want}"
                ),
                json!({ "expected": want, "largest": largest }),
            )
        }));
    }
    report
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_construction_reaches_k_squared() {
        for k in 1..=3u32 {
            let map = wai_gen::family(FAMILY, &[k]).unwrap();
            let report = CHECKER.run(&Study::new(&map));
            assert!(
                report.violations.is_empty(),
                "k = {k}: {:?}",
                report.violations
            );
            assert!(report.counts["largest_single"] >= u64::from(k * k));
            assert_eq!(report.cases[FIG_5_4], 1, "k = {k}");
            if k >= 2 {
                assert!(report.cases.contains_key(ST_REACHED), "k = {k}");
            }
            // The classes, plus the tightness instance.
            assert!(report.examined >= 2, "k = {k}");
        }
    }

    #[test]
    fn planted_excess_and_shortfall_are_reported() {
        // One artificial edge, one valid embedding: at most 1 single edge,
        // but 2 planted (two sets of one edge each would need t = 2).
        let c = CandidateSets::from_sets(vec![0], vec![0], vec![vec![vec![5]]]);
        let mut planted = c.clone();
        planted.all.insert(6);
        let report = check_classes(10, &[c, planted], None);
        assert_eq!((report.examined, report.violations.len()), (2, 1));
        assert!(report.violations[0].what.contains("above min(s·t, n)"));
        // The construction's count not reached.
        let c = CandidateSets::from_sets(vec![0], vec![0], vec![vec![vec![5]]]);
        let report = check_classes(10, &[c], Some(4));
        assert_eq!(report.violations.len(), 1);
        assert!(report.violations[0].what.contains("not k² = 4"));
    }
}
