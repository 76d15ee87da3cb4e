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
    office_scan(&scan, &[]);
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
            "angles[0] = null is not a finite number",
        ),
        (r#"{"ranges": [1]}"#, vec![], 1, "neither a wai scan"),
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
        "base,range10,range10-unstated",
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
    assert_eq!(v["queries"], 12 * 3 * 2);
    let map = &v["maps"][0];
    assert_eq!(map["kind"], "repeated rooms");
    let rows = map["rows"].as_array().unwrap();
    assert_eq!(rows.len(), 6);
    // The same scans with and without their range stated localize alike.
    assert_eq!(rows[2]["condition"], "10 m range cutoff");
    assert_eq!(rows[4]["condition"], "10 m cutoff, unstated");
    let rate = |i: usize| rows[i]["answer_set_contains_truth_rate"].as_f64().unwrap();
    assert!(
        (rate(2) - rate(4)).abs() <= 1.0 / 12.0 + 1e-9,
        "{} vs {}",
        rate(2),
        rate(4)
    );
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

/// A scan of office:2:3 at (3.5, −2.5) heading 30°, σ = 2 cm, with the
/// further `wai scan` options `extra`, written by `wai scan` to `path`.
fn office_scan(path: &std::path::Path, extra: &[&str]) -> serde_json::Value {
    let p = path.to_str().unwrap();
    let mut args = vec![
        "scan",
        "office:2:3",
        "--at",
        "3.5,-2.5,30",
        "--noise",
        "0.02",
    ];
    args.extend_from_slice(extra);
    args.extend_from_slice(&["--out", p]);
    let out = wai(&args, b"");
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    serde_json::from_slice(&std::fs::read(path).unwrap()).unwrap()
}

/// [`office_scan`] with a 4 m range: some beams have no return.
fn short_range_scan(dir: &std::path::Path) -> serde_json::Value {
    office_scan(&dir.join("short.json"), &["--max-range", "4"])
}

#[test]
fn a_scan_without_a_stated_range_or_in_ros_form_is_read_and_says_what_it_assumed() {
    let dir = tmp("forms");
    let stated = short_range_scan(&dir);
    let lost = stated["ranges"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|r| r.is_null())
        .count();
    assert!(lost > 0, "the 4 m scan loses no beam");
    let mut unstated = stated.clone();
    unstated.as_object_mut().unwrap().remove("sensor");
    // The ROS form: angles from angle_min in steps of angle_increment, no
    // return as +Inf (written by Python's json as a bare Infinity).
    let angles = stated["angles"].as_array().unwrap();
    let (a0, a1) = (angles[0].as_f64().unwrap(), angles[1].as_f64().unwrap());
    let ranges: Vec<String> = stated["ranges"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| r.as_f64().map_or("Infinity".into(), |r| r.to_string()))
        .collect();
    let ros = format!(
        r#"{{"angle_min": {a0}, "angle_max": {}, "angle_increment": {}, "range_min": 0.0,
            "range_max": 4.0, "ranges": [{}], "intensities": []}}"#,
        a0 + (a1 - a0) * (angles.len() - 1) as f64,
        a1 - a0,
        ranges.join(",")
    );
    let files = [
        ("stated.json", stated.to_string()),
        ("unstated.json", unstated.to_string()),
        ("ros.json", ros),
    ];
    for (name, body) in &files {
        std::fs::write(dir.join(name), body).unwrap();
    }
    let path = |name: &str| dir.join(name).to_str().unwrap().to_owned();
    let run = |name: &str, extra: &[&str]| {
        let p = path(name);
        let mut args = vec!["localize-scan", "office:2:3", &p, "--compass", "none"];
        args.extend_from_slice(extra);
        let out = wai(&args, b"");
        assert_eq!(out.status.code(), Some(0), "{name}: {}", text(&out.stderr));
        out
    };
    let json = |name: &str, extra: &[&str]| -> serde_json::Value {
        let mut e = vec!["--json"];
        e.extend_from_slice(extra);
        serde_json::from_slice(&run(name, &e).stdout).expect("JSON")
    };
    let (s, u, r) = (
        json("stated.json", &[]),
        json("unstated.json", &[]),
        json("ros.json", &[]),
    );
    // Stated: read against 4 m, no warning. Unstated: against the longest
    // return, with a warning, and still the right pose.
    assert_eq!(s["range"]["basis"], "stated");
    assert_eq!(s["warnings"].as_array().unwrap().len(), 0);
    assert_eq!(u["range"]["basis"], "longest return");
    assert_eq!(u["range"]["beams_without_return"], lost);
    let w = u["warnings"][0].as_str().unwrap();
    assert!(w.contains("states no maximum range"), "{w}");
    for v in [&s, &u, &r] {
        let (x, y, _) = pose_of(&v["best"]["pose"]);
        assert!((x - 3.5).hypot(y + 2.5) < 0.1, "({x}, {y})");
    }
    // The ROS form is detected, reads the same beams and answers the same.
    assert_eq!(r["scan"]["format"], "ROS sensor_msgs/LaserScan JSON");
    assert_eq!(s["scan"]["format"], "wai scan JSON");
    // Up to the rounding of angle_min + i · angle_increment (1e-15 rad).
    let same = |a: &serde_json::Value, b: &serde_json::Value| {
        let ((x, y, h), (u, v, g)) = (pose_of(&a["pose"]), pose_of(&b["pose"]));
        (x - u).abs() < 1e-9 && (y - v).abs() < 1e-9 && (h - g).abs() < 1e-7
    };
    assert!(
        same(&r["best"], &s["best"]),
        "{} vs {}",
        r["best"],
        s["best"]
    );
    let (rs, ss) = (
        r["answer_set"].as_array().unwrap(),
        s["answer_set"].as_array().unwrap(),
    );
    assert_eq!(rs.len(), ss.len());
    assert!(rs.iter().zip(ss).all(|(a, b)| same(a, b)));
    // Stating the range on the command line silences the warning.
    let quiet = json("unstated.json", &["--max-range", "4"]);
    assert_eq!(quiet["range"]["basis"], "stated");
    assert_eq!(quiet["warnings"].as_array().unwrap().len(), 0);
    // The text answer says the format, the range read and the warning.
    let t = text(&run("unstated.json", &[]).stdout);
    for want in [
        "scan: wai scan JSON",
        "sensing range: not stated",
        "warning: the scan states no maximum range",
        "units: m",
    ] {
        assert!(t.contains(want), "{want} missing from: {t}");
    }
    let t = text(&run("ros.json", &[]).stdout);
    assert!(
        t.contains("scan: ROS sensor_msgs/LaserScan JSON, 720 beams"),
        "{t}"
    );
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn several_scans_share_one_preprocessing_and_a_refused_one_does_not_stop_the_rest() {
    let dir = tmp("batch");
    let good = short_range_scan(&dir);
    let mut blind = good.clone();
    blind["ranges"] = serde_json::json!(vec![serde_json::Value::Null; 720]);
    std::fs::write(dir.join("a.json"), good.to_string()).unwrap();
    std::fs::write(dir.join("b.json"), blind.to_string()).unwrap();
    std::fs::write(dir.join("c.json"), good.to_string()).unwrap();
    let p = |n: &str| dir.join(n).to_str().unwrap().to_owned();
    let (a, b, c) = (p("a.json"), p("b.json"), p("c.json"));
    let out = wai(&["localize-scan", "office:2:3", &a, &b, &c], b"");
    // Every scan answered or refused by name, then exit 1 for the refusal.
    assert_eq!(out.status.code(), Some(1), "{}", text(&out.stderr));
    let t = text(&out.stdout);
    assert!(
        t.contains("REFUSED") && t.contains("b.json: not localizable"),
        "{t}"
    );
    assert!(t.contains("3 scans (1 refused)"), "{t}");
    assert!(
        t.contains("of the 2 that record their pose: best pose within 0.5 m and 10° 2 times"),
        "{t}"
    );
    assert!(text(&out.stderr).contains("1 of 3 scans refused"));
    let out = wai(&["localize-scan", "office:2:3", &a, &c, "--json"], b"");
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["summary"]["success_rate"], 1.0);
    assert_eq!(v["summary"]["answer_set_contains_truth_rate"], 1.0);
    assert_eq!(v["scans"].as_array().unwrap().len(), 2);
    // One drawing needs one answer.
    let svg = p("x.svg");
    let out = wai(&["localize-scan", "office:2:3", &a, &c, "--svg", &svg], b"");
    assert_eq!(out.status.code(), Some(2));
    std::fs::remove_dir_all(&dir).ok();
}
