//! Claim C4.10 (Corollary 4.10): the intersection polygon of two
//! overlapping valid embeddings has at most four type-5 edges (parts of an
//! artificial edge meeting two artificial edges of the other embedding).
//!
//! ## Trust
//! Exact, on the same intersections and the same classification as
//! [`super::l4_7`].
//!
//! ## Cases
//! Each intersection polygon hits "0 type 5" to "4 type 5", its number of
//! type-5 edges (the proof: each comes from an LR/LR or RL/RL crossing of
//! Lemma 4.9, at most two of them, two edges each); progress toward "4
//! type 5" is the most on one polygon.

use rug::Rational;
use serde_json::json;
use wai_embed::intersection::EdgeType;

use super::l4_7::classified_pairs;
use crate::framework::{Case, Checker, Report, Violation};
use wai_study::Study;

const ID: &str = "C4.10";

/// By the number of type-5 edges: the case's name.
const FIVES: [&str; 5] = ["0 type 5", "1 type 5", "2 type 5", "3 type 5", "4 type 5"];

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study).with_cases(&[
    Case {
        name: FIVES[0],
        what: "an intersection polygon with no type-5 edge",
    },
    Case {
        name: FIVES[1],
        what: "an intersection polygon with one type-5 edge",
    },
    Case {
        name: FIVES[2],
        what: "an intersection polygon with two type-5 edges (one LR/LR or RL/RL crossing)",
    },
    Case {
        name: FIVES[3],
        what: "an intersection polygon with three type-5 edges",
    },
    Case {
        name: FIVES[4],
        what: "an intersection polygon with four type-5 edges, the bound (Figs 4.15 and 4.16)",
    },
]);

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
        if let Some(case) = FIVES.get(fives) {
            report.hit(case);
        }
        report.progress_toward(FIVES[4], Rational::from(fives));
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
