//! The production algorithm (triangular expansion) against the reference,
//! on degenerate maps and viewpoints; and the triangulation's sanity.

use crate::common::viewpoints;
use crate::laws::test_maps;
use wai_visibility::reference::visibility_polygon;
use wai_visibility::{Triangulation, VisibilityIndex};

#[test]
fn triangulations_are_sane() {
    let mut maps = test_maps();
    for kind in [
        "random-orthogonal",
        "special-orthogonal",
        "special-comb",
        "special-chamfer",
        "random-simple-star",
    ] {
        for seed in 0..40 {
            maps.push(wai_gen::random(kind, 30 + seed as usize, seed).unwrap());
        }
    }
    for map in &maps {
        Triangulation::new(map)
            .sanity_check(map)
            .unwrap_or_else(|e| panic!("{e}: {:?}", map.vertices()));
    }
}

#[test]
fn expansion_equals_reference() {
    let mut examined = 0;
    for map in test_maps() {
        let index = VisibilityIndex::new(&map);
        for p in viewpoints(&map, 12) {
            let want = visibility_polygon(&map, &p).unwrap();
            let got = index.visibility_polygon(&p).unwrap();
            assert_eq!(got, want, "viewpoint {p} in {:?}", map.vertices());
            examined += 1;
        }
    }
    assert!(examined > 500, "only {examined}");
}

#[test]
fn expansion_reports_boundary_and_outside() {
    let map = crate::common::map(&[(0, 0), (4, 0), (4, 2), (2, 2), (2, 4), (0, 4)]);
    let index = VisibilityIndex::new(&map);
    for (q, boundary) in [
        ((4, 1), true),
        ((2, 2), true),
        ((0, 3), true),
        ((3, 3), false),
        ((9, 9), false),
    ] {
        let e = index
            .visibility_polygon(&crate::common::pt(q.0, q.1))
            .unwrap_err();
        let is_boundary = matches!(e, wai_visibility::VisibilityError::OnBoundary(_));
        assert_eq!(is_boundary, boundary, "{q:?}: {e}");
    }
}

/// `vertex_view(x)` names exactly the vertices x sees (`sees`: the closed
/// segment meets the boundary only at its ends), in counter-clockwise
/// order from x + 1, on orthogonal maps (collinear vertices everywhere)
/// and random simple ones; every sector names a map edge.
#[test]
fn vertex_view_lists_what_a_vertex_sees() {
    use wai_exact::{sees, Point, RatPoint, Sight};
    let mut checked = 0;
    for kind in [
        "random-orthogonal",
        "random-simple-star",
        "random-simple-2opt",
    ] {
        for seed in 0..6u64 {
            let Ok(map) = wai_gen::random(kind, 30, seed) else {
                continue;
            };
            let index = wai_visibility::VisibilityIndex::new(&map);
            let v = map.vertices();
            let n = map.n();
            for x in 0..n {
                let view = index.vertex_view(x);
                let mut seen: Vec<usize> = view.iter().map(|&(lo, _)| lo).collect();
                assert_eq!(seen[0], (x + 1) % n, "map {kind}/{seed}, vertex {x}");
                assert!(view.iter().all(|&(_, e)| e < n));
                seen.push((x + n - 1) % n);
                seen.dedup();
                let at = |p: Point| RatPoint::from(p);
                let mut expected: Vec<usize> = (0..n)
                    .filter(|&j| {
                        j != x
                            && (j == (x + 1) % n
                                || j == (x + n - 1) % n
                                || sees(v, &at(v[x]), &at(v[j])) == Sight::Visible)
                    })
                    .collect();
                let mut got = seen.clone();
                got.sort_unstable();
                got.dedup();
                expected.sort_unstable();
                assert_eq!(got, expected, "map {kind}/{seed}, vertex {x}");
                assert_eq!(got.len(), seen.len(), "each seen vertex starts one sector");
                checked += 1;
            }
        }
    }
    assert!(checked > 300, "{checked}");
}
