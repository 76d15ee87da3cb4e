//! Claim C4.10 (Corollary 4.10): the intersection polygon of two
//! overlapping valid embeddings has at most four type-5 edges (parts of an
//! artificial edge meeting two artificial edges of the other embedding).
//!
//! ## Trust
//! Exact, on the same intersections and the same classification as
//! [`super::l4_7`]. Count `with type 5`: intersections that have one.

use serde_json::json;
use wai_embed::intersection::EdgeType;

use super::l4_7::classified_pairs;
use crate::framework::{Checker, Report, Violation};
use wai_study::Study;

const ID: &str = "C4.10";

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study);

/// Checks C4.10 on every intersection polygon in scope.
fn check_study(study: &Study<'_>) -> Report {
    let mut report = Report::new(ID);
    for (pair, _, types) in classified_pairs(study) {
        let fives = types
            .iter()
            .filter(|t| **t == Some(EdgeType::TwoCrossings))
            .count();
        report.record(check(fives).map(|mut v| {
            v.data["pair"] = json!([pair.first, pair.second]);
            v
        }));
        if fives > 0 {
            report.count("with type 5", 1);
        }
    }
    report
}

/// At most four type-5 edges.
pub fn check(fives: usize) -> Option<Violation> {
    (fives > 4).then(|| {
        Violation::with_data(
            format!("an intersection polygon has {fives} type-5 edges"),
            json!({ "type_5_edges": fives }),
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn holds_on_the_funnel_figure() {
        let map = wai_gen::repeated_niches(195);
        let report = CHECKER.run(&Study::new(&map));
        assert!(report.examined > 0);
        assert!(report.violations.is_empty());
    }

    #[test]
    fn planted_five_is_reported() {
        assert!(check(4).is_none());
        assert!(check(5).unwrap().what.contains("5 type-5"));
    }
}
