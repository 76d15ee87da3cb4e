//! The Hausdorff distance of sec. 6.6 (eqs. 6.2 and 6.3) between scan
//! points and polygon boundaries, its k-th ranked (partial) variant, and
//! the thesis's scan-to-cell distance.
//!
//! # What is exact and what is bounded
//! - From a finite point set A to a point set or a set of segments B,
//!   δ→(A, B) = max_a min_b ‖a − b‖ is computed exactly (up to `f64`
//!   rounding of each point-to-segment distance): a finite max of finite
//!   mins.
//! - From a set of segments A, the sup runs over infinitely many points.
//!   Along a segment of A, d(x) = dist(x, B) = min_j d_j(x) is 1-Lipschitz
//!   and each d_j (distance to one feature of B) is convex, so on a piece
//!   of length ℓ with end values d₀, d₁ it is at most (d₀ + d₁ + ℓ)/2 and
//!   at most min_j max(d_j at the ends). [`directed_segments_to_points`]
//!   and [`directed_segments_to_segments`] bisect the pieces whose bound
//!   exceeds the best value found by more than `tol`: the result r is an
//!   attained value, so r ≤ δ→(A, B) ≤ r + tol (a certified bound, not a
//!   sample).
//!
//! # The k-th Hausdorff distance
//! Huttenlocher's partial distance ranks the distances d(a, B), a ∈ A,
//! in ascending order and takes the k-th instead of the largest: with
//! k = |A| it is δ→(A, B); with k = |A| − o it ignores any o points of A,
//! so o outliers (returns off unknown obstacles, sec. 6.9) cannot raise
//! it.
//!
//! # Scan to cell
//! As in sec. 6.6, the scan is placed into a visibility cell by a pose:
//! its origin at a point of the cell (the cell's [`centre_of_gravity`])
//! with a known heading (exact compass), and the distance is the directed
//! δ→(S, ∂V) from the scan to the polygon's boundary (the direction that
//! stays finite for skeletons with artificial edges).

use crate::polar::Pt;
use crate::walls::Segment;
use crate::Pose;

/// Why a Hausdorff distance could not be computed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum HausdorffError {
    #[error("the set {0} is empty")]
    Empty(&'static str),
    #[error("a coordinate of {0} is not finite")]
    NotFinite(&'static str),
    #[error("the rank {k} is not in 1..={n}")]
    BadRank { k: usize, n: usize },
    #[error("the tolerance {0} is not finite and > 0")]
    BadTolerance(f64),
    #[error("the polygon has {0} vertices or zero area: no centre of gravity")]
    Degenerate(usize),
}

fn check_points(a: &[Pt], name: &'static str) -> Result<(), HausdorffError> {
    if a.is_empty() {
        return Err(HausdorffError::Empty(name));
    }
    if a.iter().any(|p| !(p.0.is_finite() && p.1.is_finite())) {
        return Err(HausdorffError::NotFinite(name));
    }
    Ok(())
}

fn check_segments(a: &[Segment], name: &'static str) -> Result<(), HausdorffError> {
    if a.is_empty() {
        return Err(HausdorffError::Empty(name));
    }
    if a.iter()
        .flatten()
        .any(|p| !(p.0.is_finite() && p.1.is_finite()))
    {
        return Err(HausdorffError::NotFinite(name));
    }
    Ok(())
}

fn check_tol(tol: f64) -> Result<(), HausdorffError> {
    if tol.is_finite() && tol > 0.0 {
        Ok(())
    } else {
        Err(HausdorffError::BadTolerance(tol))
    }
}

fn dist(a: Pt, b: Pt) -> f64 {
    (a.0 - b.0).hypot(a.1 - b.1)
}

/// The distance from `p` to the segment `s` (its nearest point, an end or
/// the foot of the perpendicular).
pub fn point_segment_distance(p: Pt, s: &Segment) -> f64 {
    let [a, b] = *s;
    let e = (b.0 - a.0, b.1 - a.1);
    let len2 = e.0 * e.0 + e.1 * e.1;
    if len2 == 0.0 {
        return dist(p, a);
    }
    let t = (((p.0 - a.0) * e.0 + (p.1 - a.1) * e.1) / len2).clamp(0.0, 1.0);
    dist(p, (a.0 + t * e.0, a.1 + t * e.1))
}

fn to_points(p: Pt, b: &[Pt]) -> f64 {
    b.iter().map(|&q| dist(p, q)).fold(f64::INFINITY, f64::min)
}

fn to_segments(p: Pt, b: &[Segment]) -> f64 {
    b.iter()
        .map(|s| point_segment_distance(p, s))
        .fold(f64::INFINITY, f64::min)
}

/// Eq. 6.3 between finite point sets: δ→(A, B) = max_a min_b ‖a − b‖.
pub fn directed_points(a: &[Pt], b: &[Pt]) -> Result<f64, HausdorffError> {
    check_points(a, "A")?;
    check_points(b, "B")?;
    Ok(a.iter().map(|&p| to_points(p, b)).fold(0.0, f64::max))
}

/// Eq. 6.2 between finite point sets: max(δ→(A, B), δ→(B, A)).
pub fn hausdorff_points(a: &[Pt], b: &[Pt]) -> Result<f64, HausdorffError> {
    Ok(directed_points(a, b)?.max(directed_points(b, a)?))
}

/// Eq. 6.3 from a finite point set to the union of segments `b` (e.g. a
/// polygon's boundary), exactly.
pub fn directed_points_to_segments(a: &[Pt], b: &[Segment]) -> Result<f64, HausdorffError> {
    check_points(a, "A")?;
    check_segments(b, "B")?;
    Ok(a.iter().map(|&p| to_segments(p, b)).fold(0.0, f64::max))
}

/// The largest value over the segments `a` of d(x) = min_j d_j(x), where
/// each d_j (the distance to one point or segment of B) is convex and
/// 1-Lipschitz, to within `tol` below (module docs). On a piece [p, q] of
/// length ℓ, d is at most (d(p) + d(q) + ℓ)/2 (Lipschitz) and at most
/// min_j max(d_j(p), d_j(q)) (each d_j is convex, so below its larger end
/// value); a piece is bisected only while the smaller bound exceeds the
/// best value found by more than `tol`. The convexity bound closes at
/// once a piece whose two ends have the same nearest feature, so a flat
/// stretch (a segment parallel to a wall) costs nothing; the bisection
/// only chases the points where the nearest feature changes.
fn sup_over_segments(a: &[Segment], nb: usize, dj: impl Fn(usize, Pt) -> f64, tol: f64) -> f64 {
    let d = |x: Pt| (0..nb).map(|j| dj(j, x)).fold(f64::INFINITY, f64::min);
    let convex_bound = |p: Pt, q: Pt| {
        (0..nb)
            .map(|j| dj(j, p).max(dj(j, q)))
            .fold(f64::INFINITY, f64::min)
    };
    let mut best: f64 = 0.0;
    // (start, end, d(start), d(end))
    let mut stack: Vec<(Pt, Pt, f64, f64)> = Vec::new();
    for s in a {
        let (d0, d1) = (d(s[0]), d(s[1]));
        best = best.max(d0).max(d1);
        stack.push((s[0], s[1], d0, d1));
    }
    while let Some((p, q, d0, d1)) = stack.pop() {
        if (d0 + d1 + dist(p, q)) / 2.0 <= best + tol || convex_bound(p, q) <= best + tol {
            continue;
        }
        let m = ((p.0 + q.0) / 2.0, (p.1 + q.1) / 2.0);
        if m == p || m == q {
            // No representable point between: the piece is done.
            continue;
        }
        let dm = d(m);
        best = best.max(dm);
        stack.push((p, m, d0, dm));
        stack.push((m, q, dm, d1));
    }
    best
}

/// Eq. 6.3 from the union of segments `a` to a finite point set `b`, to
/// within `tol`: the result r satisfies r ≤ δ→(A, B) ≤ r + tol.
pub fn directed_segments_to_points(
    a: &[Segment],
    b: &[Pt],
    tol: f64,
) -> Result<f64, HausdorffError> {
    check_segments(a, "A")?;
    check_points(b, "B")?;
    check_tol(tol)?;
    Ok(sup_over_segments(a, b.len(), |j, p| dist(p, b[j]), tol))
}

/// Eq. 6.3 between unions of segments, to within `tol`: the result r
/// satisfies r ≤ δ→(A, B) ≤ r + tol.
pub fn directed_segments_to_segments(
    a: &[Segment],
    b: &[Segment],
    tol: f64,
) -> Result<f64, HausdorffError> {
    check_segments(a, "A")?;
    check_segments(b, "B")?;
    check_tol(tol)?;
    Ok(sup_over_segments(
        a,
        b.len(),
        |j, p| point_segment_distance(p, &b[j]),
        tol,
    ))
}

/// Eq. 6.2 between a finite point set and a union of segments (scan
/// points against a polygon boundary), to within `tol` below.
pub fn hausdorff_points_segments(a: &[Pt], b: &[Segment], tol: f64) -> Result<f64, HausdorffError> {
    Ok(directed_points_to_segments(a, b)?.max(directed_segments_to_points(b, a, tol)?))
}

/// Eq. 6.2 between unions of segments, to within `tol` below.
pub fn hausdorff_segments(a: &[Segment], b: &[Segment], tol: f64) -> Result<f64, HausdorffError> {
    Ok(directed_segments_to_segments(a, b, tol)?.max(directed_segments_to_segments(b, a, tol)?))
}

fn kth(mut d: Vec<f64>, k: usize) -> Result<f64, HausdorffError> {
    if k == 0 || k > d.len() {
        return Err(HausdorffError::BadRank { k, n: d.len() });
    }
    let (_, v, _) = d.select_nth_unstable_by(k - 1, f64::total_cmp);
    Ok(*v)
}

/// The k-th Hausdorff distance (Huttenlocher's partial δ→, a robust form
/// of eq. 6.3): the k-th smallest of d(a, B), a ∈ A, k in 1..=|A|.
pub fn kth_directed_points(a: &[Pt], b: &[Pt], k: usize) -> Result<f64, HausdorffError> {
    check_points(a, "A")?;
    check_points(b, "B")?;
    kth(a.iter().map(|&p| to_points(p, b)).collect(), k)
}

/// The k-th Hausdorff distance from a finite point set to a union of
/// segments: the k-th smallest of d(a, B), a ∈ A.
pub fn kth_directed_points_to_segments(
    a: &[Pt],
    b: &[Segment],
    k: usize,
) -> Result<f64, HausdorffError> {
    check_points(a, "A")?;
    check_segments(b, "B")?;
    kth(a.iter().map(|&p| to_segments(p, b)).collect(), k)
}

/// The scan points (robot frame, x ahead) in the map frame at `pose`.
pub fn place(points: &[Pt], pose: &Pose) -> Vec<Pt> {
    let (s, c) = pose.heading.sin_cos();
    points
        .iter()
        .map(|&(x, y)| (pose.x + c * x - s * y, pose.y + s * x + c * y))
        .collect()
}

/// The scan-to-cell distance of sec. 6.6: the scan `points` (robot frame)
/// placed at `pose` (a point of the cell, e.g. its [`centre_of_gravity`],
/// and the compass heading), then δ→(S, ∂V) (eq. 6.3) to the polygon
/// `boundary`, exactly.
pub fn scan_to_polygon(
    points: &[Pt],
    pose: &Pose,
    boundary: &[Segment],
) -> Result<f64, HausdorffError> {
    directed_points_to_segments(&place(points, pose), boundary)
}

/// [`scan_to_polygon`] with the k-th Hausdorff distance instead of the
/// maximum: robust to |S| − k returns off unknown obstacles.
pub fn scan_to_polygon_kth(
    points: &[Pt],
    pose: &Pose,
    boundary: &[Segment],
    k: usize,
) -> Result<f64, HausdorffError> {
    kth_directed_points_to_segments(&place(points, pose), boundary, k)
}

/// The boundary segments of the polygon with `vertices` (closed ring).
pub fn boundary(vertices: &[Pt]) -> Vec<Segment> {
    let n = vertices.len();
    (0..n)
        .map(|i| [vertices[i], vertices[(i + 1) % n]])
        .collect()
}

/// The centre of gravity (area centroid) of the simple polygon with
/// `vertices`, where sec. 6.6 places the scan in a cell.
pub fn centre_of_gravity(vertices: &[Pt]) -> Result<Pt, HausdorffError> {
    check_points(vertices, "the polygon")?;
    let n = vertices.len();
    if n < 3 {
        return Err(HausdorffError::Degenerate(n));
    }
    // Relative to the first vertex, to keep the shoelace sums small.
    let o = vertices[0];
    let (mut area2, mut cx, mut cy) = (0.0, 0.0, 0.0);
    for i in 0..n {
        let a = (vertices[i].0 - o.0, vertices[i].1 - o.1);
        let b = (vertices[(i + 1) % n].0 - o.0, vertices[(i + 1) % n].1 - o.1);
        let w = a.0 * b.1 - a.1 * b.0;
        area2 += w;
        cx += (a.0 + b.0) * w;
        cy += (a.1 + b.1) * w;
    }
    if area2 == 0.0 || !area2.is_finite() {
        return Err(HausdorffError::Degenerate(n));
    }
    Ok((o.0 + cx / (3.0 * area2), o.1 + cy / (3.0 * area2)))
}
