//! Closed segments between input points and their classified intersection.

use crate::line::Line;
use crate::point::Point;
use crate::predicates::{compare_along, orientation, Orientation};
use std::cmp::Ordering;

/// The closed segment from `a` to `b`, `a != b`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Segment {
    a: Point,
    b: Point,
}

impl Segment {
    /// `None` if `a == b`.
    pub fn new(a: Point, b: Point) -> Option<Self> {
        (a != b).then_some(Segment { a, b })
    }
    pub fn a(&self) -> Point {
        self.a
    }
    pub fn b(&self) -> Point {
        self.b
    }
    pub fn line(&self) -> Line {
        Line::new(self.a, self.b).expect("a segment has distinct endpoints")
    }

    /// Whether `p` lies on the closed segment.
    pub fn contains(&self, p: Point) -> bool {
        orientation(self.a, self.b, p) == Orientation::Collinear && self.contains_collinear(p)
    }

    /// For `p` on the segment's line: whether it lies between the endpoints.
    fn contains_collinear(&self, p: Point) -> bool {
        let l = self.line();
        compare_along(&l, self.a, p) != Ordering::Greater
            && compare_along(&l, p, self.b) != Ordering::Greater
    }
}

/// How two closed segments meet.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SegmentIntersection {
    /// No common point.
    None,
    /// One common point, interior to both segments (construct it with
    /// [`crate::construct_intersection`] on the two lines).
    Crossing,
    /// One common point, an endpoint of at least one segment.
    Touching { at: Point },
    /// Collinear with a common piece of positive length from `start` to
    /// `end` (ordered along the first segment); both are input endpoints.
    Overlap { start: Point, end: Point },
}

/// Classify how the closed segments `s` and `t` meet.
///
/// # Edge cases
/// Segments sharing an endpoint touch; collinear segments meeting in one
/// endpoint touch; collinear segments sharing more overlap.
/// ```
/// use wai_exact::{classify_segments, Point, Segment, SegmentIntersection as X};
/// let s = |a: (i128, i128), b: (i128, i128)| Segment::new(Point::new(a.0, a.1), Point::new(b.0, b.1)).unwrap();
/// assert_eq!(classify_segments(&s((0, 0), (4, 4)), &s((0, 4), (4, 0))), X::Crossing);
/// assert_eq!(classify_segments(&s((0, 0), (4, 0)), &s((2, 0), (2, 3))), X::Touching { at: Point::new(2, 0) });
/// assert_eq!(classify_segments(&s((0, 0), (4, 0)), &s((4, 0), (9, 0))), X::Touching { at: Point::new(4, 0) });
/// assert_eq!(
///     classify_segments(&s((0, 0), (4, 0)), &s((6, 0), (2, 0))),
///     X::Overlap { start: Point::new(2, 0), end: Point::new(4, 0) }
/// );
/// ```
pub fn classify_segments(s: &Segment, t: &Segment) -> SegmentIntersection {
    use Orientation::Collinear;
    let o1 = orientation(s.a, s.b, t.a);
    let o2 = orientation(s.a, s.b, t.b);
    if o1 == Collinear && o2 == Collinear {
        return collinear_overlap(s, t);
    }
    let o3 = orientation(t.a, t.b, s.a);
    let o4 = orientation(t.a, t.b, s.b);
    if o1 != Collinear && o2 != Collinear && o3 != Collinear && o4 != Collinear {
        return if o1 != o2 && o3 != o4 {
            SegmentIntersection::Crossing
        } else {
            SegmentIntersection::None
        };
    }
    // Not all collinear: at most one common point, an endpoint on the other.
    let touching = [(o1, t.a, s), (o2, t.b, s), (o3, s.a, t), (o4, s.b, t)]
        .into_iter()
        .find(|(o, p, seg)| *o == Collinear && seg.contains_collinear(*p));
    match touching {
        Some((_, at, _)) => SegmentIntersection::Touching { at },
        None => SegmentIntersection::None,
    }
}

fn collinear_overlap(s: &Segment, t: &Segment) -> SegmentIntersection {
    let l = s.line();
    let cmp = |p: Point, q: Point| compare_along(&l, p, q);
    let (t_lo, t_hi) = if cmp(t.a, t.b) == Ordering::Greater {
        (t.b, t.a)
    } else {
        (t.a, t.b)
    };
    let start = if cmp(s.a, t_lo) == Ordering::Less {
        t_lo
    } else {
        s.a
    };
    let end = if cmp(s.b, t_hi) == Ordering::Greater {
        t_hi
    } else {
        s.b
    };
    match cmp(start, end) {
        Ordering::Less => SegmentIntersection::Overlap { start, end },
        Ordering::Equal => SegmentIntersection::Touching { at: start },
        Ordering::Greater => SegmentIntersection::None,
    }
}
