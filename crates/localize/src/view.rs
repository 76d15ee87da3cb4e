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

use crate::fast::{cmp_products, det2};
use crate::small_triple;
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
    /// The vertices as `i128` homogeneous triples when every coordinate is
    /// below 2^126 in magnitude (so that negation and `unsigned_abs` are
    /// safe): the fast path of [`crate::fast`]. Derived from `vertices`.
    fast: Option<Vec<[i128; 3]>>,
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

/// The label (a, b, c) of the line through `p` and `q`, in coordinates
/// relative to `o`: a·x + b·y = c, primitive, a > 0 or a = 0 < b.
pub(crate) fn label_through(p: &RatPoint, q: &RatPoint, o: &RatPoint) -> LineLabel {
    let (p, q) = (p.sub(o), q.sub(o));
    // The homogeneous line p × q: A·x + B·y + C·w = 0.
    let a = Integer::from(p.hy() * q.hw()) - Integer::from(p.hw() * q.hy());
    let b = Integer::from(p.hw() * q.hx()) - Integer::from(p.hx() * q.hw());
    // a·x + b·y = c with c = −C.
    let c = Integer::from(p.hy() * q.hx()) - Integer::from(p.hx() * q.hy());
    LineLabel::normalized(a, b, c)
}

/// (nx/den, ny/den) if den divides both: in i64 where the values fit
/// (`i128` division is a slow library call), one division each, checked by
/// a product.
fn exact_quotients(nx: i128, ny: i128, den: i128) -> Option<(i128, i128)> {
    if let (Ok(nx), Ok(ny), Ok(den)) = (i64::try_from(nx), i64::try_from(ny), i64::try_from(den)) {
        let (qx, qy) = (nx / den, ny / den);
        return (qx * den == nx && qy * den == ny).then(|| (i128::from(qx), i128::from(qy)));
    }
    (nx % den == 0 && ny % den == 0).then(|| (nx / den, ny / den))
}

impl RobotView {
    /// Check and normalise V, its vertices in map units relative to the
    /// robot. A clockwise polygon is reversed and 180° vertices are dropped;
    /// both are recorded in [`RobotView::notes`].
    pub fn new(v: Vec<RatPoint>) -> Result<RobotView, ViewError> {
        let notes = Vec::new();
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
        let mut view = RobotView::build(v, notes);
        // Orientation: a counter-clockwise star-shaped polygon turns
        // counter-clockwise around the robot (or runs along a ray) at every
        // edge; a clockwise one the other way. Mixed turns are refused below.
        let mut turns: Vec<Ordering> = (0..m).map(|i| view.cross_ij(i, (i + 1) % m)).collect();
        if turns.iter().all(|t| *t == Ordering::Equal) {
            return Err(ViewError::Degenerate);
        }
        if !turns.contains(&Ordering::Greater) {
            view.vertices.reverse();
            if let Some(f) = &mut view.fast {
                f.reverse();
            }
            view.notes
                .push("the polygon was clockwise; reversed".to_string());
            turns = (0..m).map(|i| view.cross_ij(i, (i + 1) % m)).collect();
        }
        // Star-shaped from o, and radially monotone.
        let mut wraps = 0usize;
        for (i, turn) in turns.iter().enumerate() {
            let j = (i + 1) % m;
            match turn {
                Ordering::Less => return Err(ViewError::NotStarShaped(i, j)),
                Ordering::Equal => {
                    if view.dot_ij(i, j) != Ordering::Greater {
                        return Err(ViewError::ThroughRobot(i, j));
                    }
                }
                Ordering::Greater => {
                    if view.angle_before(j, i) {
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
        let v = &view.vertices;
        let mut keep = vec![true; m];
        for i in 0..m {
            let (h, j) = ((i + m - 1) % m, (i + 1) % m);
            if view.orient(h, i, j) == Orientation::Collinear {
                let back = v[i].sub(&v[h]).dot_sign(&v[j].sub(&v[i])) != Ordering::Greater;
                if back {
                    return Err(ViewError::Spike(h, i));
                }
                keep[i] = false;
            }
        }
        let dropped = keep.iter().filter(|k| !**k).count();
        if dropped == 0 {
            return Ok(view);
        }
        let RobotView {
            vertices,
            mut notes,
            ..
        } = view;
        notes.push(format!(
            "{dropped} vertices with a straight (180°) angle removed"
        ));
        let v = vertices
            .into_iter()
            .zip(&keep)
            .filter(|(_, k)| **k)
            .map(|(p, _)| p)
            .collect();
        Ok(RobotView::build(v, notes))
    }

    fn build(vertices: Vec<RatPoint>, notes: Vec<String>) -> RobotView {
        let fast = vertices.iter().map(small_triple).collect();
        RobotView {
            vertices,
            fast,
            notes,
        }
    }

    /// The sign of v_i × v_j (positions relative to the robot).
    #[inline]
    fn cross_ij(&self, i: usize, j: usize) -> Ordering {
        match &self.fast {
            Some(f) => cmp_products(f[i][0], f[j][1], f[i][1], f[j][0]),
            None => self.vertices[i].cross_sign(&self.vertices[j]),
        }
    }

    /// The sign of v_i · v_j.
    #[inline]
    fn dot_ij(&self, i: usize, j: usize) -> Ordering {
        match &self.fast {
            // Coordinates below 2^126: the negation is safe.
            Some(f) => cmp_products(f[i][0], f[j][0], -f[i][1], f[j][1]),
            None => self.vertices[i].dot_sign(&self.vertices[j]),
        }
    }

    /// Whether the direction of v_b comes strictly before that of v_a in
    /// [0, 2π), for v_a, v_b not on one ray.
    fn angle_before(&self, b: usize, a: usize) -> bool {
        let (pb, pa) = (&self.vertices[b], &self.vertices[a]);
        // RatPoint::compare_angle, with the cross sign's fast path.
        match pa.upper_half().cmp(&pb.upper_half()) {
            Ordering::Less => true,
            Ordering::Greater => false,
            Ordering::Equal => self.cross_ij(b, a) == Ordering::Greater,
        }
    }

    /// For v_i, v_j on one ray from the robot: whether v_j is the farther.
    #[inline]
    fn farther(&self, i: usize, j: usize) -> bool {
        if let Some(f) = &self.fast {
            // Same ray: compare one non-zero coordinate's magnitude.
            let c = if f[i][0] != 0 { 0 } else { 1 };
            return cmp_products(f[j][c].abs(), f[i][2], f[i][c].abs(), f[j][2])
                == Ordering::Greater;
        }
        let v = &self.vertices;
        v[j].sub(&v[i]).dot_sign(&v[i]) == Ordering::Greater
    }

    /// The orientation of (v_h, v_i, v_j).
    #[inline]
    fn orient(&self, h: usize, i: usize, j: usize) -> Orientation {
        if let Some(f) = &self.fast {
            let (a, b, c) = (&f[h], &f[i], &f[j]);
            if a[2] == b[2] && b[2] == c[2] {
                // One denominator (the usual case: map vertices minus the
                // robot): the numerators' orientation. Coordinates below
                // 2^126, so the differences fit.
                return match cmp_products(b[0] - a[0], c[1] - b[1], b[1] - a[1], c[0] - b[0]) {
                    Ordering::Greater => Orientation::CounterClockwise,
                    Ordering::Less => Orientation::Clockwise,
                    Ordering::Equal => Orientation::Collinear,
                };
            }
            let d = |a: &[i128; 3], b: &[i128; 3]| {
                Some((det2(b[0], a[2], a[0], b[2])?, det2(b[1], a[2], a[1], b[2])?))
            };
            if let (Some(u), Some(w)) = (d(&f[h], &f[i]), d(&f[i], &f[j])) {
                return match cmp_products(u.0, w.1, u.1, w.0) {
                    Ordering::Greater => Orientation::CounterClockwise,
                    Ordering::Less => Orientation::Clockwise,
                    Ordering::Equal => Orientation::Collinear,
                };
            }
        }
        let v = &self.vertices;
        orientation_rat(&v[h], &v[i], &v[j])
    }

    /// v_a against v_b by x, then y.
    #[inline]
    fn lex(&self, a: usize, b: usize) -> Ordering {
        if let Some(f) = &self.fast {
            let (p, q) = (&f[a], &f[b]);
            if p[2] == q[2] {
                return (p[0], p[1]).cmp(&(q[0], q[1]));
            }
            return cmp_products(p[0], q[2], q[0], p[2])
                .then_with(|| cmp_products(p[1], q[2], q[1], p[2]));
        }
        crate::cmp_points(&self.vertices[a], &self.vertices[b])
    }

    /// The label of the line through v_i and v_j relative to v_o, as
    /// [`label_through`] gives it, in `i128` when every step fits (`None`
    /// otherwise). The line is a map edge's, so its primitive normal and
    /// its offset from the map vertex v_o are small integers even when v_i
    /// and v_j are spurious vertices with large coordinates.
    fn label_fast(&self, i: usize, j: usize, o: usize) -> Option<LineLabel> {
        let f = self.fast.as_ref()?;
        let (p, q, r) = (&f[i], &f[j], &f[o]);
        // The direction q − p times p_w·q_w.
        let dx = det2(q[0], p[2], p[0], q[2])?;
        let dy = det2(q[1], p[2], p[1], q[2])?;
        let g = wai_exact::gcd_u128(dx.unsigned_abs(), dy.unsigned_abs());
        let g = i128::try_from(g).ok().filter(|&g| g > 0)?;
        let (mut a, mut b) = (dy / g, -dx / g);
        if a < 0 || (a == 0 && b < 0) {
            a = -a;
            b = -b;
        }
        // c = a·(p − o)_x + b·(p − o)_y, an integer.
        let ex = det2(p[0], r[2], r[0], p[2])?;
        let ey = det2(p[1], r[2], r[1], p[2])?;
        let den = p[2].checked_mul(r[2])?;
        let num = a.checked_mul(ex)?.checked_add(b.checked_mul(ey)?)?;
        if num % den != 0 {
            return None;
        }
        Some(LineLabel {
            a: Integer::from(a),
            b: Integer::from(b),
            c: Integer::from(num / den),
        })
    }

    /// v_i − v_o if it is an integer vector.
    fn offset(&self, i: usize, o: usize) -> Option<(i128, i128)> {
        if let Some(f) = &self.fast {
            let (p, q) = (&f[i], &f[o]);
            if p[2] == q[2] {
                // One denominator w: (p − q)/w, the differences fitting.
                let (nx, ny, w) = (p[0] - q[0], p[1] - q[1], p[2]);
                if w == 1 {
                    return Some((nx, ny));
                }
                return exact_quotients(nx, ny, w);
            }
            if let (Some(nx), Some(ny), Some(den)) = (
                det2(p[0], q[2], q[0], p[2]),
                det2(p[1], q[2], q[1], p[2]),
                p[2].checked_mul(q[2]),
            ) {
                return exact_quotients(nx, ny, den);
            }
        }
        self.vertices[i]
            .sub(&self.vertices[o])
            .to_point()
            .map(|p| (p.x, p.y))
    }

    /// V_p of a map viewpoint `p`, as the robot at `p` sees it: every vertex
    /// minus `p`.
    pub fn from_visibility(vp: &wai_visibility::VisibilityPolygon) -> RobotView {
        let p = vp.viewpoint();
        RobotView::build(
            vp.vertices().iter().map(|u| u.point.sub(p)).collect(),
            Vec::new(),
        )
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
        self.vertices.iter().map(|u| u.sub(&p.neg())).collect()
    }

    /// Whether edge `i` is spurious (Def 3.4): collinear with the robot.
    pub fn is_spurious_edge(&self, i: usize) -> bool {
        self.cross_ij(i, (i + 1) % self.vertices.len()) == Ordering::Equal
    }

    /// Which edges and which vertices are spurious (Def 3.4): the edges
    /// collinear with the robot, and the farther ends of those edges.
    pub fn classify(&self) -> (Vec<bool>, Vec<bool>) {
        let m = self.vertices.len();
        let edges: Vec<bool> = (0..m).map(|i| self.is_spurious_edge(i)).collect();
        let mut s = vec![false; m];
        for i in 0..m {
            if edges[i] {
                let j = (i + 1) % m;
                s[if self.farther(i, j) { j } else { i }] = true;
            }
        }
        (edges, s)
    }

    /// V* from V (Def 3.7): v0 is the leftmost, then lowest, non-spurious
    /// vertex reflex in V (else of all non-spurious vertices), as the
    /// map-side skeleton chooses it; offsets from v0 must be integers (map
    /// vertices differ by integer vectors in map units).
    pub fn skeleton(&self) -> Result<ViewSkeleton, NoSkeleton> {
        let v = &self.vertices;
        let m = v.len();
        let (spurious_edge, spurious) = self.classify();
        let kept: Vec<usize> = (0..m).filter(|&i| !spurious[i]).collect();
        if kept.is_empty() {
            return Err(NoSkeleton::NoVertex);
        }
        // v0: the lexicographically least kept vertex that is reflex in V,
        // else the least kept vertex. Reflexivity is tested only for a
        // vertex that would beat the best so far.
        let mut best: Option<usize> = None;
        for &i in &kept {
            if best.is_some_and(|b| self.lex(i, b) != Ordering::Less) {
                continue;
            }
            if self.orient((i + m - 1) % m, i, (i + 1) % m) == Orientation::Clockwise {
                best = Some(i);
            }
        }
        let o0 = best.unwrap_or_else(|| {
            *kept
                .iter()
                .min_by(|&&a, &&b| self.lex(a, b))
                .expect("non-empty")
        });
        let start = kept.iter().position(|&i| i == o0).expect("kept");
        let mut order = kept;
        order.rotate_left(start);
        let v0 = &v[o0];
        let k = order.len();
        let mut offsets = Vec::with_capacity(k);
        let mut labels = Vec::with_capacity(k);
        for s in 0..k {
            let (i, j) = (order[s], order[(s + 1) % k]);
            offsets.push(self.offset(i, o0).ok_or(NoSkeleton::OffGrid(i))?);
            // The edges from i to j: one solid edge, maybe with a
            // spurious edge before and after it.
            let len = (j + m - i) % m;
            let len = if len == 0 { m } else { len };
            let mut solid = None;
            let mut count = 0;
            for t in 0..len {
                let e = (i + t) % m;
                if !spurious_edge[e] {
                    count += 1;
                    solid = Some(e);
                }
            }
            match (len, solid) {
                (1, Some(_)) if count == 1 => labels.push(None),
                (_, Some(e)) if count == 1 => labels.push(Some(
                    self.label_fast(e, (e + 1) % m, o0)
                        .unwrap_or_else(|| label_through(&v[e], &v[(e + 1) % m], v0)),
                )),
                _ => return Err(NoSkeleton::BadPath(i, j, count)),
            }
        }
        Ok(ViewSkeleton {
            key: SkeletonKey { offsets, labels },
            robot: v0.neg(),
            origin_index: o0,
        })
    }

    /// V relative to v0 = `v[origin_index]`, starting there: the form
    /// [`wai_visibility::reconstruct`] returns, to compare with.
    pub fn from_origin(&self, origin_index: usize) -> Vec<RatPoint> {
        let v = &self.vertices;
        let m = v.len();
        (0..m)
            .map(|s| v[(origin_index + s) % m].sub(&v[origin_index]))
            .collect()
    }
}
