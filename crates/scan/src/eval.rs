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
/// (the base scanner, 5 boxes, a 180° field of view, a 10 m range cutoff
/// and the same cutoff in scans that do not state it each get their own
/// row).
#[derive(Debug, Clone, PartialEq)]
pub struct Condition {
    pub name: &'static str,
    pub sensor: crate::Sensor,
    pub obstacles: usize,
    /// Side of each obstacle box, metres.
    pub obstacle_side: f64,
    /// Whether the scans state the sensor's range (as `wai scan` writes
    /// them) or leave it out (as most other tools do).
    pub states_range: bool,
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
            states_range: true,
        }
    }

    /// The base condition and its four variations, in table order.
    pub fn standard() -> Vec<Condition> {
        let base = Condition::base();
        let cut = crate::Sensor {
            max_range: Some(10.0),
            ..base.sensor.clone()
        };
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
                sensor: cut.clone(),
                ..base.clone()
            },
            Condition {
                name: "10 m cutoff, unstated",
                sensor: cut,
                states_range: false,
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
            let mut scan = crate::simulate(map, &obstacles, p, &condition.sensor, s)?;
            if !condition.states_range {
                scan.max_range = None;
            }
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

/// The x axis of [`cdf_svg`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum CdfAxis {
    /// Linear from 0 to this value.
    Fixed(f64),
    /// Linear from 0 to the 99th percentile of the finite values of all
    /// series, rounded up to 1, 2 or 5 × 10^k.
    Fitted,
    /// Logarithmic from the decade at or below the 1st percentile of the
    /// positive finite values to their 99th percentile rounded up; smaller
    /// values (and 0) are drawn at the left edge.
    Log,
    /// [`CdfAxis::Log`] if the 99th percentile of the positive finite
    /// values is over 100 times their 1st percentile (errors of
    /// millimetres and of metres in one plot), else [`CdfAxis::Fitted`].
    Auto,
}

/// An SVG plot of empirical CDFs: one step curve per named series of
/// sorted values (∞ values never reach the curve's top), each in its own
/// colour and dash, the legend to the right of the plot area. The x axis
/// is `axis` ([`CdfAxis`]); a note under it says which and how it was
/// fitted. Tick steps follow from the axis length in pixels and the
/// width of the labels, so labels never overlap.
pub fn cdf_svg(title: &str, x_label: &str, axis: CdfAxis, series: &[(String, &[f64])]) -> String {
    use crate::draw::{legend, nice_ceil, tick_step, tick_text, xml, Mark, CHAR_PX};
    use std::fmt::Write as _;
    const COLOURS: [&str; 8] = [
        "#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#17becf", "#e377c2",
    ];
    const DASHES: [&str; 3] = ["", "7 3", "2 2"];
    let mut finite: Vec<f64> = series
        .iter()
        .flat_map(|(_, v)| v.iter().copied())
        .filter(|v| v.is_finite() && *v >= 0.0)
        .collect();
    finite.sort_by(f64::total_cmp);
    let positive: Vec<f64> = finite.iter().copied().filter(|v| *v > 0.0).collect();
    let q99 = quantile(&finite, 0.99);
    let (p01, p99) = (quantile(&positive, 0.01), quantile(&positive, 0.99));
    let log_fits = p01.is_finite() && p99 > 100.0 * p01;
    let axis = match axis {
        CdfAxis::Auto if log_fits => CdfAxis::Log,
        CdfAxis::Auto => CdfAxis::Fitted,
        CdfAxis::Log if !(p01.is_finite() && p99 > p01) => CdfAxis::Fitted,
        a => a,
    };
    // (x_min, x_max, log, note)
    let (x_min, x_max, log, axis_note) = match axis {
        CdfAxis::Fixed(m) => (0.0, m, false, format!("x axis fixed: 0 to {m}")),
        CdfAxis::Log => {
            let lo = 10f64.powf(p01.log10().floor());
            let hi = nice_ceil(p99);
            (
                lo,
                hi,
                true,
                format!(
                    "log x axis: from {} (the decade at or below the 1st percentile of positive values, {p01:.2e}; smaller values drawn at the left edge) to the 99th percentile ({p99:.3}) rounded up, {}",
                    tick_text(lo, lo),
                    tick_text(hi, hi)
                ),
            )
        }
        _ if q99.is_finite() && q99 > 0.0 => {
            let m = nice_ceil(q99);
            (
                0.0,
                m,
                false,
                format!(
                    "x axis fitted: 0 to the 99th percentile of finite values ({q99:.3}), rounded up to {}",
                    tick_text(m, m)
                ),
            )
        }
        _ => (
            0.0,
            1.0,
            false,
            "x axis 0 to 1: no positive finite value".to_string(),
        ),
    };
    let (left, top, pw, ph) = (64.0, 48.0, 460.0, 300.0);
    // x ticks (value, label): a step wide enough for the labels it makes;
    // on a log axis every decade, or every second or third if they crowd.
    let x_ticks: Vec<(f64, String)> = if log {
        let (k0, k1) = (x_min.log10().round() as i32, x_max.log10().floor() as i32);
        let decade_px = pw / (x_max / x_min).log10();
        let widest = (k0..=k1)
            .map(|k| tick_text(10f64.powi(k), 10f64.powi(k)).len())
            .max()
            .unwrap_or(1) as f64;
        let every = ((widest * CHAR_PX + 12.0) / decade_px).ceil().max(1.0) as i32;
        (k0..=k1)
            .filter(|k| (k - k0) % every == 0)
            .map(|k| (10f64.powi(k), tick_text(10f64.powi(k), 10f64.powi(k))))
            .collect()
    } else {
        let mut step = tick_step(x_max, pw, 3.0 * CHAR_PX);
        for _ in 0..3 {
            let widest = (0..)
                .map(|k| f64::from(k) * step)
                .take_while(|v| *v <= x_max * (1.0 + 1e-9))
                .map(|v| tick_text(v, step).len())
                .max()
                .unwrap_or(1);
            step = tick_step(x_max, pw, widest as f64 * CHAR_PX);
        }
        (0..)
            .map(|k| f64::from(k) * step)
            .take_while(|v| *v <= x_max * (1.0 + 1e-9))
            .map(|v| (v, tick_text(v, step)))
            .collect()
    };
    let y_step = tick_step(1.0, ph, 14.0);
    let sx = |x: f64| {
        if log {
            left + pw * (x.clamp(x_min, x_max) / x_min).ln() / (x_max / x_min).ln()
        } else {
            left + pw * (x.min(x_max) / x_max)
        }
    };
    let sy = |y: f64| top + ph * (1.0 - y);
    let entries: Vec<(Mark, String)> = series
        .iter()
        .enumerate()
        .map(|(i, (name, values))| {
            let beyond = values
                .iter()
                .filter(|v| !v.is_finite() || **v > x_max)
                .count();
            let label = if beyond > 0 {
                format!("{name} ({beyond} of {} beyond the axis)", values.len())
            } else {
                name.clone()
            };
            (
                Mark::Line(
                    COLOURS[i % COLOURS.len()].into(),
                    2.0,
                    DASHES[i % DASHES.len()].into(),
                ),
                label,
            )
        })
        .collect();
    let (legend_svg, lw, _) = legend(left + pw + 16.0, top, &entries);
    let w = left + pw + 16.0 + lw + 10.0;
    let title_lines = wai_render::wrap(title, (w / 8.0) as usize);
    let top_shift = 18.0 * (title_lines.len() as f64 - 1.0);
    let note_lines = wai_render::wrap(&axis_note, ((pw + left) / 6.2) as usize);
    let h = top + ph + 58.0 + 14.0 * note_lines.len() as f64 + top_shift;
    let mut s = String::new();
    let _ = write!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w:.0}" height="{h:.0}" viewBox="0 0 {w:.1} {h:.1}" font-family="sans-serif" font-size="12"><rect width="100%" height="100%" fill="white"/>"#,
    );
    for (i, l) in title_lines.iter().enumerate() {
        let _ = write!(
            s,
            r#"<text x="{:.1}" y="{:.1}" text-anchor="middle" font-size="14">{}</text>"#,
            w / 2.0,
            20.0 + 18.0 * i as f64,
            xml(l)
        );
    }
    let _ = write!(s, r#"<g transform="translate(0 {top_shift:.1})">"#);
    let mut k = 0;
    while f64::from(k) * y_step <= 1.0 + 1e-9 {
        let f = f64::from(k) * y_step;
        let _ = write!(
            s,
            r##"<line x1="{left}" x2="{}" y1="{y:.2}" y2="{y:.2}" stroke="#e4e4e4"/><line x1="{}" x2="{left}" y1="{y:.2}" y2="{y:.2}" stroke="#222"/><text x="{}" y="{:.2}" text-anchor="end">{}</text>"##,
            left + pw,
            left - 4.0,
            left - 7.0,
            sy(f) + 4.0,
            tick_text(f, y_step),
            y = sy(f),
        );
        k += 1;
    }
    if log {
        // Unlabelled grid lines at 2–9 × 10^k.
        let mut d = x_min;
        while d < x_max {
            for m in 2..10 {
                let v = d * f64::from(m);
                if v < x_max {
                    let _ = write!(
                        s,
                        r##"<line x1="{x:.2}" x2="{x:.2}" y1="{top}" y2="{}" stroke="#f0f0f0"/>"##,
                        top + ph,
                        x = sx(v)
                    );
                }
            }
            d *= 10.0;
        }
    }
    for (v, label) in &x_ticks {
        let _ = write!(
            s,
            r##"<line x1="{x:.2}" x2="{x:.2}" y1="{top}" y2="{}" stroke="#e4e4e4"/><line x1="{x:.2}" x2="{x:.2}" y1="{}" y2="{}" stroke="#222"/><text class="x-tick" x="{x:.2}" y="{}" text-anchor="middle">{label}</text>"##,
            top + ph,
            top + ph,
            top + ph + 4.0,
            top + ph + 17.0,
            x = sx(*v),
        );
    }
    let _ = write!(
        s,
        r##"<rect x="{left}" y="{top}" width="{pw}" height="{ph}" fill="none" stroke="#222"/><text x="{}" y="{}" text-anchor="middle">{}</text><text x="16" y="{}" transform="rotate(-90 16 {})" text-anchor="middle">fraction of queries (CDF)</text>"##,
        left + pw / 2.0,
        top + ph + 36.0,
        xml(&if log {
            format!("{x_label}, log scale")
        } else {
            x_label.to_string()
        }),
        top + ph / 2.0,
        top + ph / 2.0
    );
    for (i, l) in note_lines.iter().enumerate() {
        let _ = write!(
            s,
            r##"<text class="axis-note" x="8" y="{:.1}" font-size="11" fill="#555">{}</text>"##,
            top + ph + 54.0 + 14.0 * i as f64,
            xml(l)
        );
    }
    for (i, (_, values)) in series.iter().enumerate() {
        let colour = COLOURS[i % COLOURS.len()];
        let dash = DASHES[i % DASHES.len()];
        let n = values.len().max(1) as f64;
        let mut pts = format!("{:.2},{:.2}", sx(0.0), sy(0.0));
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
        let _ = write!(
            s,
            r#"<polyline points="{pts}" fill="none" stroke="{colour}" stroke-width="1.8" stroke-dasharray="{dash}"/>"#,
        );
    }
    s.push_str("</g>");
    let _ = write!(
        s,
        r#"<g transform="translate(0 {top_shift:.1})">{legend_svg}</g>"#
    );
    s.push_str("</svg>\n");
    s
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
