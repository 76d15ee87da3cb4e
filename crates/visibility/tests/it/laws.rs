//! Laws of V_p and V*_p on generated maps with degenerate viewpoints.

use crate::common::viewpoints;
use rug::Integer;
use wai_exact::{orientation_rat, sees, Orientation, Point, RatPoint, Sight};
use wai_map::Map;
use wai_visibility::reference::visibility_polygon;
use wai_visibility::{reconstruct, EdgeKind, OnMap, Skeleton, VisibilityPolygon};

/// Maps of every generator kind at small sizes, and the thesis families.
pub fn test_maps() -> Vec<Map> {
    let mut maps = Vec::new();
    for kind in wai_gen::RANDOM_KINDS {
        for seed in 0..4 {
            let n = kind.min_n.max(8) + 2 * seed as usize;
            maps.push(wai_gen::random(kind.id, n, seed).unwrap());
        }
    }
    for f in wai_gen::FAMILIES {
        maps.push(wai_gen::family(f.id, &[2]).unwrap());
    }
    maps.extend(wai_gen::exhaustive_polyomino_maps(
        5,
        wai_gen::Symmetry::Free,
    ));
    maps
}

fn translate(p: &RatPoint, dx: i128, dy: i128) -> RatPoint {
    RatPoint::new(
        Integer::from(p.hw() * dx) + p.hx(),
        Integer::from(p.hw() * dy) + p.hy(),
        p.hw().clone(),
    )
    .unwrap()
}

/// Every law of one V_p.
fn check_laws(map: &Map, p: &RatPoint, vp: &VisibilityPolygon) {
    let n = vp.len();
    let v = vp.vertices();
    assert!(n >= 3);
    for i in 0..n {
        let (a, b, c) = (&v[i].point, &v[(i + 1) % n].point, &v[(i + 2) % n].point);
        // Star-shaped from p: p is left of or on every edge; on exactly for spurious ones.
        let o = orientation_rat(a, b, p);
        let spurious = vp.edges()[i].kind == EdgeKind::Spurious;
        assert_eq!(
            o == Orientation::Collinear,
            spurious,
            "edge {i} of V_p at {p}"
        );
        assert!(o != Orientation::Clockwise, "p right of edge {i}");
        // No 180° vertex.
        assert_ne!(
            orientation_rat(a, b, c),
            Orientation::Collinear,
            "straight vertex {}",
            (i + 1) % n
        );
        // Vertices lie where they say, and non-spurious edges on their map edge.
        match v[i].on_map {
            OnMap::Vertex(k) => assert_eq!(*a, RatPoint::from(map.vertices()[k])),
            OnMap::Edge(k) => {
                let l = map.edge(k).line();
                assert_eq!(wai_exact::side_of_line_rat(&l, a), wai_exact::Side::On);
            }
        }
        if let Some(k) = vp.edges()[i].map_edge {
            let l = map.edge(k).line();
            for q in [a, b] {
                assert_eq!(wai_exact::side_of_line_rat(&l, q), wai_exact::Side::On);
            }
            // The midpoint of a non-spurious edge is visible (it is on the map boundary).
            assert_eq!(
                sees(map.vertices(), p, &RatPoint::midpoint(a, b)),
                Sight::Visible,
                "edge {i}"
            );
        }
    }
    // Non-spurious map-vertex vertices are exactly the visible map vertices.
    let mut shown: Vec<usize> = v
        .iter()
        .filter(|x| !x.spurious)
        .filter_map(|x| match x.on_map {
            OnMap::Vertex(k) => Some(k),
            OnMap::Edge(_) => None,
        })
        .collect();
    shown.sort_unstable();
    let visible: Vec<usize> = (0..map.n())
        .filter(|&k| sees(map.vertices(), p, &map.vertices()[k].into()).is_visible())
        .collect();
    assert_eq!(shown, visible, "viewpoint {p}");
}

#[test]
fn laws_hold_on_generated_maps_and_degenerate_viewpoints() {
    let mut examined = 0;
    for map in test_maps() {
        for p in viewpoints(&map, 12) {
            let vp = visibility_polygon(&map, &p).unwrap();
            check_laws(&map, &p, &vp);
            // The skeleton: p lies in its kernel (Lemma 3.4), and V_p is
            // rebuilt exactly from the key and p relative to v0 (Thm 3.2).
            let sk = Skeleton::of(&map, &vp).unwrap();
            assert_ne!(
                sk.kernel().locate(&p),
                wai_exact::Containment::Outside,
                "{p}"
            );
            let o = sk.origin();
            let rebuilt = reconstruct(&sk.key(), &translate(&p, -o.x, -o.y));
            let start = vp
                .points()
                .iter()
                .position(|q| *q == RatPoint::from(o))
                .unwrap();
            let mut expect: Vec<RatPoint> = vp
                .points()
                .iter()
                .map(|q| translate(q, -o.x, -o.y))
                .collect();
            expect.rotate_left(start);
            assert_eq!(rebuilt, expect, "viewpoint {p}");
            examined += 1;
        }
    }
    assert!(examined > 500, "only {examined} viewpoints");
}

/// An integer affine map of the plane.
type Transform = fn(Point) -> Point;

/// V_p and V*_p move with the map: translation, 90° rotation, reflection and
/// a cyclic shift of the vertex list give the transformed polygon and an
/// equal skeleton key (translation) or the transformed skeleton.
#[test]
fn invariant_under_translation_rotation_reflection_and_shift() {
    let transforms: [(&str, Transform); 3] = [
        ("translate", |p| Point::new(p.x + 1000, p.y - 77)),
        ("rotate", |p| Point::new(-p.y, p.x)),
        ("reflect", |p| Point::new(-p.x, p.y)),
    ];
    let rat_map = |f: fn(Point) -> Point, q: &RatPoint| {
        // Apply an integer affine map to a rational point via its homogeneous form.
        let w = q.hw().clone();
        let img = |x: &Integer, y: &Integer| {
            let o = f(Point::new(0, 0));
            let ex = f(Point::new(1, 0));
            let ey = f(Point::new(0, 1));
            let lin = |ax: i128, ay: i128, ox: i128| {
                Integer::from(x * (ax - ox)) + Integer::from(y * ay) + Integer::from(&w * ox)
            };
            (lin(ex.x, ey.x - o.x, o.x), lin(ex.y, ey.y - o.y, o.y))
        };
        let (x, y) = img(q.hx(), q.hy());
        RatPoint::new(x, y, w).unwrap()
    };
    let mut examined = 0;
    for map in test_maps().into_iter().step_by(3) {
        let views = viewpoints(&map, 5);
        for (name, f) in transforms {
            let ring: Vec<Point> = map.vertices().iter().map(|&p| f(p)).collect();
            let (tmap, _) = Map::from_ring(ring).unwrap();
            for p in &views {
                let a = visibility_polygon(&map, p).unwrap();
                let b = visibility_polygon(&tmap, &rat_map(f, p)).unwrap();
                let mut want: Vec<RatPoint> = a.points().iter().map(|q| rat_map(f, q)).collect();
                let got = b.points();
                // Same cyclic sequence (a reflection also reverses it, and
                // normalisation may start the ring elsewhere).
                if name == "reflect" {
                    want.reverse();
                }
                let k = got
                    .iter()
                    .position(|q| *q == want[0])
                    .expect("same vertices");
                let mut rotated = got.clone();
                rotated.rotate_left(k);
                assert_eq!(rotated, want, "{name} at {p}");
                let kinds = |vp: &VisibilityPolygon| {
                    let mut v: Vec<EdgeKind> = vp.edges().iter().map(|e| e.kind).collect();
                    v.sort_by_key(|k| *k as u8);
                    v
                };
                assert_eq!(kinds(&a), kinds(&b), "{name}");
                if name == "translate" {
                    let (sa, sb) = (
                        Skeleton::of(&map, &a).unwrap(),
                        Skeleton::of(&tmap, &b).unwrap(),
                    );
                    assert_eq!(sa.key(), sb.key(), "skeletons are translation invariant");
                }
                examined += 1;
            }
        }
        // Cyclic shift of the input ring: identical V_p.
        let mut ring = map.vertices().to_vec();
        ring.rotate_left(1);
        let (smap, _) = Map::from_ring(ring).unwrap();
        for p in &views {
            let (a, b) = (
                visibility_polygon(&map, p).unwrap(),
                visibility_polygon(&smap, p).unwrap(),
            );
            assert_eq!(a.points(), b.points());
            assert_eq!(
                Skeleton::of(&map, &a).unwrap().key(),
                Skeleton::of(&smap, &b).unwrap().key()
            );
        }
    }
    assert!(examined > 100, "only {examined}");
}
