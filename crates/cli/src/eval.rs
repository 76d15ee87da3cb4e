#![allow(
    clippy::float_arithmetic,
    reason = "scans, poses, errors and timings are approximate"
)]
//! `wai eval`: the scan localizer's evaluation protocol over many maps —
//! seeded poses, simulated scans under each condition, success rates,
//! answer sets, times and error CDF plots — side by side with the peers.
//! The engine is [`wai_scan::eval`].

use std::path::{Path, PathBuf};
use std::time::Instant;

use serde_json::{json, Value};
use wai_map::Map;
use wai_scan::eval::{self, CompassMode, Condition, Outcome, Summary, Trial};
use wai_scan::{Options, Pose, Scan, ScanLocalizer};

use crate::Failure;

use crate::scan_maps::*;

#[derive(clap::Args, Debug)]
pub struct Args {
    /// Maps: files (JSON map format or GeoJSON; `PATH@UNITS` sets one
    /// map's units) or generated maps `rooms:K`, `office:K[:SEED]`,
    /// `family:ID:P1,P2,…` (generated maps are in metres).
    #[arg(required = true)]
    pub maps: Vec<String>,
    /// Seeded random poses per map (at least 0.2 m from every wall).
    #[arg(long, default_value_t = 500, value_parser = crate::options::positive_count, allow_negative_numbers = true)]
    pub poses: usize,
    #[arg(long, default_value_t = 1, value_parser = crate::options::count_u64, allow_negative_numbers = true)]
    pub seed: u64,
    /// Compass modes, comma-separated: `exact`, `none`, `noisy:ε` (ε in
    /// degrees; the reading is off by a seeded uniform error in [−ε, ε]).
    #[arg(long, default_value = "exact,none")]
    pub compass: String,
    /// Conditions, comma-separated: `base` (720 beams over 360°, σ 2 cm),
    /// `boxes` (5 unknown 0.5 m boxes), `fov180`, `range10` (10 m cutoff),
    /// `range10-unstated` (the same scans not stating their range),
    /// or `all`.
    #[arg(long, default_value = "all")]
    pub conditions: String,
    /// Run a peer on the same scans in the same call: `karto`
    /// (karto-scanmatcher at its default settings, installed by
    /// scripts/install-karto), `karto:R` (an R-metre grid and smear), or
    /// `karto:KEY=V,…` with keys `window` (m, or `none` for one window
    /// over the whole map), `resolution`, `smear` (m), `coarse`, `fine`
    /// (degrees) and `refine` (true/false). Repeatable.
    #[arg(long)]
    pub peer: Vec<String>,
    /// Queries per map and condition given to each peer (the first ones
    /// of ours; peers are slow).
    #[arg(long, default_value_t = 100, value_parser = crate::options::count, allow_negative_numbers = true)]
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
    #[arg(long, value_parser = crate::options::fraction, allow_negative_numbers = true)]
    pub require_answer_set: Option<f64>,
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
                "range10-unstated" => 4,
                _ => {
                    return Err(Failure::usage(format!(
                        "condition {c:?}: expected base, boxes, fov180, range10, range10-unstated or all"
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
pub(crate) trait Peer {
    fn name(&self) -> String;
    /// The settings the peer runs with on this map, as it reports them.
    fn settings(&self) -> Value;
    fn localize(&mut self, scan: &Scan, max_range: Option<f64>) -> Result<Outcome, String>;
}

pub(crate) fn start_peer(name: &str, map: &Map) -> Result<Box<dyn Peer>, Failure> {
    peers::start(name, map)
}

mod peers {
    use super::{Failure, Map, Outcome, Peer, Scan, Value};
    use wai_scan::peer::{KartoConfig, KartoPeer};

    struct Karto {
        name: String,
        peer: KartoPeer,
    }

    impl Peer for Karto {
        fn name(&self) -> String {
            self.name.clone()
        }

        fn settings(&self) -> Value {
            self.peer.settings().clone()
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

    /// The settings of the peer `name`: `karto` (the defaults), `karto:R`
    /// (an R-metre grid and smear) or `karto:KEY=V,…`.
    pub fn karto_config(name: &str) -> Result<KartoConfig, Failure> {
        let usage = |why: String| {
            Failure::usage(format!(
                "peer {name:?}: {why}; expected karto, karto:R (the grid in metres, (0, 1]) \
                 or karto:KEY=V,… with keys window (m or none), resolution, smear (m), \
                 coarse, fine (degrees), refine (true/false)"
            ))
        };
        let mut config = KartoConfig::default();
        let Some(rest) = name.strip_prefix("karto:") else {
            return if name == "karto" {
                Ok(config)
            } else {
                Err(usage("unknown peer".into()))
            };
        };
        let positive = |key: &str, v: &str, max: f64| match v.parse::<f64>() {
            Ok(x) if x.is_finite() && x > 0.0 && x <= max => Ok(x),
            _ => Err(usage(format!("{key}={v} is not a number in (0, {max}]"))),
        };
        if !rest.contains('=') {
            let r = positive("resolution", rest, 1.0)?;
            config.resolution = r;
            config.smear_deviation = r;
            return Ok(config);
        }
        let mut smear = None;
        for item in rest.split(',') {
            let (key, v) = item
                .split_once('=')
                .ok_or_else(|| usage(format!("{item:?} is not KEY=V")))?;
            match key {
                "window" if v == "none" => config.window = None,
                "window" => config.window = Some(positive(key, v, 1000.0)?),
                "resolution" => config.resolution = positive(key, v, 1.0)?,
                "smear" => smear = Some(positive(key, v, 1.0)?),
                "coarse" => config.coarse_angle_deg = positive(key, v, 180.0)?,
                "fine" => config.fine_angle_deg = positive(key, v, 180.0)?,
                "refine" => {
                    config.refine = v
                        .parse()
                        .map_err(|_| usage(format!("refine={v} is not true or false")))?;
                }
                _ => return Err(usage(format!("unknown key {key:?}"))),
            }
        }
        // A grid given without a smear smears by one cell.
        config.smear_deviation = smear.unwrap_or(config.resolution);
        Ok(config)
    }

    pub fn start(name: &str, map: &Map) -> Result<Box<dyn Peer>, Failure> {
        let config = karto_config(name)?;
        let peer = KartoPeer::spawn_map(map, &config)
            .map_err(|e| Failure::io(format!("peer {name}: {e}")))?;
        Ok(Box::new(Karto {
            name: name.to_owned(),
            peer,
        }))
    }
}

pub fn run(args: &Args) -> Result<(), Failure> {
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
        let peer_settings: Vec<Value> = peers
            .iter()
            .map(|p| json!({"name": p.name(), "settings": p.settings()}))
            .collect();
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
                        .localize(&t.scan, t.scan.max_range)
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
            eval::CdfAxis::Auto,
            &series
                .iter()
                .map(|(l, v)| (l.clone(), v.as_slice()))
                .collect::<Vec<_>>(),
        );
        crate::scan::write(&cdf_path, &svg)?;
        if !args.json {
            print_table(
                m,
                &full,
                preprocess_s,
                &rows,
                &summaries,
                &peer_settings,
                &cdf_path,
            );
        }
        map_reports.push(json!({
            "map": m.name,
            "kind": m.kind,
            "units": m.units,
            "units_assumed": m.units_assumed,
            "vertices": m.map.n(),
            "cells": full.cells().len(),
            "sites": full.sites().len(),
            "preprocess_s": preprocess_s,
            "poses": poses.len(),
            "rows": row_json,
            "peer_settings": peer_settings,
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
        eval::CdfAxis::Auto,
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
            // The settings sent; what each map derived from them is in its
            // `peer_settings`.
            if let Ok(c) = peers::karto_config(name) {
                j["config"] = c.to_json();
            }
            j
        })
        .collect::<Vec<_>>());
    report["maps"] = json!(map_reports);
    report["cdf_svg"] = json!(cdf_all.display().to_string());
    let text = serde_json::to_string_pretty(&report).expect("plain JSON") + "\n";
    let json_path = args.out.join("eval.json");
    crate::scan::write(&json_path, &text)?;
    if args.json {
        out!("{text}");
    } else {
        outln!(
            "\nall maps: {} queries, success {:.1} % (strict {:.1} %, loose {:.1} %), answer set holds the truth {:.1} %, median {:.2} ms",
            overall.queries,
            100.0 * overall.success_rate,
            100.0 * overall.success_rate_strict,
            100.0 * overall.success_rate_loose,
            100.0 * overall.answer_set_contains_truth_rate,
            overall.median_ms
        );
        outln!(
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
    peer_settings: &[Value],
    cdf: &Path,
) {
    outln!(
        "\n{} ({}, units {}): n = {}, {} cells, {} sites, preprocessed in {preprocess_s:.2} s; {} poses",
        m.name,
        m.kind,
        m.units,
        m.map.n(),
        loc.cells().len(),
        loc.sites().len(),
        rows.first().map_or(0, |r| r.trials.len())
    );
    if let Some(why) = &m.units_assumed {
        outln!("  units {}: {why}", m.units);
    }
    outln!(
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
        outln!(
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
    for p in peer_settings {
        outln!(
            "  peer {}: {}",
            p["name"].as_str().unwrap_or("?"),
            settings_line(&p["settings"])
        );
    }
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
            outln!(
                "  {:<24} look-alikes: {} of {} queries in a room answer the truth and all its look-alikes ({:.2} a query)",
                "",
                l["answer_set_holds_truth_and_all_look_alikes"],
                l["queries_in_rooms"],
                l["mean_look_alikes_per_query"].as_f64().unwrap_or(f64::NAN)
            );
        }
    }
    outln!("  error CDF: {}", cdf.display());
}

/// A peer's settings on one line: `key value` pairs, by key.
fn settings_line(settings: &Value) -> String {
    match settings.as_object() {
        Some(o) => o
            .iter()
            .map(|(k, v)| format!("{k} {v}"))
            .collect::<Vec<_>>()
            .join(", "),
        None => settings.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::peers::karto_config;
    use wai_scan::peer::KartoConfig;

    #[test]
    fn peer_names_give_karto_settings() {
        assert_eq!(karto_config("karto").unwrap(), KartoConfig::default());
        let c = karto_config("karto:0.1").unwrap();
        assert_eq!((c.resolution, c.smear_deviation), (0.1, 0.1));
        let c = karto_config("karto:window=none,resolution=0.1,coarse=4,refine=false").unwrap();
        assert_eq!(c.window, None);
        assert_eq!((c.resolution, c.smear_deviation), (0.1, 0.1));
        assert_eq!(c.coarse_angle_deg, 4.0);
        assert!(!c.refine);
        let c = karto_config("karto:window=8,smear=0.08").unwrap();
        assert_eq!(c.window, Some(8.0));
        assert_eq!(c.smear_deviation, 0.08);
        for bad in [
            "kart",
            "karto:0",
            "karto:window=-1",
            "karto:speed=3",
            "karto:refine=maybe",
            "karto:x",
        ] {
            assert!(karto_config(bad).is_err(), "{bad}");
        }
    }
}
