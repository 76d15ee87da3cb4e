//! Where rays of one direction leave the map, from every map vertex at
//! once: the directional trapezoidalization behind Guibas et al.'s one-shot
//! localization in O(mn) (thesis sec. 3.2), built by one plane sweep.
//!
//! A visibility polygon is a region: the closure of the interior points
//! that its viewpoint sees, with no antennas along walls. So the spurious
//! edge that runs along the ray from q through a map vertex a ends where
//! the region *beside* the ray ends, on the side σ of the ray where V
//! lies: where the rays from q turned infinitesimally towards σ stop,
//! which near any point of the ray is the ray moved infinitesimally
//! (parallel) towards σ. For a direction d, a side σ and a map vertex a,
//! the **exit** of the ray from a is the first point beyond a where that
//! moved ray, coming from inside the map before a, leaves it: a itself when
//! it does not pass a. Running along a wall that has the interior on side
//! σ does not end it; a wall across it, or a vertex whose exterior reaches
//! the σ side of the ray, does (even when the ray itself goes on into the
//! map beyond that vertex).
//!
//! The sweep: rotate and scale so that d points up, with
//! u = d_y·x − d_x·y (across) and w = d_x·x + d_y·y (along), an
//! orientation-preserving map of integers to integers. Sweep the vertices
//! by u; the status holds the edges that cross the current vertical line L
//! properly, ordered bottom to top (edges of a simple polygon do not cross,
//! so their order never changes while both are in it). Going up L from a,
//! the moved ray can leave the map only at *features*: a proper crossing
//! of an edge (the first one above a runs leftward, from inside to
//! outside), or a map vertex on L that it cannot pass (`blocks`). The
//! exit is the first feature, from a itself upward: the lower of the next
//! edge in the status and the next blocking vertex on L.
//!
//! Cost: O(n log n) per direction and side; coordinates are `i128` when the
//! rotated ones stay below 2^126 (differences fit, products are compared
//! exactly by [`crate::fast::cmp_products`]), GMP otherwise.

use crate::fast::cmp_products;
use rug::Integer;
use std::cmp::Ordering;
use std::collections::BTreeSet;
use wai_exact::Point;

/// Where the ray from a map vertex leaves the map.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Exit {
    /// At map vertex `b` (`b` may be the ray's own start: it leaves at once).
    Vertex(usize),
    /// In the interior of map edge `e` (from vertex `e` to the next vertex of its ring).
    Edge(usize),
}

/// A side of a directed ray.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Side {
    /// Counter-clockwise of the direction.
    Left,
    /// Clockwise of the direction.
    Right,
}

/// The exits of the rays of one direction from every vertex of a map, on
/// one side.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RayExits {
    exits: Vec<Exit>,
}

impl RayExits {
    /// The exits in direction `d` (not zero), on side `side`, from every
    /// vertex of the counter-clockwise simple polygon `ring`.
    pub fn new(ring: &[Point], d: (&Integer, &Integer), side: Side) -> RayExits {
        let n = ring.len();
        let next: Vec<usize> = (0..n).map(|i| (i + 1) % n).collect();
        RayExits::of_rings(ring, &next, d, side)
    }

    /// [`RayExits::new`] for every vertex of a map, holes and all: the
    /// edges of every ring, the free space on their left. The sweep needs
    /// only that no two edges cross, which holds for a map with holes too.
    pub fn of_map(map: &wai_map::Map, d: (&Integer, &Integer), side: Side) -> RayExits {
        let next: Vec<usize> = (0..map.n()).map(|i| map.next(i)).collect();
        RayExits::of_rings(map.vertices(), &next, d, side)
    }

    /// The exits over the edges `i → next[i]` of `points`.
    fn of_rings(points: &[Point], next: &[usize], d: (&Integer, &Integer), side: Side) -> RayExits {
        assert!(
            d.0.cmp0() != Ordering::Equal || d.1.cmp0() != Ordering::Equal,
            "a direction is not zero"
        );
        let mut prev = vec![0; next.len()];
        for (i, &j) in next.iter().enumerate() {
            prev[j] = i;
        }
        let links = Links { next, prev: &prev };
        let exits = match rotate_small(points, d) {
            Some(rotated) => sweep(&rotated, &links, side),
            None => sweep(&rotate_big(points, d), &links, side),
        };
        RayExits { exits }
    }

    /// The exit of the ray from vertex `a`.
    pub fn exit(&self, a: usize) -> Exit {
        self.exits[a]
    }
}

/// Each vertex's neighbours along its ring.
struct Links<'a> {
    next: &'a [usize],
    prev: &'a [usize],
}

/// (u, w) of every vertex in `i128`, if each is below 2^126 in magnitude.
fn rotate_small(ring: &[Point], d: (&Integer, &Integer)) -> Option<Vec<[i128; 2]>> {
    let (dx, dy) = (d.0.to_i128()?, d.1.to_i128()?);
    let small = |z: i128| (z.unsigned_abs() < 1u128 << 126).then_some(z);
    ring.iter()
        .map(|p| {
            let u = dy.checked_mul(p.x)?.checked_sub(dx.checked_mul(p.y)?)?;
            let w = dx.checked_mul(p.x)?.checked_add(dy.checked_mul(p.y)?)?;
            Some([small(u)?, small(w)?])
        })
        .collect()
}

fn rotate_big(ring: &[Point], d: (&Integer, &Integer)) -> Vec<[Integer; 2]> {
    ring.iter()
        .map(|p| {
            [
                Integer::from(d.1 * p.x) - Integer::from(d.0 * p.y),
                Integer::from(d.0 * p.x) + Integer::from(d.1 * p.y),
            ]
        })
        .collect()
}

/// Exact coordinates the sweep runs on.
trait Coord: Clone + Ord {
    /// The orientation of (p, q, r): Greater for counter-clockwise.
    fn orient(p: &[Self; 2], q: &[Self; 2], r: &[Self; 2]) -> Ordering;
}

impl Coord for i128 {
    fn orient(p: &[i128; 2], q: &[i128; 2], r: &[i128; 2]) -> Ordering {
        // Coordinates below 2^126: the differences fit.
        cmp_products(q[0] - p[0], r[1] - p[1], q[1] - p[1], r[0] - p[0])
    }
}

impl Coord for Integer {
    fn orient(p: &[Integer; 2], q: &[Integer; 2], r: &[Integer; 2]) -> Ordering {
        let a = Integer::from(&q[0] - &p[0]) * Integer::from(&r[1] - &p[1]);
        let b = Integer::from(&q[1] - &p[1]) * Integer::from(&r[0] - &p[0]);
        a.cmp(&b)
    }
}

/// A key of the sweep status: an edge crossing the sweep line (left end
/// `p`, right end `q`, p.u < q.u), or a query point (`edge` = None, p = q).
struct Key<'a, T> {
    p: &'a [T; 2],
    q: &'a [T; 2],
    edge: Option<usize>,
}

impl<T: Coord> Key<'_, T> {
    /// How `self` lies against edge key `e` where both are defined: the
    /// edges in the status never cross and are never collinear (a simple
    /// polygon), so the side of one endpoint decides, unless it is shared.
    fn against_edge(&self, e: &Key<'_, T>) -> Ordering {
        if self.p[0] >= e.p[0] {
            match T::orient(e.p, e.q, self.p) {
                Ordering::Equal => T::orient(e.p, e.q, self.q),
                o => o,
            }
        } else {
            // e's left end lies above or below `self`.
            match T::orient(self.p, self.q, e.p) {
                Ordering::Equal => T::orient(self.p, self.q, e.q).reverse(),
                o => o.reverse(),
            }
        }
    }
}

impl<T: Coord> Ord for Key<'_, T> {
    fn cmp(&self, other: &Self) -> Ordering {
        match (self.edge, other.edge) {
            (Some(a), Some(b)) if a == b => Ordering::Equal,
            (_, Some(_)) => self.against_edge(other),
            (Some(_), None) => other.against_edge(self).reverse(),
            (None, None) => self.p[1].cmp(&other.p[1]),
        }
    }
}

impl<T: Coord> PartialOrd for Key<'_, T> {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl<T: Coord> PartialEq for Key<'_, T> {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}

impl<T: Coord> Eq for Key<'_, T> {}

/// Whether vertex `b` on the line stops the region beside the ray on side
/// `side` (d pointing up). Near b the ray, moved infinitesimally to that
/// side, sees every direction of the open half-plane of that side (from
/// down, turned towards it, to up, turned towards it), so it passes b only
/// if that half-plane lies in the cone of the interior at b, which turns
/// counter-clockwise from the edge out of b to the edge back into it. A
/// convex cone is narrower than a half-plane: a convex vertex always
/// stops it. A reflex vertex stops it when its exterior wedge (from the
/// edge back to the edge out, less than a half-plane) meets the
/// half-plane: when an edge points strictly into it, or the wedge holds up
/// or down turned towards it.
fn blocks<T: Coord>(r: &[[T; 2]], links: &Links<'_>, b: usize, convex: bool, side: Side) -> bool {
    if convex {
        return true;
    }
    let (prev, v, next) = (&r[links.prev[b]], &r[b], &r[links.next[b]]);
    // The side as the sign of u: left of up is −u.
    let s = match side {
        Side::Left => Ordering::Less,
        Side::Right => Ordering::Greater,
    };
    let (back_u, out_u) = (prev[0].cmp(&v[0]), next[0].cmp(&v[0]));
    if back_u == s || out_u == s {
        return true;
    }
    let (back_w, out_w) = (prev[1].cmp(&v[1]), next[1].cmp(&v[1]));
    // t = (sδ, ±1) is in the open wedge from back to out iff back × t > 0
    // and t × out > 0. back × t = back_u·(±1) − back_w·sδ, and
    // t × out = sδ·out_w − (±1)·out_u: the first term decides unless it
    // is zero.
    let sign = |o: Ordering, positive: bool| if positive { o } else { o.reverse() };
    let in_wedge = |up: bool| {
        // Consecutive vertices differ, so a zero u means a non-zero w.
        let bt = match back_u {
            Ordering::Equal => sign(back_w, s == Ordering::Less),
            u => sign(u, up),
        };
        let to = match out_u {
            Ordering::Equal => sign(out_w, s == Ordering::Greater),
            u => sign(u, !up),
        };
        bt == Ordering::Greater && to == Ordering::Greater
    };
    in_wedge(true) || in_wedge(false)
}

fn sweep<T: Coord>(r: &[[T; 2]], links: &Links<'_>, side: Side) -> Vec<Exit> {
    let n = r.len();
    let convex: Vec<bool> = (0..n)
        .map(|i| {
            let (p, v, q) = (&r[links.prev[i]], &r[i], &r[links.next[i]]);
            T::orient(p, v, q) == Ordering::Greater
        })
        .collect();
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_by(|&a, &b| r[a].cmp(&r[b]));
    // The edge from vertex e to e + 1, left end first, if not vertical.
    let edge_key = |e: usize| {
        let (a, b) = (&r[e], &r[links.next[e]]);
        match a[0].cmp(&b[0]) {
            Ordering::Less => Some(Key {
                p: a,
                q: b,
                edge: Some(e),
            }),
            Ordering::Greater => Some(Key {
                p: b,
                q: a,
                edge: Some(e),
            }),
            Ordering::Equal => None,
        }
    };
    let mut status: BTreeSet<Key<'_, T>> = BTreeSet::new();
    let mut exits = vec![Exit::Vertex(usize::MAX); n];
    let mut start = 0;
    while start < n {
        let u = &r[order[start]][0];
        let end = start
            + order[start..]
                .iter()
                .take_while(|&&v| r[v][0] == *u)
                .count();
        let group = &order[start..end];
        // Edges ending on this line stop crossing it properly.
        for &v in group {
            for e in [links.prev[v], v] {
                if let Some(k) = edge_key(e) {
                    if std::ptr::eq(k.q, &r[v]) {
                        status.remove(&k);
                    }
                }
            }
        }
        // Going up the line: the next vertex that stops the region.
        let mut next_stop: Option<usize> = None;
        for &a in group.iter().rev() {
            let stops = blocks(r, links, a, convex[a], side);
            exits[a] = if stops {
                Exit::Vertex(a)
            } else {
                let probe = Key {
                    p: &r[a],
                    q: &r[a],
                    edge: None,
                };
                let edge = status
                    .range((
                        std::ops::Bound::Excluded(&probe),
                        std::ops::Bound::Unbounded,
                    ))
                    .next();
                match (edge, next_stop) {
                    (None, None) => unreachable!("a ray from inside a bounded map leaves it"),
                    (None, Some(b)) => Exit::Vertex(b),
                    (Some(k), None) => Exit::Edge(k.edge.expect("an edge")),
                    (Some(k), Some(b)) => {
                        // b below the edge's crossing: b comes first.
                        let b_key = Key {
                            p: &r[b],
                            q: &r[b],
                            edge: None,
                        };
                        if b_key.against_edge(k) == Ordering::Less {
                            Exit::Vertex(b)
                        } else {
                            Exit::Edge(k.edge.expect("an edge"))
                        }
                    }
                }
            };
            if stops {
                next_stop = Some(a);
            }
        }
        // Edges starting on this line cross the lines to its right.
        for &v in group {
            for e in [links.prev[v], v] {
                if let Some(k) = edge_key(e) {
                    if std::ptr::eq(k.p, &r[v]) {
                        status.insert(k);
                    }
                }
            }
        }
        start = end;
    }
    exits
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ring(pts: &[(i128, i128)]) -> Vec<Point> {
        pts.iter().map(|&(x, y)| Point { x, y }).collect()
    }

    fn exits(r: &[Point], dx: i64, dy: i64, side: Side) -> Vec<Exit> {
        let d = (Integer::from(dx), Integer::from(dy));
        let e = RayExits::new(r, (&d.0, &d.1), side);
        (0..r.len()).map(|a| e.exit(a)).collect()
    }

    use Exit::{Edge, Vertex};
    use Side::{Left, Right};

    #[test]
    fn convex_vertices_stop_and_reflex_ones_open_one_side() {
        // An L: (2,2) is its reflex vertex; the upper arm spans x in [0, 4].
        let l = ring(&[(0, 0), (2, 0), (2, 2), (4, 2), (4, 4), (0, 4)]);
        for (d, side) in [
            ((0, 1), Left),
            ((0, 1), Right),
            ((1, 1), Left),
            ((1, 1), Right),
        ] {
            let e = exits(&l, d.0, d.1, side);
            for v in [0, 1, 3, 4, 5] {
                assert_eq!(e[v], Vertex(v), "convex vertex {v}");
            }
        }
        // Up from (2,2): on the left the arm opens, on the right the
        // exterior below (4,2)'s edge lies beside the ray at once.
        assert_eq!(exits(&l, 0, 1, Left)[2], Edge(4));
        assert_eq!(exits(&l, 0, 1, Right)[2], Vertex(2));
        // Up-right to the convex corner (4,4) on the left side.
        assert_eq!(exits(&l, 1, 1, Left)[2], Vertex(4));
        assert_eq!(exits(&l, 1, 1, Right)[2], Vertex(2));
    }

    #[test]
    fn a_grazed_reflex_vertex_stops_the_side_where_its_exterior_lies() {
        // The ray from (11,11) in direction (−4,−3) passes (7,8), whose
        // exterior (x > 7, y < 8) lies on the left of the ray although the
        // ray itself goes on into the map beyond it.
        let m = ring(&[
            (0, 4),
            (2, 4),
            (2, 0),
            (5, 0),
            (5, 4),
            (7, 4),
            (7, 8),
            (15, 8),
            (15, 14),
            (11, 14),
            (11, 11),
            (5, 11),
            (5, 8),
            (2, 8),
            (2, 11),
            (0, 11),
        ]);
        assert_eq!(exits(&m, -4, -3, Left)[10], Vertex(6));
        assert_eq!(exits(&m, -4, -3, Right)[10], Vertex(10));
    }
}
