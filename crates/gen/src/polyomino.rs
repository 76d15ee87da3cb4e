//! Polyominoes whose boundary is a simple polygon, and orthogonal maps
//! built from them: random growth, exhaustive enumeration, unit edges
//! traced into a ring and stretched by per-column and per-row widths.
//!
//! A finite set of unit cells has a simple polygon as its boundary exactly
//! when it is 4-connected, has no *pinch* (two cells touching only at a
//! corner while both cells sharing an edge with them are missing) and no
//! hole (a bounded 4-connected component of the complement). The
//! enumeration checks the three conditions globally; random growth checks
//! them locally at the added cell, and the tests compare the two.

use crate::ring::{drop_straight, into_map};
use rand::Rng;
use rand_chacha::ChaCha8Rng;
use std::collections::{BTreeSet, HashMap, HashSet, VecDeque};
use wai_exact::Point;
use wai_map::Map;

/// A unit cell `[x, x + 1] × [y, y + 1]`.
pub type Cell = (i32, i32);

const N4: [Cell; 4] = [(1, 0), (0, 1), (-1, 0), (0, -1)];
/// The eight neighbours in cyclic (counter-clockwise) order, starting east.
const N8: [Cell; 8] = [
    (1, 0),
    (1, 1),
    (0, 1),
    (-1, 1),
    (-1, 0),
    (-1, -1),
    (0, -1),
    (1, -1),
];

/// Which polyominoes count as different in an enumeration.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Symmetry {
    /// Equal up to translation only (OEIS A001168 counts all of them).
    Fixed,
    /// Equal up to translation, rotation and reflection (OEIS A000105).
    Free,
}

/// A polyomino whose boundary is a simple polygon: a non-empty,
/// 4-connected, hole-free, pinch-free set of unit cells, translated so that
/// its least x and least y are 0. Cells are kept sorted, so equal shapes
/// compare equal.
#[derive(Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Polyomino {
    cells: Vec<Cell>,
}

/// Translates `cells` so the least x and y are 0 and sorts them.
fn normalise(cells: impl IntoIterator<Item = Cell>) -> Vec<Cell> {
    let mut v: Vec<Cell> = cells.into_iter().collect();
    let mx = v.iter().map(|c| c.0).min().unwrap_or(0);
    let my = v.iter().map(|c| c.1).min().unwrap_or(0);
    for c in &mut v {
        *c = (c.0 - mx, c.1 - my);
    }
    v.sort_unstable();
    v.dedup();
    v
}

fn add(a: Cell, b: Cell) -> Cell {
    (a.0 + b.0, a.1 + b.1)
}

/// Whether the cell set is 4-connected.
fn connected(set: &HashSet<Cell>) -> bool {
    let Some(&start) = set.iter().next() else {
        return false;
    };
    let mut seen = HashSet::from([start]);
    let mut queue = VecDeque::from([start]);
    while let Some(c) = queue.pop_front() {
        for d in N4 {
            let nb = add(c, d);
            if set.contains(&nb) && seen.insert(nb) {
                queue.push_back(nb);
            }
        }
    }
    seen.len() == set.len()
}

/// Whether some 2×2 window holds exactly two diagonal cells.
fn has_pinch(set: &HashSet<Cell>) -> bool {
    set.iter().any(|&(x, y)| {
        [(1, 1), (1, -1)].iter().any(|&(dx, dy)| {
            set.contains(&(x + dx, y + dy))
                && !set.contains(&(x + dx, y))
                && !set.contains(&(x, y + dy))
        })
    })
}

/// Whether the complement has a bounded 4-connected component.
fn has_hole(set: &HashSet<Cell>) -> bool {
    let (x0, x1) = (
        set.iter().map(|c| c.0).min().unwrap_or(0) - 1,
        set.iter().map(|c| c.0).max().unwrap_or(0) + 1,
    );
    let (y0, y1) = (
        set.iter().map(|c| c.1).min().unwrap_or(0) - 1,
        set.iter().map(|c| c.1).max().unwrap_or(0) + 1,
    );
    let area = (x1 - x0 + 1) as usize * (y1 - y0 + 1) as usize;
    let start = (x0, y0);
    let mut seen = HashSet::from([start]);
    let mut queue = VecDeque::from([start]);
    while let Some(c) = queue.pop_front() {
        for d in N4 {
            let nb = add(c, d);
            if (x0..=x1).contains(&nb.0)
                && (y0..=y1).contains(&nb.1)
                && !set.contains(&nb)
                && seen.insert(nb)
            {
                queue.push_back(nb);
            }
        }
    }
    seen.len() + set.len() != area
}

/// Whether the boundary of the cell set is one simple polygon (global
/// check: connected, no pinch, no hole).
pub fn has_simple_boundary(cells: &[Cell]) -> bool {
    let set: HashSet<Cell> = cells.iter().copied().collect();
    !set.is_empty() && connected(&set) && !has_pinch(&set) && !has_hole(&set)
}

impl Polyomino {
    /// The polyomino of these cells, or `None` if they are empty or their
    /// boundary is not a simple polygon.
    pub fn new(cells: impl IntoIterator<Item = Cell>) -> Option<Self> {
        let cells = normalise(cells);
        has_simple_boundary(&cells).then_some(Polyomino { cells })
    }

    /// The single unit square.
    pub fn monomino() -> Self {
        Polyomino {
            cells: vec![(0, 0)],
        }
    }

    /// The cells, sorted, with least x and y equal to 0.
    pub fn cells(&self) -> &[Cell] {
        &self.cells
    }

    pub fn len(&self) -> usize {
        self.cells.len()
    }

    /// Always false: a polyomino has at least one cell.
    pub fn is_empty(&self) -> bool {
        self.cells.is_empty()
    }

    /// Columns and rows spanned: `(width, height)`.
    pub fn extent(&self) -> (usize, usize) {
        let w = self.cells.iter().map(|c| c.0).max().unwrap_or(0) + 1;
        let h = self.cells.iter().map(|c| c.1).max().unwrap_or(0) + 1;
        (w as usize, h as usize)
    }

    /// The number of boundary vertices (corners with one or three of the
    /// four cells around them present; pinch-freeness rules out two
    /// diagonal ones).
    pub fn vertex_count(&self) -> usize {
        let set: HashSet<Cell> = self.cells.iter().copied().collect();
        corner_count(&set)
    }

    /// Whether adding cell `c` (given in this polyomino's coordinates, not
    /// yet present, 4-adjacent to it) keeps the boundary simple — the local
    /// test random growth uses; the tests compare it with
    /// [`has_simple_boundary`].
    pub fn can_add(&self, c: Cell) -> bool {
        let set: HashSet<Cell> = self.cells.iter().copied().collect();
        !set.contains(&c) && N4.iter().any(|&d| set.contains(&add(c, d))) && can_add(&set, c)
    }

    /// The polyominoes obtained by removing one cell that still have a
    /// simple boundary (the shrink steps of the strategies).
    pub fn shrinks(&self) -> Vec<Polyomino> {
        if self.cells.len() <= 1 {
            return Vec::new();
        }
        (0..self.cells.len())
            .filter_map(|i| {
                let rest = self
                    .cells
                    .iter()
                    .enumerate()
                    .filter(|&(j, _)| j != i)
                    .map(|(_, &c)| c);
                Polyomino::new(rest)
            })
            .collect()
    }

    /// The boundary as a counter-clockwise ring of lattice points, one unit
    /// per cell, without 180° vertices. Starts at the lowest vertex of the
    /// leftmost column.
    pub fn ring(&self) -> Vec<Point> {
        let (w, h) = self.extent();
        self.ring_with_widths(&vec![1; w], &vec![1; h])
    }

    /// The boundary with every cell an `s × s` square.
    pub fn ring_scaled(&self, s: i128) -> Vec<Point> {
        let (w, h) = self.extent();
        self.ring_with_widths(&vec![s; w], &vec![s; h])
    }

    /// The boundary with column `i` of width `cols[i]` and row `j` of
    /// height `rows[j]` (all positive). Stretching the grid lines
    /// monotonically keeps the boundary simple and orthogonal.
    pub fn ring_with_widths(&self, cols: &[i128], rows: &[i128]) -> Vec<Point> {
        let (w, h) = self.extent();
        assert!(cols.len() >= w && rows.len() >= h);
        assert!(cols.iter().chain(rows).all(|&v| v > 0));
        let prefix = |v: &[i128]| {
            let mut out = vec![0i128];
            for &x in v {
                out.push(out.last().expect("non-empty") + x);
            }
            out
        };
        let (xs, ys) = (prefix(cols), prefix(rows));
        trace_boundary(&self.cells)
            .into_iter()
            .map(|(x, y)| Point::new(xs[x as usize], ys[y as usize]))
            .collect()
    }

    /// The map of the unit-scale boundary.
    pub fn to_map(&self) -> Map {
        into_map(self.ring(), format!("polyomino-{}", self.cells.len()))
    }
}

/// Corners of the cell set that are polygon vertices.
fn corner_count(set: &HashSet<Cell>) -> usize {
    let mut corners: HashSet<Cell> = HashSet::new();
    for &(x, y) in set {
        for c in [(x, y), (x + 1, y), (x, y + 1), (x + 1, y + 1)] {
            corners.insert(c);
        }
    }
    corners
        .into_iter()
        .filter(|&(x, y)| {
            let k = [(x, y), (x - 1, y), (x, y - 1), (x - 1, y - 1)]
                .iter()
                .filter(|c| set.contains(c))
                .count();
            k == 1 || k == 3
        })
        .count()
}

/// The counter-clockwise boundary of a simple polyomino as lattice corners
/// (before stretching), without 180° vertices.
fn trace_boundary(cells: &[Cell]) -> Vec<Cell> {
    let set: HashSet<Cell> = cells.iter().copied().collect();
    // Unit edges with the cell on their left.
    let mut next: HashMap<Cell, Cell> = HashMap::new();
    let mut put = |a: Cell, b: Cell| {
        let old = next.insert(a, b);
        assert!(old.is_none(), "pinch at {a:?}: not a simple polyomino");
    };
    for &(x, y) in cells {
        if !set.contains(&(x, y - 1)) {
            put((x, y), (x + 1, y));
        }
        if !set.contains(&(x + 1, y)) {
            put((x + 1, y), (x + 1, y + 1));
        }
        if !set.contains(&(x, y + 1)) {
            put((x + 1, y + 1), (x, y + 1));
        }
        if !set.contains(&(x - 1, y)) {
            put((x, y + 1), (x, y));
        }
    }
    let start = *next.keys().min().expect("non-empty polyomino");
    let mut ring = vec![start];
    let mut cur = next[&start];
    while cur != start {
        ring.push(cur);
        cur = next[&cur];
    }
    assert_eq!(ring.len(), next.len(), "boundary is not one cycle: hole");
    let pts: Vec<Point> = ring
        .iter()
        .map(|&(x, y)| Point::new(x.into(), y.into()))
        .collect();
    drop_straight(&pts)
        .into_iter()
        .map(|p| (p.x as i32, p.y as i32))
        .collect()
}

/// Whether adding `c` (not in `set`, 4-adjacent to it) to a simple cell set
/// keeps it simple: no new pinch at `c`, and the present cells among the
/// eight neighbours of `c` form one cyclic run (two runs would close a loop
/// around a missing neighbour: a hole).
pub(crate) fn can_add(set: &HashSet<Cell>, c: Cell) -> bool {
    let present: Vec<bool> = N8.iter().map(|&d| set.contains(&add(c, d))).collect();
    // Diagonals sit at odd indices; a present diagonal with both flanking
    // orthogonal neighbours missing is a pinch.
    for i in (1..8).step_by(2) {
        if present[i] && !present[i - 1] && !present[(i + 1) % 8] {
            return false;
        }
    }
    let runs = (0..8)
        .filter(|&i| present[i] && !present[(i + 7) % 8])
        .count();
    runs == 1
}

/// Whether the lattice point `(x, y)` is a corner of the boundary: one or
/// three of the four cells around it are present.
fn is_corner(set: &HashSet<Cell>, (x, y): Cell) -> bool {
    let k = [(x, y), (x - 1, y), (x, y - 1), (x - 1, y - 1)]
        .iter()
        .filter(|c| set.contains(c))
        .count();
    k == 1 || k == 3
}

/// The four lattice corners of cell `(x, y)`.
fn cell_corners((x, y): Cell) -> [Cell; 4] {
    [(x, y), (x + 1, y), (x, y + 1), (x + 1, y + 1)]
}

/// Grows a random simple polyomino from one cell until its boundary has at
/// least `min_vertices` vertices or it has `max_cells` cells.
///
/// Each step adds a random empty 4-neighbour that keeps the boundary simple
/// ([`can_add`]); with probability 3/4 it prefers one touching exactly one
/// cell, which makes branchy shapes with many vertices. Candidates are drawn
/// from the frontier by rejection (at most 64 draws, then a deterministic
/// scan), and the corner count is updated locally, so growth takes about
/// linear time. One added cell changes the vertex count by at most 4, so the
/// result has fewer than `min_vertices + 4` vertices when it stops on the
/// count.
pub(crate) fn grow(min_vertices: usize, max_cells: usize, rng: &mut ChaCha8Rng) -> Polyomino {
    let mut set: HashSet<Cell> = HashSet::from([(0, 0)]);
    let mut order: Vec<Cell> = vec![(0, 0)];
    let mut corners = 4usize;
    // The empty 4-neighbours of the set, in insertion order (deterministic).
    let mut frontier: Vec<Cell> = N4.iter().map(|&d| add((0, 0), d)).collect();
    let mut in_frontier: HashMap<Cell, usize> =
        frontier.iter().enumerate().map(|(i, &c)| (c, i)).collect();
    let is_leaf = |set: &HashSet<Cell>, c: Cell| {
        N4.iter().filter(|&&d| set.contains(&add(c, d))).count() == 1
    };
    while corners < min_vertices && set.len() < max_cells {
        let want_leaf = rng.random_ratio(3, 4);
        let mut chosen = None;
        for attempt in 0..64 {
            let c = frontier[rng.random_range(0..frontier.len())];
            if can_add(&set, c) && (!want_leaf || attempt >= 48 || is_leaf(&set, c)) {
                chosen = Some(c);
                break;
            }
        }
        // A simple polyomino always has an addable neighbour: a cell next
        // to the lowest cell of the leftmost column is one.
        let c = chosen.unwrap_or_else(|| {
            frontier
                .iter()
                .copied()
                .filter(|&c| can_add(&set, c))
                .min()
                .expect("a simple polyomino has an addable neighbour")
        });
        let before = cell_corners(c)
            .iter()
            .filter(|&&g| is_corner(&set, g))
            .count();
        set.insert(c);
        let after = cell_corners(c)
            .iter()
            .filter(|&&g| is_corner(&set, g))
            .count();
        corners = corners + after - before;
        order.push(c);
        // Remove c from the frontier (swap-remove) and add its empty neighbours.
        let i = in_frontier.remove(&c).expect("c came from the frontier");
        frontier.swap_remove(i);
        if i < frontier.len() {
            in_frontier.insert(frontier[i], i);
        }
        for d in N4 {
            let nb = add(c, d);
            if !set.contains(&nb) && !in_frontier.contains_key(&nb) {
                in_frontier.insert(nb, frontier.len());
                frontier.push(nb);
            }
        }
    }
    debug_assert_eq!(corners, corner_count(&set));
    Polyomino {
        cells: normalise(order),
    }
}

/// All fixed polyominoes (up to translation) with exactly `k` cells,
/// holes and pinches included, as normalised sorted cell lists.
fn all_fixed(k: usize) -> BTreeSet<Vec<Cell>> {
    let mut level: BTreeSet<Vec<Cell>> = BTreeSet::new();
    if k == 0 {
        return level;
    }
    level.insert(vec![(0, 0)]);
    for _ in 1..k {
        let mut next = BTreeSet::new();
        for p in &level {
            let set: HashSet<Cell> = p.iter().copied().collect();
            for &c in p {
                for d in N4 {
                    let nb = add(c, d);
                    if !set.contains(&nb) {
                        next.insert(normalise(p.iter().copied().chain([nb])));
                    }
                }
            }
        }
        level = next;
    }
    level
}

/// The least of the eight rotations and reflections of a cell list.
fn free_canonical(cells: &[Cell]) -> Vec<Cell> {
    let maps: [fn(Cell) -> Cell; 8] = [
        |(x, y)| (x, y),
        |(x, y)| (-x, y),
        |(x, y)| (x, -y),
        |(x, y)| (-x, -y),
        |(x, y)| (y, x),
        |(x, y)| (-y, x),
        |(x, y)| (y, -x),
        |(x, y)| (-y, -x),
    ];
    maps.iter()
        .map(|f| normalise(cells.iter().map(|&c| f(c))))
        .min()
        .expect("eight transforms")
}

/// Every polyomino with exactly `k` cells whose boundary is a simple
/// polygon, each once up to `symmetry`, in sorted order.
///
/// Counts (verified by the tests): fixed 1, 2, 6, 19, 63, 216, 756, 2684
/// for k = 1..8, i.e. OEIS A001168 (1, 2, 6, 19, 63, 216, 760, 2725) minus
/// the fixed polyominoes with a hole (4 at k = 7, 41 at k = 8); free 1, 1,
/// 2, 5, 12, 35, 107, 363 (OEIS A000104, polyominoes without holes). A
/// pinch in a connected set always encloses a hole (the 4-path joining the
/// two diagonal cells closes a loop around one of the two missing cells),
/// so excluding pinches excludes nothing further.
pub fn polyominoes(k: usize, symmetry: Symmetry) -> Vec<Polyomino> {
    let fixed = all_fixed(k);
    let simple = fixed.into_iter().filter(|p| has_simple_boundary(p));
    let cells: BTreeSet<Vec<Cell>> = match symmetry {
        Symmetry::Fixed => simple.collect(),
        Symmetry::Free => simple.map(|p| free_canonical(&p)).collect(),
    };
    cells.into_iter().map(|cells| Polyomino { cells }).collect()
}

/// The maps of all polyominoes with `1..=max_cells` cells and a simple
/// boundary (unit squares), smallest first; see [`polyominoes`] for the
/// counts.
pub fn exhaustive_polyomino_maps(
    max_cells: usize,
    symmetry: Symmetry,
) -> impl Iterator<Item = Map> {
    (1..=max_cells).flat_map(move |k| polyominoes(k, symmetry).into_iter().map(|p| p.to_map()))
}
