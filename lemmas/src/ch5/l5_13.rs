//! Claim L5.13 (Lemma 5.13): if map edges e and f are valid candidate
//! edges of different artificial edges in each of k ≥ 2 embeddings of one
//! skeleton, then one of those embeddings has an artificial edge that
//! every line of sight to e (from inside any of the k) crosses — the one
//! through which it sees e — and likewise one for f.
//!
//! ## Trust
//! Exact, on every class with a valid embedding and every pair {e, f} with
//! k ≥ 2 ([`wai_study::edge_pairs`]). The lines of sight are Def 4.4's from
//! the witness cells, one sight fan per cell ([`wai_embed::SightFan`]);
//! whether all lines of a fan meet a window is decided exactly when the
//! window is a chord of the map (its ends map vertices, nothing else of
//! the boundary on it: [`wai_embed::Chord`], by which part of the map the
//! witness cell and the candidate edge lie in), and otherwise by
//! [`wai_embed::SightFan::lines_meet_segment`], which proves it, refutes it
//! with a concrete line of sight, or leaves it open. For e (and f) the
//! candidate crossed edges are the k windows through which the embeddings
//! see it: e passes when one window is proved crossed by every fan that
//! sees e; e fails when every window is refuted. A pair is examined when
//! both e and f are decided; a pair left open is counted as `undecided`,
//! never as held. Counts: `windows_tried`, `undecided`.
//!
//! ## Cases
//! By k: two embeddings ([`K2`]) or more ([`K3`]); and, for a pair that
//! holds, whether the common windows of e and f are artificial edges of
//! one embedding, h_{j_l} = h_{j_r} ([`ONE_EMBEDDING`]), or of two
//! ([`TWO_EMBEDDINGS`], the leftmost and rightmost lines of sight of the
//! proof in different embeddings, Fig 5.13).

use serde_json::json;
use wai_embed::{Chord, SightFan};
use wai_exact::QPoint;

use crate::framework::{Case, Checker, Report, Violation};
use wai_study::Study;

const ID: &str = "L5.13";

/// A pair shared by two embeddings.
pub const K2: &str = "k=2";
/// A pair shared by three or more embeddings.
pub const K3: &str = "k≥3";
/// Both common windows in one embedding.
pub const ONE_EMBEDDING: &str = "one embedding";
/// The common windows in two different embeddings.
pub const TWO_EMBEDDINGS: &str = "two embeddings";

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study)
    .outer_ring_only("a chord between two map vertices cuts a map without holes in two (wai_embed::Chord); with holes it need not").with_cases(&[
    Case {
        name: K2,
        what: "map edges e, f candidate edges of different artificial edges in k = 2 embeddings",
    },
    Case {
        name: K3,
        what: "map edges e, f candidate edges of different artificial edges in k ≥ 3 embeddings",
    },
    Case {
        name: ONE_EMBEDDING,
        what: "a pair whose common windows h_{j_l}(a_l) (crossed by every line of sight to e) \
               and h_{j_r}(ã_r) (to f) belong to one embedding",
    },
    Case {
        name: TWO_EMBEDDINGS,
        what: "a pair whose common windows belong to two different embeddings h_{j_l} ≠ h_{j_r} \
               (Fig 5.13)",
    },
]);

/// The verdict on one edge of a pair.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Verdict {
    /// The window (by its position among those given) every fan crosses.
    Crossed(usize),
    /// Every window is missed by a line of sight of some fan.
    Refuted,
    Undecided,
}

/// Whether one of `windows` is met by every line of sight of every fan in
/// `fans` (each fan's lines to the one edge, from one embedding), on the
/// map with vertices `ring`: exactly when the window is a chord
/// ([`Chord`]), else by [`SightFan::lines_meet_segment`].
pub fn common_window(ring: &[QPoint], windows: &[(QPoint, QPoint)], fans: &[&SightFan]) -> Verdict {
    let mut refuted = 0;
    for (l, (a, b)) in windows.iter().enumerate() {
        let chord = Chord::new(ring, a, b);
        let mut all = Some(true);
        for f in fans {
            let verdict = match &chord {
                Some(c) => c.crossed_by(f),
                None => f.lines_meet_segment(a, b),
            };
            match verdict {
                Some(true) => {}
                Some(false) => {
                    all = Some(false);
                    break;
                }
                None => all = None,
            }
        }
        match all {
            Some(true) => return Verdict::Crossed(l),
            Some(false) => refuted += 1,
            None => {}
        }
    }
    if refuted == windows.len() {
        Verdict::Refuted
    } else {
        Verdict::Undecided
    }
}

/// Checks L5.13 on every class.
fn check_study(study: &Study<'_>) -> Report {
    let mut report = Report::new(ID);
    let ring: Vec<QPoint> = study
        .map()
        .vertices()
        .iter()
        .map(|&v| QPoint::from(v))
        .collect();
    for (class, c) in study.candidate_sets().iter().enumerate() {
        for ((e, f), shared) in study.edge_pairs()[class].iter() {
            if e > f || shared.len() < 2 {
                continue;
            }
            // For e (then f): by embedding, the fans that see it and the
            // window they look through, with the embedding's position j.
            let side = |edge: usize, i_of: &dyn Fn(usize) -> usize| {
                let mut windows = Vec::new();
                let mut owners = Vec::new();
                let mut fans: Vec<&SightFan> = Vec::new();
                for s in shared {
                    let h = c.embeddings[s.j];
                    let a = c.artificial[i_of(s.j)];
                    let seen: Vec<&SightFan> = study.fans_seeing(class, h, (a, edge)).collect();
                    if let Some(first) = seen.first() {
                        windows.push((first.v1.clone(), first.v2.clone()));
                        owners.push(s.j);
                    }
                    fans.extend(seen);
                }
                (windows, owners, fans)
            };
            let i_e = |j: usize| shared.iter().find(|s| s.j == j).expect("listed").i;
            let i_f = |j: usize| shared.iter().find(|s| s.j == j).expect("listed").i_tilde;
            let mut verdicts = Vec::new();
            let mut owner = Vec::new();
            for (edge, i_of) in [(e, &i_e as &dyn Fn(usize) -> usize), (f, &i_f)] {
                let (windows, owners, fans) = side(edge, i_of);
                report.count("windows_tried", windows.len() as u64);
                let verdict = common_window(&ring, &windows, &fans);
                if let Verdict::Crossed(l) = verdict {
                    owner.push(owners[l]);
                }
                verdicts.push((edge, verdict));
            }
            if verdicts.iter().any(|v| v.1 == Verdict::Undecided)
                && !verdicts.iter().any(|v| v.1 == Verdict::Refuted)
            {
                report.count("undecided", 1);
                continue;
            }
            let refuted: Vec<usize> = verdicts
                .iter()
                .filter(|v| v.1 == Verdict::Refuted)
                .map(|v| v.0)
                .collect();
            report.hit(if shared.len() == 2 { K2 } else { K3 });
            if let [l, r] = owner[..] {
                report.hit(if l == r {
                    ONE_EMBEDDING
                } else {
                    TWO_EMBEDDINGS
                });
            }
            report.record((!refuted.is_empty()).then(|| {
                Violation::with_data(
                    format!(
                        "map edges {e} and {f} in {} embeddings: no window of edge(s) {refuted:?} is crossed by every line of sight to it",
                        shared.len()
                    ),
                    json!({
                        "class": class,
                        "edges": [e, f],
                        "refuted": refuted,
                        "embeddings": shared.iter().map(|s| c.embeddings[s.j]).collect::<Vec<_>>(),
                    }),
                )
            }));
        }
    }
    report
}

#[cfg(test)]
mod tests {
    use super::*;
    use rug::Rational;
    use wai_embed::Piece;

    fn pt(x: i64, y: i64) -> QPoint {
        QPoint::new(Rational::from(x), Rational::from(y))
    }

    /// A witness square below a window (0,0)–(4,0), seeing the edge
    /// (100,10)–(-100,10) above it (the map edge runs right to left).
    fn fan() -> SightFan {
        let cell = Piece::Polygon(vec![pt(1, -3), pt(3, -3), pt(3, -1), pt(1, -1)]);
        SightFan::new(
            &cell,
            0,
            0,
            (pt(4, 0), pt(0, 0)),
            7,
            (pt(100, 10), pt(-100, 10)),
        )
    }

    #[test]
    fn windows_are_proved_refuted_or_left_open() {
        let f = fan();
        // Its own window, and a wide bar across the whole fan beyond it.
        assert_eq!(f.lines_meet_segment(&pt(0, 0), &pt(4, 0)), Some(true));
        assert_eq!(f.lines_meet_segment(&pt(-50, 5), &pt(50, 5)), Some(true));
        // A wide bar before the window, between it and the cell.
        let half = Rational::from((-1, 2));
        let bar = (
            QPoint::new((-50).into(), half.clone()),
            QPoint::new(50.into(), half),
        );
        assert_eq!(f.lines_meet_segment(&bar.0, &bar.1), Some(true));
        // A bar through the cell's middle: the lines from below it cross
        // it, those from above do not — left open or refuted, never proved.
        assert_ne!(f.lines_meet_segment(&pt(-50, -2), &pt(50, -2)), Some(true));
        // A short bar beside the fan: missed.
        assert_eq!(f.lines_meet_segment(&pt(20, 5), &pt(30, 5)), Some(false));
        let bars = [(pt(20, 5), pt(30, 5)), (pt(-50, 5), pt(50, 5))];
        // A map around the fan, with chords at y = 5 (between the cell and
        // the edge: crossed) and from (-110, -50) to (110, 5) (passing
        // below the cell: not crossed); the edge itself is no chord.
        let ring: Vec<QPoint> = [
            (-100, 10),
            (-110, 5),
            (-110, -50),
            (110, -50),
            (110, 5),
            (105, 6),
            (105, 8),
            (100, 10),
        ]
        .iter()
        .map(|&(x, y)| pt(x, y))
        .collect();
        let across = Chord::new(&ring, &ring[1], &ring[4]).expect("a chord");
        assert_eq!(across.crossed_by(&f), Some(true));
        let below = Chord::new(&ring, &ring[2], &ring[4]).expect("a chord");
        assert_eq!(below.crossed_by(&f), Some(false));
        assert!(Chord::new(&ring, &ring[7], &ring[0]).is_none());
        assert!(Chord::new(&ring, &ring[1], &pt(0, 0)).is_none());
        let w = [
            (ring[2].clone(), ring[4].clone()),
            (ring[1].clone(), ring[4].clone()),
        ];
        assert_eq!(common_window(&ring, &w, &[&f]), Verdict::Crossed(1));
        assert_eq!(common_window(&ring, &w[..1], &[&f]), Verdict::Refuted);
        // Not map vertices: no chord, so the hull tests decide.
        assert_eq!(common_window(&[], &bars, &[&f]), Verdict::Crossed(1));
        assert_eq!(common_window(&[], &bars[..1], &[&f]), Verdict::Refuted);
    }
}
