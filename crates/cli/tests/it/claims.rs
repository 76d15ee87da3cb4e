//! `wai claims`: README.md's claims table is what the command generates
//! from `lemmas/last-run.json` and the registry; `--json` has the keys the
//! dashboard reads; `--help` answers at once; a missing or malformed record is a
//! clear error (exit 3).

use super::{text, wai};
use std::path::{Path, PathBuf};

const README: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../../README.md");
const RECORD: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../../lemmas/last-run.json");
const START: &str = "<!-- claims-table:start -->\n";
const END: &str = "<!-- claims-table:end -->";
const REGENERATE: &str =
    "cargo run --release -p wai-cli -- claims --markdown --write-readme README.md";

fn tmp(name: &str) -> PathBuf {
    std::env::temp_dir().join(format!("wai-cli-claims-{}-{name}", std::process::id()))
}

/// `wai claims` with `args` must fail with exit 3, nothing on stdout, and
/// a message containing every one of `needles`.
fn check_fails(args: &[&str], needles: &[&str]) {
    let out = wai(args, b"");
    let err = text(&out.stderr);
    assert_eq!(out.status.code(), Some(3), "{args:?}: {err}");
    assert!(!err.contains("panicked"), "{err}");
    assert!(err.starts_with("error: "), "{err}");
    for n in needles {
        assert!(err.contains(n), "missing {n:?} in: {err}");
    }
    assert!(out.stdout.is_empty(), "nothing on stdout when failing");
}

#[test]
fn readme_table_is_up_to_date() {
    let readme = std::fs::read_to_string(README).expect("README.md is readable");
    let start = readme.find(START).expect("README.md has the start marker") + START.len();
    let end = start
        + readme[start..]
            .find(END)
            .expect("README.md has the end marker");
    let out = wai(&["claims", "--markdown"], b"");
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let generated = text(&out.stdout);
    assert!(
        readme[start..end] == generated,
        "README.md's claims table is stale (the registry or lemmas/last-run.json changed); \
         regenerate it with `{REGENERATE}`"
    );
}

#[test]
fn write_readme_rewrites_only_the_table() {
    let path = tmp("readme.md");
    let before = format!("# Title\n\n{START}stale\n{END}\n\nafter\n");
    std::fs::write(&path, &before).unwrap();
    let out = wai(
        &[
            "claims",
            "--markdown",
            "--write-readme",
            path.to_str().unwrap(),
        ],
        b"",
    );
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert!(out.stdout.is_empty());
    let after = std::fs::read_to_string(&path).unwrap();
    let table = text(&wai(&["claims", "--markdown"], b"").stdout);
    assert_eq!(after, format!("# Title\n\n{START}{table}{END}\n\nafter\n"));
    std::fs::write(&path, "no markers here\n").unwrap();
    check_fails(
        &[
            "claims",
            "--markdown",
            "--write-readme",
            path.to_str().unwrap(),
        ],
        &["no line <!-- claims-table:start -->"],
    );
    std::fs::remove_file(path).ok();
}

#[test]
fn json_has_every_claim_with_its_keys() {
    let out = wai(&["claims", "--json"], b"");
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    for key in ["command", "commit", "date", "seconds", "maps", "map_kinds"] {
        assert!(!v["run"][key].is_null(), "run.{key} missing: {}", v["run"]);
    }
    let claims = v["claims"].as_array().unwrap();
    let ids: Vec<&str> = claims.iter().map(|c| c["id"].as_str().unwrap()).collect();
    let registry: Vec<&str> = wai_lemmas::CLAIMS.iter().map(|c| c.id).collect();
    assert_eq!(ids, registry, "every claim, in catalogue order");
    for c in claims {
        for key in [
            "id",
            "kind",
            "checker",
            "examined",
            "violations",
            "known_failures",
            "max_ratio",
            "max_ratio_approx",
            "max_ratio_map",
            "cases",
            "cases_never_hit",
        ] {
            assert!(c.get(key).is_some(), "{key} missing from {c}");
        }
    }
    let t517 = claims.iter().find(|c| c["id"] == "T5.17").unwrap();
    assert_eq!(t517["checker"], "wai_lemmas::ch5::t5_17");
    assert_eq!(t517["kind"], "bound");
    // Every claim has its checker.
    for c in claims {
        assert!(c["checker"].is_string(), "no checker: {c}");
    }
    // Each exact ratio reads back as a rational.
    for c in claims.iter().filter(|c| !c["max_ratio"].is_null()) {
        let q: rug::Rational = c["max_ratio"].as_str().unwrap().parse().unwrap();
        assert!(q >= 0, "{c}");
        assert!(c["max_ratio_approx"].is_number(), "{c}");
    }
}

/// A record that covers two claims, one of them examined 0 times: every
/// other checked claim reads "not run", the empty one "NOT TESTED".
#[test]
fn untested_and_unrun_claims_are_named() {
    let path = tmp("partial.json");
    let hand_made: serde_json::Value = serde_json::from_str(
        r#"{"version": 2, "command": "hand-made", "commit": "abc", "date": "2025-01-31",
            "seconds": 1, "maps": 1, "map_kinds": [{"kind": "square", "maps": 1}],
            "claims": [
              {"id": "T5.17", "examined": 1, "violations": 0, "known_failures": 0,
               "max_ratio": "80/41", "max_ratio_map": "square", "cases": {}, "counts": {}},
              {"id": "L4.6", "examined": 0, "violations": 0, "known_failures": 0,
               "max_ratio": null, "max_ratio_map": null, "cases": {}, "counts": {}}]}"#,
    )
    .unwrap();
    // Sealed as `wai check --record` seals what it writes.
    let sealed = wai_hunt::record::RunRecord::from_json_unsealed(&hand_made)
        .unwrap()
        .to_json();
    std::fs::write(&path, sealed.to_string()).unwrap();
    let out = wai(&["claims", "--record", path.to_str().unwrap()], b"");
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let s = text(&out.stdout);
    let line = |id: &str| -> String {
        s.lines()
            .find(|l| l.split_whitespace().next() == Some(id))
            .unwrap_or_else(|| panic!("no line for {id} in {s}"))
            .to_owned()
    };
    assert!(s.contains("command  hand-made"), "{s}");
    assert!(line("T5.17").contains("80/41 ≈ 1.9512 on square"), "{s}");
    assert!(line("L4.6").contains("0 — NOT TESTED"), "{s}");
    assert!(line("T4.2").contains("not run"), "{s}");
    assert!(line("C3.8").contains("not run"), "{s}");
    assert!(s.contains("1 NOT TESTED (0 examined): L4.6"), "{s}");
    let out = wai(
        &["claims", "--json", "--record", path.to_str().unwrap()],
        b"",
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let claim = |id: &str| -> serde_json::Value {
        v["claims"]
            .as_array()
            .unwrap()
            .iter()
            .find(|c| c["id"] == id)
            .unwrap()
            .clone()
    };
    assert_eq!(claim("T5.17")["max_ratio"], "80/41");
    assert_eq!(claim("L4.6")["status"], "not tested");
    assert!(claim("T4.2")["examined"].is_null());
    assert_eq!(claim("T4.2")["status"], "not run");
    std::fs::remove_file(path).ok();
}

#[test]
fn help_answers_without_starting_work() {
    let out = wai(&["claims", "--help"], b"");
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let help = text(&out.stdout);
    for flag in ["--json", "--record", "--markdown", "--write-readme"] {
        assert!(help.contains(flag), "{flag} missing from: {help}");
    }
}

#[test]
fn missing_or_malformed_records_are_clear_errors() {
    check_fails(
        &["claims", "--record", "/nonexistent/run.json"],
        &["/nonexistent/run.json", "cannot read the run record"],
    );
    let path = tmp("bad.json");
    let p = path.to_str().unwrap();
    std::fs::write(&path, "{\"version\": 1, ").unwrap();
    check_fails(&["claims", "--record", p], &[p, "malformed JSON"]);
    let good = std::fs::read_to_string(RECORD).expect("lemmas/last-run.json");
    let bad = good.replacen("\"examined\": ", "\"examined\": -", 1);
    std::fs::write(&path, bad).unwrap();
    check_fails(
        &["claims", "--json", "--record", p],
        &[p, "claims[0].examined: expected a non-negative integer"],
    );
    // A count raised by hand, consistent in itself, breaks the seal.
    let edited = good.replacen("\"examined\": ", "\"examined\": 1", 1);
    std::fs::write(&path, edited).unwrap();
    check_fails(
        &["claims", "--record", p],
        &[
            p,
            "digest: the content was changed after `wai check` wrote it",
        ],
    );
    std::fs::remove_file(&path).ok();
    assert!(!Path::new(&path).exists());
}

/// The record is found under the repository the command is run in, never
/// through the path the binary was built at: outside any copy of the
/// repository `wai claims` says so (exit 3) unless given `--record`, and
/// from any folder inside it, it reads that copy's record.
#[test]
fn the_record_is_found_from_the_current_directory() {
    let outside = tmp("outside");
    std::fs::create_dir_all(&outside).unwrap();
    let run_in = |dir: &Path, args: &[&str]| {
        std::process::Command::new(env!("CARGO_BIN_EXE_wai"))
            .args(args)
            .current_dir(dir)
            .output()
            .expect("the wai binary runs")
    };
    let out = run_in(&outside, &["claims"]);
    let err = text(&out.stderr);
    assert_eq!(out.status.code(), Some(3), "{err}");
    assert!(err.contains("not inside a copy of this repository") && err.contains("--record"));

    let out = run_in(&outside, &["claims", "--record", RECORD]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));

    let inside = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let out = run_in(&inside, &["claims"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let repo = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let record = repo.canonicalize().unwrap().join("lemmas/last-run.json");
    assert!(text(&out.stdout).contains(&record.display().to_string()));
    std::fs::remove_dir_all(&outside).ok();
}
