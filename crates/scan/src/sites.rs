//! The cells the localizer compares a scan with: each 2-cell of the
//! visibility cell decomposition (sec. 3.6) with its centre of gravity, the
//! point the thesis stands at to give the cell's skeleton a polygonal
//! representative V_p (sec. 6.7), and which cells are neighbours (for the
//! coarsening step of sec. 6.10.4).
//!
//! The decomposition is exact; the centres are read as `f64` in input
//! units. A 2-cell is convex (a face of an arrangement of the map's
//! interior and the visibility rays, every reflex vertex emitting the rays
//! along both of its edges), so its centre of gravity lies inside it.

use rug::{Integer, Rational};
use wai_cells::Decomposition;
use wai_exact::RatPoint;

/// A 2-cell as the localizer sees it.
#[derive(Debug, Clone, PartialEq)]
pub struct CellSite {
    /// Its position in [`Decomposition::cells`].
    pub cell: usize,
    /// Its equivalence class (the index of its skeleton).
    pub class: usize,
    /// Its centre of gravity, in input units.
    pub centre: (f64, f64),
    /// Its area, in square input units.
    pub area: f64,
    /// Its boundary (convex, counter-clockwise), in input units.
    pub polygon: Vec<(f64, f64)>,
}

/// A rational point in input units as `f64`.
pub fn to_f64(p: &RatPoint, scale: &Integer) -> (f64, f64) {
    let w = Integer::from(p.hw() * scale);
    (
        Rational::from((p.hx().clone(), w.clone())).to_f64(),
        Rational::from((p.hy().clone(), w)).to_f64(),
    )
}

/// Every 2-cell of `d` with its centre, and the pairs of cells (by
/// position) that share a boundary edge.
pub fn cell_sites(d: &Decomposition<'_>) -> (Vec<CellSite>, Vec<(usize, usize)>) {
    let arr = d.arrangement();
    let scale = d.map().scale();
    let cells = d.cells();
    let mut position = vec![usize::MAX; arr.face_count()];
    for (i, &f) in cells.iter().enumerate() {
        position[f] = i;
    }
    let mut neighbours = Vec::new();
    let sites = cells
        .iter()
        .enumerate()
        .map(|(i, &f)| {
            let pts: Vec<(f64, f64)> = arr
                .face_points(f)
                .iter()
                .map(|p| to_f64(p, scale))
                .collect();
            for h in arr.face_half_edges(f) {
                let other = position[arr.half_edge(arr.half_edge(h).twin).face];
                if other != usize::MAX && other > i {
                    neighbours.push((i, other));
                }
            }
            let (centre, area) = centroid(&pts);
            CellSite {
                cell: i,
                class: d.skeleton_of(f),
                centre,
                area,
                polygon: pts,
            }
        })
        .collect();
    neighbours.sort_unstable();
    neighbours.dedup();
    (sites, neighbours)
}

/// The centre of gravity and area of a simple polygon (shoelace formula,
/// relative to its first vertex to keep the products small).
pub fn centroid(pts: &[(f64, f64)]) -> ((f64, f64), f64) {
    let o = pts[0];
    let (mut a2, mut cx, mut cy) = (0.0, 0.0, 0.0);
    for k in 1..pts.len().saturating_sub(1) {
        let (p, q) = (
            (pts[k].0 - o.0, pts[k].1 - o.1),
            (pts[k + 1].0 - o.0, pts[k + 1].1 - o.1),
        );
        let cross = p.0 * q.1 - p.1 * q.0;
        a2 += cross;
        cx += (p.0 + q.0) * cross;
        cy += (p.1 + q.1) * cross;
    }
    if a2.abs() < f64::MIN_POSITIVE {
        let n = pts.len() as f64;
        let sx: f64 = pts.iter().map(|p| p.0).sum();
        let sy: f64 = pts.iter().map(|p| p.1).sum();
        return ((sx / n, sy / n), 0.0);
    }
    (
        (o.0 + cx / (3.0 * a2), o.1 + cy / (3.0 * a2)),
        a2.abs() / 2.0,
    )
}

/// The points of the square lattice of spacing `spacing` (anchored at the
/// origin) that lie inside the convex counter-clockwise `polygon` by at
/// least `margin`.
pub fn lattice_points(polygon: &[(f64, f64)], spacing: f64, margin: f64) -> Vec<(f64, f64)> {
    let (mut lo, mut hi) = (polygon[0], polygon[0]);
    for p in polygon {
        lo = (lo.0.min(p.0), lo.1.min(p.1));
        hi = (hi.0.max(p.0), hi.1.max(p.1));
    }
    let inside = |q: (f64, f64)| {
        (0..polygon.len()).all(|i| {
            let (a, b) = (polygon[i], polygon[(i + 1) % polygon.len()]);
            let e = (b.0 - a.0, b.1 - a.1);
            let len = e.0.hypot(e.1);
            len == 0.0 || (e.0 * (q.1 - a.1) - e.1 * (q.0 - a.0)) / len >= margin
        })
    };
    let (i0, i1) = (
        (lo.0 / spacing).ceil() as i64,
        (hi.0 / spacing).floor() as i64,
    );
    let (j0, j1) = (
        (lo.1 / spacing).ceil() as i64,
        (hi.1 / spacing).floor() as i64,
    );
    (i0..=i1)
        .flat_map(|i| (j0..=j1).map(move |j| (i as f64 * spacing, j as f64 * spacing)))
        .filter(|&q| inside(q))
        .collect()
}
