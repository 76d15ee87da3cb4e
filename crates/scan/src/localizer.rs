//! Localization from a noisy scan (ch. 6): the ROLOPRO scheme — the
//! visibility cells of the map, each with the PCF of its centre of gravity
//! (sec. 6.7), searched for the cells whose PCM to the scan is least —
//! followed by what the thesis did not build: each of the best cells is
//! refined to a pose by point-to-line ICP ([`crate::icp`]) and scored
//! against the map, and the answer is the best pose together with every
//! pose that scores as well within a tolerance, so that a building of
//! identical rooms answers with each look-alike place.

use std::borrow::Cow;
use std::collections::HashMap;
use std::time::Instant;

use wai_cells::Decomposition;
use wai_map::Map;

use crate::coarsen::coarsen;
use crate::icp::{self, IcpOptions};
use crate::mbt::Mbt;
use crate::range::{RangeBasis, SensingRange};
use crate::signature::{Compass, Plans, ScanSignature, Signature, BOUND_SLACK};
use crate::sites::{cell_sites, lattice_points, CellSite};
use crate::walls::Walls;
use crate::{Pose, Scan};

/// The MBT's pruning slack: the rotation search computes the PCM through
/// `f32` FFTs, whose relative error stays far below this.
const ROTATION_SLACK: f64 = 1e-3;

/// The candidates of a query are drawn from this many times as many
/// ranked sites, keeping those at least [`DIVERSE_METRES`] apart or
/// [`DIVERSE_RADIANS`] apart in heading.
const POOL: usize = 4;
const DIVERSE_METRES: f64 = 0.5;
const DIVERSE_RADIANS: f64 = 0.087;

/// The pruning of landings before the fine ICP stage: every 4th beam, and
/// a margin far wider than the answer set's (`answer_ratio` 2): a coarse
/// landing is up to a few centimetres off, which costs the quick score
/// more than the final one.
const QUICK_STRIDE: usize = 4;
const QUICK_RATIO: f64 = 4.0;
const QUICK_SLACK: f64 = 2e-3;

/// How the localizer is built and queried.
#[derive(Debug, Clone, PartialEq)]
pub struct Options {
    /// Sample angles of a signature (720: the thesis's scanners).
    pub samples: usize,
    /// The sensing range the sites' PCFs are capped at when built (eq.
    /// 6.8); `None`: uncapped. A query is read with its own scan's range
    /// ([`SensingRange`]), and a lower one caps the PCFs again for that
    /// query.
    pub max_range: Option<f64>,
    /// How many of the best sites are refined to poses.
    pub candidates: usize,
    /// Beyond ROLOPRO: besides its centre, a cell larger than a square of
    /// this side also stands at the points of a lattice of this spacing
    /// inside it, so that no start of the refinement lies far from the
    /// robot in a big cell (sec. 6.7: the error grows with the cell).
    pub lattice: Option<f64>,
    /// The residual cap τ of [`icp::score`], input units.
    pub tau: f64,
    /// A pose joins the answer set when its score is at most
    /// `ratio` × best + `slack`.
    pub answer_ratio: f64,
    pub answer_slack: f64,
    pub icp: IcpOptions,
    /// The coarsening step of sec. 6.10.4: neighbouring cells whose
    /// centres' PCFs lie within this PCM of a group's representative are
    /// one cell (the representative's centre stands for them all).
    pub coarsen: Option<f64>,
    /// The memory the sites' signatures may take, in bytes. The lattice is
    /// widened until its sites fit (a plan in millimetres read as metres
    /// must not take the machine down); if one site per cell does not fit,
    /// [`ScanLocalizer::try_new`] refuses with the estimate.
    pub max_memory: u64,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            samples: 720,
            max_range: None,
            candidates: 12,
            lattice: Some(0.5),
            tau: 0.2,
            answer_ratio: 2.0,
            answer_slack: 4e-4,
            icp: IcpOptions::default(),
            coarsen: None,
            max_memory: DEFAULT_MAX_MEMORY,
        }
    }
}

/// [`Options::max_memory`] by default: 1 GiB, about 70,000 sites of 720
/// samples.
pub const DEFAULT_MAX_MEMORY: u64 = 1 << 30;

/// The bytes one site costs: its signature (the samples as `f32`, two
/// spectra of complex `f32`, the low magnitudes as `f64`), the site and
/// its share of the tree, rounded up.
pub fn site_bytes(samples: usize) -> u64 {
    let samples = samples as u64;
    let signature = samples * 4 + 2 * samples * 8 + 25 * 8 + 4 * 24 + 8;
    signature + std::mem::size_of::<Site>() as u64 + 64
}

/// How many sites fit [`Options::max_memory`].
fn site_budget(opts: &Options) -> u64 {
    opts.max_memory / site_bytes(opts.samples)
}

/// Why [`ScanLocalizer::try_new`] refuses a map.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error(
    "the map has {cells} cells, and one site per cell needs about {needed_mib} MiB for \
     the signatures, over the limit of {limit_mib} MiB (raise it with --max-memory)"
)]
pub struct TooLarge {
    pub cells: usize,
    pub needed_mib: u64,
    pub limit_mib: u64,
}

/// The lattice spacing that keeps the sites within `budget`: `spacing`,
/// or wider when the cells larger than a lattice square would get more
/// lattice points than the budget leaves after one site per cell. A cell
/// of area A gets about A / g² points at spacing g.
fn fitted_spacing(cells: &[CellSite], spacing: f64, budget: u64) -> f64 {
    let room = budget.saturating_sub(cells.len() as u64).max(1) as f64;
    let big: f64 = cells
        .iter()
        .filter(|c| c.area > spacing * spacing)
        .map(|c| c.area)
        .sum();
    if big / (spacing * spacing) <= room {
        spacing
    } else {
        // The lattice points of a convex cell at spacing g are at most
        // A / g² plus its perimeter's share; 10 % more spacing covers it.
        (big / room).sqrt() * 1.1
    }
}

/// The preprocessed map.
#[derive(Debug)]
pub struct ScanLocalizer {
    walls: Walls,
    cells: Vec<CellSite>,
    sites: Vec<Site>,
    neighbours: Vec<(usize, usize)>,
    signatures: Vec<Signature>,
    /// The Monotonous Bisector Tree over the sites' signatures (sec. 6.4),
    /// with D the unmasked, unrotated PCM (see [`crate::signature`]).
    tree: Mbt,
    /// Cells before and after the coarsening step.
    coarsened: (usize, usize),
    plans: Plans,
    cap: f64,
    opts: Options,
    spacing: Option<f64>,
}

/// A point the localizer stands at: a cell's centre of gravity or a
/// lattice point inside a big cell.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Site {
    /// The cell (its position in [`ScanLocalizer::cells`]).
    pub cell: usize,
    pub at: (f64, f64),
    /// Whether it is the cell's centre of gravity.
    pub centre: bool,
}

/// A site ranked by its PCM to the scan.
#[derive(Debug, Clone, PartialEq)]
pub struct RankedCell {
    /// Index into [`ScanLocalizer::sites`].
    pub site: usize,
    pub pcm: f64,
    /// The heading the PCM's rotation gives.
    pub heading: f64,
}

/// A refined pose and its score (lower is better).
#[derive(Debug, Clone, PartialEq)]
pub struct Hypothesis {
    pub pose: Pose,
    pub score: f64,
    /// The ranked cell it was refined from.
    pub from_site: usize,
    /// How far the map lets every beam without a return run from this
    /// pose: the least range the map gives along them (∞ with none). A
    /// sensor reaching further would have seen a wall there, so a stated
    /// range above it rules the pose out. Filled in for the answer set.
    pub clear_to: f64,
}

/// What a query returns.
#[derive(Debug, Clone, PartialEq)]
pub struct ScanAnswer {
    /// The candidates: the best sites by PCM, best first, at least
    /// 0.5 m or 5° apart; without an exact compass followed by those of the
    /// second ranking, at the best refined pose's heading.
    pub ranked: Vec<RankedCell>,
    /// The best refined pose.
    pub best: Option<Hypothesis>,
    /// Every distinct refined pose scoring within the tolerance, best first.
    pub answer_set: Vec<Hypothesis>,
    /// PCM evaluations made.
    pub evaluations: usize,
    /// The sensing range the scan was read with, and why.
    pub range: SensingRange,
}

impl ScanAnswer {
    /// What the reader must know about this answer: the range's warnings
    /// ([`SensingRange::warnings`]) and, when the range was only bounded
    /// and the answer set holds poses a longer range would tell apart, how
    /// far each answer's beams without a return are clear
    /// ([`Hypothesis::clear_to`]).
    pub fn warnings(&self) -> Vec<String> {
        let mut out = self.range.warnings();
        let bounded = matches!(
            self.range.basis,
            RangeBasis::LongestReturn | RangeBasis::LooseStatement
        );
        if !bounded || self.answer_set.len() < 2 {
            return out;
        }
        // A pose stays possible for sensor ranges up to its clear_to: when
        // these differ, a known range would narrow the set.
        let reach: Vec<f64> = self.answer_set.iter().map(|h| h.clear_to).collect();
        let (lo, hi) = reach
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), r| {
                (l.min(*r), h.max(*r))
            });
        if hi - lo > 0.2 {
            let listed: Vec<String> = reach.iter().map(|r| format!("{r:.2}")).collect();
            out.push(format!(
                "the range decides between the {} answers: they differ in what lies beyond \
                 {:.3} m along the beams without a return; a sensor known to reach R m rules \
                 out each answer whose such beams meet a wall within R (in answer order: {} m)",
                self.answer_set.len(),
                self.range.cap,
                listed.join(", ")
            ));
        }
        out
    }
}

/// A local query: only cells whose centre lies within `radius` of `at`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Near {
    pub at: (f64, f64),
    pub radius: f64,
}

impl ScanLocalizer {
    /// Decomposes `map` and preprocesses it.
    pub fn new(map: &Map, opts: Options) -> ScanLocalizer {
        ScanLocalizer::from_decomposition(&Decomposition::new(map), opts)
    }

    /// [`ScanLocalizer::new`], refusing a map whose cells alone need more
    /// than [`Options::max_memory`].
    pub fn try_new(map: &Map, opts: Options) -> Result<ScanLocalizer, TooLarge> {
        ScanLocalizer::try_new_with_progress(map, opts, &|_, _, _| {})
    }

    /// [`ScanLocalizer::try_new`], reporting `progress(stage, done, total)`
    /// through the stages of a long preprocessing: `"cells"` (the
    /// decomposition, over its cells of every dimension), `"signatures"`
    /// (over the sites), then `"tree"` once before and after the metric
    /// tree is built.
    pub fn try_new_with_progress(
        map: &Map,
        opts: Options,
        progress: &(dyn Fn(&str, usize, usize) + Sync),
    ) -> Result<ScanLocalizer, TooLarge> {
        let d =
            Decomposition::with_progress(map, &mut |done, total| progress("cells", done, total));
        let cells = d.cells().len();
        if cells as u64 > site_budget(&opts) {
            return Err(TooLarge {
                cells,
                needed_mib: (cells as u64 * site_bytes(opts.samples)).div_ceil(1 << 20),
                limit_mib: opts.max_memory >> 20,
            });
        }
        Ok(ScanLocalizer::preprocess(&d, opts, progress))
    }

    /// Preprocesses a decomposed map: one signature per 2-cell, and the
    /// lattice points of the big cells, the lattice widened to fit
    /// [`Options::max_memory`] ([`ScanLocalizer::lattice_spacing`]).
    pub fn from_decomposition(d: &Decomposition<'_>, opts: Options) -> ScanLocalizer {
        ScanLocalizer::preprocess(d, opts, &|_, _, _| {})
    }

    fn preprocess(
        d: &Decomposition<'_>,
        opts: Options,
        progress: &(dyn Fn(&str, usize, usize) + Sync),
    ) -> ScanLocalizer {
        use rayon::prelude::*;
        use std::sync::atomic::{AtomicUsize, Ordering};
        let walls = Walls::new(crate::walls(d.map()));
        let (cells, neighbours) = cell_sites(d);
        let spacing = opts
            .lattice
            .map(|g| fitted_spacing(&cells, g, site_budget(&opts)));
        let mut sites = Vec::with_capacity(cells.len());
        let mut cell_list = Vec::with_capacity(cells.len());
        for c in cells {
            let extra = match spacing {
                Some(g) if c.area > g * g => lattice_points(&c.polygon, g, 0.05),
                _ => Vec::new(),
            };
            let lattice: Vec<Site> = extra
                .into_iter()
                .map(|at| Site {
                    cell: c.cell,
                    at,
                    centre: false,
                })
                .collect();
            sites.push(Site {
                cell: c.cell,
                at: c.centre,
                centre: true,
            });
            sites.extend(lattice);
            cell_list.push(c);
        }
        let plans = Plans::new(opts.samples);
        let cap = opts.max_range.unwrap_or(f64::INFINITY);
        let (done, total) = (AtomicUsize::new(0), sites.len());
        let step = (total / 100).max(1);
        progress("signatures", 0, total);
        let mut signatures: Vec<Signature> = sites
            .par_iter()
            .map(|s| {
                let sig = Signature::of_point(&walls, s.at, cap, &plans);
                let k = done.fetch_add(1, Ordering::Relaxed) + 1;
                if k % step == 0 {
                    progress("signatures", k, total);
                }
                sig
            })
            .collect();
        progress("signatures", total, total);
        let before = cell_list.len();
        let mut after = before;
        if let Some(threshold) = opts.coarsen {
            // Cell i's centre is the site whose `cell` is i and `centre` set.
            let mut centre_site = vec![0; before];
            for (k, s) in sites.iter().enumerate() {
                if s.centre {
                    centre_site[s.cell] = k;
                }
            }
            let dist = |i: usize, j: usize| {
                signatures[centre_site[i]].distance(&signatures[centre_site[j]])
            };
            let groups = coarsen(before, &neighbours, dist, threshold);
            after = groups.len();
            let keep: Vec<bool> = sites
                .iter()
                .map(|s| !s.centre || groups.representatives[groups.group_of[s.cell]] == s.cell)
                .collect();
            let mut k = 0;
            sites.retain(|_| (keep[k], k += 1).0);
            let mut k = 0;
            signatures.retain(|_| (keep[k], k += 1).0);
        }
        progress("tree", 0, 1);
        let tree = Mbt::build(signatures.len(), 8, |i, j| {
            signatures[i].distance(&signatures[j])
        })
        .with_slack(ROTATION_SLACK);
        progress("tree", 1, 1);
        ScanLocalizer {
            walls,
            cells: cell_list,
            sites,
            neighbours,
            signatures,
            tree,
            coarsened: (before, after),
            plans,
            cap,
            opts,
            spacing,
        }
    }

    /// The lattice spacing used: [`Options::lattice`], or wider where its
    /// sites would not fit [`Options::max_memory`]; `None` without a
    /// lattice.
    pub fn lattice_spacing(&self) -> Option<f64> {
        self.spacing
    }

    /// The number of cells before and after the coarsening step.
    pub fn coarsened(&self) -> (usize, usize) {
        self.coarsened
    }

    /// The 2-cells, by position in the decomposition.
    pub fn cells(&self) -> &[CellSite] {
        &self.cells
    }

    /// The sites, each cell's centre first, then its lattice points.
    pub fn sites(&self) -> &[Site] {
        &self.sites
    }

    pub fn neighbours(&self) -> &[(usize, usize)] {
        &self.neighbours
    }

    pub fn walls(&self) -> &Walls {
        &self.walls
    }

    pub fn options(&self) -> &Options {
        &self.opts
    }

    /// The sites' signatures capped at `cap` (eq. 6.8): as built when `cap`
    /// is not below the build's range ([`Options::max_range`]), else capped
    /// again. Capping is 1-Lipschitz in every sample, so the tree built with
    /// the uncapped D still bounds the capped PCM (see [`crate::signature`]).
    fn signatures_at(&self, cap: f64) -> Cow<'_, [Signature]> {
        use rayon::prelude::*;
        if cap >= self.cap {
            return Cow::Borrowed(&self.signatures);
        }
        Cow::Owned(
            self.signatures
                .par_iter()
                .map(|v| v.capped(cap, &self.plans))
                .collect(),
        )
    }

    /// The cells whose PCM to `scan` is least, best first (ties by site),
    /// and how many PCMs were evaluated, the scan read with its own
    /// sensing range ([`SensingRange::of`]). A full scan visits the cells
    /// in the order of a rotation-free lower bound of their PCM and stops
    /// when the bound passes the k-th best PCM found
    /// ([`ScanSignature::lower_bound`]); the result is the same as
    /// [`ScanLocalizer::rank_linear`]'s (a test checks it).
    pub fn rank(
        &self,
        scan: &Scan,
        compass: &Compass,
        near: Option<Near>,
        k: usize,
    ) -> (Vec<RankedCell>, usize) {
        let cap = SensingRange::of(scan).cap;
        self.rank_at(scan, compass, near, k, cap, &self.signatures_at(cap))
    }

    /// [`ScanLocalizer::rank`] with the PCFs capped at `cap`, `signatures`
    /// being the sites' signatures capped there.
    fn rank_at(
        &self,
        scan: &Scan,
        compass: &Compass,
        near: Option<Near>,
        k: usize,
        cap: f64,
        signatures: &[Signature],
    ) -> (Vec<RankedCell>, usize) {
        if k == 0 {
            return (Vec::new(), 0);
        }
        let cap = cap.min(self.cap);
        let s = ScanSignature::new(scan, compass.heading(), cap, &self.plans);
        let eligible = self.eligible(near);
        let bounds: Option<Vec<(f64, usize)>> = eligible
            .iter()
            .map(|&i| s.lower_bound(&signatures[i]).map(|b| (b, i)))
            .collect();
        let Some(mut bounds) = bounds else {
            if near.is_some() {
                return self.rank_all(&s, signatures, &eligible, compass, k);
            }
            // The rotation search gives the heading with the PCM: keep it
            // for the sites that end up ranked.
            let mut headings: HashMap<usize, f64> = HashMap::new();
            let (found, stats) = self.tree.k_nearest_with_stats(k, |i| {
                let r = self.ranked_cell(&s, signatures, i, compass);
                headings.insert(i, r.heading);
                r.pcm
            });
            let ranked = found
                .into_iter()
                .map(|nb| RankedCell {
                    site: nb.item,
                    pcm: nb.distance,
                    heading: headings[&nb.item],
                })
                .collect();
            return (ranked, stats.evaluations);
        };
        bounds.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
        let mut best: Vec<RankedCell> = Vec::with_capacity(k + 1);
        let mut evaluations = 0;
        for (bound, i) in bounds {
            if best.len() == k {
                let kth = best[k - 1].pcm;
                if bound > kth * (1.0 + BOUND_SLACK) + 1e-6 {
                    break;
                }
            }
            let cell = self.ranked_cell(&s, signatures, i, compass);
            evaluations += 1;
            let pcm = cell.pcm;
            let at = best.partition_point(|c| c.pcm < pcm || (c.pcm == pcm && c.site < i));
            if at < k {
                best.insert(at, cell);
                best.truncate(k);
            }
        }
        (best, evaluations)
    }

    /// [`ScanLocalizer::rank`] by evaluating every cell (the reference).
    pub fn rank_linear(
        &self,
        scan: &Scan,
        compass: &Compass,
        near: Option<Near>,
        k: usize,
    ) -> (Vec<RankedCell>, usize) {
        let cap = SensingRange::of(scan).cap.min(self.cap);
        let signatures = self.signatures_at(cap);
        let s = ScanSignature::new(scan, compass.heading(), cap, &self.plans);
        self.rank_all(&s, &signatures, &self.eligible(near), compass, k)
    }

    /// Site `i` with its PCM to the scan `s` under `compass` and the
    /// heading that PCM gives.
    fn ranked_cell(
        &self,
        s: &ScanSignature,
        signatures: &[Signature],
        i: usize,
        compass: &Compass,
    ) -> RankedCell {
        let (pcm, heading) = s.pcm(&signatures[i], compass, &self.plans);
        RankedCell {
            site: i,
            pcm,
            heading,
        }
    }

    fn eligible(&self, near: Option<Near>) -> Vec<usize> {
        (0..self.sites.len())
            .filter(|&i| {
                let c = self.sites[i].at;
                near.is_none_or(|n| (c.0 - n.at.0).hypot(c.1 - n.at.1) <= n.radius)
            })
            .collect()
    }

    fn rank_all(
        &self,
        s: &ScanSignature,
        signatures: &[Signature],
        eligible: &[usize],
        compass: &Compass,
        k: usize,
    ) -> (Vec<RankedCell>, usize) {
        let mut ranked: Vec<RankedCell> = eligible
            .iter()
            .map(|&i| self.ranked_cell(s, signatures, i, compass))
            .collect();
        let evaluations = ranked.len();
        ranked.sort_by(|a, b| a.pcm.total_cmp(&b.pcm).then(a.site.cmp(&b.site)));
        ranked.truncate(k);
        (ranked, evaluations)
    }

    /// Localizes `scan`: ranks the cells, refines the best, and answers
    /// with the best pose and the set of poses as good. The scan is read
    /// with its sensing range ([`SensingRange::of`]); when its stated range
    /// is contradicted at the best pose (lost beams facing walls well within
    /// it: [`SensingRange::is_contradicted_by`]), it is read again with
    /// its longest return as the range, and the answer says so.
    pub fn localize(&self, scan: &Scan, compass: &Compass, near: Option<Near>) -> ScanAnswer {
        let range = SensingRange::of(scan);
        let answer = self.localize_with(scan, compass, near, range);
        if answer.range.basis != RangeBasis::Stated || answer.range.lost == 0 {
            return answer;
        }
        let Some(best) = &answer.best else {
            return answer;
        };
        let contradicted = self.contradicted(scan, &best.pose, answer.range.cap);
        match answer.range.loosened(contradicted) {
            Some(loose) if answer.range.is_contradicted_by(contradicted) => {
                let again = self.localize_with(scan, compass, near, loose);
                ScanAnswer {
                    evaluations: answer.evaluations + again.evaluations,
                    ..again
                }
            }
            _ => answer,
        }
    }

    /// [`Hypothesis::clear_to`]: the least range the map gives from `pose`
    /// along the beams of `scan` without a return.
    fn clear_to(&self, scan: &Scan, pose: &Pose) -> f64 {
        scan.angles
            .iter()
            .zip(&scan.ranges)
            .filter(|(_, r)| r.is_none())
            .map(|(a, _)| self.walls.range(pose, *a))
            .fold(f64::INFINITY, f64::min)
    }

    /// The lost beams of `scan` that face a wall within `cap`, by more than
    /// the score's τ, from `pose`.
    fn contradicted(&self, scan: &Scan, pose: &Pose, cap: f64) -> usize {
        scan.angles
            .iter()
            .zip(&scan.ranges)
            .filter(|(a, r)| r.is_none() && self.walls.range(pose, **a) < cap - self.opts.tau)
            .count()
    }

    /// [`ScanLocalizer::localize`] with the scan read against `range`.
    fn localize_with(
        &self,
        scan: &Scan,
        compass: &Compass,
        near: Option<Near>,
        range: SensingRange,
    ) -> ScanAnswer {
        let points = scan.points();
        let signatures = self.signatures_at(range.cap);
        let mut landed: Vec<(Pose, usize)> = Vec::new();
        let (mut ranked, mut evaluations) =
            self.candidates(scan, compass, near, range.cap, &signatures);
        self.land(&ranked, &points, &mut landed);
        let (mut hypotheses, best_quick) =
            self.refine(scan, &points, &landed, f64::INFINITY, range.cap);
        // Beyond ROLOPRO: without an exact compass, the best refined pose
        // knows the heading; ranking again at that heading (sharper: one
        // rotation, eq. 6.7) finds the places a rotation search ranked
        // too low — in a symmetric building, the look-alikes.
        if !matches!(compass, Compass::Exact(_)) {
            let best = hypotheses.iter().min_by(|a, b| a.score.total_cmp(&b.score));
            if let Some(heading) = best.map(|b| b.pose.heading) {
                let (again, more) =
                    self.candidates(scan, &Compass::Exact(heading), near, range.cap, &signatures);
                evaluations += more;
                let first = landed.len();
                self.land(&again, &points, &mut landed);
                hypotheses.extend(
                    self.refine(scan, &points, &landed[first..], best_quick, range.cap)
                        .0,
                );
                ranked.extend(again);
            }
        }
        hypotheses.sort_by(|a, b| {
            a.score
                .total_cmp(&b.score)
                .then(a.from_site.cmp(&b.from_site))
        });
        let best = hypotheses.first().cloned();
        let mut answer_set: Vec<Hypothesis> = Vec::new();
        if let Some(b) = &best {
            let limit = self.opts.answer_ratio * b.score + self.opts.answer_slack;
            for h in hypotheses.iter().filter(|h| h.score <= limit) {
                if !answer_set.iter().any(|a| same_place(&a.pose, &h.pose)) {
                    answer_set.push(Hypothesis {
                        clear_to: self.clear_to(scan, &h.pose),
                        ..h.clone()
                    });
                }
            }
        }
        let best = answer_set.first().cloned().or(best);
        ScanAnswer {
            ranked,
            best,
            answer_set,
            evaluations,
            range,
        }
    }

    /// The candidates under `compass`: neighbouring sites (slivers along
    /// one ray, lattice points) rank alike and would send the refinement
    /// to one place several times, so they are the best sites at least
    /// `DIVERSE_METRES` or `DIVERSE_RADIANS` apart, drawn from a pool of
    /// `POOL` × as many; and the PCM evaluations made.
    fn candidates(
        &self,
        scan: &Scan,
        compass: &Compass,
        near: Option<Near>,
        cap: f64,
        signatures: &[Signature],
    ) -> (Vec<RankedCell>, usize) {
        let k = self.opts.candidates;
        let (pool, evaluations) =
            self.rank_at(scan, compass, near, k.saturating_mul(POOL), cap, signatures);
        let mut ranked: Vec<RankedCell> = Vec::with_capacity(k);
        for r in pool {
            if ranked.len() == k {
                break;
            }
            let at = self.sites[r.site].at;
            let close = |q: &RankedCell| {
                let b = self.sites[q.site].at;
                (at.0 - b.0).hypot(at.1 - b.1) < DIVERSE_METRES
                    && icp::wrap(r.heading - q.heading).abs() < DIVERSE_RADIANS
            };
            if !ranked.iter().any(close) {
                ranked.push(r);
            }
        }
        (ranked, evaluations)
    }

    /// The coarse ICP stages from each candidate; starts that land on a
    /// place already in `landed` are refined once.
    fn land(&self, ranked: &[RankedCell], points: &[(f64, f64)], landed: &mut Vec<(Pose, usize)>) {
        for r in ranked {
            let c = self.sites[r.site].at;
            let start = Pose {
                x: c.0,
                y: c.1,
                heading: r.heading,
            };
            let pose = icp::coarse(&self.walls, points, start, &self.opts.icp);
            if !landed.iter().any(|(p, _)| same_landing(p, &pose)) {
                landed.push((pose, r.site));
            }
        }
    }

    /// The fine ICP stage and the score of each landing whose quick score
    /// (every `QUICK_STRIDE`-th beam) is not far worse than the best of
    /// these landings' and `floor` (the best quick score of an earlier
    /// pass): the others cannot join the answer set. Also the best quick
    /// score, `floor` included. Lost beams are scored against `cap`.
    fn refine(
        &self,
        scan: &Scan,
        points: &[(f64, f64)],
        landed: &[(Pose, usize)],
        floor: f64,
        cap: f64,
    ) -> (Vec<Hypothesis>, f64) {
        let quick: Vec<f64> = landed
            .iter()
            .map(|(p, _)| {
                icp::score_strided(&self.walls, scan, p, cap, self.opts.tau, QUICK_STRIDE)
            })
            .collect();
        let best_quick = quick.iter().copied().fold(floor, f64::min);
        let keep = QUICK_RATIO * best_quick + QUICK_SLACK;
        let hypotheses = landed
            .iter()
            .zip(quick)
            .filter(|(_, q)| *q <= keep)
            .map(|(&(coarse, site), _)| {
                let pose = icp::fine(&self.walls, points, coarse, &self.opts.icp);
                let score = if pose.x.is_finite() && pose.y.is_finite() {
                    icp::score(&self.walls, scan, &pose, cap, self.opts.tau)
                } else {
                    f64::INFINITY
                };
                Hypothesis {
                    pose,
                    score,
                    from_site: site,
                    clear_to: f64::INFINITY,
                }
            })
            .collect();
        (hypotheses, best_quick)
    }

    /// [`ScanLocalizer::localize`] and the time it took, in milliseconds.
    pub fn localize_timed(
        &self,
        scan: &Scan,
        compass: &Compass,
        near: Option<Near>,
    ) -> (ScanAnswer, f64) {
        let t = Instant::now();
        let a = self.localize(scan, compass, near);
        (a, t.elapsed().as_secs_f64() * 1e3)
    }
}

/// Two coarse poses within 2 cm and 0.5° converge to one place.
fn same_landing(a: &Pose, b: &Pose) -> bool {
    (a.x - b.x).hypot(a.y - b.y) < 0.02
        && icp::wrap(a.heading - b.heading).abs() < 0.5f64.to_radians()
}

/// Two poses within 0.25 input units and 5° are one place.
fn same_place(a: &Pose, b: &Pose) -> bool {
    (a.x - b.x).hypot(a.y - b.y) < 0.25
        && icp::wrap(a.heading - b.heading).abs() < 5f64.to_radians()
}
