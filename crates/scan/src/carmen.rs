//! CARMEN laser logs: the text format of the Radish datasets (plain or
//! gzip-compressed), as real robots recorded them.
//!
//! Read: `FLASER` (the old front-laser message), `ROBOTLASER1` and `ODOM`;
//! `PARAM` lines are kept; every other message is counted and skipped.
//!
//! - `FLASER n r1 … rn x y θ odom_x odom_y odom_θ timestamp host
//!   logger_timestamp`: `x y θ` is the pose the scan was taken from (in the
//!   "corrected" logs, the SLAM estimate). The beams are CARMEN's
//!   convention for the message, which states no angles: a field of view
//!   of 179° for 180 beams (179.5° for 360, 100° for 401, 99.75° for 400,
//!   else 180°), centred on the heading, in equal steps of 1° (0.5°, 0.25°,
//!   else fov / (n − 1)).
//! - `ROBOTLASER1 type start fov resolution max_range accuracy
//!   remission_mode n r1 … rn m e1 … em laser_x laser_y laser_θ robot_x
//!   robot_y robot_θ tv rv forward side turn timestamp host
//!   logger_timestamp`: angles from `start` in steps of `resolution`; the
//!   scan is taken from the laser's pose.
//! - `ODOM x y θ tv rv accel timestamp host logger_timestamp`.
//!
//! A reading at or above the sensor's maximum is **no return**: the
//! maximum is `ROBOTLASER1`'s own, else `PARAM robot_front_laser_max`, else
//! the log's largest reading when it repeats (the value a SICK reports for
//! nothing seen: 81.83 or 81.91 m in the Intel and Freiburg logs, 50 m in
//! ACES).

use std::collections::BTreeMap;
use std::io::Read;

/// One laser scan of a log.
#[derive(Clone, Debug, PartialEq)]
pub struct LogScan {
    /// 1-based line of the log.
    pub line: usize,
    /// The pose the scan was taken from: x, y in metres, θ in radians.
    pub pose: [f64; 3],
    /// The angle of each beam, radians from the heading.
    pub angles: Vec<f64>,
    /// What each beam read, metres, as recorded.
    pub ranges: Vec<f64>,
    /// The sensor's maximum as `ROBOTLASER1` states it.
    pub max_range: Option<f64>,
    pub timestamp: f64,
}

/// One odometry reading.
#[derive(Clone, Debug, PartialEq)]
pub struct Odometry {
    pub line: usize,
    pub pose: [f64; 3],
    pub timestamp: f64,
}

/// A CARMEN log.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct CarmenLog {
    pub scans: Vec<LogScan>,
    pub odometry: Vec<Odometry>,
    /// `PARAM name value` lines.
    pub params: BTreeMap<String, String>,
    /// Messages not read, by kind, with their counts.
    pub skipped: BTreeMap<String, usize>,
}

/// Why a log cannot be read, with the line.
#[derive(Debug, thiserror::Error)]
pub enum CarmenError {
    #[error("not gzip data that decompresses: {0}")]
    Gzip(std::io::Error),
    #[error("not UTF-8 text (line {line})")]
    NotText { line: usize },
    #[error("line {line}: {kind}: {message}")]
    Bad {
        line: usize,
        kind: String,
        message: String,
    },
    #[error("no laser scan (FLASER or ROBOTLASER1) in the log")]
    NoScan,
}

/// Logs larger than this when decompressed are refused.
pub const MAX_LOG_BYTES: u64 = 2 << 30;

/// Read a log, plain or gzip-compressed (by its magic bytes).
pub fn read(bytes: &[u8]) -> Result<CarmenLog, CarmenError> {
    let text;
    let body: &[u8] = if bytes.starts_with(&[0x1f, 0x8b]) {
        let mut out = Vec::new();
        flate2::read::MultiGzDecoder::new(bytes)
            .take(MAX_LOG_BYTES + 1)
            .read_to_end(&mut out)
            .map_err(CarmenError::Gzip)?;
        if out.len() as u64 > MAX_LOG_BYTES {
            return Err(CarmenError::Gzip(std::io::Error::other(format!(
                "more than {MAX_LOG_BYTES} bytes decompressed"
            ))));
        }
        text = out;
        &text
    } else {
        bytes
    };
    parse(body)
}

fn parse(body: &[u8]) -> Result<CarmenLog, CarmenError> {
    let mut log = CarmenLog::default();
    for (k, raw) in body.split(|&b| b == b'\n').enumerate() {
        let line = k + 1;
        let text = std::str::from_utf8(raw).map_err(|_| CarmenError::NotText { line })?;
        let mut tokens = text.split_whitespace();
        let Some(kind) = tokens.next() else { continue };
        if kind.starts_with('#') {
            continue;
        }
        let rest: Vec<&str> = tokens.collect();
        let bad = |message: String| CarmenError::Bad {
            line,
            kind: kind.to_string(),
            message,
        };
        match kind {
            "FLASER" => log.scans.push(flaser(line, &rest).map_err(bad)?),
            "ROBOTLASER1" => log.scans.push(robotlaser(line, &rest).map_err(bad)?),
            "ODOM" => {
                let f = Fields::new(&rest);
                log.odometry.push(Odometry {
                    line,
                    pose: [
                        f.num(0, "x").map_err(bad)?,
                        f.num(1, "y").map_err(bad)?,
                        f.num(2, "theta").map_err(bad)?,
                    ],
                    timestamp: f.num(6, "timestamp").unwrap_or(f64::NAN),
                });
            }
            "PARAM" => {
                if let [name, value, ..] = rest[..] {
                    log.params.insert(name.to_string(), value.to_string());
                }
            }
            other => *log.skipped.entry(other.to_string()).or_default() += 1,
        }
    }
    if log.scans.is_empty() {
        return Err(CarmenError::NoScan);
    }
    Ok(log)
}

struct Fields<'a>(&'a [&'a str]);

impl<'a> Fields<'a> {
    fn new(tokens: &'a [&'a str]) -> Self {
        Fields(tokens)
    }
    fn num(&self, k: usize, name: &str) -> Result<f64, String> {
        let t = self
            .0
            .get(k)
            .ok_or_else(|| format!("{name} missing (field {} of {})", k + 1, self.0.len()))?;
        let v: f64 = t
            .parse()
            .map_err(|_| format!("{name} {t:?} is not a number (field {})", k + 1))?;
        if v.is_finite() {
            Ok(v)
        } else {
            Err(format!("{name} {t:?} is not finite (field {})", k + 1))
        }
    }
    fn count(&self, k: usize, name: &str) -> Result<usize, String> {
        let t = self.0.get(k).ok_or_else(|| format!("{name} missing"))?;
        let n: usize = t
            .parse()
            .map_err(|_| format!("{name} {t:?} is not a count (field {})", k + 1))?;
        if n > 100_000 {
            return Err(format!("{name} {n}: more beams than any laser has"));
        }
        Ok(n)
    }
    fn ranges(&self, from: usize, n: usize) -> Result<Vec<f64>, String> {
        (from..from + n)
            .map(|k| {
                let r = self.num(k, "range")?;
                if r < 0.0 {
                    Err(format!("range {r} is negative (field {})", k + 1))
                } else {
                    Ok(r)
                }
            })
            .collect()
    }
}

/// CARMEN's field of view and step for a `FLASER` of `n` beams.
pub fn flaser_geometry(n: usize) -> (f64, f64) {
    use std::f64::consts::PI;
    let deg = PI / 180.0;
    match n {
        181 => (PI, deg),
        180 => (179.0 * deg, deg),
        361 => (PI, deg / 2.0),
        360 => (179.5 * deg, deg / 2.0),
        401 => (100.0 * deg, deg / 4.0),
        400 => (99.75 * deg, deg / 4.0),
        _ => (PI, PI / (n.max(2) - 1) as f64),
    }
}

fn flaser(line: usize, rest: &[&str]) -> Result<LogScan, String> {
    let f = Fields::new(rest);
    let n = f.count(0, "the number of beams")?;
    let ranges = f.ranges(1, n)?;
    let p = 1 + n;
    let pose = [f.num(p, "x")?, f.num(p + 1, "y")?, f.num(p + 2, "theta")?];
    let timestamp = f.num(p + 6, "timestamp").unwrap_or(f64::NAN);
    let (fov, step) = flaser_geometry(n);
    let start = -fov / 2.0;
    Ok(LogScan {
        line,
        pose,
        angles: (0..n).map(|i| start + i as f64 * step).collect(),
        ranges,
        max_range: None,
        timestamp,
    })
}

fn robotlaser(line: usize, rest: &[&str]) -> Result<LogScan, String> {
    let f = Fields::new(rest);
    let start = f.num(1, "start_angle")?;
    let step = f.num(3, "angular_resolution")?;
    let max_range = f.num(4, "maximum_range")?;
    let n = f.count(7, "the number of beams")?;
    let ranges = f.ranges(8, n)?;
    let m = f.count(8 + n, "the number of remissions")?;
    let p = 9 + n + m;
    let pose = [
        f.num(p, "laser x")?,
        f.num(p + 1, "laser y")?,
        f.num(p + 2, "laser theta")?,
    ];
    let timestamp = f.num(p + 11, "timestamp").unwrap_or(f64::NAN);
    Ok(LogScan {
        line,
        pose,
        angles: (0..n).map(|i| start + i as f64 * step).collect(),
        ranges,
        max_range: (max_range > 0.0).then_some(max_range),
        timestamp,
    })
}

impl CarmenLog {
    /// The reading at or above which a scan's beam is no return: see the
    /// module docs. `None` when nothing says (every reading a return).
    pub fn no_return_at(&self, scan: &LogScan) -> Option<f64> {
        if let Some(m) = scan.max_range {
            return Some(m);
        }
        if let Some(m) = self
            .params
            .get("robot_front_laser_max")
            .and_then(|v| v.parse::<f64>().ok())
            .filter(|m| *m > 0.0)
        {
            return Some(m);
        }
        self.largest_repeated_reading()
    }

    /// The log's largest reading, if it occurs at least ten times.
    fn largest_repeated_reading(&self) -> Option<f64> {
        let max = self
            .scans
            .iter()
            .flat_map(|s| s.ranges.iter().copied())
            .fold(0.0, f64::max);
        let times = self
            .scans
            .iter()
            .flat_map(|s| s.ranges.iter())
            .filter(|&&r| r == max)
            .count();
        (max > 0.0 && times >= 10).then_some(max)
    }

    /// Scan `k` as the localizer reads scans: angles from the heading,
    /// no-return beams as `None`, the sensor's maximum stated when known.
    pub fn scan(&self, k: usize) -> crate::Scan {
        let s = &self.scans[k];
        let cut = self.no_return_at(s);
        crate::Scan {
            angles: s.angles.clone(),
            ranges: s
                .ranges
                .iter()
                .map(|&r| match cut {
                    Some(c) if r >= c => None,
                    _ => Some(r),
                })
                .collect(),
            max_range: cut,
        }
    }
}
