//! The YAML half of a ROS `map_server` map: the keys `image`, `resolution`,
//! `origin`, `occupied_thresh`, `free_thresh`, `negate` and `mode`, each
//! number read exactly from its text.
//!
//! This reads the flat subset of YAML those files use (`key: value` lines,
//! `#` comments, quoted strings, `[a, b, c]` lists); other keys are ignored.

use crate::error::GridError;
use rug::Rational;
use std::path::{Path, PathBuf};

/// How pixel values become occupancy (the `mode` key).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    /// Free, occupied or unknown by the thresholds (the default).
    Trinary,
    /// As trinary for free and occupied; values between are graded (here:
    /// not free, as unknown cells are).
    Scale,
    /// Pixel values are occupancy values; refused, as it has no thresholds.
    Raw,
}

/// The metadata of an occupancy grid.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct GridMeta {
    /// The image file as written (relative to the YAML file's folder unless
    /// absolute).
    pub image: String,
    /// Metres per cell, > 0.
    pub resolution: Rational,
    /// The world position of the image's lower-left corner, in metres.
    pub origin: [Rational; 2],
    /// Cells whose occupancy exceeds this are occupied.
    pub occupied_thresh: Rational,
    /// Cells whose occupancy is below this are free.
    pub free_thresh: Rational,
    /// White is occupied, black free.
    pub negate: bool,
    pub mode: Mode,
}

impl GridMeta {
    /// The image's path: `image` as written, relative to `yaml`'s folder.
    pub fn image_path(&self, yaml: &Path) -> PathBuf {
        let image = Path::new(&self.image);
        if image.is_absolute() {
            image.to_path_buf()
        } else {
            yaml.parent().unwrap_or(Path::new("")).join(image)
        }
    }
}

/// Parse the YAML text of `path` (named in errors).
pub fn parse(path: &Path, text: &str) -> Result<GridMeta, GridError> {
    let yaml_err = |line: usize, message: String| GridError::Yaml {
        path: path.to_path_buf(),
        line,
        message,
    };
    let bad = |field: &'static str, message: String| GridError::BadField {
        path: path.to_path_buf(),
        field,
        message,
    };
    let mut fields: Vec<(String, String, usize)> = Vec::new();
    for (k, raw) in text.lines().enumerate() {
        let line = k + 1;
        let body = strip_comment(raw).trim();
        if body.is_empty() || body == "---" || body == "..." {
            continue;
        }
        let Some((key, value)) = body.split_once(':') else {
            return Err(yaml_err(
                line,
                format!("expected `key: value`, found {body:?}"),
            ));
        };
        let key = key.trim().to_string();
        if fields.iter().any(|(k, _, _)| *k == key) {
            return Err(yaml_err(line, format!("key {key:?} given twice")));
        }
        fields.push((key, unquote(value.trim()).to_string(), line));
    }
    let get = |key: &str| {
        fields
            .iter()
            .find(|(k, _, _)| k == key)
            .map(|(_, v, l)| (v.as_str(), *l))
    };
    let missing = |field: &'static str, what: &'static str| GridError::MissingField {
        path: path.to_path_buf(),
        field,
        what,
    };
    let number = |field: &'static str, text: &str| -> Result<Rational, GridError> {
        parse_number(text).map_err(|m| bad(field, format!("{text:?} {m}")))
    };
    let image = get("image")
        .ok_or_else(|| missing("image", "the image file"))?
        .0
        .to_string();
    if image.is_empty() {
        return Err(bad("image", "empty".into()));
    }
    let resolution = number(
        "resolution",
        get("resolution")
            .ok_or_else(|| missing("resolution", "metres per cell"))?
            .0,
    )?;
    if resolution <= 0 {
        return Err(bad(
            "resolution",
            format!("{resolution} metres per cell: must be above 0"),
        ));
    }
    let (origin_text, origin_line) =
        get("origin").ok_or_else(|| missing("origin", "[x, y, yaw] of the lower-left corner"))?;
    let Some(list) = origin_text
        .strip_prefix('[')
        .and_then(|s| s.strip_suffix(']'))
    else {
        return Err(yaml_err(
            origin_line,
            format!("origin: expected [x, y, yaw], found {origin_text:?}"),
        ));
    };
    let parts: Vec<&str> = list.split(',').map(str::trim).collect();
    if parts.len() != 3 {
        return Err(bad(
            "origin",
            format!("expected three numbers [x, y, yaw], found {}", parts.len()),
        ));
    }
    let origin = [number("origin", parts[0])?, number("origin", parts[1])?];
    let yaw = number("origin", parts[2])?;
    if yaw != 0 {
        return Err(bad(
            "origin",
            format!("yaw {} is not 0: rotated grids are not read (rotating the cells would leave exact grid coordinates)", parts[2]),
        ));
    }
    let thresh = |field: &'static str, default: Option<&str>| -> Result<Rational, GridError> {
        let text = match (get(field), default) {
            (Some((v, _)), _) => v.to_string(),
            (None, Some(d)) => d.to_string(),
            (None, None) => return Err(missing(field, "an occupancy probability in [0, 1]")),
        };
        let v = number(field, &text)?;
        if !(0..=1).contains(&v) {
            return Err(bad(field, format!("{text}: not in [0, 1]")));
        }
        Ok(v)
    };
    let occupied_thresh = thresh("occupied_thresh", None)?;
    let free_thresh = thresh("free_thresh", None)?;
    if free_thresh > occupied_thresh {
        return Err(bad(
            "free_thresh",
            format!(
                "{} is above occupied_thresh {}: the thresholds are out of order",
                wai_map::format_exact(&free_thresh),
                wai_map::format_exact(&occupied_thresh)
            ),
        ));
    }
    let negate = match get("negate").map(|(v, _)| v) {
        None | Some("0") | Some("false") | Some("False") | Some("no") => false,
        Some("1") | Some("true") | Some("True") | Some("yes") => true,
        Some(other) => return Err(bad("negate", format!("{other:?}: expected 0 or 1"))),
    };
    let mode = match get("mode").map(|(v, _)| v) {
        None | Some("trinary") => Mode::Trinary,
        Some("scale") => Mode::Scale,
        Some("raw") => {
            return Err(bad(
                "mode",
                "raw: pixel values are occupancy values without thresholds; only trinary and scale are read".into(),
            ))
        }
        Some(other) => {
            return Err(bad(
                "mode",
                format!("{other:?}: expected trinary, scale or raw"),
            ))
        }
    };
    Ok(GridMeta {
        image,
        resolution,
        origin,
        occupied_thresh,
        free_thresh,
        negate,
        mode,
    })
}

/// The line without a `#` comment (a `#` at the start or after a space,
/// outside quotes).
fn strip_comment(line: &str) -> &str {
    let mut quote = None;
    let mut prev = ' ';
    for (i, c) in line.char_indices() {
        match (quote, c) {
            (None, '"' | '\'') => quote = Some(c),
            (Some(q), c) if c == q => quote = None,
            (None, '#') if prev.is_whitespace() => return &line[..i],
            _ => {}
        }
        prev = c;
    }
    line
}

fn unquote(v: &str) -> &str {
    for q in ['"', '\''] {
        if let Some(inner) = v.strip_prefix(q).and_then(|s| s.strip_suffix(q)) {
            return inner;
        }
    }
    v
}

/// An exact number as YAML writes it: also `.5`, `5.`, `+5` and exponents
/// (`1e-3`, `2.5E2`), all read exactly.
pub(crate) fn parse_number(text: &str) -> Result<Rational, String> {
    let t = text.trim();
    let (mantissa, exponent) = match t.find(['e', 'E']) {
        Some(k) => {
            let e: i32 = t[k + 1..]
                .parse()
                .map_err(|_| "is not a number".to_string())?;
            if e.unsigned_abs() > 400 {
                return Err("has an exponent beyond ±400".into());
            }
            (&t[..k], e)
        }
        None => (t, 0),
    };
    let (sign, digits) = match mantissa.strip_prefix('-') {
        Some(rest) => ("-", rest),
        None => ("", mantissa.strip_prefix('+').unwrap_or(mantissa)),
    };
    let mut digits = digits.to_string();
    if digits.starts_with('.') {
        digits.insert(0, '0');
    }
    if digits.ends_with('.') {
        digits.push('0');
    }
    let v = wai_map::parse_exact(&format!("{sign}{digits}"))
        .map_err(|e| format!("is not a number: {e}"))?;
    let power = Rational::from(rug::Integer::from(rug::Integer::u_pow_u(
        10,
        exponent.unsigned_abs(),
    )));
    let scale = if exponent >= 0 { power } else { power.recip() };
    Ok(v * scale)
}
