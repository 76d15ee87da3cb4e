//! Star-shaped polygons and their exact polar coordinate functions
//! (sec. 6.7, Def 6.2, eq. 6.5; the capped variant of eq. 6.8).
//!
//! A [`StarPolygon`] is a polygon with a kernel point p_K that strictly
//! sees every edge. Its PCF is piecewise: the ray from p_K in direction φ
//! meets edge i (on the line at distance c_i > 0 from p_K) at distance
//! c_i / sin(φ + α_i), for φ in the angular interval the edge spans, where
//! α_i = π/2 − θ_i and θ_i is the direction of the foot of the
//! perpendicular from p_K to the edge's line. [`Pcf`] holds these pieces
//! over [0, 2π), so the PCF is evaluated exactly (up to `f64` rounding of
//! the ray–line intersection) at any angle, and [`crate::pcm`] integrates
//! them in closed form.
//!
//! The capped PCF pcf' = min(pcf, range) of eq. 6.8 has, besides edge
//! pieces, constant [`Shape::Cap`] pieces: an edge piece is split where
//! c / sin(φ + α) crosses the range.
//!
//! # Edge cases
//! - A kernel point on the line of an edge (the edge seen edge-on, the
//!   discontinuity of sec. 6.9) or outside the polygon is refused: every
//!   edge must subtend a strictly positive angle, and the angles must add
//!   up to exactly one turn.
//! - A clockwise vertex list is reversed; a polygon is stored
//!   counter-clockwise.
//! - Angles are normalised to [0, 2π); a vertex exactly at angle 0 starts
//!   the first piece.

use std::f64::consts::{FRAC_PI_2, PI, TAU};

use crate::Scan;

/// A point or vector in the plane.
pub type Pt = (f64, f64);

/// Why a polygon, a PCF or a scan polygon was refused.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum PolarError {
    #[error("a star-shaped polygon needs at least 3 vertices, got {0}")]
    TooFewVertices(usize),
    #[error("{0} is not finite")]
    NotFinite(String),
    #[error("the kernel point does not strictly see edge {edge} (from vertex {edge} to the next)")]
    NotSeen { edge: usize },
    #[error("the boundary winds {turns} times around the kernel point, not once")]
    Winding { turns: i64 },
    #[error("the sensing range {0} is not finite and > 0")]
    BadRange(f64),
    #[error("the scan has {0} returns and beams; it needs at least 3 beams")]
    ScanTooShort(usize),
    #[error("the scan leaves a gap of {gap} rad between beams {after} and the next: V_S would not surround the origin")]
    ScanGap { after: usize, gap: f64 },
}

/// An angle in [0, 2π).
pub(crate) fn normalise(a: f64) -> f64 {
    let r = a.rem_euclid(TAU);
    // rem_euclid of a tiny negative angle rounds to 2π itself.
    if r >= TAU {
        0.0
    } else {
        r
    }
}

fn cross(a: Pt, b: Pt) -> f64 {
    a.0 * b.1 - a.1 * b.0
}

fn dot(a: Pt, b: Pt) -> f64 {
    a.0 * b.0 + a.1 * b.1
}

/// A polygon that is star-shaped with respect to a given kernel point
/// (sec. 6.7): p_K ∈ ker P, strictly seeing every edge.
///
/// The fields are private so that a value always satisfies the check of
/// [`StarPolygon::new`].
#[derive(Debug, Clone, PartialEq)]
pub struct StarPolygon {
    kernel: Pt,
    vertices: Vec<Pt>,
}

impl StarPolygon {
    /// The polygon with `vertices` (either orientation; stored
    /// counter-clockwise) and kernel point `kernel`.
    ///
    /// Refuses fewer than 3 vertices, non-finite coordinates, an edge the
    /// kernel point does not strictly see (cross product of the two vertex
    /// vectors not > 0: on the edge's line, behind it, or a repeated
    /// vertex) and a boundary that does not wind exactly once around the
    /// kernel point. A *radial* edge — both ends on one ray from the
    /// kernel point, pointing away from it, up to a relative 1e-9 — is
    /// accepted: visibility polygons have them (spurious edges along
    /// visibility rays), and the PCF jumps there (sec. 6.9). These together make P simple and star-shaped with
    /// p_K in the interior of ker P: the angle along the boundary then
    /// increases strictly through one turn, so each ray meets it once.
    pub fn new(kernel: Pt, vertices: Vec<Pt>) -> Result<StarPolygon, PolarError> {
        if vertices.len() < 3 {
            return Err(PolarError::TooFewVertices(vertices.len()));
        }
        if !(kernel.0.is_finite() && kernel.1.is_finite()) {
            return Err(PolarError::NotFinite(format!(
                "the kernel point {kernel:?}"
            )));
        }
        if let Some(i) = vertices
            .iter()
            .position(|v| !(v.0.is_finite() && v.1.is_finite()))
        {
            return Err(PolarError::NotFinite(format!(
                "vertex {i} {:?}",
                vertices[i]
            )));
        }
        let rel = |v: Pt| (v.0 - kernel.0, v.1 - kernel.1);
        let n = vertices.len();
        let turning = |vs: &[Pt]| -> f64 {
            (0..n)
                .map(|i| {
                    let (a, b) = (rel(vs[i]), rel(vs[(i + 1) % n]));
                    cross(a, b).atan2(dot(a, b))
                })
                .sum()
        };
        let mut vertices = vertices;
        if turning(&vertices) < 0.0 {
            vertices.reverse();
        }
        for i in 0..n {
            let (a, b) = (rel(vertices[i]), rel(vertices[(i + 1) % n]));
            if radial(a, b) {
                continue;
            }
            if cross(a, b).partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
                return Err(PolarError::NotSeen { edge: i });
            }
        }
        if (0..n).all(|i| radial(rel(vertices[i]), rel(vertices[(i + 1) % n]))) {
            return Err(PolarError::NotSeen { edge: 0 });
        }
        // Every edge subtends an angle in (0, π), so the sum is a whole
        // number of turns up to rounding.
        let turns = (turning(&vertices) / TAU).round() as i64;
        if turns != 1 {
            return Err(PolarError::Winding { turns });
        }
        Ok(StarPolygon { kernel, vertices })
    }

    /// V_S, the approximated visibility polygon of a scan (sec. 6.7): the
    /// scan points, in angle order, joined by segments, with the origin of
    /// the robot's frame as kernel point.
    ///
    /// A lost return (`None`, beyond the sensor's limit) becomes a vertex
    /// at distance `range` on its beam, as if the wall stood at the sensing
    /// range: with pcf' capped at the same `range` (eq. 6.8) the lost beam
    /// then reads exactly `range`, what the capped PCF of the map polygon
    /// reads there. Measured ranges are kept as they are (cap with
    /// [`Pcf::capped`]).
    ///
    /// Refuses a scan with fewer than 3 beams, a non-finite or
    /// non-positive range (noise clamped to 0 puts a vertex on the kernel
    /// point), a bad `range`, and a scan whose beams leave an angular gap
    /// of π or more (a partial field of view): V_S would not surround the
    /// origin. Repeated beam angles are refused by [`StarPolygon::new`].
    pub fn from_scan(scan: &Scan, range: f64) -> Result<StarPolygon, PolarError> {
        if !(range.is_finite() && range > 0.0) {
            return Err(PolarError::BadRange(range));
        }
        let m = scan.angles.len().min(scan.ranges.len());
        if m < 3 {
            return Err(PolarError::ScanTooShort(m));
        }
        let mut beams: Vec<(f64, f64)> = Vec::with_capacity(m);
        for (i, (&a, r)) in scan.angles.iter().zip(&scan.ranges).enumerate() {
            let r = r.unwrap_or(range);
            if !(a.is_finite() && r.is_finite() && r > 0.0) {
                return Err(PolarError::NotFinite(format!(
                    "beam {i} (angle {a}, range {r}; a range must be > 0)"
                )));
            }
            beams.push((normalise(a), r));
        }
        beams.sort_by(|x, y| x.0.total_cmp(&y.0));
        for i in 0..m {
            let next = if i + 1 < m {
                beams[i + 1].0
            } else {
                beams[0].0 + TAU
            };
            let gap = next - beams[i].0;
            if gap >= PI {
                return Err(PolarError::ScanGap { after: i, gap });
            }
        }
        let vertices = beams
            .iter()
            .map(|&(a, r)| (r * a.cos(), r * a.sin()))
            .collect();
        StarPolygon::new((0.0, 0.0), vertices)
    }

    /// The kernel point p_K.
    pub fn kernel(&self) -> Pt {
        self.kernel
    }

    /// The vertices, counter-clockwise.
    pub fn vertices(&self) -> &[Pt] {
        &self.vertices
    }

    /// The PCF of the polygon about its kernel point (Def 6.2).
    pub fn pcf(&self) -> Pcf {
        let n = self.vertices.len();
        let rel = |v: Pt| (v.0 - self.kernel.0, v.1 - self.kernel.1);
        let is_radial = |i: usize| radial(rel(self.vertices[i]), rel(self.vertices[(i + 1) % n]));
        // A radial edge (on a ray from p_K: a spurious edge of V_p, sec.
        // 6.9's jump of the PCF) has no width: the edge after it starts at
        // the angle where the edge before it ended, exactly.
        let mut ang: Vec<f64> = self
            .vertices
            .iter()
            .map(|&v| {
                let a = rel(v);
                normalise(a.1.atan2(a.0))
            })
            .collect();
        let start = (0..n).find(|&i| !is_radial((i + n - 1) % n)).unwrap_or(0);
        for k in 0..n {
            let i = (start + k) % n;
            if is_radial(i) {
                ang[(i + 1) % n] = ang[i];
            }
        }
        let mut pieces = Vec::with_capacity(n + 1);
        for i in 0..n {
            if is_radial(i) {
                continue;
            }
            let (a, b) = (rel(self.vertices[i]), rel(self.vertices[(i + 1) % n]));
            let e = (b.0 - a.0, b.1 - a.1);
            let len = e.0.hypot(e.1);
            // The outward normal of a counter-clockwise edge, and the
            // distance of its line from p_K (> 0: checked in `new`).
            let c = cross(a, b) / len;
            // θ: the direction of the outward normal (e.1, −e.0), where the
            // foot of the perpendicular from p_K lies; α = π/2 − θ turns
            // c / cos(φ − θ) into the thesis's c / sin(φ + α).
            let theta = (-e.0).atan2(e.1);
            let shape = Shape::Edge {
                c,
                alpha: normalise(FRAC_PI_2 - theta),
            };
            let (from, to) = (ang[i], ang[(i + 1) % n]);
            if to > from {
                pieces.push(Piece { from, to, shape });
            } else {
                // The edge crosses angle 0 (or ends exactly there).
                pieces.push(Piece {
                    from,
                    to: TAU,
                    shape,
                });
                if to > 0.0 {
                    pieces.push(Piece {
                        from: 0.0,
                        to,
                        shape,
                    });
                }
            }
        }
        pieces.sort_by(|x, y| x.from.total_cmp(&y.from));
        Pcf { pieces }
    }
}

/// The function on one piece of a PCF.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Shape {
    /// c / sin(φ + α): the ray meets an edge on the line at distance c
    /// from the kernel point (eq. 6.5, sec. 6.8).
    Edge { c: f64, alpha: f64 },
    /// The constant sensing range, where the capped PCF cuts off (eq. 6.8).
    Cap(f64),
}

impl Shape {
    /// The value at angle φ (any representative of φ mod 2π on the piece).
    pub fn value(&self, phi: f64) -> f64 {
        match *self {
            Shape::Edge { c, alpha } => c / (phi + alpha).sin(),
            Shape::Cap(r) => r,
        }
    }
}

/// One piece of a PCF: `shape` over the angles [`from`, `to`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Piece {
    pub from: f64,
    pub to: f64,
    pub shape: Shape,
}

/// A polar coordinate function (Def 6.2, or its capped form of eq. 6.8)
/// as its pieces over [0, 2π): contiguous, sorted, the first starting at
/// 0 and the last ending at 2π.
#[derive(Debug, Clone, PartialEq)]
pub struct Pcf {
    pieces: Vec<Piece>,
}

impl Pcf {
    /// The pieces over [0, 2π), in angle order (sec. 6.8: each edge gives a
    /// piece c_i / sin(φ + α_i); an edge across angle 0 gives two).
    pub fn pieces(&self) -> &[Piece] {
        &self.pieces
    }

    /// pcf(φ) (eq. 6.5), for any real φ (the function has period 2π).
    pub fn value(&self, phi: f64) -> f64 {
        let phi = normalise(phi);
        let k = self
            .pieces
            .partition_point(|p| p.to <= phi)
            .min(self.pieces.len() - 1);
        self.pieces[k].shape.value(phi)
    }

    /// The capped PCF pcf' = min(pcf, range) (eq. 6.8): each edge piece
    /// split where c / sin(φ + α) crosses `range`, the part beyond it
    /// replaced by a constant [`Shape::Cap`] piece (adjacent cap pieces
    /// merged). Capping a capped PCF again caps at the smaller range.
    pub fn capped(&self, range: f64) -> Result<Pcf, PolarError> {
        if !(range.is_finite() && range > 0.0) {
            return Err(PolarError::BadRange(range));
        }
        let mut out: Vec<Piece> = Vec::with_capacity(self.pieces.len() + 2);
        let mut push = |p: Piece| {
            if p.to <= p.from {
                return;
            }
            if let (Some(last), Shape::Cap(r)) = (out.last_mut(), p.shape) {
                if last.shape == Shape::Cap(r) {
                    last.to = p.to;
                    return;
                }
            }
            out.push(p);
        };
        for p in &self.pieces {
            match p.shape {
                Shape::Cap(r) => push(Piece {
                    shape: Shape::Cap(r.min(range)),
                    ..*p
                }),
                Shape::Edge { c, alpha } => {
                    if c >= range {
                        push(Piece {
                            shape: Shape::Cap(range),
                            ..*p
                        });
                        continue;
                    }
                    // On the piece φ + α lies in (0, π) + 2πk for one k;
                    // below the cap where sin(φ + α) ≥ c / range, i.e.
                    // φ + α − 2πk ∈ [β, π − β].
                    let mid = (p.from + p.to) / 2.0;
                    let k = ((mid + alpha) / TAU).floor();
                    let beta = (c / range).asin();
                    let lo = (beta - alpha + TAU * k).clamp(p.from, p.to);
                    let hi = (PI - beta - alpha + TAU * k).clamp(p.from, p.to);
                    push(Piece {
                        from: p.from,
                        to: lo,
                        shape: Shape::Cap(range),
                    });
                    push(Piece {
                        from: lo,
                        to: hi.max(lo),
                        shape: p.shape,
                    });
                    push(Piece {
                        from: hi.max(lo),
                        to: p.to,
                        shape: Shape::Cap(range),
                    });
                }
            }
        }
        Ok(Pcf { pieces: out })
    }

    /// The supporting angles of sec. 6.8 (Fig. 6.4 a), in [0, 2π), sorted:
    /// every breakpoint (a vertex, or where a capped piece starts or ends)
    /// and the local minimum of every edge piece c / sin(φ + α) that lies
    /// inside its piece (φ + α = π/2).
    pub fn supporting_angles(&self) -> Vec<f64> {
        let mut out = Vec::with_capacity(2 * self.pieces.len());
        for p in &self.pieces {
            out.push(p.from);
            if let Shape::Edge { alpha, .. } = p.shape {
                let m = normalise(FRAC_PI_2 - alpha);
                if m > p.from && m < p.to {
                    out.push(m);
                }
            }
        }
        out.sort_by(f64::total_cmp);
        out.dedup();
        out
    }
}

/// Whether the edge from `a` to `b` (relative to the kernel point) lies on
/// one ray from it: collinear up to a relative 1e-9, same direction, not a
/// repeated vertex.
fn radial(a: Pt, b: Pt) -> bool {
    let (la, lb) = (a.0.hypot(a.1), b.0.hypot(b.1));
    cross(a, b).abs() <= 1e-9 * la * lb && dot(a, b) > 0.0 && (la - lb).abs() > 1e-12 * la.max(lb)
}
