//! The fast predicates against their GMP versions in `wai_exact::reference`,
//! on one seeded batch of 1024 inputs with coordinates below `2^20`.
//!
//! Ids: `predicates/<predicate>/{fast,rug}`; each iteration runs the whole
//! batch.

// The allocator of every binary of the workspace (see Cargo.toml).
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::time::Duration;
use wai_exact::{
    compare_intersections_along, orientation, reference, side_of_intersection, Line, Point,
};

const BATCH: usize = 1024;
const COORD: i128 = 1 << 20;

fn point(rng: &mut ChaCha8Rng) -> Point {
    Point::new(
        rng.random_range(-COORD + 1..COORD),
        rng.random_range(-COORD + 1..COORD),
    )
}

fn line(rng: &mut ChaCha8Rng) -> Line {
    loop {
        if let Some(l) = Line::new(point(rng), point(rng)) {
            return l;
        }
    }
}

fn bench(c: &mut Criterion) {
    let mut rng = ChaCha8Rng::seed_from_u64(1);
    let triples: Vec<[Point; 3]> = (0..BATCH)
        .map(|_| [point(&mut rng), point(&mut rng), point(&mut rng)])
        .collect();
    let lines: Vec<[Line; 3]> = (0..BATCH)
        .map(|_| [line(&mut rng), line(&mut rng), line(&mut rng)])
        .collect();

    let mut g = c.benchmark_group("predicates");
    g.measurement_time(Duration::from_secs(3)).sample_size(30);
    g.bench_function("orientation/fast", |b| {
        b.iter(|| {
            for [p, q, r] in black_box(&triples) {
                black_box(orientation(*p, *q, *r));
            }
        })
    });
    g.bench_function("orientation/rug", |b| {
        b.iter(|| {
            for [p, q, r] in black_box(&triples) {
                black_box(reference::orientation(*p, *q, *r));
            }
        })
    });
    g.bench_function("side_of_intersection/fast", |b| {
        b.iter(|| {
            for [l3, l1, l2] in black_box(&lines) {
                black_box(side_of_intersection(l3, l1, l2));
            }
        })
    });
    g.bench_function("side_of_intersection/rug", |b| {
        b.iter(|| {
            for [l3, l1, l2] in black_box(&lines) {
                black_box(reference::side_of_intersection(l3, l1, l2));
            }
        })
    });
    g.bench_function("compare_intersections_along/fast", |b| {
        b.iter(|| {
            for [l0, l1, l2] in black_box(&lines) {
                black_box(compare_intersections_along(l0, l1, l2));
            }
        })
    });
    g.bench_function("compare_intersections_along/rug", |b| {
        b.iter(|| {
            for [l0, l1, l2] in black_box(&lines) {
                black_box(reference::compare_intersections_along(l0, l1, l2));
            }
        })
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
