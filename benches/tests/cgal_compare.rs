//! A small run of the `compare_cgal` binary (wai's exact visibility polygons
//! against CGAL's, modulo CGAL's documented conventions): 0 unexplained
//! mismatches. The full run is the binary itself:
//!
//! ```sh
//! benches/peers/build.sh
//! cargo run --release -p wai-benches --bin compare_cgal
//! ```
//!
//! Without the peer binary the tests pass after printing
//! "CGAL peer not built; run benches/peers/build.sh".

use std::io::Write;
use std::process::{Command, Output};
use wai_benches::cgal;

/// Print past the test harness's capture, so a skipped test is visible.
fn say(msg: &str) {
    let _ = writeln!(std::io::stderr(), "{msg}");
}

fn peer_built() -> bool {
    if cgal::available() {
        return true;
    }
    say(&format!(
        "CGAL peer not built; run benches/peers/build.sh (looked for {})",
        cgal::binary_path().display()
    ));
    false
}

fn compare_cgal(args: &[&str]) -> (Output, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_compare_cgal"))
        .args(args)
        .output()
        .expect("compare_cgal starts");
    let stdout = String::from_utf8_lossy(&out.stdout).into_owned();
    (out, stdout)
}

/// The number after `label` at the start of a report line.
fn figure(report: &str, label: &str) -> usize {
    report
        .lines()
        .find_map(|l| l.trim_start().strip_prefix(label))
        .and_then(|rest| rest.split_whitespace().next())
        .and_then(|v| v.parse().ok())
        .unwrap_or_else(|| panic!("no {label:?} line in the report:\n{report}"))
}

/// 252 random maps (7 of each kind × size, n from 10 to 500) and the thesis
/// families, 4 viewpoints each, degenerate ones included: every polygon of
/// ours equals CGAL's up to CGAL's collinear in-between vertices, and the
/// reference's.
#[test]
fn random_maps_match_cgal() {
    if !peer_built() {
        return;
    }
    let (out, report) = compare_cgal(&["--polygons", "252", "--viewpoints", "4", "--no-datasets"]);
    say(&report);
    assert!(
        out.status.success(),
        "compare_cgal failed ({}):\n{report}\n{}",
        out.status,
        String::from_utf8_lossy(&out.stderr)
    );
    assert_eq!(figure(&report, "unexplained:"), 0);
    // The random maps, then the thesis families.
    assert!(figure(&report, "maps:") > 252, "{report}");
    let compared = figure(&report, "polygons compared with CGAL:");
    assert!(compared >= 252 * 3, "{compared} comparisons");
    let exact = figure(&report, "exact matches:");
    let after_c2 = figure(
        &report,
        "matches after C2 (CGAL's collinear in-between vertices dropped):",
    );
    assert_eq!(exact + after_c2, compared);
    // The degenerate viewpoints do exercise the collinear convention.
    assert!(after_c2 > 0, "no match needed C2:\n{report}");
}

/// The harness is not blind: with a vertex dropped from every 10th polygon
/// of ours, each such polygon is reported and the exit status is 1.
#[test]
fn injected_faults_are_reported() {
    if !peer_built() {
        return;
    }
    let (out, report) = compare_cgal(&[
        "--polygons",
        "36",
        "--viewpoints",
        "3",
        "--no-datasets",
        "--inject-fault",
        "10",
    ]);
    assert_eq!(out.status.code(), Some(1), "{report}");
    let injected = figure(&report, "injected faults (self-test):");
    assert!(injected >= 10, "{report}");
    assert_eq!(figure(&report, "ours != CGAL (after C1-C3):"), injected);
    assert_eq!(
        report.matches("[ours != CGAL (after C1-C3)]").count(),
        injected
    );
}
