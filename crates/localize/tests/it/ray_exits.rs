//! The sweep of ray exits against a brute force that shares nothing with
//! it: the line moved by a concrete tiny epsilon to the side, every point
//! where it meets the boundary, sorted, and the midpoint of each gap
//! located in the map.

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::{Integer, Rational};
use wai_exact::{
    locate_rat, orientation_rat, BigVector, Containment, Orientation, Point, RatPoint,
};
use wai_localize::ray_exits::{Exit, RayExits, Side};
use wai_map::Map;

/// a + t·d for rational t = num/den (den > 0).
fn along(a: Point, d: &(Integer, Integer), num: &Integer, den: &Integer) -> RatPoint {
    RatPoint::new(
        Integer::from(den * a.x) + Integer::from(num * &d.0),
        Integer::from(den * a.y) + Integer::from(num * &d.1),
        den.clone(),
    )
    .unwrap()
}

/// t of point p = a + t·d on the ray, as (num, den): t = (p − a)·d / |d|².
fn param(a: Point, d: &(Integer, Integer), p: &RatPoint) -> (Integer, Integer) {
    let w = p.hw();
    let num = (p.hx() - Integer::from(w * a.x)) * &d.0 + (p.hy() - Integer::from(w * a.y)) * &d.1;
    let den = w * (Integer::from(&d.0 * &d.0) + Integer::from(&d.1 * &d.1));
    (num, den)
}

/// The exit of the ray from vertex `a` in direction `d` on side `side`, by
/// brute force with concrete epsilons: the parameter t (point a + t·d)
/// where the parallel line moved by 2^-400·|d| to that side, started
/// 2^-200 before a, first leaves the map; `None` when it starts outside.
/// On the test maps (coordinates and directions below 2^110) the moved
/// line meets every wall within far less than 2^-200 of where the ray
/// does, and distinct features are far more than 2^-100 apart, so this is
/// the limit the sweep computes, up to 2^-100.
fn brute_exit(ring: &[Point], a: usize, d: &(Integer, Integer), side: Side) -> Option<Rational> {
    let n = ring.len();
    let perp = match side {
        Side::Left => (Integer::from(-&d.1), d.0.clone()),
        Side::Right => (d.1.clone(), Integer::from(-&d.0)),
    };
    let eps = Rational::from((1, Integer::from(1) << 400));
    let o = ring[a];
    let start = (
        Rational::from(o.x) + Rational::from(&eps * &perp.0),
        Rational::from(o.y) + Rational::from(&eps * &perp.1),
    );
    let (dx, dy) = (Rational::from(&d.0), Rational::from(&d.1));
    let at = |t: &Rational| {
        let x = &start.0 + Rational::from(t * &dx);
        let y = &start.1 + Rational::from(t * &dy);
        RatPoint::new(
            Integer::from(x.numer() * y.denom()),
            Integer::from(y.numer() * x.denom()),
            Integer::from(x.denom() * y.denom()),
        )
        .unwrap()
    };
    let t0 = -Rational::from((1, Integer::from(1) << 200));
    if locate_rat(ring, &at(&t0)) != Containment::Inside {
        return None;
    }
    // Where the moved line meets each edge p + s·(q − p), s in [0, 1].
    let mut ts = vec![t0.clone()];
    for e in 0..n {
        let (p, q) = (ring[e], ring[(e + 1) % n]);
        let (ex, ey) = (Rational::from(q.x - p.x), Rational::from(q.y - p.y));
        let den = Rational::from(&dx * &ey) - Rational::from(&dy * &ex);
        if den == 0 {
            continue;
        }
        let (px, py) = (
            Rational::from(p.x) - &start.0,
            Rational::from(p.y) - &start.1,
        );
        let t = (Rational::from(&px * &ey) - Rational::from(&py * &ex)) / &den;
        let s = (Rational::from(&px * &dy) - Rational::from(&py * &dx)) / &den;
        if (0..=1).contains(&s) && t > t0 {
            ts.push(t);
        }
    }
    ts.sort();
    ts.dedup();
    for k in 0..ts.len() - 1 {
        let mid = Rational::from(&ts[k] + &ts[k + 1]) / 2;
        match locate_rat(ring, &at(&mid)) {
            Containment::Inside => {}
            Containment::Outside => return Some(ts[k].clone()),
            Containment::OnBoundary => {
                panic!("the moved line runs along a wall: pick another epsilon")
            }
        }
    }
    // Beyond the last crossing the line is outside the bounded map.
    ts.pop()
}

fn exit_point(ring: &[Point], a: usize, d: &(Integer, Integer), exit: Exit) -> RatPoint {
    let n = ring.len();
    match exit {
        Exit::Vertex(b) => RatPoint::from(ring[b]),
        Exit::Edge(e) => {
            let (p, q) = (ring[e], ring[(e + 1) % n]);
            let o = ring[a];
            let pq = BigVector::between(p, q);
            let num = BigVector::between(o, p).cross(&pq);
            let den = BigVector::new(d.0.clone(), d.1.clone()).cross(&pq);
            let (num, den) = if den < 0 { (-num, -den) } else { (num, den) };
            let x = along(o, d, &num, &den);
            // An edge exit lies strictly inside its edge.
            assert_eq!(
                orientation_rat(&RatPoint::from(p), &RatPoint::from(q), &x),
                Orientation::Collinear
            );
            assert!(x != RatPoint::from(p) && x != RatPoint::from(q));
            x
        }
    }
}

/// Directions that stress the sweep: the axes and diagonals (along walls,
/// through rows of vertices), the map's own vertex differences (rays
/// through several vertices), and random ones.
fn directions(ring: &[Point], rng: &mut ChaCha8Rng) -> Vec<(Integer, Integer)> {
    let mut d: Vec<(i128, i128)> = vec![
        (1, 0),
        (0, 1),
        (-1, 0),
        (0, -1),
        (1, 1),
        (-1, 1),
        (1, -1),
        (-1, -1),
        (2, 1),
        (-1, 3),
    ];
    for _ in 0..6 {
        let (i, j) = (
            rng.random_range(0..ring.len()),
            rng.random_range(0..ring.len()),
        );
        if ring[i] != ring[j] {
            d.push((ring[j].x - ring[i].x, ring[j].y - ring[i].y));
        }
        d.push((rng.random_range(-50..=50), rng.random_range(-50..=50)));
    }
    d.into_iter()
        .filter(|&(x, y)| (x, y) != (0, 0))
        .map(|(x, y)| (Integer::from(x), Integer::from(y)))
        .collect()
}

fn check(map: &Map, dirs: &[(Integer, Integer)]) -> usize {
    let ring = map.vertices();
    let mut checked = 0;
    for d in dirs {
        for side in [Side::Left, Side::Right] {
            let exits = RayExits::new(ring, (&d.0, &d.1), side);
            for a in 0..ring.len() {
                let got = exit_point(ring, a, d, exits.exit(a));
                let (num, den) = param(ring[a], d, &got);
                let got_t = Rational::from((num, den));
                let want_t = brute_exit(ring, a, d, side).unwrap_or_default();
                let tolerance = Rational::from((1, Integer::from(1) << 100));
                assert!(
                    Rational::from(&got_t - &want_t).abs() < tolerance,
                    "map {:?}, direction ({}, {}) {side:?}, vertex {a}: {:?} at t = {got_t}, brute force t = {want_t}",
                    map.name(),
                    d.0,
                    d.1,
                    exits.exit(a)
                );
                checked += 1;
            }
        }
    }
    checked
}

#[test]
fn exits_equal_the_brute_force_on_degenerate_and_random_maps() {
    let mut rng = ChaCha8Rng::seed_from_u64(11);
    let mut maps = Vec::new();
    for seed in 0..6 {
        maps.push(wai_gen::random("random-orthogonal", 24, seed).unwrap());
        maps.push(wai_gen::random("special-orthogonal", 20, seed).unwrap());
        maps.push(wai_gen::random("special-comb", 20, seed).unwrap());
        maps.push(wai_gen::random("random-simple-2opt", 16, seed).unwrap());
    }
    maps.push(wai_gen::family("corridor-niches", &[4]).unwrap());
    maps.push(wai_gen::family("overlap-fan", &[2]).unwrap());
    maps.push(wai_gen::layout("repeated-niches", 0).unwrap());
    let mut checked = 0;
    for map in &maps {
        let dirs = directions(map.vertices(), &mut rng);
        checked += check(map, &dirs);
    }
    eprintln!("{checked} ray exits checked");
    assert!(checked > 10_000, "{checked}");
}

/// Coordinates near 2^100 and directions whose rotated coordinates need
/// more than 126 bits: the GMP sweep.
#[test]
fn big_coordinates_take_the_gmp_sweep_and_agree() {
    let mut rng = ChaCha8Rng::seed_from_u64(12);
    for seed in 0..3 {
        let map = wai_gen::random("special-orthogonal", 14, seed).unwrap();
        let scaled = map.scaled_up(90).unwrap();
        let mut dirs = directions(scaled.vertices(), &mut rng);
        dirs.push((Integer::from(1) << 40, Integer::from(3)));
        dirs.push((Integer::from(-7), (Integer::from(1) << 50) + 1));
        assert!(check(&scaled, &dirs) > 100);
    }
}
