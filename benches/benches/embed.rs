//! The embeddings (Def 3.11) of every class's skeleton, with candidate
//! edges and kernels, ids `embed/{map}/{param}` (the aim: all embeddings
//! of all classes of the thesis-size map in ≤ 1 s). The decomposition is
//! built once, outside the measurement.

// The allocator of every binary of the workspace (see Cargo.toml).
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use std::time::Duration;
use wai_cells::Decomposition;
use wai_embed::Embedder;
use wai_visibility::VisibilityIndex;

fn bench(c: &mut Criterion) {
    let maps = wai_benches::maps::thesis_size();
    let mut g = c.benchmark_group("embed");
    g.sample_size(10).measurement_time(Duration::from_secs(5));
    for (name, param, map) in &maps {
        let keys = Decomposition::new(map).skeletons().to_vec();
        let total: usize = {
            let index = VisibilityIndex::new(map);
            let e = Embedder::new(&index);
            keys.iter().map(|k| e.embeddings(k).len()).sum()
        };
        eprintln!(
            "embed/{name}/{param}: {} skeletons, {total} embeddings",
            keys.len()
        );
        // Throughput in skeletons per second.
        g.throughput(Throughput::Elements(keys.len() as u64));
        g.bench_with_input(BenchmarkId::new(*name, *param), map, |b, m| {
            b.iter(|| {
                let index = VisibilityIndex::new(m);
                let e = Embedder::new(&index);
                keys.iter()
                    .map(|k| {
                        e.embeddings(k)
                            .iter()
                            .map(|h| h.kernel(m).vertices().len())
                            .sum::<usize>()
                    })
                    .sum::<usize>()
            })
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
