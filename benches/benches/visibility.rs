//! One visibility query (V_p by triangular expansion, preprocessing
//! excluded) on random simple and random orthogonal maps of growing n,
//! and the same queries through CGAL's `Triangular_expansion_visibility_2`
//! when its peer is built (`benches/peers/build.sh`). Ids:
//! `visibility/{ours,cgal-exact,cgal-lazy}/{random-simple-star,random-orthogonal}/n=N`.
//!
//! Ours: point location, expansion and the exact rational vertices of
//! V_p with their classification. CGAL (timed inside the peer process with
//! `iter_custom`, so no pipe is timed): `compute_visibility` after point
//! location (done once per viewpoint, outside the timing); `cgal-exact`
//! also forces the exact value of every output coordinate, the fair
//! comparison for exact output; `cgal-lazy` leaves Epeck's lazy values.

// The allocator of every binary of the workspace (see Cargo.toml).
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::time::Duration;
use wai_benches::cgal::CgalPeer;
use wai_benches::viewpoints::interior_viewpoints;
use wai_map::Map;
use wai_visibility::VisibilityIndex;

const SIZES: &[usize] = &[10, 100, 1000, 4000, 10_000];

fn maps() -> Vec<(&'static str, usize, Map)> {
    let mut out = Vec::new();
    for &n in SIZES {
        out.push((
            "random-simple-star",
            n,
            wai_gen::random("random-simple-star", n, 1).unwrap(),
        ));
        out.push((
            "random-orthogonal",
            n,
            wai_gen::random("random-orthogonal", n, 1).unwrap(),
        ));
    }
    out
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("visibility");
    g.sample_size(20)
        .measurement_time(Duration::from_secs(3))
        .warm_up_time(Duration::from_secs(1));
    let mut rng = ChaCha8Rng::seed_from_u64(7);
    let mut peer = if wai_benches::cgal::available() {
        CgalPeer::spawn().ok()
    } else {
        eprintln!("CGAL peer not built (benches/peers/build.sh): timing ours only");
        None
    };
    for (kind, n, map) in maps() {
        let index = VisibilityIndex::new(&map);
        let views = interior_viewpoints(&map, 16, rng.random());
        let mut k = 0;
        g.bench_with_input(
            BenchmarkId::new(format!("ours/{kind}"), format!("n={n}")),
            &(),
            |b, _| {
                b.iter(|| {
                    k = (k + 1) % views.len();
                    std::hint::black_box(index.visibility_polygon(&views[k]).unwrap())
                })
            },
        );
        let Some(peer) = peer.as_mut() else { continue };
        peer.set_polygon(map.vertices(), map.scale())
            .expect("CGAL accepts the map");
        for (label, exact) in [("cgal-exact", true), ("cgal-lazy", false)] {
            let id = BenchmarkId::new(format!("{label}/{kind}"), format!("n={n}"));
            g.bench_with_input(id, &(), |b, _| {
                b.iter_custom(|iters| {
                    // Spread the iterations over the viewpoints; the peer
                    // reports the median per query of each batch.
                    let per = u32::try_from(iters.div_ceil(views.len() as u64))
                        .unwrap_or(u32::MAX)
                        .max(1);
                    let total: u64 = views
                        .iter()
                        .map(|q| {
                            let ns = if exact {
                                peer.bench_exact(q, per)
                            } else {
                                peer.bench(q, per)
                            };
                            ns.expect("CGAL answers") * u64::from(per)
                        })
                        .sum();
                    Duration::from_nanos(total * iters / (u64::from(per) * views.len() as u64))
                })
            });
        }
    }
    g.finish();
}

/// V_p and V*_p (with its canonical key) from a viewpoint near every vertex
/// of a 1 000-vertex map, preprocessing excluded: the loop over all
/// vertices is one iteration. Id `skeleton/every-vertex/{kind}/n=1000`.
fn every_vertex(c: &mut Criterion) {
    let mut g = c.benchmark_group("skeleton");
    g.sample_size(10).measurement_time(Duration::from_secs(5));
    for kind in ["random-simple-star", "random-orthogonal"] {
        let map = wai_gen::random(kind, 1000, 1).unwrap();
        let index = VisibilityIndex::new(&map);
        let views = wai_benches::viewpoints::near_vertices(&map);
        let id = BenchmarkId::new(format!("every-vertex/{kind}"), format!("n={}", map.n()));
        g.bench_with_input(id, &(), |b, _| {
            b.iter(|| {
                views
                    .iter()
                    .map(|p| {
                        let vp = index.visibility_polygon(p).unwrap();
                        let sk = wai_visibility::Skeleton::of(&map, &vp).unwrap();
                        std::hint::black_box(sk.key()).offsets.len()
                    })
                    .sum::<usize>()
            })
        });
    }
    g.finish();
}

criterion_group!(benches, bench, every_vertex);
criterion_main!(benches);
