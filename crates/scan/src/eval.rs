//! The evaluation protocol of issue 12: seeded random poses in a map, a
//! simulated scan at each, the localizer's answer compared with the truth.
//!
//! Success is a position error below 0.5 m and a heading error below 10°
//! (strict: 0.1 m and 2°; loose: 1 m and 30°), measured on the best pose;
//! the answer set succeeds when one of its poses is within the (normal)
//! tolerance of the truth.

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use wai_map::Map;

use crate::icp::wrap;
use crate::walls::Walls;
use crate::Pose;

/// A success tolerance: position and heading.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tolerance {
    pub metres: f64,
    pub degrees: f64,
}

pub const NORMAL: Tolerance = Tolerance {
    metres: 0.5,
    degrees: 10.0,
};
pub const STRICT: Tolerance = Tolerance {
    metres: 0.1,
    degrees: 2.0,
};
pub const LOOSE: Tolerance = Tolerance {
    metres: 1.0,
    degrees: 30.0,
};

/// The position and heading errors of `got` against `truth`.
pub fn errors(got: &Pose, truth: &Pose) -> (f64, f64) {
    (
        (got.x - truth.x).hypot(got.y - truth.y),
        wrap(got.heading - truth.heading).abs().to_degrees(),
    )
}

impl Tolerance {
    pub fn accepts(&self, got: &Pose, truth: &Pose) -> bool {
        let (d, a) = errors(got, truth);
        d < self.metres && a < self.degrees
    }
}

/// `count` poses drawn uniformly from the part of `map` at least
/// `clearance` from every wall (a robot has a body), headings uniform,
/// from a ChaCha8 generator seeded with `seed`. Inside-ness is decided
/// exactly ([`Pose::check_inside`]).
pub fn random_poses(
    map: &Map,
    walls: &Walls,
    count: usize,
    clearance: f64,
    seed: u64,
) -> Vec<Pose> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let (lo, hi) = map.bounding_box();
    let s = map.scale().to_f64();
    let (x0, y0, x1, y1) = (
        lo.x as f64 / s,
        lo.y as f64 / s,
        hi.x as f64 / s,
        hi.y as f64 / s,
    );
    let mut poses = Vec::with_capacity(count);
    let mut tries = 0usize;
    while poses.len() < count && tries < 10_000 * count.max(1) {
        tries += 1;
        let p = Pose {
            x: rng.random_range(x0..x1),
            y: rng.random_range(y0..y1),
            heading: rng.random_range(-std::f64::consts::PI..std::f64::consts::PI),
        };
        if p.check_inside(map).is_ok() && walls.nearest((p.x, p.y), clearance).is_none() {
            poses.push(p);
        }
    }
    poses
}
