//! Claim L4.8 (Lemma 4.8, Def 4.2): an artificial edge h(a) that meets two
//! artificial edges h'(b), h'(c) of an overlapping valid embedding is a
//! left-right edge with respect to both or a right-left edge with respect
//! to both.
//!
//! ## Trust
//! Exact over whole witness regions, on the overlapping pairs of
//! [`wai_study::Study::embedding_pairs`], both ways round: Def 4.2 is stated
//! for a witness, and the lemma for any. The classification of h(a) from w
//! changes only where w crosses the line of h(a), h'(b) or h'(c); so each
//! witness cell is cut by those lines
//! ([`wai_embed::piece::part_points`]) and one point of each part tested.
//! Witnesses on such a line leave the classification undecided
//! ([`wai_embed::intersection::left_right`] gives `None`); count
//! `undecided`.
//!
//! ## Cases
//! Each decided instance hits the lemma's two outcomes: "LR to both" or
//! "RL to both" (Def 4.2; the proof rules out the mixed one, Fig 4.11).

use serde_json::json;
use wai_embed::intersection::{artificial_crossings, left_right};
use wai_embed::piece::part_points;
use wai_embed::{Piece, SkeletonRing};

use crate::framework::{Case, Checker, Report, Violation};
use wai_study::Study;

const ID: &str = "L4.8";

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study).with_cases(&[
    Case {
        name: "LR to both",
        what: "an artificial edge meeting two of the other embedding, a left-right edge with respect to both (Def 4.2)",
    },
    Case {
        name: "RL to both",
        what: "the same, a right-left edge with respect to both",
    },
]);

/// Checks L4.8 on every artificial edge that meets two of the other
/// embedding, from every witness.
fn check_study(study: &Study<'_>) -> Report {
    let rings = study.skeleton_rings();
    let mut report = Report::new(ID);
    for pair in study.embedding_pairs() {
        if !pair.overlap() {
            continue;
        }
        for (one, other) in [(pair.first, pair.second), (pair.second, pair.first)] {
            let (p, q) = (&rings[one.0][one.1], &rings[other.0][other.1]);
            let witnesses = study.witness_pieces(one.0, one.1);
            let mut r = check(p, q, witnesses);
            r.tag("pair", || json!([one, other]));
            report.absorb(r);
        }
    }
    report
}

/// Every artificial edge of `p` meeting exactly two artificial edges of
/// `q`, from every witness of `p` (the points of `witnesses`).
pub fn check(p: &SkeletonRing, q: &SkeletonRing, witnesses: &[Piece]) -> Report {
    let mut report = Report::new(ID);
    let line = |r: &SkeletonRing, k: usize| {
        let (x, y) = r.edge(k);
        (x.clone(), y.clone())
    };
    for i in p.artificial_edges() {
        let meets = artificial_crossings(p, i, q);
        let [b, c] = meets[..] else { continue };
        let lines = [line(p, i), line(q, b), line(q, c)];
        for w in &part_points(witnesses, &lines) {
            let (sb, sc) = (
                left_right(w, p.edge(i), q.edge(b)),
                left_right(w, p.edge(i), q.edge(c)),
            );
            let (Some(sb), Some(sc)) = (sb, sc) else {
                report.count("undecided", 1);
                continue;
            };
            let name = |lr: bool| if lr { "LR" } else { "RL" };
            if sb == sc {
                report.hit(if sb { "LR to both" } else { "RL to both" });
            }
            report.record((sb != sc).then(|| {
                let (a0, a1) = p.edge(i);
                Violation::with_data(
                    format!(
                        "artificial edge {a0}–{a1}, seen from witness {w}, is {} with respect to one artificial edge of the other embedding and {} with respect to the other",
                        name(sb),
                        name(sc)
                    ),
                    json!({ "edge": i, "against": [b, c], "witness": w.to_string() }),
                )
            }));
        }
    }
    report
}

#[cfg(test)]
mod tests {
    use super::*;
    use wai_exact::Point;
    use wai_exact::QPoint;

    #[test]
    fn holds_on_repeated_niches() {
        crate::fixtures::holds_on(&CHECKER, wai_gen::repeated_niches, &[195, 12, 16]);
    }

    #[test]
    fn planted_mixed_sense_is_reported() {
        // A horizontal artificial edge seen from below, crossed by two
        // artificial edges leaning the same way: LR against one, RL
        // against the other is impossible for a real embedding; here one
        // leans left, the other right, so the senses differ.
        let pts = |v: &[(i128, i128)]| v.iter().map(|&(x, y)| Point::new(x, y)).collect::<Vec<_>>();
        let p = SkeletonRing::new(
            &pts(&[(-4, 0), (4, 0), (4, 2), (-4, 2)]),
            vec![false, false, true, false],
        );
        let q = SkeletonRing::new(
            &pts(&[
                (-3, 1),
                (-2, 1),
                (-1, 3),
                (1, 3),
                (2, 1),
                (3, 1),
                (3, 6),
                (-3, 6),
            ]),
            vec![false, true, false, true, false, false, false, false],
        );
        let w = Piece::Point(QPoint::new(rug::Rational::from(0), rug::Rational::from(1)));
        let report = check(&p, &q, &[w]);
        assert_eq!(report.examined, 1);
        assert_eq!(report.violations.len(), 1, "{:?}", report.violations);
    }
}
