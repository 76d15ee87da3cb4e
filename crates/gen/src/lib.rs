//! Seeded generators of valid maps: random simple and
//! orthogonal polygons, all small polyominoes, collinearity-biased
//! "special" maps, and the thesis's worst-case families (Figs 3.12, 3.15,
//! 4.1, 5.4), seeded layouts for the chapter 4 and 5 claims (overlapping
//! embeddings, crossing, interweaved and shared candidate edges), plus
//! proptest strategies and a quickcheck `Arbitrary`.
//!
//! Every generator builds a ring that is valid by construction — simple,
//! counter-clockwise, no 180° vertex — and returns the [`wai_map::Map`] of
//! it; `Map::from_ring` never rejects nor normalises it (a violation is a
//! bug of this crate and panics). Random generators are deterministic
//! functions of their seed ([`rand_chacha::ChaCha8Rng::seed_from_u64`]).
//!
//! Entry points by id, for the CLI and the benches:
//! - [`family`]`(id, params)` with the ids of [`FAMILIES`];
//! - [`random`]`(kind, n, seed)` with the ids of [`RANDOM_KINDS`];
//! - [`layout`]`(id, seed)` with the ids of [`LAYOUTS`];
//! - [`exhaustive_polyomino_maps`] for the exhaustive mode;
//! - [`bytes::map_from_bytes`] for the fuzz targets: a small valid map
//!   of one of several shapes from an `arbitrary::Unstructured` byte
//!   stream, and [`bytes::map_from_seed`] for the same from a seed.
//!
//! # Invariant
//! No decision reads a float: angular order, crossings and collinearity
//! are decided by `wai_exact` predicates on integer points.

mod bottles;
pub mod bytes;
mod families;
mod grid;
mod holes;
mod indoor;
mod interweave;
pub mod mutate;
mod polyomino;
mod repeated;
mod ring;
mod simple;
mod special;
mod strategies;

pub use bottles::{bottled_niches, BottleLayout};
pub use families::{
    comb_convex_chain, comb_layout, convex_niches, convex_niches_layout, convex_niches_viewpoints,
    convex_niches_with, corridor_niches, corridor_niches_viewpoints, overlap_fan,
    overlap_fan_viewpoints, CombLayout, ConvexNichesLayout, MAX_FAMILY_VERTICES,
};
pub use grid::window_grid;
pub use holes::{pillar_rays, random_with_holes, HoledKindInfo, HOLED_KINDS};
pub use indoor::{office, repeated_rooms};
pub use interweave::{
    interweaved_gaps, shared_niches, shared_spiked_niches, CeilingNotch, PinholeLayout,
    SharedLayout,
};
pub use polyomino::{
    exhaustive_polyomino_maps, has_simple_boundary, polyominoes, Cell, Polyomino, Symmetry,
};
pub use repeated::{kernel_funnels, repeated_niches, RepeatedLayout};
pub use ring::{reflex_count, ring_problem};
pub use strategies::{
    arb_map, arb_orthogonal_map, arb_polyomino, arb_simple_map, shrink_map, ArbMap,
    PolyominoStrategy,
};

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use wai_map::Map;

/// What a generator entry point can reject.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum GenError {
    #[error("unknown family {0:?} (known: {known})", known = family_ids())]
    UnknownFamily(String),
    #[error("unknown random kind {0:?} (known: {known})", known = kind_ids())]
    UnknownKind(String),
    #[error("unknown layout {0:?} (known: {known})", known = layout_ids())]
    UnknownLayout(String),
    #[error("family {family} takes {expected} parameters, got {got}")]
    ParamCount {
        family: &'static str,
        expected: &'static str,
        got: usize,
    },
    #[error("family {family}: parameter {param} = {value} is below its minimum {min}")]
    ParamTooSmall {
        family: &'static str,
        param: &'static str,
        value: u32,
        min: u32,
    },
    #[error("family {family} would have {n} vertices, more than {max}")]
    TooLarge {
        family: &'static str,
        n: u64,
        max: u64,
    },
    #[error("random kind {kind}: n = {n} is outside {min}..={max}")]
    SizeOutOfRange {
        kind: &'static str,
        n: usize,
        min: usize,
        max: usize,
    },
}

fn family_ids() -> String {
    FAMILIES.iter().map(|f| f.id).collect::<Vec<_>>().join(", ")
}

fn layout_ids() -> String {
    LAYOUTS.iter().map(|l| l.id).collect::<Vec<_>>().join(", ")
}

fn kind_ids() -> String {
    RANDOM_KINDS
        .iter()
        .map(|k| k.id)
        .collect::<Vec<_>>()
        .join(", ")
}

/// A thesis family: its id, its parameters and where it comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FamilyInfo {
    /// The id used by [`family`], the CLI (`gen --family ID --param P`),
    /// the benches and `CLAIMS.md`.
    pub id: &'static str,
    /// The parameters in order, `name ≥ min: meaning`.
    pub params: &'static str,
    /// The thesis statement and figure it realises.
    pub reference: &'static str,
    /// The claim ids of `CLAIMS.md` it is the family of.
    pub claims: &'static [&'static str],
    /// `n` as a function of the parameters.
    pub n: &'static str,
    /// `r` as a function of the parameters.
    pub r: &'static str,
}

/// The thesis families, by id.
pub const FAMILIES: &[FamilyInfo] = &[
    FamilyInfo {
        id: "corridor-niches",
        params: "k >= 1: number of identical south niches",
        reference: "Lemma 3.7 (tightness), Fig 3.12 extended",
        claims: &["L3.7t"],
        n: "4k + 4",
        r: "2k",
    },
    FamilyInfo {
        id: "comb-convex-chain",
        params: "niches >= 1: south niches; chain >= 2: vertices of the convex north chain \
                 (one parameter k means niches = chain = k)",
        reference: "Theorem 3.9 (tightness), Fig 3.15",
        claims: &["T3.9c", "T3.9b"],
        n: "4 niches + chain + 2",
        r: "2 niches",
    },
    FamilyInfo {
        id: "overlap-fan",
        params: "z >= 0: 2z + 1 south niches, 4z + 1 north niches, 2z + 1 overlapping embeddings",
        reference: "Lemma 4.1 (proof), Fig 4.1 extended",
        claims: &["L4.1"],
        n: "24z + 12",
        r: "12z + 4",
    },
    FamilyInfo {
        id: "convex-niches",
        params: "k >= 1: fan = views = k; or fan >= 1, views >= 1: artificial edges per \
                 skeleton (s - 2) and embeddings (t)",
        reference: "Lemma 5.3 (tightness), Fig 5.4",
        claims: &["L5.3", "T5.17t"],
        n: "4 + 4 views + (fan + views - 1)(fan + 3); 2k^2 + 9k + 1 for one parameter",
        r: "2 views + 2 (fan + views - 1); 6k - 2 for one parameter",
    },
    FamilyInfo {
        id: "window-grid",
        params: "c >= 1: pieces of each of the two broken walls",
        reference: "Theorem 5.17 (tightness: Omega(r^2) with n = Theta(r)), Fig 5.2",
        claims: &["T5.17t"],
        n: "8c + 12",
        r: "4c + 4",
    },
];

/// The map of family `id` with `params` (see [`FAMILIES`]).
///
/// ```
/// let m = wai_gen::family("corridor-niches", &[8]).unwrap();
/// assert_eq!((m.n(), m.r()), (36, 16));
/// assert!(wai_gen::family("no-such-family", &[1]).is_err());
/// ```
pub fn family(id: &str, params: &[u32]) -> Result<Map, GenError> {
    let count = |expected: &'static str, family: &'static str| GenError::ParamCount {
        family,
        expected,
        got: params.len(),
    };
    match id {
        "corridor-niches" => match *params {
            [k] => families::corridor_niches(k),
            _ => Err(count("1", "corridor-niches")),
        },
        "comb-convex-chain" => match *params {
            [k] => families::comb_convex_chain(k, k),
            [niches, chain] => families::comb_convex_chain(niches, chain),
            _ => Err(count("1 or 2", "comb-convex-chain")),
        },
        "overlap-fan" => match *params {
            [z] => families::overlap_fan(z),
            _ => Err(count("1", "overlap-fan")),
        },
        "window-grid" => match *params {
            [c] => grid::window_grid(c),
            _ => Err(count("1", "window-grid")),
        },
        "convex-niches" => match *params {
            [k] => families::convex_niches(k),
            [fan, views] => families::convex_niches_with(fan, views),
            _ => Err(count("1 or 2", "convex-niches")),
        },
        _ => Err(GenError::UnknownFamily(id.to_owned())),
    }
}

/// A random map kind: its id and what `n` means for it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct KindInfo {
    /// The id used by [`random`].
    pub id: &'static str,
    /// How the map is made.
    pub method: &'static str,
    /// The vertex count reached for a requested `n`.
    pub vertices: &'static str,
    /// Accepted `n`.
    pub min_n: usize,
    pub max_n: usize,
}

/// The random map kinds, by id.
pub const RANDOM_KINDS: &[KindInfo] = &[
    KindInfo {
        id: "random-simple-star",
        method: "star-shaped: n lattice points of [-(4n+8), 4n+8]^2 on distinct rays from the \
                 origin, sorted by exact angle; redrawn until the origin is strictly inside \
                 the kernel and no three consecutive vertices are collinear",
        vertices: "exactly n",
        min_n: 3,
        max_n: 20_000,
    },
    KindInfo {
        id: "random-simple-2opt",
        method: "2-opt untangling of a random tour of n lattice points of [0, 4n+8]^2 in \
                 general position (no three collinear)",
        vertices: "exactly n",
        min_n: 3,
        max_n: 300,
    },
    KindInfo {
        id: "random-orthogonal",
        method: "boundary of a randomly grown hole-free, pinch-free polyomino, columns and \
                 rows stretched by random widths 1..=4",
        vertices: "n' with max(n,4) <= n' <= max(n,4) + 3 (even)",
        min_n: 4,
        max_n: 20_000,
    },
    KindInfo {
        id: "special-orthogonal",
        method: "as random-orthogonal on the unit grid: few distinct coordinates, many \
                 collinear edges and vertices on common lines",
        vertices: "n' with max(n,4) <= n' <= max(n,4) + 3 (even)",
        min_n: 4,
        max_n: 20_000,
    },
    KindInfo {
        id: "special-comb",
        method: "corridor with unit niches in random slots of one common grid on both sides, \
                 depths 1 or 2: aligned walls and backs",
        vertices: "4 + 4 ceil((n - 4) / 4)",
        min_n: 4,
        max_n: 20_000,
    },
    KindInfo {
        id: "special-chamfer",
        method: "random polyomino scaled by 3 with random corners cut at 45 degrees: edges on \
                 few axis-parallel and diagonal lines",
        vertices: "exactly n",
        min_n: 4,
        max_n: 20_000,
    },
];

/// A random map of kind `kind` (see [`RANDOM_KINDS`]) with about `n`
/// vertices, a deterministic function of `(kind, n, seed)`.
///
/// ```
/// let a = wai_gen::random("random-simple-star", 12, 7).unwrap();
/// let b = wai_gen::random("random-simple-star", 12, 7).unwrap();
/// assert_eq!(a.vertices(), b.vertices());
/// assert_eq!(a.n(), 12);
/// ```
pub fn random(kind: &str, n: usize, seed: u64) -> Result<Map, GenError> {
    let info = RANDOM_KINDS
        .iter()
        .find(|k| k.id == kind)
        .ok_or_else(|| GenError::UnknownKind(kind.to_owned()))?;
    if n < info.min_n || n > info.max_n {
        return Err(GenError::SizeOutOfRange {
            kind: info.id,
            n,
            min: info.min_n,
            max: info.max_n,
        });
    }
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let range = 4 * n as i128 + 8;
    let ring = match info.id {
        "random-simple-star" => simple::star_ring(n, range, &mut rng),
        "random-simple-2opt" => simple::two_opt_ring(n, range, &mut rng),
        "random-orthogonal" => {
            let poly = polyomino::grow(n, usize::MAX, &mut rng);
            let (w, h) = poly.extent();
            let mut widths =
                |k: usize| -> Vec<i128> { (0..k).map(|_| rng.random_range(1..=4)).collect() };
            let (cols, rows) = (widths(w), widths(h));
            poly.ring_with_widths(&cols, &rows)
        }
        "special-orthogonal" => special::coarse_orthogonal_ring(n, &mut rng),
        "special-comb" => special::comb_ring((n - 4).div_ceil(4), &mut rng),
        "special-chamfer" => special::chamfered_ring(n, &mut rng),
        _ => unreachable!("every id of RANDOM_KINDS has a generator"),
    };
    Ok(ring::into_map(
        ring,
        format!("{}/n={n},seed={seed}", info.id),
    ))
}

/// A seeded layout: repeated rooms whose embeddings overlap (chapter 4) or
/// share candidate edges (chapter 5).
#[derive(Clone, Copy, Debug)]
pub struct LayoutInfo {
    pub id: &'static str,
    /// What its maps show.
    pub shows: &'static str,
    pub generate: fn(u64) -> Map,
}

/// The chapter 4 and 5 layouts, for [`layout`] and the CLI's `gen
/// --layout`.
pub const LAYOUTS: &[LayoutInfo] = &[
    LayoutInfo {
        id: "repeated-niches",
        shows: "funnels under a corridor with flared niches: overlapping valid embeddings, \
                often overlapping kernels (Figs 4.1, 4.2; T4.2, T4.3)",
        generate: repeated_niches,
    },
    LayoutInfo {
        id: "kernel-funnels",
        shows: "funnels flared under a corridor tall enough that neighbouring funnels' \
                kernels meet: overlapping valid embeddings with overlapping kernels \
                (Example 4.1, Fig 4.1; T4.3)",
        generate: kernel_funnels,
    },
    LayoutInfo {
        id: "bottled-niches",
        shows: "rooms under bottles with spiked back walls: artificial edges with two valid \
                candidate edges that cross the other room's (Fig 4.31; T4.19, C4.20)",
        generate: bottled_niches,
    },
    LayoutInfo {
        id: "interweaved-gaps",
        shows: "two pinhole rooms whose door cones sweep one ceiling of flats and notches: \
                gaps of two embeddings that are interweaved and nested (Def 5.6, Example \
                5.1, Fig 5.5; L5.5-L5.9)",
        generate: interweaved_gaps,
    },
    LayoutInfo {
        id: "shared-niches",
        shows: "rooms under bottles, each room seeing 5 or 7 backs: pairs of backs that are \
                candidate edges of different artificial edges in 4 or 6 embeddings (Figs \
                5.13-5.15; L5.13, L5.14)",
        generate: shared_niches,
    },
    LayoutInfo {
        id: "shared-spiked-niches",
        shows: "rooms under bottles with three spikes on each back wall: a pair of back \
                pieces, the second a multiple candidate edge, in 2 embeddings (T5.15)",
        generate: shared_spiked_niches,
    },
];

/// The map of layout `id` (one of [`LAYOUTS`]) for `seed`.
///
/// ```
/// let m = wai_gen::layout("bottled-niches", 1).unwrap();
/// assert_eq!(m, wai_gen::bottled_niches(1));
/// assert!(wai_gen::layout("nope", 1).is_err());
/// ```
pub fn layout(id: &str, seed: u64) -> Result<Map, GenError> {
    LAYOUTS
        .iter()
        .find(|l| l.id == id)
        .map(|l| (l.generate)(seed))
        .ok_or_else(|| GenError::UnknownLayout(id.to_owned()))
}
