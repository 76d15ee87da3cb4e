//! Claim T5.17t (Theorem 5.17's tightness, chapter 5 introduction): the
//! O(n + r²) bound on an equivalence class is reached by both terms — some
//! maps have a class of complexity Ω(n), others one of Ω(r²), here with
//! n = Θ(r) so that the r² term is not n's in disguise.
//!
//! ## Trust
//! Exact counts on the maps of two constructions, recognised by their
//! vertices ([`wai_study::family::parameter_of`]) whatever their names:
//! - `window-grid` c (Fig 5.2 grown, `wai_gen::window_grid`): n = 8c + 12,
//!   r = 4c + 4, and the construction promises one class with a 2-cell for
//!   every pair of wall pieces, at least c² cells (8c² complexity measured
//!   for c = 2…32);
//! - a convex map (r = 0): its one cell, of complexity 2n, is its class.
//!
//! One instance per recognised map, counted by case ([`OMEGA_R2`] for
//! `window-grid`, [`OMEGA_N`] for a convex map); count
//! `largest_class_cells`. Growth beyond the recognised parameters is the
//! sweep's (`max_ec_vs_n_r2.svg`, series `window-grid`).

use serde_json::json;

use crate::framework::over;
use crate::framework::{Case, Checker, Report, Violation};
use wai_study::family::parameter_of;
use wai_study::Study;

const ID: &str = "T5.17t";

/// A `window-grid` map: the Ω(r²) term.
pub const OMEGA_R2: &str = "Ω(r²)";
/// A convex map: the Ω(n) term.
pub const OMEGA_N: &str = "Ω(n)";

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study).with_cases(&[
    Case {
        name: OMEGA_R2,
        what: "a window-grid map: one class of at least c² cells with n, r = Θ(c) (the r² term \
               of Theorem 5.17 reached)",
    },
    Case {
        name: OMEGA_N,
        what: "a convex map: its one class of complexity 2n (the n term reached)",
    },
]);

/// Checks T5.17t on the maps of its constructions.
fn check_study(study: &Study<'_>) -> Report {
    let map = study.map();
    let mut report = Report::new(ID);
    if let Some(c) = parameter_of(map, "window-grid") {
        let cells = study
            .decomposition()
            .classes()
            .iter()
            .map(Vec::len)
            .max()
            .unwrap_or(0);
        report.hit(OMEGA_R2);
        report.count("largest_class_cells", cells as u64);
        report.record(check_grid(c as usize, cells));
        report.measure(
            over(cells, (c as u128).pow(2)),
            json!({"c": c, "largest_class_cells": cells}),
        );
    } else if map.r() == 0 {
        let counts = study.decomposition().counts();
        report.hit(OMEGA_N);
        report.record(check_convex(counts.n, counts.max_class_complexity));
    }
    report
}

/// `window-grid` c: some class has at least c² cells.
pub fn check_grid(c: usize, largest_class_cells: usize) -> Option<Violation> {
    (largest_class_cells < c * c).then(|| {
        Violation::with_data(
            format!("window-grid c = {c}: the largest class has {largest_class_cells} cells, fewer than c² = {}", c * c),
            json!({"c": c, "largest_class_cells": largest_class_cells}),
        )
    })
}

/// A convex map of n vertices: its class has complexity at least n.
pub fn check_convex(n: usize, max_class_complexity: usize) -> Option<Violation> {
    (max_class_complexity < n).then(|| {
        Violation::with_data(
            format!("a convex map of {n} vertices has max |EC| = {max_class_complexity} < n"),
            json!({"n": n, "max_class_complexity": max_class_complexity}),
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_grid_reaches_c_squared_cells() {
        for c in [1u32, 3, 5] {
            let map = wai_gen::family("window-grid", &[c])
                .unwrap()
                .with_name("renamed");
            let report = CHECKER.run(&Study::new(&map));
            assert_eq!(
                (report.examined, report.violations.len()),
                (1, 0),
                "c = {c}"
            );
            assert!(report.counts["largest_class_cells"] >= u64::from(c * c));
        }
    }

    #[test]
    fn planted_shortfalls_are_reported() {
        assert!(check_grid(4, 15).is_some() && check_grid(4, 16).is_none());
        assert!(check_convex(6, 5).is_some() && check_convex(6, 12).is_none());
        // Maps of neither construction are not examined.
        let map = wai_gen::family("corridor-niches", &[2]).unwrap();
        assert_eq!(CHECKER.run(&Study::new(&map)).examined, 0);
    }
}
