//! The size of Alg 3.14's preprocessing, counted from the decomposition:
//! the trapezoids of the overlay of every class
//! (`wai_localize::ClassOverlay`), without building the overlays.
//!
//! An overlay places every cell of a class — its 2-cells as polygons, its
//! 1-cells as segments, its 0-cells as points, all of them, kept or
//! absorbed — translated by minus its embedding's origin vertex. It cuts
//! the plane into slabs at the x of every vertex of those shapes and of
//! every crossing of two edges on different lines strictly inside both
//! edges' x-ranges; each slab is cut into trapezoids by the distinct lines
//! of the non-vertical edges spanning it. So a class of slab boundaries
//! x_0 < … < x_m has
//!
//!   trapezoids = m + Σ_lines (slabs covered by the line's edges),
//!
//! one more trapezoid than pieces in each of its m slabs.
//!
//! Every edge of a cell lies on a map edge or a visibility ray, a line
//! through two map vertices, which the arrangement records
//! ([`wai_cells::Support`]); translated by an integer origin it is still a
//! line through two integer points, a·x + b·y = c with integer
//! coefficients (kept with (a, b) primitive, which makes equal lines equal
//! triples), and every slab boundary is a rational x = num / den read
//! off an arrangement point or the crossing of two such lines. Nothing is
//! built in GMP: the count works in `i128`.
//!
//! # Implementation note: the `i128` bounds
//! With map coordinates below 2^B: a line through two map points, kept
//! with (a, b) primitive, has a and b below 2^(B+1) and c = a·x + b·y
//! below 2^(2B+2), and translated by a map point's −o, c below 2^(2B+3);
//! an arrangement point (the meeting point of two such lines,
//! homogeneous, `RatPoint` in lowest terms) has W below 2^(2B+3) and X
//! below 2^(3B+4), and X − o.x·W below 2^(3B+5); a crossing's x is
//! num / det with det below 2^(2B+3) and num below 2^(3B+5). Comparing two
//! slab boundaries multiplies a numerator by a denominator: below
//! 2^(5B+8), within an `i128` for B ≤ 23. Every operation here is checked
//! all the same (`checked_mul`, `checked_sub`): on any overflow, and for
//! arrangement points whose homogeneous coordinates do not fit an `i128`,
//! [`trapezoids`] returns `None` and the caller counts the localizer's own
//! overlays ([`crate::Study::preprocessing_size`]). The tests compare the
//! count with `Localizer::trapezoids` on maps of every kind and check the
//! fallback on a map scaled past the bound.

use rustc_hash::FxHashMap as HashMap;
use std::cmp::Ordering;

use wai_cells::{Arrangement, Decomposition, LowerSite, Support};
use wai_exact::Point;

/// A slab boundary num / den, den > 0.
#[derive(Clone, Copy, Debug)]
struct X {
    num: i128,
    den: i128,
}

impl X {
    /// The exact order of two boundaries, if the products fit.
    fn cmp(self, other: X) -> Option<Ordering> {
        let l = self.num.checked_mul(other.den)?;
        let r = other.num.checked_mul(self.den)?;
        Some(l.cmp(&r))
    }
}

/// A line a·x + b·y = c, non-vertical (b ≠ 0) where spans use it.
#[derive(Clone, Copy, Debug)]
struct Line {
    a: i128,
    b: i128,
    c: i128,
}

impl Line {
    /// The line through integer points p and q (p ≠ q) as a key: a·x + b·y
    /// = c with (a, b) primitive and its first non-zero entry positive,
    /// which makes equal lines equal keys (c then follows).
    fn through(p: Point, q: Point) -> Option<Line> {
        let a = q.y.checked_sub(p.y)?;
        let b = p.x.checked_sub(q.x)?;
        let g = i128::try_from(gcd(a.unsigned_abs(), b.unsigned_abs())).ok()?;
        let (a, b) = if a < 0 || (a == 0 && b < 0) {
            (a.checked_neg()? / g, b.checked_neg()? / g)
        } else {
            (a / g, b / g)
        };
        let c = a.checked_mul(p.x)?.checked_add(b.checked_mul(p.y)?)?;
        Some(Line { a, b, c })
    }

    /// The same line translated by −o (a key still).
    fn translated(self, o: Point) -> Option<Line> {
        let shift = self
            .a
            .checked_mul(o.x)?
            .checked_add(self.b.checked_mul(o.y)?)?;
        Some(Line {
            c: self.c.checked_sub(shift)?,
            ..self
        })
    }

    /// The x where two lines meet, if they are not parallel (None: an
    /// overflow, `Some(None)`: parallel).
    fn crossing_x(self, other: Line) -> Option<Option<X>> {
        let det = self
            .a
            .checked_mul(other.b)?
            .checked_sub(other.a.checked_mul(self.b)?)?;
        if det == 0 {
            return Some(None);
        }
        let num = self
            .c
            .checked_mul(other.b)?
            .checked_sub(other.c.checked_mul(self.b)?)?;
        Some(Some(if det < 0 {
            X {
                num: num.checked_neg()?,
                den: -det,
            }
        } else {
            X { num, den: det }
        }))
    }
}

fn gcd(mut a: u128, mut b: u128) -> u128 {
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a.max(1)
}

/// A non-vertical edge of a placed cell: its line (by index) and its
/// x-range.
#[derive(Clone, Copy, Debug)]
struct Span {
    line: usize,
    x0: X,
    x1: X,
}

/// The x of an arrangement point, (X, W) of its homogeneous coordinates,
/// translated by −o: (X − o.x·W) / W.
fn x_of(p: Option<(i128, i128)>, o: Point) -> Option<X> {
    let (hx, hw) = p?;
    Some(X {
        num: hx.checked_sub(o.x.checked_mul(hw)?)?,
        den: hw,
    })
}

/// Two map points on the line that arrangement edge `e` lies on: the map
/// edge's ends, or the ends of the line of a ray of its group.
pub(crate) fn support_points(arr: &Arrangement, e: usize) -> (Point, Point) {
    match arr.edge_support(e) {
        Support::MapEdge(i) => {
            let v = arr.map().vertices();
            (v[i], v[(i + 1) % v.len()])
        }
        Support::Rays(g) => {
            let line = &arr.rays()[arr.ray_group(g).rays[0]].line;
            (line.a(), line.b())
        }
    }
}

/// The shapes of one class, translated: slab boundaries and spans.
#[derive(Default)]
struct Class {
    xs: Vec<X>,
    spans: Vec<Span>,
    lines: Vec<Line>,
    ids: HashMap<(i128, i128, i128), usize>,
}

impl Class {
    /// Adds an edge from `x0` to `x1` (the x of its ends, translated) on
    /// `line` (untranslated), translated by −o.
    fn edge(&mut self, x0: X, x1: X, line: Option<Line>, o: Point) -> Option<()> {
        let order = x0.cmp(x1)?;
        if order == Ordering::Equal {
            return Some(()); // vertical: on a slab boundary
        }
        let line = line?.translated(o)?;
        let next = self.lines.len();
        let id = *self.ids.entry((line.a, line.b, line.c)).or_insert(next);
        if id == next {
            self.lines.push(line);
        }
        let (x0, x1) = if order == Ordering::Less {
            (x0, x1)
        } else {
            (x1, x0)
        };
        self.spans.push(Span { line: id, x0, x1 });
        Some(())
    }

    /// The trapezoids of the class's overlay.
    fn trapezoids(mut self) -> Option<usize> {
        // Two cells of one embedding that share an edge give it twice, with
        // the same numbers: once is enough for crossings and cover.
        let key = |s: &Span| (s.line, s.x0.num, s.x0.den, s.x1.num, s.x1.den);
        self.spans.sort_unstable_by_key(key);
        self.spans.dedup_by_key(|s| key(s));
        // Crossings strictly inside both spans' x-ranges.
        let mut order: Vec<usize> = (0..self.spans.len()).collect();
        let mut failed = false;
        order.sort_by(|&a, &b| {
            self.spans[a].x0.cmp(self.spans[b].x0).unwrap_or_else(|| {
                failed = true;
                Ordering::Equal
            })
        });
        if failed {
            return None;
        }
        let mut active: Vec<usize> = Vec::new();
        for &s in &order {
            let sp = self.spans[s];
            let mut keep = Vec::with_capacity(active.len());
            for &t in &active {
                if self.spans[t].x1.cmp(sp.x0)? == Ordering::Greater {
                    keep.push(t);
                }
            }
            active = keep;
            for &t in &active {
                let tp = self.spans[t];
                if tp.line == sp.line {
                    continue;
                }
                let Some(x) = self.lines[sp.line].crossing_x(self.lines[tp.line])? else {
                    continue;
                };
                let inside = |span: Span| -> Option<bool> {
                    Some(span.x0.cmp(x)? == Ordering::Less && x.cmp(span.x1)? == Ordering::Less)
                };
                if inside(sp)? && inside(tp)? {
                    self.xs.push(x);
                }
            }
            active.push(s);
        }
        let mut failed = false;
        let mut cmp = |a: &X, b: &X| {
            a.cmp(*b).unwrap_or_else(|| {
                failed = true;
                Ordering::Equal
            })
        };
        self.xs.sort_by(&mut cmp);
        self.xs.dedup_by(|a, b| cmp(a, b) == Ordering::Equal);
        if failed {
            return None;
        }
        let slabs = self.xs.len().saturating_sub(1);
        let index = |x: X| -> Option<usize> {
            let mut failed = false;
            let at = self.xs.binary_search_by(|y| {
                y.cmp(x).unwrap_or_else(|| {
                    failed = true;
                    Ordering::Equal
                })
            });
            (!failed).then_some(at.ok()?)
        };
        // By line: the slab ranges of its spans, merged.
        let mut ranges: Vec<Vec<(usize, usize)>> = vec![Vec::new(); self.lines.len()];
        for sp in &self.spans {
            ranges[sp.line].push((index(sp.x0)?, index(sp.x1)?));
        }
        let mut pieces = 0;
        for mut r in ranges {
            r.sort_unstable();
            let mut end = 0;
            for (i0, i1) in r {
                let from = i0.max(end);
                if i1 > from {
                    pieces += i1 - from;
                }
                end = end.max(i1);
            }
        }
        Some(slabs + pieces)
    }
}

/// The trapezoids of the overlays of every class of `d` (what
/// `wai_localize::Localizer::from_decomposition(d).trapezoids()` counts),
/// or `None` when a number does not fit the `i128` paths.
pub fn trapezoids(d: &Decomposition<'_>) -> Option<usize> {
    let arr = d.arrangement();
    let v = d.map().vertices();
    // By arrangement vertex, (X, W); by arrangement edge, its line.
    let xs: Vec<Option<(i128, i128)>> = arr
        .points()
        .iter()
        .map(|p| Some((p.hx().to_i128()?, p.hw().to_i128()?)))
        .collect();
    let lines: Vec<Option<Line>> = (0..arr.edge_count())
        .map(|e| {
            let (p, q) = support_points(arr, e);
            Line::through(p, q)
        })
        .collect();
    let mut classes: Vec<Class> = (0..d.classes().len()).map(|_| Class::default()).collect();
    for (k, cells) in d.classes().iter().enumerate() {
        for &f in cells {
            let o = v[d.origin_of(f)];
            let class = &mut classes[k];
            for h in arr.face_cycle(f) {
                let x0 = x_of(xs[arr.half_edge(h).origin], o)?;
                let x1 = x_of(xs[arr.dest(h)], o)?;
                class.xs.push(x0);
                class.edge(x0, x1, lines[h / 2], o)?;
            }
        }
    }
    for c in d.lower_cells() {
        let o = v[c.origin];
        let class = &mut classes[c.class];
        match c.site {
            LowerSite::Edge(e) => {
                let x0 = x_of(xs[arr.half_edge(2 * e).origin], o)?;
                let x1 = x_of(xs[arr.dest(2 * e)], o)?;
                class.xs.push(x0);
                class.xs.push(x1);
                class.edge(x0, x1, lines[e], o)?;
            }
            LowerSite::Vertex(x) => class.xs.push(x_of(xs[x], o)?),
        }
    }
    classes.into_iter().map(Class::trapezoids).sum()
}
