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
//! placed there (Guibas et al.'s one-shot query), without a visibility
//! polygon except in degenerate placements.

use crate::view::{RobotView, ViewSkeleton};
use crate::{dot_sign, shifted, sub};
use crate::{Answer, Localizer};
use rug::Integer;
use std::cmp::Ordering;
use std::collections::HashMap;
use wai_exact::{orientation_rat, sees, Containment, Orientation, Point, RatPoint};
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
        if wai_exact::locate_rat(map.vertices(), &q) != Containment::Inside {
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
    /// Placements the one-shot oracle decided by computing V_q.
    pub one_shot_degenerate: usize,
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
    let (one_shot, one_shot_degenerate) = one_shot(index, &view);
    if positions != one_shot {
        return Err(format!(
            "localizer {} answers, one-shot {}",
            positions.len(),
            one_shot.len()
        ));
    }
    Ok(CrossCheck {
        view,
        skeleton,
        answer,
        one_shot_degenerate,
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

/// The sign of u × d for an integer u and a homogeneous direction d.
fn cross_dir(u: (i128, i128), d: &(Integer, Integer)) -> Ordering {
    (Integer::from(u.0) * &d.1 - Integer::from(u.1) * &d.0).cmp0()
}

/// Where the direction `d` (homogeneous numerators, any positive scale)
/// goes from map vertex `a` of the counter-clockwise `ring`: the interior
/// near `a` is the cone turning counter-clockwise from the edge to `a + 1`
/// to the edge to `a − 1`.
fn cone(ring: &[Point], a: usize, d: &(Integer, Integer)) -> Cone {
    let n = ring.len();
    let (p, v, q) = (ring[(a + n - 1) % n], ring[a], ring[(a + 1) % n]);
    let out = (q.x - v.x, q.y - v.y);
    let back = (p.x - v.x, p.y - v.y);
    let (s1, s2) = (cross_dir(out, d), cross_dir(back, d).reverse());
    let parallel = |u: (i128, i128)| {
        cross_dir(u, d) == Ordering::Equal
            && (Integer::from(u.0) * &d.0 + Integer::from(u.1) * &d.1).cmp0() == Ordering::Greater
    };
    if parallel(out) || parallel(back) {
        return Cone::Along;
    }
    let convex = Integer::from(out.0) * back.1 - Integer::from(out.1) * back.0 > 0;
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

/// The one-shot localization without preprocessing (after Guibas, Motwani
/// and Raghavan, thesis sec. 3.3): the O(r) placements that send v0 to a
/// reflex vertex, each verified by local conditions on V + q instead of
/// computing V_q. With P = V + q:
///
/// 1. every non-spurious vertex of P is a map vertex (a hash lookup);
/// 2. every full edge of P is a map edge, and every half or partial edge
///    lies on one map edge, running the same way;
/// 3. at every non-spurious vertex the ray from q continues into the map
///    exactly when P has a spurious edge there (a local test at the map
///    vertex), and every spurious edge of P runs through the interior of
///    the map to its far end (one exact segment test, O(n)).
///
/// Then ∂P lies in M, so P ⊆ M (M has no holes) and q sees all of P; and
/// every ray from q leaves M where it leaves P, so V_q = P. A placement
/// where a ray from q runs along a map edge, grazes a vertex on a spurious
/// edge or ends at a map vertex (the degenerate cases, where the local
/// tests do not decide) is decided by computing V_q exactly instead, and
/// counted in the second value returned.
///
/// Cost: O(n) to hash the vertices, then per placement O(m) lookups and
/// one O(n) segment test per spurious edge: O(n + r·(m + s·n)) for s
/// spurious edges. Guibas et al. replace the segment tests by a
/// trapezoidal decomposition of the map along the spurious edges'
/// directions, built in O(mn), for O(mn) in all; that structure is not
/// built here.
pub fn one_shot(index: &VisibilityIndex<'_>, v: &RobotView) -> (Vec<RatPoint>, usize) {
    let Ok(sk) = v.skeleton() else {
        return (Vec::new(), 0);
    };
    let map = index.map();
    let ring = map.vertices();
    let n = ring.len();
    let at: HashMap<Point, usize> = ring.iter().enumerate().map(|(i, &p)| (p, i)).collect();
    let verts = v.vertices();
    let m = verts.len();
    let (radial, spurious) = v.classify();
    // Offsets of V's vertices from v0, exact.
    let v0 = &verts[sk.origin_index];
    let rel: Vec<RatPoint> = verts.iter().map(|p| sub(p, v0)).collect();
    let mut found = Vec::new();
    let mut degenerate = 0;
    'placement: for u in v0_images(map) {
        let uo = ring[u];
        let place = |p: &RatPoint| shifted(p, uo, 1);
        let q = place(&sk.robot);
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
        let mut unsure = false;
        for i in 0..m {
            let j = (i + 1) % m;
            if radial[i] {
                // 3. A spurious edge: near end kept, far end spurious.
                let (near, far) = if spurious[j] { (i, j) } else { (j, i) };
                let (a, s) = (idx[near], place(&rel[far]));
                let d = direction(&ring[a], &s);
                match cone(ring, a, &d) {
                    Cone::Inside => {}
                    Cone::Outside => continue 'placement,
                    Cone::Along => unsure = true,
                }
                if s.to_point().is_some_and(|p| at.contains_key(&p)) {
                    unsure = true; // ends at a map vertex
                } else if !sees(ring, &RatPoint::from(ring[a]), &s).is_visible() {
                    // Crossing the boundary rejects; grazing or running
                    // along it is decided exactly below.
                    unsure = true;
                }
                continue;
            }
            // 2. A solid edge.
            match (spurious[i], spurious[j]) {
                (false, false) => {
                    if idx[j] != (idx[i] + 1) % n {
                        continue 'placement;
                    }
                }
                (false, true) => {
                    let a = idx[i];
                    if !on_edge(ring, a, &place(&rel[j])) {
                        continue 'placement;
                    }
                }
                (true, false) => {
                    let b = idx[j];
                    if !on_edge(ring, (b + n - 1) % n, &place(&rel[i])) {
                        continue 'placement;
                    }
                }
                (true, true) => {
                    let (s1, s2) = (place(&rel[i]), place(&rel[j]));
                    let on_one = (0..n).any(|e| {
                        on_edge(ring, e, &s1)
                            && on_edge(ring, e, &s2)
                            && same_way(ring, e, &s1, &s2)
                    });
                    if !on_one {
                        continue 'placement;
                    }
                }
            }
        }
        // 3. Rays through non-spurious vertices without a spurious edge
        // stop there.
        for i in 0..m {
            let blocking = (radial[i] && spurious[(i + 1) % m])
                || (radial[(i + m - 1) % m] && spurious[(i + m - 1) % m]);
            if spurious[i] || blocking {
                continue;
            }
            let a = idx[i];
            match cone(ring, a, &direction_from(&q, &ring[a])) {
                Cone::Outside => {}
                Cone::Inside => continue 'placement,
                Cone::Along => unsure = true,
            }
        }
        if unsure {
            degenerate += 1;
            let ok = index
                .visibility_polygon(&q)
                .is_ok_and(|vq| same_ring(&vq.points(), &v.placed_at(&q)));
            if !ok {
                continue 'placement;
            }
        }
        found.push(q);
    }
    found.sort_by(crate::cmp_points);
    (found, degenerate)
}

/// s − a, scaled by s's positive w.
fn direction(a: &Point, s: &RatPoint) -> (Integer, Integer) {
    let w = s.hw();
    (
        s.hx() - Integer::from(w * a.x),
        s.hy() - Integer::from(w * a.y),
    )
}

/// a − q (the ray from q beyond a), scaled by q's positive w.
fn direction_from(q: &RatPoint, a: &Point) -> (Integer, Integer) {
    let w = q.hw();
    (
        Integer::from(w * a.x) - q.hx(),
        Integer::from(w * a.y) - q.hy(),
    )
}

/// Whether `p` lies on the closed map edge `e`.
fn on_edge(ring: &[Point], e: usize, p: &RatPoint) -> bool {
    let (a, b) = (ring[e], ring[(e + 1) % ring.len()]);
    let (a, b) = (RatPoint::from(a), RatPoint::from(b));
    if orientation_rat(&a, &b, p) != Orientation::Collinear {
        return false;
    }
    let d1 = sub(p, &a);
    let d2 = sub(&b, p);
    let e = sub(&b, &a);
    dot_sign(&d1, &e) != Ordering::Less && dot_sign(&d2, &e) != Ordering::Less
}

/// Whether s1 → s2 runs the way of map edge `e`.
fn same_way(ring: &[Point], e: usize, s1: &RatPoint, s2: &RatPoint) -> bool {
    let (a, b) = (ring[e], ring[(e + 1) % ring.len()]);
    let d = sub(s2, s1);
    (Integer::from(d.hx() * (b.x - a.x)) + Integer::from(d.hy() * (b.y - a.y))).cmp0()
        == Ordering::Greater
}
