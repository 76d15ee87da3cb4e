//! The decomposition with skeletons and classes (Defs 3.9, 3.10):
//! hand-derived classes on the L room and the corridor with one niche, the
//! Lemma 3.7 class of `corridor-niches` (one skeleton, k cells), and
//! consistency laws on random maps of every kind with a T3.3b spot check
//! at a second interior point of every cell.

use crate::common::{map, pt};
use std::collections::BTreeSet;
use wai_cells::{Counts, Decomposition, FaceId, KeptAbsorbed, LowerSite, Support};
use wai_exact::{orientation_rat, Orientation, RatPoint};
use wai_map::Map;
use wai_visibility::{Skeleton, SkeletonKey, VisibilityIndex};

/// The cell whose boundary vertices are exactly `pts`.
fn cell_with(d: &Decomposition, pts: &[RatPoint]) -> FaceId {
    let arr = d.arrangement();
    let want: BTreeSet<&RatPoint> = pts.iter().collect();
    *d.cells()
        .iter()
        .find(|&&f| {
            let got: BTreeSet<&RatPoint> =
                arr.face_vertices(f).iter().map(|&v| arr.point(v)).collect();
            got == want
        })
        .unwrap_or_else(|| panic!("no cell {pts:?}"))
}

/// Number of vertices of a cell's skeleton.
fn skeleton_len(d: &Decomposition, cell: FaceId) -> usize {
    d.skeletons()[d.skeleton_of(cell)].offsets.len()
}

/// Every structural law of a decomposition; returns the number of cells
/// spot-checked at a second interior point.
fn check_laws(d: &Decomposition) -> usize {
    let m = d.map();
    let arr = d.arrangement();
    let name = m.name().unwrap_or("unnamed");
    arr.sanity_check().unwrap_or_else(|e| panic!("{name}: {e}"));
    // Cells: the bounded faces in face order.
    let faces: Vec<FaceId> = arr.cells().collect();
    assert_eq!(d.cells(), &faces[..], "{name}");
    // Classes partition the cells, each class ascending and non-empty
    // (with a 2-cell or a kept lower-dimensional cell), the classes with a
    // 2-cell first, ordered by first cell, and agree with `skeleton_of`.
    assert_eq!(d.classes().len(), d.skeletons().len(), "{name}");
    let mut seen = vec![false; arr.face_count()];
    for (i, class) in d.classes().iter().enumerate() {
        assert!(
            !class.is_empty() || !d.class_lower_cells(i).is_empty(),
            "{name}: class {i} empty"
        );
        if i > 0 && !class.is_empty() {
            assert!(
                !d.classes()[i - 1].is_empty(),
                "{name}: class {i} after a lower-only class"
            );
        }
        assert!(class.windows(2).all(|w| w[0] < w[1]), "{name}: class {i}");
        for &c in class {
            assert!(!seen[c], "{name}: cell {c} in two classes");
            seen[c] = true;
            assert_eq!(d.skeleton_of(c), i, "{name}: cell {c}");
        }
        let want: usize = class.iter().map(|&c| 2 * d.cell_size(c)).sum();
        assert_eq!(d.class_complexity(i), want, "{name}: |EC| of class {i}");
    }
    assert!(
        d.cells().iter().all(|&c| seen[c]),
        "{name}: a cell in no class"
    );
    let firsts: Vec<FaceId> = d
        .classes()
        .iter()
        .filter_map(|c| c.first().copied())
        .collect();
    assert!(
        firsts.windows(2).all(|w| w[0] < w[1]),
        "{name}: class order"
    );
    let keys: BTreeSet<&SkeletonKey> = d.skeletons().iter().collect();
    assert_eq!(keys.len(), d.skeletons().len(), "{name}: repeated key");
    // Sizes and N.
    for &c in d.cells() {
        assert_eq!(d.cell_size(c), arr.face_vertices(c).len(), "{name}");
        assert_eq!(d.cell_size(c), arr.face_half_edges(c).len(), "{name}");
    }
    let sizes: usize = d.cells().iter().map(|&c| d.cell_size(c)).sum();
    assert_eq!(d.total_complexity(), 2 * sizes, "{name}");
    let classes_total: usize = (0..d.classes().len()).map(|i| d.class_complexity(i)).sum();
    assert_eq!(d.total_complexity(), classes_total, "{name}: N = Σ |EC|");
    let max = (0..d.classes().len())
        .map(|i| d.class_complexity(i))
        .max()
        .unwrap();
    assert_eq!(d.max_class_complexity(), max, "{name}");
    // Counts.
    assert_eq!(
        d.counts(),
        Counts {
            n: m.n(),
            r: m.r(),
            rays: d.rays().len(),
            cells: d.cells().len(),
            total_complexity: d.total_complexity(),
            classes: d.classes().len(),
            max_class_complexity: max,
            vertices: arr.vertex_count(),
            edges: arr.edge_count(),
            conflicts: arr.conflicts().len(),
            one_cells: lower_tally(d, 1),
            zero_cells: lower_tally(d, 0),
        },
        "{name}"
    );
    // Cells of every dimension: one 1-cell per ray edge, one 0-cell per
    // vertex off ∂M; an absorbed cell lies beside its 2-cell and shares its
    // class; a kept one is listed by its class.
    let ray_edges = (0..arr.edge_count())
        .filter(|&e| matches!(arr.edge_support(e), Support::Rays(_)))
        .count();
    let inner_vertices = (0..arr.vertex_count())
        .filter(|&v| !arr.is_on_map_boundary(v))
        .count();
    let c = d.counts();
    assert_eq!(c.one_cells.kept + c.one_cells.absorbed, ray_edges, "{name}");
    assert_eq!(
        c.zero_cells.kept + c.zero_cells.absorbed,
        inner_vertices,
        "{name}"
    );
    for (i, l) in d.lower_cells().iter().enumerate() {
        let beside: Vec<usize> = match l.site {
            LowerSite::Edge(e) => vec![arr.half_edge(2 * e).face, arr.half_edge(2 * e + 1).face],
            LowerSite::Vertex(v) => arr.faces_around(v),
        };
        match l.absorbed_by {
            Some(f) => {
                assert!(beside.contains(&f), "{name}: {l:?}");
                assert_eq!(d.skeleton_of(f), l.class, "{name}: {l:?}");
                assert!(!d.class_lower_cells(l.class).contains(&i), "{name}: {l:?}");
            }
            None => assert!(d.class_lower_cells(l.class).contains(&i), "{name}: {l:?}"),
        }
    }
    assert_eq!(d.assignment().edge_owners().len(), arr.edge_count());
    // Representatives are strictly inside their cell; a second interior
    // point (the midpoint of the representative and a boundary vertex) has
    // the same skeleton (T3.3b, interior part), computed independently.
    let index = VisibilityIndex::new(m);
    let key = |p: &RatPoint| {
        let vp = index.visibility_polygon(p).unwrap();
        Skeleton::of(m, &vp).unwrap().key()
    };
    let mut spot = 0;
    for &c in d.cells() {
        let rep = d.representative(c);
        let vs = arr.face_vertices(c);
        for (i, &v) in vs.iter().enumerate() {
            let w = vs[(i + 1) % vs.len()];
            assert_eq!(
                orientation_rat(arr.point(v), arr.point(w), rep),
                Orientation::CounterClockwise,
                "{name}: representative {rep} of cell {c} not interior"
            );
        }
        assert_eq!(key(rep), d.skeletons()[d.skeleton_of(c)], "{name}");
        let q = RatPoint::midpoint(rep, arr.point(vs[spot % vs.len()]));
        assert_eq!(
            key(&q),
            d.skeletons()[d.skeleton_of(c)],
            "{name}: cell {c}: {rep} and {q}"
        );
        spot += 1;
    }
    spot
}

/// The L room (counts as in `arrangement::l_room`: 8 vertices, 12 edges,
/// 5 cells). By hand, the cells see different sets of map vertices, so all
/// five skeletons differ (the map's mirror symmetry in x = y does not
/// help: skeletons are compared up to translation only):
/// - the square (0, 0), (2, 0), (2, 2), (0, 2) sees all 6 vertices;
/// - the triangle (2, 0), (4, 0), (2, 2) (east of x = 2, below x + y = 4)
///   loses (2, 4) behind the corner: 5;
/// - the triangle (4, 0), (4, 2), (2, 2) (above x + y = 4) also loses
///   (0, 4): 4;
/// - their mirror images lose (4, 2), then (4, 0) as well: 5 and 4.
///
/// Every cell is its own class; sizes 4 + 4 · 3 = 16, N = 32, max |EC| = 8
/// (the square).
#[test]
fn l_room() {
    let m = map(&[(0, 0), (4, 0), (4, 2), (2, 2), (2, 4), (0, 4)]);
    let d = Decomposition::new(&m);
    check_laws(&d);
    assert_eq!(
        d.counts(),
        Counts {
            n: 6,
            r: 1,
            rays: 4,
            cells: 5,
            total_complexity: 32,
            classes: 5,
            max_class_complexity: 8,
            vertices: 8,
            edges: 12,
            conflicts: 0,
            // The 4 rays from (2, 2) cross nothing: 4 ray edges, each with
            // the skeleton of the cell on its anchor's side.
            one_cells: KeptAbsorbed {
                kept: 0,
                absorbed: 4
            },
            zero_cells: KeptAbsorbed::default(),
        }
    );
    let expect = [
        (vec![pt(0, 0), pt(2, 0), pt(2, 2), pt(0, 2)], 6),
        (vec![pt(2, 0), pt(4, 0), pt(2, 2)], 5),
        (vec![pt(4, 0), pt(4, 2), pt(2, 2)], 4),
        (vec![pt(0, 2), pt(2, 2), pt(0, 4)], 5),
        (vec![pt(2, 2), pt(2, 4), pt(0, 4)], 4),
    ];
    for (pts, len) in expect {
        let c = cell_with(&d, &pts);
        assert_eq!(skeleton_len(&d, c), len, "{pts:?}");
        assert_eq!(d.classes()[d.skeleton_of(c)], vec![c]);
    }
    let square = cell_with(&d, &[pt(0, 0), pt(2, 0), pt(2, 2), pt(0, 2)]);
    assert_eq!(d.class_complexity(d.skeleton_of(square)), 8);
}

/// `corridor-niches` k = 1 (counts as in `arrangement::corridor_one_niche`:
/// 15 vertices, 23 edges, 9 cells). By hand every cell has its own
/// skeleton. In the niche (x in [4, 6], y < 0): the bottom cell sees only
/// the niche's 4 vertices; the left triangle (4, 0), (4, −2), (5, −1)
/// sees them and the far corner (10, 4), the right triangle the other far
/// corner (0, 4), the mouth triangle both. In the corridor: the cell over
/// the mouth sees all 8 vertices; the triangles beside it lose one niche
/// bottom corner each ((4, −4) west of x = 4, (6, −4) east of x = 6); the
/// two end cells see the 6 corridor vertices and no niche bottom, with
/// the artificial edge on the niche's far wall, x = 6 for the west end and
/// x = 4 for the east end. Sizes 4+3+5+3+4+3+4+3+3 = 32: N = 64; the
/// largest cell, the niche bottom, has |EC| = 10.
#[test]
fn corridor_one_niche() {
    let m = wai_gen::family("corridor-niches", &[1]).unwrap();
    let d = Decomposition::new(&m);
    check_laws(&d);
    assert_eq!(
        d.counts(),
        Counts {
            n: 8,
            r: 2,
            rays: 8,
            cells: 9,
            total_complexity: 64,
            classes: 9,
            max_class_complexity: 10,
            vertices: 15,
            edges: 23,
            conflicts: 0,
            // Every ray edge and the one crossing inside have the skeleton
            // of a 2-cell beside them: the sec. 3.6 rule holds on this map.
            one_cells: KeptAbsorbed {
                kept: 0,
                absorbed: 9
            },
            zero_cells: KeptAbsorbed {
                kept: 0,
                absorbed: 1
            },
        }
    );
    // The niche bottom sees exactly the niche: 4 skeleton vertices, and
    // the mouth becomes an artificial edge on y = 0.
    let bottom = cell_with(&d, &[pt(4, -2), pt(5, -1), pt(6, -2), pt(6, -4), pt(4, -4)]);
    let key = &d.skeletons()[d.skeleton_of(bottom)];
    assert_eq!(key.offsets, vec![(0, 0), (0, -4), (2, -4), (2, 0)]);
    assert_eq!(key.labels.iter().filter(|l| l.is_some()).count(), 1);
    // Skeleton sizes as derived above.
    let expect = [
        (vec![pt(4, 0), pt(4, -2), pt(5, -1)], 5),
        (vec![pt(6, -2), pt(6, 0), pt(5, -1)], 5),
        (vec![pt(6, 0), pt(4, 0), pt(5, -1)], 6),
        (vec![pt(0, 0), pt(4, 0), pt(2, 4), pt(0, 4)], 6),
        (vec![pt(6, 0), pt(10, 0), pt(10, 4), pt(8, 4)], 6),
        (vec![pt(4, 4), pt(2, 4), pt(4, 0)], 7),
        (vec![pt(8, 4), pt(6, 4), pt(6, 0)], 7),
    ];
    for (pts, len) in expect {
        assert_eq!(skeleton_len(&d, cell_with(&d, &pts)), len, "{pts:?}");
    }
    // The corridor cell over the mouth sees all 8 vertices, no artificial
    // edge.
    let over = cell_with(&d, &[pt(6, 4), pt(4, 4), pt(4, 0), pt(6, 0)]);
    let key = &d.skeletons()[d.skeleton_of(over)];
    assert_eq!(key.offsets.len(), 8);
    assert!(key.labels.iter().all(Option::is_none));
}

/// Lemma 3.7 (tightness; claim L3.7t): in `corridor-niches` k, the niche
/// bottoms all have the niche-0 skeleton translated: one class with
/// exactly 1 · k + 0 cells; every other class is a single cell. The whole
/// decomposition grows linearly: 9k cells, 8k + 1 classes, N = 60k + 4,
/// max |EC| = 10k (the growing class).
#[test]
fn corridor_niches_one_class_grows_linearly() {
    for k in 1..=5u32 {
        let m = wai_gen::family("corridor-niches", &[k]).unwrap();
        let d = Decomposition::new(&m);
        check_laws(&d);
        let k = k as usize;
        let big: Vec<usize> = (0..d.classes().len())
            .filter(|&i| d.classes()[i].len() > 1)
            .collect();
        if k == 1 {
            assert!(big.is_empty());
        } else {
            assert_eq!(big.len(), 1, "k = {k}: classes with several cells");
            assert_eq!(d.classes()[big[0]].len(), k, "k = {k}");
        }
        // The class of the deepest viewpoint of niche 0 holds one cell per
        // niche, each containing that niche's viewpoint.
        let vps = wai_gen::corridor_niches_viewpoints(k as u32);
        let class = class_of_point(&d, &RatPoint::from(vps[0]));
        assert_eq!(d.classes()[class].len(), k, "k = {k}");
        for vp in &vps {
            assert_eq!(class_of_point(&d, &RatPoint::from(*vp)), class);
        }
        assert_eq!(d.class_complexity(class), 10 * k);
        let c = d.counts();
        assert_eq!(
            (
                c.cells,
                c.classes,
                c.total_complexity,
                c.max_class_complexity
            ),
            (9 * k, 8 * k + 1, 60 * k + 4, 10 * k),
            "k = {k}"
        );
        assert_eq!(c.conflicts, 0);
    }
}

/// The class of the cell whose interior contains `p`.
fn class_of_point(d: &Decomposition, p: &RatPoint) -> usize {
    let arr = d.arrangement();
    let cell = d
        .cells()
        .iter()
        .copied()
        .find(|&c| {
            let vs = arr.face_vertices(c);
            (0..vs.len()).all(|i| {
                orientation_rat(arr.point(vs[i]), arr.point(vs[(i + 1) % vs.len()]), p)
                    == Orientation::CounterClockwise
            })
        })
        .unwrap_or_else(|| panic!("{p} is in no cell's interior"));
    d.skeleton_of(cell)
}

#[test]
fn random_maps_of_every_kind() {
    let (mut maps, mut cells) = (0, 0);
    for kind in wai_gen::RANDOM_KINDS {
        for n in [kind.min_n.max(6), 14, 30] {
            if n > kind.max_n {
                continue;
            }
            for seed in 0..2 {
                let m = wai_gen::random(kind.id, n, seed).unwrap();
                cells += check_laws(&Decomposition::new(&m));
                maps += 1;
            }
        }
    }
    assert!(maps >= 20, "{maps} maps");
    assert!(cells >= 1000, "{cells} cells");
}

#[test]
fn thesis_families_small() {
    let mut checked = 0;
    for f in wai_gen::FAMILIES {
        for k in 1..=2u32 {
            let Ok(m) = wai_gen::family(f.id, &[k]) else {
                continue;
            };
            if m.n() > 30 {
                continue;
            }
            check_laws(&Decomposition::new(&m));
            checked += 1;
        }
    }
    assert!(checked >= 4, "{checked}");
}

/// `with_progress` reports 0 first, the total last (the cells of every
/// dimension), never decreasing, through the lower-dimensional cells too,
/// and builds the same decomposition as `new`.
#[test]
fn progress_is_monotone_and_complete() {
    let m: Map = wai_gen::random("random-orthogonal", 20, 3).unwrap();
    let mut calls = Vec::new();
    let d = Decomposition::with_progress(&m, &mut |done, total| calls.push((done, total)));
    let total = d.cells().len() + d.lower_cells().len();
    assert_eq!(calls.first(), Some(&(0, total)));
    assert!(
        calls
            .iter()
            .any(|&(done, _)| done > d.cells().len() && done < total),
        "no progress among the 1- and 0-cells: {calls:?}"
    );
    assert_eq!(calls.last(), Some(&(total, total)));
    assert!(calls
        .windows(2)
        .all(|w| w[0].0 <= w[1].0 && w[1].1 == total));
    assert!(calls.len() >= 3, "{calls:?}");
    let e = Decomposition::new(&m);
    assert_eq!(d.counts(), e.counts());
    assert_eq!(d.skeletons(), e.skeletons());
    assert_eq!(d.classes(), e.classes());
}

fn lower_tally(d: &Decomposition<'_>, dim: u8) -> KeptAbsorbed {
    let mut t = KeptAbsorbed::default();
    for l in d.lower_cells().iter().filter(|l| l.dimension() == dim) {
        if l.absorbed_by.is_some() {
            t.absorbed += 1;
        } else {
            t.kept += 1;
        }
    }
    t
}

/// The `i64` paths of the rays and of the arrangement's pairs of rays
/// (map coordinates below 2^30) against the general ones: each map scaled
/// by 2^31 has the same decomposition, count for count and class for
/// class, with its skeletons scaled.
#[test]
fn same_decomposition_beyond_the_i64_paths() {
    let maps = [
        wai_gen::random("random-orthogonal", 30, 1).unwrap(),
        wai_gen::random("random-simple-2opt", 20, 2).unwrap(),
        wai_gen::family("comb-convex-chain", &[3]).unwrap(),
        wai_gen::family("overlap-fan", &[0]).unwrap(),
        wai_gen::family("corridor-niches", &[2]).unwrap(),
    ];
    let s: i128 = 1 << 31;
    for m in &maps {
        let big = m.scaled_up(31).unwrap();
        let (d, e) = (Decomposition::new(m), Decomposition::new(&big));
        assert_eq!(d.counts(), e.counts(), "{:?}", m.name());
        assert_eq!(d.classes(), e.classes(), "{:?}", m.name());
        // Vertex ids follow the order in which crossings are found, which
        // may differ: 0-cells are compared by their points.
        let by_point = |d: &Decomposition, scale: i128| {
            let mut cells: Vec<_> = d
                .lower_cells()
                .iter()
                .map(|l| {
                    let site = match l.site {
                        LowerSite::Edge(e) => (Some(e), None),
                        LowerSite::Vertex(v) => {
                            let p = d.arrangement().point(v);
                            let x = rug::Integer::from(p.hx() * scale);
                            let y = rug::Integer::from(p.hy() * scale);
                            (None, Some(RatPoint::new(x, y, p.hw().clone()).unwrap()))
                        }
                    };
                    (site, l.class, l.origin, l.absorbed_by)
                })
                .collect();
            cells.sort();
            cells
        };
        assert!(
            by_point(&d, s) == by_point(&e, 1),
            "{:?}: lower cells",
            m.name()
        );
        for (a, b) in d.skeletons().iter().zip(e.skeletons()) {
            let scaled: Vec<(i128, i128)> =
                a.offsets.iter().map(|&(x, y)| (x * s, y * s)).collect();
            assert_eq!(scaled, b.offsets, "{:?}", m.name());
        }
    }
}
