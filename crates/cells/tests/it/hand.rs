//! Hand-checked maps: every ray, end, side and grazed vertex derived on
//! paper (the derivations are in the comments).

use crate::common::{check_map, map, pt, rat};
use wai_cells::{group_by_line, visibility_rays, LineKey, OnMap, RaySide, VisibilityRay};
use wai_exact::{Line, Point, RatPoint};
use wai_map::Map;

use RaySide::{Left as L, Right as R};

/// An expected ray: anchor, from, side, end, grazed vertices.
struct Ray(usize, usize, RaySide, End, &'static [usize]);

/// An expected end: at a vertex, or on edge `i` at `(x / w, y / w)`.
enum End {
    V(usize),
    E(usize, i64, i64, i64),
}

fn matches(map: &Map, got: &VisibilityRay, want: &Ray) -> bool {
    let Ray(anchor, from, side, end, grazed) = want;
    let (on_map, point) = match *end {
        End::V(i) => (OnMap::Vertex(i), RatPoint::from(map.vertices()[i])),
        End::E(i, x, y, w) => (OnMap::Edge(i), rat(x, y, w)),
    };
    (got.anchor, got.from, got.side) == (*anchor, *from, *side)
        && got.end.on_map == on_map
        && got.end.point == point
        && got.grazed == *grazed
}

/// Check the laws on `map`, that each expected ray is computed exactly as
/// given and, if `all`, that there are no others.
fn check(map: &Map, expect: &[Ray], all: bool) -> Vec<VisibilityRay> {
    check_map(map);
    let rays = visibility_rays(map);
    for want in expect {
        let got = rays.iter().find(|r| (r.anchor, r.from) == (want.0, want.1));
        let got = got.unwrap_or_else(|| panic!("no ray from {} anchored at {}", want.1, want.0));
        assert!(
            matches(map, got, want),
            "ray from {} anchored at {}: got {got:?}",
            want.1,
            want.0
        );
    }
    if all {
        assert_eq!(rays.len(), expect.len(), "{rays:#?}");
    }
    rays
}

/// The L room: reflex vertex 3 = (2, 2), neighbours 2 = (4, 2) and 4 = (2, 4);
/// exterior cone at 3 is the quadrant x ≥ 2, y ≥ 2.
/// - from 0 = (0, 0): visible, direction (1, 1) is in the exterior cone: none (a);
/// - from 1 = (4, 0): visible, direction (−1, 1) reaches the corner (0, 4)
///   = vertex 5, whose edges lie on both sides: ends there (d); the
///   neighbours (4, 2), (2, 4) lie to the right;
/// - from 2 (adjacent): west along y = 2 to (0, 2) on edge 5; (2, 4) right;
/// - from 4 (adjacent): south along x = 2 to (2, 0) on edge 0; (4, 2) left;
/// - from 5 = (0, 4): visible, direction (1, −1) reaches the corner (4, 0)
///   = vertex 1 (d); neighbours left.
#[test]
fn l_room() {
    let m = map(&[(0, 0), (4, 0), (4, 2), (2, 2), (2, 4), (0, 4)]);
    check(
        &m,
        &[
            Ray(3, 1, R, End::V(5), &[]),
            Ray(3, 2, R, End::E(5, 0, 2, 1), &[]),
            Ray(3, 4, L, End::E(0, 2, 0, 1), &[]),
            Ray(3, 5, L, End::V(1), &[]),
        ],
        true,
    );
}

/// `corridor-niches` with k = 1, derived by hand: ring (0, 0), (4, 0),
/// (4, −4), (6, −4), (6, 0), (10, 0), (10, 4), (0, 4); reflex 1 = (4, 0) and
/// 4 = (6, 0), exterior cones the third and fourth quadrants at them.
///
/// Anchor 1: from 0 (adjacent) east along the niche's mouth to (6, 0),
/// where the wall y = 0 resumes (edge 4–5 on the line): ends at vertex 4
/// (b); from 2 (adjacent) north to (4, 4) on edge 6; from 3 = (6, −4),
/// visible through the niche, direction (−2, 4) to (2, 4) on edge 6; from
/// 7 = (0, 4), direction (1, −1) into the niche to (6, −2) on edge 3. From 4:
/// visible along the mouth, but westwards the line runs along edge 0, on
/// the boundary of the exterior cone: none (a). From 5: blocked by vertex
/// 4. From 6 = (10, 4): visible, direction (−6, −4) in the exterior cone:
/// none (a). Anchor 4 mirrors anchor 1 in x = 5 (vertices 0↔5, 1↔4, 2↔3,
/// 6↔7, edge 3↔1, sides swapped). So 8 rays.
#[test]
fn corridor_niches_k1() {
    let m = wai_gen::family("corridor-niches", &[1]).unwrap();
    let expected: Vec<(i128, i128)> = vec![
        (0, 0),
        (4, 0),
        (4, -4),
        (6, -4),
        (6, 0),
        (10, 0),
        (10, 4),
        (0, 4),
    ];
    assert_eq!(
        m.vertices(),
        expected
            .iter()
            .map(|&(x, y)| Point::new(x, y))
            .collect::<Vec<_>>()
    );
    check(
        &m,
        &[
            Ray(1, 0, R, End::V(4), &[]),
            Ray(1, 2, L, End::E(6, 4, 4, 1), &[]),
            Ray(1, 3, L, End::E(6, 2, 4, 1), &[]),
            Ray(1, 7, R, End::E(3, 6, -2, 1), &[]),
            Ray(4, 5, L, End::V(1), &[]),
            Ray(4, 3, R, End::E(6, 6, 4, 1), &[]),
            Ray(4, 2, R, End::E(6, 8, 4, 1), &[]),
            Ray(4, 6, L, End::E(1, 4, -2, 1), &[]),
        ],
        true,
    );
}

/// Three 1-wide blocks hang from the ceiling of a 12 × 12 room; their
/// lower-left corners 13 = (2, 6), 9 = (4, 4), 5 = (6, 2) are reflex and lie
/// on x + y = 8, where each corner's two edges (up and east) lie on one
/// side: rays on that line graze them (b) and overlap (c).
fn blocks() -> Map {
    map(&[
        (0, 0),
        (12, 0),
        (12, 12),
        (7, 12),
        (7, 2),
        (6, 2),
        (6, 12),
        (5, 12),
        (5, 4),
        (4, 4),
        (4, 12),
        (3, 12),
        (3, 6),
        (2, 6),
        (2, 12),
        (0, 12),
    ])
}

/// On x + y = 8: from 5 anchored at 9 north-west through the grazed corner
/// 13 to (0, 8) on the west wall (edge 15); from 13 anchored at 9
/// south-east through the grazed corner 5 to (8, 0) on the floor (edge 0);
/// from 9 anchored at 5 to (8, 0); from 9 anchored at 13 to (0, 8). From 13
/// anchored at 5 and from 5 anchored at 13 there is none: 9 blocks the
/// view. The corners' edges point up and east: right of the north-west
/// direction, left of the south-east one.
#[test]
fn grazing_and_collinear_rays() {
    let m = blocks();
    let rays = check(
        &m,
        &[
            Ray(9, 5, R, End::E(15, 0, 8, 1), &[13]),
            Ray(9, 13, L, End::E(0, 8, 0, 1), &[5]),
            Ray(5, 9, L, End::E(0, 8, 0, 1), &[]),
            Ray(13, 9, R, End::E(15, 0, 8, 1), &[]),
        ],
        false,
    );
    assert!(!rays
        .iter()
        .any(|r| (r.anchor, r.from) == (5, 13) || (r.anchor, r.from) == (13, 5)));
    // (c) The helper groups exactly these four on x + y = 8.
    let groups = group_by_line(&rays);
    let diag = LineKey::of(&Line::new(Point::new(0, 8), Point::new(8, 0)).unwrap());
    assert_eq!((diag.a(), diag.b(), diag.c().to_i32()), (1, 1, Some(8)));
    let on_diag: Vec<(usize, usize)> = groups[&diag]
        .iter()
        .map(|&i| (rays[i].anchor, rays[i].from))
        .collect();
    assert_eq!(on_diag, vec![(5, 9), (9, 5), (9, 13), (13, 9)]);
    // Every ray is in exactly the group of its line.
    let total: usize = groups.values().map(Vec::len).sum();
    assert_eq!(total, rays.len());
    for (k, members) in &groups {
        for &i in members {
            assert!(k.contains(rays[i].source()) && k.contains(rays[i].start()));
        }
    }
}

/// Line keys are canonical: independent of the two points and direction.
#[test]
fn line_key_is_canonical() {
    let l = |a: (i128, i128), b: (i128, i128)| {
        LineKey::of(&Line::new(Point::new(a.0, a.1), Point::new(b.0, b.1)).unwrap())
    };
    assert_eq!(l((0, 8), (8, 0)), l((6, 2), (2, 6)));
    assert_eq!(l((0, 8), (8, 0)), l((3, 5), (-4, 12)));
    assert_ne!(l((0, 8), (8, 0)), l((0, 9), (9, 0)));
    let k = l((4, 6), (4, -1));
    assert_eq!((k.a(), k.b(), k.c().to_i32()), (1, 0, Some(4)));
    let k = l((7, 3), (-2, 3));
    assert_eq!((k.a(), k.b(), k.c().to_i32()), (0, 1, Some(3)));
}

/// Two 4 × 4 rooms joined through a door [4, 5] × [1, 2] in a wall of
/// thickness 1: collinear walls (y = 0 and y = 4 on both sides), door
/// jambs on common lines, and rays that pass through the door with
/// rational ends.
///
/// Vertices: 0 (0, 0), 1 (4, 0), 2 (4, 1), 3 (5, 1), 4 (5, 0), 5 (9, 0),
/// 6 (9, 4), 7 (5, 4), 8 (5, 2), 9 (4, 2), 10 (4, 4), 11 (0, 4); the door
/// corners 2, 3, 8, 9 are reflex.
/// - from 0 anchored at 2: slope 1/4 through the door ((5, 5/4)) to
///   (9, 9/4) on the east wall, edge 5; the anchor's edges (south, east)
///   lie right of the direction (4, 1);
/// - from 1 anchored at 2 (adjacent): north along the jamb x = 4 to
///   (4, 2), vertex 9, where the wall x = 4 resumes (b);
/// - from 3 anchored at 2 (adjacent): west along y = 1 to (0, 1), edge 11;
/// - from 2 anchored at 8: the door's diagonal (1, 1) from (5, 2) to
///   (7, 4) on the ceiling, edge 6; from 8 anchored at 2: back from (4, 1)
///   to (3, 0) on the floor, edge 0;
/// - from 11 anchored at 9: slope −1/2 from (4, 2) through the door to
///   (8, 0) on the floor of the east room, edge 4;
/// - from 10 anchored at 9 (adjacent): south along x = 4 to vertex 2 (b);
/// - from 5 anchored at 3: slope −1/4 through the door to (0, 9/4), edge 11.
#[test]
fn office_with_door() {
    let m = map(&[
        (0, 0),
        (4, 0),
        (4, 1),
        (5, 1),
        (5, 0),
        (9, 0),
        (9, 4),
        (5, 4),
        (5, 2),
        (4, 2),
        (4, 4),
        (0, 4),
    ]);
    assert_eq!(m.reflex_vertices(), &[2, 3, 8, 9]);
    check(
        &m,
        &[
            Ray(2, 0, R, End::E(5, 36, 9, 4), &[]),
            Ray(2, 1, R, End::V(9), &[]),
            Ray(2, 3, L, End::E(11, 0, 1, 1), &[]),
            Ray(8, 2, L, End::E(6, 7, 4, 1), &[]),
            Ray(2, 8, L, End::E(0, 3, 0, 1), &[]),
            Ray(9, 11, L, End::E(4, 8, 0, 1), &[]),
            Ray(9, 10, L, End::V(2), &[]),
            Ray(3, 5, L, End::E(11, 0, 9, 4), &[]),
        ],
        false,
    );
}

/// A ray through several grazed vertices: four blocks hanging from the
/// ceiling with lower-left corners on x + y = 10.
#[test]
fn ray_through_several_vertices() {
    // Corners (2, 8), (4, 6), (6, 4), (8, 2); blocks 1 wide reaching y = 14.
    let mut ring = vec![(0, 0), (14, 0), (14, 14)];
    for &(x, y) in &[(8, 2), (6, 4), (4, 6), (2, 8)] {
        ring.extend([(x + 1, 14), (x + 1, y), (x, y), (x, 14)]);
    }
    ring.push((0, 14));
    let m = map(&ring);
    let idx = |p: (i128, i128)| {
        m.vertices()
            .iter()
            .position(|&q| q == Point::new(p.0, p.1))
            .unwrap()
    };
    let (c1, c2, c3, c4) = (idx((2, 8)), idx((4, 6)), idx((6, 4)), idx((8, 2)));
    let rays = visibility_rays(&m);
    check_map(&m);
    // From (2, 8) anchored at (4, 6): grazes (6, 4) and (8, 2), ends on the
    // floor at (10, 0), edge 0.
    let r = rays
        .iter()
        .find(|r| (r.anchor, r.from) == (c2, c1))
        .unwrap();
    assert_eq!(r.grazed, vec![c3, c4]);
    assert_eq!((r.end.on_map, &r.end.point), (OnMap::Edge(0), &pt(10, 0)));
    // From (8, 2) anchored at (6, 4): grazes (4, 6), (2, 8); ends at (0, 10)
    // on the west wall, the last edge.
    let r = rays
        .iter()
        .find(|r| (r.anchor, r.from) == (c3, c4))
        .unwrap();
    assert_eq!(r.grazed, vec![c2, c1]);
    assert_eq!(
        (r.end.on_map, &r.end.point),
        (OnMap::Edge(m.n() - 1), &pt(0, 10))
    );
}

/// A ray whose end is exactly a convex map vertex, in a non-orthogonal
/// map: vertices 0 (0, 0), 1 (8, 0), 2 (4, 2), 3 (12, 3), 4 (10, 5),
/// 5 (0, 5); 2 is reflex. The ray from 0 anchored at 2 follows y = x / 2
/// and ends at the corner 4 = (10, 5), whose neighbours (12, 3) and (0, 5)
/// lie on opposite sides (d); the anchor's neighbours lie to the right.
#[test]
fn ray_ends_at_a_convex_vertex() {
    let m = map(&[(0, 0), (8, 0), (4, 2), (12, 3), (10, 5), (0, 5)]);
    assert_eq!(m.reflex_vertices(), &[2]);
    check(&m, &[Ray(2, 0, R, End::V(4), &[])], false);
}
