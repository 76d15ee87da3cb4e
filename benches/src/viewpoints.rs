//! Seeded interior viewpoints for benchmarks.

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::Integer;
use wai_exact::{Containment, RatPoint};
use wai_map::Map;

/// `count` distinct points strictly inside `map`, each with a denominator of
/// 1000 in map units (so most lie on no line through two vertices), drawn
/// from the bounding box with a seeded generator.
pub fn interior_viewpoints(map: &Map, count: usize, seed: u64) -> Vec<RatPoint> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let (lo, hi) = map.bounding_box();
    let mut out: Vec<RatPoint> = Vec::new();
    let mut tries = 0usize;
    while out.len() < count {
        tries += 1;
        assert!(tries < 1_000_000, "no interior points found");
        let fx: u32 = rng.random_range(1..1000);
        let fy: u32 = rng.random_range(1..1000);
        let x = Integer::from(lo.x) * 1000 + Integer::from(hi.x - lo.x) * fx;
        let y = Integer::from(lo.y) * 1000 + Integer::from(hi.y - lo.y) * fy;
        let p = RatPoint::new(x, y, Integer::from(1000)).expect("positive denominator");
        if map.locate(&p) == Containment::Inside && !out.contains(&p) {
            out.push(p);
        }
    }
    out
}

/// For every map vertex v with neighbours u and w, an interior point near
/// it: `v ± s / K` with `s = (u − v) + (w − v)`, which points into the
/// interior angle at a convex vertex and out of it at a reflex one (hence
/// the sign), and the least power of two `K ≥ 64` that puts the point
/// strictly inside.
pub fn near_vertices(map: &Map) -> Vec<RatPoint> {
    let v = map.vertices();
    let n = v.len();
    (0..n)
        .map(|i| {
            let (a, b, c) = (v[map.prev(i)], v[i], v[map.next(i)]);
            let sign = if map.is_reflex(i) { -1 } else { 1 };
            let sx = sign * ((a.x - b.x) + (c.x - b.x));
            let sy = sign * ((a.y - b.y) + (c.y - b.y));
            let mut k = Integer::from(64);
            loop {
                let p = RatPoint::new(
                    Integer::from(&k * b.x) + sx,
                    Integer::from(&k * b.y) + sy,
                    k.clone(),
                )
                .expect("positive denominator");
                if map.locate(&p) == Containment::Inside {
                    break p;
                }
                k *= 2;
                assert!(
                    k.significant_bits() < 200,
                    "no interior point near vertex {i}"
                );
            }
        })
        .collect()
}

/// Up to `count` points strictly inside `map` with random denominators
/// from 1 to 8 (a robot's position as a user would give it), drawn from
/// the bounding box with a seeded generator; fewer if 100 draws per point
/// do not find them (a map much thinner than its box).
pub fn small_denominator_points(map: &Map, count: usize, seed: u64) -> Vec<RatPoint> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let (lo, hi) = map.bounding_box();
    let mut out = Vec::new();
    let mut tries = 0;
    while out.len() < count && tries < 100 * count {
        tries += 1;
        let w: i128 = rng.random_range(1..=8);
        let p = RatPoint::from_i128(
            rng.random_range(lo.x * w..=hi.x * w),
            rng.random_range(lo.y * w..=hi.y * w),
            w,
        )
        .expect("w > 0");
        if map.locate(&p) == Containment::Inside {
            out.push(p);
        }
    }
    out
}

/// What the robot sees from [`small_denominator_points`]: V_p relative to
/// p, the localizer's input.
pub fn robot_views(map: &Map, count: usize, seed: u64) -> Vec<wai_localize::RobotView> {
    let index = wai_visibility::VisibilityIndex::new(map);
    small_denominator_points(map, count, seed)
        .iter()
        .map(|p| {
            wai_localize::RobotView::from_visibility(
                &index.visibility_polygon(p).expect("strictly inside"),
            )
        })
        .collect()
}
