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
    /// The map boundary: map edge `i` (from vertex `i` to `i + 1`).
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
    /// Triangulate `map` (n − 2 triangles) by ear clipping, O(n·r).
    ///
    /// # Edge cases
    /// Orthogonal maps produce many straight (180°) vertices in the shrinking
    /// polygon; they are never ears, and an ear is accepted only if no
    /// reflex or straight vertex of the remaining polygon lies in its closed
    /// triangle, so no diagonal touches a vertex.
    pub fn new(map: &Map) -> Triangulation {
        map.expect_no_holes("the triangulation of the map");
        let v = map.vertices();
        let n = v.len();
        let mut next: Vec<usize> = (0..n).map(|i| (i + 1) % n).collect();
        let mut prev: Vec<usize> = (0..n).map(|i| (i + n - 1) % n).collect();
        let turn = |p: usize, c: usize, q: usize| orientation(v[p], v[c], v[q]);
        let mut alive = vec![true; n];
        // Vertices that are not strictly convex in the remaining polygon.
        let mut concave: Vec<bool> = (0..n)
            .map(|i| turn(prev[i], i, next[i]) != Orientation::CounterClockwise)
            .collect();
        let mut concave_list: Vec<usize> = (0..n).filter(|&i| concave[i]).collect();
        let mut triangles: Vec<[u32; 3]> = Vec::with_capacity(n - 2);
        let mut across: Vec<[Across; 3]> = Vec::with_capacity(n - 2);
        // Diagonal (a, b) created as the third side of a triangle, keyed by
        // its direction in that triangle.
        let mut diagonals: HashMap<(usize, usize), (u32, usize)> = HashMap::new();
        let mut remaining = n;
        let mut c = 0usize;
        let mut since_clip = 0usize;
        while remaining > 3 {
            let (p, q) = (prev[c], next[c]);
            let ear = !concave[c]
                && concave_list.iter().all(|&u| {
                    !alive[u]
                        || u == p
                        || u == q
                        || u == c
                        || !in_closed_triangle(v[p], v[c], v[q], v[u])
                });
            if !ear {
                c = q;
                since_clip += 1;
                assert!(
                    since_clip <= 2 * remaining,
                    "no ear found: the map is not simple"
                );
                continue;
            }
            since_clip = 0;
            let t = triangles.len() as u32;
            let side = |a: usize,
                        b: usize,
                        diagonals: &mut HashMap<(usize, usize), (u32, usize)>,
                        across: &mut Vec<[Across; 3]>| {
                if (a + 1) % n == b {
                    Across::MapEdge(a as u32)
                } else {
                    let (u, k) = diagonals
                        .remove(&(b, a))
                        .expect("an older triangle made this diagonal");
                    across[u as usize][k] = Across::Triangle(t);
                    Across::Triangle(u)
                }
            };
            let s0 = side(p, c, &mut diagonals, &mut across);
            let s1 = side(c, q, &mut diagonals, &mut across);
            triangles.push([p as u32, c as u32, q as u32]);
            // Side 2 (q → p) is linked when a later triangle uses p → q.
            across.push([s0, s1, Across::MapEdge(u32::MAX)]);
            diagonals.insert((q, p), (t, 2));
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
        let p = prev[c];
        let q = next[c];
        let t = triangles.len() as u32;
        let mut last = [Across::MapEdge(0); 3];
        for (k, (a, b)) in [(p, c), (c, q), (q, p)].into_iter().enumerate() {
            last[k] = if (a + 1) % n == b {
                Across::MapEdge(a as u32)
            } else {
                let (u, j) = diagonals
                    .remove(&(b, a))
                    .expect("an older triangle made this diagonal");
                across[u as usize][j] = Across::Triangle(t);
                Across::Triangle(u)
            };
        }
        triangles.push([p as u32, c as u32, q as u32]);
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

    /// Check the structure: n − 2 counter-clockwise triangles of positive
    /// area, areas summing to the map's, symmetric adjacency, every map edge
    /// once, and no diagonal touching a vertex other than its endpoints.
    pub fn sanity_check(&self, map: &Map) -> Result<(), String> {
        let v = map.vertices();
        let n = map.n();
        if self.len() != n - 2 {
            return Err(format!("{} triangles for n = {n}", self.len()));
        }
        let mut area = rug::Integer::new();
        let mut edges_seen = vec![0u8; n];
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
                        if e as usize != x || (x + 1) % n != y {
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
                        if let Some(w) =
                            (0..n).find(|&w| w != x && w != y && on_open_segment(v[x], v[y], v[w]))
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
