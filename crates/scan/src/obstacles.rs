//! Unknown obstacles (sec. 6.1): furniture the map does not show, as small
//! axis-parallel boxes that block beams.

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use wai_map::Map;

use crate::Pose;

/// An axis-parallel box in the map's input units, `min < max` on both axes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Obstacle {
    pub min: (f64, f64),
    pub max: (f64, f64),
}

impl Obstacle {
    /// Its four sides, counter-clockwise.
    pub fn sides(&self) -> [[(f64, f64); 2]; 4] {
        let (a, b) = (self.min, self.max);
        let c = [a, (b.0, a.1), b, (a.0, b.1)];
        [[c[0], c[1]], [c[1], c[2]], [c[2], c[3]], [c[3], c[0]]]
    }

    /// True if `(x, y)` lies in the closed box.
    pub fn contains(&self, x: f64, y: f64) -> bool {
        (self.min.0..=self.max.0).contains(&x) && (self.min.1..=self.max.1).contains(&y)
    }
}

/// `count` boxes of side `side` placed at random (seeded) inside `map`,
/// each with its corners strictly inside the map, no map vertex inside it
/// and no wall crossing its sides (so it lies in the map's interior), and at
/// least `side` away from the pose, so it never swallows the robot.
/// Fewer if 1000 draws per box do not find room.
pub fn random_obstacles(
    map: &Map,
    pose: &Pose,
    count: usize,
    side: f64,
    seed: u64,
) -> Vec<Obstacle> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let scale = map.scale().to_f64();
    let (lo, hi) = map.bounding_box();
    let (lo, hi) = (
        (lo.x as f64 / scale, lo.y as f64 / scale),
        (hi.x as f64 / scale, hi.y as f64 / scale),
    );
    let walls = crate::walls(map);
    let vertices: Vec<(f64, f64)> = walls.iter().map(|w| w[0]).collect();
    let mut out = Vec::new();
    if hi.0 - lo.0 <= side || hi.1 - lo.1 <= side {
        return out;
    }
    for _ in 0..count {
        for _ in 0..1000 {
            let x = rng.random_range(lo.0..hi.0 - side);
            let y = rng.random_range(lo.1..hi.1 - side);
            let o = Obstacle {
                min: (x, y),
                max: (x + side, y + side),
            };
            let corners = [o.min, (o.max.0, o.min.1), o.max, (o.min.0, o.max.1)];
            let inside = corners.iter().all(|&(cx, cy)| {
                Pose {
                    x: cx,
                    y: cy,
                    heading: 0.0,
                }
                .check_inside(map)
                .is_ok()
            });
            let clear = !vertices.iter().any(|&(vx, vy)| o.contains(vx, vy))
                && !o
                    .sides()
                    .iter()
                    .any(|s| walls.iter().any(|w| crosses(s, w)));
            let far = (pose.x < o.min.0 - side || pose.x > o.max.0 + side)
                || (pose.y < o.min.1 - side || pose.y > o.max.1 + side);
            if inside && clear && far {
                out.push(o);
                break;
            }
        }
    }
    out
}

/// True if the closed segments `a` and `b` meet.
fn crosses(a: &[(f64, f64); 2], b: &[(f64, f64); 2]) -> bool {
    let orient = |p: (f64, f64), q: (f64, f64), r: (f64, f64)| {
        let v = (q.0 - p.0) * (r.1 - p.1) - (q.1 - p.1) * (r.0 - p.0);
        if v > 0.0 {
            1
        } else if v < 0.0 {
            -1
        } else {
            0
        }
    };
    let (d1, d2) = (orient(a[0], a[1], b[0]), orient(a[0], a[1], b[1]));
    let (d3, d4) = (orient(b[0], b[1], a[0]), orient(b[0], b[1], a[1]));
    if d1 * d2 < 0 && d3 * d4 < 0 {
        return true;
    }
    let within = |p: (f64, f64), q: (f64, f64), r: (f64, f64)| {
        r.0 >= p.0.min(q.0) && r.0 <= p.0.max(q.0) && r.1 >= p.1.min(q.1) && r.1 <= p.1.max(q.1)
    };
    (d1 == 0 && within(a[0], a[1], b[0]))
        || (d2 == 0 && within(a[0], a[1], b[1]))
        || (d3 == 0 && within(b[0], b[1], a[0]))
        || (d4 == 0 && within(b[0], b[1], a[1]))
}
