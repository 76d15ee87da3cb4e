//! The scan localizer's parts against their references: the walls grid
//! against loops over every wall, the ranking (lower-bound order, MBT,
//! local queries) against a linear scan of every site, the Parseval bound
//! below the PCM, ICP convergence, the answer set on a building of
//! identical rooms, the units, the indoor generators and the evaluation
//! bookkeeping — each checker shown to fail on a planted violation.

use std::f64::consts::{FRAC_PI_2, PI, TAU};

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use wai_exact::Point;
use wai_map::Map;
use wai_scan::eval::{self, CompassMode, Condition, Outcome, Trial};
use wai_scan::signature::{Plans, ScanSignature, Signature};
use wai_scan::units::{to_metres, Units};
use wai_scan::walls::Walls;
use wai_scan::{icp, simulate, Compass, Near, Options, Pose, ScanLocalizer, Sensor};

fn walls_of(map: &Map) -> Walls {
    Walls::new(wai_scan::peer::map_walls(map))
}

fn noisy() -> Sensor {
    Sensor {
        sigma: 0.02,
        ..Sensor::default()
    }
}

#[test]
fn the_walls_grid_casts_and_pairs_like_a_loop_over_every_wall() {
    let map = wai_gen::office(3, 7);
    let walls = walls_of(&map);
    let mut rng = ChaCha8Rng::seed_from_u64(3);
    let poses = eval::random_poses(&map, &walls, 60, 0.0, 5);
    let mut rays = 0;
    for p in &poses {
        for _ in 0..20 {
            let a: f64 = rng.random_range(-PI..PI);
            let d = (a.cos(), a.sin());
            let (grid, brute) = (walls.cast((p.x, p.y), d), walls.cast_brute((p.x, p.y), d));
            assert!(
                (grid - brute).abs() <= 1e-9 * brute.max(1.0),
                "ray from {p:?} at {a}: grid {grid}, brute {brute}"
            );
            rays += 1;
        }
        // Orthogonal maps: axis-parallel rays graze collinear walls.
        for k in 0..4 {
            let a = FRAC_PI_2 * f64::from(k);
            let d = (a.cos(), a.sin());
            assert_eq!(walls.cast((p.x, p.y), d), walls.cast_brute((p.x, p.y), d));
        }
        for gate in [0.1, 0.5, 2.0] {
            let q = (
                p.x + rng.random_range(-1.0..1.0),
                p.y + rng.random_range(-1.0..1.0),
            );
            let (a, b) = (walls.nearest(q, gate), walls.nearest_brute(q, gate));
            assert_eq!(a.is_some(), b.is_some(), "{q:?} gate {gate}");
            if let (Some(a), Some(b)) = (a, b) {
                assert!((a.distance - b.distance).abs() < 1e-12);
            }
        }
    }
    assert_eq!(rays, 1200);
}

#[test]
fn a_point_behind_a_thin_wall_pairs_with_the_face_the_robot_sees() {
    // A room 4 m wide whose right wall is 0.2 m thick: x = 4 inside, the
    // next room's face at x = 4.2.
    let walls = Walls::new(vec![
        [(4.0, 0.0), (4.0, 4.0)], // inner face of the left room, seen from x < 4
        [(4.2, 4.0), (4.2, 0.0)], // face of the room beyond, seen from x > 4.2
    ]);
    let robot = (2.0, 2.0);
    // A scan point that overshot the wall by 15 cm: the nearest wall is the
    // far face, but the robot sees the near one.
    let p = (4.15, 2.0);
    let any = walls.nearest(p, 1.0).unwrap();
    assert!((any.point.0 - 4.2).abs() < 1e-12);
    let facing = walls.nearest_facing(p, 1.0, Some(robot)).unwrap();
    assert!((facing.point.0 - 4.0).abs() < 1e-12, "{facing:?}");
}

/// A localizer on a small office, and scans from seeded poses.
fn office() -> (Map, ScanLocalizer) {
    let map = wai_gen::office(2, 3);
    let loc = ScanLocalizer::new(&map, Options::default());
    (map, loc)
}

fn same_ranking(a: &[wai_scan::RankedCell], b: &[wai_scan::RankedCell]) -> bool {
    a.len() == b.len()
        && a.iter()
            .zip(b)
            .all(|(x, y)| x.site == y.site && (x.pcm - y.pcm).abs() <= 1e-9 * y.pcm.max(1.0))
}

#[test]
fn the_ranking_equals_a_linear_scan_for_every_compass_field_of_view_and_local_query() {
    let (map, loc) = office();
    let poses = eval::random_poses(&map, loc.walls(), 12, 0.2, 11);
    let half = Sensor { fov: PI, ..noisy() };
    // A 3 m sensor loses beams: stated, the PCFs are capped at 3 m again
    // for the query; not stated, at the longest return.
    let short = Sensor {
        max_range: Some(3.0),
        ..noisy()
    };
    let mut checked = 0;
    for (i, p) in poses.iter().enumerate() {
        for (sensor, stated) in [
            (noisy(), true),
            (half.clone(), true),
            (short.clone(), true),
            (short.clone(), false),
        ] {
            let mut scan = simulate(&map, &[], p, &sensor, i as u64).unwrap();
            if !stated {
                scan.max_range = None;
            }
            for compass in [
                Compass::Exact(p.heading),
                Compass::Noisy {
                    heading: p.heading + 0.05,
                    eps: 0.1,
                },
                Compass::None,
            ] {
                for near in [
                    None,
                    Some(Near {
                        at: (p.x, p.y),
                        radius: 3.0,
                    }),
                ] {
                    let (fast, evals) = loc.rank(&scan, &compass, near, 10);
                    let (slow, all) = loc.rank_linear(&scan, &compass, near, 10);
                    assert!(
                        same_ranking(&fast, &slow),
                        "pose {i}, {compass:?}, fov {}, near {near:?}",
                        sensor.fov
                    );
                    assert!(evals <= all.max(loc.sites().len()));
                    if let Some(n) = near {
                        for r in &fast {
                            let at = loc.sites()[r.site].at;
                            assert!((at.0 - n.at.0).hypot(at.1 - n.at.1) <= n.radius);
                        }
                    }
                    checked += 1;
                }
            }
        }
    }
    assert_eq!(checked, 12 * 4 * 3 * 2);
}

#[test]
fn a_query_capped_below_the_build_ranks_as_a_localizer_built_at_that_range() {
    // Built uncapped and queried with a 3 m scan, the PCFs are capped again
    // per query: the ranking must be the one of a localizer built at 3 m.
    let (map, uncapped) = office();
    let built = ScanLocalizer::new(
        &map,
        Options {
            max_range: Some(3.0),
            ..Options::default()
        },
    );
    let sensor = Sensor {
        max_range: Some(3.0),
        ..noisy()
    };
    let mut lost = 0;
    for (i, p) in eval::random_poses(&map, built.walls(), 8, 0.2, 23)
        .iter()
        .enumerate()
    {
        let scan = simulate(&map, &[], p, &sensor, i as u64).unwrap();
        lost += usize::from(scan.returns() < scan.ranges.len());
        for compass in [Compass::Exact(p.heading), Compass::None] {
            let (a, _) = uncapped.rank(&scan, &compass, None, 10);
            let (b, _) = built.rank(&scan, &compass, None, 10);
            assert!(same_ranking(&a, &b), "pose {i}, {compass:?}");
            let (x, y) = (
                uncapped.localize(&scan, &compass, None),
                built.localize(&scan, &compass, None),
            );
            assert_eq!(x.best, y.best, "pose {i}, {compass:?}");
        }
    }
    assert!(lost >= 4, "only {lost} scans lose beams");
}

#[test]
fn the_ranking_comparison_fails_on_a_planted_reordering() {
    let (map, loc) = office();
    let p = eval::random_poses(&map, loc.walls(), 1, 0.2, 2)[0];
    let scan = simulate(&map, &[], &p, &noisy(), 0).unwrap();
    let (slow, _) = loc.rank_linear(&scan, &Compass::None, None, 5);
    let mut planted = slow.clone();
    planted.swap(0, 1);
    assert!(!same_ranking(&planted, &slow));
    let mut off = slow.clone();
    off[2].pcm *= 1.01;
    assert!(!same_ranking(&off, &slow));
}

#[test]
fn the_parseval_bound_never_exceeds_the_pcm_under_any_rotation() {
    let (map, loc) = office();
    let plans = Plans::new(720);
    let walls = loc.walls();
    let poses = eval::random_poses(&map, walls, 6, 0.2, 4);
    let mut pairs = 0;
    for (i, p) in poses.iter().enumerate() {
        let scan = simulate(&map, &[], p, &noisy(), i as u64).unwrap();
        let s = ScanSignature::new(&scan, p.heading, f64::INFINITY, &plans);
        for site in loc.sites().iter().step_by(7) {
            let v = Signature::of_point(walls, site.at, f64::INFINITY, &plans);
            let bound = s.lower_bound(&v).expect("a full scan has a bound");
            let (pcm, _) = s.min_over_rotations(&v, None, &plans);
            assert!(
                bound <= pcm * (1.0 + wai_scan::signature::BOUND_SLACK) + 1e-6,
                "bound {bound} > pcm {pcm}"
            );
            pairs += 1;
        }
    }
    assert!(pairs > 100, "{pairs}");
    // A masked scan has no bound (the ranking takes the MBT path).
    let half = Sensor { fov: PI, ..noisy() };
    let scan = simulate(&map, &[], &poses[0], &half, 0).unwrap();
    let s = ScanSignature::new(&scan, 0.0, f64::INFINITY, &plans);
    let v = Signature::of_point(walls, loc.sites()[0].at, f64::INFINITY, &plans);
    assert!(s.lower_bound(&v).is_none());
}

#[test]
fn the_skeleton_distance_is_a_metric_on_the_sites() {
    // The MBT (sec. 6.4) needs the triangle inequality of D (eq. 6.1).
    let (_, loc) = office();
    let plans = Plans::new(720);
    let sigs: Vec<Signature> = loc
        .sites()
        .iter()
        .step_by(37)
        .map(|s| Signature::of_point(loc.walls(), s.at, f64::INFINITY, &plans))
        .collect();
    let mut triples = 0;
    for a in &sigs {
        assert_eq!(a.distance(a), 0.0);
        for b in &sigs {
            assert!((a.distance(b) - b.distance(a)).abs() < 1e-9);
            for c in sigs.iter().take(10) {
                assert!(a.distance(c) <= a.distance(b) + b.distance(c) + 1e-6);
                triples += 1;
            }
        }
    }
    assert!(triples > 1000, "{triples}");
}

#[test]
fn a_noiseless_scan_from_a_site_ranks_that_site_first() {
    let (map, loc) = office();
    let mut checked = 0;
    for (k, site) in loc.sites().iter().enumerate().step_by(97) {
        let p = Pose {
            x: site.at.0,
            y: site.at.1,
            heading: 0.7,
        };
        if p.check_inside(&map).is_err() {
            continue;
        }
        let scan = simulate(&map, &[], &p, &Sensor::default(), 0).unwrap();
        let (ranked, _) = loc.rank(&scan, &Compass::Exact(0.7), None, 3);
        let first = loc.sites()[ranked[0].site].at;
        // Another site may stand at the same spot (a lattice point on a
        // centre); the first one ranked is at the robot's place.
        assert!(
            (first.0 - p.x).hypot(first.1 - p.y) < 0.05,
            "site {k} at {:?}: first {first:?}",
            site.at
        );
        checked += 1;
    }
    assert!(checked >= 5, "{checked}");
}

#[test]
fn icp_pulls_a_start_half_a_metre_and_ten_degrees_off_onto_the_truth() {
    let (map, loc) = office();
    let poses = eval::random_poses(&map, loc.walls(), 10, 0.5, 8);
    let opts = wai_scan::icp::IcpOptions::default();
    let mut within = 0;
    for (i, truth) in poses.iter().enumerate() {
        let scan = simulate(&map, &[], truth, &noisy(), i as u64).unwrap();
        let a = 0.7 * i as f64;
        let start = Pose {
            x: truth.x + 0.5 * a.cos(),
            y: truth.y + 0.5 * a.sin(),
            heading: truth.heading + 10f64.to_radians(),
        };
        let got = icp::refine(loc.walls(), &scan.points(), start, &opts);
        if eval::STRICT.accepts(&got, truth) {
            within += 1;
        }
        let s_truth = icp::score(loc.walls(), &scan, truth, f64::INFINITY, 0.2);
        let s_start = icp::score(loc.walls(), &scan, &start, f64::INFINITY, 0.2);
        // Noise σ = 2 cm scores about σ² = 4e-4 at the truth.
        assert!(s_truth < 1e-3, "{s_truth}");
        assert!(s_start > 5.0 * s_truth, "{s_start} vs {s_truth}");
    }
    // Starts can land in a doorway's other room; most must not.
    assert!(within >= 8, "{within} of 10 within 0.1 m / 2°");
}

#[test]
fn the_localizer_finds_poses_in_an_office_with_and_without_compass() {
    let (map, loc) = office();
    let poses = eval::random_poses(&map, loc.walls(), 20, 0.2, 21);
    for mode in [CompassMode::Exact, CompassMode::None] {
        let trials = eval::trials(&map, &poses, &Condition::base(), mode, 9).unwrap();
        let outs: Vec<Outcome> = trials
            .iter()
            .map(|t| Outcome::of(&loc.localize(&t.scan, &t.compass, None), 0.0))
            .collect();
        let s = eval::summarise(&trials, &outs);
        assert!(s.success_rate >= 0.95, "{mode:?}: {}", s.success_rate);
        assert!(s.answer_set_contains_truth_rate >= s.success_rate);
    }
}

#[test]
fn the_answer_set_in_identical_rooms_holds_the_truth_and_every_look_alike() {
    let rooms = 3;
    let map = wai_gen::repeated_rooms(rooms);
    let loc = ScanLocalizer::new(&map, Options::default());
    // Poses in the middle room, away from its door.
    let mut full = 0;
    let mut counts = vec![];
    for (i, (x, y)) in [(7.0, 4.5), (8.5, 5.5), (9.2, 3.0)].into_iter().enumerate() {
        let truth = Pose {
            x,
            y,
            heading: 0.4 * i as f64,
        };
        let scan = simulate(&map, &[], &truth, &noisy(), i as u64).unwrap();
        let answer = loc.localize(&scan, &Compass::Exact(truth.heading), None);
        let twins = eval::room_twins(&truth, rooms as usize, 5.0, 1.0, 2.2);
        assert_eq!(twins.len(), 2);
        let alikes: Vec<Pose> = twins
            .into_iter()
            .filter(|q| eval::indistinguishable(loc.walls(), &truth, q, &scan.angles, None))
            .collect();
        counts.push(alikes.len());
        let holds = |p: &Pose| {
            answer
                .answer_set
                .iter()
                .any(|h| eval::NORMAL.accepts(&h.pose, p))
        };
        assert!(
            holds(&truth),
            "truth {truth:?} not in {:?}",
            answer.answer_set
        );
        if alikes.iter().all(holds) {
            full += 1;
        }
        // The planted check: without its look-alikes the set fails.
        let only_best: Vec<Pose> = answer.best.iter().map(|h| h.pose).collect();
        assert!(!alikes
            .iter()
            .chain([&truth])
            .all(|p| only_best.iter().any(|b| eval::NORMAL.accepts(b, p))));
    }
    assert_eq!(full, 3, "every look-alike answered");
    // Deep in the room both twins look alike; near the door, only the twin
    // whose corridor ends as far away does.
    assert_eq!(counts, vec![2, 2, 1]);
}

#[test]
fn room_twins_are_the_same_pose_in_the_other_rooms() {
    let p = Pose {
        x: 7.3,
        y: 4.0,
        heading: 1.0,
    };
    let xs: Vec<f64> = eval::room_twins(&p, 4, 5.0, 1.0, 2.2)
        .iter()
        .map(|q| q.x)
        .collect();
    assert_eq!(xs.len(), 3);
    for want in [2.3, 12.3, 17.3] {
        assert!(xs.iter().any(|x| (x - want).abs() < 1e-12), "{xs:?}");
    }
    let corridor = Pose { y: 1.0, ..p };
    assert!(eval::room_twins(&corridor, 4, 5.0, 1.0, 2.2).is_empty());
}

#[test]
fn identical_rooms_have_identical_scans() {
    let map = wai_gen::repeated_rooms(4);
    let walls = walls_of(&map);
    // From the same spot of rooms 1 and 2, the room's own walls give the
    // same ranges for every beam that does not leave through the door.
    for (x, y, a) in [(2.0, 5.0, 0.3), (4.0, 3.0, 2.0), (3.3, 5.9, -1.2)] {
        let p = Pose { x, y, heading: a };
        let q = Pose { x: x + 5.0, ..p };
        let r = Pose { x: x + 10.0, ..p };
        for k in 0..72 {
            let b = TAU * f64::from(k) / 72.0;
            let up = (a + b).sin() > 0.0;
            if up {
                let (rp, rq, rr) = (walls.range(&p, b), walls.range(&q, b), walls.range(&r, b));
                assert!((rp - rq).abs() < 1e-9 && (rq - rr).abs() < 1e-9);
            }
        }
    }
    assert_eq!(
        map.n(),
        4 + 8 * 4,
        "a corridor and four rooms of 8 vertices"
    );
}

#[test]
fn offices_are_seeded_valid_and_of_thousands_of_cells() {
    let a = wai_gen::office(3, 5);
    assert_eq!(a.vertices(), wai_gen::office(3, 5).vertices());
    assert_ne!(a.vertices(), wai_gen::office(3, 6).vertices());
    assert!(a.is_orthogonal());
    // Decimetres, scale 10: input units are metres.
    assert_eq!(a.scale().to_f64(), 10.0);
    let loc = ScanLocalizer::new(&a, Options::default());
    assert!(loc.cells().len() > 500, "{}", loc.cells().len());
}

#[test]
fn units_become_metres() {
    let square = |s: i128| {
        Map::from_ring(vec![
            Point::new(0, 0),
            Point::new(s, 0),
            Point::new(s, s),
            Point::new(0, s),
        ])
        .unwrap()
        .0
    };
    let width = |m: &Map| {
        let (lo, hi) = m.bounding_box();
        (hi.x - lo.x) as f64 / m.scale().to_f64()
    };
    let px = to_metres(&square(400), Units::Scale(0.025)).unwrap();
    assert_eq!(width(&px), 10.0, "400 px = 10 m");
    assert_eq!(width(&to_metres(&square(7), Units::Metres).unwrap()), 7.0);
    // 0.001° of latitude is 111.195 m on the mean-radius sphere; of
    // longitude at latitude 56.46° (Dundee) cos(56.46°) times that.
    let deg = Map::from_scaled_ring(
        vec![
            Point::new(-2_970_000, 56_460_000),
            Point::new(-2_969_000, 56_460_000),
            Point::new(-2_969_000, 56_461_000),
            Point::new(-2_970_000, 56_461_000),
        ],
        rug::Integer::from(1_000_000),
    )
    .unwrap()
    .0;
    let ll = to_metres(&deg, Units::LonLatDegrees).unwrap();
    let (lo, hi) = ll.bounding_box();
    let s = ll.scale().to_f64();
    let (w, h) = ((hi.x - lo.x) as f64 / s, (hi.y - lo.y) as f64 / s);
    assert!((h - 111.195).abs() < 0.002, "{h}");
    assert!(
        (w - 111.195 * 56.46f64.to_radians().cos()).abs() < 0.002,
        "{w}"
    );
}

#[test]
fn trials_are_seeded_and_the_same_scans_for_every_compass() {
    let map = wai_gen::office(1, 2);
    let walls = walls_of(&map);
    let poses = eval::random_poses(&map, &walls, 5, 0.2, 1);
    assert_eq!(poses.len(), 5);
    for p in &poses {
        assert!(walls.nearest((p.x, p.y), 0.2).is_none());
    }
    let c = &Condition::standard()[1];
    let a = eval::trials(&map, &poses, c, CompassMode::Exact, 3).unwrap();
    let b = eval::trials(&map, &poses, c, CompassMode::None, 3).unwrap();
    let n = eval::trials(&map, &poses, c, CompassMode::Noisy(0.1), 3).unwrap();
    for ((x, y), z) in a.iter().zip(&b).zip(&n) {
        assert_eq!(x.scan, y.scan);
        assert_eq!(x.scan, z.scan);
        assert_eq!(x.obstacles.len(), 5);
        assert_eq!(x.compass, Compass::Exact(x.truth.heading));
        assert_eq!(y.compass, Compass::None);
        match z.compass {
            Compass::Noisy { heading, eps } => {
                assert_eq!(eps, 0.1);
                assert!((heading - z.truth.heading).abs() <= 0.1);
            }
            other => panic!("{other:?}"),
        }
    }
    // Another compass's readings without simulating again: the same trials.
    for (from, to) in [(&a, &n), (&n, &b), (&b, &a)] {
        let mode = match to[0].compass {
            Compass::Exact(_) => CompassMode::Exact,
            Compass::None => CompassMode::None,
            Compass::Noisy { .. } => CompassMode::Noisy(0.1),
        };
        let swapped = eval::with_compass(from, mode, 3);
        for (x, y) in swapped.iter().zip(to) {
            assert_eq!((x.truth, &x.scan, x.compass), (y.truth, &y.scan, y.compass));
        }
    }
    let again = eval::trials(&map, &poses[..2], c, CompassMode::Exact, 3).unwrap();
    assert_eq!(
        again[1].scan, a[1].scan,
        "a trial does not depend on the others"
    );
    assert_ne!(
        eval::trials(&map, &poses, c, CompassMode::Exact, 4).unwrap()[0].scan,
        a[0].scan
    );
}

#[test]
fn compass_modes_parse_and_refuse_nonsense() {
    assert_eq!(CompassMode::parse("exact"), Ok(CompassMode::Exact));
    assert_eq!(CompassMode::parse("none"), Ok(CompassMode::None));
    assert_eq!(
        CompassMode::parse("noisy:10"),
        Ok(CompassMode::Noisy(10f64.to_radians()))
    );
    for bad in ["noisy:", "noisy:-1", "noisy:nan", "noisy:200", "north", ""] {
        assert!(CompassMode::parse(bad).is_err(), "{bad}");
    }
}

#[test]
fn the_summary_counts_what_it_is_given() {
    let truth = Pose {
        x: 0.0,
        y: 0.0,
        heading: 0.0,
    };
    let trial = |t: Pose| Trial {
        truth: t,
        obstacles: vec![],
        scan: wai_scan::Scan {
            angles: vec![0.0],
            ranges: vec![Some(1.0)],
            max_range: None,
        },
        compass: Compass::None,
    };
    let at = |x: f64, deg: f64| Pose {
        x,
        y: 0.0,
        heading: deg.to_radians(),
    };
    let trials: Vec<Trial> = (0..4).map(|_| trial(truth)).collect();
    let outs = vec![
        // strict success
        Outcome {
            best: Some(at(0.05, 1.0)),
            set: vec![at(0.05, 1.0)],
            ms: 1.0,
        },
        // success, not strict
        Outcome {
            best: Some(at(0.3, 5.0)),
            set: vec![at(0.3, 5.0)],
            ms: 2.0,
        },
        // loose only; the set holds the truth
        Outcome {
            best: Some(at(0.8, 20.0)),
            set: vec![at(0.8, 20.0), at(0.0, 0.0)],
            ms: 3.0,
        },
        // nothing
        Outcome {
            best: None,
            set: vec![],
            ms: 10.0,
        },
    ];
    let s = eval::summarise(&trials, &outs);
    assert_eq!(s.queries, 4);
    assert_eq!(s.success_rate_strict, 0.25);
    assert_eq!(s.success_rate, 0.5);
    assert_eq!(s.success_rate_loose, 0.75);
    assert_eq!(s.answer_set_contains_truth_rate, 0.75);
    assert_eq!(s.mean_answer_set_size, 1.0);
    assert_eq!(s.median_ms, 2.0);
    assert_eq!(s.p90_ms, 10.0);
    assert!(s.position_errors[3].is_infinite());
    let j = s.to_json();
    for key in [
        "success_rate",
        "success_rate_strict",
        "success_rate_loose",
        "answer_set_contains_truth_rate",
        "median_ms",
    ] {
        assert!(j.get(key).is_some(), "{key}");
    }
    assert!(eval::quantile(&[], 0.5).is_nan());
    let svg = eval::cdf_svg(
        "t <1>",
        "m",
        eval::CdfAxis::Auto,
        &[("ours".into(), &s.position_errors)],
    );
    assert!(svg.starts_with("<svg") && svg.contains("t &lt;1&gt;") && svg.contains("polyline"));
}

/// The x tick labels of a CDF plot: (x, text), left to right.
fn x_ticks(svg: &str) -> Vec<(f64, String)> {
    svg.split(r#"<text class="x-tick" x=""#)
        .skip(1)
        .map(|t| {
            let x = t[..t.find('"').unwrap()].parse().unwrap();
            let t = &t[t.find('>').unwrap() + 1..];
            (x, t[..t.find("</text>").unwrap()].to_string())
        })
        .collect()
}

/// The value of attribute `name` at or after `from` in `svg`.
fn attr_after(svg: &str, from: &str, name: &str) -> f64 {
    let s = &svg[svg.find(from).unwrap()..];
    let i = s.find(&format!(" {name}=\"")).unwrap() + name.len() + 3;
    s[i..i + s[i..].find('"').unwrap()].parse().unwrap()
}

#[test]
fn cdf_plots_fit_their_axis_to_the_data_and_keep_labels_apart() {
    let small: Vec<f64> = (1..=200).map(|k| f64::from(k) * 0.0000685).collect();
    let wide: Vec<f64> = (1..=200).map(|k| f64::from(k) * 6.17).collect();
    let mut mixed: Vec<f64> = (1..=100).map(|k| f64::from(k) * 0.00003).collect();
    mixed.extend([5.0, 10.0, 15.0, f64::INFINITY]);
    for (values, axis, note) in [
        (&small, eval::CdfAxis::Auto, "x axis fitted"),
        (&wide, eval::CdfAxis::Auto, "x axis fitted"),
        (&wide, eval::CdfAxis::Fixed(1234.5), "x axis fixed"),
        (&mixed, eval::CdfAxis::Auto, "log x axis"),
        (&small, eval::CdfAxis::Log, "log x axis"),
    ] {
        let names = ["a series with a long name", "another", "a third"];
        let series: Vec<(String, &[f64])> = names
            .iter()
            .map(|n| (n.to_string(), values.as_slice()))
            .collect();
        let svg = eval::cdf_svg("A plot", "error (m)", axis, &series);
        assert!(svg.contains(note), "{note}: {svg}");
        let ticks = x_ticks(&svg);
        assert!(ticks.len() >= 3, "{ticks:?}");
        // Neighbouring labels (12 px text, at most 7 px a character) leave
        // a gap.
        for w in ticks.windows(2) {
            let half = |t: &str| t.chars().count() as f64 * 7.0 / 2.0;
            assert!(
                w[1].0 - w[0].0 >= half(&w[0].1) + half(&w[1].1) + 4.0,
                "{:?} and {:?} overlap",
                w[0],
                w[1]
            );
        }
        // The legend is right of the plot area and inside the picture.
        let plot_right = attr_after(&svg, r#"<rect x="64""#, "width") + 64.0;
        let lx = attr_after(&svg, r#"<g class="legend""#, "x");
        let lw = attr_after(&svg, r#"<g class="legend""#, "width");
        let width = attr_after(&svg, "<svg", "width");
        assert!(lx > plot_right && lx + lw <= width, "{lx} {lw} {width}");
        for n in names {
            assert!(svg.contains(&format!(">{n}")), "{n}");
        }
    }
    // The fitted axis ends at the 99th percentile rounded up: 0.0137 → 0.02.
    let svg = eval::cdf_svg("t", "m", eval::CdfAxis::Auto, &[("s".into(), &small)]);
    assert_eq!(x_ticks(&svg).last().unwrap().1, "0.020");
}

#[test]
fn the_sampled_pcm_agrees_with_the_closed_form_on_exact_visibility_polygons() {
    // The localizer's signatures sample the PCF at 720 angles (signature.rs);
    // eq. 6.7 in closed form (pcm.rs) on the exact V_p is the reference.
    use wai_exact::RatPoint;
    use wai_scan::pcm::pcm_fixed;
    use wai_scan::polar::StarPolygon;
    let (map, loc) = office();
    let index = wai_visibility::VisibilityIndex::new(&map);
    let plans = Plans::new(720);
    let scale = map.scale().clone();
    let pcf_at = |at: (f64, f64)| {
        let exact = |v: f64| rug::Rational::from_f64(v).unwrap() * &scale;
        let p = RatPoint::from_rationals(exact(at.0), exact(at.1));
        let vp = index.visibility_polygon(&p).expect("an interior site");
        let pts: Vec<(f64, f64)> = vp
            .points()
            .iter()
            .map(|q| wai_scan::sites::to_f64(q, &scale))
            .collect();
        StarPolygon::new(at, pts)
            .expect("V_p is star-shaped from p")
            .pcf()
    };
    let sites: Vec<(f64, f64)> = loc.sites().iter().step_by(53).map(|s| s.at).collect();
    let pcfs: Vec<_> = sites.iter().map(|&a| pcf_at(a)).collect();
    let sigs: Vec<Signature> = sites
        .iter()
        .map(|&a| Signature::of_point(loc.walls(), a, f64::INFINITY, &plans))
        .collect();
    let mut pairs = 0;
    let mut worst: f64 = 0.0;
    for i in 0..sites.len() {
        for j in (i + 1)..sites.len().min(i + 6) {
            let exact = pcm_fixed(&pcfs[i], &pcfs[j], 0.0);
            let sampled = sigs[i].distance(&sigs[j]);
            let rel = (sampled - exact).abs() / exact.max(1e-9);
            worst = worst.max(rel);
            pairs += 1;
        }
    }
    assert!(pairs >= 40, "{pairs}");
    // Sampling a PCF with jumps at 0.5° steps: 0.9 % measured.
    assert!(worst < 0.02, "worst relative difference {worst}");
}

/// A long preprocessing shows where it is: the decomposition over its
/// cells, the signatures over the sites, the tree, each ending complete.
#[test]
fn preprocessing_reports_its_stages_to_the_end() {
    use std::sync::Mutex;
    let map = wai_gen::office(2, 3);
    let seen: Mutex<Vec<(String, usize, usize)>> = Mutex::new(Vec::new());
    let loc =
        ScanLocalizer::try_new_with_progress(&map, Options::default(), &|stage, done, total| {
            seen.lock().unwrap().push((stage.to_owned(), done, total));
        })
        .expect("a small office fits");
    let seen = seen.into_inner().unwrap();
    for stage in ["cells", "signatures", "tree"] {
        let last = seen.iter().rev().find(|(s, _, _)| s == stage);
        let (_, done, total) = last.unwrap_or_else(|| panic!("no {stage} in {seen:?}"));
        assert!(done == total && *total > 0, "{stage}: {done} of {total}");
    }
    let first = |stage: &str| seen.iter().position(|(s, _, _)| s == stage).unwrap();
    assert!(first("cells") < first("signatures") && first("signatures") < first("tree"));
    assert!(loc.sites().len() >= loc.cells().len());
}
