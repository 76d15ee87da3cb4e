//! Tests of wai-render: the pictures are well-formed and say what they show.
#![allow(
    clippy::float_arithmetic,
    reason = "pixel sizes read back from the pictures (output only)"
)]

use std::collections::BTreeSet;
use wai_exact::Point;
use wai_exact::RatPoint;
use wai_map::Map;
use wai_render::{class_colours, map_svg, visibility_svg, MapStyle, MapUnits};

/// The texts of the legend's entries.
fn legend_entries(svg: &str) -> Vec<String> {
    wai_render::legend_texts(svg)
}

/// The scale bar's label ("5 map units", "20 m").
fn scale_bar(svg: &str) -> Option<String> {
    let g = &svg[svg.find(r#"<g class="scale-bar">"#)?..];
    let g = &g[..g.find("</g>")?];
    let t = &g[g.find("<text")?..];
    let t = &t[t.find('>')? + 1..];
    Some(t[..t.find("</text>")?].to_string())
}

/// The width and height of an SVG document and of its first polygon's
/// bounding box.
fn sizes(svg: &str) -> ((f64, f64), (f64, f64)) {
    let attr = |s: &str, name: &str| -> f64 {
        let i = s.find(&format!(" {name}=\"")).unwrap() + name.len() + 3;
        s[i..i + s[i..].find('"').unwrap()].parse().unwrap()
    };
    let i = svg.find("points=\"").unwrap() + 8;
    let pts: Vec<(f64, f64)> = svg[i..i + svg[i..].find('"').unwrap()]
        .split(' ')
        .map(|p| {
            let (x, y) = p.split_once(',').unwrap();
            (x.parse().unwrap(), y.parse().unwrap())
        })
        .collect();
    let span = |f: fn(&(f64, f64)) -> f64| {
        let v: Vec<f64> = pts.iter().map(f).collect();
        v.iter().cloned().fold(f64::MIN, f64::max) - v.iter().cloned().fold(f64::MAX, f64::min)
    };
    (
        (attr(svg, "width"), attr(svg, "height")),
        (span(|p| p.0), span(|p| p.1)),
    )
}

fn l_shape() -> Map {
    let ring = [(0, 0), (4, 0), (4, 2), (2, 2), (2, 4), (0, 4)].map(|(x, y)| Point::new(x, y));
    Map::from_ring(ring.to_vec())
        .unwrap()
        .0
        .with_name("L <room>")
}

#[test]
fn map_picture_marks_reflex_vertices() {
    let svg = map_svg(
        &l_shape(),
        &MapStyle {
            vertex_labels: true,
            ..MapStyle::default()
        },
    );
    assert!(svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"));
    assert_eq!(svg.matches("</circle>").count(), 6); // the legend's dots have no tooltip
    assert_eq!(svg.matches("(reflex)").count(), 1);
    assert!(svg.contains("vertex 3 (2, 2) (reflex)"));
    assert!(svg.contains("L &lt;room&gt;: n = 6, r = 1"));
    // Six labels, the caption, the scale bar's text, and the legend's
    // title, four entries and the vertex index's sample.
    assert_eq!(svg.matches("<text").count(), 14, "{svg}");
    for entry in [
        "map (walls and inside)",
        "convex vertex (5)",
        "reflex vertex (1)",
        "vertex index",
    ] {
        assert!(
            legend_entries(&svg).iter().any(|e| e.ends_with(entry)),
            "{entry}: {svg}"
        );
    }
}

#[test]
fn scaled_maps_show_input_units() {
    let ring = [(0, 0), (3, 0), (0, 3)].map(|(x, y)| Point::new(x, y));
    let (map, _) = Map::from_scaled_ring(ring.to_vec(), 2.into()).unwrap();
    let svg = map_svg(&map, &MapStyle::default());
    assert!(svg.contains("vertex 1 (1.5, 0)"), "{svg}");
    assert!(svg.contains("units of 1/2"));
}

#[test]
fn map_pictures_have_a_scale_bar_in_map_units() {
    // 4 units over 800 px: a fifth of the drawing is 0.8 units, the bar 0.5.
    let svg = map_svg(&l_shape(), &MapStyle::default());
    assert_eq!(scale_bar(&svg).as_deref(), Some("0.5 map units"), "{svg}");
    let metres = map_svg(
        &l_shape(),
        &MapStyle {
            units: Some(MapUnits::Metres),
            ..MapStyle::default()
        },
    );
    assert_eq!(scale_bar(&metres).as_deref(), Some("0.5 m"));
    // A big map: 3000 units, a fifth is 600, the bar 500.
    let ring = [(0, 0), (3000, 0), (0, 2000)].map(|(x, y)| Point::new(x, y));
    let big = Map::from_ring(ring.to_vec()).unwrap().0;
    let svg = map_svg(&big, &MapStyle::default());
    assert_eq!(scale_bar(&svg).as_deref(), Some("500 map units"));
}

/// A square of 0.001° × 0.001° at latitude 60° N, in degrees.
fn lonlat_square() -> Map {
    let ring = [(0, 60_000), (1, 60_000), (1, 60_001), (0, 60_001)]
        .map(|(x, y)| Point::new(x + 10_000, y));
    Map::from_scaled_ring(ring.to_vec(), 1000.into())
        .unwrap()
        .0
        .with_name("square in degrees")
}

#[test]
fn lonlat_maps_are_drawn_projected_with_the_scale_bar_in_metres() {
    let map = lonlat_square();
    assert_eq!(MapUnits::guess(&map), MapUnits::LonLat);
    assert_eq!(MapUnits::guess(&l_shape()), MapUnits::Plain);
    let svg = map_svg(&map, &MapStyle::default());
    // cos 60° = 1/2: the square is drawn half as wide as high.
    let (_, (w, h)) = sizes(&svg);
    assert!((w / h - 0.5).abs() < 0.01, "{w} × {h}");
    // 0.001° of latitude is 111 m over 800 px; the drawing is 400 px
    // wide, a fifth of it 11 m, the bar 10 m.
    assert_eq!(scale_bar(&svg).as_deref(), Some("10 m"), "{svg}");
    assert!(svg.contains("equirectangular"));
    // Unprojected, when told the units are plain.
    let plain = map_svg(
        &map,
        &MapStyle {
            units: Some(MapUnits::Plain),
            ..MapStyle::default()
        },
    );
    let (_, (w, h)) = sizes(&plain);
    assert!((w / h - 1.0).abs() < 0.01, "{w} × {h}");
    assert_eq!(scale_bar(&plain).as_deref(), Some("0.0002 map units"));
}

#[test]
fn the_legend_lies_outside_the_drawing_and_inside_the_picture() {
    let svg = map_svg(&l_shape(), &MapStyle::default());
    let ((w, _), _) = sizes(&svg);
    let i = svg.find(r#"<g class="legend""#).unwrap();
    let rect = &svg[i..];
    let x: f64 = {
        let j = rect.find(r#"<rect x=""#).unwrap() + 9;
        rect[j..j + rect[j..].find('"').unwrap()].parse().unwrap()
    };
    let lw: f64 = {
        let j = rect.find(r#"width=""#).unwrap() + 7;
        rect[j..j + rect[j..].find('"').unwrap()].parse().unwrap()
    };
    // The drawing is 800 px wide with margins of 40.
    assert!(x >= 880.0 && x + lw <= w, "{x} + {lw} against {w}");
}

#[test]
fn visibility_pictures_name_every_kind_of_mark() {
    use wai_visibility::{Skeleton, VisibilityIndex};
    let map = l_shape();
    let p = RatPoint::from_rationals(rug::Rational::from(3), rug::Rational::from((1, 2)));
    let vp = VisibilityIndex::new(&map).visibility_polygon(&p).unwrap();
    let sk = Skeleton::of(&map, &vp).unwrap();
    let svg = visibility_svg(&map, &vp, Some(&sk), &MapStyle::default());
    let entries = legend_entries(&svg);
    for needle in [
        "map (walls and inside)",
        "visibility polygon V_p",
        "full edge of V_p",
        "spurious edge of V_p",
        "vertex of V_p",
        "artificial edge of the skeleton",
        "label line",
        "skeleton origin v0",
        "viewpoint p",
    ] {
        assert!(
            entries.iter().any(|e| e.contains(needle)),
            "{needle}: {entries:?}"
        );
    }
    assert_eq!(scale_bar(&svg).as_deref(), Some("0.5 map units"));
}

#[test]
fn adjacent_classes_get_different_colours() {
    // A path of 500 classes, a clique of 12 and a star of 60: every edge
    // joins two colours that differ.
    let mut adjacent = BTreeSet::new();
    for k in 0..499 {
        adjacent.insert((k, k + 1));
    }
    for a in 500..512 {
        for b in a + 1..512 {
            adjacent.insert((a, b));
        }
    }
    for b in 513..573 {
        adjacent.insert((512, b));
    }
    let colours = class_colours(573, &adjacent);
    for &(a, b) in &adjacent {
        assert_ne!(colours[a], colours[b], "classes {a} and {b}");
    }
    // Many colours are used, not two alternating.
    let distinct: BTreeSet<&String> = colours.iter().collect();
    assert!(distinct.len() >= 20, "{}", distinct.len());
    // Deterministic.
    assert_eq!(colours, class_colours(573, &adjacent));
}
