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

/// The metric frame a longitude/latitude map is localized in: x east and
/// y north in metres from the map's south-west corner (its least
/// longitude and least latitude), by the equirectangular projection at
/// that corner's latitude.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LonLatFrame {
    /// The origin's longitude and latitude, degrees.
    pub lon0: f64,
    pub lat0: f64,
    /// Metres per degree of longitude (at `lat0`) and of latitude.
    pub east_per_degree: f64,
    pub north_per_degree: f64,
}

impl LonLatFrame {
    /// The frame of a map whose coordinates are longitude, latitude.
    pub fn of(map: &Map) -> LonLatFrame {
        let pts = degrees(map);
        let lon0 = pts.iter().map(|p| p.0).fold(f64::INFINITY, f64::min);
        let lat0 = pts.iter().map(|p| p.1).fold(f64::INFINITY, f64::min);
        let k = EARTH_RADIUS * std::f64::consts::PI / 180.0;
        LonLatFrame {
            lon0,
            lat0,
            east_per_degree: k * lat0.to_radians().cos(),
            north_per_degree: k,
        }
    }

    /// A point of the frame (metres) as longitude, latitude.
    pub fn to_lonlat(&self, x: f64, y: f64) -> (f64, f64) {
        (
            self.lon0 + x / self.east_per_degree,
            self.lat0 + y / self.north_per_degree,
        )
    }

    /// Longitude, latitude as a point of the frame (metres).
    pub fn to_metres(&self, lon: f64, lat: f64) -> (f64, f64) {
        (
            (lon - self.lon0) * self.east_per_degree,
            (lat - self.lat0) * self.north_per_degree,
        )
    }

    /// One line saying what the frame is.
    pub fn describe(&self) -> String {
        format!(
            "x east, y north in metres from lon {:.7}, lat {:.7} (the map's south-west corner; equirectangular at that latitude)",
            self.lon0, self.lat0
        )
    }
}

/// The map's vertices in its own units, as floating point.
fn degrees(map: &Map) -> Vec<(f64, f64)> {
    map.vertices()
        .iter()
        .map(|p| {
            (
                Rational::from((Integer::from(p.x), map.scale().clone())).to_f64(),
                Rational::from((Integer::from(p.y), map.scale().clone())).to_f64(),
            )
        })
        .collect()
}

/// `map` in metres, vertices (holes' too) rounded to the millimetre; a
/// longitude, latitude map in its [`LonLatFrame`].
pub fn to_metres(map: &Map, units: Units) -> Result<Map, MapErrors> {
    let pts = degrees(map);
    let metres: Vec<(f64, f64)> = match units {
        Units::Metres => pts,
        Units::Scale(k) => pts.iter().map(|&(x, y)| (x * k, y * k)).collect(),
        Units::LonLatDegrees => {
            let frame = LonLatFrame::of(map);
            pts.iter()
                .map(|&(lon, lat)| frame.to_metres(lon, lat))
                .collect()
        }
    };
    let mut points = metres
        .iter()
        .map(|&(x, y)| Point::new((x * 1000.0).round() as i128, (y * 1000.0).round() as i128));
    // Every ring, holes included, in the map's order.
    let mut rings: Vec<Vec<Point>> = (0..=map.hole_count())
        .map(|k| points.by_ref().take(map.ring(k).len()).collect())
        .collect();
    let outer = rings.remove(0);
    let (m, _) = Map::from_scaled_rings(outer, rings, Integer::from(1000))?;
    let m = m.with_units(wai_map::Units::Metres);
    let m = match map.name() {
        Some(name) => m.with_name(name),
        None => m,
    };
    Ok(match map.source() {
        Some(s) => m.with_source(s),
        None => m,
    })
}
