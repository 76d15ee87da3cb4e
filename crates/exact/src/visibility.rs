//! The visibility relation between two points of a polygon (thesis sec. 2.2).

use crate::point::{Point, RatPoint};
use crate::polygon::{locate_rat, Containment};
use crate::predicates::{orientation_rat, side_of_line_rat, Orientation, Side};
use crate::Line;
use rug::Rational;

/// The answer of [`sees`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Sight {
    /// The closed segment meets the boundary at most in its endpoints and
    /// runs through the polygon.
    Visible,
    /// The segment meets the boundary at a point other than its endpoints:
    /// it crosses, grazes or runs along edge `edge` (from vertex `edge` to
    /// vertex `edge + 1`). The first such edge in ring order is named.
    Blocked { edge: usize },
    /// Both endpoints are on the boundary and the open segment between them
    /// lies outside the polygon.
    Exterior,
    /// An endpoint lies outside the polygon.
    EndpointOutside,
}

impl Sight {
    pub fn is_visible(self) -> bool {
        self == Sight::Visible
    }
}

fn coords(p: &RatPoint) -> (Rational, Rational) {
    (
        Rational::from((p.hx().clone(), p.hw().clone())),
        Rational::from((p.hy().clone(), p.hw().clone())),
    )
}

/// For `x` collinear with `p` and `q`: whether it lies on the closed segment.
fn between(p: &RatPoint, q: &RatPoint, x: &RatPoint) -> bool {
    let ((px, py), (qx, qy), (xx, xy)) = (coords(p), coords(q), coords(x));
    let within = |a: &Rational, b: &Rational, v: &Rational| {
        let (lo, hi) = if a <= b { (a, b) } else { (b, a) };
        lo <= v && v <= hi
    };
    within(&px, &qx, &xx) && within(&py, &qy, &xy)
}

/// Whether `p` and `q` see each other in the simple polygon `ring`: the
/// closed segment `pq` meets the boundary at most in `{p, q}` (thesis sec.
/// 2.2) and lies in the polygon.
///
/// # Edge cases
/// Grazing a vertex blocks; running along an edge blocks; two boundary
/// points whose chord leaves the polygon do not see each other; a point of
/// the polygon sees itself.
/// ```
/// use wai_exact::{sees, Point, RatPoint, Sight};
/// // An L-shaped room: the reflex vertex (2, 2) blocks the view around the corner.
/// let l = [(0, 0), (4, 0), (4, 2), (2, 2), (2, 4), (0, 4)].map(|(x, y)| Point::new(x, y));
/// let at = |x: i128, y: i128| RatPoint::from(Point::new(x, y));
/// assert_eq!(sees(&l, &at(1, 3), &at(1, 1)), Sight::Visible);
/// assert_eq!(sees(&l, &at(1, 3), &at(3, 1)), Sight::Blocked { edge: 2 }); // grazes (2, 2)
/// assert_eq!(sees(&l, &at(4, 2), &at(2, 4)), Sight::Exterior);
/// assert_eq!(sees(&l, &at(0, 0), &at(4, 0)), Sight::Blocked { edge: 0 }); // along an edge
/// ```
pub fn sees(ring: &[Point], p: &RatPoint, q: &RatPoint) -> Sight {
    let n = ring.len();
    sees_among(
        (0..n).map(|i| (i, ring[i], ring[(i + 1) % n])),
        |x| locate_rat(ring, x),
        p,
        q,
    )
}

/// [`sees`] in a region bounded by several rings (a map with holes, thesis
/// sec. 2.1): `edges` are the boundary's edges `(id, a, b)`, `locate` the
/// region's containment. A blocked sight names the first edge of `edges`
/// it meets.
pub fn sees_among(
    edges: impl IntoIterator<Item = (usize, Point, Point)>,
    locate: impl Fn(&RatPoint) -> Containment,
    p: &RatPoint,
    q: &RatPoint,
) -> Sight {
    let lp = locate(p);
    let lq = locate(q);
    if lp == Containment::Outside || lq == Containment::Outside {
        return Sight::EndpointOutside;
    }
    if p == q {
        return Sight::Visible;
    }
    for (i, a, b) in edges {
        let Some(edge) = Line::new(a, b) else {
            continue;
        };
        if meets_beyond_endpoints(&edge, p, q) {
            return Sight::Blocked { edge: i };
        }
    }
    // The open segment avoids the boundary: it is wholly inside or outside.
    if lp == Containment::Inside || lq == Containment::Inside {
        return Sight::Visible;
    }
    match locate(&RatPoint::midpoint(p, q)) {
        Containment::Inside => Sight::Visible,
        _ => Sight::Exterior,
    }
}

/// Whether the closed edge `ab` meets the closed segment `pq` (p ≠ q) in a
/// point other than `p` and `q`.
fn meets_beyond_endpoints(edge: &Line, p: &RatPoint, q: &RatPoint) -> bool {
    let (a, b) = (RatPoint::from(edge.a()), RatPoint::from(edge.b()));
    let o1 = side_of_line_rat(edge, p);
    let o2 = side_of_line_rat(edge, q);
    if o1 == Side::On && o2 == Side::On {
        // Collinear: the common part is a segment, a point or empty. A
        // segment of positive length always has points other than p and q;
        // a single common point of two collinear segments is an endpoint of
        // both, so it is p or q.
        let overlap_len_positive = {
            let inner = [&a, &b].into_iter().filter(|x| between(p, q, x)).count()
                + [p, q].into_iter().filter(|x| between(&a, &b, x)).count();
            // Two or more containments mean a shared piece, unless the only
            // shared point is a common endpoint counted from both sides.
            inner >= 2 && !single_shared_endpoint(&a, &b, p, q)
        };
        return overlap_len_positive;
    }
    let o3 = orientation_rat(p, q, &a);
    let o4 = orientation_rat(p, q, &b);
    if o1 == Side::On && between(&a, &b, p) {
        return false; // the only common point is p
    }
    if o2 == Side::On && between(&a, &b, q) {
        return false; // the only common point is q
    }
    if (o3 == Orientation::Collinear && between(p, q, &a))
        || (o4 == Orientation::Collinear && between(p, q, &b))
    {
        return true; // a vertex of the edge lies on pq and is neither p nor q
    }
    let opposite = |x: Side, y: Side| {
        matches!(
            (x, y),
            (Side::Left, Side::Right) | (Side::Right, Side::Left)
        )
    };
    let opposite_o = |x: Orientation, y: Orientation| {
        matches!(
            (x, y),
            (Orientation::CounterClockwise, Orientation::Clockwise)
                | (Orientation::Clockwise, Orientation::CounterClockwise)
        )
    };
    opposite(o1, o2) && opposite_o(o3, o4)
}

/// For collinear segments `ab` and `pq`: whether they share exactly one
/// point, a common endpoint, and nothing more.
fn single_shared_endpoint(a: &RatPoint, b: &RatPoint, p: &RatPoint, q: &RatPoint) -> bool {
    let shared = [(a, p), (a, q), (b, p), (b, q)]
        .into_iter()
        .find(|(x, y)| x == y)
        .map(|(x, _)| x.clone());
    let Some(s) = shared else { return false };
    // The other endpoints must lie on opposite sides of the shared one.
    let other_ab = if *a == s { b } else { a };
    let other_pq = if *p == s { q } else { p };
    !between(&s, other_ab, other_pq) && !between(&s, other_pq, other_ab)
}
