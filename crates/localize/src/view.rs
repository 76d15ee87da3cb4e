//! What the robot sees: a visibility polygon V given relative to the robot
//! (the robot at the origin o, thesis sec. 3.2), checked to be one, and its
//! skeleton V* computed from V alone (Alg 3.13 steps 1–3).
//!
//! A map-side `VisibilityPolygon` knows where each vertex lies on the map;
//! the robot does not. Everything here is decided from V's own geometry:
//! an edge is spurious when it is collinear with o (Def 3.4), a vertex is
//! spurious when it is the farther end of a spurious edge, and the edge
//! kinds and the skeleton follow (Defs 3.5–3.7). Tests compare the result
//! with the map-side skeleton of the same viewpoint.

use rug::Integer;
use std::cmp::Ordering;
use wai_exact::{orientation_rat, Orientation, RatPoint};
use wai_visibility::{LineLabel, SkeletonKey};

/// Why a polygon is not the visibility polygon of any point of any map.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum ViewError {
    #[error("a visibility polygon has at least 3 vertices; this one has {0}")]
    TooFew(usize),
    #[error("vertices {0} and {1} are the same point")]
    Repeated(usize, usize),
    #[error("vertex {0} is the robot's position (the origin); the robot lies inside what it sees")]
    AtRobot(usize),
    #[error("edge {0} (vertex {0} to {1}) turns clockwise around the robot: the polygon is not star-shaped from the origin")]
    NotStarShaped(usize, usize),
    #[error("edge {0} (vertex {0} to {1}) passes through the robot's position")]
    ThroughRobot(usize, usize),
    #[error("edges {0} and {1} run back along one ray from the robot (a spike of no width)")]
    Spike(usize, usize),
    #[error("the boundary winds {0} times around the robot, not once (self-intersecting)")]
    Winding(usize),
    #[error("the polygon has zero area")]
    Degenerate,
}

/// A checked visibility polygon relative to the robot: counter-clockwise,
/// star-shaped from the origin o, which lies in its interior, with no 180°
/// vertex (removed on input, as for maps).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RobotView {
    vertices: Vec<RatPoint>,
    /// What normalisation changed (reversed orientation, dropped vertices).
    notes: Vec<String>,
}

/// V* computed from V (Alg 3.13 steps 1–3): the key the preprocessed
/// structure is searched with, and where the robot is relative to v0.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ViewSkeleton {
    pub key: SkeletonKey,
    /// The robot's position relative to the skeleton origin v0: o − v0.
    pub robot: RatPoint,
    /// The index of v0 among V's vertices.
    pub origin_index: usize,
}

/// Why V* could not be formed although V is a star-shaped polygon: no map
/// point sees such a V (a localization answers "nowhere" with this reason).
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum NoSkeleton {
    #[error("non-spurious vertex {0} is not at an integer offset from v0 in map units, so it is no map vertex of any placement")]
    OffGrid(usize),
    #[error("between non-spurious vertices {0} and {1} the boundary has {2} non-spurious edges, not 1 (Def 3.7)")]
    BadPath(usize, usize, usize),
    #[error("V has no non-spurious vertex")]
    NoVertex,
}

fn origin() -> RatPoint {
    RatPoint::from_i128(0, 0, 1).expect("w = 1")
}

/// The sign of the cross product a × b (of positions relative to o).
fn cross(a: &RatPoint, b: &RatPoint) -> Ordering {
    (Integer::from(a.hx() * b.hy()) - Integer::from(a.hy() * b.hx())).cmp0()
}

/// The sign of the dot product a · b.
fn dot(a: &RatPoint, b: &RatPoint) -> Ordering {
    (Integer::from(a.hx() * b.hx()) + Integer::from(a.hy() * b.hy())).cmp0()
}

/// 0 for directions in [0, π), 1 for [π, 2π).
fn half(p: &RatPoint) -> u8 {
    match (p.hy().cmp0(), p.hx().cmp0()) {
        (Ordering::Greater, _) | (Ordering::Equal, Ordering::Greater) => 0,
        _ => 1,
    }
}

/// Whether the direction of `b` comes strictly before that of `a` in
/// [0, 2π), for `a`, `b` not on one ray.
fn angle_less(b: &RatPoint, a: &RatPoint) -> bool {
    match half(b).cmp(&half(a)) {
        Ordering::Less => true,
        Ordering::Greater => false,
        Ordering::Equal => cross(b, a) == Ordering::Greater,
    }
}

fn sub(a: &RatPoint, b: &RatPoint) -> RatPoint {
    let (aw, bw) = (a.hw(), b.hw());
    RatPoint::new(
        Integer::from(a.hx() * bw) - Integer::from(b.hx() * aw),
        Integer::from(a.hy() * bw) - Integer::from(b.hy() * aw),
        Integer::from(aw * bw),
    )
    .expect("positive denominators")
}

fn neg(a: &RatPoint) -> RatPoint {
    RatPoint::new(-a.hx().clone(), -a.hy().clone(), a.hw().clone()).expect("w > 0")
}

/// The label (a, b, c) of the line through `p` and `q`, in coordinates
/// relative to `o`: a·x + b·y = c, primitive, a > 0 or a = 0 < b.
pub(crate) fn label_through(p: &RatPoint, q: &RatPoint, o: &RatPoint) -> LineLabel {
    let (p, q) = (sub(p, o), sub(q, o));
    // The homogeneous line p × q: A·x + B·y + C·w = 0.
    let a = Integer::from(p.hy() * q.hw()) - Integer::from(p.hw() * q.hy());
    let b = Integer::from(p.hw() * q.hx()) - Integer::from(p.hx() * q.hw());
    let c = Integer::from(p.hy() * q.hx()) - Integer::from(p.hx() * q.hy());
    let g = Integer::from(a.gcd_ref(&b)).gcd(&c);
    let (mut a, mut b, mut c) = (a / &g, b / &g, c / &g);
    if a < 0 || (a == 0 && b < 0) {
        a = -a;
        b = -b;
        c = -c;
    }
    LineLabel { a, b, c }
}

impl RobotView {
    /// Check and normalise V, its vertices in map units relative to the
    /// robot. A clockwise polygon is reversed and 180° vertices are dropped;
    /// both are recorded in [`RobotView::notes`].
    pub fn new(mut v: Vec<RatPoint>) -> Result<RobotView, ViewError> {
        let mut notes = Vec::new();
        if v.len() < 3 {
            return Err(ViewError::TooFew(v.len()));
        }
        let o = origin();
        let m = v.len();
        for i in 0..m {
            if v[i] == o {
                return Err(ViewError::AtRobot(i));
            }
            if v[i] == v[(i + 1) % m] {
                return Err(ViewError::Repeated(i, (i + 1) % m));
            }
        }
        // The sign of twice the signed area, for the orientation.
        let area = {
            let mut s = rug::Rational::new();
            for i in 0..m {
                let (a, b) = (&v[i], &v[(i + 1) % m]);
                let num = Integer::from(a.hx() * b.hy()) - Integer::from(a.hy() * b.hx());
                s += rug::Rational::from((num, Integer::from(a.hw() * b.hw())));
            }
            s.cmp0()
        };
        match area {
            Ordering::Equal => return Err(ViewError::Degenerate),
            Ordering::Less => {
                v.reverse();
                notes.push("the polygon was clockwise; reversed".to_string());
            }
            Ordering::Greater => {}
        }
        // Star-shaped from o, and radially monotone.
        let mut wraps = 0usize;
        for i in 0..m {
            let j = (i + 1) % m;
            match cross(&v[i], &v[j]) {
                Ordering::Less => return Err(ViewError::NotStarShaped(i, j)),
                Ordering::Equal => {
                    if dot(&v[i], &v[j]) != Ordering::Greater {
                        return Err(ViewError::ThroughRobot(i, j));
                    }
                }
                Ordering::Greater => {
                    if angle_less(&v[j], &v[i]) {
                        wraps += 1;
                    }
                }
            }
        }
        if wraps != 1 {
            return Err(ViewError::Winding(wraps));
        }
        // Consecutive radial edges: a reversal is a spike; the same
        // direction is a 180° vertex. Consecutive collinear sweeping edges
        // are 180° vertices too.
        let mut keep = vec![true; m];
        for i in 0..m {
            let (h, j) = ((i + m - 1) % m, (i + 1) % m);
            if orientation_rat(&v[h], &v[i], &v[j]) == Orientation::Collinear {
                let back = dot(&sub(&v[i], &v[h]), &sub(&v[j], &v[i])) != Ordering::Greater;
                if back {
                    return Err(ViewError::Spike(h, i));
                }
                keep[i] = false;
            }
        }
        let dropped = keep.iter().filter(|k| !**k).count();
        if dropped > 0 {
            notes.push(format!(
                "{dropped} vertices with a straight (180°) angle removed"
            ));
            v = v
                .into_iter()
                .zip(&keep)
                .filter(|(_, k)| **k)
                .map(|(p, _)| p)
                .collect();
        }
        Ok(RobotView { vertices: v, notes })
    }

    /// V_p of a map viewpoint `p`, as the robot at `p` sees it: every vertex
    /// minus `p`.
    pub fn from_visibility(vp: &wai_visibility::VisibilityPolygon) -> RobotView {
        let p = vp.viewpoint();
        RobotView {
            vertices: vp.vertices().iter().map(|u| sub(&u.point, p)).collect(),
            notes: Vec::new(),
        }
    }

    /// The vertices, counter-clockwise, relative to the robot.
    pub fn vertices(&self) -> &[RatPoint] {
        &self.vertices
    }

    /// What [`RobotView::new`] changed.
    pub fn notes(&self) -> &[String] {
        &self.notes
    }

    /// V translated so that the robot stands at `p`.
    pub fn placed_at(&self, p: &RatPoint) -> Vec<RatPoint> {
        self.vertices.iter().map(|u| sub(u, &neg(p))).collect()
    }

    /// Whether edge `i` is spurious (Def 3.4): collinear with the robot.
    pub fn is_spurious_edge(&self, i: usize) -> bool {
        let m = self.vertices.len();
        cross(&self.vertices[i], &self.vertices[(i + 1) % m]) == Ordering::Equal
    }

    /// Which vertices are spurious (Def 3.4): the farther ends of spurious
    /// edges.
    pub fn spurious_vertices(&self) -> Vec<bool> {
        let v = &self.vertices;
        let m = v.len();
        let mut s = vec![false; m];
        for i in 0..m {
            let j = (i + 1) % m;
            if self.is_spurious_edge(i) {
                // On one ray: the farther one has the larger dot with itself
                // along the ray, i.e. (v_j − v_i) · v_i > 0 means j is farther.
                let far = if dot(&sub(&v[j], &v[i]), &v[i]) == Ordering::Greater {
                    j
                } else {
                    i
                };
                s[far] = true;
            }
        }
        s
    }

    /// V* from V (Def 3.7): v0 is the leftmost, then lowest, non-spurious
    /// vertex reflex in V (else of all non-spurious vertices), as the
    /// map-side skeleton chooses it; offsets from v0 must be integers (map
    /// vertices differ by integer vectors in map units).
    pub fn skeleton(&self) -> Result<ViewSkeleton, NoSkeleton> {
        let v = &self.vertices;
        let m = v.len();
        let spurious = self.spurious_vertices();
        let kept: Vec<usize> = (0..m).filter(|&i| !spurious[i]).collect();
        if kept.is_empty() {
            return Err(NoSkeleton::NoVertex);
        }
        let reflex: Vec<usize> = kept
            .iter()
            .copied()
            .filter(|&i| {
                orientation_rat(&v[(i + m - 1) % m], &v[i], &v[(i + 1) % m])
                    == Orientation::Clockwise
            })
            .collect();
        let pool = if reflex.is_empty() { &kept } else { &reflex };
        let lex = |a: &RatPoint, b: &RatPoint| {
            let x = (Integer::from(a.hx() * b.hw()) - Integer::from(b.hx() * a.hw())).cmp0();
            x.then_with(|| (Integer::from(a.hy() * b.hw()) - Integer::from(b.hy() * a.hw())).cmp0())
        };
        let o0 = *pool
            .iter()
            .min_by(|&&a, &&b| lex(&v[a], &v[b]))
            .expect("non-empty");
        let start = kept.iter().position(|&i| i == o0).expect("kept");
        let mut order = kept.clone();
        order.rotate_left(start);
        let v0 = &v[o0];
        let k = order.len();
        let mut offsets = Vec::with_capacity(k);
        let mut labels = Vec::with_capacity(k);
        for s in 0..k {
            let (i, j) = (order[s], order[(s + 1) % k]);
            let off = sub(&v[i], v0).to_point().ok_or(NoSkeleton::OffGrid(i))?;
            offsets.push((off.x, off.y));
            let path: Vec<usize> = {
                let mut p = vec![i];
                let mut e = (i + 1) % m;
                while e != j {
                    p.push(e);
                    e = (e + 1) % m;
                }
                p
            };
            let solid: Vec<usize> = path
                .iter()
                .copied()
                .filter(|&e| !self.is_spurious_edge(e))
                .collect();
            match (path.len(), solid.as_slice()) {
                (1, [_]) => labels.push(None),
                (_, [e]) => labels.push(Some(label_through(&v[*e], &v[(*e + 1) % m], v0))),
                (_, other) => return Err(NoSkeleton::BadPath(i, j, other.len())),
            }
        }
        Ok(ViewSkeleton {
            key: SkeletonKey { offsets, labels },
            robot: neg(v0),
            origin_index: o0,
        })
    }

    /// V relative to v0 = `v[origin_index]`, starting there: the form
    /// [`wai_visibility::reconstruct`] returns, to compare with.
    pub fn from_origin(&self, origin_index: usize) -> Vec<RatPoint> {
        let v = &self.vertices;
        let m = v.len();
        (0..m)
            .map(|s| sub(&v[(origin_index + s) % m], &v[origin_index]))
            .collect()
    }
}
