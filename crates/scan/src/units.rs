//! Maps in metres, so that one σ, one range limit and one success radius
//! mean the same on every map of an evaluation.
//!
//! The result is an exact map again: each vertex rounded to the
//! millimetre (scale 1000), then validated like any input — a rounding
//! that made the ring degenerate is refused, not repaired.

use rug::{Integer, Rational};
use wai_exact::Point;
use wai_map::{Map, MapErrors};

/// How a map's input units become metres.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Units {
    /// Already metres.
    Metres,
    /// Multiply by this many metres per unit (e.g. image pixels).
    Scale(f64),
    /// Longitude, latitude in degrees (WGS 84): a local equirectangular
    /// projection about the map's south-west corner, exact to well under a
    /// millimetre over a building.
    LonLatDegrees,
}

/// The mean Earth radius (IUGG), metres.
const EARTH_RADIUS: f64 = 6_371_008.8;

/// `map` in metres, vertices rounded to the millimetre.
pub fn to_metres(map: &Map, units: Units) -> Result<Map, MapErrors> {
    let pts: Vec<(f64, f64)> = map
        .vertices()
        .iter()
        .map(|p| {
            (
                Rational::from((Integer::from(p.x), map.scale().clone())).to_f64(),
                Rational::from((Integer::from(p.y), map.scale().clone())).to_f64(),
            )
        })
        .collect();
    let metres: Vec<(f64, f64)> = match units {
        Units::Metres => pts,
        Units::Scale(k) => pts.iter().map(|&(x, y)| (x * k, y * k)).collect(),
        Units::LonLatDegrees => {
            let lon0 = pts.iter().map(|p| p.0).fold(f64::INFINITY, f64::min);
            let lat0 = pts.iter().map(|p| p.1).fold(f64::INFINITY, f64::min);
            let k = EARTH_RADIUS * std::f64::consts::PI / 180.0;
            let kx = k * lat0.to_radians().cos();
            pts.iter()
                .map(|&(lon, lat)| ((lon - lon0) * kx, (lat - lat0) * k))
                .collect()
        }
    };
    let ring: Vec<Point> = metres
        .iter()
        .map(|&(x, y)| Point::new((x * 1000.0).round() as i128, (y * 1000.0).round() as i128))
        .collect();
    let (m, _) = Map::from_scaled_ring(ring, Integer::from(1000))?;
    let m = match map.name() {
        Some(name) => m.with_name(name),
        None => m,
    };
    Ok(match map.source() {
        Some(s) => m.with_source(s),
        None => m,
    })
}
