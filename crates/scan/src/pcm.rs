//! The polar coordinate metric (Def 6.3, eqs. 6.6 and 6.7) between exact,
//! piecewise PCFs ([`crate::polar::Pcf`], capped or not), and its
//! minimisation over rotations by the first approximative approach of
//! sec. 6.8.
//!
//! # The integral for one rotation (eq. 6.7), in closed form
//! [`pcm_fixed`] merges the breakpoints of pcf_P(· − t) and pcf_Q in one
//! pass, O(m + n). On each elementary interval [u, v] both functions are
//! fixed shapes, and ∫(f − g)² = ∫f² − 2∫fg + ∫g² with, for A = φ + α₁,
//! B = φ + α₂ (sin A, sin B > 0 on the interval) and δ = α₁ − α₂:
//! - ∫ c²/sin²A = c² [−cot A]ᵤᵛ = c² sin(v − u) / (sin A(u) sin A(v));
//! - ∫ c₁c₂/(sin A sin B) = c₁c₂ [ln(sin B / sin A)]ᵤᵛ / sin δ, since
//!   (ln sin B − ln sin A)' = cot B − cot A = sin δ / (sin A sin B); with
//!   sin B / sin A = cos δ − sin δ cot A this is evaluated as
//!   ln_1p(−2 sin²(δ/2) − sin δ cot A) / sin δ, accurate as δ → 0 (for
//!   δ = 0 exactly, the squared form);
//! - ∫ R c / sin A = R c [ln tan(A/2)]ᵤᵛ and ∫ R² = R² (v − u) for a
//!   capped piece (eq. 6.8).
//!
//! The sum is clamped at 0 before the square root: where the two functions
//! nearly agree, rounding in the three terms (about 1e-16 of ∫f² + ∫g²)
//! could make it slightly negative. So a PCM of exactly equal functions is
//! 0, and otherwise the absolute error is about 1e-8 · ‖pcf‖ near 0 and
//! 1e-15 relative elsewhere.
//!
//! # The minimum over rotations (eq. 6.6): an approximation
//! Sec. 6.8 calls the exact minimum hard and, as its first approach,
//! minimises only over the O(mn) rotations that put a supporting angle of
//! one PCF on a supporting angle of the other
//! ([`crate::polar::Pcf::supporting_angles`]: breakpoints and the minima of
//! the c / sin pieces). [`pcm`] does that and then refines:
//! 1. the candidate rotations: every t = s_Q − s_P, plus (a safety net
//!    that is not in the thesis) [`GRID`] equally spaced rotations, and,
//!    for a noisy compass, only those in [h − ε, h + ε] plus h and both
//!    ends;
//! 2. eq. 6.7 evaluated exactly at each, in closed form, O(m + n) each;
//! 3. golden-section search on the bracket [t_{i−1}, t_{i+1}] around each
//!    of the [`REFINED`] lowest discrete local minima t_i, down to a
//!    bracket width of [`T_TOL`] rad.
//!
//! The result is the least value of eq. 6.7 met, at its rotation. It is
//! always an *upper bound* of the true minimum (every value is an exact
//! evaluation at a real rotation), never above the best candidate, and for
//! a noisy compass never above the exact-compass value at h. It equals the
//! true minimum up to O(T_TOL²) · h'' (far below 1e-12 for polygons of
//! unit size) whenever the global minimiser lies in a refined bracket in
//! which eq. 6.7 is unimodal; nothing certifies that, and the tests compare
//! against a dense grid of rotations instead. As the thesis notes, the
//! approximation may break the triangle inequality that the exact
//! minimum satisfies; within this tolerance the tests find it holds.

use std::f64::consts::TAU;

use crate::polar::{normalise, Pcf, Piece, Shape};
use crate::Compass;

/// Extra equally spaced candidate rotations over the allowed interval (a
/// safety net beside the thesis's supporting-angle pairs).
pub const GRID: usize = 64;

/// How many of the lowest discrete local minima are refined.
pub const REFINED: usize = 8;

/// The bracket width (radians) at which golden-section search stops.
pub const T_TOL: f64 = 1e-10;

/// A minimum of eq. 6.7 over rotations: the value and the rotation t
/// (the angle pcf_P is turned by: pcf_P(φ − t) against pcf_Q(φ)).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rotation {
    pub value: f64,
    pub t: f64,
}

/// The pieces of pcf_P(· − t) over [0, 2π), in order, contiguous, the
/// first from 0 and the last to 2π. A piece's α becomes α − t.
fn rotated(p: &Pcf, t: f64) -> Vec<Piece> {
    let t = normalise(t);
    let turn = |s: Shape| match s {
        Shape::Edge { c, alpha } => Shape::Edge {
            c,
            alpha: alpha - t,
        },
        cap => cap,
    };
    let pieces = p.pieces();
    // Pieces from k on start at 2π or beyond once turned: they wrap.
    let k = pieces.partition_point(|q| q.from + t < TAU);
    let mut out = Vec::with_capacity(pieces.len() + 1);
    if k > 0 {
        let last = pieces[k - 1];
        if last.to + t > TAU {
            out.push(Piece {
                from: 0.0,
                to: last.to + t - TAU,
                shape: turn(last.shape),
            });
        }
    }
    for q in &pieces[k..] {
        out.push(Piece {
            from: q.from + t - TAU,
            to: q.to + t - TAU,
            shape: turn(q.shape),
        });
    }
    for q in &pieces[..k] {
        out.push(Piece {
            from: q.from + t,
            to: (q.to + t).min(TAU),
            shape: turn(q.shape),
        });
    }
    if let Some(first) = out.first_mut() {
        first.from = 0.0;
    }
    if let Some(last) = out.last_mut() {
        last.to = TAU;
    }
    out
}

/// ∫ᵤᵛ dφ / sin²(φ + α).
fn inv_sin_sq(alpha: f64, u: f64, v: f64) -> f64 {
    (v - u).sin() / ((u + alpha).sin() * (v + alpha).sin())
}

/// ∫ᵤᵛ dφ / (sin(φ + a1) sin(φ + a2)), both sines > 0 on [u, v].
fn inv_sin_sin(a1: f64, a2: f64, u: f64, v: f64) -> f64 {
    let delta = a1 - a2;
    let sd = delta.sin();
    if sd == 0.0 {
        return inv_sin_sq(a1, u, v);
    }
    let half = (delta / 2.0).sin();
    // ln(sin B / sin A) / sin δ with sin B / sin A − 1 = −2 sin²(δ/2) −
    // sin δ cot A, so that ln_1p keeps its precision as δ → 0.
    let term = |phi: f64| {
        let a = phi + a1;
        (-2.0 * half * half - sd * a.cos() / a.sin()).ln_1p() / sd
    };
    term(v) - term(u)
}

/// ln tan(A/2), for sin A > 0, without cancellation near A = 0 or π.
fn ln_tan_half(a: f64) -> f64 {
    let (s, c) = a.sin_cos();
    if c >= 0.0 {
        (s / (1.0 + c)).ln()
    } else {
        ((1.0 - c) / s).ln()
    }
}

/// ∫ᵤᵛ (f − g)² for the shapes f, g (the closed forms of the module docs).
fn segment_integral(f: Shape, g: Shape, u: f64, v: f64) -> f64 {
    if v <= u {
        return 0.0;
    }
    match (f, g) {
        (Shape::Cap(r1), Shape::Cap(r2)) => (r1 - r2).powi(2) * (v - u),
        (Shape::Edge { c, alpha }, Shape::Cap(r)) | (Shape::Cap(r), Shape::Edge { c, alpha }) => {
            c * c * inv_sin_sq(alpha, u, v)
                - 2.0 * r * c * (ln_tan_half(v + alpha) - ln_tan_half(u + alpha))
                + r * r * (v - u)
        }
        (Shape::Edge { c: c1, alpha: a1 }, Shape::Edge { c: c2, alpha: a2 }) => {
            if c1 == c2 && (a1 - a2).sin() == 0.0 && (a1 - a2).cos() > 0.0 {
                // The same line: the functions agree.
                return 0.0;
            }
            c1 * c1 * inv_sin_sq(a1, u, v) - 2.0 * c1 * c2 * inv_sin_sin(a1, a2, u, v)
                + c2 * c2 * inv_sin_sq(a2, u, v)
        }
    }
}

/// The squared integral norm of eq. 6.7 at rotation `t`.
fn squared(p: &Pcf, q: &Pcf, t: f64) -> f64 {
    if !t.is_finite() {
        return f64::NAN;
    }
    let a = rotated(p, t);
    let b = q.pieces();
    let (mut i, mut j, mut at, mut sum) = (0, 0, 0.0, 0.0);
    while i < a.len() && j < b.len() {
        let end = a[i].to.min(b[j].to);
        sum += segment_integral(a[i].shape, b[j].shape, at, end);
        at = at.max(end);
        if a[i].to <= end {
            i += 1;
        }
        if b[j].to <= end {
            j += 1;
        }
    }
    // Not `max`, which would turn a NaN into 0.
    if sum < 0.0 {
        0.0
    } else {
        sum
    }
}

/// Eq. 6.7: sqrt(∫₀^{2π} (pcf_P(φ − t) − pcf_Q(φ))² dφ), in closed form
/// in O(m + n) — the PCM with an exact compass (heading t). `p` and `q`
/// may be capped (eq. 6.8). The accuracy is stated in the module docs.
/// A non-finite `t` gives NaN (as does a non-finite compass in [`pcm`]).
pub fn pcm_fixed(p: &Pcf, q: &Pcf, t: f64) -> f64 {
    squared(p, q, t).sqrt()
}

/// Eq. 6.7 by the midpoint rule with `n` samples: the reference
/// [`pcm_fixed`] is tested against (error O(1/n²) for smooth pieces).
pub fn pcm_sampled(p: &Pcf, q: &Pcf, t: f64, n: usize) -> f64 {
    let n = n.max(1);
    let h = TAU / n as f64;
    let sum: f64 = (0..n)
        .map(|j| {
            let phi = (j as f64 + 0.5) * h;
            (p.value(phi - t) - q.value(phi)).powi(2)
        })
        .sum();
    (sum * h).sqrt()
}

/// The PCM of Def 6.3 under what the compass says (sec. 6.10.4):
/// - [`Compass::Exact`]`(h)`: eq. 6.7 at t = h, exactly;
/// - [`Compass::Noisy`]: the minimum of eq. 6.7 over t ∈ [h − ε, h + ε]
///   (all rotations once ε ≥ π), approximated;
/// - [`Compass::None`]: eq. 6.6, the minimum over t ∈ [0, 2π),
///   approximated.
///
/// The approximation (sec. 6.8's first approach plus golden-section
/// refinement) and its tolerance are described in the module docs.
pub fn pcm(p: &Pcf, q: &Pcf, compass: &Compass) -> Rotation {
    match *compass {
        Compass::Exact(h) => Rotation {
            value: pcm_fixed(p, q, h),
            t: normalise(h),
        },
        Compass::Noisy { heading, eps } if eps.abs() < std::f64::consts::PI => {
            minimise(p, q, heading - eps.abs(), 2.0 * eps.abs(), Some(heading))
        }
        Compass::Noisy { .. } | Compass::None => minimise(p, q, 0.0, TAU, None),
    }
}

/// The least eq. 6.7 over t = start + s, s ∈ [0, width] (`width` = 2π: the
/// whole circle, taken circularly).
fn minimise(p: &Pcf, q: &Pcf, start: f64, width: f64, centre: Option<f64>) -> Rotation {
    let circle = width >= TAU;
    let h = |s: f64| squared(p, q, start + s);
    // Candidate offsets s: supporting-angle pairs in range, the grid, the
    // ends and the centre.
    let sp = p.supporting_angles();
    let sq = q.supporting_angles();
    let mut offsets = Vec::with_capacity(sp.len() * sq.len() + GRID + 3);
    for a in &sp {
        for b in &sq {
            let s = normalise(b - a - start);
            if s <= width {
                offsets.push(s);
            }
        }
    }
    offsets.extend((0..GRID).map(|k| width * k as f64 / GRID as f64));
    if !circle {
        offsets.push(width);
    }
    if let Some(c) = centre {
        offsets.push(normalise(c - start).min(width));
    }
    offsets.sort_by(f64::total_cmp);
    offsets.dedup_by(|a, b| (*a - *b).abs() < 1e-13);
    let values: Vec<f64> = offsets.iter().map(|&s| h(s)).collect();
    let n = offsets.len();
    let mut best = (values[0], offsets[0]);
    for (&v, &s) in values.iter().zip(&offsets) {
        if v < best.0 {
            best = (v, s);
        }
    }
    // Discrete local minima and their brackets.
    let mut minima: Vec<(f64, f64, f64)> = Vec::new();
    for i in 0..n {
        let (lo, hi) = if circle {
            let lo = if i == 0 {
                offsets[n - 1] - TAU
            } else {
                offsets[i - 1]
            };
            let hi = if i + 1 == n {
                offsets[0] + TAU
            } else {
                offsets[i + 1]
            };
            (lo, hi)
        } else {
            (offsets[i.saturating_sub(1)], offsets[(i + 1).min(n - 1)])
        };
        let left = if circle {
            values[(i + n - 1) % n]
        } else {
            values[i.saturating_sub(1)]
        };
        let right = if circle {
            values[(i + 1) % n]
        } else {
            values[(i + 1).min(n - 1)]
        };
        if values[i] <= left && values[i] <= right {
            minima.push((values[i], lo, hi));
        }
    }
    minima.sort_by(|a, b| a.0.total_cmp(&b.0));
    for &(_, lo, hi) in minima.iter().take(REFINED) {
        let (v, s) = golden(&h, lo, hi);
        if v < best.0 {
            best = (v, s);
        }
    }
    Rotation {
        value: best.0.sqrt(),
        t: normalise(start + best.1),
    }
}

/// Golden-section search for a minimum of `h` on [lo, hi], to a bracket
/// width of [`T_TOL`]; the least value evaluated and where.
fn golden(h: &impl Fn(f64) -> f64, mut lo: f64, mut hi: f64) -> (f64, f64) {
    let r = (5f64.sqrt() - 1.0) / 2.0;
    let mut x1 = hi - r * (hi - lo);
    let mut x2 = lo + r * (hi - lo);
    let (mut f1, mut f2) = (h(x1), h(x2));
    let mut best = if f1 <= f2 { (f1, x1) } else { (f2, x2) };
    while hi - lo > T_TOL {
        if f1 <= f2 {
            hi = x2;
            x2 = x1;
            f2 = f1;
            x1 = hi - r * (hi - lo);
            f1 = h(x1);
            if f1 < best.0 {
                best = (f1, x1);
            }
        } else {
            lo = x1;
            x1 = x2;
            f1 = f2;
            x2 = lo + r * (hi - lo);
            f2 = h(x2);
            if f2 < best.0 {
                best = (f2, x2);
            }
        }
    }
    best
}
