//! Simulated scans against hand-computed ranges: a square room seen from
//! its centre and off-centre, noise statistics, determinism, the range
//! cutoff, a 180° field of view, obstacles that shadow walls, and the
//! refusals (pose outside, on a wall, inside an obstacle, bad settings).
#![allow(clippy::float_arithmetic, reason = "ranges are floats")]

use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI, TAU};
use wai_exact::Point;
use wai_map::Map;
use wai_scan::{random_obstacles, simulate, true_range, Obstacle, Pose, ScanError, Sensor};

fn map(ring: &[(i128, i128)]) -> Map {
    Map::from_ring(ring.iter().map(|&(x, y)| Point::new(x, y)).collect())
        .expect("valid")
        .0
}

fn square() -> Map {
    map(&[(0, 0), (4, 0), (4, 4), (0, 4)])
}

fn pose(x: f64, y: f64, heading: f64) -> Pose {
    Pose { x, y, heading }
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() < 1e-9
}

#[test]
fn ranges_in_a_square_room_are_the_distances_to_its_walls() {
    let m = square();
    let p = pose(1.0, 2.0, 0.0);
    for (angle, want) in [
        (0.0, 3.0),
        (FRAC_PI_2, 2.0),
        (PI, 1.0),
        (-FRAC_PI_2, 2.0),
        (FRAC_PI_4, 2.0 * 2f64.sqrt()),
        (3.0 * FRAC_PI_4, 2f64.sqrt()),
    ] {
        let got = true_range(&m, &[], &p, angle);
        assert!(close(got, want), "angle {angle}: {got} != {want}");
    }
    // The heading turns the scan: heading π/2 looks where angle π/2 did.
    let turned = pose(1.0, 2.0, FRAC_PI_2);
    assert!(close(true_range(&m, &[], &turned, 0.0), 2.0));
}

#[test]
fn a_noiseless_scan_has_the_true_ranges_at_equal_angles() {
    let m = square();
    let p = pose(2.0, 2.0, 0.3);
    let sensor = Sensor {
        beams: 8,
        ..Sensor::default()
    };
    let scan = simulate(&m, &[], &p, &sensor, 1).unwrap();
    assert_eq!(scan.angles.len(), 8);
    assert!(close(scan.angles[0], -PI));
    for w in scan.angles.windows(2) {
        assert!(close(w[1] - w[0], TAU / 8.0));
    }
    for (a, r) in scan.angles.iter().zip(&scan.ranges) {
        assert!(close(r.unwrap(), true_range(&m, &[], &p, *a)));
    }
    assert_eq!(scan.points().len(), 8);
}

#[test]
fn noise_is_gaussian_with_the_given_sigma_and_seeded() {
    let m = map(&[(0, 0), (100, 0), (100, 100), (0, 100)]);
    let p = pose(50.0, 50.0, 0.0);
    let sensor = Sensor {
        beams: 20_000,
        sigma: 0.02,
        ..Sensor::default()
    };
    let a = simulate(&m, &[], &p, &sensor, 7).unwrap();
    let b = simulate(&m, &[], &p, &sensor, 7).unwrap();
    assert_eq!(a, b, "the same seed gives the same scan");
    let c = simulate(&m, &[], &p, &sensor, 8).unwrap();
    assert_ne!(a, c);
    let errors: Vec<f64> = a
        .angles
        .iter()
        .zip(&a.ranges)
        .map(|(ang, r)| r.unwrap() - true_range(&m, &[], &p, *ang))
        .collect();
    let n = errors.len() as f64;
    let mean = errors.iter().sum::<f64>() / n;
    let sd = (errors.iter().map(|e| (e - mean).powi(2)).sum::<f64>() / n).sqrt();
    // Standard error of the mean 0.02/√20000 ≈ 1.4e-4; of the sd ≈ 1e-4.
    assert!(mean.abs() < 7e-4, "mean {mean}");
    assert!((sd - 0.02).abs() < 7e-4, "sd {sd}");
}

#[test]
fn returns_beyond_the_range_limit_are_lost() {
    let m = map(&[(0, 0), (20, 0), (20, 2), (0, 2)]);
    let p = pose(1.0, 1.0, 0.0);
    let sensor = Sensor {
        beams: 4,
        max_range: Some(10.0),
        ..Sensor::default()
    };
    let scan = simulate(&m, &[], &p, &sensor, 0).unwrap();
    // Beams at -π (1 m), -π/2 (1 m), 0 (19 m: lost), π/2 (1 m).
    let kept: Vec<bool> = scan.ranges.iter().map(Option::is_some).collect();
    assert_eq!(kept, vec![true, true, false, true]);
}

#[test]
fn a_half_circle_scanner_spans_minus_to_plus_ninety_degrees() {
    let sensor = Sensor {
        beams: 181,
        fov: PI,
        ..Sensor::default()
    };
    assert!(close(sensor.angle(0), -FRAC_PI_2));
    assert!(close(sensor.angle(90), 0.0));
    assert!(close(sensor.angle(180), FRAC_PI_2));
}

#[test]
fn an_obstacle_shadows_the_wall_behind_it() {
    let m = square();
    let p = pose(1.0, 2.0, 0.0);
    let box_ = Obstacle {
        min: (2.0, 1.5),
        max: (2.5, 2.5),
    };
    assert!(close(true_range(&m, &[box_], &p, 0.0), 1.0));
    assert!(close(true_range(&m, &[box_], &p, PI), 1.0));
    let placed = random_obstacles(&m, &p, 3, 0.3, 5);
    assert_eq!(placed.len(), 3);
    for o in &placed {
        assert!(!o.contains(p.x, p.y));
        assert!(o.min.0 > 0.0 && o.max.0 < 4.0 && o.min.1 > 0.0 && o.max.1 < 4.0);
    }
    assert_eq!(placed, random_obstacles(&m, &p, 3, 0.3, 5), "seeded");
}

#[test]
fn obstacles_stay_out_of_walls_in_an_orthogonal_map() {
    // A comb: thin walls that a box could straddle with all corners inside.
    let m = map(&[
        (0, 0),
        (9, 0),
        (9, 9),
        (6, 9),
        (6, 3),
        (5, 3),
        (5, 9),
        (4, 9),
        (4, 3),
        (3, 3),
        (3, 9),
        (0, 9),
    ]);
    let p = pose(1.0, 1.0, 0.0);
    for o in random_obstacles(&m, &p, 20, 1.5, 3) {
        for x in [o.min.0, o.max.0] {
            for y in [o.min.1, o.max.1] {
                assert!(pose(x, y, 0.0).check_inside(&m).is_ok());
            }
        }
        // No wall runs between the corners: the box's centre sees them all.
        let c = ((o.min.0 + o.max.0) / 2.0, (o.min.1 + o.max.1) / 2.0);
        let centre = pose(c.0, c.1, 0.0);
        let half_diag = ((o.max.0 - o.min.0).powi(2) + (o.max.1 - o.min.1).powi(2)).sqrt() / 2.0;
        for k in 0..4 {
            let a = FRAC_PI_4 + FRAC_PI_2 * f64::from(k);
            assert!(true_range(&m, &[], &centre, a) >= half_diag - 1e-9);
        }
    }
}

#[test]
fn bad_poses_and_settings_are_refused() {
    let m = square();
    let s = Sensor::default();
    assert!(matches!(
        simulate(&m, &[], &pose(5.0, 1.0, 0.0), &s, 0),
        Err(ScanError::Outside(_))
    ));
    assert!(matches!(
        simulate(&m, &[], &pose(0.0, 1.0, 0.0), &s, 0),
        Err(ScanError::OnBoundary(_))
    ));
    assert!(matches!(
        simulate(&m, &[], &pose(f64::NAN, 1.0, 0.0), &s, 0),
        Err(ScanError::NotFinite(_))
    ));
    let box_ = Obstacle {
        min: (0.5, 0.5),
        max: (1.5, 1.5),
    };
    assert!(matches!(
        simulate(&m, &[box_], &pose(1.0, 1.0, 0.0), &s, 0),
        Err(ScanError::InObstacle(_, 0))
    ));
    for bad in [
        Sensor {
            beams: 0,
            ..Sensor::default()
        },
        Sensor {
            fov: 0.0,
            ..Sensor::default()
        },
        Sensor {
            fov: 7.0,
            ..Sensor::default()
        },
        Sensor {
            sigma: -1.0,
            ..Sensor::default()
        },
        Sensor {
            max_range: Some(0.0),
            ..Sensor::default()
        },
    ] {
        let e = simulate(&m, &[], &pose(1.0, 1.0, 0.0), &bad, 0).unwrap_err();
        assert!(matches!(e, ScanError::Config(_)), "{e}");
    }
    // A pose just inside by one ulp of a binary fraction is accepted: the
    // decision is exact.
    assert!(pose(f64::EPSILON, 1.0, 0.0).check_inside(&m).is_ok());
}

#[test]
fn a_scan_in_a_generated_orthogonal_map_has_a_return_on_every_beam() {
    let m = wai_gen::random("random-orthogonal", 20, 3).unwrap();
    // The first interior lattice point found by a walk over a fine grid.
    let (lo, hi) = m.bounding_box();
    let p = (lo.x * 4..hi.x * 4)
        .flat_map(|x| (lo.y * 4..hi.y * 4).map(move |y| (x, y)))
        .map(|(x, y)| pose(x as f64 / 4.0 + 0.125, y as f64 / 4.0 + 0.125, 0.0))
        .find(|p| p.check_inside(&m).is_ok())
        .expect("an interior point");
    let scan = simulate(&m, &[], &p, &Sensor::default(), 0).unwrap();
    assert!(scan
        .ranges
        .iter()
        .all(|r| r.is_some_and(|r| r.is_finite() && r > 0.0)));
}
mod carmen;
mod caster;
mod distances;
mod independent;
mod index;
mod localizer;
mod peer;
