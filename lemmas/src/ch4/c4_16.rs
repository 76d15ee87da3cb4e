//! Claim C4.16 (Corollary 4.16): for two overlapping valid embeddings h, h'
//! of one skeleton, every line parallel to t = h'(v0) − h(v0) that crosses
//! their intersection has the witnesses w and w' on the same side.
//!
//! ## Trust
//! Exact over whole witness regions, on every pair of T4.2
//! ([`wai_study::Study::overlapping_pairs`]). Project onto the normal of t:
//! the lines parallel to t crossing the intersection's inside are those
//! whose offset lies strictly between the least and greatest projection of
//! its vertices, (l, u); the witnesses' projections range over (or to) the
//! least and greatest projection of their cells' vertices. Some line has
//! a witness of each strictly on either side iff max(inf W, l) < min(sup W', u)
//! or the same with W and W' swapped.
//!
//! ## Cases
//! "kernels overlap" or "kernels apart" as for [`super::c4_15`]; and the
//! side of the intersection both witness regions lie on, which the proof
//! fixes without loss of generality ("below l"): "witnesses left of t"
//! (every witness projects at or beyond the intersection's left end) or
//! "witnesses right of t".

use rug::Rational;
use serde_json::json;
use wai_embed::piece::projection;
use wai_embed::{Intersection, Piece};
use wai_exact::QPoint;

use super::c4_15::{kernel_case, KERNEL_CASES};
use crate::framework::{Case, Checker, Report, Violation};
use wai_study::Study;

const ID: &str = "C4.16";

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study).with_cases(&[
    KERNEL_CASES[0],
    KERNEL_CASES[1],
    Case {
        name: "witnesses left of t",
        what: "both witness regions beyond the intersection on the left of t (the proof's \"above l\")",
    },
    Case {
        name: "witnesses right of t",
        what: "both witness regions beyond the intersection on the right of t (the proof's \"below l\")",
    },
]);

/// Checks C4.16 on every overlapping pair of valid embeddings of one
/// skeleton.
fn check_study(study: &Study<'_>) -> Report {
    let map = study.map().vertices();
    let mut report = Report::new(ID);
    for pair in study.overlapping_pairs() {
        let all = &study.embeddings()[pair.class];
        let (o, o2) = (
            map[all[pair.a].embedding.origin],
            map[all[pair.b].embedding.origin],
        );
        let t = QPoint::from(o2).sub(&QPoint::from(o));
        let x = study
            .intersection(&study.embedding_pairs()[pair.pair])
            .expect("an overlapping pair has an intersection");
        let (w, w2) = (
            study.witness_pieces(pair.class, pair.a),
            study.witness_pieces(pair.class, pair.b),
        );
        report.hit(kernel_case(pair.kernels_overlap));
        if let Some(case) = side(x, &t, w, w2) {
            report.hit(case);
        }
        report.record(check(x, &t, w, w2).map(|mut v| {
            v.data["class"] = json!(pair.class);
            v.data["pair"] = json!([pair.a, pair.b]);
            v
        }));
    }
    report
}

/// The least and greatest of `n · v` over the vertices, if any.
fn range(n: &QPoint, vertices: impl Iterator<Item = QPoint>) -> Option<(Rational, Rational)> {
    let v: Vec<QPoint> = vertices.collect();
    (!v.is_empty()).then(|| projection(n, &v))
}

/// The side of the intersection `x` both witness regions lie on, seen
/// along `t`, if they lie on one.
pub fn side(x: &Intersection, t: &QPoint, w: &[Piece], w2: &[Piece]) -> Option<&'static str> {
    let n = t.perp();
    let (l, u) = range(&n, x.cycles.iter().flatten().map(|e| e.from.clone()))?;
    let (lo, hi) = range(&n, w.iter().chain(w2).flat_map(Piece::vertices))?;
    if lo >= u {
        Some("witnesses left of t")
    } else if hi <= l {
        Some("witnesses right of t")
    } else {
        None
    }
}

/// One pair, with translation `t` from the first origin to the second.
pub fn check(x: &Intersection, t: &QPoint, w: &[Piece], w2: &[Piece]) -> Option<Violation> {
    let n = t.perp();
    let (l, u) = range(&n, x.cycles.iter().flatten().map(|e| e.from.clone()))?;
    let (a_lo, a_hi) = range(&n, w.iter().flat_map(Piece::vertices))?;
    let (b_lo, b_hi) = range(&n, w2.iter().flat_map(Piece::vertices))?;
    let split =
        |lo: &Rational, hi: &Rational| lo.clone().max(l.clone()) < hi.clone().min(u.clone());
    (split(&a_lo, &b_hi) || split(&b_lo, &a_hi)).then(|| {
        Violation::with_data(
            "a line parallel to the translation between the embeddings crosses their intersection with their witnesses on either side",
            json!({
                "intersection": [l.to_string(), u.to_string()],
                "first_witnesses": [a_lo.to_string(), a_hi.to_string()],
                "second_witnesses": [b_lo.to_string(), b_hi.to_string()],
            }),
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn holds_on_repeated_niches() {
        crate::fixtures::holds_on(&CHECKER, wai_gen::repeated_niches, &[195, 12]);
    }

    #[test]
    fn planted_witnesses_on_either_side_are_reported() {
        let ring = wai_embed::piece::ints;
        let p = ring(&[(0, 0), (4, 0), (4, 4), (0, 4)]);
        let q = ring(&[(2, 0), (6, 0), (6, 4), (2, 4)]);
        let t = QPoint::new(Rational::from(2), Rational::new());
        let pt = |x: i64, y: i64| Piece::Point(QPoint::new(Rational::from(x), Rational::from(y)));
        // t horizontal: the lines y = c, 0 < c < 4, cross the overlap.
        let x = Intersection::of(&p, &q);
        assert!(check(&x, &t, &[pt(1, 1)], &[pt(5, 3)]).is_some());
        assert!(check(&x, &t, &[pt(1, 5)], &[pt(5, 6)]).is_none());
    }
}
