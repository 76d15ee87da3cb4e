//! Point location in the triangulation: a uniform grid over the map's
//! bounding box listing, per cell, the triangles whose bounding boxes meet
//! it.

use crate::triangulation::Triangulation;
use rug::ops::DivRounding;
use rug::Integer;
use wai_exact::{Point, RatPoint};
use wai_map::Map;

/// Buckets of triangles by grid cell.
#[derive(Clone, Debug)]
pub(crate) struct Grid {
    origin: Point,
    /// Side of a cell in map units (at least 1).
    cell: i128,
    cols: usize,
    rows: usize,
    /// Triangles of cell `(i, j)` at `start[j * cols + i] .. start[.. + 1]`.
    start: Vec<u32>,
    items: Vec<u32>,
}

impl Grid {
    /// About one triangle per cell.
    pub(crate) fn new(map: &Map, tri: &Triangulation) -> Grid {
        let (lo, hi) = map.bounding_box();
        let (w, h) = (hi.x - lo.x + 1, hi.y - lo.y + 1);
        // Cell side: the longer extent over sqrt(T).
        let target = (tri.len().isqrt() + 1) as i128;
        let cell = (w.max(h) / target).max(1);
        let cols = usize::try_from((w + cell - 1) / cell).unwrap_or(1).max(1);
        let rows = usize::try_from((h + cell - 1) / cell).unwrap_or(1).max(1);
        let v = map.vertices();
        let index = |c: i128, o: i128| ((c - o) / cell) as usize;
        let mut buckets: Vec<Vec<u32>> = vec![Vec::new(); cols * rows];
        for t in 0..tri.len() {
            let c = tri.triangle(t).map(|i| v[i]);
            let (x0, x1) = (
                c.iter().map(|p| p.x).min().unwrap(),
                c.iter().map(|p| p.x).max().unwrap(),
            );
            let (y0, y1) = (
                c.iter().map(|p| p.y).min().unwrap(),
                c.iter().map(|p| p.y).max().unwrap(),
            );
            for j in index(y0, lo.y)..=index(y1, lo.y).min(rows - 1) {
                for i in index(x0, lo.x)..=index(x1, lo.x).min(cols - 1) {
                    buckets[j * cols + i].push(t as u32);
                }
            }
        }
        let mut start = Vec::with_capacity(buckets.len() + 1);
        let mut items = Vec::new();
        for b in buckets {
            start.push(items.len() as u32);
            items.extend(b);
        }
        start.push(items.len() as u32);
        Grid {
            origin: lo,
            cell,
            cols,
            rows,
            start,
            items,
        }
    }

    /// The triangles that may hold `p`; empty if p is outside the box.
    pub(crate) fn candidates(&self, p: &RatPoint) -> &[u32] {
        // floor((X/W − origin) / cell) = floor((X − origin·W) / (cell·W)),
        // in checked `i128` when the values fit, else in GMP.
        let small = |num: &Integer, o: i128| -> Option<Option<usize>> {
            let (num, w) = (num.to_i128()?, p.hw().to_i128()?);
            let d = w.checked_mul(self.cell)?;
            let q = num.checked_sub(w.checked_mul(o)?)?.div_euclid(d);
            Some(usize::try_from(q).ok())
        };
        let axis = |num: &Integer, o: i128| -> Option<usize> {
            if let Some(q) = small(num, o) {
                return q;
            }
            let d = Integer::from(p.hw() * self.cell);
            let q = (num - Integer::from(p.hw() * o)).div_floor(d);
            q.to_usize()
        };
        let (Some(i), Some(j)) = (axis(p.hx(), self.origin.x), axis(p.hy(), self.origin.y)) else {
            return &[];
        };
        if i >= self.cols || j >= self.rows {
            return &[];
        }
        let k = j * self.cols + i;
        &self.items[self.start[k] as usize..self.start[k + 1] as usize]
    }
}
