//! Common interior points of several simple polygons, exactly: the
//! question behind Lemma 4.1 ("embeddings that all overlap in one point").

use crate::piece::segment_cuts;
use crate::witness::{locate, Locus};
use rug::Rational;
use wai_exact::QPoint;

/// A point in the interior of every polygon of `polygons` (simple,
/// counter-clockwise), if their interiors share one.
///
/// Exact and complete, by vertical slabs: between two consecutive
/// x-coordinates of the polygons' vertices and of the points where edges
/// of different polygons meet, no edges cross, so on the slab's middle
/// line the faces of the overlay are the intervals between consecutive
/// edge crossings; the middle of each is tested. Every face of the
/// overlay meets some slab's middle line.
pub fn common_interior_point(polygons: &[Vec<QPoint>]) -> Option<QPoint> {
    let edges: Vec<(usize, &QPoint, &QPoint)> = polygons
        .iter()
        .enumerate()
        .flat_map(|(k, p)| (0..p.len()).map(move |i| (k, &p[i], &p[(i + 1) % p.len()])))
        .collect();
    let mut xs: Vec<Rational> = polygons.iter().flatten().map(|p| p.x.clone()).collect();
    for (i, &(k, a, b)) in edges.iter().enumerate() {
        for &(l, c, d) in &edges[i + 1..] {
            if k == l {
                continue;
            }
            for t in segment_cuts(a, b, c, d) {
                xs.push(a.along(&b.sub(a), &t).x);
            }
        }
    }
    xs.sort();
    xs.dedup();
    for w in xs.windows(2) {
        let xm = Rational::from(&w[0] + &w[1]) / 2u32;
        let mut ys: Vec<Rational> = edges
            .iter()
            .filter(|(_, a, b)| (a.x < xm) != (b.x < xm))
            .map(|(_, a, b)| {
                let t = Rational::from(&xm - &a.x) / Rational::from(&b.x - &a.x);
                &a.y + Rational::from(&b.y - &a.y) * t
            })
            .collect();
        ys.sort();
        ys.dedup();
        for v in ys.windows(2) {
            let p = QPoint::new(xm.clone(), Rational::from(&v[0] + &v[1]) / 2u32);
            if polygons
                .iter()
                .all(|q| matches!(locate(q, &p), Locus::Inside))
            {
                return Some(p);
            }
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::piece::ints as ring;

    #[test]
    fn three_squares_share_a_corner_region_or_not() {
        let a = ring(&[(0, 0), (4, 0), (4, 4), (0, 4)]);
        let b = ring(&[(2, 2), (6, 2), (6, 6), (2, 6)]);
        let c = ring(&[(3, -1), (5, -1), (5, 3), (3, 3)]);
        let p = common_interior_point(&[a.clone(), b.clone(), c.clone()]).unwrap();
        assert!(p.x > 3 && p.x < 4 && p.y > 2 && p.y < 3, "{p}");
        // Pairwise overlapping, no common point.
        let d = ring(&[(0, 3), (2, 3), (2, 7), (0, 7)]);
        assert!(common_interior_point(&[a.clone(), b.clone(), d.clone()]).is_none());
        // Touching only along an edge.
        let e = ring(&[(4, 0), (8, 0), (8, 4), (4, 4)]);
        assert!(common_interior_point(&[a, e]).is_none());
    }
}
