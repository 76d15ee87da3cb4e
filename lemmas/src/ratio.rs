//! The shared machinery of the **bound** claims: a ratio measured exactly on
//! every map, its maximum over a run, and a ceiling that makes the checker
//! able to fail.
//!
//! An asymptotic bound cannot be violated by one map; what one map gives is
//! the ratio of the quantity to the bound's expression. Each bound checker
//! reports that ratio (examined = 1 per map) and calls a violation any ratio
//! above its claim's ceiling: a constant far above every ratio seen on the
//! generated maps, the thesis families and the datasets, so that a value
//! above it is either a bug of ours or a map worth a look — never evidence
//! against an O(·) statement by itself. The scaling sweep
//! (`benches/src/bin/sweep.rs`) fits the growth exponents.

use rug::{Integer, Rational};
use serde_json::json;
use wai_cells::{Counts, Decomposition};
use wai_map::Map;

use crate::driver::{Checker, Report, Violation};
use crate::sample;
use crate::Study;

/// A measured ratio and what it was measured on.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Measured {
    pub ratio: Rational,
    pub counts: Counts,
}

/// Measure `ratio(counts)` on `map` and compare it with `ceiling`.
pub fn check(
    id: &'static str,
    map: &Map,
    ceiling: &Rational,
    ratio: fn(&Counts) -> Rational,
) -> (Report, Measured) {
    let counts = Decomposition::new(map).counts();
    check_counts(id, map, &counts, ceiling, ratio)
}

/// As [`check`], on counts already measured (planted tests feed fakes).
pub fn check_counts(
    id: &'static str,
    map: &Map,
    counts: &Counts,
    ceiling: &Rational,
    ratio: fn(&Counts) -> Rational,
) -> (Report, Measured) {
    let value = ratio(counts);
    let mut report = Report::new(id);
    let violation = (value > *ceiling).then(|| {
        Violation::with_data(
            format!(
                "{id}: map {}: ratio {value} (≈ {:.4}) above the ceiling {ceiling}",
                sample::map_name(map),
                value.to_f64()
            ),
            json!({
                "map": sample::map_name(map),
                "ratio": value.to_string(),
                "ceiling": ceiling.to_string(),
                "n": counts.n, "r": counts.r, "cells": counts.cells,
                "total_complexity": counts.total_complexity,
                "max_class_complexity": counts.max_class_complexity,
            }),
        )
    });
    report.record(violation);
    report.measure(
        value.clone(),
        json!({"n": counts.n, "r": counts.r, "max_class_complexity": counts.max_class_complexity}),
    );
    (
        report,
        Measured {
            ratio: value,
            counts: counts.clone(),
        },
    )
}

/// The checker of one bound claim: its id, the ratio it measures and the
/// ceiling above which a ratio is reported.
#[derive(Debug, Clone, Copy)]
pub struct BoundChecker {
    pub id: &'static str,
    pub measure: fn(&Counts) -> Rational,
    pub ceiling: fn() -> Rational,
}

impl BoundChecker {
    /// The report and the measured ratio.
    pub fn check_with_ratio(&self, study: &Study<'_>) -> (Report, Measured) {
        let counts = study.decomposition().counts();
        check_counts(
            self.id,
            study.map(),
            &counts,
            &(self.ceiling)(),
            self.measure,
        )
    }
}

impl Checker for BoundChecker {
    fn id(&self) -> &'static str {
        self.id
    }
    fn check_study(&self, study: &Study<'_>) -> Report {
        self.check_with_ratio(study).0
    }
}

/// `a / b` as an exact ratio, with `b` at least 1.
pub fn over(a: usize, b: u128) -> Rational {
    Rational::from((Integer::from(a), Integer::from(b.max(1))))
}
