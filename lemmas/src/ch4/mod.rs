//! The checkers of chapter 4's claims, one module per claim id, and what
//! several of them share: the figures stored in `counterexamples/`
//! ([`Figure`]) that the example claims recognise.

pub mod c4_10;
pub mod c4_15;
pub mod c4_16;
pub mod c4_20;
pub mod e4_1;
pub mod e4_10;
pub mod e4_28;
pub mod l4_1;
pub mod l4_17;
pub mod l4_18;
pub mod l4_5;
pub mod l4_6;
pub mod l4_7;
pub mod l4_8;
pub mod l4_9;
pub mod t4_19;
pub mod t4_2;
pub mod t4_3;

use serde_json::Value;
use wai_exact::RatPoint;
use wai_map::{json::from_json, parse_exact, Map};
use wai_study::Study;
use wai_visibility::Skeleton;

/// A map stored in `counterexamples/` as a thesis figure, with the
/// viewpoints its note talks about. An example claim's checker embeds its
/// files (`include_str!`) and recognises their maps the way the tight
/// claims recognise family maps ([`wai_study::family::parameter_of`]):
/// by their vertices.
#[derive(Debug)]
pub struct Figure {
    /// The file's name in `counterexamples/`.
    pub file: &'static str,
    pub map: Map,
    /// The stored `viewpoints`, in the map's (scaled) coordinates.
    pub viewpoints: Vec<RatPoint>,
}

impl Figure {
    /// Parses a stored figure file.
    ///
    /// # Panics
    /// If the embedded text is not a valid map with viewpoints `[["x",
    /// "y"], …]` (the loader test of `counterexamples/` holds every file
    /// to that).
    pub fn parse(file: &'static str, text: &str) -> Figure {
        let map = from_json(text.as_bytes())
            .unwrap_or_else(|e| panic!("{file}: not a valid map: {e}"))
            .map;
        let value: Value = serde_json::from_str(text).expect("valid JSON");
        let viewpoints = value["viewpoints"]
            .as_array()
            .map(|a| a.iter().map(|v| viewpoint(file, &map, v)).collect())
            .unwrap_or_default();
        Figure {
            file,
            map,
            viewpoints,
        }
    }

    /// Whether `map` is this figure's map: the same vertices in the same
    /// order (its name does not matter).
    pub fn is(&self, map: &Map) -> bool {
        map.n() == self.map.n() && map.vertices() == self.map.vertices()
    }

    /// On the figure's own map: the class of the viewpoints' skeleton,
    /// if they all have the same one and it is a class of the study.
    pub fn class(&self, study: &Study<'_>) -> Option<usize> {
        let mut keys = self.viewpoints.iter().map(|p| {
            let vp = study.index().visibility_polygon(p).ok()?;
            Skeleton::of(study.map(), &vp).ok().map(|s| s.key())
        });
        let first = keys.next()??;
        for k in keys {
            if k.as_ref() != Some(&first) {
                return None;
            }
        }
        study
            .decomposition()
            .skeletons()
            .iter()
            .position(|k| *k == first)
    }
}

/// A viewpoint `["x", "y"]` of exact strings, scaled like the map.
fn viewpoint(file: &str, map: &Map, v: &Value) -> RatPoint {
    let coords: Vec<&str> = v
        .as_array()
        .filter(|a| a.len() == 2)
        .and_then(|a| a.iter().map(Value::as_str).collect())
        .unwrap_or_else(|| panic!("{file}: viewpoint {v} is not [\"x\", \"y\"]"));
    let [x, y] = [coords[0], coords[1]].map(|s| {
        parse_exact(s).unwrap_or_else(|e| panic!("{file}: viewpoint {v}: {e}")) * map.scale()
    });
    RatPoint::new(
        x.numer().clone() * y.denom(),
        y.numer().clone() * x.denom(),
        x.denom().clone() * y.denom(),
    )
    .expect("the denominators are positive")
}

/// Declares `fn $name() -> &'static Figure`, the stored file
/// `counterexamples/$file` parsed once.
macro_rules! figure {
    ($(#[$doc:meta])* $name:ident, $file:literal) => {
        $(#[$doc])*
        pub fn $name() -> &'static $crate::ch4::Figure {
            static FIGURE: std::sync::OnceLock<$crate::ch4::Figure> = std::sync::OnceLock::new();
            FIGURE.get_or_init(|| {
                $crate::ch4::Figure::parse(
                    $file,
                    include_str!(concat!("../../../counterexamples/", $file)),
                )
            })
        }
    };
}
pub(crate) use figure;
