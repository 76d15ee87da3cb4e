//! The per-map pipeline the search lives on: a [`wai_study::Study`] of one
//! small map and every claim checker over it (`wai_hunt::run`), on the
//! first maps of each kind `wai check --maps all` draws, ids
//! `study/{kind}/{map}`. A kind's maps are the stream's own (seed 1), so a
//! regression here is one `wai check` would feel.

// The allocator of every binary of the workspace (see Cargo.toml).
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use std::time::Duration;
use wai_hunt::stream::{parse_kinds, MapKind, Stream};

/// Maps per kind: a few, so that a kind's figure is not one map's; one of
/// a layout, whose maps take seconds each.
fn maps_per_kind(kind: &MapKind) -> u64 {
    match kind {
        MapKind::Layout(_) => 1,
        _ => 4,
    }
}

fn bench(c: &mut Criterion) {
    let checkers: Vec<_> = wai_lemmas::checkers().collect();
    let mut g = c.benchmark_group("study");
    g.sample_size(10).measurement_time(Duration::from_secs(4));
    for spec in parse_kinds("all").expect("the group all") {
        let kind = spec.kind.id();
        let count = maps_per_kind(&spec.kind);
        let stream = Stream::Generated {
            kinds: vec![spec],
            seed: 1,
        };
        let maps: Vec<_> = (0..count)
            .map_while(|i| stream.map(i).map(|(_, m)| m))
            .collect();
        let n: usize = maps.iter().map(|m| m.n()).sum();
        g.throughput(Throughput::Elements(maps.len() as u64));
        let label = format!("{}maps,n={n}", maps.len());
        g.bench_with_input(BenchmarkId::new(kind, label), &maps, |b, maps| {
            b.iter(|| wai_hunt::run(&checkers, maps).maps)
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
