//! The GMP path of every fast predicate: the same formulas on
//! [`rug::Integer`], exact for any `i128` input.
//!
//! The fast predicates route here beyond their bit bounds; tests compare the
//! two on random and adversarial inputs at and beyond the bounds.

use crate::line::Line;
use crate::point::{Point, RatPoint};
use crate::predicates::{Orientation, Side};
use crate::vector::BigVector;
use rug::Integer;
use std::cmp::Ordering;

/// `b − a` in GMP integers.
fn diff(b: Point, a: Point) -> BigVector {
    BigVector::between(a, b)
}

/// [`crate::orientation`] on GMP integers.
pub fn orientation(a: Point, b: Point, c: Point) -> Orientation {
    Orientation::from_sign(diff(b, a).cross(&diff(c, a)).cmp0())
}

/// [`crate::compare_along`] on GMP integers.
pub fn compare_along(l: &Line, p: Point, q: Point) -> Ordering {
    let dot = diff(q, p).dot(&diff(l.b(), l.a()));
    Ordering::Equal.cmp(&dot.cmp0())
}

/// [`crate::side_of_intersection`] on GMP integers.
pub fn side_of_intersection(l3: &Line, l1: &Line, l2: &Line) -> Option<Side> {
    let d1 = diff(l1.b(), l1.a());
    let d2 = diff(l2.b(), l2.a());
    let d3 = diff(l3.b(), l3.a());
    let den = d1.cross(&d2);
    if den == 0 {
        return None;
    }
    let num = diff(l2.a(), l1.a()).cross(&d2);
    let s = d3.cross(&diff(l1.a(), l3.a())) * &den + num * d3.cross(&d1);
    Some(Side::from_sign(s.cmp0()).flip_if(den < 0))
}

/// [`crate::compare_intersections_along`] on GMP integers.
pub fn compare_intersections_along(l0: &Line, l1: &Line, l2: &Line) -> Option<Ordering> {
    let d0 = diff(l0.b(), l0.a());
    let d1 = diff(l1.b(), l1.a());
    let d2 = diff(l2.b(), l2.a());
    let (e1, e2) = (d0.cross(&d1), d0.cross(&d2));
    if e1 == 0 || e2 == 0 {
        return None;
    }
    let n1 = diff(l1.a(), l0.a()).cross(&d1);
    let n2 = diff(l2.a(), l0.a()).cross(&d2);
    let flip = (e1 < 0) != (e2 < 0);
    let s = n1 * e2 - n2 * e1;
    let ord = s.cmp0();
    Some(if flip { ord.reverse() } else { ord })
}

/// [`crate::construct_intersection`] on GMP integers.
pub fn construct_intersection(l1: &Line, l2: &Line) -> Option<RatPoint> {
    let (a1, b1, a2, b2) = (l1.a(), l1.b(), l2.a(), l2.b());
    let (d1, d2) = (diff(b1, a1), diff(b2, a2));
    let den = d1.cross(&d2);
    if den == 0 {
        return None;
    }
    let num = diff(a2, a1).cross(&d2);
    // a1 + (num / den) · d1, in homogeneous form over den.
    let x = Integer::from(&den * a1.x) + Integer::from(&num * &d1.x);
    let y = Integer::from(&den * a1.y) + Integer::from(&num * &d1.y);
    RatPoint::new(x, y, den)
}
