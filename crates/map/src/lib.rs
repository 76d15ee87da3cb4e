//! Maps: validated simple polygons with exact integer coordinates (thesis
//! ch. 2; Alg 3.14 step 1).
//!
//! The principal type is [`Map`]: a simple polygon without holes,
//! counter-clockwise, with no 180° vertex, whose vertices are integer
//! [`wai_exact::Point`]s. Input in decimal or rational units is scaled
//! exactly to integers by the least common denominator, which the map keeps
//! as its [`Map::scale`] for output.
//!
//! Every bad input is a typed [`MapError`] that says what is wrong and
//! where; [`validate_all`] collects every problem of a ring, not only the
//! first. [`json`] reads and writes the map format of
//! `data/datasets/README.md`; [`geojson`] imports a GeoJSON Polygon.
//!
//! # Invariant
//! No floating point is read: numbers are parsed from their text.

pub mod digest;
mod error;
pub mod geojson;
pub mod json;
mod number;
mod polygon;
mod units;
mod validate;

pub use error::{IntersectionKind, MapError, MapErrors, NumberError, Position};
pub use number::{format_exact, parse_exact, MAX_NUMBER_LEN};
pub use polygon::{Loaded, Map, Normalisation};
pub use units::Units;
pub use validate::validate_all;
