//! Claim L5.7 (Lemma 5.7): all interweaved gap pairs (Def 5.6) of two
//! embeddings use the same pair of artificial edges.
//!
//! ## Trust
//! Exact, on every class with a valid embedding: for each two embeddings
//! with an interweaved pair of gap chains ([`wai_study::GapStructure`]),
//! one instance, the set of (artificial edge of the first, of the second)
//! over all their interweaved pairs must have one element.
//!
//! ## Cases
//! Two embeddings with one interweaved pair of gaps ([`ONE_PAIR`]: the
//! lemma holds trivially) or several ([`SEVERAL_PAIRS`]: the lemma has
//! content), with the most pairs of two embeddings as progress toward it.

use std::collections::{BTreeMap, BTreeSet};

use rug::Rational;
use serde_json::json;

use crate::framework::{Case, Checker, Report, Violation};
use wai_study::GapStructure;

use super::over_gap_classes;
use wai_study::Study;

const ID: &str = "L5.7";

/// Two embeddings interweaved through one pair of gaps.
pub const ONE_PAIR: &str = "one pair";
/// Two embeddings interweaved through several pairs of gaps.
pub const SEVERAL_PAIRS: &str = "several pairs";

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study)
    .outer_ring_only("gap chains run along the boundary from one candidate edge to the next (Def 5.4): boundary order on one ring").with_cases(&[
    Case {
        name: ONE_PAIR,
        what: "two embeddings with exactly one pair of interweaved gaps (Def 5.6)",
    },
    Case {
        name: SEVERAL_PAIRS,
        what: "two embeddings with two or more pairs of interweaved gaps: the premise of \
               Lemma 5.7 with content (Fig 5.7)",
    },
]);

/// Checks L5.7 on every class.
fn check_study(study: &Study<'_>) -> Report {
    over_gap_classes(study, ID, |g, _| check_class(g))
}

/// L5.7 on one class's gap structure (embeddings and artificial edges by
/// their positions j and i).
pub fn check_class(g: &GapStructure) -> Report {
    let mut report = Report::new(ID);
    let mut uses: BTreeMap<(usize, usize), BTreeSet<(usize, usize)>> = BTreeMap::new();
    let mut gap_pairs: BTreeMap<(usize, usize), usize> = BTreeMap::new();
    for ((j1, i1), (j2, i2)) in g.interweaved() {
        let key = if j1 < j2 {
            ((j1, j2), (i1, i2))
        } else {
            ((j2, j1), (i2, i1))
        };
        uses.entry(key.0).or_default().insert(key.1);
        *gap_pairs.entry(key.0).or_default() += 1;
    }
    for (&(j1, j2), &count) in &gap_pairs {
        if count == 1 {
            report.hit(ONE_PAIR);
            report.progress_toward(SEVERAL_PAIRS, Rational::from(count));
        } else {
            report.hit(SEVERAL_PAIRS);
        }
        let pairs = &uses[&(j1, j2)];
        report.record((pairs.len() > 1).then(|| {
            Violation::with_data(
                format!(
                    "embeddings at positions {j1} and {j2} are interweaved through {} pairs of artificial edges",
                    pairs.len()
                ),
                json!({"j1": j1, "j2": j2, "artificial_pairs": pairs}),
            )
        }));
    }
    report
}

#[cfg(test)]
mod tests {
    use super::*;
    use wai_embed::GapChain;

    #[test]
    fn planted_second_pair_of_artificial_edges_is_reported() {
        // Embeddings 0 and 1 interweave through (a0, a0) and (a1, a0).
        let chains = vec![
            GapChain::new(1, 6, 0, 0, 30),
            GapChain::new(4, 9, 1, 0, 30),
            GapChain::new(7, 12, 0, 1, 30),
        ];
        let g = GapStructure::new(chains, vec![], 2);
        assert_eq!(g.interweaved().len(), 2);
        let report = check_class(&g);
        assert_eq!((report.examined, report.violations.len()), (1, 1));
        assert_eq!(report.cases[SEVERAL_PAIRS], 1);
        // Without the second: one pair, no violation.
        let chains = vec![GapChain::new(1, 6, 0, 0, 30), GapChain::new(4, 9, 1, 0, 30)];
        let report = check_class(&GapStructure::new(chains, vec![], 2));
        assert_eq!((report.examined, report.violations.len()), (1, 0));
        assert_eq!(report.cases[ONE_PAIR], 1);
    }
}
