//! `wai localize` and `wai preprocess`: every answer on a map with repeated
//! rooms, the empty answer with its reason, and clear errors for bad
//! polygons.

use super::{text, wai};
use std::path::{Path, PathBuf};
use wai_cells::Decomposition;
use wai_localize::{Localizer, RobotView};
use wai_visibility::VisibilityIndex;

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("wai-cli-localize-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d.join(name)
}

/// corridor-niches with `k` niches, written to a temporary file.
fn niches_file(name: &str, k: u32) -> PathBuf {
    let file = tmp(name);
    let map = wai_gen::family("corridor-niches", &[k]).unwrap();
    std::fs::write(&file, wai_map::json::to_json(&map)).unwrap();
    file
}

/// `wai localize MAP --polygon POLY` and `extra` arguments.
fn localize_polygon(map: &Path, poly: &Path, extra: &[&str]) -> std::process::Output {
    let mut args = vec![
        "localize",
        map.to_str().unwrap(),
        "--polygon",
        poly.to_str().unwrap(),
    ];
    args.extend_from_slice(extra);
    wai(&args, b"")
}

fn json(out: &std::process::Output) -> serde_json::Value {
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    serde_json::from_slice(&out.stdout).expect("JSON on stdout")
}

#[test]
fn repeated_rooms_answer_with_every_room_also_from_a_preprocessed_file() {
    let map = wai_gen::family("corridor-niches", &[4]).unwrap();
    let file = tmp("niches.json");
    std::fs::write(&file, wai_map::json::to_json(&map)).unwrap();
    // The cell with the most answers, found through the library.
    let d = Decomposition::new(&map);
    let loc = Localizer::from_decomposition(&d);
    let index = VisibilityIndex::new(&map);
    let (best, p) = d
        .cells()
        .iter()
        .map(|&c| {
            let p = d.representative(c).clone();
            let v = RobotView::from_visibility(&index.visibility_polygon(&p).unwrap());
            (loc.localize(&v).placements.len(), p)
        })
        .max_by_key(|(a, _)| *a)
        .unwrap();
    assert!(best >= 4);
    let at = format!("{}/{},{}/{}", p.hx(), p.hw(), p.hy(), p.hw());
    let direct = json(&wai(
        &["localize", file.to_str().unwrap(), "--at", &at, "--json"],
        b"",
    ));
    let answers = direct["answers"].as_array().unwrap();
    assert_eq!(answers.len(), best, "{direct}");
    assert!(direct["class"].is_u64());
    // Every answer names its origin vertex and an exact position.
    for a in answers {
        assert!(a["origin_vertex"].is_u64());
        assert_eq!(a["position"].as_array().unwrap().len(), 2);
    }
    let pre = tmp("niches.wai.json");
    let out = wai(
        &[
            "preprocess",
            file.to_str().unwrap(),
            "-o",
            pre.to_str().unwrap(),
        ],
        b"",
    );
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let svg = tmp("answers.svg");
    let again = json(&wai(
        &[
            "localize",
            pre.to_str().unwrap(),
            "--at",
            &at,
            "--json",
            "--svg",
            svg.to_str().unwrap(),
        ],
        b"",
    ));
    assert_eq!(direct, again, "the preprocessed file answers the same");
    // The map on standard input, read once.
    let piped = json(&wai(
        &["localize", "-", "--at", &at, "--json"],
        wai_map::json::to_json(&map).as_bytes(),
    ));
    assert_eq!(direct, piped, "a map on standard input answers the same");
    assert!(std::fs::read_to_string(&svg)
        .unwrap()
        .contains(&format!("{best} answers")));
}

#[test]
fn a_polygon_nothing_sees_gets_the_empty_answer_and_the_reason() {
    let file = niches_file("niches2.json", 2);
    let poly = tmp("square.json");
    std::fs::write(&poly, r#"[["-1","-1"],["1","-1"],["1","1"],["-1","1"]]"#).unwrap();
    let out = localize_polygon(&file, &poly, &["--json"]);
    let v = json(&out);
    assert_eq!(v["answers"].as_array().unwrap().len(), 0);
    assert!(
        v["reason"]
            .as_str()
            .unwrap()
            .contains("no cell of the map has"),
        "{v}"
    );
    let out = localize_polygon(&file, &poly, &[]);
    assert!(
        text(&out.stdout).starts_with("no position: "),
        "{}",
        text(&out.stdout)
    );
}

#[test]
fn bad_polygons_get_a_clear_error_and_a_nonzero_exit() {
    let file = niches_file("niches3.json", 2);
    let cases: [(&str, &str, &str); 5] = [
        (
            "c.json",
            r#"[[-2,-2],[2,-2],[2,2],[1,2],[1,1],[-2,1]]"#,
            "not star-shaped",
        ),
        (
            "star.json",
            r#"[[10,0],[-8,6],[3,-10],[3,10],[-8,-6]]"#,
            "winds 2 times",
        ),
        (
            "robot.json",
            r#"{"vertices": [[-1,0],[1,0],[0,1]]}"#,
            "passes through the robot",
        ),
        (
            "bad.json",
            r#"[["1","x"],[0,1],[-1,0]]"#,
            "not an exact number",
        ),
        ("trunc.json", r#"[[1,0],[0,1"#, "not JSON"),
    ];
    for (name, body, needle) in cases {
        let poly = tmp(name);
        std::fs::write(&poly, body).unwrap();
        let out = localize_polygon(&file, &poly, &[]);
        let err = text(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{name}: {err}");
        assert!(err.contains(needle), "{name}: {err}");
        assert!(!err.contains("panicked"), "{err}");
    }
    // Both or neither of --at and --polygon: a usage error.
    let out = wai(&["localize", file.to_str().unwrap()], b"");
    assert_eq!(out.status.code(), Some(2), "{}", text(&out.stderr));
    // A damaged preprocessed file is refused.
    let pre = tmp("damaged.json");
    std::fs::write(&pre, r#"{"format": "wai-localizer", "version": 99}"#).unwrap();
    let out = wai(&["localize", pre.to_str().unwrap(), "--at", "1,1"], b"");
    assert_eq!(out.status.code(), Some(1));
    assert!(
        text(&out.stderr).contains("version 99"),
        "{}",
        text(&out.stderr)
    );
}
