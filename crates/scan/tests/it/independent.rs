//! Scans made outside the crate's simulator, as other tools write them: an
//! independent ray caster (its own intersection code, beam convention and
//! noise), written as files in both formats, with and without a stated
//! maximum range, read back through [`wai_scan::format`] and localized.
//!
//! What is checked: a scan that does not state its range localizes as well
//! as the same scan stating it (the lost beams read against the longest
//! return, and a warning says so); the ROS LaserScan form of a scan reads
//! to the same beams and answers the same; a loose stated range is caught.

use crate::caster::{cast, ros_file, wai_file, BEAMS};
use wai_scan::eval::{random_poses, NORMAL};
use wai_scan::format::{self, ScanFormat};
use wai_scan::range::RangeBasis;
use wai_scan::walls::Walls;
use wai_scan::{Compass, Options, Pose, ScanLocalizer};

struct Rates {
    queries: usize,
    success: usize,
    in_set: usize,
}

fn localize_all(
    loc: &ScanLocalizer,
    files: &[(Pose, String)],
    compass: impl Fn(&Pose) -> Compass,
) -> (Rates, Vec<wai_scan::ScanAnswer>) {
    let tol = NORMAL;
    let mut rates = Rates {
        queries: 0,
        success: 0,
        in_set: 0,
    };
    let mut answers = Vec::new();
    for (truth, text) in files {
        let file = format::read(text.as_bytes()).expect("a scan file");
        let a = loc.localize(&file.scan, &compass(truth), None);
        rates.queries += 1;
        rates.success += usize::from(a.best.as_ref().is_some_and(|b| tol.accepts(&b.pose, truth)));
        rates.in_set += usize::from(a.answer_set.iter().any(|h| tol.accepts(&h.pose, truth)));
        answers.push(a);
    }
    (rates, answers)
}

#[test]
fn scans_without_a_stated_range_localize_as_well_as_with_it_and_say_so() {
    // An office of two rows of 4 rooms with niches, seen by an 8 m sensor:
    // many poses have beams with no return.
    let map = wai_gen::office(4, 2);
    let walls = Walls::new(wai_scan::peer::map_walls(&map));
    let loc = ScanLocalizer::new(&map, Options::default());
    let poses = random_poses(&map, &walls, 24, 0.2, 17);
    let range = 8.0;
    let (mut stated, mut unstated) = (Vec::new(), Vec::new());
    let mut lost = 0;
    for (k, p) in poses.iter().enumerate() {
        let ranges = cast(&map, p, range, k as u64);
        lost += usize::from(ranges.iter().any(Option::is_none));
        stated.push((*p, wai_file(&ranges, Some(range), None)));
        unstated.push((*p, wai_file(&ranges, None, None)));
    }
    assert!(lost >= poses.len() / 3, "only {lost} scans have lost beams");
    let compass = |p: &Pose| Compass::Exact(p.heading);
    let (with, _) = localize_all(&loc, &stated, compass);
    let (without, answers) = localize_all(&loc, &unstated, compass);
    eprintln!(
        "{} queries: range stated {} right, {} in the answer set; not stated {} right, {} in the set",
        with.queries, with.success, with.in_set, without.success, without.in_set
    );
    assert!(
        with.success + 1 >= with.queries,
        "stated: {} of {}",
        with.success,
        with.queries
    );
    assert!(
        without.success + 1 >= with.success,
        "{} vs {}",
        without.success,
        with.success
    );
    assert!(
        without.in_set + 1 >= with.in_set,
        "{} vs {}",
        without.in_set,
        with.in_set
    );
    // Every unstated scan with lost beams was read against its longest
    // return and warns; the stated ones do not.
    for (a, (_, text)) in answers.iter().zip(&unstated) {
        let file = format::read(text.as_bytes()).unwrap();
        let has_lost = file.scan.ranges.iter().any(Option::is_none);
        assert_eq!(a.range.basis == RangeBasis::LongestReturn, has_lost);
        assert_eq!(!a.range.warnings().is_empty(), has_lost, "{:?}", a.range);
    }
}

#[test]
fn the_ros_form_of_a_scan_reads_to_the_same_beams_and_answers_the_same() {
    let map = wai_gen::repeated_rooms(4);
    let walls = Walls::new(wai_scan::peer::map_walls(&map));
    let loc = ScanLocalizer::new(&map, Options::default());
    let range = 8.0;
    for (k, p) in random_poses(&map, &walls, 4, 0.2, 3).iter().enumerate() {
        let ranges = cast(&map, p, range, 100 + k as u64);
        let ours = format::read(wai_file(&ranges, Some(range), None).as_bytes()).unwrap();
        let ros = format::read(ros_file(&ranges, range).as_bytes()).unwrap();
        assert_eq!(
            (ours.format, ros.format),
            (ScanFormat::Wai, ScanFormat::RosLaserScan)
        );
        assert_eq!(ros.scan.max_range, Some(range));
        assert_eq!(ros.beams_in_file, BEAMS);
        // Beam by beam: the same angle (ROS counts from angle_min) and the
        // same reading; a value above range_max is no return.
        assert!(
            ros.scan.ranges == ours.scan.ranges,
            "pose {k}: the readings differ"
        );
        for (a, b) in ros.scan.angles.iter().zip(&ours.scan.angles) {
            assert!((a - b).abs() < 1e-12);
        }
        let above = (0..BEAMS).filter(|i| ranges[*i].is_none() && i % 5 == 0);
        assert_eq!(ros.beyond_max, above.count());
        let c = Compass::None;
        let (x, y) = (
            loc.localize(&ours.scan, &c, None),
            loc.localize(&ros.scan, &c, None),
        );
        assert_eq!(x.best, y.best, "pose {k}");
        assert_eq!(x.answer_set, y.answer_set, "pose {k}");
    }
}

#[test]
fn ros_readings_are_read_by_the_ros_rules() {
    // NaN and a value below range_min are discarded, -Inf (too close)
    // too; +Inf, "inf", null and a value above range_max are no return.
    let text = r#"{"op": "publish", "topic": "/scan", "msg": {"angle_min": -1.0,
        "angle_max": 1.0, "angle_increment": 0.25, "range_min": 0.1, "range_max": 5.0,
        "ranges": [1.0, NaN, 0.05, -Infinity, Infinity, "inf", null, 7.5, 2.0]}}"#;
    let f = format::read(text.as_bytes()).unwrap();
    assert_eq!(f.format, ScanFormat::RosLaserScan);
    assert_eq!(f.beams_in_file, 9);
    assert_eq!(
        (
            f.discarded.invalid,
            f.discarded.below_min,
            f.discarded.too_close
        ),
        (1, 1, 1)
    );
    assert_eq!(f.beyond_max, 1);
    assert_eq!(
        f.scan.ranges,
        vec![Some(1.0), None, None, None, None, Some(2.0)]
    );
    assert_eq!(f.scan.angles, vec![-1.0, 0.0, 0.25, 0.5, 0.75, 1.0]);
    assert!(f.describe().contains("3 discarded"), "{}", f.describe());
    // Refused with the reason: a header that disagrees with the ranges, no
    // increment, a negative range, more than a turn of beams.
    for (bad, why) in [
        (
            r#"{"angle_min": 0, "angle_max": 3, "angle_increment": 0.1, "ranges": [1, 1]}"#,
            "angle_max",
        ),
        (
            r#"{"angle_min": 0, "angle_increment": 0, "ranges": [1, 1]}"#,
            "angle_increment is 0",
        ),
        (
            r#"{"angle_min": 0, "angle_increment": 0.1, "ranges": [1, -1]}"#,
            "ranges[1] = -1 is negative",
        ),
        (
            r#"{"angle_min": 0, "angle_increment": 1, "ranges": [1, 1, 1, 1, 1, 1, 1]}"#,
            "full turn",
        ),
        (
            r#"{"angle_min": 0, "angle_increment": 0.1, "range_min": 2, "range_max": 1, "ranges": [1]}"#,
            "not below",
        ),
        (r#"{"ranges": [1]}"#, "neither"),
        (r#"{"angles": [0, 1], "ranges": [1, "far"]}"#, "ranges[1]"),
    ] {
        let e = format::read(bad.as_bytes()).unwrap_err();
        assert!(e.contains(why), "{bad}: {e}");
    }
}

#[test]
fn a_loose_stated_range_is_caught_and_the_scan_read_by_its_returns() {
    // The sensor loses every return beyond 6 m but its file states 30 m, as
    // ROS drivers state their nominal range: read as stated, the lost beams
    // would charge the true pose for every wall between 6 and 30 m.
    let map = wai_gen::repeated_rooms(6);
    let walls = Walls::new(wai_scan::peer::map_walls(&map));
    let loc = ScanLocalizer::new(&map, Options::default());
    let tol = NORMAL;
    let mut caught = 0;
    let poses = random_poses(&map, &walls, 12, 0.2, 29);
    for (k, p) in poses.iter().enumerate() {
        let ranges = cast(&map, p, 6.0, 300 + k as u64);
        if ranges.iter().filter(|r| r.is_none()).count() < 20 {
            continue;
        }
        let file = format::read(wai_file(&ranges, Some(30.0), None).as_bytes()).unwrap();
        let a = loc.localize(&file.scan, &Compass::Exact(p.heading), None);
        if a.range.basis == RangeBasis::LooseStatement {
            caught += 1;
            assert!(a.range.cap < 6.1, "{:?}", a.range);
            let w = a.range.warnings().join(" ");
            assert!(w.contains("looks loose"), "{w}");
            // Rooms 6 m deep look alike: the truth is one of the answers.
            assert!(
                a.answer_set.iter().any(|h| tol.accepts(&h.pose, p)),
                "pose {k}: {p:?} not among {:?}",
                a.answer_set.iter().map(|h| h.pose).collect::<Vec<_>>()
            );
        }
    }
    assert!(caught >= 4, "caught {caught}");
}

#[test]
fn a_stated_range_that_holds_is_kept() {
    let map = wai_gen::repeated_rooms(6);
    let walls = Walls::new(wai_scan::peer::map_walls(&map));
    let loc = ScanLocalizer::new(&map, Options::default());
    for (k, p) in random_poses(&map, &walls, 8, 0.2, 41).iter().enumerate() {
        let ranges = cast(&map, p, 10.0, 500 + k as u64);
        let file = format::read(wai_file(&ranges, Some(10.0), None).as_bytes()).unwrap();
        let a = loc.localize(&file.scan, &Compass::Exact(p.heading), None);
        let lost = ranges.iter().any(Option::is_none);
        let want = if lost {
            RangeBasis::Stated
        } else {
            RangeBasis::NotNeeded
        };
        assert_eq!(a.range.basis, want, "pose {k}");
        assert!(a.range.warnings().is_empty(), "{:?}", a.range.warnings());
    }
}

#[test]
fn dropped_beams_leave_a_masked_gap_and_the_rest_still_matches() {
    use wai_scan::signature::{Plans, ScanSignature, Signature};
    let map = wai_gen::office(2, 3);
    let walls = Walls::new(wai_scan::peer::map_walls(&map));
    let plans = Plans::new(720);
    let p = random_poses(&map, &walls, 1, 0.2, 5)[0];
    let full = wai_scan::simulate(&map, &[], &p, &wai_scan::Sensor::default(), 0).unwrap();
    let truth = Signature::of_point(&walls, (p.x, p.y), f64::INFINITY, &plans);
    let whole = ScanSignature::new(&full, p.heading, f64::INFINITY, &plans);
    assert!(whole.mask.iter().all(|w| *w == 1.0));
    // Ten beams (5°) discarded: the samples between the beams either side
    // of the gap are masked — ten or eleven of the 0.5° samples — and
    // nothing else.
    let mut gap = full.clone();
    gap.angles.drain(100..110);
    gap.ranges.drain(100..110);
    let s = ScanSignature::new(&gap, p.heading, f64::INFINITY, &plans);
    let masked = s.mask.iter().filter(|w| **w == 0.0).count();
    assert!((10..=11).contains(&masked), "{masked} samples masked");
    assert!(
        s.lower_bound(&truth).is_none(),
        "a masked scan has no full-circle bound"
    );
    // V_S cuts corners between beams; the gap adds nothing to that.
    let base = whole.distance(&truth);
    assert!(
        s.distance(&truth) <= base + 1e-9,
        "{} > {base}",
        s.distance(&truth)
    );
    // A lost beam read against no range at all masks its two segments
    // rather than reading infinity.
    let mut lost = full.clone();
    lost.ranges[300] = None;
    let s = ScanSignature::new(&lost, p.heading, f64::INFINITY, &plans);
    let masked = s.mask.iter().filter(|w| **w == 0.0).count();
    assert!((1..=2).contains(&masked), "{masked} samples masked");
    assert!(s.values.iter().all(|v| v.is_finite()));
    // A planted wrong range is seen: the checker can fail.
    let mut wrong = full.clone();
    wrong.ranges[300] = wrong.ranges[300].map(|r| r + 5.0);
    let s = ScanSignature::new(&wrong, p.heading, f64::INFINITY, &plans);
    assert!(s.distance(&truth) > base + 0.1, "{}", s.distance(&truth));
}

#[test]
fn when_the_range_would_decide_between_answers_the_answer_says_which() {
    // Identical rooms off a corridor, a 6 m sensor that does not state its
    // range: from a room, the look-alike rooms differ only down the
    // corridor, beyond the longest return.
    let map = wai_gen::repeated_rooms(6);
    let walls = Walls::new(wai_scan::peer::map_walls(&map));
    let loc = ScanLocalizer::new(&map, Options::default());
    let mut decided = 0;
    for (k, p) in random_poses(&map, &walls, 16, 0.2, 61).iter().enumerate() {
        let ranges = cast(&map, p, 6.0, 700 + k as u64);
        let file = format::read(wai_file(&ranges, None, None).as_bytes()).unwrap();
        let a = loc.localize(&file.scan, &Compass::Exact(p.heading), None);
        if a.range.lost == 0 {
            assert!(a.answer_set.iter().all(|h| h.clear_to == f64::INFINITY));
            continue;
        }
        // Every answer is clear at least to the range read (up to τ), and
        // the truth's beams without return are clear beyond 6 m (noise).
        for h in &a.answer_set {
            assert!(
                h.clear_to > a.range.cap - 0.25,
                "{} < {}",
                h.clear_to,
                a.range.cap
            );
            if NORMAL.accepts(&h.pose, p) {
                assert!(h.clear_to > 5.9, "truth clear to {}", h.clear_to);
            }
        }
        let w = a.warnings().join(" ");
        let spread = a.answer_set.iter().map(|h| h.clear_to).fold(0.0, f64::max)
            - a.answer_set
                .iter()
                .map(|h| h.clear_to)
                .fold(f64::INFINITY, f64::min);
        assert_eq!(w.contains("the range decides"), spread > 0.2, "{w}");
        decided += usize::from(spread > 0.2);
    }
    // Look-alike rooms differ nowhere within reach of their lost beams:
    // their beams without return are all clear to about the same range,
    // so no range would decide, and no answer says it would.
    assert_eq!(decided, 0);
    // Answers whose lost beams reach different distances: a known range
    // would tell them apart, and the answer says so, listing them.
    let answer_with = |clear: &[f64]| {
        let h = |c: f64| wai_scan::Hypothesis {
            pose: Pose {
                x: 0.0,
                y: 0.0,
                heading: 0.0,
            },
            score: 1e-4,
            from_site: 0,
            clear_to: c,
        };
        let mut range = wai_scan::range::SensingRange::of(&wai_scan::Scan {
            angles: vec![0.0, 1.0, 2.0, 3.0],
            ranges: vec![Some(5.6), None, Some(2.0), Some(3.0)],
            max_range: None,
        });
        range.lost = 1;
        wai_scan::ScanAnswer {
            ranked: Vec::new(),
            best: Some(h(clear[0])),
            answer_set: clear.iter().map(|&c| h(c)).collect(),
            evaluations: 0,
            range,
        }
    };
    let w = answer_with(&[12.0, 7.0]).warnings().join(" ");
    assert!(
        w.contains("the range decides between the 2 answers") && w.contains("12.00, 7.00 m"),
        "{w}"
    );
    let w = answer_with(&[6.0, 6.1]).warnings().join(" ");
    assert!(!w.contains("the range decides"), "{w}");
    assert!(w.contains("states no maximum range"), "{w}");
}
