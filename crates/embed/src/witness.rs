//! Def 4.1: witnesses, valid embeddings and valid candidate edges.
//!
//! A witness of an embedding h of V* is a point w ∈ h(ker V*) with
//! V*_w = V*. The points with skeleton V* are the cells of EC_{V*} of every
//! dimension (claim T3.3b), and by Lemma 3.5 (claim L3.5) each lies in the
//! kernel of exactly one embedding: the one whose h(v0) is the cell's own
//! v0. So the **witness region** of h is the union of the cells of the
//! class whose origin is h(v0), and h is **valid** iff it has one.
//!
//! A 1- or 0-cell that an adjacent 2-cell absorbs (same skeleton, same
//! embedding) belongs to that 2-cell's witness region; it is not listed
//! as a piece of its own. Questions of visibility are unaffected: a point
//! that sees something is surrounded by points that see it too, among them
//! points of the absorbing 2-cell.

use crate::embedding::Embedding;
use crate::piece::{Bounds, Piece};
use std::cmp::Ordering;
use std::collections::BTreeSet;
use wai_cells::{Decomposition, FaceId, LowerSite};
use wai_exact::{orientation_rat, turn, Orientation, QPoint, RatPoint};
use wai_visibility::{Skeleton, SkeletonEdge, VisibilityIndex};

/// A cell of the decomposition, of any dimension.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum CellRef {
    /// A 2-cell: a face of the arrangement.
    Face(FaceId),
    /// A kept 1- or 0-cell: its index in [`Decomposition::lower_cells`].
    Lower(usize),
}

/// A cell of a witness region: which cell, its points, and one exact point
/// of it (the decomposition's representative).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct WitnessCell {
    pub cell: CellRef,
    pub piece: Piece,
    pub point: RatPoint,
}

/// The witness region of one embedding (Def 4.1).
#[derive(Clone, Debug, PartialEq, Eq, Default)]
pub struct Witnesses {
    pub cells: Vec<WitnessCell>,
}

impl Witnesses {
    /// Def 4.1: h is valid iff it has a witness.
    pub fn is_valid(&self) -> bool {
        !self.cells.is_empty()
    }

    /// The pieces, for [`crate::Sightlines`].
    pub fn pieces(&self) -> Vec<Piece> {
        self.cells.iter().map(|c| c.piece.clone()).collect()
    }
}

/// The points of a cell as a [`Piece`].
pub fn piece_of(d: &Decomposition<'_>, cell: CellRef) -> Piece {
    let arr = d.arrangement();
    let at = |v| QPoint::from(arr.point(v));
    match cell {
        CellRef::Face(f) => {
            let points = arr.face_points(f);
            let mut v: Vec<QPoint> = points.iter().map(QPoint::from).collect();
            // Counter-clockwise, as Piece wants (the arrangement's cells are,
            // but the piece's span test depends on it, so make sure): a cell
            // is convex (Theorem 3.3 (1), the arrangement's sanity check), so
            // its first turn that is not straight gives its orientation.
            let m = points.len();
            let turn = (0..m)
                .map(|i| orientation_rat(&points[i], &points[(i + 1) % m], &points[(i + 2) % m]))
                .find(|o| *o != Orientation::Collinear);
            if turn == Some(Orientation::Clockwise) {
                v.reverse();
            }
            Piece::Polygon(v)
        }
        CellRef::Lower(i) => match d.lower_cells()[i].site {
            LowerSite::Edge(e) => {
                let h = arr.half_edge(2 * e);
                Piece::Segment(at(h.origin), at(arr.dest(2 * e)))
            }
            LowerSite::Vertex(v) => Piece::Point(at(v)),
        },
    }
}

/// The witness regions of the embeddings of class `class`'s skeleton whose
/// origins h(v0) are `origins`, in their order: the class's 2-cells and
/// kept lower cells, each given to the embedding at its own v0.
///
/// A cell whose v0 is the origin of none of them is left out (that would
/// break Lemma 3.4, which claim L3.5 checks).
pub fn witness_regions(d: &Decomposition<'_>, class: usize, origins: &[usize]) -> Vec<Witnesses> {
    let mut out = vec![Witnesses::default(); origins.len()];
    let slot = |origin: usize| origins.iter().position(|&o| o == origin);
    for &f in &d.classes()[class] {
        if let Some(i) = slot(d.origin_of(f)) {
            let cell = CellRef::Face(f);
            out[i].cells.push(WitnessCell {
                piece: piece_of(d, cell),
                point: d.representative(f).clone(),
                cell,
            });
        }
    }
    for &l in d.class_lower_cells(class) {
        let lower = &d.lower_cells()[l];
        if let Some(i) = slot(lower.origin) {
            let cell = CellRef::Lower(l);
            out[i].cells.push(WitnessCell {
                piece: piece_of(d, cell),
                point: d.lower_representative(lower),
                cell,
            });
        }
    }
    out
}

/// By witness cell of `h` (as `witnesses.cells`), by skeleton edge: the
/// map edge that carries the edge's half or partial edge in V_w for the
/// cell's points (`None` for full edges).
///
/// One point per witness cell suffices: along a connected set of points
/// with one skeleton the map edge under a partial edge cannot change,
/// since passing from one edge of the label line to another would uncover
/// the vertex between them (Lemma 3.1 (3)).
///
/// # Panics
/// If V_w of a witness cell's point cannot be computed or has another
/// skeleton than h's class (a bug the claims T3.3b and L3.5 catch).
pub fn witness_views(
    index: &VisibilityIndex<'_>,
    h: &Embedding,
    witnesses: &Witnesses,
) -> Vec<Vec<Option<usize>>> {
    witnesses
        .cells
        .iter()
        .map(|w| {
            let vp = index
                .visibility_polygon(&w.point)
                .expect("a witness lies inside the map");
            let s = Skeleton::of(index.map(), &vp).expect("a witness's V_w has a skeleton");
            assert_eq!(
                s.map_vertices(),
                h.vertices.as_slice(),
                "witness {} does not have the skeleton of its embedding",
                w.point
            );
            s.edges()
                .iter()
                .map(|e| match e {
                    SkeletonEdge::Artificial { map_edge, .. } => Some(*map_edge),
                    SkeletonEdge::Full { .. } => None,
                })
                .collect()
        })
        .collect()
}

/// Def 4.1: the valid candidate edges of each artificial edge of `h`
/// (by skeleton edge, as [`Embedding::candidates`]; empty for full edges
/// and for an embedding with no witness): the map edges that carry the
/// edge's half or partial edge in V_w for some witness w
/// ([`witness_views`]).
///
/// # Panics
/// As [`witness_views`].
pub fn valid_candidate_edges(
    index: &VisibilityIndex<'_>,
    h: &Embedding,
    witnesses: &Witnesses,
) -> Vec<Vec<usize>> {
    valid_from_views(h.vertices.len(), &witness_views(index, h, witnesses))
}

/// [`valid_candidate_edges`] from the views [`witness_views`] gives.
pub fn valid_from_views(edges: usize, views: &[Vec<Option<usize>>]) -> Vec<Vec<usize>> {
    let mut valid: Vec<BTreeSet<usize>> = vec![BTreeSet::new(); edges];
    for view in views {
        for (i, e) in view.iter().enumerate() {
            if let Some(e) = e {
                valid[i].insert(*e);
            }
        }
    }
    valid.into_iter().map(|s| s.into_iter().collect()).collect()
}

/// The sight fans ([`crate::SightFan`]) of `h`: one per witness cell and
/// artificial edge, from the cells' `views` ([`witness_views`]).
pub fn sight_fans(
    map: &wai_map::Map,
    h: &Embedding,
    witnesses: &Witnesses,
    views: &[Vec<Option<usize>>],
) -> Vec<crate::SightFan> {
    let v = map.vertices();
    let n = v.len();
    let k = h.vertices.len();
    let at = |m: usize| QPoint::from(v[m]);
    let mut out = Vec::new();
    for (cell, (w, view)) in witnesses.cells.iter().zip(views).enumerate() {
        for (i, e) in view.iter().enumerate() {
            if let Some(e) = *e {
                out.push(crate::SightFan::new(
                    &w.piece,
                    cell,
                    i,
                    (at(h.vertices[i]), at(h.vertices[(i + 1) % k])),
                    e,
                    (at(e), at((e + 1) % n)),
                ));
            }
        }
    }
    out
}

/// The pairs `(a, b)`, `a < b`, of embeddings of one skeleton that are
/// both valid (`witnesses`, in the same order) and whose embedded skeleton
/// polygons overlap: the premise of Theorem 4.2.
pub fn overlapping_valid_pairs(
    map: &wai_map::Map,
    embeddings: &[Embedding],
    witnesses: &[Witnesses],
) -> Vec<(usize, usize)> {
    let rings: Vec<Vec<QPoint>> = embeddings
        .iter()
        .map(|h| h.polygon(map).into_iter().map(QPoint::from).collect())
        .collect();
    let mut out = Vec::new();
    for a in 0..embeddings.len() {
        for b in a + 1..embeddings.len() {
            if witnesses[a].is_valid()
                && witnesses[b].is_valid()
                && interiors_overlap(&rings[a], &rings[b])
            {
                out.push((a, b));
            }
        }
    }
    out
}

/// Whether two embedded kernels overlap (Theorem 4.3's premise): both
/// have an interior and the interiors share a point. A kernel that is a
/// point or a segment overlaps nothing.
pub fn kernels_overlap(a: &wai_visibility::ConvexRegion, b: &wai_visibility::ConvexRegion) -> bool {
    let ring = |k: &wai_visibility::ConvexRegion| -> Vec<QPoint> {
        k.vertices().iter().map(QPoint::from).collect()
    };
    a.has_interior() && b.has_interior() && interiors_overlap(&ring(a), &ring(b))
}

/// Whether the interiors of two simple polygons, each counter-clockwise,
/// share a point (sec. 4.2: the embeddings *overlap*; sharing only
/// boundary points, they merely intersect, sec. 4.6).
///
/// Exact and complete: a face of the overlay of both boundaries that lies
/// in both interiors is bounded by a piece of an edge of one of them, on
/// that polygon's inner (left) side. So each edge of either polygon is cut
/// where the other's boundary meets it, and the left side of each piece's
/// midpoint is tested against the other polygon: inside it, or on an edge
/// of it running the same way.
pub fn interiors_overlap(p: &[QPoint], q: &[QPoint]) -> bool {
    let (bp, bq) = (Bounds::of(p), Bounds::of(q));
    // Boxes that share no interior point: neither do the polygons.
    if bp.hi.0 <= bq.lo.0 || bq.hi.0 <= bp.lo.0 || bp.hi.1 <= bq.lo.1 || bq.hi.1 <= bp.lo.1 {
        return false;
    }
    if let (Some(sp), Some(sq)) = (
        crate::intersection::fast_ring(p),
        crate::intersection::fast_ring(q),
    ) {
        return crate::intersection::fast_overlaps(&sp, &sq);
    }
    one_side_overlaps(p, q, &bq) || one_side_overlaps(q, p, &bp)
}

/// [`interiors_overlap`] in GMP rationals: the path for points beyond
/// [`crate::intersection::FAST_BITS`], and the reference of the integer
/// one.
pub fn interiors_overlap_rational(p: &[QPoint], q: &[QPoint]) -> bool {
    let (bp, bq) = (Bounds::of(p), Bounds::of(q));
    if bp.hi.0 <= bq.lo.0 || bq.hi.0 <= bp.lo.0 || bp.hi.1 <= bq.lo.1 || bq.hi.1 <= bp.lo.1 {
        return false;
    }
    one_side_overlaps(p, q, &bq) || one_side_overlaps(q, p, &bp)
}

fn one_side_overlaps(p: &[QPoint], q: &[QPoint], bq: &Bounds) -> bool {
    let (np, nq) = (p.len(), q.len());
    for i in 0..np {
        let (a, b) = (&p[i], &p[(i + 1) % np]);
        // An edge outside q's box has no piece inside q or along its edges.
        if !bq.meets(a, b) {
            continue;
        }
        let dir = b.sub(a);
        // Cut points along a→b, as parameters in [0, 1].
        let mut cuts = vec![rug::Rational::new(), rug::Rational::from(1)];
        for j in 0..nq {
            let (c, e) = (&q[j], &q[(j + 1) % nq]);
            for t in crate::piece::segment_cuts(a, b, c, e) {
                cuts.push(t);
            }
        }
        cuts.sort();
        cuts.dedup();
        for w in cuts.windows(2) {
            let mid = a.along(&dir, &(rug::Rational::from(&w[0] + &w[1]) / 2u32));
            match locate(q, &mid) {
                Locus::Inside => return true,
                Locus::Outside => {}
                Locus::OnEdge(j) => {
                    let (c, e) = (&q[j], &q[(j + 1) % nq]);
                    // Same direction: both interiors on the left.
                    if dir.dot(&e.sub(c)) > 0 {
                        return true;
                    }
                }
            }
        }
    }
    false
}

/// Whether the closed segment `ab` and the closed simple polygon `q`
/// share a point.
pub fn segment_meets_polygon(a: &QPoint, b: &QPoint, q: &[QPoint]) -> bool {
    !matches!(locate(q, a), Locus::Outside)
        || (0..q.len()).any(|j| crate::piece::segments_meet(a, b, &q[j], &q[(j + 1) % q.len()]))
}

pub(crate) enum Locus {
    Inside,
    Outside,
    OnEdge(usize),
}

/// Where `x` lies relative to the simple polygon `q` (crossing number,
/// exact).
pub(crate) fn locate(q: &[QPoint], x: &QPoint) -> Locus {
    let n = q.len();
    let mut inside = false;
    for j in 0..n {
        let (a, b) = (&q[j], &q[(j + 1) % n]);
        // An edge wholly above or below x neither holds it nor crosses
        // its horizontal.
        if (a.y < x.y && b.y < x.y) || (a.y > x.y && b.y > x.y) {
            continue;
        }
        if crate::piece::segments_meet(a, b, x, x) {
            return Locus::OnEdge(j);
        }
        // Half-open rule on y.
        if (a.y > x.y) != (b.y > x.y) {
            // x is left of the upward crossing iff the turn agrees.
            let t = turn(a, b, x);
            let up = b.y > a.y;
            if (up && t == Ordering::Greater) || (!up && t == Ordering::Less) {
                inside = !inside;
            }
        }
    }
    if inside {
        Locus::Inside
    } else {
        Locus::Outside
    }
}
