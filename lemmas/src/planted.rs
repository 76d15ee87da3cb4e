//! Planted bugs: checkers that are wrong on purpose, so that the
//! counterexample search (`wai check --plant`, the `claims_ch3` fuzz target
//! with `WAI_PLANT`) can be shown to find a violation and shrink it
//! (a search must be able to fail).
//!
//! A planted checker reports under a real claim's id, so the driver, the
//! shrinker and the replay treat it exactly like the real checker. It is
//! never in [`crate::CLAIMS`]: only a caller that names it runs it.

use wai_study::{sample, Study};
use wai_visibility::SkeletonKey;

use crate::ch3::t3_2;
use crate::framework::{Checker, Report};

/// A planted bug: its name, what it gets wrong, and its checker.
#[derive(Debug, Clone, Copy)]
pub struct Planted {
    pub name: &'static str,
    pub what: &'static str,
    pub checker: Checker,
}

/// Every planted bug.
pub const PLANTED: &[Planted] = &[
    Planted {
        name: "shifted-labels",
        what: "T3.2 fed a wrong skeleton key: the labels of V*_p shifted by one \
               edge, so V_p rebuilt from the key differs wherever V_p has a spurious edge",
        checker: SHIFTED_LABELS,
    },
    Planted {
        name: "panics",
        what: "T3.2's checker panics on every map with two or more reflex vertices \
               (a checker bug): the search must catch it, store the map and go on",
        checker: PANICS,
    },
];

/// The names of [`PLANTED`], for messages.
pub fn names() -> Vec<&'static str> {
    PLANTED.iter().map(|p| p.name).collect()
}

/// The checker of planted bug `name`.
pub fn checker(name: &str) -> Option<Checker> {
    PLANTED.iter().find(|p| p.name == name).map(|p| p.checker)
}

/// `checkers` with `plant` in place of the real checker of its claim;
/// unchanged if `plant` is `None` or its claim is not among them.
pub fn swap_in(
    checkers: impl Iterator<Item = Checker>,
    plant: Option<Checker>,
) -> impl Iterator<Item = Checker> {
    checkers.map(move |c| match plant {
        Some(p) if p.id == c.id => p,
        _ => c,
    })
}

/// T3.2's rebuild (V_p from V*_p and p − v0) with the key's labels shifted
/// by one edge: a wrong key. Every sampled viewpoint is one instance.
pub const SHIFTED_LABELS: Checker = Checker::new("T3.2", shifted_labels);

fn shift_labels(mut key: SkeletonKey) -> SkeletonKey {
    key.labels.rotate_right(1);
    key
}

fn shifted_labels(study: &Study<'_>) -> Report {
    let mut report = Report::new("T3.2");
    for vp in study.sampled_polygons(sample::VIEWPOINTS).iter() {
        report.absorb(t3_2::check_polygon_with_key(study.map(), vp, shift_labels));
    }
    report
}

/// A checker bug on purpose: T3.2's checker that panics on every map with
/// r ≥ 2, and checks nothing on the others.
pub const PANICS: Checker = Checker::new("T3.2", |study| {
    let r = study.map().r();
    assert!(r < 2, "planted panic: a map with {r} reflex vertices");
    Report::new("T3.2")
});

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_planted_bug_shows_on_a_map_with_a_reflex_vertex_only() {
        let l = wai_gen::family("corridor-niches", &[1]).expect("family");
        let report = SHIFTED_LABELS.check_map(&l);
        assert!(report.examined > 0);
        assert!(!report.violations.is_empty(), "{report:?}");
        let square = wai_map::Map::from_ring(
            [(0, 0), (4, 0), (4, 4), (0, 4)]
                .iter()
                .map(|&(x, y)| wai_exact::Point::new(x, y))
                .collect(),
        )
        .expect("square")
        .0;
        let report = SHIFTED_LABELS.check_map(&square);
        assert!(report.examined > 0 && report.violations.is_empty());
    }

    #[test]
    fn every_planted_name_has_a_checker() {
        for p in PLANTED {
            assert!(checker(p.name).is_some(), "{}", p.name);
        }
        assert!(checker("nope").is_none());
    }
}
