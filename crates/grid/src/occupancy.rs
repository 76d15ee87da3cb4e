//! Which cells are free, by the ROS `map_server` rule, decided exactly.
//!
//! A pixel of value x (white = maxval) has occupancy
//! p = (maxval − x) / maxval, or x / maxval with `negate`; it is free when
//! p < `free_thresh` and occupied when p > `occupied_thresh` (`map_server`
//! compares in floating point; here the thresholds are the exact decimals
//! of the YAML file, so a pixel exactly at a threshold is never free).
//! Unknown cells (between the thresholds) are obstacles for the map: the
//! robot's free space is what it has seen free.

use crate::meta::GridMeta;
use crate::pgm::Image;
use rug::Rational;

/// Whether each possible pixel value is free, indexed by value.
pub fn free_values(meta: &GridMeta, maxval: u16) -> Vec<bool> {
    (0..=maxval)
        .map(|x| {
            let dark = if meta.negate { x } else { maxval - x };
            let p = Rational::from((u32::from(dark), u32::from(maxval)));
            p < meta.free_thresh
        })
        .collect()
}

/// The free cells, row after row from the **bottom** (row 0 is the image's
/// last), so that cell (c, r) covers `[c, c+1] × [r, r+1]` in grid units.
pub fn free_cells(meta: &GridMeta, image: &Image) -> Vec<bool> {
    let table = free_values(meta, image.maxval);
    let mut free = Vec::with_capacity(image.width * image.height);
    for r in (0..image.height).rev() {
        let row = &image.pixels[r * image.width..(r + 1) * image.width];
        free.extend(row.iter().map(|&x| table[usize::from(x)]));
    }
    free
}
