//! Integration tests of wai-map: one binary, one module per concern.

mod datasets;
mod errors;
mod geojson;
mod holes;
mod normalise;
mod numbers;
mod roundtrip;
mod sweep;

use wai_exact::Point;

/// Integer points from pairs.
pub fn ring(pts: &[(i128, i128)]) -> Vec<Point> {
    pts.iter().map(|&(x, y)| Point::new(x, y)).collect()
}
