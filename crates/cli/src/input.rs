//! Reading maps from files or standard input, in either format.

use crate::Failure;
use std::io::Read;
use std::path::Path;
use wai_map::geojson::from_geojson_with;
use wai_map::json::{from_json_with, ReadOptions};
use wai_map::{Loaded, MapError};

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

/// How a map file is read.
#[derive(clap::Args, Clone, Copy, Debug, Default)]
pub struct FormatArg {
    /// Input format.
    #[arg(long, value_enum, default_value_t = Format::Auto)]
    pub format: Format,
    /// Round every coordinate to the nearest multiple of 2^-BITS before
    /// reading it exactly (for sources whose exact values need more than 100
    /// bits over their common denominator, such as a stray subnormal double;
    /// how many coordinates moved, and how far, is printed).
    #[arg(long, value_name = "BITS", value_parser = clap::value_parser!(u32).range(0..=i64::from(wai_map::json::MAX_GRID_BITS)))]
    pub grid: Option<u32>,
}

impl From<Format> for FormatArg {
    fn from(format: Format) -> FormatArg {
        FormatArg { format, grid: None }
    }
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

/// Read and validate a map without holes, printing normalisation notes on
/// stderr; or build the generated map `path` names (`rooms:K`,
/// `office:K[:SEED]`, `family:ID:P1,…`, when no file has that name). A map
/// with holes is refused: the stages of the thesis's chapters 3–5 assume
/// none.
pub fn load(path: &Path, read: impl Into<FormatArg>) -> Result<Loaded, Failure> {
    let loaded = load_with_holes(path, read)?;
    refuse_holes(path, &loaded)?;
    Ok(loaded)
}

/// [`load`] for the commands that read maps with holes.
pub fn load_with_holes(path: &Path, read: impl Into<FormatArg>) -> Result<Loaded, Failure> {
    if let Some(map) = generated(path)? {
        return Ok(Loaded {
            map,
            normalisation: Default::default(),
        });
    }
    read_map(path, &read_bytes(path)?, &read.into())
}

fn refuse_holes(path: &Path, loaded: &Loaded) -> Result<(), Failure> {
    loaded
        .map
        .require_no_holes("this command")
        .map_err(|e| {
            Failure::invalid(format!(
                "{}: {e} (the thesis's chapters 3–5 assume a map without holes; `wai info`, `render`, `vis`, `decompose`, `embeddings`, `preprocess`, `localize`, `scan`, `localize-scan`, `eval` and `check --files` or `--replay` read maps with holes)",
                path.display()
            ))
        })
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

/// [`load_with_holes`] for bytes already read from `path` (named in messages).
pub fn load_bytes(
    path: &Path,
    bytes: &[u8],
    read: impl Into<FormatArg>,
) -> Result<Loaded, Failure> {
    read_map(path, bytes, &read.into())
}

/// Parse, validate and normalise a map file's bytes, holes and all.
fn read_map(path: &Path, bytes: &[u8], read: &FormatArg) -> Result<Loaded, Failure> {
    let options = ReadOptions {
        grid_bits: read.grid,
    };
    let format = read.format;
    let geo = match format {
        Format::Auto => looks_like_geojson(bytes),
        Format::Json => false,
        Format::Geojson => true,
    };
    let parsed = if geo {
        from_geojson_with(bytes, &options)
    } else {
        from_json_with(bytes, &options)
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
    if !norm.reversed_holes.is_empty() {
        let list: Vec<String> = norm.reversed_holes.iter().map(usize::to_string).collect();
        eprintln!(
            "note: {shown}: hole(s) {} were counter-clockwise; reversed to clockwise (first vertex kept)",
            list.join(", ")
        );
    }
    if !norm.removed_collinear_holes.is_empty() {
        let list: Vec<String> = norm
            .removed_collinear_holes
            .iter()
            .map(|(h, i)| format!("hole {h} position {i}"))
            .collect();
        eprintln!(
            "note: {shown}: removed {} hole vertex(es) with a straight (180°) angle, at {} (Alg 3.14 step 1)",
            list.len(),
            list.join(", ")
        );
    }
    if let Some(r) = &norm.rounded {
        eprintln!(
            "note: {shown}: rounded to multiples of 2^-{}: {} coordinate(s) moved, the largest by {} (about {:.3e})",
            r.bits,
            r.moved,
            wai_map::format_exact(&r.largest),
            r.largest.to_f64()
        );
    }
}
