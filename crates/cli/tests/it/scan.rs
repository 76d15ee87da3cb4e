//! `wai scan`: `--help` answers at once; a scan of a square room has the
//! ranges to its walls, is seeded, and bad poses and settings are refused
//! with a message.

use super::{text, wai};

const SQUARE: &[u8] = br#"{"outer": [["0", "0"], ["4", "0"], ["4", "4"], ["0", "4"]]}"#;

#[test]
fn help_answers_without_starting_work() {
    let out = wai(&["scan", "--help"], b"");
    assert_eq!(out.status.code(), Some(0));
    let help = text(&out.stdout);
    for flag in [
        "--at",
        "--noise",
        "--beams",
        "--fov",
        "--max-range",
        "--obstacles",
        "--seed",
    ] {
        assert!(help.contains(flag), "{flag} missing from: {help}");
    }
}

#[test]
fn a_scan_of_a_square_room_has_the_ranges_to_its_walls() {
    let out = wai(&["scan", "-", "--at", "1,2,90", "--beams", "4"], SQUARE);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
    let ranges: Vec<f64> = v["ranges"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| r.as_f64().unwrap())
        .collect();
    // Heading 90°: beams at -180°, -90°, 0°, 90° relative to it look
    // down, right, up and left.
    for (got, want) in ranges.iter().zip([2.0, 3.0, 2.0, 1.0]) {
        assert!((got - want).abs() < 1e-9, "{ranges:?}");
    }
    assert_eq!(v["sensor"]["beams"], 4);
    let noisy = |seed: &str| {
        wai(
            &[
                "scan",
                "-",
                "--at",
                "1,2",
                "--noise",
                "0.05",
                "--seed",
                seed,
                "--obstacles",
                "2",
            ],
            SQUARE,
        )
        .stdout
    };
    assert_eq!(noisy("3"), noisy("3"));
    assert_ne!(noisy("3"), noisy("4"));
}

#[test]
fn bad_poses_and_settings_are_refused() {
    // From a file: some refusals come before standard input would be read.
    let file = std::env::temp_dir().join(format!("wai-scan-square-{}.json", std::process::id()));
    std::fs::write(&file, SQUARE).unwrap();
    let f = file.to_str().unwrap();
    for (args, code, needle) in [
        (vec!["scan", f, "--at", "9,1"], 1, "outside the map"),
        (vec!["scan", f, "--at", "0,1"], 1, "on the map's boundary"),
        (vec!["scan", f, "--at", "1"], 2, "expected x,y"),
        (vec!["scan", f, "--at", "1,x"], 2, "not a number"),
        (
            vec!["scan", f, "--at", "1,1", "--beams", "0"],
            2,
            "expected a whole number ≥ 1",
        ),
        (vec!["scan", f, "--at", "1,1", "--noise", "-1"], 2, "noise"),
    ] {
        let out = wai(&args, b"");
        let err = text(&out.stderr);
        assert_eq!(out.status.code(), Some(code), "{args:?}: {err}");
        assert!(err.contains(needle), "{args:?}: {err}");
        assert!(!err.contains("panicked"));
    }
    std::fs::remove_file(&file).ok();
}

/// An L-shaped room of about 23 × 17 m, in longitude and latitude.
const LONLAT_L: &str = r#"{"outer": [["8", "47"], ["8.0003", "47"], ["8.0003", "47.0001"],
    ["8.00015", "47.0001"], ["8.00015", "47.00015"], ["8", "47.00015"]]}"#;

#[test]
fn a_lonlat_map_is_localized_in_a_stated_frame_and_answered_in_lonlat() {
    let dir = std::env::temp_dir().join(format!("wai-lonlat-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let map = dir.join("l.json");
    std::fs::write(&map, LONLAT_L).unwrap();
    let map = map.to_str().unwrap();
    // The pose is in metres of the frame: 5 m east, 4 m north of the corner.
    let scan = wai(&["scan", map, "--at", "5,4,30", "--beams", "360"], b"");
    assert_eq!(scan.status.code(), Some(0), "{}", text(&scan.stderr));
    let scan_file = dir.join("s.json");
    std::fs::write(&scan_file, &scan.stdout).unwrap();
    let s = scan_file.to_str().unwrap();
    let out = wai(&["localize-scan", map, s, "--json"], b"");
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
    assert_eq!(v["units"], "lonlat");
    let frame = &v["frame"];
    assert_eq!(
        (frame["lon0"].as_f64(), frame["lat0"].as_f64()),
        (Some(8.0), Some(47.0))
    );
    assert!(frame["description"]
        .as_str()
        .unwrap()
        .contains("south-west"));
    let best = &v["best"]["pose"];
    let (x, y) = (best["x"].as_f64().unwrap(), best["y"].as_f64().unwrap());
    assert!((x - 5.0).abs() < 0.1 && (y - 4.0).abs() < 0.1, "{best}");
    // The same pose in degrees: a metre is about 1.3e-5° of longitude and
    // 9.0e-6° of latitude at 47° N.
    let (lon, lat) = (best["lon"].as_f64().unwrap(), best["lat"].as_f64().unwrap());
    let east = frame["east_metres_per_degree"].as_f64().unwrap();
    let north = frame["north_metres_per_degree"].as_f64().unwrap();
    assert!((75_000.0..76_500.0).contains(&east), "{east}");
    assert!((111_000.0..111_400.0).contains(&north), "{north}");
    assert!((lon - (8.0 + x / east)).abs() < 1e-9, "{lon}");
    assert!((lat - (47.0 + y / north)).abs() < 1e-9, "{lat}");
    // The text answer says the frame and gives the pose in degrees too.
    let out = text(&wai(&["localize-scan", map, s], b"").stdout);
    assert!(out.contains("frame: x east, y north in metres"), "{out}");
    assert!(out.contains("lon 8.0000"), "{out}");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn units_stated_in_the_map_file_come_before_the_guess() {
    let dir = std::env::temp_dir().join(format!("wai-units-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    // A 5 × 4 cm box looks like degrees to the guess unless it says it is
    // in metres; a box of 0.0005° × 0.0004° is guessed right; a plan in
    // centimetres states its scale.
    let cases = [
        (r#""units": "m", "#, "0.05", "0.04", "m", "0.02,0.02"),
        ("", "0.0005", "0.0004", "lonlat", "2,2"),
        (
            r#""units": "scale:0.01", "#,
            "500",
            "400",
            "scale:0.01",
            "2,2",
        ),
    ];
    for (i, (units, w, h, want, at)) in cases.into_iter().enumerate() {
        let map = dir.join(format!("m{i}.json"));
        std::fs::write(
            &map,
            format!(
                r#"{{{units}"outer": [["0", "0"], ["{w}", "0"], ["{w}", "{h}"], ["0", "{h}"]]}}"#
            ),
        )
        .unwrap();
        let map = map.to_str().unwrap();
        let scan = wai(&["scan", map, "--at", at, "--beams", "90"], b"");
        assert_eq!(scan.status.code(), Some(0), "{}", text(&scan.stderr));
        let s = dir.join(format!("s{i}.json"));
        std::fs::write(&s, &scan.stdout).unwrap();
        let out = wai(&["localize-scan", map, s.to_str().unwrap(), "--json"], b"");
        assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
        let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        assert_eq!(v["units"], want, "{units}");
        assert_eq!(v["frame"].is_null(), want != "lonlat", "{units}");
    }
    std::fs::remove_dir_all(&dir).ok();
}
