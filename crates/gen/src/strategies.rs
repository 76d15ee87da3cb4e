//! proptest strategies and a quickcheck `Arbitrary` that produce valid maps
//! and shrink toward fewer vertices and smaller coordinates.
//!
//! Orthogonal maps come from polyomino cell sets and shrink by dropping
//! one cell at a time while the boundary stays simple
//! ([`Polyomino::shrinks`]); simple polygons come from `(n, range, seed)`
//! and shrink through proptest's shrinking of `n` and `range`. The
//! quickcheck newtype [`ArbMap`] shrinks any map by [`shrink_map`].

use crate::polyomino::{grow, Polyomino};
use crate::ring::into_map;
use crate::{simple, special};
use proptest::prelude::*;
use proptest::strategy::{NewTree, ValueTree};
use proptest::test_runner::TestRunner;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use wai_exact::Point;
use wai_map::Map;

/// Random simple polyominoes of `1..=max_cells` cells (random growth),
/// shrinking by removing cells.
#[derive(Clone, Copy, Debug)]
pub struct PolyominoStrategy {
    pub max_cells: usize,
}

/// The value tree of [`PolyominoStrategy`].
#[derive(Clone, Debug)]
pub struct PolyominoTree {
    current: Polyomino,
    /// The value before the last simplification, to go back to.
    prev: Option<Polyomino>,
    /// Which shrink of `current` to try next.
    next: usize,
}

impl ValueTree for PolyominoTree {
    type Value = Polyomino;

    fn current(&self) -> Polyomino {
        self.current.clone()
    }

    fn simplify(&mut self) -> bool {
        let shrinks = self.current.shrinks();
        match shrinks.into_iter().nth(self.next) {
            Some(s) => {
                self.prev = Some(std::mem::replace(&mut self.current, s));
                self.next = 0;
                true
            }
            None => false,
        }
    }

    fn complicate(&mut self) -> bool {
        match self.prev.take() {
            Some(p) => {
                self.current = p;
                self.next += 1;
                true
            }
            None => false,
        }
    }
}

impl Strategy for PolyominoStrategy {
    type Tree = PolyominoTree;
    type Value = Polyomino;

    fn new_tree(&self, runner: &mut TestRunner) -> NewTree<Self> {
        let seed = runner.rng().next_u64();
        let cells = 1 + (runner.rng().next_u64() % self.max_cells.max(1) as u64) as usize;
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        Ok(PolyominoTree {
            current: grow(usize::MAX, cells, &mut rng),
            prev: None,
            next: 0,
        })
    }
}

/// Simple polyominoes of up to 24 cells.
pub fn arb_polyomino() -> PolyominoStrategy {
    PolyominoStrategy { max_cells: 24 }
}

/// Orthogonal maps: unit-square boundaries of simple polyominoes of up to
/// 24 cells, shrinking cell by cell.
pub fn arb_orthogonal_map() -> impl Strategy<Value = Map> {
    arb_polyomino().prop_map(|p| p.to_map())
}

/// Simple (not necessarily orthogonal) maps of 3 to 24 vertices: star-shaped
/// or 2-opt, coordinates within `n + range`, shrinking `n` and `range`.
pub fn arb_simple_map() -> impl Strategy<Value = Map> {
    (any::<bool>(), 3usize..=24, 0i128..=64, any::<u64>()).prop_map(|(star, n, extra, seed)| {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let range = n as i128 + extra + 2;
        let ring = if star {
            simple::star_ring(n, range, &mut rng)
        } else {
            simple::two_opt_ring(n, range, &mut rng)
        };
        into_map(ring, format!("arb-simple/n={n}"))
    })
}

/// Any map of this crate's random kinds: simple, orthogonal, and the
/// collinearity-biased special maps (unit-grid polyominoes, aligned combs,
/// 45° chamfers).
pub fn arb_map() -> impl Strategy<Value = Map> {
    let special = (0u8..3, 4usize..=24, any::<u64>()).prop_map(|(kind, n, seed)| {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let ring = match kind {
            0 => special::comb_ring((n - 4).div_ceil(4), &mut rng),
            1 => special::chamfered_ring(n, &mut rng),
            _ => special::coarse_orthogonal_ring(n, &mut rng),
        };
        into_map(ring, format!("arb-special/n={n}"))
    });
    prop_oneof![arb_simple_map(), arb_orthogonal_map(), special]
}

/// The one-step shrinks of a map, each a valid map: translated to the
/// origin (if not there), coordinates halved (rounding down; kept only if
/// the ring stays valid), and each single vertex removed (kept only if
/// valid). Each step lowers `n` or the extent or moves the least corner to
/// the origin, so repeated shrinking ends.
pub fn shrink_map(map: &Map) -> Vec<Map> {
    let v = map.vertices();
    let min_x = v.iter().map(|p| p.x).min().unwrap_or(0);
    let min_y = v.iter().map(|p| p.y).min().unwrap_or(0);
    let try_ring = |ring: Vec<Point>| Map::from_ring(ring).ok().map(|(m, _)| m);
    let mut out = Vec::new();
    if (min_x, min_y) != (0, 0) {
        out.extend(try_ring(
            v.iter()
                .map(|p| Point::new(p.x - min_x, p.y - min_y))
                .collect(),
        ));
    } else {
        let half: Vec<Point> = v
            .iter()
            .map(|p| Point::new(p.x.div_euclid(2), p.y.div_euclid(2)))
            .collect();
        if half.as_slice() != v {
            out.extend(try_ring(half));
        }
    }
    if v.len() > 3 {
        for i in 0..v.len() {
            let mut ring = v.to_vec();
            ring.remove(i);
            out.extend(try_ring(ring));
        }
    }
    out
}

/// A quickcheck map: any of this crate's random kinds, with
/// `n ≤ max(4, gen.size())`; shrinks by [`shrink_map`].
#[derive(Clone, Debug)]
pub struct ArbMap(pub Map);

impl quickcheck::Arbitrary for ArbMap {
    fn arbitrary(g: &mut quickcheck::Gen) -> Self {
        let kinds = crate::RANDOM_KINDS;
        let kind = g.choose(kinds).expect("non-empty");
        let top = g.size().clamp(kind.min_n, 24);
        let n =
            kind.min_n + <usize as quickcheck::Arbitrary>::arbitrary(g) % (top - kind.min_n + 1);
        let seed = <u64 as quickcheck::Arbitrary>::arbitrary(g);
        ArbMap(crate::random(kind.id, n, seed).expect("n within the kind's range"))
    }

    fn shrink(&self) -> Box<dyn Iterator<Item = Self>> {
        Box::new(shrink_map(&self.0).into_iter().map(ArbMap))
    }
}
