//! Bytes → a random map with holes (`wai_fuzz::holed_map_of`) → every
//! claim checker (through `wai_hunt::run`).
//!
//! Law: no checker panics, and a checker that walks one ring examines
//! nothing (`wai_fuzz::check_holes`). The claims' own violations on maps
//! with holes are findings, not failures: the thesis assumes no holes.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| wai_fuzz::check_holes(data));
