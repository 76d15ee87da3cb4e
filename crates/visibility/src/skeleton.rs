//! The visibility skeleton V*_p (Def 3.7), its canonical encoding, its
//! kernel (Def 3.12) and the reconstruction of V_p (Thm 3.2).

use crate::kernel::{kernel_of_ring, ConvexRegion};
use crate::polygon::{EdgeKind, OnMap, VisibilityPolygon};
use rug::Integer;
use wai_exact::{orientation_rat, Orientation, Point, RatPoint};
use wai_map::Map;

/// The line `a·x + b·y = c` in coordinates relative to the skeleton's
/// origin v0 (Def 3.7 (5), (6)), in lowest terms with `a > 0`, or `a = 0`
/// and `b > 0`: equal lines have equal labels.
#[derive(Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct LineLabel {
    pub a: Integer,
    pub b: Integer,
    pub c: Integer,
}

impl LineLabel {
    /// The label of the line through `p` and `q` (distinct), relative to `origin`.
    pub fn through(p: Point, q: Point, origin: Point) -> LineLabel {
        LineLabel::through_small(p, q, origin)
            .unwrap_or_else(|| LineLabel::through_gmp(p, q, origin))
    }

    /// [`LineLabel::through`] in GMP integers, for any coordinates.
    fn through_gmp(p: Point, q: Point, origin: Point) -> LineLabel {
        let a = Integer::from(q.y) - p.y;
        let b = Integer::from(p.x) - q.x;
        let c = Integer::from(&a * (p.x - origin.x)) + Integer::from(&b * (p.y - origin.y));
        LineLabel::normalized(a, b, c)
    }

    /// [`LineLabel::through`] in `i128`, when every coordinate is below
    /// `2^61` in magnitude: then a, b and the offsets from the origin are
    /// below `2^62`, each product below `2^124` and c below `2^125`; the
    /// gcd divides exactly, so the label is the same as in GMP.
    fn through_small(p: Point, q: Point, origin: Point) -> Option<LineLabel> {
        let fits = |c: i128| c.unsigned_abs() < 1 << 61;
        if ![p.x, p.y, q.x, q.y, origin.x, origin.y]
            .into_iter()
            .all(fits)
        {
            return None;
        }
        let (a, b) = (q.y - p.y, p.x - q.x);
        let c = a * (p.x - origin.x) + b * (p.y - origin.y);
        let g = wai_exact::gcd_u128(
            wai_exact::gcd_u128(a.unsigned_abs(), b.unsigned_abs()),
            c.unsigned_abs(),
        );
        // g ≥ 1 (a, b not both 0) and g ≤ max(|a|, |b|) < 2^62.
        let g = g as i128;
        let s = if a < 0 || (a == 0 && b < 0) { -1 } else { 1 };
        Some(LineLabel {
            a: Integer::from(s * (a / g)),
            b: Integer::from(s * (b / g)),
            c: Integer::from(s * (c / g)),
        })
    }

    /// The label of the line `a·x + b·y = c` (a, b not both 0): divided by
    /// the gcd of the three, with the sign that makes `a > 0`, or `a = 0`
    /// and `b > 0`.
    pub fn normalized(a: Integer, b: Integer, c: Integer) -> LineLabel {
        let g = Integer::from(a.gcd_ref(&b)).gcd(&c);
        let (mut a, mut b, mut c) = (a / &g, b / &g, c / &g);
        if a < 0 || (a == 0 && b < 0) {
            a = -a;
            b = -b;
            c = -c;
        }
        LineLabel { a, b, c }
    }

    /// Whether the point `(x, y)` (relative to the origin) lies on the line.
    pub fn contains(&self, x: i128, y: i128) -> bool {
        Integer::from(&self.a * x) + Integer::from(&self.b * y) == self.c
    }
}

/// An edge of a skeleton, from vertex `i` to vertex `i + 1`.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum SkeletonEdge {
    /// A full edge of V_p: the map edge `map_edge`.
    Full { map_edge: usize },
    /// Def 3.7 (3), (4): replaces a half or partial edge lying on map edge
    /// `map_edge`, whose line the label gives.
    Artificial { label: LineLabel, map_edge: usize },
}

/// The canonical encoding of a skeleton: vertex offsets from the origin v0,
/// counter-clockwise from v0, and the label of each artificial edge (`None`
/// for full edges). Two skeletons are equal exactly when their keys are.
#[derive(Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct SkeletonKey {
    pub offsets: Vec<(i128, i128)>,
    pub labels: Vec<Option<LineLabel>>,
}

/// The visibility skeleton V*_p of a viewpoint (Def 3.7), in map
/// coordinates: the identity embedding of Lemma 3.4.
///
/// # Canonical origin
/// v0 is the leftmost, then lowest, vertex of V_p that is reflex in V_p
/// (Def 3.7 (6) suggests the leftmost). It is well defined: vertices of V_p
/// are distinct points, and reflex vertices of V_p are never spurious (Lemma
/// 3.1 (1)), so v0 is a vertex of the skeleton. A V_p without reflex
/// vertices is the whole map, convex (r = 0, outside the thesis's
/// assumption); then v0 is its leftmost, then lowest, vertex.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Skeleton {
    vertices: Vec<Point>,
    map_vertices: Vec<usize>,
    edges: Vec<SkeletonEdge>,
}

/// Why a skeleton could not be built: the visibility polygon breaks a
/// lemma the skeleton relies on (a checker reports these as violations).
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum SkeletonError {
    #[error("non-spurious vertex {0} of V_p is not a map vertex")]
    NonSpuriousOffMap(usize),
    #[error(
        "the V_p boundary between skeleton vertices {0} and {1} has {2} non-spurious edges, not 1"
    )]
    BadArtificialPath(usize, usize, usize),
    #[error("V_p has no non-spurious vertex")]
    NoVertex,
}

impl Skeleton {
    /// V*_p from V_p.
    pub fn of(map: &Map, vp: &VisibilityPolygon) -> Result<Skeleton, SkeletonError> {
        let verts = vp.vertices();
        let n = verts.len();
        // Non-spurious vertices and their map vertex.
        let mut keep: Vec<(usize, usize)> = Vec::new();
        for (i, v) in verts.iter().enumerate() {
            if !v.spurious {
                match v.on_map {
                    OnMap::Vertex(m) => keep.push((i, m)),
                    OnMap::Edge(_) => return Err(SkeletonError::NonSpuriousOffMap(i)),
                }
            }
        }
        if keep.is_empty() {
            return Err(SkeletonError::NoVertex);
        }
        let origin_vp = canonical_origin(vp, &keep);
        let start = keep
            .iter()
            .position(|&(i, _)| i == origin_vp)
            .expect("origin is kept");
        keep.rotate_left(start);
        let origin = map.vertices()[keep[0].1];
        let k = keep.len();
        let mut edges = Vec::with_capacity(k);
        for s in 0..k {
            let (i, _) = keep[s];
            let (j, _) = keep[(s + 1) % k];
            // The V_p edges from vertex i to vertex j.
            let mut path = Vec::new();
            let mut e = i;
            loop {
                path.push(e);
                e = (e + 1) % n;
                if e == j {
                    break;
                }
            }
            let solid: Vec<usize> = path
                .iter()
                .copied()
                .filter(|&e| vp.edges()[e].kind != EdgeKind::Spurious)
                .collect();
            let edge = match (path.len(), solid.as_slice()) {
                (1, [e]) if vp.edges()[*e].kind == EdgeKind::Full => SkeletonEdge::Full {
                    map_edge: vp.edges()[*e]
                        .map_edge
                        .expect("non-spurious edges lie on the map"),
                },
                (_, [e]) => {
                    let me = vp.edges()[*e]
                        .map_edge
                        .expect("non-spurious edges lie on the map");
                    let (a, b) = (map.vertices()[me], map.vertices()[map.next(me)]);
                    SkeletonEdge::Artificial {
                        label: LineLabel::through(a, b, origin),
                        map_edge: me,
                    }
                }
                (_, other) => return Err(SkeletonError::BadArtificialPath(i, j, other.len())),
            };
            edges.push(edge);
        }
        Ok(Skeleton {
            vertices: keep.iter().map(|&(_, m)| map.vertices()[m]).collect(),
            map_vertices: keep.iter().map(|&(_, m)| m).collect(),
            edges,
        })
    }

    /// The origin v0, in map coordinates.
    pub fn origin(&self) -> Point {
        self.vertices[0]
    }
    /// The vertices, counter-clockwise from v0, in map coordinates: the
    /// skeleton polygon V◇.
    pub fn vertices(&self) -> &[Point] {
        &self.vertices
    }
    /// The map vertex of each skeleton vertex.
    pub fn map_vertices(&self) -> &[usize] {
        &self.map_vertices
    }
    pub fn edges(&self) -> &[SkeletonEdge] {
        &self.edges
    }
    /// The number of artificial edges.
    pub fn artificial_count(&self) -> usize {
        self.edges
            .iter()
            .filter(|e| matches!(e, SkeletonEdge::Artificial { .. }))
            .count()
    }

    /// The canonical encoding.
    pub fn key(&self) -> SkeletonKey {
        let o = self.origin();
        SkeletonKey {
            offsets: self
                .vertices
                .iter()
                .map(|v| (v.x - o.x, v.y - o.y))
                .collect(),
            labels: self
                .edges
                .iter()
                .map(|e| match e {
                    SkeletonEdge::Full { .. } => None,
                    SkeletonEdge::Artificial { label, .. } => Some(label.clone()),
                })
                .collect(),
        }
    }

    /// ker V* (Def 3.12), in map coordinates.
    pub fn kernel(&self) -> ConvexRegion {
        kernel_of_ring(&self.vertices)
    }
}

/// The leftmost, then lowest, vertex of V_p reflex in V_p, else of all kept.
fn canonical_origin(vp: &VisibilityPolygon, keep: &[(usize, usize)]) -> usize {
    let v = vp.vertices();
    let n = v.len();
    let reflex: Vec<usize> = keep
        .iter()
        .map(|&(i, _)| i)
        .filter(|&i| {
            orientation_rat(
                &v[(i + n - 1) % n].point,
                &v[i].point,
                &v[(i + 1) % n].point,
            ) == Orientation::Clockwise
        })
        .collect();
    let pool: Vec<usize> = if reflex.is_empty() {
        keep.iter().map(|&(i, _)| i).collect()
    } else {
        reflex
    };
    let at = |i: usize| {
        v[i].point
            .to_point()
            .expect("kept vertices are map vertices")
    };
    pool.into_iter()
        .min_by_key(|&i| {
            let p = at(i);
            (p.x, p.y)
        })
        .expect("at least one vertex")
}

/// Rebuild V_p from a skeleton's key and the viewpoint relative to the
/// origin v0 (the constructive direction of Thm 3.2). The result is V_p's
/// vertex sequence relative to v0, starting at v0.
///
/// Each artificial edge u→w with label line l stands for the boundary
/// u → s1 → s2 → w of V_p, where s1 = ray(p, u) ∩ l is inserted unless u
/// lies on l (a half edge starting at u), and s2 = ray(p, w) ∩ l unless w
/// lies on l.
pub fn reconstruct(key: &SkeletonKey, p_rel: &RatPoint) -> Vec<RatPoint> {
    let k = key.offsets.len();
    let mut out = Vec::new();
    for s in 0..k {
        let u = key.offsets[s];
        let w = key.offsets[(s + 1) % k];
        out.push(RatPoint::from(Point::new(u.0, u.1)));
        if let Some(l) = &key.labels[s] {
            if !l.contains(u.0, u.1) {
                out.extend(ray_meets_line(p_rel, u, l));
            }
            if !l.contains(w.0, w.1) {
                out.extend(ray_meets_line(p_rel, w, l));
            }
        }
    }
    out
}

/// The point where the line from p through u meets l; `None` if parallel.
fn ray_meets_line(p: &RatPoint, u: (i128, i128), l: &LineLabel) -> Option<RatPoint> {
    let (x, y, w) = (p.hx(), p.hy(), p.hw());
    let dx = Integer::from(w * u.0) - x;
    let dy = Integer::from(w * u.1) - y;
    // p + t(u − p) on l:  t = (cW − aX − bY) / (a·dx + b·dy).
    let num = Integer::from(&l.c * w) - Integer::from(&l.a * x) - Integer::from(&l.b * y);
    let den = Integer::from(&l.a * &dx) + Integer::from(&l.b * &dy);
    if den == 0 {
        return None;
    }
    let px = Integer::from(x * &den) + Integer::from(&num * &dx);
    let py = Integer::from(y * &den) + Integer::from(&num * &dy);
    RatPoint::new(px, py, Integer::from(w * &den))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The `i128` labels equal the GMP ones: every line through two points
    /// of a small grid, and random points up to the `2^61` bound.
    #[test]
    fn small_labels_equal_gmp_labels() {
        let grid: Vec<Point> = (-3..=3)
            .flat_map(|x| (-3..=3).map(move |y| Point::new(x, y)))
            .collect();
        let o = Point::new(1, -2);
        for &p in &grid {
            for &q in grid.iter().filter(|&&q| q != p) {
                let small = LineLabel::through_small(p, q, o).expect("small");
                assert_eq!(small, LineLabel::through_gmp(p, q, o), "{p} {q}");
            }
        }
        let mut rng = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = |bits: u32| {
            rng ^= rng << 13;
            rng ^= rng >> 7;
            rng ^= rng << 17;
            let v = (rng >> (64 - bits)) as i128;
            if rng & 1 == 0 {
                v
            } else {
                -v
            }
        };
        let mut checked = 0;
        for bits in [3u32, 20, 40, 60, 61, 62] {
            for _ in 0..500 {
                let mut pt = || Point::new(next(bits), next(bits));
                let (p, q, o) = (pt(), pt(), pt());
                if p == q {
                    continue;
                }
                if let Some(small) = LineLabel::through_small(p, q, o) {
                    assert_eq!(small, LineLabel::through_gmp(p, q, o), "{p} {q} {o}");
                    checked += 1;
                }
                assert_eq!(LineLabel::through(p, q, o), LineLabel::through_gmp(p, q, o));
            }
        }
        assert!(checked >= 2000, "{checked}");
    }
}
