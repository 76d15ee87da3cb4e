//! Scan files: the workspace's own JSON (as `wai scan` writes it) and ROS
//! `sensor_msgs/LaserScan` as JSON, told apart by their fields.
//!
//! - **Ours**: `{"angles": [...], "ranges": [... | null], "sensor":
//!   {"max_range", "min_range"}, "pose": {"x", "y", "heading_degrees"}}`,
//!   angles in radians relative to the heading, `null` for no return.
//! - **ROS LaserScan**: `angle_min`, `angle_increment` (`angle_max` checked
//!   against them), `range_min`, `range_max`, `ranges`; `intensities`,
//!   `header`, `time_increment` and `scan_time` ignored; bare, or wrapped
//!   as rosbridge publishes it (`{"op": "publish", "msg": {...}}`).
//!
//! Each range is read by the ROS rules (the message's comments and REP
//! 117), in both formats: `+Inf` (`"inf"`), a value above the maximum range
//! and `null` (which rosbridge writes for non-finite floats) mean *no
//! return*: nothing within the range along that beam (a lost beam of the
//! scan model, [`crate::range`]). `NaN`, `-Inf` (too close to measure) and
//! a value below the minimum range are *discarded*: they say nothing, so the
//! beam is dropped and its angles are masked (a gap in V_S, like a partial
//! field of view). The non-standard bare tokens `NaN`, `Infinity` and
//! `-Infinity` that Python's `json` module writes are accepted.

use serde_json::Value;

use crate::{Pose, Scan};

/// The format a scan file was read in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ScanFormat {
    /// `{"angles", "ranges", "sensor", "pose"}`, as `wai scan` writes it.
    Wai,
    /// ROS `sensor_msgs/LaserScan` as JSON.
    RosLaserScan,
}

impl ScanFormat {
    pub fn label(self) -> &'static str {
        match self {
            ScanFormat::Wai => "wai scan JSON",
            ScanFormat::RosLaserScan => "ROS sensor_msgs/LaserScan JSON",
        }
    }
}

/// Beams dropped while reading, by reason.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Discarded {
    /// NaN: an invalid reading.
    pub invalid: usize,
    /// −Inf: too close to measure.
    pub too_close: usize,
    /// Below the stated minimum range.
    pub below_min: usize,
}

impl Discarded {
    pub fn total(&self) -> usize {
        self.invalid + self.too_close + self.below_min
    }
}

/// A scan read from a file, and what the file said about it.
#[derive(Debug, Clone, PartialEq)]
pub struct ScanFile {
    /// The beams kept, with the stated maximum range.
    pub scan: Scan,
    pub format: ScanFormat,
    /// The minimum range the file states.
    pub min_range: Option<f64>,
    /// The compass heading the file records (ours: `pose.heading_degrees`),
    /// in radians.
    pub heading: Option<f64>,
    /// The pose the file says the scan was taken at (ours: `pose.x`,
    /// `pose.y`), if it says so.
    pub pose: Option<Pose>,
    /// Beams in the file, before any was discarded.
    pub beams_in_file: usize,
    pub discarded: Discarded,
    /// Values above the stated maximum range, read as no return.
    pub beyond_max: usize,
}

impl ScanFile {
    /// One line saying what was read.
    pub fn describe(&self) -> String {
        let d = &self.discarded;
        let mut parts = vec![format!(
            "{}, {} beams",
            self.format.label(),
            self.beams_in_file
        )];
        let lost = self.scan.ranges.iter().filter(|r| r.is_none()).count();
        parts.push(format!("{lost} without a return"));
        if self.beyond_max > 0 {
            parts.push(format!(
                "{} of them above the maximum range",
                self.beyond_max
            ));
        }
        if d.total() > 0 {
            let mut why = Vec::new();
            for (k, what) in [
                (d.invalid, "NaN"),
                (d.too_close, "-Inf: too close"),
                (d.below_min, "below the minimum range"),
            ] {
                if k > 0 {
                    why.push(format!("{k} {what}"));
                }
            }
            parts.push(format!("{} discarded ({})", d.total(), why.join(", ")));
        }
        parts.join(", ")
    }
}

/// One range as the file gives it.
enum Reading {
    Range(f64),
    NoReturn,
    Invalid,
    TooClose,
}

/// Reads a scan file's bytes (either format; see the module docs).
pub fn read(bytes: &[u8]) -> Result<ScanFile, String> {
    let text = std::str::from_utf8(wai_map::json::strip_bom(bytes))
        .map_err(|e| format!("not UTF-8: {e}"))?;
    let text = quote_non_finite(text);
    let v: Value = serde_json::from_str(&text).map_err(|e| format!("not JSON: {e}"))?;
    let msg = match v.get("msg") {
        Some(m) if m.get("angle_min").is_some() => m,
        _ => &v,
    };
    if msg.get("angles").is_some() {
        read_wai(msg)
    } else if msg.get("angle_min").is_some() || msg.get("angle_increment").is_some() {
        read_ros(msg)
    } else {
        Err(
            "neither a wai scan (\"angles\", \"ranges\") nor a ROS LaserScan \
             (\"angle_min\", \"angle_increment\", \"ranges\")"
                .into(),
        )
    }
}

/// `text` with the bare tokens `NaN`, `Infinity` and `-Infinity` outside
/// strings turned into the strings `"nan"`, `"inf"` and `"-inf"`.
fn quote_non_finite(text: &str) -> std::borrow::Cow<'_, str> {
    if !(text.contains("NaN") || text.contains("Infinity")) {
        return text.into();
    }
    let mut out = String::with_capacity(text.len() + 16);
    let (mut in_string, mut escaped) = (false, false);
    let mut rest = text;
    while let Some(c) = rest.chars().next() {
        if in_string {
            match (escaped, c) {
                (true, _) => escaped = false,
                (false, '\\') => escaped = true,
                (false, '"') => in_string = false,
                _ => {}
            }
        } else if c == '"' {
            in_string = true;
        } else {
            let token = [
                ("-Infinity", "\"-inf\""),
                ("Infinity", "\"inf\""),
                ("NaN", "\"nan\""),
            ]
            .into_iter()
            .find(|(bare, _)| rest.starts_with(bare));
            if let Some((bare, quoted)) = token {
                out.push_str(quoted);
                rest = &rest[bare.len()..];
                continue;
            }
        }
        out.push(c);
        rest = &rest[c.len_utf8()..];
    }
    out.into()
}

/// A positive finite number at `key` of `v`, if present (`null`: absent).
fn optional_positive(v: &Value, key: &str, label: &str) -> Result<Option<f64>, String> {
    match v.get(key) {
        None | Some(Value::Null) => Ok(None),
        Some(x) => match x.as_f64() {
            Some(r) if r.is_finite() && r >= 0.0 => Ok(Some(r)),
            _ => Err(format!("{label} = {x} is not a finite number ≥ 0")),
        },
    }
}

fn reading(x: &Value, at: &str) -> Result<Reading, String> {
    match x {
        Value::Null => Ok(Reading::NoReturn),
        Value::String(s) => match s.trim().to_ascii_lowercase().as_str() {
            "inf" | "+inf" | "infinity" | "+infinity" => Ok(Reading::NoReturn),
            "-inf" | "-infinity" => Ok(Reading::TooClose),
            "nan" => Ok(Reading::Invalid),
            _ => Err(format!("{at} = {x} is not a range")),
        },
        _ => match x.as_f64() {
            Some(r) if r.is_finite() && r >= 0.0 => Ok(Reading::Range(r)),
            Some(r) if r.is_finite() => Err(format!("{at} = {r} is negative")),
            _ => Err(format!("{at} = {x} is not a range")),
        },
    }
}

/// The beams kept from `angles` and the readings, by the rules of the
/// module docs.
fn keep(
    angles: Vec<f64>,
    ranges: &[Value],
    min: Option<f64>,
    max: Option<f64>,
    format: ScanFormat,
) -> Result<ScanFile, String> {
    let mut discarded = Discarded::default();
    let mut beyond_max = 0;
    let (mut kept_angles, mut kept) = (Vec::new(), Vec::new());
    for (i, (a, x)) in angles.iter().zip(ranges).enumerate() {
        let r = match reading(x, &format!("ranges[{i}]"))? {
            Reading::Invalid => {
                discarded.invalid += 1;
                continue;
            }
            Reading::TooClose => {
                discarded.too_close += 1;
                continue;
            }
            Reading::NoReturn => None,
            Reading::Range(r) if min.is_some_and(|m| r < m) => {
                discarded.below_min += 1;
                continue;
            }
            Reading::Range(r)
                if format == ScanFormat::RosLaserScan && max.is_some_and(|m| r > m) =>
            {
                beyond_max += 1;
                None
            }
            Reading::Range(r) => Some(r),
        };
        kept_angles.push(*a);
        kept.push(r);
    }
    Ok(ScanFile {
        scan: Scan {
            angles: kept_angles,
            ranges: kept,
            max_range: max,
        },
        format,
        min_range: min,
        heading: None,
        pose: None,
        beams_in_file: angles.len(),
        discarded,
        beyond_max,
    })
}

fn read_wai(v: &Value) -> Result<ScanFile, String> {
    let array = |key: &str| {
        v.get(key)
            .and_then(Value::as_array)
            .ok_or_else(|| format!("no array {key:?}"))
    };
    let angles = array("angles")?
        .iter()
        .enumerate()
        .map(|(i, a)| {
            a.as_f64()
                .filter(|a| a.is_finite())
                .ok_or_else(|| format!("angles[{i}] = {a} is not a finite number"))
        })
        .collect::<Result<Vec<f64>, String>>()?;
    let ranges = array("ranges")?;
    if angles.len() != ranges.len() || angles.is_empty() {
        return Err(format!(
            "{} angles and {} ranges: expected as many, at least one",
            angles.len(),
            ranges.len()
        ));
    }
    let sensor = v.get("sensor").cloned().unwrap_or(Value::Null);
    let max = optional_positive(&sensor, "max_range", "sensor.max_range")?.filter(|m| *m > 0.0);
    let min = optional_positive(&sensor, "min_range", "sensor.min_range")?;
    let mut file = keep(angles, ranges, min, max, ScanFormat::Wai)?;
    let pose = v.get("pose");
    file.heading = match pose.and_then(|p| p.get("heading_degrees")) {
        None | Some(Value::Null) => None,
        Some(h) => Some(
            h.as_f64()
                .filter(|h| h.is_finite())
                .ok_or_else(|| format!("pose.heading_degrees = {h} is not a finite number"))?
                .to_radians(),
        ),
    };
    let coordinate = |k: &str| pose.and_then(|p| p.get(k)).and_then(Value::as_f64);
    file.pose = match (coordinate("x"), coordinate("y")) {
        (Some(x), Some(y)) if x.is_finite() && y.is_finite() => Some(Pose {
            x,
            y,
            heading: file.heading.unwrap_or(0.0),
        }),
        _ => None,
    };
    Ok(file)
}

fn read_ros(v: &Value) -> Result<ScanFile, String> {
    let number = |key: &str| -> Result<f64, String> {
        let x = v
            .get(key)
            .ok_or_else(|| format!("a ROS LaserScan needs {key:?}"))?;
        x.as_f64()
            .filter(|f| f.is_finite())
            .ok_or_else(|| format!("{key} = {x} is not a finite number"))
    };
    let angle_min = number("angle_min")?;
    let increment = number("angle_increment")?;
    if increment == 0.0 {
        return Err("angle_increment is 0: the beams would share one angle".into());
    }
    let ranges = v
        .get("ranges")
        .and_then(Value::as_array)
        .ok_or("a ROS LaserScan needs the array \"ranges\"")?;
    if ranges.is_empty() {
        return Err("\"ranges\" is empty".into());
    }
    if (ranges.len() as f64 * increment.abs()) > std::f64::consts::TAU * (1.0 + 1e-6) {
        return Err(format!(
            "{} beams {} rad apart span more than a full turn",
            ranges.len(),
            increment.abs()
        ));
    }
    if let Some(x) = v.get("angle_max").filter(|x| !x.is_null()) {
        let angle_max = x
            .as_f64()
            .filter(|f| f.is_finite())
            .ok_or_else(|| format!("angle_max = {x} is not a finite number"))?;
        // Drivers disagree on whether angle_max is the last beam's angle or
        // one step beyond it; anything further off is another scan's header.
        let last = angle_min + increment * (ranges.len() - 1) as f64;
        if (angle_max - last).abs() > 1.5 * increment.abs() + 1e-6 {
            return Err(format!(
                "angle_max = {angle_max} but {} beams from angle_min = {angle_min} in steps of \
                 {increment} end at {last}",
                ranges.len()
            ));
        }
    }
    let min = optional_positive(v, "range_min", "range_min")?.filter(|m| *m > 0.0);
    let max = optional_positive(v, "range_max", "range_max")?.filter(|m| *m > 0.0);
    if let (Some(lo), Some(hi)) = (min, max) {
        if lo >= hi {
            return Err(format!("range_min = {lo} is not below range_max = {hi}"));
        }
    }
    let angles = (0..ranges.len())
        .map(|i| angle_min + increment * i as f64)
        .collect();
    keep(angles, ranges, min, max, ScanFormat::RosLaserScan)
}
