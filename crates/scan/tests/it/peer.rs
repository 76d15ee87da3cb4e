//! The karto-scanmatcher peer (a separate GPL-3 process, wai_scan::peer):
//! a noiseless scan in a small L-shaped room is matched to its pose, a bad
//! message gets an error answer and the process goes on serving, and a
//! missing interpreter is reported as "not installed".
//!
//! Where the peer is not installed (`scripts/install-karto`, which
//! `scripts/bootstrap` tries), these tests say SKIPPED and check nothing;
//! in CI (`WAI_CI`, set by `.ci/run`) they fail instead.

use wai_exact::Point;
use wai_map::Map;
use wai_scan::eval::{errors, STRICT};
use wai_scan::peer::{map_walls, KartoConfig, KartoPeer, PeerError, INSTALL_HINT};
use wai_scan::{simulate, Pose, Sensor};

/// An L-shaped room in metres: an 8 × 3 m arm and a 3 × 6 m arm, so no
/// rotation maps it onto itself.
fn l_room() -> Map {
    let ring = [(0, 0), (8, 0), (8, 3), (3, 3), (3, 6), (0, 6)];
    Map::from_ring(ring.iter().map(|&(x, y)| Point::new(x, y)).collect())
        .expect("valid")
        .0
}

/// The peer holding `map`, or `None` (said loudly) where it is not
/// installed outside CI.
fn peer(map: &Map) -> Option<KartoPeer> {
    match KartoPeer::spawn(&map_walls(map), &KartoConfig::default()) {
        Ok(p) => Some(p),
        Err(e @ PeerError::NotInstalled { .. }) if std::env::var_os("WAI_CI").is_none() => {
            // Past the test harness's capture: a skip must be seen.
            use std::io::Write as _;
            let _ = writeln!(std::io::stderr(), "SKIPPED: {e} (CI requires the peer)");
            None
        }
        Err(e) => panic!(
            "the karto peer did not start: {e}\n(install it with scripts/install-karto, \
             which scripts/bootstrap runs)"
        ),
    }
}

fn scan_360(map: &Map, pose: &Pose) -> wai_scan::Scan {
    let sensor = Sensor {
        beams: 360,
        ..Sensor::default()
    };
    simulate(map, &[], pose, &sensor, 0).expect("inside")
}

#[test]
fn karto_finds_the_pose_of_a_noiseless_scan_in_an_l_room() {
    let map = l_room();
    let Some(mut karto) = peer(&map) else {
        return;
    };
    for truth in [
        Pose {
            x: 1.3,
            y: 4.2,
            heading: 0.7,
        },
        Pose {
            x: 6.1,
            y: 1.1,
            heading: -2.0,
        },
    ] {
        let got = karto
            .localize(&scan_360(&map, &truth), None)
            .expect("an answer");
        let (d, a) = errors(&got.pose, &truth);
        assert!(
            STRICT.accepts(&got.pose, &truth),
            "{truth:?}: karto says {:?}, off by {d:.3} m and {a:.2}°",
            got.pose
        );
        assert!(got.response > 0.9 && got.response <= 1.0, "{got:?}");
        assert!(got.ms > 0.0);
    }
}

#[test]
fn a_bad_message_gets_an_error_answer_and_the_peer_keeps_serving() {
    let map = l_room();
    let Some(mut karto) = peer(&map) else {
        return;
    };
    assert!(karto.build_ms() >= 0.0);
    assert!(karto.settings()["search_size"].as_f64().is_some());
    for bad in [
        "not json",
        "[1, 2]",
        r#"{"angles": [0.0, 1.0], "ranges": [1.0]}"#,
        r#"{"angles": [0.0, 0.5, 3.0], "ranges": [1.0, 1.0, 1.0]}"#,
        r#"{"angles": [0.0, 1.0], "ranges": [null, null]}"#,
    ] {
        let answer = karto.raw(bad).expect("an answer, not a death");
        assert!(answer["error"].is_string(), "{bad} → {answer}");
    }
    // A scan with returns lost beyond a range limit still matches; the
    // process has survived the bad messages and serves several queries.
    let truth = Pose {
        x: 2.0,
        y: 1.0,
        heading: 3.0,
    };
    let sensor = Sensor {
        beams: 360,
        max_range: Some(5.0),
        ..Sensor::default()
    };
    let scan = simulate(&map, &[], &truth, &sensor, 0).unwrap();
    assert!(scan.ranges.iter().any(Option::is_none));
    for _ in 0..2 {
        let got = karto.localize(&scan, Some(5.0)).expect("an answer");
        assert!(STRICT.accepts(&got.pose, &truth), "{:?}", got.pose);
    }
    let refused = karto.localize(
        &wai_scan::Scan {
            angles: vec![0.0, 0.1],
            ranges: vec![None, None],
        },
        None,
    );
    assert!(matches!(refused, Err(PeerError::Refused(_))), "{refused:?}");
}

#[test]
fn a_missing_interpreter_says_how_to_install() {
    let walls = map_walls(&l_room());
    let e = KartoPeer::spawn_with(
        std::path::Path::new("/nonexistent/karto-venv/bin/python"),
        &walls,
        &KartoConfig::default(),
    )
    .unwrap_err();
    assert!(matches!(e, PeerError::NotInstalled { .. }), "{e}");
    assert!(e.to_string().contains(INSTALL_HINT), "{e}");
}
