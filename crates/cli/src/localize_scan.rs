#![allow(
    clippy::float_arithmetic,
    reason = "scans, poses, errors and timings are approximate"
)]
//! `wai localize-scan`: one laser scan against a map (thesis ch. 6): the
//! ranked cells, the refined pose and the answer set. The engine is
//! [`wai_scan`].

use std::path::PathBuf;
use std::time::Instant;

use serde_json::json;
use wai_scan::eval::CompassMode;
use wai_scan::{Compass, Options, ScanLocalizer};

use crate::Failure;

use crate::scan_maps::*;

#[derive(clap::Args, Debug)]
pub struct Args {
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
    /// Draw the map, the scan at the best pose and the answer set here.
    #[arg(long)]
    pub svg: Option<PathBuf>,
}

pub fn run(args: &Args) -> Result<(), Failure> {
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
    if let Err(why) = scan.localizable(matches!(compass, Compass::Exact(_))) {
        return Err(Failure::invalid(format!(
            "{}: not localizable: {why}",
            args.scan.display()
        )));
    }
    let t = Instant::now();
    let opts = Options {
        max_range,
        max_memory: args.max_memory,
        ..Options::default()
    };
    let asked = opts.lattice;
    let loc = ScanLocalizer::try_new(&m.map, opts)
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
    let (answer, ms) = loc.localize_timed(&scan, &compass, near);
    if let Some(path) = &args.svg {
        let svg = wai_scan::draw::answer_svg(loc.walls(), &scan, &answer, None, 800.0);
        crate::scan::write(path, &svg)?;
    }
    let cell_of = |site: usize| loc.sites()[site].cell;
    let frame = m.frame;
    let pose_out = |p: &wai_scan::Pose| {
        let mut v = pose_json(p);
        if let Some(f) = &frame {
            let (lon, lat) = f.to_lonlat(p.x, p.y);
            v["lon"] = json!(lon);
            v["lat"] = json!(lat);
        }
        v
    };
    if args.json {
        let out = json!({
            "map": m.name,
            "units": m.units,
            "compass": args.compass,
            "cells": loc.cells().len(),
            "sites": loc.sites().len(),
            "lattice_spacing": loc.lattice_spacing(),
            "preprocess_s": preprocess_s,
            "ms": ms,
            "frame": frame.map(|f| json!({
                "description": f.describe(),
                "lon0": f.lon0,
                "lat0": f.lat0,
                "east_metres_per_degree": f.east_per_degree,
                "north_metres_per_degree": f.north_per_degree,
            })),
            "best": answer.best.as_ref().map(|h| json!({"pose": pose_out(&h.pose), "score": h.score, "cell": cell_of(h.from_site)})),
            "answer_set": answer.answer_set.iter().map(|h| json!({"pose": pose_out(&h.pose), "score": h.score, "cell": cell_of(h.from_site)})).collect::<Vec<_>>(),
            "ranked": answer.ranked.iter().map(|r| json!({"cell": cell_of(r.site), "site": loc.sites()[r.site].at, "pcm": r.pcm, "heading_degrees": r.heading.to_degrees()})).collect::<Vec<_>>(),
            "pcm_evaluations": answer.evaluations,
        });
        outln!(
            "{}",
            serde_json::to_string_pretty(&out).expect("plain JSON")
        );
        return Ok(());
    }
    outln!(
        "{}: {} cells, {} sites{lattice}, preprocessed in {preprocess_s:.2} s; query {ms:.1} ms ({} PCM evaluations)",
        m.name,
        loc.cells().len(),
        loc.sites().len(),
        answer.evaluations
    );
    outln!("units: {}; poses in metres", m.units);
    if let Some(f) = &frame {
        outln!("frame: {}", f.describe());
    }
    let lonlat = |p: &wai_scan::Pose| match &frame {
        Some(f) => {
            let (lon, lat) = f.to_lonlat(p.x, p.y);
            format!(" = lon {lon:.7}, lat {lat:.7}")
        }
        None => String::new(),
    };
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
        outln!(
            "  ({:.3}, {:.3}){} {:.2}°  score {:.5}",
            h.pose.x,
            h.pose.y,
            lonlat(&h.pose),
            h.pose.heading.to_degrees(),
            h.score
        );
    }
    Ok(())
}
