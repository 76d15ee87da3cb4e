use wai_map::geojson::from_geojson;
use wai_map::MapError;

#[test]
fn polygon_feature_and_collection() {
    let poly = r#"{"type": "Polygon", "coordinates": [[[0, 0], [4, 0], [4, 3], [0, 3], [0, 0]]]}"#;
    let feature =
        format!(r#"{{"type": "Feature", "properties": {{"name": "hall"}}, "geometry": {poly}}}"#);
    let coll = format!(r#"{{"type": "FeatureCollection", "features": [{feature}]}}"#);
    for text in [poly.to_string(), feature.clone(), coll] {
        let l = from_geojson(text.as_bytes()).unwrap();
        assert_eq!(l.map.n(), 4);
        assert!(l.normalisation.is_identity());
    }
    assert_eq!(
        from_geojson(feature.as_bytes()).unwrap().map.name(),
        Some("hall")
    );
}

#[test]
fn lon_lat_decimals_are_exact_and_clockwise_is_normalised() {
    let text = r#"{"type": "Polygon", "coordinates": [[[-2.978015585426666, 56.460347539964033, 12],
        [-2.978015585426666, 56.46040], [-2.97790, 56.46040], [-2.978015585426666, 56.460347539964033, 12]]]}"#;
    let l = from_geojson(text.as_bytes()).unwrap();
    assert!(l.normalisation.reversed);
    assert_eq!(l.map.n(), 3);
    assert_eq!(
        *l.map.scale(),
        rug::Integer::from(rug::Integer::u_pow_u(10, 15))
    );
}

#[test]
fn interior_rings_are_holes_and_other_geometries_are_clear_errors() {
    let holes = r#"{"type": "Polygon", "coordinates": [[[0,0],[9,0],[0,9],[0,0]], [[1,1],[2,1],[1,2],[1,1]]]}"#;
    let loaded = from_geojson(holes.as_bytes()).unwrap();
    assert_eq!(loaded.map.hole_count(), 1);
    // RFC 7946 holes are clockwise; this one is not, and is reversed.
    assert_eq!(loaded.normalisation.reversed_holes, vec![0]);
    assert_eq!(loaded.map.ring(1).len(), 3);
    let outside = r#"{"type": "Polygon", "coordinates": [[[0,0],[9,0],[0,9],[0,0]], [[8,8],[8,9],[9,8],[8,8]]]}"#;
    assert!(matches!(
        &from_geojson(outside.as_bytes()).unwrap_err().0[..],
        [MapError::HoleOutside { hole: 0, .. }]
    ));
    let line = r#"{"type": "LineString", "coordinates": [[0,0],[1,1]]}"#;
    let e = from_geojson(line.as_bytes()).unwrap_err();
    assert!(
        e.to_string()
            .contains("expected a Polygon, found GeoJSON type \"LineString\""),
        "{e}"
    );
    let two = r#"{"type": "FeatureCollection", "features": []}"#;
    assert!(from_geojson(two.as_bytes())
        .unwrap_err()
        .to_string()
        .contains("found 0"));
}
