//! Claim R3.4 (Remark 3.4, Fig 3.10): an embedding of a skeleton may have
//! no witness, when the candidate edge of an artificial edge is shorter
//! than the artificial edge itself — every point that sees part of the
//! candidate edge sees both its ends, so no point has the skeleton there.
//!
//! An example claim: `counterexamples/R3.4-short-candidate.json` must show
//! the configuration, and the checker counts it on every map.
//!
//! ## Trust
//! Exact. On every map, every embedding of every class's skeleton
//! ([`wai_study::Study::embeddings`]: every map vertex tried as h(v0),
//! Def 3.11 exact) is sorted by its witness region (Def 4.1: the class's
//! cells of every dimension at its origin, [`wai_embed::witness_regions`])
//! and by the lengths of its artificial edges and their candidate edges
//! (squared Euclidean lengths, exact integers). The stored map is
//! recognised by its vertices (the file is compiled in); on it the checker
//! examines one instance, violated unless some embedding shows the
//! configuration. Other maps examine nothing and count the configuration
//! where it occurs.
//!
//! ## Cases
//! **short candidate** (an embedding without witness with an artificial
//! edge all of whose candidate edges are shorter than it: Remark 3.4's
//! configuration) and **no witness otherwise** (an embedding without
//! witness for another reason).

use std::sync::OnceLock;

use rug::Integer;
use serde_json::json;
use wai_exact::Point;
use wai_map::Map;
use wai_study::Study;

use crate::framework::{Case, Checker, Report, Violation};

const ID: &str = "R3.4";

/// The stored map of the remark's figure.
const STORED: &str = include_str!("../../../counterexamples/R3.4-short-candidate.json");

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study).with_cases(&[
    Case {
        name: SHORT,
        what: "an embedding without witness with an artificial edge whose candidate edges \
               are all shorter than it (Remark 3.4, Fig 3.10)",
    },
    Case {
        name: OTHER,
        what: "an embedding without witness for another reason (Def 4.1)",
    },
]);

/// Case: Remark 3.4's configuration.
pub const SHORT: &str = "short candidate";
/// Case: an embedding without witness otherwise.
pub const OTHER: &str = "no witness otherwise";

/// The vertices of the stored map.
fn stored_vertices() -> &'static [Point] {
    static VERTICES: OnceLock<Vec<Point>> = OnceLock::new();
    VERTICES.get_or_init(|| {
        wai_map::json::from_json(STORED.as_bytes())
            .expect("the stored figure is a valid map")
            .map
            .vertices()
            .to_vec()
    })
}

/// Whether `map` is the stored map of Fig 3.10.
pub fn is_stored_map(map: &Map) -> bool {
    map.vertices() == stored_vertices()
}

fn squared_length(a: Point, b: Point) -> Integer {
    let (dx, dy) = (Integer::from(b.x) - a.x, Integer::from(b.y) - a.y);
    Integer::from(&dx * &dx) + Integer::from(&dy * &dy)
}

/// The embeddings that show the configuration, as (class, index in
/// [`Study::embeddings`], artificial edge), and the number without witness
/// otherwise.
pub fn short_candidates(study: &Study<'_>) -> (Vec<(usize, usize, usize)>, usize) {
    let map = study.map();
    let v = map.vertices();
    let keys = study.decomposition().skeletons();
    let mut short = Vec::new();
    let mut other = 0;
    for (class, (hs, ws)) in study.embeddings().iter().zip(study.witnesses()).enumerate() {
        for (j, (h, w)) in hs.iter().zip(ws).enumerate() {
            if w.is_valid() {
                continue;
            }
            let h = &h.embedding;
            let k = h.vertices.len();
            let found = (0..k).find(|&i| {
                keys[class].labels[i].is_some() && {
                    let own = squared_length(v[h.vertices[i]], v[h.vertices[(i + 1) % k]]);
                    h.candidates[i]
                        .iter()
                        .all(|&e| squared_length(v[e], v[map.next(e)]) < own)
                }
            });
            match found {
                Some(i) => short.push((class, j, i)),
                None => other += 1,
            }
        }
    }
    (short, other)
}

/// Checks R3.4: counts the configuration, and on the stored map examines
/// whether it shows.
fn check_study(study: &Study<'_>) -> Report {
    let (short, other) = short_candidates(study);
    judge(is_stored_map(study.map()), &short, other)
}

/// The report on a map with `short` embeddings in the configuration and
/// `other` without witness otherwise; `stored`: the map is the stored
/// figure, which must show it.
fn judge(stored: bool, short: &[(usize, usize, usize)], other: usize) -> Report {
    let mut report = Report::new(ID);
    for _ in short {
        report.hit(SHORT);
    }
    for _ in 0..other {
        report.hit(OTHER);
    }
    if stored {
        report.record(short.is_empty().then(|| {
            Violation::with_data(
                "the stored map of Fig 3.10 has no embedding without witness whose candidate \
                 edge is shorter than its artificial edge",
                json!({"map": "R3.4-short-candidate.json", "without_witness": other}),
            )
        }));
    }
    report
}

#[cfg(test)]
mod tests {
    use super::*;

    fn stored() -> Map {
        wai_map::json::from_json(STORED.as_bytes()).unwrap().map
    }

    #[test]
    fn the_stored_map_shows_the_configuration() {
        let map = stored();
        let study = Study::new(&map);
        let r = CHECKER.run(&study);
        assert_eq!(
            (r.examined, r.violations.len()),
            (1, 0),
            "{:?}",
            r.violations
        );
        assert_eq!(r.cases.get(SHORT), Some(&1));
        // The embedding at the east niche, whose pillar's bottom is the
        // short candidate edge.
        let (short, _) = short_candidates(&study);
        let (class, j, _) = short[0];
        let h = &study.embeddings()[class][j].embedding;
        assert_eq!(map.vertices()[h.origin], Point::new(20, -4));
    }

    #[test]
    fn other_maps_are_counted_not_examined() {
        let map = wai_gen::family("corridor-niches", &[2]).unwrap();
        let r = CHECKER.run(&Study::new(&map));
        assert_eq!(r.examined, 0);
        assert!(r.violations.is_empty());
    }

    #[test]
    fn a_stored_map_without_the_configuration_is_reported() {
        // Widen the pillar's bottom from 2 to 8 units (x from 21..23 to
        // 18..26), longer than the artificial edge (4): the configuration
        // is gone, and judged as the stored map it is a violation.
        let moved: Vec<Point> = stored()
            .vertices()
            .iter()
            .map(|p| match (p.x, p.y) {
                (23, y) => Point::new(26, y),
                (21, y) => Point::new(18, y),
                _ => *p,
            })
            .collect();
        let wide = Map::from_ring(moved).unwrap().0;
        assert!(!is_stored_map(&wide));
        let (short, other) = short_candidates(&Study::new(&wide));
        assert!(short.is_empty());
        let r = judge(true, &short, other);
        assert_eq!((r.examined, r.violations.len()), (1, 1));
    }
}
