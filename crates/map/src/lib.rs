//! Maps: validated polygons, possibly with holes, with exact integer
//! coordinates (thesis ch. 2; Alg 3.14 step 1).
//!
//! The principal type is [`Map`]: a simple polygon, possibly with holes
//! (thesis sec. 2.1), its outer ring counter-clockwise and its holes
//! clockwise, with no 180° vertex, whose vertices are integer
//! [`wai_exact::Point`]s. Input in decimal or rational units is scaled
//! exactly to integers by the least common denominator, which the map keeps
//! as its [`Map::scale`] for output; a reader may be asked to round to a
//! binary grid first ([`json::ReadOptions`]), and says what moved.
//!
//! The thesis's chapters 3–5 assume a map without holes; a stage built on
//! that assumption refuses a holed map with [`Map::require_no_holes`].
//!
//! Every bad input is a typed [`MapError`] that says what is wrong and
//! where; [`validate_all`] collects every problem of a ring, not only the
//! first ([`validate_rings`] every problem of a map with holes). [`json`] reads and writes the map format of
//! `data/datasets/README.md`; [`geojson`] imports a GeoJSON Polygon (its
//! interior rings are holes).
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

pub use error::{IntersectionKind, MapError, MapErrors, NumberError, Position, Ring};
pub use number::{format_exact, parse_exact, Rounding, MAX_NUMBER_LEN};
pub use polygon::{Loaded, Map, Normalisation};
pub use units::Units;
pub use validate::{validate_all, validate_rings};
