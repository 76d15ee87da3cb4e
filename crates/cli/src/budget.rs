//! The memory a decomposition may take, estimated before the work starts:
//! every command that decomposes a map (`decompose`, `embeddings`,
//! `preprocess`, `localize` on a map) refuses one whose estimate is above
//! the limit, saying the estimate and how to raise the limit.

use crate::failure::Failure;
use wai_cells::{vertex_bound, VisibilityRay};
use wai_map::Map;

/// Bytes per arrangement vertex assumed by the memory estimate: exact
/// points, half-edges, edge geometry, faces, cells of every dimension and
/// the skeleton keys of the classes. Measured as peak RSS over vertices of
/// random-orthogonal maps (seed 1), with the incremental skeletons: 5.6 KiB
/// at n = 1000 (28,273 vertices, 155 MiB), 5.5 KiB at n = 2000 (49,559
/// vertices, 267 MiB) and 5.7 KiB at n = 4000 (110,230 vertices, 614 MiB);
/// comb-convex-chain k = 64, whose 80,033 classes have long keys: 9.1 KiB
/// (80,290 vertices, 716 MiB). 12 KiB leaves a margin.
const BYTES_PER_VERTEX: u64 = 12 * 1024;

/// Seconds per arrangement vertex for the time shown beside the estimate:
/// about the slowest rate measured (a 1,000-vertex random star polygon,
/// 1.9 million cells in 34 s on two cores); the vertex bound is an upper
/// bound, so the real time is often shorter.
const SECONDS_PER_VERTEX: f64 = 2.0e-5;

/// Bounds above which the estimate is shown before the work starts.
const SHOW_ABOVE_VERTICES: u64 = 200_000;

/// The limit options of a command that decomposes a map.
#[derive(clap::Args, Debug, Clone)]
pub struct MemoryArgs {
    /// The memory the decomposition may take (e.g. 4G, 512M): a map whose
    /// estimate is larger is refused before the work starts. Default: the
    /// memory available now.
    #[arg(long, value_parser = crate::options::bytes)]
    pub max_memory: Option<u64>,
    /// Skip the memory estimate made before the work starts.
    #[arg(long)]
    pub force: bool,
}

/// The memory the machine has available now, from /proc/meminfo.
fn available_bytes() -> Option<u64> {
    let info = std::fs::read_to_string("/proc/meminfo").ok()?;
    let line = info.lines().find(|l| l.starts_with("MemAvailable:"))?;
    let kib: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kib * 1024)
}

/// Refuse, before the arrangement is built, a map whose decomposition could
/// not fit, from an upper bound on the arrangement's vertices that counts
/// the real crossings of the rays with predicates only
/// ([`wai_cells::vertex_bound`]); show the estimate on stderr when it is
/// large.
pub fn check_decomposition(
    map: &Map,
    rays: &[VisibilityRay],
    limits: &MemoryArgs,
) -> Result<(), Failure> {
    if limits.force {
        return Ok(());
    }
    let r = rays.len() as u64;
    let bound = vertex_bound(map, rays);
    let need = bound.saturating_mul(BYTES_PER_VERTEX);
    let (limit, what) = match (limits.max_memory, available_bytes()) {
        (Some(m), _) => (Some(m), "--max-memory"),
        (None, avail) => (avail, "the memory available now"),
    };
    match limit {
        Some(limit) if need > limit => Err(Failure::invalid(format!(
            "map too large for the memory allowed: {r} visibility rays give at most {bound} decomposition vertices, \
             estimated {}, above {} ({what}); raise the limit with --max-memory, or skip the estimate with --force",
            size(need),
            size(limit)
        ))),
        _ => {
            if bound > SHOW_ABOVE_VERTICES {
                eprintln!(
                    "note: {r} visibility rays, at most {bound} decomposition vertices: up to {:.1} GiB and {}",
                    size(need),
                    duration(bound)
                );
            }
            Ok(())
        }
    }
}

#[allow(
    clippy::float_arithmetic,
    reason = "a size shown to the user; decides no geometry"
)]
fn size(bytes: u64) -> String {
    let b = bytes as f64;
    if b < f64::from(1u32 << 30) {
        format!("{:.1} MiB", b / f64::from(1u32 << 20))
    } else {
        format!("{:.1} GiB", b / f64::from(1u32 << 30))
    }
}

#[allow(
    clippy::float_arithmetic,
    reason = "a time shown to the user; decides no geometry"
)]
fn duration(vertices: u64) -> String {
    let s = vertices as f64 * SECONDS_PER_VERTEX;
    if s < 120.0 {
        format!("about {s:.0} s")
    } else {
        format!("about {:.0} min", s / 60.0)
    }
}
