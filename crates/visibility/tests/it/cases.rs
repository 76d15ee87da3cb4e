//! Hand-checked visibility polygons and skeletons.

use crate::common::{map, pt, rat};
use wai_exact::Point;
use wai_visibility::reference::visibility_polygon;
use wai_visibility::{reconstruct, EdgeKind, OnMap, Skeleton, VisibilityError};

#[test]
fn l_shape_around_the_corner() {
    // p = (1, 3) in the upper arm; the ray through the reflex vertex (2, 2)
    // reaches the map vertex (4, 0) exactly.
    let m = map(&[(0, 0), (4, 0), (4, 2), (2, 2), (2, 4), (0, 4)]);
    let vp = visibility_polygon(&m, &pt(1, 3)).unwrap();
    assert_eq!(
        vp.points(),
        vec![pt(0, 0), pt(4, 0), pt(2, 2), pt(2, 4), pt(0, 4)]
    );
    let kinds: Vec<EdgeKind> = vp.edges().iter().map(|e| e.kind).collect();
    use EdgeKind::*;
    assert_eq!(kinds, vec![Half, Spurious, Full, Full, Full]);
    // (4, 0) is a map vertex, yet spurious: the far end of a spurious edge.
    assert!(vp.vertices()[1].spurious);
    assert_eq!(vp.vertices()[1].on_map, OnMap::Vertex(1));
    assert_eq!(vp.edges()[0].blocking, vec![2]);
    let sk = Skeleton::of(&m, &vp).unwrap();
    assert_eq!(sk.origin(), Point::new(2, 2));
    assert_eq!(
        sk.vertices(),
        &[
            Point::new(2, 2),
            Point::new(2, 4),
            Point::new(0, 4),
            Point::new(0, 0)
        ]
    );
    assert_eq!(sk.artificial_count(), 1);
    let key = sk.key();
    assert_eq!(key.offsets, vec![(0, 0), (0, 2), (-2, 2), (-2, -2)]);
    let label = key.labels[3].as_ref().unwrap();
    assert_eq!(
        (label.a.to_i32(), label.b.to_i32(), label.c.to_i32()),
        (Some(0), Some(1), Some(-2))
    );
    // Thm 3.2: rebuild V_p from the key and p relative to v0 = (2, 2).
    let rebuilt = reconstruct(&key, &pt(-1, 1));
    assert_eq!(
        rebuilt,
        vec![pt(0, 0), pt(0, 2), pt(-2, 2), pt(-2, -2), pt(2, -2)]
    );
}

#[test]
fn partial_edge_through_a_doorway() {
    // A room with a door in its north wall leading to a corridor.
    // Room: (0,0)-(6,0)-(6,4)-(4,4) door (4,4)-(2,4)... corridor above.
    let m = map(&[
        (0, 0),
        (6, 0),
        (6, 4),
        (4, 4),
        (4, 5),
        (10, 5),
        (10, 8),
        (-4, 8),
        (-4, 5),
        (2, 5),
        (2, 4),
        (0, 4),
    ]);
    let p = rat(3, 1, 1);
    let vp = visibility_polygon(&m, &p).unwrap();
    // Through the door p sees a piece of the corridor's north wall y = 8.
    let partial: Vec<usize> = (0..vp.len())
        .filter(|&i| vp.edges()[i].kind == EdgeKind::Partial)
        .collect();
    assert_eq!(partial.len(), 1, "{vp:#?}");
    let e = &vp.edges()[partial[0]];
    assert_eq!(e.map_edge, Some(6)); // (10, 8) -> (-4, 8)
    assert_eq!(e.blocking.len(), 2);
    // The partial edge runs from ray(p,(4,5)) to ray(p,(2,5)) on y = 8:
    // x = 3 + (8-1)/(5-1) * (±1) = 3 ± 7/4.
    let i = partial[0];
    assert_eq!(vp.vertices()[i].point, rat(19, 32, 4));
    assert_eq!(vp.vertices()[(i + 1) % vp.len()].point, rat(5, 32, 4));
    let sk = Skeleton::of(&m, &vp).unwrap();
    assert!(sk.kernel().locate(&p) != wai_exact::Containment::Outside);
}

#[test]
fn viewpoint_must_be_interior() {
    let m = map(&[(0, 0), (4, 0), (4, 4), (0, 4)]);
    assert!(matches!(
        visibility_polygon(&m, &pt(4, 1)),
        Err(VisibilityError::OnBoundary(_))
    ));
    assert!(matches!(
        visibility_polygon(&m, &pt(5, 1)),
        Err(VisibilityError::Outside(_))
    ));
}

#[test]
fn comb_collinear_with_edges() {
    // A comb whose teeth backs are collinear, viewed from a point on the
    // line of the teeth's side walls (collinear with map edges).
    let m = map(&[
        (0, 0),
        (9, 0),
        (9, 3),
        (8, 3),
        (8, 1),
        (7, 1),
        (7, 3),
        (5, 3),
        (5, 1),
        (4, 1),
        (4, 3),
        (2, 3),
        (2, 1),
        (1, 1),
        (1, 3),
        (0, 3),
    ]);
    // x = 4 is the line of the edge (4,1)-(4,3); p lies on it below.
    let p = rat(8, 1, 2);
    let vp = visibility_polygon(&m, &p).unwrap();
    for (i, e) in vp.edges().iter().enumerate() {
        if e.kind == EdgeKind::Spurious {
            // A spurious edge along the map edge x = 4 (the case after Def 3.4).
            let (a, b) = (
                &vp.vertices()[i].point,
                &vp.vertices()[(i + 1) % vp.len()].point,
            );
            if a.to_point().is_some_and(|q| q.x == 4) && b.to_point().is_some_and(|q| q.x == 4) {
                return;
            }
        }
    }
    panic!("expected a spurious edge along x = 4: {vp:#?}");
}
