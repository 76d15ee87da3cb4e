//! Claim E4.1 (Examples 4.1 and 4.2, Figs 4.1 and 4.2): two valid
//! embeddings of one skeleton can have overlapping skeleton polygons and
//! overlapping kernels — with artificial edges that meet only in map
//! vertices (Fig 4.1), or even strictly cross (Fig 4.2).
//!
//! ## Trust
//! Exact. Two stored figures, recognised by their vertices
//! ([`super::Figure`]): on `counterexamples/E4.1-fig-4-1-adjacent-funnels.json`
//! the viewpoints' skeleton must have an overlapping pair of valid
//! embeddings whose kernels overlap and whose artificial edges meet only
//! in shared map vertices (at least two on the same pair of vertices and
//! one on a single vertex, as in Fig 4.1); on
//! `counterexamples/E4.1-funnels-kernels-overlap.json` the same with an
//! artificial edge of one strictly crossing one of the other (Fig 4.2). A
//! figure that no longer shows its configuration is a violation (count
//! `figures`: stored figures checked). Elsewhere every overlapping pair
//! of [`wai_study::Study::overlapping_pairs`] is one instance, and the
//! cases count the configurations wherever they occur. Kernels overlap as
//! [`wai_embed::kernels_overlap`] decides (exact interiors); how the
//! artificial edges meet is read from the map vertices with the exact
//! integer predicates of [`wai_exact::classify_segments`].

use serde_json::json;
use wai_exact::{classify_segments, Segment, SegmentIntersection};
use wai_map::Map;
use wai_study::{OverlappingPair, Study};

use super::{figure, Figure};
use crate::framework::{Case, Checker, Report, Violation};

const ID: &str = "E4.1";

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study).with_cases(&[
    Case {
        name: "kernels overlap",
        what: "two valid embeddings of one skeleton whose skeleton polygons and kernels overlap (Example 4.1)",
    },
    Case {
        name: "vertices only",
        what: "kernels overlap and the artificial edges of the two meet only in shared map vertices, none crossing or touching another (Fig 4.1)",
    },
    Case {
        name: "strictly crossing",
        what: "kernels overlap and an artificial edge of one strictly crosses one of the other (Example 4.2, Fig 4.2)",
    },
]);

figure!(
    /// Fig 4.1: funnels that touch at one floor vertex.
    fig_4_1,
    "E4.1-fig-4-1-adjacent-funnels.json"
);
figure!(
    /// Fig 4.2: funnels whose embeddings' artificial edges strictly cross
    /// (`wai_gen::repeated_niches(195)`).
    fig_4_2,
    "E4.1-funnels-kernels-overlap.json"
);

/// How the artificial edges of two embeddings of one skeleton meet, over
/// all pairs (one of each): on the same two map vertices, on exactly one,
/// strictly crossing (interiors), touching otherwise (an end on the
/// other, or along a common line).
#[derive(Debug, Default, Clone, Copy, PartialEq, Eq)]
pub struct Relations {
    pub same_vertices: usize,
    pub one_vertex: usize,
    pub strictly_crossing: usize,
    pub touching: usize,
}

impl Relations {
    /// Fig 4.1's configuration: artificial edges meet, and only in
    /// shared map vertices.
    pub fn vertices_only(&self) -> bool {
        self.strictly_crossing == 0
            && self.touching == 0
            && self.same_vertices + self.one_vertex > 0
    }
}

/// The [`Relations`] of the artificial edges of embeddings `a` and `b`
/// (positions in the class's embeddings) of the skeleton of `class`.
pub fn relations(study: &Study<'_>, class: usize, a: usize, b: usize) -> Relations {
    let labels = &study.decomposition().skeletons()[class].labels;
    let all = &study.embeddings()[class];
    let (va, vb) = (&all[a].embedding.vertices, &all[b].embedding.vertices);
    relations_of(study.map(), labels.iter().map(Option::is_some), va, vb)
}

/// [`relations`] from the artificial flags of the skeleton edges and the
/// map vertices of the two embeddings.
pub fn relations_of(
    map: &Map,
    artificial: impl Iterator<Item = bool>,
    va: &[usize],
    vb: &[usize],
) -> Relations {
    let k = va.len();
    let art: Vec<usize> = artificial
        .enumerate()
        .filter_map(|(i, a)| a.then_some(i))
        .collect();
    let pts = map.vertices();
    let mut r = Relations::default();
    for &i in &art {
        let e = [va[i], va[(i + 1) % k]];
        for &j in &art {
            let f = [vb[j], vb[(j + 1) % k]];
            let shared = e.iter().filter(|x| f.contains(x)).count();
            let seg = |s: [usize; 2]| Segment::new(pts[s[0]], pts[s[1]]).expect("an edge");
            let meet = classify_segments(&seg(e), &seg(f));
            match (shared, meet) {
                (2, _) => r.same_vertices += 1,
                (1, SegmentIntersection::Overlap { .. }) => r.touching += 1,
                (1, _) => r.one_vertex += 1,
                (_, SegmentIntersection::Crossing) => r.strictly_crossing += 1,
                (_, SegmentIntersection::None) => {}
                _ => r.touching += 1,
            }
        }
    }
    r
}

/// Checks E4.1: the stored figures show their configurations; every
/// overlapping pair is counted by configuration.
fn check_study(study: &Study<'_>) -> Report {
    let mut report = Report::new(ID);
    let mut found = Vec::new();
    for pair in study.overlapping_pairs() {
        report.record(None);
        if !pair.kernels_overlap {
            continue;
        }
        report.hit("kernels overlap");
        let r = relations(study, pair.class, pair.a, pair.b);
        if r.vertices_only() {
            report.hit("vertices only");
        }
        if r.strictly_crossing > 0 {
            report.hit("strictly crossing");
        }
        found.push((pair, r));
    }
    for (fig, shows) in [
        (fig_4_1(), &fig_4_1_shown as &dyn Fn(&Relations) -> bool),
        (fig_4_2(), &|r: &Relations| r.strictly_crossing > 0),
    ] {
        if fig.is(study.map()) {
            report.count("figures", 1);
            report.record(check_figure(study, fig, &found, shows));
        }
    }
    report
}

/// Fig 4.1 as drawn: the northern artificial edges on the same pairs of
/// map vertices, the two down to the floor sharing the vertex between the
/// funnels, nothing crossing.
fn fig_4_1_shown(r: &Relations) -> bool {
    r.vertices_only() && r.same_vertices >= 2 && r.one_vertex >= 1
}

/// The stored figure `fig` on its own map: the viewpoints' skeleton has
/// an overlapping pair among `found` (pairs whose kernels overlap, with
/// their relations) that `shows` the figure's configuration.
pub fn check_figure(
    study: &Study<'_>,
    fig: &Figure,
    found: &[(&OverlappingPair, Relations)],
    shows: &dyn Fn(&Relations) -> bool,
) -> Option<Violation> {
    let class = fig.class(study);
    let shown = found
        .iter()
        .any(|(p, r)| Some(p.class) == class && shows(r));
    (!shown).then(|| {
        Violation::with_data(
            format!(
                "the stored figure {} no longer shows two valid embeddings of its viewpoints' skeleton with overlapping kernels and the artificial edges of its example",
                fig.file
            ),
            json!({ "file": fig.file, "class": class }),
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn both_figures_show_their_configurations() {
        for (fig, case) in [
            (fig_4_1(), "vertices only"),
            (fig_4_2(), "strictly crossing"),
        ] {
            let report = CHECKER.check_map(&fig.map);
            assert!(report.violations.is_empty(), "{:?}", report.violations);
            assert_eq!(report.counts["figures"], 1);
            assert!(report.cases["kernels overlap"] >= 1);
            assert!(report.cases.get(case).is_some_and(|&k| k >= 1), "{case}");
        }
    }

    #[test]
    fn other_maps_count_without_figures() {
        let map = wai_gen::family("overlap-fan", &[1]).unwrap();
        let report = CHECKER.check_map(&map);
        assert!(report.examined > 0);
        assert!(!report.counts.contains_key("figures"));
        assert!(report.violations.is_empty());
    }

    #[test]
    fn planted_figure_without_its_configuration_is_reported() {
        // Fig 4.2's map held to Fig 4.1's configuration: its artificial
        // edges cross, so it does not show it.
        let fig = fig_4_2();
        let study = Study::new(&fig.map);
        let found: Vec<(&OverlappingPair, Relations)> = study
            .overlapping_pairs()
            .iter()
            .filter(|p| p.kernels_overlap)
            .map(|p| (p, relations(&study, p.class, p.a, p.b)))
            .collect();
        assert!(check_figure(&study, fig, &found, &|r| r.strictly_crossing > 0).is_none());
        let v = check_figure(&study, fig, &found, &fig_4_1_shown).expect("not Fig 4.1");
        assert!(v.what.contains("no longer shows"));
    }
}
