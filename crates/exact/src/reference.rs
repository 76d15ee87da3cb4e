//! The GMP path of every fast predicate: the same formulas on
//! [`rug::Integer`], exact for any `i128` input.
//!
//! The fast predicates route here beyond their bit bounds; tests compare the
//! two on random and adversarial inputs at and beyond the bounds.

use crate::line::Line;
use crate::point::{Point, RatPoint};
use crate::predicates::{Orientation, Side};
use rug::Integer;
use std::cmp::Ordering;

fn big(v: i128) -> Integer {
    Integer::from(v)
}

fn cross(ux: &Integer, uy: &Integer, vx: &Integer, vy: &Integer) -> Integer {
    Integer::from(ux * vy) - Integer::from(uy * vx)
}

fn diff(b: Point, a: Point) -> (Integer, Integer) {
    (big(b.x) - a.x, big(b.y) - a.y)
}

/// [`crate::orientation`] on GMP integers.
pub fn orientation(a: Point, b: Point, c: Point) -> Orientation {
    let (ux, uy) = diff(b, a);
    let (vx, vy) = diff(c, a);
    Orientation::from_sign(cross(&ux, &uy, &vx, &vy).cmp0())
}

/// [`crate::compare_along`] on GMP integers.
pub fn compare_along(l: &Line, p: Point, q: Point) -> Ordering {
    let (dx, dy) = diff(l.b(), l.a());
    let (ux, uy) = diff(q, p);
    let dot = ux * dx + uy * dy;
    Ordering::Equal.cmp(&dot.cmp0())
}

/// [`crate::side_of_intersection`] on GMP integers.
pub fn side_of_intersection(l3: &Line, l1: &Line, l2: &Line) -> Option<Side> {
    let (d1x, d1y) = diff(l1.b(), l1.a());
    let (d2x, d2y) = diff(l2.b(), l2.a());
    let (d3x, d3y) = diff(l3.b(), l3.a());
    let den = cross(&d1x, &d1y, &d2x, &d2y);
    if den == 0 {
        return None;
    }
    let (ex, ey) = diff(l2.a(), l1.a());
    let num = cross(&ex, &ey, &d2x, &d2y);
    let (fx, fy) = diff(l1.a(), l3.a());
    let s = cross(&d3x, &d3y, &fx, &fy) * &den + num * cross(&d3x, &d3y, &d1x, &d1y);
    Some(Side::from_sign(s.cmp0()).flip_if(den < 0))
}

/// [`crate::compare_intersections_along`] on GMP integers.
pub fn compare_intersections_along(l0: &Line, l1: &Line, l2: &Line) -> Option<Ordering> {
    let (d0x, d0y) = diff(l0.b(), l0.a());
    let (d1x, d1y) = diff(l1.b(), l1.a());
    let (d2x, d2y) = diff(l2.b(), l2.a());
    let e1 = cross(&d0x, &d0y, &d1x, &d1y);
    let e2 = cross(&d0x, &d0y, &d2x, &d2y);
    if e1 == 0 || e2 == 0 {
        return None;
    }
    let (f1x, f1y) = diff(l1.a(), l0.a());
    let (f2x, f2y) = diff(l2.a(), l0.a());
    let n1 = cross(&f1x, &f1y, &d1x, &d1y);
    let n2 = cross(&f2x, &f2y, &d2x, &d2y);
    let flip = (e1 < 0) != (e2 < 0);
    let s = n1 * e2 - n2 * e1;
    let ord = s.cmp0();
    Some(if flip { ord.reverse() } else { ord })
}

/// [`crate::construct_intersection`] on GMP integers.
pub fn construct_intersection(l1: &Line, l2: &Line) -> Option<RatPoint> {
    let (a1, b1, a2, b2) = (l1.a(), l1.b(), l2.a(), l2.b());
    let (d1x, d1y) = diff(b1, a1);
    let (d2x, d2y) = diff(b2, a2);
    let den = cross(&d1x, &d1y, &d2x, &d2y);
    if den == 0 {
        return None;
    }
    let (ex, ey) = diff(a2, a1);
    let num = cross(&ex, &ey, &d2x, &d2y);
    // a1 + (num / den) · d1, in homogeneous form over den.
    let x = Integer::from(&den * a1.x) + Integer::from(&num * &d1x);
    let y = Integer::from(&den * a1.y) + Integer::from(&num * &d1y);
    RatPoint::new(x, y, den)
}
