//! Claim C5.18 (Corollary 5.18): preprocessing a map by Algorithm 3.14
//! costs O(N(n + r²)) time and space, N the total complexity of the cells
//! (Thm 3.9). Measured: the ratio S / (N(n + r²)) on every map, S the size
//! of the structure the preprocessing builds.
//!
//! # What S is
//! The space of Alg 3.14 is dominated by steps 17–26, one overlay of the
//! cells of each class with its point-location structure: the thesis
//! bounds it by Σ_{V*} |EC_{V*}|² (eq. 3.2, an arrangement of |EC| segments
//! and a point location linear in it), and Theorem 5.17's |EC| = O(n + r²)
//! turns that into O(N(n + r²)). The earlier steps (rays, arrangement,
//! skeletons written down, the search trees) take O(nN), within the bound.
//! This workspace's overlay (`wai_localize::ClassOverlay`) locates points
//! with slabs: the plane cut at the x of every cell vertex and every
//! crossing of two cell edges, each slab cut by the edges spanning it into
//! trapezoids. S is the number of trapezoids over all classes
//! (`Localizer::trapezoids`): the subdivision the point location searches,
//! of which the overlay arrangement's vertices, edges and faces are each at
//! most a constant times as many (every arrangement vertex is a corner of a
//! trapezoid, every face a union of trapezoids). So S bounds the thesis's
//! space from above; a slab structure can grow faster than the arrangement
//! (up to |EC|³ per class), so a ratio that grows on some family would be a
//! cost of the slab method, not a refutation. The label lists of the
//! trapezoids (which cells cover each), which the thesis stores without
//! blowup by the interval trees of Guibas et al., are not counted (the
//! sweep's `overlay_size` has them); the cells placed are (`cells_placed`).
//!
//! Time is not measured here: a checker is deterministic. The scaling sweep
//! (`benches/src/bin/sweep.rs`) fits the log–log slope of the preprocessing
//! time and of S against N(n + r²) on the scaling families.
//!
//! ## Trust
//! Exact counts of the structure the localizer builds from the study's
//! decomposition, counted from the decomposition without building it
//! ([`wai_study::Study::preprocessing_size`], `wai_study::preprocessing`:
//! `i128` arithmetic, every operation checked, the localizer's own count
//! where a number does not fit; tested equal to
//! `Localizer::trapezoids` on maps of every kind); N is the
//! decomposition's total complexity. A bound is never decided by one map
//! ([`crate::framework::Report::hold_to`]).

use serde_json::json;
use wai_localize::Localizer;
use wai_study::Study;

use crate::framework::{over, Ceiling, Checker, Report};

const ID: &str = "C5.18";

/// The checker. The ceiling is 6× the largest ratio seen: 1/3 (a
/// triangle: one cell in two slabs of three trapezoids, against
/// N(n + r²) = 6 · 3) over the corpus (912 maps), 500 maps of every kind
/// (`--maps all`) and 150 of the chapter 5 layouts.
pub const CHECKER: Checker = Checker::new(ID, check_study).with_ceiling(Ceiling(2, 1));

/// S, the size of the preprocessed structure: trapezoids over all classes.
pub fn size(loc: &Localizer) -> usize {
    loc.trapezoids()
}

/// N(n + r²).
pub fn bound(total_complexity: usize, n: usize, r: usize) -> u128 {
    total_complexity as u128 * (n as u128 + (r as u128).pow(2))
}

/// S / (N(n + r²)) on the study's map.
fn check_study(study: &Study<'_>) -> Report {
    let map = study.map();
    let d = study.decomposition();
    let placed = d.cells().len() + d.lower_cells().len();
    measure(
        study.preprocessing_size(),
        placed,
        d.total_complexity(),
        map.n(),
        map.r(),
    )
}

/// The report of one map's counts.
pub fn measure(
    size: usize,
    cells_placed: usize,
    total_complexity: usize,
    n: usize,
    r: usize,
) -> Report {
    let b = bound(total_complexity, n, r);
    let mut report = CHECKER.bound_report(Some((
        over(size, b),
        json!({
            "trapezoids": size,
            "cells_placed": cells_placed,
            "total_complexity": total_complexity,
            "n": n,
            "r": r,
        }),
    )));
    report.count("trapezoids", size as u64);
    report.count("cells_placed", cells_placed as u64);
    report
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn measures_and_can_fail() {
        super::super::tests::assert_measures_and_can_fail(&CHECKER);
    }

    #[test]
    fn the_ratio_of_the_counts() {
        let map = wai_gen::family("corridor-niches", &[2]).unwrap();
        let study = Study::new(&map);
        let report = CHECKER.run(&study);
        let loc = study.localizer();
        let (n, r) = (map.n(), map.r());
        let want = over(
            loc.trapezoids(),
            bound(study.decomposition().total_complexity(), n, r),
        );
        assert_eq!(report.largest.expect("a ratio").ratio, want);
        assert_eq!(report.counts["trapezoids"], loc.trapezoids() as u64);
        assert_eq!(report.counts["cells_placed"], loc.cells() as u64);
    }

    #[test]
    fn planted_excess_is_reported() {
        // A structure of N(n + r²) + 1 trapezoids against a ceiling of 1.
        let planted = CHECKER.with_ceiling(Ceiling(1, 1));
        let report = planted.judge(measure(6 * 7 + 1, 1, 6, 3, 2));
        assert_eq!(report.violations.len(), 1);
        assert!(report.violations[0].what.contains("above the ceiling"));
        assert!(CHECKER
            .judge(measure(6 * 7, 1, 6, 3, 2))
            .violations
            .is_empty());
    }
}
