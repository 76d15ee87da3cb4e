//! Claim E4.28 (sec. 4.6, Fig 4.28): Theorem 4.2 needs its embeddings to
//! *overlap*. Two valid embeddings of one skeleton that only intersect —
//! their skeleton polygons share a segment or a point, no interior point —
//! can have witnesses that see each other.
//!
//! ## Trust
//! Exact over whole witness regions. The pairs are those of
//! [`wai_study::Study::touching_pairs`]: valid embeddings of one skeleton
//! whose skeleton polygons' boundaries share a point (exact segment
//! tests) while their interiors do not ([`wai_embed::interiors_overlap`]);
//! whether a witness of one sees a witness of the other is the search
//! over lines of [`wai_embed::Sightlines`], as for Theorem 4.2, a
//! "visible" verdict carrying two points re-checked by
//! `wai_exact::sees`. The stored figure
//! `counterexamples/E4.28-intersecting-hexagons.json`, recognised by its
//! vertices ([`super::Figure`]), must show such a pair for its viewpoints'
//! skeleton, sharing an artificial edge and with mutually visible
//! witnesses; otherwise a violation (count `figures`). Elsewhere every
//! such pair is one instance, and the cases count the configuration
//! wherever it occurs.

use serde_json::json;
use wai_study::{Study, TouchingPair};

use super::{figure, Figure};
use crate::framework::{Case, Checker, Report, Violation};

const ID: &str = "E4.28";

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study).with_cases(&[
    Case {
        name: "visible",
        what: "two valid embeddings of one skeleton that intersect without overlapping and have witnesses that see each other (Fig 4.28)",
    },
    Case {
        name: "invisible",
        what: "two such embeddings whose witnesses do not see each other, as Theorem 4.2 would have it if it applied",
    },
    Case {
        name: "common artificial edge",
        what: "two such embeddings sharing an artificial edge, the same two map vertices in both (Fig 4.28: they intersect in exactly one artificial edge)",
    },
]);

figure!(
    /// Fig 4.28: two convex hexagons sharing one artificial edge.
    fig_4_28,
    "E4.28-intersecting-hexagons.json"
);

/// Whether embeddings `a` and `b` of the skeleton of `class` have an
/// artificial edge on the same two map vertices.
pub fn common_artificial_edge(study: &Study<'_>, class: usize, a: usize, b: usize) -> bool {
    let labels = &study.decomposition().skeletons()[class].labels;
    let all = &study.embeddings()[class];
    let ends = |h: usize| -> Vec<[usize; 2]> {
        let v = &all[h].embedding.vertices;
        (0..v.len())
            .filter(|&i| labels[i].is_some())
            .map(|i| {
                let mut e = [v[i], v[(i + 1) % v.len()]];
                e.sort_unstable();
                e
            })
            .collect()
    };
    let eb = ends(b);
    ends(a).iter().any(|e| eb.contains(e))
}

/// Checks E4.28: the stored figure shows Fig 4.28; every pair of valid
/// embeddings of one skeleton that intersect without overlapping is
/// counted by configuration.
fn check_study(study: &Study<'_>) -> Report {
    let mut report = Report::new(ID);
    let mut shown = Vec::new();
    for pair in study.touching_pairs() {
        report.record(None);
        let common = common_artificial_edge(study, pair.class, pair.a, pair.b);
        if common {
            report.hit("common artificial edge");
        }
        if pair.sight.is_visible() {
            report.hit("visible");
            if common {
                shown.push(pair);
            }
        } else {
            report.hit("invisible");
        }
    }
    let fig = fig_4_28();
    if fig.is(study.map()) {
        report.count("figures", 1);
        report.record(figure_verdict(fig, fig.class(study), &shown));
    }
    report
}

/// The stored figure on its own map: among the pairs `shown` (sharing an
/// artificial edge, witnesses visible) one of the viewpoints' skeleton
/// `class`.
pub fn figure_verdict(
    fig: &Figure,
    class: Option<usize>,
    shown: &[&TouchingPair],
) -> Option<Violation> {
    let ok = shown.iter().any(|p| Some(p.class) == class);
    (!ok).then(|| {
        Violation::with_data(
            format!(
                "the stored figure {} no longer shows two intersecting, not overlapping, valid embeddings of its viewpoints' skeleton that share an artificial edge and whose witnesses see each other",
                fig.file
            ),
            json!({ "file": fig.file, "class": class }),
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_figure_shows_visible_witnesses() {
        let report = CHECKER.check_map(&fig_4_28().map);
        assert!(report.violations.is_empty(), "{:?}", report.violations);
        assert_eq!(report.counts["figures"], 1);
        assert!(report.cases["visible"] >= 1);
        assert!(report.cases["common artificial edge"] >= 1);
    }

    #[test]
    fn planted_figure_without_its_pair_is_reported() {
        let fig = fig_4_28();
        let study = Study::new(&fig.map);
        let class = fig.class(&study).expect("the viewpoints share a skeleton");
        let pairs: Vec<&TouchingPair> = study.touching_pairs().iter().collect();
        assert!(figure_verdict(fig, Some(class), &pairs).is_none());
        let v = figure_verdict(fig, Some(class), &[]).expect("nothing shown");
        assert!(v.what.contains("no longer shows"));
    }
}
