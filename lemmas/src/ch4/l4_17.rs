//! Claim L4.17 (Lemma 4.17): within one embedding h, a line of sight from
//! inside h(V◇) through h(a) to a candidate edge of a and one through
//! h(a') to a candidate edge of a' ≠ a never meet outside h(V◇); so a map
//! edge is a candidate edge of at most one artificial edge of h.
//!
//! ## Trust
//! Two parts, each exact.
//! - **Lines of sight from the witnesses**, on every valid embedding: for
//!   each two (artificial edge, valid candidate edge) of h on different
//!   artificial edges (`examined`), whether a line of sight from a witness
//!   through one and one through the other meet behind them (outside
//!   h(V◇)). Such lines lie in the open hull of the artificial edge and
//!   its candidate edge, or on the open candidate edge; where those
//!   regions of the two are apart (`apart`) nothing can meet, and
//!   otherwise the sight fans ([`wai_embed::SightFan`]) of every witness
//!   cell that sees the one against every cell that sees the other
//!   (`fan_pairs` counts these cell pairs, pruned or not) are intersected
//!   exactly; a violation comes with two certified lines of sight and the
//!   point where they meet. The lemma speaks of lines from anywhere
//!   inside h(V◇); those from points that are not witnesses are not
//!   examined.
//! - **The corollary**, on every valid embedding: no map edge is a valid
//!   candidate edge (Def 4.1) of two artificial edges (counted as
//!   `embeddings`).
//!
//! ## A finding: the corollary fails for Def 3.11's candidate edges
//! Def 3.11 asks of a candidate edge only a point that both ends of h(a)
//! see. A map edge on the label line can meet that through one point, an
//! end of it that h(v) sees *along* the label line, over a niche's mouth
//! (h(v) the niche's other corner): no line of sight crosses h(a) to it,
//! so the lemma says nothing about it, yet it is a candidate of h(a), and
//! of another artificial edge with the same label line that sees it
//! properly. Such shared edges are counted as `shared_def_3_11`, not as
//! violations; `counterexamples/L4.17-shared-candidate-edge.json` keeps
//! one. Chapter 5 counts valid candidate edges (the sets C_{i,j}), which
//! the corollary covers.
//!
//! ## Cases
//! Each two (artificial edge, valid candidate edge) of one embedding hits
//! "regions apart" (the regions their lines of sight lie in are apart:
//! nothing to intersect) or "regions meet" (the sight fans were
//! intersected exactly); each valid embedding's corollary check hits
//! "corollary".

use serde_json::json;
use std::cell::OnceCell;
use wai_embed::piece::open_hulls_meet;
use wai_embed::{crossing, Piece, SightFan};
use wai_exact::{convex_hull, Point, QPoint};

use crate::framework::{Case, Checker, Report, Violation};
use wai_study::Study;

const ID: &str = "L4.17";

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study)
    .outer_ring_only("its sight fans (wai_embed::SightFan) take the boundary behind an artificial edge as one chain of one ring").with_cases(&[
    Case {
        name: "regions apart",
        what: "two (artificial edge, candidate edge) of one embedding whose lines of sight lie in regions that are apart (Fig 4.29 cannot arise)",
    },
    Case {
        name: "regions meet",
        what: "two such whose regions meet: every line of sight from a witness through one against every one through the other",
    },
    Case {
        name: "corollary",
        what: "a valid embedding whose valid candidate edges are checked to serve one artificial edge each",
    },
]);

/// Checks L4.17 on every embedding.
fn check_study(study: &Study<'_>) -> Report {
    let mut report = Report::new(ID);
    let map = study.map();
    let ring = map.vertices();
    for (class, hs) in study.embeddings().iter().enumerate() {
        for (i, h) in hs.iter().enumerate() {
            if check_candidates(&h.embedding.candidates).is_some() {
                report.count("shared_def_3_11", 1);
            }
            if !study.witnesses()[class][i].is_valid() {
                continue;
            }
            let tag = |mut v: Violation| {
                v.data["class"] = json!(class);
                v.data["embedding"] = json!(i);
                v
            };
            report.count("embeddings", 1);
            let valid = study.valid_candidates(class, i);
            report.hit("corollary");
            report.record(check_candidates(valid).map(tag));
            // The sight regions: (artificial edge, candidate edge), the
            // number of witness cells that see it, and the region its
            // lines of sight behind the artificial edge lie in.
            let views = &study.views()[class][i];
            let polygon = h.polygon();
            let k = polygon.len();
            let mut regions = Vec::new();
            for (a, edges) in valid.iter().enumerate() {
                for &c in edges {
                    let cells = views.iter().filter(|v| v[a] == Some(c)).count();
                    let corners = [polygon[a], polygon[(a + 1) % k], ring[c], ring[map.next(c)]];
                    regions.push(Region::new((a, c), cells, corners));
                }
            }
            for (x, r1) in regions.iter().enumerate() {
                for r2 in regions[x + 1..].iter().filter(|r| r.key.0 != r1.key.0) {
                    report.count("fan_pairs", (r1.cells * r2.cells) as u64);
                    if !r1.meets(r2) {
                        report.count("apart", 1);
                        report.hit("regions apart");
                        report.record(None);
                        continue;
                    }
                    report.hit("regions meet");
                    let found = study
                        .fans_seeing(class, i, r1.key)
                        .flat_map(|f| study.fans_seeing(class, i, r2.key).map(move |g| (f, g)))
                        .find_map(|(f, g)| violation(map, f, g));
                    report.record(found.map(tag));
                }
            }
        }
    }
    report
}

/// The region behind one (artificial edge, candidate edge) of an
/// embedding ([`behind`]), with the number of witness cells that see the
/// candidate edge through the artificial edge; its pieces built when a
/// box test first leaves the question open.
struct Region {
    key: (usize, usize),
    cells: usize,
    /// The window's ends, then the edge's (map vertices).
    corners: [Point; 4],
    /// The closed box around the corners: (min x, min y, max x, max y).
    bounds: [i128; 4],
    pieces: OnceCell<Vec<Piece>>,
}

impl Region {
    fn new(key: (usize, usize), cells: usize, corners: [Point; 4]) -> Region {
        let xs = corners.map(|p| p.x);
        let ys = corners.map(|p| p.y);
        let min = |v: [i128; 4]| v.into_iter().min().expect("four");
        let max = |v: [i128; 4]| v.into_iter().max().expect("four");
        Region {
            key,
            cells,
            corners,
            bounds: [min(xs), min(ys), max(xs), max(ys)],
            pieces: OnceCell::new(),
        }
    }

    fn pieces(&self) -> &[Piece] {
        self.pieces.get_or_init(|| {
            let [w0, w1, e0, e1] = self.corners.map(QPoint::from);
            behind(&(w0, w1), &(e0, e1))
        })
    }

    /// The region's pieces as the point sets whose open hulls they are:
    /// the edge, and the four corners if they span a polygon.
    fn point_sets(&self) -> Vec<&[Point]> {
        let c = &self.corners;
        let flat = [c[1], c[2], c[3]]
            .iter()
            .all(|&x| wai_exact::orientation(c[0], c[1], x) == wai_exact::Orientation::Collinear)
            && wai_exact::orientation(c[0], c[2], c[3]) == wai_exact::Orientation::Collinear;
        let mut out: Vec<&[Point]> = vec![&c[2..]];
        if !flat {
            out.push(c);
        }
        out
    }

    /// Whether the two regions share a point: boxes first, then the
    /// pieces exactly ([`open_hulls_meet`] on integers, or
    /// [`Piece::meets`]).
    fn meets(&self, o: &Region) -> bool {
        let (a, b) = (self.bounds, o.bounds);
        if a[2] < b[0] || b[2] < a[0] || a[3] < b[1] || b[3] < a[1] {
            return false;
        }
        let fast = self.point_sets().into_iter().try_fold(false, |any, x| {
            o.point_sets()
                .into_iter()
                .try_fold(any, |any, y| Some(any || open_hulls_meet(x, y)?))
        });
        fast.unwrap_or_else(|| meets(self.pieces(), o.pieces()))
    }
}

/// A region that holds every line of sight through the artificial edge
/// `window` to the map edge `edge` behind it, beyond the window: the open
/// hull of the two (B° and the region of a fan lie inside it) and the
/// open edge (where the seen intervals lie).
fn behind(window: &(QPoint, QPoint), edge: &(QPoint, QPoint)) -> Vec<Piece> {
    let hull = convex_hull(vec![
        window.0.clone(),
        window.1.clone(),
        edge.0.clone(),
        edge.1.clone(),
    ]);
    let mut out = vec![Piece::Segment(edge.0.clone(), edge.1.clone())];
    if hull.len() >= 3 {
        out.push(Piece::Polygon(hull));
    }
    out
}

fn meets(a: &[Piece], b: &[Piece]) -> bool {
    a.iter().any(|p| b.iter().any(|q| p.meets(q)))
}

/// The corollary on one embedding's (valid) candidate edges, by skeleton
/// edge.
pub fn check_candidates(candidates: &[Vec<usize>]) -> Option<Violation> {
    // (map edge, artificial edge), sorted: a map edge of two artificial
    // edges appears twice in a row.
    let mut owners: Vec<(usize, usize)> = candidates
        .iter()
        .enumerate()
        .flat_map(|(a, edges)| edges.iter().map(move |&e| (e, a)))
        .collect();
    owners.sort_unstable();
    let (e, a, b) = owners
        .windows(2)
        .find(|w| w[0].0 == w[1].0 && w[0].1 != w[1].1)
        .map(|w| (w[0].0, w[0].1, w[1].1))?;
    Some(Violation::with_data(
        format!(
            "map edge {e} is a candidate edge of artificial edges {a} and {b} of one embedding"
        ),
        json!({ "map_edge": e, "artificial_edges": [a, b] }),
    ))
}

/// Two fans of one embedding on different artificial edges: their lines
/// of sight meet behind the artificial edges (outside h(V◇)).
pub fn violation(map: &wai_map::Map, f: &SightFan, g: &SightFan) -> Option<Violation> {
    crossing(map, f, g, true).map(|x| {
        Violation::with_data(
            format!(
                "lines of sight through artificial edges {} and {} of one embedding meet at {} outside it",
                f.artificial, g.artificial, x.at
            ),
            json!({
                "artificial_edges": [f.artificial, g.artificial],
                "map_edges": [f.edge, g.edge],
                "at": x.at.to_string(),
                "first": [x.first.0.to_string(), x.first.1.to_string()],
                "second": [x.second.0.to_string(), x.second.1.to_string()],
            }),
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn holds_on_repeated_niches() {
        let mut report = Report::new(ID);
        for seed in [195, 114] {
            let map = wai_gen::repeated_niches(seed);
            report.absorb(CHECKER.run(&Study::new(&map)));
        }
        assert!(report.violations.is_empty(), "{:?}", report.violations);
        assert!(report.counts["fan_pairs"] > 0);
        assert!(report.examined > report.counts["apart"]);
    }

    #[test]
    fn regions_meet_as_their_pieces_do() {
        // The integer test of two regions against the rational pieces, on
        // every two regions of every valid embedding.
        let mut pairs = 0;
        for map in [
            wai_gen::repeated_niches(195),
            wai_gen::bottled_niches(0),
            wai_gen::bytes::map_from_seed(84),
        ] {
            let study = Study::new(&map);
            let ring = map.vertices();
            for (class, hs) in study.embeddings().iter().enumerate() {
                for (i, h) in hs.iter().enumerate() {
                    if !study.witnesses()[class][i].is_valid() {
                        continue;
                    }
                    let polygon = h.polygon();
                    let k = polygon.len();
                    let mut regions = Vec::new();
                    for (a, edges) in study.valid_candidates(class, i).iter().enumerate() {
                        for &c in edges {
                            let corners =
                                [polygon[a], polygon[(a + 1) % k], ring[c], ring[map.next(c)]];
                            regions.push(Region::new((a, c), 1, corners));
                        }
                    }
                    for r1 in &regions {
                        for r2 in &regions {
                            assert_eq!(r1.meets(r2), meets(r1.pieces(), r2.pieces()));
                            pairs += 1;
                        }
                    }
                }
            }
        }
        assert!(pairs > 1000, "{pairs}");
    }

    #[test]
    fn planted_shared_candidate_edge_is_reported() {
        assert!(check_candidates(&[vec![3], vec![], vec![5, 7]]).is_none());
        assert!(check_candidates(&[vec![3, 7], vec![], vec![5, 7]]).is_some());
    }
}
