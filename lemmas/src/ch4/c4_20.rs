//! Claim C4.20 (Corollary 4.20): if c1, c2 (valid candidate edges of a in
//! h, c1 first on their directed line) and c1', c2' (of a' in an
//! overlapping h' ≠ h, c1' first) cross each other pairwise (Def 4.4),
//! they appear on ∂M in the order c1, c2, c1', c2' (cyclically, which is
//! also the order c1', c2', c1, c2).
//!
//! ## Trust
//! Exact, on every quadruple (c1 < c2 of one artificial edge of h, c1' <
//! c2' of one of h') of valid candidate edges of every overlapping pair of
//! valid embeddings of one skeleton (`examined`; the claim is symmetric in
//! h and h', so each pair is taken one way; `out_of_order` of them are not
//! in the order c1, c2, c1', c2'). The four crossings are decided by
//! [`wai_study::Study::crosses`] over whole witness regions for every
//! quadruple; `mutually_crossing` counts those that meet the corollary's
//! premise, and one of them out of order is a violation. Readings of
//! "directed line" and "between" as in [`super::t4_19`].
//!
//! ## Cases
//! The orders c1, c2, c1', c2' and c1', c2', c1, c2 of the corollary are
//! one cyclic order read from two starts, so the cases are those of the
//! premise: each mutually crossing quadruple hits "same artificial edge"
//! (h(a) and h'(a') join the same two map vertices, as the necks of Fig
//! 4.31) or "different artificial edges".

use serde_json::json;

use super::t4_19::ordered_candidates;
use crate::framework::{Case, Checker, Report, Violation};
use wai_study::Study;

const ID: &str = "C4.20";

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study)
    .outer_ring_only("the claim orders candidate edges counter-clockwise along the boundary: one ring").with_cases(&[
    Case {
        name: "same artificial edge",
        what: "mutually crossing candidate edges of artificial edges h(a), h'(a') on the same two map vertices (the necks of Fig 4.31)",
    },
    Case {
        name: "different artificial edges",
        what: "mutually crossing candidate edges of artificial edges on different map vertices",
    },
]);

/// Checks C4.20 on every quadruple of mutually crossing candidate edges
/// of two overlapping valid embeddings of one skeleton.
fn check_study(study: &Study<'_>) -> Report {
    on_boundary(study, &|e| e)
}

/// The check with `position` giving each map edge's place on the
/// counter-clockwise boundary (the identity for [`Order`]; a test moves
/// one edge to plant a violation in a real configuration).
pub fn on_boundary(study: &Study<'_>, position: &dyn Fn(usize) -> usize) -> Report {
    let n = study.map().n();
    let mut report = Report::new(ID);
    let pairs = |e: &[usize]| -> Vec<[usize; 2]> {
        (0..e.len())
            .flat_map(|i| (i + 1..e.len()).map(move |j| [e[i], e[j]]))
            .collect()
    };
    for (k, p) in study.overlapping_pairs().iter().enumerate() {
        let (mine, theirs) = (
            ordered_candidates(study, p.class, p.a),
            ordered_candidates(study, p.class, p.b),
        );
        for (a, edges) in mine.iter().enumerate() {
            for (a2, others) in theirs.iter().enumerate() {
                for c in pairs(edges) {
                    for d in pairs(others) {
                        let mut verdict =
                            check(n, c.map(position), d.map(position)).map(|mut v| {
                                v.data["c"] = json!(c);
                                v.data["c_prime"] = json!(d);
                                v
                            });
                        if verdict.is_some() {
                            report.count("out_of_order", 1);
                        }
                        let all = c.iter().all(|&c| {
                            d.iter()
                                .all(|&d| study.crosses(k, (a, c), (a2, d)).is_some())
                        });
                        if all {
                            report.count("mutually_crossing", 1);
                            let all = &study.embeddings()[p.class];
                            let ends = |h: usize, s: usize| {
                                let v = &all[h].embedding.vertices;
                                let mut e = [v[s], v[(s + 1) % v.len()]];
                                e.sort_unstable();
                                e
                            };
                            report.hit(if ends(p.a, a) == ends(p.b, a2) {
                                "same artificial edge"
                            } else {
                                "different artificial edges"
                            });
                        } else {
                            verdict = None;
                        }
                        report.record(verdict.map(|mut v| {
                            v.data["class"] = json!(p.class);
                            v.data["embeddings"] = json!([p.a, p.b]);
                            v.data["artificial_edges"] = json!([a, a2]);
                            v
                        }));
                    }
                }
            }
        }
    }
    report
}

/// One quadruple (each pair in the order of its line): counter-clockwise
/// from c1, the boundary meets c2, then c1', then c2'.
pub fn check(n: usize, [c1, c2]: [usize; 2], [d1, d2]: [usize; 2]) -> Option<Violation> {
    let r = |x: usize| (x + n - c1) % n;
    if r(c2) < r(d1) && r(d1) < r(d2) {
        return None;
    }
    Some(Violation::with_data(
        format!("mutually crossing candidate edges {c1}, {c2} and {d1}, {d2} interleave or run backwards on the boundary"),
        json!({ "c": [c1, c2], "c_prime": [d1, d2] }),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn holds_on_bottled_niches() {
        let mut report = Report::new(ID);
        for seed in [0, 1, 11] {
            let map = wai_gen::bottled_niches(seed);
            report.absorb(CHECKER.run(&Study::new(&map)));
        }
        assert!(report.violations.is_empty(), "{:?}", report.violations);
        // Fig 4.31's configuration: quadruples that cross pairwise.
        assert!(report.counts["mutually_crossing"] > 0);
    }

    #[test]
    fn an_edge_moved_between_a_crossing_pair_is_reported() {
        // Fig 4.31's map: find a mutually crossing quadruple, then move
        // c1' on the boundary to the edge after c1 (between c1 and c2):
        // the whole check must report the interleaving.
        let map = wai_gen::bottled_niches(0);
        let study = Study::new(&map);
        let quadruple = study
            .overlapping_pairs()
            .iter()
            .enumerate()
            .find_map(|(k, p)| {
                let (mine, theirs) = (
                    ordered_candidates(&study, p.class, p.a),
                    ordered_candidates(&study, p.class, p.b),
                );
                let two = |e: &Vec<usize>| (e.len() == 2).then(|| [e[0], e[1]]);
                mine.iter().enumerate().find_map(|(a, c)| {
                    let c = two(c)?;
                    theirs.iter().enumerate().find_map(|(a2, d)| {
                        let d = two(d)?;
                        c.iter()
                            .all(|&c| {
                                d.iter()
                                    .all(|&d| study.crosses(k, (a, c), (a2, d)).is_some())
                            })
                            .then_some((c, d))
                    })
                })
            });
        let (c, d) = quadruple.expect("Fig 4.31 has a mutually crossing quadruple");
        assert!(CHECKER.run(&study).violations.is_empty());
        let after = (c[0] + 1) % map.n();
        let swapped = |e: usize| match e {
            e if e == d[0] => after,
            e if e == after => d[0],
            e => e,
        };
        let report = on_boundary(&study, &swapped);
        assert!(
            report
                .violations
                .iter()
                .any(|v| v.data["c"] == json!(c) && v.data["c_prime"] == json!(d)),
            "{:?}",
            report.violations
        );
    }

    #[test]
    fn planted_orders_are_reported() {
        assert!(check(20, [2, 5], [8, 11]).is_none());
        // Wrapping around the start of the boundary is still in order.
        assert!(check(20, [17, 19], [1, 4]).is_none());
        // Interleaved.
        assert!(check(20, [2, 8], [5, 11]).is_some());
        // c2' before c1'.
        assert!(check(20, [2, 5], [11, 8]).is_some());
    }
}
