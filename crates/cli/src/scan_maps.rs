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
use wai_scan::Pose;

use crate::input::{load_with_holes, Format};
use crate::Failure;

/// A map of an evaluation, in metres.
pub(crate) struct EvalMap {
    pub name: String,
    pub(crate) kind: &'static str,
    pub map: Map,
    pub(crate) units: String,
    /// What `--units auto` assumed to choose the units, if it assumed.
    pub(crate) units_assumed: Option<String>,
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

/// The units `auto` picks for `map` read from `path`, and what was assumed
/// to pick them when the file states none: the units its file states,
/// else longitude/latitude if it looks so ([`wai_map::Map::looks_lonlat`]),
/// 0.025 m per pixel for an R2V file, else metres.
fn auto_units(path: &str, map: &Map) -> (Units, Option<String>) {
    match map.units() {
        Some(wai_map::Units::Metres) => (Units::Metres, None),
        Some(wai_map::Units::LonLat) => (Units::LonLatDegrees, None),
        // Numerator over denominator: the nearest double for a decimal
        // such as 0.01 (`Rational::to_f64` rounds toward zero).
        Some(wai_map::Units::Scale(k)) => {
            (Units::Scale(k.numer().to_f64() / k.denom().to_f64()), None)
        }
        None if map.looks_lonlat() => (
            Units::LonLatDegrees,
            Some(
                "assumed: the file states no units and its coordinates look like \
                 longitude/latitude degrees"
                    .into(),
            ),
        ),
        // R2V annotations are image pixels; floor plans of flats at about
        // 40 px per metre (an assumption: the source gives no scale).
        None if path.contains("r2v") => (
            Units::Scale(0.025),
            Some(
                "assumed: an R2V plan is in pixels and states no scale; read at 0.025 m \
                 per pixel (give PATH@scale:K or --units to change it)"
                    .into(),
            ),
        ),
        None => (
            Units::Metres,
            Some("assumed: the file states no units; read as metres".into()),
        ),
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

/// A map file converted to metres.
pub(crate) struct InMetres {
    pub map: Map,
    /// The units it was read in (`m`, `lonlat`, `scale:K`).
    pub units: String,
    /// What `--units auto` assumed to choose them, when the file states none.
    pub assumed: Option<String>,
    /// For a longitude/latitude map, the metric frame.
    pub frame: Option<LonLatFrame>,
}

/// `map`, read from `path`, in metres by `units` (`auto` guesses).
pub(crate) fn in_metres(path: &str, map: Map, units: &str) -> Result<InMetres, Failure> {
    let (u, assumed) = match parse_units(units)? {
        Some(u) => (u, None),
        None => auto_units(path, &map),
    };
    if u == Units::Metres {
        return Ok(InMetres {
            map,
            units: units_label(u),
            assumed,
            frame: None,
        });
    }
    let frame = (u == Units::LonLatDegrees).then(|| LonLatFrame::of(&map));
    let metres = to_metres(&map, u).map_err(|e| {
        Failure::invalid(format!(
            "{path}: in metres ({}) the map is no longer valid: {e}",
            units_label(u)
        ))
    })?;
    Ok(InMetres {
        map: metres,
        units: units_label(u),
        assumed,
        frame,
    })
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
        units_assumed: None,
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
    let map = load_with_holes(Path::new(path), Format::Auto)?.map;
    let name = map.name().map_or_else(|| path.to_owned(), str::to_owned);
    let m = in_metres(path, map, units)?;
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
        map: m.map,
        units: m.units,
        units_assumed: m.assumed,
        rooms: None,
        frame: m.frame,
    })
}

/// The scan file at `path`, in either format ([`wai_scan::format`]).
pub(crate) fn read_scan(path: &Path) -> Result<wai_scan::format::ScanFile, Failure> {
    let bytes = crate::input::read_bytes(path)?;
    wai_scan::format::read(&bytes).map_err(|e| Failure::invalid(format!("{}: {e}", path.display())))
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
