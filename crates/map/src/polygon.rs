//! The validated map: a polygon, possibly with holes (thesis sec. 2.1).

use crate::error::MapErrors;
use crate::validate::validate_scaled_rings;
use rug::Integer;
use wai_exact::{
    locate_rat, orientation, signed_area_twice, Containment, Orientation, Point, RatPoint, Segment,
};

/// A map: a simple polygon, possibly with holes (thesis sec. 2.1; the
/// thesis's chapters 3–5 assume none, sec. 6.4 drops the assumption),
/// normalised as Alg 3.14 step 1 asks.
///
/// The free space is the outer ring's interior minus the holes' closures.
/// Vertices are numbered ring after ring: the outer ring first, then each
/// hole in input order; edge `i` runs from vertex `i` to [`Map::next`]`(i)`,
/// the next vertex of the same ring, so the free space lies on the left of
/// every edge.
///
/// Invariants: the outer ring counter-clockwise and every hole clockwise;
/// each ring at least 3 vertices, simple, with no 180° vertex (no two
/// consecutive edges collinear); no two vertices equal; no two rings meet;
/// every hole inside the outer ring and in no other hole; every coordinate
/// below `2^MAX_COORD_BITS` in magnitude. Coordinates are integers; the
/// input's value of a coordinate `c` is `c / scale`, with the least such
/// scale.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Map {
    name: Option<String>,
    source: Option<String>,
    units: Option<crate::Units>,
    vertices: Vec<Point>,
    /// Where each ring starts in `vertices`: `[0]` for a map without holes.
    ring_starts: Vec<usize>,
    scale: Integer,
    reflex: Vec<usize>,
}

/// What [`Map::from_rings`] changed to normalise valid rings.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Normalisation {
    /// The outer ring was clockwise and was reversed, keeping its first
    /// vertex.
    pub reversed: bool,
    /// Input positions of the outer ring's 180° vertices that were removed.
    pub removed_collinear: Vec<usize>,
    /// Holes (0-based, input order) that were counter-clockwise and were
    /// reversed, keeping their first vertex.
    pub reversed_holes: Vec<usize>,
    /// `(hole, input position)` of the holes' 180° vertices that were
    /// removed.
    pub removed_collinear_holes: Vec<(usize, usize)>,
    /// Coordinates rounded to a grid on reading, if the reader was asked to
    /// ([`crate::json::ReadOptions::grid_bits`]).
    pub rounded: Option<crate::Rounding>,
}

impl Normalisation {
    /// Whether the input was already in normal form.
    pub fn is_identity(&self) -> bool {
        !self.reversed
            && self.removed_collinear.is_empty()
            && self.reversed_holes.is_empty()
            && self.removed_collinear_holes.is_empty()
            && self.rounded.as_ref().is_none_or(|r| r.moved == 0)
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
        Map::from_scaled_rings(ring, Vec::new(), scale)
    }

    /// A map with holes: the outer ring and the holes' rings, in either
    /// orientation, validated together ([`crate::validate_rings`]) and
    /// normalised: the outer ring counter-clockwise, every hole clockwise
    /// (each reversed keeping its first vertex), 180° vertices removed.
    pub fn from_rings(
        outer: Vec<Point>,
        holes: Vec<Vec<Point>>,
    ) -> Result<(Map, Normalisation), MapErrors> {
        Map::from_scaled_rings(outer, holes, Integer::from(1))
    }

    /// [`Map::from_rings`] for coordinates in units of `1 / scale`.
    pub fn from_scaled_rings(
        outer: Vec<Point>,
        holes: Vec<Vec<Point>>,
        scale: Integer,
    ) -> Result<(Map, Normalisation), MapErrors> {
        assert!(scale > 0, "the scale is a positive denominator");
        let errors = validate_scaled_rings(&outer, &holes, &scale);
        if !errors.is_empty() {
            return Err(MapErrors(errors));
        }
        let mut norm = Normalisation::default();
        let (mut vertices, reversed, removed) = normalise_ring(&outer, true);
        norm.reversed = reversed;
        norm.removed_collinear = removed;
        let mut ring_starts = vec![0];
        for (k, hole) in holes.iter().enumerate() {
            let (ring, reversed, removed) = normalise_ring(hole, false);
            if reversed {
                norm.reversed_holes.push(k);
            }
            norm.removed_collinear_holes
                .extend(removed.into_iter().map(|i| (k, i)));
            ring_starts.push(vertices.len());
            vertices.extend(ring);
        }
        let map = Map::assemble(None, None, vertices, ring_starts, scale);
        Ok((map, norm))
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

    /// Build from normalised rings, reducing the scale to the least one.
    fn assemble(
        name: Option<String>,
        source: Option<String>,
        mut vertices: Vec<Point>,
        ring_starts: Vec<usize>,
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
        let mut map = Map {
            name,
            source,
            units: None,
            vertices,
            ring_starts,
            scale,
            reflex: Vec::new(),
        };
        // A hole's vertex that is convex as a vertex of the hole turns
        // clockwise in the hole's clockwise ring: reflex in the free space.
        map.reflex = (0..map.n())
            .filter(|&i| {
                orientation(
                    map.vertices[map.prev(i)],
                    map.vertices[i],
                    map.vertices[map.next(i)],
                ) == Orientation::Clockwise
            })
            .collect();
        map
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

    /// Every vertex, ring after ring: the outer ring counter-clockwise, then
    /// each hole clockwise. Without holes, the map's ring.
    pub fn vertices(&self) -> &[Point] {
        &self.vertices
    }

    /// The number of vertices of every ring, n.
    pub fn n(&self) -> usize {
        self.vertices.len()
    }

    /// The outer ring, counter-clockwise.
    pub fn outer(&self) -> &[Point] {
        self.ring(0)
    }

    /// The number of holes, h.
    pub fn hole_count(&self) -> usize {
        self.ring_starts.len() - 1
    }

    pub fn has_holes(&self) -> bool {
        self.hole_count() > 0
    }

    /// The holes' rings, clockwise, in input order.
    pub fn holes(&self) -> impl ExactSizeIterator<Item = &[Point]> + '_ {
        (1..self.ring_starts.len()).map(|k| self.ring(k))
    }

    /// Ring `k`: 0 is the outer ring, `k >= 1` hole `k - 1`.
    pub fn ring(&self, k: usize) -> &[Point] {
        &self.vertices[self.ring_range(k)]
    }

    /// The positions in [`Map::vertices`] of ring `k`'s vertices.
    pub fn ring_range(&self, k: usize) -> std::ops::Range<usize> {
        let end = self
            .ring_starts
            .get(k + 1)
            .copied()
            .unwrap_or(self.vertices.len());
        self.ring_starts[k]..end
    }

    /// The ring of vertex `i`: 0 for the outer ring, `k >= 1` for hole
    /// `k - 1`.
    pub fn ring_of(&self, i: usize) -> usize {
        self.ring_starts.partition_point(|&s| s <= i) - 1
    }

    /// The vertex after `i` along its ring (free space on the left).
    pub fn next(&self, i: usize) -> usize {
        if self.ring_starts.len() == 1 {
            return if i + 1 == self.vertices.len() {
                0
            } else {
                i + 1
            };
        }
        let r = self.ring_range(self.ring_of(i));
        if i + 1 == r.end {
            r.start
        } else {
            i + 1
        }
    }

    /// The vertex before `i` along its ring.
    pub fn prev(&self, i: usize) -> usize {
        if self.ring_starts.len() == 1 {
            return if i == 0 {
                self.vertices.len() - 1
            } else {
                i - 1
            };
        }
        let r = self.ring_range(self.ring_of(i));
        if i == r.start {
            r.end - 1
        } else {
            i - 1
        }
    }

    /// For the library entry points of the stages built on the thesis's
    /// chapters 3–5 setting, which would silently misread a hole.
    ///
    /// # Panics
    /// If the map has holes, naming `stage`: callers that take maps from
    /// users check [`Map::require_no_holes`] first.
    #[track_caller]
    pub fn expect_no_holes(&self, stage: &str) {
        if let Err(e) = self.require_no_holes(stage) {
            panic!("{e}");
        }
    }

    /// Where `p` lies: in the free space (inside the outer ring and outside
    /// every hole), on the boundary of any ring, or outside (beyond the
    /// outer ring or inside a hole).
    pub fn locate(&self, p: &RatPoint) -> Containment {
        match locate_rat(self.outer(), p) {
            Containment::Inside => {}
            other => return other,
        }
        for hole in self.holes() {
            match locate_rat(hole, p) {
                Containment::Outside => {}
                Containment::OnBoundary => return Containment::OnBoundary,
                Containment::Inside => return Containment::Outside,
            }
        }
        Containment::Inside
    }

    /// Whether `p` and `q` see each other in the free space (thesis sec.
    /// 2.2, every ring a boundary): [`wai_exact::sees`] over the edges of
    /// every ring, `Blocked { edge: i }` naming map edge `i` (from vertex
    /// `i` to [`Map::next`]`(i)`).
    pub fn sees(&self, p: &RatPoint, q: &RatPoint) -> wai_exact::Sight {
        let v = &self.vertices;
        wai_exact::sees_among(
            (0..v.len()).map(|i| (i, v[i], v[self.next(i)])),
            |x| self.locate(x),
            p,
            q,
        )
    }

    /// An error naming `stage` if the map has holes: for the stages that
    /// assume the thesis's chapters 3–5 setting of a map without holes.
    pub fn require_no_holes(&self, stage: &str) -> Result<(), crate::MapError> {
        if self.has_holes() {
            Err(crate::MapError::HolesNotSupported {
                count: self.hole_count(),
                stage: stage.to_string(),
            })
        } else {
            Ok(())
        }
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

    /// Edge `i`, from vertex `i` to vertex [`Map::next`]`(i)` (without
    /// holes, `i + 1 (mod n)`).
    pub fn edge(&self, i: usize) -> Segment {
        Segment::new(self.vertices[i], self.vertices[self.next(i)]).expect("no repeated vertex")
    }

    pub fn edges(&self) -> impl Iterator<Item = Segment> + '_ {
        (0..self.n()).map(|i| self.edge(i))
    }

    /// Twice the free space's area, in integer units (divide by `scale²`
    /// for input units): the outer ring's less the holes'.
    pub fn area_twice(&self) -> Integer {
        // Clockwise holes have negative signed areas.
        (0..self.ring_starts.len())
            .map(|k| signed_area_twice(self.ring(k)))
            .sum()
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

/// A valid ring in the orientation asked for (counter-clockwise for the
/// outer ring, clockwise for a hole), reversed keeping its first vertex if
/// need be, without its 180° vertices; with whether it was reversed and the
/// input positions removed, ascending.
fn normalise_ring(ring: &[Point], ccw: bool) -> (Vec<Point>, bool, Vec<usize>) {
    let n = ring.len();
    let mut index: Vec<usize> = (0..n).collect();
    let area = signed_area_twice(ring);
    let reversed = if ccw { area < 0 } else { area > 0 };
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
    (index.iter().map(|&i| ring[i]).collect(), reversed, removed)
}
