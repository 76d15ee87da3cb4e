//! Polar coordinate functions sampled at equal angles, and the polar
//! coordinate metric between them (Def 6.2, Def 6.3, eqs. 6.6–6.8) as the
//! localizer's index uses it.
//!
//! A [`Signature`] is the PCF of a polygon about a kernel point, sampled at
//! the `N` map-frame angles φ_j = −π + 2πj/N and capped at the sensing
//! range (eq. 6.8). The PCM of two signatures is the Riemann sum of eq. 6.7,
//! sqrt(Σ_j w_j (a_j − b_j)² · 2π/N), with weights w_j ∈ {0, 1} that mask
//! the angles a partial scan does not cover (sec. 6.10.4). The closed-form
//! integral of [`crate::pcm`] is the reference (a test compares them); sampling at the scan's own
//! resolution loses nothing the scan had.
//!
//! Rotations are whole steps of 2π/N: the minimum over rotations (no
//! compass) or over an interval of them (noisy compass) is taken over the
//! shifts s of the samples, for all shifts at once by one circular
//! cross-correlation (FFT):
//! Σ_j w_j (S_j − V_{j+s})² = Σ w S² + (w ⋆ V²)(s) − 2 (wS ⋆ V)(s).
//!
//! # The triangle inequality the index needs (eq. 6.1)
//! Let D(V1, V2) = sqrt(Σ_j (V1_j − V2_j)² · 2π/N), unmasked and unrotated.
//! For any mask w and any set of allowed shifts,
//! d(S, V2) = min_s ‖S − ρ_s V2‖_w ≤ ‖S − ρ_s V1‖_w + ‖ρ_s V1 − ρ_s V2‖_w
//! ≤ ‖S − ρ_s V1‖_w + D(V1, V2) for every s, since a mask only drops terms
//! and a shift only reorders them; taking the s that attains d(S, V1)
//! gives d(S, V2) ≤ d(S, V1) + D(V1, V2). So one Monotonous Bisector Tree
//! built with D serves every compass mode and every field of view.

use rustfft::num_complex::Complex;
use rustfft::{Fft, FftPlanner};
use std::f64::consts::{PI, TAU};
use std::sync::Arc;

use crate::walls::Walls;
use crate::Scan;

/// The number of sample angles of a signature.
pub fn angle(n: usize, j: usize) -> f64 {
    -PI + TAU * j as f64 / n as f64
}

/// A PCF sampled at `n` equal map-frame angles, capped at the sensing
/// range, with the FFTs that the rotation search needs.
#[derive(Debug, Clone)]
pub struct Signature {
    /// The samples, capped.
    pub values: Vec<f32>,
    spectrum: Vec<Complex<f32>>,
    spectrum_sq: Vec<Complex<f32>>,
    magnitudes: Vec<f64>,
    /// Σ_j V_j², in `f64`.
    energy: f64,
}

/// Low frequencies whose magnitudes give the rotation-free lower bound.
const BOUND_FREQUENCIES: usize = 24;

/// |X_k| for k = 0..=K (K below n/2).
fn magnitudes(spectrum: &[Complex<f32>]) -> Vec<f64> {
    let k = BOUND_FREQUENCIES.min(spectrum.len().saturating_sub(1) / 2);
    spectrum[..=k].iter().map(|c| f64::from(c.norm())).collect()
}

/// What the robot knows of its heading (sec. 6.10.4).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Compass {
    /// The heading, exactly: one rotation (eq. 6.7).
    Exact(f64),
    /// The heading within ±`eps`: the minimum over [h − ε, h + ε].
    Noisy { heading: f64, eps: f64 },
    /// Nothing: the minimum over all rotations (eq. 6.6).
    None,
}

impl Compass {
    /// The heading the scan is first turned by.
    pub fn heading(&self) -> f64 {
        match *self {
            Compass::Exact(h) | Compass::Noisy { heading: h, .. } => h,
            Compass::None => 0.0,
        }
    }
}

/// FFT plans for one sample count.
#[derive(Clone)]
pub struct Plans {
    n: usize,
    forward: Arc<dyn Fft<f32>>,
    inverse: Arc<dyn Fft<f32>>,
}

impl std::fmt::Debug for Plans {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Plans({})", self.n)
    }
}

impl Plans {
    pub fn new(n: usize) -> Plans {
        let mut planner = FftPlanner::new();
        Plans {
            n,
            forward: planner.plan_fft_forward(n),
            inverse: planner.plan_fft_inverse(n),
        }
    }

    pub fn n(&self) -> usize {
        self.n
    }

    fn fft(&self, values: impl Iterator<Item = f32>) -> Vec<Complex<f32>> {
        let mut buf: Vec<Complex<f32>> = values.map(|v| Complex::new(v, 0.0)).collect();
        self.forward.process(&mut buf);
        buf
    }
}

impl Signature {
    /// The signature of samples `values` (already capped).
    pub fn from_values(values: Vec<f32>, plans: &Plans) -> Signature {
        assert_eq!(values.len(), plans.n, "one value per sample angle");
        let spectrum = plans.fft(values.iter().copied());
        let spectrum_sq = plans.fft(values.iter().map(|v| v * v));
        Signature {
            magnitudes: magnitudes(&spectrum),
            energy: values.iter().map(|x| f64::from(*x).powi(2)).sum(),
            values,
            spectrum,
            spectrum_sq,
        }
    }

    /// The PCF of the visibility polygon of `p` in the map (its walls),
    /// sampled and capped at `cap` (eq. 6.8): the polygonal representative
    /// V_p of a cell (sec. 6.7).
    pub fn of_point(walls: &Walls, p: (f64, f64), cap: f64, plans: &Plans) -> Signature {
        let n = plans.n;
        let values = (0..n)
            .map(|j| {
                let a = angle(n, j);
                walls.cast(p, (a.cos(), a.sin())).min(cap) as f32
            })
            .collect();
        Signature::from_values(values, plans)
    }

    /// This signature capped at a lower range `cap` (eq. 6.8 again: capping
    /// a capped PCF caps at the smaller range).
    pub fn capped(&self, cap: f64, plans: &Plans) -> Signature {
        Signature::from_values(
            self.values.iter().map(|v| v.min(cap as f32)).collect(),
            plans,
        )
    }

    /// D: the unmasked, unrotated PCM of two signatures.
    pub fn distance(&self, other: &Signature) -> f64 {
        let sum: f64 = self
            .values
            .iter()
            .zip(&other.values)
            .map(|(a, b)| f64::from(a - b).powi(2))
            .sum();
        (sum * TAU / self.values.len() as f64).sqrt()
    }
}

/// A scan turned into the samples of its approximated visibility polygon
/// V_S (sec. 6.1: the scan points joined by segments), at the signature
/// angles, turned by a heading, with a mask of the angles it covers.
#[derive(Debug, Clone)]
pub struct ScanSignature {
    /// The masked samples w_j S_j.
    pub values: Vec<f32>,
    /// w_j: 1 where the scan covers the angle.
    pub mask: Vec<f32>,
    heading: f64,
    spectrum: Vec<Complex<f32>>,
    mask_spectrum: Vec<Complex<f32>>,
    energy: f64,
    /// Whether the scan covers every angle (w ≡ 1).
    full: bool,
    magnitudes: Vec<f64>,
}

impl ScanSignature {
    /// Samples V_S of `scan` turned by `heading` at the `plans.n()` angles,
    /// capped at `cap` (eq. 6.8): a lost return reads `cap`, as the map's
    /// capped PCF reads beyond the sensing range (the scan model of
    /// [`crate::range`]).
    ///
    /// V_S joins each beam's point to the next beam's, in angle order, unless
    /// the two beams are more than [`GAP_STEPS`] typical steps apart (a
    /// partial field of view, or beams dropped as invalid): the angles of
    /// such a gap are masked out (w = 0), as are the angles next to a lost
    /// return when `cap` is infinite (a lost return can only be read
    /// against a finite range).
    pub fn new(scan: &Scan, heading: f64, cap: f64, plans: &Plans) -> ScanSignature {
        let n = plans.n;
        let mut beams: Vec<(f64, Option<f64>)> = scan
            .angles
            .iter()
            .zip(&scan.ranges)
            .filter(|(a, _)| a.is_finite())
            .map(|(&a, &r)| (crate::polar::normalise(a), r.map(|r| r.min(cap))))
            .collect();
        beams.sort_by(|x, y| x.0.total_cmp(&y.0));
        beams.dedup_by(|x, y| x.0 == y.0);
        let m = beams.len();
        let max_gap = GAP_STEPS * typical_step(&beams);
        let lost = if cap.is_finite() { Some(cap) } else { None };
        let mut values = vec![0.0f32; n];
        let mut mask = vec![0.0f32; n];
        for j in 0..n {
            if m < 2 {
                break;
            }
            // The beam at or before this angle (robot frame), circularly.
            let rel = crate::polar::normalise(angle(n, j) - heading);
            let k = beams.partition_point(|b| b.0 <= rel);
            let (i0, i1) = if k == 0 { (m - 1, 0) } else { (k - 1, k % m) };
            let a0 = beams[i0].0;
            let a1 = if i1 == 0 {
                beams[0].0 + TAU
            } else {
                beams[i1].0
            };
            let at = if rel < a0 { rel + TAU } else { rel };
            if a1 - a0 > max_gap {
                continue;
            }
            let (Some(r0), Some(r1)) = (beams[i0].1.or(lost), beams[i1].1.or(lost)) else {
                continue;
            };
            let s = through_segment(r0, r1, a0, a1 - a0, at);
            values[j] = s.min(cap) as f32;
            mask[j] = 1.0;
        }
        let spectrum = plans.fft(values.iter().copied());
        let mask_spectrum = plans.fft(mask.iter().copied());
        let energy = values.iter().map(|v| f64::from(*v).powi(2)).sum();
        let full = mask.iter().all(|w| *w == 1.0);
        ScanSignature {
            full,
            magnitudes: magnitudes(&spectrum),
            values,
            mask,
            heading,
            spectrum,
            mask_spectrum,
            energy,
        }
    }

    /// A lower bound of the PCM to `v` under every rotation, for a scan
    /// that covers every angle (`None` otherwise). By Parseval,
    /// Σ_j (S_j − V_{j+s})² = (1/N) Σ_k |Ŝ_k − V̂_k e^{2πiks/N}|², and each
    /// term is at least (|Ŝ_k| − |V̂_k|)², whatever s; keeping only the
    /// lowest frequencies (each k ≥ 1 counts twice: X_{N−k} = conj X_k for
    /// real samples) bounds the sum from below. The bound is computed from
    /// `f32` spectra: [`BOUND_SLACK`] absorbs their rounding.
    pub fn lower_bound(&self, v: &Signature) -> Option<f64> {
        if !self.full {
            return None;
        }
        let n = self.values.len() as f64;
        let sum: f64 = self
            .magnitudes
            .iter()
            .zip(&v.magnitudes)
            .enumerate()
            .map(|(k, (a, b))| if k == 0 { 1.0 } else { 2.0 } * (a - b).powi(2))
            .sum();
        Some((sum / n * TAU / n).sqrt())
    }

    /// The PCM at the scan's own heading (exact compass, eq. 6.7).
    pub fn distance(&self, v: &Signature) -> f64 {
        let sum: f64 = self
            .values
            .iter()
            .zip(&self.mask)
            .zip(&v.values)
            .map(|((s, w), v)| f64::from(w * (s - v)).powi(2))
            .sum();
        (sum * TAU / self.values.len() as f64).sqrt()
    }

    /// The least PCM over the shifts s with |s| ≤ `max_shift` (all shifts
    /// when `None`), and the heading it gives: the scan's heading plus
    /// s·2π/N.
    pub fn min_over_rotations(
        &self,
        v: &Signature,
        max_shift: Option<usize>,
        plans: &Plans,
    ) -> (f64, f64) {
        let n = plans.n;
        // (wS ⋆ V)(s) = Σ_j wS_j V_{j+s}: the inverse FFT of conj(F wS) · F V,
        // and likewise (w ⋆ V²).
        let mut cross: Vec<Complex<f32>> = self
            .spectrum
            .iter()
            .zip(&v.spectrum)
            .map(|(a, b)| a.conj() * b)
            .collect();
        plans.inverse.process(&mut cross);
        // A full scan has w ≡ 1: (w ⋆ V²)(s) = Σ V² whatever s; only a
        // masked one needs the second correlation.
        let sq: Vec<Complex<f32>> = if self.full {
            Vec::new()
        } else {
            let mut sq: Vec<Complex<f32>> = self
                .mask_spectrum
                .iter()
                .zip(&v.spectrum_sq)
                .map(|(a, b)| a.conj() * b)
                .collect();
            plans.inverse.process(&mut sq);
            sq
        };
        let scale = 1.0 / n as f64;
        let value = |s: usize| {
            let v2 = if self.full {
                v.energy
            } else {
                f64::from(sq[s].re) * scale
            };
            self.energy + v2 - 2.0 * f64::from(cross[s].re) * scale
        };
        let shifts: Box<dyn Iterator<Item = usize>> = match max_shift {
            Some(k) if 2 * k + 1 < n => Box::new((0..=k).chain(n - k..n)),
            _ => Box::new(0..n),
        };
        let (best_s, best) = shifts
            .map(|s| (s, value(s)))
            .min_by(|a, b| a.1.total_cmp(&b.1).then(a.0.cmp(&b.0)))
            .expect("n > 0");
        let shift = if best_s > n / 2 {
            best_s as f64 - n as f64
        } else {
            best_s as f64
        };
        (
            (best.max(0.0) * TAU / n as f64).sqrt(),
            self.heading + shift * TAU / n as f64,
        )
    }

    /// The PCM under `compass` (the scan was turned by its heading) and the
    /// heading it gives.
    pub fn pcm(&self, v: &Signature, compass: &Compass, plans: &Plans) -> (f64, f64) {
        match *compass {
            Compass::Exact(h) => (self.distance(v), h),
            Compass::Noisy { eps, .. } => {
                let k = (eps / (TAU / plans.n as f64)).round() as usize;
                self.min_over_rotations(v, Some(k), plans)
            }
            Compass::None => self.min_over_rotations(v, None, plans),
        }
    }
}

/// The rounding allowance of [`ScanSignature::lower_bound`]: a site is
/// skipped only when its bound exceeds the k-th best value found by more
/// than this relative margin (plus 1e-6 absolute).
pub const BOUND_SLACK: f64 = 1e-3;

/// Beams further apart than this many typical steps leave a gap in V_S
/// (masked): a full scan's step is uniform, so only a partial field of
/// view or dropped beams make such gaps.
pub const GAP_STEPS: f64 = 1.5;

/// The typical angle between neighbouring beams (sorted by angle): the
/// median of the positive steps, circularly; 2π for fewer than two beams.
fn typical_step(beams: &[(f64, Option<f64>)]) -> f64 {
    let m = beams.len();
    if m < 2 {
        return TAU;
    }
    let mut steps: Vec<f64> = (0..m)
        .map(|i| {
            if i + 1 < m {
                beams[i + 1].0 - beams[i].0
            } else {
                beams[0].0 + TAU - beams[i].0
            }
        })
        .filter(|d| *d > 0.0)
        .collect();
    steps.sort_by(f64::total_cmp);
    steps.get(steps.len() / 2).copied().unwrap_or(TAU)
}

/// The range along direction `a` (robot frame) to the segment between the
/// scan points at angles `a0` and `a0 + step` with ranges `r0`, `r1`.
fn through_segment(r0: f64, r1: f64, a0: f64, step: f64, a: f64) -> f64 {
    let p0 = (r0 * a0.cos(), r0 * a0.sin());
    let p1 = (r1 * (a0 + step).cos(), r1 * (a0 + step).sin());
    let d = (a.cos(), a.sin());
    let e = (p1.0 - p0.0, p1.1 - p0.1);
    let denom = d.0 * e.1 - d.1 * e.0;
    if denom.abs() < 1e-12 {
        return r0.min(r1);
    }
    let t = (p0.0 * e.1 - p0.1 * e.0) / denom;
    if t.is_finite() && t > 0.0 {
        t
    } else {
        r0.min(r1)
    }
}
