//! The decomposition (rays, arrangement, the skeleton of every cell of
//! every dimension, classes) of thesis-size and family maps, ids
//! `decompose/{map}/{param}`; and the sec. 3.6 boundary assignment, which
//! the decomposition no longer needs, on its own: `assignment/{map}/{param}`.

// The allocator of every binary of the workspace (see Cargo.toml).
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

use criterion::{criterion_group, criterion_main, BatchSize, BenchmarkId, Criterion, Throughput};
use std::time::Duration;
use wai_cells::{visibility_rays, Arrangement, Decomposition};
use wai_map::Map;

fn maps() -> Vec<(String, String, Map)> {
    vec![
        (
            "banana".into(),
            "n=76,r=54".into(),
            wai_benches::maps::banana(20, 56),
        ),
        (
            "random-orthogonal".into(),
            "n=76".into(),
            wai_gen::random("random-orthogonal", 76, 1).unwrap(),
        ),
        (
            "corridor-niches".into(),
            "k=16".into(),
            wai_gen::family("corridor-niches", &[16]).unwrap(),
        ),
        (
            "comb-convex-chain".into(),
            "k=16".into(),
            wai_gen::family("comb-convex-chain", &[16]).unwrap(),
        ),
        (
            "comb-convex-chain".into(),
            "k=64".into(),
            wai_gen::family("comb-convex-chain", &[64]).unwrap(),
        ),
    ]
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("decompose");
    g.sample_size(10).measurement_time(Duration::from_secs(5));
    for (name, param, map) in maps() {
        let counts = Decomposition::new(&map).counts();
        eprintln!(
            "decompose/{name}/{param}: n = {}, r = {}, cells = {}, N = {}",
            counts.n, counts.r, counts.cells, counts.total_complexity
        );
        // Throughput in 2-cells per second, the sweep's measure.
        g.throughput(Throughput::Elements(counts.cells as u64));
        g.bench_with_input(BenchmarkId::new(&name, &param), &map, |b, m| {
            b.iter(|| {
                let d = Decomposition::new(m);
                (d.cells().len(), d.classes().len(), d.lower_cells().len())
            })
        });
    }
    g.finish();
    let mut g = c.benchmark_group("assignment");
    g.sample_size(10).measurement_time(Duration::from_secs(3));
    for (name, param, map) in maps() {
        let rays = visibility_rays(&map);
        g.bench_with_input(BenchmarkId::new(name, param), &map, |b, m| {
            b.iter_batched(
                || Arrangement::new(m, &rays),
                |a| a.conflicts().len(),
                BatchSize::LargeInput,
            )
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
