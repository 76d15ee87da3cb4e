//! Laws of visibility rays on generated maps: every law of
//! `common::check_rays` (including completeness against a brute-force
//! enumeration with `sees`), and invariance under translation, 90°
//! rotation, reflection and a cyclic shift of the start vertex.

use crate::common::{check_map, check_rays, key, map, RayKey};
use proptest::prelude::*;
use rug::Integer;
use wai_cells::{visibility_rays, OnMap, VisibilityRay};
use wai_exact::{Point, RatPoint};
use wai_map::Map;

/// Random maps of every kind, n ≤ 40, several seeds.
#[test]
fn random_maps_of_every_kind() {
    let mut maps = 0;
    let mut rays = 0;
    for kind in wai_gen::RANDOM_KINDS {
        let mut kind_rays = 0;
        for n in [kind.min_n.max(6), 12, 20, 28, 40] {
            for seed in 0..4 {
                let m = wai_gen::random(kind.id, n, seed).unwrap();
                kind_rays += check_map(&m);
                maps += 1;
            }
        }
        assert!(kind_rays > 0, "{}: no ray examined", kind.id);
        rays += kind_rays;
    }
    assert!(maps >= 100 && rays > 1000, "{maps} maps, {rays} rays");
}

/// The thesis families at small parameters.
#[test]
fn thesis_families() {
    for f in wai_gen::FAMILIES {
        let mut checked = 0;
        for k in 0..=4u32 {
            let Ok(m) = wai_gen::family(f.id, &[k]) else {
                continue;
            };
            if m.n() > 80 {
                continue;
            }
            assert!(check_map(&m) > 0, "{}: no ray", f.id);
            checked += 1;
        }
        assert!(checked >= 2, "{}: only {checked} maps", f.id);
    }
}

/// `corridor-niches`: 8 rays for k = 1 (derived in
/// `hand::corridor_niches_k1`), and more rays with every niche.
#[test]
fn corridor_niches_counts() {
    let counts: Vec<usize> = (1..=4)
        .map(|k| check_map(&wai_gen::family("corridor-niches", &[k]).unwrap()))
        .collect();
    assert_eq!(counts[0], 8);
    assert!(counts.windows(2).all(|w| w[0] < w[1]), "{counts:?}");
}

/// All polyominoes with at most 6 cells (free), as unit-square maps.
#[test]
fn exhaustive_polyominoes() {
    let mut maps = 0;
    let mut rays = 0;
    for m in wai_gen::exhaustive_polyomino_maps(6, wai_gen::Symmetry::Free) {
        rays += check_map(&m);
        maps += 1;
    }
    assert!(maps > 50 && rays > 0, "{maps} maps, {rays} rays");
}

/// A rigid motion of the plane: integer translation after a rotation by a
/// multiple of 90° and an optional reflection in the y axis.
#[derive(Clone, Copy, Debug)]
struct Motion {
    reflect: bool,
    quarter_turns: u8,
    shift: (i128, i128),
}

impl Motion {
    fn point(&self, p: Point) -> Point {
        let (mut x, mut y) = (p.x, p.y);
        if self.reflect {
            x = -x;
        }
        for _ in 0..self.quarter_turns {
            (x, y) = (-y, x);
        }
        Point::new(x + self.shift.0, y + self.shift.1)
    }

    fn rat(&self, p: &RatPoint) -> RatPoint {
        let (mut x, mut y, w) = (p.hx().clone(), p.hy().clone(), p.hw().clone());
        if self.reflect {
            x = -x;
        }
        for _ in 0..self.quarter_turns {
            (x, y) = (-y, x);
        }
        let x = x + Integer::from(&w * self.shift.0);
        let y = y + Integer::from(&w * self.shift.1);
        RatPoint::new(x, y, w).unwrap()
    }
}

/// The map moved by `m` with its start vertex shifted by `start`, and the
/// index of each old vertex in the new map.
fn moved(map: &Map, m: Motion, start: usize) -> (Map, Vec<usize>) {
    let n = map.n();
    let ring: Vec<Point> = (0..n)
        .map(|k| m.point(map.vertices()[(k + start) % n]))
        .collect();
    let (new, norm) = Map::from_ring(ring).unwrap();
    assert!(norm.removed_collinear.is_empty());
    assert_eq!(norm.reversed, m.reflect);
    let index = map
        .vertices()
        .iter()
        .map(|&p| {
            let q = m.point(p);
            new.vertices().iter().position(|&r| r == q).unwrap()
        })
        .collect();
    (new, index)
}

/// The key of `ray` after the motion, in the new map's indices.
fn moved_key(ray: &VisibilityRay, n: usize, m: Motion, index: &[usize]) -> RayKey {
    let (vertex, i) = match ray.end.on_map {
        OnMap::Vertex(i) => (true, index[i]),
        OnMap::Edge(i) => {
            let (a, b) = (index[i], index[(i + 1) % n]);
            // The new edge joins the images of the old edge's endpoints.
            (false, if b == (a + 1) % n { a } else { b })
        }
    };
    (
        index[ray.anchor],
        index[ray.from],
        if m.reflect {
            ray.side.flipped()
        } else {
            ray.side
        },
        vertex,
        i,
        m.rat(&ray.end.point),
        ray.grazed.iter().map(|&u| index[u]).collect(),
    )
}

fn check_invariance(map: &Map) {
    let rays = visibility_rays(map);
    let motions = [
        (false, 0, (-7, 13)),
        (false, 1, (0, 0)),
        (false, 3, (5, -2)),
        (true, 0, (0, 0)),
        (true, 2, (11, 3)),
    ];
    for (reflect, quarter_turns, shift) in motions {
        for start in [0, 1, map.n() / 2] {
            let m = Motion {
                reflect,
                quarter_turns,
                shift,
            };
            let (new, index) = moved(map, m, start);
            let mut want: Vec<RayKey> = rays
                .iter()
                .map(|r| moved_key(r, map.n(), m, &index))
                .collect();
            let mut got: Vec<RayKey> = visibility_rays(&new).iter().map(key).collect();
            want.sort();
            got.sort();
            assert_eq!(got, want, "{:?} moved by {m:?}, start {start}", map.name());
        }
    }
}

#[test]
fn invariant_under_rigid_motions() {
    for kind in wai_gen::RANDOM_KINDS {
        for seed in 0..2 {
            check_invariance(&wai_gen::random(kind.id, 16, seed).unwrap());
        }
    }
    check_invariance(&wai_gen::family("corridor-niches", &[2]).unwrap());
    check_invariance(&wai_gen::family("overlap-fan", &[0]).unwrap());
    check_invariance(&map(&[(0, 0), (4, 0), (4, 2), (2, 2), (2, 4), (0, 4)]));
}

/// Scaling by 2^40 and 2^70 takes every predicate off its `i128` fast
/// path (`INTERSECTION_FAST_BITS = 30`, `ORIENTATION_FAST_BITS = 62`) onto
/// GMP, and the rays off their own `i64` path (coordinates below 2^30):
/// the rays scale with the map.
#[test]
fn invariant_under_scaling_beyond_fast_paths() {
    let maps = [
        wai_gen::random("special-chamfer", 24, 3).unwrap(),
        wai_gen::random("random-simple-star", 20, 1).unwrap(),
        wai_gen::family("corridor-niches", &[2]).unwrap(),
        // Orthogonal: collinear edges, rays through several vertices.
        wai_gen::random("random-orthogonal", 40, 2).unwrap(),
        wai_gen::family("comb-convex-chain", &[3]).unwrap(),
    ];
    for m in &maps {
        let rays = visibility_rays(m);
        for bits in [40, 70] {
            let s: i128 = 1 << bits;
            let big = m.scaled_up(bits).unwrap();
            let scale = |p: &RatPoint| {
                RatPoint::new(
                    Integer::from(p.hx() * s),
                    Integer::from(p.hy() * s),
                    p.hw().clone(),
                )
                .unwrap()
            };
            let want: Vec<RayKey> = rays
                .iter()
                .map(|r| {
                    let mut k = key(r);
                    k.5 = scale(&k.5);
                    k
                })
                .collect();
            let got: Vec<RayKey> = visibility_rays(&big).iter().map(key).collect();
            assert_eq!(got, want, "{:?} scaled by 2^{bits}", m.name());
            if bits == 40 {
                check_map(&big.with_name(format!("{:?} scaled", m.name())));
            }
        }
    }
}

/// A 76-vertex map with 54 reflex vertices, the size of the thesis's
/// ROLOPRO map: a banana between the parabolas y = x² (21 vertices, convex
/// chain) and y = x² + 200 (55 vertices, all but one end reflex).
#[test]
fn banana_76_54() {
    let mut ring: Vec<Point> = (-10..=10)
        .map(|i: i128| Point::new(6 * i, 36 * i * i))
        .collect();
    ring.extend((0..55).map(|k: i128| {
        let x = 64 - 2 * k;
        Point::new(x, x * x + 200)
    }));
    let (m, _) = Map::from_ring(ring).unwrap();
    assert_eq!((m.n(), m.r()), (76, 54));
    assert!(check_map(&m.with_name("banana")) > 0);
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, ..ProptestConfig::default() })]

    /// The laws on arbitrary maps of the generator's strategies (shrinking
    /// to a small map on failure).
    #[test]
    fn laws_on_arbitrary_maps(m in wai_gen::arb_map()) {
        check_map(&m);
    }
}

// Planted violations: the law checker fails on wrong rays.

fn l_room_rays() -> (Map, Vec<VisibilityRay>) {
    let m = map(&[(0, 0), (4, 0), (4, 2), (2, 2), (2, 4), (0, 4)]);
    let rays = visibility_rays(&m);
    (m, rays)
}

#[test]
#[should_panic(expected = "rays against brute force")]
fn planted_missing_ray() {
    let (m, mut rays) = l_room_rays();
    rays.pop();
    check_rays(&m, &rays);
}

/// The blocks map of `hand::grazing_and_collinear_rays`.
fn blocks() -> Map {
    map(&[
        (0, 0),
        (12, 0),
        (12, 12),
        (7, 12),
        (7, 2),
        (6, 2),
        (6, 12),
        (5, 12),
        (5, 4),
        (4, 4),
        (4, 12),
        (3, 12),
        (3, 6),
        (2, 6),
        (2, 12),
        (0, 12),
    ])
}

#[test]
#[should_panic(expected = "the ray could go on")]
fn planted_ray_stopped_at_a_grazed_vertex() {
    let m = blocks();
    let mut rays = visibility_rays(&m);
    // The ray from 13 anchored at 9 grazes 5 = (6, 2); stop it there.
    let r = rays
        .iter_mut()
        .find(|r| (r.anchor, r.from) == (9, 13))
        .unwrap();
    assert_eq!(r.grazed, vec![5]);
    r.grazed.clear();
    r.end.point = RatPoint::from(Point::new(6, 2));
    r.end.on_map = OnMap::Vertex(5);
    check_rays(&m, &rays);
}

#[test]
#[should_panic(expected = "side")]
fn planted_wrong_side() {
    let (m, mut rays) = l_room_rays();
    rays[0].side = rays[0].side.flipped();
    check_rays(&m, &rays);
}

#[test]
#[should_panic(expected = "vertices on the ray")]
fn planted_missing_graze() {
    let m = blocks();
    let mut rays = visibility_rays(&m);
    for r in &mut rays {
        r.grazed.clear();
    }
    check_rays(&m, &rays);
}
