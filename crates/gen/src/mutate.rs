//! Seeded mutations of maps, for the local search of `wai
//! search-extremes` and `wai check --target`.
//!
//! A [`Mutation`] proposes a new ring from a map's vertices: move a vertex,
//! shift an edge along its normal, insert a displaced vertex on an edge,
//! add a rectangular niche (or bump) on an edge, remove a vertex, collapse
//! an edge, or double every coordinate. Unlike the generators of this
//! crate, a proposal is **not** valid by construction: every one is handed
//! to [`Map::from_ring`], which refuses a self-intersecting or degenerate
//! ring with an error, and [`mutate`] draws again. Nothing here panics on
//! a bad proposal.
//!
//! Orthogonal maps stay orthogonal unless [`Limits::keep_orthogonal`] is
//! off: [`Mutation::ShiftEdge`], [`Mutation::AddNiche`],
//! [`Mutation::CollapseEdge`] and [`Mutation::Refine`] map an orthogonal
//! ring to an orthogonal one (a shift or a niche moves along an
//! axis-parallel normal; a collapse moves an edge onto its neighbour's
//! line), and the result is checked with [`Map::is_orthogonal`].
//!
//! Every draw comes from the caller's random number generator, so a seeded
//! generator gives the same mutants in the same order.
//!
//! # Invariant
//! No decision reads a float: proposals are integer vectors; validity is
//! decided by `wai_map`'s exact validation.

use rand::Rng;
use wai_exact::{gcd_u128, Point};
use wai_map::Map;

/// One mutation operator.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Mutation {
    /// Displace one vertex by a random integer vector.
    MoveVertex,
    /// Translate both ends of one edge by a multiple of its primitive
    /// normal (keeps an axis-parallel edge axis-parallel).
    ShiftEdge,
    /// Insert a vertex on an edge (a lattice point of it, or near its
    /// middle) and displace it.
    InsertVertex,
    /// Replace a piece `[p, q]` of an edge (lattice points of it) by the
    /// three sides of a rectangle: `p, p + D, q + D, q` with `D` a
    /// multiple of the edge's primitive normal, outwards (a niche) or
    /// inwards (a bump).
    AddNiche,
    /// Remove one vertex.
    RemoveVertex,
    /// Collapse edge `v_i v_{i+1}` by translating the next edge by
    /// `v_i - v_{i+1}`: `v_{i+1}` is removed and `v_{i+2}` moves along the
    /// line of the edge after it (or the mirror image, on the other side).
    CollapseEdge,
    /// Double every coordinate: the same map at a finer grid, so that
    /// later moves can be smaller relative to it.
    Refine,
}

impl Mutation {
    /// Every operator, in a fixed order.
    pub const ALL: [Mutation; 7] = [
        Mutation::MoveVertex,
        Mutation::ShiftEdge,
        Mutation::InsertVertex,
        Mutation::AddNiche,
        Mutation::RemoveVertex,
        Mutation::CollapseEdge,
        Mutation::Refine,
    ];

    /// Whether the operator maps an orthogonal ring to an orthogonal one.
    pub const fn keeps_orthogonal(self) -> bool {
        matches!(
            self,
            Mutation::ShiftEdge | Mutation::AddNiche | Mutation::CollapseEdge | Mutation::Refine
        )
    }

    /// A short name for reports.
    pub const fn name(self) -> &'static str {
        match self {
            Mutation::MoveVertex => "move-vertex",
            Mutation::ShiftEdge => "shift-edge",
            Mutation::InsertVertex => "insert-vertex",
            Mutation::AddNiche => "add-niche",
            Mutation::RemoveVertex => "remove-vertex",
            Mutation::CollapseEdge => "collapse-edge",
            Mutation::Refine => "refine",
        }
    }

    /// The relative frequency with which [`mutate`] draws the operator.
    const fn weight(self) -> u32 {
        match self {
            Mutation::MoveVertex => 4,
            Mutation::ShiftEdge => 3,
            Mutation::InsertVertex => 2,
            Mutation::AddNiche => 3,
            Mutation::RemoveVertex => 2,
            Mutation::CollapseEdge => 2,
            Mutation::Refine => 1,
        }
    }
}

/// What a mutant may be.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Limits {
    /// At most this many vertices (after normalisation).
    pub max_n: usize,
    /// At least this many vertices.
    pub min_n: usize,
    /// Every coordinate below `2^max_coord_bits` in magnitude.
    pub max_coord_bits: u32,
    /// An orthogonal map is mutated only by the operators that keep it
    /// orthogonal, and a mutant that is not is refused.
    pub keep_orthogonal: bool,
}

impl Default for Limits {
    /// At most 40 vertices, coordinates below 2^24 (well inside every
    /// fast path of `wai_exact` and `wai_cells`), orthogonal maps kept
    /// orthogonal.
    fn default() -> Self {
        Limits {
            max_n: 40,
            min_n: 4,
            max_coord_bits: 24,
            keep_orthogonal: true,
        }
    }
}

/// A valid mutant and how it was made.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Mutant {
    pub map: Map,
    pub mutation: Mutation,
    /// Proposals refused before this one (invalid rings, or outside the
    /// [`Limits`], or equal to the parent).
    pub refused: usize,
}

/// How many proposals [`mutate`] makes before giving up.
pub const ATTEMPTS: usize = 64;

/// A valid mutant of `map` within `limits`, or `None` if [`ATTEMPTS`]
/// proposals in a row were refused. The result differs from `map`; it is
/// whatever [`Map::from_ring`] makes of the proposal (a clockwise ring is
/// reversed, 180° vertices dropped), named like its parent.
///
/// ```
/// use rand::SeedableRng;
/// let map = wai_gen::family("corridor-niches", &[2]).unwrap();
/// let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(7);
/// let m = wai_gen::mutate::mutate(&map, &Default::default(), &mut rng).unwrap();
/// assert!(m.map.is_orthogonal() && m.map != map);
/// ```
pub fn mutate<R: Rng + ?Sized>(map: &Map, limits: &Limits, rng: &mut R) -> Option<Mutant> {
    let orthogonal = limits.keep_orthogonal && map.is_orthogonal();
    let ops: Vec<Mutation> = Mutation::ALL
        .into_iter()
        .filter(|m| !orthogonal || m.keeps_orthogonal())
        .collect();
    let total: u32 = ops.iter().map(|m| m.weight()).sum();
    let mut refused = 0;
    for _ in 0..ATTEMPTS {
        let mut pick = rng.random_range(0..total);
        let op = *ops
            .iter()
            .find(|m| {
                let w = m.weight();
                if pick < w {
                    true
                } else {
                    pick -= w;
                    false
                }
            })
            .expect("pick < total");
        let accepted = propose(map.vertices(), op, limits, rng)
            .and_then(|ring| accept(ring, map, orthogonal, limits));
        match accepted {
            Some(m) => {
                let m = match map.name() {
                    Some(name) => m.with_name(name),
                    None => m,
                };
                return Some(Mutant {
                    map: m,
                    mutation: op,
                    refused,
                });
            }
            None => refused += 1,
        }
    }
    None
}

/// The map of `ring` if it is valid, within `limits`, orthogonal when
/// `orthogonal` asks it, and different from `parent`.
fn accept(ring: Vec<Point>, parent: &Map, orthogonal: bool, limits: &Limits) -> Option<Map> {
    let bound = 1i128 << limits.max_coord_bits;
    if ring
        .iter()
        .any(|p| p.x.abs() >= bound || p.y.abs() >= bound)
    {
        return None;
    }
    let (map, _) = Map::from_ring(ring).ok()?;
    let fits = (limits.min_n..=limits.max_n).contains(&map.n());
    (fits && (!orthogonal || map.is_orthogonal()) && map.vertices() != parent.vertices())
        .then_some(map)
}

/// The largest extent of the ring's bounding box (at least 1).
fn span(ring: &[Point]) -> i128 {
    let (mut lo, mut hi) = (ring[0], ring[0]);
    for p in ring {
        lo = Point::new(lo.x.min(p.x), lo.y.min(p.y));
        hi = Point::new(hi.x.max(p.x), hi.y.max(p.y));
    }
    (hi.x - lo.x).max(hi.y - lo.y).max(1)
}

/// A random step length: half the time 1 or 2, else up to a quarter of
/// the map's extent.
fn step<R: Rng + ?Sized>(span: i128, rng: &mut R) -> i128 {
    if rng.random_bool(0.5) {
        rng.random_range(1..=2)
    } else {
        rng.random_range(1..=(span / 4).max(2))
    }
}

fn signed<R: Rng + ?Sized>(x: i128, rng: &mut R) -> i128 {
    if rng.random_bool(0.5) {
        x
    } else {
        -x
    }
}

/// The primitive direction of edge `a b` (its vector over the gcd of its
/// coordinates) and that gcd: the edge's lattice points are `a + t·u`,
/// `0 ≤ t ≤ g`.
fn primitive(a: Point, b: Point) -> (Point, i128) {
    let (dx, dy) = (b.x - a.x, b.y - a.y);
    let g = gcd_u128(dx.unsigned_abs(), dy.unsigned_abs()).max(1) as i128;
    (Point::new(dx / g, dy / g), g)
}

fn add(p: Point, d: Point, k: i128) -> Option<Point> {
    Some(Point::new(
        p.x.checked_add(d.x.checked_mul(k)?)?,
        p.y.checked_add(d.y.checked_mul(k)?)?,
    ))
}

/// The ring operator `op` proposes for `ring`, or `None` where it does not
/// apply (too few vertices, a coordinate overflow). The proposal may be
/// invalid; [`mutate`] validates it.
pub fn propose<R: Rng + ?Sized>(
    ring: &[Point],
    op: Mutation,
    limits: &Limits,
    rng: &mut R,
) -> Option<Vec<Point>> {
    let n = ring.len();
    if n < 3 {
        return None;
    }
    let s = span(ring);
    let i = rng.random_range(0..n);
    let (a, b) = (ring[i], ring[(i + 1) % n]);
    let mut out = ring.to_vec();
    match op {
        Mutation::MoveVertex => {
            let (dx, dy) = loop {
                let dx = if rng.random_bool(0.7) {
                    signed(step(s, rng), rng)
                } else {
                    0
                };
                let dy = if rng.random_bool(0.7) {
                    signed(step(s, rng), rng)
                } else {
                    0
                };
                if (dx, dy) != (0, 0) {
                    break (dx, dy);
                }
            };
            out[i] = Point::new(a.x.checked_add(dx)?, a.y.checked_add(dy)?);
        }
        Mutation::ShiftEdge => {
            let (u, _) = primitive(a, b);
            let normal = Point::new(-u.y, u.x);
            let unit = normal.x.abs().max(normal.y.abs());
            let k = signed((step(s, rng) / unit).max(1), rng);
            out[i] = add(a, normal, k)?;
            out[(i + 1) % n] = add(b, normal, k)?;
        }
        Mutation::InsertVertex => {
            if n + 1 > limits.max_n {
                return None;
            }
            let (u, g) = primitive(a, b);
            let on = if g >= 2 {
                add(a, u, rng.random_range(1..g))?
            } else {
                Point::new(a.x + (b.x - a.x) / 2, a.y + (b.y - a.y) / 2)
            };
            let normal = Point::new(-u.y, u.x);
            let unit = normal.x.abs().max(normal.y.abs());
            let k = signed((step(s, rng) / unit).max(1), rng);
            let mut p = add(on, normal, k)?;
            if rng.random_bool(0.5) {
                p = Point::new(p.x + signed(1, rng), p.y + signed(1, rng));
            }
            out.insert(i + 1, p);
        }
        Mutation::AddNiche => {
            let (u, g) = primitive(a, b);
            let (mut t1, mut t2) = (rng.random_range(0..=g), rng.random_range(0..=g));
            if t1 == t2 {
                return None;
            }
            if t1 > t2 {
                std::mem::swap(&mut t1, &mut t2);
            }
            // Outwards: the right of a counter-clockwise ring's edge.
            let outward = Point::new(u.y, -u.x);
            let unit = outward.x.abs().max(outward.y.abs());
            let k = signed((step(s, rng) / unit).max(1), rng);
            let (p, q) = (add(a, u, t1)?, add(a, u, t2)?);
            let mut niche = Vec::with_capacity(4);
            if t1 > 0 {
                niche.push(p);
            }
            niche.extend([add(p, outward, k)?, add(q, outward, k)?]);
            if t2 < g {
                niche.push(q);
            }
            if n + niche.len() > limits.max_n {
                return None;
            }
            out.splice(i + 1..i + 1, niche);
        }
        Mutation::RemoveVertex => {
            if n <= limits.min_n.max(3) {
                return None;
            }
            out.remove(i);
        }
        Mutation::CollapseEdge => {
            if n <= limits.min_n.max(4) {
                return None;
            }
            let d = Point::new(a.x - b.x, a.y - b.y);
            if rng.random_bool(0.5) {
                // v_{i+1} lands on v_i: drop it, move v_{i+2} by the same.
                let j = (i + 2) % n;
                out[j] = add(ring[j], d, 1)?;
                out.remove((i + 1) % n);
            } else {
                // Mirror image: v_i lands on v_{i+1}, v_{i-1} moves by b - a.
                let j = (i + n - 1) % n;
                out[j] = add(ring[j], d, -1)?;
                out.remove(i);
            }
        }
        Mutation::Refine => {
            if s >= 1i128 << (limits.max_coord_bits / 2) {
                return None;
            }
            for p in &mut out {
                *p = Point::new(p.x * 2, p.y * 2);
            }
        }
    }
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ring_problem;
    use rand::SeedableRng;
    use rand_chacha::ChaCha8Rng;
    use std::collections::BTreeMap;

    fn starts() -> Vec<Map> {
        let mut maps = vec![
            crate::family("corridor-niches", &[2]).unwrap(),
            crate::family("convex-niches", &[1]).unwrap(),
            crate::family("comb-convex-chain", &[2]).unwrap(),
            crate::family("overlap-fan", &[0]).unwrap(),
        ];
        for kind in crate::RANDOM_KINDS {
            maps.push(crate::random(kind.id, 10, 3).unwrap());
        }
        maps
    }

    /// Every mutant of a long seeded walk from each start is a valid map
    /// (by `wai_map`'s validation and by the independent `ring_problem`),
    /// within the limits, different from its parent, and orthogonal when
    /// its start was; and every operator produced some mutant.
    #[test]
    fn every_mutation_keeps_the_map_valid() {
        let limits = Limits {
            max_n: 24,
            ..Limits::default()
        };
        let mut used: BTreeMap<Mutation, usize> = BTreeMap::new();
        for (s, start) in starts().into_iter().enumerate() {
            let orthogonal = start.is_orthogonal();
            for seed in 0..4u64 {
                let mut rng = ChaCha8Rng::seed_from_u64(1000 * s as u64 + seed);
                let mut map = start.clone();
                for step in 0..300 {
                    let Some(m) = mutate(&map, &limits, &mut rng) else {
                        panic!("start {s} seed {seed} step {step}: no valid mutant")
                    };
                    let v = m.map.vertices();
                    assert_eq!(ring_problem(v), None, "{:?} gave {v:?}", m.mutation);
                    assert!(wai_map::validate_all(v).is_empty());
                    assert!((limits.min_n..=limits.max_n).contains(&m.map.n()));
                    assert_ne!(m.map.vertices(), map.vertices());
                    if orthogonal {
                        assert!(m.map.is_orthogonal(), "{:?} gave {v:?}", m.mutation);
                        assert!(m.mutation.keeps_orthogonal());
                    }
                    let bound = 1i128 << limits.max_coord_bits;
                    assert!(v.iter().all(|p| p.x.abs() < bound && p.y.abs() < bound));
                    *used.entry(m.mutation).or_default() += 1;
                    map = m.map;
                }
            }
        }
        for op in Mutation::ALL {
            assert!(used.get(&op).copied().unwrap_or(0) > 0, "{op:?} never used");
        }
    }

    /// Orthogonal maps may leave orthogonality when asked to.
    #[test]
    fn orthogonal_maps_may_be_freed() {
        let limits = Limits {
            keep_orthogonal: false,
            ..Limits::default()
        };
        let mut map = crate::family("corridor-niches", &[2]).unwrap();
        let mut rng = ChaCha8Rng::seed_from_u64(5);
        let mut left = false;
        for _ in 0..100 {
            map = mutate(&map, &limits, &mut rng).unwrap().map;
            left |= !map.is_orthogonal();
        }
        assert!(left);
    }

    /// The same seed gives the same mutants, in the same order.
    #[test]
    fn mutants_are_a_function_of_the_seed() {
        let walk = |seed: u64| {
            let mut rng = ChaCha8Rng::seed_from_u64(seed);
            let mut map = crate::random("random-simple-2opt", 12, 1).unwrap();
            let mut out = Vec::new();
            for _ in 0..50 {
                let m = mutate(&map, &Limits::default(), &mut rng).unwrap();
                out.push((m.mutation, m.refused, m.map.vertices().to_vec()));
                map = m.map;
            }
            out
        };
        assert_eq!(walk(9), walk(9));
        assert_ne!(walk(9), walk(10));
    }

    /// A niche on an edge of a square, spelled out.
    #[test]
    fn a_niche_is_three_sides_of_a_rectangle() {
        let ring = [
            Point::new(0, 0),
            Point::new(1, 0),
            Point::new(1, 1),
            Point::new(0, 1),
        ]
        .map(|p| Point::new(4 * p.x, 4 * p.y));
        let mut rng = ChaCha8Rng::seed_from_u64(0);
        let limits = Limits::default();
        let mut seen = 0;
        for _ in 0..200 {
            let Some(r) = propose(&ring, Mutation::AddNiche, &limits, &mut rng) else {
                continue;
            };
            let Some(m) = accept(r, &Map::from_ring(ring.to_vec()).unwrap().0, true, &limits)
            else {
                continue;
            };
            // Two, one or no corners of the new rectangle on the square's
            // corners (a niche along the whole edge moves the edge out).
            assert!(m.is_orthogonal() && [4, 6, 8].contains(&m.n()), "{m:?}");
            seen += 1;
        }
        assert!(seen > 50);
    }

    /// Removing and collapsing never go below the minimum size.
    #[test]
    fn shrinking_stops_at_the_minimum() {
        let square = Map::from_ring(vec![
            Point::new(0, 0),
            Point::new(2, 0),
            Point::new(2, 2),
            Point::new(0, 2),
        ])
        .unwrap()
        .0;
        let mut rng = ChaCha8Rng::seed_from_u64(1);
        let limits = Limits::default();
        for op in [Mutation::RemoveVertex, Mutation::CollapseEdge] {
            assert_eq!(propose(square.vertices(), op, &limits, &mut rng), None);
        }
    }
}
