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
