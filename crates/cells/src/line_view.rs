//! What a point on a ray line sees along that line: the map vertices on
//! the line, and for a viewpoint just beside it, which of them it sees.
//!
//! Crossing an arrangement edge changes the visibility of map vertices on
//! the edge's line only (the boundary of the region that sees a vertex v
//! lies on lines through v). Those are found by walking along the line:
//! this is the whole update of the incremental skeletons (sec. 3.9.2).

use crate::arrangement::Along;
use crate::eye::{angle_cmp, dir, mul, Dir, PointRef};
use crate::small::SmallCoords;
use rug::Rational;
use std::cmp::Ordering;
use wai_exact::{BigVector, Point, Vector};
use wai_map::Map;

/// A side of a directed line.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Beside {
    Left,
    Right,
}

/// What lies at a point of the line where something happens.
#[derive(Clone, Debug)]
enum Event {
    /// Map vertex `v`; `left`/`right`: an incident map edge leaves it
    /// strictly to that side (a viewpoint passing it on that side is
    /// blocked).
    Vertex { v: u32, left: bool, right: bool },
    /// A map edge crosses the line in its relative interior.
    Crossing,
}

/// The open stretch of the line between two consecutive events.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Stretch {
    Interior,
    Exterior,
    /// Along a map edge, whose interior side is given.
    Edge(Beside),
}

/// One line of the arrangement's rays, directed by `dir`, with its events
/// sorted along it: their positions, and apart (what the walk reads, 8
/// bytes an event) what they are.
#[derive(Clone, Debug)]
pub(crate) struct LineView {
    /// A point of the line, and its direction.
    through: Point,
    dir: Vector,
    positions: Vec<Along>,
    events: Vec<Event>,
    /// `stretches[i]` lies between events `i` and `i + 1`.
    stretches: Vec<Stretch>,
    /// The map vertices on the line, ascending.
    on_line: Vec<u32>,
}

/// The position of an integer point along direction `d`: `p · d`.
fn position(p: Point, d: Vector) -> Rational {
    Rational::from(BigVector::between(Point::new(0, 0), p).dot(&d.to_big()))
}

/// [`position`] as an [`Along`], in checked `i128` when it fits.
fn position_along(p: Point, d: Vector) -> Along {
    match mul(p.x, d.x).and_then(|a| a.checked_add(mul(p.y, d.y)?)) {
        Some(t) => Along::Small(t, 1),
        None => Along::from_rational(position(p, d)),
    }
}

/// The position along the line through `o` with direction `d` where the
/// segment from `a` to `b` (on opposite sides of it) crosses it:
/// `a + s (b − a)` with `s = −(d × (a − o)) / (d × (b − a))`, so the
/// position is `a · d − (d × (a − o)) (d · (b − a)) / (d × (b − a))`.
fn crossing_along(o: Point, a: Point, b: Point, d: Vector) -> Along {
    let fast = || -> Option<Along> {
        // Checked throughout: no bound is assumed.
        let cross = |u: Vector| mul(d.x, u.y)?.checked_sub(mul(d.y, u.x)?);
        let dot = |u: Vector| mul(d.x, u.x)?.checked_add(mul(d.y, u.y)?);
        let ca = cross(Vector::between(o, a)?)?;
        let e = Vector::between(a, b)?;
        let cb = cross(e)?;
        let along = dot(e)?;
        let ad = dot(Vector::new(a.x, a.y))?;
        let num = mul(ad, cb)?.checked_sub(mul(ca, along)?)?;
        // The denominator is nonzero (a and b are on opposite sides).
        if cb > 0 {
            Some(Along::Small(num, cb))
        } else {
            Some(Along::Small(num.checked_neg()?, cb.checked_neg()?))
        }
    };
    fast().unwrap_or_else(|| Along::from_rational(crossing_gmp(o, a, b, d)))
}

/// [`crossing_along`] on GMP integers.
fn crossing_gmp(o: Point, a: Point, b: Point, d: Vector) -> Rational {
    let d_big = d.to_big();
    let e = BigVector::between(a, b);
    let ca = d_big.cross(&BigVector::between(o, a));
    let cb = d_big.cross(&e);
    let along = e.dot(&d_big);
    position(a, d) - Rational::from((ca * along, cb))
}

impl LineView {
    /// The line through map vertex `from` with direction `dir`
    /// (primitive); `small`: the map's coordinates on the `i64` path, if
    /// they fit it.
    pub(crate) fn new(map: &Map, small: Option<&SmallCoords>, from: usize, d: Vector) -> LineView {
        let v = map.vertices();
        let through = v[from];
        // By map vertex: `Greater` left of the line, `Less` right of it.
        let sides: Vec<Ordering> = match small {
            Some(s) => s.turns_from(from, d),
            None => {
                let ld = Dir::Small(d);
                v.iter().map(|&p| ld.cross_sign(&dir(through, p))).collect()
            }
        };
        let mut events: Vec<(Along, Event)> = Vec::new();
        for (i, &p) in v.iter().enumerate() {
            if sides[i] == Ordering::Equal {
                let nb = [sides[map.prev(i)], sides[map.next(i)]];
                events.push((
                    position_along(p, d),
                    Event::Vertex {
                        v: i as u32,
                        left: nb.contains(&Ordering::Greater),
                        right: nb.contains(&Ordering::Less),
                    },
                ));
            }
            let j = map.next(i);
            if sides[i] != Ordering::Equal && sides[j] != Ordering::Equal && sides[i] != sides[j] {
                events.push((crossing_along(through, p, v[j], d), Event::Crossing));
            }
        }
        events.sort_by(|a, b| a.0.cmp(&b.0));
        debug_assert!(events
            .windows(2)
            .all(|w| w[0].0.cmp(&w[1].0) == Ordering::Less));
        let mut stretches = Vec::with_capacity(events.len().saturating_sub(1));
        let forward = Dir::Small(d);
        let backward = Dir::Small(-d);
        let inside = |z: u32, w: &Dir| {
            let z = z as usize;
            let base = dir(v[z], v[map.next(z)]);
            let last = dir(v[z], v[map.prev(z)]);
            // Strictly inside the interior angle, which runs
            // counter-clockwise from the edge to z + 1 to the edge to z − 1.
            angle_cmp(&base, &base, w) == Ordering::Less
                && angle_cmp(&base, w, &last) == Ordering::Less
        };
        let mut before = Stretch::Exterior;
        for i in 0..events.len().saturating_sub(1) {
            let s = match (&events[i].1, &events[i + 1].1) {
                (Event::Vertex { v: a, .. }, Event::Vertex { v: b, .. })
                    if map.next(*a as usize) == *b as usize =>
                {
                    Stretch::Edge(Beside::Left)
                }
                (Event::Vertex { v: a, .. }, Event::Vertex { v: b, .. })
                    if map.next(*b as usize) == *a as usize =>
                {
                    Stretch::Edge(Beside::Right)
                }
                (Event::Vertex { v: a, .. }, _) => interior_if(inside(*a, &forward)),
                (Event::Crossing, Event::Vertex { v: b, .. }) => interior_if(inside(*b, &backward)),
                (Event::Crossing, Event::Crossing) => match before {
                    Stretch::Interior => Stretch::Exterior,
                    _ => Stretch::Interior,
                },
            };
            stretches.push(s);
            before = s;
        }
        let (positions, events): (Vec<Along>, Vec<Event>) = events.into_iter().unzip();
        let mut on_line: Vec<u32> = events
            .iter()
            .filter_map(|e| match e {
                Event::Vertex { v, .. } => Some(*v),
                Event::Crossing => None,
            })
            .collect();
        on_line.sort_unstable();
        LineView {
            through,
            dir: d,
            positions,
            events,
            stretches,
            on_line,
        }
    }

    /// The map vertices on the line, ascending.
    pub(crate) fn vertices(&self) -> &[u32] {
        &self.on_line
    }

    /// Whether point `p` lies on the line.
    pub(crate) fn passes(&self, p: Point) -> bool {
        Dir::Small(self.dir).cross_sign(&dir(self.through, p)) == Ordering::Equal
    }

    /// Whether map vertex `v` lies on the line.
    pub(crate) fn contains(&self, v: u32) -> bool {
        self.on_line.binary_search(&v).is_ok()
    }

    /// The position along the line of a point on it.
    pub(crate) fn position_of(&self, q: PointRef<'_>) -> Along {
        Along::of(self.dir, q)
    }

    /// The slot of a point of the line at position `t` that is not an
    /// event: the number of events before it. Points in one open stretch
    /// share a slot; points of an arrangement edge on the line do too,
    /// since every event inside a ray's segment is an arrangement vertex.
    pub(crate) fn slot(&self, t: &Along) -> usize {
        self.positions
            .partition_point(|s| s.cmp(t) != Ordering::Greater)
    }

    /// [`LineView::slot`], for a point known to lie at or after slot
    /// `from`: a pass from there, for points taken in order along the line.
    pub(crate) fn slot_from(&self, t: &Along, mut from: usize) -> usize {
        while from < self.positions.len() && self.positions[from].cmp(t) != Ordering::Greater {
            from += 1;
        }
        from
    }

    /// The number of events strictly before position `t`.
    pub(crate) fn slot_before(&self, t: &Along) -> usize {
        self.positions
            .partition_point(|s| s.cmp(t) == Ordering::Less)
    }

    /// The map vertices on the line seen from a point of the interior of
    /// the map in slot `slot` ([`LineView::slot`]) (`beside = None`), or
    /// from viewpoints just beside it on that side, pushed to `out`.
    ///
    /// On the line a viewpoint sees only the nearest vertex each way, if
    /// the stretch to it is interior (the open segment must avoid the
    /// boundary). Beside it, the view runs on past a vertex unless one of
    /// its edges leaves to that side, and along a map edge whose interior
    /// is on that side.
    pub(crate) fn seen_in(&self, slot: usize, beside: Option<Beside>, out: &mut Vec<u32>) {
        // Forward: events slot, slot + 1, ...; backward: slot − 1, ...
        self.walk(slot, true, beside, out);
        if slot > 0 {
            self.walk(slot - 1, false, beside, out);
        }
    }

    /// Whether a viewpoint just beside the line on side `beside`, in slot
    /// `slot`, sees more of the line's vertices than a point of the slot
    /// itself: whether [`LineView::seen_in`] runs past the nearest vertex
    /// either way.
    pub(crate) fn sees_past(&self, slot: usize, beside: Beside) -> bool {
        let past = |i: usize, forward: bool| {
            matches!(self.events[i], Event::Vertex { .. })
                && self
                    .step(i, forward, beside)
                    .is_some_and(|j| matches!(self.events[j], Event::Vertex { .. }))
        };
        (slot < self.events.len() && past(slot, true)) || (slot > 0 && past(slot - 1, false))
    }

    fn walk(&self, mut i: usize, forward: bool, beside: Option<Beside>, out: &mut Vec<u32>) {
        while i < self.events.len() {
            let Event::Vertex { v, .. } = self.events[i] else {
                return;
            };
            out.push(v);
            match beside.and_then(|side| self.step(i, forward, side)) {
                Some(j) => i = j,
                None => return,
            }
        }
    }

    /// From vertex event `i`, the next event a viewpoint just beside the
    /// line on side `side` sees along it, if the view runs on: past the
    /// vertex unless one of its edges leaves to that side, and through the
    /// stretch beyond if it is interior or a map edge with its interior on
    /// that side.
    fn step(&self, i: usize, forward: bool, side: Beside) -> Option<usize> {
        let Event::Vertex { left, right, .. } = self.events[i] else {
            return None;
        };
        if (side == Beside::Left && left) || (side == Beside::Right && right) {
            return None;
        }
        let (s, j) = if forward {
            (*self.stretches.get(i)?, i + 1)
        } else {
            (self.stretches[i.checked_sub(1)?], i - 1)
        };
        match s {
            Stretch::Interior => Some(j),
            Stretch::Edge(interior) if interior == side => Some(j),
            Stretch::Exterior | Stretch::Edge(_) => None,
        }
    }
}

fn interior_if(b: bool) -> Stretch {
    if b {
        Stretch::Interior
    } else {
        Stretch::Exterior
    }
}

#[cfg(test)]
mod tests {
    use super::{crossing_along, crossing_gmp, position, position_along};
    use crate::eye::{dir, Dir};
    use proptest::prelude::*;
    use std::cmp::Ordering;
    use wai_exact::Point;

    fn coord() -> impl Strategy<Value = i128> {
        prop_oneof![-20i128..20, -(1i128 << 100)..(1i128 << 100)]
    }

    fn point() -> impl Strategy<Value = Point> {
        (coord(), coord()).prop_map(|(x, y)| Point::new(x, y))
    }

    proptest! {
        /// The checked-`i128` positions equal the GMP ones, small
        /// coordinates (fast path) and up to 2^100 (fallback) alike.
        #[test]
        fn positions_agree_with_gmp(o in point(), a in point(), b in point(), q in point()) {
            prop_assume!(o != q);
            let d = q - o;
            prop_assert_eq!(position_along(a, d).big(), position(a, d));
            let ld = Dir::Small(d);
            let (sa, sb) = (ld.cross_sign(&dir(o, a)), ld.cross_sign(&dir(o, b)));
            prop_assume!(sa != Ordering::Equal && sb != Ordering::Equal && sa != sb);
            prop_assert_eq!(crossing_along(o, a, b, d).big(), crossing_gmp(o, a, b, d));
        }
    }
}
