//! Arbitrary bytes as an occupancy grid: the first byte says how many of
//! the rest are the YAML file, the others are the image.
//!
//! Laws: neither reader panics, nor does tracing a grid they accept; a
//! traced map's free space is exactly its region's cells (area = cells ×
//! resolution², without simplification), and it has one hole per enclosed
//! obstacle left.
#![no_main]

use libfuzzer_sys::fuzz_target;
use rug::{Integer, Rational};
use std::path::Path;
use wai_grid::{import_parts, meta, pgm, ImportOptions};

fuzz_target!(|bytes: &[u8]| {
    let Some((&k, rest)) = bytes.split_first() else {
        return;
    };
    let (yaml, image) = rest.split_at((k as usize).min(rest.len()));
    let Ok(meta) = meta::parse(Path::new("fuzz.yaml"), &String::from_utf8_lossy(yaml)) else {
        return;
    };
    let Ok(header) = pgm::header(image) else {
        return;
    };
    if header.width.saturating_mul(header.height) > 4096 {
        return;
    }
    let Ok(image) = pgm::pixels(image, &header) else {
        return;
    };
    let options = ImportOptions {
        min_hole_area: Rational::from(k % 4) * &meta.resolution * &meta.resolution,
        ..ImportOptions::default()
    };
    let Ok((map, report)) = import_parts(&meta, &image, &options) else {
        return;
    };
    let area = Rational::from((
        map.area_twice(),
        Integer::from(map.scale() * map.scale()) * 2u32,
    ));
    let cells = Rational::from(report.region.region_cells) * &meta.resolution * &meta.resolution;
    assert_eq!(area, cells, "the traced map is not the region");
    assert_eq!(map.hole_count() as u64, report.region.holes);
});
