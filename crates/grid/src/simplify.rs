//! Douglas–Peucker simplification of traced rings, exactly: a vertex is
//! dropped only if every dropped vertex between two kept ones lies within
//! the tolerance of the segment joining them (distances compared squared,
//! in integers). A ring that would keep fewer than three vertices is kept
//! whole. The caller validates the simplified map: rings that came too
//! close are reported, not repaired.

use rug::{Integer, Rational};

/// Whether point `p` lies within distance √`t2` of segment `ab`.
fn within(a: (i64, i64), b: (i64, i64), p: (i64, i64), t2: &Rational) -> bool {
    let (abx, aby) = (i128::from(b.0 - a.0), i128::from(b.1 - a.1));
    let (apx, apy) = (i128::from(p.0 - a.0), i128::from(p.1 - a.1));
    let len2 = abx * abx + aby * aby;
    let dot = abx * apx + aby * apy;
    let d2 = |x: i128, y: i128| Rational::from(Integer::from(x * x + y * y));
    if len2 == 0 || dot <= 0 {
        return d2(apx, apy) <= *t2;
    }
    if dot >= len2 {
        return d2(i128::from(p.0 - b.0), i128::from(p.1 - b.1)) <= *t2;
    }
    let cross = Integer::from(abx * apy - aby * apx);
    // dist² = cross² / len2.
    Rational::from((cross.square(), Integer::from(len2))) <= *t2
}

/// Indices kept of the open chain `pts[lo..=hi]` (both ends kept).
fn chain(pts: &[(i64, i64)], lo: usize, hi: usize, t2: &Rational, keep: &mut Vec<bool>) {
    if hi <= lo + 1 {
        return;
    }
    // Every point within the tolerance: drop them all.
    if (lo + 1..hi).all(|k| within(pts[lo], pts[hi], pts[k], t2)) {
        return;
    }
    // Else split at the point farthest from the chord (by the squared
    // cross product over the chord's length, the same for every k).
    let (a, b) = (pts[lo], pts[hi]);
    let far = (lo + 1..hi)
        .max_by_key(|&k| {
            let p = pts[k];
            let c = i128::from(b.0 - a.0) * i128::from(p.1 - a.1)
                - i128::from(b.1 - a.1) * i128::from(p.0 - a.0);
            let d = i128::from(p.0 - a.0).pow(2) + i128::from(p.1 - a.1).pow(2);
            (c.abs(), d)
        })
        .expect("a point between");
    keep[far] = true;
    chain(pts, lo, far, t2, keep);
    chain(pts, far, hi, t2, keep);
}

/// `ring` simplified with tolerance √`t2` (in the ring's units, squared).
pub fn ring(ring: &[(i64, i64)], t2: &Rational) -> Vec<(i64, i64)> {
    let n = ring.len();
    if n <= 3 {
        return ring.to_vec();
    }
    // Anchors: the first corner and the corner farthest from it.
    let far = (1..n)
        .max_by_key(|&k| {
            i128::from(ring[k].0 - ring[0].0).pow(2) + i128::from(ring[k].1 - ring[0].1).pow(2)
        })
        .expect("n > 3");
    let mut closed = ring.to_vec();
    closed.push(ring[0]);
    let mut keep = vec![false; n + 1];
    keep[0] = true;
    keep[far] = true;
    chain(&closed, 0, far, t2, &mut keep);
    chain(&closed, far, n, t2, &mut keep);
    let out: Vec<(i64, i64)> = (0..n).filter(|&k| keep[k]).map(|k| ring[k]).collect();
    if out.len() < 3 {
        ring.to_vec()
    } else {
        out
    }
}
