//! Tests of wai-render: the pictures are well-formed and say what they show.

use wai_exact::Point;
use wai_map::Map;
use wai_render::{map_svg, MapStyle};

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
    assert_eq!(svg.matches("<circle").count(), 6);
    assert_eq!(svg.matches("(reflex)").count(), 1);
    assert!(svg.contains("vertex 3 (2, 2) (reflex)"));
    assert!(svg.contains("L &lt;room&gt;: n = 6, r = 1"));
    assert_eq!(svg.matches("<text").count(), 7); // six labels and the caption
}

#[test]
fn scaled_maps_show_input_units() {
    let ring = [(0, 0), (3, 0), (0, 3)].map(|(x, y)| Point::new(x, y));
    let (map, _) = Map::from_scaled_ring(ring.to_vec(), 2.into()).unwrap();
    let svg = map_svg(&map, &MapStyle::default());
    assert!(svg.contains("vertex 1 (1.5, 0)"), "{svg}");
    assert!(svg.contains("units of 1/2"));
}
