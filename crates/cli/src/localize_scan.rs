#![allow(
    clippy::float_arithmetic,
    reason = "scans, poses, errors and timings are approximate"
)]
//! `wai localize-scan`: one laser scan against a map (thesis ch. 6): the
//! ranked cells, the refined pose and the answer set. The engine is
//! [`wai_scan`].

use std::path::{Path, PathBuf};
use std::time::Instant;

use serde_json::{json, Value};
use wai_scan::eval::CompassMode;
use wai_scan::format::ScanFile;
use wai_scan::{Compass, Options, Pose, Scan, ScanLocalizer};

use crate::Failure;

use crate::scan_maps::*;

#[derive(clap::Args, Debug)]
pub struct Args {
    /// Map file (JSON map format or GeoJSON), or a generated map:
    /// `rooms:K`, `office:K[:SEED]`, `family:ID:P1,P2,…`.
    pub map: String,
    /// The scan, or several (one preprocessing of the map serves them all;
    /// with several, one line each and a summary, with success rates for
    /// the files that record their pose). In metres and radians: as `wai
    /// scan` writes it
    /// ({"angles": [...], "ranges": [... | null], optional "sensor":
    /// {"max_range", "min_range"} and "pose": {"heading_degrees"}), or a ROS
    /// sensor_msgs/LaserScan as JSON (angle_min, angle_increment,
    /// range_min, range_max, ranges); the format is detected. A null or
    /// +Inf range is no return within the sensor's range; NaN, -Inf and
    /// ranges below the minimum are discarded.
    #[arg(required = true)]
    pub scans: Vec<PathBuf>,
    /// The sensor's maximum range in metres, stated here (over the scan
    /// file's). Without one, beams with no return are read as beyond the
    /// longest return, and the answer warns.
    #[arg(long, value_parser = crate::options::positive, allow_negative_numbers = true)]
    pub max_range: Option<f64>,
    /// What the robot knows of its heading: `exact`, `noisy:ε` (ε in
    /// degrees) or `none`. The reading is --heading, else the scan file's
    /// pose heading.
    #[arg(long, default_value = "exact")]
    pub compass: String,
    /// The compass reading in degrees (counter-clockwise from the x axis).
    #[arg(long, value_parser = crate::options::finite, allow_negative_numbers = true)]
    pub heading: Option<f64>,
    /// The map's units: `auto`, `m`, `lonlat` or `scale:K` (K metres per
    /// unit). Auto: the units the map file states (its "units" field),
    /// else longitude/latitude when the map spans less than 0.1° within
    /// ±180/±90, 0.025 m per pixel for an R2V file, else metres.
    /// Every map is localized in metres; a longitude/latitude map in a
    /// local frame (x east, y north from its south-west corner, printed
    /// with the answer), and its poses are given in longitude, latitude
    /// too.
    #[arg(long, default_value = "auto")]
    pub units: String,
    /// A local query (sec. 6.10.4): only cells whose site lies within R
    /// metres of X,Y.
    #[arg(long, allow_hyphen_values = true, value_name = "X,Y,R")]
    pub near: Option<String>,
    /// Print JSON instead of text.
    #[arg(long)]
    pub json: bool,
    /// The memory the sites may take (e.g. 512M, 2G): the lattice of sites
    /// in big cells is widened to fit, and a map whose cells alone do not
    /// fit is refused with the estimate.
    #[arg(long, default_value = "1G", value_parser = crate::options::bytes)]
    pub max_memory: u64,
    /// Draw the map, the scan at the best pose and the answer set here (one
    /// scan only).
    #[arg(long)]
    pub svg: Option<PathBuf>,
}

/// One scan file read and checked, with the compass it is localized under.
struct Query {
    path: PathBuf,
    file: ScanFile,
    scan: Scan,
    compass: Compass,
}

fn query(args: &Args, mode: &CompassMode, path: &Path) -> Result<Query, Failure> {
    let file = read_scan(path)?;
    let mut scan = file.scan.clone();
    if args.max_range.is_some() {
        scan.max_range = args.max_range;
    }
    let reading = args.heading.map(f64::to_radians).or(file.heading);
    let compass = match (mode, reading) {
        (CompassMode::None, _) => Compass::None,
        (_, None) => {
            return Err(Failure::usage(format!(
                "{}: a compass needs a reading: give --heading or a scan with \
                 pose.heading_degrees",
                path.display()
            )))
        }
        (CompassMode::Exact, Some(h)) => Compass::Exact(h),
        (CompassMode::Noisy(eps), Some(h)) => Compass::Noisy {
            heading: h,
            eps: *eps,
        },
    };
    if let Err(why) = scan.localizable(matches!(compass, Compass::Exact(_))) {
        return Err(Failure::invalid(format!(
            "{}: not localizable: {why}",
            path.display()
        )));
    }
    Ok(Query {
        path: path.to_owned(),
        file,
        scan,
        compass,
    })
}

fn scan_json(q: &Query) -> Value {
    let f = &q.file;
    json!({
        "file": q.path.display().to_string(),
        "format": f.format.label(),
        "beams_in_file": f.beams_in_file,
        "beams_kept": q.scan.angles.len(),
        "discarded": {
            "invalid": f.discarded.invalid,
            "too_close": f.discarded.too_close,
            "below_min_range": f.discarded.below_min,
        },
        "above_max_range": f.beyond_max,
        "min_range": f.min_range,
    })
}

pub fn run(args: &Args) -> Result<(), Failure> {
    let mode = CompassMode::parse(&args.compass).map_err(Failure::usage)?;
    if args.svg.is_some() && args.scans.len() > 1 {
        return Err(Failure::usage("--svg draws one answer: give one scan"));
    }
    let m = load_map(&args.map, &args.units)?;
    // Every file is read and checked before the map is preprocessed; a
    // usage error stops everything, a bad scan only itself in a batch.
    let mut queries = Vec::with_capacity(args.scans.len());
    for p in &args.scans {
        match query(args, &mode, p) {
            Err(f) if f.code == 2 || args.scans.len() == 1 => return Err(f),
            q => queries.push(q),
        }
    }
    let t = Instant::now();
    // The sites are built uncapped: each query is read with its own scan's
    // sensing range (wai_scan::range).
    let opts = Options {
        max_memory: args.max_memory,
        ..Options::default()
    };
    let asked = opts.lattice;
    let loc = crate::failure::scan_localizer(&m.map, opts)
        .map_err(|e| Failure::invalid(format!("{}: refused: {e}", m.name)))?;
    let lattice = match (loc.lattice_spacing(), asked) {
        (Some(g), Some(d)) if g > d => format!(
            "; lattice widened from {d} to {g:.2} m to fit --max-memory {} MiB",
            args.max_memory >> 20
        ),
        (Some(g), _) => format!("; lattice {g} m"),
        (None, _) => String::new(),
    };
    let preprocess_s = t.elapsed().as_secs_f64();
    let near = args.near.as_deref().map(parse_near).transpose()?;
    let frame = m.frame;
    let map_json = json!({
        "map": m.name,
        "units": m.units,
        "units_assumed": m.units_assumed,
        "compass": args.compass,
        "cells": loc.cells().len(),
        "sites": loc.sites().len(),
        "lattice_spacing": loc.lattice_spacing(),
        "preprocess_s": preprocess_s,
        "frame": frame.map(|f| json!({
            "description": f.describe(),
            "lon0": f.lon0,
            "lat0": f.lat0,
            "east_metres_per_degree": f.east_per_degree,
            "north_metres_per_degree": f.north_per_degree,
        })),
    });
    let header = format!(
        "{}: {} cells, {} sites{lattice}, preprocessed in {preprocess_s:.2} s",
        m.name,
        loc.cells().len(),
        loc.sites().len(),
    );
    let units = match &m.units_assumed {
        Some(why) => format!("units: {} ({why}); poses in metres", m.units),
        None => format!("units: {}; poses in metres", m.units),
    };
    let cell_of = |site: usize| loc.sites()[site].cell;
    let pose_out = |p: &Pose| {
        let mut v = pose_json(p);
        if let Some(f) = &frame {
            let (lon, lat) = f.to_lonlat(p.x, p.y);
            v["lon"] = json!(lon);
            v["lat"] = json!(lat);
        }
        v
    };
    let lonlat = |p: &Pose| match &frame {
        Some(f) => {
            let (lon, lat) = f.to_lonlat(p.x, p.y);
            format!(" = lon {lon:.7}, lat {lat:.7}")
        }
        None => String::new(),
    };
    if let [Ok(q)] = &queries[..] {
        let (answer, ms) = loc.localize_timed(&q.scan, &q.compass, near);
        if let Some(path) = &args.svg {
            let svg = wai_scan::draw::answer_svg(loc.walls(), &q.scan, &answer, None, 800.0);
            crate::scan::write(path, &svg)?;
        }
        let warnings = answer.warnings();
        if args.json {
            for w in &warnings {
                eprintln!("wai localize-scan: warning: {w}");
            }
            let mut out = map_json;
            out["scan"] = scan_json(q);
            out["range"] = answer.range.to_json();
            out["warnings"] = json!(warnings);
            out["ms"] = json!(ms);
            out["best"] = json!(answer.best.as_ref().map(|h| json!({"pose": pose_out(&h.pose), "score": h.score, "cell": cell_of(h.from_site)})));
            out["answer_set"] = json!(answer.answer_set.iter().map(|h| json!({"pose": pose_out(&h.pose), "score": h.score, "cell": cell_of(h.from_site), "clear_to": h.clear_to.is_finite().then_some(h.clear_to)})).collect::<Vec<_>>());
            out["ranked"] = json!(answer.ranked.iter().map(|r| json!({"cell": cell_of(r.site), "site": loc.sites()[r.site].at, "pcm": r.pcm, "heading_degrees": r.heading.to_degrees()})).collect::<Vec<_>>());
            out["pcm_evaluations"] = json!(answer.evaluations);
            outln!(
                "{}",
                serde_json::to_string_pretty(&out).expect("plain JSON")
            );
            return Ok(());
        }
        outln!(
            "{header}; query {ms:.1} ms ({} PCM evaluations)",
            answer.evaluations
        );
        outln!("{units}");
        outln!("scan: {}", q.file.describe());
        outln!("{}", answer.range.describe());
        if let Some(f) = &frame {
            outln!("frame: {}", f.describe());
        }
        match &answer.best {
            None => outln!("no pose found"),
            Some(b) => outln!(
                "best pose ({:.3}, {:.3}){} heading {:.2}° in cell {}, score {:.5}",
                b.pose.x,
                b.pose.y,
                lonlat(&b.pose),
                b.pose.heading.to_degrees(),
                cell_of(b.from_site),
                b.score
            ),
        }
        outln!(
            "answer set ({} poses as good as the best):",
            answer.answer_set.len()
        );
        for h in &answer.answer_set {
            let clear = if h.clear_to.is_finite() {
                format!("  beams without return clear to {:.2} m", h.clear_to)
            } else {
                String::new()
            };
            outln!(
                "  ({:.3}, {:.3}){} {:.2}°  score {:.5}{clear}",
                h.pose.x,
                h.pose.y,
                lonlat(&h.pose),
                h.pose.heading.to_degrees(),
                h.score
            );
        }
        for w in &warnings {
            outln!("warning: {w}");
        }
        return Ok(());
    }
    batch(args, &loc, &queries, near, map_json, &header, &units)
}

/// Several scans against one preprocessed map: a line (or JSON object)
/// each, and the success rates over the files that record their pose.
fn batch(
    args: &Args,
    loc: &ScanLocalizer,
    queries: &[Result<Query, Failure>],
    near: Option<wai_scan::Near>,
    map_json: Value,
    header: &str,
    units: &str,
) -> Result<(), Failure> {
    let tol = wai_scan::eval::NORMAL;
    if !args.json {
        outln!("{header}");
        outln!("{units}");
    }
    let (mut posed, mut right, mut in_set, mut warned) = (0usize, 0usize, 0usize, 0usize);
    let mut times = Vec::with_capacity(queries.len());
    let mut rows = Vec::with_capacity(queries.len());
    let mut refused = 0usize;
    for q in queries {
        let q = match q {
            Ok(q) => q,
            Err(f) => {
                refused += 1;
                if args.json {
                    eprintln!("wai localize-scan: {}", f.message);
                    rows.push(json!({ "refused": f.message }));
                } else {
                    outln!("REFUSED {}", f.message);
                }
                continue;
            }
        };
        let (answer, ms) = loc.localize_timed(&q.scan, &q.compass, near);
        times.push(ms);
        let warnings = answer.warnings();
        warned += usize::from(!warnings.is_empty());
        let truth = q.file.pose;
        let is_right = truth.and_then(|t| answer.best.as_ref().map(|b| tol.accepts(&b.pose, &t)));
        let holds = truth.map(|t| answer.answer_set.iter().any(|h| tol.accepts(&h.pose, &t)));
        if truth.is_some() {
            posed += 1;
            right += usize::from(is_right == Some(true));
            in_set += usize::from(holds == Some(true));
        }
        if args.json {
            for w in &warnings {
                eprintln!("wai localize-scan: {}: warning: {w}", q.path.display());
            }
            rows.push(json!({
                "scan": scan_json(q),
                "range": answer.range.to_json(),
                "warnings": warnings,
                "ms": ms,
                "best": answer.best.as_ref().map(|h| json!({"pose": pose_json(&h.pose), "score": h.score})),
                "answer_set": answer.answer_set.iter().map(|h| json!({"pose": pose_json(&h.pose), "score": h.score})).collect::<Vec<_>>(),
                "truth": truth.map(|t| pose_json(&t)),
                "best_within_tolerance": is_right,
                "answer_set_holds_truth": holds,
            }));
            continue;
        }
        let best = match &answer.best {
            Some(b) => format!(
                "({:.3}, {:.3}) {:.2}° score {:.5}",
                b.pose.x,
                b.pose.y,
                b.pose.heading.to_degrees(),
                b.score
            ),
            None => "no pose".into(),
        };
        let verdict = match (truth, is_right, holds) {
            (Some(t), r, h) => {
                let (d, a) = answer.best.as_ref().map_or((f64::NAN, f64::NAN), |b| {
                    wai_scan::eval::errors(&b.pose, &t)
                });
                format!(
                    "; off by {d:.3} m, {a:.1}°: {}, truth {}in the set",
                    if r == Some(true) { "right" } else { "WRONG" },
                    if h == Some(true) { "" } else { "NOT " }
                )
            }
            _ => String::new(),
        };
        outln!(
            "{}: {best}, {} in the answer set; range {}{verdict}; {ms:.1} ms",
            q.path.display(),
            answer.answer_set.len(),
            answer.range.basis.label(),
        );
        for w in &warnings {
            outln!("  warning: {w}");
        }
    }
    let median = wai_scan::eval::quantile(&times, 0.5);
    let rate = |k: usize| {
        if posed == 0 {
            None
        } else {
            Some(k as f64 / posed as f64)
        }
    };
    if args.json {
        let mut out = map_json;
        out["scans"] = json!(rows);
        out["summary"] = json!({
            "scans": queries.len(),
            "refused": refused,
            "with_pose": posed,
            "tolerance": {"metres": tol.metres, "degrees": tol.degrees},
            "best_within_tolerance": right,
            "answer_set_holds_truth": in_set,
            "success_rate": rate(right),
            "answer_set_contains_truth_rate": rate(in_set),
            "scans_with_warnings": warned,
            "median_ms": median,
        });
        outln!(
            "{}",
            serde_json::to_string_pretty(&out).expect("plain JSON")
        );
        return refusal(refused, queries.len());
    }
    outln!(
        "{} scans ({refused} refused), median query {median:.1} ms, {warned} with warnings",
        queries.len()
    );
    if posed > 0 {
        outln!(
            "of the {posed} that record their pose: best pose within {} m and {}° {right} \
             times ({:.1}%), truth in the answer set {in_set} times ({:.1}%)",
            tol.metres,
            tol.degrees,
            100.0 * right as f64 / posed as f64,
            100.0 * in_set as f64 / posed as f64
        );
    }
    refusal(refused, queries.len())
}

/// A batch with refused scans ends with exit status 1, after every answer.
fn refusal(refused: usize, of: usize) -> Result<(), Failure> {
    if refused == 0 {
        Ok(())
    } else {
        Err(Failure::invalid(format!(
            "{refused} of {of} scans refused (each is named above)"
        )))
    }
}
