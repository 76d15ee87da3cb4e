//! The validated map polygon.

use crate::error::MapErrors;
use crate::validate::validate_scaled;
use rug::Integer;
use wai_exact::{orientation, signed_area_twice, Orientation, Point, Segment};

/// A map: a simple polygon without holes (thesis ch. 2), normalised as
/// Alg 3.14 step 1 asks.
///
/// Invariants: counter-clockwise; at least 3 vertices; no two vertices
/// equal; no 180° vertex (no two consecutive edges collinear); simple; every
/// coordinate below `2^MAX_COORD_BITS` in magnitude. Coordinates are
/// integers; the input's value of a coordinate `c` is `c / scale`, with the
/// least such scale.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Map {
    name: Option<String>,
    source: Option<String>,
    units: Option<crate::Units>,
    vertices: Vec<Point>,
    scale: Integer,
    reflex: Vec<usize>,
}

/// What [`Map::from_ring`] changed to normalise a valid ring.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Normalisation {
    /// The ring was clockwise and was reversed, keeping its first vertex.
    pub reversed: bool,
    /// Input positions of the 180° vertices that were removed.
    pub removed_collinear: Vec<usize>,
}

impl Normalisation {
    /// Whether the input was already in normal form.
    pub fn is_identity(&self) -> bool {
        !self.reversed && self.removed_collinear.is_empty()
    }
}

/// A map read from a file, with what normalisation changed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Loaded {
    pub map: Map,
    pub normalisation: Normalisation,
}

impl Map {
    /// Validate a ring of integer points (either orientation) and normalise
    /// it: clockwise rings are reversed keeping their first vertex, and 180°
    /// vertices are removed. Every problem is reported, as by
    /// [`crate::validate_all`].
    pub fn from_ring(ring: Vec<Point>) -> Result<(Map, Normalisation), MapErrors> {
        Map::from_scaled_ring(ring, Integer::from(1))
    }

    /// [`Map::from_ring`] for coordinates in units of `1 / scale`.
    pub fn from_scaled_ring(
        ring: Vec<Point>,
        scale: Integer,
    ) -> Result<(Map, Normalisation), MapErrors> {
        assert!(scale > 0, "the scale is a positive denominator");
        let errors = validate_scaled(&ring, &scale);
        if !errors.is_empty() {
            return Err(MapErrors(errors));
        }
        let n = ring.len();
        let mut index: Vec<usize> = (0..n).collect();
        let reversed = signed_area_twice(&ring) < 0;
        if reversed {
            index[1..].reverse();
        }
        let mut removed = Vec::new();
        // Drop 180° vertices until none is left; a valid ring keeps >= 3.
        loop {
            let m = index.len();
            let straight = (0..m).find(|&k| {
                let (a, b, c) = (
                    ring[index[(k + m - 1) % m]],
                    ring[index[k]],
                    ring[index[(k + 1) % m]],
                );
                orientation(a, b, c) == Orientation::Collinear
            });
            match straight {
                Some(k) => removed.push(index.remove(k)),
                None => break,
            }
        }
        removed.sort_unstable();
        let vertices: Vec<Point> = index.iter().map(|&i| ring[i]).collect();
        let map = Map::assemble(None, None, vertices, scale);
        Ok((
            map,
            Normalisation {
                reversed,
                removed_collinear: removed,
            },
        ))
    }

    /// The map enlarged `2^bits` times about the origin: every coordinate
    /// shifted left by `bits`, the scale and names kept. Enlarging keeps
    /// every invariant but the coordinate bound (a simple ring stays simple,
    /// turns keep their signs), so nothing is validated again; a coordinate
    /// that would reach `2^MAX_COORD_BITS` is an error, located as
    /// [`Map::from_ring`] locates it. Tests use it to take a map off the
    /// narrow-integer fast paths.
    pub fn scaled_up(&self, bits: u32) -> Result<Map, MapErrors> {
        let max = wai_exact::MAX_COORD_BITS;
        for (i, p) in self.vertices.iter().enumerate() {
            let need = (128 - p.x.unsigned_abs().leading_zeros())
                .max(128 - p.y.unsigned_abs().leading_zeros())
                + bits;
            if need > max {
                return Err(MapErrors(vec![crate::MapError::CoordinateTooLarge {
                    path: format!("vertex {i}"),
                    bits: u64::from(need),
                    max,
                }]));
            }
        }
        Ok(Map {
            vertices: self
                .vertices
                .iter()
                .map(|p| Point::new(p.x << bits, p.y << bits))
                .collect(),
            ..self.clone()
        })
    }

    /// Build from a normalised ring, reducing the scale to the least one.
    fn assemble(
        name: Option<String>,
        source: Option<String>,
        mut vertices: Vec<Point>,
        mut scale: Integer,
    ) -> Map {
        let mut g = scale.clone();
        for p in &vertices {
            g.gcd_mut(&Integer::from(p.x));
            g.gcd_mut(&Integer::from(p.y));
        }
        if g > 1 {
            let g128 = g.to_i128().expect("g divides the scale and a coordinate");
            for p in &mut vertices {
                *p = Point::new(p.x / g128, p.y / g128);
            }
            scale /= g;
        }
        let n = vertices.len();
        let reflex = (0..n)
            .filter(|&i| {
                orientation(
                    vertices[(i + n - 1) % n],
                    vertices[i],
                    vertices[(i + 1) % n],
                ) == Orientation::Clockwise
            })
            .collect();
        Map {
            name,
            source,
            units: None,
            vertices,
            scale,
            reflex,
        }
    }

    pub fn with_name(mut self, name: impl Into<String>) -> Map {
        self.name = Some(name.into());
        self
    }

    pub fn with_source(mut self, source: impl Into<String>) -> Map {
        self.source = Some(source.into());
        self
    }

    /// The map with the units its file states.
    pub fn with_units(mut self, units: crate::Units) -> Map {
        self.units = Some(units);
        self
    }

    /// The units the map's file states, if it states any.
    pub fn units(&self) -> Option<&crate::Units> {
        self.units.as_ref()
    }

    pub fn name(&self) -> Option<&str> {
        self.name.as_deref()
    }

    pub fn source(&self) -> Option<&str> {
        self.source.as_deref()
    }

    /// The vertices, counter-clockwise.
    pub fn vertices(&self) -> &[Point] {
        &self.vertices
    }

    /// The number of vertices, n.
    pub fn n(&self) -> usize {
        self.vertices.len()
    }

    /// The number of reflex vertices, r.
    pub fn r(&self) -> usize {
        self.reflex.len()
    }

    /// Indices of the reflex vertices (interior angle above 180°), ascending.
    pub fn reflex_vertices(&self) -> &[usize] {
        &self.reflex
    }

    pub fn is_reflex(&self, i: usize) -> bool {
        self.reflex.binary_search(&i).is_ok()
    }

    /// The input value of a coordinate `c` is `c / scale`.
    pub fn scale(&self) -> &Integer {
        &self.scale
    }

    /// Edge `i`, from vertex `i` to vertex `i + 1 (mod n)`.
    pub fn edge(&self, i: usize) -> Segment {
        let n = self.n();
        Segment::new(self.vertices[i], self.vertices[(i + 1) % n]).expect("no repeated vertex")
    }

    pub fn edges(&self) -> impl Iterator<Item = Segment> + '_ {
        (0..self.n()).map(|i| self.edge(i))
    }

    /// Twice the area, in integer units (divide by `scale²` for input units).
    pub fn area_twice(&self) -> Integer {
        signed_area_twice(&self.vertices)
    }

    /// Whether every edge is horizontal or vertical.
    pub fn is_orthogonal(&self) -> bool {
        self.edges()
            .all(|e| e.a().x == e.b().x || e.a().y == e.b().y)
    }

    /// The least and greatest corner of the bounding box.
    pub fn bounding_box(&self) -> (Point, Point) {
        let xs = self.vertices.iter().map(|p| p.x);
        let ys = self.vertices.iter().map(|p| p.y);
        (
            Point::new(xs.clone().min().unwrap_or(0), ys.clone().min().unwrap_or(0)),
            Point::new(xs.max().unwrap_or(0), ys.max().unwrap_or(0)),
        )
    }
}
