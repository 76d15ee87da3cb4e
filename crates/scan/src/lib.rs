//! The realistic scenario of chapter 6 (sec. 6.1): a range sensor gives a
//! finite, noisy scan, not a visibility polygon.
//!
//! [`simulate`] casts `beams` rays at equal angles over a field of view
//! from a [`Pose`] in a map (the map's walls plus unknown [`Obstacle`]s,
//! small boxes the map does not know), adds seeded Gaussian noise to each
//! range and drops the returns beyond a range cutoff. The scan is the
//! robot's view: angles relative to its heading, ranges in the units of the
//! map it is given (the commands give every map in metres).
//!
//! # The scan model
//! What a scan says, and how each part of it enters the localizer (the
//! thesis's sec. 6.1, 6.7 and eq. 6.8; [`range`] and [`format`] implement
//! it):
//! - A **beam** is an angle θ, in radians counter-clockwise from the
//!   robot's heading (x ahead), and what came back along it. Beams need
//!   not be equally spaced nor cover the full circle; they are taken in
//!   angle order. Ranges and positions are in metres.
//! - A **return** r: the nearest surface along the beam lies at r, up to
//!   noise.
//! - **No return** (`null`, ROS `+Inf`, or above a stated maximum): nothing
//!   within the sensor's range R along the beam — the wall is *beyond R*,
//!   never "at infinity" (a closed map has a wall along every ray).
//! - A **discarded** reading (ROS `NaN`, `-Inf`, below the minimum range)
//!   says nothing: the beam is dropped, leaving a gap.
//! - The **maximum range** R is what the scan's source states; without a
//!   statement only a bound is known — R is at least the longest return.
//!   Lost beams are read against one range C ≤ R: the stated R, or the
//!   longest return when none is stated or the statement is contradicted
//!   by the map at the best pose ([`range::SensingRange`]; the answer then
//!   carries a warning). With no lost beam no range is needed.
//! - A **minimum range** only discards readings below it.
//!
//! How each enters the localizer:
//! - *V_S and its PCF* (sec. 6.7): the points of neighbouring beams joined
//!   by segments, a lost beam's point at distance C, every range capped at
//!   C (eq. 6.8); where neighbouring beams are more than 1.5 typical steps
//!   apart (a partial field of view, discarded beams) the angles between
//!   them are masked out of the metric.
//! - *The map's PCFs* at the sites are capped at the same C, so at the true
//!   pose a lost beam reads C on both sides.
//! - *The metric* (Def 6.3) is the masked Riemann sum of eq. 6.7 over the
//!   covered angles, minimised over the rotations the compass allows.
//! - *The ranking bound*: the rotation-free Parseval bound serves scans
//!   that cover every angle; the bisector tree's triangle inequality holds
//!   for any mask and any cap (capping is 1-Lipschitz), so one tree built
//!   uncapped serves every query.
//! - *The refinement*: ICP pairs returns only; a pose is scored by the
//!   mean of min(e², τ²), e the difference of measured and predicted range
//!   for a return, and for a lost beam how far the predicted range falls
//!   short of C.
//!
//! # Number model
//! This crate is where floating point is allowed to decide: sensor data
//! is approximate by nature. The map stays exact;
//! its vertices are read as `f64` (vertex / scale) for ray casting. Only
//! one decision is exact: whether the pose lies inside the map, decided on
//! the pose's exact binary value ([`Pose::check_inside`]), so a pose on a
//! wall or outside is refused the same way everywhere.
//!
//! # Edge cases
//! - A beam that grazes a vertex hits the nearer of the two edges there
//!   (whichever gives the smaller distance; both give the same one).
//! - A beam along a wall (collinear with an edge) ignores that edge and
//!   hits the next one: a sensor does not see a wall edge-on.
//! - Noise never makes a range negative: a noisy range is clamped at 0.
#![allow(
    clippy::float_arithmetic,
    reason = "sensor data is approximate: the scan localizer is where floats may decide"
)]

pub mod carmen;
pub mod coarsen;
pub mod draw;
pub mod eval;
pub mod format;
pub mod hausdorff;
pub mod icp;
mod localizer;
pub mod log_map;
pub mod mbt;
mod obstacles;
pub mod pcm;
pub mod peer;
pub mod polar;
pub mod range;
pub mod signature;
pub mod sites;
pub mod units;
pub mod walls;

pub use localizer::{
    site_bytes, Hypothesis, Near, Options, RankedCell, ScanAnswer, ScanLocalizer, TooLarge,
    DEFAULT_MAX_MEMORY,
};
pub use obstacles::{random_obstacles, Obstacle};
pub use signature::Compass;

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::Rational;
use serde_json::{json, Value};
use wai_exact::{Containment, RatPoint};
use wai_map::Map;

/// Where the robot is and where it looks: a position in the map's input
/// units and a heading in radians, counter-clockwise from the x axis.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pose {
    pub x: f64,
    pub y: f64,
    pub heading: f64,
}

impl Pose {
    /// Refuses a pose that is not strictly inside `map` (or not finite),
    /// deciding on the exact value of the two `f64`s.
    pub fn check_inside(&self, map: &Map) -> Result<(), ScanError> {
        if !(self.x.is_finite() && self.y.is_finite() && self.heading.is_finite()) {
            return Err(ScanError::NotFinite(*self));
        }
        let exact = |v: f64| Rational::from_f64(v).expect("finite") * map.scale();
        let p = RatPoint::from_rationals(exact(self.x), exact(self.y));
        match map.locate(&p) {
            Containment::Inside => Ok(()),
            Containment::OnBoundary => Err(ScanError::OnBoundary(*self)),
            Containment::Outside => Err(ScanError::Outside(*self)),
        }
    }
}

/// Why a scan could not be simulated.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ScanError {
    #[error("the pose ({}, {}) lies outside the map", .0.x, .0.y)]
    Outside(Pose),
    #[error("the pose ({}, {}) lies on the map's boundary", .0.x, .0.y)]
    OnBoundary(Pose),
    #[error("the pose {0:?} is not finite")]
    NotFinite(Pose),
    #[error("the pose ({}, {}) lies inside obstacle {}", .0.x, .0.y, .1)]
    InObstacle(Pose, usize),
    #[error("bad sensor setting: {0}")]
    Config(String),
}

/// The sensor: how many beams over which field of view, the noise and the
/// range limit.
#[derive(Debug, Clone, PartialEq)]
pub struct Sensor {
    /// Beams, at equal angles (the thesis's scanners: 360 or 720).
    pub beams: usize,
    /// The field of view in radians, centred on the heading: 2π for a full
    /// circle, π for a 180° scanner.
    pub fov: f64,
    /// The standard deviation of the Gaussian range noise (input units).
    pub sigma: f64,
    /// Returns beyond this range are lost (`None` in the scan).
    pub max_range: Option<f64>,
}

impl Default for Sensor {
    /// 720 beams over the full circle, no noise, no range limit.
    fn default() -> Self {
        Sensor {
            beams: 720,
            fov: std::f64::consts::TAU,
            sigma: 0.0,
            max_range: None,
        }
    }
}

impl Sensor {
    fn check(&self) -> Result<(), ScanError> {
        let bad = |what: String| Err(ScanError::Config(what));
        if self.beams == 0 {
            return bad("at least one beam".into());
        }
        if !(self.fov > 0.0 && self.fov <= std::f64::consts::TAU) {
            return bad(format!("the field of view {} is not in (0, 2π]", self.fov));
        }
        if !(self.sigma >= 0.0 && self.sigma.is_finite()) {
            return bad(format!("the noise σ {} is not ≥ 0", self.sigma));
        }
        if let Some(r) = self.max_range {
            if r.is_nan() || r <= 0.0 {
                return bad(format!("the range limit {r} is not > 0"));
            }
        }
        Ok(())
    }

    /// The angle of beam `i` relative to the heading: the beams split the
    /// field of view into equal steps, the first at −fov/2 (a full circle
    /// starts at −π and does not repeat its end).
    pub fn angle(&self, i: usize) -> f64 {
        let full = (self.fov - std::f64::consts::TAU).abs() < 1e-12;
        let steps = if full || self.beams == 1 {
            self.beams
        } else {
            self.beams - 1
        };
        -self.fov / 2.0 + self.fov * i as f64 / steps.max(1) as f64
    }
}

/// A scan (the scan model of the crate's docs): per beam its angle
/// relative to the heading and the measured range, `None` where no return
/// came back (nothing within the sensor's range), and the maximum range
/// its source states, if it states one.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Scan {
    pub angles: Vec<f64>,
    pub ranges: Vec<Option<f64>>,
    /// The sensor's maximum range as the scan's source states it
    /// (`sensor.max_range`, ROS `range_max`); `None`: not stated. How it is
    /// used, and what is inferred without it: [`range::SensingRange`].
    pub max_range: Option<f64>,
}

impl Scan {
    /// The scan as JSON: `{"angles": [...], "ranges": [... | null]}`.
    pub fn to_json(&self) -> Value {
        json!({ "angles": self.angles, "ranges": self.ranges })
    }

    /// The returns: beams with a range.
    pub fn returns(&self) -> usize {
        self.ranges.iter().filter(|r| r.is_some()).count()
    }

    /// Whether the scan can fix a pose at all, or why not: a pose has two
    /// unknowns when the heading is known (`heading_known`: an exact
    /// compass) and three when it is not, and each return is one equation,
    /// so fewer returns than unknowns leave a continuum of poses that fit
    /// exactly, and any ranking of them would be arbitrary.
    pub fn localizable(&self, heading_known: bool) -> Result<(), String> {
        let needed = if heading_known { 2 } else { 3 };
        match self.returns() {
            k if k >= needed => Ok(()),
            0 => Err(format!(
                "the scan has no returns (all {} beams are null: nothing within \
                 range), so every pose fits it",
                self.ranges.len()
            )),
            k => Err(format!(
                "the scan has {k} return{} of {} beams; a pose has {needed} unknowns \
                 {}, so it needs at least {needed}",
                if k == 1 { "" } else { "s" },
                self.ranges.len(),
                if heading_known {
                    "(x, y) with the heading known"
                } else {
                    "(x, y, heading) without an exact compass"
                }
            )),
        }
    }

    /// The scan points in the robot's frame (x ahead), one per return.
    pub fn points(&self) -> Vec<(f64, f64)> {
        self.angles
            .iter()
            .zip(&self.ranges)
            .filter_map(|(a, r)| r.map(|r| (r * a.cos(), r * a.sin())))
            .collect()
    }
}

/// The walls of `map` as `f64` segments in input units.
pub(crate) fn walls(map: &Map) -> Vec<[(f64, f64); 2]> {
    let scale = map.scale().to_f64();
    let v = map.vertices();
    (0..v.len())
        .map(|i| {
            let (a, b) = (v[i], v[map.next(i)]);
            [
                (a.x as f64 / scale, a.y as f64 / scale),
                (b.x as f64 / scale, b.y as f64 / scale),
            ]
        })
        .collect()
}

/// The true range from `pose` along the beam at `angle` (relative to the
/// heading) to the nearest wall or obstacle side.
pub fn true_range(map: &Map, obstacles: &[Obstacle], pose: &Pose, angle: f64) -> f64 {
    cast(&segments(map, obstacles), pose, angle)
}

fn segments(map: &Map, obstacles: &[Obstacle]) -> Vec<[(f64, f64); 2]> {
    let mut all = walls(map);
    all.extend(obstacles.iter().flat_map(Obstacle::sides));
    all
}

fn cast(segments: &[[(f64, f64); 2]], pose: &Pose, angle: f64) -> f64 {
    let a = pose.heading + angle;
    let d = (a.cos(), a.sin());
    segments
        .iter()
        .filter_map(|s| walls::hit((pose.x, pose.y), d, s))
        .fold(f64::INFINITY, f64::min)
}

/// A scan of `map` (with the unknown `obstacles`) from `pose` by `sensor`,
/// the noise drawn from a ChaCha8 generator seeded with `seed`.
///
/// Refuses a pose that is not strictly inside the map, or inside an
/// obstacle, and a sensor setting out of range. A closed map always
/// returns a hit, so a range is `None` only beyond `max_range`.
pub fn simulate(
    map: &Map,
    obstacles: &[Obstacle],
    pose: &Pose,
    sensor: &Sensor,
    seed: u64,
) -> Result<Scan, ScanError> {
    sensor.check()?;
    pose.check_inside(map)?;
    if let Some(k) = obstacles.iter().position(|o| o.contains(pose.x, pose.y)) {
        return Err(ScanError::InObstacle(*pose, k));
    }
    let segments = segments(map, obstacles);
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let angles: Vec<f64> = (0..sensor.beams).map(|i| sensor.angle(i)).collect();
    let ranges = angles
        .iter()
        .map(|&a| {
            let truth = cast(&segments, pose, a);
            // The noise is drawn for every beam, kept or not, so the same
            // seed gives the same noise whatever the range limit.
            let noisy = (truth + sensor.sigma * gaussian(&mut rng)).max(0.0);
            match sensor.max_range {
                Some(limit) if truth > limit => None,
                _ => Some(noisy),
            }
        })
        .collect();
    Ok(Scan {
        angles,
        ranges,
        max_range: sensor.max_range,
    })
}

/// A standard normal sample (Box–Muller).
fn gaussian<R: Rng + ?Sized>(rng: &mut R) -> f64 {
    let u1: f64 = rng.random::<f64>().max(f64::MIN_POSITIVE);
    let u2: f64 = rng.random();
    (-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos()
}
