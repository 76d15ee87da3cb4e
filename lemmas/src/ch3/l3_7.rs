//! Claim L3.7 (Lemma 3.7): a skeleton has at most r embeddings in the map
//! (valid or not), r the number of reflex map vertices.
//!
//! The proof places h(v0) on a reflex vertex; for a map with no reflex
//! vertex (convex, outside the thesis's assumption) the one skeleton's v0
//! is a convex vertex and the bound read is max(r, 1).
//!
//! ## Trust
//! Exhaustive over the skeletons (classes) of each map, exact: the
//! embeddings are all those of Def 3.11 ([`wai_embed::Embedder`], every map
//! vertex tried as h(v0), reflex or not, so the bound is not assumed).
//!
//! ## Cases
//! Each skeleton by its number e of embeddings: **one embedding**,
//! **several embeddings** (2 ≤ e < r), **r embeddings** (e = r ≥ 2: the
//! bound reached, as the corridor of niches does, Fig 3.12; a map
//! approaches it with the progress e / r); and, counted besides, **with an
//! invalid one** (a skeleton one of whose embeddings has no witness,
//! Remark 3.4: the lemma counts those too).

use serde_json::json;
use wai_embed::Witnesses;

use crate::framework::{over, Case, Checker, Report, Violation};
use wai_study::Embedded;
use wai_study::Study;

const ID: &str = "L3.7";

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study).with_cases(&[
    Case {
        name: ONE,
        what: "a skeleton with one embedding",
    },
    Case {
        name: SEVERAL,
        what: "a skeleton with 2 <= e < r embeddings",
    },
    Case {
        name: REACHED,
        what: "a skeleton with e = r >= 2 embeddings: the bound of Lemma 3.7 reached",
    },
    Case {
        name: INVALID,
        what: "a skeleton with an embedding that has no witness (Remark 3.4)",
    },
]);

/// Case: one embedding.
pub const ONE: &str = "one embedding";
/// Case: several embeddings, fewer than r.
pub const SEVERAL: &str = "several embeddings";
/// Case: r ≥ 2 embeddings.
pub const REACHED: &str = "r embeddings";
/// Case: an embedding without witness.
pub const INVALID: &str = "with an invalid one";

/// Checks L3.7 on every skeleton of a map.
fn check_study(study: &Study<'_>) -> Report {
    check_classes(
        study.map().reflex_vertices().len(),
        study.embeddings(),
        study.witnesses(),
    )
}

/// The check proper: every class has at most max(r, 1) embeddings.
/// `witnesses`: by class and embedding, its witness region (for the
/// case of an invalid embedding).
pub fn check_classes(r: usize, by_class: &[Vec<Embedded>], witnesses: &[Vec<Witnesses>]) -> Report {
    let mut report = Report::new(ID);
    for (class, all) in by_class.iter().enumerate() {
        report.examined += 1;
        let e = all.len();
        match e {
            0 => {}
            1 => report.hit(ONE),
            _ if e >= r => report.hit(REACHED),
            _ => report.hit(SEVERAL),
        }
        if r >= 2 {
            report.progress_toward(REACHED, over(e, r as u128));
        }
        if witnesses
            .get(class)
            .is_some_and(|ws| ws.iter().any(|w| !w.is_valid()))
        {
            report.hit(INVALID);
        }
        if all.len() > r.max(1) {
            let origins: Vec<usize> = all.iter().map(|h| h.embedding.origin).collect();
            report.violations.push(Violation::with_data(
                format!("skeleton {class} has {} embeddings, r = {r}", all.len()),
                json!({ "class": class, "r": r, "origins": origins }),
            ));
        }
    }
    report
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn holds_and_is_tight_on_a_corridor_of_niches() {
        let map = wai_gen::family("corridor-niches", &[3]).unwrap();
        let study = Study::new(&map);
        let report = CHECKER.run(&study);
        assert_eq!(
            report.examined as usize,
            study.decomposition().skeletons().len()
        );
        assert!(report.violations.is_empty(), "{:?}", report.violations);
        // One skeleton embeds once per niche (L3.7t): 3 of r = 6.
        assert_eq!(study.embeddings().iter().map(Vec::len).max(), Some(3));
        assert_eq!(
            report.toward.get(REACHED),
            Some(&rug::Rational::from((1, 2)))
        );
        assert!(report.cases.get(SEVERAL).is_some_and(|&k| k > 0));
    }

    #[test]
    fn planted_excess_is_reported() {
        let map = wai_gen::family("corridor-niches", &[2]).unwrap();
        let study = Study::new(&map);
        let mut by_class = study.embeddings().to_vec();
        let r = map.reflex_vertices().len();
        let one = by_class.iter().find(|c| !c.is_empty()).unwrap()[0].clone();
        by_class[0] = vec![one; r + 1];
        let report = check_classes(r, &by_class, study.witnesses());
        assert_eq!(report.violations.len(), 1);
        assert!(report.violations[0].what.contains("embeddings, r ="));
    }
}
