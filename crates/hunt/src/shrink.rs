//! Shrinking a counterexample to a map a person can read.
//!
//! A violation found on a 30-vertex random map says little; the same
//! violation on a 7-vertex map with coordinates below 10 can be drawn and
//! followed by hand. [`shrink`] takes a map on which a predicate holds ("the
//! checker of claim X reports a violation that is not a known failure") and
//! greedily applies the first simplification that keeps the map valid and
//! the predicate true, until none does:
//!
//! 1. the one-step shrinks of the property tests
//!    ([`wai_gen::shrink_map`]: drop one vertex, halve every
//!    coordinate), then drop two consecutive vertices;
//! 2. pull an edge flush with the line through a neighbouring vertex
//!    (parallel to itself): a rectangular niche or bump disappears, a step
//!    gets shorter;
//! 3. divide every coordinate (relative to the least corner) by their
//!    common divisor;
//! 4. compress the coordinates: the distinct x (and y) values, in order,
//!    become 0, 1, 2, … (the order type of an orthogonal map survives);
//! 5. pull one coordinate of one vertex toward 0: halve it, or subtract 1.
//!
//! On a map with holes, dropping one hole comes first; the moves above then
//! change the outer ring only, the holes staying where they are.
//!
//! A proposal is accepted only if it lowers the measure (n, width + height,
//! the sum of the coordinates relative to the least corner)
//! lexicographically, so shrinking ends; the result is finally translated
//! to the origin. Every proposal goes through [`Map::from_rings`] (a
//! self-intersecting or degenerate ring is skipped, never a panic; collinear
//! vertices it removes are gone) and only then to the predicate.
//! Deterministic: the same map and predicate give the same result.
//!
//! # Edge cases
//! The result is locally minimal for these moves only: no single move
//! keeps the violation, which does not make it the smallest counterexample.
//! The predicate is called at most `max_tries` times; when that runs out
//! the map reached so far is returned with [`Shrunk::exhausted`] set.

use wai_exact::Point;
use wai_map::Map;

/// What [`shrink`] reached.
#[derive(Debug, Clone)]
pub struct Shrunk {
    /// The smallest map found on which the predicate holds (the input if no
    /// move kept it).
    pub map: Map,
    /// The vertex count of the input.
    pub from_n: usize,
    /// Moves accepted.
    pub steps: usize,
    /// Valid proposals handed to the predicate.
    pub tries: usize,
    /// True if `max_tries` ran out before a full pass found no move.
    pub exhausted: bool,
}

/// Shrinks `map` while `holds` stays true; see the module doc. `holds(map)`
/// should be true on the input (if it is not, the input is returned as is,
/// with `steps == 0`).
pub fn shrink(map: &Map, mut holds: impl FnMut(&Map) -> bool, max_tries: usize) -> Shrunk {
    let name = map.name().unwrap_or("map").to_owned();
    let mut best = map.clone();
    let mut out = Shrunk {
        map: map.clone(),
        from_n: map.n(),
        steps: 0,
        tries: 0,
        exhausted: false,
    };
    'pass: loop {
        let rings = rings_of(&best);
        let all: Vec<Point> = rings.concat();
        let bound = measure(&all);
        let (outer, holes) = (&rings[0], &rings[1..]);
        // A map with holes: drop one hole, then move the outer ring with the
        // holes kept where they are.
        let drop_hole = (0..holes.len()).map(|k| {
            let mut kept = rings.clone();
            kept.remove(k + 1);
            kept
        });
        let outer_only = Map::from_ring(outer.clone()).map(|(m, _)| m);
        let outer_moves = outer_only
            .iter()
            .flat_map(wai_gen::shrink_map)
            .map(|m| m.vertices().to_vec())
            .chain(proposals(outer))
            .map(|o| std::iter::once(o).chain(holes.iter().cloned()).collect());
        for proposal in drop_hole.chain(outer_moves) {
            let proposal: Vec<Vec<Point>> = proposal;
            if measure(&proposal.concat()) >= bound {
                continue;
            }
            let Some(candidate) = assemble(proposal) else {
                continue;
            };
            if out.tries == max_tries {
                out.exhausted = true;
                break 'pass;
            }
            out.tries += 1;
            if holds(&candidate) {
                out.steps += 1;
                best = candidate;
                continue 'pass;
            }
        }
        break;
    }
    let rings = rings_of(&best);
    let all = rings.concat();
    let (dx, dy) = (
        all.iter().map(|p| p.x).min().unwrap_or(0),
        all.iter().map(|p| p.y).min().unwrap_or(0),
    );
    let moved = rings
        .iter()
        .map(|r| r.iter().map(|p| Point::new(p.x - dx, p.y - dy)).collect())
        .collect();
    if let Some(moved) = assemble(moved) {
        best = moved;
    }
    out.map = best.with_name(format!("{name}, shrunk"));
    out
}

/// The map's rings: the outer ring, then the holes.
fn rings_of(map: &Map) -> Vec<Vec<Point>> {
    (0..=map.hole_count())
        .map(|k| map.ring(k).to_vec())
        .collect()
}

/// The map of these rings, if they make a valid one.
fn assemble(mut rings: Vec<Vec<Point>>) -> Option<Map> {
    let outer = rings.remove(0);
    Map::from_rings(outer, rings).ok().map(|(m, _)| m)
}

/// What every accepted move lowers: (n, width + height, the sum of the
/// coordinates relative to the least corner).
fn measure(ring: &[Point]) -> (usize, i128, i128) {
    let min_x = ring.iter().map(|p| p.x).min().unwrap_or(0);
    let min_y = ring.iter().map(|p| p.y).min().unwrap_or(0);
    let max_x = ring.iter().map(|p| p.x).max().unwrap_or(0);
    let max_y = ring.iter().map(|p| p.y).max().unwrap_or(0);
    let sum = ring.iter().map(|p| (p.x - min_x) + (p.y - min_y)).sum();
    (ring.len(), (max_x - min_x) + (max_y - min_y), sum)
}

/// Every proposal of one pass, in the order of the module doc: the ones
/// that lower n first.
fn proposals(ring: &[Point]) -> impl Iterator<Item = Vec<Point>> + '_ {
    let n = ring.len();
    let drop_two = (0..n).map(move |i| without(ring, &[i, (i + 1) % n]));
    let flush = (0..n).flat_map(move |i| {
        // Edge (b, c) = (i, i+1), pulled onto the line through a = i-1 or
        // d = i+2 parallel to itself.
        let (a, d) = (ring[(i + n - 1) % n], ring[(i + 2) % n]);
        [a, d].into_iter().map(move |to| flush(ring, i, to))
    });
    let whole = [normalised(ring, true), compressed(ring)].into_iter();
    let pulls = (0..n).flat_map(move |i| {
        let p = ring[i];
        [
            Point::new(p.x / 2, p.y),
            Point::new(p.x, p.y / 2),
            Point::new(p.x - p.x.signum(), p.y),
            Point::new(p.x, p.y - p.y.signum()),
        ]
        .into_iter()
        .map(move |q| {
            let mut r = ring.to_vec();
            r[i] = q;
            r
        })
    });
    drop_two
        .chain(flush)
        .chain(whole)
        .chain(pulls)
        .map(dedup_cyclic)
}

/// `ring` without the vertices at `drop`.
fn without(ring: &[Point], drop: &[usize]) -> Vec<Point> {
    ring.iter()
        .enumerate()
        .filter(|(k, _)| !drop.contains(k))
        .map(|(_, &p)| p)
        .collect()
}

/// Edge (i, i+1) translated along its normal onto the parallel line through
/// `to`: both ends move by the normal component of `to − ring[i]`. Exact
/// only when that component is integral; otherwise `ring` unchanged. Axis
/// parallel edges (every edge of an orthogonal map) always qualify.
fn flush(ring: &[Point], i: usize, to: Point) -> Vec<Point> {
    let n = ring.len();
    let (b, c) = (ring[i], ring[(i + 1) % n]);
    let (dx, dy) = if b.x == c.x {
        (to.x - b.x, 0)
    } else if b.y == c.y {
        (0, to.y - b.y)
    } else {
        return ring.to_vec();
    };
    let mut r = ring.to_vec();
    r[i] = Point::new(b.x + dx, b.y + dy);
    r[(i + 1) % n] = Point::new(c.x + dx, c.y + dy);
    r
}

/// `ring` translated so its least x and y are 0 and, if `divide`, divided
/// by the greatest common divisor of all its coordinates.
fn normalised(ring: &[Point], divide: bool) -> Vec<Point> {
    let min_x = ring.iter().map(|p| p.x).min().unwrap_or(0);
    let min_y = ring.iter().map(|p| p.y).min().unwrap_or(0);
    let moved: Vec<Point> = ring
        .iter()
        .map(|p| Point::new(p.x - min_x, p.y - min_y))
        .collect();
    let g = moved
        .iter()
        .fold(0i128, |g, p| gcd(gcd(g, p.x.abs()), p.y.abs()));
    if g <= 1 || !divide {
        return moved;
    }
    moved.iter().map(|p| Point::new(p.x / g, p.y / g)).collect()
}

/// `ring` with each coordinate replaced by its rank among the distinct
/// values of that axis.
fn compressed(ring: &[Point]) -> Vec<Point> {
    let ranks = |values: Vec<i128>| {
        let mut v = values;
        v.sort_unstable();
        v.dedup();
        v
    };
    let xs = ranks(ring.iter().map(|p| p.x).collect());
    let ys = ranks(ring.iter().map(|p| p.y).collect());
    let rank = |v: &[i128], c: i128| v.binary_search(&c).unwrap_or(0) as i128;
    ring.iter()
        .map(|p| Point::new(rank(&xs, p.x), rank(&ys, p.y)))
        .collect()
}

/// `ring` without vertices equal to their successor (a flushed edge can
/// land on its neighbour's end).
fn dedup_cyclic(mut ring: Vec<Point>) -> Vec<Point> {
    ring.dedup();
    while ring.len() > 1 && ring.first() == ring.last() {
        ring.pop();
    }
    ring
}

fn gcd(a: i128, b: i128) -> i128 {
    if b == 0 {
        a
    } else {
        gcd(b, a % b)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn map(ring: &[(i128, i128)]) -> Map {
        Map::from_ring(ring.iter().map(|&(x, y)| Point::new(x, y)).collect())
            .expect("valid")
            .0
    }

    #[test]
    fn a_map_with_holes_shrinks_to_a_valid_map_with_holes() {
        let map = wai_gen::random_with_holes("orthogonal-pillars", 12, 3, 5).expect("holed map");
        assert!(map.hole_count() >= 2, "{}", map.hole_count());
        // Kept while some hole remains: the holes are dropped down to one,
        // and the outer ring shrinks around it.
        let s = shrink(&map, |m| m.has_holes(), 10_000);
        assert_eq!(s.map.hole_count(), 1);
        assert!(s.map.n() < map.n() && s.steps > 0);
        let (lo, _) = s.map.bounding_box();
        assert_eq!((lo.x, lo.y), (0, 0));
        // Kept only with every hole: no hole is dropped.
        let s = shrink(&map, |m| m.hole_count() == map.hole_count(), 10_000);
        assert_eq!(s.map.hole_count(), map.hole_count());
    }

    #[test]
    fn a_predicate_on_reflex_vertices_shrinks_to_one_notch() {
        // A comb with three notches; "has a reflex vertex" holds all along.
        let comb = map(&[
            (0, 0),
            (40, 0),
            (40, 30),
            (30, 30),
            (30, 10),
            (20, 10),
            (20, 30),
            (10, 30),
            (10, 10),
            (0, 10),
        ]);
        let s = shrink(&comb, |m| m.r() > 0, 10_000);
        assert!(s.map.r() > 0);
        assert!(s.map.n() <= 6, "{:?}", s.map.vertices());
        assert!(s.steps > 0 && !s.exhausted);
        // Coordinates pulled down to small integers.
        assert!(s
            .map
            .vertices()
            .iter()
            .all(|p| p.x.abs() <= 4 && p.y.abs() <= 4));
        assert_eq!(s.from_n, 10);
    }

    #[test]
    fn a_predicate_that_fails_at_once_leaves_the_map() {
        let square = map(&[(0, 0), (8, 0), (8, 8), (0, 8)]);
        let s = shrink(&square, |_| false, 100);
        assert_eq!(s.map.vertices(), square.vertices());
        assert_eq!(s.steps, 0);
    }

    #[test]
    fn the_try_budget_is_kept() {
        let comb = map(&[
            (0, 0),
            (9, 0),
            (9, 9),
            (6, 9),
            (6, 3),
            (3, 3),
            (3, 9),
            (0, 9),
        ]);
        let mut calls = 0;
        let s = shrink(
            &comb,
            |_| {
                calls += 1;
                false
            },
            5,
        );
        assert!(s.exhausted);
        assert_eq!((s.tries, calls), (5, 5));
    }
}
