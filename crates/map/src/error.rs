//! Typed errors with locations.

use rug::Rational;
use std::fmt;

/// A point in the map's input units, for error messages.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Position {
    pub x: Rational,
    pub y: Rational,
}

impl fmt::Display for Position {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "({}, {})",
            crate::number::format_exact(&self.x),
            crate::number::format_exact(&self.y)
        )
    }
}

/// Why a coordinate's text is not an exact number of the accepted syntax
/// (`[+-]digits[.digits]` or `[+-]digits/digits`).
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum NumberError {
    #[error("empty number")]
    Empty,
    #[error("exponent notation is not accepted: write the number in full (e.g. 1200, not 1.2e3)")]
    Exponent,
    #[error("not a number: NaN and infinities have no exact value")]
    NotFinite,
    #[error("zero denominator")]
    ZeroDenominator,
    #[error("unexpected character {found:?} at position {position}")]
    Unexpected { found: char, position: usize },
    #[error("longer than {max} characters")]
    TooLong { max: usize },
}

/// How two edges of a ring meet where they must not.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum IntersectionKind {
    /// The edges cross at a point interior to both.
    Crossing,
    /// A vertex touches the other edge (or the edges share a vertex that is
    /// not their common endpoint in the ring).
    Touching,
    /// The edges run along each other.
    Overlap,
}

/// A ring of a map: the outer boundary or a hole (0-based, input order).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Ring {
    Outer,
    Hole(usize),
}

impl fmt::Display for Ring {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Ring::Outer => write!(f, "the outer ring"),
            Ring::Hole(k) => write!(f, "hole {k}"),
        }
    }
}

/// Everything that can be wrong with a map, with where it is wrong.
///
/// Vertex and edge numbers are 0-based positions in the input ring; edge
/// `i` runs from vertex `i` to vertex `i + 1` (the last closes the ring).
/// Holes are numbered from 0 in input order; a problem of one hole's ring
/// comes wrapped in [`MapError::InHole`]. Points are in the input's units.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum MapError {
    #[error("empty input: expected a map")]
    Empty,
    #[error("not UTF-8 text: invalid byte at offset {offset}")]
    NotUtf8 { offset: usize },
    #[error("malformed JSON at line {line}, column {column}: {message}")]
    Syntax {
        line: usize,
        column: usize,
        message: String,
    },
    #[error("{path}: {message}")]
    Structure { path: String, message: String },
    #[error("{path}: {text:?} is not an exact number: {reason}")]
    BadNumber {
        path: String,
        text: String,
        reason: NumberError,
    },
    #[error(
        "{path}: coordinate too large: it needs {bits} bits as an integer over the common denominator; at most {max} are supported"
    )]
    CoordinateTooLarge { path: String, bits: u64, max: u32 },
    #[error("{stage} does not support maps with holes yet: the map has {count} hole(s)")]
    HolesNotSupported { count: usize, stage: String },
    #[error("hole {hole}: {error}")]
    InHole { hole: usize, error: Box<MapError> },
    #[error("{ring_a} and {ring_b} meet: {ring_a}'s edge {edge_a} and {ring_b}'s edge {edge_b} {} at {at}", match .kind {
        IntersectionKind::Crossing => "cross",
        IntersectionKind::Touching => "touch",
        IntersectionKind::Overlap => "overlap, starting",
    })]
    RingsMeet {
        ring_a: Ring,
        edge_a: usize,
        ring_b: Ring,
        edge_b: usize,
        kind: IntersectionKind,
        at: Position,
    },
    #[error("hole {hole} lies outside the outer ring (its vertex 0 is at {at})")]
    HoleOutside { hole: usize, at: Position },
    #[error("hole {inner} lies inside hole {outer}: a hole in a hole is not part of the map's free space")]
    HoleInHole { inner: usize, outer: usize },
    #[error("a map needs at least 3 distinct vertices; found {found}")]
    TooFewVertices { found: usize },
    #[error("vertex {second} repeats vertex {first} at {at}{}", if *.closing { " (rings are open: do not repeat the first vertex at the end)" } else { "" })]
    RepeatedVertex {
        first: usize,
        second: usize,
        at: Position,
        closing: bool,
    },
    #[error("the map is not simple: edges {edge_a} and {edge_b} {} at {at}", match .kind {
        IntersectionKind::Crossing => "cross",
        IntersectionKind::Touching => "touch",
        IntersectionKind::Overlap => "overlap, starting",
    })]
    SelfIntersection {
        edge_a: usize,
        edge_b: usize,
        kind: IntersectionKind,
        at: Position,
    },
    #[error("zero area: all {n} vertices lie on one line")]
    ZeroArea { n: usize },
}

/// One or more [`MapError`]s, as collected by [`crate::validate_all`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct MapErrors(pub Vec<MapError>);

impl MapErrors {
    pub fn one(e: MapError) -> Self {
        MapErrors(vec![e])
    }
    pub fn first(&self) -> &MapError {
        &self.0[0]
    }
    pub fn iter(&self) -> impl Iterator<Item = &MapError> {
        self.0.iter()
    }
}

impl From<MapError> for MapErrors {
    fn from(e: MapError) -> Self {
        MapErrors::one(e)
    }
}

impl fmt::Display for MapErrors {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.0.as_slice() {
            [one] => write!(f, "{one}"),
            many => {
                write!(f, "{} problems:", many.len())?;
                for e in many {
                    write!(f, "\n  - {e}")?;
                }
                Ok(())
            }
        }
    }
}

impl std::error::Error for MapErrors {}
