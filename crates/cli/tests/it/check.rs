//! `wai check`: `--help` answers at once; a clean run exits 0 and names
//! what it examined; the planted bug (a T3.2 checker fed a wrong skeleton
//! key) is found within a minute of search, shrunk to a map of at most 12
//! vertices, stored in the format of `counterexamples/`, and replayed; bad
//! usage is refused with a message.

use super::{text, wai};
use std::path::PathBuf;

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("wai-cli-check-{}-{name}", std::process::id()));
    std::fs::remove_dir_all(&d).ok();
    d
}

#[test]
fn help_answers_without_starting_work() {
    let out = wai(&["check", "--help"], b"");
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let help = text(&out.stdout);
    for flag in [
        "--maps",
        "--count",
        "--budget",
        "--seed",
        "--threads",
        "--json",
        "--replay",
        "--plant",
        "--record",
    ] {
        assert!(help.contains(flag), "{flag} missing from: {help}");
    }
}

#[test]
fn a_clean_run_reports_examined_counts_and_exits_0() {
    let out = wai(
        &[
            "check",
            "T3.3a",
            "T5.17",
            "--maps",
            "random-orthogonal:6-10",
            "--count",
            "4",
            "--json",
        ],
        b"",
    );
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
    assert_eq!(v["maps"], 4);
    let claims = v["claims"].as_array().expect("claims");
    assert_eq!(claims.len(), 2);
    assert_eq!(claims[0]["id"], "T3.3a");
    assert!(claims[0]["examined"].as_u64().unwrap() > 0);
    assert_eq!(claims[1]["violations"], 0);
    assert!(claims[1]["max_ratio"].is_string(), "T5.17 measures a ratio");
    assert_eq!(v["counterexamples"], serde_json::json!([]));
}

/// Maps with holes: the claims that assume none are checked on them, the
/// one-ring checkers are named apart, and a stored counterexample keeps
/// its holes (L3.1c: a pillar splits the wall p sees).
#[test]
fn a_run_on_maps_with_holes_names_the_one_ring_checkers_and_stores_holes() {
    let dir = tmp("holes");
    let out = wai(
        &[
            "check",
            "L3.1c",
            "L5.13",
            "T3.3b",
            "--maps",
            "orthogonal-pillars",
            "--count",
            "6",
            "--out",
            dir.to_str().unwrap(),
        ],
        b"",
    );
    let stdout = text(&out.stdout);
    assert_eq!(
        out.status.code(),
        Some(1),
        "{stdout}\n{}",
        text(&out.stderr)
    );
    assert!(
        stdout.contains("checkers that walk one ring, run on the maps without holes only: ")
            && stdout.contains("L5.13"),
        "{stdout}"
    );
    let file = dir.join("L3.1c-check-seed0-map0.json");
    let stored: serde_json::Value =
        serde_json::from_slice(&std::fs::read(&file).expect("a counterexample")).expect("JSON");
    assert!(
        !stored["holes"].as_array().expect("holes").is_empty(),
        "{stored}"
    );
    let replay = wai(&["check", "--replay", file.to_str().unwrap()], b"");
    assert_eq!(replay.status.code(), Some(1), "{}", text(&replay.stdout));
}

#[test]
fn the_planted_bug_is_found_shrunk_stored_and_replayed() {
    let dir = tmp("planted");
    let out = wai(
        &[
            "check",
            "T3.2",
            "--plant",
            "shifted-labels",
            "--maps",
            "random-orthogonal:16-30,random-simple-2opt:16-30",
            "--budget",
            "60s",
            "--first",
            "--out",
            dir.to_str().unwrap(),
        ],
        b"",
    );
    let stdout = text(&out.stdout);
    assert_eq!(
        out.status.code(),
        Some(1),
        "{stdout}\n{}",
        text(&out.stderr)
    );
    assert!(stdout.contains("PLANTED BUG shifted-labels"), "{stdout}");
    let files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .expect("the counterexample folder")
        .map(|e| e.unwrap().path())
        .collect();
    assert_eq!(files.len(), 1, "{files:?}");
    let file = &files[0];
    let name = file.file_name().unwrap().to_string_lossy().into_owned();
    assert!(name.starts_with("T3.2-check-seed0-"), "{name}");
    let stored: serde_json::Value =
        serde_json::from_slice(&std::fs::read(file).unwrap()).expect("JSON");
    assert_eq!(stored["claim"], "T3.2");
    assert_eq!(stored["kind"], "violation");
    assert!(stored["note"].as_str().unwrap().contains("not known yet"));
    let n = stored["outer"].as_array().unwrap().len();
    let found = stored["meta"]["check"]["n_found"].as_u64().unwrap();
    assert!(n <= 12, "shrunk to {n} vertices");
    assert!(found >= 16 && (n as u64) < found, "{found} -> {n}");
    // The stored map is a valid map and still breaks the planted checker.
    let replay = wai(&["check", "--replay", file.to_str().unwrap()], b"");
    assert_eq!(replay.status.code(), Some(1), "{}", text(&replay.stdout));
    assert!(text(&replay.stdout).contains("planted bug shifted-labels"));
    // The file is sealed: with its planted bug edited out it is refused…
    let mut real = stored.clone();
    real["meta"]["check"]["planted"] = serde_json::Value::Null;
    let real_file = dir.join("real.json");
    std::fs::write(&real_file, real.to_string()).unwrap();
    let replay = wai(&["check", "--replay", real_file.to_str().unwrap()], b"");
    assert_eq!(replay.status.code(), Some(1), "{}", text(&replay.stderr));
    assert!(
        text(&replay.stderr).contains("refused: digest.content"),
        "{}",
        text(&replay.stderr)
    );
    // …and as a hand-made copy (no digest) the real T3.2 checker holds there.
    real.as_object_mut().unwrap().remove("digest");
    std::fs::write(&real_file, real.to_string()).unwrap();
    let replay = wai(&["check", "--replay", real_file.to_str().unwrap()], b"");
    assert_eq!(replay.status.code(), Some(0), "{}", text(&replay.stdout));
    assert!(text(&replay.stdout).contains("T3.2 holds on this map"));
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn bad_usage_is_refused_with_a_message() {
    for (args, needle) in [
        (vec!["check", "X9.9"], "no claim X9.9"),
        (vec!["check", "--maps", "nope"], "unknown map kind"),
        (vec!["check", "--chapter", "7"], "chapters 3, 4 and 5"),
        (vec!["check", "--count", "1", "--budget", "1s"], "not both"),
        (vec!["check", "--plant", "nope"], "planted bugs are"),
        (
            vec!["check", "--replay", "/nonexistent/x.json"],
            "/nonexistent/x.json",
        ),
    ] {
        let out = wai(&args, b"");
        let err = text(&out.stderr);
        assert!(matches!(out.status.code(), Some(2 | 3)), "{args:?}: {err}");
        assert!(err.contains(needle), "{args:?}: {err}");
        assert!(!err.contains("panicked"), "{err}");
    }
}
