//! Bytes → a small valid map (`wai_gen::bytes`) and up to six viewpoints →
//! the production visibility query (`VisibilityIndex`, triangular
//! expansion) against the reference algorithm (`reference::visibility_polygon`,
//! angular sort).
//!
//! Viewpoints are exact rational points, most of them degenerate: on the
//! line through two map vertices beyond the second (where visibility rays
//! run, Def 3.8), between two vertices, where two such lines meet, on a
//! map vertex or edge (the boundary), and on a rational grid over the
//! bounding box.
//!
//! Laws: both algorithms give the same result, exactly — the same
//! visibility polygon, or the same error (outside, on the boundary); an
//! interior point has a visibility polygon and a skeleton (Def 3.7), and
//! the skeleton read off the expansion (`VisibilityIndex::skeleton_at`,
//! which the decompose target and the claim checkers query) is the one
//! `Skeleton::of` forms from V_p.
#![no_main]

use arbitrary::Unstructured;
use libfuzzer_sys::fuzz_target;
use rug::Integer;
use wai_exact::{construct_intersection, locate_rat, Containment, Line, Point, RatPoint};
use wai_map::Map;
use wai_visibility::{reference, MapSkeleton, Skeleton, VisibilityIndex};

/// `a + (t/d)·(b − a)` for integers `t`, `d > 0`.
fn along(a: Point, b: Point, t: i128, d: i128) -> Option<RatPoint> {
    let x = Integer::from(a.x) * d + Integer::from(b.x - a.x) * t;
    let y = Integer::from(a.y) * d + Integer::from(b.y - a.y) * t;
    RatPoint::new(x, y, Integer::from(d))
}

/// One viewpoint read from the bytes.
fn viewpoint(u: &mut Unstructured<'_>, map: &Map) -> arbitrary::Result<Option<RatPoint>> {
    let v = map.vertices();
    let n = v.len();
    let vertex = |u: &mut Unstructured<'_>| u.choose_index(n).map(|i| v[i]);
    Ok(match u.int_in_range(0..=4u8)? {
        // Beyond b on the line a b: a visibility ray's line when b is reflex.
        0 => {
            let (a, b) = (vertex(u)?, vertex(u)?);
            let d = u.int_in_range(1..=12i128)?;
            let t = d + u.int_in_range(1..=2 * d)?;
            along(a, b, t, d)
        }
        // Between two vertices (a chord, or a map edge).
        1 => {
            let (a, b) = (vertex(u)?, vertex(u)?);
            let d = u.int_in_range(1..=12i128)?;
            along(a, b, u.int_in_range(0..=d)?, d)
        }
        // Where the lines through two pairs of vertices meet.
        2 => {
            let l1 = Line::new(vertex(u)?, vertex(u)?);
            let l2 = Line::new(vertex(u)?, vertex(u)?);
            match (l1, l2) {
                (Some(l1), Some(l2)) => construct_intersection(&l1, &l2),
                _ => None,
            }
        }
        // On a map edge, at a rational parameter.
        3 => {
            let i = u.choose_index(n)?;
            let d = u.int_in_range(1..=8i128)?;
            along(v[i], v[(i + 1) % n], u.int_in_range(0..=d)?, d)
        }
        // A rational grid over the bounding box.
        _ => {
            let (lo, hi) = map.bounding_box();
            let d = u.int_in_range(1..=16i128)?;
            let (tx, ty) = (u.int_in_range(0..=d)?, u.int_in_range(0..=d)?);
            let x = Integer::from(lo.x) * d + Integer::from(hi.x - lo.x) * tx;
            let y = Integer::from(lo.y) * d + Integer::from(hi.y - lo.y) * ty;
            RatPoint::new(x, y, Integer::from(d))
        }
    })
}

fuzz_target!(|data: &[u8]| {
    let Some((map, mut u)) = wai_fuzz::map_of(data) else {
        return;
    };
    let index = VisibilityIndex::new(&map);
    let count = u.int_in_range(1..=6u8).unwrap_or(1);
    for _ in 0..count {
        let p = match viewpoint(&mut u, &map) {
            Ok(Some(p)) => p,
            Ok(None) => continue, // two lines that do not meet, or one that is no line
            Err(_) => break,
        };
        let got = index.visibility_polygon(&p);
        let want = reference::visibility_polygon(&map, &p);
        let name = map.name().unwrap_or("unnamed");
        assert_eq!(
            got,
            want,
            "VisibilityIndex and the reference differ at {p} in {name}: {:?}",
            map.vertices()
        );
        if locate_rat(map.vertices(), &p) == Containment::Inside {
            let vp = got.unwrap_or_else(|e| panic!("interior point {p} in {name}: {e}"));
            let sk = Skeleton::of(&map, &vp)
                .unwrap_or_else(|e| panic!("no skeleton at interior point {p} in {name}: {e}"));
            let at = index.skeleton_at(&p).unwrap_or_else(|e| {
                panic!("skeleton_at fails at interior point {p} in {name}: {e}")
            });
            assert_eq!(
                at,
                MapSkeleton::of(&sk),
                "skeleton_at and Skeleton::of differ at {p} in {name}"
            );
        }
    }
});
