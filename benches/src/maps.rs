//! Maps for benchmarks beyond the generators' kinds.

use wai_exact::Point;
use wai_map::Map;

/// A "banana": the region between the parabolas y = x² (below, `lower`
/// vertices, convex) and y = x² + h (above, `upper` vertices, all but the
/// two ends reflex) over one x-range — concave chains of walls as in the
/// thesis's real-world map. `banana(20, 56)` has n = 76 and r = 54, the size
/// of the thesis's ROLOPRO map (76 vertices, 54 reflex).
pub fn banana(lower: i128, upper: i128) -> Map {
    assert!(lower >= 2 && upper >= 2);
    // x spans [-l, l] with both chains on integer x: l is a multiple of
    // (lower - 1) and (upper - 1).
    let l = (lower - 1) * (upper - 1);
    let h = 4 * l * l;
    let mut ring = Vec::new();
    for i in 0..lower {
        let x = -l + 2 * l * i / (lower - 1);
        ring.push(Point::new(x, x * x));
    }
    for j in 0..upper {
        let x = l - 2 * l * j / (upper - 1);
        ring.push(Point::new(x, x * x + h));
    }
    Map::from_ring(ring)
        .expect("a banana is simple")
        .0
        .with_name(format!("banana-{lower}-{upper}"))
}

/// The maps the embed and localize benches share, as (name, parameter,
/// map): the thesis-size banana (n = 76, r = 54), a random orthogonal map
/// of the same n, and corridor-niches k = 16 (repeated identical rooms).
pub fn thesis_size() -> Vec<(&'static str, &'static str, Map)> {
    vec![
        ("banana", "n=76,r=54", banana(20, 56)),
        (
            "random-orthogonal",
            "n=76",
            wai_gen::random("random-orthogonal", 76, 1).expect("a kind"),
        ),
        (
            "corridor-niches",
            "k=16",
            wai_gen::family("corridor-niches", &[16]).expect("a family"),
        ),
    ]
}
