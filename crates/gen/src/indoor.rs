//! Indoor floors for the noisy-scan localizer (ch. 6), in decimetres
//! (scale 10, so the input unit is the metre): walls 0.2 m thick, doors
//! 1 m wide, corridors 2 m wide.
//!
//! - [`repeated_rooms`]: k identical rooms off one corridor — the
//!   symmetric building where every room has look-alikes (the scan
//!   localizer's answer set must hold them all).
//! - [`office`]: two rows of rooms of seeded widths and depths along a
//!   corridor, seeded door positions, and a seeded niche in some back
//!   walls — a floor of a few thousand visibility cells.

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::Integer;
use wai_exact::Point;
use wai_map::Map;

/// A room above (`up`) or below the corridor: its x extent, its depth,
/// the door's left x, and an optional niche in its back wall (left x,
/// width, depth).
struct Room {
    x0: i128,
    x1: i128,
    depth: i128,
    door: i128,
    niche: Option<(i128, i128, i128)>,
}

const WALL: i128 = 2;
const DOOR: i128 = 10;
const CORRIDOR: i128 = 20;

/// The ring points of a room hanging off the line y = `base`, traversed
/// right to left for a room above (`sign` = 1) — the caller's walk runs
/// along the corridor's top wall leftwards — or left to right for a room
/// below (`sign` = −1).
fn room_points(r: &Room, base: i128, sign: i128) -> Vec<(i128, i128)> {
    let y_in = base + sign * WALL;
    let y_back = y_in + sign * r.depth;
    let mut back = vec![(r.x1, y_back)];
    if let Some((nx, nw, nd)) = r.niche {
        back.extend([
            (nx + nw, y_back),
            (nx + nw, y_back + sign * nd),
            (nx, y_back + sign * nd),
            (nx, y_back),
        ]);
    }
    back.push((r.x0, y_back));
    let mut pts = vec![(r.door + DOOR, base), (r.door + DOOR, y_in), (r.x1, y_in)];
    pts.extend(back);
    pts.extend([(r.x0, y_in), (r.door, y_in), (r.door, base)]);
    if sign < 0 {
        // Below the corridor the walk runs left to right: mirror the order.
        pts.reverse();
    }
    pts
}

/// A corridor from x = 0 to `length` with `above` rooms over it and
/// `below` rooms under it.
fn floor(length: i128, above: &[Room], below: &[Room]) -> Map {
    let mut ring: Vec<(i128, i128)> = vec![(0, 0)];
    for r in below {
        ring.extend(room_points(r, 0, -1));
    }
    ring.push((length, 0));
    ring.push((length, CORRIDOR));
    for r in above.iter().rev() {
        ring.extend(room_points(r, CORRIDOR, 1));
    }
    ring.push((0, CORRIDOR));
    let ring = ring.into_iter().map(|(x, y)| Point::new(x, y)).collect();
    Map::from_scaled_ring(ring, Integer::from(10))
        .expect("the rooms are disjoint and the ring simple by construction")
        .0
}

/// `k` ≥ 1 identical 4 m × 4 m rooms above a corridor, 5 m apart, each
/// with its door 1 m from its left wall; the corridor reaches 1 m past
/// the outer rooms.
pub fn repeated_rooms(k: u32) -> Map {
    let k = i128::from(k.max(1));
    let rooms: Vec<Room> = (0..k)
        .map(|i| Room {
            x0: 10 + 50 * i,
            x1: 50 + 50 * i,
            depth: 40,
            door: 20 + 50 * i,
            niche: None,
        })
        .collect();
    floor(50 * k + 10, &rooms, &[])
}

/// `rooms` ≥ 1 rooms on each side of a corridor, widths 3–6 m, depths
/// 3–5 m, doors anywhere along the room, and a niche (1–2 m wide, 0.5–1 m
/// deep) in every other back wall, seeded.
pub fn office(rooms: u32, seed: u64) -> Map {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let row = |rng: &mut ChaCha8Rng| {
        let mut x = 10;
        let mut out = Vec::new();
        for i in 0..rooms {
            let w: i128 = rng.random_range(30..=60);
            let depth: i128 = rng.random_range(30..=50);
            let door = x + rng.random_range(5..=w - DOOR - 5);
            let niche = (i % 2 == 1).then(|| {
                let nw: i128 = rng.random_range(10..=20);
                let nx = x + rng.random_range(5..=w - nw - 5);
                (nx, nw, rng.random_range(5..=10))
            });
            out.push(Room {
                x0: x,
                x1: x + w,
                depth,
                door,
                niche,
            });
            x += w + WALL;
        }
        (out, x)
    };
    let (above, xa) = row(&mut rng);
    let (below, xb) = row(&mut rng);
    floor(xa.max(xb) + 8, &above, &below)
}
