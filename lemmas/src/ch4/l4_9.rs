//! Claim L4.9 (Lemma 4.9, Def 4.2): for two overlapping valid embeddings
//! with witnesses w, w', among the meeting pairs (h(a), h'(b)) of
//! artificial edges — each classified LR or RL, h(a) from w against h'(b)
//! and h'(b) from w' against h(a) — at most one is LR/LR, at most one is
//! RL/RL, and of the x LR/RL and y RL/LR pairs, min{x, y} ≤ 1.
//!
//! ## Trust
//! Exact over whole witness regions, on the overlapping pairs of
//! [`wai_study::Study::embedding_pairs`]: the tallies change only where w or
//! w' crosses the line of a meeting artificial edge, so each witness
//! region is cut by those lines ([`wai_embed::piece::part_points`]) and
//! every pair of parts, one of each region, is tested. A meeting pair that
//! a witness on a line leaves undecided (collinear common artificial
//! edges, type 2, always are) is left out of the tallies; count
//! `undecided`.
//!
//! ## Cases
//! Each instance (a pair of embeddings seen from one part of each witness
//! region) hits the intersection types of the proof it has (Fig 4.14's
//! rows): "LR/LR", "RL/RL", "LR/RL", "RL/LR", once each if present; and
//! "x ≥ 2" when one of the mixed counts exceeds one (the lemma allows it
//! for one of x and y only). Progress toward "x ≥ 2" is the larger mixed
//! count.

use serde_json::json;
use wai_embed::intersection::left_right;
use wai_embed::piece::part_points;
use wai_embed::SkeletonRing;
use wai_exact::QPoint;

use crate::framework::{Case, Checker, Report, Violation};
use rug::Rational;
use wai_study::Study;

const ID: &str = "L4.9";

/// The four intersection types, in the order of [`tallies`].
const TYPES: [&str; 4] = ["LR/LR", "RL/RL", "LR/RL", "RL/LR"];

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study).with_cases(&[
    Case {
        name: TYPES[0],
        what: "an LR-edge of h meeting an LR-edge of h' (Fig 4.14, first row; at most one)",
    },
    Case {
        name: TYPES[1],
        what: "an RL-edge meeting an RL-edge (last row; at most one)",
    },
    Case {
        name: TYPES[2],
        what: "an LR-edge of h meeting an RL-edge of h' (second row; x of them)",
    },
    Case {
        name: TYPES[3],
        what: "an RL-edge of h meeting an LR-edge of h' (third row; y of them)",
    },
    Case {
        name: "x ≥ 2",
        what: "more than one mixed intersection of one kind: max{x, y} ≥ 2, which the lemma allows for one of them",
    },
]);

/// Checks L4.9 on every overlapping pair and pair of witnesses.
fn check_study(study: &Study<'_>) -> Report {
    let rings = study.skeleton_rings();
    let mut report = Report::new(ID);
    for pair in study.embedding_pairs() {
        if !pair.overlap() {
            continue;
        }
        let (p, q) = (
            &rings[pair.first.0][pair.first.1],
            &rings[pair.second.0][pair.second.1],
        );
        let meeting = meeting_pairs(p, q);
        let lines = lines_of(p, q, &meeting);
        let ws = part_points(study.witness_pieces(pair.first.0, pair.first.1), &lines);
        let ws2 = part_points(study.witness_pieces(pair.second.0, pair.second.1), &lines);
        for w in &ws {
            for w2 in &ws2 {
                let mut r = check_meeting(p, q, &meeting, w, w2);
                r.tag("pair", || json!([pair.first, pair.second]));
                report.absorb(r);
            }
        }
    }
    report
}

/// The pairs (i, j) of an artificial edge of `p` and one of `q` that
/// meet ([`SkeletonRing::edges_meet`], as [`wai_embed::intersection::edges_meet`]).
pub fn meeting_pairs(p: &SkeletonRing, q: &SkeletonRing) -> Vec<(usize, usize)> {
    p.artificial_edges()
        .flat_map(|i| q.artificial_edges().map(move |j| (i, j)))
        .filter(|&(i, j)| p.edges_meet(i, q, j))
        .collect()
}

/// The lines of the artificial edges of `p` and `q` that meet one of the
/// other: the only lines across which a witness's tallies change.
pub fn meeting_lines(p: &SkeletonRing, q: &SkeletonRing) -> Vec<(QPoint, QPoint)> {
    lines_of(p, q, &meeting_pairs(p, q))
}

/// The lines of the edges of the `meeting` pairs.
fn lines_of(
    p: &SkeletonRing,
    q: &SkeletonRing,
    meeting: &[(usize, usize)],
) -> Vec<(QPoint, QPoint)> {
    let mut lines = Vec::new();
    for &(i, j) in meeting {
        for (x, y) in [p.edge(i), q.edge(j)] {
            lines.push((x.clone(), y.clone()));
        }
    }
    lines.sort();
    lines.dedup();
    lines
}

/// The tallies (LR/LR, RL/RL, LR/RL, RL/LR) of one pair and witnesses,
/// and how many meeting pairs were undecided.
pub fn tallies(p: &SkeletonRing, q: &SkeletonRing, w: &QPoint, w2: &QPoint) -> ([usize; 4], u64) {
    tallies_of(p, q, &meeting_pairs(p, q), w, w2)
}

/// [`tallies`] over the `meeting` pairs of [`meeting_pairs`].
fn tallies_of(
    p: &SkeletonRing,
    q: &SkeletonRing,
    meeting: &[(usize, usize)],
    w: &QPoint,
    w2: &QPoint,
) -> ([usize; 4], u64) {
    let mut t = [0; 4];
    let mut undecided = 0;
    for &(i, j) in meeting {
        match (
            left_right(w, p.edge(i), q.edge(j)),
            left_right(w2, q.edge(j), p.edge(i)),
        ) {
            (Some(true), Some(true)) => t[0] += 1,
            (Some(false), Some(false)) => t[1] += 1,
            (Some(true), Some(false)) => t[2] += 1,
            (Some(false), Some(true)) => t[3] += 1,
            _ => undecided += 1,
        }
    }
    (t, undecided)
}

/// One pair of embeddings from one pair of witnesses.
pub fn check(p: &SkeletonRing, q: &SkeletonRing, w: &QPoint, w2: &QPoint) -> Report {
    check_meeting(p, q, &meeting_pairs(p, q), w, w2)
}

/// [`check`] with the pairs of [`meeting_pairs`].
fn check_meeting(
    p: &SkeletonRing,
    q: &SkeletonRing,
    meeting: &[(usize, usize)],
    w: &QPoint,
    w2: &QPoint,
) -> Report {
    let mut report = Report::new(ID);
    let (t, undecided) = tallies_of(p, q, meeting, w, w2);
    report.count("undecided", undecided);
    for (k, name) in TYPES.iter().enumerate() {
        if t[k] > 0 {
            report.hit(name);
        }
    }
    let [lrlr, rlrl, x, y] = t;
    if x.max(y) >= 2 {
        report.hit("x ≥ 2");
    }
    report.progress_toward("x ≥ 2", Rational::from(x.max(y)));
    report.record((lrlr > 1 || rlrl > 1 || x.min(y) > 1).then(|| {
        Violation::with_data(
            format!(
                "from witnesses {w} and {w2}: {lrlr} LR/LR, {rlrl} RL/RL, {x} LR/RL and {y} RL/LR intersections"
            ),
            json!({ "lr_lr": lrlr, "rl_rl": rlrl, "lr_rl": x, "rl_lr": y }),
        )
    }));
    report
}

#[cfg(test)]
mod tests {
    use super::*;
    use wai_exact::Point;

    #[test]
    fn holds_on_repeated_niches() {
        crate::fixtures::holds_on(&CHECKER, wai_gen::repeated_niches, &[195, 12, 16]);
    }

    #[test]
    fn planted_two_lr_lr_are_reported() {
        // Two artificial edges of p, each crossed by one of q, every
        // crossing LR/LR from the witnesses chosen.
        let pts = |v: &[(i128, i128)]| v.iter().map(|&(x, y)| Point::new(x, y)).collect::<Vec<_>>();
        let p = SkeletonRing::new(&pts(&[(0, 0), (4, 0), (4, 4), (0, 4)]), vec![true; 4]);
        let q = SkeletonRing::new(&pts(&[(3, -1), (5, 1), (1, 5), (-1, 3)]), vec![true; 4]);
        let pt = |x: i64, y: i64| QPoint::new(rug::Rational::from(x), rug::Rational::from(y));
        let (t, _) = tallies(&p, &q, &pt(1, 1), &pt(2, 2));
        let report = check(&p, &q, &pt(1, 1), &pt(2, 2));
        assert_eq!(report.examined, 1);
        assert_eq!(
            report.violations.is_empty(),
            t[0] <= 1 && t[1] <= 1 && t[2].min(t[3]) <= 1
        );
        assert!(t.iter().sum::<usize>() >= 4, "{t:?}");
    }
}
