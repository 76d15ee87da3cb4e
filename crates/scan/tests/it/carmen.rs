//! CARMEN logs: the message formats, gzip, the three real logs, and a map
//! built from scans cast in a known room with a pillar.

use crate::caster::{cast, relative_angles};
use std::io::Write;
use wai_scan::carmen::{read, CarmenError, CarmenLog, LogScan};
use wai_scan::log_map::{occupancy_grid, GridOptions};
use wai_scan::Pose;

fn flaser_line(n: usize, r: f64, pose: (f64, f64, f64)) -> String {
    let ranges: Vec<String> = (0..n).map(|_| format!("{r}")).collect();
    format!(
        "FLASER {n} {} {} {} {} {} {} {} 12.5 host 12.5",
        ranges.join(" "),
        pose.0,
        pose.1,
        pose.2,
        pose.0,
        pose.1,
        pose.2
    )
}

#[test]
fn the_messages_are_read_with_carmen_angles() {
    let text = format!(
        "# message formats defined: PARAM SYNC ODOM FLASER\nPARAM robot_front_laser_max 30.0 nohost 0\nODOM 1 2 0.5 0 0 0 3.25 host 3.25\n{}\nNEFF 15\nROBOTLASER1 0 -1.25 2.5 0.5 20.0 0.01 0 3 1.0 2.0 20.0 0 4 5 0.1 4 5 0.1 0 0 0 0 0 7.5 host 7.5\n",
        flaser_line(180, 2.0, (1.0, -2.0, 0.25))
    );
    let log = read(text.as_bytes()).unwrap();
    assert_eq!((log.scans.len(), log.odometry.len()), (2, 1));
    assert_eq!(log.skipped.get("NEFF"), Some(&1));
    assert_eq!(log.odometry[0].pose, [1.0, 2.0, 0.5]);
    let f = &log.scans[0];
    assert_eq!((f.line, f.pose, f.timestamp), (4, [1.0, -2.0, 0.25], 12.5));
    // 180 beams: CARMEN's 179° field of view in 1° steps, centred.
    let deg = std::f64::consts::PI / 180.0;
    assert!((f.angles[0] + 89.5 * deg).abs() < 1e-12 && (f.angles[179] - 89.5 * deg).abs() < 1e-12);
    let r = &log.scans[1];
    assert_eq!(
        (r.angles.len(), r.max_range, r.pose),
        (3, Some(20.0), [4.0, 5.0, 0.1])
    );
    assert!((r.angles[2] - (-1.25 + 1.0)).abs() < 1e-12);
    // No return: at or above the stated maximum.
    assert_eq!(log.no_return_at(f), Some(30.0));
    let scan = log.scan(1);
    assert_eq!(scan.ranges, vec![Some(1.0), Some(2.0), None]);
    assert_eq!(scan.max_range, Some(20.0));
    // The same log gzip-compressed.
    let mut gz = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::fast());
    gz.write_all(text.as_bytes()).unwrap();
    assert_eq!(read(&gz.finish().unwrap()).unwrap(), log);
}

#[test]
fn bad_lines_are_located() {
    let e = |t: &str| read(t.as_bytes()).unwrap_err().to_string();
    assert!(e("ODOM 1 2 0\nFLASER 3 1 2\n").contains("line 2: FLASER: range missing"));
    assert!(e("FLASER 2 1 x 0 0 0 0 0 0 1 h 1\n")
        .contains("line 1: FLASER: range \"x\" is not a number (field 3)"));
    assert!(e("FLASER 2 1 -1 0 0 0 0 0 0 1 h 1\n").contains("range -1 is negative"));
    assert!(e("FLASER 9999999 1\n").contains("more beams than any laser has"));
    assert!(e("FLASER 1 1 0 0 nan 0 0 0 1 h 1\n").contains("theta \"nan\" is not finite"));
    assert!(matches!(
        read(b"ODOM 1 2 3 0 0 0 1 h 1\n"),
        Err(CarmenError::NoScan)
    ));
    assert!(matches!(
        read(&[0x1f, 0x8b, 0, 1, 2]),
        Err(CarmenError::Gzip(_))
    ));
}

#[test]
fn the_three_real_logs() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../data/datasets/laser");
    for (name, scans, beams, no_return) in [
        ("intel-corrected.log.gz", 910, 180, 81.83),
        ("aces-corrected.log.gz", 440, 180, 50.0),
        ("freiburg-079-corrected.log.gz", 4791, 360, 80.99),
    ] {
        let path = dir.join(name);
        let log = read(&std::fs::read(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display())))
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!(log.scans.len(), scans, "{name}");
        assert!(log.scans.iter().all(|s| s.ranges.len() == beams), "{name}");
        assert_eq!(log.no_return_at(&log.scans[0]), Some(no_return), "{name}");
        let lost: usize = (0..scans)
            .map(|k| log.scan(k).ranges.iter().filter(|r| r.is_none()).count())
            .sum();
        assert!(lost > 0, "{name}: the no-return readings are found");
    }
}

#[test]
fn a_map_built_from_scans_finds_the_room_and_its_pillar() {
    // A 10 × 8 m room with a 2 × 2 m pillar at [4, 6] × [3, 5].
    let text = r#"{"outer": [["0","0"],["10","0"],["10","8"],["0","8"]], "holes": [[["4","3"],["4","5"],["6","5"],["6","3"]]]}"#;
    let room = wai_map::json::from_json(text.as_bytes()).unwrap().map;
    let mut log = CarmenLog::default();
    let mut k = 0;
    for x in [1.0, 2.5, 5.0, 7.5, 9.0] {
        for y in [1.0, 2.0, 6.0, 7.0] {
            let pose = Pose {
                x,
                y,
                heading: 0.3 * k as f64,
            };
            let ranges = cast(&room, &pose, 30.0, k);
            log.scans.push(LogScan {
                line: k as usize + 1,
                pose: [x, y, pose.heading],
                angles: relative_angles(),
                ranges: ranges.iter().map(|r| r.unwrap_or(40.0)).collect(),
                max_range: Some(40.0),
                timestamp: k as f64,
            });
            k += 1;
        }
    }
    let all: Vec<usize> = (0..log.scans.len()).collect();
    let options = GridOptions {
        resolution: wai_map::parse_exact("0.05").unwrap(),
        margin: 2,
    };
    let (meta, image) = occupancy_grid(&log, &all, &options);
    let import = wai_grid::ImportOptions {
        min_hole_area: wai_map::parse_exact("0.05").unwrap(),
        ..Default::default()
    };
    let (map, _) = wai_grid::import_parts(&meta, &image, &import).unwrap();
    assert_eq!(map.hole_count(), 1, "the pillar, and nothing else");
    let s = map.scale().to_f64();
    let area = map.area_twice().to_f64() / (2.0 * s * s);
    assert!((area - 76.0).abs() < 0.05 * 76.0, "area {area}");
    let hole = map.holes().next().unwrap();
    let xs = hole.iter().map(|p| p.x as f64 / s);
    let (lo, hi) = (
        xs.clone().fold(f64::MAX, f64::min),
        xs.fold(f64::MIN, f64::max),
    );
    assert!(
        (lo - 4.0).abs() <= 0.1 && (hi - 6.0).abs() <= 0.1,
        "pillar x from {lo} to {hi}"
    );
    let (blo, bhi) = map.bounding_box();
    assert!((blo.x as f64 / s).abs() <= 0.1 && (bhi.y as f64 / s - 8.0).abs() <= 0.1);
}
