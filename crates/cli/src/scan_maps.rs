#![allow(
    clippy::float_arithmetic,
    reason = "scans, poses, errors and timings are approximate"
)]
//! The maps and scans of the chapter 6 commands (`wai scan`, `wai
//! localize-scan`, `wai eval`): generated floors (`rooms:K`, `office:K`,
//! `family:ID:P…`) or files, in metres by their units, and scan files.

use std::path::Path;

use serde_json::{json, Value};
use wai_map::Map;
use wai_scan::units::{to_metres, LonLatFrame, Units};
use wai_scan::{Pose, Scan};

use crate::input::{load, Format};
use crate::Failure;

/// A map of an evaluation, in metres.
pub(crate) struct EvalMap {
    pub name: String,
    pub(crate) kind: &'static str,
    pub map: Map,
    pub(crate) units: String,
    /// For `rooms:K`: K rooms, 5 m apart, the first from x = 1 m, floors
    /// at y = 2.2 m (see [`wai_gen::repeated_rooms`]).
    pub(crate) rooms: Option<usize>,
    /// For a longitude/latitude map: the metric frame it is localized in.
    pub(crate) frame: Option<LonLatFrame>,
}

pub(crate) fn parse_units(text: &str) -> Result<Option<Units>, Failure> {
    match text {
        "auto" => Ok(None),
        "m" => Ok(Some(Units::Metres)),
        "lonlat" => Ok(Some(Units::LonLatDegrees)),
        _ => match text.strip_prefix("scale:").map(str::parse::<f64>) {
            Some(Ok(k)) if k.is_finite() && k > 0.0 => Ok(Some(Units::Scale(k))),
            _ => Err(Failure::usage(format!(
                "units {text:?}: expected auto, m, lonlat or scale:K with K > 0"
            ))),
        },
    }
}

/// The units `auto` picks for `map` read from `path`: the units its file
/// states, else longitude/latitude if it looks so
/// ([`wai_map::Map::looks_lonlat`]), 0.025 m per pixel for an R2V file,
/// else metres.
fn auto_units(path: &str, map: &Map) -> Units {
    match map.units() {
        Some(wai_map::Units::Metres) => Units::Metres,
        Some(wai_map::Units::LonLat) => Units::LonLatDegrees,
        // Numerator over denominator: the nearest double for a decimal
        // such as 0.01 (`Rational::to_f64` rounds toward zero).
        Some(wai_map::Units::Scale(k)) => Units::Scale(k.numer().to_f64() / k.denom().to_f64()),
        None if map.looks_lonlat() => Units::LonLatDegrees,
        // R2V annotations are image pixels; floor plans of flats at about
        // 40 px per metre (an assumption: the source gives no scale).
        None if path.contains("r2v") => Units::Scale(0.025),
        None => Units::Metres,
    }
}

pub(crate) fn units_label(u: Units) -> String {
    match u {
        Units::Metres => "m".into(),
        Units::LonLatDegrees => "lonlat".into(),
        Units::Scale(k) => format!("scale:{k}"),
    }
}

fn gen_failure(spec: &str, e: impl std::fmt::Display) -> Failure {
    Failure::usage(format!("{spec}: {e}"))
}

fn parse_u32(spec: &str, s: &str) -> Result<u32, Failure> {
    s.parse()
        .map_err(|_| Failure::usage(format!("{spec}: {s:?} is not a count")))
}

/// Whether `spec` names a generated map rather than a file.
pub(crate) fn is_generated(spec: &str) -> bool {
    ["rooms:", "office:", "family:"]
        .iter()
        .any(|p| spec.starts_with(p))
        && !Path::new(spec).exists()
}

/// `map`, read from `path`, in metres by `units` (`auto` guesses), the
/// units used, and for a longitude/latitude map the frame.
pub(crate) fn in_metres(
    path: &str,
    map: Map,
    units: &str,
) -> Result<(Map, String, Option<LonLatFrame>), Failure> {
    let u = parse_units(units)?.unwrap_or_else(|| auto_units(path, &map));
    if u == Units::Metres {
        return Ok((map, units_label(u), None));
    }
    let frame = (u == Units::LonLatDegrees).then(|| LonLatFrame::of(&map));
    let metres = to_metres(&map, u).map_err(|e| {
        Failure::invalid(format!(
            "{path}: in metres ({}) the map is no longer valid: {e}",
            units_label(u)
        ))
    })?;
    Ok((metres, units_label(u), frame))
}

pub(crate) fn load_map(spec: &str, units: &str) -> Result<EvalMap, Failure> {
    if is_generated(spec) {
        generate(spec)
    } else {
        load_file(spec, units)
    }
}

/// The generated map `spec` names (`rooms:K`, `office:K[:SEED]`,
/// `family:ID:P1,P2,…`), in metres.
pub(crate) fn generate(spec: &str) -> Result<EvalMap, Failure> {
    let generated = |kind, map: Map, rooms| EvalMap {
        name: spec.to_owned(),
        kind,
        map,
        units: "m".into(),
        rooms,
        frame: None,
    };
    if let Some(k) = spec.strip_prefix("rooms:") {
        let k = parse_u32(spec, k)?;
        if !(1..=200).contains(&k) {
            return Err(Failure::usage(format!("{spec}: between 1 and 200 rooms")));
        }
        return Ok(generated(
            "repeated rooms",
            wai_gen::repeated_rooms(k),
            Some(k as usize),
        ));
    }
    if let Some(rest) = spec.strip_prefix("office:") {
        let mut parts = rest.splitn(2, ':');
        let k = parse_u32(spec, parts.next().unwrap_or(""))?;
        let seed = parts.next().map_or(Ok(1), |s| {
            s.parse::<u64>()
                .map_err(|_| Failure::usage(format!("{spec}: {s:?} is not a seed")))
        })?;
        if !(1..=100).contains(&k) {
            return Err(Failure::usage(format!(
                "{spec}: between 1 and 100 rooms a side"
            )));
        }
        return Ok(generated("office", wai_gen::office(k, seed), None));
    }
    if let Some(rest) = spec.strip_prefix("family:") {
        let (id, params) = rest.split_once(':').unwrap_or((rest, ""));
        let params = params
            .split(',')
            .filter(|s| !s.is_empty())
            .map(|s| parse_u32(spec, s))
            .collect::<Result<Vec<_>, _>>()?;
        let map = wai_gen::family(id, &params).map_err(|e| gen_failure(spec, e))?;
        return Ok(generated("family", map, None));
    }
    Err(Failure::usage(format!(
        "{spec}: expected rooms:K, office:K[:SEED] or family:ID:P1,P2,…"
    )))
}

fn load_file(spec: &str, units: &str) -> Result<EvalMap, Failure> {
    let (path, units) = match spec.rsplit_once('@') {
        Some((p, u)) if !Path::new(spec).exists() => (p, u),
        _ => (spec, units),
    };
    let map = load(Path::new(path), Format::Auto)?.map;
    let name = map.name().map_or_else(|| path.to_owned(), str::to_owned);
    let (metres, u, frame) = in_metres(path, map, units)?;
    let kind = if path.contains("westport") {
        "westport"
    } else if path.contains("r2v") {
        "r2v"
    } else {
        "file"
    };
    Ok(EvalMap {
        name,
        kind,
        map: metres,
        units: u,
        rooms: None,
        frame,
    })
}

pub(crate) fn read_scan(path: &Path) -> Result<(Scan, Option<f64>, Option<f64>), Failure> {
    let bytes = crate::input::read_bytes(path)?;
    let shown = path.display();
    let v: Value = serde_json::from_slice(wai_map::json::strip_bom(&bytes))
        .map_err(|e| Failure::invalid(format!("{shown}: not JSON: {e}")))?;
    let numbers = |key: &str| -> Result<Vec<Option<f64>>, Failure> {
        v.get(key)
            .and_then(Value::as_array)
            .ok_or_else(|| Failure::invalid(format!("{shown}: no array {key:?}")))?
            .iter()
            .enumerate()
            .map(|(i, x)| match x {
                Value::Null => Ok(None),
                _ => x
                    .as_f64()
                    .filter(|f| f.is_finite())
                    .map(Some)
                    .ok_or_else(|| {
                        Failure::invalid(format!("{shown}: {key}[{i}] is not a finite number"))
                    }),
            })
            .collect()
    };
    let angles = numbers("angles")?;
    let ranges = numbers("ranges")?;
    if angles.len() != ranges.len() || angles.is_empty() {
        return Err(Failure::invalid(format!(
            "{shown}: {} angles and {} ranges: expected as many, at least one",
            angles.len(),
            ranges.len()
        )));
    }
    let angles = angles
        .into_iter()
        .enumerate()
        .map(|(i, a)| a.ok_or_else(|| Failure::invalid(format!("{shown}: angles[{i}] is null"))))
        .collect::<Result<Vec<_>, _>>()?;
    if let Some((i, r)) = ranges
        .iter()
        .enumerate()
        .find(|(_, r)| r.is_some_and(|r| r < 0.0))
    {
        return Err(Failure::invalid(format!(
            "{shown}: ranges[{i}] = {} is negative",
            r.unwrap_or_default()
        )));
    }
    let max_range = v
        .pointer("/sensor/max_range")
        .and_then(Value::as_f64)
        .filter(|r| r.is_finite() && *r > 0.0);
    let heading = match v.pointer("/pose/heading_degrees") {
        None | Some(Value::Null) => None,
        Some(h) => Some(h.as_f64().filter(|h| h.is_finite()).ok_or_else(|| {
            Failure::invalid(format!(
                "{shown}: pose.heading_degrees = {h} is not a finite number"
            ))
        })?),
    }
    .map(f64::to_radians);
    Ok((Scan { angles, ranges }, max_range, heading))
}

pub(crate) fn pose_json(p: &Pose) -> Value {
    json!({ "x": p.x, "y": p.y, "heading_degrees": p.heading.to_degrees() })
}

pub(crate) fn parse_near(text: &str) -> Result<wai_scan::Near, Failure> {
    let v: Vec<f64> = text
        .split(',')
        .map(|s| s.trim().parse::<f64>())
        .collect::<Result<_, _>>()
        .map_err(|_| Failure::usage(format!("--near {text:?}: expected X,Y,R")))?;
    match v[..] {
        [x, y, r] if x.is_finite() && y.is_finite() && r.is_finite() && r > 0.0 => {
            Ok(wai_scan::Near {
                at: (x, y),
                radius: r,
            })
        }
        _ => Err(Failure::usage(format!(
            "--near {text:?}: expected X,Y,R with R > 0"
        ))),
    }
}
