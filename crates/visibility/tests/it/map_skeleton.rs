//! `VisibilityIndex::skeleton_at` (V*_p in map terms, read off the
//! expansion) against `Skeleton::of` on V_p, and its comparisons against
//! key equality, on degenerate maps and viewpoints.

use crate::common::viewpoints;
use crate::laws::test_maps;
use wai_visibility::{MapSkeleton, Skeleton, VisibilityIndex};

#[test]
fn skeleton_at_equals_the_skeleton_of_v_p() {
    let mut maps = test_maps();
    for kind in ["special-orthogonal", "special-comb", "special-chamfer"] {
        for seed in 0..10 {
            maps.push(wai_gen::random(kind, 20 + seed as usize, seed).unwrap());
        }
    }
    let mut examined = 0;
    for map in &maps {
        let index = VisibilityIndex::new(map);
        let views = viewpoints(map, 30);
        let mut skeletons = Vec::new();
        for p in &views {
            let vp = index.visibility_polygon(p).unwrap();
            let want = Skeleton::of(map, &vp).map(|s| MapSkeleton::of(&s));
            let got = index.skeleton_at(p);
            assert_eq!(
                got.clone().map_err(|e| e.to_string()),
                want.clone().map_err(|e| format!("V*_p: {e}")),
                "viewpoint {p} in {:?}",
                map.vertices()
            );
            if let Ok(sk) = got {
                let key = Skeleton::of(map, &vp).unwrap().key();
                assert_eq!(sk.key(map), key);
                assert!(sk.is(map, sk.origin(), &key));
                skeletons.push((sk, key));
            }
            examined += 1;
        }
        // `same` and `is` are key equality in the same embedding.
        for (a, ka) in &skeletons {
            for (b, kb) in &skeletons {
                let equal = a.origin() == b.origin() && ka == kb;
                assert_eq!(a.same(map, b), equal, "{a:?} / {b:?}");
                assert_eq!(a.is(map, b.origin(), kb), equal, "{a:?} / {kb:?}");
            }
        }
    }
    assert!(examined > 2000, "only {examined}");
}
