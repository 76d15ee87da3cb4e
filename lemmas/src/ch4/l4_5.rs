//! Claim L4.5 (Lemma 4.5): for two valid embeddings h, h' (skeletons may
//! differ), an embedded artificial edge h(a) meets at most two artificial
//! edges of h', and the part of h(a) in h'(V◇) — on the boundary of the
//! intersection — is a single segment (or point).
//!
//! ## Trust
//! Exact, on the pairs of [`wai_study::Study::embedding_pairs`]: every pair of
//! valid embeddings of one skeleton, and of different skeletons on maps of
//! at most [`wai_study::CROSS_SKELETON_MAX_N`] vertices, whose bounding
//! boxes meet (other pairs hold trivially); each artificial edge of either
//! against the other. "Meets" counts closed segments sharing a point other
//! than a common end ([`wai_embed::intersection::edges_meet`]); the part
//! inside h'(V◇) is counted as maximal pieces, exactly
//! ([`wai_embed::intersection::pieces_inside`]). Counts: `different
//! skeletons` (instances from such pairs).
//!
//! ## Cases
//! Each artificial edge h(a) hits "0 crossings", "1 crossing" or "2
//! crossings": how many artificial edges of the other embedding it meets
//! (Fig 4.8 (a) is the case of two); progress toward "2 crossings" is the
//! most met by one edge.

use rug::Rational;
use serde_json::json;
use wai_embed::intersection::artificial_crossings;
use wai_embed::SkeletonRing;

use crate::framework::{Case, Checker, Report, Violation};
use wai_study::Study;

const ID: &str = "L4.5";

/// By the number of artificial edges met: the case's name.
const CROSSINGS: [&str; 3] = ["0 crossings", "1 crossing", "2 crossings"];

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study).with_cases(&[
    Case {
        name: CROSSINGS[0],
        what: "an artificial edge of one valid embedding that meets no artificial edge of the other",
    },
    Case {
        name: CROSSINGS[1],
        what: "an artificial edge meeting exactly one artificial edge of the other",
    },
    Case {
        name: CROSSINGS[2],
        what: "an artificial edge meeting two artificial edges of the other, the most Lemma 4.5 allows (Fig 4.8 (a))",
    },
]);

/// Checks L4.5 on every pair of valid embeddings in scope.
fn check_study(study: &Study<'_>) -> Report {
    let rings = study.skeleton_rings();
    let mut report = Report::new(ID);
    for pair in study.embedding_pairs() {
        let (p, q) = (
            &rings[pair.first.0][pair.first.1],
            &rings[pair.second.0][pair.second.1],
        );
        let mut r = check_edges(p, q);
        r.absorb(check_edges(q, p));
        if !pair.same_skeleton() {
            report.count("different skeletons", r.examined);
        }
        r.tag("pair", || json!([pair.first, pair.second]));
        report.absorb(r);
    }
    report
}

/// Every artificial edge of `p` against `q`.
pub fn check_edges(p: &SkeletonRing, q: &SkeletonRing) -> Report {
    let mut report = Report::new(ID);
    for i in p.artificial_edges() {
        let meets = artificial_crossings(p, i, q);
        let (a, b) = p.edge(i);
        let inside = p.edge_pieces_inside(i, q);
        if let Some(case) = CROSSINGS.get(meets.len()) {
            report.hit(case);
        }
        report.progress_toward(CROSSINGS[2], Rational::from(meets.len()));
        report.record((meets.len() > 2 || inside > 1).then(|| {
            Violation::with_data(
                format!(
                    "artificial edge {a}–{b} meets {} artificial edges of the other embedding and lies in it in {inside} pieces",
                    meets.len()
                ),
                json!({ "edge": [a.to_string(), b.to_string()], "meets": meets, "pieces_inside": inside }),
            )
        }));
    }
    report
}

#[cfg(test)]
mod tests {
    use super::*;
    use wai_exact::Point;

    #[test]
    fn holds_on_the_funnel_figure_pairs() {
        let map = wai_gen::repeated_niches(195);
        let report = CHECKER.run(&Study::new(&map));
        assert!(report.examined > 0);
        assert!(report.violations.is_empty(), "{:?}", report.violations);
    }

    #[test]
    fn planted_three_crossings_and_two_pieces_are_reported() {
        let pts = |v: &[(i128, i128)]| v.iter().map(|&(x, y)| Point::new(x, y)).collect::<Vec<_>>();
        // A long artificial edge (the bottom of a rectangle) under a comb
        // of three teeth, each side of a tooth artificial.
        let p = SkeletonRing::new(
            &pts(&[(0, 0), (10, 0), (10, 4), (0, 4)]),
            vec![true, false, false, false],
        );
        let comb = pts(&[
            (1, -2),
            (9, -2),
            (9, 2),
            (8, 2),
            (8, -1),
            (6, -1),
            (6, 2),
            (4, 2),
            (4, -1),
            (2, -1),
            (2, 2),
            (1, 2),
        ]);
        let q = SkeletonRing::new(&comb, vec![true; comb.len()]);
        let report = check_edges(&p, &q);
        assert_eq!(report.examined, 1);
        assert_eq!(report.violations.len(), 1);
        assert!(
            report.violations[0].what.contains("meets 6"),
            "{}",
            report.violations[0].what
        );
    }
}
