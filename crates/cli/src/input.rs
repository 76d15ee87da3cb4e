//! Reading maps from files or standard input, in either format.

use crate::Failure;
use std::io::Read;
use std::path::Path;
use wai_map::{geojson::from_geojson, json::from_json, Loaded, MapError};

/// The input format of a map file.
#[derive(clap::ValueEnum, Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Format {
    /// GeoJSON if the file's top-level object has a "type", else the map format.
    #[default]
    Auto,
    /// The map format of data/datasets/README.md.
    Json,
    /// A GeoJSON Polygon (or a Feature or FeatureCollection holding one).
    Geojson,
}

#[derive(clap::Args, Debug)]
pub struct FormatArg {
    /// Input format.
    #[arg(long, value_enum, default_value_t = Format::Auto)]
    pub format: Format,
}

/// Files larger than this are refused before reading: no map of interest
/// comes near it, and a stray binary or log file is caught early.
const MAX_FILE_BYTES: u64 = 512 * 1024 * 1024;

pub(crate) fn read_bytes(path: &Path) -> Result<Vec<u8>, Failure> {
    let shown = path.display();
    if path == Path::new("-") {
        let mut buf = Vec::new();
        std::io::stdin()
            .take(MAX_FILE_BYTES + 1)
            .read_to_end(&mut buf)
            .map_err(|e| Failure::io(format!("standard input: {e}")))?;
        if buf.len() as u64 > MAX_FILE_BYTES {
            return Err(Failure::invalid(format!(
                "standard input: larger than {MAX_FILE_BYTES} bytes"
            )));
        }
        return Ok(buf);
    }
    let meta = std::fs::metadata(path).map_err(|e| Failure::io(format!("{shown}: {e}")))?;
    if meta.is_dir() {
        return Err(Failure::io(format!(
            "{shown}: is a directory, expected a map file"
        )));
    }
    if meta.len() > MAX_FILE_BYTES {
        return Err(Failure::invalid(format!(
            "{shown}: {} bytes is larger than the {MAX_FILE_BYTES} bytes a map file may have",
            meta.len()
        )));
    }
    std::fs::read(path).map_err(|e| Failure::io(format!("{shown}: {e}")))
}

fn looks_like_geojson(bytes: &[u8]) -> bool {
    // Cheap sniff; the chosen parser reports any real problem.
    serde_json::from_slice::<serde_json::Value>(wai_map::json::strip_bom(bytes))
        .ok()
        .and_then(|v| v.get("type").cloned())
        .is_some()
}

/// Read and validate a map, printing normalisation notes on stderr; or
/// build the generated map `path` names (`rooms:K`, `office:K[:SEED]`,
/// `family:ID:P1,…`, when no file has that name).
pub fn load(path: &Path, format: Format) -> Result<Loaded, Failure> {
    if let Some(map) = generated(path)? {
        return Ok(Loaded {
            map,
            normalisation: Default::default(),
        });
    }
    load_bytes(path, &read_bytes(path)?, format)
}

/// The generated map `path` names, if it names one rather than a file.
pub(crate) fn generated(path: &Path) -> Result<Option<wai_map::Map>, Failure> {
    match path.to_str() {
        Some(spec) if crate::scan_maps::is_generated(spec) => {
            let map = crate::scan_maps::generate(spec)?.map;
            Ok(Some(match map.name() {
                Some(_) => map,
                None => map.with_name(spec),
            }))
        }
        _ => Ok(None),
    }
}

/// The help line of a map argument.
pub(crate) const MAP_HELP: &str = "Map file (JSON map format or GeoJSON; `-` reads standard input), or a generated map: `rooms:K`, `office:K[:SEED]`, `family:ID:P1,P2,…` (in metres)";

/// [`load`] for bytes already read from `path` (named in messages).
pub fn load_bytes(path: &Path, bytes: &[u8], format: Format) -> Result<Loaded, Failure> {
    let geo = match format {
        Format::Auto => looks_like_geojson(bytes),
        Format::Json => false,
        Format::Geojson => true,
    };
    let parsed = if geo {
        from_geojson(bytes)
    } else {
        from_json(bytes)
    };
    let loaded = parsed.map_err(|errors| {
        let shown = path.display();
        let mut msg = match errors.0.as_slice() {
            [one] => format!("{shown}: {one}"),
            many => format!("{shown}: {} problems", many.len()),
        };
        if errors.0.len() > 1 {
            for e in errors.0.iter().take(20) {
                msg.push_str(&format!("\n  - {e}"));
            }
            if errors.0.len() > 20 {
                msg.push_str(&format!("\n  … and {} more", errors.0.len() - 20));
            }
        }
        if matches!(errors.first(), MapError::Syntax { .. }) && !geo && format == Format::Auto {
            msg.push_str("\n  (expected the map format of data/datasets/README.md or GeoJSON)");
        }
        Failure::invalid(msg)
    })?;
    note_normalisation(path, &loaded);
    Ok(loaded)
}

pub fn note_normalisation(path: &Path, loaded: &Loaded) {
    let norm = &loaded.normalisation;
    let shown = path.display();
    if norm.reversed {
        eprintln!("note: {shown}: the ring was clockwise; reversed to counter-clockwise (first vertex kept)");
    }
    if !norm.removed_collinear.is_empty() {
        let list: Vec<String> = norm
            .removed_collinear
            .iter()
            .map(usize::to_string)
            .collect();
        eprintln!(
            "note: {shown}: removed {} vertex(es) with a straight (180°) angle, at input positions {} (Alg 3.14 step 1)",
            list.len(),
            list.join(", ")
        );
    }
}
