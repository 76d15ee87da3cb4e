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

use serde_json::json;

use crate::framework::{Checker, Report, Violation};
use wai_study::Embedded;
use wai_study::Study;

const ID: &str = "L3.7";

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study);

/// Checks L3.7 on every skeleton of a map.
fn check_study(study: &Study<'_>) -> Report {
    check_classes(study.map().reflex_vertices().len(), study.embeddings())
}

/// The check proper: every class has at most max(r, 1) embeddings.
pub fn check_classes(r: usize, by_class: &[Vec<Embedded>]) -> Report {
    let mut report = Report::new(ID);
    for (class, all) in by_class.iter().enumerate() {
        report.examined += 1;
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
        // One skeleton embeds once per niche (L3.7t).
        assert_eq!(study.embeddings().iter().map(Vec::len).max(), Some(3));
    }

    #[test]
    fn planted_excess_is_reported() {
        let map = wai_gen::family("corridor-niches", &[2]).unwrap();
        let study = Study::new(&map);
        let mut by_class = study.embeddings().to_vec();
        let r = map.reflex_vertices().len();
        let one = by_class.iter().find(|c| !c.is_empty()).unwrap()[0].clone();
        by_class[0] = vec![one; r + 1];
        let report = check_classes(r, &by_class);
        assert_eq!(report.violations.len(), 1);
        assert!(report.violations[0].what.contains("embeddings, r ="));
    }
}
