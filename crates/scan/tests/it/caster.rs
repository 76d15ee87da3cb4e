//! An independent laser simulator: its own ray casting (Cramer's rule on
//! each wall, not the crate's walls grid), its own beam convention (720
//! beams from −π in 0.5° steps relative to the heading), its own noise
//! (ChaCha20, σ = 2 cm) and its own file writers for both scan formats.
//! Shared by the tests (`tests/it/independent.rs`) and the example that
//! writes scan files for a measurement (`examples/independent-scans.rs`).
#![allow(clippy::float_arithmetic, reason = "a float ray caster")]
#![allow(dead_code, reason = "each includer uses a part")]

use std::f64::consts::PI;

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha20Rng;
use wai_map::Map;
use wai_scan::Pose;

/// 720 beams from −π in 0.5° steps, relative to the heading.
pub const BEAMS: usize = 720;
pub const SIGMA: f64 = 0.02;

/// The first hit of the ray p + t·d (t > 0) on the segment [a, b], by
/// Cramer's rule on p + t·d = a + u·(b − a), u ∈ [0, 1].
fn hit(p: (f64, f64), d: (f64, f64), a: (f64, f64), b: (f64, f64)) -> Option<f64> {
    let e = (b.0 - a.0, b.1 - a.1);
    let det = e.0 * d.1 - e.1 * d.0;
    if det == 0.0 {
        return None;
    }
    let w = (a.0 - p.0, a.1 - p.1);
    let t = (e.0 * w.1 - e.1 * w.0) / det;
    let u = (d.0 * w.1 - d.1 * w.0) / det;
    (t > 1e-12 && (-1e-12..=1.0 + 1e-12).contains(&u)).then_some(t)
}

/// The map's boundary in metres, read straight from its exact vertices.
fn segments(map: &Map) -> Vec<((f64, f64), (f64, f64))> {
    let s = map.scale().to_f64();
    let v: Vec<(f64, f64)> = map
        .vertices()
        .iter()
        .map(|p| (p.x as f64 / s, p.y as f64 / s))
        .collect();
    // Along each ring, holes included.
    (0..v.len()).map(|i| (v[i], v[map.next(i)])).collect()
}

/// A scan by the independent caster: per beam the noisy range, or `None`
/// where it is beyond `range`.
pub fn cast(map: &Map, pose: &Pose, range: f64, seed: u64) -> Vec<Option<f64>> {
    let walls = segments(map);
    let mut rng = ChaCha20Rng::seed_from_u64(seed ^ 0x5eed_0f1d);
    (0..BEAMS)
        .map(|i| {
            let a = pose.heading - PI + (i as f64 * 0.5).to_radians();
            let d = (a.cos(), a.sin());
            let truth = walls
                .iter()
                .filter_map(|&(p, q)| hit((pose.x, pose.y), d, p, q))
                .fold(f64::INFINITY, f64::min);
            let (u1, u2): (f64, f64) = (rng.random::<f64>().max(1e-300), rng.random());
            let noise = SIGMA * (-2.0 * u1.ln()).sqrt() * (2.0 * PI * u2).sin();
            // A measurement beyond the range is no return, as a sensor gives it.
            let measured = (truth + noise).max(0.0);
            (measured <= range).then_some(measured)
        })
        .collect()
}

pub fn relative_angles() -> Vec<f64> {
    (0..BEAMS)
        .map(|i| -PI + (i as f64 * 0.5).to_radians())
        .collect()
}

/// The scan in the workspace's format, its range stated or not, with the
/// pose it was taken at if given.
pub fn wai_file(ranges: &[Option<f64>], stated: Option<f64>, pose: Option<&Pose>) -> String {
    let mut v = serde_json::json!({ "angles": relative_angles(), "ranges": ranges });
    if let Some(p) = pose {
        v["pose"] = serde_json::json!({
            "x": p.x, "y": p.y, "heading_degrees": p.heading.to_degrees()
        });
    }
    if let Some(r) = stated {
        v["sensor"] = serde_json::json!({ "max_range": r });
    }
    v.to_string()
}

/// The scan as a ROS LaserScan: no return written as +Inf (Python's bare
/// `Infinity`) and, for every fifth lost beam, as a value above range_max
/// (as drivers do); two beams discarded as NaN and below range_min.
pub fn ros_file(ranges: &[Option<f64>], range_max: f64) -> String {
    let values: Vec<String> = ranges
        .iter()
        .enumerate()
        .map(|(i, r)| match r {
            Some(r) => format!("{r}"),
            None if i % 5 == 0 => format!("{}", range_max + 1.0),
            None => "Infinity".into(),
        })
        .collect();
    format!(
        r#"{{"header": {{"frame_id": "laser", "stamp": {{"sec": 1, "nanosec": 0}}}},
"angle_min": {}, "angle_max": {}, "angle_increment": {},
"time_increment": 0.0, "scan_time": 0.1, "range_min": 0.05, "range_max": {range_max},
"ranges": [{}], "intensities": []}}"#,
        -PI,
        -PI + ((BEAMS - 1) as f64 * 0.5).to_radians(),
        0.5f64.to_radians(),
        values.join(", ")
    )
}
