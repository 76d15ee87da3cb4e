//! GeoJSON import (RFC 7946): one Polygon, its interior rings the map's
//! holes.
//!
//! Accepted: a `Polygon` geometry, a `MultiPolygon` of one polygon, a
//! `Feature` with such a geometry, or a `FeatureCollection` with exactly one
//! feature. Numbers are read exactly from their text (no exponents). The
//! closing position of the ring is dropped; a third coordinate (altitude) is
//! ignored. Interior rings are holes, in their order. The feature's `properties.name`, if a string, names the map.

use crate::error::{MapError, MapErrors};
use crate::json::{build, collect_rings, parse_value, read_ring, structure, ReadOptions};
use crate::polygon::Loaded;
use serde_json::{Map as Object, Value};

/// Read a GeoJSON Polygon as a map.
pub fn from_geojson(bytes: &[u8]) -> Result<Loaded, MapErrors> {
    from_geojson_with(bytes, &ReadOptions::default())
}

/// [`from_geojson`] with [`ReadOptions`].
pub fn from_geojson_with(bytes: &[u8], options: &ReadOptions) -> Result<Loaded, MapErrors> {
    let root = parse_value(bytes)?;
    let (polygon, path, name) = find_polygon(&root, "$", None)?;
    let Value::Array(rings) = polygon else {
        return Err(structure(&path, "expected the Polygon's array of rings").into());
    };
    if rings.is_empty() {
        return Err(structure(&path, "the Polygon has no ring").into());
    }
    let read = rings
        .iter()
        .enumerate()
        .map(|(k, ring)| {
            let mut coords = read_ring(ring, &format!("{path}[{k}]"), true)?;
            // RFC 7946 rings repeat their first position at the end.
            if coords.len() >= 4 {
                let m = coords.len();
                if coords[0].value == coords[m - 2].value && coords[1].value == coords[m - 1].value
                {
                    coords.truncate(m - 2);
                }
            }
            Ok(coords)
        })
        .collect();
    let rings = collect_rings(read)?;
    build(rings, name, Some("GeoJSON".to_string()), options)
}

fn kind<'a>(obj: &'a Object<String, Value>, path: &str) -> Result<&'a str, MapError> {
    obj.get("type")
        .and_then(Value::as_str)
        .ok_or_else(|| structure(path, "expected a GeoJSON object with a \"type\""))
}

fn find_polygon<'a>(
    v: &'a Value,
    path: &str,
    name: Option<String>,
) -> Result<(&'a Value, String, Option<String>), MapError> {
    let Value::Object(obj) = v else {
        return Err(structure(path, "expected a GeoJSON object"));
    };
    let member = |key: &str| {
        obj.get(key)
            .ok_or_else(|| structure(path, &format!("missing member \"{key}\"")))
    };
    match kind(obj, path)? {
        "Polygon" => Ok((member("coordinates")?, format!("{path}.coordinates"), name)),
        "MultiPolygon" => match member("coordinates")? {
            Value::Array(polys) if polys.len() == 1 => {
                Ok((&polys[0], format!("{path}.coordinates[0]"), name))
            }
            Value::Array(polys) => Err(structure(
                path,
                &format!(
                    "expected one polygon, found a MultiPolygon of {}",
                    polys.len()
                ),
            )),
            _ => Err(structure(path, "expected an array of polygons")),
        },
        "Feature" => {
            let name = obj
                .get("properties")
                .and_then(|p| p.get("name"))
                .and_then(Value::as_str)
                .map(str::to_string)
                .or(name);
            find_polygon(member("geometry")?, &format!("{path}.geometry"), name)
        }
        "FeatureCollection" => match member("features")? {
            Value::Array(fs) if fs.len() == 1 => {
                find_polygon(&fs[0], &format!("{path}.features[0]"), name)
            }
            Value::Array(fs) => Err(structure(
                path,
                &format!("expected exactly one feature, found {}", fs.len()),
            )),
            _ => Err(structure(path, "expected an array of features")),
        },
        other => Err(structure(
            path,
            &format!("expected a Polygon, found GeoJSON type {other:?}"),
        )),
    }
}
