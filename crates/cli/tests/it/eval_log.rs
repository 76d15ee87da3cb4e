//! `wai eval-log` on a CARMEN log written here: a 12 × 8 m room with two
//! pillars, scanned by a 181-beam 180° scanner (σ 1 cm) along a loop. The
//! map is built from the even scans, the odd ones are localized against
//! it, and the report says how many were found, with and without the
//! log's heading as a compass.

use super::{text, wai};
use wai_exact::Point;
use wai_scan::{simulate, Pose, Sensor};

/// The FLASER lines of scans taken at `poses` in `map`, with a header.
fn carmen_log(map: &wai_map::Map, poses: &[Pose]) -> String {
    let sensor = Sensor {
        beams: 181,
        fov: std::f64::consts::PI,
        sigma: 0.01,
        max_range: Some(30.0),
    };
    let mut log = String::from("# a room with two pillars, scanned along a loop\nPARAM robot_front_laser_max 30.0 nohost 0\n");
    for (i, p) in poses.iter().enumerate() {
        let scan = simulate(map, &[], p, &sensor, i as u64).unwrap();
        let ranges: Vec<String> = scan
            .ranges
            .iter()
            .map(|r| format!("{:.3}", r.unwrap_or(30.0)))
            .collect();
        log.push_str(&format!(
            "FLASER 181 {} {:.4} {:.4} {:.5} {:.4} {:.4} {:.5} {}.0 nohost {}.0\n",
            ranges.join(" "),
            p.x,
            p.y,
            p.heading,
            p.x,
            p.y,
            p.heading,
            i,
            i
        ));
    }
    log
}

#[test]
fn the_odd_scans_of_a_log_are_found_in_the_map_of_its_even_scans() {
    let pts = |v: &[(i128, i128)]| v.iter().map(|&(x, y)| Point::new(x, y)).collect::<Vec<_>>();
    let (map, _) = wai_map::Map::from_rings(
        pts(&[(0, 0), (12, 0), (12, 8), (0, 8)]),
        vec![
            pts(&[(3, 3), (4, 3), (4, 4), (3, 4)]),
            pts(&[(8, 5), (9, 5), (9, 6), (8, 6)]),
        ],
    )
    .unwrap();
    // A loop around both pillars, the scanner facing along the path.
    let mut poses = Vec::new();
    for k in 0..80 {
        let t = std::f64::consts::TAU * k as f64 / 80.0;
        let (x, y) = (6.0 + 4.5 * t.cos(), 4.0 + 2.8 * t.sin());
        poses.push(Pose {
            x,
            y,
            heading: t + std::f64::consts::FRAC_PI_2,
        });
    }
    let dir = std::env::temp_dir().join(format!("wai-eval-log-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let log = dir.join("room.log");
    std::fs::write(&log, carmen_log(&map, &poses)).unwrap();
    let out = wai(
        &[
            "eval-log",
            log.to_str().unwrap(),
            "--resolution",
            "0.05",
            "--simplify",
            "0.1",
            "--out",
            dir.to_str().unwrap(),
            "--json",
        ],
        b"",
    );
    assert!(out.status.success(), "{}", text(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["queries"], 40, "{v}");
    assert_eq!(v["map"]["holes"], 2, "the two pillars: {v}");
    assert_eq!(v["query_poses_outside_the_map"], 0, "{v}");
    let rate = |i: usize, key: &str| v["ours"][i]["summary"][key].as_f64().unwrap();
    assert_eq!(v["ours"][0]["compass"], "no compass");
    assert_eq!(v["ours"][1]["compass"], "log heading");
    // The room is symmetric under a half turn but for the pillars: the
    // answer set holds the truth nearly always, the best pose mostly.
    for i in 0..2 {
        assert!(rate(i, "answer_set_contains_truth_rate") >= 0.9, "{v}");
        assert!(rate(i, "success_rate") >= 0.7, "{v}");
    }
    for file in [
        "cdf-room.svg",
        "outcomes-room.csv",
        "eval-log-room.json",
        "room-map.json",
    ] {
        assert!(dir.join(file).exists(), "{file}");
    }
    let csv = std::fs::read_to_string(dir.join("outcomes-room.csv")).unwrap();
    assert_eq!(csv.lines().count(), 1 + 2 * 40);
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn bad_options_and_logs_are_refused() {
    let out = wai(&["eval-log", "/nonexistent.log"], b"");
    assert_ne!(out.status.code(), Some(0));
    assert!(
        text(&out.stderr).contains("/nonexistent.log"),
        "{}",
        text(&out.stderr)
    );
    let dir = std::env::temp_dir().join(format!("wai-eval-log-bad-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let log = dir.join("x.log");
    std::fs::write(&log, "FLASER 3 1 1 1 0 0 0 0 0 0 0.0 h 0.0\n").unwrap();
    let out = wai(
        &["eval-log", log.to_str().unwrap(), "--compass", "sideways"],
        b"",
    );
    assert_eq!(out.status.code(), Some(2), "{}", text(&out.stderr));
    assert!(
        text(&out.stderr).contains("--compass"),
        "{}",
        text(&out.stderr)
    );
    std::fs::remove_dir_all(&dir).ok();
}
