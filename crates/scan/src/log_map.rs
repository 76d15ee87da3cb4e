//! A map built from a laser log: the scans' rays into an occupancy grid,
//! then traced into an exact map with holes ([`wai_grid`]).
//!
//! Each return marks the cell of its end point hit and the cells the ray
//! crosses before it passed (sampled every half cell); a beam without
//! return marks nothing (where its wall is, is unknown). A cell's
//! occupancy is hits / (hits + passes); its pixel is written as `map_saver`
//! would, `255 · (1 − occupancy)`, and never-observed cells are unknown
//! (205). The grid then goes the way of any `map_server` grid: free below
//! the free threshold, traced along cell edges.

use crate::carmen::CarmenLog;
use rug::Rational;
use wai_grid::meta::{GridMeta, Mode};
use wai_grid::pgm::Image;

/// The pixel value of a cell never observed (as `map_saver` writes it).
pub const UNKNOWN: u16 = 205;

/// How to rasterise a log.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct GridOptions {
    /// Metres per cell, exact (the grid's `resolution`).
    pub resolution: Rational,
    /// Cells of margin around everything observed.
    pub margin: usize,
}

/// The occupancy grid of `scans` (indices into `log.scans`), with
/// `map_server` metadata (standard thresholds 0.65 and 0.196).
pub fn occupancy_grid(
    log: &CarmenLog,
    scans: &[usize],
    options: &GridOptions,
) -> (GridMeta, Image) {
    let res = options.resolution.to_f64();
    // The extent: every pose and every return's end point.
    let mut points = Vec::new();
    for &k in scans {
        let s = &log.scans[k];
        let cut = log.no_return_at(s);
        points.push((s.pose[0], s.pose[1]));
        for (a, &r) in s.angles.iter().zip(&s.ranges) {
            if cut.is_some_and(|c| r >= c) {
                continue;
            }
            let t = s.pose[2] + a;
            points.push((s.pose[0] + r * t.cos(), s.pose[1] + r * t.sin()));
        }
    }
    let (mut x0, mut y0, mut x1, mut y1) = (f64::MAX, f64::MAX, f64::MIN, f64::MIN);
    for &(x, y) in &points {
        x0 = x0.min(x);
        y0 = y0.min(y);
        x1 = x1.max(x);
        y1 = y1.max(y);
    }
    let margin = options.margin as i64;
    let c0 = (x0 / res).floor() as i64 - margin;
    let r0 = (y0 / res).floor() as i64 - margin;
    let width = ((x1 / res).floor() as i64 - c0 + 1 + margin) as usize;
    let height = ((y1 / res).floor() as i64 - r0 + 1 + margin) as usize;
    // hits and passes per cell, rows from the bottom.
    let mut hits = vec![0u32; width * height];
    let mut passes = vec![0u32; width * height];
    let cell = |x: f64, y: f64| -> Option<usize> {
        let c = (x / res).floor() as i64 - c0;
        let r = (y / res).floor() as i64 - r0;
        ((0..width as i64).contains(&c) && (0..height as i64).contains(&r))
            .then(|| r as usize * width + c as usize)
    };
    for &k in scans {
        let s = &log.scans[k];
        let cut = log.no_return_at(s);
        let (px, py) = (s.pose[0], s.pose[1]);
        for (a, &r) in s.angles.iter().zip(&s.ranges) {
            if cut.is_some_and(|c| r >= c) {
                continue;
            }
            let t = s.pose[2] + a;
            let (dx, dy) = (t.cos(), t.sin());
            let end = cell(px + r * dx, py + r * dy);
            let steps = (2.0 * r / res).ceil() as usize;
            let mut last = None;
            for i in 0..steps {
                let d = i as f64 * res / 2.0;
                let here = cell(px + d * dx, py + d * dy);
                if here != last && here != end {
                    if let Some(h) = here {
                        passes[h] += 1;
                    }
                }
                last = here;
            }
            if let Some(e) = end {
                hits[e] += 1;
            }
        }
    }
    // Pixels, row 0 at the top.
    let mut pixels = Vec::with_capacity(width * height);
    for r in (0..height).rev() {
        for c in 0..width {
            let (h, p) = (hits[r * width + c], passes[r * width + c]);
            pixels.push(if h + p == 0 {
                UNKNOWN
            } else {
                (255.0 * f64::from(p) / f64::from(h + p)).floor() as u16
            });
        }
    }
    let q = |s: &str| wai_map::parse_exact(s).expect("a constant");
    let meta = GridMeta {
        image: String::new(),
        resolution: options.resolution.clone(),
        origin: [
            Rational::from(&options.resolution * rug::Integer::from(c0)),
            Rational::from(&options.resolution * rug::Integer::from(r0)),
        ],
        occupied_thresh: q("0.65"),
        free_thresh: q("0.196"),
        negate: false,
        mode: Mode::Trinary,
    };
    (
        meta,
        Image {
            width,
            height,
            maxval: 255,
            pixels,
        },
    )
}

/// The YAML text of `meta` for an image file `image` (a `map_server` pair).
pub fn yaml(meta: &GridMeta, image: &str) -> String {
    let f = wai_map::format_exact;
    format!(
        "image: {image}\nresolution: {}\norigin: [{}, {}, 0]\nnegate: 0\noccupied_thresh: {}\nfree_thresh: {}\nmode: trinary\n",
        f(&meta.resolution),
        f(&meta.origin[0]),
        f(&meta.origin[1]),
        f(&meta.occupied_thresh),
        f(&meta.free_thresh),
    )
}
