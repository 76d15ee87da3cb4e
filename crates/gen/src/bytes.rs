//! Maps from bytes, valid by construction, for the structure-aware fuzz
//! targets (`fuzz/`) and `wai check`'s map kind "bytes": the targets
//! build maps from bytes the way the generators do, instead of returning
//! early on invalid input.
//!
//! [`map_from_bytes`] reads a [`Shape`] and its parameters from an
//! [`arbitrary::Unstructured`] and builds the map with this crate's own
//! builders — nothing here draws a polygon of its own:
//!
//! | shape | builder | stresses |
//! |---|---|---|
//! | [`Shape::Ring`] | lattice points straight from the bytes, [`Map::from_ring`] | chapter 3 on arbitrary simple polygons; collinear and repeated points are common, and a rejected ring falls back to [`Shape::Star`] |
//! | [`Shape::Star`] | `random-simple-star` (angular sort of lattice points) | general position, convex and reflex chains |
//! | [`Shape::Polyomino`] | `random-orthogonal` growth, unit or stretched grid | collinear walls, rays through several vertices, doorways (A3.6, T3.3b) |
//! | [`Shape::Chamfer`] | `special-chamfer` | edges on few axis-parallel and diagonal lines |
//! | [`Shape::Comb`] | `special-comb` | corridors with aligned niches: repeated skeletons (L3.7, chapter 4) |
//! | [`Shape::Corridor`] | [`crate::RepeatedLayout`] with 2–3 funnels | overlapping embeddings (T4.2, T4.3) |
//! | [`Shape::Rooms`] | [`crate::SharedLayout::plain`], `view` 1, 1–2 rooms, perhaps one spike | partial edges, shared and multiple candidate edges (chapter 5) |
//! | [`Shape::Family`] | [`crate::family`] at small parameters, then 0–4 [`crate::mutate::mutate`] moves | the thesis's worst cases and their neighbourhoods |
//!
//! Every map is small — at most about 30 vertices, coordinates below a few
//! hundred (a mutated family may double them) — so that every checker runs
//! in milliseconds to a second on it. A random choice a builder needs comes
//! from a [`ChaCha8Rng`] seeded with eight bytes of the input, so the map is
//! a deterministic function of the bytes.
//!
//! # Edge cases
//! - No input panics: every builder is called inside the parameter ranges
//!   it documents, and a ring that is not valid by construction (the
//!   [`Shape::Ring`] points, a hand-made [`Shape::Corridor`] or
//!   [`Shape::Rooms`] layout) goes through [`Map::from_ring`], falling back
//!   to a simpler shape if it is rejected.
//! - Bytes that run out read as zeros (`arbitrary`'s convention), which
//!   picks the first shape and the smallest parameters: the empty input
//!   gives a valid map too.
//!
//! ```
//! let mut u = arbitrary::Unstructured::new(&[3, 1, 4, 1, 5, 9, 2, 6]);
//! let map = wai_gen::bytes::map_from_bytes(&mut u).unwrap();
//! assert!(map.n() >= 3 && map.name().unwrap().starts_with("bytes/"));
//! ```
//!
//! # Invariant
//! No decision reads a float; a map returned is accepted by
//! [`Map::from_ring`] unchanged.

use crate::mutate::{mutate, Limits};
use crate::{polyomino, simple, special, RepeatedLayout, SharedLayout};
use arbitrary::Unstructured;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use wai_exact::Point;
use wai_map::Map;

/// The kinds of map [`map_from_bytes`] builds (module doc).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Shape {
    Ring,
    Star,
    Polyomino,
    Chamfer,
    Comb,
    Corridor,
    Rooms,
    Family,
}

/// Every shape, in the order the first byte picks them.
pub const SHAPES: &[Shape] = &[
    Shape::Ring,
    Shape::Star,
    Shape::Polyomino,
    Shape::Chamfer,
    Shape::Comb,
    Shape::Corridor,
    Shape::Rooms,
    Shape::Family,
];

impl Shape {
    /// The shape's name, the first word of its maps' names after `bytes/`.
    pub const fn id(self) -> &'static str {
        match self {
            Shape::Ring => "ring",
            Shape::Star => "star",
            Shape::Polyomino => "polyomino",
            Shape::Chamfer => "chamfer",
            Shape::Comb => "comb",
            Shape::Corridor => "corridor",
            Shape::Rooms => "rooms",
            Shape::Family => "family",
        }
    }

    /// Whether every map of the shape is orthogonal.
    pub const fn is_orthogonal(self) -> bool {
        matches!(self, Shape::Polyomino | Shape::Comb)
    }
}

/// The largest vertex count a shape aims at (a mutated family may exceed
/// it only if the family itself does, which none at these parameters do).
pub const MAX_VERTICES: usize = 30;

/// A valid map built from the bytes (module doc).
pub fn map_from_bytes(u: &mut Unstructured<'_>) -> arbitrary::Result<Map> {
    shaped_map_from_bytes(u).map(|(_, map)| map)
}

/// [`map_from_bytes`] with the shape the map was built as (after any
/// fallback: a rejected [`Shape::Ring`] gives a [`Shape::Star`]).
pub fn shaped_map_from_bytes(u: &mut Unstructured<'_>) -> arbitrary::Result<(Shape, Map)> {
    let shape = SHAPES[u.choose_index(SHAPES.len())?];
    match shape {
        Shape::Ring => match ring(u)? {
            Some(map) => Ok((Shape::Ring, map)),
            None => star(u).map(|m| (Shape::Star, m)),
        },
        Shape::Star => star(u).map(|m| (shape, m)),
        Shape::Polyomino => polyomino(u).map(|m| (shape, m)),
        Shape::Chamfer => chamfer(u).map(|m| (shape, m)),
        Shape::Comb => comb(u).map(|m| (shape, m)),
        Shape::Corridor => match corridor(u)? {
            Some(map) => Ok((shape, map)),
            None => comb(u).map(|m| (Shape::Comb, m)),
        },
        Shape::Rooms => match rooms(u)? {
            Some(map) => Ok((shape, map)),
            None => comb(u).map(|m| (Shape::Comb, m)),
        },
        Shape::Family => family(u).map(|m| (shape, m)),
    }
}

/// How many bytes [`map_from_seed`] draws.
pub const SEED_BYTES: usize = 256;

/// The map of [`SEED_BYTES`] bytes drawn from `ChaCha8Rng::seed_from_u64(seed)`
/// (the map kind "bytes" of `wai check`), or the unit square if they do not
/// make one. Its name ends in `seed=<seed>`.
///
/// ```
/// let a = wai_gen::bytes::map_from_seed(5);
/// assert_eq!(a, wai_gen::bytes::map_from_seed(5));
/// assert!(a.name().unwrap().ends_with("seed=5"));
/// ```
pub fn map_from_seed(seed: u64) -> Map {
    use rand::RngCore;
    let mut bytes = [0u8; SEED_BYTES];
    ChaCha8Rng::seed_from_u64(seed).fill_bytes(&mut bytes);
    let map = map_from_bytes(&mut Unstructured::new(&bytes)).unwrap_or_else(|_| unit_square());
    let name = map.name().unwrap_or("bytes/square").to_owned();
    map.with_name(format!("{name} seed={seed}"))
}

/// The fallback of [`map_from_seed`].
fn unit_square() -> Map {
    let ring = vec![
        Point::new(0, 0),
        Point::new(1, 0),
        Point::new(1, 1),
        Point::new(0, 1),
    ];
    crate::ring::into_map(ring, "bytes/square")
}

/// A generator seeded with eight bytes of the input.
fn rng(u: &mut Unstructured<'_>) -> arbitrary::Result<ChaCha8Rng> {
    Ok(ChaCha8Rng::seed_from_u64(u.arbitrary()?))
}

/// The map of `ring` if [`Map::from_ring`] accepts it (normalised: a
/// clockwise ring reversed, 180° vertices dropped), named `name`.
fn validated(ring: Vec<Point>, name: String) -> Option<Map> {
    Map::from_ring(ring)
        .ok()
        .map(|(map, _)| map.with_name(name))
}

/// [`Shape::Ring`]: 3 to 16 lattice points of `[0, range]²`, `range` 3 to
/// 15, in the order read; `None` if they do not make a simple polygon.
fn ring(u: &mut Unstructured<'_>) -> arbitrary::Result<Option<Map>> {
    let count = u.int_in_range(3..=16usize)?;
    let range = u.int_in_range(3..=15i128)?;
    let mut points = Vec::with_capacity(count);
    for _ in 0..count {
        points.push(Point::new(
            u.int_in_range(0..=range)?,
            u.int_in_range(0..=range)?,
        ));
    }
    Ok(validated(
        points,
        format!("bytes/ring n={count} range={range}"),
    ))
}

/// [`Shape::Star`]: `random-simple-star` with 3 to 12 vertices.
fn star(u: &mut Unstructured<'_>) -> arbitrary::Result<Map> {
    let n = u.int_in_range(3..=12usize)?;
    let mut rng = rng(u)?;
    let ring = simple::star_ring(n, 4 * n as i128 + 8, &mut rng);
    Ok(crate::ring::into_map(ring, format!("bytes/star n={n}")))
}

/// [`Shape::Polyomino`]: a grown polyomino of at most 16 cells that stops
/// at 4 to 24 vertices, on the unit grid or with columns and rows 1 to 3
/// wide.
fn polyomino(u: &mut Unstructured<'_>) -> arbitrary::Result<Map> {
    let min_vertices = u.int_in_range(4..=24usize)?;
    let max_cells = u.int_in_range(1..=16usize)?;
    let stretched = u.arbitrary::<bool>()?;
    let mut rng = rng(u)?;
    let poly = polyomino::grow(min_vertices, max_cells, &mut rng);
    let (w, h) = poly.extent();
    let ring = if stretched {
        let mut widths = |k: usize| -> arbitrary::Result<Vec<i128>> {
            (0..k).map(|_| u.int_in_range(1..=3i128)).collect()
        };
        let (cols, rows) = (widths(w)?, widths(h)?);
        poly.ring_with_widths(&cols, &rows)
    } else {
        poly.ring()
    };
    Ok(crate::ring::into_map(
        ring,
        format!(
            "bytes/polyomino cells={} min_vertices={min_vertices} stretched={stretched}",
            poly.len()
        ),
    ))
}

/// [`Shape::Chamfer`]: `special-chamfer` with exactly 4 to 24 vertices.
fn chamfer(u: &mut Unstructured<'_>) -> arbitrary::Result<Map> {
    let n = u.int_in_range(4..=24usize)?;
    let mut rng = rng(u)?;
    Ok(crate::ring::into_map(
        special::chamfered_ring(n, &mut rng),
        format!("bytes/chamfer n={n}"),
    ))
}

/// [`Shape::Comb`]: `special-comb` with 1 to 6 niches (`n = 4 + 4·niches`).
fn comb(u: &mut Unstructured<'_>) -> arbitrary::Result<Map> {
    let niches = u.int_in_range(1..=6usize)?;
    let mut rng = rng(u)?;
    Ok(crate::ring::into_map(
        special::comb_ring(niches, &mut rng),
        format!("bytes/comb niches={niches}"),
    ))
}

/// [`Shape::Corridor`]: the jittered [`RepeatedLayout`] of a seed from the
/// bytes, cut down to 2 funnels (3 when its pitch ratio `k` is 1) and 0 or
/// 1 extra niche at each end: 20 to 32 vertices. `None` if the cut layout's
/// ring is rejected (it never is for the seeded ranges; checked anyway).
fn corridor(u: &mut Unstructured<'_>) -> arbitrary::Result<Option<Map>> {
    let seed: u64 = u.arbitrary()?;
    let mut l = RepeatedLayout::of_seed(seed);
    l.funnels = if l.k == 1 {
        u.int_in_range(2..=3i128)?
    } else {
        2
    };
    let extra = if l.funnels == 3 {
        0
    } else {
        u.int_in_range(0..=1i128)?
    };
    l.niches = (l.funnels - 1) * l.k + 1 + 2 * extra;
    l.margin = l.north_pitch * (extra + 1);
    Ok(validated(
        l.ring(),
        format!(
            "bytes/corridor repeated-niches seed={seed} funnels={} niches={}",
            l.funnels, l.niches
        ),
    ))
}

/// [`Shape::Rooms`]: [`SharedLayout::plain`] with `view` 1, one or two
/// rooms, pitch 50 to 90, depth 8 to 24 and a chamber depth in its allowed
/// range; a single room may get one spike on every back wall, at the
/// neck's axis or where the view from a pitch away lands (as
/// [`SharedLayout::spiked`] places them). 20 to 29 vertices. `None` if the
/// spiked ring is rejected.
fn rooms(u: &mut Unstructured<'_>) -> arbitrary::Result<Option<Map>> {
    let rooms = u.int_in_range(1..=2i128)?;
    let pitch = u.int_in_range(50..=90i128)?;
    let depth = u.int_in_range(8..=24i128)?;
    let chamber_depth = u.int_in_range((depth + 3) / 4..=depth)?;
    let mut l = SharedLayout::plain(1, rooms, pitch, depth, chamber_depth);
    let spike = if rooms == 1 {
        let s = pitch * chamber_depth / (l.height + depth);
        match u.int_in_range(0..=3u8)? {
            1 => Some(0),
            2 => Some(s),
            3 => Some(-s),
            _ => None,
        }
    } else {
        None
    };
    l.spikes.extend(spike);
    Ok(validated(
        l.ring(),
        format!(
            "bytes/rooms rooms={rooms} pitch={pitch} depth={depth} \
             chamber_depth={chamber_depth} spike={spike:?}"
        ),
    ))
}

/// [`Shape::Family`]: a thesis family at small parameters (at most 28
/// vertices), then 0 to 4 mutation moves (at most [`MAX_VERTICES`]
/// vertices, coordinates below 2^16; an orthogonal family stays
/// orthogonal).
fn family(u: &mut Unstructured<'_>) -> arbitrary::Result<Map> {
    let (id, params): (&str, Vec<u32>) = match u.int_in_range(0..=4u8)? {
        0 => ("corridor-niches", vec![u.int_in_range(1..=4)?]),
        1 => (
            "comb-convex-chain",
            vec![u.int_in_range(1..=3)?, u.int_in_range(2..=4)?],
        ),
        2 => ("overlap-fan", vec![0]),
        3 => (
            "convex-niches",
            vec![u.int_in_range(1..=2)?, u.int_in_range(1..=2)?],
        ),
        _ => ("window-grid", vec![u.int_in_range(1..=2)?]),
    };
    let moves = u.int_in_range(0..=4usize)?;
    let mut rng = rng(u)?;
    let Ok(mut map) = crate::family(id, &params) else {
        // Every parameter above is in its family's range.
        return comb(u);
    };
    let limits = Limits {
        max_n: MAX_VERTICES.max(map.n()),
        min_n: 4,
        max_coord_bits: 16,
        keep_orthogonal: true,
    };
    let mut made = 0;
    for _ in 0..moves {
        if let Some(m) = mutate(&map, &limits, &mut rng) {
            map = m.map;
            made += 1;
        }
    }
    let params: Vec<String> = params.iter().map(u32::to_string).collect();
    Ok(map.with_name(format!(
        "bytes/family {id} params={} moves={made}",
        params.join(",")
    )))
}
