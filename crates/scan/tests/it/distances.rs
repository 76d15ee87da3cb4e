//! The distance functions of secs. 6.5–6.8: exact PCFs of star-shaped
//! polygons (Def 6.2), the closed-form PCM for one rotation (eq. 6.7)
//! against hand-computed integrals and the midpoint rule, its minimum over
//! rotations (eq. 6.6, sec. 6.8's approximation) against a dense grid, the
//! metric laws (identity, symmetry, triangle inequality, invariance under
//! translation and rotation), what survives the cap of eq. 6.8, the
//! compass modes, V_S from a scan, and the Hausdorff distances of
//! sec. 6.6 (exact, certified, k-th ranked, scan to cell). Refusals are
//! asserted on the `Err`.

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI, SQRT_2, TAU};
use wai_exact::Point;
use wai_map::Map;
use wai_scan::hausdorff::{
    boundary, centre_of_gravity, directed_points, directed_points_to_segments,
    directed_segments_to_points, directed_segments_to_segments, hausdorff_points,
    hausdorff_points_segments, hausdorff_segments, kth_directed_points,
    kth_directed_points_to_segments, scan_to_polygon, scan_to_polygon_kth, HausdorffError,
};
use wai_scan::pcm::{pcm, pcm_fixed, pcm_sampled};
use wai_scan::polar::{Pcf, PolarError, Pt, Shape, StarPolygon};
use wai_scan::{simulate, Compass, Pose, Scan, Sensor};

fn square(half: f64, centre: Pt) -> StarPolygon {
    let (x, y) = centre;
    StarPolygon::new(
        centre,
        vec![
            (x + half, y - half),
            (x + half, y + half),
            (x - half, y + half),
            (x - half, y - half),
        ],
    )
    .unwrap()
}

fn turn(p: Pt, about: Pt, a: f64) -> Pt {
    let (s, c) = a.sin_cos();
    let (dx, dy) = (p.0 - about.0, p.1 - about.1);
    (about.0 + c * dx - s * dy, about.1 + s * dx + c * dy)
}

/// `poly` rotated by `a` about its kernel point.
fn rotate(poly: &StarPolygon, a: f64) -> StarPolygon {
    let k = poly.kernel();
    StarPolygon::new(k, poly.vertices().iter().map(|&v| turn(v, k, a)).collect()).unwrap()
}

fn translate(poly: &StarPolygon, d: Pt) -> StarPolygon {
    let k = poly.kernel();
    StarPolygon::new(
        (k.0 + d.0, k.1 + d.1),
        poly.vertices()
            .iter()
            .map(|v| (v.0 + d.0, v.1 + d.1))
            .collect(),
    )
    .unwrap()
}

/// A random star-shaped polygon: 3..=`max` vertices at sorted random
/// angles (gaps below π − 0.2) and radii in [0.5, 2] about a random
/// kernel point.
fn random_star(rng: &mut ChaCha8Rng, max: usize) -> StarPolygon {
    loop {
        let m = rng.random_range(3..=max);
        let mut angles: Vec<f64> = (0..m).map(|_| rng.random::<f64>() * TAU).collect();
        angles.sort_by(f64::total_cmp);
        let ok = (0..m).all(|i| {
            let next = if i + 1 < m {
                angles[i + 1]
            } else {
                angles[0] + TAU
            };
            next - angles[i] < PI - 0.2 && next - angles[i] > 1e-3
        });
        if !ok {
            continue;
        }
        let k = (
            rng.random::<f64>() * 4.0 - 2.0,
            rng.random::<f64>() * 4.0 - 2.0,
        );
        let vertices = angles
            .iter()
            .map(|a| {
                let r = 0.5 + 1.5 * rng.random::<f64>();
                (k.0 + r * a.cos(), k.1 + r * a.sin())
            })
            .collect();
        return StarPolygon::new(k, vertices).unwrap();
    }
}

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol
}

/// The least eq. 6.7 over `n` equally spaced rotations in [lo, lo + width].
fn grid_min(p: &Pcf, q: &Pcf, lo: f64, width: f64, n: usize) -> f64 {
    (0..=n)
        .map(|k| pcm_fixed(p, q, lo + width * k as f64 / n as f64))
        .fold(f64::INFINITY, f64::min)
}

// ---------------------------------------------------------------- PCF

#[test]
fn the_pcf_of_a_square_about_its_centre_is_half_the_side_over_the_cosine() {
    let sq = square(0.5, (3.0, -1.0)).pcf();
    assert!(close(sq.value(0.0), 0.5, 1e-15));
    assert!(close(sq.value(FRAC_PI_4), 0.5 * SQRT_2, 1e-15));
    assert!(close(sq.value(PI / 3.0), 0.5 / (PI / 3.0).sin(), 1e-15));
    assert!(close(sq.value(-0.3), 0.5 / 0.3f64.cos(), 1e-15));
    assert!(close(sq.value(TAU + 0.3), sq.value(0.3), 1e-15), "periodic");
    // Four edges, the one across angle 0 split in two.
    let pieces = sq.pieces();
    assert_eq!(pieces.len(), 5);
    assert_eq!(pieces[0].from, 0.0);
    assert_eq!(pieces[4].to, TAU);
    for w in pieces.windows(2) {
        assert_eq!(w[0].to, w[1].from, "contiguous");
    }
    // Supporting angles: the 4 vertices, the 4 minima (one at 0, which is
    // also a breakpoint).
    let s = sq.supporting_angles();
    assert_eq!(s.len(), 8, "{s:?}");
    for (k, a) in s.iter().enumerate() {
        assert!(close(*a, FRAC_PI_4 * k as f64, 1e-12), "{s:?}");
    }
}

#[test]
fn the_pcf_of_a_random_star_polygon_is_the_ray_edge_intersection() {
    let mut rng = ChaCha8Rng::seed_from_u64(11);
    for _ in 0..20 {
        let p = random_star(&mut rng, 10);
        let f = p.pcf();
        let k = p.kernel();
        let vs = p.vertices();
        for _ in 0..50 {
            let phi = rng.random::<f64>() * 4.0 * PI - TAU;
            let d = (phi.cos(), phi.sin());
            // Brute force: the nearest hit of the ray over all edges.
            let hit = (0..vs.len())
                .filter_map(|i| {
                    let (a, b) = (vs[i], vs[(i + 1) % vs.len()]);
                    let e = (b.0 - a.0, b.1 - a.1);
                    let den = d.0 * e.1 - d.1 * e.0;
                    let w = (a.0 - k.0, a.1 - k.1);
                    let t = (w.0 * e.1 - w.1 * e.0) / den;
                    let u = (w.0 * d.1 - w.1 * d.0) / den;
                    (t > 0.0 && (-1e-12..=1.0 + 1e-12).contains(&u)).then_some(t)
                })
                .fold(f64::INFINITY, f64::min);
            assert!(
                close(f.value(phi), hit, 1e-9 * hit),
                "{} vs {hit}",
                f.value(phi)
            );
        }
        // At a vertex the value is its distance.
        for v in vs {
            let r = (v.0 - k.0).hypot(v.1 - k.1);
            assert!(close(f.value((v.1 - k.1).atan2(v.0 - k.0)), r, 1e-9 * r));
        }
    }
}

#[test]
fn the_capped_pcf_is_the_minimum_with_the_range() {
    let mut rng = ChaCha8Rng::seed_from_u64(12);
    for _ in 0..20 {
        let p = random_star(&mut rng, 10);
        let f = p.pcf();
        let range = 0.4 + 1.5 * rng.random::<f64>();
        let g = f.capped(range).unwrap();
        for _ in 0..200 {
            let phi = rng.random::<f64>() * TAU;
            assert!(close(g.value(phi), f.value(phi).min(range), 1e-12));
        }
        for w in g.pieces().windows(2) {
            assert_eq!(w[0].to, w[1].from, "contiguous");
            assert!(!(matches!(w[0].shape, Shape::Cap(_)) && w[0].shape == w[1].shape));
        }
        assert_eq!(g.pieces()[0].from, 0.0);
        assert_eq!(g.pieces().last().unwrap().to, TAU);
        assert_eq!(g.capped(range).unwrap(), g, "capping twice changes nothing");
    }
    assert_eq!(
        square(1.0, (0.0, 0.0)).pcf().capped(0.0),
        Err(PolarError::BadRange(0.0))
    );
}

#[test]
fn bad_polygons_are_refused() {
    let sq = vec![(1.0, -1.0), (1.0, 1.0), (-1.0, 1.0), (-1.0, -1.0)];
    assert!(matches!(
        StarPolygon::new((5.0, 5.0), sq.clone()),
        Err(PolarError::NotSeen { .. })
    ));
    // On an edge's line (the edge seen edge-on, sec. 6.9).
    assert!(matches!(
        StarPolygon::new((1.0, 0.0), sq.clone()),
        Err(PolarError::NotSeen { edge: 0 })
    ));
    assert_eq!(
        StarPolygon::new((0.0, 0.0), sq[..2].to_vec()),
        Err(PolarError::TooFewVertices(2))
    );
    let mut nan = sq.clone();
    nan[2].0 = f64::NAN;
    assert!(matches!(
        StarPolygon::new((0.0, 0.0), nan),
        Err(PolarError::NotFinite(_))
    ));
    assert!(matches!(
        StarPolygon::new((f64::INFINITY, 0.0), sq.clone()),
        Err(PolarError::NotFinite(_))
    ));
    // A reflex vertex hiding an edge from the kernel point: an arrow.
    let arrow = vec![(2.0, 0.0), (-1.0, 1.0), (1.5, 0.0), (-1.0, -1.0)];
    assert!(matches!(
        StarPolygon::new((0.0, 0.0), arrow),
        Err(PolarError::NotSeen { .. })
    ));
    // A pentagram: every edge seen, but the boundary winds twice.
    let star: Vec<Pt> = (0..5)
        .map(|k| (f64::from(2 * k) * TAU / 5.0).sin_cos())
        .map(|(s, c)| (c, s))
        .collect();
    assert_eq!(
        StarPolygon::new((0.0, 0.0), star),
        Err(PolarError::Winding { turns: 2 })
    );
    // A repeated vertex gives an edge of no angle.
    let mut dup = sq.clone();
    dup.insert(1, sq[0]);
    assert!(matches!(
        StarPolygon::new((0.0, 0.0), dup),
        Err(PolarError::NotSeen { .. })
    ));
    // Clockwise is accepted and stored counter-clockwise.
    let mut cw = sq.clone();
    cw.reverse();
    let p = StarPolygon::new((0.0, 0.0), cw).unwrap();
    assert_eq!(p.pcf(), square(1.0, (0.0, 0.0)).pcf());
}

// ---------------------------------------------------------------- PCM

#[test]
fn the_pcm_of_squares_matches_the_hand_computed_integrals() {
    // ‖pcf‖² of a square of side s about its centre: 8 · ∫₀^{π/4}
    // (s/2)²/cos² = 8 (s/2)² tan(π/4) = 2 s².
    let unit = square(0.5, (0.0, 0.0)).pcf();
    let double = square(1.0, (0.0, 0.0)).pcf();
    // pcf of the side-2 square is twice the unit one: the difference is
    // the unit pcf, of norm √2.
    assert!(close(pcm_fixed(&unit, &double, 0.0), SQRT_2, 1e-12));
    // Over rotations the best is aligned (Cauchy–Schwarz): still √2.
    let r = pcm(&unit, &double, &Compass::None);
    assert!(close(r.value, SQRT_2, 1e-9), "{r:?}");
    assert!(
        close((r.t / FRAC_PI_2).round() * FRAC_PI_2, r.t, 1e-6),
        "{r:?}"
    );
    // Turned by π/4: on [0, π/4] the two pieces are 1/(2 cos φ) and
    // 1/(2 cos(φ − π/4)); ∫ 1/(cos φ cos(φ − π/4)) = [ln cos(φ − π/4) −
    // ln cos φ]/sin(π/4) = √2 ln 2. Eight such intervals: ⟨f(· − π/4), f⟩
    // = 8 · √2 ln 2 / 4 = 2√2 ln 2.
    let cross = 2.0 * SQRT_2 * 2f64.ln();
    let turned = rotate(&square(0.5, (0.0, 0.0)), FRAC_PI_4).pcf();
    assert!(close(
        pcm_fixed(&turned, &unit, 0.0),
        (4.0 - 2.0 * cross).sqrt(),
        1e-12
    ));
    assert!(close(
        pcm_fixed(&unit, &unit, FRAC_PI_4),
        (4.0 - 2.0 * cross).sqrt(),
        1e-12
    ));
    // ‖f(· − π/4) − 2f‖² = 2 + 8 − 4 · 2√2 ln 2.
    assert!(close(
        pcm_fixed(&unit, &double, FRAC_PI_4),
        (10.0 - 4.0 * cross).sqrt(),
        1e-12
    ));
}

#[test]
fn the_capped_pcm_matches_the_hand_computed_integral() {
    // A side-2 square capped at R against a huge square capped at R (the
    // constant R): 8 ∫₀^{φ₀} (1/cos φ − R)² with cos φ₀ = 1/R, i.e.
    // 8 (tan φ₀ − 2R ln(sec φ₀ + tan φ₀) + R² φ₀).
    let r: f64 = 1.2;
    let phi0 = (1.0 / r).acos();
    let hand = 8.0 * (phi0.tan() - 2.0 * r * (r + phi0.tan()).ln() + r * r * phi0);
    let small = square(1.0, (0.0, 0.0)).pcf().capped(r).unwrap();
    let big = square(10.0, (0.0, 0.0)).pcf().capped(r).unwrap();
    assert_eq!(big.pieces().len(), 1, "one constant piece");
    assert!(close(pcm_fixed(&small, &big, 0.3), hand.sqrt(), 1e-12));
    assert!(close(pcm_fixed(&big, &small, -1.0), hand.sqrt(), 1e-12));
}

#[test]
fn the_closed_form_agrees_with_the_midpoint_rule() {
    let mut rng = ChaCha8Rng::seed_from_u64(21);
    for case in 0..40 {
        let p = random_star(&mut rng, 12);
        let q = random_star(&mut rng, 12);
        let (mut f, mut g) = (p.pcf(), q.pcf());
        if case % 2 == 1 {
            let range = 0.5 + rng.random::<f64>();
            f = f.capped(range).unwrap();
            g = g.capped(range).unwrap();
        }
        let t = rng.random::<f64>() * 20.0 - 10.0;
        let exact = pcm_fixed(&f, &g, t);
        let sampled = pcm_sampled(&f, &g, t, 20_000);
        assert!(
            close(exact, sampled, 1e-4),
            "case {case}: {exact} vs {sampled}"
        );
    }
}

#[test]
fn the_pcm_of_a_polygon_with_itself_is_zero_and_of_others_positive() {
    let mut rng = ChaCha8Rng::seed_from_u64(22);
    for _ in 0..20 {
        let p = random_star(&mut rng, 10);
        let f = p.pcf();
        assert_eq!(pcm_fixed(&f, &f, 0.0), 0.0);
        assert!(pcm(&f, &f, &Compass::None).value < 1e-7);
        let q = random_star(&mut rng, 10);
        assert!(pcm_fixed(&f, &q.pcf(), 0.0) > 1e-3);
        // Scaled by 1.1 about the kernel point: ‖1.1f − f‖ = 0.1 ‖f‖.
        let k = p.kernel();
        let scaled = StarPolygon::new(
            k,
            p.vertices()
                .iter()
                .map(|v| (k.0 + 1.1 * (v.0 - k.0), k.1 + 1.1 * (v.1 - k.1)))
                .collect(),
        )
        .unwrap()
        .pcf();
        let energy = pcm_fixed(&scaled, &f, 0.0) / 0.1;
        let sampled = pcm_sampled(&scaled, &f, 0.0, 20_000) / 0.1;
        assert!(close(energy, sampled, 1e-3));
    }
}

#[test]
fn a_rotated_polygon_is_at_zero_without_a_compass_but_not_with_one() {
    let mut rng = ChaCha8Rng::seed_from_u64(23);
    for _ in 0..20 {
        let p = random_star(&mut rng, 10);
        let a = rng.random::<f64>() * TAU;
        let f = p.pcf();
        let g = rotate(&p, a).pcf();
        let r = pcm(&f, &g, &Compass::None);
        assert!(r.value < 1e-6, "{r:?}");
        assert!(close(pcm_fixed(&f, &g, a), 0.0, 1e-6));
        assert!(pcm_fixed(&f, &g, 0.0) > 1e-3 || (a % TAU).min(TAU - a % TAU) < 1e-2);
        // The rotation found turns p onto its copy.
        assert!(pcm_fixed(&f, &g, r.t) <= r.value + 1e-12);
    }
}

#[test]
fn the_pcm_is_symmetric_and_invariant_under_translation_and_rotation() {
    let mut rng = ChaCha8Rng::seed_from_u64(24);
    for _ in 0..20 {
        let p = random_star(&mut rng, 9);
        let q = random_star(&mut rng, 9);
        let (f, g) = (p.pcf(), q.pcf());
        let t = rng.random::<f64>() * TAU;
        let d = pcm_fixed(&f, &g, t);
        assert!(close(d, pcm_fixed(&g, &f, -t), 1e-9));
        let none = pcm(&f, &g, &Compass::None).value;
        assert!(close(none, pcm(&g, &f, &Compass::None).value, 1e-7));
        let v = (rng.random::<f64>() * 10.0, rng.random::<f64>() * -10.0);
        let moved = pcm_fixed(&translate(&p, v).pcf(), &g, t);
        assert!(close(d, moved, 1e-9), "{d} vs {moved}");
        let a = rng.random::<f64>() * TAU;
        let pr = rotate(&p, a).pcf();
        assert!(close(pcm_fixed(&pr, &g, t - a), d, 1e-9));
        assert!(close(pcm(&pr, &g, &Compass::None).value, none, 1e-7));
    }
}

#[test]
fn the_pcm_satisfies_the_triangle_inequality() {
    let mut rng = ChaCha8Rng::seed_from_u64(25);
    for case in 0..25 {
        let ps: Vec<Pcf> = (0..3).map(|_| random_star(&mut rng, 8).pcf()).collect();
        let (a, b, c) = (&ps[0], &ps[1], &ps[2]);
        // Fixed rotations compose: ‖a(·−t₁−t₂) − c‖ ≤ ‖a(·−t₁−t₂) −
        // b(·−t₂)‖ + ‖b(·−t₂) − c‖.
        let (t1, t2) = (rng.random::<f64>() * TAU, rng.random::<f64>() * TAU);
        let ac = pcm_fixed(a, c, t1 + t2);
        assert!(
            ac <= pcm_fixed(a, b, t1) + pcm_fixed(b, c, t2) + 1e-9,
            "case {case}"
        );
        let (ab, bc, ac) = (
            pcm(a, b, &Compass::None).value,
            pcm(b, c, &Compass::None).value,
            pcm(a, c, &Compass::None).value,
        );
        assert!(ac <= ab + bc + 1e-7, "case {case}: {ac} > {ab} + {bc}");
        assert!(ab <= ac + bc + 1e-7 && bc <= ab + ac + 1e-7, "case {case}");
    }
}

#[test]
fn with_the_cap_the_pcm_is_only_a_pseudo_metric() {
    // Eq. 6.8: beyond the sensing range every polygon looks the same, so
    // distinct polygons can be at distance 0 ...
    let big = square(4.0, (0.0, 0.0)).pcf().capped(1.0).unwrap();
    let bigger = square(6.0, (1.0, 1.0)).pcf().capped(1.0).unwrap();
    assert_ne!(square(4.0, (0.0, 0.0)), square(6.0, (1.0, 1.0)));
    assert_eq!(pcm_fixed(&big, &bigger, 0.7), 0.0);
    // ... but for one rotation it is still an L2 distance between (capped)
    // functions: symmetric and with the triangle inequality.
    let mut rng = ChaCha8Rng::seed_from_u64(26);
    for case in 0..40 {
        let range = 0.6 + rng.random::<f64>();
        let ps: Vec<Pcf> = (0..3)
            .map(|_| random_star(&mut rng, 8).pcf().capped(range).unwrap())
            .collect();
        let (a, b, c) = (&ps[0], &ps[1], &ps[2]);
        let t = rng.random::<f64>() * TAU;
        let ab = pcm_fixed(a, b, t);
        assert!(close(ab, pcm_fixed(b, a, -t), 1e-9));
        assert!(
            pcm_fixed(a, c, t) <= ab + pcm_fixed(b, c, 0.0) + 1e-9,
            "case {case}"
        );
    }
}

#[test]
fn the_minimum_over_rotations_matches_a_dense_grid() {
    let mut rng = ChaCha8Rng::seed_from_u64(27);
    for case in 0..12 {
        let (mut f, mut g) = (
            random_star(&mut rng, 8).pcf(),
            random_star(&mut rng, 8).pcf(),
        );
        if case % 3 == 2 {
            f = f.capped(1.0).unwrap();
            g = g.capped(1.0).unwrap();
        }
        let r = pcm(&f, &g, &Compass::None);
        // The value is attained at the rotation reported.
        assert!(close(pcm_fixed(&f, &g, r.t), r.value, 1e-12));
        let grid = grid_min(&f, &g, 0.0, TAU, 4000);
        assert!(
            r.value <= grid + 1e-9,
            "case {case}: {} > grid {grid}",
            r.value
        );
        // And the grid point nearest the minimum is not far above it
        // (eq. 6.7 is Lipschitz in t): the minimum is a real one.
        assert!(grid - r.value < 0.05, "case {case}");
        // A noisy compass: the minimum over [h − ε, h + ε].
        let (h, eps) = (rng.random::<f64>() * TAU, 0.3);
        let n = pcm(&f, &g, &Compass::Noisy { heading: h, eps });
        let grid = grid_min(&f, &g, h - eps, 2.0 * eps, 1000);
        assert!(
            n.value <= grid + 1e-9,
            "case {case}: {} > grid {grid}",
            n.value
        );
        let off = (n.t - (h - eps)).rem_euclid(TAU);
        assert!(off <= 2.0 * eps + 1e-9, "case {case}: t {} outside", n.t);
    }
}

#[test]
fn a_noisy_compass_lies_between_none_and_exact() {
    let mut rng = ChaCha8Rng::seed_from_u64(28);
    for case in 0..20 {
        let (f, g) = (
            random_star(&mut rng, 8).pcf(),
            random_star(&mut rng, 8).pcf(),
        );
        let h = rng.random::<f64>() * TAU;
        let exact = pcm(&f, &g, &Compass::Exact(h)).value;
        assert!(close(exact, pcm_fixed(&f, &g, h), 0.0));
        let none = pcm(&f, &g, &Compass::None).value;
        let mut last = exact;
        for eps in [0.0, 0.05, 0.2, 1.0, 3.0] {
            let noisy = pcm(&f, &g, &Compass::Noisy { heading: h, eps }).value;
            assert!(
                noisy <= last + 1e-12,
                "case {case}: ε {eps} gave {noisy} > {last}"
            );
            assert!(
                none <= noisy + 1e-7,
                "case {case}: ε {eps}: none {none} > {noisy}"
            );
            if eps == 0.0 {
                assert!(close(noisy, exact, 1e-12));
            }
            last = noisy;
        }
        let all = pcm(
            &f,
            &g,
            &Compass::Noisy {
                heading: h,
                eps: 4.0,
            },
        )
        .value;
        assert!(close(all, none, 1e-12));
        // A heading that is not a number gives no distance, not 0.
        assert!(pcm(&f, &g, &Compass::Exact(f64::NAN)).value.is_nan());
        let nan = Compass::Noisy {
            heading: f64::NAN,
            eps: 0.1,
        };
        assert!(pcm(&f, &g, &nan).value.is_nan());
    }
}

// ---------------------------------------------------------------- V_S

fn room() -> Map {
    Map::from_ring(
        [(0, 0), (6, 0), (6, 4), (0, 4)]
            .iter()
            .map(|&(x, y)| Point::new(x, y))
            .collect(),
    )
    .unwrap()
    .0
}

#[test]
fn v_s_of_a_scan_in_a_convex_room_is_the_room_about_the_pose() {
    let m = room();
    let pose = Pose {
        x: 2.0,
        y: 1.5,
        heading: 0.8,
    };
    let sensor = Sensor {
        beams: 90,
        ..Sensor::default()
    };
    let scan = simulate(&m, &[], &pose, &sensor, 0).unwrap();
    let vs = StarPolygon::from_scan(&scan, 100.0).unwrap();
    assert_eq!(vs.kernel(), (0.0, 0.0));
    assert_eq!(vs.vertices().len(), 90);
    let f = vs.pcf();
    for (a, r) in scan.angles.iter().zip(&scan.ranges) {
        assert!(close(f.value(*a), r.unwrap(), 1e-9));
    }
    // The room about the pose, in the map frame: the scan's chords lie on
    // the walls except across the four corners.
    let map_poly = StarPolygon::new(
        (pose.x, pose.y),
        vec![(0.0, 0.0), (6.0, 0.0), (6.0, 4.0), (0.0, 4.0)],
    )
    .unwrap()
    .pcf();
    let at = pcm(&f, &map_poly, &Compass::Exact(pose.heading)).value;
    assert!(at < 0.05, "{at}");
    assert!(pcm(&f, &map_poly, &Compass::Exact(pose.heading + 0.5)).value > 10.0 * at);
    let found = pcm(&f, &map_poly, &Compass::None);
    assert!(found.value <= at + 1e-12);
    assert!(close(found.t, pose.heading, 0.05), "{found:?}");
}

#[test]
fn lost_returns_become_vertices_at_the_range_and_gaps_are_refused() {
    let scan = Scan {
        angles: vec![0.0, FRAC_PI_2, PI, 3.0 * FRAC_PI_2],
        ranges: vec![Some(1.0), None, Some(2.0), Some(1.0)],
        max_range: None,
    };
    let vs = StarPolygon::from_scan(&scan, 5.0).unwrap();
    assert!(close(vs.pcf().value(FRAC_PI_2), 5.0, 1e-12));
    assert!(close(vs.pcf().value(PI), 2.0, 1e-12));
    assert_eq!(
        StarPolygon::from_scan(&scan, -1.0),
        Err(PolarError::BadRange(-1.0))
    );
    // A 180° scanner leaves a gap of π behind the robot.
    let half = Scan {
        angles: vec![-FRAC_PI_2, 0.0, FRAC_PI_2],
        ranges: vec![Some(1.0); 3],
        max_range: None,
    };
    assert!(matches!(
        StarPolygon::from_scan(&half, 5.0),
        Err(PolarError::ScanGap { .. })
    ));
    let zero = Scan {
        angles: vec![0.0, 2.0, 4.0],
        ranges: vec![Some(1.0), Some(0.0), Some(1.0)],
        max_range: None,
    };
    assert!(matches!(
        StarPolygon::from_scan(&zero, 5.0),
        Err(PolarError::NotFinite(_))
    ));
    let short = Scan {
        angles: vec![0.0, 2.0],
        ranges: vec![Some(1.0); 2],
        max_range: None,
    };
    assert_eq!(
        StarPolygon::from_scan(&short, 5.0),
        Err(PolarError::ScanTooShort(2))
    );
}

// ---------------------------------------------------------------- Hausdorff

fn square_ring(side: f64) -> Vec<Pt> {
    vec![(0.0, 0.0), (side, 0.0), (side, side), (0.0, side)]
}

#[test]
fn hausdorff_distances_of_points_to_a_square() {
    let sq = boundary(&square_ring(2.0));
    assert_eq!(directed_points_to_segments(&[(1.0, 1.0)], &sq), Ok(1.0));
    assert_eq!(directed_points_to_segments(&[(3.0, 1.0)], &sq), Ok(1.0));
    assert!(close(
        directed_points_to_segments(&[(3.0, 3.0)], &sq).unwrap(),
        SQRT_2,
        1e-15
    ));
    assert!(close(
        directed_points_to_segments(&[(1.0, 1.0), (3.0, 3.0), (0.5, 0.0)], &sq).unwrap(),
        SQRT_2,
        1e-15
    ));
    // The corners against the boundary: 0 one way, half a side the other
    // (the mid-edges), certified to within the tolerance.
    let corners = square_ring(2.0);
    assert_eq!(directed_points_to_segments(&corners, &sq), Ok(0.0));
    let back = directed_segments_to_points(&sq, &corners, 1e-9).unwrap();
    assert!((1.0 - 1e-9..=1.0).contains(&back), "{back}");
    let both = hausdorff_points_segments(&corners, &sq, 1e-9).unwrap();
    assert!(close(both, 1.0, 1e-9));
}

#[test]
fn the_directed_distance_is_not_symmetric() {
    let a = [(0.0, 0.0)];
    let b = [(0.0, 0.0), (10.0, 0.0)];
    assert_eq!(directed_points(&a, &b), Ok(0.0));
    assert_eq!(directed_points(&b, &a), Ok(10.0));
    assert_eq!(hausdorff_points(&a, &b), Ok(10.0));
    assert_eq!(hausdorff_points(&b, &a), Ok(10.0));
}

#[test]
fn segment_distances_find_the_interior_maximum() {
    // Along [(0,0), (2,0)] the distance to {(0,1), (2,1)} peaks mid-way at
    // √2, not at the ends (1).
    let a = [[(0.0, 0.0), (2.0, 0.0)]];
    let tol = 1e-7;
    let r = directed_segments_to_points(&a, &[(0.0, 1.0), (2.0, 1.0)], tol).unwrap();
    assert!((SQRT_2 - tol..=SQRT_2).contains(&r), "{r}");
    let b = [[(0.0, 1.0), (0.0, 2.0)], [(2.0, 1.0), (2.0, 2.0)]];
    let r = directed_segments_to_segments(&a, &b, tol).unwrap();
    assert!((SQRT_2 - tol..=SQRT_2).contains(&r), "{r}");
    // Back: the farthest point of B is (0, 2) or (2, 2), at distance 2.
    let r = hausdorff_segments(&a, &b, tol).unwrap();
    assert!(close(r, 2.0, tol), "{r}");
    // A wall parallel to the other: d is flat, 1 everywhere, and the
    // convexity bound closes every piece at once even at a tiny tolerance.
    let long = [[(0.0, 0.0), (1000.0, 0.0)]];
    let parallel = [[(0.0, 1.0), (1000.0, 1.0)]];
    assert_eq!(hausdorff_segments(&long, &parallel, 1e-12), Ok(1.0));
    // Against a dense sample of A on random segment sets.
    let mut rng = ChaCha8Rng::seed_from_u64(31);
    let seg = |rng: &mut ChaCha8Rng| {
        let mut p = || (rng.random::<f64>() * 4.0, rng.random::<f64>() * 4.0);
        [p(), p()]
    };
    for _ in 0..10 {
        let a: Vec<_> = (0..3).map(|_| seg(&mut rng)).collect();
        let b: Vec<_> = (0..4).map(|_| seg(&mut rng)).collect();
        let r = directed_segments_to_segments(&a, &b, 1e-6).unwrap();
        let sampled: Vec<Pt> = a
            .iter()
            .flat_map(|s| {
                (0..=2000).map(move |k| {
                    let t = f64::from(k) / 2000.0;
                    (
                        s[0].0 + t * (s[1].0 - s[0].0),
                        s[0].1 + t * (s[1].1 - s[0].1),
                    )
                })
            })
            .collect();
        let dense = directed_points_to_segments(&sampled, &b).unwrap();
        // The dense sample is below the sup, and the sup is at most a
        // half sample step (≤ 4√2/4000) above it.
        assert!(r + 1e-6 >= dense, "{r} < {dense}");
        assert!(r <= dense + 4.0 * SQRT_2 / 4000.0, "{r} vs {dense}");
    }
}

#[test]
fn the_kth_hausdorff_distance_ignores_outliers() {
    let sq = boundary(&square_ring(4.0));
    let mut pts: Vec<Pt> = (0..40)
        .map(|k| {
            let s = 0.4 * f64::from(k % 10);
            match k / 10 {
                0 => (s, 0.0),
                1 => (4.0, s),
                2 => (4.0 - s, 4.0),
                _ => (0.0, 4.0 - s),
            }
        })
        .collect();
    assert!(directed_points_to_segments(&pts, &sq).unwrap() < 1e-12);
    // Two returns off an unknown obstacle.
    pts.push((2.0, 2.0));
    pts.push((1.0, 3.0));
    let n = pts.len();
    let full = directed_points_to_segments(&pts, &sq).unwrap();
    assert_eq!(full, 2.0);
    assert_eq!(kth_directed_points_to_segments(&pts, &sq, n), Ok(full));
    assert_eq!(kth_directed_points_to_segments(&pts, &sq, n - 1), Ok(1.0));
    assert!(kth_directed_points_to_segments(&pts, &sq, n - 2).unwrap() < 1e-12);
    let corners = square_ring(4.0);
    assert_eq!(
        kth_directed_points(&pts, &corners, n),
        directed_points(&pts, &corners)
    );
    assert_eq!(
        kth_directed_points(&pts, &corners, 0),
        Err(HausdorffError::BadRank { k: 0, n })
    );
    assert_eq!(
        kth_directed_points_to_segments(&pts, &sq, n + 1),
        Err(HausdorffError::BadRank { k: n + 1, n })
    );
}

#[test]
fn the_hausdorff_distance_is_a_metric_and_rigidly_invariant() {
    let mut rng = ChaCha8Rng::seed_from_u64(32);
    let set = |rng: &mut ChaCha8Rng| -> Vec<Pt> {
        let n = rng.random_range(1..12);
        (0..n)
            .map(|_| (rng.random::<f64>() * 5.0, rng.random::<f64>() * 5.0))
            .collect()
    };
    for _ in 0..200 {
        let (a, b, c) = (set(&mut rng), set(&mut rng), set(&mut rng));
        let ab = hausdorff_points(&a, &b).unwrap();
        let bc = hausdorff_points(&b, &c).unwrap();
        let ac = hausdorff_points(&a, &c).unwrap();
        assert!(ac <= ab + bc + 1e-12);
        assert_eq!(ab, hausdorff_points(&b, &a).unwrap());
        assert_eq!(hausdorff_points(&a, &a), Ok(0.0));
        let (ang, d) = (rng.random::<f64>() * TAU, (rng.random::<f64>(), -3.0));
        let moved = |s: &[Pt]| -> Vec<Pt> {
            s.iter()
                .map(|&p| {
                    let q = turn(p, (0.0, 0.0), ang);
                    (q.0 + d.0, q.1 + d.1)
                })
                .collect()
        };
        assert!(close(
            hausdorff_points(&moved(&a), &moved(&b)).unwrap(),
            ab,
            1e-12
        ));
        let segs = boundary(&c);
        let pd = directed_points_to_segments(&a, &segs).unwrap();
        let moved_segs = boundary(&moved(&c));
        assert!(close(
            directed_points_to_segments(&moved(&a), &moved_segs).unwrap(),
            pd,
            1e-12
        ));
    }
}

#[test]
fn a_scan_placed_at_the_true_pose_fits_its_room() {
    let m = room();
    let pose = Pose {
        x: 2.0,
        y: 1.0,
        heading: 0.4,
    };
    let scan = simulate(&m, &[], &pose, &Sensor::default(), 0).unwrap();
    let points = scan.points();
    let ring = vec![(0.0, 0.0), (6.0, 0.0), (6.0, 4.0), (0.0, 4.0)];
    let walls = boundary(&ring);
    assert!(scan_to_polygon(&points, &pose, &walls).unwrap() < 1e-9);
    let turned = Pose {
        heading: 0.4 + FRAC_PI_4,
        ..pose
    };
    assert!(scan_to_polygon(&points, &turned, &walls).unwrap() > 0.5);
    // At the room's centre of gravity (3, 2) the scan is off by the
    // displacement along x or y at most: between 0 and √(1² + 1²).
    let g = centre_of_gravity(&ring).unwrap();
    assert!(close(g.0, 3.0, 1e-12) && close(g.1, 2.0, 1e-12));
    let at_centre = Pose {
        x: g.0,
        y: g.1,
        ..pose
    };
    let d = scan_to_polygon(&points, &at_centre, &walls).unwrap();
    assert!(d > 0.5 && d <= SQRT_2 + 1e-9, "{d}");
    // Outliers: three points pushed 1.5 off the walls are ignored by the
    // k-th distance with k = |S| − 3.
    let mut noisy = points.clone();
    for k in [0, 200, 400] {
        let (x, y) = noisy[k];
        let r = x.hypot(y);
        noisy[k] = (x * (r - 1.5) / r, y * (r - 1.5) / r);
    }
    assert!(scan_to_polygon(&noisy, &pose, &walls).unwrap() > 0.3);
    let n = noisy.len();
    assert!(scan_to_polygon_kth(&noisy, &pose, &walls, n - 3).unwrap() < 1e-9);
}

#[test]
fn centre_of_gravity_of_an_l_shape() {
    // An L of three unit squares: centroids (0.5, 0.5), (1.5, 0.5),
    // (0.5, 1.5): mean (5/6, 5/6).
    let l = [
        (0.0, 0.0),
        (2.0, 0.0),
        (2.0, 1.0),
        (1.0, 1.0),
        (1.0, 2.0),
        (0.0, 2.0),
    ];
    let g = centre_of_gravity(&l).unwrap();
    assert!(
        close(g.0, 5.0 / 6.0, 1e-12) && close(g.1, 5.0 / 6.0, 1e-12),
        "{g:?}"
    );
    assert_eq!(
        centre_of_gravity(&[(0.0, 0.0), (1.0, 1.0), (2.0, 2.0)]),
        Err(HausdorffError::Degenerate(3))
    );
}

#[test]
fn bad_hausdorff_inputs_are_refused() {
    let sq = boundary(&square_ring(1.0));
    assert_eq!(
        directed_points(&[], &[(0.0, 0.0)]),
        Err(HausdorffError::Empty("A"))
    );
    assert_eq!(
        directed_points_to_segments(&[(0.0, 0.0)], &[]),
        Err(HausdorffError::Empty("B"))
    );
    assert_eq!(
        directed_points(&[(f64::NAN, 0.0)], &[(0.0, 0.0)]),
        Err(HausdorffError::NotFinite("A"))
    );
    assert_eq!(
        directed_segments_to_segments(&sq, &[[(0.0, 0.0), (f64::INFINITY, 0.0)]], 1e-3),
        Err(HausdorffError::NotFinite("B"))
    );
    for tol in [0.0, -1.0, f64::NAN] {
        assert!(matches!(
            directed_segments_to_points(&sq, &[(0.0, 0.0)], tol),
            Err(HausdorffError::BadTolerance(_))
        ));
    }
}
