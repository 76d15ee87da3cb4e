#![allow(
    clippy::float_arithmetic,
    reason = "sensor settings and scans are approximate"
)]
//! `wai scan`: a simulated laser scan of a map from a pose (thesis sec. 6.1;
//! the engine is [`wai_scan`]), written as JSON.

use std::path::{Path, PathBuf};

use serde_json::json;
use wai_scan::{random_obstacles, simulate, Pose, Sensor};

use crate::input::{load_with_holes, Format};
use crate::Failure;

#[derive(clap::Args, Debug)]
pub struct Args {
    /// Map file (JSON map format or GeoJSON; `-` reads standard input), or
    /// a generated map: `rooms:K`, `office:K[:SEED]`, `family:ID:P1,…`.
    pub map: PathBuf,
    /// The map's units: `auto`, `m`, `lonlat` or `scale:K` (see `wai
    /// localize-scan --help`); the scan is in metres.
    #[arg(long, default_value = "auto")]
    pub units: String,
    /// The pose `x,y` or `x,y,θ`: position in metres (the map converted by
    /// --units; a longitude/latitude map in its local frame, x east and y
    /// north from its south-west corner), heading θ in degrees
    /// counter-clockwise from the x axis (default 0).
    #[arg(long, allow_hyphen_values = true)]
    pub at: String,
    /// Standard deviation of the Gaussian range noise, in metres.
    #[arg(long, default_value_t = 0.0, value_parser = crate::options::non_negative, allow_negative_numbers = true)]
    pub noise: f64,
    /// Beams at equal angles.
    #[arg(long, default_value_t = 720, value_parser = crate::options::positive_count, allow_negative_numbers = true)]
    pub beams: usize,
    /// Field of view in degrees, in (0, 360], centred on the heading (the
    /// thesis's scanners see 360 or 180).
    #[arg(long, default_value_t = 360.0, value_parser = crate::options::fov_degrees, allow_negative_numbers = true)]
    pub fov: f64,
    /// Returns beyond this range are lost (null in the scan).
    #[arg(long, value_parser = crate::options::positive, allow_negative_numbers = true)]
    pub max_range: Option<f64>,
    /// Unknown obstacles: this many boxes the map does not know.
    #[arg(long, default_value_t = 0, value_parser = crate::options::count, allow_negative_numbers = true)]
    pub obstacles: usize,
    /// Side of each obstacle box, in metres.
    #[arg(long, default_value_t = 0.5, value_parser = crate::options::positive, allow_negative_numbers = true)]
    pub obstacle_size: f64,
    /// Seed of the noise and the obstacles.
    #[arg(long, default_value_t = 0, value_parser = crate::options::count_u64, allow_negative_numbers = true)]
    pub seed: u64,
    /// Write the scan here instead of standard output.
    #[arg(long)]
    pub out: Option<PathBuf>,
}

fn parse_pose(text: &str) -> Result<Pose, Failure> {
    let parts: Vec<&str> = text.split(',').map(str::trim).collect();
    let num = |s: &str, what: &str| {
        s.parse::<f64>()
            .ok()
            .filter(|v| v.is_finite())
            .ok_or_else(|| Failure::usage(format!("--at {text:?}: {what} {s:?} is not a number")))
    };
    match parts[..] {
        [x, y] => Ok(Pose {
            x: num(x, "x")?,
            y: num(y, "y")?,
            heading: 0.0,
        }),
        [x, y, t] => Ok(Pose {
            x: num(x, "x")?,
            y: num(y, "y")?,
            heading: num(t, "θ")?.to_radians(),
        }),
        _ => Err(Failure::usage(format!(
            "--at {text:?}: expected x,y or x,y,θ"
        ))),
    }
}

pub fn run(args: &Args) -> Result<(), Failure> {
    let pose = parse_pose(&args.at)?;
    let (map, units, units_assumed) = match args.map.to_str() {
        Some(spec) if crate::scan_maps::is_generated(spec) || args.units != "auto" => {
            let m = crate::scan_maps::load_map(spec, &args.units)?;
            (m.map, m.units, m.units_assumed)
        }
        _ => {
            let map = load_with_holes(&args.map, Format::Auto)?.map;
            let m = crate::scan_maps::in_metres(&args.map.display().to_string(), map, "auto")?;
            (m.map, m.units, m.assumed)
        }
    };
    if let Some(why) = &units_assumed {
        eprintln!("wai scan: map units {units}: {why}");
    }
    let sensor = Sensor {
        beams: args.beams,
        fov: args.fov.to_radians(),
        sigma: args.noise,
        max_range: args.max_range,
    };
    if !(args.obstacle_size > 0.0 && args.obstacle_size.is_finite()) {
        return Err(Failure::usage("--obstacle-size must be positive"));
    }
    let obstacles = random_obstacles(&map, &pose, args.obstacles, args.obstacle_size, args.seed);
    let scan = simulate(&map, &obstacles, &pose, &sensor, args.seed).map_err(|e| match e {
        wai_scan::ScanError::Config(_) => Failure::usage(e.to_string()),
        _ => Failure::invalid(format!("{}: {e}", args.map.display())),
    })?;
    let mut out = scan.to_json();
    out["map"] = json!(map
        .name()
        .map_or_else(|| args.map.display().to_string(), str::to_owned));
    out["units"] =
        json!({ "map": units, "assumed": units_assumed, "scan": "m", "pose": "m, degrees" });
    out["pose"] = json!({ "x": pose.x, "y": pose.y, "heading_degrees": pose.heading.to_degrees() });
    out["sensor"] = json!({
        "beams": sensor.beams,
        "fov_degrees": args.fov,
        "noise": sensor.sigma,
        "max_range": sensor.max_range,
        "seed": args.seed,
    });
    out["obstacles"] = json!(obstacles
        .iter()
        .map(|o| json!({ "min": [o.min.0, o.min.1], "max": [o.max.0, o.max.1] }))
        .collect::<Vec<_>>());
    if args.obstacles > obstacles.len() {
        eprintln!(
            "wai scan: only {} of {} obstacles found room in the map",
            obstacles.len(),
            args.obstacles
        );
    }
    let text = serde_json::to_string(&out).expect("plain JSON values") + "\n";
    match &args.out {
        Some(path) => write(path, &text),
        None => {
            out!("{text}");
            Ok(())
        }
    }
}

pub(crate) fn write(path: &Path, text: &str) -> Result<(), Failure> {
    std::fs::write(path, text).map_err(|e| Failure::io(format!("{}: {e}", path.display())))
}
