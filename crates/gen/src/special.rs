//! "Special" maps biased to degeneracies: few distinct
//! coordinates, so that many edges lie on one line, many vertices lie on
//! lines through two others and many visibility rays pass through one
//! point.

use crate::polyomino::grow;
use rand::Rng;
use rand_chacha::ChaCha8Rng;
use wai_exact::Point;

/// Orthogonal boundary of a random polyomino on the unit grid: every
/// coordinate is one of few small integers, so edges are collinear in bulk.
pub(crate) fn coarse_orthogonal_ring(n: usize, rng: &mut ChaCha8Rng) -> Vec<Point> {
    grow(n.max(4), usize::MAX, rng).ring()
}

/// A corridor `[0, 2s + 1] × [0, 2]` with unit-wide niches on a common
/// grid of `s` slots per side (slot `i` spans `[2i + 1, 2i + 2]`), the
/// niches on both sides at aligned positions with depth 1 or 2, so their
/// walls and backs share lines. `niches ≤ 2s` niches are placed in random
/// slots; `n = 4 + 4·niches`.
pub(crate) fn comb_ring(niches: usize, rng: &mut ChaCha8Rng) -> Vec<Point> {
    let slots = niches.max(1);
    // Choose `niches` of the 2·slots (side, slot) places.
    let mut places: Vec<(bool, usize)> = (0..slots).flat_map(|i| [(false, i), (true, i)]).collect();
    for i in 0..niches {
        let j = rng.random_range(i..places.len());
        places.swap(i, j);
    }
    let mut south: Vec<usize> = Vec::new();
    let mut north: Vec<usize> = Vec::new();
    for &(is_north, i) in &places[..niches] {
        if is_north {
            north.push(i);
        } else {
            south.push(i);
        }
    }
    south.sort_unstable();
    north.sort_unstable();
    let len = 2 * slots as i128 + 1;
    let height = 2;
    let mut ring = vec![Point::new(0, 0)];
    for &i in &south {
        let (a, d) = (2 * i as i128 + 1, rng.random_range(1..=2));
        ring.extend([
            Point::new(a, 0),
            Point::new(a, -d),
            Point::new(a + 1, -d),
            Point::new(a + 1, 0),
        ]);
    }
    ring.extend([Point::new(len, 0), Point::new(len, height)]);
    for &i in north.iter().rev() {
        let (a, d) = (2 * i as i128 + 1, rng.random_range(1..=2));
        ring.extend([
            Point::new(a + 1, height),
            Point::new(a + 1, height + d),
            Point::new(a, height + d),
            Point::new(a, height),
        ]);
    }
    ring.push(Point::new(0, height));
    ring
}

/// An orthogonal ring on the lattice scaled by 3, with some corners cut at
/// 45°: corner `v` with incoming direction `d_in` and outgoing `d_out`
/// (unit, axis-parallel) becomes `v - d_in, v + d_out`. At a convex corner
/// this cuts a triangle off the cell there, at a reflex corner it adds one
/// inside the empty cell there; edges have length ≥ 3, so at least 1 is
/// left between two cuts and the ring stays simple with no 180° vertex.
/// All cuts lie on the few lines `x ± y = c`, a diagonal degeneracy.
pub(crate) fn chamfer(ring: &[Point], cut: &[bool]) -> Vec<Point> {
    let n = ring.len();
    let unit = |a: Point, b: Point| Point::new((b.x - a.x).signum(), (b.y - a.y).signum());
    let mut out = Vec::with_capacity(2 * n);
    for i in 0..n {
        let (u, v, w) = (ring[(i + n - 1) % n], ring[i], ring[(i + 1) % n]);
        if cut[i] {
            let (din, dout) = (unit(u, v), unit(v, w));
            out.push(Point::new(v.x - din.x, v.y - din.y));
            out.push(Point::new(v.x + dout.x, v.y + dout.y));
        } else {
            out.push(v);
        }
    }
    out
}

/// A chamfered orthogonal ring with exactly `n ≥ 4` vertices: a grown
/// polyomino with `m` vertices, `max(⌈n/2⌉, 4) ≤ m ≤ max(⌈n/2⌉, 4) + 3`
/// (so `n/2 ≤ m ≤ n`; for `n ≤ 6` it is the unit square), with `n − m` of
/// its corners cut, each cut adding one vertex.
pub(crate) fn chamfered_ring(n: usize, rng: &mut ChaCha8Rng) -> Vec<Point> {
    let half = n.div_ceil(2).max(4);
    let base = grow(half, usize::MAX, rng).ring_scaled(3);
    let m = base.len();
    let cuts = n.saturating_sub(m).min(m);
    let mut idx: Vec<usize> = (0..m).collect();
    for i in 0..cuts {
        let j = rng.random_range(i..m);
        idx.swap(i, j);
    }
    let mut cut = vec![false; m];
    for &i in &idx[..cuts] {
        cut[i] = true;
    }
    chamfer(&base, &cut)
}
