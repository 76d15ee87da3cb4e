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

use crate::view::RobotView;
use rug::Integer;
use wai_exact::{Containment, RatPoint};
use wai_visibility::VisibilityIndex;

/// All positions q with V_q = V + q, ascending: O(r) visibility queries.
pub fn brute_force(index: &VisibilityIndex<'_>, v: &RobotView) -> Vec<RatPoint> {
    let Ok(sk) = v.skeleton() else {
        return Vec::new();
    };
    let map = index.map();
    let mut found = Vec::new();
    // A convex map (r = 0, outside the thesis's assumption) has v0 at its
    // leftmost, then lowest, vertex: try every vertex then.
    let all: Vec<usize> = (0..map.n()).collect();
    let candidates = if map.r() == 0 {
        &all
    } else {
        map.reflex_vertices()
    };
    for &u in candidates {
        let at = map.vertices()[u];
        let w = sk.robot.hw();
        let q = RatPoint::new(
            sk.robot.hx() + Integer::from(w * at.x),
            sk.robot.hy() + Integer::from(w * at.y),
            w.clone(),
        )
        .expect("w > 0");
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
