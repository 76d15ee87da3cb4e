//! Planted bugs: checkers that are wrong on purpose, so that the
//! counterexample search (`wai check --plant`, the `claims_ch3` fuzz target
//! with `WAI_PLANT`) can be shown to find a violation and shrink it (issue
//! 11; STYLE.md 6: a search must be able to fail).
//!
//! A planted checker reports under a real claim's id, so the driver, the
//! shrinker and the replay treat it exactly like the real checker. It is
//! never in [`crate::CLAIMS`]: only a caller that names it runs it.

use wai_visibility::SkeletonKey;

use crate::check::Maker;
use crate::driver::{Checker, Report};
use crate::{sample, t3_2, Study};

/// A planted bug: its name, what it gets wrong, its checker's constructor.
#[derive(Debug, Clone, Copy)]
pub struct Planted {
    pub name: &'static str,
    pub what: &'static str,
    pub make: Maker,
}

/// Every planted bug.
pub const PLANTED: &[Planted] = &[Planted {
    name: "shifted-labels",
    what: "T3.2 fed a wrong skeleton key: the labels of V*_p shifted by one \
           edge, so V_p rebuilt from the key differs wherever V_p has a spurious edge",
    make: shifted_labels,
}];

/// The names of [`PLANTED`], for messages.
pub fn names() -> Vec<&'static str> {
    PLANTED.iter().map(|p| p.name).collect()
}

/// The constructor of planted bug `name`'s checker.
pub fn maker(name: &str) -> Option<Maker> {
    PLANTED.iter().find(|p| p.name == name).map(|p| p.make)
}

/// The checker of planted bug `name`.
pub fn checker(name: &str) -> Option<Box<dyn Checker>> {
    maker(name).map(|make| make())
}

/// `makers` (claim ids with checker constructors, as
/// [`crate::makers`] gives them) with `plant` in place of the real checker
/// of its claim; unchanged if `plant` is `None` or its claim is not among
/// them.
pub fn swap_in(
    makers: impl Iterator<Item = (&'static str, Maker)>,
    plant: Option<Maker>,
) -> impl Iterator<Item = (&'static str, Maker)> {
    let plant = plant.map(|make| (make().id(), make));
    makers.map(move |(id, make)| match plant {
        Some((pid, pmake)) if pid == id => (id, pmake),
        _ => (id, make),
    })
}

/// [`ShiftedLabels`], boxed.
pub fn shifted_labels() -> Box<dyn Checker> {
    Box::new(ShiftedLabels)
}

/// T3.2's rebuild (V_p from V*_p and p − v0) with the key's labels shifted
/// by one edge: a wrong key. Every sampled viewpoint is one instance.
#[derive(Debug, Clone, Copy, Default)]
pub struct ShiftedLabels;

fn shift_labels(mut key: SkeletonKey) -> SkeletonKey {
    key.labels.rotate_right(1);
    key
}

impl Checker for ShiftedLabels {
    fn id(&self) -> &'static str {
        "T3.2"
    }

    fn check_study(&self, study: &Study<'_>) -> Report {
        let mut report = Report::new(self.id());
        for vp in study.sampled_polygons(sample::VIEWPOINTS).iter() {
            report.absorb(t3_2::check_polygon_with_key(study.map(), vp, shift_labels));
        }
        report
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_planted_bug_shows_on_a_map_with_a_reflex_vertex_only() {
        let l = wai_gen::family("corridor-niches", &[1]).expect("family");
        let report = ShiftedLabels.check(&l);
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
        let report = ShiftedLabels.check(&square);
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
