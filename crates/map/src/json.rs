//! The map file format of `data/datasets/README.md`, read and written
//! exactly.
//!
//! ```json
//! {"name": "room", "outer": [["0", "0"], ["7/2", "0"], ["3.5", "2"], [0, 2]]}
//! ```
//! `outer` is an open ring of `[x, y]` pairs, each coordinate an exact
//! number: a string holding an integer, a decimal or a fraction `p/q`, or a
//! JSON number written without exponent (read from its text, never through
//! a float). `holes`, if present, is an array of such rings, one per hole
//! (either orientation; they are made clockwise); `name` and `source` are
//! kept; `units`, if present, says what the
//! coordinates measure: `"m"`, `"lonlat"` or `"scale:K"` (K metres per
//! unit, [`crate::Units`]); every other field is ignored.

use crate::error::{MapError, MapErrors};
use crate::number::{format_exact, parse_exact, round_to_grid, scale_to_integers, RawCoord};
use crate::polygon::{Loaded, Map};
use rug::{Integer, Rational};
use serde_json::Value;
use std::fmt::Write;

/// How a reader treats coordinates before it scales them to integers.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ReadOptions {
    /// Round every coordinate to the nearest multiple of `2^-bits` first
    /// (reported in [`crate::Normalisation::rounded`]). For sources whose
    /// exact values need more than [`wai_exact::MAX_COORD_BITS`] bits over
    /// their common denominator — a stray subnormal double, rationals with
    /// 70-bit denominators — at the price of a slightly different map. The
    /// rounded map is validated like any other.
    pub grid_bits: Option<u32>,
}

/// The finest grid a reader may round to: on a finer one not even a
/// coordinate of magnitude 1 fits [`wai_exact::MAX_COORD_BITS`].
pub const MAX_GRID_BITS: u32 = wai_exact::MAX_COORD_BITS - 1;

/// Read a map file.
pub fn from_json(bytes: &[u8]) -> Result<Loaded, MapErrors> {
    from_json_with(bytes, &ReadOptions::default())
}

/// [`from_json`] with [`ReadOptions`].
pub fn from_json_with(bytes: &[u8], options: &ReadOptions) -> Result<Loaded, MapErrors> {
    let root = parse_value(bytes)?;
    let Value::Object(obj) = &root else {
        return Err(structure("$", "expected an object with an \"outer\" ring").into());
    };
    let outer = obj
        .get("outer")
        .ok_or_else(|| structure("$", "missing field \"outer\": the map's boundary ring"))?;
    let mut rings = vec![read_ring(outer, "outer", false)];
    match obj.get("holes") {
        None | Some(Value::Null) => {}
        Some(Value::Array(holes)) => {
            for (k, hole) in holes.iter().enumerate() {
                rings.push(read_ring(hole, &format!("holes[{k}]"), false));
            }
        }
        Some(_) => return Err(structure("holes", "expected an array of rings").into()),
    }
    let rings = collect_rings(rings)?;
    let name = optional_string(obj.get("name"), "name")?;
    let source = optional_string(obj.get("source"), "source")?;
    let units = optional_string(obj.get("units"), "units")?
        .map(|u| crate::Units::parse(&u).map_err(|e| structure("units", &e)))
        .transpose()?;
    let loaded = build(rings, name, source, options)?;
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
    let write_ring = |s: &mut String, ring: &[wai_exact::Point], indent: &str| {
        for (i, p) in ring.iter().enumerate() {
            let comma = if i + 1 < ring.len() { "," } else { "" };
            let _ = writeln!(s, "{indent}[\"{}\", \"{}\"]{comma}", unit(p.x), unit(p.y));
        }
    };
    write_ring(&mut s, map.outer(), "    ");
    if !map.has_holes() {
        s.push_str("  ],\n  \"holes\": []\n}\n");
        return s;
    }
    s.push_str("  ],\n  \"holes\": [\n");
    let h = map.hole_count();
    for (k, hole) in map.holes().enumerate() {
        s.push_str("    [\n");
        write_ring(&mut s, hole, "      ");
        s.push_str(if k + 1 < h { "    ],\n" } else { "    ]\n" });
    }
    s.push_str("  ]\n}\n");
    s
}

/// Every ring read, or every error of every ring.
pub(crate) fn collect_rings(
    read: Vec<Result<Vec<RawCoord>, MapErrors>>,
) -> Result<Vec<Vec<RawCoord>>, MapErrors> {
    let mut rings = Vec::with_capacity(read.len());
    let mut errors = Vec::new();
    for r in read {
        match r {
            Ok(ring) => rings.push(ring),
            Err(e) => errors.extend(e.0),
        }
    }
    if errors.is_empty() {
        Ok(rings)
    } else {
        Err(MapErrors(errors))
    }
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

/// Round (if asked), scale, validate and normalise the rings read from a
/// file: the outer ring first, then the holes.
pub(crate) fn build(
    rings: Vec<Vec<RawCoord>>,
    name: Option<String>,
    source: Option<String>,
    options: &ReadOptions,
) -> Result<Loaded, MapErrors> {
    let lengths: Vec<usize> = rings.iter().map(|r| r.len() / 2).collect();
    let mut coords: Vec<RawCoord> = rings.into_iter().flatten().collect();
    let rounded = match options.grid_bits {
        Some(bits) if bits > MAX_GRID_BITS => {
            return Err(structure(
                "options",
                &format!(
                    "a grid of 2^-{bits} is finer than the finest supported, 2^-{MAX_GRID_BITS}"
                ),
            )
            .into())
        }
        Some(bits) => Some(round_to_grid(&mut coords, bits)),
        None => None,
    };
    let (points, scale) = scale_to_integers(&coords).map_err(MapErrors)?;
    let mut points = points.into_iter();
    let mut rings: Vec<Vec<wai_exact::Point>> = lengths
        .iter()
        .map(|&m| points.by_ref().take(m).collect())
        .collect();
    let outer = rings.remove(0);
    let (mut map, mut normalisation) = Map::from_scaled_rings(outer, rings, scale)?;
    normalisation.rounded = rounded;
    if let Some(name) = name {
        map = map.with_name(name);
    }
    if let Some(source) = source {
        map = map.with_source(source);
    }
    Ok(Loaded { map, normalisation })
}
