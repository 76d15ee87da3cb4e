//! Integration tests of wai-grid: one binary, one module per concern.

mod files;
mod meta;
mod pgm;
mod region;

use rug::Rational;
use wai_grid::meta::{GridMeta, Mode};
use wai_grid::pgm::Image;

/// Metadata of a grid at `res` metres per cell with the origin at `o`,
/// standard thresholds.
pub fn meta(res: &str, o: (&str, &str)) -> GridMeta {
    let q = |s: &str| wai_map::parse_exact(s).unwrap();
    GridMeta {
        image: "map.pgm".into(),
        resolution: q(res),
        origin: [q(o.0), q(o.1)],
        occupied_thresh: q("0.65"),
        free_thresh: q("0.196"),
        negate: false,
        mode: Mode::Trinary,
    }
}

/// An image from text rows, top first: `.` free (254), `#` occupied (0),
/// `?` unknown (205), as `map_saver` writes them.
pub fn image(rows: &[&str]) -> Image {
    let width = rows[0].len();
    let pixels = rows
        .iter()
        .flat_map(|r| {
            assert_eq!(r.len(), width);
            r.bytes().map(|b| match b {
                b'.' => 254,
                b'#' => 0,
                _ => 205,
            })
        })
        .collect();
    Image {
        width,
        height: rows.len(),
        maxval: 255,
        pixels,
    }
}

pub fn q(s: &str) -> Rational {
    wai_map::parse_exact(s).unwrap()
}
