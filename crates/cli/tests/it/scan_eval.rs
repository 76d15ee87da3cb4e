//! `wai localize-scan` and `wai eval`: `--help` answers at once; a scan
//! written by `wai scan` is localized back to its pose; the evaluation
//! writes its JSON keys, CDF plots and look-alike counts; bad maps,
//! scans, compasses and conditions are refused with a message.

use super::{text, wai};

fn tmp(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("wai-scan-eval-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

#[test]
fn help_answers_without_starting_work() {
    for (cmd, flags) in [
        (
            "localize-scan",
            &["--compass", "--heading", "--units", "--svg", "--json"][..],
        ),
        (
            "eval",
            &[
                "--poses",
                "--seed",
                "--compass",
                "--conditions",
                "--peer",
                "--json",
                "--out",
            ][..],
        ),
    ] {
        let out = wai(&[cmd, "--help"], b"");
        assert_eq!(out.status.code(), Some(0));
        let help = text(&out.stdout);
        for flag in flags {
            assert!(help.contains(flag), "{cmd}: {flag} missing from: {help}");
        }
    }
}

fn pose_of(v: &serde_json::Value) -> (f64, f64, f64) {
    (
        v["x"].as_f64().unwrap(),
        v["y"].as_f64().unwrap(),
        v["heading_degrees"].as_f64().unwrap(),
    )
}

#[test]
fn a_scan_is_localized_back_to_its_pose_and_drawn() {
    let dir = tmp("loc");
    let scan = dir.join("scan.json");
    let svg = dir.join("answer.svg");
    let out = wai(
        &[
            "scan",
            "office:2:3",
            "--at",
            "3.5,-2.5,30",
            "--noise",
            "0.02",
            "--out",
            scan.to_str().unwrap(),
        ],
        b"",
    );
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    for compass in ["exact", "none", "noisy:5"] {
        let out = wai(
            &[
                "localize-scan",
                "office:2:3",
                scan.to_str().unwrap(),
                "--compass",
                compass,
                "--json",
                "--svg",
                svg.to_str().unwrap(),
            ],
            b"",
        );
        assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
        let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
        let (x, y, h) = pose_of(&v["best"]["pose"]);
        assert!((x - 3.5).hypot(y + 2.5) < 0.1, "{compass}: ({x}, {y})");
        assert!(
            ((h - 30.0 + 180.0).rem_euclid(360.0) - 180.0).abs() < 2.0,
            "{h}"
        );
        assert!(!v["answer_set"].as_array().unwrap().is_empty());
        assert!(v["cells"].as_u64().unwrap() > 100);
        let drawn = std::fs::read_to_string(&svg).unwrap();
        assert!(drawn.starts_with("<svg") && drawn.contains("<line"));
        let entries = super::pictures::legend_entries(&drawn);
        for needle in [
            "map walls",
            "scan return placed at the best pose",
            "best pose",
        ] {
            assert!(
                entries.iter().any(|e| e.contains(needle)),
                "{needle}: {entries:?}"
            );
        }
        let bar = super::pictures::scale_bar(&drawn).expect("a scale bar");
        assert!(bar.ends_with(" m"), "{bar}");
    }
    // A local query around the truth finds it; a malformed one is refused.
    let near = |at: &str| {
        let out = wai(
            &[
                "localize-scan",
                "office:2:3",
                scan.to_str().unwrap(),
                "--near",
                at,
                "--json",
            ],
            b"",
        );
        assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
        let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
        pose_of(&v["best"]["pose"])
    };
    let (x, y, _) = near("3,-2,2");
    assert!((x - 3.5).hypot(y + 2.5) < 0.1, "({x}, {y})");
    let bad = wai(
        &[
            "localize-scan",
            "office:2:3",
            scan.to_str().unwrap(),
            "--near",
            "1,2",
        ],
        b"",
    );
    assert_eq!(bad.status.code(), Some(2));
    // The text answer names the pose too.
    let out = wai(
        &["localize-scan", "office:2:3", scan.to_str().unwrap()],
        b"",
    );
    assert_eq!(out.status.code(), Some(0));
    assert!(text(&out.stdout).contains("best pose ("));
}

#[test]
fn bad_scans_compasses_and_maps_are_refused_with_a_message() {
    let dir = tmp("bad");
    let good = dir.join("good.json");
    std::fs::write(&good, r#"{"angles": [0, 1, 2], "ranges": [1, 1, null]}"#).unwrap();
    let cases: Vec<(&str, Vec<String>, i32, &str)> = vec![
        ("not JSON", vec![], 1, "not JSON"),
        (
            r#"{"angles": [0, 1], "ranges": [1]}"#,
            vec![],
            1,
            "2 angles and 1 ranges",
        ),
        (r#"{"angles": [0], "ranges": [-1]}"#, vec![], 1, "negative"),
        (
            r#"{"angles": [null], "ranges": [1]}"#,
            vec![],
            1,
            "angles[0] is null",
        ),
        (r#"{"ranges": [1]}"#, vec![], 1, "no array \"angles\""),
        (
            r#"{"angles": [0], "ranges": [1]}"#,
            vec!["--compass".into(), "exact".into()],
            2,
            "needs a reading",
        ),
        (
            r#"{"angles": [0], "ranges": [1]}"#,
            vec!["--compass".into(), "north".into()],
            2,
            "expected exact, none or noisy",
        ),
    ];
    for (i, (body, extra, code, needle)) in cases.into_iter().enumerate() {
        let f = dir.join(format!("scan{i}.json"));
        std::fs::write(&f, body).unwrap();
        let mut args = vec![
            "localize-scan".to_string(),
            "rooms:1".into(),
            f.display().to_string(),
        ];
        args.extend(extra);
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let out = wai(&args, b"");
        let err = text(&out.stderr);
        assert_eq!(out.status.code(), Some(code), "{body}: {err}");
        assert!(err.contains(needle), "{body}: {err}");
        assert!(!err.contains("panicked"), "{err}");
    }
    for (spec, needle) in [
        ("rooms:0", "between 1 and 200"),
        ("office:x", "is not a count"),
        ("family:no-such:1", "family:no-such:1"),
        ("/no/such/map.json", "/no/such/map.json"),
    ] {
        let out = wai(
            &[
                "localize-scan",
                spec,
                good.to_str().unwrap(),
                "--compass",
                "none",
            ],
            b"",
        );
        let err = text(&out.stderr);
        assert_ne!(out.status.code(), Some(0), "{spec}");
        assert!(err.contains(needle), "{spec}: {err}");
    }
    for (args, needle) in [
        (
            vec!["eval", "rooms:2", "--conditions", "fog"],
            "condition \"fog\"",
        ),
        (vec!["eval", "rooms:2", "--poses", "0"], "≥ 1"),
        (vec!["eval", "rooms:2", "--peer", "nobody"], "nobody"),
        (vec!["eval", "rooms:2", "--units", "furlongs"], "furlongs"),
    ] {
        let out = wai(&args, b"");
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        assert!(text(&out.stderr).contains(needle), "{}", text(&out.stderr));
    }
}

#[test]
fn an_evaluation_reports_every_key_row_plot_and_look_alike() {
    let dir = tmp("eval");
    let args = [
        "eval",
        "rooms:3",
        "--poses",
        "12",
        "--seed",
        "5",
        "--compass",
        "exact,noisy:10",
        "--conditions",
        "base,range10",
        "--json",
        "--out",
        dir.to_str().unwrap(),
    ];
    let out = wai(&args, b"");
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
    for key in [
        "success_rate",
        "success_rate_strict",
        "success_rate_loose",
        "answer_set_contains_truth_rate",
        "median_ms",
        "peers",
    ] {
        assert!(v.get(key).is_some(), "{key} missing: {v}");
    }
    assert_eq!(v["queries"], 12 * 2 * 2);
    let map = &v["maps"][0];
    assert_eq!(map["kind"], "repeated rooms");
    let rows = map["rows"].as_array().unwrap();
    assert_eq!(rows.len(), 4);
    for r in rows {
        assert!(
            r["answer_set_contains_truth_rate"].as_f64().unwrap() >= 0.75,
            "{r}"
        );
        let l = &r["look_alikes"];
        assert!(l["queries_in_rooms"].as_u64().unwrap() > 0, "{r}");
        assert!(l["answer_set_holds_truth_and_all_look_alikes"]
            .as_u64()
            .is_some());
    }
    let cdf = std::fs::read_to_string(map["cdf_svg"].as_str().unwrap()).unwrap();
    assert!(cdf.contains("polyline"));
    assert!(!super::pictures::legend_entries(&cdf).is_empty(), "{cdf}");
    // The note under the axis says how it was fitted.
    assert!(cdf.contains("x axis"), "{cdf}");
    assert!(dir.join("eval.json").exists() && dir.join("cdf-all.svg").exists());
    // The same seed gives the same figures (times aside).
    let again = wai(&args, b"");
    let w: serde_json::Value = serde_json::from_slice(&again.stdout).expect("JSON");
    assert_eq!(w["success_rate"], v["success_rate"]);
    assert_eq!(
        w["maps"][0]["rows"][1]["look_alikes"],
        v["maps"][0]["rows"][1]["look_alikes"]
    );
}

#[test]
fn karto_runs_side_by_side_on_the_same_scans() {
    // Needs scripts/install-karto (the bootstrap tries it): says SKIPPED
    // without it, but fails in CI (WAI_CI), which requires the peer.
    let python = wai_scan::peer::KartoPeer::default_python();
    if !python.exists() && std::env::var_os("WAI_CI").is_none() {
        // Past the test harness's capture: a skip must be seen.
        use std::io::Write as _;
        let _ = writeln!(
            std::io::stderr(),
            "SKIPPED: the karto peer is not installed ({} is missing); \
             scripts/install-karto installs it, and CI requires it",
            python.display()
        );
        return;
    }
    let dir = tmp("karto");
    let out = wai(
        &[
            "eval",
            "rooms:1",
            "--poses",
            "2",
            "--compass",
            "exact,none",
            "--conditions",
            "base",
            "--peer",
            "karto:0.1",
            "--peer-poses",
            "1",
            "--json",
            "--out",
            dir.to_str().unwrap(),
        ],
        b"",
    );
    assert_eq!(
        out.status.code(),
        Some(0),
        "is karto installed (scripts/install-karto)? {}",
        text(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
    let peer = &v["peers"][0];
    assert_eq!(peer["name"], "karto:0.1");
    // The settings it ran with reach the JSON: those sent, and per map
    // those the peer derived (its windows).
    assert_eq!(peer["config"]["resolution"], 0.1, "{peer}");
    assert_eq!(peer["config"]["window"], 8.0, "{peer}");
    let settings = &v["maps"][0]["peer_settings"][0];
    assert_eq!(settings["name"], "karto:0.1");
    assert_eq!(settings["settings"]["smear_deviation"], 0.1, "{settings}");
    assert!(settings["settings"]["windows"].as_u64().unwrap() >= 1);
    // One scan, shared by both compass rows, counted once.
    assert_eq!(peer["queries"], 1, "{v}");
    for row in v["maps"][0]["rows"].as_array().unwrap() {
        let p = &row["peers"][0];
        assert_eq!(p["queries"], 1);
        assert!(p["median_ms"].as_f64().unwrap() > 0.0);
        assert_eq!(p["ours_on_the_same_queries"]["queries"], 1);
    }
}

/// Sites have a memory budget (`--max-memory`): a 1 km square, where a
/// fixed lattice of 0.5 m would stand at four million sites, is answered
/// with the lattice widened to fit, and a map whose cells alone do not fit
/// is refused with the estimate and the option that raises the limit.
#[test]
fn sites_fit_the_memory_budget() {
    let dir = tmp("budget");
    std::fs::create_dir_all(&dir).unwrap();
    let map = dir.join("km.json");
    std::fs::write(
        &map,
        r#"{"name": "km", "outer": [[0, 0], [1000, 0], [1000, 1000], [0, 1000]]}"#,
    )
    .unwrap();
    let scan = dir.join("scan.json");
    let (m, s) = (map.to_str().unwrap(), scan.to_str().unwrap());
    let out = wai(
        &[
            "scan",
            m,
            "--units",
            "m",
            "--at",
            "300,400,10",
            "--beams",
            "90",
            "--out",
            s,
        ],
        b"",
    );
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let out = wai(
        &[
            "localize-scan",
            m,
            s,
            "--units",
            "m",
            "--max-memory",
            "16M",
            "--json",
        ],
        b"",
    );
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
    let budget = (16u64 << 20) / wai_scan::site_bytes(720);
    let sites = v["sites"].as_u64().unwrap();
    assert!(
        sites <= budget && sites > 100,
        "{sites} sites, budget {budget}"
    );
    assert!(v["lattice_spacing"].as_f64().unwrap() > 0.5, "{v}");

    let out = wai(&["localize-scan", "office:2", s, "--max-memory", "1M"], b"");
    let err = text(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{err}");
    assert!(
        err.contains("refused") && err.contains("MiB") && err.contains("--max-memory"),
        "{err}"
    );
    std::fs::remove_dir_all(&dir).ok();
}
