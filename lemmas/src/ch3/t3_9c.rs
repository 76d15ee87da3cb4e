//! Claim T3.9c (Theorem 3.9, tightness; Fig 3.15): a corridor with r
//! niches on its south side and a convex chain of Ω(n) vertices opposite
//! (family `comb-convex-chain`) has Ω(n²r) visibility cells.
//!
//! The thesis's construction: every chain vertex sends a visibility ray
//! into every niche, anchored at a mouth corner, and all crossings of those
//! rays lie inside the niches. In our family the `⌈c/2⌉` chain vertices
//! west of the comb see each niche's west mouth corner and the `⌊c/2⌋` east
//! of it its east corner (c the chain's length), and the rays of a west and
//! an east chain vertex cross strictly inside the niche
//! (`wai_gen::comb_convex_chain`). Two such crossings are different points
//! (two west rays of one niche meet only at their common anchor), so a map
//! of the family with `k` niches has at least `k·⌈c/2⌉·⌊c/2⌋` decomposition
//! vertices inside M. Each is a crossing of rays that run on through it
//! (rays end on ∂M), so it has degree at least 4, and Euler's formula for
//! the connected arrangement (every ray starts on ∂M) gives at least one
//! more 2-cell than interior vertices: cells ≥ `k·⌈c/2⌉·⌊c/2⌋ + 1`, which
//! is Ω(n²r) for `k = c` (n = 5k + 2, r = 2k).
//!
//! ## Trust
//! Exact, on the family's maps only, at any size (recognised by their
//! vertices, [`wai_study::family::comb_parameters`]). Each map is one
//! instance, violated if a crossing of the construction is not a vertex of
//! the production arrangement (the exact meeting point of the two rays'
//! lines, looked up among the arrangement's exact points, and strictly
//! inside its niche) or if the decomposition has fewer 2-cells than the
//! bound above. The ratio measured is cells / (n²r); the sweep fits its
//! growth on the family (`benches/src/bin/sweep.rs`, slope of cells against
//! n²r on `comb-convex-chain`).

use std::collections::HashSet;

use serde_json::json;
use wai_exact::{construct_intersection, Line, Point, RatPoint};
use wai_study::family::comb_parameters;
use wai_study::Study;

use crate::framework::{over, Checker, Report, Violation};

const ID: &str = "T3.9c";

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study);

/// Checks T3.9c on the maps of family `comb-convex-chain`.
fn check_study(study: &Study<'_>) -> Report {
    match comb_parameters(study.map()) {
        Some((niches, chain)) => check_comb(study, niches, chain, 0),
        None => Report::new(ID),
    }
}

/// The construction's lower bound on the 2-cells of
/// `comb_convex_chain(niches, chain)`: `niches·⌈chain/2⌉·⌊chain/2⌋ + 1`.
pub fn lower_bound(niches: u32, chain: u32) -> u64 {
    let (west, east) = (u64::from(chain.div_ceil(2)), u64::from(chain / 2));
    u64::from(niches) * west * east + 1
}

/// The crossings the construction promises in each niche, by niche: the
/// meeting point of the ray from each west chain vertex through the niche's
/// west mouth corner and the ray from each east chain vertex through its
/// east mouth corner.
pub fn promised_crossings(niches: u32, chain: u32) -> Vec<Vec<RatPoint>> {
    let l = wai_gen::comb_layout(niches, chain);
    l.niche_x
        .iter()
        .map(|&a| {
            let (west_corner, east_corner) = (Point::new(a, 0), Point::new(a + l.width, 0));
            l.west
                .iter()
                .flat_map(|&uw| l.east.iter().map(move |&ue| (uw, ue)))
                .filter_map(|(uw, ue)| {
                    let w = Line::new(l.chain_vertex(uw), west_corner)?;
                    let e = Line::new(l.chain_vertex(ue), east_corner)?;
                    construct_intersection(&w, &e)
                })
                .collect()
        })
        .collect()
}

/// Whether `p` lies strictly inside the square niche `[a, a + w] × [−w, 0]`.
fn strictly_in_niche(p: &RatPoint, a: i128, w: i128) -> bool {
    use rug::Integer;
    let hw = p.hw();
    let between = |c: &Integer, lo: i128, hi: i128| {
        Integer::from(hw * lo) < *c && *c < Integer::from(hw * hi)
    };
    between(p.hx(), a, a + w) && between(p.hy(), -w, 0)
}

/// The check on `comb_convex_chain(niches, chain)`; `plant` extra 2-cells
/// are demanded beyond the bound (for the planted-violation test).
pub fn check_comb(study: &Study<'_>, niches: u32, chain: u32, plant: u64) -> Report {
    let mut report = Report::new(ID);
    let d = study.decomposition();
    let arr = d.arrangement();
    let c = d.counts();
    let points: HashSet<&RatPoint> = (0..arr.vertex_count())
        .filter(|&v| !arr.is_on_map_boundary(v))
        .map(|v| arr.point(v))
        .collect();
    let l = wai_gen::comb_layout(niches, chain);
    let mut missing = Vec::new();
    for (i, crossings) in promised_crossings(niches, chain).iter().enumerate() {
        for p in crossings {
            if !strictly_in_niche(p, l.niche_x[i], l.width) || !points.contains(p) {
                missing.push(json!({"niche": i, "point": p.to_string()}));
            }
        }
    }
    let bound = lower_bound(niches, chain) + plant;
    let cells = c.cells as u64;
    let (n, r) = (c.n as u128, c.r as u128);
    report.measure(
        over(c.cells, n * n * r.max(1)),
        json!({"niches": niches, "chain": chain, "n": c.n, "r": c.r, "cells": c.cells}),
    );
    report.count("cells", cells);
    report.count("lower bound", bound);
    let ok = missing.is_empty() && cells >= bound;
    report.record((!ok).then(|| {
        Violation::with_data(
            format!(
                "comb-convex-chain with {niches} niches and a chain of {chain}: {cells} cells \
                 against the construction's {bound}, {} promised crossings missing",
                missing.len()
            ),
            json!({"niches": niches, "chain": chain, "cells": cells, "bound": bound,
                   "missing_crossings": missing}),
        )
    }));
    report
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_family_reaches_its_bound() {
        for (niches, chain) in [(1, 2), (2, 3), (3, 3), (2, 6)] {
            let map = wai_gen::family("comb-convex-chain", &[niches, chain]).unwrap();
            let r = CHECKER.run(&Study::new(&map));
            assert_eq!(r.examined, 1);
            assert!(r.violations.is_empty(), "{:?}", r.violations);
            assert!(r.counts["cells"] >= lower_bound(niches, chain));
        }
        // Not a family map: nothing to examine.
        let other = wai_gen::family("corridor-niches", &[2]).unwrap();
        assert_eq!(CHECKER.run(&Study::new(&other)).examined, 0);
    }

    #[test]
    fn every_promised_crossing_is_distinct() {
        let all = promised_crossings(3, 6);
        assert_eq!(all.len(), 3);
        for niche in &all {
            assert_eq!(niche.len(), 9);
            let distinct: HashSet<&RatPoint> = niche.iter().collect();
            assert_eq!(distinct.len(), 9);
        }
    }

    #[test]
    fn a_planted_shortfall_is_reported() {
        let map = wai_gen::family("comb-convex-chain", &[2, 4]).unwrap();
        let study = Study::new(&map);
        let cells = study.decomposition().counts().cells as u64;
        let r = check_comb(&study, 2, 4, cells);
        assert_eq!(r.violations.len(), 1);
        assert!(r.violations[0].what.contains("cells against"));
        // The wrong parameters promise crossings the map does not have.
        let r = check_comb(&study, 2, 6, 0);
        assert_eq!(r.violations.len(), 1, "{:?}", r.violations);
        assert!(r.violations[0].data["missing_crossings"]
            .as_array()
            .is_some_and(|m| !m.is_empty()));
    }
}
