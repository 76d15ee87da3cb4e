//! Oracles for the localizer, sharing nothing with its preprocessing.
//!
//! [`brute_force`]: every placement of the robot that sends the skeleton
//! origin v0 to a reflex map vertex (v0 is reflex in V, and a vertex
//! reflex in V that is not spurious is a reflex map vertex, Lemma 3.1; a
//! V with no reflex vertex is a whole convex map, whose every vertex is
//! tried),
//! kept when the visibility polygon computed there equals V translated,
//! exactly. It needs no decomposition and no cells: only V's skeleton
//! origin and the visibility algorithm, which is tested against its own
//! reference.
//!
//! [`one_shot`]: the same placements verified by local conditions on V
//! placed there and by the exits of rays along V's spurious edges (Guibas
//! et al.'s one-shot query), without any visibility polygon.

use crate::ray_exits::{Exit, RayExits, Side};
use crate::shifted;
use crate::view::{RobotView, ViewSkeleton};
use crate::{Answer, Localizer};
use rug::Integer;
use std::cmp::Ordering;
use std::collections::HashMap;
use wai_exact::{orientation_rat, BigVector, Containment, Orientation, Point, RatPoint};
use wai_map::Map;
use wai_visibility::{Skeleton, VisibilityIndex};

/// All positions q with V_q = V + q, ascending: O(r) visibility queries.
pub fn brute_force(index: &VisibilityIndex<'_>, v: &RobotView) -> Vec<RatPoint> {
    let Ok(sk) = v.skeleton() else {
        return Vec::new();
    };
    let map = index.map();
    let mut found = Vec::new();
    for u in v0_images(map) {
        let q = shifted(&sk.robot, map.vertices()[u], 1);
        if map.locate(&q) != Containment::Inside {
            continue;
        }
        let Ok(vq) = index.visibility_polygon(&q) else {
            continue;
        };
        if same_ring(&vq.points(), &v.placed_at(&q)) {
            found.push(q);
        }
    }
    found.sort_by(crate::cmp_points);
    found
}

/// What [`cross_check`] found at one viewpoint.
#[derive(Clone, Debug)]
pub struct CrossCheck {
    pub view: RobotView,
    pub skeleton: ViewSkeleton,
    pub answer: Answer,
    /// Directions the one-shot oracle swept for ray exits.
    pub one_shot_sweeps: usize,
}

/// Localize the view of map point `p` by the localizer and both oracles:
/// the skeleton formed from V alone must be the map-side one (Def 3.7),
/// the answer must contain `p`, and the three answer sets must be equal.
/// `Err` says what differs.
pub fn cross_check(
    loc: &Localizer,
    index: &VisibilityIndex<'_>,
    p: &RatPoint,
) -> Result<CrossCheck, String> {
    let vp = index.visibility_polygon(p).map_err(|e| e.to_string())?;
    let view = RobotView::from_visibility(&vp);
    let skeleton = view.skeleton().map_err(|e| e.to_string())?;
    let map_key = Skeleton::of(index.map(), &vp)
        .map_err(|e| format!("map-side skeleton: {e}"))?
        .key();
    if skeleton.key != map_key {
        return Err("V's skeleton differs from the map-side one".into());
    }
    let answer = loc.localize(&view);
    let positions = answer.positions();
    if !positions.contains(p) {
        return Err(format!(
            "the answer misses the viewpoint: {:?}",
            answer.nowhere
        ));
    }
    let brute = brute_force(index, &view);
    if positions != brute {
        return Err(format!(
            "localizer {} answers, brute force {}",
            positions.len(),
            brute.len()
        ));
    }
    let one_shot = one_shot(index.map(), &view);
    if positions != one_shot.positions {
        return Err(format!(
            "localizer {} answers, one-shot {}",
            positions.len(),
            one_shot.positions.len()
        ));
    }
    Ok(CrossCheck {
        view,
        skeleton,
        answer,
        one_shot_sweeps: one_shot.sweeps,
    })
}

/// The map vertices v0 can land on: the reflex ones; for a convex map
/// (r = 0, outside the thesis's assumption, where v0 is the leftmost, then
/// lowest, vertex) every one.
fn v0_images(map: &wai_map::Map) -> Vec<usize> {
    if map.r() == 0 {
        (0..map.n()).collect()
    } else {
        map.reflex_vertices().to_vec()
    }
}

/// Two cyclic vertex sequences equal up to the starting vertex.
pub fn same_ring(a: &[RatPoint], b: &[RatPoint]) -> bool {
    if a.len() != b.len() {
        return false;
    }
    if a.is_empty() {
        return true;
    }
    let Some(s) = b.iter().position(|p| *p == a[0]) else {
        return false;
    };
    (0..a.len()).all(|i| a[i] == b[(s + i) % b.len()])
}

/// Where a direction `d` leaving map vertex `a` goes, locally.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Cone {
    /// Strictly into the interior of the map.
    Inside,
    /// Strictly out of the map.
    Outside,
    /// Along one of the two map edges at `a`.
    Along,
}

/// Where the direction `d` (homogeneous numerators, any positive scale)
/// goes from map vertex `a`: the interior near `a` is the cone turning
/// counter-clockwise from the edge to the next vertex of its ring to the
/// edge to the previous one.
fn cone(map: &Map, a: usize, d: &BigVector) -> Cone {
    let ring = map.vertices();
    let (p, v, q) = (ring[map.prev(a)], ring[a], ring[map.next(a)]);
    let (out, back) = ((q - v).to_big(), (p - v).to_big());
    let (s1, s2) = (out.cross_sign(d), back.cross_sign(d).reverse());
    let parallel =
        |u: &BigVector| u.cross_sign(d) == Ordering::Equal && u.dot_sign(d) == Ordering::Greater;
    if parallel(&out) || parallel(&back) {
        return Cone::Along;
    }
    let convex = out.cross_sign(&back) == Ordering::Greater;
    let inside = if convex {
        s1 == Ordering::Greater && s2 == Ordering::Greater
    } else {
        s1 == Ordering::Greater || s2 == Ordering::Greater
    };
    if inside {
        Cone::Inside
    } else {
        Cone::Outside
    }
}

/// What [`one_shot`] found.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct OneShot {
    /// Every position q with V_q = V + q, ascending.
    pub positions: Vec<RatPoint>,
    /// Directions for which the ray exits of the map were swept.
    pub sweeps: usize,
}

/// The one-shot localization without preprocessing of Guibas, Motwani and
/// Raghavan (thesis sec. 3.2): the O(r) placements that send v0 to a
/// reflex vertex, each verified in O(m) by local conditions on V + q
/// instead of computing V_q. With P = V + q:
///
/// 1. every non-spurious vertex of P is a map vertex (a hash lookup);
/// 2. every full edge of P is a map edge, and every half or partial edge
///    lies on one map edge, running the same way;
/// 3. at a non-spurious vertex a of P with no spurious edge beyond it, the
///    ray from q leaves the map at a on both sides (a local test at the
///    map vertex);
/// 4. every spurious edge of P runs from its map vertex a exactly to the
///    exit of the ray from a in its direction, on the side where P lies
///    ([`RayExits`]).
///
/// Then ∂P lies in M, so P ⊆ M when M has no holes, and on a map with
/// holes when no hole lies inside P (5: a point inside each hole is not
/// inside P, since a hole meets ∂P ⊆ M in boundary points only); q sees all
/// of P; and
/// every ray from q in a direction through no vertex of P leaves M's
/// interior where it leaves P, so V_q = P (both are closures of what q
/// sees). Conversely V_q = P satisfies all four. Rays that run along walls,
/// graze vertices or end at a map vertex need no special case: the
/// one-sided exits say where the region beside each ray ends.
///
/// Cost: O(n) to hash the vertices; per placement O(m) lookups and tests;
/// and, for each direction of a spurious edge of V, one sweep of the map
/// in O(n log n) (Guibas et al.'s trapezoidalization along that direction,
/// O(n) with a linear-time triangulation). A sweep is made only when a
/// placement reaches test 4, and once per direction: O(n + r·m + s·n log n)
/// for s spurious edges, O(mn log n) at worst.
pub fn one_shot(map: &Map, v: &RobotView) -> OneShot {
    let mut out = OneShot {
        positions: Vec::new(),
        sweeps: 0,
    };
    let Ok(sk) = v.skeleton() else {
        return out;
    };
    let ring = map.vertices();
    let inside_holes = hole_points(map);
    let at: HashMap<Point, usize> = ring.iter().enumerate().map(|(i, &p)| (p, i)).collect();
    let verts = v.vertices();
    let m = verts.len();
    let (radial, spurious) = v.classify();
    // Each spurious vertex ends one spurious edge (a checked V has no
    // spike and no 180° vertex): its near end, and the index of the ray
    // (direction, and the side of it where V lies) among the distinct
    // ones. V lies left of an edge run counter-clockwise: left of the ray
    // when the edge runs outwards.
    let mut near_of = vec![usize::MAX; m];
    let mut ray_of = vec![usize::MAX; m];
    let mut rays: Vec<((Integer, Integer), Side)> = Vec::new();
    for i in (0..m).filter(|&i| radial[i]) {
        let j = (i + 1) % m;
        let (near, far, side) = if spurious[j] {
            (i, j, Side::Left)
        } else {
            (j, i, Side::Right)
        };
        near_of[far] = near;
        let ray = (primitive(&verts[near]), side);
        ray_of[far] = rays.iter().position(|e| *e == ray).unwrap_or_else(|| {
            rays.push(ray);
            rays.len() - 1
        });
    }
    let mut tables: Vec<Option<RayExits>> = vec![None; rays.len()];
    // Offsets of V's vertices from v0, exact.
    let v0 = &verts[sk.origin_index];
    let rel: Vec<RatPoint> = verts.iter().map(|p| p.sub(v0)).collect();
    'placement: for u in v0_images(map) {
        let uo = ring[u];
        let place = |p: &RatPoint| shifted(p, uo, 1);
        // 1. Non-spurious vertices on map vertices.
        let mut idx = vec![usize::MAX; m];
        for i in 0..m {
            if !spurious[i] {
                let Some(p) = place(&rel[i]).to_point() else {
                    continue 'placement;
                };
                match at.get(&p) {
                    Some(&a) => idx[i] = a,
                    None => continue 'placement,
                }
            }
        }
        // 2. Full and half edges (partial ones after 4).
        for i in 0..m {
            let j = (i + 1) % m;
            if radial[i] {
                continue;
            }
            let ok = match (spurious[i], spurious[j]) {
                (false, false) => idx[j] == map.next(idx[i]),
                (false, true) => on_edge(map, idx[i], &place(&rel[j])),
                (true, false) => on_edge(map, map.prev(idx[j]), &place(&rel[i])),
                (true, true) => true,
            };
            if !ok {
                continue 'placement;
            }
        }
        // 3. Rays that must stop at their non-spurious vertex.
        for i in 0..m {
            let beyond = (radial[i] && spurious[(i + 1) % m])
                || (radial[(i + m - 1) % m] && spurious[(i + m - 1) % m]);
            if spurious[i] || beyond {
                continue;
            }
            let d = BigVector::new(verts[i].hx().clone(), verts[i].hy().clone());
            if cone(map, idx[i], &d) != Cone::Outside {
                continue 'placement;
            }
        }
        // 4. Spurious edges end where their rays leave the map.
        let mut exit_at = vec![Exit::Vertex(usize::MAX); m];
        for far in 0..m {
            if !spurious[far] {
                continue;
            }
            let k = ray_of[far];
            let table = tables[k].get_or_insert_with(|| {
                out.sweeps += 1;
                let ((dx, dy), side) = &rays[k];
                RayExits::of_map(map, (dx, dy), *side)
            });
            let exit = table.exit(idx[near_of[far]]);
            let s = place(&rel[far]);
            let ok = match exit {
                Exit::Vertex(b) => s.to_point() == Some(ring[b]),
                // s lies on the ray beyond its map vertex, which meets the
                // line of the edge once.
                Exit::Edge(e) => {
                    let (a, b) = (RatPoint::from(ring[e]), RatPoint::from(ring[map.next(e)]));
                    orientation_rat(&a, &b, &s) == Orientation::Collinear
                }
            };
            if !ok {
                continue 'placement;
            }
            exit_at[far] = exit;
        }
        // 2 (cont.). A partial edge lies on the map edge its first end
        // exits on (at a vertex exit, one of the two edges there).
        for i in 0..m {
            let j = (i + 1) % m;
            if radial[i] || !(spurious[i] && spurious[j]) {
                continue;
            }
            let edges = match exit_at[i] {
                Exit::Edge(e) => [e, e],
                Exit::Vertex(b) => [b, map.prev(b)],
            };
            let (s1, s2) = (place(&rel[i]), place(&rel[j]));
            let on_one = edges.iter().any(|&e| {
                on_edge(map, e, &s1) && on_edge(map, e, &s2) && same_way(map, e, &s1, &s2)
            });
            if !on_one {
                continue 'placement;
            }
        }
        // 5. No hole inside P.
        if !inside_holes.is_empty() {
            let p: Vec<RatPoint> = rel.iter().map(place).collect();
            if inside_holes.iter().any(|h| strictly_inside(&p, h)) {
                continue 'placement;
            }
        }
        out.positions.push(shifted(&sk.robot, uo, 1));
    }
    out.positions.sort_by(crate::cmp_points);
    out
}

/// The direction of `p` from the origin as a primitive integer vector.
fn primitive(p: &RatPoint) -> (Integer, Integer) {
    let g = Integer::from(p.hx().gcd_ref(p.hy()));
    (Integer::from(p.hx() / &g), Integer::from(p.hy() / &g))
}

/// A point strictly inside each hole of `map`: for the hole's least vertex
/// v (a convex corner of the hole) with neighbours u and w, the centroid of
/// u v w if no other vertex of the hole lies in that closed triangle, else
/// the midpoint of v and the vertex in it farthest from the line u w
/// (a diagonal of the hole).
fn hole_points(map: &Map) -> Vec<RatPoint> {
    let v = map.vertices();
    (1..=map.hole_count())
        .map(|k| {
            let range = map.ring_range(k);
            let c = range
                .clone()
                .min_by_key(|&i| (v[i].x, v[i].y))
                .expect("a ring");
            let (u, w) = (map.prev(c), map.next(c));
            let (pu, pc, pw) = (v[u], v[c], v[w]);
            let in_triangle = |x: Point| {
                use wai_exact::orientation as o;
                let s = [o(pu, pc, x), o(pc, pw, x), o(pw, pu, x)];
                let turn = o(pu, pc, pw);
                s.iter().all(|&t| t == turn || t == Orientation::Collinear)
            };
            let far = range
                .filter(|&i| i != u && i != c && i != w && in_triangle(v[i]))
                .max_by_key(|&i| (v[w] - v[u]).to_big().cross(&(v[i] - v[u]).to_big()).abs());
            match far {
                Some(f) => RatPoint::midpoint(&RatPoint::from(pc), &RatPoint::from(v[f])),
                None => {
                    let three = |a: i128, b: i128, c: i128| Integer::from(a) + b + c;
                    RatPoint::new(
                        three(pu.x, pc.x, pw.x),
                        three(pu.y, pc.y, pw.y),
                        Integer::from(3),
                    )
                    .expect("w > 0")
                }
            }
        })
        .collect()
}

/// Whether `x` lies strictly inside the polygon `p` (rational vertices,
/// any simple polygon): the crossing number, exactly.
fn strictly_inside(p: &[RatPoint], x: &RatPoint) -> bool {
    // a.y compared with x.y, through the positive denominators.
    let above = |a: &RatPoint| {
        (Integer::from(a.hy() * x.hw()) - Integer::from(x.hy() * a.hw())).cmp0()
            == Ordering::Greater
    };
    let m = p.len();
    let mut inside = false;
    for i in 0..m {
        let (a, b) = (&p[i], &p[(i + 1) % m]);
        let o = orientation_rat(a, b, x);
        if o == Orientation::Collinear {
            let (d1, d2) = (x.sub(a), b.sub(x));
            let e = b.sub(a);
            if d1.dot_sign(&e) != Ordering::Less && d2.dot_sign(&e) != Ordering::Less {
                return false; // on the boundary
            }
        }
        let (aa, ba) = (above(a), above(b));
        // An upward edge crosses x's rightward ray when x lies left of it.
        if aa != ba && (o == Orientation::CounterClockwise) == ba {
            inside = !inside;
        }
    }
    inside
}

/// Whether `p` lies on the closed map edge `e`.
fn on_edge(map: &Map, e: usize, p: &RatPoint) -> bool {
    let ring = map.vertices();
    let (a, b) = (ring[e], ring[map.next(e)]);
    let (a, b) = (RatPoint::from(a), RatPoint::from(b));
    if orientation_rat(&a, &b, p) != Orientation::Collinear {
        return false;
    }
    let d1 = p.sub(&a);
    let d2 = b.sub(p);
    let e = b.sub(&a);
    d1.dot_sign(&e) != Ordering::Less && d2.dot_sign(&e) != Ordering::Less
}

/// Whether s1 → s2 runs the way of map edge `e`.
fn same_way(map: &Map, e: usize, s1: &RatPoint, s2: &RatPoint) -> bool {
    let ring = map.vertices();
    let (a, b) = (ring[e], ring[map.next(e)]);
    let d = s2.sub(s1);
    (Integer::from(d.hx() * (b.x - a.x)) + Integer::from(d.hy() * (b.y - a.y))).cmp0()
        == Ordering::Greater
}
