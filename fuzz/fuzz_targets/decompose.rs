//! Bytes → a small valid map (`wai_gen::bytes`) → the visibility cell
//! decomposition (`wai_cells`, thesis sec. 3.6, Defs 3.8–3.10).
//!
//! Laws:
//! - the decomposition's arrangement of the map edges and the visibility
//!   rays passes its layered `sanity_check` (twins, face cycles, Euler's
//!   V − E + F = 2, orientation, convex cells, no crossings);
//! - the memory estimate's `vertex_bound` is never below the real vertex
//!   count;
//! - the classes partition the 2-cells, and N = Σ |EC|;
//! - the skeleton the walk of sec. 3.9.2 gives each cell, of every
//!   dimension, equals a fresh visibility query at its representative
//!   point (`VisibilityIndex::skeleton_at`, which the visibility target
//!   holds equal to `Skeleton::of` on V_p);
//! - the same map scaled by 2^31 (off the `i64` paths of maps below 2^30)
//!   has the same counts and classes.
#![no_main]

use libfuzzer_sys::fuzz_target;
use wai_cells::{vertex_bound, Decomposition};
use wai_exact::RatPoint;
use wai_visibility::VisibilityIndex;

fuzz_target!(|data: &[u8]| wai_fuzz::inline(|| decompose(data)));

fn decompose(data: &[u8]) {
    let Some((map, _)) = wai_fuzz::map_of(data) else {
        return;
    };
    let name = map.name().unwrap_or("unnamed").to_owned();
    let d = Decomposition::new(&map);
    let arr = d.arrangement();
    if let Err(e) = arr.sanity_check() {
        panic!("{name}: the decomposition's arrangement fails its sanity check: {e}");
    }
    let bound = vertex_bound(&map, arr.rays());
    assert!(
        bound >= arr.vertex_count() as u64,
        "{name}: vertex_bound {bound} < {} vertices",
        arr.vertex_count()
    );

    // The classes partition the 2-cells; N = Σ |EC|.
    let mut seen = vec![false; arr.face_count()];
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

    // The walked skeletons against fresh queries, cells of every dimension
    // (`skeleton_at`; the visibility target holds it equal to
    // `Skeleton::of` on V_p).
    let index = VisibilityIndex::new(&map);
    let agrees = |p: &RatPoint, origin: usize, class: usize| {
        let sk = index
            .skeleton_at(p)
            .unwrap_or_else(|e| panic!("{name}: no skeleton at representative {p}: {e}"));
        sk.is(&map, origin, &d.skeletons()[class])
    };
    for &f in d.cells() {
        let at = d.representative(f);
        assert!(
            agrees(at, d.origin_of(f), d.skeleton_of(f)),
            "{name}: 2-cell {f} at {at}: walk and query differ"
        );
    }
    for c in d.lower_cells() {
        let at = d.lower_representative(c);
        assert!(
            agrees(&at, c.origin, c.class),
            "{name}: {:?} at {at}: walk and query differ",
            c.site
        );
    }

    // Beyond the i64 paths: scaled by 2^31, the same decomposition.
    let big = map
        .scaled_up(31)
        .expect("a small map scaled by 2^31 is within the bound");
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
}
