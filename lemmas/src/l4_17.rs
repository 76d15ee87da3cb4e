//! Claim L4.17 (Lemma 4.17): within one embedding h, a line of sight from
//! inside h(V◇) through h(a) to a candidate edge of a and one through
//! h(a') to a candidate edge of a' ≠ a never meet outside h(V◇); so a map
//! edge is a candidate edge of at most one artificial edge of h.
//!
//! ## Trust
//! Two parts, each exact.
//! - **Lines of sight from the witnesses**, on every valid embedding: for
//!   each two sight fans ([`wai_embed::SightFan`]) of h on different
//!   artificial edges, whether their parts behind the artificial edges
//!   (all of the fan that lies outside h(V◇)) share a point, decided
//!   exactly over whole witness cells; a violation comes with two
//!   certified lines of sight and the point where they meet. The lemma
//!   speaks of lines from anywhere inside h(V◇); those from points that
//!   are not witnesses are not examined (counted as `fan_pairs`).
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

use serde_json::json;
use wai_embed::{crossing, valid_from_views, SightFan};

use crate::driver::{Checker, Report, Violation};
use crate::Study;

const ID: &str = "L4.17";

/// Checks L4.17 on every embedding.
#[derive(Debug, Clone, Copy, Default)]
pub struct OwnArtificialEdge;

/// The registry's constructor.
pub fn checker() -> Box<dyn Checker> {
    Box::new(OwnArtificialEdge)
}

impl Checker for OwnArtificialEdge {
    fn id(&self) -> &'static str {
        ID
    }

    fn check_study(&self, study: &Study<'_>) -> Report {
        let mut report = Report::new(ID);
        let ring = study.map().vertices();
        for (class, hs) in study.embeddings().iter().enumerate() {
            for (i, h) in hs.iter().enumerate() {
                if check_candidates(&h.embedding.candidates).is_some() {
                    report.count("shared_def_3_11", 1);
                }
                if !study.witnesses()[class][i].is_valid() {
                    continue;
                }
                report.count("embeddings", 1);
                let tag = |mut v: Violation| {
                    v.data["class"] = json!(class);
                    v.data["embedding"] = json!(i);
                    v
                };
                let k = h.embedding.vertices.len();
                let valid = valid_from_views(k, &study.views()[class][i]);
                report.record(check_candidates(&valid).map(tag));
                let fans = &study.fans()[class][i];
                let before = report.examined;
                for v in check_fans(ring, fans) {
                    report.record(v.map(tag));
                }
                report.count("fan_pairs", report.examined - before);
            }
        }
        report
    }
}

/// The corollary on one embedding's (valid) candidate edges, by skeleton
/// edge.
pub fn check_candidates(candidates: &[Vec<usize>]) -> Option<Violation> {
    for (a, ea) in candidates.iter().enumerate() {
        for (b, eb) in candidates.iter().enumerate().skip(a + 1) {
            if let Some(e) = ea.iter().find(|e| eb.contains(e)) {
                return Some(Violation::with_data(
                    format!("map edge {e} is a candidate edge of artificial edges {a} and {b} of one embedding"),
                    json!({ "map_edge": e, "artificial_edges": [a, b] }),
                ));
            }
        }
    }
    None
}

/// Every pair of fans of one embedding on different artificial edges:
/// `None` for a pair whose lines of sight do not meet behind them.
pub fn check_fans<'f>(
    ring: &'f [wai_exact::Point],
    fans: &'f [SightFan],
) -> impl Iterator<Item = Option<Violation>> + 'f {
    fans.iter().enumerate().flat_map(move |(k, f)| {
        fans[k + 1..]
            .iter()
            .filter(move |g| g.artificial != f.artificial)
            .map(move |g| {
                crossing(ring, f, g, true).map(|x| {
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
            })
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
            report.absorb(OwnArtificialEdge.check_study(&Study::new(&map)));
        }
        assert!(report.violations.is_empty(), "{:?}", report.violations);
        assert!(report.counts["fan_pairs"] > 0);
    }

    #[test]
    fn planted_shared_candidate_edge_is_reported() {
        assert!(check_candidates(&[vec![3], vec![], vec![5, 7]]).is_none());
        assert!(check_candidates(&[vec![3, 7], vec![], vec![5, 7]]).is_some());
    }
}
