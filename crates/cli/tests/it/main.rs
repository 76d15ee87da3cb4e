//! End-to-end tests of the `wai` binary: every bad input gives one clear
//! message naming what and where, a non-zero exit and no panic.

use std::io::Write;
use std::path::Path;
use std::process::{Command, Output, Stdio};

/// `wai args` started with its standard output and error piped.
fn spawn(args: &[&str], stdin: Stdio) -> std::process::Child {
    Command::new(env!("CARGO_BIN_EXE_wai"))
        .args(args)
        .stdin(stdin)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the wai binary runs")
}

fn wai(args: &[&str], stdin: &[u8]) -> Output {
    let mut child = spawn(args, Stdio::piped());
    child.stdin.take().unwrap().write_all(stdin).unwrap();
    child.wait_with_output().unwrap()
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

/// `wai info -` on `input` must fail with exit code `code` and a message
/// containing every one of `needles`.
fn check_rejected(input: &[u8], code: i32, needles: &[&str]) {
    let out = wai(&["info", "-"], input);
    let err = text(&out.stderr);
    assert_eq!(
        out.status.code(),
        Some(code),
        "input {:?}\nstderr: {err}",
        text(input)
    );
    assert!(!err.contains("panicked"), "{err}");
    assert!(err.starts_with("error: "), "{err}");
    for n in needles {
        assert!(err.contains(n), "missing {n:?} in: {err}");
    }
    assert!(out.stdout.is_empty(), "nothing on stdout when failing");
}

fn map(vertices: &str) -> Vec<u8> {
    format!(r#"{{"name": "t", "outer": {vertices}}}"#).into_bytes()
}

#[test]
fn self_intersecting_map() {
    check_rejected(
        &map(r#"[["0","0"],["2","2"],["2","0"],["0","2"]]"#),
        1,
        &["not simple", "edges 0 and 2 cross at (1, 1)"],
    );
}

#[test]
fn map_touching_itself_at_a_vertex() {
    check_rejected(
        &map(r#"[["0","0"],["4","0"],["4","4"],["3","4"],["2","0"],["1","4"],["0","4"]]"#),
        1,
        &[
            "edges 0 and 3 touch at (2, 0)",
            "edges 0 and 4 touch at (2, 0)",
        ],
    );
}

#[test]
fn repeated_vertices() {
    check_rejected(
        &map(r#"[["0","0"],["4","0"],["4","4"],["4","0"],["0","4"]]"#),
        1,
        &["vertex 3 repeats vertex 1 at (4, 0)"],
    );
}

#[test]
fn fewer_than_three_vertices() {
    check_rejected(
        &map(r#"[["0","0"],["4","0"]]"#),
        1,
        &["at least 3 distinct vertices; found 2"],
    );
}

#[test]
fn all_vertices_on_one_line() {
    check_rejected(
        &map(r#"[["0","0"],["1","1"],["2","2"],["5","5"]]"#),
        1,
        &["zero area", "one line"],
    );
}

#[test]
fn malformed_json() {
    check_rejected(
        b"{\"outer\": [[\"0\", \"0\"],\n  [1 2]]}",
        1,
        &["malformed JSON at line 2, column"],
    );
}

#[test]
fn empty_input() {
    check_rejected(b"", 1, &["empty input"]);
}

#[test]
fn binary_input() {
    check_rejected(
        &[0x1f, 0x8b, 0x08, 0x00, 0xff, 0xfe, 0xfd],
        1,
        &["not UTF-8", "offset 1"],
    );
}

#[test]
fn not_a_number() {
    check_rejected(
        &map(r#"[["0","0"],["NaN","0"],["0","1"]]"#),
        1,
        &["outer[1][0]", "\"NaN\" is not an exact number"],
    );
}

#[test]
fn zero_denominator() {
    check_rejected(
        &map(r#"[["0","0"],["1","0"],["0","1/0"]]"#),
        1,
        &["outer[2][1]", "zero denominator"],
    );
}

#[test]
fn absurdly_large_coordinates() {
    let big = "9".repeat(200);
    check_rejected(
        &map(&format!(r#"[["0","0"],["{big}","0"],["0","1"]]"#)),
        1,
        &["outer[1][0]", "coordinate too large", "at most 100"],
    );
    let huge = "9".repeat(5000);
    check_rejected(
        &map(&format!(r#"[["0","0"],["{huge}","0"],["0","1"]]"#)),
        1,
        &["outer[1][0]", "longer than 1000"],
    );
}

#[test]
fn exponents_and_floats_are_refused() {
    check_rejected(
        &map(r#"[[0,0],[1e2,0],[0,1]]"#),
        1,
        &["outer[1][0]", "exponent notation"],
    );
}

const HOLED: &[u8] =
    br#"{"outer": [["0","0"],["9","0"],["0","9"]], "holes": [[["1","1"],["2","1"],["1","2"]]]}"#;

#[test]
fn holes_are_read_decomposed_and_localized_and_the_claim_checkers_refuse_them() {
    let out = wai(&["info", "-"], HOLED);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let shown = text(&out.stdout);
    assert!(shown.contains("vertices n:   6"), "{shown}");
    assert!(shown.contains("reflex r:     3  [3, 4, 5]"), "{shown}");
    assert!(
        shown.contains("holes:        1 (3 of the n vertices on the outer ring"),
        "{shown}"
    );
    // 81/2 less 1/2.
    assert!(shown.contains("area:         40\n"), "{shown}");
    assert!(text(&out.stderr).contains("hole(s) 0 were counter-clockwise"));
    let out_file = std::env::temp_dir().join(format!("wai-holed-{}.json", std::process::id()));
    let svg = wai(&["render", "-"], HOLED);
    assert!(svg.status.success(), "{}", text(&svg.stderr));
    let svg = text(&svg.stdout);
    assert_eq!(
        svg.matches("<polygon").count(),
        2,
        "the outer ring and the hole"
    );
    assert!(svg.contains("n = 6, r = 3, 1 hole(s)"), "{svg}");
    let hole_in_grey = svg.matches("#d0d0d0").count();
    assert_eq!(hole_in_grey, 1, "the pillar drawn in grey");
    // V_p and V*_p of a viewpoint: the hole blocks the view behind it.
    let vis = wai(&["vis", "-", "--at", "4,1/2"], HOLED);
    assert!(vis.status.success(), "{}", text(&vis.stderr));
    let shown = text(&vis.stdout);
    // The shadow of the pillar on the wall x = 0, from (0, 7/6) to (0, 2.5).
    assert!(
        shown.contains("(0, 7/6)                     on map edge 2, spurious"),
        "{shown}"
    );
    assert!(
        shown.contains("(0, 2.5)                     on map edge 2, spurious"),
        "{shown}"
    );
    // The decomposition, embeddings, preprocessing and localization read
    // it (sec. 6.4); the claim checkers, whose claims assume no holes, run
    // on it where their code follows every ring.
    for command in ["decompose", "preprocess", "embeddings"] {
        let mut args = vec![command, "-"];
        if command == "preprocess" {
            args.extend(["--out", out_file.to_str().unwrap()]);
        }
        let out = wai(&args, HOLED);
        assert!(out.status.success(), "{command}: {}", text(&out.stderr));
    }
    let dec = text(&wai(&["decompose", "-"], HOLED).stdout);
    assert!(dec.contains("(n = 6, r = 3)"), "{dec}");
    let here = wai(
        &["localize", out_file.to_str().unwrap(), "--at", "4,1/2"],
        b"",
    );
    assert!(here.status.success(), "{}", text(&here.stderr));
    assert!(
        text(&here.stdout).contains("1 position(s)") && text(&here.stdout).contains("(4, 0.5)"),
        "{}",
        text(&here.stdout)
    );
    std::fs::write(&out_file, HOLED).unwrap();
    let found = out_file.with_extension("counterexamples");
    let out = wai(
        &[
            "check",
            "--files",
            out_file.to_str().unwrap(),
            "--out",
            found.to_str().unwrap(),
        ],
        b"",
    );
    std::fs::remove_dir_all(&found).ok();
    let (stdout, err) = (text(&out.stdout), text(&out.stderr));
    assert!(matches!(out.status.code(), Some(0 | 1)), "{err}");
    assert!(
        stdout.contains("checkers that walk one ring, run on the maps without holes only: "),
        "{stdout}"
    );
    assert!(!err.contains("panicked"), "{err}");
    std::fs::remove_file(&out_file).ok();
}

#[test]
fn bad_holes_are_located() {
    check_rejected(
        br#"{"outer": [["0","0"],["9","0"],["0","9"]], "holes": [[["8","8"],["8","9"],["9","8"]]]}"#,
        1,
        &["hole 0 lies outside the outer ring (its vertex 0 is at (8, 8))"],
    );
    check_rejected(
        br#"{"outer": [["0","0"],["9","0"],["0","9"]], "holes": [[["1","0"],["2","1"],["1","2"]]]}"#,
        1,
        &["the outer ring and hole 0 meet", "touch at (1, 0)"],
    );
}

#[test]
fn a_grid_reads_what_exact_values_cannot_hold() {
    let file = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../data/datasets/agplib/simple-holes/g1_simple-simple_25-100v-10h_1.json");
    let path = file.to_str().unwrap();
    let exact = wai(&["info", path], b"");
    assert_eq!(exact.status.code(), Some(1));
    assert!(
        text(&exact.stderr).contains("coordinate too large"),
        "{}",
        text(&exact.stderr)
    );
    let grid = wai(&["info", path, "--grid", "60"], b"");
    assert!(grid.status.success(), "{}", text(&grid.stderr));
    assert!(
        text(&grid.stderr).contains("rounded to multiples of 2^-60: 1 coordinate(s) moved"),
        "{}",
        text(&grid.stderr)
    );
    assert!(
        text(&grid.stdout).contains("holes:        10 ("),
        "{}",
        text(&grid.stdout)
    );
}

#[test]
fn missing_file() {
    let out = wai(&["info", "/nonexistent/map.json"], b"");
    assert_eq!(out.status.code(), Some(3));
    assert!(text(&out.stderr).contains("/nonexistent/map.json"));
}

#[test]
fn clockwise_map_is_accepted_and_normalised() {
    let out = wai(
        &["info", "-"],
        &map(r#"[["0","0"],["0","3"],["4","3"],["4","0"]]"#),
    );
    assert!(out.status.success());
    let err = text(&out.stderr);
    assert!(
        err.contains("clockwise; reversed to counter-clockwise"),
        "{err}"
    );
    assert!(text(&out.stdout).contains("vertices n:   4"));
}

#[test]
fn collinear_vertices_are_removed_with_a_note() {
    let out = wai(
        &["info", "-"],
        &map(r#"[["0","0"],["2","0"],["4","0"],["4","3"],["0","3"]]"#),
    );
    assert!(out.status.success());
    let err = text(&out.stderr);
    assert!(
        err.contains("removed 1 vertex(es) with a straight (180°) angle, at input positions 1"),
        "{err}"
    );
    assert!(text(&out.stdout).contains("vertices n:   4"));
}

#[test]
fn info_json_is_exact() {
    let out = wai(
        &["info", "--json", "-"],
        &map(r#"[["0","0"],["1.5","0"],["1.5","1/3"],["0","1/3"]]"#),
    );
    assert!(out.status.success(), "{}", text(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["n"], 4);
    assert_eq!(v["r"], 0);
    assert_eq!(v["area"], "0.5");
    assert_eq!(v["scale"], "6");
    assert_eq!(v["orthogonal"], true);
}

#[test]
fn geojson_is_detected() {
    let gj =
        br#"{"type": "Polygon", "coordinates": [[[0,0],[4,0],[4,2],[2,2],[2,4],[0,4],[0,0]]]}"#;
    let out = wai(&["info", "-"], gj);
    assert!(out.status.success(), "{}", text(&out.stderr));
    assert!(text(&out.stdout).contains("reflex r:     1  [3]"));
}

#[test]
fn render_writes_svg() {
    let out = wai(
        &["render", "--labels", "-"],
        &map(r#"[["0","0"],["4","0"],["4","2"],["2","2"],["2","4"],["0","4"]]"#),
    );
    assert!(out.status.success());
    let svg = text(&out.stdout);
    assert!(svg.starts_with("<svg") && svg.contains("(reflex)"));
}

#[test]
fn demo_runs_on_the_built_in_map() {
    let dir = std::env::temp_dir().join(format!("wai-demo-test-{}", std::process::id()));
    let out = wai(&["demo", "--out", dir.to_str().unwrap()], b"");
    assert!(out.status.success(), "{}", text(&out.stderr));
    let stdout = text(&out.stdout);
    assert!(
        stdout.contains("vertices n:   44") && stdout.contains("reflex r:     20"),
        "{stdout}"
    );
    let written = std::fs::read(dir.join("office-floor.json")).unwrap();
    let back = wai(&["info", "-"], &written);
    assert!(back.status.success());
    assert!(dir.join("office-floor.svg").exists());
    assert!(
        stdout.contains("decomposition: 150 visibility rays, 478 2-cells"),
        "{stdout}"
    );
    assert!(dir.join("office-floor-cells.svg").exists());
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn gen_usage_errors_are_clear() {
    let out = wai(&["gen", "--family", "no-such-family"], b"");
    assert_eq!(out.status.code(), Some(2));
    assert!(text(&out.stderr).contains("no-such-family"));
    let out = wai(&["info"], b"");
    assert_eq!(out.status.code(), Some(2));
    let out = wai(&["gen", "--layout", "no-such-layout"], b"");
    assert_eq!(out.status.code(), Some(2));
    assert!(text(&out.stderr).contains("bottled-niches"));
}

#[test]
fn gen_writes_the_chapter_4_layouts() {
    let out = wai(&["gen", "--list"], b"");
    assert!(text(&out.stdout).contains("bottled-niches"));
    let out = wai(&["gen", "--layout", "bottled-niches", "--seed", "3"], b"");
    assert!(out.status.success(), "{}", text(&out.stderr));
    let back = wai(&["info", "-"], &out.stdout);
    assert!(back.status.success());
    assert!(text(&back.stdout).contains("bottled-niches seed=3"));
}

const L_ROOM: &str = r#"{"outer": [["0","0"],["4","0"],["4","2"],["2","2"],["2","4"],["0","4"]]}"#;

#[test]
fn vis_prints_polygon_and_skeleton() {
    let out = wai(&["vis", "-", "--at", "1,3"], L_ROOM.as_bytes());
    assert!(out.status.success(), "{}", text(&out.stderr));
    let s = text(&out.stdout);
    assert!(s.contains("V_p: 5 vertices"), "{s}");
    assert!(
        s.contains("(4, 0)                       map vertex 1, spurious"),
        "{s}"
    );
    assert!(
        s.contains("half on map edge 0, blocked by V_p vertex 2"),
        "{s}"
    );
    assert!(s.contains("origin v0 = (2, 2) (map vertex 3)"), "{s}");
    assert!(
        s.contains("artificial, label 0·x + 1·y = -2 relative to v0"),
        "{s}"
    );
}

#[test]
fn vis_json_and_svg() {
    let svg = std::env::temp_dir().join(format!("wai-vis-{}.svg", std::process::id()));
    let out = wai(
        &[
            "vis",
            "-",
            "--at",
            "1/2,7/2",
            "--json",
            "--svg",
            svg.to_str().unwrap(),
        ],
        L_ROOM.as_bytes(),
    );
    assert!(out.status.success(), "{}", text(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["viewpoint"], serde_json::json!(["0.5", "3.5"]));
    assert_eq!(v["skeleton"]["origin"], serde_json::json!(["2", "2"]));
    let picture = std::fs::read_to_string(&svg).unwrap();
    assert!(picture.contains("spurious") && picture.contains("artificial edge"));
    std::fs::remove_file(svg).ok();
}

#[test]
fn vis_rejects_bad_viewpoints() {
    for (at, code, needle) in [
        ("9,9", 1, "lies outside the map"),
        ("4,1", 1, "lies on the boundary"),
        ("2,2", 1, "lies on the boundary"),
        ("1", 2, "expected x,y"),
        ("1,NaN", 2, "not an exact number"),
        ("-1,1", 1, "outside"),
    ] {
        let out = wai(&["vis", "-", "--at", at], L_ROOM.as_bytes());
        let err = text(&out.stderr);
        assert_eq!(out.status.code(), Some(code), "--at {at}: {err}");
        assert!(err.contains(needle), "--at {at}: {err}");
        assert!(!err.contains("panicked"));
    }
}

#[test]
fn decompose_prints_counts_and_refuses_bad_classes() {
    let out = wai(&["decompose", "-", "--json"], L_ROOM.as_bytes());
    assert!(out.status.success(), "{}", text(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(
        (v["cells"].as_u64(), v["classes"].as_u64()),
        (Some(5), Some(5))
    );
    let out = wai(
        &["decompose", "-", "--svg", "/dev/null", "--class", "99"],
        L_ROOM.as_bytes(),
    );
    assert_eq!(out.status.code(), Some(2));
    assert!(text(&out.stderr).contains("--class 99: the map has 5 classes"));
}

/// The doorway of `counterexamples/T3.3b-doorway-1d-cell.json`: its segment
/// is a kept 1-cell with a skeleton of its own, counted by dimension and
/// drawn in the SVG.
#[test]
fn decompose_counts_and_draws_cells_of_every_dimension() {
    let doorway = r#"{"name": "s-tetromino", "outer": [[0, 0], [1, 0], [1, 1], [2, 1], [2, 3], [1, 3], [1, 2], [0, 2]]}"#;
    let out = wai(&["decompose", "-", "--json"], doorway.as_bytes());
    assert!(out.status.success(), "{}", text(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let by = &v["cells_by_dimension"];
    assert_eq!(by["2"]["kept"], v["cells"]);
    assert_eq!(by["2"]["absorbed"], 0);
    assert_eq!(by["1"]["kept"], 1, "{v}");
    assert!(by["1"]["absorbed"].as_u64().unwrap() > 0, "{v}");
    assert_eq!(
        (by["0"]["kept"].as_u64(), by["0"]["absorbed"].as_u64()),
        (Some(0), Some(0))
    );
    // Peak memory is reported (Linux: /proc/self/status), at least 1 MiB.
    assert!(v["peak_memory_bytes"].as_u64().unwrap() > 1 << 20, "{v}");
    let dir = std::env::temp_dir().join(format!("wai-dims-{}.svg", std::process::id()));
    let out = wai(
        &["decompose", "-", "--svg", dir.to_str().unwrap()],
        doorway.as_bytes(),
    );
    assert!(out.status.success(), "{}", text(&out.stderr));
    let svg = std::fs::read_to_string(&dir).unwrap();
    std::fs::remove_file(&dir).ok();
    assert!(svg.contains("kept 1-cell"), "the kept 1-cell is not drawn");
}

/// `wai embeddings` on the stored figure of Examples 4.1/4.2: the JSON keys
/// of the issue, the overlapping pair with its verdict, and the SVG.
#[test]
fn embeddings_reports_the_overlapping_pair_of_the_funnel_figure() {
    let figure = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../counterexamples/E4.1-funnels-kernels-overlap.json"
    );
    let out = wai(&["embeddings", figure, "--json"], b"");
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let classes = v["classes"].as_array().unwrap();
    let with_pairs: Vec<&serde_json::Value> = classes
        .iter()
        .filter(|c| !c["overlapping_pairs"].as_array().unwrap().is_empty())
        .collect();
    assert_eq!(with_pairs.len(), 1);
    let class = with_pairs[0];
    let pair = &class["overlapping_pairs"][0];
    assert_eq!(pair["witnesses_see_each_other"], false);
    assert_eq!(pair["kernels_overlap"], true);
    for e in class["embeddings"].as_array().unwrap() {
        for key in ["origin", "valid", "witness_cells", "candidate_edges"] {
            assert!(!e[key].is_null(), "missing {key}");
        }
        assert_eq!(e["valid"], true);
    }
    let dir = std::env::temp_dir().join(format!("wai-embeddings-{}.svg", std::process::id()));
    let k = class["class"].to_string();
    let out = wai(
        &[
            "embeddings",
            figure,
            "--class",
            &k,
            "--svg",
            dir.to_str().unwrap(),
        ],
        b"",
    );
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert!(text(&out.stdout).contains("kernels overlap too; witnesses do not see each other"));
    let svg = std::fs::read_to_string(&dir).unwrap();
    assert!(svg.starts_with("<svg") && svg.contains("valid candidate edge"));
    let entries = pictures::legend_entries(&svg);
    for needle in [
        "map walls",
        "embedding at map vertex",
        "embedded skeleton polygon",
        "witness cell",
        "valid candidate edge",
        "origin h(v0)",
    ] {
        assert!(
            entries.iter().any(|e| e.contains(needle)),
            "{needle}: {entries:?}"
        );
    }
    assert!(pictures::scale_bar(&svg).is_some());
    std::fs::remove_file(dir).ok();
}

#[test]
fn embeddings_refuses_a_class_out_of_range() {
    let out = wai(&["embeddings", "-", "--class", "999"], L_ROOM.as_bytes());
    assert_eq!(out.status.code(), Some(2));
    let err = text(&out.stderr);
    assert!(err.starts_with("error: --class 999: the map has"), "{err}");
}
mod check;
mod claims;
mod eval_log;
mod extremes;
mod grid;
mod localize;
mod parallel;
mod pictures;
mod scan;
mod scan_eval;
mod shards;
mod slurm;

/// Runs `wai args` with its standard output read for `keep` bytes and then
/// closed, as `wai … | head -c keep` does; the exit status and standard
/// error.
fn with_closed_pipe(args: &[&str], keep: usize) -> (Option<i32>, String) {
    use std::io::Read;
    let mut child = spawn(args, Stdio::null());
    let mut stdout = child.stdout.take().unwrap();
    let mut head = vec![0; keep];
    stdout.read_exact(&mut head).unwrap();
    drop(stdout);
    let out = child.wait_with_output().unwrap();
    (out.status.code(), text(&out.stderr))
}

/// A reader that closes the pipe ends the command quietly with 141 (as a
/// shell reports SIGPIPE), never with a panic: output written in one piece
/// (a map's JSON, far beyond the pipe's buffer) and line by line (`wai
/// check`'s table, the pipe closed before its first line).
#[test]
fn a_closed_pipe_ends_a_command_quietly() {
    let (code, err) = with_closed_pipe(
        &[
            "gen",
            "--random",
            "random-simple-star",
            "--n",
            "3000",
            "--seed",
            "1",
        ],
        10,
    );
    assert_eq!(code, Some(141), "stderr: {err}");
    assert!(err.is_empty(), "nothing to say on a closed pipe: {err}");

    let (code, err) = with_closed_pipe(
        &["check", "T3.2", "--maps", "special-comb", "--count", "2"],
        0,
    );
    assert_eq!(code, Some(141), "stderr: {err}");
    assert!(!err.contains("panicked"), "{err}");
}

/// Every numeric option refuses NaN, infinities, negative counts and
/// values outside its documented range when the command line is read: exit
/// status 2, the option and the value named, no work started.
#[test]
fn bad_numeric_options_are_refused() {
    let cases: &[(&[&str], &str)] = &[
        (
            &["localize-scan", "office:2", "s.json", "--heading", "NaN"],
            "--heading",
        ),
        (
            &["localize-scan", "office:2", "s.json", "--heading", "1e400"],
            "not a finite number",
        ),
        (
            &["scan", "office:2", "--at", "5,5", "--fov", "400"],
            "(0, 360]",
        ),
        (&["scan", "office:2", "--at", "5,5", "--fov", "0"], "--fov"),
        (
            &["scan", "office:2", "--at", "5,5", "--max-range", "-3"],
            "--max-range",
        ),
        (
            &["scan", "office:2", "--at", "5,5", "--noise", "inf"],
            "--noise",
        ),
        (&["scan", "office:2", "--at", "5,5", "--beams", "0"], "≥ 1"),
        (
            &["scan", "office:2", "--at", "5,5", "--obstacle-size", "0"],
            "--obstacle-size",
        ),
        (&["eval", "office:2", "--poses", "-5"], "-5 is negative"),
        (
            &["eval", "office:2", "--require-answer-set", "1.5"],
            "(0, 1]",
        ),
        (&["check", "--threads", "0"], "--threads"),
        (&["check", "--count", "-1"], "negative"),
        (
            &["gen", "--random", "random-simple-star", "--n", "-4"],
            "--n",
        ),
        (&["search-extremes", "--pool", "0"], "--pool"),
        (&["decompose", "office:2", "--class", "-1"], "--class"),
    ];
    for (args, needle) in cases {
        let out = wai(args, b"");
        let err = text(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(
            err.contains(needle),
            "{args:?}: missing {needle:?} in: {err}"
        );
        assert!(!err.contains("unexpected argument"), "{args:?}: {err}");
        assert!(out.stdout.is_empty(), "{args:?}");
    }
}

/// A map file that starts with a UTF-8 byte-order mark reads as without.
#[test]
fn a_byte_order_mark_is_ignored() {
    let out = wai(
        &["info", "-"],
        b"\xEF\xBB\xBF{\"name\": \"sq\", \"outer\": [[0, 0], [1, 0], [1, 1], [0, 1]]}",
    );
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert!(text(&out.stdout).contains("vertices n:   4"));
}

/// A scan with too few returns to fix a pose is refused as not
/// localizable, with the reason, instead of a dozen "equally good" poses.
#[test]
fn a_scan_without_enough_returns_is_not_localizable() {
    let dir = std::env::temp_dir().join(format!("wai-returns-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let cases = [
        (
            r#"{"angles": [0, 1, 2], "ranges": [null, null, null]}"#,
            "exact",
            "no returns",
        ),
        (
            r#"{"angles": [0], "ranges": [1.5]}"#,
            "exact",
            "1 return of 1 beams",
        ),
        (
            r#"{"angles": [0, 1, 2], "ranges": [1.5, 2.0, null]}"#,
            "none",
            "at least 3",
        ),
    ];
    for (i, (scan, compass, needle)) in cases.iter().enumerate() {
        let path = dir.join(format!("scan-{i}.json"));
        std::fs::write(&path, scan).unwrap();
        let p = path.to_str().unwrap();
        let out = wai(
            &[
                "localize-scan",
                "office:2",
                p,
                "--compass",
                compass,
                "--heading",
                "0",
            ],
            b"",
        );
        let err = text(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{scan}: {err}");
        assert!(
            err.contains("not localizable") && err.contains(needle),
            "{scan}: {err}"
        );
    }
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn every_map_command_accepts_a_generated_map() {
    let dir = std::env::temp_dir().join(format!("wai-generated-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let pre = dir.join("rooms.json");
    let pre = pre.to_str().unwrap();
    let commands: &[&[&str]] = &[
        &["info", "rooms:2"],
        &["vis", "rooms:2", "--at", "3,1"],
        &["decompose", "rooms:2"],
        &["render", "office:2"],
        &["embeddings", "family:corridor-niches:2"],
        &["preprocess", "rooms:2", "--out", pre],
        &["localize", "rooms:2", "--at", "3,1"],
        &["localize", pre, "--at", "3,1"],
    ];
    for args in commands {
        let out = wai(args, b"");
        let err = text(&out.stderr);
        assert_eq!(out.status.code(), Some(0), "{args:?}: {err}");
        assert!(!out.stdout.is_empty(), "{args:?}: no output");
    }
    // The generated map is named by its spec.
    let info = text(&wai(&["info", "office:2"], b"").stdout);
    assert!(info.contains("office:2"), "{info}");
    // A malformed spec is a usage error naming it, not "no such file".
    for (spec, needle) in [("rooms:x", "not a count"), ("family:nope:1", "nope")] {
        let out = wai(&["decompose", spec], b"");
        let err = text(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{spec}: {err}");
        assert!(err.contains(needle), "{spec}: {err}");
    }
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn decompositions_above_the_memory_limit_are_refused_before_the_work() {
    let dir = std::env::temp_dir().join(format!("wai-budget-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let out_file = dir.join("p.json");
    let out_file = out_file.to_str().unwrap();
    let commands: &[&[&str]] = &[
        &["decompose", "office:3"],
        &["embeddings", "office:3"],
        &["preprocess", "office:3", "--out", out_file],
        &["localize", "office:3", "--at", "1,1"],
    ];
    for args in commands {
        let mut limited = args.to_vec();
        limited.extend(["--max-memory", "1M"]);
        let out = wai(&limited, b"");
        let err = text(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{args:?}: {err}");
        for needle in [
            "at most 1448 decomposition vertices",
            "17.0 MiB",
            "--max-memory",
        ] {
            assert!(
                err.contains(needle),
                "{args:?}: {needle} missing from {err}"
            );
        }
        assert!(!std::path::Path::new(out_file).exists(), "nothing written");
        // Raised, or skipped, the same command runs.
        let mut raised = args.to_vec();
        raised.extend(["--max-memory", "64M"]);
        assert_eq!(wai(&raised, b"").status.code(), Some(0), "{raised:?}");
        std::fs::remove_file(out_file).ok();
    }
    let mut forced = vec!["decompose", "office:3", "--max-memory", "1M", "--force"];
    assert_eq!(wai(&forced, b"").status.code(), Some(0));
    forced.truncate(2);
    forced.extend(["--max-memory", "0"]);
    assert_eq!(
        wai(&forced, b"").status.code(),
        Some(2),
        "a limit of 0 is a usage error"
    );
    std::fs::remove_dir_all(&dir).ok();
}
