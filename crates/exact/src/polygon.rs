//! Point location in a simple polygon given by its vertex ring.

use crate::point::{Point, RatPoint};
use crate::predicates::{orientation, side_of_line_rat, Orientation, Side};
use crate::segment::Segment;
use crate::Line;
use rug::Integer;
use std::cmp::Ordering;

/// Where a point lies with respect to a closed polygon.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Containment {
    Inside,
    OnBoundary,
    Outside,
}

/// Twice the signed area of the ring (positive for counter-clockwise), exact.
pub fn signed_area_twice(ring: &[Point]) -> Integer {
    let mut s = Integer::new();
    for (i, p) in ring.iter().enumerate() {
        let q = ring[(i + 1) % ring.len()];
        s += Integer::from(p.x) * q.y - Integer::from(p.y) * q.x;
    }
    s
}

fn edges(ring: &[Point]) -> impl Iterator<Item = (Point, Point)> + '_ {
    (0..ring.len()).map(move |i| (ring[i], ring[(i + 1) % ring.len()]))
}

/// Locate `p` with respect to the simple polygon `ring` (either orientation).
///
/// # Edge cases
/// Points on an edge or at a vertex are [`Containment::OnBoundary`].
/// ```
/// use wai_exact::{locate, Containment, Point};
/// let sq = [Point::new(0, 0), Point::new(2, 0), Point::new(2, 2), Point::new(0, 2)];
/// assert_eq!(locate(&sq, Point::new(1, 1)), Containment::Inside);
/// assert_eq!(locate(&sq, Point::new(2, 1)), Containment::OnBoundary);
/// assert_eq!(locate(&sq, Point::new(3, 2)), Containment::Outside);
/// ```
pub fn locate(ring: &[Point], p: Point) -> Containment {
    let mut inside = false;
    for (a, b) in edges(ring) {
        if Segment::new(a, b).is_some_and(|s| s.contains(p)) {
            return Containment::OnBoundary;
        }
        // Crossing number with the rightward horizontal ray from p; the
        // half-open rule (a.y > p.y) != (b.y > p.y) counts vertices once.
        if (a.y > p.y) != (b.y > p.y) {
            let o = orientation(a, b, p);
            if (o == Orientation::CounterClockwise) == (b.y > a.y) {
                inside = !inside;
            }
        }
    }
    if inside {
        Containment::Inside
    } else {
        Containment::Outside
    }
}

/// [`locate`] for a rational point.
pub fn locate_rat(ring: &[Point], p: &RatPoint) -> Containment {
    if let Some(q) = p.to_point() {
        return locate(ring, q);
    }
    // Compare an integer coordinate c with p's coordinate X/W (W > 0).
    let cmp = |c: i128, num: &Integer| Integer::from(p.hw() * c).cmp(num);
    let mut inside = false;
    for (a, b) in edges(ring) {
        let Some(l) = Line::new(a, b) else { continue };
        let side = side_of_line_rat(&l, p);
        if side == Side::On {
            let in_x = cmp(a.x.min(b.x), p.hx()) != Ordering::Greater
                && cmp(a.x.max(b.x), p.hx()) != Ordering::Less;
            let in_y = cmp(a.y.min(b.y), p.hy()) != Ordering::Greater
                && cmp(a.y.max(b.y), p.hy()) != Ordering::Less;
            if in_x && in_y {
                return Containment::OnBoundary;
            }
        }
        let a_above = cmp(a.y, p.hy()) == Ordering::Greater;
        let b_above = cmp(b.y, p.hy()) == Ordering::Greater;
        if a_above != b_above && (side == Side::Left) == (b.y > a.y) {
            inside = !inside;
        }
    }
    if inside {
        Containment::Inside
    } else {
        Containment::Outside
    }
}
