//! Claim T4.19 (Theorem 4.19): let c1, c2 be valid candidate edges of an
//! artificial edge a in h, c1 before c2 on their directed line, and c' a
//! valid candidate edge of a' in an overlapping h' ≠ h that crosses both
//! (Def 4.4). Then c' does not lie between c1 and c2 on ∂M.
//!
//! ## Trust
//! Exact, on every triple (c1, c2 of one artificial edge of h, c' of h')
//! of valid candidate edges of every overlapping pair of valid
//! embeddings of one skeleton, both embeddings taking the role of h
//! (`examined`; `between` of them have c' between c1 and c2). The
//! crossings are decided by [`wai_study::Study::crosses`] over whole witness
//! regions for every triple (none for c' = c1 or c2, Def 4.4); `crosses_both`
//! counts the triples that meet the theorem's premise, and one of them
//! with c' between c1 and c2 is a violation.
//!
//! Reading: the candidate edges of one artificial edge face it, so on
//! the counter-clockwise boundary they all run the same way along their
//! line, which gives the line its direction; "c1 before c2" compares
//! their starts along it, and "between" is the boundary strictly after
//! c1 and before c2, counter-clockwise (the peak or niche separating
//! them, Fig 3.9).
//!
//! ## Cases
//! Each triple meeting the premise (c' crosses c1 and c2) hits a case of
//! the last part of the proof, on the artificial edge h'(a') of c' and its
//! ends x', y': "z' on h(a)" (one of them is an end of h(a), the proof's
//! first case), "z' beyond h(a)" (none is, and one lies strictly beyond
//! the line of h(a), on the side of its candidate edges: the second case),
//! or "z' short of h(a)" (neither: the proof's claim says this cannot
//! happen when c' lies between c1 and c2, and says nothing otherwise).

use serde_json::json;
use wai_exact::{Point, QPoint};

use crate::framework::{Case, Checker, Report, Violation};
use wai_study::Study;

const ID: &str = "T4.19";

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study)
    .outer_ring_only("its cases order candidate edges counter-clockwise along the boundary: one ring").with_cases(&[
    Case {
        name: "z' on h(a)",
        what: "c' crosses c1 and c2, and an end of its artificial edge h'(a') is an end of h(a) (the proof's first case, Fig 4.35)",
    },
    Case {
        name: "z' beyond h(a)",
        what: "c' crosses c1 and c2, and an end of h'(a') lies strictly beyond the line of h(a), on its candidate edges' side (the second case, Fig 4.34)",
    },
    Case {
        name: "z' short of h(a)",
        what: "c' crosses c1 and c2, and neither end of h'(a') is on h(a) or beyond its line",
    },
]);

/// The case of the proof of T4.19 for artificial edge `a` of embedding
/// `h` and `a2` of `h2` (class `class`): where the ends of h'(a') lie
/// with respect to h(a).
pub fn z_case(
    study: &Study<'_>,
    class: usize,
    (h, a): (usize, usize),
    (h2, a2): (usize, usize),
) -> &'static str {
    let all = &study.embeddings()[class];
    let (v, v2) = (&all[h].embedding.vertices, &all[h2].embedding.vertices);
    let k = v.len();
    let ends = [v[a], v[(a + 1) % k]];
    let ends2 = [v2[a2], v2[(a2 + 1) % k]];
    let map = study.map().vertices();
    if ends2.iter().any(|e| ends.contains(e)) {
        "z' on h(a)"
    } else if ends2.iter().any(|&e| {
        // h(V◇) is counter-clockwise: its inside lies left of h(a), the
        // candidate edges right of it.
        wai_exact::orientation(map[ends[0]], map[ends[1]], map[e])
            == wai_exact::Orientation::Clockwise
    }) {
        "z' beyond h(a)"
    } else {
        "z' short of h(a)"
    }
}

/// The valid candidate edges of each skeleton edge of embedding
/// `embedding` of class `class`, in the order of their directed line.
pub fn ordered_candidates(study: &Study<'_>, class: usize, embedding: usize) -> Vec<Vec<usize>> {
    let map = study.map().vertices();
    let mut v = study.valid_candidates(class, embedding).to_vec();
    for edges in &mut v {
        edges.sort_by(|&c1, &c2| {
            if c1 == c2 {
                std::cmp::Ordering::Equal
            } else if before(map, c1, c2) {
                std::cmp::Ordering::Less
            } else {
                std::cmp::Ordering::Greater
            }
        });
    }
    v
}

/// Def 4.4 on overlapping pair `pair`, with `h_first` telling whether
/// `x` belongs to the pair's first embedding (and `y` to the other).
pub fn crosses(
    study: &Study<'_>,
    pair: usize,
    h_first: bool,
    x: (usize, usize),
    y: (usize, usize),
) -> bool {
    if h_first {
        study.crosses(pair, x, y).is_some()
    } else {
        study.crosses(pair, y, x).is_some()
    }
}

/// Whether map edge `c1` starts before map edge `c2` along `c1`'s
/// direction (the two on one line).
pub fn before(map: &[Point], c1: usize, c2: usize) -> bool {
    let n = map.len();
    let at = |i: usize| QPoint::from(map[i]);
    let (s1, e1, s2) = (at(c1), at((c1 + 1) % n), at(c2));
    // Exact: coordinates may have up to MAX_COORD_BITS = 100 bits.
    s2.sub(&s1).dot(&e1.sub(&s1)) > 0
}

/// Whether edge `c` lies strictly after `c1` and before `c2` on the
/// counter-clockwise boundary of a map of `n` edges.
pub fn between(n: usize, c1: usize, c2: usize, c: usize) -> bool {
    let r = |x: usize| (x + n - c1) % n;
    c != c1 && r(c) < r(c2)
}

/// Checks T4.19 on every triple (c1, c2, c') of two overlapping valid
/// embeddings of one skeleton.
fn check_study(study: &Study<'_>) -> Report {
    on_boundary(study, &|e| e)
}

/// The check with `position` giving each map edge's place on the
/// counter-clockwise boundary (the identity for [`NotBetween`]; a test
/// moves one edge to plant a violation in a real configuration).
pub fn on_boundary(study: &Study<'_>, position: &dyn Fn(usize) -> usize) -> Report {
    let n = study.map().n();
    let at = |c1: usize, c2: usize, c: usize| (position(c1), position(c2), position(c));
    let mut report = Report::new(ID);
    for (k, p) in study.overlapping_pairs().iter().enumerate() {
        let (of_a, of_b) = (
            ordered_candidates(study, p.class, p.a),
            ordered_candidates(study, p.class, p.b),
        );
        for h_first in [true, false] {
            let (h, h2) = if h_first { (p.a, p.b) } else { (p.b, p.a) };
            let (mine, theirs) = if h_first {
                (&of_a, &of_b)
            } else {
                (&of_b, &of_a)
            };
            for (a, edges) in mine.iter().enumerate() {
                for (i, &c1) in edges.iter().enumerate() {
                    for &c2 in &edges[i + 1..] {
                        for (a2, others) in theirs.iter().enumerate() {
                            for &c in others {
                                let mut verdict = None;
                                let x = |c1| crosses(study, k, h_first, (a, c1), (a2, c));
                                let (q1, q2, q) = at(c1, c2, c);
                                if between(n, q1, q2, q) {
                                    report.count("between", 1);
                                }
                                if x(c1) && x(c2) {
                                    report.count("crosses_both", 1);
                                    report.hit(z_case(study, p.class, (h, a), (h2, a2)));
                                    verdict = check(n, q1, q2, q).map(|mut v| {
                                        v.data["c1"] = json!(c1);
                                        v.data["c2"] = json!(c2);
                                        v.data["c"] = json!(c);
                                        v.data["class"] = json!(p.class);
                                        v.data["embeddings"] = json!([h, h2]);
                                        v.data["artificial_edges"] = json!([a, a2]);
                                        v
                                    });
                                }
                                report.record(verdict);
                            }
                        }
                    }
                }
            }
        }
    }
    report
}

/// One triple: `c` (crossing both) is not between `c1` and `c2` (c1
/// first) on the boundary of a map of `n` edges.
pub fn check(n: usize, c1: usize, c2: usize, c: usize) -> Option<Violation> {
    between(n, c1, c2, c).then(|| {
        Violation::with_data(
            format!("candidate edge {c} crosses candidate edges {c1} and {c2} of one artificial edge and lies between them on the boundary"),
            json!({ "c1": c1, "c2": c2, "c": c }),
        )
    })
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
        // Fig 4.31's configuration: triples whose c' crosses c1 and c2.
        assert!(report.counts["crosses_both"] > 0);
        assert!(report.examined >= report.counts["crosses_both"]);
    }

    #[test]
    fn examines_nothing_without_two_valid_candidate_edges() {
        // No artificial edge of an overlapping pair on these maps has two
        // valid candidate edges (nor on 400 seeds of repeated_niches).
        for seed in [195, 114, 12] {
            let map = wai_gen::repeated_niches(seed);
            assert_eq!(CHECKER.run(&Study::new(&map)).examined, 0);
        }
    }

    #[test]
    fn an_edge_moved_between_two_crossed_edges_is_reported() {
        // Fig 4.31's map: find c1, c2 of h and c' of h' with c' crossing
        // both, then move c' on the boundary to the edge after c1 (the
        // spike between c1 and c2): the whole check must report it.
        let map = wai_gen::bottled_niches(0);
        let study = Study::new(&map);
        let n = map.n();
        let mut triple = None;
        'search: for (k, p) in study.overlapping_pairs().iter().enumerate() {
            let (mine, theirs) = (
                ordered_candidates(&study, p.class, p.a),
                ordered_candidates(&study, p.class, p.b),
            );
            for (a, edges) in mine.iter().enumerate() {
                for (i, &c1) in edges.iter().enumerate() {
                    for &c2 in &edges[i + 1..] {
                        for (a2, others) in theirs.iter().enumerate() {
                            for &c in others {
                                let x = |e| crosses(&study, k, true, (a, e), (a2, c));
                                if x(c1) && x(c2) && between(n, c1, c2, (c1 + 1) % n) {
                                    triple = Some((c1, c2, c));
                                    break 'search;
                                }
                            }
                        }
                    }
                }
            }
        }
        let (c1, c2, c) = triple.expect("Fig 4.31 has a crossing triple");
        assert!(CHECKER.run(&study).violations.is_empty());
        let spike = (c1 + 1) % n;
        let swapped = |e: usize| match e {
            e if e == c => spike,
            e if e == spike => c,
            e => e,
        };
        let report = on_boundary(&study, &swapped);
        assert!(
            report.violations.iter().any(|v| v.data["c"] == json!(c)
                && v.data["c1"] == json!(c1)
                && v.data["c2"] == json!(c2)),
            "{:?}",
            report.violations
        );
    }

    #[test]
    fn planted_edge_between_is_reported() {
        // 20 edges; c1 = 18, c2 = 2: the boundary between them is 19, 0, 1.
        assert!(check(20, 18, 2, 0).is_some());
        assert!(check(20, 18, 2, 19).is_some());
        assert!(check(20, 18, 2, 5).is_none());
        assert!(check(20, 18, 2, 2).is_none());
    }

    #[test]
    fn the_directed_line_orders_edges() {
        let map = [
            Point::new(0, 0),
            Point::new(2, 0),
            Point::new(3, 1),
            Point::new(5, 0),
            Point::new(8, 0),
            Point::new(8, 4),
        ];
        assert!(before(&map, 0, 3));
        assert!(!before(&map, 3, 0));
    }
}
