//! From free cells to a region with a clean boundary, and its boundary
//! traced along cell edges into rings.
//!
//! Cells are addressed `(c, r)`, column from the left and row from the
//! bottom, cell `(c, r)` covering `[c, c+1] × [r, r+1]` in grid units;
//! masks are row after row from the bottom.
//!
//! The map model asks that no ring touch itself or another ring, even at a
//! corner. On a grid that happens exactly at a **pinch**: a corner whose
//! four cells alternate (two region cells diagonal, two others diagonal).
//! Each pinch is resolved by giving up one of its region cells (the upper
//! one), which only shrinks the free space; the region is then taken again
//! as one 4-connected component. With no pinch, 4- and 8-connectivity
//! agree and every corner has at most one boundary edge leaving it, so the
//! boundary is a set of disjoint simple rings: one around the region
//! (counter-clockwise) and one around each obstacle it encloses
//! (clockwise).

use std::collections::VecDeque;

/// What [`region`] did.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct RegionReport {
    /// Free cells in the grid.
    pub free_cells: u64,
    /// 4-connected components of free cells.
    pub components: u64,
    /// Cells of the chosen component as first found.
    pub component_cells: u64,
    /// Free cells given up to resolve pinches.
    pub pinch_cells: u64,
    /// Cells lost because giving up pinch cells split the region (the
    /// smaller parts).
    pub split_off_cells: u64,
    /// Enclosed obstacles below the speck size, filled; and their cells.
    pub specks_filled: u64,
    pub speck_cells: u64,
    /// Cells of the final region.
    pub region_cells: u64,
    /// Enclosed obstacles left: the holes.
    pub holes: u64,
}

/// The cell holding the start, if any, else the largest component.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Choice {
    Containing(usize, usize),
    Largest,
}

/// The region of `free` (a `width × height` mask) chosen by `choice`, with
/// its pinches resolved and its enclosed obstacles of fewer than
/// `min_hole_cells` cells filled. `None` if `choice` names a cell that is
/// not free, or no cell is free.
pub fn region(
    free: &[bool],
    width: usize,
    height: usize,
    choice: Choice,
    min_hole_cells: u64,
) -> Option<(Vec<bool>, RegionReport)> {
    let mut report = RegionReport {
        free_cells: free.iter().filter(|&&f| f).count() as u64,
        ..RegionReport::default()
    };
    let (labels, sizes) = components(free, width, height, true);
    report.components = sizes.len() as u64;
    let chosen = match choice {
        Choice::Containing(c, r) => match labels[r * width + c] {
            0 => return None,
            l => l,
        },
        Choice::Largest => largest(&sizes)?,
    };
    report.component_cells = sizes[chosen as usize - 1];
    let mut mask: Vec<bool> = labels.iter().map(|&l| l == chosen).collect();
    drop(labels);
    // Resolve pinches until none is left; each pass gives up >= 1 cell.
    loop {
        let removed = resolve_pinches(&mut mask, width, height);
        if removed == 0 {
            break;
        }
        report.pinch_cells += removed;
        let before = mask.iter().filter(|&&m| m).count() as u64;
        let (labels, sizes) = components(&mask, width, height, true);
        let keep = match choice {
            Choice::Containing(c, r) if labels[r * width + c] != 0 => labels[r * width + c],
            _ => largest(&sizes)?,
        };
        for (m, &l) in mask.iter_mut().zip(&labels) {
            *m = l == keep;
        }
        report.split_off_cells += before - sizes[keep as usize - 1];
    }
    // Enclosed obstacles: components of the rest that do not reach the
    // grid's border. With no pinch, 4-connectivity is the right one.
    let (labels, sizes) = components(&mask, width, height, false);
    let mut touches_border = vec![false; sizes.len() + 1];
    for c in 0..width {
        touches_border[labels[c] as usize] = true;
        touches_border[labels[(height - 1) * width + c] as usize] = true;
    }
    for r in 0..height {
        touches_border[labels[r * width] as usize] = true;
        touches_border[labels[r * width + width - 1] as usize] = true;
    }
    let speck: Vec<bool> = (0..=sizes.len())
        .map(|l| l > 0 && !touches_border[l] && sizes[l - 1] < min_hole_cells)
        .collect();
    for (m, &l) in mask.iter_mut().zip(&labels) {
        if speck[l as usize] {
            *m = true;
        }
    }
    for l in 1..=sizes.len() {
        if speck[l] {
            report.specks_filled += 1;
            report.speck_cells += sizes[l - 1];
        } else if !touches_border[l] {
            report.holes += 1;
        }
    }
    report.region_cells = mask.iter().filter(|&&m| m).count() as u64;
    Some((mask, report))
}

fn largest(sizes: &[u64]) -> Option<u32> {
    // The first of the largest, in scan order: deterministic.
    let best = sizes.iter().copied().max()?;
    Some(sizes.iter().position(|&s| s == best)? as u32 + 1)
}

/// 4-connected components of the cells whose mask equals `value`: a label
/// per cell (0 for the others) and each label's size (label `l` at `l-1`).
pub fn components(mask: &[bool], width: usize, height: usize, value: bool) -> (Vec<u32>, Vec<u64>) {
    let mut labels = vec![0u32; mask.len()];
    let mut sizes = Vec::new();
    let mut queue = VecDeque::new();
    for start in 0..mask.len() {
        if mask[start] != value || labels[start] != 0 {
            continue;
        }
        let label = sizes.len() as u32 + 1;
        let mut size = 0;
        labels[start] = label;
        queue.push_back(start);
        while let Some(k) = queue.pop_front() {
            size += 1;
            let (c, r) = (k % width, k / width);
            let mut visit = |j: usize| {
                if mask[j] == value && labels[j] == 0 {
                    labels[j] = label;
                    queue.push_back(j);
                }
            };
            if c > 0 {
                visit(k - 1);
            }
            if c + 1 < width {
                visit(k + 1);
            }
            if r > 0 {
                visit(k - width);
            }
            if r + 1 < height {
                visit(k + width);
            }
        }
        sizes.push(size);
    }
    (labels, sizes)
}

/// Whether the interior corner `(c, r)` (1 ≤ c < width, 1 ≤ r < height) is
/// a pinch of `mask`.
fn is_pinch(mask: &[bool], width: usize, c: usize, r: usize) -> bool {
    let at = |c: usize, r: usize| mask[r * width + c];
    let (bl, br, tl, tr) = (at(c - 1, r - 1), at(c, r - 1), at(c - 1, r), at(c, r));
    bl == tr && tl == br && bl != tl
}

/// Give up the upper region cell of every pinch; how many were given up.
fn resolve_pinches(mask: &mut [bool], width: usize, height: usize) -> u64 {
    let mut removed = 0;
    for r in 1..height {
        for c in 1..width {
            if is_pinch(mask, width, c, r) {
                let upper = if mask[r * width + c - 1] { c - 1 } else { c };
                mask[r * width + upper] = false;
                removed += 1;
            }
        }
    }
    removed
}

/// The boundary of a pinch-free `mask` as rings of grid corners, each
/// without its straight corners, the region on the left of every edge:
/// counter-clockwise around the region, clockwise around what it encloses.
/// Rings come in scan order of their lowest-leftmost corner.
pub fn rings(mask: &[bool], width: usize, height: usize) -> Vec<Vec<(i64, i64)>> {
    const NONE: u8 = 0;
    const RIGHT: u8 = 1;
    const UP: u8 = 2;
    const LEFT: u8 = 3;
    const DOWN: u8 = 4;
    let cw = width + 1;
    let m = |c: isize, r: isize| {
        c >= 0
            && r >= 0
            && (c as usize) < width
            && (r as usize) < height
            && mask[r as usize * width + c as usize]
    };
    // The boundary edge leaving each corner, if any.
    let mut out = vec![NONE; cw * (height + 1)];
    for r in 0..height {
        for c in 0..width {
            if !mask[r * width + c] {
                continue;
            }
            let (ci, ri) = (c as isize, r as isize);
            if !m(ci, ri - 1) {
                out[r * cw + c] = RIGHT;
            }
            if !m(ci + 1, ri) {
                out[r * cw + c + 1] = UP;
            }
            if !m(ci, ri + 1) {
                out[(r + 1) * cw + c + 1] = LEFT;
            }
            if !m(ci - 1, ri) {
                out[(r + 1) * cw + c] = DOWN;
            }
        }
    }
    let mut rings = Vec::new();
    for start in 0..out.len() {
        if out[start] == NONE {
            continue;
        }
        let mut ring = Vec::new();
        let mut k = start;
        let mut came = NONE;
        loop {
            let dir = out[k];
            if dir == NONE {
                break;
            }
            out[k] = NONE;
            if dir != came {
                ring.push(k);
            }
            came = dir;
            k = match dir {
                RIGHT => k + 1,
                UP => k + cw,
                LEFT => k - 1,
                _ => k - cw,
            };
        }
        // The start was kept whatever its turn; drop_straight decides.
        rings.push(
            ring.into_iter()
                .map(|k| ((k % cw) as i64, (k / cw) as i64))
                .collect::<Vec<_>>(),
        );
    }
    rings.into_iter().map(|ring| drop_straight(&ring)).collect()
}

/// A ring without corners where it goes straight on.
fn drop_straight(ring: &[(i64, i64)]) -> Vec<(i64, i64)> {
    let n = ring.len();
    (0..n)
        .filter(|&i| {
            let (a, b, c) = (ring[(i + n - 1) % n], ring[i], ring[(i + 1) % n]);
            (b.0 - a.0) * (c.1 - b.1) != (b.1 - a.1) * (c.0 - b.0)
        })
        .map(|i| ring[i])
        .collect()
}

/// Twice the signed area of a ring of grid corners.
pub fn area_twice(ring: &[(i64, i64)]) -> i128 {
    let n = ring.len();
    (0..n)
        .map(|i| {
            let (a, b) = (ring[i], ring[(i + 1) % n]);
            i128::from(a.0) * i128::from(b.1) - i128::from(b.0) * i128::from(a.1)
        })
        .sum()
}
