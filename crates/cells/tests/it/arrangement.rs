//! The arrangement of map edges and visibility rays: hand-checked counts,
//! the boundary assignment of sec. 3.6 on hand-derived maps, sanity checks
//! on generated maps, planted violations, and a T3.3b spot check.

use crate::common::{map, pt};
use rug::Integer;
use wai_cells::{visibility_rays, Arrangement, Conflict, FaceId, Support};
use wai_exact::RatPoint;
use wai_map::Map;
use wai_visibility::{Skeleton, VisibilityIndex};

fn build(m: &Map) -> Arrangement {
    let arr = Arrangement::new(m, &visibility_rays(m));
    if let Err(e) = arr.sanity_check() {
        panic!("{}: {e}", m.name().unwrap_or("unnamed"));
    }
    arr
}

/// Check (vertices, edges, faces including the outer one).
fn check(m: &Map, expect: (usize, usize, usize)) -> Arrangement {
    let arr = build(m);
    assert_eq!(
        (arr.vertex_count(), arr.edge_count(), arr.face_count()),
        expect
    );
    arr
}

fn vertex_at(arr: &Arrangement, p: &RatPoint) -> usize {
    (0..arr.vertex_count())
        .find(|&v| arr.point(v) == p)
        .unwrap_or_else(|| panic!("no vertex at {p}"))
}

fn edge_between(arr: &Arrangement, p: &RatPoint, q: &RatPoint) -> usize {
    let (a, b) = (vertex_at(arr, p), vertex_at(arr, q));
    (0..arr.edge_count())
        .find(|&e| {
            let (x, y) = (arr.half_edge(2 * e).origin, arr.dest(2 * e));
            (x, y) == (a, b) || (x, y) == (b, a)
        })
        .unwrap_or_else(|| panic!("no edge {p} – {q}"))
}

/// The cell whose vertex set is exactly `pts`.
fn cell_with(arr: &Arrangement, pts: &[RatPoint]) -> FaceId {
    let mut want: Vec<usize> = pts.iter().map(|p| vertex_at(arr, p)).collect();
    want.sort_unstable();
    arr.cells()
        .find(|&f| {
            let mut vs = arr.face_vertices(f);
            vs.sort_unstable();
            vs == want
        })
        .unwrap_or_else(|| panic!("no cell {pts:?}"))
}

/// The L room (see `hand::l_room`): 4 rays from the corner (2, 2), all
/// meeting only there; the two diagonal rays (from 1 and from 5) lie on
/// x + y = 4 in opposite directions: one group. Vertices: 6 map vertices,
/// the ends (0, 2) and (2, 0): 8. Edges: map edges 0 and 5 split once
/// (8 pieces) plus 4 rays: 12. Euler: F = 2 − 8 + 12 = 6, i.e. 5 cells.
#[test]
fn l_room() {
    let m = map(&[(0, 0), (4, 0), (4, 2), (2, 2), (2, 4), (0, 4)]);
    let arr = check(&m, (8, 12, 6));
    assert_eq!(arr.ray_groups().len(), 3);
    assert!(arr.conflicts().is_empty());
    // The ray from 4 (south along x = 2, side left = east) gives its
    // points to the cell (2, 0), (4, 0), (2, 2).
    let e = edge_between(&arr, &pt(2, 2), &pt(2, 0));
    let east = cell_with(&arr, &[pt(2, 0), pt(4, 0), pt(2, 2)]);
    assert_eq!(arr.owner_of_edge(e), east);
    // The ray from 2 (west along y = 2, side right = north).
    let e = edge_between(&arr, &pt(2, 2), &pt(0, 2));
    let north = cell_with(&arr, &[pt(0, 2), pt(2, 2), pt(0, 4)]);
    assert_eq!(arr.owner_of_edge(e), north);
    // Map edges belong to their one cell.
    let e = edge_between(&arr, &pt(4, 0), &pt(4, 2));
    assert_eq!(
        arr.owner_of_edge(e),
        cell_with(&arr, &[pt(4, 0), pt(4, 2), pt(2, 2)])
    );
    // Every vertex has an owner among its cells.
    for v in 0..arr.vertex_count() {
        let f = arr.owner_of_vertex(v).expect("no conflict");
        assert!(arr.face_vertices(f).contains(&v));
    }
}

/// `corridor-niches` k = 1 (rays derived in `hand::corridor_niches_k1`).
/// The mouth (4, 0)–(6, 0) carries two rays in opposite directions (from 0
/// anchored at 1, east, right; from 5 anchored at 4, west, left): both give
/// it to the niche: one edge, no conflict. The niche's diagonals x + y = 4
/// (from 7 anchored at 1, to (6, −2)) and x − y = 6 (from 6 anchored at 4,
/// to (4, −2)) cross at (5, −1); nothing else crosses away from the
/// anchors (x = 4 and x = 6 are parallel, the other two diverge upwards).
/// Vertices: 8 + the ends (4, 4), (2, 4), (6, 4), (8, 4), (6, −2),
/// (4, −2) + (5, −1) = 15. Edges: map pieces 1 + 2 + 1 + 2 + 1 + 1 + 5 + 1
/// = 14, ray pieces 1 (mouth) + 4 (vertical and steep) + 2 + 2 = 9: 23.
/// F = 2 − 15 + 23 = 10: 5 cells in the corridor, 4 in the niche.
#[test]
fn corridor_one_niche() {
    let m = wai_gen::family("corridor-niches", &[1]).unwrap();
    let arr = check(&m, (15, 23, 10));
    assert!(arr.conflicts().is_empty());
    let mouth = edge_between(&arr, &pt(4, 0), &pt(6, 0));
    assert_eq!(arr.edge_rays(mouth).len(), 2);
    let top = cell_with(&arr, &[pt(4, 0), pt(6, 0), pt(5, -1)]);
    assert_eq!(arr.owner_of_edge(mouth), top);
    // (5, −1): side right of (1, −1) (x + y < 4) and left of (−1, −1)
    // (x − y > 6): the bottom cell.
    let x = vertex_at(&arr, &pt(5, -1));
    let bottom = cell_with(
        &arr,
        &[pt(4, -2), pt(5, -1), pt(6, -2), pt(6, -4), pt(4, -4)],
    );
    assert_eq!(arr.owner_of_vertex(x), Some(bottom));
    // The piece (4, 0)–(5, −1) of x + y = 4 goes to the cell below-left.
    let e = edge_between(&arr, &pt(4, 0), &pt(5, -1));
    let left = cell_with(&arr, &[pt(4, 0), pt(5, -1), pt(4, -2)]);
    assert_eq!(arr.owner_of_edge(e), left);
}

/// Two niches: more cells, still sane and conflict-free.
#[test]
fn corridor_two_niches() {
    let m = wai_gen::family("corridor-niches", &[2]).unwrap();
    let arr = build(&m);
    assert!(arr.face_count() > 10);
    assert!(arr.conflicts().is_empty(), "{:?}", arr.conflicts());
}

/// The blocks of `hand::blocks`: four rays on x + y = 8 overlap (from 5
/// anchored at 9 grazing 13, from 13 anchored at 9 grazing 5, from 9
/// anchored at 5, from 9 anchored at 13). On that line the pieces are
/// (0, 8)–(2, 6)–(4, 4)–(6, 2)–(8, 0), covered by 2 rays each.
#[test]
fn overlapping_collinear_rays() {
    let m = map(&[
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
    ]);
    let arr = build(&m);
    // The group on x + y = 8: its edges run from (0, 8) to (8, 0), split
    // wherever other rays cross; between (2, 6) and (6, 2) only the two
    // grazing rays (from 5 and from 13, anchored at 9) cover them, beyond
    // those corners a grazing ray and the ray anchored there.
    let g = (0..arr.ray_groups().len())
        .find(|&g| {
            let k = &arr.ray_group(g).key;
            (k.a(), k.b(), k.c().to_i32()) == (1, 1, Some(8))
        })
        .expect("the group on x + y = 8");
    assert_eq!(arr.ray_group(g).rays.len(), 4);
    let on_line: Vec<usize> = (0..arr.edge_count())
        .filter(|&e| arr.edge_support(e) == Support::Rays(g))
        .collect();
    assert!(on_line.len() >= 4);
    let (a, b) = (vertex_at(&arr, &pt(2, 6)), vertex_at(&arr, &pt(6, 2)));
    let inner = |e: usize| {
        let x = |v: usize| rug::Rational::from((arr.point(v).hx(), arr.point(v).hw()));
        let (p, q) = (arr.half_edge(2 * e).origin, arr.dest(2 * e));
        let lo = x(a);
        let hi = x(b);
        x(p) >= lo && x(p) <= hi && x(q) >= lo && x(q) <= hi
    };
    for &e in &on_line {
        let want = if inner(e) { 1 } else { 2 };
        assert_eq!(arr.edge_rays(e).len(), want, "edge {e}");
    }
    for v in [pt(0, 8), pt(2, 6), pt(4, 4), pt(6, 2), pt(8, 0)] {
        vertex_at(&arr, &v);
    }
    // The corners' edges point up and east: every ray on the line gives
    // its points to the north-east side; no conflict on that line.
    for c in arr.conflicts() {
        if let Conflict::Edge { edge, .. } = c {
            assert!(!on_line.contains(edge), "conflict on x + y = 8: {c:?}");
        }
    }
}

/// Three or more rays through one interior point give one vertex: find
/// such vertices on generated maps, and check no two vertices coincide.
#[test]
fn many_rays_through_one_point() {
    let mut found = 0;
    for seed in 0..6 {
        let m = wai_gen::random("special-orthogonal", 20, seed).unwrap();
        let arr = build(&m);
        let mut pts: Vec<&RatPoint> = (0..arr.vertex_count()).map(|v| arr.point(v)).collect();
        let all = pts.len();
        pts.sort();
        pts.dedup();
        assert_eq!(pts.len(), all, "duplicate vertices");
        found += (0..arr.vertex_count())
            .filter(|&v| !arr.is_on_map_boundary(v) && arr.outgoing(v).len() >= 6)
            .count();
    }
    assert!(found > 0, "no interior vertex with three lines through it");
}

/// A hand-made point with three concurrent rays: a square room [0, 8]²
/// with notches whose rays meet at (4, 4)... built as the L room's
/// anchor: all four rays meet at the anchor, a map vertex, once.
#[test]
fn rays_meeting_at_an_anchor_share_it() {
    let m = map(&[(0, 0), (4, 0), (4, 2), (2, 2), (2, 4), (0, 4)]);
    let arr = build(&m);
    assert_eq!(arr.outgoing(3).len(), 6); // 2 map edges, 4 rays
}

#[test]
fn random_maps_of_every_kind() {
    let mut maps = 0;
    for kind in wai_gen::RANDOM_KINDS {
        for n in [kind.min_n.max(6), 12, 20, 30] {
            if n > kind.max_n {
                continue;
            }
            for seed in 0..3 {
                let m = wai_gen::random(kind.id, n, seed).unwrap();
                build(&m);
                maps += 1;
            }
        }
    }
    assert!(maps >= 30, "{maps} maps");
}

#[test]
fn thesis_families() {
    for f in wai_gen::FAMILIES {
        let mut checked = 0;
        for k in 0..=3u32 {
            let Ok(m) = wai_gen::family(f.id, &[k]) else {
                continue;
            };
            if m.n() > 40 {
                continue;
            }
            build(&m);
            checked += 1;
        }
        assert!(checked >= 1, "{}: no map", f.id);
    }
}

#[test]
fn free_polyominoes_up_to_6() {
    let mut count = 0;
    for m in wai_gen::exhaustive_polyomino_maps(6, wai_gen::Symmetry::Free) {
        build(&m);
        count += 1;
    }
    assert!(count >= 35, "{count}");
}

/// Planted violations: the checks can fail.
#[test]
fn planted_broken_twin() {
    let m = map(&[(0, 0), (4, 0), (4, 2), (2, 2), (2, 4), (0, 4)]);
    let mut arr = build(&m);
    arr.corrupt_twin_for_tests(0, 3);
    let err = arr.sanity_check().unwrap_err();
    assert!(err.contains("twin"), "{err}");
}

/// Without its rays the L room is one non-convex face (T3.3a fails).
#[test]
fn planted_non_convex_face() {
    let m = map(&[(0, 0), (4, 0), (4, 2), (2, 2), (2, 4), (0, 4)]);
    let arr = Arrangement::new(&m, &[]);
    arr.check_topology().unwrap();
    let err = arr.sanity_check().unwrap_err();
    assert!(err.contains("not convex"), "{err}");
    // Moving a vertex is caught as well.
    let mut arr = build(&m);
    let v = vertex_at(&arr, &pt(2, 0));
    arr.corrupt_point_for_tests(v, pt(3, 1));
    assert!(arr.sanity_check().is_err());
}

/// The average of the points, exactly.
fn centroid(pts: &[&RatPoint]) -> RatPoint {
    let w: Integer = pts.iter().map(|p| p.hw().clone()).product();
    let (mut x, mut y) = (Integer::new(), Integer::new());
    for p in pts {
        let s = Integer::from(&w / p.hw());
        x += Integer::from(p.hx() * &s);
        y += Integer::from(p.hy() * &s);
    }
    RatPoint::new(x, y, w * pts.len() as u32).unwrap()
}

/// T3.3b spot check: distinct interior points of a cell have equal
/// skeletons.
#[test]
fn same_skeleton_inside_each_cell() {
    let maps = [
        map(&[(0, 0), (4, 0), (4, 2), (2, 2), (2, 4), (0, 4)]),
        wai_gen::family("corridor-niches", &[1]).unwrap(),
        wai_gen::family("corridor-niches", &[2]).unwrap(),
        wai_gen::random("random-orthogonal", 12, 1).unwrap(),
    ];
    let mut cells = 0;
    for m in &maps {
        let arr = build(m);
        let index = VisibilityIndex::new(m);
        let key = |p: &RatPoint| {
            let vp = index.visibility_polygon(p).unwrap();
            Skeleton::of(m, &vp).unwrap().key()
        };
        for f in arr.cells() {
            let vs: Vec<&RatPoint> = arr.face_vertices(f).iter().map(|&v| arr.point(v)).collect();
            let c = centroid(&vs);
            let k = key(&c);
            for v in vs.iter().take(3) {
                let q = RatPoint::midpoint(&c, v);
                assert_eq!(key(&q), k, "cell {f}: {c} and {q}");
            }
            cells += 1;
        }
    }
    assert!(cells > 20, "{cells}");
}

/// The memory estimate's vertex bound, from predicates only, is never below
/// the arrangement's real vertex count, and equals it where no three rays
/// cross in one point (each pair of meeting rays adds one vertex).
#[test]
fn vertex_bound_bounds_the_arrangement() {
    let mut maps: Vec<Map> = Vec::new();
    for kind in wai_gen::RANDOM_KINDS {
        for seed in 0..3 {
            maps.push(wai_gen::random(kind.id, kind.min_n.max(20), seed).unwrap());
        }
    }
    for f in wai_gen::FAMILIES {
        if let Ok(m) = wai_gen::family(f.id, &[2]) {
            maps.push(m);
        }
    }
    let mut exact = 0;
    for m in &maps {
        let rays = wai_cells::visibility_rays(m);
        let bound = wai_cells::vertex_bound(m, &rays);
        let real = Arrangement::new(m, &rays).vertex_count() as u64;
        assert!(bound >= real, "{:?}: bound {bound} < {real}", m.name());
        exact += usize::from(bound == real);
    }
    assert!(
        exact > maps.len() / 4,
        "the bound is exact on only {exact} maps"
    );
}
