//! Sharded runs through the command line: the four shards of a run
//! (`wai check --shard I/4 --record …`), merged by `wai merge`, give the
//! unsharded run's record; a missing shard makes a partial merge (exit 1)
//! that names it and the command that re-runs it; a record edited or of
//! another run is refused (exit 3); a checker that panics is caught,
//! stored with its replay command, and the shard goes on.

use super::{text, wai};
use std::path::{Path, PathBuf};

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("wai-cli-shards-{}-{name}", std::process::id()));
    std::fs::remove_dir_all(&d).ok();
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn json(path: &Path) -> serde_json::Value {
    serde_json::from_slice(&std::fs::read(path).unwrap()).expect("JSON")
}

const RUN: [&str; 8] = [
    "check",
    "--maps",
    "random-orthogonal:6-10,random-simple-star:5-9,family:1-2,bytes",
    "--count",
    "30",
    "--seed",
    "5",
    "T3.9a,L3.7,T5.17,O5.3,L4.6",
];

/// `wai check RUN --shard shard --record dir/name`.
fn shard(dir: &Path, shard: &str, name: &str) -> PathBuf {
    let record = dir.join(name);
    let mut args = RUN.to_vec();
    args.extend(["--shard", shard, "--threads", "1", "--record"]);
    args.push(record.to_str().unwrap());
    let out = wai(&args, b"");
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert!(
        text(&out.stdout).starts_with(&format!("wai check shard {shard}:")),
        "{}",
        text(&out.stdout)
    );
    record
}

#[test]
fn four_shards_merge_into_the_unsharded_record() {
    let dir = tmp("equal");
    let whole = dir.join("whole.json");
    let mut args = RUN.to_vec();
    args.extend(["--record", whole.to_str().unwrap()]);
    let out = wai(&args, b"");
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let records: Vec<PathBuf> = (0..4)
        .map(|i| shard(&dir, &format!("{i}/4"), &format!("shard-{i}.json")))
        .collect();
    let s1 = json(&records[1]);
    assert_eq!(s1["shards"]["count"], 4);
    assert_eq!(s1["shards"]["missing"], serde_json::json!([0, 2, 3]));
    let entry = &s1["shards"]["present"][0];
    assert_eq!(entry["index"], 1);
    assert!(entry["binary"].as_str().unwrap().starts_with("sha256:"));
    assert!(entry["started"].as_str().unwrap().ends_with('Z'));
    assert_eq!(
        s1["shards"]["run"],
        "wai check T3.9a,L3.7,T5.17,O5.3,L4.6 --maps random-orthogonal:6-10,random-simple-star:5-9,family:1-2,bytes --count 30 --seed 5"
    );
    // Merged in another order than their indices.
    let merged = dir.join("merged.json");
    let mut args = vec!["merge"];
    args.extend([&records[2], &records[0], &records[3], &records[1]].map(|p| p.to_str().unwrap()));
    args.extend(["--record", merged.to_str().unwrap()]);
    let out = wai(&args, b"");
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert!(
        text(&out.stdout).contains("4 of 4 shards"),
        "{}",
        text(&out.stdout)
    );
    let (a, b) = (json(&whole), json(&merged));
    for key in ["maps", "map_kinds", "claims"] {
        assert_eq!(a[key], b[key], "{key}");
    }
    assert_eq!(b["maps"], 30);
    assert_eq!(b["shards"]["missing"], serde_json::json!([]));
    // The dashboard reads the merge and says where it came from.
    let out = wai(
        &["claims", "--markdown", "--record", merged.to_str().unwrap()],
        b"",
    );
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert!(
        text(&out.stdout).contains("merged from 4 shards"),
        "{}",
        text(&out.stdout)
    );
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn a_missing_shard_is_named_and_its_rerun_completes_the_merge() {
    let dir = tmp("missing");
    let records: Vec<PathBuf> = [0, 1, 3]
        .iter()
        .map(|i| shard(&dir, &format!("{i}/4"), &format!("shard-{i}.json")))
        .collect();
    let partial = dir.join("partial.json");
    let mut args = vec!["merge"];
    args.extend(records.iter().map(|p| p.to_str().unwrap()));
    args.extend(["--record", partial.to_str().unwrap()]);
    let out = wai(&args, b"");
    assert_eq!(out.status.code(), Some(1), "{}", text(&out.stderr));
    let err = text(&out.stderr);
    assert!(err.contains("PARTIAL: 1 of 4 shards missing (2)"), "{err}");
    assert!(err.contains("--shard 2/4"), "{err}");
    assert_eq!(json(&partial)["shards"]["missing"], serde_json::json!([2]));
    let out = wai(&["claims", "--record", partial.to_str().unwrap()], b"");
    assert!(text(&out.stdout).contains("PARTIAL: 1 of 4 shards missing (2)"));
    let out = wai(
        &["claims", "--json", "--record", partial.to_str().unwrap()],
        b"",
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
    assert_eq!(v["run"]["partial"], true);
    // The shard re-run alone, merged with the partial merge.
    let repaired = shard(&dir, "2/4", "shard-2.json");
    let full = dir.join("full.json");
    let out = wai(
        &[
            "merge",
            partial.to_str().unwrap(),
            repaired.to_str().unwrap(),
            "--record",
            full.to_str().unwrap(),
        ],
        b"",
    );
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    // The same as merging the four shards' records at once.
    let at_once = dir.join("at-once.json");
    let mut args = vec!["merge"];
    args.extend(records.iter().map(|p| p.to_str().unwrap()));
    args.extend([
        repaired.to_str().unwrap(),
        "--record",
        at_once.to_str().unwrap(),
    ]);
    assert_eq!(wai(&args, b"").status.code(), Some(0));
    assert_eq!(json(&full), json(&at_once));
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn records_that_do_not_merge_are_refused() {
    let dir = tmp("refused");
    let a = shard(&dir, "0/2", "a.json");
    let refused = |records: &[&Path], needle: &str| {
        let mut args = vec!["merge"];
        args.extend(records.iter().map(|p| p.to_str().unwrap()));
        let out = wai(&args, b"");
        assert_eq!(out.status.code(), Some(3), "{}", text(&out.stdout));
        assert!(
            text(&out.stderr).contains(needle),
            "{needle:?}: {}",
            text(&out.stderr)
        );
    };
    refused(&[&a, &a], "shard 0/2 is in both");
    // Another run: another seed.
    let other = dir.join("other.json");
    let mut args = RUN.to_vec();
    args[6] = "6";
    args.extend(["--shard", "1/2", "--record", other.to_str().unwrap()]);
    assert_eq!(wai(&args, b"").status.code(), Some(0));
    refused(&[&a, &other], "are not of one run: runs");
    // Edited by hand: the digest no longer matches.
    let edited = dir.join("edited.json");
    let text_a = std::fs::read_to_string(&a).unwrap();
    std::fs::write(
        &edited,
        text_a.replacen("\"violations\": 0", "\"violations\": 1", 1),
    )
    .unwrap();
    refused(&[&edited], "digest");
    refused(&[Path::new("/nonexistent/shard.json")], "cannot read");
    // Bad --shard values are usage errors.
    for bad in ["2/2", "1/0", "x"] {
        let mut args = RUN.to_vec();
        args.extend(["--shard", bad]);
        assert_eq!(wai(&args, b"").status.code(), Some(2), "{bad}");
    }
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn a_checker_that_panics_is_stored_and_the_shard_goes_on() {
    let dir = tmp("panic");
    let record = dir.join("shard.json");
    let out_dir = dir.join("found");
    let out = wai(
        &[
            "check",
            "T3.2,T5.17",
            "--plant",
            "panics",
            "--maps",
            "random-orthogonal:6-12",
            "--count",
            "24",
            "--shard",
            "1/2",
            "--record",
            record.to_str().unwrap(),
            "--out",
            out_dir.to_str().unwrap(),
        ],
        b"",
    );
    // A counterexample: exit 1, and every map of the shard was checked.
    assert_eq!(out.status.code(), Some(1), "{}", text(&out.stderr));
    let stdout = text(&out.stdout);
    assert!(
        stdout.contains("the checker panicked: planted panic"),
        "{stdout}"
    );
    let r = json(&record);
    assert_eq!(r["maps"], 12);
    let t317 = r["claims"]
        .as_array()
        .unwrap()
        .iter()
        .find(|c| c["id"] == "T5.17")
        .unwrap();
    assert_eq!(t317["examined"], 12);
    let files = r["shards"]["present"][0]["counterexamples"]
        .as_array()
        .unwrap();
    assert_eq!(files.len(), 1);
    let file = files[0].as_str().unwrap();
    let stored: serde_json::Value = json(Path::new(file));
    let replay = stored["meta"]["check"]["replay"].as_str().unwrap();
    assert_eq!(replay, format!("wai check --replay {file}"));
    // The replay runs the planted checker again: still a panic, caught.
    let out = wai(&["check", "--replay", file], b"");
    assert_eq!(out.status.code(), Some(1), "{}", text(&out.stderr));
    assert!(text(&out.stdout).contains("VIOLATION: the checker panicked"));
    std::fs::remove_dir_all(dir).ok();
}
