//! The map file format of `data/datasets/README.md`, read and written
//! exactly.
//!
//! ```json
//! {"name": "room", "outer": [["0", "0"], ["7/2", "0"], ["3.5", "2"], [0, 2]]}
//! ```
//! `outer` is an open ring of `[x, y]` pairs, each coordinate an exact
//! number: a string holding an integer, a decimal or a fraction `p/q`, or a
//! JSON number written without exponent (read from its text, never through
//! a float). `holes`, if present, must be empty (holes are not supported
//! yet); `name` and `source` are kept; `units`, if present, says what the
//! coordinates measure: `"m"`, `"lonlat"` or `"scale:K"` (K metres per
//! unit, [`crate::Units`]); every other field is ignored.

use crate::error::{MapError, MapErrors};
use crate::number::{format_exact, parse_exact, scale_to_integers, RawCoord};
use crate::polygon::{Loaded, Map};
use rug::{Integer, Rational};
use serde_json::Value;
use std::fmt::Write;

/// Read a map file.
pub fn from_json(bytes: &[u8]) -> Result<Loaded, MapErrors> {
    let root = parse_value(bytes)?;
    let Value::Object(obj) = &root else {
        return Err(structure("$", "expected an object with an \"outer\" ring").into());
    };
    if let Some(holes) = obj.get("holes") {
        match holes {
            Value::Array(h) if h.is_empty() => {}
            Value::Array(h) => return Err(MapError::HolesNotSupported { count: h.len() }.into()),
            Value::Null => {}
            _ => return Err(structure("holes", "expected an array of rings").into()),
        }
    }
    let outer = obj
        .get("outer")
        .ok_or_else(|| structure("$", "missing field \"outer\": the map's boundary ring"))?;
    let coords = read_ring(outer, "outer", false)?;
    let name = optional_string(obj.get("name"), "name")?;
    let source = optional_string(obj.get("source"), "source")?;
    let units = optional_string(obj.get("units"), "units")?
        .map(|u| crate::Units::parse(&u).map_err(|e| structure("units", &e)))
        .transpose()?;
    let loaded = build(coords, name, source)?;
    Ok(match units {
        Some(u) => Loaded {
            map: loaded.map.with_units(u),
            ..loaded
        },
        None => loaded,
    })
}

/// Write a map in the same format; [`from_json`] reads it back equal.
///
/// Coordinates are written as strings in input units (integers, finite
/// decimals, else `p/q`), one vertex per line.
pub fn to_json(map: &Map) -> String {
    let mut s = String::from("{\n");
    if let Some(name) = map.name() {
        let _ = writeln!(s, "  \"name\": {},", Value::from(name));
    }
    if let Some(source) = map.source() {
        let _ = writeln!(s, "  \"source\": {},", Value::from(source));
    }
    if let Some(units) = map.units() {
        let _ = writeln!(s, "  \"units\": \"{units}\",");
    }
    s.push_str("  \"outer\": [\n");
    let unit = |c: i128| format_exact(&Rational::from((Integer::from(c), map.scale().clone())));
    for (i, p) in map.vertices().iter().enumerate() {
        let comma = if i + 1 < map.n() { "," } else { "" };
        let _ = writeln!(s, "    [\"{}\", \"{}\"]{comma}", unit(p.x), unit(p.y));
    }
    s.push_str("  ],\n  \"holes\": []\n}\n");
    s
}

pub(crate) fn structure(path: &str, message: &str) -> MapError {
    MapError::Structure {
        path: path.to_string(),
        message: message.to_string(),
    }
}

/// Bytes to a JSON value, with an error for empty, non-UTF-8 and malformed
/// input.
/// `bytes` without a leading UTF-8 byte-order mark (EF BB BF), which some
/// editors write and JSON readers may ignore (RFC 8259 sec. 8.1).
pub fn strip_bom(bytes: &[u8]) -> &[u8] {
    bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes)
}

pub(crate) fn parse_value(bytes: &[u8]) -> Result<Value, MapError> {
    let body = strip_bom(bytes);
    let text = std::str::from_utf8(body).map_err(|e| MapError::NotUtf8 {
        offset: bytes.len() - body.len() + e.valid_up_to(),
    })?;
    if text.trim().is_empty() {
        return Err(MapError::Empty);
    }
    serde_json::from_str(text).map_err(|e| {
        let full = e.to_string();
        let message = match full.rfind(" at line ") {
            Some(k) => full[..k].to_string(),
            None => full,
        };
        MapError::Syntax {
            line: e.line(),
            column: e.column(),
            message,
        }
    })
}

fn optional_string(v: Option<&Value>, path: &str) -> Result<Option<String>, MapError> {
    match v {
        None | Some(Value::Null) => Ok(None),
        Some(Value::String(s)) => Ok(Some(s.clone())),
        Some(_) => Err(structure(path, "expected a string")),
    }
}

/// Read a ring of positions. GeoJSON positions may carry more than two
/// numbers (an altitude), which are ignored when `extra_ok`.
pub(crate) fn read_ring(v: &Value, path: &str, extra_ok: bool) -> Result<Vec<RawCoord>, MapErrors> {
    let Value::Array(vertices) = v else {
        return Err(structure(path, "expected an array of [x, y] vertices").into());
    };
    let mut errors = Vec::new();
    let mut coords = Vec::with_capacity(2 * vertices.len());
    for (i, vertex) in vertices.iter().enumerate() {
        let vpath = format!("{path}[{i}]");
        let pair = match vertex {
            Value::Array(xy) if xy.len() == 2 || (extra_ok && xy.len() > 2) => xy,
            _ => {
                errors.push(structure(&vpath, "expected a vertex [x, y] of two numbers"));
                continue;
            }
        };
        for (k, c) in pair.iter().take(2).enumerate() {
            let cpath = format!("{vpath}[{k}]");
            let text = match c {
                Value::String(s) => s.clone(),
                Value::Number(n) => n.to_string(),
                _ => {
                    errors.push(structure(
                        &cpath,
                        "expected a number or a string holding an exact number",
                    ));
                    continue;
                }
            };
            match parse_exact(&text) {
                Ok(value) => coords.push(RawCoord { path: cpath, value }),
                Err(reason) => errors.push(MapError::BadNumber {
                    path: cpath,
                    text: truncate(&text),
                    reason,
                }),
            }
        }
    }
    if errors.is_empty() {
        Ok(coords)
    } else {
        Err(MapErrors(errors))
    }
}

fn truncate(text: &str) -> String {
    match text.char_indices().nth(40) {
        Some((k, _)) => format!("{}…", &text[..k]),
        None => text.to_string(),
    }
}

/// Scale, validate and normalise a ring read from a file.
pub(crate) fn build(
    coords: Vec<RawCoord>,
    name: Option<String>,
    source: Option<String>,
) -> Result<Loaded, MapErrors> {
    let (points, scale) = scale_to_integers(&coords).map_err(MapErrors)?;
    let (mut map, normalisation) = Map::from_scaled_ring(points, scale)?;
    if let Some(name) = name {
        map = map.with_name(name);
    }
    if let Some(source) = source {
        map = map.with_source(source);
    }
    Ok(Loaded { map, normalisation })
}
