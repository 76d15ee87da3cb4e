//! Claim T4.2 (Theorem 4.2, the main theorem of chapter 4): two different
//! valid embeddings of the same skeleton whose embedded skeleton polygons
//! overlap have mutually invisible witnesses — no witness of one sees any
//! witness of the other.
//!
//! ## Trust
//! Exhaustive and exact over whole witness regions, not sampled points.
//! Every pair of valid embeddings of every skeleton is tested for interior
//! overlap of h(V◇) and h'(V◇) ([`wai_embed::interiors_overlap`], exact
//! and complete); the witness regions are the class's cells of every
//! dimension at each embedding's v0 (Def 4.1 with Lemma 3.5, which L3.5
//! checks); whether any point of one sees any point of the other is
//! decided by the search over lines of [`wai_embed::Sightlines`], complete
//! because visibility is open (see its doc). A "visible" verdict carries
//! two exact points re-checked by `wai_exact::sees`; on maps of at most
//! [`CROSS_CHECK_MAX_N`] vertices every verdict is also reached by the
//! second, independent method (cuts and sweeps from points), and a
//! disagreement is reported as a violation (of our code) — the counts
//! `cross-checked` and `visible` say how many.
//!
//! ## Cases
//! Each pair hits "kernels overlap" (Theorem 4.3's premise, proved first)
//! or "kernels apart" (only Theorem 4.2's, proved through Lemmas
//! 4.11–4.14). The proof then takes a line l parallel to the translation
//! t = h'(v0) − h(v0) through the inside of the intersection I that leaves
//! I, in direction t, through an artificial edge a of h, and in direction
//! −t through an artificial edge b' of h' (Lemma 4.14's point x); a' = a +
//! t and b = b' − t. [`proof_lines`] finds every such pair (a, b') exactly,
//! one line per open slab between the projections of I's vertices, and
//! each pair hits the case of the order on ∂M of the eight ends (sec. 4.3,
//! with the ∂M order for the angular one, as the proof of Theorem 4.2
//! does): "order 1" to "order 4" (case 4 the proof rules out when the
//! kernels overlap; Fig 4.28 is one when they only touch), each once a
//! pair; "other order" if lines exist but none has its ends in one of the
//! four orders (the proof would have a gap), or "no line l" (Lemma 4.14
//! says never).
//!
//! ## A finding: not every line l has one of the four orders
//! The proof of Theorem 4.2 reads the angular orders around x as orders
//! on ∂M, equal when x sees the eight ends (Remark 4.3). A line through a
//! common artificial edge of h and h' (type 2) can have its ends in
//! another ∂M order although their angular order around x is one of the
//! four (`wai_gen::bytes::map_from_seed(84)`: a1 comes after b2 on ∂M,
//! hidden from x behind a niche's wall). The proof needs one line only,
//! and every pair seen so far has one with a proper order; such lines are
//! counted as `lines of another order`.

use std::collections::BTreeSet;

use rug::Rational;
use serde_json::{json, Value};
use wai_embed::piece::{offsets_between, Piece};
use wai_embed::{Intersection, Mutual, Sightlines, Witnesses};
use wai_exact::QPoint;

use crate::framework::{Case, Checker, Report, Violation};
use wai_study::Study;
use wai_study::{Embedded, OverlappingPair};

const ID: &str = "T4.2";

/// The cases of the order on ∂M of the ends of a, a', b, b' (sec. 4.3),
/// and the line of Lemma 4.14 missing; shared with Theorem 4.3.
pub const ORDER_CASES: [Case; 7] = [
    Case {
        name: "order 1",
        what: "a1' ≺ a1 ≺ b1' ≺ b1 ≺ b2 ≺ b2' ≺ a2 ≺ a2' on ∂M (sec. 4.3, case 1, Fig 4.4)",
    },
    Case {
        name: "order 2",
        what: "a1' ≺ b1' ≼ a1 ≺ b1 ≺ b2 ≺ b2' ≺ a2 ≺ a2': the middle ends above l swapped or equal (case 2)",
    },
    Case {
        name: "order 3",
        what: "a1' ≺ a1 ≺ b1' ≺ b1 ≺ b2 ≺ a2 ≼ b2' ≺ a2': the middle ends below l swapped or equal (case 3)",
    },
    Case {
        name: "order 4",
        what: "both middle pairs swapped or equal (case 4, impossible when the kernels overlap; Fig 4.28 is one when they only touch)",
    },
    Case {
        name: "other order",
        what: "the eight ends in none of the four orders the proof derives",
    },
    Case {
        name: "no line l",
        what: "no line parallel to t through the intersection leaves it through an artificial edge of h one way and of h' the other (Lemma 4.14 says there always is one)",
    },
    Case {
        name: "ends on several rings",
        what: "a map with holes: the eight ends lie on more than one ring of ∂M, so the proof's order along ∂M does not exist (thesis sec. 6.4)",
    },
];

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study).with_cases(&[
    Case {
        name: "kernels overlap",
        what: "the embedded kernels overlap too (Theorem 4.3's premise)",
    },
    Case {
        name: "kernels apart",
        what: "the skeleton polygons overlap, the kernels do not (Theorem 4.2 beyond Theorem 4.3)",
    },
    ORDER_CASES[0],
    ORDER_CASES[1],
    ORDER_CASES[2],
    ORDER_CASES[3],
    ORDER_CASES[4],
    ORDER_CASES[5],
    ORDER_CASES[6],
]);

/// Maps up to this many vertices have every verdict cross-checked. The
/// whole corpus (`wai check --maps corpus`) is below it: there the cross-check
/// adds about 18 % to T4.2's time (87 s against 74 s, 66,634 pairs).
pub const CROSS_CHECK_MAX_N: usize = 1000;

/// Checks T4.2 on every overlapping pair of valid embeddings of a map.
fn check_study(study: &Study<'_>) -> Report {
    let cross = (study.map().n() <= CROSS_CHECK_MAX_N).then(|| study.sightlines());
    let mut report = Report::new(ID);
    for pair in study.overlapping_pairs() {
        report.absorb(check_pairs(
            ID,
            [pair].into_iter(),
            study.embeddings(),
            study.witnesses(),
            cross,
        ));
        report.hit(if pair.kernels_overlap {
            "kernels overlap"
        } else {
            "kernels apart"
        });
        hit_orders(&mut report, &proof_lines(study, pair, None));
    }
    report
}

/// Counts the order cases of one pair's lines: each of the four orders
/// some line shows, once; "other order" if lines exist but none shows
/// one of the four (the proof needs one line only); "no line l" if there
/// is none. Count `lines of another order`: lines whose ends are in none
/// of the four orders, on pairs with a line that is.
pub fn hit_orders(report: &mut Report, cases: &[&'static str]) {
    if cases.is_empty() {
        report.hit("no line l");
        return;
    }
    let proper: BTreeSet<&'static str> = cases
        .iter()
        .copied()
        .filter(|c| *c != "other order")
        .collect();
    if proper.is_empty() {
        report.hit("other order");
        return;
    }
    let others = cases.len() - cases.iter().filter(|c| proper.contains(*c)).count();
    if others > 0 {
        report.count("lines of another order", others as u64);
    }
    for case in proper {
        report.hit(case);
    }
}

/// The order cases (names of [`ORDER_CASES`]) of the lines l of the proof
/// for one overlapping pair, h its embedding `a`, h' its `b`, one per
/// pair (a, b') of artificial edges some line shows: one line per open
/// slab between the projections of the intersection's vertices on the
/// normal of t (restricted to offsets strictly inside `within` when
/// given), and on it every stretch inside the intersection that ends, in
/// direction t, on an artificial edge a of h and, in direction −t, on an
/// artificial edge b' of h'. Empty if there is none.
pub fn proof_lines(
    study: &Study<'_>,
    pair: &OverlappingPair,
    within: Option<(Rational, Rational)>,
) -> Vec<&'static str> {
    let all = &study.embeddings()[pair.class];
    let (h, h2) = (&all[pair.a].embedding, &all[pair.b].embedding);
    let map = study.map().vertices();
    let t = QPoint::from(map[h2.origin]).sub(&QPoint::from(map[h.origin]));
    let x = study
        .intersection(&study.embedding_pairs()[pair.pair])
        .expect("an overlapping pair has an intersection");
    let rings = study.skeleton_rings();
    let (p, q) = (&rings[pair.class][pair.a], &rings[pair.class][pair.b]);
    exits(x, &t, within, &|i| p.artificial[i], &|j| q.artificial[j])
        .into_iter()
        .map(|(i, j)| order_case(study.map(), &t, h, h2, i, j))
        .collect()
}

/// The pairs (i, j) of edges such that some line parallel to `t` (one per
/// open slab between the projections of `x`'s vertices on the normal of
/// `t`, within `within` if given) has a stretch inside `x` leaving it in
/// direction `t` through an edge on P's edge i (`on_p`, with `art_p(i)`)
/// and in direction −t through one on Q's edge j (`on_q`, `art_q(j)`).
pub fn exits(
    x: &Intersection,
    t: &QPoint,
    within: Option<(Rational, Rational)>,
    art_p: &dyn Fn(usize) -> bool,
    art_q: &dyn Fn(usize) -> bool,
) -> BTreeSet<(usize, usize)> {
    let n = t.perp();
    let edges: Vec<_> = x.cycles.iter().flatten().collect();
    let vertices: Vec<QPoint> = edges.iter().map(|e| e.from.clone()).collect();
    let proj: Vec<(Rational, Rational)> = edges
        .iter()
        .map(|e| (n.dot(&e.from), n.dot(&e.to)))
        .collect();
    let offsets = match within {
        Some((lo, hi)) => offsets_between(&vertices, &n, lo, hi),
        None => {
            let mut u: Vec<Rational> = proj.iter().map(|p| p.0.clone()).collect();
            u.sort();
            u.dedup();
            u.windows(2)
                .map(|w| Rational::from(&w[0] + &w[1]) / 2u32)
                .collect()
        }
    };
    let mut out = BTreeSet::new();
    for u in offsets {
        // Where the line n·P = u crosses each edge, as t·P.
        let mut hits: Vec<(Rational, usize)> = Vec::new();
        for (k, e) in edges.iter().enumerate() {
            let (a, b) = (&proj[k].0, &proj[k].1);
            if (*a < u) == (*b < u) {
                continue;
            }
            let lambda = Rational::from(&u - a) / Rational::from(b - a);
            let (ta, tb) = (t.dot(&e.from), t.dot(&e.to));
            hits.push((Rational::from(&tb - &ta) * lambda + ta, k));
        }
        hits.sort();
        // The line misses every vertex: crossings alternate, entering
        // first.
        for w in hits.chunks(2) {
            let [(_, enter), (_, leave)] = w else {
                continue;
            };
            let (enter, leave) = (edges[*enter], edges[*leave]);
            if let (Some(i), Some(j)) = (leave.on_p, enter.on_q) {
                if art_p(i) && art_q(j) {
                    out.insert((i, j));
                }
            }
        }
    }
    out
}

/// The case of the order on ∂M of the ends of a = h's skeleton edge `i`,
/// a' = h''s, b' = h''s edge `j`, b = h's, "above" meaning left of `t`.
/// On a map with holes the order is along the one ring that holds all
/// eight ends; ends on several rings have no such order.
fn order_case(
    whole: &wai_map::Map,
    t: &QPoint,
    h: &wai_embed::Embedding,
    h2: &wai_embed::Embedding,
    i: usize,
    j: usize,
) -> &'static str {
    let map = whole.vertices();
    let k = h.vertices.len();
    let ends = |e: &wai_embed::Embedding, s: usize| {
        let (u, v) = (e.vertices[s], e.vertices[(s + 1) % k]);
        // (above, below): the end left of t first.
        let left = t.cross(&QPoint::from(map[u]).sub(&QPoint::from(map[v]))) > 0;
        if left {
            (u, v)
        } else {
            (v, u)
        }
    };
    let (a1, a2) = ends(h, i);
    let (a1p, a2p) = ends(h2, i);
    let (b1, b2) = ends(h, j);
    let (b1p, b2p) = ends(h2, j);
    let ring = whole.ring_of(a1p);
    if [a1, a2, a2p, b1, b2, b1p, b2p]
        .iter()
        .any(|&v| whole.ring_of(v) != ring)
    {
        return "ends on several rings";
    }
    let on_ring = whole.ring_range(ring);
    let (base, n) = (on_ring.start, on_ring.len());
    let pos = |v: usize| (v - base + n - (a1p - base)) % n;
    let lt = |x: usize, y: usize| pos(x) < pos(y);
    let le = |x: usize, y: usize| pos(x) <= pos(y);
    // a1' ≺ ·, the ends above l before those below, and the outer ones.
    let frame = lt(a1p, a1)
        && lt(a1p, b1p)
        && lt(a1, b1)
        && lt(b1p, b1)
        && lt(b1, b2)
        && lt(b2, b2p)
        && lt(b2, a2)
        && lt(b2p, a2p)
        && lt(a2, a2p);
    if !frame {
        return "other order";
    }
    let above_swapped = le(b1p, a1);
    let below_swapped = le(a2, b2p);
    match (above_swapped, below_swapped) {
        (false, false) => "order 1",
        (true, false) => "order 2",
        (false, true) => "order 3",
        (true, true) => "order 4",
    }
}

/// The open range of projections on `n` of the common interior of two
/// convex regions (Theorem 4.3's kernels), if they overlap.
pub fn common_range(a: &[QPoint], b: &[QPoint], n: &QPoint) -> Option<(Rational, Rational)> {
    let mut left = Piece::Polygon(a.to_vec());
    for i in 0..b.len() {
        left = left.clip(&b[i], &b[(i + 1) % b.len()], std::cmp::Ordering::Greater)?;
    }
    let v = left.vertices();
    let p: Vec<Rational> = v.iter().map(|x| n.dot(x)).collect();
    let lo = p.iter().min()?.clone();
    let hi = p.iter().max()?.clone();
    (lo < hi).then_some((lo, hi))
}

/// The check proper, shared with T4.3 (which passes its own id and the
/// pairs whose kernels overlap): each pair's witnesses must not see each
/// other; with `cross`, each verdict is reached a second time by the
/// independent method and the two must agree.
pub fn check_pairs<'p>(
    id: &'static str,
    pairs: impl Iterator<Item = &'p OverlappingPair>,
    embeddings: &[Vec<Embedded>],
    witnesses: &[Vec<Witnesses>],
    cross: Option<&Sightlines<'_>>,
) -> Report {
    let mut report = Report::new(id);
    for pair in pairs {
        report.examined += 1;
        let ws = &witnesses[pair.class];
        let data = |extra: Value| {
            let h = &embeddings[pair.class];
            json!({
                "class": pair.class,
                "origins": [h[pair.a].embedding.origin, h[pair.b].embedding.origin],
                "witness_cells": [ws[pair.a].cells.len(), ws[pair.b].cells.len()],
                "kernels_overlap": pair.kernels_overlap,
                "detail": extra,
            })
        };
        if let Some(sl) = cross {
            report.count("cross-checked", 1);
            let second = sl.regions_by_points(&ws[pair.a].pieces(), &ws[pair.b].pieces());
            if second.is_visible() != pair.sight.is_visible() {
                report.violations.push(Violation::with_data(
                    format!(
                        "the two mutual-visibility methods disagree on embeddings {} and {} of skeleton {} (a bug in our code)",
                        pair.a, pair.b, pair.class
                    ),
                    data(json!({
                        "by_lines": describe(&pair.sight),
                        "by_points": describe(&second),
                    })),
                ));
                continue;
            }
        }
        if let Mutual::Visible { from, to } = &pair.sight {
            report.count("visible", 1);
            report.violations.push(Violation::with_data(
                format!(
                    "witness {from} of one embedding of skeleton {} sees witness {to} of an overlapping one",
                    pair.class
                ),
                data(json!({ "from": from.to_string(), "to": to.to_string() })),
            ));
        }
    }
    report
}

fn describe(m: &Mutual) -> Value {
    match m {
        Mutual::Visible { from, to } => json!({ "visible": [from.to_string(), to.to_string()] }),
        Mutual::Invisible { tested } => json!({ "invisible": { "sight_lines_tested": tested } }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use wai_embed::WitnessCell;

    #[test]
    fn holds_on_the_overlap_fan_and_every_verdict_is_cross_checked() {
        let map = wai_gen::family("overlap-fan", &[1]).unwrap();
        let study = Study::new(&map);
        let report = CHECKER.run(&study);
        assert!(report.examined > 0);
        assert_eq!(report.counts.get("cross-checked"), Some(&report.examined));
        assert!(report.violations.is_empty(), "{:?}", report.violations);
    }

    #[test]
    fn order_cases_need_one_proper_line() {
        let mut r = Report::new(ID);
        hit_orders(&mut r, &["other order", "order 2"]);
        hit_orders(&mut r, &["other order"]);
        hit_orders(&mut r, &[]);
        assert_eq!(r.cases["order 2"], 1);
        assert_eq!(r.cases["other order"], 1);
        assert_eq!(r.cases["no line l"], 1);
        assert_eq!(r.counts["lines of another order"], 1);
    }

    #[test]
    fn planted_visible_witnesses_are_reported() {
        // The overlap fan's first overlapping pair, with the second
        // embedding's witness region replaced by a cell the first region
        // sees: the checker must report it, with a certificate.
        let map = wai_gen::family("overlap-fan", &[1]).unwrap();
        let study = Study::new(&map);
        let pair = study.overlapping_pairs()[0].clone();
        let mut witnesses = study.witnesses().to_vec();
        let own = witnesses[pair.class][pair.a].cells[0].clone();
        let wai_embed::CellRef::Face(f) = own.cell else {
            panic!("the fan's witnesses are 2-cells")
        };
        // A 2-cell beside the first witness cell: the two see each other.
        let d = study.decomposition();
        let arr = d.arrangement();
        let beside = arr
            .face_half_edges(f)
            .into_iter()
            .map(|h| arr.half_edge(arr.half_edge(h).twin).face)
            .find(|&g| g != arr.outer_face())
            .expect("a witness cell has a neighbouring cell");
        let near = WitnessCell {
            cell: wai_embed::CellRef::Face(beside),
            piece: wai_embed::piece_of(d, wai_embed::CellRef::Face(beside)),
            point: d.representative(beside).clone(),
        };
        witnesses[pair.class][pair.b].cells = vec![near];
        let mut planted = pair.clone();
        planted.sight = study.sightlines().regions_by_lines(
            &witnesses[pair.class][pair.a].pieces(),
            &witnesses[pair.class][pair.b].pieces(),
        );
        // T4.3 reports the same computation under its own id.
        for id in [ID, "T4.3"] {
            let report = check_pairs(
                id,
                [&planted].into_iter(),
                study.embeddings(),
                &witnesses,
                Some(study.sightlines()),
            );
            assert_eq!(report.claim, id);
            assert_eq!(report.examined, 1);
            assert_eq!(report.violations.len(), 1, "{:?}", report.violations);
            assert!(report.violations[0].what.contains("sees witness"));
        }
    }
}
