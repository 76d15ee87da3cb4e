#![allow(
    clippy::float_arithmetic,
    reason = "scans, poses, errors and timings are approximate (issue 12)"
)]
//! `wai localize-scan` (one scan against a map: the ranked cells, the
//! refined pose and the answer set) and `wai eval` (the evaluation
//! protocol of issue 12 over many maps, side by side with the peers).
//! The engine is [`wai_scan`]; chapter 6 of the thesis.

use std::path::{Path, PathBuf};
use std::time::Instant;

use serde_json::{json, Value};
use wai_map::Map;
use wai_scan::eval::{self, CompassMode, Condition, Outcome, Summary, Trial};
use wai_scan::units::{to_metres, Units};
use wai_scan::{Compass, Options, Pose, Scan, ScanLocalizer};

use crate::input::{load, Format};
use crate::Failure;

#[derive(clap::Args, Debug)]
pub struct LocalizeArgs {
    /// Map file (JSON map format or GeoJSON), or a generated map:
    /// `rooms:K`, `office:K[:SEED]`, `family:ID:P1,P2,…`.
    pub map: String,
    /// The scan, as `wai scan` writes it: {"angles": [...], "ranges": [... | null]}
    /// (angles in radians relative to the heading; optional "sensor": {"max_range"}
    /// and "pose": {"heading_degrees"}).
    pub scan: PathBuf,
    /// What the robot knows of its heading: `exact`, `noisy:ε` (ε in
    /// degrees) or `none`. The reading is --heading, else the scan file's
    /// pose heading.
    #[arg(long, default_value = "exact")]
    pub compass: String,
    /// The compass reading in degrees (counter-clockwise from the x axis).
    #[arg(long, allow_hyphen_values = true)]
    pub heading: Option<f64>,
    /// The map's units: `auto`, `m`, `lonlat` or `scale:K` (K metres per
    /// unit). Auto: longitude/latitude when the map spans less than 0.1°
    /// within ±180/±90, 0.025 m per pixel for an R2V file, else metres.
    #[arg(long, default_value = "auto")]
    pub units: String,
    /// A local query (sec. 6.10.4): only cells whose site lies within R
    /// metres of X,Y.
    #[arg(long, allow_hyphen_values = true, value_name = "X,Y,R")]
    pub near: Option<String>,
    /// Print JSON instead of text.
    #[arg(long)]
    pub json: bool,
    /// Draw the map, the scan at the best pose and the answer set here.
    #[arg(long)]
    pub svg: Option<PathBuf>,
}

#[derive(clap::Args, Debug)]
pub struct EvalArgs {
    /// Maps: files (JSON map format or GeoJSON; `PATH@UNITS` sets one
    /// map's units) or generated maps `rooms:K`, `office:K[:SEED]`,
    /// `family:ID:P1,P2,…` (generated maps are in metres).
    #[arg(required = true)]
    pub maps: Vec<String>,
    /// Seeded random poses per map (at least 0.2 m from every wall).
    #[arg(long, default_value_t = 500)]
    pub poses: usize,
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Compass modes, comma-separated: `exact`, `none`, `noisy:ε` (ε in
    /// degrees; the reading is off by a seeded uniform error in [−ε, ε]).
    #[arg(long, default_value = "exact,none")]
    pub compass: String,
    /// Conditions, comma-separated: `base` (720 beams over 360°, σ 2 cm),
    /// `boxes` (5 unknown 0.5 m boxes), `fov180`, `range10` (10 m cutoff),
    /// or `all`.
    #[arg(long, default_value = "all")]
    pub conditions: String,
    /// Run a peer on the same scans in the same call: `karto`
    /// (karto-scanmatcher, installed by scripts/install-karto). Repeatable.
    #[arg(long)]
    pub peer: Vec<String>,
    /// Queries per map and condition given to each peer (the first ones
    /// of ours; peers are slow).
    #[arg(long, default_value_t = 100)]
    pub peer_poses: usize,
    /// The conditions the peers run under (as --conditions; `all` is
    /// every condition evaluated).
    #[arg(long, default_value = "all")]
    pub peer_conditions: String,
    /// Units of the map files (see `wai localize-scan --help`).
    #[arg(long, default_value = "auto")]
    pub units: String,
    /// Folder for the error CDF plots (SVG) and eval.json.
    #[arg(long, default_value = "target/wai-eval")]
    pub out: PathBuf,
    /// Print the JSON on standard output instead of the tables.
    #[arg(long)]
    pub json: bool,
    /// Exit 1 when our answer set holds the truth in fewer than this
    /// fraction of all queries (a regression gate for CI).
    #[arg(long)]
    pub require_answer_set: Option<f64>,
}

/// A map of an evaluation, in metres.
pub(crate) struct EvalMap {
    pub name: String,
    kind: &'static str,
    pub map: Map,
    units: String,
    /// For `rooms:K`: K rooms, 5 m apart, the first from x = 1 m, floors
    /// at y = 2.2 m (see [`wai_gen::repeated_rooms`]).
    rooms: Option<usize>,
}

fn parse_units(text: &str) -> Result<Option<Units>, Failure> {
    match text {
        "auto" => Ok(None),
        "m" => Ok(Some(Units::Metres)),
        "lonlat" => Ok(Some(Units::LonLatDegrees)),
        _ => match text.strip_prefix("scale:").map(str::parse::<f64>) {
            Some(Ok(k)) if k.is_finite() && k > 0.0 => Ok(Some(Units::Scale(k))),
            _ => Err(Failure::usage(format!(
                "units {text:?}: expected auto, m, lonlat or scale:K with K > 0"
            ))),
        },
    }
}

/// The units `auto` picks for `map` read from `path`.
fn auto_units(path: &str, map: &Map) -> Units {
    let s = map.scale().to_f64();
    let (lo, hi) = map.bounding_box();
    let (x0, y0, x1, y1) = (
        lo.x as f64 / s,
        lo.y as f64 / s,
        hi.x as f64 / s,
        hi.y as f64 / s,
    );
    let in_degrees = x0 >= -180.0 && x1 <= 180.0 && y0 >= -90.0 && y1 <= 90.0;
    if in_degrees && x1 - x0 < 0.1 && y1 - y0 < 0.1 {
        Units::LonLatDegrees
    } else if path.contains("r2v") {
        // R2V annotations are image pixels; floor plans of flats at about
        // 40 px per metre (an assumption: the source gives no scale).
        Units::Scale(0.025)
    } else {
        Units::Metres
    }
}

fn units_label(u: Units) -> String {
    match u {
        Units::Metres => "m".into(),
        Units::LonLatDegrees => "lonlat".into(),
        Units::Scale(k) => format!("scale:{k}"),
    }
}

fn gen_failure(spec: &str, e: impl std::fmt::Display) -> Failure {
    Failure::usage(format!("{spec}: {e}"))
}

fn parse_u32(spec: &str, s: &str) -> Result<u32, Failure> {
    s.parse()
        .map_err(|_| Failure::usage(format!("{spec}: {s:?} is not a count")))
}

/// Whether `spec` names a generated map rather than a file.
pub(crate) fn is_generated(spec: &str) -> bool {
    ["rooms:", "office:", "family:"]
        .iter()
        .any(|p| spec.starts_with(p))
        && !Path::new(spec).exists()
}

/// `map`, read from `path`, in metres by `units` (`auto` guesses), and the
/// units used.
pub(crate) fn in_metres(path: &str, map: Map, units: &str) -> Result<(Map, String), Failure> {
    let u = parse_units(units)?.unwrap_or_else(|| auto_units(path, &map));
    if u == Units::Metres {
        return Ok((map, units_label(u)));
    }
    let metres = to_metres(&map, u).map_err(|e| {
        Failure::invalid(format!(
            "{path}: in metres ({}) the map is no longer valid: {e}",
            units_label(u)
        ))
    })?;
    Ok((metres, units_label(u)))
}

pub(crate) fn load_map(spec: &str, units: &str) -> Result<EvalMap, Failure> {
    let generated = |kind, map: Map, rooms| EvalMap {
        name: spec.to_owned(),
        kind,
        map,
        units: "m".into(),
        rooms,
    };
    if !is_generated(spec) {
        return load_file(spec, units);
    }
    if let Some(k) = spec.strip_prefix("rooms:") {
        let k = parse_u32(spec, k)?;
        if !(1..=200).contains(&k) {
            return Err(Failure::usage(format!("{spec}: between 1 and 200 rooms")));
        }
        return Ok(generated(
            "repeated rooms",
            wai_gen::repeated_rooms(k),
            Some(k as usize),
        ));
    }
    if let Some(rest) = spec.strip_prefix("office:") {
        let mut parts = rest.splitn(2, ':');
        let k = parse_u32(spec, parts.next().unwrap_or(""))?;
        let seed = parts.next().map_or(Ok(1), |s| {
            s.parse::<u64>()
                .map_err(|_| Failure::usage(format!("{spec}: {s:?} is not a seed")))
        })?;
        if !(1..=100).contains(&k) {
            return Err(Failure::usage(format!(
                "{spec}: between 1 and 100 rooms a side"
            )));
        }
        return Ok(generated("office", wai_gen::office(k, seed), None));
    }
    if let Some(rest) = spec.strip_prefix("family:") {
        let (id, params) = rest.split_once(':').unwrap_or((rest, ""));
        let params = params
            .split(',')
            .filter(|s| !s.is_empty())
            .map(|s| parse_u32(spec, s))
            .collect::<Result<Vec<_>, _>>()?;
        let map = wai_gen::family(id, &params).map_err(|e| gen_failure(spec, e))?;
        return Ok(generated("family", map, None));
    }
    Err(Failure::usage(format!(
        "{spec}: expected rooms:K, office:K[:SEED] or family:ID:P1,P2,…"
    )))
}

fn load_file(spec: &str, units: &str) -> Result<EvalMap, Failure> {
    let (path, units) = match spec.rsplit_once('@') {
        Some((p, u)) if !Path::new(spec).exists() => (p, u),
        _ => (spec, units),
    };
    let map = load(Path::new(path), Format::Auto)?.map;
    let name = map.name().map_or_else(|| path.to_owned(), str::to_owned);
    let (metres, u) = in_metres(path, map, units)?;
    let kind = if path.contains("westport") {
        "westport"
    } else if path.contains("r2v") {
        "r2v"
    } else {
        "file"
    };
    Ok(EvalMap {
        name,
        kind,
        map: metres,
        units: u,
        rooms: None,
    })
}

fn read_scan(path: &Path) -> Result<(Scan, Option<f64>, Option<f64>), Failure> {
    let bytes = crate::input::read_bytes(path)?;
    let shown = path.display();
    let v: Value = serde_json::from_slice(&bytes)
        .map_err(|e| Failure::invalid(format!("{shown}: not JSON: {e}")))?;
    let numbers = |key: &str| -> Result<Vec<Option<f64>>, Failure> {
        v.get(key)
            .and_then(Value::as_array)
            .ok_or_else(|| Failure::invalid(format!("{shown}: no array {key:?}")))?
            .iter()
            .enumerate()
            .map(|(i, x)| match x {
                Value::Null => Ok(None),
                _ => x
                    .as_f64()
                    .filter(|f| f.is_finite())
                    .map(Some)
                    .ok_or_else(|| {
                        Failure::invalid(format!("{shown}: {key}[{i}] is not a finite number"))
                    }),
            })
            .collect()
    };
    let angles = numbers("angles")?;
    let ranges = numbers("ranges")?;
    if angles.len() != ranges.len() || angles.is_empty() {
        return Err(Failure::invalid(format!(
            "{shown}: {} angles and {} ranges: expected as many, at least one",
            angles.len(),
            ranges.len()
        )));
    }
    let angles = angles
        .into_iter()
        .enumerate()
        .map(|(i, a)| a.ok_or_else(|| Failure::invalid(format!("{shown}: angles[{i}] is null"))))
        .collect::<Result<Vec<_>, _>>()?;
    if let Some((i, r)) = ranges
        .iter()
        .enumerate()
        .find(|(_, r)| r.is_some_and(|r| r < 0.0))
    {
        return Err(Failure::invalid(format!(
            "{shown}: ranges[{i}] = {} is negative",
            r.unwrap_or_default()
        )));
    }
    let max_range = v
        .pointer("/sensor/max_range")
        .and_then(Value::as_f64)
        .filter(|r| r.is_finite() && *r > 0.0);
    let heading = v
        .pointer("/pose/heading_degrees")
        .and_then(Value::as_f64)
        .map(f64::to_radians);
    Ok((Scan { angles, ranges }, max_range, heading))
}

fn pose_json(p: &Pose) -> Value {
    json!({ "x": p.x, "y": p.y, "heading_degrees": p.heading.to_degrees() })
}

fn parse_near(text: &str) -> Result<wai_scan::Near, Failure> {
    let v: Vec<f64> = text
        .split(',')
        .map(|s| s.trim().parse::<f64>())
        .collect::<Result<_, _>>()
        .map_err(|_| Failure::usage(format!("--near {text:?}: expected X,Y,R")))?;
    match v[..] {
        [x, y, r] if x.is_finite() && y.is_finite() && r.is_finite() && r > 0.0 => {
            Ok(wai_scan::Near {
                at: (x, y),
                radius: r,
            })
        }
        _ => Err(Failure::usage(format!(
            "--near {text:?}: expected X,Y,R with R > 0"
        ))),
    }
}

pub fn localize_scan(args: &LocalizeArgs) -> Result<(), Failure> {
    let mode = CompassMode::parse(&args.compass).map_err(Failure::usage)?;
    let m = load_map(&args.map, &args.units)?;
    let (scan, max_range, file_heading) = read_scan(&args.scan)?;
    let reading = args.heading.map(f64::to_radians).or(file_heading);
    let compass = match (mode, reading) {
        (CompassMode::None, _) => Compass::None,
        (_, None) => {
            return Err(Failure::usage(
                "a compass needs a reading: give --heading or a scan with pose.heading_degrees",
            ))
        }
        (CompassMode::Exact, Some(h)) => Compass::Exact(h),
        (CompassMode::Noisy(eps), Some(h)) => Compass::Noisy { heading: h, eps },
    };
    let t = Instant::now();
    let loc = ScanLocalizer::new(
        &m.map,
        Options {
            max_range,
            ..Options::default()
        },
    );
    let preprocess_s = t.elapsed().as_secs_f64();
    let near = args.near.as_deref().map(parse_near).transpose()?;
    let (answer, ms) = loc.localize_timed(&scan, &compass, near);
    if let Some(path) = &args.svg {
        let svg = wai_scan::draw::answer_svg(loc.walls(), &scan, &answer, None, 800.0);
        crate::scan::write(path, &svg)?;
    }
    let cell_of = |site: usize| loc.sites()[site].cell;
    if args.json {
        let out = json!({
            "map": m.name,
            "units": m.units,
            "compass": args.compass,
            "cells": loc.cells().len(),
            "sites": loc.sites().len(),
            "preprocess_s": preprocess_s,
            "ms": ms,
            "best": answer.best.as_ref().map(|h| json!({"pose": pose_json(&h.pose), "score": h.score, "cell": cell_of(h.from_site)})),
            "answer_set": answer.answer_set.iter().map(|h| json!({"pose": pose_json(&h.pose), "score": h.score, "cell": cell_of(h.from_site)})).collect::<Vec<_>>(),
            "ranked": answer.ranked.iter().map(|r| json!({"cell": cell_of(r.site), "site": loc.sites()[r.site].at, "pcm": r.pcm, "heading_degrees": r.heading.to_degrees()})).collect::<Vec<_>>(),
            "pcm_evaluations": answer.evaluations,
        });
        println!(
            "{}",
            serde_json::to_string_pretty(&out).expect("plain JSON")
        );
        return Ok(());
    }
    println!(
        "{}: {} cells, {} sites, preprocessed in {preprocess_s:.2} s; query {ms:.1} ms ({} PCM evaluations)",
        m.name,
        loc.cells().len(),
        loc.sites().len(),
        answer.evaluations
    );
    match &answer.best {
        None => println!("no pose found"),
        Some(b) => println!(
            "best pose ({:.3}, {:.3}) heading {:.2}° in cell {}, score {:.5}",
            b.pose.x,
            b.pose.y,
            b.pose.heading.to_degrees(),
            cell_of(b.from_site),
            b.score
        ),
    }
    println!(
        "answer set ({} poses as good as the best):",
        answer.answer_set.len()
    );
    for h in &answer.answer_set {
        println!(
            "  ({:.3}, {:.3}) {:.2}°  score {:.5}",
            h.pose.x,
            h.pose.y,
            h.pose.heading.to_degrees(),
            h.score
        );
    }
    Ok(())
}

/// What one row measured: ours, and each peer on the first queries.
struct Row {
    condition: &'static str,
    compass: String,
    trials: Vec<Trial>,
    ours: Vec<Outcome>,
    look_alikes: Option<Value>,
    peers: Vec<(String, Vec<Outcome>)>,
}

fn conditions(text: &str) -> Result<Vec<Condition>, Failure> {
    let all = Condition::standard();
    if text == "all" {
        return Ok(all);
    }
    text.split(',')
        .map(|c| {
            let i = match c {
                "base" => 0,
                "boxes" => 1,
                "fov180" => 2,
                "range10" => 3,
                _ => {
                    return Err(Failure::usage(format!(
                        "condition {c:?}: expected base, boxes, fov180, range10 or all"
                    )))
                }
            };
            Ok(all[i].clone())
        })
        .collect()
}

/// The look-alike figures of a `rooms:K` row: of the queries whose pose is
/// in a room, how often the answer set holds the truth and every
/// look-alike (the same pose in another room), and how often each peer's
/// one answer was wrong there.
fn look_alike_figures(
    rooms: usize,
    walls: &wai_scan::walls::Walls,
    max_range: Option<f64>,
    row_trials: &[Trial],
    ours: &[Outcome],
    peers: &[(String, Vec<Outcome>)],
) -> Value {
    // A twin (the same pose in another room) is a look-alike when the map
    // gives it the same ranges: a view through the door may tell rooms
    // apart by where the corridor ends.
    let alike = |t: &Trial| -> Vec<Pose> {
        eval::room_twins(&t.truth, rooms, 5.0, 1.0, 2.2)
            .into_iter()
            .filter(|q| eval::indistinguishable(walls, &t.truth, q, &t.scan.angles, max_range))
            .collect()
    };
    let in_rooms: Vec<usize> = (0..row_trials.len())
        .filter(|&i| !eval::room_twins(&row_trials[i].truth, rooms, 5.0, 1.0, 2.2).is_empty())
        .collect();
    let alikes: f64 = in_rooms
        .iter()
        .map(|&i| alike(&row_trials[i]).len() as f64)
        .sum();
    let holds = |o: &Outcome, p: &Pose| o.set.iter().any(|s| eval::NORMAL.accepts(s, p));
    let complete = in_rooms
        .iter()
        .filter(|&&i| {
            let t = &row_trials[i];
            holds(&ours[i], &t.truth) && alike(t).iter().all(|p| holds(&ours[i], p))
        })
        .count();
    let sizes: f64 = in_rooms.iter().map(|&i| ours[i].set.len() as f64).sum();
    let peer_failures: Vec<Value> = peers
        .iter()
        .map(|(name, outs)| {
            let queried: Vec<usize> = in_rooms
                .iter()
                .copied()
                .filter(|&i| i < outs.len())
                .collect();
            let failed = queried
                .iter()
                .filter(|&&i| {
                    !outs[i]
                        .best
                        .as_ref()
                        .is_some_and(|b| eval::NORMAL.accepts(b, &row_trials[i].truth))
                })
                .count();
            json!({"name": name, "queries_in_rooms": queried.len(), "failures": failed})
        })
        .collect();
    json!({
        "rooms": rooms,
        "queries_in_rooms": in_rooms.len(),
        "mean_look_alikes_per_query": alikes / in_rooms.len().max(1) as f64,
        "answer_set_holds_truth_and_all_look_alikes": complete,
        "answer_set_holds_truth_and_all_look_alikes_rate": complete as f64 / in_rooms.len().max(1) as f64,
        "mean_answer_set_size_in_rooms": sizes / in_rooms.len().max(1) as f64,
        "peers": peer_failures,
    })
}

/// A running peer: answers one scan at a time.
trait Peer {
    fn name(&self) -> String;
    fn localize(&mut self, scan: &Scan, max_range: Option<f64>) -> Result<Outcome, String>;
}

fn start_peer(name: &str, map: &Map) -> Result<Box<dyn Peer>, Failure> {
    peers::start(name, map)
}

mod peers {
    use super::{Failure, Map, Outcome, Peer, Scan};
    use wai_scan::peer::{map_walls, KartoConfig, KartoPeer};

    struct Karto {
        name: String,
        peer: KartoPeer,
    }

    impl Peer for Karto {
        fn name(&self) -> String {
            self.name.clone()
        }

        fn localize(&mut self, scan: &Scan, max_range: Option<f64>) -> Result<Outcome, String> {
            let a = self
                .peer
                .localize(scan, max_range)
                .map_err(|e| e.to_string())?;
            // The match's own time, measured in the peer (no pipes, no
            // JSON): the fairest time to quote for it.
            Ok(Outcome {
                best: Some(a.pose),
                set: vec![a.pose],
                ms: a.ms,
            })
        }
    }

    /// `karto` (karto-scanmatcher at its default 0.05 m grid) or
    /// `karto:R` (an R-metre grid).
    pub fn start(name: &str, map: &Map) -> Result<Box<dyn Peer>, Failure> {
        let resolution = match name {
            "karto" => KartoConfig::default().resolution,
            _ => match name.strip_prefix("karto:").map(str::parse::<f64>) {
                Some(Ok(r)) if r.is_finite() && r > 0.0 && r <= 1.0 => r,
                _ => {
                    return Err(Failure::usage(format!(
                        "peer {name:?}: expected karto or karto:R with R the grid in metres (0, 1]"
                    )))
                }
            },
        };
        let config = KartoConfig {
            resolution,
            smear_deviation: resolution,
            ..KartoConfig::default()
        };
        let peer = KartoPeer::spawn(&map_walls(map), &config)
            .map_err(|e| Failure::io(format!("peer {name}: {e}")))?;
        Ok(Box::new(Karto {
            name: name.to_owned(),
            peer,
        }))
    }
}

pub fn eval(args: &EvalArgs) -> Result<(), Failure> {
    let modes = args
        .compass
        .split(',')
        .map(CompassMode::parse)
        .collect::<Result<Vec<_>, _>>()
        .map_err(Failure::usage)?;
    let conds = conditions(&args.conditions)?;
    let peer_conds = conditions(&args.peer_conditions)?;
    if args.poses == 0 {
        return Err(Failure::usage("--poses must be at least 1"));
    }
    parse_units(&args.units)?;
    let maps = args
        .maps
        .iter()
        .map(|s| load_map(s, &args.units))
        .collect::<Result<Vec<_>, _>>()?;
    std::fs::create_dir_all(&args.out)
        .map_err(|e| Failure::io(format!("{}: {e}", args.out.display())))?;
    let mut map_reports = Vec::new();
    let mut all_trials: Vec<Trial> = Vec::new();
    let mut all_ours: Vec<Outcome> = Vec::new();
    let mut all_peers: Vec<(String, Vec<Trial>, Vec<Outcome>)> = Vec::new();
    let mut overall_series: Vec<(String, Vec<f64>)> = Vec::new();
    for m in &maps {
        let bar = crate::progress_bar(0);
        bar.set_message(format!("{}: decomposing and preprocessing", m.name));
        let t = Instant::now();
        let full = ScanLocalizer::new(&m.map, Options::default());
        let preprocess_s = t.elapsed().as_secs_f64();
        let needs_cut = conds.iter().any(|c| c.sensor.max_range.is_some());
        let cut = needs_cut.then(|| {
            ScanLocalizer::new(
                &m.map,
                Options {
                    max_range: Some(10.0),
                    ..Options::default()
                },
            )
        });
        let poses = eval::random_poses(&m.map, full.walls(), args.poses, 0.2, args.seed);
        if poses.len() < args.poses {
            bar.finish_and_clear();
            return Err(Failure::invalid(format!(
                "{}: only {} of {} poses at least 0.2 m from every wall could be drawn",
                m.name,
                poses.len(),
                args.poses
            )));
        }
        let mut peers: Vec<Box<dyn Peer>> = args
            .peer
            .iter()
            .map(|p| start_peer(p, &m.map))
            .collect::<Result<_, _>>()?;
        let peer_rows = conds
            .iter()
            .filter(|c| peer_conds.iter().any(|p| p.name == c.name))
            .count();
        let queries = conds.len() * modes.len() * poses.len()
            + peer_rows * peers.len() * args.peer_poses.min(poses.len());
        bar.set_length(queries as u64);
        let mut rows: Vec<Row> = Vec::new();
        for c in &conds {
            let loc = match (&cut, c.sensor.max_range) {
                (Some(l), Some(_)) => l,
                _ => &full,
            };
            // The scans of this condition, simulated once: every compass
            // row and every peer gets the same ones.
            let scans = eval::trials(&m.map, &poses, c, CompassMode::None, args.seed)
                .map_err(|e| Failure::invalid(format!("{}: {e}", m.name)))?;
            let mut peer_outcomes: Vec<(String, Vec<Outcome>)> = Vec::new();
            let peers_here = peer_conds.iter().any(|p| p.name == c.name);
            for peer in peers.iter_mut().filter(|_| peers_here) {
                let trials = &scans[..args.peer_poses.min(scans.len())];
                let mut outs = Vec::with_capacity(trials.len());
                for (i, t) in trials.iter().enumerate() {
                    bar.set_message(format!(
                        "{}: {}, peer {} query {i}",
                        m.name,
                        c.name,
                        peer.name()
                    ));
                    let o = peer
                        .localize(&t.scan, c.sensor.max_range)
                        .map_err(|e| Failure::io(format!("peer {}: {e}", peer.name())))?;
                    outs.push(o);
                    bar.inc(1);
                }
                peer_outcomes.push((peer.name(), outs));
            }
            for mode in &modes {
                let trials = eval::with_compass(&scans, *mode, args.seed);
                bar.set_message(format!("{}: {}, compass {}", m.name, c.name, mode.label()));
                let ours: Vec<Outcome> = trials
                    .iter()
                    .map(|t| {
                        let (a, ms) = loc.localize_timed(&t.scan, &t.compass, None);
                        bar.inc(1);
                        Outcome::of(&a, ms)
                    })
                    .collect();
                let look_alikes = m.rooms.map(|k| {
                    look_alike_figures(
                        k,
                        loc.walls(),
                        c.sensor.max_range,
                        &trials,
                        &ours,
                        &peer_outcomes,
                    )
                });
                rows.push(Row {
                    condition: c.name,
                    compass: mode.label(),
                    trials,
                    ours,
                    look_alikes,
                    peers: peer_outcomes.clone(),
                });
            }
        }
        bar.finish_and_clear();
        let summaries: Vec<Summary> = rows
            .iter()
            .map(|r| eval::summarise(&r.trials, &r.ours))
            .collect();
        // The error CDF of this map: ours per row, each peer per condition.
        let mut series: Vec<(String, Vec<f64>)> = Vec::new();
        let mut row_json = Vec::new();
        for (r, s) in rows.iter().zip(&summaries) {
            series.push((
                format!("{} / {}", r.condition, r.compass),
                s.position_errors.clone(),
            ));
            let mut j = s.to_json();
            j["condition"] = json!(r.condition);
            j["compass"] = json!(r.compass);
            j["peers"] = json!(r
                .peers
                .iter()
                .map(|(name, outs)| {
                    let n = outs.len();
                    let ps = eval::summarise(&r.trials[..n], outs);
                    let same = eval::summarise(&r.trials[..n], &r.ours[..n]);
                    if !series
                        .iter()
                        .any(|(l, _)| *l == format!("{name} / {}", r.condition))
                    {
                        series.push((
                            format!("{name} / {}", r.condition),
                            ps.position_errors.clone(),
                        ));
                    }
                    let mut pj = ps.to_json();
                    pj["name"] = json!(name);
                    pj["compass"] = json!("none (full-circle search)");
                    pj["ours_on_the_same_queries"] = json!({
                        "queries": n,
                        "success_rate": same.success_rate,
                        "median_ms": same.median_ms,
                    });
                    pj["median_ms_ratio_peer_over_ours"] = json!(ps.median_ms / same.median_ms);
                    pj
                })
                .collect::<Vec<_>>());
            if let Some(l) = &r.look_alikes {
                j["look_alikes"] = l.clone();
            }
            // How much the scans saw: a scan with few returns (an empty
            // hall beyond the range limit) is ambiguous for any localizer.
            let fractions: Vec<f64> = r
                .trials
                .iter()
                .map(|t| {
                    t.scan.ranges.iter().filter(|x| x.is_some()).count() as f64
                        / t.scan.ranges.len().max(1) as f64
                })
                .collect();
            j["mean_returns_fraction"] =
                json!(fractions.iter().sum::<f64>() / fractions.len().max(1) as f64);
            j["queries_under_25_percent_returns"] =
                json!(fractions.iter().filter(|f| **f < 0.25).count());
            row_json.push(j);
        }
        let slug: String = m
            .name
            .chars()
            .map(|c| {
                if c.is_ascii_alphanumeric() || c == '-' {
                    c
                } else {
                    '_'
                }
            })
            .collect();
        let cdf_path = args.out.join(format!("cdf-{slug}.svg"));
        let svg = eval::cdf_svg(
            &format!("Position error CDF: {} ({} poses)", m.name, poses.len()),
            "position error of the best pose (m)",
            1.0,
            &series
                .iter()
                .map(|(l, v)| (l.clone(), v.as_slice()))
                .collect::<Vec<_>>(),
        );
        crate::scan::write(&cdf_path, &svg)?;
        if !args.json {
            print_table(m, &full, preprocess_s, &rows, &summaries, &cdf_path);
        }
        map_reports.push(json!({
            "map": m.name,
            "kind": m.kind,
            "units": m.units,
            "vertices": m.map.n(),
            "cells": full.cells().len(),
            "sites": full.sites().len(),
            "preprocess_s": preprocess_s,
            "poses": poses.len(),
            "rows": row_json,
            "cdf_svg": cdf_path.display().to_string(),
        }));
        let mut counted: Vec<&str> = Vec::new();
        for (r, summary) in rows.into_iter().zip(summaries) {
            let label = format!("{} / {}", r.condition, r.compass);
            match overall_series.iter_mut().find(|(l, _)| *l == label) {
                Some((_, v)) => v.extend(summary.position_errors),
                None => overall_series.push((label, summary.position_errors)),
            }
            // Every compass row of a condition holds the same peer answers
            // (peers use no compass): count them once.
            let first_of_condition = !counted.contains(&r.condition);
            counted.push(r.condition);
            for (name, outs) in r.peers.iter().filter(|_| first_of_condition) {
                let n = outs.len();
                match all_peers.iter_mut().find(|(p, ..)| p == name) {
                    Some((_, ts, os)) => {
                        ts.extend_from_slice(&r.trials[..n]);
                        os.extend_from_slice(outs);
                    }
                    None => all_peers.push((name.clone(), r.trials[..n].to_vec(), outs.clone())),
                }
            }
            all_trials.extend(r.trials);
            all_ours.extend(r.ours);
        }
    }
    for (name, ts, os) in &all_peers {
        let mut e = eval::summarise(ts, os).position_errors;
        e.sort_by(f64::total_cmp);
        overall_series.push((name.clone(), e));
    }
    for (_, v) in &mut overall_series {
        v.sort_by(f64::total_cmp);
    }
    let cdf_all = args.out.join("cdf-all.svg");
    let svg = eval::cdf_svg(
        &format!("Position error CDF over {} maps", maps.len()),
        "position error of the best pose (m)",
        1.0,
        &overall_series
            .iter()
            .map(|(l, v)| (l.clone(), v.as_slice()))
            .collect::<Vec<_>>(),
    );
    crate::scan::write(&cdf_all, &svg)?;
    let overall: Summary = eval::summarise(&all_trials, &all_ours);
    let mut report = overall.to_json();
    report["seed"] = json!(args.seed);
    report["poses_per_map"] = json!(args.poses);
    report["compass"] = json!(modes.iter().map(CompassMode::label).collect::<Vec<_>>());
    report["conditions"] = json!(conds.iter().map(|c| c.name).collect::<Vec<_>>());
    report["peers"] = json!(all_peers
        .iter()
        .map(|(name, ts, os)| {
            let mut j = eval::summarise(ts, os).to_json();
            j["name"] = json!(name);
            j
        })
        .collect::<Vec<_>>());
    report["maps"] = json!(map_reports);
    report["cdf_svg"] = json!(cdf_all.display().to_string());
    let text = serde_json::to_string_pretty(&report).expect("plain JSON") + "\n";
    let json_path = args.out.join("eval.json");
    crate::scan::write(&json_path, &text)?;
    if args.json {
        print!("{text}");
    } else {
        println!(
            "\nall maps: {} queries, success {:.1} % (strict {:.1} %, loose {:.1} %), answer set holds the truth {:.1} %, median {:.2} ms",
            overall.queries,
            100.0 * overall.success_rate,
            100.0 * overall.success_rate_strict,
            100.0 * overall.success_rate_loose,
            100.0 * overall.answer_set_contains_truth_rate,
            overall.median_ms
        );
        println!(
            "error CDF: {}; JSON: {}",
            cdf_all.display(),
            json_path.display()
        );
    }
    if let Some(min) = args.require_answer_set {
        if overall.answer_set_contains_truth_rate < min {
            return Err(Failure::invalid(format!(
                "the answer set held the truth in {:.3} of the queries, below the required {min}",
                overall.answer_set_contains_truth_rate
            )));
        }
    }
    Ok(())
}

fn print_table(
    m: &EvalMap,
    loc: &ScanLocalizer,
    preprocess_s: f64,
    rows: &[Row],
    summaries: &[Summary],
    cdf: &Path,
) {
    println!(
        "\n{} ({}, units {}): n = {}, {} cells, {} sites, preprocessed in {preprocess_s:.2} s; {} poses",
        m.name,
        m.kind,
        m.units,
        m.map.n(),
        loc.cells().len(),
        loc.sites().len(),
        rows.first().map_or(0, |r| r.trials.len())
    );
    println!(
        "  {:<24} {:<14} {:>8} {:>8} {:>8} {:>8} {:>6} {:>9} {:>9}",
        "condition",
        "localizer",
        "success",
        "strict",
        "loose",
        "set∋true",
        "|set|",
        "median ms",
        "p90 ms"
    );
    let line = |cond: &str, who: &str, s: &Summary| {
        println!(
            "  {:<24} {:<14} {:>7.1}% {:>7.1}% {:>7.1}% {:>7.1}% {:>6.2} {:>9.2} {:>9.2}",
            cond,
            who,
            100.0 * s.success_rate,
            100.0 * s.success_rate_strict,
            100.0 * s.success_rate_loose,
            100.0 * s.answer_set_contains_truth_rate,
            s.mean_answer_set_size,
            s.median_ms,
            s.p90_ms
        );
    };
    let mut shown_peers: Vec<String> = Vec::new();
    for (r, s) in rows.iter().zip(summaries) {
        line(r.condition, &format!("ours/{}", r.compass), s);
        for (name, outs) in &r.peers {
            let key = format!("{name}/{}", r.condition);
            if shown_peers.contains(&key) {
                continue;
            }
            shown_peers.push(key);
            let n = outs.len();
            line(
                r.condition,
                &format!("{name} ({n})"),
                &eval::summarise(&r.trials[..n], outs),
            );
        }
        if let Some(l) = &r.look_alikes {
            println!(
                "  {:<24} look-alikes: {} of {} queries in a room answer the truth and all its look-alikes ({:.2} a query)",
                "",
                l["answer_set_holds_truth_and_all_look_alikes"],
                l["queries_in_rooms"],
                l["mean_look_alikes_per_query"].as_f64().unwrap_or(f64::NAN)
            );
        }
    }
    println!("  error CDF: {}", cdf.display());
}
