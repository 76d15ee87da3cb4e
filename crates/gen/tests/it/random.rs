//! Every random kind: validity on ≥ 1000 maps, documented vertex counts,
//! determinism, and the error of each bad request.

use crate::common::check_valid;
use wai_gen::{random, GenError, RANDOM_KINDS};
use wai_map::Map;

/// The vertex count each kind documents for a requested `n`.
fn expected_n(kind: &str, n: usize, got: usize) -> bool {
    match kind {
        "random-simple-star" | "random-simple-2opt" => got == n,
        "random-orthogonal" | "special-orthogonal" => {
            let lo = n.max(4);
            got & 1 == 0 && lo <= got && got <= lo + 3
        }
        "special-comb" => got == 4 + 4 * (n - 4).div_ceil(4),
        "special-chamfer" => got == n,
        _ => panic!("kind {kind} has no expectation here"),
    }
}

/// 1000 seeds per kind, `n` cycling through 3..=26 (from the kind's
/// minimum), every map valid and of the documented size.
#[test]
fn thousand_maps_per_kind_are_valid() {
    for kind in RANDOM_KINDS {
        let mut orthogonal = 0;
        for seed in 0..1000u64 {
            let n = kind.min_n + (seed as usize % 24);
            let m = random(kind.id, n, seed).unwrap();
            check_valid(&m);
            assert!(
                expected_n(kind.id, n, m.n()),
                "{}: n = {n}, got {}",
                kind.id,
                m.n()
            );
            orthogonal += usize::from(m.is_orthogonal());
        }
        let expect_orthogonal = matches!(
            kind.id,
            "random-orthogonal" | "special-orthogonal" | "special-comb"
        );
        if expect_orthogonal {
            assert_eq!(orthogonal, 1000, "{}", kind.id);
        }
    }
}

/// Larger sizes, fewer seeds.
#[test]
fn large_maps_are_valid() {
    for kind in RANDOM_KINDS {
        for (seed, n) in [(1u64, 60usize), (2, 100), (3, 150)] {
            let m = random(kind.id, n, seed).unwrap();
            check_valid(&m);
            assert!(
                expected_n(kind.id, n, m.n()),
                "{}: n = {n}, got {}",
                kind.id,
                m.n()
            );
        }
    }
}

#[test]
fn same_seed_same_map_other_seed_other_map() {
    for kind in RANDOM_KINDS {
        let a = random(kind.id, 20, 42).unwrap();
        let b = random(kind.id, 20, 42).unwrap();
        assert_eq!(a.vertices(), b.vertices(), "{}", kind.id);
        assert_eq!(a.name(), b.name());
        let distinct: std::collections::BTreeSet<Vec<_>> = (0..20u64)
            .map(|s| random(kind.id, 20, s).unwrap().vertices().to_vec())
            .collect();
        assert!(
            distinct.len() >= 15,
            "{}: only {} distinct maps",
            kind.id,
            distinct.len()
        );
    }
}

/// A fixed seed's output is pinned, so a change of the generators (or of
/// `rand_chacha`'s stream) that would silently change every seeded test
/// and every recorded counterexample seed is seen here first.
#[test]
fn seeded_output_is_pinned() {
    let m = random("random-simple-star", 5, 0).unwrap();
    let got: Vec<(i128, i128)> = m.vertices().iter().map(|p| (p.x, p.y)).collect();
    assert_eq!(got, [(3, 25), (-4, 22), (-9, 8), (-20, 15), (-2, -25)]);
}

#[test]
fn special_maps_are_degenerate() {
    // Collinear non-adjacent edges are the point of the special kinds.
    fn collinear_edge_pairs(m: &Map) -> usize {
        let v = m.vertices();
        let n = v.len();
        let mut k = 0;
        for i in 0..n {
            for j in i + 2..n {
                let (a, b) = (v[i], v[(i + 1) % n]);
                let (c, d) = (v[j], v[(j + 1) % n]);
                let col = |p| wai_exact::orientation(a, b, p) == wai_exact::Orientation::Collinear;
                k += usize::from(col(c) && col(d));
            }
        }
        k
    }
    for kind in ["special-orthogonal", "special-comb", "special-chamfer"] {
        let total: usize = (0..50u64)
            .map(|s| collinear_edge_pairs(&random(kind, 24, s).unwrap()))
            .sum();
        assert!(
            total >= 100,
            "{kind}: only {total} collinear edge pairs in 50 maps"
        );
    }
    // The chamfered maps do have 45° edges.
    let diagonal = (0..20u64).any(|s| !random("special-chamfer", 24, s).unwrap().is_orthogonal());
    assert!(diagonal);
}

#[test]
fn bad_requests_are_errors() {
    assert!(matches!(
        random("no-such-kind", 10, 0),
        Err(GenError::UnknownKind(_))
    ));
    assert!(matches!(
        random("random-simple-star", 2, 0),
        Err(GenError::SizeOutOfRange { min: 3, .. })
    ));
    assert!(matches!(
        random("random-orthogonal", 3, 0),
        Err(GenError::SizeOutOfRange { min: 4, .. })
    ));
    let msg = random("nope", 10, 0).unwrap_err().to_string();
    assert!(msg.contains("random-simple-star"), "{msg}");
}

/// The second-opinion checker can fail: one planted fault of
/// each kind it looks for.
#[test]
fn ring_problem_catches_planted_faults() {
    use wai_exact::Point;
    let r =
        |v: &[(i128, i128)]| -> Vec<Point> { v.iter().map(|&(x, y)| Point::new(x, y)).collect() };
    let bad = [
        r(&[(0, 0), (2, 2), (2, 0), (0, 2)]),         // bow tie
        r(&[(0, 0), (1, 0), (2, 0), (2, 2), (0, 2)]), // 180° vertex
        r(&[(0, 0), (0, 2), (2, 2), (2, 0)]),         // clockwise
        r(&[(0, 0), (4, 0), (4, 4), (2, 0), (0, 4)]), // vertex on an edge
        r(&[(0, 0), (1, 0)]),
    ];
    for ring in bad {
        assert!(wai_gen::ring_problem(&ring).is_some(), "{ring:?}");
    }
    assert_eq!(
        wai_gen::ring_problem(&r(&[(0, 0), (2, 0), (2, 2), (0, 2)])),
        None
    );
}

/// `repeated_niches`: valid for many seeds (the ring is checked by
/// `Map::from_ring` on construction), deterministic, and its viewpoints
/// lie inside, one per funnel at the same place in each.
#[test]
fn repeated_niches_are_valid_and_their_viewpoints_repeat() {
    for seed in 0..500 {
        let m = wai_gen::repeated_niches(seed);
        assert_eq!(m, wai_gen::repeated_niches(seed));
        let l = wai_gen::RepeatedLayout::of_seed(seed);
        let vs = l.viewpoints();
        assert_eq!(vs.len() as i128, l.funnels);
        for w in vs.windows(2) {
            assert_eq!((w[1].x - w[0].x, w[1].y - w[0].y), (l.k * l.north_pitch, 0));
        }
        for v in vs {
            assert_eq!(
                wai_exact::locate(m.vertices(), v),
                wai_exact::Containment::Inside,
                "seed {seed}"
            );
        }
    }
}

/// `kernel_funnels`: valid for many seeds, deterministic, flared funnels
/// at every niche pitch, and the corridor taller than the height where the
/// upward wedges of two neighbouring funnels cross (their kernels meet
/// below the ceiling).
#[test]
fn kernel_funnels_are_valid_and_their_wedges_meet_below_the_ceiling() {
    for seed in 0..500 {
        let m = wai_gen::kernel_funnels(seed);
        assert_eq!(m, wai_gen::kernel_funnels(seed));
        let l = wai_gen::RepeatedLayout::kernels_of_seed(seed);
        assert_eq!(l.k, 1);
        let (hb, ht) = (l.funnel_bottom / 2, l.funnel_top / 2);
        assert!(hb < ht && 2 * ht < l.north_pitch, "seed {seed}: {l:?}");
        // At the ceiling a wedge's half width, ht + height·(ht − hb)/depth,
        // exceeds half the pitch: (ht − q/2)·depth + height·(ht − hb) > 0.
        let q2 = l.north_pitch / 2;
        assert!(
            (ht - q2) * l.funnel_depth + l.height * (ht - hb) > 0,
            "seed {seed}: {l:?}"
        );
        for v in l.viewpoints() {
            assert_eq!(
                wai_exact::locate(m.vertices(), v),
                wai_exact::Containment::Inside,
                "seed {seed}"
            );
        }
    }
}

/// `bottled_niches`: valid for many seeds, deterministic; two viewpoints
/// per room, the same two in every room, inside the map; the spikes lie
/// inside the chamber and the chambers do not touch.
#[test]
fn bottled_niches_are_valid_and_their_viewpoints_repeat() {
    for seed in 0..500 {
        let m = wai_gen::bottled_niches(seed);
        assert_eq!(m, wai_gen::bottled_niches(seed));
        let l = wai_gen::BottleLayout::of_seed(seed);
        assert!(l.spikes[4] + l.spike_width < l.chamber && 2 * l.chamber < l.pitch);
        assert!(2 * l.mouth < l.pitch, "seed {seed}: rooms touch");
        let vs = l.viewpoints();
        assert_eq!(vs.len() as i128, 2 * l.rooms);
        for w in vs.windows(3) {
            assert_eq!((w[2].x - w[0].x, w[2].y - w[0].y), (l.pitch, 0));
        }
        for v in vs {
            assert_eq!(
                wai_exact::locate(m.vertices(), v),
                wai_exact::Containment::Inside,
                "seed {seed}"
            );
        }
    }
}

/// The chapter 5 layouts (`interweaved_gaps`, `shared_niches`,
/// `shared_spiked_niches`): valid for many seeds, deterministic, and their
/// viewpoints lie inside, at the same places in every room.
#[test]
fn chapter_5_layouts_are_valid_and_their_viewpoints_repeat() {
    for seed in 0..300 {
        let m = wai_gen::interweaved_gaps(seed);
        check_valid(&m);
        assert_eq!(m, wai_gen::interweaved_gaps(seed));
        let l = wai_gen::PinholeLayout::of_seed(seed);
        let [a, b] = l.viewpoints();
        for v in [a, b] {
            assert_eq!(
                wai_exact::locate(m.vertices(), v),
                wai_exact::Containment::Inside,
                "seed {seed}"
            );
        }
        assert!(
            a.y == b.y && a.x < l.width() && b.x > l.apart,
            "seed {seed}"
        );
        for (l, m) in [
            (
                wai_gen::SharedLayout::of_seed(seed),
                wai_gen::shared_niches(seed),
            ),
            (
                wai_gen::SharedLayout::spiked_of_seed(seed),
                wai_gen::shared_spiked_niches(seed),
            ),
        ] {
            check_valid(&m);
            assert!(
                2 * l.mouth < l.pitch && 2 * l.chamber < l.pitch,
                "seed {seed}"
            );
            let vs = l.viewpoints();
            let per_room = vs.len() / l.rooms as usize;
            for w in vs.windows(per_room + 1) {
                let (p, q) = (w[0], w[per_room]);
                assert_eq!((q.x - p.x, q.y - p.y), (l.pitch, 0), "seed {seed}");
            }
            for v in vs {
                assert_eq!(
                    wai_exact::locate(m.vertices(), v),
                    wai_exact::Containment::Inside,
                    "seed {seed}"
                );
            }
        }
    }
}
