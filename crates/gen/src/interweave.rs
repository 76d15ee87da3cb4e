//! Seeded maps for the claims of thesis secs. 5.4 and 5.5, which random
//! maps and the chapter 4 layouts never reach:
//!
//! - [`interweaved_gaps`]: two valid embeddings of one skeleton whose gaps
//!   (Def 5.5) are **interweaved** and **nested** (Def 5.6), the situation
//!   of Example 5.1 and Fig 5.5 (Lemmas 5.5–5.9);
//! - [`shared_niches`]: map edges e, f that are valid candidate edges of
//!   different artificial edges in k ≥ 4 valid embeddings of one skeleton
//!   (the premise of Lemmas 5.13 and 5.14, Figs 5.13–5.15);
//! - [`shared_spiked_niches`]: the same with f a *multiple* candidate edge
//!   in its set, |C_{ĩ,j}| > 1, in k = 2 embeddings (Theorem 5.15,
//!   Fig 5.16).
//!
//! # Pinhole rooms ([`PinholeLayout`])
//! A skeleton is invariant under translation (Def 3.7 (6)), so two rooms
//! that are translates of each other have one skeleton, and the label of
//! an artificial edge, a line, moves with the embedding (Def 3.11 (3)).
//! A simple polygon cannot give a room two doors into one connected region
//! (the wall between the doors would be a hole), so the map is a path of
//! regions joined by narrow doors:
//!
//! ```text
//!   chamber 1 ─a─ room 1 ─b─ hall ─a─ room 2 ─b─ chamber 2
//! ```
//!
//! Room 2 is room 1 moved east by [`PinholeLayout::apart`]. Each room lies
//! below a wall of thickness `wall` pierced by two doors of width `door`,
//! short vertical tunnels: door a near its west end, door b near its east
//! end. A witness between the doors sees through each tunnel a narrow cone
//! (a pinhole camera): through door a up and west, bounded by the tunnel's
//! bottom-east and top-west corners, through door b up and east. The cones
//! end on far horizontal walls without showing any vertex, so each gives
//! a partial edge (Def 3.5), an artificial edge labelled with the far
//! wall's line. As the witness moves, a cone sweeps the far wall (its
//! slope from vertical is below `door / wall`), so one artificial edge
//! can see several collinear map edges, separated by recesses it never
//! sees into: multiple candidate edges (Def 5.4, as Example 3.3's peak).
//!
//! - Room 1's door a opens into chamber 1, whose ceiling is one edge at
//!   height [`low`](PinholeLayout::low); its door b opens into the hall.
//! - Room 2's door a opens into the hall; its door b into chamber 2, whose
//!   ceiling is one edge at height [`high`](PinholeLayout::high).
//! - The hall's ceiling is at `low`, with notches up to `high`. Room 2's
//!   door-a cone (label y = `low`, as in room 1) lands on the **flats**
//!   between the notches: the set C of h₂(a) holds several flats. Room 1's
//!   door-b cone (label y = `high`, as in room 2) passes through a notch's
//!   mouth onto its **top**: the set C of h₁(b) holds several tops. A
//!   **tooth** hanging from a notch's top splits it into two tops.
//!
//! The two cones cross in the hall and sweep the same stretch of it. Along
//! the boundary (westwards on the ceiling) a flat, a notch, a flat and a
//! notch alternate: two consecutive flats and two consecutive tops
//! interleave, A₁, B₁, A₂, B₂, so their gaps are **interweaved**; the two
//! tops on either side of a tooth lie between two consecutive flats, so
//! their gap is **nested** into the flats' gap. Exactly the pattern of
//! Fig 5.5, where g(a₂, a₃) is nested into g(b₁, b₂), itself interweaved
//! with g(a₁, a₂). The embeddings do not overlap (Lemma 5.6), and the
//! interweavement graph (Def 5.9) is one special node on two embeddings.
//!
//! Why it holds (the tunnel of door b at x ∈ [x_b, x_b + w], y ∈ [0, T],
//! a witness u west of it and D' below the wall): the cone's west ray
//! through (x_b, 0) reaches height Y at x_b + uY/D', its east ray through
//! (x_b + w, T) at x_b + w + (u + w)(Y − T)/(T + D'); the cone is nonempty
//! for u/D' < w/T and its width at Y is (Y + D')(w − uT/D')/(T + D'),
//! about 6 at most for witnesses deeper than `low`/2 (the rooms of
//! [`PinholeLayout::of_seed`] are deeper than that), while notch tops are
//! 14 to 20 wide (the cone drifts by at most `high − low` between
//! a notch's mouth and top) and flats 12 to 18. The stretch the two cones
//! share is reached at slopes below 4/5 of `door / wall`, by the choice of
//! `low`; both doors of a room are seen at once where the two slopes sum
//! to `between / D'` < 2, which holds deep in the room.
//!
//! # Shared niches ([`SharedLayout`])
//! A hall with `rooms` identical rooms in its floor at pitch `pitch`
//! (which gives every room one skeleton, as in [`crate::repeated_niches`])
//! and identical bottles in its ceiling at the same pitch, as in
//! [`crate::bottled_niches`]: a narrow neck opening into a wide chamber
//! whose back wall is seen only through the neck, a partial edge. From
//! deep in a room the view through its mouth covers the ceiling up to
//! `view` + ½ pitches on either side, so a witness sees the backs of
//! `2·view + 1` bottles, each through its own artificial edge (the neck),
//! and the room one pitch east sees the same backs through the neighbouring
//! artificial edges. The back of bottle n and of bottle n + 1 are then
//! valid candidate edges of different artificial edges in the 2·`view`
//! embeddings of the rooms n + 1 − `view` to n + `view`: k = 4 for
//! `view` = 2 and k = 6 for `view` = 3 (Lemma 5.13's and Lemma 5.14's
//! premise; the views cross as in Fig 5.13, and neighbouring embeddings
//! overlap in the hall).
//!
//! With spikes on the back walls, [`SharedLayout::spiked_of_seed`] keeps
//! `view` = 1 and places spikes at −s, 0 and s from the neck's axis, where
//! the view through a bottle lands from the room below it (0) and from
//! the rooms a pitch away (±s, s = pitch·chamber_depth/(height + depth)):
//! witnesses west and east of a room's axis see either side of each spike
//! (Example 3.3's peak), so every neck's set C_{i,j} has two back pieces. The
//! piece between the spikes 0 and s is seen from the room below and from
//! the room a pitch west; unlike [`crate::bottled_niches`], whose spikes at
//! ±s/2 separate exactly these views, nothing separates them here, so f =
//! that piece is a multiple candidate edge in both rooms' sets, and e =
//! the piece between −s and 0 of the bottle a pitch west is a candidate
//! edge in both: k = 2 for Theorem 5.15.

use crate::ring::into_map;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use wai_exact::Point;
use wai_map::Map;

/// A notch in the hall's ceiling of a [`PinholeLayout`]: its x-range at
/// the ceiling, and the teeth hanging from its top, by x-range.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CeilingNotch {
    pub west: i128,
    pub east: i128,
    pub teeth: Vec<(i128, i128)>,
}

/// The parameters of one [`interweaved_gaps`] map (integers; room 1's
/// south-west corner is (0, −`depth`) and its ceiling is y = 0).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PinholeLayout {
    /// Door width w and wall thickness T: a cone's slope from vertical is
    /// below w/T.
    pub door: i128,
    pub wall: i128,
    /// Each room: from its west wall to door a, from door a to door b
    /// (where the witnesses are), from door b to its east wall; its depth.
    pub margin: i128,
    pub between: i128,
    pub depth: i128,
    /// Room 2 is room 1 moved east by `apart`.
    pub apart: i128,
    /// The ceilings: chamber 1's and the hall's flats at `low`, chamber 2's
    /// and the notches' tops at `high`, teeth down to `tooth`.
    pub low: i128,
    pub high: i128,
    pub tooth: i128,
    /// The hall's notches, west to east.
    pub notches: Vec<CeilingNotch>,
    /// How far chamber 1 reaches west of door a and chamber 2 east of
    /// door b.
    pub chamber: i128,
}

impl PinholeLayout {
    /// The jittered layout of `seed`: depth, ceiling heights, the number
    /// (2 to 4), widths and order of the notches, one of them with a tooth.
    pub fn of_seed(seed: u64) -> PinholeLayout {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let (door, wall, margin) = (2, 2, 2);
        let rise = 2 * rng.random_range(2..=4i128);
        let count = rng.random_range(2..=4usize);
        let toothed = rng.random_range(0..count);
        // West to east, as offsets from door b's west edge, from just east
        // of its tunnel: a flat, then notch and flat alternating.
        let mut x = door + 2 + rng.random_range(12..=18i128);
        let mut notches = Vec::new();
        for k in 0..count {
            let west = x;
            let mut teeth = Vec::new();
            x += rng.random_range(14..=20i128);
            if k == toothed {
                let t = rng.random_range(2..=4i128);
                teeth.push((x, x + t));
                x += t + rng.random_range(14..=20i128);
            }
            notches.push(CeilingNotch {
                west,
                east: x,
                teeth,
            });
            x += rng.random_range(12..=18i128);
        }
        // Door a of room 2 is 2 east of the last flat; both cones reach
        // the far end of the shared stretch at slope 4/5 of w/T (= 1).
        let reach = x + 2 + door;
        let low = 2 * ((5 * reach + 7) / 8 + 1);
        let high = low + rise;
        // Deep rooms keep the cones narrow: (Y + D')·w/(T + D') is about
        // 6 where D' > low/2.
        let depth = 2 * (low / 4 + rng.random_range(2..=10i128));
        let between = depth - 2 * rng.random_range(0..=5i128);
        let xb = margin + door + between;
        for n in &mut notches {
            n.west += xb;
            n.east += xb;
            for t in &mut n.teeth {
                *t = (t.0 + xb, t.1 + xb);
            }
        }
        let apart = xb + x + 2 - margin;
        PinholeLayout {
            door,
            wall,
            margin,
            between,
            depth,
            apart,
            low,
            high,
            tooth: low + rise / 2,
            notches,
            chamber: high + 10,
        }
    }

    /// The west edge of door a and of door b in room 1.
    fn doors(&self) -> (i128, i128) {
        (self.margin, self.margin + self.door + self.between)
    }

    /// Room 1's width.
    pub fn width(&self) -> i128 {
        self.doors().1 + self.door + self.margin
    }

    /// The divider between door a's chamber and door b's region, above
    /// room 1: its west and east face.
    fn divider(&self) -> (i128, i128) {
        let mid = self.doors().0 + self.door + self.between / 2;
        (mid - 2, mid + 2)
    }

    /// The ring, counter-clockwise from room 1's south-west corner: room 1,
    /// the hall's floor, room 2, chamber 2, room 2's door a, the hall's
    /// ceiling westwards, room 1's door b, chamber 1.
    fn ring(&self) -> Vec<Point> {
        let p = Point::new;
        let (w, t, d, q) = (self.door, self.wall, self.depth, self.apart);
        let ((xa, xb), width) = (self.doors(), self.width());
        let (dw, de) = self.divider();
        let mut ring = vec![
            p(0, -d),
            p(width, -d),
            p(width, 0),
            p(xb + w, 0),
            p(xb + w, t),
            p(q + xa, t),
            p(q + xa, 0),
            p(q, 0),
            p(q, -d),
            p(q + width, -d),
            p(q + width, 0),
            p(q + xb + w, 0),
            p(q + xb + w, t),
            p(q + xb + w + self.chamber, t),
            p(q + xb + w + self.chamber, self.high),
            p(q + de, self.high),
            p(q + de, t),
            p(q + xb, t),
            p(q + xb, 0),
            p(q + xa + w, 0),
            p(q + xa + w, t),
            p(q + dw, t),
            p(q + dw, self.low),
        ];
        for n in self.notches.iter().rev() {
            ring.extend([p(n.east, self.low), p(n.east, self.high)]);
            for &(west, east) in n.teeth.iter().rev() {
                ring.extend([
                    p(east, self.high),
                    p(east, self.tooth),
                    p(west, self.tooth),
                    p(west, self.high),
                ]);
            }
            ring.extend([p(n.west, self.high), p(n.west, self.low)]);
        }
        ring.extend([
            p(de, self.low),
            p(de, t),
            p(xb, t),
            p(xb, 0),
            p(xa + w, 0),
            p(xa + w, t),
            p(dw, t),
            p(dw, self.low),
            p(xa - self.chamber, self.low),
            p(xa - self.chamber, t),
            p(xa, t),
            p(xa, 0),
            p(0, 0),
        ]);
        ring
    }

    /// The map of this layout.
    ///
    /// # Panics
    /// If the layout's ring is not a valid map (a hand-made layout whose
    /// notches overlap or leave the hall); [`PinholeLayout::of_seed`]'s
    /// never do.
    pub fn map(&self, name: impl Into<String>) -> Map {
        into_map(self.ring(), name)
    }

    /// One witness in each room, deep and between the doors, whose cones
    /// land on the middle of the first notch's top (room 1, door b) and of
    /// the flat west of it (room 2, door a); rounded to the grid, so they
    /// land near, not at, those points.
    pub fn viewpoints(&self) -> [Point; 2] {
        let (xa, xb) = self.doors();
        let dd = self.depth - 1;
        let first = &self.notches[0];
        let top = first.teeth.first().map_or(first.east, |t| t.0);
        // Room 1: the west ray through (x_b, 0) lands at x_b + u·high/D'.
        let u1 = ((first.west + top) / 2 - xb) * dd / self.high;
        // Room 2: the east ray through (apart + x_a + w, 0) lands at
        // apart + x_a + w − u·low/D'.
        let flat = (xb + self.door + first.west) / 2;
        let u2 = (self.apart + xa + self.door - flat) * dd / self.low;
        [
            Point::new(xb - u1, -dd),
            Point::new(self.apart + xa + self.door + u2, -dd),
        ]
    }
}

/// The map of a jittered [`PinholeLayout`]: two pinhole rooms whose gaps
/// are interweaved and nested (Def 5.6, Example 5.1, Fig 5.5).
///
/// ```
/// let l = wai_gen::PinholeLayout::of_seed(4);
/// let m = wai_gen::interweaved_gaps(4);
/// assert_eq!(m, wai_gen::interweaved_gaps(4));
/// // Rooms, doors, chambers and dividers: 36 vertices; 4 per notch and
/// // per tooth.
/// let teeth: usize = l.notches.iter().map(|n| n.teeth.len()).sum();
/// assert_eq!(m.n(), 36 + 4 * l.notches.len() + 4 * teeth);
/// ```
pub fn interweaved_gaps(seed: u64) -> Map {
    PinholeLayout::of_seed(seed).map(format!("interweaved-gaps seed={seed}"))
}

/// The parameters of one [`shared_niches`] or [`shared_spiked_niches`] map
/// (integers; the hall's floor is y = 0).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SharedLayout {
    /// Pitch of rooms and bottles.
    pub pitch: i128,
    /// Rooms: count, half-width of the mouth (the room is as wide as its
    /// mouth), depth.
    pub rooms: i128,
    pub mouth: i128,
    pub depth: i128,
    /// Hall height.
    pub height: i128,
    /// How many bottles a witness sees on either side of the one above its
    /// room; there are `rooms + 2·view` bottles.
    pub view: i128,
    /// Bottles: half-width of the neck, depth and half-width of the
    /// chamber.
    pub neck: i128,
    pub chamber_depth: i128,
    pub chamber: i128,
    /// Spikes on each back wall: offsets from the neck's axis, half-width,
    /// depth.
    pub spikes: Vec<i128>,
    pub spike_width: i128,
    pub spike_depth: i128,
}

impl SharedLayout {
    /// The plain layout of `seed` (no spikes): `view` 2 or 3, `2·view` or
    /// `2·view + 1` rooms, jittered pitch, depth and chamber depth.
    pub fn of_seed(seed: u64) -> SharedLayout {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let view = rng.random_range(2..=3i128);
        let pitch = 10 * rng.random_range(8..=14i128);
        let depth = 10 * rng.random_range(6..=10i128);
        let chamber_depth = rng.random_range(depth / 2..=3 * depth / 4);
        let rooms = 2 * view + rng.random_range(0..=1i128);
        SharedLayout::plain(view, rooms, pitch, depth, chamber_depth)
    }

    /// The plain layout (no spikes) that sees `view` bottles on either side
    /// of a room's own, with `rooms` rooms of depth `depth` at pitch `pitch`
    /// and chambers `chamber_depth` deep. The mouth is 2/5 of the pitch,
    /// and the hall as high as puts the view's half-width at the ceiling,
    /// mouth·(height + depth)/depth, at (view + 1/2)·pitch; a chamber is
    /// as wide as the views from `view` pitches away need.
    ///
    /// # Panics
    /// Unless `view ≥ 1`, `rooms ≥ 1`, `pitch ≥ 50`, `depth ≥ 8` and
    /// `depth/4 ≤ chamber_depth ≤ depth` (outside those rooms or chambers
    /// may touch).
    pub fn plain(
        view: i128,
        rooms: i128,
        pitch: i128,
        depth: i128,
        chamber_depth: i128,
    ) -> SharedLayout {
        assert!(view >= 1 && rooms >= 1 && pitch >= 50 && depth >= 8);
        assert!(4 * chamber_depth >= depth && chamber_depth <= depth);
        let height = depth * (10 * view + 1) / 4;
        // Where the view from one pitch away lands on a back wall.
        let s = pitch * chamber_depth / (height + depth);
        SharedLayout {
            pitch,
            rooms,
            mouth: 2 * pitch / 5,
            depth,
            height,
            view,
            neck: 2,
            chamber_depth,
            chamber: (2 * view + 1) * s / 2 + 4,
            spikes: Vec::new(),
            spike_width: 1,
            spike_depth: 2,
        }
    }

    /// The spiked layout of `seed`: `view` 1, two or three rooms, the
    /// ranges of [`crate::BottleLayout::of_seed`].
    pub fn spiked_of_seed(seed: u64) -> SharedLayout {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let pitch = 20 * rng.random_range(12..=20i128);
        let depth = 20 * rng.random_range(8..=12i128);
        let height = rng.random_range(5 * depth / 2..=7 * depth / 2);
        let chamber_depth = rng.random_range(3 * depth / 4..=depth);
        let rooms = rng.random_range(2..=3i128);
        SharedLayout::spiked(rooms, pitch, depth, height, chamber_depth)
    }

    /// The spiked layout (`view` 1) with `rooms` rooms of depth `depth` at
    /// pitch `pitch`, a hall `height` high and chambers `chamber_depth`
    /// deep: the mouth puts the view's half-width at the ceiling at about
    /// 1.4 pitches (as [`crate::bottled_niches`]), and each back wall has
    /// spikes at −s, 0 and s, s = pitch·chamber_depth/(height + depth),
    /// in a chamber 3s/2 wide on either side (see the module doc).
    ///
    /// # Panics
    /// Unless `rooms ≥ 1`, `pitch ≥ 40`, `height > 2·depth`,
    /// `chamber_depth ≤ depth` and s ≥ 4 (outside those rooms, chambers or
    /// spikes may touch).
    pub fn spiked(
        rooms: i128,
        pitch: i128,
        depth: i128,
        height: i128,
        chamber_depth: i128,
    ) -> SharedLayout {
        assert!(rooms >= 1 && pitch >= 40 && height > 2 * depth && chamber_depth <= depth);
        let s = pitch * chamber_depth / (height + depth);
        assert!(s >= 4, "spikes {s} apart");
        SharedLayout {
            pitch,
            rooms,
            mouth: 7 * pitch * depth / (5 * (depth + height)),
            depth,
            height,
            view: 1,
            neck: 2,
            chamber_depth,
            chamber: 3 * s / 2,
            spikes: vec![-s, 0, s],
            spike_width: 1,
            spike_depth: 2,
        }
    }

    /// The axis of room `i`, and of bottle `i` above it (bottles run from
    /// `-view` to `rooms - 1 + view`).
    pub fn x(&self, i: i128) -> i128 {
        (self.view + 1) * self.pitch + i * self.pitch
    }

    /// Witnesses deep in each room, at the same places in every room: in a
    /// plain layout one on the room's axis, which sees the backs of
    /// `2·view + 1` bottles; in a spiked layout one on either side of the
    /// axis (between the bounds of [`crate::bottled_niches`]), which see
    /// the back walls on either side of the spikes.
    pub fn viewpoints(&self) -> Vec<Point> {
        let offsets = if self.spikes.is_empty() {
            vec![0]
        } else {
            let hi = 2 * self.pitch * self.depth / (5 * self.height);
            let lo = (self.neck * (self.height + self.depth + self.chamber_depth)
                + self.spike_width * (self.height + self.depth)
                + self.spike_depth * (self.pitch + hi))
                / self.chamber_depth;
            let px = (lo + hi) / 2;
            vec![-px, px]
        };
        (0..self.rooms)
            .flat_map(|i| {
                offsets
                    .iter()
                    .map(move |dx| Point::new(self.x(i) + dx, 1 - self.depth))
            })
            .collect()
    }

    /// The ring, counter-clockwise from the hall's south-west corner: the
    /// floor eastwards with its rooms, then the ceiling westwards with its
    /// bottles.
    pub(crate) fn ring(&self) -> Vec<Point> {
        let p = Point::new;
        let west = self.x(-self.view) - self.pitch;
        let east = self.x(self.rooms - 1 + self.view) + self.pitch;
        let mut ring = vec![p(west, 0)];
        for i in 0..self.rooms {
            let x = self.x(i);
            ring.extend([
                p(x - self.mouth, 0),
                p(x - self.mouth, -self.depth),
                p(x + self.mouth, -self.depth),
                p(x + self.mouth, 0),
            ]);
        }
        ring.extend([p(east, 0), p(east, self.height)]);
        let back = self.height + self.chamber_depth;
        let mut spikes = self.spikes.clone();
        spikes.sort_unstable();
        for j in (-self.view..self.rooms + self.view).rev() {
            let x = self.x(j);
            ring.extend([p(x + self.neck, self.height), p(x + self.chamber, back)]);
            for s in spikes.iter().rev() {
                ring.extend([
                    p(x + s + self.spike_width, back),
                    p(x + s, back - self.spike_depth),
                    p(x + s - self.spike_width, back),
                ]);
            }
            ring.extend([p(x - self.chamber, back), p(x - self.neck, self.height)]);
        }
        ring.push(p(west, self.height));
        ring
    }

    /// The map of this layout.
    ///
    /// # Panics
    /// If the layout's ring is not a valid map (a hand-made layout whose
    /// rooms, chambers or spikes touch); the seeded layouts' never do.
    pub fn map(&self, name: impl Into<String>) -> Map {
        into_map(self.ring(), name)
    }
}

/// The map of a plain [`SharedLayout::of_seed`]: the backs of neighbouring
/// bottles are candidate edges of different artificial edges in 4 or 6
/// embeddings (Lemmas 5.13, 5.14; Figs 5.13–5.15).
///
/// ```
/// let l = wai_gen::SharedLayout::of_seed(2);
/// let m = wai_gen::shared_niches(2);
/// assert_eq!(m, wai_gen::shared_niches(2));
/// // The hall's 4 corners, 4 per room and per bottle.
/// assert_eq!(m.n() as i128, 4 + 4 * l.rooms + 4 * (l.rooms + 2 * l.view));
/// ```
pub fn shared_niches(seed: u64) -> Map {
    SharedLayout::of_seed(seed).map(format!("shared-niches seed={seed}"))
}

/// The map of a [`SharedLayout::spiked_of_seed`]: a pair of back pieces,
/// the second a multiple candidate edge, in 2 embeddings (Theorem 5.15).
///
/// ```
/// let l = wai_gen::SharedLayout::spiked_of_seed(2);
/// let m = wai_gen::shared_spiked_niches(2);
/// // The hall's 4 corners, 4 per room, 4 per bottle and 3 per spike.
/// assert_eq!(m.n() as i128, 4 + 4 * l.rooms + 13 * (l.rooms + 2));
/// ```
pub fn shared_spiked_niches(seed: u64) -> Map {
    SharedLayout::spiked_of_seed(seed).map(format!("shared-spiked-niches seed={seed}"))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ring_problem;

    #[test]
    fn pinhole_layouts_have_both_notches_within_the_cones_reach() {
        for seed in 0..300 {
            let l = PinholeLayout::of_seed(seed);
            assert_eq!(ring_problem(&l.ring()), None, "seed {seed}");
            // A plain notch (for interweaved gaps) and one with a tooth
            // (for nested ones), west to east, inside the hall.
            assert!(l.notches.iter().any(|n| n.teeth.is_empty()));
            assert!(l.notches.iter().any(|n| !n.teeth.is_empty()));
            let (_, xb) = l.doors();
            assert!(l.divider().1 < l.notches[0].west);
            assert!(l.notches.windows(2).all(|w| w[0].east < w[1].west));
            // Both cones reach the shared stretch at slope 4/5 of w/T, and
            // the rooms are deeper than low/2.
            let reach = l.apart + l.margin + l.door - xb;
            assert!(5 * reach * l.wall <= 4 * l.door * l.low, "seed {seed}");
            assert!(2 * l.depth > l.low && l.between <= l.depth, "seed {seed}");
        }
    }

    #[test]
    fn shared_layouts_are_valid_over_their_parameters() {
        for view in 1..=5 {
            for rooms in [1, 2, 2 * view + 1] {
                for pitch in [50, 73, 140, 400] {
                    for depth in [8, 61, 100] {
                        for chamber_depth in [(depth + 3) / 4, depth / 2, depth] {
                            let l = SharedLayout::plain(view, rooms, pitch, depth, chamber_depth);
                            assert_eq!(ring_problem(&l.ring()), None, "{l:?}");
                            assert!(2 * l.chamber < l.pitch && 2 * l.mouth < l.pitch);
                        }
                    }
                }
            }
        }
        for rooms in [1, 3] {
            for pitch in [40, 240, 400] {
                for depth in [8, 160, 240] {
                    for height in [2 * depth + 1, 3 * depth, 4 * depth] {
                        for chamber_depth in [3 * depth / 4, depth] {
                            if pitch * chamber_depth / (height + depth) < 4 {
                                continue;
                            }
                            let l =
                                SharedLayout::spiked(rooms, pitch, depth, height, chamber_depth);
                            assert_eq!(ring_problem(&l.ring()), None, "{l:?}");
                            assert!(2 * l.chamber < l.pitch && 2 * l.mouth < l.pitch);
                        }
                    }
                }
            }
        }
    }
}
