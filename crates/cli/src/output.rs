//! What several subcommands share to write their results: files (their
//! folders made), standard output, and exact numbers in the map's units.

use std::path::Path;

use rug::{Integer, Rational};
use wai_map::{format_exact, Map};

use crate::failure::Failure;

/// Writes `text` to `path`, making its folder first.
pub fn write_file(path: &Path, text: &str) -> Result<(), Failure> {
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir).map_err(|e| Failure::io(format!("{}: {e}", dir.display())))?;
    }
    std::fs::write(path, text).map_err(|e| Failure::io(format!("{}: {e}", path.display())))
}

/// Writes `text` to `out`, or to standard output.
pub fn output(out: Option<&Path>, text: &str) -> Result<(), Failure> {
    match out {
        Some(path) => write_file(path, text),
        None => {
            out!("{text}");
            Ok(())
        }
    }
}

/// A coordinate of the map's integer frame in the map's input units.
pub fn unit(map: &Map, c: i128) -> String {
    format_exact(&Rational::from((Integer::from(c), map.scale().clone())))
}
