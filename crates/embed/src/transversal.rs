//! Whether one line meets three relatively open convex pieces — the
//! question behind Corollary 4.15 (does a line through two witnesses cross
//! the intersection of their embeddings?), decided exactly and completely.

use crate::mutual::{axes, between, upper};
use crate::piece::{offsets_between, projection, Piece};
use rug::Rational;
use wai_exact::{convex_hull, QPoint};

/// A line meeting `a`, `b` and `c`, as a point of `a` and a point of `b`
/// on it, if there is one.
///
/// The lines meeting three open pieces form an open set of lines (of the
/// lines through a point, if a piece is a point), and which lines meet
/// them changes only where a line passes a vertex of a piece. So one line
/// per cell of that arrangement is tested: a direction strictly between
/// two consecutive directions of vertex pairs, an offset strictly between
/// two consecutive projections of the vertices — as in
/// [`crate::Sightlines::by_lines`]. Two pieces on one line leave that line
/// only.
pub fn transversal(a: &Piece, b: &Piece, c: &Piece) -> Option<(QPoint, QPoint)> {
    let meets = |p0: &QPoint, d: &QPoint| -> Option<(QPoint, QPoint)> {
        let (sa, sb) = (a.span(p0, d)?, b.span(p0, d)?);
        c.span(p0, d)?;
        Some((p0.along(d, &sa.inner()), p0.along(d, &sb.inner())))
    };
    let (va, vb, vc) = (a.vertices(), b.vertices(), c.vertices());
    let h = convex_hull(va.iter().chain(&vb).cloned().collect());
    if h.len() <= 2 {
        // a and b on one line (or both one point: no line at all).
        return match h.as_slice() {
            [p, q] => meets(p, &q.sub(p)),
            _ => None,
        };
    }
    let fixed = match (a, b, c) {
        (Piece::Point(p), _, _) | (_, Piece::Point(p), _) | (_, _, Piece::Point(p)) => {
            Some(p.clone())
        }
        _ => None,
    };
    let mut e: Vec<QPoint> = va.clone();
    e.extend(vb.iter().cloned());
    e.extend(vc.iter().cloned());
    e.sort();
    e.dedup();
    let mut dirs: Vec<QPoint> = axes().to_vec();
    for (i, x) in e.iter().enumerate() {
        for y in &e[i + 1..] {
            if fixed.as_ref().is_some_and(|f| f != x && f != y) {
                continue;
            }
            dirs.push(upper(y.sub(x)));
        }
    }
    for d in between(dirs).into_iter().filter(QPoint::upper_half) {
        let n = d.perp();
        let nn = n.dot(&n);
        let offsets: Vec<Rational> = match &fixed {
            Some(f) => vec![n.dot(f)],
            None => {
                let (ra, rb, rc) = (
                    projection(&n, &va),
                    projection(&n, &vb),
                    projection(&n, &vc),
                );
                let lo = ra.0.max(rb.0).max(rc.0);
                let hi = ra.1.min(rb.1).min(rc.1);
                if lo >= hi {
                    continue;
                }
                offsets_between(&e, &n, lo, hi)
            }
        };
        for u in offsets {
            let p0 = n.scale(&(u / &nn));
            if let Some(found) = meets(&p0, &d) {
                return Some(found);
            }
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::piece::int as pt;

    #[test]
    fn three_squares_in_a_row_and_off_it() {
        let sq = |x: i64, y: i64| {
            Piece::Polygon(vec![pt(x, y), pt(x + 1, y), pt(x + 1, y + 1), pt(x, y + 1)])
        };
        assert!(transversal(&sq(0, 0), &sq(4, 0), &sq(2, 0)).is_some());
        // A line through two unit squares far apart cannot reach a square
        // far off their band.
        assert!(transversal(&sq(0, 0), &sq(10, 0), &sq(5, 5)).is_none());
        // Stacked over the first, the third needs a steep line, which
        // misses the second; beside the diagonal, a line grazes all three.
        assert!(transversal(&sq(0, 0), &sq(4, 0), &sq(0, 2)).is_none());
        assert!(transversal(&sq(0, 0), &sq(2, 2), &sq(1, 0)).is_some());
        // Two points: their line.
        let (p, q) = (Piece::Point(pt(0, 0)), Piece::Point(pt(4, 4)));
        assert!(transversal(&p, &q, &sq(1, 1)).is_some());
        assert!(transversal(&p, &q, &sq(2, 0)).is_none());
    }
}
