//! `wai search-extremes`: `--help` answers at once; a tiny `--evals`
//! budget writes loadable figures in the format of `counterexamples/`,
//! and the same seed and evaluation count write the same files.

use super::{text, wai};
use std::path::{Path, PathBuf};

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("wai-cli-extremes-{}-{name}", std::process::id()));
    std::fs::remove_dir_all(&d).ok();
    d
}

fn run(out: &Path, extra: &[&str]) -> std::process::Output {
    let mut args = vec!["search-extremes", "--out", out.to_str().unwrap()];
    args.extend_from_slice(extra);
    wai(&args, b"")
}

#[test]
fn help_answers_without_starting_work() {
    let out = wai(&["search-extremes", "--help"], b"");
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let help = text(&out.stdout);
    for flag in [
        "--ratio", "--budget", "--evals", "--seed", "--start", "--out",
    ] {
        assert!(help.contains(flag), "{flag} missing from: {help}");
    }
    assert!(help.contains("cmult") && help.contains("wedge"));
}

#[test]
fn usage_errors_are_clear() {
    let dir = tmp("usage");
    let out = run(&dir, &["--ratio", "ec"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(text(&out.stderr).contains("--budget"));
    let out = run(&dir, &["--ratio", "ec", "--budget", "ten minutes"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(text(&out.stderr).contains("is not a duration"));
    let out = run(&dir, &["--ratio", "nope", "--evals", "1"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(!dir.exists(), "nothing is written on a usage error");
}

#[test]
fn a_tiny_budget_writes_the_same_figures_twice() {
    let args = [
        "--ratio", "ec", "--evals", "60", "--seed", "3", "--start", "both", "--max-n", "16",
        "--keep", "2", "--pool", "3", "--stall", "10",
    ];
    let (a, b) = (tmp("a"), tmp("b"));
    let (out_a, out_b) = (run(&a, &args), run(&b, &args));
    for o in [&out_a, &out_b] {
        assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
        assert!(!text(&o.stderr).contains("panicked"));
    }
    let summary = text(&out_a.stdout);
    assert!(summary.contains("60 evaluations"), "{summary}");
    assert!(summary.contains("best: "), "{summary}");
    assert!(
        summary.contains("corridor-niches"),
        "the families are compared: {summary}"
    );
    assert!(
        summary.contains("reproduce: wai search-extremes --ratio ec --evals 60 --seed 3"),
        "{summary}"
    );
    for name in [
        "T5.17-extreme-ec-seed3.json",
        "T5.17-extreme-ec-seed3-2.json",
    ] {
        let bytes = std::fs::read(a.join(name)).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!(
            bytes,
            std::fs::read(b.join(name)).unwrap(),
            "{name} differs"
        );
        let map = wai_map::json::from_json(&bytes).expect("a valid map").map;
        assert!(map.n() <= 16 && map.r() >= 1);
        let v: serde_json::Value = serde_json::from_slice(&bytes).unwrap();
        assert_eq!(v["claim"], "T5.17");
        assert_eq!(v["kind"], "figure");
        assert!(!v["note"].as_str().unwrap().is_empty());
        let search = &v["meta"]["search"];
        assert_eq!(search["evaluations"], 60);
        assert_eq!(search["seed"], 3);
        // The stored ratio is exact and is the map's.
        let value = search["value"].as_str().unwrap();
        let c = wai_cells::Decomposition::new(&map).counts();
        assert_eq!(value, wai_lemmas::ch5::t5_17::measure(&c).to_string());
        // `wai info` reads it back.
        let info = wai(&["info", "-"], &bytes);
        assert!(info.status.success(), "{}", text(&info.stderr));
    }
    // Everything but the elapsed time agrees.
    let strip = |s: &str| -> String {
        s.lines()
            .filter(|l| !l.starts_with("search-extremes:") && !l.starts_with("wrote "))
            .collect::<Vec<_>>()
            .join("\n")
    };
    assert_eq!(strip(&summary), strip(&text(&out_b.stdout)));
    std::fs::remove_dir_all(a).ok();
    std::fs::remove_dir_all(b).ok();
}

#[test]
fn k_is_stored_under_theorem_5_15() {
    let dir = tmp("k");
    let out = run(
        &dir,
        &[
            "--ratio", "k", "--evals", "2", "--start", "families", "--max-n", "12",
        ],
    );
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let bytes = std::fs::read(dir.join("T5.15-extreme-k-seed0.json")).unwrap();
    let v: serde_json::Value = serde_json::from_slice(&bytes).unwrap();
    assert_eq!(
        (v["claim"].as_str(), v["kind"].as_str()),
        (Some("T5.15"), Some("figure"))
    );
    assert!(v["note"]
        .as_str()
        .unwrap()
        .contains("within Theorem 5.15's bound 6"));
    std::fs::remove_dir_all(dir).ok();
}
