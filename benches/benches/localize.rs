//! The exact reference localizer (Algs 3.13–3.14), ids `localize/{stage}/{map}`:
//! preprocessing (Alg 3.14: decomposition and one overlay per class),
//! the query (Alg 3.13) over a fixed set of simulated views (alone, and
//! with V's input check), and the brute-force and one-shot oracles on
//! the same views in the same run as the reference points. Query throughput is in queries per second: the median time per
//! query is the iteration median divided by the number of views.

// The allocator of every binary of the workspace (see Cargo.toml).
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use std::time::Duration;
use wai_localize::{oracle, Localizer, RobotView};
use wai_visibility::VisibilityIndex;

fn bench(c: &mut Criterion) {
    let mut maps = wai_benches::maps::thesis_size();
    maps.push((
        "random-orthogonal",
        "n=500",
        wai_gen::random("random-orthogonal", 500, 1).unwrap(),
    ));
    let mut g = c.benchmark_group("localize");
    g.sample_size(10).measurement_time(Duration::from_secs(5));
    for (name, param, map) in &maps {
        let id = format!("{name}/{param}");
        let loc = Localizer::new(map);
        let (items, traps) = (loc.cells(), loc.trapezoids());
        let vs = wai_benches::viewpoints::robot_views(map, 200, 1);
        let m: usize = vs.iter().map(|v| v.vertices().len()).sum::<usize>() / vs.len();
        let a: usize = vs.iter().map(|v| loc.localize(v).placements.len()).sum();
        eprintln!(
            "localize/{id}: {} classes, {items} cells, {traps} trapezoids; {} views, mean m = {m}, {a} answers",
            loc.classes(),
            vs.len()
        );
        if map.n() <= 100 {
            g.throughput(Throughput::Elements(1));
            g.bench_with_input(BenchmarkId::new("preprocess", &id), map, |b, m| {
                b.iter(|| Localizer::new(m).classes())
            });
        }
        g.throughput(Throughput::Elements(vs.len() as u64));
        g.bench_with_input(BenchmarkId::new("query", &id), &vs, |b, vs| {
            b.iter(|| {
                vs.iter()
                    .map(|v| loc.localize(v).placements.len())
                    .sum::<usize>()
            })
        });
        // The same with V's input check (as `wai localize --polygon` does),
        // from a copy of its vertices.
        g.bench_with_input(BenchmarkId::new("check-and-query", &id), &vs, |b, vs| {
            b.iter(|| {
                vs.iter()
                    .map(|v| {
                        let checked = RobotView::new(v.vertices().to_vec()).expect("a true V");
                        loc.localize(&checked).placements.len()
                    })
                    .sum::<usize>()
            })
        });
        let index = VisibilityIndex::new(map);
        g.bench_with_input(BenchmarkId::new("brute-force", &id), &vs, |b, vs| {
            b.iter(|| {
                vs.iter()
                    .map(|v| oracle::brute_force(&index, v).len())
                    .sum::<usize>()
            })
        });
        g.bench_with_input(BenchmarkId::new("one-shot", &id), &vs, |b, vs| {
            b.iter(|| {
                vs.iter()
                    .map(|v| oracle::one_shot(index.map(), v).positions.len())
                    .sum::<usize>()
            })
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
