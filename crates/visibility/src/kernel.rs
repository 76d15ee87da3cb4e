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
pub fn kernel_of_ring(ring: &[Point]) -> ConvexRegion {
    let xs = ring.iter().map(|p| p.x);
    let ys = ring.iter().map(|p| p.y);
    let (x0, x1) = (xs.clone().min().unwrap_or(0) - 1, xs.max().unwrap_or(0) + 1);
    let (y0, y1) = (ys.clone().min().unwrap_or(0) - 1, ys.max().unwrap_or(0) + 1);
    let corners = [
        Point::new(x0, y0),
        Point::new(x1, y0),
        Point::new(x1, y1),
        Point::new(x0, y1),
    ];
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
        region = clip(&region, &cut);
        if region.is_empty() {
            break;
        }
    }
    ConvexRegion {
        vertices: region.into_iter().map(|(p, _)| p).collect(),
    }
}

/// Clip a convex region to the closed half-plane left of `cut`.
fn clip(region: &[(RatPoint, Line)], cut: &Line) -> Vec<(RatPoint, Line)> {
    let m = region.len();
    let sides: Vec<Side> = region
        .iter()
        .map(|(p, _)| side_of_line_rat(cut, p))
        .collect();
    if sides.iter().all(|&s| s != Side::Right) {
        return region.to_vec();
    }
    let mut out: Vec<(RatPoint, Line)> = Vec::new();
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
            if let Some(x) = construct_intersection(cut, line) {
                let next_line = if si == Side::Left { *cut } else { *line };
                out.push((x, next_line));
            }
        }
    }
    // Exit and re-entry at one point, or a region shrunk to a point.
    out.dedup_by(|a, b| a.0 == b.0);
    while out.len() > 1 && out.first().map(|f| &f.0) == out.last().map(|l| &l.0) {
        out.pop();
    }
    out
}
