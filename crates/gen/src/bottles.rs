//! Seeded maps with **bottled niches**: the configuration of Fig 4.31
//! (Theorem 4.19, Corollary 4.20), where an artificial edge of two
//! overlapping embeddings has two valid candidate edges and the candidate
//! edges of the two embeddings cross each other.
//!
//! A hall with identical rectangular rooms in its floor at pitch `t` and
//! identical bottles in its ceiling at the same pitch, one above each room
//! and one more at each end. A bottle is a narrow neck in the ceiling that
//! opens into a wide chamber, whose back wall carries five small spikes.
//! From deep in a room the view through the mouth covers the ceiling from
//! the bottle one pitch to the left to the one a pitch to the right (the
//! mouth's half-width `M` is chosen so that the view's half-width at the
//! ceiling is about `1.4 t`), and through each neck it reaches the back
//! wall of the chamber, one fifth to one third of a pitch further on:
//! - through the bottle above, nearly straight up, on either side of the
//!   middle spike — on its left from witnesses in the right half of the
//!   room, on its right from those in the left half. The two sides are two
//!   valid candidate edges of one artificial edge (Example 3.3's peak);
//! - through the bottles a pitch away, on either side of the outer spikes
//!   (offset `±s`, `s = t·d/(H + D)`), split the same way.
//!
//! The spikes at `±s/2` separate those edges, so the neighbouring room's
//! view through the bottle above this room lands on other map edges than
//! this room's, and its lines of sight cross this room's in the neck: the
//! candidate edges of one room cross the other room's (Def 4.4). The
//! rooms' views overlap in the hall, so their embeddings overlap.
//!
//! Why it holds (distances in the map's units; `px` the witness's offset
//! from its room's axis, at depth about `D`): the view's edge on the
//! ceiling moves by `px·H/D`, and stays between two necks for `|px| <
//! 0.4·t·D/H`; the view on a back wall moves by `px·d/(H + D)` and clears
//! a spike of half-width `w` and depth `k` beside a neck of half-width `m`
//! for `|px| > (m·(H + D + d) + w·(H + D) + k·(t + |px|))/d` (the last
//! term: lines of sight from a pitch away reach the spike's tip obliquely).
//! The parameter ranges keep the second bound below the first (at most
//! about 21 against at least 27), and the chambers' side walls flatter than
//! any line of sight through the neck.

use crate::SharedLayout;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use wai_exact::Point;
use wai_map::Map;

/// The parameters of one [`bottled_niches`] map (integers).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct BottleLayout {
    /// Pitch of rooms and bottles.
    pub pitch: i128,
    /// Rooms: count, half-width of the mouth (the room is as wide as its
    /// mouth), depth.
    pub rooms: i128,
    pub mouth: i128,
    pub depth: i128,
    /// Hall height.
    pub height: i128,
    /// Bottles: half-width of the neck, depth and half-width of the
    /// chamber.
    pub neck: i128,
    pub chamber_depth: i128,
    pub chamber: i128,
    /// Spikes on each back wall: offsets from the neck's axis, half-width,
    /// depth.
    pub spikes: [i128; 5],
    pub spike_width: i128,
    pub spike_depth: i128,
}

impl BottleLayout {
    /// The jittered layout of `seed`.
    pub fn of_seed(seed: u64) -> BottleLayout {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let pitch = 20 * rng.random_range(12..=20i128);
        let depth = 20 * rng.random_range(8..=12i128);
        let height = rng.random_range(5 * depth / 2..=7 * depth / 2);
        // The view's half-width at the ceiling, M·(H + D)/D, about 1.4 t.
        let mouth = 7 * pitch * depth / (5 * (depth + height));
        let chamber_depth = rng.random_range(3 * depth / 4..=depth);
        // Where the view from a pitch away lands on a back wall.
        let s = pitch * chamber_depth / (height + depth);
        BottleLayout {
            pitch,
            rooms: rng.random_range(2..=3i128),
            mouth,
            depth,
            height,
            neck: 2,
            chamber_depth,
            chamber: 3 * s / 2,
            spikes: [-s, -s / 2, 0, s / 2, s],
            spike_width: 1,
            spike_depth: 2,
        }
    }

    /// The axis of room `i` (bottle `i` is above it; bottles `-1` and
    /// `rooms` are the extra ones at the ends).
    pub fn x(&self, i: i128) -> i128 {
        2 * self.pitch + i * self.pitch
    }

    /// The same hall as a [`SharedLayout`] with one extra bottle at each
    /// end (`view` 1), whose ring it is drawn with.
    pub fn hall(&self) -> SharedLayout {
        SharedLayout {
            pitch: self.pitch,
            rooms: self.rooms,
            mouth: self.mouth,
            depth: self.depth,
            height: self.height,
            view: 1,
            neck: self.neck,
            chamber_depth: self.chamber_depth,
            chamber: self.chamber,
            spikes: self.spikes.to_vec(),
            spike_width: self.spike_width,
            spike_depth: self.spike_depth,
        }
    }

    /// Two witnesses of each room, one in each half, at the same places in
    /// every room: the first sees the back wall of the bottle above on the
    /// right of the middle spike, the second on its left.
    pub fn viewpoints(&self) -> Vec<Point> {
        // Between the two bounds of the module doc, near the bottom.
        let hi = 2 * self.pitch * self.depth / (5 * self.height);
        let lo = (self.neck * (self.height + self.depth + self.chamber_depth)
            + self.spike_width * (self.height + self.depth)
            + self.spike_depth * (self.pitch + hi))
            / self.chamber_depth;
        let px = (lo + hi) / 2;
        (0..self.rooms)
            .flat_map(|i| {
                let x = self.x(i);
                [x - px, x + px].map(|x| Point::new(x, 1 - self.depth))
            })
            .collect()
    }
}

/// The map of a jittered [`BottleLayout`]: counter-clockwise from the
/// hall's south-west corner, the floor eastwards with its rooms, then the
/// ceiling westwards with its bottles.
///
/// ```
/// let m = wai_gen::bottled_niches(3);
/// assert!(m.n() >= 40 && m.r() >= 16);
/// ```
pub fn bottled_niches(seed: u64) -> Map {
    BottleLayout::of_seed(seed)
        .hall()
        .map(format!("bottled-niches seed={seed}"))
}
