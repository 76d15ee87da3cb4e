//! Arbitrary bytes as a CARMEN laser log (plain or gzip).
//!
//! Laws: the reader never panics; every scan it returns has one angle per
//! range, and reads as the localizer's scan without panicking, its lost
//! beams exactly those at or above the no-return reading.
#![no_main]

use libfuzzer_sys::fuzz_target;
use wai_scan::carmen::read;

fuzz_target!(|bytes: &[u8]| {
    let Ok(log) = read(bytes) else {
        return;
    };
    for (k, s) in log.scans.iter().enumerate() {
        assert_eq!(s.angles.len(), s.ranges.len());
        let scan = log.scan(k);
        let cut = log.no_return_at(s);
        for (r, got) in s.ranges.iter().zip(&scan.ranges) {
            assert_eq!(got.is_none(), cut.is_some_and(|c| *r >= c));
        }
    }
});
