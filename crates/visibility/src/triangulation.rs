//! A triangulation of the map by ear clipping, with adjacency: the
//! preprocessing of the triangular-expansion visibility algorithm.

use std::collections::HashMap;
use wai_exact::{orientation, Orientation, Point};
use wai_map::Map;

/// What lies across a side of a triangle.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Across {
    /// Another triangle.
    Triangle(u32),
    /// The map boundary: map edge `i` (from vertex `i` to
    /// [`Map::next`]`(i)`).
    MapEdge(u32),
}

/// A triangulation of a map whose vertices are exactly the map's vertices.
///
/// Triangle `t` has vertices `triangles[t]` counter-clockwise; its side `k`
/// runs from corner `k` to corner `k + 1` and `across[t][k]` says what lies
/// beyond it.
#[derive(Clone, Debug)]
pub struct Triangulation {
    pub(crate) triangles: Vec<[u32; 3]>,
    pub(crate) across: Vec<[Across; 3]>,
    /// By triangle and side with a triangle across: that triangle's side
    /// back (`entry`).
    entries: Vec<[u8; 3]>,
}

impl Triangulation {
    /// Triangulate `map` (n + 2h − 2 triangles for h holes) by ear
    /// clipping, O(n·r); holes are first joined to the outer ring by
    /// bridges ([`bridged_ring`]), which become diagonals.
    ///
    /// # Edge cases
    /// Orthogonal maps produce many straight (180°) vertices in the shrinking
    /// polygon; they are never ears, and an ear is accepted only if no
    /// reflex or straight vertex of the remaining polygon lies in its closed
    /// triangle, so no diagonal touches a vertex. A bridge's ends appear
    /// twice in the ring; an ear at one appearance is also refused if an
    /// edge at another appearance of one of its corners enters it.
    pub fn new(map: &Map) -> Triangulation {
        let v = map.vertices();
        let ring: Vec<usize> = if map.has_holes() {
            bridged_ring(map)
        } else {
            (0..map.n()).collect()
        };
        // Slots: places in the ring; `at[s]` is slot s's vertex.
        let at = |s: usize| ring[s];
        let n = ring.len();
        let mut next: Vec<usize> = (0..n).map(|i| (i + 1) % n).collect();
        let mut prev: Vec<usize> = (0..n).map(|i| (i + n - 1) % n).collect();
        let turn = |p: usize, c: usize, q: usize| orientation(v[at(p)], v[at(c)], v[at(q)]);
        let mut alive = vec![true; n];
        // Slots of vertices that appear more than once (bridge ends).
        let mut seen = vec![0u8; map.n()];
        for &i in &ring {
            seen[i] += 1;
        }
        let shared: Vec<usize> = (0..n).filter(|&s| seen[at(s)] > 1).collect();
        // Slots that are not strictly convex in the remaining polygon.
        let mut concave: Vec<bool> = (0..n)
            .map(|i| turn(prev[i], i, next[i]) != Orientation::CounterClockwise)
            .collect();
        let mut concave_list: Vec<usize> = (0..n).filter(|&i| concave[i]).collect();
        let mut triangles: Vec<[u32; 3]> = Vec::with_capacity(n - 2);
        let mut across: Vec<[Across; 3]> = Vec::with_capacity(n - 2);
        // Diagonal (a, b) (vertices) met as a side of one triangle and
        // waiting for the triangle across, keyed by its direction there.
        let mut diagonals: HashMap<(usize, usize), (u32, usize)> = HashMap::new();
        let side = |t: u32,
                    k: usize,
                    a: usize,
                    b: usize,
                    diagonals: &mut HashMap<(usize, usize), (u32, usize)>,
                    across: &mut Vec<[Across; 3]>| {
            if map.next(a) == b {
                Across::MapEdge(a as u32)
            } else if let Some((u, j)) = diagonals.remove(&(b, a)) {
                across[u as usize][j] = Across::Triangle(t);
                Across::Triangle(u)
            } else {
                diagonals.insert((a, b), (t, k));
                Across::MapEdge(u32::MAX)
            }
        };
        let mut remaining = n;
        let mut c = 0usize;
        let mut since_clip = 0usize;
        while remaining > 3 {
            let (p, q) = (prev[c], next[c]);
            let corners = [at(p), at(c), at(q)];
            let ear = !concave[c]
                && concave_list.iter().all(|&u| {
                    !alive[u]
                        || corners.contains(&at(u))
                        || !in_closed_triangle(v[at(p)], v[at(c)], v[at(q)], v[at(u)])
                })
                && shared.iter().all(|&u| {
                    !alive[u]
                        || u == p
                        || u == c
                        || u == q
                        || !corners.contains(&at(u))
                        || !enters(v, corners, at(u), [at(prev[u]), at(next[u])])
                });
            if !ear {
                c = q;
                since_clip += 1;
                assert!(
                    since_clip <= 2 * remaining,
                    "no ear found: the map is not valid"
                );
                continue;
            }
            since_clip = 0;
            let t = triangles.len() as u32;
            across.push([Across::MapEdge(u32::MAX); 3]);
            let [a, b, d] = corners;
            for (k, (x, y)) in [(a, b), (b, d), (d, a)].into_iter().enumerate() {
                let s = side(t, k, x, y, &mut diagonals, &mut across);
                across[t as usize][k] = s;
            }
            triangles.push([a as u32, b as u32, d as u32]);
            alive[c] = false;
            next[p] = q;
            prev[q] = p;
            remaining -= 1;
            for x in [p, q] {
                let was = concave[x];
                concave[x] = turn(prev[x], x, next[x]) != Orientation::CounterClockwise;
                if concave[x] && !was {
                    concave_list.push(x);
                }
            }
            concave_list.retain(|&u| alive[u] && concave[u]);
            c = p;
        }
        // The last triangle.
        let (p, q) = (prev[c], next[c]);
        let t = triangles.len() as u32;
        across.push([Across::MapEdge(u32::MAX); 3]);
        let [a, b, d] = [at(p), at(c), at(q)];
        for (k, (x, y)) in [(a, b), (b, d), (d, a)].into_iter().enumerate() {
            let s = side(t, k, x, y, &mut diagonals, &mut across);
            across[t as usize][k] = s;
        }
        debug_assert!(diagonals.is_empty(), "every diagonal has two triangles");
        let last = across.pop().expect("just pushed");
        triangles.push([a as u32, b as u32, d as u32]);
        across.push(last);
        let entries = (0..triangles.len())
            .map(|t| {
                let c = triangles[t];
                let mut back = [0u8; 3];
                for (k, b) in back.iter_mut().enumerate() {
                    if let Across::Triangle(u) = across[t][k] {
                        let (a, d) = (c[k], c[(k + 1) % 3]);
                        let cu = triangles[u as usize];
                        let j = (0..3)
                            .find(|&j| cu[j] == d && cu[(j + 1) % 3] == a)
                            .expect("symmetric adjacency");
                        *b = j as u8;
                    }
                }
                back
            })
            .collect();
        Triangulation {
            triangles,
            across,
            entries,
        }
    }

    /// For side `side` of triangle `t` with triangle u across it, the side
    /// of u that is the same segment (run the other way).
    pub(crate) fn entry(&self, t: usize, side: usize) -> usize {
        self.entries[t][side] as usize
    }

    pub fn len(&self) -> usize {
        self.triangles.len()
    }
    pub fn is_empty(&self) -> bool {
        self.triangles.is_empty()
    }
    pub fn triangle(&self, t: usize) -> [usize; 3] {
        self.triangles[t].map(|i| i as usize)
    }
    pub fn across(&self, t: usize, side: usize) -> Across {
        self.across[t][side]
    }

    /// Check the structure: n + 2h − 2 counter-clockwise triangles of
    /// positive area, areas summing to the map's, symmetric adjacency,
    /// every map edge once, and no diagonal touching a vertex other than
    /// its endpoints.
    pub fn sanity_check(&self, map: &Map) -> Result<(), String> {
        let v = map.vertices();
        let n = map.n();
        let h = map.hole_count();
        if self.len() != n + 2 * h - 2 {
            return Err(format!("{} triangles for n = {n}, h = {h}", self.len()));
        }
        let mut area = rug::Integer::new();
        let mut edges_seen = vec![0u8; n];
        // Vertices by abscissa: a diagonal is tested against those in its
        // x-range only.
        let mut by_x: Vec<usize> = (0..n).collect();
        by_x.sort_by_key(|&w| v[w].x);
        for t in 0..self.len() {
            let [a, b, c] = self.triangle(t);
            if orientation(v[a], v[b], v[c]) != Orientation::CounterClockwise {
                return Err(format!("triangle {t} is not counter-clockwise"));
            }
            area += wai_exact::signed_area_twice(&[v[a], v[b], v[c]]);
            let corners = [a, b, c];
            for k in 0..3 {
                let (x, y) = (corners[k], corners[(k + 1) % 3]);
                match self.across(t, k) {
                    Across::MapEdge(e) => {
                        if e as usize != x || map.next(x) != y {
                            return Err(format!("triangle {t} side {k} is not map edge {e}"));
                        }
                        edges_seen[e as usize] += 1;
                    }
                    Across::Triangle(u) => {
                        let back = (0..3).any(|j| {
                            let cu = self.triangle(u as usize);
                            cu[j] == y
                                && cu[(j + 1) % 3] == x
                                && self.across(u as usize, j) == Across::Triangle(t as u32)
                        });
                        if !back {
                            return Err(format!("triangle {t} side {k}: adjacency not symmetric"));
                        }
                        let (lo, hi) = (v[x].x.min(v[y].x), v[x].x.max(v[y].x));
                        let from = by_x.partition_point(|&w| v[w].x < lo);
                        let to = by_x.partition_point(|&w| v[w].x <= hi);
                        if let Some(&w) = by_x[from..to]
                            .iter()
                            .find(|&&w| w != x && w != y && on_open_segment(v[x], v[y], v[w]))
                        {
                            return Err(format!("diagonal {x}-{y} touches vertex {w}"));
                        }
                    }
                }
            }
        }
        if area != map.area_twice() {
            return Err("triangle areas do not sum to the map's area".into());
        }
        if let Some(e) = edges_seen.iter().position(|&k| k != 1) {
            return Err(format!("map edge {e} bounds {} triangles", edges_seen[e]));
        }
        Ok(())
    }
}

fn on_open_segment(a: Point, b: Point, p: Point) -> bool {
    p != a && p != b && wai_exact::Segment::new(a, b).is_some_and(|s| s.contains(p))
}

/// Whether `u` lies in the closed counter-clockwise triangle `a b c`.
fn in_closed_triangle(a: Point, b: Point, c: Point, u: Point) -> bool {
    orientation(a, b, u) != Orientation::Clockwise
        && orientation(b, c, u) != Orientation::Clockwise
        && orientation(c, a, u) != Orientation::Clockwise
}

/// Whether an edge from corner `x` of the counter-clockwise triangle
/// `corners` towards either of `ends` runs into the triangle's interior.
fn enters(v: &[Point], corners: [usize; 3], x: usize, ends: [usize; 2]) -> bool {
    let k = corners.iter().position(|&c| c == x).expect("x is a corner");
    let (a, b) = (corners[(k + 1) % 3], corners[(k + 2) % 3]);
    ends.iter().any(|&y| {
        orientation(v[x], v[a], v[y]) == Orientation::CounterClockwise
            && orientation(v[x], v[y], v[b]) == Orientation::CounterClockwise
    })
}

/// The map's rings joined into one weakly simple ring of vertex indices by
/// one bridge per hole (each bridge run both ways, so its two ends appear
/// twice), the free space on the left throughout.
///
/// Holes are joined in order of their rightmost vertex M, right to left,
/// each by the classic construction: the ray from M to the right meets
/// the ring joined so far first at a vertex (the bridge's other end) or
/// inside an edge at I; then, of the vertices in the closed triangle M, I,
/// P (P the edge's end further right), the one seen at the least angle
/// from the ray, the nearest of those — visible from M, as nothing can
/// cross the triangle without putting a vertex at a smaller angle. Holes
/// not yet joined lie left of M and cannot meet the triangle. Decisions are
/// exact (rational crossing abscissae, orientations).
pub fn bridged_ring(map: &Map) -> Vec<usize> {
    use rug::{Integer, Rational};
    let v = map.vertices();
    let mut ring: Vec<usize> = map.ring_range(0).collect();
    // Each hole's rightmost vertex (the highest of those), holes right first.
    let mut holes: Vec<(usize, usize)> = (1..=map.hole_count())
        .map(|k| {
            let m = map
                .ring_range(k)
                .max_by_key(|&i| (v[i].x, v[i].y))
                .expect("a hole has vertices");
            (k, m)
        })
        .collect();
    holes.sort_by_key(|&(k, m)| (std::cmp::Reverse(v[m].x), std::cmp::Reverse(v[m].y), k));
    for (k, m) in holes {
        let mp = v[m];
        // The nearest point of the ring on the ray y = M.y, x > M.x.
        let mut best: Option<(Rational, Option<usize>, usize)> = None; // (x, vertex hit, slot of edge)
        let len = ring.len();
        for s in 0..len {
            let (a, b) = (ring[s], ring[(s + 1) % len]);
            let (pa, pb) = (v[a], v[b]);
            let (da, db) = (pa.y - mp.y, pb.y - mp.y);
            let hit: Option<(Rational, Option<usize>)> = if da == 0 && db == 0 {
                let first = if pa.x <= pb.x { a } else { b };
                (v[first].x > mp.x).then(|| (Rational::from(v[first].x), Some(first)))
            } else if da == 0 {
                (pa.x > mp.x).then(|| (Rational::from(pa.x), Some(a)))
            } else if db == 0 {
                (pb.x > mp.x).then(|| (Rational::from(pb.x), Some(b)))
            } else if (da < 0) != (db < 0) {
                // x = A.x + (M.y − A.y)(B.x − A.x) / (B.y − A.y).
                let x = Rational::from(pa.x)
                    + Rational::from((
                        Integer::from(-da) * Integer::from(pb.x - pa.x),
                        Integer::from(pb.y - pa.y),
                    ));
                (x > mp.x).then_some((x, None))
            } else {
                None
            };
            if let Some((x, vertex)) = hit {
                let better = match &best {
                    None => true,
                    Some((bx, bv, _)) => x < *bx || (x == *bx && vertex.is_some() && bv.is_none()),
                };
                if better {
                    best = Some((x, vertex, s));
                }
            }
        }
        let (ix, vertex, s) = best.expect("the outer ring surrounds every hole");
        let target = match vertex {
            Some(w) => w,
            None => {
                let (a, b) = (ring[s], ring[(s + 1) % len]);
                let pnt = if v[b].x > v[a].x { b } else { a };
                // The closed triangle M, I, P, with I = (ix, M.y): a point
                // is in it when it is on P's side of the ray (or on it),
                // right of M, and not beyond the line I P from M.
                let side_p = (v[pnt].y - mp.y).signum();
                let inside = |w: usize| -> bool {
                    let q = v[w];
                    let dy = q.y - mp.y;
                    if q.x <= mp.x || dy.signum() == -side_p {
                        return false;
                    }
                    // Not beyond line I–P: same side as M (or on it).
                    // side(Q) = (P − I) × (Q − I), exactly over the
                    // denominator of I.x.
                    let (num, den) = (ix.numer().clone(), ix.denom().clone());
                    let cross = |q: Point| -> Integer {
                        let px = Integer::from(v[pnt].x) * &den - &num;
                        let py = Integer::from(v[pnt].y - mp.y) * &den;
                        let qx = Integer::from(q.x) * &den - &num;
                        let qy = Integer::from(q.y - mp.y) * &den;
                        px * qy - py * qx
                    };
                    let (sm, sq) = (cross(mp).signum(), cross(q).signum());
                    sq == 0 || sq == sm
                };
                let mut pick = pnt;
                for &w in &ring {
                    if w == m || !inside(w) {
                        continue;
                    }
                    // Smaller angle: |dy_w| · dx_pick < |dy_pick| · dx_w;
                    // at the same angle, nearer.
                    let (dxw, dyw) = (v[w].x - mp.x, (v[w].y - mp.y).abs());
                    let (dxp, dyp) = (v[pick].x - mp.x, (v[pick].y - mp.y).abs());
                    let lhs = Integer::from(dyw) * Integer::from(dxp);
                    let rhs = Integer::from(dyp) * Integer::from(dxw);
                    if lhs < rhs || (lhs == rhs && dxw < dxp) {
                        pick = w;
                    }
                }
                pick
            }
        };
        // The appearance of the target whose free-space wedge holds M.
        let len = ring.len();
        let slot = (0..len)
            .filter(|&s| ring[s] == target)
            .find(|&s| {
                let (pv, nv) = (v[ring[(s + len - 1) % len]], v[ring[(s + 1) % len]]);
                in_wedge(v[target], nv, pv, mp)
            })
            .expect("the bridge's end sees M inside its wedge");
        let hole: Vec<usize> = {
            let r = map.ring_range(k);
            let at = m - r.start;
            let mut h: Vec<usize> = r.clone().skip(at).chain(r.clone().take(at)).collect();
            h.push(m);
            h
        };
        let mut joined = Vec::with_capacity(len + hole.len() + 1);
        joined.extend_from_slice(&ring[..=slot]);
        joined.extend_from_slice(&hole);
        joined.push(target);
        joined.extend_from_slice(&ring[slot + 1..]);
        ring = joined;
    }
    ring
}

/// Whether direction `x − o` lies strictly inside the free-space wedge at
/// `o`, swept counter-clockwise from `o → next` to `o → prev`.
fn in_wedge(o: Point, next: Point, prev: Point, x: Point) -> bool {
    use Orientation::{Clockwise, CounterClockwise};
    match orientation(o, next, prev) {
        // Convex wedge.
        CounterClockwise => {
            orientation(o, next, x) == CounterClockwise
                && orientation(o, x, prev) == CounterClockwise
        }
        // Reflex wedge: not in the closed convex complement.
        Clockwise => {
            !(orientation(o, prev, x) != Clockwise && orientation(o, x, next) != Clockwise)
        }
        // Straight: the half-plane left of o → next.
        _ => orientation(o, next, x) == CounterClockwise,
    }
}
