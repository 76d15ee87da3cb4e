//! `classify_segments`: one case per variant of `SegmentIntersection`, each
//! checked under swapping and reversing the segments and under translation,
//! 90° rotation, reflection and scaling (the last two push coordinates past
//! `2^62`, onto the GMP path).

use crate::common::{config, pt};
use proptest::prelude::*;
use wai_exact::{classify_segments, Point, Segment, SegmentIntersection as X};

type S = ((i128, i128), (i128, i128));
type PointMap = Box<dyn Fn(Point) -> Point>;

fn seg(s: S) -> Segment {
    Segment::new(pt(s.0 .0, s.0 .1), pt(s.1 .0, s.1 .1)).expect("distinct endpoints")
}

fn map_seg(s: &Segment, f: &impl Fn(Point) -> Point) -> Segment {
    Segment::new(f(s.a()), f(s.b())).expect("injective map")
}

fn map_result(r: X, f: &impl Fn(Point) -> Point) -> X {
    match r {
        X::None => X::None,
        X::Crossing => X::Crossing,
        X::Touching { at } => X::Touching { at: f(at) },
        X::Overlap { start, end } => X::Overlap {
            start: f(start),
            end: f(end),
        },
    }
}

/// The same answer with an overlap read in the other direction.
fn reversed(r: X) -> X {
    match r {
        X::Overlap { start, end } => X::Overlap {
            start: end,
            end: start,
        },
        r => r,
    }
}

/// `classify_segments(s, t) == expect`, and the answers it implies for the
/// swapped and reversed pairs and for the transformed inputs.
fn check(s: S, t: S, expect: X) {
    let (s, t) = (seg(s), seg(t));
    let rev = |x: &Segment| Segment::new(x.b(), x.a()).expect("distinct");
    assert_eq!(classify_segments(&s, &t), expect, "{s:?} {t:?}");
    assert_eq!(classify_segments(&s, &rev(&t)), expect, "t reversed");
    assert_eq!(
        classify_segments(&rev(&s), &t),
        reversed(expect),
        "s reversed"
    );
    // Swapped: the same set of common points, ordered along t.
    let swapped = classify_segments(&t, &s);
    let same_direction = {
        let (ds, dt) = (
            (s.b().x - s.a().x, s.b().y - s.a().y),
            (t.b().x - t.a().x, t.b().y - t.a().y),
        );
        ds.0 * dt.0 + ds.1 * dt.1 > 0
    };
    let want = if same_direction {
        expect
    } else {
        reversed(expect)
    };
    assert_eq!(swapped, want, "swapped");
    let big = 1i128 << 90;
    let maps: [(&str, PointMap); 5] = [
        (
            "translate",
            Box::new(move |p: Point| pt(p.x + big, p.y - big + 3)),
        ),
        ("rotate", Box::new(|p: Point| pt(-p.y, p.x))),
        ("reflect", Box::new(|p: Point| pt(p.x, -p.y))),
        ("scale", Box::new(|p: Point| pt(p.x << 70, p.y << 70))),
        (
            "near the bound",
            Box::new(|p: Point| pt(p.x + (1 << 62) - 8, p.y - (1 << 62) + 8)),
        ),
    ];
    for (name, f) in &maps {
        let got = classify_segments(&map_seg(&s, f), &map_seg(&t, f));
        assert_eq!(got, map_result(expect, f), "{name}: {s:?} {t:?}");
    }
}

#[test]
fn every_variant() {
    let touch = |x, y| X::Touching { at: pt(x, y) };
    let overlap = |a: (i128, i128), b: (i128, i128)| X::Overlap {
        start: pt(a.0, a.1),
        end: pt(b.0, b.1),
    };
    // Crossing: interiors meet in one point, integer or not.
    check(((0, 0), (4, 4)), ((0, 4), (4, 0)), X::Crossing);
    check(((0, 0), (3, 1)), ((1, 1), (2, 0)), X::Crossing);
    check(((0, 0), (1, 0)), ((0, -1), (1, 1)), X::Crossing);
    // Touching at a shared endpoint, not collinear.
    check(((0, 0), (4, 0)), ((0, 0), (0, 4)), touch(0, 0));
    check(((0, 0), (4, 0)), ((4, 0), (6, 3)), touch(4, 0));
    check(((0, 0), (4, 4)), ((4, 4), (0, 8)), touch(4, 4));
    // T-touch: an endpoint of one in the interior of the other.
    check(((0, 0), (4, 0)), ((2, 0), (2, 3)), touch(2, 0));
    check(((2, 0), (2, 3)), ((0, 0), (4, 0)), touch(2, 0));
    check(((0, 0), (6, 3)), ((2, 1), (0, 5)), touch(2, 1));
    // Collinear, meeting in one endpoint.
    check(((0, 0), (4, 0)), ((4, 0), (9, 0)), touch(4, 0));
    check(((0, 0), (4, 0)), ((9, 0), (4, 0)), touch(4, 0));
    check(((0, 0), (2, 2)), ((-3, -3), (0, 0)), touch(0, 0));
    // Collinear overlap, ordered along the first segment.
    check(((0, 0), (4, 0)), ((6, 0), (2, 0)), overlap((2, 0), (4, 0)));
    check(((4, 0), (0, 0)), ((2, 0), (6, 0)), overlap((4, 0), (2, 0)));
    check(((0, 0), (3, 3)), ((1, 1), (5, 5)), overlap((1, 1), (3, 3)));
    // Containment: one segment inside the other, with or without a shared end.
    check(((0, 0), (9, 0)), ((2, 0), (5, 0)), overlap((2, 0), (5, 0)));
    check(((2, 0), (5, 0)), ((0, 0), (9, 0)), overlap((2, 0), (5, 0)));
    check(((0, 0), (9, 0)), ((0, 0), (5, 0)), overlap((0, 0), (5, 0)));
    check(((0, 0), (9, 0)), ((5, 0), (9, 0)), overlap((5, 0), (9, 0)));
    check(((0, 0), (2, 6)), ((0, 0), (2, 6)), overlap((0, 0), (2, 6)));
    check(((0, 0), (2, 6)), ((2, 6), (0, 0)), overlap((0, 0), (2, 6)));
    // Disjoint collinear.
    check(((0, 0), (4, 0)), ((5, 0), (9, 0)), X::None);
    check(((0, 0), (1, 1)), ((3, 3), (2, 2)), X::None);
    // Disjoint parallel.
    check(((0, 0), (4, 0)), ((0, 1), (4, 1)), X::None);
    check(((0, 0), (4, 2)), ((1, 1), (5, 3)), X::None);
    // Disjoint, not parallel: the lines meet outside one or both segments,
    // or an endpoint lies on the other's line beyond it.
    check(((0, 0), (4, 0)), ((5, -1), (5, 1)), X::None);
    check(((0, 0), (4, 0)), ((2, 1), (2, 3)), X::None);
    check(((0, 0), (4, 0)), ((6, 0), (7, 5)), X::None);
    check(((0, 0), (1, 0)), ((3, 1), (2, 3)), X::None);
}

/// Large coordinates: the extremes of `MAX_COORD_BITS = 100`.
#[test]
fn at_the_coordinate_limit() {
    let m = (1i128 << 100) - 1;
    let s = Segment::new(pt(-m, -m), pt(m, m)).expect("distinct");
    let t = Segment::new(pt(-m, m), pt(m, -m)).expect("distinct");
    assert_eq!(classify_segments(&s, &t), X::Crossing);
    let u = Segment::new(pt(m - 1, m - 1), pt(m, m)).expect("distinct");
    assert_eq!(
        classify_segments(&s, &u),
        X::Overlap {
            start: pt(m - 1, m - 1),
            end: pt(m, m)
        }
    );
    let v = Segment::new(pt(m, m), pt(m, -m)).expect("distinct");
    assert_eq!(classify_segments(&s, &v), X::Touching { at: pt(m, m) });
    let w = Segment::new(pt(m, m - 1), pt(m - 1, m - 2)).expect("distinct");
    assert_eq!(classify_segments(&s, &w), X::None);
}

/// A naive classification by exhaustive search: the lattice points of both
/// segments on a fine grid decide `Touching`/`Overlap` for collinear or
/// endpoint contacts, and a crossing is a sign change on both sides.
fn naive(s: &Segment, t: &Segment) -> X {
    let on = |x: &Segment, p: Point| {
        let (a, b) = (x.a(), x.b());
        let cross = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
        cross == 0
            && a.x.min(b.x) <= p.x
            && p.x <= a.x.max(b.x)
            && a.y.min(b.y) <= p.y
            && p.y <= a.y.max(b.y)
    };
    // Common endpoints, ordered along s.
    let mut shared: Vec<Point> = [s.a(), s.b()]
        .into_iter()
        .filter(|&p| on(t, p))
        .chain([t.a(), t.b()].into_iter().filter(|&p| on(s, p)))
        .collect();
    let key =
        |p: &Point| (p.x - s.a().x) * (s.b().x - s.a().x) + (p.y - s.a().y) * (s.b().y - s.a().y);
    shared.sort_by_key(key);
    shared.dedup();
    match shared.as_slice() {
        [] => {}
        [p] => return X::Touching { at: *p },
        [p, .., q] => return X::Overlap { start: *p, end: *q },
    }
    let side = |x: &Segment, p: Point| {
        let (a, b) = (x.a(), x.b());
        ((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x)).signum()
    };
    let apart = |x: &Segment, y: &Segment| side(x, y.a()) * side(x, y.b()) < 0;
    if apart(s, t) && apart(t, s) {
        X::Crossing
    } else {
        X::None
    }
}

proptest! {
    #![proptest_config(config(4000))]

    /// Against the naive classification on a small grid, where collinear
    /// and touching configurations are frequent.
    #[test]
    fn agrees_with_naive_on_a_small_grid(c in prop::array::uniform8(-3i128..=3)) {
        let (Some(s), Some(t)) = (
            Segment::new(pt(c[0], c[1]), pt(c[2], c[3])),
            Segment::new(pt(c[4], c[5]), pt(c[6], c[7])),
        ) else { return Ok(()) };
        prop_assert_eq!(classify_segments(&s, &t), naive(&s, &t), "{:?} {:?}", s, t);
    }
}
