//! The kernel of a polygon with integer vertices: the intersection of the
//! closed half-planes to the left of its edges (thesis sec. 2.2; Def 3.12
//! applies it to the skeleton polygon V◇).

use wai_exact::{
    construct_intersection, orientation_rat, side_of_line_rat, Containment, Line, Orientation,
    Point, RatPoint, Side,
};

/// A closed convex region with exact vertices, counter-clockwise: empty, a
/// point, a segment (two vertices) or a convex polygon.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ConvexRegion {
    vertices: Vec<RatPoint>,
}

impl ConvexRegion {
    pub fn vertices(&self) -> &[RatPoint] {
        &self.vertices
    }
    pub fn is_empty(&self) -> bool {
        self.vertices.is_empty()
    }
    /// Whether the region has a non-empty interior.
    pub fn has_interior(&self) -> bool {
        let v = &self.vertices;
        v.len() >= 3
            && (0..v.len()).any(|i| {
                orientation_rat(&v[i], &v[(i + 1) % v.len()], &v[(i + 2) % v.len()])
                    != Orientation::Collinear
            })
    }
    /// Locate `q` in the closed region.
    pub fn locate(&self, q: &RatPoint) -> Containment {
        let v = &self.vertices;
        match v.len() {
            0 => Containment::Outside,
            1 => {
                if v[0] == *q {
                    Containment::OnBoundary
                } else {
                    Containment::Outside
                }
            }
            _ => {
                let mut on = false;
                for i in 0..v.len() {
                    let (a, b) = (&v[i], &v[(i + 1) % v.len()]);
                    match orientation_rat(a, b, q) {
                        Orientation::Clockwise => return Containment::Outside,
                        Orientation::Collinear => on = true,
                        Orientation::CounterClockwise => {}
                    }
                }
                if v.len() == 2 {
                    // A segment: collinear with both "edges"; q must be between.
                    return if on && within_segment(&v[0], &v[1], q) {
                        Containment::OnBoundary
                    } else {
                        Containment::Outside
                    };
                }
                if on {
                    Containment::OnBoundary
                } else {
                    Containment::Inside
                }
            }
        }
    }
}

fn within_segment(a: &RatPoint, b: &RatPoint, q: &RatPoint) -> bool {
    use rug::Integer;
    // For q collinear with a and b: compare homogeneous coordinates.
    let key = |p: &RatPoint, c: fn(&RatPoint) -> &Integer| (c(p).clone(), p.hw().clone());
    let le = |x: (Integer, Integer), y: (Integer, Integer)| x.0 * &y.1 <= y.0 * &x.1;
    for c in [RatPoint::hx as fn(&RatPoint) -> &Integer, RatPoint::hy] {
        let (ka, kb, kq) = (key(a, c), key(b, c), key(q, c));
        let (lo, hi) = if le(ka.clone(), kb.clone()) {
            (ka, kb)
        } else {
            (kb, ka)
        };
        if !(le(lo, kq.clone()) && le(kq, hi)) {
            return false;
        }
    }
    true
}

/// The kernel of the polygon `ring` (counter-clockwise, integer vertices):
/// every point that sees the whole polygon.
///
/// The clipping runs on `i128` homogeneous points ([`kernel_small`]) and
/// falls back to GMP points when a product would overflow; both give the
/// same region (tested).
pub fn kernel_of_ring(ring: &[Point]) -> ConvexRegion {
    kernel_small(ring).unwrap_or_else(|| kernel_exact(ring))
}

/// [`kernel_of_ring`] with GMP points throughout.
pub fn kernel_exact(ring: &[Point]) -> ConvexRegion {
    let corners = grown_box(ring);
    // Each vertex with the line of the edge to the next vertex.
    let mut region: Vec<(RatPoint, Line)> = (0..4)
        .map(|i| {
            let line = Line::new(corners[i], corners[(i + 1) % 4]).expect("a box of positive size");
            (RatPoint::from(corners[i]), line)
        })
        .collect();
    for i in 0..ring.len() {
        let Some(cut) = Line::new(ring[i], ring[(i + 1) % ring.len()]) else {
            continue;
        };
        if let Some(clipped) = clip(&region, &cut) {
            region = clipped;
        }
        if region.is_empty() {
            break;
        }
    }
    ConvexRegion {
        vertices: region.into_iter().map(|(p, _)| p).collect(),
    }
}

/// The bounding box of `ring` grown by 1, counter-clockwise.
fn grown_box(ring: &[Point]) -> [Point; 4] {
    let xs = ring.iter().map(|p| p.x);
    let ys = ring.iter().map(|p| p.y);
    let (x0, x1) = (xs.clone().min().unwrap_or(0) - 1, xs.max().unwrap_or(0) + 1);
    let (y0, y1) = (ys.clone().min().unwrap_or(0) - 1, ys.max().unwrap_or(0) + 1);
    [
        Point::new(x0, y0),
        Point::new(x1, y0),
        Point::new(x1, y1),
        Point::new(x0, y1),
    ]
}

/// A point `(x / w, y / w)` with `w > 0`, in lowest terms (as
/// `wai_exact::construct_intersection_i128` gives them: equal points have
/// equal triples).
type Triple = [i128; 3];

/// The side of the directed line `l` on which `p` lies, in checked `i128`
/// arithmetic: `None` on overflow. The sign of
/// `(b − a) × (p − a)·w` with `w > 0`.
fn side_small(l: &Line, p: &Triple) -> Option<Side> {
    use wai_exact::mul_checked;
    let (a, b) = (l.a(), l.b());
    let [x, y, w] = *p;
    let (dx, dy) = (b.x.checked_sub(a.x)?, b.y.checked_sub(a.y)?);
    let (ux, uy) = (
        x.checked_sub(mul_checked(a.x, w)?)?,
        y.checked_sub(mul_checked(a.y, w)?)?,
    );
    let s = mul_checked(dx, uy)?.checked_sub(mul_checked(dy, ux)?)?;
    Some(match s.cmp(&0) {
        std::cmp::Ordering::Greater => Side::Left,
        std::cmp::Ordering::Less => Side::Right,
        std::cmp::Ordering::Equal => Side::On,
    })
}

/// [`kernel_of_ring`] on `i128` homogeneous points; `None` if some
/// intermediate value does not fit (every product is checked, so the
/// result, when there is one, is exact).
pub fn kernel_small(ring: &[Point]) -> Option<ConvexRegion> {
    let corners = grown_box(ring);
    let mut region: Vec<(Triple, Line)> = (0..4)
        .map(|i| {
            let line = Line::new(corners[i], corners[(i + 1) % 4]).expect("a box of positive size");
            ([corners[i].x, corners[i].y, 1], line)
        })
        .collect();
    for i in 0..ring.len() {
        let Some(cut) = Line::new(ring[i], ring[(i + 1) % ring.len()]) else {
            continue;
        };
        if let Some(clipped) = clip_small(&region, &cut)? {
            region = clipped;
        }
        if region.is_empty() {
            break;
        }
    }
    let vertices = region
        .into_iter()
        .map(|([x, y, w], _)| RatPoint::from_i128(x, y, w))
        .collect::<Option<Vec<RatPoint>>>()?;
    Some(ConvexRegion { vertices })
}

/// [`clip`] on `i128` points; `None` on overflow.
fn clip_small(region: &[(Triple, Line)], cut: &Line) -> Option<Option<Vec<(Triple, Line)>>> {
    clip_by(
        region,
        cut,
        |p| side_small(cut, p),
        wai_exact::construct_intersection_i128,
        same_triple,
    )
}

/// Whether two triples in lowest terms are one point: field by field,
/// without the library comparison of byte blocks that `==` on the arrays
/// may become.
#[inline]
fn same_triple(a: &Triple, b: &Triple) -> bool {
    ((a[0] ^ b[0]) | (a[1] ^ b[1]) | (a[2] ^ b[2])) == 0
}

/// Clip a convex region to the closed half-plane left of `cut`; `None`
/// when the region lies in it already (unchanged).
fn clip(region: &[(RatPoint, Line)], cut: &Line) -> Option<Vec<(RatPoint, Line)>> {
    clip_by(
        region,
        cut,
        |p| Some(side_of_line_rat(cut, p)),
        |a, b| Some(construct_intersection(a, b)),
        |a, b| a == b,
    )
    .expect("the GMP path never declines")
}

/// The clipping of [`clip`] and [`clip_small`] in terms of the point
/// type's `side` of `cut`, the `meet` of two lines (`Some(None)`:
/// parallel) and point equality `same`; `None` where either declines (an
/// overflow), `Some(None)` when no vertex lies right of `cut` (the region
/// is unchanged, and not copied).
fn clip_by<P: Clone>(
    region: &[(P, Line)],
    cut: &Line,
    side: impl Fn(&P) -> Option<Side>,
    meet: impl Fn(&Line, &Line) -> Option<Option<P>>,
    same: impl Fn(&P, &P) -> bool,
) -> Option<Option<Vec<(P, Line)>>> {
    let m = region.len();
    let sides = region
        .iter()
        .map(|(p, _)| side(p))
        .collect::<Option<Vec<Side>>>()?;
    if sides.iter().all(|&s| s != Side::Right) {
        return Some(None);
    }
    let mut out: Vec<(P, Line)> = Vec::new();
    for i in 0..m {
        let j = (i + 1) % m;
        let (p, line) = &region[i];
        let (si, sj) = (sides[i], sides[j]);
        if si != Side::Right {
            // From a vertex on the cut towards the outside, the boundary
            // now runs along the cut; otherwise along its old line.
            let next_line = if si == Side::On && sj != Side::Left {
                *cut
            } else {
                *line
            };
            out.push((p.clone(), next_line));
        }
        let crossing = matches!(
            (si, sj),
            (Side::Left, Side::Right) | (Side::Right, Side::Left)
        );
        if crossing {
            if let Some(x) = meet(cut, line)? {
                let next_line = if si == Side::Left { *cut } else { *line };
                out.push((x, next_line));
            }
        }
    }
    // Exit and re-entry at one point, or a region shrunk to a point.
    out.dedup_by(|a, b| same(&a.0, &b.0));
    while out.len() > 1 && same(&out[0].0, &out[out.len() - 1].0) {
        out.pop();
    }
    Some(Some(out))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The `i128` clipping gives the GMP clipping's region, on maps of
    /// every kind, their sub-rings (skeleton-like polygons with collinear
    /// and parallel edges) and large scales; beyond the range it declines.
    #[test]
    fn the_small_kernel_equals_the_exact_one() {
        let mut rings: Vec<Vec<Point>> = Vec::new();
        for kind in wai_gen::RANDOM_KINDS {
            for seed in 0..6 {
                let m = wai_gen::random(kind.id, kind.min_n.max(6) + seed as usize, seed).unwrap();
                let v = m.vertices().to_vec();
                // Star-shaped pieces: every third vertex dropped.
                let sub: Vec<Point> = v
                    .iter()
                    .enumerate()
                    .filter(|(i, _)| i % 3 != 2)
                    .map(|(_, p)| *p)
                    .collect();
                rings.push(v);
                rings.push(sub);
            }
        }
        for f in wai_gen::FAMILIES {
            rings.push(wai_gen::family(f.id, &[2]).unwrap().vertices().to_vec());
        }
        let (mut small, mut declined) = (0, 0);
        for ring in &rings {
            for scale in [1i128, 1 << 20, 1 << 40] {
                let scaled: Vec<Point> = ring
                    .iter()
                    .map(|p| Point::new(p.x * scale, p.y * scale))
                    .collect();
                match kernel_small(&scaled) {
                    Some(k) => {
                        assert_eq!(k, kernel_exact(&scaled), "{scaled:?}");
                        small += 1;
                    }
                    None => declined += 1,
                }
            }
        }
        assert!(small > 100 && declined > 0, "{small} {declined}");
    }
}
