//! Lines through two distinct input points.

use crate::point::Point;
use crate::predicates::{side_of_line, Side};

/// The directed line through two distinct input points `a` and `b`.
///
/// Every line of the thesis (map edges, visibility rays, the lines labelling
/// artificial edges) passes through two map vertices, so this is the only
/// line type: its coefficients stay small and exact.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Line {
    a: Point,
    b: Point,
}

impl Line {
    /// The line from `a` towards `b`; `None` if `a == b`.
    pub fn new(a: Point, b: Point) -> Option<Self> {
        (a != b).then_some(Line { a, b })
    }

    pub fn a(&self) -> Point {
        self.a
    }

    pub fn b(&self) -> Point {
        self.b
    }

    /// The same line, directed the other way.
    pub fn reversed(&self) -> Line {
        Line {
            a: self.b,
            b: self.a,
        }
    }

    pub fn contains(&self, p: Point) -> bool {
        side_of_line(self, p) == Side::On
    }
}
