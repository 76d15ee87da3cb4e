//! The local matching step the thesis leaves out (sec. 6.10: "this
//! postprocessing step was not implemented"): from a cell's centre and the
//! rotation the PCM found, refine the pose by point-to-line ICP against
//! the map's walls, then score it by how well the scan's ranges agree with
//! the ranges the map predicts there.
//!
//! Each ICP step pairs every scan point (in the map frame of the current
//! pose) with the nearest wall within a gate, and solves the linearised
//! least-squares problem for (dx, dy, dθ) in the normal equations
//! (nalgebra, 3×3), with Cauchy weights so that unknown obstacles and wrong
//! pairs pull less. The gates shrink stage by stage (coarse to fine), so a
//! start a metre or two off still finds its walls.

use nalgebra::{Matrix3, Vector3};

use crate::walls::Walls;
use crate::{Pose, Scan};

/// How ICP runs.
#[derive(Debug, Clone, PartialEq)]
pub struct IcpOptions {
    /// The pairing gates, one stage each, in input units.
    pub gates: Vec<f64>,
    /// The most iterations per stage.
    pub iterations: usize,
    /// The Cauchy scale of the residual weights.
    pub cauchy: f64,
    /// Use every k-th point in all stages but the last.
    pub coarse_stride: usize,
}

impl Default for IcpOptions {
    fn default() -> Self {
        IcpOptions {
            gates: vec![2.0, 1.0, 0.5, 0.2],
            iterations: 8,
            cauchy: 0.1,
            coarse_stride: 8,
        }
    }
}

/// Refine `start` so that the robot-frame `points` lie on the walls:
/// [`coarse`], then [`fine`].
pub fn refine(walls: &Walls, points: &[(f64, f64)], start: Pose, opts: &IcpOptions) -> Pose {
    fine(walls, points, coarse(walls, points, start, opts), opts)
}

/// Every stage but the last, on every `coarse_stride`-th point: where a
/// start converges to, cheaply (the localizer merges starts that land on
/// one place before refining them further).
pub fn coarse(walls: &Walls, points: &[(f64, f64)], start: Pose, opts: &IcpOptions) -> Pose {
    let stages = &opts.gates[..opts.gates.len().saturating_sub(1)];
    let mut pose = start;
    for &gate in stages {
        pose = iterate(walls, points, pose, gate, opts.coarse_stride.max(1), opts);
    }
    pose
}

/// The last stage, on every point.
pub fn fine(walls: &Walls, points: &[(f64, f64)], start: Pose, opts: &IcpOptions) -> Pose {
    let mut pose = match opts.gates.last() {
        Some(&gate) => iterate(walls, points, start, gate, 1, opts),
        None => start,
    };
    pose.heading = wrap(pose.heading);
    pose
}

fn iterate(
    walls: &Walls,
    points: &[(f64, f64)],
    start: Pose,
    gate: f64,
    stride: usize,
    opts: &IcpOptions,
) -> Pose {
    let mut pose = start;
    for _ in 0..opts.iterations {
        let Some(step) = step(walls, points, &pose, gate, stride, opts.cauchy) else {
            break;
        };
        pose.x += step.x;
        pose.y += step.y;
        pose.heading += step.z;
        if step.x.hypot(step.y) < 1e-4 && step.z.abs() < 1e-5 {
            break;
        }
    }
    pose
}

/// One Gauss–Newton step, or `None` when too few points pair.
fn step(
    walls: &Walls,
    points: &[(f64, f64)],
    pose: &Pose,
    gate: f64,
    stride: usize,
    cauchy: f64,
) -> Option<Vector3<f64>> {
    let (sin, cos) = pose.heading.sin_cos();
    let mut h = Matrix3::<f64>::zeros();
    let mut b = Vector3::<f64>::zeros();
    let mut paired = 0usize;
    for q in points.iter().step_by(stride) {
        let r = (cos * q.0 - sin * q.1, sin * q.0 + cos * q.1);
        let p = (pose.x + r.0, pose.y + r.1);
        let Some(near) = walls.nearest_facing(p, gate, Some((pose.x, pose.y))) else {
            continue;
        };
        let n = near.normal;
        let e = n.0 * (p.0 - near.point.0) + n.1 * (p.1 - near.point.1);
        // d p / d θ = (−r.y, r.x).
        let j = Vector3::new(n.0, n.1, n.0 * -r.1 + n.1 * r.0);
        let w = 1.0 / (1.0 + (e / cauchy).powi(2));
        h += w * j * j.transpose();
        b += w * e * j;
        paired += 1;
    }
    if paired < 6 {
        return None;
    }
    // A touch of damping keeps a corridor's unconstrained direction still.
    let damped = h + Matrix3::identity() * (1e-6 * h.trace().max(1e-12));
    damped.lu().solve(&(-b))
}

/// How well `scan` agrees with the map seen from `pose`: the mean over the
/// beams of min(e², τ²). For a return, e is the difference of measured and
/// predicted range; a lost return says "beyond `cap`" (the scan model of
/// [`crate::range`]), so e is how far the predicted range falls short of
/// `cap`, and 0 when the map puts the wall beyond it (with `cap` infinite a
/// lost beam costs τ²: no wall of a closed map is beyond every range). The
/// noise-free truth scores 0; noise σ scores ≈ σ².
pub fn score(walls: &Walls, scan: &Scan, pose: &Pose, cap: f64, tau: f64) -> f64 {
    score_strided(walls, scan, pose, cap, tau, 1)
}

/// [`score`] on every `stride`-th beam: a cheap estimate that lets the
/// localizer drop hopeless landings before refining them.
pub fn score_strided(
    walls: &Walls,
    scan: &Scan,
    pose: &Pose,
    cap: f64,
    tau: f64,
    stride: usize,
) -> f64 {
    let stride = stride.max(1);
    let t2 = tau * tau;
    let total: f64 = scan
        .angles
        .iter()
        .zip(&scan.ranges)
        .step_by(stride)
        .map(|(a, r)| {
            let predicted = walls.range(pose, *a);
            match r {
                Some(r) => (r - predicted).powi(2).min(t2),
                None if cap.is_finite() => (cap - predicted).max(0.0).powi(2).min(t2),
                None => t2,
            }
        })
        .sum();
    total / scan.angles.len().div_ceil(stride).max(1) as f64
}

/// An angle in (−π, π].
pub fn wrap(a: f64) -> f64 {
    let w = a.rem_euclid(std::f64::consts::TAU);
    if w > std::f64::consts::PI {
        w - std::f64::consts::TAU
    } else {
        w
    }
}
