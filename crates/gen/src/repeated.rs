//! Seeded maps with **repeated** rooms: a corridor with identical funnels
//! in its south wall and identical flared niches in its north wall, at
//! pitches that fit each other, so that a point deep in one funnel and the
//! same point in the next have one skeleton — the configuration of
//! chapter 4 (Figs 4.1, 4.2, Lemma 4.1), which random maps almost never
//! have. The parameters (pitches, widths, depths, flare, corridor height,
//! how many of each) are jittered per seed; within one map the pattern is
//! exactly periodic, as equal skeletons need.
//!
//! Funnels that widen upwards have kernels shaped like upward wedges, so
//! neighbouring embeddings overlap not only in their skeleton polygons
//! (Theorem 4.2's premise) but often in their kernels too (Theorem 4.3's).

use crate::ring::into_map;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use wai_exact::Point;
use wai_map::Map;

/// The parameters of one [`repeated_niches`] map.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RepeatedLayout {
    /// North niche pitch `q`; the funnel pitch is `k·q`.
    pub north_pitch: i128,
    pub k: i128,
    /// Funnels: count, width at the bottom and at the top (`≥` bottom),
    /// depth.
    pub funnels: i128,
    pub funnel_bottom: i128,
    pub funnel_top: i128,
    pub funnel_depth: i128,
    /// North niches: count, opening width, back width (`>` opening), depth.
    pub niches: i128,
    pub niche_mouth: i128,
    pub niche_back: i128,
    pub niche_depth: i128,
    /// Corridor height and the x of the first funnel's centre (the first
    /// niche's centre is on `x = margin` too).
    pub height: i128,
    pub margin: i128,
}

impl RepeatedLayout {
    /// The jittered layout of `seed`.
    pub fn of_seed(seed: u64) -> RepeatedLayout {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let q = 2 * rng.random_range(3..=8i128);
        let k = rng.random_range(1..=2i128);
        let funnels = rng.random_range(2..=4i128);
        // Half the seeds: shallow funnels flared to half the pitch under a
        // tall corridor, whose kernels are wide enough to overlap.
        let wide = rng.random_bool(0.5);
        let funnel_bottom = if wide {
            2
        } else {
            2 * rng.random_range(1..=(q * k / 4).max(1))
        };
        let funnel_top = if wide {
            2 * (q * k / 4)
        } else {
            funnel_bottom + 2 * rng.random_range(0..=(q * k / 2 - funnel_bottom) / 2)
        };
        let funnel_depth = if wide {
            rng.random_range(2..=q / 2)
        } else {
            rng.random_range(2..=3 * q)
        };
        let height = if wide {
            rng.random_range(2 * q..=4 * q)
        } else {
            rng.random_range(q / 2..=3 * q)
        };
        let niche_back = 2 * rng.random_range(2..=(q / 2 - 1).max(2));
        let niche_mouth = 2 * rng.random_range(1..=niche_back / 2 - 1);
        let extra = rng.random_range(1..=3i128);
        RepeatedLayout {
            north_pitch: q,
            k,
            funnels,
            funnel_bottom,
            funnel_top,
            funnel_depth,
            niches: (funnels - 1) * k + 1 + 2 * extra,
            niche_mouth,
            niche_back,
            niche_depth: rng.random_range(1..=q),
            height,
            margin: q * (extra + 1),
        }
    }

    /// The jittered layout of `seed` whose neighbouring funnels' kernels
    /// meet below the ceiling: funnels at every niche pitch, flared (the
    /// mouth wider than the bottom), under a corridor taller than the
    /// height where the upward wedges of two neighbours cross. The
    /// embeddings of the funnels' skeleton then overlap in their kernels
    /// (Theorem 4.3's premise), which the seeds of
    /// [`RepeatedLayout::of_seed`] reach only now and then.
    pub fn kernels_of_seed(seed: u64) -> RepeatedLayout {
        let mut rng = ChaCha8Rng::seed_from_u64(seed ^ 0x006b_6572_6e65_6c73);
        let q = 2 * rng.random_range(3..=8i128);
        let funnels = rng.random_range(2..=4i128);
        // Half widths of the bottom and the mouth: hb < ht < q/2, so the
        // funnels flare and their mouths stay apart (q ≥ 6).
        let hb = rng.random_range(1..=(q / 2 - 2).min(2));
        let ht = rng.random_range(hb + 1..=q / 2 - 1);
        let depth = rng.random_range(2..=(q / 2).max(2));
        // A wedge's half width at height h over the mouth is ht + h(ht −
        // hb)/depth; two wedges q apart cross where that reaches q/2.
        let meet = ((q / 2 - ht) * depth).div_euclid(ht - hb) + 1;
        let niche_back = 2 * rng.random_range(2..=(q / 2 - 1).max(2));
        let niche_mouth = 2 * rng.random_range(1..=niche_back / 2 - 1);
        let extra = rng.random_range(1..=3i128);
        RepeatedLayout {
            north_pitch: q,
            k: 1,
            funnels,
            funnel_bottom: 2 * hb,
            funnel_top: 2 * ht,
            funnel_depth: depth,
            niches: funnels + 2 * extra,
            niche_mouth,
            niche_back,
            niche_depth: rng.random_range(1..=q),
            height: meet + rng.random_range(2..=2 * q),
            margin: q * (extra + 1),
        }
    }

    /// The centre of funnel `i`.
    pub fn funnel_x(&self, i: i128) -> i128 {
        self.margin + (self.extra() + i * self.k) * self.north_pitch
    }

    fn extra(&self) -> i128 {
        (self.niches - (self.funnels - 1) * self.k - 1) / 2
    }

    /// The centre of north niche `j`.
    fn niche_x(&self, j: i128) -> i128 {
        self.margin + j * self.north_pitch
    }

    /// The corridor's east end.
    fn length(&self) -> i128 {
        self.niche_x(self.niches - 1) + self.margin
    }

    /// A point deep in each funnel, at the same place in each: the
    /// candidates for witnesses of the repeated skeleton.
    pub fn viewpoints(&self) -> Vec<Point> {
        (0..self.funnels)
            .map(|i| Point::new(self.funnel_x(i), 1 - self.funnel_depth))
            .collect()
    }
}

/// The map of a jittered [`RepeatedLayout`]: counter-clockwise from the
/// south-west corner, the south wall eastwards with its funnels, then the
/// north wall westwards with its niches.
///
/// ```
/// let m = wai_gen::repeated_niches(7);
/// assert!(m.n() >= 20 && m.r() >= 4);
/// ```
pub fn repeated_niches(seed: u64) -> Map {
    into_map(
        RepeatedLayout::of_seed(seed).ring(),
        format!("repeated-niches seed={seed}"),
    )
}

/// The map of [`RepeatedLayout::kernels_of_seed`]: repeated funnels whose
/// embeddings overlap in their kernels.
///
/// ```
/// let m = wai_gen::kernel_funnels(3);
/// assert!(m.n() >= 20 && m.r() >= 4);
/// ```
pub fn kernel_funnels(seed: u64) -> Map {
    into_map(
        RepeatedLayout::kernels_of_seed(seed).ring(),
        format!("kernel-funnels seed={seed}"),
    )
}

impl RepeatedLayout {
    /// The ring of the layout (see [`repeated_niches`]); valid for the
    /// layouts of [`RepeatedLayout::of_seed`], and for hand-made ones only
    /// when their niches and funnels fit their pitches (`wai_gen::bytes`
    /// validates it).
    pub(crate) fn ring(&self) -> Vec<Point> {
        let l = self;
        let p = Point::new;
        let mut ring = vec![p(0, 0)];
        let (hb, ht) = (l.funnel_bottom / 2, l.funnel_top / 2);
        for i in 0..l.funnels {
            let x = l.funnel_x(i);
            ring.extend([
                p(x - ht, 0),
                p(x - hb, -l.funnel_depth),
                p(x + hb, -l.funnel_depth),
                p(x + ht, 0),
            ]);
        }
        let len = l.length();
        ring.extend([p(len, 0), p(len, l.height)]);
        let (hm, hk) = (l.niche_mouth / 2, l.niche_back / 2);
        let top = l.height + l.niche_depth;
        for j in (0..l.niches).rev() {
            let x = l.niche_x(j);
            ring.extend([
                p(x + hm, l.height),
                p(x + hk, top),
                p(x - hk, top),
                p(x - hm, l.height),
            ]);
        }
        ring.push(p(0, l.height));
        ring
    }
}
