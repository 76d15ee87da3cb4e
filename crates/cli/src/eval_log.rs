#![allow(
    clippy::float_arithmetic,
    reason = "scans, poses, errors and timings are approximate"
)]
//! `wai eval-log`: global localization of a real laser log's scans against
//! a map built from the log's other scans (thesis sec. 6.4's setting:
//! a real building, pillars and all). The map comes from one half of the
//! scans (`wai map-from-log`'s path: occupancy grid, traced boundary,
//! simplified), the queries are the other half, and each query's truth is
//! its SLAM-corrected laser pose. Each query is localized over the whole
//! map, with no compass and with the log's heading as a compass; success
//! is the best pose within 0.5 m and 10° (strict 0.1 m and 2°, loose 1 m
//! and 30°), and the answer set holding the truth is counted apart. A peer
//! (karto-scanmatcher) runs on the first queries, side by side. Pictures:
//! the error CDF, and the map with the query poses coloured by outcome.

use crate::eval::start_peer;
use crate::failure::Failure;
use crate::map_from_log::{build_map, read_log, Build, Half};
use serde_json::{json, Value};
use std::path::PathBuf;
use std::time::Instant;
use wai_scan::eval::{self, CompassMode, Outcome, Summary, Trial};
use wai_scan::{Compass, Options, Pose};

#[derive(clap::Args, Debug)]
pub struct Args {
    /// A CARMEN log (FLASER, ROBOTLASER1, ODOM lines), plain or .gz, with
    /// corrected poses.
    pub log: PathBuf,
    /// The scans that build the map; the queries are the other half.
    #[arg(long, value_enum, default_value_t = Half::Even)]
    pub map_scans: Half,
    /// Metres per cell of the occupancy grid (exact decimal).
    #[arg(long, default_value = "0.05")]
    pub resolution: String,
    /// Fill enclosed obstacles below this area (m²).
    #[arg(long, value_name = "M2", default_value = "0.05")]
    pub min_hole_area: String,
    /// Drop boundary corners within this many metres (exact, keeping the
    /// map valid): the decomposition's size grows with the corners.
    #[arg(long, value_name = "METRES", default_value = "0.2")]
    pub simplify: String,
    /// Compass modes, comma-separated: `none` (every heading searched),
    /// `log` (the log's corrected heading as an exact compass), `noisy:ε`
    /// (that heading off by a seeded uniform error in [−ε, ε] degrees).
    #[arg(long, default_value = "none,log")]
    pub compass: String,
    /// Localize only the first this many query scans (0: all of them).
    #[arg(long, default_value_t = 0)]
    pub queries: usize,
    /// Run a peer on the same scans: `karto`, `karto:R` or
    /// `karto:KEY=V,…` (see `wai eval --help`). Repeatable.
    #[arg(long)]
    pub peer: Vec<String>,
    /// Query scans given to each peer (the first ones; peers are slow).
    #[arg(long, default_value_t = 30)]
    pub peer_queries: usize,
    /// The memory the scan localizer's sites may take (e.g. 512M, 8G): the
    /// lattice of sites in big cells is widened to fit.
    #[arg(long, value_parser = crate::options::bytes, default_value = "4G")]
    pub max_memory: u64,
    /// Seed of the noisy compass readings.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Folder for the map, the error CDF (SVG), the outcomes (CSV) and
    /// eval-log.json.
    #[arg(long, default_value = "target/wai-eval-log")]
    pub out: PathBuf,
    /// Print the JSON on standard output instead of the table.
    #[arg(long)]
    pub json: bool,
}

/// A compass mode of this command: the log's heading, noisy or not, or
/// none.
fn modes(text: &str) -> Result<Vec<(String, CompassMode)>, Failure> {
    text.split(',')
        .map(|m| match m.trim() {
            "log" => Ok(("log heading".to_owned(), CompassMode::Exact)),
            "none" => Ok(("no compass".to_owned(), CompassMode::None)),
            other => match CompassMode::parse(other) {
                Ok(c @ CompassMode::Noisy(_)) => Ok((format!("log heading ±{}", c.label()), c)),
                _ => Err(Failure::usage(format!(
                    "--compass {other:?}: expected none, log or noisy:ε (degrees)"
                ))),
            },
        })
        .collect()
}

pub fn run(args: &Args) -> Result<(), Failure> {
    let modes = modes(&args.compass)?;
    let build = Build::parse(
        &args.resolution,
        &args.min_hole_area,
        Some(&args.simplify),
        args.map_scans,
        None,
    )?;
    let log = read_log(&args.log)?;
    let t = Instant::now();
    let (map, said) = build_map(&args.log, &log, &build)?;
    let map_s = t.elapsed().as_secs_f64();
    eprintln!("{said}");
    std::fs::create_dir_all(&args.out)
        .map_err(|e| Failure::io(format!("{}: {e}", args.out.display())))?;
    let stem: String = args
        .log
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default()
        .split('.')
        .next()
        .unwrap_or("log")
        .to_owned();
    crate::output::write_file(
        &args.out.join(format!("{stem}-map.json")),
        &wai_map::json::to_json(&map),
    )?;

    // The queries: the other half's scans, each with its corrected pose.
    let queries: Vec<usize> = (0..log.scans.len())
        .filter(|&k| !args.map_scans.picks(k))
        .take(if args.queries == 0 {
            usize::MAX
        } else {
            args.queries
        })
        .collect();
    if queries.is_empty() {
        return Err(Failure::invalid(format!(
            "{}: no query scan outside the map's half",
            args.log.display()
        )));
    }
    let base: Vec<Trial> = queries
        .iter()
        .map(|&k| {
            let [x, y, heading] = log.scans[k].pose;
            Trial {
                truth: Pose { x, y, heading },
                obstacles: Vec::new(),
                scan: log.scan(k),
                compass: Compass::None,
            }
        })
        .collect();
    let outside = base
        .iter()
        .filter(|t| t.truth.check_inside(&map).is_err())
        .count();

    eprintln!(
        "preprocessing the scan localizer on {} (n = {}, {} holes) …",
        map.name().unwrap_or("the map"),
        map.n(),
        map.hole_count()
    );
    let t = Instant::now();
    let opts = Options {
        max_memory: args.max_memory,
        ..Options::default()
    };
    let loc = crate::failure::scan_localizer(&map, opts)
        .map_err(|e| Failure::invalid(format!("{}: refused: {e}", args.log.display())))?;
    let preprocess_s = t.elapsed().as_secs_f64();

    let bar = crate::progress_bar((base.len() * modes.len()) as u64);
    let mut rows: Vec<(String, Vec<Trial>, Vec<Outcome>)> = Vec::new();
    for (label, mode) in &modes {
        let trials = eval::with_compass(&base, *mode, args.seed);
        bar.set_message(format!("{stem}: {label}"));
        let outs: Vec<Outcome> = trials
            .iter()
            .map(|t| {
                let (a, ms) = loc.localize_timed(&t.scan, &t.compass, None);
                bar.inc(1);
                Outcome::of(&a, ms)
            })
            .collect();
        rows.push((label.clone(), trials, outs));
    }
    bar.finish_and_clear();
    let mut peers: Vec<(String, Value, Vec<Trial>, Vec<Outcome>)> = Vec::new();
    for name in &args.peer {
        let mut peer = start_peer(name, &map)?;
        let trials = &base[..args.peer_queries.min(base.len())];
        let bar = crate::progress_bar(trials.len() as u64);
        bar.set_message(format!("{stem}: peer {name}"));
        let mut outs = Vec::with_capacity(trials.len());
        for t in trials {
            outs.push(
                peer.localize(&t.scan, t.scan.max_range)
                    .map_err(|e| Failure::io(format!("peer {name}: {e}")))?,
            );
            bar.inc(1);
        }
        bar.finish_and_clear();
        peers.push((peer.name(), peer.settings(), trials.to_vec(), outs));
    }

    // Ours on the peers' queries too, for a fair side by side.
    let summaries: Vec<(String, Summary)> = rows
        .iter()
        .map(|(l, t, o)| (l.clone(), eval::summarise(t, o)))
        .collect();
    let on_peer_queries: Vec<(String, Summary)> = match peers.first() {
        Some((_, _, pt, _)) => rows
            .iter()
            .map(|(l, t, o)| (l.clone(), eval::summarise(&t[..pt.len()], &o[..pt.len()])))
            .collect(),
        None => Vec::new(),
    };
    let peer_summaries: Vec<(String, Value, Summary)> = peers
        .iter()
        .map(|(n, s, t, o)| (n.clone(), s.clone(), eval::summarise(t, o)))
        .collect();

    let mut series: Vec<(String, Vec<f64>)> = summaries
        .iter()
        .map(|(l, s)| (format!("ours, {l}"), s.position_errors.clone()))
        .collect();
    series.extend(
        peer_summaries
            .iter()
            .map(|(n, _, s)| (format!("{n}, no compass"), s.position_errors.clone())),
    );
    let cdf = args.out.join(format!("cdf-{stem}.svg"));
    let svg = eval::cdf_svg(
        &format!("Position error CDF: {stem}, {} query scans", base.len()),
        "position error of the best pose (m)",
        eval::CdfAxis::Auto,
        &series
            .iter()
            .map(|(l, v)| (l.clone(), v.as_slice()))
            .collect::<Vec<_>>(),
    );
    crate::scan::write(&cdf, &svg)?;
    // Every query's outcome, for pictures and second looks.
    let mut csv = String::from("scan,line,true_x,true_y,true_heading_deg,compass,best_x,best_y,best_heading_deg,position_error_m,heading_error_deg,answer_set,set_holds_truth,ms\n");
    for (label, trials, outs) in &rows {
        for ((t, o), &k) in trials.iter().zip(outs).zip(&queries) {
            let (d, a) = o.best.as_ref().map_or((f64::INFINITY, f64::INFINITY), |b| {
                eval::errors(b, &t.truth)
            });
            let holds = o.set.iter().any(|p| eval::NORMAL.accepts(p, &t.truth));
            let (bx, by, bh) = o.best.map_or((f64::NAN, f64::NAN, f64::NAN), |b| {
                (b.x, b.y, b.heading.to_degrees())
            });
            csv.push_str(&format!(
                "{k},{},{:.4},{:.4},{:.3},{label},{bx:.4},{by:.4},{bh:.3},{d:.4},{a:.3},{},{holds},{:.3}\n",
                log.scans[k].line,
                t.truth.x,
                t.truth.y,
                t.truth.heading.to_degrees(),
                o.set.len(),
                o.ms
            ));
        }
    }
    // The query poses on the map, coloured by outcome, one picture per
    // compass mode.
    let kinds = [
        ("#2ca02c", "best pose within 0.5 m and 10°"),
        ("#ff7f0e", "answer set holds the truth, best pose elsewhere"),
        ("#d62728", "truth not in the answer set"),
    ];
    let mut pictures = Vec::new();
    for (label, trials, outs) in &rows {
        let points: Vec<((f64, f64), usize)> = trials
            .iter()
            .zip(outs)
            .map(|(t, o)| {
                let right = o
                    .best
                    .as_ref()
                    .is_some_and(|b| eval::NORMAL.accepts(b, &t.truth));
                let held = o.set.iter().any(|p| eval::NORMAL.accepts(p, &t.truth));
                (
                    (t.truth.x, t.truth.y),
                    if right {
                        0
                    } else if held {
                        1
                    } else {
                        2
                    },
                )
            })
            .collect();
        let slug = label.replace(|c: char| !c.is_ascii_alphanumeric(), "-");
        let path = args.out.join(format!("outcomes-{stem}-{slug}.svg"));
        let svg = wai_scan::draw::points_svg(
            loc.walls(),
            &format!("{stem}: {} query scans, {label}", trials.len()),
            &points,
            &kinds,
            900.0,
        );
        crate::scan::write(&path, &svg)?;
        pictures.push(path.display().to_string());
    }
    let csv_path = args.out.join(format!("outcomes-{stem}.csv"));
    crate::output::write_file(&csv_path, &csv)?;

    let report = json!({
        "log": args.log.display().to_string(),
        "map": {
            "name": map.name(),
            "scans": format!("{:?}", args.map_scans).to_lowercase(),
            "n": map.n(),
            "r": map.r(),
            "holes": map.hole_count(),
            "resolution_m": args.resolution,
            "simplify_m": args.simplify,
            "built_s": map_s,
            "cells": loc.cells().len(),
            "sites": loc.sites().len(),
            "preprocess_s": preprocess_s,
        },
        "queries": base.len(),
        "query_poses_outside_the_map": outside,
        "ours": summaries.iter().map(|(l, s)| json!({"compass": l, "summary": s.to_json()})).collect::<Vec<_>>(),
        "ours_on_peer_queries": on_peer_queries.iter().map(|(l, s)| json!({"compass": l, "summary": s.to_json()})).collect::<Vec<_>>(),
        "peers": peer_summaries.iter().map(|(n, settings, s)| json!({"peer": n, "settings": settings, "summary": s.to_json()})).collect::<Vec<_>>(),
        "cdf_svg": cdf.display().to_string(),
        "outcomes_csv": csv_path.display().to_string(),
        "outcome_maps_svg": pictures,
    });
    crate::output::write_file(
        &args.out.join(format!("eval-log-{stem}.json")),
        &serde_json::to_string_pretty(&report).expect("plain JSON"),
    )?;
    if args.json {
        outln!(
            "{}",
            serde_json::to_string_pretty(&report).expect("plain JSON")
        );
        return Ok(());
    }
    outln!(
        "{stem}: map from the {} scans: n = {}, r = {}, {} holes; {} cells, {} sites, preprocessed in {preprocess_s:.1} s",
        format!("{:?}", args.map_scans).to_lowercase(),
        map.n(),
        map.r(),
        map.hole_count(),
        loc.cells().len(),
        loc.sites().len()
    );
    outln!(
        "{} query scans ({} with the true pose outside the map's free space)",
        base.len(),
        outside
    );
    let header = format!(
        "  {:<34} {:>7} {:>8} {:>8} {:>8} {:>8} {:>6} {:>9} {:>9}",
        "localizer",
        "queries",
        "success",
        "strict",
        "loose",
        "set∋true",
        "|set|",
        "median ms",
        "p90 ms"
    );
    outln!("{header}");
    let row = |name: &str, s: &Summary| {
        format!(
            "  {:<34} {:>7} {:>7.1}% {:>7.1}% {:>7.1}% {:>7.1}% {:>6.2} {:>9.1} {:>9.1}",
            name,
            s.queries,
            100.0 * s.success_rate,
            100.0 * s.success_rate_strict,
            100.0 * s.success_rate_loose,
            100.0 * s.answer_set_contains_truth_rate,
            s.mean_answer_set_size,
            s.median_ms,
            s.p90_ms
        )
    };
    for (l, s) in &summaries {
        outln!("{}", row(&format!("ours, {l}"), s));
    }
    for (l, s) in &on_peer_queries {
        outln!("{}", row(&format!("ours, {l} (peer queries)"), s));
    }
    for (n, _, s) in &peer_summaries {
        outln!("{}", row(&format!("{n}, no compass"), s));
    }
    outln!(
        "error CDF: {}; outcomes: {}; JSON: {}",
        cdf.display(),
        csv_path.display(),
        args.out.join(format!("eval-log-{stem}.json")).display()
    );
    Ok(())
}
