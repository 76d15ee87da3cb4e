//! Claim C4.15 (Corollary 4.15): for two overlapping valid embeddings of
//! one skeleton, the intersection of their skeleton polygons lies entirely
//! on one side of the line through any witness w of one and w' of the
//! other.
//!
//! ## Trust
//! Exact over whole witness regions, on every pair of T4.2
//! ([`wai_study::Study::overlapping_pairs`]). A line crosses the inside of
//! the intersection I (one region, L4.6) iff it has vertices of I strictly
//! on both sides, i.e. iff it meets the interior of I's convex hull. So the
//! claim fails iff one line meets a witness cell of each and the open hull
//! — three open convex sets — which [`wai_embed::transversal`] decides
//! exactly and completely; a violation comes with the two witnesses.
//!
//! ## Cases
//! "kernels overlap" or "kernels apart": whether the pair's kernels
//! overlap too, i.e. whether the corollary rests on Theorem 4.3's proof
//! or on Theorem 4.2's general one.

use serde_json::json;
use wai_embed::{transversal, Intersection, Piece};
use wai_exact::QPoint;

use crate::framework::{Case, Checker, Report, Violation};
use wai_study::Study;

const ID: &str = "C4.15";

/// The two premises, shared with Corollary 4.16.
pub const KERNEL_CASES: [Case; 2] = [
    Case {
        name: "kernels overlap",
        what: "the embedded kernels overlap too (Theorem 4.3's premise)",
    },
    Case {
        name: "kernels apart",
        what: "the skeleton polygons overlap, the kernels do not (Theorem 4.2 beyond Theorem 4.3)",
    },
];

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study).with_cases(&KERNEL_CASES);

/// The name of the kernel case of a pair.
pub fn kernel_case(kernels_overlap: bool) -> &'static str {
    KERNEL_CASES[usize::from(!kernels_overlap)].name
}

/// Checks C4.15 on every overlapping pair of valid embeddings of one
/// skeleton.
fn check_study(study: &Study<'_>) -> Report {
    let mut report = Report::new(ID);
    for pair in study.overlapping_pairs() {
        let x = study
            .intersection(&study.embedding_pairs()[pair.pair])
            .expect("an overlapping pair has an intersection");
        report.hit(kernel_case(pair.kernels_overlap));
        report.record(
            check(
                x,
                study.witness_pieces(pair.class, pair.a),
                study.witness_pieces(pair.class, pair.b),
            )
            .map(|mut v| {
                v.data["class"] = json!(pair.class);
                v.data["pair"] = json!([pair.a, pair.b]);
                v
            }),
        );
    }
    report
}

/// The open convex hull of the intersection `x`.
fn open_hull(x: &Intersection) -> Option<Piece> {
    let points: Vec<QPoint> = x.cycles.iter().flatten().map(|e| e.from.clone()).collect();
    let h = wai_exact::convex_hull(points);
    (h.len() >= 3).then_some(Piece::Polygon(h))
}

/// One pair: no line through a witness of each crosses the intersection.
pub fn check(x: &Intersection, w: &[Piece], w2: &[Piece]) -> Option<Violation> {
    let hull = open_hull(x)?;
    for a in w {
        for b in w2 {
            if let Some((x, y)) = transversal(a, b, &hull) {
                return Some(Violation::with_data(
                    format!("the line through witnesses {x} and {y} crosses the intersection of their embeddings"),
                    json!({ "witnesses": [x.to_string(), y.to_string()] }),
                ));
            }
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;
    use rug::Rational;

    #[test]
    fn holds_on_repeated_niches() {
        crate::fixtures::holds_on(&CHECKER, wai_gen::repeated_niches, &[195, 12]);
    }

    #[test]
    fn planted_witnesses_across_the_intersection_are_reported() {
        let ring = wai_embed::piece::ints;
        let p = ring(&[(0, 0), (4, 0), (4, 4), (0, 4)]);
        let q = ring(&[(2, 2), (6, 2), (6, 6), (2, 6)]);
        let pt = |x: i64, y: i64| Piece::Point(QPoint::new(Rational::from(x), Rational::from(y)));
        // Witnesses on the diagonal through the overlap: violated.
        let x = Intersection::of(&p, &q);
        assert!(check(&x, &[pt(1, 1)], &[pt(5, 5)]).is_some());
        // Witnesses beside it, their line passing below: holds.
        assert!(check(&x, &[pt(1, 1)], &[pt(5, 1)]).is_none());
    }
}
