//! Claim L4.18 (Lemma 4.18): if a candidate edge c of h crosses a
//! candidate edge c' of h' (Def 4.4) and the two embeddings overlap, then
//! h(a) meets h'(V◇) or h'(a') meets h(V◇).
//!
//! ## Trust
//! Exact over whole witness regions, on every pair (c of h, c' of h') of
//! valid candidate edges, c ≠ c', of every overlapping pair of valid
//! embeddings of one skeleton (`examined`). When h(a) meets h'(V◇) or
//! h'(a') meets h(V◇) the claim holds whether or not c and c' cross
//! (`artificial_edge_meets`); otherwise (`both_outside`) they must not
//! cross, which [`wai_study::Study::crosses`] decides on the union of all
//! lines of sight from each witness cell through the artificial edge
//! ([`wai_embed::SightFan`]); a crossing comes with two certified lines
//! of sight that meet. "Meets" is read on closed sets (an artificial edge
//! touching the other polygon at one point meets it), the weaker
//! conclusion, so a violation here is one under either reading.
//!
//! ## Cases
//! Which of the lemma's alternatives holds for each instance, the two
//! categories the thesis sorts crossing candidate edges of overlapping
//! embeddings into: "one meets" (exactly one of h(a), h'(a') meets the
//! other skeleton polygon), "both meet" (both do, as in Fig 4.31), or
//! "neither" (then c and c' must not cross).

use serde_json::json;
use wai_embed::segment_meets_polygon;
use wai_exact::QPoint;

use crate::framework::{Case, Checker, Report, Violation};
use wai_study::Study;

const ID: &str = "L4.18";

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study).with_cases(&[
    Case {
        name: "one meets",
        what: "exactly one of h(a) and h'(a') meets the other embedding's skeleton polygon",
    },
    Case {
        name: "both meet",
        what: "h(a) meets h'(V◇) and h'(a') meets h(V◇) (Fig 4.31)",
    },
    Case {
        name: "neither",
        what: "neither artificial edge meets the other polygon: c and c' must not cross",
    },
]);

/// Checks L4.18 on every pair of crossing candidate edges of two
/// overlapping valid embeddings of one skeleton.
fn check_study(study: &Study<'_>) -> Report {
    let mut report = Report::new(ID);
    let rings = study.skeleton_rings();
    for (k, p) in study.overlapping_pairs().iter().enumerate() {
        let (r, r2) = (&rings[p.class][p.a].ring, &rings[p.class][p.b].ring);
        let (va, vb) = (
            study.valid_candidates(p.class, p.a),
            study.valid_candidates(p.class, p.b),
        );
        let edge =
            |ring: &[QPoint], i: usize| (ring[i].clone(), ring[(i + 1) % ring.len()].clone());
        for (i, ci) in va.iter().enumerate().filter(|(_, c)| !c.is_empty()) {
            for (j, cj) in vb.iter().enumerate().filter(|(_, c)| !c.is_empty()) {
                let (a, a2) = (edge(r, i), edge(r2, j));
                let meets = [
                    segment_meets_polygon(&a.0, &a.1, r2),
                    segment_meets_polygon(&a2.0, &a2.1, r),
                ];
                let case = match meets {
                    [true, true] => "both meet",
                    [false, false] => "neither",
                    _ => "one meets",
                };
                // The violation a crossing would be, if neither edge
                // meets the other polygon.
                let outside = (!meets[0] && !meets[1]).then(|| outside_violation(&a, &a2));
                for &c in ci {
                    for &c2 in cj.iter().filter(|&&c2| c2 != c) {
                        report.hit(case);
                        let Some(outside) = &outside else {
                            report.count("artificial_edge_meets", 1);
                            report.record(None);
                            continue;
                        };
                        report.count("both_outside", 1);
                        let found = study.crosses(k, (i, c), (j, c2));
                        report.record(found.map(|x| {
                            let mut v = outside.clone();
                            v.data["class"] = json!(p.class);
                            v.data["pair"] = json!([p.a, p.b]);
                            v.data["candidate_edges"] = json!([c, c2]);
                            v.data["sight"] = json!({
                                "at": x.at.to_string(),
                                "first": [x.first.0.to_string(), x.first.1.to_string()],
                                "second": [x.second.0.to_string(), x.second.1.to_string()],
                            });
                            v
                        }));
                    }
                }
            }
        }
    }
    report
}

/// One pair of artificial edges: h(a) (`a`, of h(V◇) `ring`) or h'(a')
/// (`a2`, of `ring2`) meets the other polygon; if neither does, the
/// violation a crossing of their candidate edges would be.
pub fn check(
    a: &(QPoint, QPoint),
    ring: &[QPoint],
    a2: &(QPoint, QPoint),
    ring2: &[QPoint],
) -> Option<Violation> {
    if segment_meets_polygon(&a.0, &a.1, ring2) || segment_meets_polygon(&a2.0, &a2.1, ring) {
        return None;
    }
    Some(outside_violation(a, a2))
}

/// The violation crossing candidate edges of `a` and `a2` are when
/// neither artificial edge meets the other polygon.
fn outside_violation(a: &(QPoint, QPoint), a2: &(QPoint, QPoint)) -> Violation {
    Violation::with_data(
        format!(
            "crossing candidate edges whose artificial edges {}–{} and {}–{} both lie outside the other embedding",
            a.0, a.1, a2.0, a2.1
        ),
        json!({ "artificial_edges": [[a.0.to_string(), a.1.to_string()], [a2.0.to_string(), a2.1.to_string()]] }),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use wai_embed::piece::ints;

    #[test]
    fn holds_on_repeated_niches() {
        crate::fixtures::holds_on(&CHECKER, wai_gen::repeated_niches, &[195, 114]);
    }

    #[test]
    fn planted_artificial_edges_outside_both_are_reported() {
        let p = ints(&[(0, 0), (4, 0), (4, 4), (0, 4)]);
        let q = ints(&[(2, 2), (6, 2), (6, 6), (2, 6)]);
        let seg = |a: (i64, i64), b: (i64, i64)| {
            let v = ints(&[a, b]);
            (v[0].clone(), v[1].clone())
        };
        // h(a) = p's bottom edge, h'(a') = q's top edge: each misses the
        // other polygon.
        assert!(check(&seg((0, 0), (4, 0)), &p, &seg((6, 6), (2, 6)), &q).is_some());
        // p's right edge runs through q.
        assert!(check(&seg((4, 0), (4, 4)), &p, &seg((6, 6), (2, 6)), &q).is_none());
        // Touching q's corner counts as meeting it.
        assert!(check(&seg((4, 4), (0, 4)), &p, &seg((6, 6), (2, 6)), &q).is_none());
    }
}
