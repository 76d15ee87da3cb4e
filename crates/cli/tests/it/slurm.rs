//! The Slurm scripts on a real one-node Slurm cluster
//! (`scripts/slurm/local-cluster start`, which `.ci/run` runs): a run
//! submitted as a 4-shard job array (`scripts/slurm/submit`) merges, in
//! the merge job that follows the array, into the unsharded run's record;
//! a shard cancelled while it runs (`scancel`) is named missing by that
//! merge, which is marked partial, and submitting again runs that shard
//! alone and completes the merge with the same result.
//!
//! Without a running cluster the test says SKIPPED; in CI (`WAI_CI`) it
//! fails instead.

use super::text;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

fn repo() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// `SLURM_CONF` of the local cluster, if it takes jobs.
fn cluster() -> Option<String> {
    let script = repo().join("scripts/slurm/local-cluster");
    let up = Command::new(&script).arg("status").status().ok()?.success();
    if !up {
        return None;
    }
    let env = Command::new(&script).arg("env").output().ok()?;
    let line = text(&env.stdout);
    Some(
        line.trim()
            .trim_start_matches("export SLURM_CONF=")
            .to_owned(),
    )
}

fn slurm(conf: &str, program: &str, args: &[&str]) -> std::process::Output {
    Command::new(program)
        .args(args)
        .env("SLURM_CONF", conf)
        .output()
        .unwrap_or_else(|e| panic!("{program}: {e}"))
}

/// The state of job `id` (`R`, `PD`, …), or `None` once it left the queue.
fn state(conf: &str, id: &str) -> Option<String> {
    let out = slurm(conf, "squeue", &["-h", "-j", id, "-o", "%t"]);
    let s = text(&out.stdout).trim().to_owned();
    (out.status.success() && !s.is_empty()).then_some(s)
}

fn wait_gone(conf: &str, id: &str) {
    let start = Instant::now();
    while state(conf, id).is_some() {
        assert!(
            start.elapsed() < Duration::from_secs(600),
            "job {id} still queued after 10 minutes"
        );
        std::thread::sleep(Duration::from_millis(300));
    }
}

const RUN: [&str; 8] = [
    "--maps",
    "random-orthogonal:8-14,repeated-niches,bytes",
    "--count",
    "320",
    "--seed",
    "3",
    "T3.9a,L3.7,T4.2,L4.6,T5.17,O5.3",
    "--no-shrink",
];

/// `scripts/slurm/submit dir 4 -- RUN` with `bin` as the shards' binary:
/// (array job, merge job).
fn submit(conf: &str, dir: &Path, bin: &Path) -> (String, String) {
    let mut args = vec![dir.to_str().unwrap(), "4", "--"];
    args.extend(RUN);
    let out = Command::new(repo().join("scripts/slurm/submit"))
        .args(&args)
        .env("SLURM_CONF", conf)
        .env("WAI_BIN", bin)
        // A test may run from a checkout with changes: the shards say
        // +dirty and are merged because one binary ran them.
        .env("WAI_ALLOW_DIRTY", "1")
        .output()
        .expect("submit runs");
    assert!(out.status.success(), "{}", text(&out.stderr));
    let ids: Vec<String> = text(&out.stdout)
        .split_whitespace()
        .map(str::to_owned)
        .collect();
    assert_eq!(ids.len(), 2, "{}", text(&out.stdout));
    (ids[0].clone(), ids[1].clone())
}

fn json(path: &Path) -> serde_json::Value {
    serde_json::from_slice(
        &std::fs::read(path).unwrap_or_else(|e| panic!("{}: {e}", path.display())),
    )
    .expect("JSON")
}

fn same_run(a: &serde_json::Value, b: &serde_json::Value) {
    for key in ["maps", "map_kinds", "claims"] {
        assert_eq!(a[key], b[key], "{key}");
    }
}

#[test]
fn a_job_array_merges_into_the_unsharded_run_and_a_cancelled_shard_is_repaired() {
    let Some(conf) = cluster() else {
        assert!(
            std::env::var_os("WAI_CI").is_none(),
            "CI requires the local Slurm cluster: scripts/slurm/local-cluster start"
        );
        eprintln!("SKIPPED: no local Slurm cluster (scripts/slurm/local-cluster start)");
        return;
    };
    let base = std::env::temp_dir().join(format!("wai-slurm-{}", std::process::id()));
    std::fs::remove_dir_all(&base).ok();
    std::fs::create_dir_all(&base).unwrap();
    // The unsharded run.
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
    assert_eq!(whole["maps"], 320);

    // Four shards and their merge job.
    let dir = base.join("run");
    let wai = Path::new(env!("CARGO_BIN_EXE_wai"));
    let (_, merge) = submit(&conf, &dir, wai);
    wait_gone(&conf, &merge);
    let merged = json(&dir.join("merged.json"));
    same_run(&merged, &whole);
    assert_eq!(merged["shards"]["missing"], serde_json::json!([]));
    assert_eq!(merged["shards"]["present"].as_array().unwrap().len(), 4);

    // Shard 2 cancelled while it runs: the merge names it missing. A shard
    // of 80 maps can finish between two polls of squeue, so shard 2 runs
    // through a wrapper that holds it (as a running task) until cancelled;
    // the other shards run the binary at once.
    let dir = base.join("cancelled");
    let held = base.join("wai-holding-shard-2");
    std::fs::write(
        &held,
        format!(
            "#!/bin/sh\ncase \" $* \" in *' 2/4 '*) sleep 3600 ;; esac\nexec '{}' \"$@\"\n",
            wai.display()
        ),
    )
    .unwrap();
    {
        use std::os::unix::fs::PermissionsExt;
        std::fs::set_permissions(&held, std::fs::Permissions::from_mode(0o755)).unwrap();
    }
    let (array, merge) = submit(&conf, &dir, &held);
    let task = format!("{array}_2");
    let start = Instant::now();
    loop {
        match state(&conf, &task).as_deref() {
            Some("R") => break,
            Some(_) => {}
            None => panic!("shard 2 left the queue before it could be cancelled"),
        }
        assert!(
            start.elapsed() < Duration::from_secs(300),
            "shard 2 never ran"
        );
        std::thread::sleep(Duration::from_millis(100));
    }
    let out = slurm(&conf, "scancel", &[&task]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    wait_gone(&conf, &merge);
    assert!(
        !dir.join("shard-2.json").exists(),
        "a cancelled shard leaves no record"
    );
    let partial = json(&dir.join("merged.json"));
    assert_eq!(partial["shards"]["missing"], serde_json::json!([2]));
    let log = std::fs::read_dir(dir.join("slurm"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .find(|p| {
            p.file_name()
                .unwrap()
                .to_string_lossy()
                .starts_with("merge-")
        })
        .expect("the merge job's output");
    let said = std::fs::read_to_string(log).unwrap();
    assert!(
        said.contains("PARTIAL: 1 of 4 shards missing (2)"),
        "{said}"
    );

    // Submitted again: shard 2 alone, then the merge, equal to the whole.
    let (array, merge) = submit(&conf, &dir, wai);
    let out = slurm(&conf, "squeue", &["-h", "-j", &array, "-o", "%K"]);
    let tasks = text(&out.stdout);
    assert!(tasks.trim().is_empty() || tasks.trim() == "2", "{tasks}");
    wait_gone(&conf, &merge);
    let repaired = json(&dir.join("merged.json"));
    same_run(&repaired, &whole);
    assert_eq!(repaired["shards"]["missing"], serde_json::json!([]));
    std::fs::remove_dir_all(&base).ok();
}
