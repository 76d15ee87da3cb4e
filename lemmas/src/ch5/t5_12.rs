//! Claim T5.12 (Theorem 5.12): a skeleton has O(r) multiple candidate
//! edges (Def 5.4). Measured: the ratio max |C_mult| / r over the classes
//! of every map.
//!
//! The thesis proves it under Assumption 5.10 (sec. 5.4.4); the ratio is
//! measured on every map regardless.
//!
//! ## Cases
//! Per class with a multiple candidate edge, which parts of Assumption
//! 5.10 hold ([`wai_study::GapStructure`]): all three ([`ASSUMED`], Lemma
//! 5.11 applies as it stands), or each part that fails — (1) two valid
//! embeddings overlap ([`OVERLAPPING`]), (2) an interweavement has two
//! parallel lines l_i ([`PARALLEL`]: the lines of its (embedding,
//! artificial edge) pairs, those of their candidate edges), (3) two gaps
//! are nested ([`NESTED`]) — the reductions the thesis argues after the
//! lemma.
//!
//! ## Trust
//! Exact counts: C_{i,j} from the witness views of [`wai_study::Study`] over
//! the valid embeddings of each class's skeleton. A bound is never
//! decided by one map ([`Report::hold_to`]): a ratio above the ceiling
//! is reported as a map worth a look.

use serde_json::json;
use wai_embed::CandidateSets;
use wai_study::{GapStructure, Study};

use crate::framework::{over, Case, Ceiling, Checker, Report};

const ID: &str = "T5.12";

/// Assumption 5.10 holds: no overlap, no parallel lines, no nesting.
pub const ASSUMED: &str = "assumption holds";
/// Assumption 5.10 (1) fails: overlapping valid embeddings.
pub const OVERLAPPING: &str = "overlapping embeddings";
/// Assumption 5.10 (2) fails: parallel lines in an interweavement.
pub const PARALLEL: &str = "parallel lines";
/// Assumption 5.10 (3) fails: nested gaps.
pub const NESTED: &str = "nested gaps";

const CASES: &[Case] = &[
    Case {
        name: ASSUMED,
        what: "a skeleton with multiple candidate edges that meets all of Assumption 5.10: no \
               overlapping embeddings, no parallel lines l_i in an interweavement, no nested \
               gaps (Lemma 5.11 as stated)",
    },
    Case {
        name: OVERLAPPING,
        what: "a skeleton with multiple candidate edges and two overlapping valid embeddings \
               (Assumption 5.10 (1) fails: the virtual embedding of Fig 5.10)",
    },
    Case {
        name: PARALLEL,
        what: "a skeleton with an interweavement (Def 5.8) two of whose lines h_j(l_i) are \
               parallel (Assumption 5.10 (2) fails: the shift of Fig 5.11)",
    },
    Case {
        name: NESTED,
        what: "a skeleton with two nested gaps (Def 5.6; Assumption 5.10 (3) fails: \
               Fig 5.12)",
    },
];

/// The checker. The ceiling is far above every ratio seen: 1/2 (2
/// multiple candidate edges, r = 4, on `convex-niches` k = 1) over 1,501
/// maps — the stress corpus (901) and 300 each of `bottled_niches` and
/// `repeated_niches`, whose overlapping embeddings have several valid
/// candidate edges per artificial edge — and 4/5 (n = 15, r = 5) found by
/// a 10-minute `wai search-extremes --ratio cmult`
/// (`counterexamples/T5.12-extreme-*`).
pub const CHECKER: Checker = Checker::new(ID, check_study)
    .outer_ring_only("gap chains run along the boundary from one candidate edge to the next (Def 5.4): boundary order on one ring")
    .with_cases(CASES)
    .with_ceiling(Ceiling(4, 1));

/// max |C_mult| / r against the ceiling, and the parts of Assumption 5.10
/// by class.
fn check_study(study: &Study<'_>) -> Report {
    let sets = study.candidate_sets();
    let mut report = check_classes(&CHECKER, study.map(), sets);
    for (c, g) in sets.iter().zip(study.gap_structures()) {
        if !c.multiple.is_empty() {
            for case in assumption_cases(study.map(), c, g) {
                report.hit(case);
            }
        }
    }
    report
}

/// The cases of Assumption 5.10 on one class: [`ASSUMED`], or the parts
/// that fail.
pub fn assumption_cases(
    map: &wai_map::Map,
    c: &CandidateSets,
    g: &GapStructure,
) -> Vec<&'static str> {
    let mut out = Vec::new();
    if !g.overlapping.is_empty() {
        out.push(OVERLAPPING);
    }
    if g.graph
        .interweave_classes
        .iter()
        .any(|class| has_parallel_lines(map, c, class))
    {
        out.push(PARALLEL);
    }
    if g.related.iter().any(|r| r.2.is_nested()) {
        out.push(NESTED);
    }
    if out.is_empty() {
        out.push(ASSUMED);
    }
    out
}

/// Whether two of the lines h_j(l_i) of the (embedding, artificial edge)
/// pairs of one interweavement are parallel (or the same): each line is
/// that of the candidate edges of C_{i,j}, compared by the cross product
/// of the edges' directions.
pub fn has_parallel_lines(map: &wai_map::Map, c: &CandidateSets, class: &[(usize, usize)]) -> bool {
    let v = map.vertices();
    let dirs: Vec<(i128, i128)> = class
        .iter()
        .filter_map(|&(j, i)| c.sets[j][i].first())
        .map(|&e| {
            let (a, b) = (v[e], v[map.next(e)]);
            (b.x - a.x, b.y - a.y)
        })
        .collect();
    (0..dirs.len()).any(|a| {
        (a + 1..dirs.len()).any(|b| {
            let cross = rug::Integer::from(dirs[a].0) * dirs[b].1
                - rug::Integer::from(dirs[a].1) * dirs[b].0;
            cross == 0
        })
    })
}

/// The check on the candidate sets of every class, by `checker` (this
/// claim's, or one with a planted ceiling): the ratio max |C_mult| / r
/// (r at least 1), and the largest |C_mult| as a count.
pub fn check_classes(checker: &Checker, map: &wai_map::Map, classes: &[CandidateSets]) -> Report {
    let (class, mult) = classes
        .iter()
        .enumerate()
        .map(|(k, c)| (k, c.multiple.len()))
        .max_by_key(|&(k, m)| (m, std::cmp::Reverse(k)))
        .unwrap_or((0, 0));
    let mut report = checker.bound_report(Some((
        over(mult, map.r() as u128),
        json!({"class": class, "multiple": mult, "r": map.r()}),
    )));
    report.count("largest_multiple", mult as u64);
    report
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn measures_on_a_map_with_multiple_candidate_edges() {
        let map = wai_gen::family("convex-niches", &[3]).unwrap();
        let study = Study::new(&map);
        let report = check_classes(&CHECKER, &map, study.candidate_sets());
        assert_eq!((report.examined, report.violations.len()), (1, 0));
        let ratio = report.largest.expect("a ratio").ratio;
        assert!(ratio > 0, "the layout has multiple candidate edges");
        let report = CHECKER.run(&study);
        assert!(
            !report.cases.is_empty(),
            "a class with C_mult has its cases"
        );
    }

    #[test]
    fn the_parts_of_the_assumption() {
        use wai_embed::GapChain;
        let hexagon = wai_map::Map::from_ring(
            [(0, 0), (4, 0), (6, 2), (4, 4), (0, 4), (-2, 2)]
                .iter()
                .map(|&(x, y)| wai_exact::Point::new(x, y))
                .collect(),
        )
        .unwrap()
        .0;
        // Edges 0 ((0,0)→(4,0)) and 3 ((4,4)→(0,4)) are parallel, edge 1
        // is not.
        let parallel =
            CandidateSets::from_sets(vec![0], vec![0, 1], vec![vec![vec![0]], vec![vec![3]]]);
        let crossing =
            CandidateSets::from_sets(vec![0], vec![0, 1], vec![vec![vec![0]], vec![vec![1]]]);
        let class = [(0, 0), (1, 0)];
        assert!(has_parallel_lines(&hexagon, &parallel, &class));
        assert!(!has_parallel_lines(&hexagon, &crossing, &class));
        // Gaps (0, 2) of h_0 and (1, 4) of h_1 interweave.
        let chains = vec![GapChain::new(0, 2, 0, 0, 6), GapChain::new(1, 4, 1, 0, 6)];
        let g = GapStructure::new(chains, vec![], 2);
        assert_eq!(g.graph.interweave_classes, vec![vec![(0, 0), (1, 0)]]);
        assert_eq!(assumption_cases(&hexagon, &parallel, &g), vec![PARALLEL]);
        assert_eq!(assumption_cases(&hexagon, &crossing, &g), vec![ASSUMED]);
        let nested = vec![GapChain::new(0, 4, 0, 0, 6), GapChain::new(1, 3, 1, 0, 6)];
        let g = GapStructure::new(nested, vec![(0, 1)], 2);
        assert_eq!(
            assumption_cases(&hexagon, &crossing, &g),
            vec![OVERLAPPING, NESTED]
        );
    }

    #[test]
    fn planted_excess_is_reported() {
        // 2r + 1 multiple candidate edges on a map with r reflex vertices,
        // against a ceiling of 2.
        let map = wai_gen::family("corridor-niches", &[1]).unwrap();
        let edges: Vec<usize> = (0..=2 * map.r()).collect();
        let c = CandidateSets::from_sets(vec![0], vec![0], vec![vec![edges]]);
        let planted = CHECKER.with_ceiling(Ceiling(2, 1));
        let report = planted.judge(check_classes(&planted, &map, &[c]));
        assert_eq!(report.violations.len(), 1);
        assert!(report.largest.expect("a ratio").ratio > 2);
    }
}
