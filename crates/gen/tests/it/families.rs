//! The thesis families: exact (n, r), validity, and the structure each
//! documents, checked with exact visibility.

use crate::common::check_valid;
use std::collections::BTreeSet;
use wai_exact::{orientation, sees, Orientation, Point, RatPoint};
use wai_gen::*;
use wai_map::Map;

fn check(map: &Map, n: usize, r: usize) {
    check_valid(map);
    assert_eq!((map.n(), map.r()), (n, r), "{:?}", map.name());
}

/// The map vertices `v` sees, translated by `-v`.
fn visible_from(map: &Map, v: Point) -> BTreeSet<(i128, i128)> {
    let ring = map.vertices();
    let at = RatPoint::from(v);
    ring.iter()
        .filter(|&&w| sees(ring, &at, &RatPoint::from(w)).is_visible())
        .map(|w| (w.x - v.x, w.y - v.y))
        .collect()
}

/// All viewpoints see the same translated vertex set, equal to `expected`
/// for viewpoint `i` (given absolute).
fn check_views(map: &Map, views: &[Point], expected: impl Fn(usize) -> Vec<Point>) {
    let mut first: Option<BTreeSet<(i128, i128)>> = None;
    for (i, &v) in views.iter().enumerate() {
        let seen = visible_from(map, v);
        let want: BTreeSet<(i128, i128)> =
            expected(i).iter().map(|w| (w.x - v.x, w.y - v.y)).collect();
        assert_eq!(seen, want, "{:?}: viewpoint {i} at {v}", map.name());
        match &first {
            None => first = Some(seen),
            Some(f) => assert_eq!(&seen, f, "viewpoint {i} is not a translate of viewpoint 0"),
        }
    }
}

fn pt(x: i128, y: i128) -> Point {
    Point::new(x, y)
}

fn niche_corners(a: i128, w: i128, d: i128) -> Vec<Point> {
    vec![pt(a, 0), pt(a, -d), pt(a + w, -d), pt(a + w, 0)]
}

#[test]
fn corridor_niches_sizes_and_views() {
    for k in [1u32, 2, 3, 8, 20, 100] {
        let m = corridor_niches(k).unwrap();
        check(&m, 4 * k as usize + 4, 2 * k as usize);
    }
    for k in [1u32, 4, 7] {
        let m = corridor_niches(k).unwrap();
        let views = corridor_niches_viewpoints(k);
        assert_eq!(views.len(), k as usize);
        check_views(&m, &views, |i| niche_corners(4 + 4 * i as i128, 2, 4));
    }
}

#[test]
fn comb_convex_chain_sizes() {
    for (niches, chain) in [
        (1u32, 2u32),
        (1, 3),
        (2, 5),
        (4, 4),
        (8, 8),
        (3, 40),
        (30, 3),
        (16, 64),
    ] {
        let m = comb_convex_chain(niches, chain).unwrap();
        check(
            &m,
            4 * niches as usize + chain as usize + 2,
            2 * niches as usize,
        );
    }
}

/// The chain is strictly convex: every chain vertex and both corridor
/// corners turn left (also implied by r = 2·niches above), checked here
/// directly on the chain with its neighbours.
#[test]
fn comb_chain_is_strictly_convex() {
    for (niches, chain) in [(2u32, 7u32), (5, 30)] {
        let l = comb_layout(niches, chain);
        let mut pts = vec![pt(0, 0)];
        pts.extend(l.west.iter().chain(&l.east).map(|&u| l.chain_vertex(u)));
        pts.push(pt(l.scale * l.u_max, 0));
        for w in pts.windows(3) {
            assert_eq!(
                orientation(w[0], w[1], w[2]),
                Orientation::Clockwise,
                "{w:?}"
            );
        }
    }
}

/// Every west-east pair of rays crosses strictly inside each niche, at
/// depth ≤ w/2, and the crossings in one niche are pairwise distinct:
/// `⌈chain/2⌉·⌊chain/2⌋` per niche.
#[test]
fn comb_rays_cross_inside_the_niches() {
    fn reduce(num: i128, den: i128) -> (i128, i128) {
        fn gcd(a: i128, b: i128) -> i128 {
            if b == 0 {
                a.abs()
            } else {
                gcd(b, a % b)
            }
        }
        let g = gcd(num, den).max(1);
        (num / g, den / g)
    }
    for (niches, chain) in [(1u32, 2u32), (3, 9), (6, 20), (2, 41)] {
        let l = comb_layout(niches, chain);
        let w = l.width;
        for &a in &l.niche_x {
            let mut crossings = BTreeSet::new();
            for &uw in &l.west {
                let v = l.chain_vertex(uw);
                for &ue in &l.east {
                    let u = l.chain_vertex(ue);
                    let (dx1, dx2) = (a - v.x, u.x - a - w);
                    assert!(dx1 >= v.y && dx2 >= u.y, "rays fall at least one per one");
                    // Depth of the crossing: D = w·vy·uy / (dx1·uy + dx2·vy).
                    let den = dx1 * u.y + dx2 * v.y;
                    let num = w * v.y * u.y;
                    assert!(num > 0 && 2 * num <= w * den, "crossing not within w/2");
                    // x = a + D·dx1/vy = a + w·uy·dx1/den.
                    let x = reduce(a * den + w * u.y * dx1, den);
                    let depth = reduce(num, den);
                    crossings.insert((x, depth));
                }
            }
            assert_eq!(crossings.len(), l.west.len() * l.east.len(), "niche at {a}");
        }
    }
}

/// Small instance: every chain vertex sees every mouth corner (exact).
#[test]
fn comb_chain_sees_every_mouth_corner() {
    let (niches, chain) = (3u32, 6u32);
    let m = comb_convex_chain(niches, chain).unwrap();
    let l = comb_layout(niches, chain);
    let ring = m.vertices();
    for &u in l.west.iter().chain(&l.east) {
        let v = RatPoint::from(l.chain_vertex(u));
        for &a in &l.niche_x {
            for c in [pt(a, 0), pt(a + l.width, 0)] {
                assert!(
                    sees(ring, &v, &RatPoint::from(c)).is_visible(),
                    "u={u} corner {c}"
                );
            }
        }
    }
}

#[test]
fn overlap_fan_sizes() {
    for z in [0u32, 1, 2, 5, 20] {
        let m = overlap_fan(z).unwrap();
        check(&m, 24 * z as usize + 12, 12 * z as usize + 4);
    }
}

#[test]
fn overlap_fan_views() {
    for z in [0u32, 1, 2, 3] {
        let zz = i128::from(z);
        let m = overlap_fan(z).unwrap();
        let h = 10 * zz + 4;
        let views = overlap_fan_viewpoints(z);
        assert_eq!(views.len(), 2 * z as usize + 1);
        check_views(&m, &views, |i| {
            let i = i as i128;
            let mut want = niche_corners(10 + 10 * (i + zz), 2, 2);
            for j in i..=i + 2 * zz {
                want.extend([pt(10 + 10 * j, h), pt(12 + 10 * j, h)]);
            }
            want
        });
    }
}

#[test]
fn convex_niches_sizes() {
    for k in [1u32, 2, 3, 6, 12] {
        let m = convex_niches(k).unwrap();
        let k = k as usize;
        check(&m, 2 * k * k + 9 * k + 1, 6 * k - 2);
    }
    for (f, t) in [(1u32, 1u32), (1, 5), (5, 1), (3, 7), (8, 2)] {
        let m = convex_niches_with(f, t).unwrap();
        let (f, t) = (f as usize, t as usize);
        check(
            &m,
            4 + 4 * t + (f + t - 1) * (f + 3),
            2 * t + 2 * (f + t - 1),
        );
    }
}

#[test]
fn convex_niches_views_and_candidate_edges() {
    for (f, t) in [(1u32, 1u32), (2, 2), (3, 3), (4, 2), (2, 5)] {
        let m = convex_niches_with(f, t).unwrap();
        let l = convex_niches_layout(f, t);
        let views = convex_niches_viewpoints(f, t);
        assert_eq!(views.len(), t as usize);
        check_views(&m, &views, |i| {
            let i = i as i128;
            let c = l.viewpoint(i).x;
            let mut want = vec![pt(c - 1, 0), pt(c - 1, -2), pt(c + 1, -2), pt(c + 1, 0)];
            for j in i..i + l.fan {
                let mouth = l.north_mouth(j);
                want.extend([pt(mouth.x - 1, mouth.y), pt(mouth.x + 1, mouth.y)]);
            }
            want
        });
        // The central ray into north niche i + q runs strictly between the
        // directions of dome vertices B_q and B_{q+1}.
        let o = pt(0, 0);
        for (i, v) in views.iter().enumerate() {
            for q in 0..l.fan {
                let mouth = l.north_mouth(i as i128 + q);
                let d = pt(mouth.x - v.x, mouth.y - v.y);
                let (bq, bq1) = (l.dome[q as usize], l.dome[q as usize + 1]);
                assert_eq!(orientation(o, bq, d), Orientation::Clockwise);
                assert_eq!(orientation(o, d, bq1), Orientation::Clockwise);
            }
        }
    }
}

#[test]
fn registry_builds_every_family() {
    for f in FAMILIES {
        let m = family(f.id, &[3]).unwrap_or_else(|e| panic!("{}: {e}", f.id));
        check_valid(&m);
        assert!(m.name().unwrap().starts_with(f.id));
        assert!(!f.reference.is_empty() && !f.claims.is_empty());
    }
    assert_eq!(family("comb-convex-chain", &[2, 9]).unwrap().n(), 19);
    assert_eq!(
        family("convex-niches", &[2, 3]).unwrap().n(),
        4 + 12 + 4 * 5
    );
    let ids: BTreeSet<&str> = FAMILIES.iter().map(|f| f.id).collect();
    let claims_ids = [
        "comb-convex-chain",
        "corridor-niches",
        "overlap-fan",
        "convex-niches",
        // T5.17t's Omega(r^2) with n = Theta(r) (CLAIMS.md names no family).
        "window-grid",
    ];
    assert_eq!(ids, claims_ids.into_iter().collect());
}

#[test]
fn bad_parameters_are_errors() {
    assert!(matches!(
        family("nope", &[1]),
        Err(GenError::UnknownFamily(_))
    ));
    assert!(matches!(
        family("corridor-niches", &[]),
        Err(GenError::ParamCount { .. })
    ));
    assert!(matches!(
        family("overlap-fan", &[1, 2]),
        Err(GenError::ParamCount { .. })
    ));
    assert!(matches!(
        family("corridor-niches", &[0]),
        Err(GenError::ParamTooSmall {
            param: "k",
            min: 1,
            ..
        })
    ));
    assert!(matches!(
        family("comb-convex-chain", &[3, 1]),
        Err(GenError::ParamTooSmall { param: "chain", .. })
    ));
    assert!(matches!(
        family("corridor-niches", &[u32::MAX]),
        Err(GenError::TooLarge { .. })
    ));
    assert!(matches!(
        family("convex-niches", &[100_000]),
        Err(GenError::TooLarge { .. })
    ));
}

#[test]
fn families_are_deterministic() {
    for f in FAMILIES {
        assert_eq!(family(f.id, &[4]).unwrap(), family(f.id, &[4]).unwrap());
    }
}
