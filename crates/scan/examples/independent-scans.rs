//! Writes scans of a map by an independent simulator (its own ray casting,
//! beam convention, noise and writers: `tests/it/caster.rs`) as files, for
//! measuring the localizer on scans it did not make:
//!
//! ```sh
//! cargo run --release -p wai-scan --example independent-scans -- MAP OUT_DIR [POSES] [RANGE] [SEED]
//! ```
//!
//! MAP is `office:K[:SEED]`, `rooms:K` or a JSON map file (longitude /
//! latitude maps are put in metres as `wai localize-scan` does). For each
//! of POSES seeded poses (default 50, at least 0.2 m from every wall) it
//! writes `OUT_DIR/stated/pose-N.json` (the range RANGE, default 30 m,
//! stated), `OUT_DIR/unstated/pose-N.json` (the same beams, no range
//! stated) — both recording the pose — and `OUT_DIR/ros/pose-N.json` (the
//! same beams as a ROS LaserScan).
#![allow(clippy::float_arithmetic, reason = "a float ray caster")]

#[path = "../tests/it/caster.rs"]
mod caster;

use std::path::PathBuf;

use wai_map::Map;
use wai_scan::eval::random_poses;
use wai_scan::units::{to_metres, Units};
use wai_scan::walls::Walls;

fn map(spec: &str) -> Result<Map, String> {
    if let Some(rest) = spec.strip_prefix("office:") {
        let mut parts = rest.split(':').map(str::parse::<u64>);
        let k = parts.next().and_then(Result::ok).ok_or("office:K[:SEED]")?;
        let seed = parts
            .next()
            .map_or(Ok(1), |s| s.map_err(|e| e.to_string()))?;
        let k = u32::try_from(k).map_err(|e| e.to_string())?;
        return Ok(wai_gen::office(k, seed));
    }
    if let Some(k) = spec.strip_prefix("rooms:") {
        return Ok(wai_gen::repeated_rooms(k.parse().map_err(|_| "rooms:K")?));
    }
    let bytes = std::fs::read(spec).map_err(|e| format!("{spec}: {e}"))?;
    let map = wai_map::json::from_json(&bytes)
        .map_err(|e| format!("{spec}: {e:?}"))?
        .map;
    map.require_no_holes("the scan localizer")
        .map_err(|e| format!("{spec}: {e}"))?;
    if map.looks_lonlat() {
        return to_metres(&map, Units::LonLatDegrees).map_err(|e| format!("{spec}: {e:?}"));
    }
    Ok(map)
}

fn main() -> Result<(), String> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.len() < 2 || args.iter().any(|a| a == "--help" || a == "-h") {
        println!("usage: independent-scans MAP OUT_DIR [POSES] [RANGE] [SEED]");
        return Ok(());
    }
    let num = |i: usize, default: f64| -> Result<f64, String> {
        args.get(i).map_or(Ok(default), |s| {
            s.parse().map_err(|_| format!("{s:?} is not a number"))
        })
    };
    let (poses, range, seed) = (num(2, 50.0)? as usize, num(3, 30.0)?, num(4, 1.0)? as u64);
    let map = map(&args[0])?;
    let out = PathBuf::from(&args[1]);
    for sub in ["stated", "unstated", "ros"] {
        std::fs::create_dir_all(out.join(sub)).map_err(|e| e.to_string())?;
    }
    let walls = Walls::new(wai_scan::peer::map_walls(&map));
    let mut lost = 0;
    for (k, p) in random_poses(&map, &walls, poses, 0.2, seed)
        .iter()
        .enumerate()
    {
        let ranges = caster::cast(&map, p, range, seed.wrapping_mul(1_000_003) + k as u64);
        lost += usize::from(ranges.iter().any(Option::is_none));
        let name = format!("pose-{k:03}.json");
        let files = [
            ("stated", caster::wai_file(&ranges, Some(range), Some(p))),
            ("unstated", caster::wai_file(&ranges, None, Some(p))),
            ("ros", caster::ros_file(&ranges, range)),
        ];
        for (sub, text) in files {
            std::fs::write(out.join(sub).join(&name), text).map_err(|e| e.to_string())?;
        }
    }
    println!(
        "{poses} poses of {}: {lost} scans have beams beyond {range} m; written to {}",
        args[0],
        out.display()
    );
    Ok(())
}
