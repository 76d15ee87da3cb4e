//! The thesis's worst-case constructions as parameterised families.
//!
//! Each family is a corridor running east–west (the south wall on `y = 0`)
//! with niches; each documents its exact vertex count `n`, its reflex
//! count `r`, and the structure it is built to have. Where the structure
//! rests on chosen viewpoints, a `*_viewpoints` function returns them, and
//! `tests/it/families.rs` checks with [`wai_exact::sees`] that they see
//! exactly the vertices claimed.

use crate::ring::into_map;
use crate::GenError;
use wai_exact::Point;
use wai_map::Map;

/// Largest vertex count a family call may produce.
pub const MAX_FAMILY_VERTICES: u64 = 1 << 20;

pub(crate) fn check_size(family: &'static str, n: u64) -> Result<(), GenError> {
    if n > MAX_FAMILY_VERTICES {
        return Err(GenError::TooLarge {
            family,
            n,
            max: MAX_FAMILY_VERTICES,
        });
    }
    Ok(())
}

fn need(family: &'static str, param: &'static str, value: u32, min: u32) -> Result<(), GenError> {
    if value < min {
        return Err(GenError::ParamTooSmall {
            family,
            param,
            value,
            min,
        });
    }
    Ok(())
}

fn p(x: i128, y: i128) -> Point {
    Point::new(x, y)
}

/// Appends a rectangular south niche `[a, a + w] × [-d, 0]` to a ring that
/// walks the south wall eastwards.
fn south_niche(ring: &mut Vec<Point>, a: i128, w: i128, d: i128) {
    ring.extend([p(a, 0), p(a, -d), p(a + w, -d), p(a + w, 0)]);
}

// ---------------------------------------------------------------------------
// corridor-niches

const CN_W: i128 = 2; // niche width
const CN_D: i128 = 4; // niche depth
const CN_H: i128 = 4; // corridor height
const CN_P: i128 = 4; // niche pitch
const CN_M: i128 = 4; // corridor margin west and east of the niches

/// Family `corridor-niches`, Lemma 3.7 (tightness, Fig 3.12 extended): a
/// corridor `[0, 4k + 6] × [0, 4]` with `k ≥ 1` identical rectangular south
/// niches `[4 + 4i, 6 + 4i] × [-4, 0]`, `i < k`, and a straight north wall
/// (the proof notes the northern niches of Fig 3.12 "could also be replaced
/// by one long edge").
///
/// `n = 4k + 4`, `r = 2k` (the niche mouth corners).
///
/// Structure: the viewpoint `(5 + 4i, -3)` deep in niche `i`
/// ([`corridor_niches_viewpoints`]) sees exactly the four vertices of its
/// niche, and its visibility polygon is the translate by `(4i, 0)` of that
/// of niche 0; so one skeleton has `k = r/2` embeddings (Ω(r), claim
/// L3.7t).
pub fn corridor_niches(k: u32) -> Result<Map, GenError> {
    const F: &str = "corridor-niches";
    need(F, "k", k, 1)?;
    check_size(F, 4 * u64::from(k) + 4)?;
    let k = i128::from(k);
    let len = 2 * CN_M + (k - 1) * CN_P + CN_W;
    let mut ring = vec![p(0, 0)];
    for i in 0..k {
        south_niche(&mut ring, CN_M + i * CN_P, CN_W, CN_D);
    }
    ring.extend([p(len, 0), p(len, CN_H), p(0, CN_H)]);
    Ok(into_map(ring, format!("{F}/k={k}")))
}

/// The viewpoints of [`corridor_niches`]: `(5 + 4i, -3)` for `i < k`.
pub fn corridor_niches_viewpoints(k: u32) -> Vec<Point> {
    (0..i128::from(k))
        .map(|i| p(CN_M + i * CN_P + CN_W / 2, -3))
        .collect()
}

// ---------------------------------------------------------------------------
// comb-convex-chain

/// The layout of [`comb_convex_chain`], exposed for its tests.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CombLayout {
    /// Horizontal scale `S` of the chain: chain vertex `u` is
    /// `(S·u, u·(U − u))`.
    pub scale: i128,
    /// `U = chain + 3`; the corridor's south wall runs from `(0, 0)` to
    /// `(S·U, 0)`.
    pub u_max: i128,
    /// The `u` of the chain vertices west of the comb, `1..=⌈chain/2⌉`.
    pub west: Vec<i128>,
    /// The `u` of the chain vertices east of the comb,
    /// `U − ⌊chain/2⌋..U`.
    pub east: Vec<i128>,
    /// West mouth corner x of each niche (the niches are
    /// `[a, a + w] × [−w, 0]`).
    pub niche_x: Vec<i128>,
    /// Niche width `w` (= depth).
    pub width: i128,
}

impl CombLayout {
    fn new(niches: i128, chain: i128) -> Self {
        let west_n = (chain + 1) / 2;
        let east_n = chain / 2;
        let u_max = chain + 3;
        let scale = ((u_max * u_max + 3) / 4).max(2 * (2 * niches - 1));
        let width = scale / (2 * niches - 1);
        let a0 = scale * (west_n + 1) + (scale - (2 * niches - 1) * width) / 2;
        CombLayout {
            scale,
            u_max,
            west: (1..=west_n).collect(),
            east: (u_max - east_n..u_max).collect(),
            niche_x: (0..niches).map(|i| a0 + 2 * i * width).collect(),
            width,
        }
    }

    /// The chain vertex with parameter `u`.
    pub fn chain_vertex(&self, u: i128) -> Point {
        p(self.scale * u, u * (self.u_max - u))
    }
}

/// Family `comb-convex-chain`, Thm 3.9 (tightness, Fig 3.15): a corridor
/// whose south wall `y = 0` carries `niches ≥ 1` square niches and whose
/// north side is a strictly convex chain of `chain ≥ 2` vertices on the
/// parabola `y = x (S·U − x) / S²` (vertex `u` is `(S·u, u·(U − u))`,
/// `U = chain + 3`, `S = max(⌈U²/4⌉, 4·niches − 2)`), which also passes
/// through the corridor's corners `(0, 0)` and `(S·U, 0)`. The chain
/// vertices split into `⌈chain/2⌉` west of the comb (`u = 1, 2, …`) and
/// `⌊chain/2⌋` east of it (`u = U − 1, U − 2, …`); the niches
/// (`w = ⌊S / (2·niches − 1)⌋` wide and deep, pitch `2w`) sit in
/// `[S·(⌈chain/2⌉ + 1), S·(⌈chain/2⌉ + 2)]`. See [`CombLayout`].
///
/// `n = 4·niches + chain + 2`, `r = 2·niches` (the mouth corners; the
/// chain and corridor corners are convex).
///
/// Structure: the corridor above `y = 0` is convex, so every chain vertex
/// sees every mouth corner; the visibility ray from a west chain vertex
/// through a niche's west mouth corner and the one from an east chain
/// vertex through its east mouth corner cross strictly inside the niche,
/// at depth at most `w/2` (both rays fall at least one unit per unit
/// down). So each niche holds `⌈chain/2⌉·⌊chain/2⌋` ray crossings:
/// Ω(n²) per niche, Ω(n²r) cells in all (claim T3.9c).
pub fn comb_convex_chain(niches: u32, chain: u32) -> Result<Map, GenError> {
    const F: &str = "comb-convex-chain";
    need(F, "niches", niches, 1)?;
    need(F, "chain", chain, 2)?;
    check_size(F, 4 * u64::from(niches) + u64::from(chain) + 2)?;
    let l = comb_layout(niches, chain);
    let mut ring = vec![p(0, 0)];
    for &a in &l.niche_x {
        south_niche(&mut ring, a, l.width, l.width);
    }
    ring.push(p(l.scale * l.u_max, 0));
    for &u in l.east.iter().rev().chain(l.west.iter().rev()) {
        ring.push(l.chain_vertex(u));
    }
    Ok(into_map(ring, format!("{F}/niches={niches},chain={chain}")))
}

/// The layout of `comb_convex_chain(niches, chain)` (parameters as there).
pub fn comb_layout(niches: u32, chain: u32) -> CombLayout {
    CombLayout::new(i128::from(niches.max(1)), i128::from(chain.max(2)))
}

// ---------------------------------------------------------------------------
// overlap-fan

const OF_P: i128 = 10; // pitch of both rows of niches

/// Family `overlap-fan`, the construction in the proof of Lemma 4.1 (Fig
/// 4.1 extended): a corridor `[0, 40z + 22] × [0, H]`, `H = 10z + 4`, with
/// `x = 2z + 1` rectangular south niches and `y = 4z + 1` trapezoidal north
/// niches, both at pitch 10.
///
/// North niche `j < 4z + 1`: mouth `[10 + 10j, 12 + 10j]` on `y = H`, back
/// wall `[7 + 10j, 15 + 10j]` on `y = H + 2` (the walls lean outwards, so
/// the back corners hide behind the mouth corners). South niche `i < 2z + 1`:
/// `[10 + 10(i + z), 12 + 10(i + z)] × [-2, 0]`, centred under north niche
/// `i + z`.
///
/// `n = 24z + 12`, `r = 12z + 4` (all mouth corners).
///
/// Structure: the viewpoint `(11 + 10(i + z), -1)` in south niche `i`
/// ([`overlap_fan_viewpoints`]) sees exactly the four vertices of its niche
/// and the two mouth corners of each north niche `i, …, i + 2z` — `2z + 1`
/// north niches, each seen through its mouth only, giving `2z + 1`
/// horizontal artificial edges — and its visibility polygon is the
/// translate by `(10i, 0)` of that of viewpoint 0. So one skeleton has
/// `2z + 1` embeddings, and the westmost and eastmost share the artificial
/// edge on north niche `2z`'s mouth, south of which all of them overlap
/// (claim L4.1).
pub fn overlap_fan(z: u32) -> Result<Map, GenError> {
    const F: &str = "overlap-fan";
    check_size(F, 24 * u64::from(z) + 12)?;
    let z = i128::from(z);
    let h = 10 * z + 4;
    let len = 40 * z + 22;
    let mut ring = vec![p(0, 0)];
    for i in 0..2 * z + 1 {
        south_niche(&mut ring, 10 + OF_P * (i + z), 2, 2);
    }
    ring.extend([p(len, 0), p(len, h)]);
    for j in (0..4 * z + 1).rev() {
        let m = 10 + OF_P * j;
        ring.extend([p(m + 2, h), p(m + 5, h + 2), p(m - 3, h + 2), p(m, h)]);
    }
    ring.push(p(0, h));
    Ok(into_map(ring, format!("{F}/z={z}")))
}

/// The viewpoints of [`overlap_fan`]: `(11 + 10(i + z), -1)`, `i ≤ 2z`.
pub fn overlap_fan_viewpoints(z: u32) -> Vec<Point> {
    let z = i128::from(z);
    (0..2 * z + 1).map(|i| p(11 + OF_P * (i + z), -1)).collect()
}

// ---------------------------------------------------------------------------
// convex-niches

/// The layout of [`convex_niches`], exposed for its tests.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ConvexNichesLayout {
    /// North niches seen by each viewpoint, `f`.
    pub fan: i128,
    /// Viewpoints, south niches and embeddings, `t`.
    pub views: i128,
    /// Half the pitch, `p`; niches repeat every `2p`.
    pub half_pitch: i128,
    /// The corridor height `H = f·p − 1`.
    pub height: i128,
    /// Dome vertices relative to a mouth centre, west to east:
    /// `B_q = λ_q·(2q − f, f)`, `λ_q = 3f² + 1 − (2q − f)²`, `q = 0..=f`.
    pub dome: Vec<Point>,
}

impl ConvexNichesLayout {
    fn new(fan: i128, views: i128) -> Self {
        let l = 3 * fan * fan + 1;
        let dome: Vec<Point> = (0..=fan)
            .map(|q| {
                let u = 2 * q - fan;
                let lambda = l - u * u;
                p(lambda * u, lambda * fan)
            })
            .collect();
        let half_pitch = dome.iter().map(|b| b.x.abs()).max().unwrap_or(0) + 3;
        ConvexNichesLayout {
            fan,
            views,
            half_pitch,
            height: fan * half_pitch - 1,
            dome,
        }
    }

    /// Number of north niches, `f + t − 1`.
    pub fn north_niches(&self) -> i128 {
        self.fan + self.views - 1
    }

    /// The mouth centre of north niche `j` on `y = H`: `x = 2p(j + 1)`.
    pub fn north_mouth(&self, j: i128) -> Point {
        p(2 * self.half_pitch * (j + 1), self.height)
    }

    /// The viewpoint in south niche `i`, `(2p(i + 1) + (f − 1)p, −1)`.
    pub fn viewpoint(&self, i: i128) -> Point {
        p(
            2 * self.half_pitch * (i + 1) + (self.fan - 1) * self.half_pitch,
            -1,
        )
    }
}

/// Family `convex-niches`, Lemma 5.3 (tightness, Fig 5.4):
/// `convex_niches(k) = convex_niches_with(k, k)`.
///
/// `n = 2k² + 9k + 1`, `r = 6k − 2`.
pub fn convex_niches(k: u32) -> Result<Map, GenError> {
    convex_niches_with(k, k)
}

/// Family `convex-niches` with `s − 2 = fan ≥ 1` horizontal artificial
/// edges and `t = views ≥ 1` embeddings (Fig 5.4 (a), (b)): a corridor
/// `[0, 2p(f + t + 1)] × [0, H]` with `t` rectangular south niches
/// `[c − 1, c + 1] × [−2, 0]` around the viewpoints `(c, −1)` and
/// `f + t − 1` identical convex north niches, each a mouth of width 2 and
/// a convex dome of `f + 1` vertices `B_0, …, B_f` (see
/// [`ConvexNichesLayout`]; `p` and `H = f·p − 1` grow like `f³`).
///
/// `n = 4 + 4t + (f + t − 1)(f + 3)`, `r = 2t + 2(f + t − 1)` (the mouth
/// corners; every dome vertex is convex).
///
/// Structure: viewpoint `i` ([`convex_niches_viewpoints`]) sees exactly the
/// four vertices of its south niche and the two mouth corners of north
/// niches `i, …, i + f − 1`; through the mouth of north niche `i + q` it
/// sees a piece of dome edge `B_q B_{q+1}` only (the ray from viewpoint
/// `i` through the mouth centre has direction `(2q − f + 1, f)`, strictly
/// between the directions `(2q − f, f)` of `B_q` and `(2q − f + 2, f)` of
/// `B_{q+1}`). The `t` visibility polygons are translates, so one skeleton
/// with `f` horizontal artificial edges has `t` embeddings, and its
/// artificial edge `q` in embedding `i` has the single candidate edge
/// `B_q B_{q+1}` of niche `i + q`: `f·t` distinct single candidate edges,
/// Ω(r²) for `f = t` (claim L5.3).
pub fn convex_niches_with(fan: u32, views: u32) -> Result<Map, GenError> {
    const F: &str = "convex-niches";
    need(F, "fan", fan, 1)?;
    need(F, "views", views, 1)?;
    let (f, t) = (u64::from(fan), u64::from(views));
    check_size(F, 4 + 4 * t + (f + t - 1) * (f + 3))?;
    let l = ConvexNichesLayout::new(i128::from(fan), i128::from(views));
    let (hp, h) = (l.half_pitch, l.height);
    let len = 2 * hp * (l.north_niches() + 1);
    let mut ring = vec![p(0, 0)];
    for i in 0..l.views {
        let c = l.viewpoint(i).x;
        south_niche(&mut ring, c - 1, 2, 2);
    }
    ring.extend([p(len, 0), p(len, h)]);
    for j in (0..l.north_niches()).rev() {
        let m = l.north_mouth(j);
        ring.push(p(m.x + 1, h));
        ring.extend(l.dome.iter().rev().map(|b| p(m.x + b.x, h + b.y)));
        ring.push(p(m.x - 1, h));
    }
    ring.push(p(0, h));
    Ok(into_map(ring, format!("{F}/fan={fan},views={views}")))
}

/// The viewpoints of [`convex_niches_with`]`(fan, views)`.
pub fn convex_niches_viewpoints(fan: u32, views: u32) -> Vec<Point> {
    let l = convex_niches_layout(fan, views);
    (0..l.views).map(|i| l.viewpoint(i)).collect()
}

/// The layout of [`convex_niches_with`]`(fan, views)`.
pub fn convex_niches_layout(fan: u32, views: u32) -> ConvexNichesLayout {
    ConvexNichesLayout::new(i128::from(fan.max(1)), i128::from(views.max(1)))
}
