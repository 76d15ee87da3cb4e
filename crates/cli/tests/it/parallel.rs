//! `scripts/parallel/check.sh`: a run as three shards under GNU parallel
//! merges into the unsharded run's record; with one record removed (a
//! shard that failed or was killed), the same command runs that shard
//! alone and the merge is the same again.
//!
//! Without GNU parallel the test says SKIPPED; in CI (`WAI_CI`, whose
//! `.ci/run` installs it) it fails instead.

use super::text;
use std::path::Path;
use std::process::Command;

const RUN: [&str; 7] = [
    "--maps",
    "random-orthogonal:6-12,random-simple-star:5-9,bytes",
    "--count",
    "45",
    "--seed",
    "8",
    "T3.9a,L3.7,T5.17,O5.3",
];

fn json(path: &Path) -> serde_json::Value {
    serde_json::from_slice(
        &std::fs::read(path).unwrap_or_else(|e| panic!("{}: {e}", path.display())),
    )
    .expect("JSON")
}

/// `check.sh dir 3 --jobs 2 -- RUN`: its exit status and standard error.
fn check_sh(dir: &Path) -> (Option<i32>, String) {
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scripts/parallel/check.sh");
    let mut args = vec![dir.to_str().unwrap(), "3", "--jobs", "2"];
    args.extend(["--wai", env!("CARGO_BIN_EXE_wai"), "--"]);
    args.extend(RUN);
    let out = Command::new(script)
        .args(&args)
        // A test may run from a checkout with changes (one binary runs
        // every shard, so they merge).
        .env("WAI_ALLOW_DIRTY", "1")
        .output()
        .expect("check.sh runs");
    (out.status.code(), text(&out.stderr))
}

#[test]
fn three_shards_under_gnu_parallel_merge_and_resume() {
    let has_parallel = Command::new("parallel")
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success());
    if !has_parallel {
        assert!(
            std::env::var_os("WAI_CI").is_none(),
            "CI requires GNU parallel (apt-get install parallel)"
        );
        eprintln!("SKIPPED: GNU parallel is not installed");
        return;
    }
    let base = std::env::temp_dir().join(format!("wai-parallel-{}", std::process::id()));
    std::fs::remove_dir_all(&base).ok();
    std::fs::create_dir_all(&base).unwrap();
    let whole = base.join("whole.json");
    let mut args = vec!["check"];
    args.extend(RUN);
    args.extend(["--record", whole.to_str().unwrap()]);
    let out = Command::new(env!("CARGO_BIN_EXE_wai"))
        .args(&args)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let whole = json(&whole);

    let dir = base.join("run");
    let (code, err) = check_sh(&dir);
    assert_eq!(code, Some(0), "{err}");
    assert!(
        err.contains("0 of 3 shards have a record; running 3"),
        "{err}"
    );
    let merged = json(&dir.join("merged.json"));
    for key in ["maps", "map_kinds", "claims"] {
        assert_eq!(merged[key], whole[key], "{key}");
    }
    assert_eq!(merged["shards"]["missing"], serde_json::json!([]));

    // Shard 1's record gone: the same command runs it alone.
    std::fs::remove_file(dir.join("shard-1.json")).unwrap();
    let (code, err) = check_sh(&dir);
    assert_eq!(code, Some(0), "{err}");
    assert!(
        err.contains("2 of 3 shards have a record; running 1"),
        "{err}"
    );
    let again = json(&dir.join("merged.json"));
    for key in ["maps", "map_kinds", "claims"] {
        assert_eq!(again[key], whole[key], "{key}");
    }
    // Every attempt is in the job log: three, then one.
    let log = std::fs::read_to_string(dir.join("joblog")).unwrap();
    let attempts = log.lines().filter(|l| l.contains("--shard ")).count();
    assert_eq!(attempts, 4, "{log}");
    std::fs::remove_dir_all(&base).ok();
}
