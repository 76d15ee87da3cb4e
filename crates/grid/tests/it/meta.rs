//! The YAML half: every field read exactly, every bad one named.

use std::path::Path;
use wai_grid::meta::{parse, Mode};
use wai_grid::GridError;

const GOOD: &str = "image: room.pgm   # written by map_saver\nresolution: 0.050000\norigin: [-10.000000, -7.5, 0.000000]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\nmode: trinary\n";

fn err(text: &str) -> String {
    parse(Path::new("m.yaml"), text).unwrap_err().to_string()
}

#[test]
fn a_map_saver_file_is_read_exactly() {
    let m = parse(Path::new("/maps/m.yaml"), GOOD).unwrap();
    assert_eq!(m.image, "room.pgm");
    assert_eq!(m.resolution, crate::q("1/20"));
    assert_eq!(m.origin, [crate::q("-10"), crate::q("-15/2")]);
    assert_eq!(m.free_thresh, crate::q("0.196"));
    assert_eq!((m.negate, m.mode), (false, Mode::Trinary));
    assert_eq!(
        m.image_path(Path::new("/maps/m.yaml")),
        Path::new("/maps/room.pgm")
    );
    // Quotes, exponents, `.5` and the absence of optional keys.
    let m = parse(
        Path::new("m.yaml"),
        "image: \"/abs/a b.pgm\"\nresolution: 5e-2\norigin: [.5, -2., 0]\noccupied_thresh: 0.65\nfree_thresh: 1.96E-1\n",
    )
    .unwrap();
    assert_eq!(
        m.image_path(Path::new("x/m.yaml")),
        Path::new("/abs/a b.pgm")
    );
    assert_eq!(m.resolution, crate::q("0.05"));
    assert_eq!(m.origin, [crate::q("0.5"), crate::q("-2")]);
    assert_eq!(m.free_thresh, crate::q("0.196"));
}

#[test]
fn bad_metadata_is_refused_with_the_field() {
    let without = |key: &str| -> String {
        GOOD.lines()
            .filter(|l| !l.starts_with(key))
            .collect::<Vec<_>>()
            .join("\n")
    };
    let with = |key: &str, value: &str| -> String {
        GOOD.lines()
            .map(|l| {
                if l.starts_with(key) {
                    format!("{key}: {value}")
                } else {
                    l.to_string()
                }
            })
            .collect::<Vec<_>>()
            .join("\n")
    };
    assert!(err(&without("image")).contains("missing field \"image\""));
    assert!(err(&without("resolution")).contains("missing field \"resolution\""));
    assert!(err(&with("resolution", "-0.05"))
        .contains("resolution: -1/20 metres per cell: must be above 0"));
    assert!(err(&with("resolution", "0")).contains("must be above 0"));
    assert!(err(&with("resolution", "fine")).contains("resolution: \"fine\" is not a number"));
    assert!(err(&with("free_thresh", "0.7")).contains("the thresholds are out of order"));
    assert!(err(&with("occupied_thresh", "1.5")).contains("occupied_thresh: 1.5: not in [0, 1]"));
    assert!(err(&with("origin", "[1, 2, 0.5]")).contains("rotated grids are not read"));
    assert!(err(&with("origin", "[1, 2]")).contains("expected three numbers"));
    assert!(err(&with("origin", "1 2 0")).contains("line 3: origin: expected [x, y, yaw]"));
    assert!(err(&with("mode", "raw")).contains("mode: raw"));
    assert!(err(&with("negate", "maybe")).contains("negate: \"maybe\""));
    assert!(err("image: a.pgm\nresolution 0.05\n").contains("line 2: expected `key: value`"));
    assert!(err(&format!("{GOOD}image: b.pgm\n")).contains("line 8: key \"image\" given twice"));
    assert!(matches!(
        parse(Path::new("m.yaml"), &without("free_thresh")),
        Err(GridError::MissingField {
            field: "free_thresh",
            ..
        })
    ));
}
