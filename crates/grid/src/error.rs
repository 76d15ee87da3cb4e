//! What can be wrong with an occupancy grid, with where.

use std::path::PathBuf;

/// Everything [`crate::import`] refuses, each naming the file, line or
/// field at fault.
#[derive(Debug, thiserror::Error)]
pub enum GridError {
    #[error("{path}: {error}")]
    Io {
        path: PathBuf,
        error: std::io::Error,
    },
    #[error("{path}: line {line}: {message}")]
    Yaml {
        path: PathBuf,
        line: usize,
        message: String,
    },
    #[error("{path}: missing field {field:?} ({what})")]
    MissingField {
        path: PathBuf,
        field: &'static str,
        what: &'static str,
    },
    #[error("{path}: {field}: {message}")]
    BadField {
        path: PathBuf,
        field: &'static str,
        message: String,
    },
    #[error("{path}: not a PGM image we read: {message}")]
    Image { path: PathBuf, message: String },
    #[error(
        "{path}: {width} × {height} = {cells} cells, above the limit of {max} (about {bytes_per_cell} bytes each while tracing); raise it with --max-cells if the machine has the memory"
    )]
    TooLarge {
        path: PathBuf,
        width: u64,
        height: u64,
        cells: u64,
        max: u64,
        bytes_per_cell: u64,
    },
    #[error("no free cell: with these thresholds every cell is occupied or unknown")]
    NoFreeCell,
    #[error("the point ({x}, {y}) {reason}")]
    StartNotFree {
        x: String,
        y: String,
        reason: String,
    },
    #[error("the traced map is not valid: {0}")]
    Map(wai_map::MapErrors),
}
