//! The triangulation of maps with holes: bridges, then ear clipping, checked
//! on random holed maps, the AGPLIB maps with holes and grid-traced rooms.

use wai_map::json::{from_json_with, ReadOptions};
use wai_map::Map;
use wai_visibility::bridged_ring;
use wai_visibility::Triangulation;

fn check(map: &Map, what: &str) {
    let ring = bridged_ring(map);
    // Every vertex once, the two ends of each bridge twice.
    assert_eq!(ring.len(), map.n() + 2 * map.hole_count(), "{what}");
    let t = Triangulation::new(map);
    t.sanity_check(map)
        .unwrap_or_else(|e| panic!("{what}: {e}"));
}

#[test]
fn random_maps_with_holes() {
    let mut maps = 0;
    // The random kinds (the chapter 4 layouts with pillars are one large
    // map per seed, for the claim checkers).
    for kind in wai_gen::HOLED_KINDS
        .iter()
        .filter(|k| ["orthogonal-pillars", "simple-holes"].contains(&k.id))
    {
        for seed in 0..60 {
            for (n, h) in [(6, 1), (12, 3), (24, 8), (60, 15)] {
                let map = wai_gen::random_with_holes(kind.id, n, h, seed).unwrap();
                check(&map, &format!("{} n={n} h={h} seed={seed}", kind.id));
                maps += 1;
            }
        }
    }
    assert_eq!(maps, 480);
}

#[test]
fn pillars_in_line_with_each_other_and_the_walls() {
    // Rays from each pillar's rightmost corner run along the next pillar's
    // edges and through the walls' corners: every tie at once.
    let text = r#"{"outer": [["0","0"],["20","0"],["20","4"],["14","4"],["14","8"],["20","8"],["20","12"],["0","12"]],
        "holes": [[["2","2"],["2","4"],["4","4"],["4","2"]],
                  [["6","2"],["6","4"],["8","4"],["8","2"]],
                  [["10","2"],["10","4"],["12","4"],["12","2"]],
                  [["6","6"],["6","8"],["8","8"],["8","6"]],
                  [["10","8"],["10","10"],["12","10"],["12","8"]],
                  [["2","8"],["2","10"],["4","10"],["4","8"]]]}"#;
    let map = wai_map::json::from_json(text.as_bytes()).unwrap().map;
    check(&map, "aligned pillars");
}

#[test]
fn agplib_maps_with_holes() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../data/datasets/agplib");
    let mut maps = 0;
    for family in ["simple-holes", "ortho-holes"] {
        let mut files: Vec<_> = std::fs::read_dir(dir.join(family))
            .unwrap()
            .map(|e| e.unwrap().path())
            .filter(|p| p.extension().is_some_and(|e| e == "json"))
            .collect();
        files.sort();
        for f in files {
            let bytes = std::fs::read(&f).unwrap();
            let map = from_json_with(
                &bytes,
                &ReadOptions {
                    grid_bits: Some(60),
                },
            )
            .unwrap()
            .map;
            check(&map, &f.display().to_string());
            maps += 1;
        }
    }
    assert_eq!(maps, 36);
}

/// Viewpoints of a map with holes: a shifted rational grid over its
/// bounding box and the midpoints of vertex pairs, kept where in the free
/// space.
fn viewpoints(map: &Map, steps: i128) -> Vec<wai_exact::RatPoint> {
    use rug::Integer;
    use wai_exact::{Containment, RatPoint};
    let v = map.vertices();
    let mut out = Vec::new();
    for i in 0..v.len() {
        for j in (i + 1..v.len()).step_by(3) {
            out.push(RatPoint::midpoint(&v[i].into(), &v[j].into()));
        }
    }
    let (lo, hi) = map.bounding_box();
    for i in 1..steps {
        for j in 1..steps {
            let x = Integer::from(lo.x) * steps + (hi.x - lo.x) * i;
            let y = Integer::from(lo.y) * steps + (hi.y - lo.y) * j;
            out.push(RatPoint::new(x * 7 + 1, y * 7 + 2, Integer::from(steps * 7)).unwrap());
        }
    }
    out.retain(|q| map.locate(q) == Containment::Inside);
    out
}

#[test]
fn visibility_and_skeletons_on_maps_with_holes() {
    let mut compared = 0;
    let mut maps = vec![];
    // The random kinds (the chapter 4 layouts with pillars are one large
    // map per seed, for the claim checkers).
    for kind in wai_gen::HOLED_KINDS
        .iter()
        .filter(|k| ["orthogonal-pillars", "simple-holes"].contains(&k.id))
    {
        for seed in 0..12 {
            maps.push(wai_gen::random_with_holes(kind.id, 14, 5, seed).unwrap());
        }
    }
    for map in &maps {
        let index = wai_visibility::VisibilityIndex::new(map);
        for p in viewpoints(map, 9) {
            let fast = index.visibility_polygon(&p).unwrap();
            let reference = wai_visibility::reference::visibility_polygon(map, &p).unwrap();
            assert_eq!(fast, reference, "{:?} at {p:?}", map.name());
            // The skeleton: read off the expansion as from V_p; p in its
            // kernel (Lemma 3.4); V_p rebuilt from the key (Thm 3.2).
            let sk = wai_visibility::Skeleton::of(map, &fast).unwrap();
            assert_eq!(
                index.skeleton_at(&p).unwrap(),
                wai_visibility::MapSkeleton::of(&sk),
                "{:?} at {p:?}",
                map.name()
            );
            assert_ne!(sk.kernel().locate(&p), wai_exact::Containment::Outside);
            let o = sk.origin();
            let shift = |q: &wai_exact::RatPoint| {
                wai_exact::RatPoint::new(
                    rug::Integer::from(q.hx() - q.hw() * o.x),
                    rug::Integer::from(q.hy() - q.hw() * o.y),
                    q.hw().clone(),
                )
                .unwrap()
            };
            let rebuilt = wai_visibility::reconstruct(&sk.key(), &shift(&p));
            let start = fast
                .points()
                .iter()
                .position(|q| *q == wai_exact::RatPoint::from(o))
                .unwrap();
            let mut expect: Vec<_> = fast.points().iter().map(shift).collect();
            expect.rotate_left(start);
            assert_eq!(rebuilt, expect, "{:?} at {p:?}", map.name());
            compared += 1;
        }
        // In a hole and on a hole's edge: refused as outside, on the boundary.
        let hole = map.holes().next().unwrap();
        // The holes are convex: the centroid of three corners is inside.
        let inside_hole = wai_exact::RatPoint::new(
            rug::Integer::from(hole[0].x + hole[1].x + hole[2].x),
            rug::Integer::from(hole[0].y + hole[1].y + hole[2].y),
            rug::Integer::from(3),
        )
        .unwrap();
        let got = index.visibility_polygon(&inside_hole);
        assert!(
            matches!(got, Err(wai_visibility::VisibilityError::Outside(_))),
            "{:?} {hole:?}: {got:?}",
            map.name()
        );
        let on_edge = wai_exact::RatPoint::midpoint(&hole[0].into(), &hole[1].into());
        assert!(matches!(
            index.visibility_polygon(&on_edge),
            Err(wai_visibility::VisibilityError::OnBoundary(_))
        ));
    }
    assert!(compared > 2000, "{compared}");
}
