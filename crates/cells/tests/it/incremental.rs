//! The incremental skeletons (sec. 3.9.2) against a fresh visibility query
//! at the representative point of every cell of every dimension: every
//! polyomino map up to 6 cells (orthogonal, full of collinear edges and
//! rays through several vertices), every family at small parameters, and
//! seeded maps of every random kind (the dataset maps: see `datasets`).

use wai_cells::Decomposition;
use wai_exact::RatPoint;
use wai_gen::{exhaustive_polyomino_maps, Symmetry, FAMILIES, RANDOM_KINDS};
use wai_map::Map;
use wai_visibility::{Skeleton, VisibilityIndex};

/// Every cell of `map` compared; the number of cells, or the first
/// mismatch.
pub fn compare(map: &Map) -> Result<usize, String> {
    let d = Decomposition::new(map);
    let index = VisibilityIndex::new(map);
    let fresh = |p: &RatPoint| {
        let vp = index
            .visibility_polygon(p)
            .expect("interior points have V_p");
        let sk = Skeleton::of(map, &vp).expect("and a skeleton");
        (sk.origin(), sk.key())
    };
    let v = map.vertices();
    let mut count = 0;
    for &f in d.cells() {
        let walked = (v[d.origin_of(f)], d.skeletons()[d.skeleton_of(f)].clone());
        if fresh(d.representative(f)) != walked {
            return Err(format!("2-cell {f} at {}", d.representative(f)));
        }
        count += 1;
    }
    for c in d.lower_cells() {
        let walked = (v[c.origin], d.skeletons()[c.class].clone());
        let at = d.lower_representative(c);
        if fresh(&at) != walked {
            return Err(format!("{:?} at {at}", c.site));
        }
        count += 1;
    }
    Ok(count)
}

fn check_all(maps: impl IntoIterator<Item = Map>) -> (usize, usize) {
    let (mut maps_done, mut cells) = (0, 0);
    for map in maps {
        match compare(&map) {
            Ok(k) => cells += k,
            Err(e) => panic!("map {:?}: the walk and the query differ: {e}", map.name()),
        }
        maps_done += 1;
    }
    (maps_done, cells)
}

#[test]
fn every_polyomino_up_to_6_cells() {
    let (maps, cells) = check_all(exhaustive_polyomino_maps(6, Symmetry::Free));
    assert!(maps > 50 && cells > 1000, "{maps} maps, {cells} cells");
}

#[test]
fn every_family() {
    let maps = FAMILIES.iter().flat_map(|f| {
        (1..=3u32).filter_map(move |k| {
            let params: Vec<u32> = f.params.split(',').map(|_| k + 1).collect();
            wai_gen::family(f.id, &params).ok()
        })
    });
    let (maps, cells) = check_all(maps);
    assert!(maps >= FAMILIES.len(), "{maps} maps, {cells} cells");
}

#[test]
fn seeded_maps_of_every_random_kind() {
    let maps = RANDOM_KINDS.iter().flat_map(|k| {
        (0..6u64).filter_map(move |seed| wai_gen::random(k.id, k.min_n.max(24), seed).ok())
    });
    let (maps, cells) = check_all(maps);
    assert_eq!(maps, RANDOM_KINDS.len() * 6, "{cells} cells");
}

/// What a decomposition computed, for comparing two runs.
type Snapshot = (
    wai_cells::Counts,
    Vec<(usize, usize)>,
    Vec<wai_cells::LowerCell>,
    Vec<wai_visibility::SkeletonKey>,
);

fn snapshot(map: &Map) -> Snapshot {
    let d = Decomposition::new(map);
    let cells = d
        .cells()
        .iter()
        .map(|&f| (d.skeleton_of(f), d.origin_of(f)))
        .collect();
    (
        d.counts(),
        cells,
        d.lower_cells().to_vec(),
        d.skeletons().to_vec(),
    )
}

fn pool(threads: usize) -> rayon::ThreadPool {
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("a thread pool")
}

/// The walk splits the cells into one part per thread, each walked from
/// its own queries: one thread and four give the same decomposition (the
/// same classes in the same order, origins and lower cells), and with four
/// every cell of every dimension still equals a fresh query.
#[test]
fn threads_do_not_change_the_decomposition() {
    let maps = [
        wai_gen::family("comb-convex-chain", &[16]).expect("a family map"),
        wai_gen::random("random-orthogonal", 120, 3).expect("a random map"),
        wai_gen::random("random-simple-star", 40, 5).expect("a random map"),
    ];
    for map in &maps {
        let one = pool(1).install(|| snapshot(map));
        let four = pool(4).install(|| snapshot(map));
        assert!(
            one.1.len() >= 4 * 256,
            "{} cells: too few for 4 parts",
            one.1.len()
        );
        assert!(one == four, "1 and 4 threads differ on {:?}", map.name());
        pool(4)
            .install(|| compare(map))
            .unwrap_or_else(|e| panic!("{:?}: {e}", map.name()));
    }
}
