//! Bytes → a small valid map (`wai_gen::bytes`) → the visibility cell
//! decomposition (`wai_cells`, thesis sec. 3.6, Defs 3.8–3.10).
//!
//! Laws:
//! - the arrangement of the map edges and the visibility rays passes its
//!   layered `sanity_check` (twins, face cycles, Euler's V − E + F = 2,
//!   orientation, convex cells), built alone (`Arrangement::new`) and
//!   inside the `Decomposition`, and the two have the same counts;
//! - the memory estimate's `vertex_bound` is never below the real vertex
//!   count;
//! - the classes partition the 2-cells, and N = Σ |EC|;
//! - the skeleton the walk of sec. 3.9.2 gives each cell, of every
//!   dimension, equals a fresh visibility query at its representative
//!   point (`VisibilityIndex` + `Skeleton::of`);
//! - the same map scaled by 2^31 (off the `i64` paths of maps below 2^30)
//!   has the same counts and classes.
#![no_main]

use libfuzzer_sys::fuzz_target;
use wai_cells::{vertex_bound, visibility_rays, Arrangement, Decomposition};
use wai_exact::{Point, RatPoint};
use wai_map::Map;
use wai_visibility::{Skeleton, VisibilityIndex};

fuzz_target!(|data: &[u8]| {
    wai_fuzz::init();
    let Some((map, _)) = wai_fuzz::map_of(data) else {
        return;
    };
    let name = map.name().unwrap_or("unnamed").to_owned();
    let rays = visibility_rays(&map);
    let arr = Arrangement::new(&map, &rays);
    if let Err(e) = arr.sanity_check() {
        panic!("{name}: Arrangement::new fails its sanity check: {e}");
    }
    let bound = vertex_bound(&map, &rays);
    assert!(
        bound >= arr.vertex_count() as u64,
        "{name}: vertex_bound {bound} < {} vertices",
        arr.vertex_count()
    );

    let d = Decomposition::new(&map);
    let inner = d.arrangement();
    if let Err(e) = inner.sanity_check() {
        panic!("{name}: the decomposition's arrangement fails its sanity check: {e}");
    }
    assert_eq!(
        (inner.vertex_count(), inner.edge_count(), inner.face_count()),
        (arr.vertex_count(), arr.edge_count(), arr.face_count()),
        "{name}: the decomposition's arrangement differs from Arrangement::new's"
    );

    // The classes partition the 2-cells; N = Σ |EC|.
    let mut seen = vec![false; inner.face_count()];
    for (i, class) in d.classes().iter().enumerate() {
        for &c in class {
            assert!(!seen[c], "{name}: cell {c} in two classes");
            seen[c] = true;
            assert_eq!(d.skeleton_of(c), i, "{name}: cell {c} and its class");
        }
    }
    assert!(
        d.cells().iter().all(|&c| seen[c]),
        "{name}: a cell in no class"
    );
    let total: usize = (0..d.classes().len()).map(|i| d.class_complexity(i)).sum();
    assert_eq!(d.total_complexity(), total, "{name}: N = Σ |EC|");

    // The walked skeletons against fresh queries, cells of every dimension.
    let index = VisibilityIndex::new(&map);
    let v = map.vertices();
    let fresh = |p: &RatPoint| {
        let vp = index
            .visibility_polygon(p)
            .unwrap_or_else(|e| panic!("{name}: representative {p}: {e}"));
        let sk = Skeleton::of(&map, &vp)
            .unwrap_or_else(|e| panic!("{name}: no skeleton at representative {p}: {e}"));
        (sk.origin(), sk.key())
    };
    for &f in d.cells() {
        let walked = (v[d.origin_of(f)], d.skeletons()[d.skeleton_of(f)].clone());
        let at = d.representative(f);
        assert!(
            fresh(at) == walked,
            "{name}: 2-cell {f} at {at}: walk and query differ"
        );
    }
    for c in d.lower_cells() {
        let walked = (v[c.origin], d.skeletons()[c.class].clone());
        let at = d.lower_representative(c);
        assert!(
            fresh(&at) == walked,
            "{name}: {:?} at {at}: walk and query differ",
            c.site
        );
    }

    // Beyond the i64 paths: scaled by 2^31, the same decomposition.
    let s: i128 = 1 << 31;
    let ring = v.iter().map(|p| Point::new(p.x * s, p.y * s)).collect();
    let (big, _) = Map::from_ring(ring).expect("a scaled valid map is valid");
    let e = Decomposition::new(&big);
    assert_eq!(
        d.counts(),
        e.counts(),
        "{name}: counts change when scaled by 2^31"
    );
    assert_eq!(
        d.classes(),
        e.classes(),
        "{name}: classes change when scaled by 2^31"
    );
});
