//! The input check of V and the reasons for empty answers.

use wai_exact::{Point, RatPoint};
use wai_localize::{Localizer, NoSkeleton, Nowhere, RobotView, ViewError};
use wai_map::Map;

fn p(x: i128, y: i128) -> RatPoint {
    RatPoint::from_i128(x, y, 1).unwrap()
}

fn view(pts: &[(i128, i128)]) -> Result<RobotView, ViewError> {
    RobotView::new(pts.iter().map(|&(x, y)| p(x, y)).collect())
}

#[test]
fn bad_polygons_are_refused_with_the_reason() {
    assert_eq!(view(&[(1, 0), (0, 1)]), Err(ViewError::TooFew(2)));
    assert_eq!(view(&[(0, 0), (1, 0), (0, 1)]), Err(ViewError::AtRobot(0)));
    assert_eq!(
        view(&[(1, -1), (1, -1), (0, 1)]),
        Err(ViewError::Repeated(0, 1))
    );
    // A "C": edge 3 turns clockwise around the robot.
    assert_eq!(
        view(&[(-2, -2), (2, -2), (2, 2), (1, 2), (1, 1), (-2, 1)]),
        Err(ViewError::NotStarShaped(3, 4))
    );
    // The robot on the boundary.
    assert_eq!(
        view(&[(-1, 0), (1, 0), (0, 1)]),
        Err(ViewError::ThroughRobot(0, 1))
    );
    // A pentagram: star-shaped edge by edge, but it winds twice.
    assert_eq!(
        view(&[(10, 0), (-8, 6), (3, -10), (3, 10), (-8, -6)]),
        Err(ViewError::Winding(2))
    );
    // Out along the ray at angle 0 and back: a spike.
    assert_eq!(
        view(&[(-1, -1), (1, -1), (2, 0), (4, 0), (3, 0), (1, 1), (-1, 1)]),
        Err(ViewError::Spike(2, 3))
    );
    assert_eq!(view(&[(1, 0), (2, 0), (3, 0)]), Err(ViewError::Degenerate));
}

#[test]
fn clockwise_input_is_reversed_and_straight_vertices_dropped() {
    let v = view(&[(-1, 1), (1, 1), (1, 0), (1, -1), (-1, -1)]).unwrap();
    assert_eq!(v.vertices().len(), 4);
    assert_eq!(v.notes().len(), 2, "{:?}", v.notes());
}

/// The L room of the cells crate's example: the square part sees all six
/// vertices, the legs do not.
fn l_room() -> Map {
    let ring = [(0, 0), (4, 0), (4, 2), (2, 2), (2, 4), (0, 4)];
    Map::from_ring(ring.iter().map(|&(x, y)| Point::new(x, y)).collect())
        .unwrap()
        .0
}

#[test]
fn empty_answers_say_why() {
    let map = l_room();
    let loc = Localizer::new(&map);
    let rel = |rx: i128, ry: i128| {
        RobotView::new(
            map.vertices()
                .iter()
                .map(|v| RatPoint::from_i128(v.x - rx, v.y - ry, 1).unwrap())
                .collect(),
        )
        .unwrap()
    };
    // From (1, 1) the robot sees the whole L: one answer, itself.
    let a = loc.localize(&rel(1, 1));
    assert_eq!(a.positions(), vec![p(1, 1)], "{:?}", a.nowhere);
    // A square nothing in the L sees.
    let a = loc.localize(&view(&[(-1, -1), (5, -1), (5, 5), (-1, 5)]).unwrap());
    assert_eq!(a.nowhere, Some(Nowhere::NoClass));
    // Vertices at half-integer offsets from each other are no map vertices.
    let half = RatPoint::from_i128(3, 2, 2).unwrap();
    let v = RobotView::new(vec![p(-1, -1), p(1, -1), half, p(-1, 1)]).unwrap();
    assert!(matches!(
        loc.localize(&v).nowhere,
        Some(Nowhere::NoSkeleton(NoSkeleton::OffGrid(_)))
    ));
}
