//! The overlay of one equivalence class (Alg 3.14 steps 18–23): every cell
//! of the class — of every dimension, kept or absorbed — translated so that
//! its embedding's origin vertex sits at the skeleton origin, with a slab
//! structure for point location (Example 3.5, Fig 3.12 (c)).
//!
//! Slabs are cut at the x of every cell vertex and of every crossing of two
//! cell edges (cells of different embeddings overlap, and their edges
//! cross). Inside an open slab no two edges cross, so the edges spanning it
//! are ordered bottom to top; collinear edges of different cells are one
//! piece. The open trapezoid between two consecutive pieces lies inside or
//! outside each 2-cell as a whole, so it carries the list of 2-cells that
//! cover it: a query strictly inside a trapezoid is answered by two binary
//! searches and that list.
//!
//! A query on a slab line or on a piece (a point on a ray, a 1- or 0-cell,
//! a cell edge) locates the four points p + (±ε, ±δ) around it
//! symbolically: the 2-cells holding p are those holding all four. The
//! 1- and 0-cells holding p are found by the pieces through it, its slab
//! line and its point, and tested exactly. The tests compare every path
//! with testing every cell of the class (`locate_exact`).

use crate::fast::cmp_products;
use crate::{small_i128, small_triple};
use rug::{Integer, Rational};
use std::cmp::Ordering;
use std::collections::HashMap;
use wai_exact::{orientation_rat, Orientation, RatPoint};

/// Where a cell of the decomposition lies: a 2-cell (a face of the
/// arrangement) or a 1- or 0-cell (an index into
/// `Decomposition::lower_cells`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum CellSite {
    Face(usize),
    Lower(usize),
}

/// A cell's shape, translated by minus its embedding's origin vertex.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Shape {
    /// An open convex polygon, counter-clockwise (straight vertices allowed).
    Polygon(Vec<RatPoint>),
    /// An open segment.
    Segment(RatPoint, RatPoint),
    /// A point.
    Point(RatPoint),
}

/// One cell of a class in the overlay.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Item {
    /// The map vertex that is the origin v0 of the cell's embedding.
    pub origin: usize,
    pub site: CellSite,
    pub shape: Shape,
}

/// A line a·x + b·y = c with integer coefficients, primitive; b > 0 for a
/// non-vertical line.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Line {
    pub a: Integer,
    pub b: Integer,
    pub c: Integer,
}

impl Line {
    fn through(p: &RatPoint, q: &RatPoint) -> Line {
        let zero = RatPoint::from_i128(0, 0, 1).expect("w = 1");
        let l = crate::view::label_through(p, q, &zero);
        let (a, b, c) = (l.a, l.b, l.c);
        if b < 0 {
            Line {
                a: -a,
                b: -b,
                c: -c,
            }
        } else {
            Line { a, b, c }
        }
    }

    /// The sign of a·x + b·y − c at `p`: above the line when positive (b > 0).
    fn side(&self, p: &RatPoint) -> Ordering {
        (Integer::from(&self.a * p.hx()) + Integer::from(&self.b * p.hy())
            - Integer::from(&self.c * p.hw()))
        .cmp0()
    }

    /// y on this (non-vertical) line at `x`.
    fn y_at(&self, x: &Rational) -> Rational {
        (Rational::from(&self.c) - Rational::from(&self.a) * x) / Rational::from(&self.b)
    }
}

/// One slab: the pieces that span it, bottom to top, and by trapezoid (0
/// below the first piece, `pieces.len()` above the last) the items whose
/// 2-cell covers it.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Slab {
    pub pieces: Vec<u32>,
    pub labels: Vec<Vec<u32>>,
}

/// The overlay of one class with its point-location structure.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ClassOverlay {
    pub items: Vec<Item>,
    /// The slab boundaries, ascending.
    pub xs: Vec<Rational>,
    pub lines: Vec<Line>,
    /// Slab `s` lies between `xs[s]` and `xs[s + 1]`.
    pub slabs: Vec<Slab>,
    /// `xs` and `lines` as `i128`s when they all fit: the fast path.
    fast: Option<FastParts>,
    /// The 1- and 0-cells by where they lie, for points on slab lines and
    /// pieces. Derived from `items` and `lines`.
    lower: LowerIndex,
}

/// The 1- and 0-cells of a class by their supporting line, their x (a
/// vertical segment) or their point.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
struct LowerIndex {
    /// Non-vertical segments by line id.
    on_line: Vec<Vec<u32>>,
    /// Vertical segments by their x.
    vertical: HashMap<Rational, Vec<u32>>,
    /// 0-cells by their point.
    points: HashMap<RatPoint, Vec<u32>>,
}

/// The slab boundaries as (numerator, denominator) and the lines as
/// (a, b, c), all in `i128`.
type FastParts = (Vec<(i128, i128)>, Vec<[i128; 3]>);

fn x_of(p: &RatPoint) -> Rational {
    Rational::from((p.hx().clone(), p.hw().clone()))
}

impl Item {
    /// Whether `p` lies in the (open) cell.
    pub fn contains(&self, p: &RatPoint) -> bool {
        match &self.shape {
            Shape::Polygon(ring) => {
                let k = ring.len();
                (0..k).all(|i| {
                    orientation_rat(&ring[i], &ring[(i + 1) % k], p)
                        == Orientation::CounterClockwise
                })
            }
            Shape::Segment(a, b) => {
                orientation_rat(a, b, p) == Orientation::Collinear
                    && p.sub(a).dot_sign(&b.sub(a)) == Ordering::Greater
                    && p.sub(b).dot_sign(&a.sub(b)) == Ordering::Greater
            }
            Shape::Point(q) => q == p,
        }
    }

    fn vertices(&self) -> Vec<&RatPoint> {
        match &self.shape {
            Shape::Polygon(ring) => ring.iter().collect(),
            Shape::Segment(a, b) => vec![a, b],
            Shape::Point(q) => vec![q],
        }
    }

    /// The edges (as point pairs) of a polygon or the segment itself.
    fn edges(&self) -> Vec<(&RatPoint, &RatPoint)> {
        match &self.shape {
            Shape::Polygon(ring) => {
                let k = ring.len();
                (0..k).map(|i| (&ring[i], &ring[(i + 1) % k])).collect()
            }
            Shape::Segment(a, b) => vec![(a, b)],
            Shape::Point(_) => Vec::new(),
        }
    }
}

/// A non-vertical edge for the slab build: its line and x-range.
struct Span {
    item: u32,
    line: u32,
    x0: Rational,
    x1: Rational,
}

impl ClassOverlay {
    /// Build the overlay and its slabs.
    pub fn new(items: Vec<Item>) -> ClassOverlay {
        let mut lines: Vec<Line> = Vec::new();
        let mut line_ids: HashMap<Line, u32> = HashMap::new();
        let mut xs: Vec<Rational> = Vec::new();
        let mut spans: Vec<Span> = Vec::new();
        for (i, it) in items.iter().enumerate() {
            xs.extend(it.vertices().into_iter().map(x_of));
            for (p, q) in it.edges() {
                let (xp, xq) = (x_of(p), x_of(q));
                if xp == xq {
                    continue; // vertical: on a slab line
                }
                let l = Line::through(p, q);
                let next = lines.len() as u32;
                let id = *line_ids.entry(l.clone()).or_insert_with(|| {
                    lines.push(l);
                    next
                });
                let (x0, x1) = if xp < xq { (xp, xq) } else { (xq, xp) };
                spans.push(Span {
                    item: i as u32,
                    line: id,
                    x0,
                    x1,
                });
            }
        }
        // Crossings of edges on different lines, strictly inside both
        // x-ranges: a sweep over x-ranges.
        let mut order: Vec<usize> = (0..spans.len()).collect();
        order.sort_by(|&a, &b| spans[a].x0.cmp(&spans[b].x0));
        let mut active: Vec<usize> = Vec::new();
        let mut seen: std::collections::HashSet<(u32, u32)> = std::collections::HashSet::new();
        for &s in &order {
            active.retain(|&t| spans[t].x1 > spans[s].x0);
            for &t in &active {
                let (la, lb) = (spans[s].line, spans[t].line);
                if la == lb {
                    continue;
                }
                let key = (la.min(lb), la.max(lb));
                if let Some(x) = crossing_x(&lines[la as usize], &lines[lb as usize]) {
                    let inside = |sp: &Span| sp.x0 < x && x < sp.x1;
                    // Two lines cross once: one x per pair of lines.
                    if inside(&spans[s]) && inside(&spans[t]) && seen.insert(key) {
                        xs.push(x);
                    }
                }
            }
            active.push(s);
        }
        xs.sort();
        xs.dedup();
        let nslabs = xs.len().saturating_sub(1);
        let mut members: Vec<Vec<(u32, u32)>> = vec![Vec::new(); nslabs];
        for sp in &spans {
            let i0 = xs.binary_search(&sp.x0).expect("a vertex x");
            let i1 = xs.binary_search(&sp.x1).expect("a vertex x");
            for m in &mut members[i0..i1] {
                m.push((sp.item, sp.line));
            }
        }
        let mut slabs = Vec::with_capacity(nslabs);
        for (s, mem) in members.into_iter().enumerate() {
            let mid = (Rational::from(&xs[s] + &xs[s + 1])) / 2u32;
            let mut ids: Vec<u32> = mem.iter().map(|&(_, l)| l).collect();
            ids.sort_unstable();
            ids.dedup();
            let mut keyed: Vec<(Rational, u32)> = ids
                .into_iter()
                .map(|l| (lines[l as usize].y_at(&mid), l))
                .collect();
            keyed.sort();
            let pieces: Vec<u32> = keyed.iter().map(|&(_, l)| l).collect();
            let pos: HashMap<u32, usize> =
                pieces.iter().enumerate().map(|(i, &l)| (l, i)).collect();
            let mut labels = vec![Vec::new(); pieces.len() + 1];
            // Per polygon item: its lowest and highest piece here.
            let mut range: HashMap<u32, (usize, usize)> = HashMap::new();
            for &(item, l) in &mem {
                if !matches!(items[item as usize].shape, Shape::Polygon(_)) {
                    continue;
                }
                let p = pos[&l];
                range
                    .entry(item)
                    .and_modify(|r| *r = (r.0.min(p), r.1.max(p)))
                    .or_insert((p, p));
            }
            let mut covered: Vec<(u32, (usize, usize))> = range.into_iter().collect();
            covered.sort_unstable();
            for (item, (lo, hi)) in covered {
                for label in &mut labels[lo + 1..=hi] {
                    label.push(item);
                }
            }
            slabs.push(Slab { pieces, labels });
        }
        ClassOverlay::from_parts(items, xs, lines, slabs)
    }

    /// An overlay from its parts (as read from a file).
    pub fn from_parts(
        items: Vec<Item>,
        xs: Vec<Rational>,
        lines: Vec<Line>,
        slabs: Vec<Slab>,
    ) -> ClassOverlay {
        let fx: Option<Vec<(i128, i128)>> = xs
            .iter()
            .map(|x| Some((small_i128(x.numer())?, small_i128(x.denom())?)))
            .collect();
        let fl: Option<Vec<[i128; 3]>> = lines
            .iter()
            .map(|l| Some([small_i128(&l.a)?, small_i128(&l.b)?, small_i128(&l.c)?]))
            .collect();
        let mut lower = LowerIndex {
            on_line: vec![Vec::new(); lines.len()],
            ..LowerIndex::default()
        };
        let line_ids: HashMap<&Line, u32> = lines
            .iter()
            .enumerate()
            .map(|(i, l)| (l, i as u32))
            .collect();
        for (i, it) in items.iter().enumerate() {
            let i = i as u32;
            match &it.shape {
                Shape::Polygon(_) => {}
                Shape::Point(p) => lower.points.entry(p.clone()).or_default().push(i),
                Shape::Segment(a, b) => {
                    let x = x_of(a);
                    if x == x_of(b) {
                        lower.vertical.entry(x).or_default().push(i);
                    } else if let Some(&l) = line_ids.get(&Line::through(a, b)) {
                        lower.on_line[l as usize].push(i);
                    }
                }
            }
        }
        ClassOverlay {
            items,
            xs,
            lines,
            slabs,
            fast: fx.zip(fl),
            lower,
        }
    }

    /// Which slab holds `p` (Err: on slab line `i`); the fast path when
    /// everything fits.
    fn slab_of(&self, p: &RatPoint, q: Option<[i128; 3]>) -> Result<usize, usize> {
        if let (Some((xs, _)), Some(q)) = (&self.fast, q) {
            // The sign of x_i − X/W: x_i = n/d, d > 0, W > 0.
            return xs.binary_search_by(|&(n, d)| cmp_products(n, q[2], q[0], d));
        }
        self.xs.binary_search(&x_of(p))
    }

    /// The side of line `l` that `p` is on.
    fn side(&self, l: u32, p: &RatPoint, q: Option<[i128; 3]>) -> Ordering {
        if let (Some((_, lines)), Some(q)) = (&self.fast, q) {
            let [a, b, c] = lines[l as usize];
            let s = a
                .checked_mul(q[0])
                .zip(b.checked_mul(q[1]))
                .zip(c.checked_mul(q[2]))
                .and_then(|((ax, by), cw)| ax.checked_add(by)?.checked_sub(cw));
            if let Some(s) = s {
                return s.cmp(&0);
            }
        }
        self.lines[l as usize].side(p)
    }

    /// The items whose cell contains `p`, ascending.
    pub fn locate(&self, p: &RatPoint) -> Vec<u32> {
        match self.locate_fast(p) {
            Some(found) => found.to_vec(),
            None => self.locate_degenerate(p),
        }
    }

    /// The point-location path: the label of the open trapezoid holding
    /// `p`, or `None` when `p` lies on a slab line or a piece.
    pub fn locate_fast(&self, p: &RatPoint) -> Option<&[u32]> {
        let q = small_triple(p);
        let s = match self.slab_of(p, q) {
            Ok(_) => return None,
            Err(0) => return Some(&[]),
            Err(i) if i == self.xs.len() => return Some(&[]),
            Err(i) => i - 1,
        };
        let slab = &self.slabs[s];
        let (mut lo, mut hi) = (0usize, slab.pieces.len());
        // Invariant: pieces[..lo] are below p, pieces[hi..] above.
        while lo < hi {
            let mid = (lo + hi) / 2;
            match self.side(slab.pieces[mid], p, q) {
                Ordering::Greater => lo = mid + 1,
                Ordering::Less => hi = mid,
                Ordering::Equal => return None,
            }
        }
        Some(&slab.labels[lo])
    }

    /// A point on a slab line or a piece. The 2-cells (open and convex)
    /// holding it are those holding the four points p + (±ε, ±δ), δ ≪ ε
    /// infinitesimal, around it: each lies strictly inside a trapezoid, so
    /// four symbolic point locations and the intersection of their labels
    /// give them. The 1- and 0-cells holding it lie on a piece through it,
    /// on its slab line, or at it, and are tested exactly.
    fn locate_degenerate(&self, p: &RatPoint) -> Vec<u32> {
        let q = small_triple(p);
        let at = self.slab_of(p, q);
        let (left, right) = match at {
            // On slab line i: the slabs on either side.
            Ok(i) => (i.checked_sub(1), Some(i).filter(|&s| s < self.slabs.len())),
            Err(i) if i == 0 || i == self.xs.len() => return Vec::new(),
            Err(i) => (Some(i - 1), Some(i - 1)),
        };
        let mut found: Option<Vec<u32>> = None;
        for (sx, slab) in [(Ordering::Greater, right), (Ordering::Less, left)] {
            for sy in [Ordering::Greater, Ordering::Less] {
                let label: &[u32] = match slab {
                    Some(s) => self.label_beside(s, p, q, sx, sy),
                    None => &[],
                };
                found = Some(match found {
                    None => label.to_vec(),
                    Some(f) => f
                        .into_iter()
                        .filter(|i| label.binary_search(i).is_ok())
                        .collect(),
                });
            }
        }
        let mut found = found.unwrap_or_default();
        let exact = |found: &mut Vec<u32>, ids: &[u32]| {
            found.extend(ids.iter().filter(|&&i| self.items[i as usize].contains(p)));
        };
        if let Some(ids) = self.lower.points.get(p) {
            found.extend(ids);
        }
        if let Ok(i) = at {
            if let Some(ids) = self.lower.vertical.get(&self.xs[i]) {
                exact(&mut found, ids);
            }
        }
        // The pieces through p, in the slabs it touches: a contiguous run
        // in each, the pieces being ordered there.
        let mut seen: Vec<u32> = Vec::new();
        for s in [left, right].into_iter().flatten() {
            let pieces = &self.slabs[s].pieces;
            let lo = pieces.partition_point(|&l| self.side(l, p, q) == Ordering::Greater);
            let hi = pieces.partition_point(|&l| self.side(l, p, q) != Ordering::Less);
            for &l in &pieces[lo..hi.max(lo)] {
                if !seen.contains(&l) {
                    seen.push(l);
                    exact(&mut found, &self.lower.on_line[l as usize]);
                }
            }
        }
        found.sort_unstable();
        found.dedup();
        found
    }

    /// The label of the trapezoid of slab `s` holding p + (sx·ε, sy·δ),
    /// δ ≪ ε infinitesimal (p in the slab's closure).
    fn label_beside(
        &self,
        s: usize,
        p: &RatPoint,
        q: Option<[i128; 3]>,
        sx: Ordering,
        sy: Ordering,
    ) -> &[u32] {
        let slab = &self.slabs[s];
        // The side of a (non-vertical, b > 0) line a·x + b·y = c: its sign
        // at p, else the sign of a·sx·ε + b·sy·δ.
        let side = |l: u32| match self.side(l, p, q) {
            Ordering::Equal => match self.lines[l as usize].a.cmp0() {
                Ordering::Equal => sy,
                a if sx == Ordering::Greater => a,
                a => a.reverse(),
            },
            o => o,
        };
        let k = slab
            .pieces
            .partition_point(|&l| side(l) == Ordering::Greater);
        &slab.labels[k]
    }

    /// Every item tested for containment: the exact path for points on
    /// slab lines and pieces, and the reference the tests compare with.
    pub fn locate_exact(&self, p: &RatPoint) -> Vec<u32> {
        (0..self.items.len() as u32)
            .filter(|&i| self.items[i as usize].contains(p))
            .collect()
    }

    /// Trapezoids over all slabs: the size of the structure.
    pub fn trapezoids(&self) -> usize {
        self.slabs.iter().map(|s| s.labels.len()).sum()
    }
}

/// The x where two non-parallel lines meet.
fn crossing_x(l1: &Line, l2: &Line) -> Option<Rational> {
    let det = Integer::from(&l1.a * &l2.b) - Integer::from(&l2.a * &l1.b);
    if det == 0 {
        return None;
    }
    let num = Integer::from(&l1.c * &l2.b) - Integer::from(&l2.c * &l1.b);
    Some(Rational::from((num, det)))
}
