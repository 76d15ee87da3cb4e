//! The map edge each witness cell of an embedding sees through each
//! artificial edge, without a visibility query for a 2-cell.
//!
//! A point q of a 2-cell of the class sees exactly the vertices of h(V*)
//! (Def 3.7: the non-spurious vertices of V_q). Between two consecutive
//! ones x → y of an artificial edge, V_q's partial edge lies on one map
//! edge, which is (the rule the decomposition's walk computes skeletons by,
//! `wai_cells`' module `incremental`):
//! 1. edge x, if q lies strictly left of it (V_q leaves x along it);
//! 2. else edge y − 1, if q lies strictly left of it (V_q reaches y along
//!    it);
//! 3. else the edge the ray from q through x meets beyond x: looked up in
//!    the view from x (`VisibilityIndex::vertex_view`, its open angular
//!    sectors each with the map edge it reaches first) in the direction
//!    x − q, taken just counter-clockwise of it (V_q continues
//!    counter-clockwise after the window), which settles rays through
//!    further vertices.
//!
//! A point of a 1- or 0-cell lies on the lines these tests use, where the
//! rule needs the care the walk gives lower cells; for those this module
//! asks the visibility query ([`crate::witness_views`]). The tests compare
//! both ways on every witness cell of maps of every kind.

use std::cmp::Ordering;

use wai_exact::{orientation_rat, BigVector, Orientation, Point, RatPoint};
use wai_map::Map;
use wai_visibility::VisibilityIndex;

use crate::embedding::Embedding;
use crate::witness::{witness_views, CellRef, Witnesses};

/// [`witness_views`] by the rule of the module documentation: by witness
/// cell, by skeleton edge of `h`, the map edge seen through an artificial
/// edge (`None` for a full edge). `view(x)` is the view from map vertex x
/// (`VisibilityIndex::vertex_view(x)`, which callers may keep).
pub fn witness_views_by_rule<'v>(
    index: &VisibilityIndex<'_>,
    view: impl Fn(usize) -> &'v [(usize, usize)],
    h: &Embedding,
    witnesses: &Witnesses,
) -> Vec<Vec<Option<usize>>> {
    let map = index.map();
    let k = h.vertices.len();
    let mut out = Vec::with_capacity(witnesses.cells.len());
    for w in &witnesses.cells {
        if !matches!(w.cell, CellRef::Face(_)) {
            let one = Witnesses {
                cells: vec![w.clone()],
            };
            out.extend(witness_views(index, h, &one));
            continue;
        }
        out.push(
            (0..k)
                .map(|i| {
                    (!h.candidates[i].is_empty()).then(|| {
                        let (x, y) = (h.vertices[i], h.vertices[(i + 1) % k]);
                        seen_between(map, &view, x, y, &w.point)
                    })
                })
                .collect(),
        );
    }
    out
}

/// The map edge V_q's partial edge lies on between the consecutive seen
/// vertices x → y (cases 1–3 of the module documentation), q inside a
/// 2-cell.
fn seen_between<'v>(
    map: &Map,
    view: &impl Fn(usize) -> &'v [(usize, usize)],
    x: usize,
    y: usize,
    q: &RatPoint,
) -> usize {
    let v = map.vertices();
    let left_of = |e: usize| strictly_left(v[e], v[map.next(e)], q);
    let before_y = map.prev(y);
    if left_of(x) {
        x
    } else if left_of(before_y) {
        before_y
    } else {
        beyond(v, view(x), x, q)
    }
}

/// Whether q lies strictly left of the directed line from a to b: the sign
/// of (b − a) × (W·q − W·a) for q = (X, Y)/W, W > 0, in checked `i128`
/// arithmetic, or by `orientation_rat` where a product does not fit.
fn strictly_left(a: Point, b: Point, q: &RatPoint) -> bool {
    let small = || -> Option<bool> {
        let (x, y, w) = (q.hx().to_i128()?, q.hy().to_i128()?, q.hw().to_i128()?);
        let (dx, dy) = (b.x.checked_sub(a.x)?, b.y.checked_sub(a.y)?);
        let px = x.checked_sub(a.x.checked_mul(w)?)?;
        let py = y.checked_sub(a.y.checked_mul(w)?)?;
        Some(dx.checked_mul(py)?.checked_sub(dy.checked_mul(px)?)? > 0)
    };
    small().unwrap_or_else(|| {
        orientation_rat(&RatPoint::from(a), &RatPoint::from(b), q) == Orientation::CounterClockwise
    })
}

/// The map edge the ray from q through map vertex x meets beyond x, taken
/// just counter-clockwise of the ray: the sector of x's view whose start
/// is the last at or before the ray's direction, counter-clockwise from
/// the view's first sector.
fn beyond(v: &[Point], view: &[(usize, usize)], x: usize, q: &RatPoint) -> usize {
    let d = BigVector::toward(q, v[x]);
    let base = BigVector::between(v[x], v[view[0].0]);
    // The half-turn from `base` a direction lies in: [0, π) or [π, 2π).
    let half = |u: &BigVector| match base.cross_sign(u) {
        Ordering::Greater => 0,
        Ordering::Equal if base.dot_sign(u) == Ordering::Greater => 0,
        _ => 1,
    };
    let angle_cmp =
        |u: &BigVector, w: &BigVector| half(u).cmp(&half(w)).then_with(|| w.cross_sign(u));
    let at = view.partition_point(|&(lo, _)| {
        angle_cmp(&BigVector::between(v[x], v[lo]), &d) != Ordering::Greater
    });
    assert!(
        at > 0,
        "the ray from {q} through map vertex {x} does not enter the map beyond it"
    );
    view[at - 1].1
}

#[cfg(test)]
mod tests {
    use super::*;
    use rug::Integer;

    #[test]
    fn strictly_left_is_orientation_in_and_past_the_i128_range() {
        let p = |x: i128, y: i128| Point::new(x, y);
        let q = |x: i128, y: i128, w: i128| {
            RatPoint::new(Integer::from(x), Integer::from(y), Integer::from(w)).unwrap()
        };
        let big = 1i128 << 99;
        let cases = [
            (p(0, 0), p(4, 0), q(1, 1, 3)),
            (p(0, 0), p(4, 0), q(1, -1, 3)),
            (p(0, 0), p(4, 0), q(7, 0, 2)),
            (p(-big, 3), p(big, 5), q(1, 4, 1)),
            (p(-big, 3), p(big, 5), q(big, 2 * big, big - 1)),
            (p(big, -big), p(-big, big), q(-big, -big, 7)),
        ];
        for (a, b, c) in cases {
            let want = orientation_rat(&RatPoint::from(a), &RatPoint::from(b), &c)
                == Orientation::CounterClockwise;
            assert_eq!(strictly_left(a, b, &c), want, "{a:?} {b:?} {c}");
        }
    }
}
