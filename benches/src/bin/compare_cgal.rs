//! Compare wai's exact visibility polygons with CGAL's.
//!
//! ```sh
//! benches/peers/build.sh
//! cargo run --release -p wai-benches --bin compare_cgal -- [--polygons N] [--quick]
//! ```
//!
//! For every map and every viewpoint, three polygons are computed exactly:
//! - **ours**: the production V_p, [`VisibilityIndex::visibility_polygon`];
//! - **reference**: [`wai_visibility::reference::visibility_polygon`], on
//!   maps with n ≤ 100 only (it is O(n²) per viewpoint);
//! - **CGAL**: `Triangular_expansion_visibility_2<Arrangement_2, Tag_true>`
//!   on Epeck, through the peer of `benches/peers` ([`CgalPeer`]).
//!
//! # Inputs
//! - `--polygons N` random maps (default 2016), round robin over every kind
//!   of [`wai_gen::RANDOM_KINDS`] × n ∈ {10, 20, 50, 100, 200, 500} (n = 300
//!   instead of 500 for `random-simple-2opt`, whose generator stops there),
//!   seeds 1, 2, …;
//! - the thesis families of [`wai_gen::FAMILIES`] with the 4 least accepted
//!   values of their one parameter, whose figure viewpoints
//!   [`wai_study::sample::viewpoints`] puts first;
//! - every map of `agplib/{simple,ortho,vonkoch}` and `r2v` under the
//!   datasets directory (`<repo>/data/datasets`, or `--datasets DIR`), and
//!   the 36 AGPLIB maps with holes (`agplib/{simple,ortho}-holes`, read on
//!   the grid of 2^-60: [`HOLES_GRID_BITS`]), sent to CGAL as polygons with
//!   holes.
//!
//! Viewpoints per map: 4 of [`wai_study::sample::viewpoints`] (midpoints of
//! vertex pairs, meeting points of two lines through vertex pairs, points on
//! edge extensions, a rational grid: the degenerate positions) and 2 of
//! [`interior_viewpoints`] (random rationals with denominator 1000); for
//! n ≥ 1000, 2 + 1. All are strictly inside the map (both samplers keep only
//! such points): CGAL refuses boundary points and so does our algorithm.
//!
//! # Conventions relied on (see `benches/peers/README.md`)
//! - **C1 orientation and start**: both polygons are counter-clockwise and
//!   start at the lexicographically (x, then y) smallest vertex (ours by
//!   construction, CGAL's rotated there by the peer). The lexicographically
//!   smallest vertex of a polygon is always a corner, so C1 survives C2.
//! - **C2 collinear vertices**: CGAL reports every map vertex it meets in
//!   the middle of a straight stretch of the boundary of V_p; ours has no
//!   180° vertex. [`drop_collinear`] reduces CGAL's reply to its corners.
//!   In every case seen the stretch lies on a line through the viewpoint
//!   (p on the line of a map edge, or a window grazing several collinear
//!   reflex vertices) and the dropped point is a map vertex; both are
//!   counted.
//! - **C3 duplicates, needles**: neither side repeats a vertex or reports a
//!   needle; nothing is done for them, and a CGAL reply with a repeated
//!   vertex is reported as unexplained.
//!
//! A comparison is an *exact match* if CGAL's reply equals ours vertex for
//! vertex, a *match after C2* if `drop_collinear(cgal)` does, and an
//! *unexplained mismatch* otherwise. Also unexplained: production ≠
//! reference, an error of either side, a map CGAL refuses, a 180° or
//! repeated vertex in ours, and a failed `sees` cross-check of ours (n ≤ 100:
//! every vertex on the map boundary, every map vertex that
//! [`wai_exact::sees`] the viewpoint on the boundary of V_p). Each one is
//! printed in full with its replay data, and the exit status is 1 if there
//! is any (2 for bad arguments or a missing peer).
//!
//! Other options: `--viewpoints K`, `--no-datasets`, `--datasets DIR`,
//! `--max-dataset-n N`, `--examples K` (print matches after C2 in full),
//! `--inject-fault K` (self-test of the harness); see `--help`.
//!
//! Progress goes to stderr, the report to stdout.

// The allocator of every binary of the workspace (see Cargo.toml).
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

use rug::Integer;
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;
use wai_benches::cgal::{self, drop_collinear, CgalPeer};
use wai_benches::viewpoints::interior_viewpoints;
use wai_exact::{locate_rat, orientation_rat, sees, Containment, Orientation, RatPoint};
use wai_map::Map;
use wai_visibility::{reference, VisibilityIndex};

const SIZES: [usize; 6] = [10, 20, 50, 100, 200, 500];
const DATASET_DIRS: [&str; 6] = [
    "agplib/simple",
    "agplib/ortho",
    "agplib/vonkoch",
    "r2v",
    "agplib/simple-holes",
    "agplib/ortho-holes",
];

/// The AGPLIB maps with holes need more than 100 bits over their common
/// denominator (a subnormal double, 124-bit denominators): they are read
/// rounded to multiples of 2^-60 (`--grid 60`), which keeps orthogonal maps
/// orthogonal and moves the subnormal alone in the others.
const HOLES_GRID_BITS: u32 = 60;
/// Maps up to this size are also checked against the reference algorithm.
const REFERENCE_MAX_N: usize = 100;
/// Maps from this size on get fewer viewpoints.
const LARGE_N: usize = 1000;
/// Thesis family maps per family: the least accepted values of its one parameter.
const FAMILY_PARAMS: u32 = 4;
/// A progress line every this many viewpoints.
const PROGRESS_EVERY: usize = 500;

const USAGE: &str = concat!(
    "usage: compare_cgal [--polygons N] [--quick] [--viewpoints K] [--no-datasets]\n",
    "                    [--datasets DIR] [--max-dataset-n N] [--examples K] [--inject-fault K]\n",
    "  --polygons N       random maps (default 2016; 200 with --quick)\n",
    "  --quick            200 random maps, r2v, AGPLIB maps with n <= 100\n",
    "  --viewpoints K     viewpoints per map with n < 1000, 2/3 sampled, 1/3 random\n",
    "                     (default 6; n >= 1000: ceil(K/2))\n",
    "  --no-datasets      random maps only\n",
    "  --datasets DIR     the datasets directory (default <repo>/data/datasets)\n",
    "  --max-dataset-n N  skip AGPLIB maps with more than N vertices (default: none; --quick: 100)\n",
    "  --examples K       print the first K matches after C2 in full\n",
    "  --inject-fault K   self-test of the harness: drop a vertex from every K-th polygon of\n",
    "                     ours before comparing (each must be reported; exit status 1)",
);

#[derive(Debug)]
struct Args {
    polygons: usize,
    datasets: Option<PathBuf>,
    /// The largest AGPLIB map read (`None`: all).
    max_agplib_n: Option<usize>,
    quick: bool,
    /// Viewpoints per map with n < 1000 (half of it from n = 1000 on).
    viewpoints: usize,
    /// Self-test of the harness: corrupt every k-th polygon of ours.
    inject_fault: Option<usize>,
    /// Print this many matches after C2 in full (examples of the convention).
    examples: usize,
}

fn parse_args() -> Result<Args, String> {
    let mut polygons: Option<usize> = None;
    let mut quick = false;
    let mut no_datasets = false;
    let mut dir: Option<PathBuf> = None;
    let mut max_n: Option<usize> = None;
    let mut viewpoints = 6usize;
    let mut inject_fault: Option<usize> = None;
    let mut examples = 0usize;
    let mut it = std::env::args().skip(1);
    while let Some(a) = it.next() {
        let mut value = |name: &str| it.next().ok_or_else(|| format!("{name} needs a value"));
        match a.as_str() {
            "--polygons" => {
                let v = value("--polygons")?;
                polygons = Some(v.parse().map_err(|e| format!("--polygons {v}: {e}"))?);
            }
            "--max-dataset-n" => {
                let v = value("--max-dataset-n")?;
                max_n = Some(v.parse().map_err(|e| format!("--max-dataset-n {v}: {e}"))?);
            }
            "--viewpoints" => {
                let v = value("--viewpoints")?;
                viewpoints = v.parse().map_err(|e| format!("--viewpoints {v}: {e}"))?;
                if viewpoints < 2 {
                    return Err("--viewpoints needs at least 2".to_owned());
                }
            }
            "--inject-fault" => {
                let v = value("--inject-fault")?;
                let k: usize = v.parse().map_err(|e| format!("--inject-fault {v}: {e}"))?;
                inject_fault = Some(k.max(1));
            }
            "--examples" => {
                let v = value("--examples")?;
                examples = v.parse().map_err(|e| format!("--examples {v}: {e}"))?;
            }
            "--datasets" => dir = Some(PathBuf::from(value("--datasets")?)),
            "--quick" => quick = true,
            "--no-datasets" => no_datasets = true,
            "-h" | "--help" => return Err(String::new()),
            other => return Err(format!("unknown argument {other:?}")),
        }
    }
    let default_dir = || Path::new(env!("CARGO_MANIFEST_DIR")).join("../data/datasets");
    Ok(Args {
        polygons: polygons.unwrap_or(if quick { 200 } else { 2016 }),
        datasets: if no_datasets {
            None
        } else {
            Some(dir.unwrap_or_else(default_dir))
        },
        max_agplib_n: max_n.or(if quick { Some(100) } else { None }),
        quick,
        viewpoints,
        inject_fault,
        examples,
    })
}

/// A map to compare, with how to get it back.
#[derive(Debug)]
struct Input {
    /// The group in the per-source table (random kind or dataset directory).
    group: String,
    /// Replay data: `wai_gen::random(kind, n, seed)` or the file.
    replay: String,
    map: Map,
    /// Seed of the random viewpoints.
    seed: u64,
}

/// The `count` random maps: round robin over kinds × sizes, seeds 1, 2, ….
fn random_inputs(count: usize) -> impl Iterator<Item = Result<Input, String>> {
    let kinds = wai_gen::RANDOM_KINDS;
    let combos: Vec<(&'static str, usize)> = kinds
        .iter()
        .flat_map(|k| SIZES.iter().map(move |&n| (k.id, n.min(k.max_n))))
        .collect();
    (0..count).map(move |i| {
        let (kind, n) = combos[i % combos.len()];
        let seed = (i / combos.len()) as u64 + 1;
        let replay = format!("wai_gen::random({kind:?}, {n}, {seed})");
        let map = wai_gen::random(kind, n, seed).map_err(|e| format!("{replay}: {e}"))?;
        Ok(Input {
            group: kind.to_owned(),
            replay,
            map,
            seed: seed * 1_000_003 + n as u64,
        })
    })
}

/// The dataset files, sorted, with their group.
fn dataset_files(
    root: &Path,
    max_agplib_n: Option<usize>,
) -> Result<Vec<(String, PathBuf, Option<usize>)>, String> {
    let mut out = Vec::new();
    for dir in DATASET_DIRS {
        let full = root.join(dir);
        let entries = std::fs::read_dir(&full).map_err(|e| {
            format!(
                "cannot read {}: {e} (the run needs data/datasets; --no-datasets skips them)",
                full.display()
            )
        })?;
        let mut files: Vec<PathBuf> = entries
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| {
                p.extension().is_some_and(|x| x == "json")
                    && p.file_name().is_some_and(|f| f != "index.json")
            })
            .collect();
        files.sort();
        let limit = if dir.starts_with("agplib") {
            max_agplib_n
        } else {
            None
        };
        for f in files {
            out.push((dir.to_owned(), f, limit));
        }
    }
    Ok(out)
}

fn load_dataset(group: &str, path: &Path, seed: u64) -> Result<Input, String> {
    let bytes = std::fs::read(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let grid = group.ends_with("-holes").then_some(HOLES_GRID_BITS);
    let options = wai_map::json::ReadOptions { grid_bits: grid };
    let loaded = wai_map::json::from_json_with(&bytes, &options)
        .map_err(|e| format!("{}: {e}", path.display()))?;
    Ok(Input {
        group: group.to_owned(),
        replay: match grid {
            None => format!("wai_map::json::from_json({})", path.display()),
            Some(b) => format!(
                "wai_map::json::from_json_with({}, grid_bits: {b})",
                path.display()
            ),
        },
        map: loaded.map,
        seed,
    })
}

/// Per-group and overall counts.
#[derive(Debug, Default, Clone)]
struct Tally {
    maps: usize,
    viewpoints: usize,
    /// Viewpoints from `sample::viewpoints` (degenerate kinds and grid).
    sampled: usize,
    /// Viewpoints from `interior_viewpoints` (random rationals).
    random: usize,
    cgal_compared: usize,
    exact: usize,
    after_c2: usize,
    /// Of `after_c2`, at random (not sampled) viewpoints.
    after_c2_random: usize,
    /// Collinear vertices CGAL reported (dropped by C2): map vertices, others.
    dropped_map_vertices: usize,
    dropped_other: usize,
    /// Dropped vertices whose straight stretch lies on a line through p.
    dropped_through_p: usize,
    /// CGAL replies with a repeated vertex.
    with_duplicates: usize,
    reference_compared: usize,
    reference_equal: usize,
    /// Viewpoints whose V_p of ours passed [`sees_check`].
    sees_checked: usize,
    unexplained: usize,
    largest_n: usize,
}

impl Tally {
    fn add(&mut self, o: &Tally) {
        self.maps += o.maps;
        self.viewpoints += o.viewpoints;
        self.sampled += o.sampled;
        self.random += o.random;
        self.cgal_compared += o.cgal_compared;
        self.exact += o.exact;
        self.after_c2 += o.after_c2;
        self.after_c2_random += o.after_c2_random;
        self.dropped_map_vertices += o.dropped_map_vertices;
        self.dropped_other += o.dropped_other;
        self.dropped_through_p += o.dropped_through_p;
        self.with_duplicates += o.with_duplicates;
        self.reference_compared += o.reference_compared;
        self.reference_equal += o.reference_equal;
        self.sees_checked += o.sees_checked;
        self.unexplained += o.unexplained;
        self.largest_n = self.largest_n.max(o.largest_n);
    }
}

/// An unexplained finding, printed in full.
#[derive(Debug)]
struct Finding {
    category: &'static str,
    text: String,
}

struct Run {
    peer: CgalPeer,
    tallies: BTreeMap<String, Tally>,
    findings: Vec<Finding>,
    seen_viewpoints: usize,
    start: Instant,
    /// Viewpoints per map below [`LARGE_N`].
    viewpoints: usize,
    inject_fault: Option<usize>,
    injected: usize,
    /// Matches after C2, printed in full (at most `Args::examples`).
    examples: Vec<String>,
    max_examples: usize,
}

/// `x` on the closed segment `ab` (exactly).
fn on_segment(a: &RatPoint, b: &RatPoint, x: &RatPoint) -> bool {
    if orientation_rat(a, b, x) != Orientation::Collinear {
        return false;
    }
    // Compare coordinates over positive denominators: u/w against v/w'.
    let cmp = |u: &Integer, w: &Integer, v: &Integer, w2: &Integer| {
        Integer::from(u * w2).cmp(&Integer::from(v * w))
    };
    let within = |ca: &Integer, cb: &Integer, cx: &Integer| {
        let lo_a = cmp(ca, a.hw(), cx, x.hw()) != std::cmp::Ordering::Greater;
        let lo_b = cmp(cb, b.hw(), cx, x.hw()) != std::cmp::Ordering::Greater;
        let hi_a = cmp(ca, a.hw(), cx, x.hw()) != std::cmp::Ordering::Less;
        let hi_b = cmp(cb, b.hw(), cx, x.hw()) != std::cmp::Ordering::Less;
        (lo_a && hi_b) || (lo_b && hi_a)
    };
    within(a.hx(), b.hx(), x.hx()) && within(a.hy(), b.hy(), x.hy())
}

/// An independent check of V_p with `wai_exact` alone: every vertex lies on
/// the map's boundary, and every map vertex that `p` sees (the closed
/// segment meets the boundary only at the vertex) lies on the boundary of
/// V_p. `None` if both hold, else what failed.
fn sees_check(map: &Map, p: &RatPoint, vp: &[RatPoint]) -> Option<String> {
    let ring = map.vertices();
    for q in vp {
        let at = locate_rat(ring, q);
        if at != Containment::OnBoundary {
            return Some(format!(
                "vertex {q} of V_p is {at:?}, not on the map boundary"
            ));
        }
    }
    let k = vp.len();
    for &v in ring {
        let v = RatPoint::from(v);
        if sees(ring, p, &v).is_visible()
            && !(0..k).any(|i| on_segment(&vp[i], &vp[(i + 1) % k], &v))
        {
            return Some(format!(
                "map vertex {v} is seen from p (wai_exact::sees) but not on the boundary of V_p"
            ));
        }
    }
    None
}

fn points_text(ps: &[RatPoint]) -> String {
    let v: Vec<String> = ps.iter().map(ToString::to_string).collect();
    format!("{} vertices: {}", ps.len(), v.join(" "))
}

fn map_text(map: &Map) -> String {
    let v: Vec<String> = map.vertices().iter().map(ToString::to_string).collect();
    format!(
        "scale {}, {} vertices: {}",
        map.scale(),
        map.n(),
        v.join(" ")
    )
}

/// How each vertex in one polygon but not the other relates to the map.
fn diff_text(
    map: &Map,
    p: &RatPoint,
    ours: &[RatPoint],
    theirs: &[RatPoint],
    name: &str,
) -> String {
    let mut s = String::new();
    let describe = |q: &RatPoint| {
        let at = match map.vertices().iter().position(|&v| RatPoint::from(v) == *q) {
            Some(i) => format!("map vertex {i}"),
            None => format!("{:?}", map.locate(q)),
        };
        format!("{q} [{at}; sees(p, ·) = {:?}]", sees(map.vertices(), p, q))
    };
    for q in ours.iter().filter(|q| !theirs.contains(q)) {
        let _ = writeln!(s, "    only in ours: {}", describe(q));
    }
    for q in theirs.iter().filter(|q| !ours.contains(q)) {
        let _ = writeln!(s, "    only in {name}: {}", describe(q));
    }
    s
}

impl Run {
    fn tally(&mut self, group: &str) -> &mut Tally {
        self.tallies.entry(group.to_owned()).or_default()
    }

    fn finding(&mut self, group: &str, category: &'static str, text: String) {
        self.tally(group).unexplained += 1;
        self.findings.push(Finding { category, text });
    }

    fn progress(&self, maps: usize) {
        eprintln!(
            "compare_cgal: {} viewpoints on {maps} maps, {} unexplained, {:.1?}",
            self.seen_viewpoints,
            self.findings.len(),
            self.start.elapsed()
        );
    }

    /// Restart the peer after it died; the next map sets a polygon again.
    fn revive(&mut self, err: &str) {
        if err.contains("exited") || err.contains("write failed") || err.contains("read failed") {
            eprintln!("compare_cgal: the CGAL peer died ({err}); restarting it");
            if let Ok(p) = CgalPeer::spawn() {
                self.peer = p;
            }
        }
    }

    fn compare_map(&mut self, input: &Input, maps_done: usize) {
        let Input {
            group,
            replay,
            map,
            seed,
        } = input;
        let n = map.n();
        {
            let t = self.tally(group);
            t.maps += 1;
            t.largest_n = t.largest_n.max(n);
        }
        let header = |extra: &str| {
            let mut s = format!("  map: {replay}");
            if let Some(name) = map.name() {
                let _ = write!(s, " (name {name:?})");
            }
            let _ = write!(s, ", n = {n}\n{extra}");
            if n <= 200 {
                let _ = writeln!(s, "  map vertices (integer frame): {}", map_text(map));
            }
            s
        };
        if let Err(e) = self.peer.set_map(map) {
            self.revive(&e);
            self.finding(
                group,
                "CGAL refused the map",
                header(&format!("  error: {e}\n")),
            );
            return;
        }
        let k = if n >= LARGE_N {
            self.viewpoints.div_ceil(2)
        } else {
            self.viewpoints
        };
        let k_random = (k / 3).max(1);
        let k_sampled = k - k_random;
        let mut views: Vec<(RatPoint, &str)> = wai_study::sample::viewpoints(map, k_sampled)
            .into_iter()
            .map(|p| (p, "sampled"))
            .collect();
        for p in interior_viewpoints(map, k_random, *seed) {
            if !views.iter().any(|(q, _)| *q == p) {
                views.push((p, "random"));
            }
        }
        let index = VisibilityIndex::new(map);
        for (p, how) in &views {
            self.seen_viewpoints += 1;
            if self.seen_viewpoints.is_multiple_of(PROGRESS_EVERY) {
                self.progress(maps_done);
            }
            {
                let t = self.tally(group);
                t.viewpoints += 1;
                if *how == "sampled" {
                    t.sampled += 1;
                } else {
                    t.random += 1;
                }
            }
            debug_assert_eq!(map.locate(p), Containment::Inside);
            let vp_text = format!(
                "  viewpoint ({how}): {p}  [homogeneous x = {}, y = {}, w = {}]\n",
                p.hx(),
                p.hy(),
                p.hw()
            );
            let ours = match index.visibility_polygon(p) {
                Ok(v) => {
                    let mut pts = v.points();
                    if self
                        .inject_fault
                        .is_some_and(|f| self.seen_viewpoints.is_multiple_of(f))
                    {
                        pts.pop();
                        self.injected += 1;
                    }
                    pts
                }
                Err(e) => {
                    self.finding(
                        group,
                        "ours: error",
                        header(&format!("{vp_text}  error: {e}\n")),
                    );
                    continue;
                }
            };
            if drop_collinear(&ours) != ours {
                self.finding(
                    group,
                    "ours: 180° or repeated vertex",
                    header(&format!("{vp_text}  ours: {}\n", points_text(&ours))),
                );
            }
            if n <= REFERENCE_MAX_N {
                // `wai_exact::sees` reads one ring: maps without holes only.
                if !map.has_holes() {
                    self.tally(group).sees_checked += 1;
                    if let Some(bad) = sees_check(map, p, &ours) {
                        let text = format!("{vp_text}  ours: {}\n  {bad}\n", points_text(&ours));
                        self.finding(group, "ours: fails the sees cross-check", header(&text));
                    }
                }
                self.tally(group).reference_compared += 1;
                match reference::visibility_polygon(map, p) {
                    Ok(r) if r.points() == ours => self.tally(group).reference_equal += 1,
                    Ok(r) => {
                        let r = r.points();
                        let text = format!(
                            "{vp_text}  ours:      {}\n  reference: {}\n{}",
                            points_text(&ours),
                            points_text(&r),
                            diff_text(map, p, &ours, &r, "reference")
                        );
                        self.finding(group, "production != reference", header(&text));
                    }
                    Err(e) => {
                        self.finding(
                            group,
                            "reference: error",
                            header(&format!("{vp_text}  error: {e}\n")),
                        );
                    }
                }
            }
            let theirs = match self.peer.visibility(p) {
                Ok(v) => v,
                Err(e) => {
                    self.revive(&e);
                    self.finding(
                        group,
                        "CGAL: error",
                        header(&format!("{vp_text}  error: {e}\n")),
                    );
                    // A restarted peer has no polygon: skip the rest of the map.
                    if self.peer.scale().is_none() {
                        return;
                    }
                    continue;
                }
            };
            let t = self.tally(group);
            t.cgal_compared += 1;
            let mut distinct = theirs.clone();
            distinct.sort();
            distinct.dedup();
            if distinct.len() != theirs.len() {
                // Against C3: reported, then compared as usual.
                t.with_duplicates += 1;
                let text = format!("{vp_text}  CGAL: {}\n", points_text(&theirs));
                self.finding(group, "CGAL: repeated vertex", header(&text));
            }
            let t = self.tally(group);
            if theirs == ours {
                t.exact += 1;
                continue;
            }
            let corners = drop_collinear(&theirs);
            if corners == ours {
                t.after_c2 += 1;
                if self.examples.len() < self.max_examples {
                    let text = format!(
                        "{vp_text}  ours: {}\n  CGAL: {}\n",
                        points_text(&ours),
                        points_text(&theirs)
                    );
                    self.examples.push(header(&text));
                }
                let t = self.tally(group);
                if *how == "random" {
                    t.after_c2_random += 1;
                }
                let k = theirs.len();
                for (i, q) in theirs.iter().enumerate() {
                    if corners.contains(q) {
                        continue;
                    }
                    if map.vertices().iter().any(|&v| RatPoint::from(v) == *q) {
                        t.dropped_map_vertices += 1;
                    } else {
                        t.dropped_other += 1;
                    }
                    // q is collinear with its neighbours; is the line through p?
                    if orientation_rat(p, &theirs[(i + k - 1) % k], q) == Orientation::Collinear {
                        t.dropped_through_p += 1;
                    }
                }
                continue;
            }
            let text = format!(
                "{vp_text}  ours:         {}\n  CGAL:         {}\n  CGAL corners: {}\n{}",
                points_text(&ours),
                points_text(&theirs),
                points_text(&corners),
                diff_text(map, p, &ours, &corners, "CGAL")
            );
            self.finding(group, "ours != CGAL (after C1-C3)", header(&text));
        }
    }
}

fn main() -> ExitCode {
    let args = match parse_args() {
        Ok(a) => a,
        Err(e) => {
            if e.is_empty() {
                wai_output::outln!("{USAGE}");
                return ExitCode::SUCCESS;
            }
            eprintln!("compare_cgal: {e}\n{USAGE}");
            return ExitCode::from(2);
        }
    };
    if !cgal::available() {
        eprintln!(
            "compare_cgal: CGAL peer not built; run benches/peers/build.sh (looked for {})",
            cgal::binary_path().display()
        );
        return ExitCode::from(2);
    }
    let peer = match CgalPeer::spawn() {
        Ok(p) => p,
        Err(e) => {
            eprintln!("compare_cgal: {e}");
            return ExitCode::from(2);
        }
    };
    let mut run = Run {
        peer,
        tallies: BTreeMap::new(),
        findings: Vec::new(),
        seen_viewpoints: 0,
        start: Instant::now(),
        viewpoints: args.viewpoints,
        inject_fault: args.inject_fault,
        injected: 0,
        examples: Vec::new(),
        max_examples: args.examples,
    };
    let mut maps = 0usize;
    let mut load_errors: Vec<String> = Vec::new();
    let t_random = Instant::now();
    for input in random_inputs(args.polygons) {
        match input {
            Ok(input) => {
                maps += 1;
                run.compare_map(&input, maps);
            }
            Err(e) => load_errors.push(e),
        }
    }
    // The thesis families, whose maps `sample::viewpoints` recognises: the
    // viewpoints of the thesis figures come first.
    for f in wai_gen::FAMILIES {
        // The FAMILY_PARAMS least accepted values of the one parameter.
        let family_maps: Vec<(u32, Map)> = (0..=FAMILY_PARAMS + 2)
            .filter_map(|k| wai_gen::family(f.id, &[k]).ok().map(|m| (k, m)))
            .take(FAMILY_PARAMS as usize)
            .collect();
        if family_maps.len() < FAMILY_PARAMS as usize {
            load_errors.push(format!("wai_gen::family({:?}, &[k]): too few maps", f.id));
        }
        for (k, map) in family_maps {
            maps += 1;
            let input = Input {
                group: "thesis families".to_owned(),
                replay: format!("wai_gen::family({:?}, &[{k}])", f.id),
                map,
                seed: 5_000_000 + u64::from(k),
            };
            run.compare_map(&input, maps);
        }
    }
    let random_time = t_random.elapsed();
    let t_data = Instant::now();
    let mut skipped_large = 0usize;
    if let Some(root) = &args.datasets {
        match dataset_files(root, args.max_agplib_n) {
            Ok(files) => {
                for (i, (group, path, limit)) in files.iter().enumerate() {
                    match load_dataset(group, path, 7_000_000 + i as u64) {
                        Ok(mut input) => {
                            if limit.is_some_and(|l| input.map.n() > l) {
                                skipped_large += 1;
                                continue;
                            }
                            if let Some(f) = path.file_name() {
                                input.replay = format!("{group}/{}", f.to_string_lossy());
                            }
                            maps += 1;
                            run.compare_map(&input, maps);
                        }
                        Err(e) => load_errors.push(e),
                    }
                }
            }
            Err(e) => load_errors.push(e),
        }
    }
    let data_time = t_data.elapsed();
    run.progress(maps);

    // The report.
    let mut total = Tally::default();
    for t in run.tallies.values() {
        total.add(t);
    }
    wai_output::outln!("# compare_cgal: wai's V_p (production, reference) against CGAL 5.5 Triangular_expansion_visibility_2 (Epeck)");
    wai_output::outln!(
        "# {} random maps and the thesis families ({:.1?}), datasets: {} ({:.1?}){}",
        args.polygons,
        random_time,
        match &args.datasets {
            Some(d) => d.display().to_string(),
            None => "none".to_owned(),
        },
        data_time,
        if args.quick { ", --quick" } else { "" }
    );
    if skipped_large > 0 {
        wai_output::outln!(
            "# AGPLIB maps above the --max-dataset-n limit, not read: {skipped_large}"
        );
    }
    wai_output::outln!();
    wai_output::outln!("| group | maps | max n | viewpoints (sampled + random) | vs CGAL | exact | after C2 | CGAL collinear vertices (map / other) | vs reference (equal) | unexplained |");
    wai_output::outln!("|---|---|---|---|---|---|---|---|---|---|");
    let row = |name: &str, t: &Tally| {
        wai_output::outln!(
            "| {name} | {} | {} | {} ({} + {}) | {} | {} | {} | {} / {} | {} ({}) | {} |",
            t.maps,
            t.largest_n,
            t.viewpoints,
            t.sampled,
            t.random,
            t.cgal_compared,
            t.exact,
            t.after_c2,
            t.dropped_map_vertices,
            t.dropped_other,
            t.reference_compared,
            t.reference_equal,
            t.unexplained
        );
    };
    for (g, t) in &run.tallies {
        row(g, t);
    }
    row("**total**", &total);
    wai_output::outln!();
    wai_output::outln!("maps: {}", total.maps);
    wai_output::outln!(
        "viewpoints: {} ({} sampled, {} random)",
        total.viewpoints,
        total.sampled,
        total.random
    );
    wai_output::outln!("polygons compared with CGAL: {}", total.cgal_compared);
    wai_output::outln!("  exact matches: {}", total.exact);
    wai_output::outln!(
        "  matches after C2 (CGAL's collinear in-between vertices dropped): {} ({} vertices dropped: {} map vertices, {} other points)",
        total.after_c2,
        total.dropped_map_vertices + total.dropped_other,
        total.dropped_map_vertices,
        total.dropped_other
    );
    wai_output::outln!(
        "    of these matches, at random viewpoints: {}",
        total.after_c2_random
    );
    wai_output::outln!(
        "    of the dropped vertices, on a straight stretch through the viewpoint: {}",
        total.dropped_through_p
    );
    wai_output::outln!(
        "  CGAL replies with a repeated vertex: {}",
        total.with_duplicates
    );
    wai_output::outln!(
        "production vs reference (n <= {REFERENCE_MAX_N}): {} compared, {} equal",
        total.reference_compared,
        total.reference_equal
    );
    wai_output::outln!(
        "sees cross-check of ours (n <= {REFERENCE_MAX_N}): {} checked, {} failed",
        total.sees_checked,
        run.findings
            .iter()
            .filter(|f| f.category == "ours: fails the sees cross-check")
            .count()
    );
    if args.inject_fault.is_some() {
        wai_output::outln!("injected faults (self-test): {}", run.injected);
    }
    let mut by_cat: BTreeMap<&str, usize> = BTreeMap::new();
    for f in &run.findings {
        *by_cat.entry(f.category).or_default() += 1;
    }
    wai_output::outln!("unexplained: {}", run.findings.len() + load_errors.len());
    for (c, k) in &by_cat {
        wai_output::outln!("  {c}: {k}");
    }
    if !load_errors.is_empty() {
        wai_output::outln!("  map not loaded: {}", load_errors.len());
    }
    wai_output::outln!("time: {:.1?}", run.start.elapsed());
    for e in &load_errors {
        wai_output::outln!("\nMAP NOT LOADED: {e}");
    }
    for (i, e) in run.examples.iter().enumerate() {
        wai_output::outln!("\nMATCH AFTER C2, example {}\n{e}", i + 1);
    }
    for (i, f) in run.findings.iter().enumerate() {
        wai_output::outln!("\nUNEXPLAINED #{} [{}]\n{}", i + 1, f.category, f.text);
    }
    if run.findings.is_empty() && load_errors.is_empty() {
        ExitCode::SUCCESS
    } else {
        ExitCode::FAILURE
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn random_inputs_cover_every_kind_and_size() {
        let combos = wai_gen::RANDOM_KINDS.len() * SIZES.len();
        let mut seen = std::collections::BTreeSet::new();
        for input in random_inputs(combos) {
            let input = input.unwrap();
            assert!(input.replay.ends_with(", 1)"), "{}", input.replay);
            seen.insert(input.replay);
        }
        assert_eq!(seen.len(), combos);
        assert!(seen
            .iter()
            .any(|r| r.contains("\"random-simple-2opt\", 300,")));
    }
}
