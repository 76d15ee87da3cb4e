//! Kernel edges and wedge edges of the visibility cells (thesis sec. 5.1,
//! Defs 5.1 and 5.2).
//!
//! A cell C with skeleton V* in embedding h_j lies in the embedded kernel
//! h_j(ker V*), and for each artificial edge a_i in one visibility wedge
//! w^e_{i,j}: the points that see the candidate edge e through h_j(a_i)
//! (Def 5.1) and through it no other point of e's line: the projection of
//! h_j(a_i) onto that line lies in e. The wedge is bounded by the lines
//! r_l, r_r through one end of h_j(a_i) and one end of e that have the two
//! other ends on one side (the outer tangents of the two segments; an end
//! on the line counts for either side). An edge of C is a
//! **kernel edge** if it lies on the boundary of h_j(ker V*) and a **wedge
//! edge** if it lies on the boundary of a visibility wedge (Def 5.2).
//!
//! Since C lies in the convex kernel, an edge of C on the supporting line
//! of a kernel edge lies on the kernel's boundary. A wedge edge is tested
//! as an edge on one of the wedge's two bounding lines; which part of the
//! line bounds the wedge is not checked (the cell lies in the wedge, so
//! an edge of it on a bounding line is on the wedge's boundary).

use std::collections::BTreeSet;
use wai_exact::{orientation, orientation_rat, Orientation, Point, RatPoint};
use wai_map::Map;
use wai_visibility::ConvexRegion;

use crate::Embedding;

/// What Def 5.2 makes of one edge of a cell.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum CellEdgeKind {
    /// On the boundary of the embedded kernel only.
    Kernel,
    /// On the boundary of a visibility wedge only.
    Wedge,
    /// On both (the thesis's classification is a partition; counted apart).
    Both,
    /// On neither: a violation of Observation 5.3.
    Neither,
}

/// The lines bounding the visibility wedge of the embedded artificial
/// edge (a, b) and the candidate edge (c, d) (Def 5.1): the lines through
/// one end of each segment that have the other two ends on one side (an
/// end on the line counts for either). Two lines for segments in general
/// position; when ends are collinear, every line that qualifies.
pub fn wedge_lines(ab: (Point, Point), cd: (Point, Point)) -> Vec<(Point, Point)> {
    let mut out = Vec::new();
    for (p, p_other) in [(ab.0, ab.1), (ab.1, ab.0)] {
        for (q, q_other) in [(cd.0, cd.1), (cd.1, cd.0)] {
            if p == q {
                continue;
            }
            let side = |x: Point| orientation(p, q, x);
            let (s1, s2) = (side(p_other), side(q_other));
            let one_side = s1 == Orientation::Collinear || s2 == Orientation::Collinear || s1 == s2;
            if one_side {
                out.push((p, q));
            }
        }
    }
    out
}

fn on_line(p: Point, q: Point, x: &RatPoint) -> bool {
    orientation_rat(&RatPoint::from(p), &RatPoint::from(q), x) == Orientation::Collinear
}

/// The bounding lines of every visibility wedge of embedding `h`: those of
/// each artificial edge with each of its valid candidate edges `valid` (by
/// skeleton edge, as `crate::valid_candidate_edges` gives them). One list
/// per embedding serves all its cells.
pub fn embedding_wedge_lines(
    map: &Map,
    h: &Embedding,
    valid: &[Vec<usize>],
) -> Vec<(Point, Point)> {
    let v = map.vertices();
    let n = v.len();
    let k = h.vertices.len();
    let mut lines: Vec<(Point, Point)> = Vec::new();
    for (i, cands) in valid.iter().enumerate() {
        let ab = (v[h.vertices[i]], v[h.vertices[(i + 1) % k]]);
        for &e in cands {
            lines.extend(wedge_lines(ab, (v[e], v[(e + 1) % n])));
        }
    }
    lines
}

/// Def 5.2 for every edge of `cell` (its vertices counter-clockwise, edge
/// k from vertex k to k + 1) in an embedding with kernel `kernel` and
/// wedge lines `lines` ([`embedding_wedge_lines`]).
pub fn classify_cell_edges(
    kernel: &ConvexRegion,
    lines: &[(Point, Point)],
    cell: &[RatPoint],
) -> Vec<CellEdgeKind> {
    let kv = kernel.vertices();
    let m = cell.len();
    (0..m)
        .map(|t| {
            let (x, y) = (&cell[t], &cell[(t + 1) % m]);
            let on_kernel = (0..kv.len()).any(|u| {
                let (a, b) = (&kv[u], &kv[(u + 1) % kv.len()]);
                a != b
                    && orientation_rat(a, b, x) == Orientation::Collinear
                    && orientation_rat(a, b, y) == Orientation::Collinear
            });
            let on_wedge = lines
                .iter()
                .any(|&(p, q)| on_line(p, q, x) && on_line(p, q, y));
            match (on_kernel, on_wedge) {
                (true, false) => CellEdgeKind::Kernel,
                (false, true) => CellEdgeKind::Wedge,
                (true, true) => CellEdgeKind::Both,
                (false, false) => CellEdgeKind::Neither,
            }
        })
        .collect()
}

/// Whether the line through `p` and `q` is the line through `r` and `s`
/// (integer points, p ≠ q and r ≠ s).
pub fn same_line((p, q): (Point, Point), (r, s): (Point, Point)) -> bool {
    orientation(r, s, p) == Orientation::Collinear && orientation(r, s, q) == Orientation::Collinear
}

/// Def 5.2 for every edge of a cell in embedding h, each edge given by its
/// supporting line (through two map points, the map edge or the
/// visibility ray the arrangement put it on): a kernel edge if that line
/// is the line of an edge of h(V◇) (`ring`), a wedge edge if it is one of
/// the wedge lines `lines` ([`embedding_wedge_lines`]).
///
/// This is [`classify_cell_edges`] for a cell that lies in h(ker V*)
/// (Observation 3.13), in integers: the kernel is the intersection of the
/// closed half-planes left of h(V◇)'s edges, so each kernel edge lies on
/// the line of an edge of h(V◇); and a segment of the cell on such a line
/// lies on the kernel's boundary (the kernel is on one side of the line),
/// hence on a kernel edge. An edge of the cell lies on a line exactly when
/// its supporting line is that line.
pub fn classify_by_lines(
    ring: &[Point],
    lines: &[(Point, Point)],
    supports: impl IntoIterator<Item = (Point, Point)>,
) -> Vec<CellEdgeKind> {
    let k = ring.len();
    supports
        .into_iter()
        .map(|edge| {
            let on_kernel = (0..k).any(|u| {
                let (a, b) = (ring[u], ring[(u + 1) % k]);
                a != b && same_line(edge, (a, b))
            });
            let on_wedge = lines.iter().any(|&l| same_line(edge, l));
            match (on_kernel, on_wedge) {
                (true, false) => CellEdgeKind::Kernel,
                (false, true) => CellEdgeKind::Wedge,
                (true, true) => CellEdgeKind::Both,
                (false, false) => CellEdgeKind::Neither,
            }
        })
        .collect()
}

/// For an edge (x, y) of a cell in embedding `h` that is neither a kernel
/// nor a wedge edge: an artificial edge i and a map vertex u such that the
/// edge lies on the line through an end of h(a_i) and u, where u is no
/// vertex of h(V*) and no end of a valid candidate edge of a_i. This is the
/// configuration Observation 5.3's case 2b overlooks: crossing the edge
/// makes u visible, but u lies on no candidate edge. Two ways it arises:
/// the extension beyond a reflex vertex of a map edge hidden on the cell's
/// side (a C-shaped polyomino of 8 vertices), and a ray through two reflex
/// vertices of which the far one hides the candidate edge from part of the
/// window (the mouth corners of Fig 5.4's niches).
pub fn occluding_vertex(
    map: &Map,
    h: &Embedding,
    valid: &[Vec<usize>],
    x: &RatPoint,
    y: &RatPoint,
) -> Option<(usize, usize)> {
    let v = map.vertices();
    let n = v.len();
    let k = h.vertices.len();
    for (i, cands) in valid.iter().enumerate() {
        if cands.is_empty() {
            continue;
        }
        let ends: BTreeSet<usize> = cands.iter().flat_map(|&e| [e, (e + 1) % n]).collect();
        for a in [h.vertices[i], h.vertices[(i + 1) % k]] {
            for u in 0..n {
                if u == a || h.vertices.contains(&u) || ends.contains(&u) {
                    continue;
                }
                if on_line(v[a], v[u], x) && on_line(v[a], v[u], y) {
                    return Some((i, u));
                }
            }
        }
    }
    None
}

/// Counts of a classification, by kind (Kernel, Wedge, Both, Neither).
pub fn tally(kinds: &[CellEdgeKind]) -> [usize; 4] {
    let mut t = [0; 4];
    for k in kinds {
        t[match k {
            CellEdgeKind::Kernel => 0,
            CellEdgeKind::Wedge => 1,
            CellEdgeKind::Both => 2,
            CellEdgeKind::Neither => 3,
        }] += 1;
    }
    t
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn outer_tangents_of_two_parallel_segments() {
        // a = (0,0)-(2,0), e = (0,4)-(2,4): the points below a that see
        // through it e and nothing else of its line lie between x = 0 and
        // x = 2; the diagonals are not wedge lines.
        let p = |x, y| Point::new(x, y);
        let mut got = wedge_lines((p(0, 0), p(2, 0)), (p(0, 4), p(2, 4)));
        got.sort_by_key(|l| (l.0.x, l.0.y, l.1.x, l.1.y));
        assert_eq!(got, vec![(p(0, 0), p(0, 4)), (p(2, 0), p(2, 4))]);
        // A half edge: a = (0,0)-(2,4) ends on e = (2,4)-(6,4). Through a,
        // (0,0) must project into e: between the lines from (0,0) to both
        // ends of e.
        let got = wedge_lines((p(0, 0), p(2, 4)), (p(2, 4), p(6, 4)));
        assert!(got.contains(&(p(0, 0), p(2, 4))));
        assert!(got.contains(&(p(0, 0), p(6, 4))));
    }
}
