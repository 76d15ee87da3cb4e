//! Douglas–Peucker simplification of traced rings, exactly, keeping the
//! map valid: a vertex is dropped only if every dropped vertex between two
//! kept ones lies within the tolerance of the segment joining them
//! (distances compared squared, in integers), and no segment of the result
//! meets another except where neighbours share their end. Where a chord
//! would cross or touch another ring, or its own ring elsewhere (two walls
//! a corridor apart simplified into each other), it is split again at its
//! farthest vertex until none does ([`rings`]). A ring that would keep
//! fewer than three vertices is kept whole. A chord that sweeps a whole
//! small hole without touching it is not caught here: the caller validates
//! the map and reports it.

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

/// `ring` simplified with tolerance √`t2` (in the ring's units, squared),
/// on its own: the segments may meet other rings ([`rings`] keeps them
/// apart).
pub fn ring(ring: &[(i64, i64)], t2: &Rational) -> Vec<(i64, i64)> {
    let keep = kept(ring, t2);
    ring.iter()
        .zip(&keep)
        .filter(|(_, &k)| k)
        .map(|(&p, _)| p)
        .collect()
}

/// Which vertices of `ring` Douglas–Peucker keeps (all when fewer than
/// three would be).
fn kept(ring: &[(i64, i64)], t2: &Rational) -> Vec<bool> {
    let n = ring.len();
    if n <= 3 {
        return vec![true; n];
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
    keep.truncate(n);
    if keep.iter().filter(|&&k| k).count() < 3 {
        vec![true; n]
    } else {
        keep
    }
}

/// Every ring simplified with tolerance √`t2`, no two segments of the
/// result meeting but neighbours at their shared end (see the module
/// documentation). `rings` must be valid: their own segments meet only so.
pub fn rings(rings: &[Vec<(i64, i64)>], t2: &Rational) -> Vec<Vec<(i64, i64)>> {
    let mut keep: Vec<Vec<bool>> = rings.iter().map(|r| kept(r, t2)).collect();
    loop {
        let segs = segments(rings, &keep);
        let mut split = Vec::new();
        for (i, j) in meeting(rings, &segs) {
            // Neighbours on one ring share an end, and only that.
            let (a, b) = (&segs[i], &segs[j]);
            let neighbours = a.ring == b.ring && (a.to == b.from || b.to == a.from);
            if neighbours && !overlap_beyond_end(rings, a, b) {
                continue;
            }
            split.extend([i, j].into_iter().filter(|&s| segs[s].dropped() > 0));
        }
        if split.is_empty() {
            break;
        }
        split.sort_unstable();
        split.dedup();
        for s in split {
            let seg = &segs[s];
            let far = farthest(&rings[seg.ring], seg.from, seg.to);
            keep[seg.ring][far] = true;
        }
    }
    rings
        .iter()
        .zip(&keep)
        .map(|(r, k)| {
            r.iter()
                .zip(k)
                .filter(|(_, &k)| k)
                .map(|(&p, _)| p)
                .collect()
        })
        .collect()
}

/// A segment of a simplified ring: from kept vertex `from` to the next
/// kept one `to` (indices into the original ring, cyclic).
struct Seg {
    ring: usize,
    from: usize,
    to: usize,
    len: usize,
}

impl Seg {
    /// The original vertices it replaces.
    fn dropped(&self) -> usize {
        (self.to + self.len - self.from) % self.len - 1
    }
}

fn segments(rings: &[Vec<(i64, i64)>], keep: &[Vec<bool>]) -> Vec<Seg> {
    let mut out = Vec::new();
    for (r, k) in keep.iter().enumerate() {
        let idx: Vec<usize> = (0..k.len()).filter(|&i| k[i]).collect();
        for w in 0..idx.len() {
            out.push(Seg {
                ring: r,
                from: idx[w],
                to: idx[(w + 1) % idx.len()],
                len: rings[r].len(),
            });
        }
    }
    out
}

/// The vertex strictly between `from` and `to` (cyclically) farthest from
/// their chord.
fn farthest(ring: &[(i64, i64)], from: usize, to: usize) -> usize {
    let n = ring.len();
    let (a, b) = (ring[from], ring[to]);
    let mut k = (from + 1) % n;
    let mut best = (k, -1i128, 0i128);
    while k != to {
        let p = ring[k];
        let c = (i128::from(b.0 - a.0) * i128::from(p.1 - a.1)
            - i128::from(b.1 - a.1) * i128::from(p.0 - a.0))
        .abs();
        let d = i128::from(p.0 - a.0).pow(2) + i128::from(p.1 - a.1).pow(2);
        if (c, d) > (best.1, best.2) {
            best = (k, c, d);
        }
        k = (k + 1) % n;
    }
    best.0
}

fn orient(a: (i64, i64), b: (i64, i64), c: (i64, i64)) -> i128 {
    let v = i128::from(b.0 - a.0) * i128::from(c.1 - a.1)
        - i128::from(b.1 - a.1) * i128::from(c.0 - a.0);
    v.signum()
}

/// Whether point `p`, collinear with `a b`, lies on the closed segment.
fn on_segment(a: (i64, i64), b: (i64, i64), p: (i64, i64)) -> bool {
    a.0.min(b.0) <= p.0 && p.0 <= a.0.max(b.0) && a.1.min(b.1) <= p.1 && p.1 <= a.1.max(b.1)
}

/// Whether the closed segments meet.
fn meet(a: (i64, i64), b: (i64, i64), c: (i64, i64), d: (i64, i64)) -> bool {
    let (o1, o2, o3, o4) = (
        orient(a, b, c),
        orient(a, b, d),
        orient(c, d, a),
        orient(c, d, b),
    );
    if o1 * o2 < 0 && o3 * o4 < 0 {
        return true;
    }
    (o1 == 0 && on_segment(a, b, c))
        || (o2 == 0 && on_segment(a, b, d))
        || (o3 == 0 && on_segment(c, d, a))
        || (o4 == 0 && on_segment(c, d, b))
}

/// For neighbours `a`, `b` sharing an end: whether they meet elsewhere too
/// (one folds back along the other).
fn overlap_beyond_end(rings: &[Vec<(i64, i64)>], a: &Seg, b: &Seg) -> bool {
    let r = &rings[a.ring];
    let (p, q) = (r[a.from], r[a.to]);
    let (s, t) = (r[b.from], r[b.to]);
    // The shared end, and the other end of each.
    let (shared, pa, pb) = if a.to == b.from { (q, p, t) } else { (p, q, s) };
    orient(shared, pa, pb) == 0
        && (i128::from(pa.0 - shared.0) * i128::from(pb.0 - shared.0)
            + i128::from(pa.1 - shared.1) * i128::from(pb.1 - shared.1))
            > 0
}

/// The pairs of segments whose closed segments meet, found through a grid
/// of buckets over their bounding boxes.
fn meeting(rings: &[Vec<(i64, i64)>], segs: &[Seg]) -> Vec<(usize, usize)> {
    let ends = |s: &Seg| (rings[s.ring][s.from], rings[s.ring][s.to]);
    let (mut lo, mut hi) = ((i64::MAX, i64::MAX), (i64::MIN, i64::MIN));
    for s in segs {
        let (a, b) = ends(s);
        for p in [a, b] {
            lo = (lo.0.min(p.0), lo.1.min(p.1));
            hi = (hi.0.max(p.0), hi.1.max(p.1));
        }
    }
    if segs.is_empty() {
        return Vec::new();
    }
    // About one segment per bucket on a side of √(segments) buckets.
    let side = (segs.len().isqrt() as i64).max(1);
    let cell = (((hi.0 - lo.0).max(hi.1 - lo.1)) / side).max(1) + 1;
    let key = |p: (i64, i64)| ((p.0 - lo.0) / cell, (p.1 - lo.1) / cell);
    let mut buckets: std::collections::HashMap<(i64, i64), Vec<usize>> =
        std::collections::HashMap::new();
    for (i, s) in segs.iter().enumerate() {
        let (a, b) = ends(s);
        let (ka, kb) = (key(a), key(b));
        for x in ka.0.min(kb.0)..=ka.0.max(kb.0) {
            for y in ka.1.min(kb.1)..=ka.1.max(kb.1) {
                buckets.entry((x, y)).or_default().push(i);
            }
        }
    }
    let mut out = Vec::new();
    for list in buckets.values() {
        for (x, &i) in list.iter().enumerate() {
            for &j in &list[x + 1..] {
                let ((a, b), (c, d)) = (ends(&segs[i]), ends(&segs[j]));
                if meet(a, b, c, d) {
                    out.push((i.min(j), i.max(j)));
                }
            }
        }
    }
    out.sort_unstable();
    out.dedup();
    out
}

#[cfg(test)]
mod tests {
    use super::{ring, rings};
    use rug::Rational;

    /// A room whose top wall bulges up around a pillar that straddles the
    /// wall's chord: alone, the bulge's corner is within the tolerance and
    /// dropped; beside the pillar it is kept, since the chord would cut
    /// the pillar.
    #[test]
    fn a_chord_that_would_cut_another_ring_is_split() {
        let outer = vec![
            (0, 0),
            (20, 0),
            (20, 10),
            (15, 10),
            (10, 13),
            (5, 10),
            (0, 10),
        ];
        let pillar = vec![(9, 9), (11, 9), (11, 11), (9, 11)];
        let t2 = Rational::from(16);
        let alone = ring(&outer, &t2);
        assert!(!alone.contains(&(10, 13)), "{alone:?}");
        let both = rings(&[outer.clone(), pillar.clone()], &t2);
        assert!(both[0].contains(&(10, 13)), "{both:?}");
        assert_eq!(both[1], pillar);
        // Far from the pillar the corner goes.
        let moved: Vec<(i64, i64)> = pillar.iter().map(|&(x, y)| (x, y - 6)).collect();
        let apart = rings(&[outer, moved], &t2);
        assert!(!apart[0].contains(&(10, 13)), "{apart:?}");
    }

    /// Random occupancy masks (walls, pillars, clutter), traced and
    /// simplified at 1 to 4 cells: every result is a valid map, while the
    /// rings simplified one by one are not always (the check has work).
    #[test]
    fn simplified_traces_of_random_grids_are_valid_maps() {
        use crate::trace::{region, rings as traced, Choice};
        use rand::{Rng, SeedableRng};
        use wai_exact::Point;
        let (w, h) = (48usize, 40usize);
        let (mut valid, mut naive_invalid) = (0, 0);
        for seed in 0..60u64 {
            let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
            let mut free = vec![true; w * h];
            for _ in 0..rng.random_range(10..40) {
                let (c, r) = (rng.random_range(0..w), rng.random_range(0..h));
                let (dw, dh) = (rng.random_range(1..8), rng.random_range(1..3));
                let (dw, dh) = if rng.random_bool(0.5) {
                    (dw, dh)
                } else {
                    (dh, dw)
                };
                for y in r..(r + dh).min(h) {
                    for x in c..(c + dw).min(w) {
                        free[y * w + x] = false;
                    }
                }
            }
            let Some((mask, _)) = region(&free, w, h, Choice::Largest, 2) else {
                continue;
            };
            let rs = traced(&mask, w, h);
            let map = |rs: &[Vec<(i64, i64)>]| {
                let pts = |r: &Vec<(i64, i64)>| {
                    r.iter()
                        .map(|&(x, y)| Point::new(x.into(), y.into()))
                        .collect::<Vec<_>>()
                };
                wai_map::Map::from_rings(pts(&rs[0]), rs[1..].iter().map(pts).collect())
            };
            for t in [1, 2, 3, 4] {
                let t2 = Rational::from(t * t);
                let out = rings(&rs, &t2);
                map(&out).unwrap_or_else(|e| panic!("seed {seed}, tolerance {t}: {e}"));
                valid += 1;
                let alone: Vec<Vec<(i64, i64)>> = rs.iter().map(|r| ring(r, &t2)).collect();
                naive_invalid += usize::from(map(&alone).is_err());
            }
        }
        assert!(valid >= 200, "{valid} maps");
        assert!(
            naive_invalid > 0,
            "ring by ring never went wrong: the test shows nothing"
        );
    }
}
