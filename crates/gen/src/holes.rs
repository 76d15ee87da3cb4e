//! Random maps with holes (thesis sec. 2.1, 6.4): rooms with pillars and
//! simple polygons with holes, valid by construction-and-test.
//!
//! A base map of a random kind is drawn, enlarged so that holes fit between
//! its lattice points, and holes are proposed at random places and kept only
//! when the map with them is valid ([`wai_map::validate_rings`]: inside,
//! meeting no ring, in no other hole). Proposals that fail are counted
//! against a budget, so a crowded map gets fewer holes than asked, never a
//! bad one.

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use wai_exact::Point;
use wai_map::Map;

/// A kind of random map with holes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct HoledKindInfo {
    pub id: &'static str,
    pub method: &'static str,
    pub min_n: usize,
    pub max_n: usize,
}

/// The kinds of random maps with holes, by id.
pub const HOLED_KINDS: &[HoledKindInfo] = &[
    HoledKindInfo {
        id: "orthogonal-pillars",
        method: "a random-orthogonal map enlarged 4 times with up to h axis-parallel \
                 rectangular pillars (1 to 3 units a side) on the lattice: pillars aligned \
                 with walls and with each other, as in real buildings",
        min_n: 4,
        max_n: 5_000,
    },
    HoledKindInfo {
        id: "simple-holes",
        method: "a random-simple-star map enlarged 8 times with up to h lattice triangles \
                 (sides up to 6 units) as holes: general position",
        min_n: 3,
        max_n: 5_000,
    },
    HoledKindInfo {
        id: "repeated-niches-pillars",
        method: "the repeated-niches layout of chapter 4 (seed), enlarged 4 times, with up to \
                 h rectangular pillars: overlapping embeddings of one skeleton beside pillars \
                 (Theorem 4.2 with holes); n is ignored",
        min_n: 1,
        max_n: 5_000,
    },
    HoledKindInfo {
        id: "kernel-funnels-pillars",
        method: "the kernel-funnels layout of chapter 4 (seed), enlarged 4 times, with up to \
                 h rectangular pillars: overlapping kernels beside pillars (Theorem 4.3 with \
                 holes); n is ignored",
        min_n: 1,
        max_n: 5_000,
    },
];

/// A random map of `kind` (see [`HOLED_KINDS`]) with about `n` outer
/// vertices and up to `holes` holes, a deterministic function of
/// `(kind, n, holes, seed)`.
pub fn random_with_holes(
    kind: &str,
    n: usize,
    holes: usize,
    seed: u64,
) -> Result<Map, crate::GenError> {
    let info = HOLED_KINDS
        .iter()
        .find(|k| k.id == kind)
        .ok_or_else(|| crate::GenError::UnknownKind(kind.to_owned()))?;
    if n < info.min_n || n > info.max_n {
        return Err(crate::GenError::SizeOutOfRange {
            kind: info.id,
            n,
            min: info.min_n,
            max: info.max_n,
        });
    }
    let (base, factor) = match info.id {
        "orthogonal-pillars" => (crate::random("random-orthogonal", n, seed)?, 4),
        "simple-holes" => (crate::random("random-simple-star", n, seed)?, 8),
        layout => {
            let id = layout.trim_end_matches("-pillars");
            (crate::layout(id, seed)?, 4)
        }
    };
    let outer: Vec<Point> = base
        .vertices()
        .iter()
        .map(|p| Point::new(p.x * factor, p.y * factor))
        .collect();
    let (lo, hi) = bounds(&outer);
    let mut rng = ChaCha8Rng::seed_from_u64(seed ^ 0x401e_5eed);
    let mut kept: Vec<Vec<Point>> = Vec::new();
    let mut budget = 40 * holes + 40;
    while kept.len() < holes && budget > 0 {
        budget -= 1;
        let x = rng.random_range(lo.x..hi.x);
        let y = rng.random_range(lo.y..hi.y);
        let hole = if info.id != "simple-holes" {
            let (w, h) = (rng.random_range(1..=3), rng.random_range(1..=3));
            vec![
                Point::new(x, y),
                Point::new(x, y + h),
                Point::new(x + w, y + h),
                Point::new(x + w, y),
            ]
        } else {
            let mut d = || (rng.random_range(-6..=6), rng.random_range(-6..=6));
            let (a, b) = (d(), d());
            vec![
                Point::new(x, y),
                Point::new(x + a.0, y + a.1),
                Point::new(x + b.0, y + b.1),
            ]
        };
        kept.push(hole);
        if !wai_map::validate_rings(&outer, &kept).is_empty() {
            kept.pop();
        }
    }
    let count = kept.len();
    let (map, _) = Map::from_rings(outer, kept).expect("every hole kept was validated");
    Ok(map.with_name(format!("{}/n={n},holes={count},seed={seed}", info.id)))
}

fn bounds(ring: &[Point]) -> (Point, Point) {
    let xs = ring.iter().map(|p| p.x);
    let ys = ring.iter().map(|p| p.y);
    (
        Point::new(xs.clone().min().unwrap_or(0), ys.clone().min().unwrap_or(0)),
        Point::new(xs.max().unwrap_or(1), ys.max().unwrap_or(1)),
    )
}

/// A room whose north wall is a convex chain of k vertices and with k
/// small triangular pillars in a row below it (thesis sec. 6.4: with holes,
/// Ω(n²r²) cells become possible). Every chain vertex sees every pillar, so
/// each pillar sends about 2k visibility rays south (away from the chain
/// vertices, tangent to the pillar), and rays of different pillars cross
/// in the open room before the south wall, far below: Θ(k²) rays and up
/// to Θ(k⁴) crossings, with n = 4k + 4 and r = 3k (the pillar corners; the
/// chain's vertices are convex). Measured (`benches/results/cells/
/// pillar-rays.md`), cells / (n²r) grows with k where Thm 3.9 bounds it
/// for maps without holes; the pillars' corners are perturbed so that the
/// rays are in general position.
pub fn pillar_rays(k: u32) -> Map {
    let k = i128::from(k.max(1));
    let width = 100 * (k + 1);
    let depth = 10_000 * k * k;
    // South corners, then the east wall's top, the chain from east to
    // west (bulging north: convex corners), the west wall's top.
    let mut outer = vec![Point::new(0, -depth), Point::new(width, -depth)];
    for m in (0..=k + 1).rev() {
        outer.push(Point::new(100 * m, 10 * m * (k + 1 - m)));
    }
    let mut holes = Vec::new();
    for i in 0..k {
        let (cx, cy) = (100 * i + 50 + (i * 7) % 13, -100 - (i * 11) % 17);
        holes.push(vec![
            Point::new(cx - 4, cy),
            Point::new(cx + 3 + i % 3, cy + 1),
            Point::new(cx + (i % 5) - 2, cy - 5),
        ]);
    }
    let (map, _) = Map::from_rings(outer, holes).expect("pillars apart below a convex chain");
    map.with_name(format!("pillar-rays k={k}"))
}
