//! Point location in a simple polygon given by its vertex ring.

use crate::point::{Point, RatPoint};
use crate::predicates::{
    orientation, point_row_small, side_of_line_rat_big, side_of_line_small, Orientation, Side,
};
use crate::segment::Segment;
use crate::vector::rat_point_small;
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
    if let Some(c) = locate_rat_small(ring, p) {
        return c;
    }
    locate_rat_big(ring, p)
}

/// [`locate_rat`] in `i128`, when `p`'s homogeneous coordinates and every
/// vertex coordinate are below `2^HOMOGENEOUS_FAST_BITS` in magnitude
/// (`None` otherwise): the same crossing rule as [`locate_rat_big`].
///
/// Implementation note: the side of each edge's line is the sign of a 3×3
/// determinant of homogeneous rows with entries below the bound
/// ([`side_of_line_small`], exact there). A vertex coordinate `c` is
/// compared with `p`'s `X / W` as `c·W` against `X`: both factors are below
/// `2^41`, so `|c·W| < 2^82`, exact in `i128` (the multiply cannot wrap).
fn locate_rat_small(ring: &[Point], p: &RatPoint) -> Option<Containment> {
    let [px, py, pw] = rat_point_small(p)?;
    if !ring.iter().all(|v| point_row_small(*v).is_some()) {
        return None;
    }
    let scaled = |c: i128| c.wrapping_mul(pw);
    let mut inside = false;
    for (a, b) in edges(ring) {
        if a == b {
            continue;
        }
        let side = side_of_line_small(a, b, [px, py, pw])?;
        if side == Side::On {
            let in_x = scaled(a.x.min(b.x)) <= px && scaled(a.x.max(b.x)) >= px;
            let in_y = scaled(a.y.min(b.y)) <= py && scaled(a.y.max(b.y)) >= py;
            if in_x && in_y {
                return Some(Containment::OnBoundary);
            }
        }
        let a_above = scaled(a.y) > py;
        let b_above = scaled(b.y) > py;
        if a_above != b_above && (side == Side::Left) == (b.y > a.y) {
            inside = !inside;
        }
    }
    Some(if inside {
        Containment::Inside
    } else {
        Containment::Outside
    })
}

/// [`locate_rat`] in GMP, for a point and ring of any size.
pub(crate) fn locate_rat_big(ring: &[Point], p: &RatPoint) -> Containment {
    // Compare an integer coordinate c with p's coordinate X/W (W > 0).
    let cmp = |c: i128, num: &Integer| Integer::from(p.hw() * c).cmp(num);
    let mut inside = false;
    for (a, b) in edges(ring) {
        let Some(l) = Line::new(a, b) else { continue };
        let side = side_of_line_rat_big(&l, p);
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

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    const B: i128 = 1 << crate::HOMOGENEOUS_FAST_BITS;

    /// Small values, values at the fast path's bound and values beyond it.
    fn coord() -> impl Strategy<Value = i128> {
        prop_oneof![-20i128..20, (-B + 1)..B, Just(B - 1), Just(-B + 1), Just(B)]
    }

    fn rat(x: i128, y: i128, w: i128) -> RatPoint {
        RatPoint::new(Integer::from(x), Integer::from(y), Integer::from(w)).expect("w != 0")
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(3000))]

        /// The `i128` path decides as GMP does, on any ring (the crossing
        /// rule is the same algebra whether or not the ring is simple) and
        /// on points anywhere, on a vertex's lines or on an edge.
        #[test]
        fn locate_rat_small_agrees_with_gmp(
            ring in prop::collection::vec((coord(), coord()), 3..8),
            p in (coord(), coord(), prop_oneof![1i128..20, 1..B, Just(B - 1), Just(B)]),
            on_edge in prop::option::of((0usize..8, 0i128..9, 1i128..9)),
        ) {
            let ring: Vec<Point> = ring.into_iter().map(|(x, y)| Point::new(x, y)).collect();
            let p = match on_edge {
                // a + (k / m)·(b − a), on the edge's line, on the edge when k ≤ m.
                Some((i, k, m)) => {
                    let (a, b) = (ring[i % ring.len()], ring[(i + 1) % ring.len()]);
                    rat(a.x * m + k * (b.x - a.x), a.y * m + k * (b.y - a.y), m)
                }
                None => rat(p.0, p.1, p.2),
            };
            let big = locate_rat_big(&ring, &p);
            if let Some(small) = locate_rat_small(&ring, &p) {
                prop_assert_eq!(small, big, "{:?} {}", ring, p);
            }
            prop_assert_eq!(locate_rat(&ring, &p), big);
        }
    }
}
