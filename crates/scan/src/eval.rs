//! The scan localizer's evaluation protocol: seeded random poses in a map, a
//! simulated scan at each, the localizer's answer compared with the truth.
//!
//! Success is a position error below 0.5 m and a heading error below 10°
//! (strict: 0.1 m and 2°; loose: 1 m and 30°), measured on the best pose;
//! the answer set succeeds when one of its poses is within the (normal)
//! tolerance of the truth.

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use wai_map::Map;

use crate::icp::wrap;
use crate::walls::Walls;
use crate::Pose;

/// A success tolerance: position and heading.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tolerance {
    pub metres: f64,
    pub degrees: f64,
}

pub const NORMAL: Tolerance = Tolerance {
    metres: 0.5,
    degrees: 10.0,
};
pub const STRICT: Tolerance = Tolerance {
    metres: 0.1,
    degrees: 2.0,
};
pub const LOOSE: Tolerance = Tolerance {
    metres: 1.0,
    degrees: 30.0,
};

/// The position and heading errors of `got` against `truth`.
pub fn errors(got: &Pose, truth: &Pose) -> (f64, f64) {
    (
        (got.x - truth.x).hypot(got.y - truth.y),
        wrap(got.heading - truth.heading).abs().to_degrees(),
    )
}

impl Tolerance {
    pub fn accepts(&self, got: &Pose, truth: &Pose) -> bool {
        let (d, a) = errors(got, truth);
        d < self.metres && a < self.degrees
    }
}

/// `count` poses drawn uniformly from the part of `map` at least
/// `clearance` from every wall (a robot has a body), headings uniform,
/// from a ChaCha8 generator seeded with `seed`. Inside-ness is decided
/// exactly ([`Pose::check_inside`]).
pub fn random_poses(
    map: &Map,
    walls: &Walls,
    count: usize,
    clearance: f64,
    seed: u64,
) -> Vec<Pose> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let (lo, hi) = map.bounding_box();
    let s = map.scale().to_f64();
    let (x0, y0, x1, y1) = (
        lo.x as f64 / s,
        lo.y as f64 / s,
        hi.x as f64 / s,
        hi.y as f64 / s,
    );
    let mut poses = Vec::with_capacity(count);
    let mut tries = 0usize;
    while poses.len() < count && tries < 10_000 * count.max(1) {
        tries += 1;
        let p = Pose {
            x: rng.random_range(x0..x1),
            y: rng.random_range(y0..y1),
            heading: rng.random_range(-std::f64::consts::PI..std::f64::consts::PI),
        };
        if p.check_inside(map).is_ok() && walls.nearest((p.x, p.y), clearance).is_none() {
            poses.push(p);
        }
    }
    poses
}

/// One condition of the protocol: the sensor and the unknown obstacles
/// (the base scanner, 5 boxes, a 180° field of view and a 10 m range
/// cutoff each get their own row).
#[derive(Debug, Clone, PartialEq)]
pub struct Condition {
    pub name: &'static str,
    pub sensor: crate::Sensor,
    pub obstacles: usize,
    /// Side of each obstacle box, metres.
    pub obstacle_side: f64,
}

impl Condition {
    /// 720 beams over the full circle, σ = 2 cm, no range limit.
    pub fn base() -> Condition {
        Condition {
            name: "720 beams, σ 2 cm",
            sensor: crate::Sensor {
                sigma: 0.02,
                ..crate::Sensor::default()
            },
            obstacles: 0,
            obstacle_side: 0.5,
        }
    }

    /// The base condition and its three variations, in table order.
    pub fn standard() -> Vec<Condition> {
        let base = Condition::base();
        vec![
            base.clone(),
            Condition {
                name: "5 unknown boxes 0.5 m",
                obstacles: 5,
                ..base.clone()
            },
            Condition {
                name: "180° field of view",
                sensor: crate::Sensor {
                    fov: std::f64::consts::PI,
                    ..base.sensor.clone()
                },
                ..base.clone()
            },
            Condition {
                name: "10 m range cutoff",
                sensor: crate::Sensor {
                    max_range: Some(10.0),
                    ..base.sensor.clone()
                },
                ..base
            },
        ]
    }
}

/// What the robot's compass tells in an evaluation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum CompassMode {
    Exact,
    /// A reading off by a seeded uniform error in [−ε, ε] (radians),
    /// searched over ±ε.
    Noisy(f64),
    None,
}

impl CompassMode {
    /// Parses `exact`, `none` or `noisy:ε` (ε in degrees).
    pub fn parse(text: &str) -> Result<CompassMode, String> {
        match text {
            "exact" => Ok(CompassMode::Exact),
            "none" => Ok(CompassMode::None),
            _ => match text.strip_prefix("noisy:").map(str::parse::<f64>) {
                Some(Ok(e)) if (0.0..=180.0).contains(&e) => {
                    Ok(CompassMode::Noisy(e.to_radians()))
                }
                _ => Err(format!(
                    "compass {text:?}: expected exact, none or noisy:ε with ε in degrees in [0, 180]"
                )),
            },
        }
    }

    pub fn label(&self) -> String {
        match self {
            CompassMode::Exact => "exact".into(),
            CompassMode::None => "none".into(),
            CompassMode::Noisy(e) => format!("noisy:{}", e.to_degrees()),
        }
    }

    /// The compass the localizer is given for a robot at heading `truth`.
    pub fn reading<R: Rng + ?Sized>(&self, truth: f64, rng: &mut R) -> crate::Compass {
        match *self {
            CompassMode::Exact => crate::Compass::Exact(truth),
            CompassMode::None => crate::Compass::None,
            CompassMode::Noisy(eps) => crate::Compass::Noisy {
                heading: truth
                    + if eps > 0.0 {
                        rng.random_range(-eps..=eps)
                    } else {
                        0.0
                    },
                eps,
            },
        }
    }
}

/// One query of an evaluation: the true pose, the obstacles the map does
/// not know, the scan and the compass reading. Every localizer of a run
/// gets the same trials.
#[derive(Debug, Clone)]
pub struct Trial {
    pub truth: Pose,
    pub obstacles: Vec<crate::Obstacle>,
    pub scan: crate::Scan,
    pub compass: crate::Compass,
}

/// The trials of `condition` at `poses`, seeded by `seed` and the pose's
/// index (so a trial does not depend on how many others are drawn).
pub fn trials(
    map: &Map,
    poses: &[Pose],
    condition: &Condition,
    compass: CompassMode,
    seed: u64,
) -> Result<Vec<Trial>, crate::ScanError> {
    poses
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let s = trial_seed(seed, i);
            let obstacles =
                crate::random_obstacles(map, p, condition.obstacles, condition.obstacle_side, s);
            let scan = crate::simulate(map, &obstacles, p, &condition.sensor, s)?;
            Ok(Trial {
                truth: *p,
                obstacles,
                scan,
                compass: compass_reading(compass, p.heading, s),
            })
        })
        .collect()
}

/// `trials` (made by [`trials`] with `seed`) with the readings of another
/// compass: the same as [`trials`] with `compass` would give, without
/// simulating the scans again.
pub fn with_compass(trials: &[Trial], compass: CompassMode, seed: u64) -> Vec<Trial> {
    trials
        .iter()
        .enumerate()
        .map(|(i, t)| Trial {
            compass: compass_reading(compass, t.truth.heading, trial_seed(seed, i)),
            ..t.clone()
        })
        .collect()
}

/// The seed of trial `i` of a run seeded with `seed`.
fn trial_seed(seed: u64, i: usize) -> u64 {
    seed ^ (i as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15)
}

/// The compass reading of a trial seeded with `s`, drawn apart from its
/// scan's noise.
fn compass_reading(compass: CompassMode, heading: f64, s: u64) -> crate::Compass {
    let mut rng = ChaCha8Rng::seed_from_u64(s.rotate_left(17));
    compass.reading(heading, &mut rng)
}

/// A localizer's answer to one trial.
#[derive(Debug, Clone, PartialEq)]
pub struct Outcome {
    /// The best pose, if any.
    pub best: Option<Pose>,
    /// Every pose it answers with (the best one included); a localizer
    /// without answer sets answers with its best pose only.
    pub set: Vec<Pose>,
    /// Wall-clock time of the query, milliseconds.
    pub ms: f64,
}

/// The figures of one localizer over a set of trials.
#[derive(Debug, Clone, PartialEq)]
pub struct Summary {
    pub queries: usize,
    pub success_rate: f64,
    pub success_rate_strict: f64,
    pub success_rate_loose: f64,
    pub answer_set_contains_truth_rate: f64,
    pub mean_answer_set_size: f64,
    pub median_ms: f64,
    pub p90_ms: f64,
    /// Position errors of the best pose, metres, sorted (∞ without an
    /// answer): the data of the error CDF.
    pub position_errors: Vec<f64>,
    /// Heading errors of the best pose, degrees, sorted.
    pub heading_errors: Vec<f64>,
}

/// The value at quantile `q` of sorted `v` (nearest rank), NaN if empty.
pub fn quantile(v: &[f64], q: f64) -> f64 {
    if v.is_empty() {
        return f64::NAN;
    }
    let i = ((q * v.len() as f64).ceil() as usize).clamp(1, v.len()) - 1;
    v[i]
}

/// Summarises `outcomes` against the trials' true poses.
pub fn summarise(trials: &[Trial], outcomes: &[Outcome]) -> Summary {
    assert_eq!(trials.len(), outcomes.len(), "one outcome per trial");
    let n = trials.len().max(1) as f64;
    let rate = |tol: &Tolerance| {
        trials
            .iter()
            .zip(outcomes)
            .filter(|(t, o)| o.best.as_ref().is_some_and(|b| tol.accepts(b, &t.truth)))
            .count() as f64
            / n
    };
    let contains = trials
        .iter()
        .zip(outcomes)
        .filter(|(t, o)| o.set.iter().any(|p| NORMAL.accepts(p, &t.truth)))
        .count() as f64
        / n;
    let mut position_errors = Vec::with_capacity(trials.len());
    let mut heading_errors = Vec::with_capacity(trials.len());
    for (t, o) in trials.iter().zip(outcomes) {
        let (d, a) = o
            .best
            .as_ref()
            .map_or((f64::INFINITY, f64::INFINITY), |b| errors(b, &t.truth));
        position_errors.push(d);
        heading_errors.push(a);
    }
    position_errors.sort_by(f64::total_cmp);
    heading_errors.sort_by(f64::total_cmp);
    let mut ms: Vec<f64> = outcomes.iter().map(|o| o.ms).collect();
    ms.sort_by(f64::total_cmp);
    Summary {
        queries: trials.len(),
        success_rate: rate(&NORMAL),
        success_rate_strict: rate(&STRICT),
        success_rate_loose: rate(&LOOSE),
        answer_set_contains_truth_rate: contains,
        mean_answer_set_size: outcomes.iter().map(|o| o.set.len() as f64).sum::<f64>() / n,
        median_ms: quantile(&ms, 0.5),
        p90_ms: quantile(&ms, 0.9),
        position_errors,
        heading_errors,
    }
}

impl Summary {
    /// The JSON of `wai eval`.
    pub fn to_json(&self) -> serde_json::Value {
        let finite = |v: f64| {
            if v.is_finite() {
                serde_json::json!(v)
            } else {
                serde_json::Value::Null
            }
        };
        serde_json::json!({
            "queries": self.queries,
            "success_rate": self.success_rate,
            "success_rate_strict": self.success_rate_strict,
            "success_rate_loose": self.success_rate_loose,
            "answer_set_contains_truth_rate": self.answer_set_contains_truth_rate,
            "mean_answer_set_size": self.mean_answer_set_size,
            "median_ms": finite(self.median_ms),
            "p90_ms": finite(self.p90_ms),
            "median_position_error_m": finite(quantile(&self.position_errors, 0.5)),
            "median_heading_error_degrees": finite(quantile(&self.heading_errors, 0.5)),
        })
    }
}

/// The twins of `truth` in a `repeated_rooms(k)`-style map: the same
/// pose moved by whole multiples of `period` along x while it stays in a
/// room (y ≥ `room_floor`) of the `rooms` rooms whose first starts at
/// `first_x` (metres). A pose in the corridor has none. A twin is a
/// look-alike only if it is [`indistinguishable`] from the truth: a view
/// through the door can tell the rooms apart by where the corridor ends.
pub fn room_twins(
    truth: &Pose,
    rooms: usize,
    period: f64,
    first_x: f64,
    room_floor: f64,
) -> Vec<Pose> {
    if truth.y < room_floor {
        return vec![];
    }
    let own = ((truth.x - first_x) / period).floor();
    (0..rooms)
        .map(|j| j as f64 - own)
        .filter(|&shift| shift != 0.0)
        .map(|shift| Pose {
            x: truth.x + shift * period,
            ..*truth
        })
        .collect()
}

/// An SVG plot of empirical CDFs: one polyline per named series of sorted
/// values (∞ values never reach the curve's top), x from 0 to `x_max`.
pub fn cdf_svg(title: &str, x_label: &str, x_max: f64, series: &[(String, &[f64])]) -> String {
    use std::fmt::Write as _;
    const COLOURS: [&str; 6] = [
        "#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b",
    ];
    let (w, h, left, bottom, top, right) = (640.0, 400.0, 60.0, 50.0, 40.0, 200.0);
    let pw = w - left - right;
    let ph = h - top - bottom;
    let sx = |x: f64| left + pw * (x.min(x_max) / x_max);
    let sy = |y: f64| top + ph * (1.0 - y);
    let mut s = String::new();
    let _ = write!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" font-family="sans-serif" font-size="12"><rect width="{w}" height="{h}" fill="white"/><text x="{}" y="20" text-anchor="middle" font-size="14">{}</text>"#,
        left + pw / 2.0,
        xml(title)
    );
    for k in 0..=10 {
        let f = f64::from(k) / 10.0;
        let _ = write!(
            s,
            r##"<line x1="{left}" x2="{}" y1="{y}" y2="{y}" stroke="#ddd"/><text x="{}" y="{}" text-anchor="end">{f:.1}</text><line x1="{x}" x2="{x}" y1="{top}" y2="{}" stroke="#ddd"/><text x="{x}" y="{}" text-anchor="middle">{:.3}</text>"##,
            left + pw,
            left - 5.0,
            sy(f) + 4.0,
            top + ph,
            top + ph + 15.0,
            x_max * f,
            y = sy(f),
            x = sx(x_max * f),
        );
    }
    let _ = write!(
        s,
        r#"<text x="{}" y="{}" text-anchor="middle">{}</text><text x="15" y="{}" transform="rotate(-90 15 {})" text-anchor="middle">fraction of queries</text>"#,
        left + pw / 2.0,
        h - 10.0,
        xml(x_label),
        top + ph / 2.0,
        top + ph / 2.0
    );
    for (i, (name, values)) in series.iter().enumerate() {
        let colour = COLOURS[i % COLOURS.len()];
        let n = values.len().max(1) as f64;
        let mut pts = format!("{},{}", sx(0.0), sy(0.0));
        for (j, v) in values.iter().enumerate() {
            if !v.is_finite() || *v > x_max {
                break;
            }
            let _ = write!(
                pts,
                " {:.2},{:.2} {:.2},{:.2}",
                sx(*v),
                sy(j as f64 / n),
                sx(*v),
                sy((j + 1) as f64 / n)
            );
        }
        let reached = values
            .iter()
            .filter(|v| v.is_finite() && **v <= x_max)
            .count() as f64
            / n;
        let _ = write!(pts, " {:.2},{:.2}", sx(x_max), sy(reached));
        let ly = top + 15.0 + 18.0 * i as f64;
        let _ = write!(
            s,
            r#"<polyline points="{pts}" fill="none" stroke="{colour}" stroke-width="1.5"/><line x1="{}" x2="{}" y1="{ly}" y2="{ly}" stroke="{colour}" stroke-width="2"/><text x="{}" y="{}">{}</text>"#,
            left + pw + 10.0,
            left + pw + 30.0,
            left + pw + 35.0,
            ly + 4.0,
            xml(name)
        );
    }
    s.push_str("</svg>\n");
    s
}

fn xml(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

impl Outcome {
    /// The outcome of a [`crate::ScanLocalizer`] answer that took `ms`.
    pub fn of(answer: &crate::ScanAnswer, ms: f64) -> Outcome {
        Outcome {
            best: answer.best.as_ref().map(|h| h.pose),
            set: answer.answer_set.iter().map(|h| h.pose).collect(),
            ms,
        }
    }
}

/// Whether a sensor at `a` and at `b` sees the same ranges: the map's
/// ranges along `angles` (relative to each pose's heading; returns beyond
/// `max_range` lost at both or agreeing) differ by a mean of
/// min(e², τ²), τ = 0.2 m, of at most (1 cm)² — the same measure as
/// [`crate::icp::score`], far below what noise σ = 2 cm gives (σ²).
pub fn indistinguishable(
    walls: &Walls,
    a: &Pose,
    b: &Pose,
    angles: &[f64],
    max_range: Option<f64>,
) -> bool {
    let limit = max_range.unwrap_or(f64::INFINITY);
    let t2 = 0.2f64 * 0.2;
    let total: f64 = angles
        .iter()
        .map(|&t| {
            let (ra, rb) = (walls.range(a, t), walls.range(b, t));
            match (ra > limit, rb > limit) {
                (true, true) => 0.0,
                (false, false) => (ra - rb).powi(2).min(t2),
                _ => t2,
            }
        })
        .sum();
    total / angles.len().max(1) as f64 <= 1e-4
}
