//! The cell count of maps with holes against n²r² (thesis sec. 6.4: with
//! holes, Ω(n²r²) cells become possible, where a map without holes has
//! O(n²r)): `wai_gen::pillar_rays(k)` — a square room with k × k
//! triangular pillars — decomposed for k = 1..=K, with n, r, the rays, the
//! cells of every dimension, the time, and the least-squares slope of
//! ln(cells) against ln(n²r²) and against ln(n²r).
//!
//! `cargo run --release -p wai-benches --bin pillar_rays -- [--max-k K]`
//! (default 4). Prints a Markdown table.

#![allow(
    clippy::float_arithmetic,
    reason = "ratios and fitted slopes for the printed table; the counts are exact"
)]

// The allocator of every binary of the workspace (see Cargo.toml).
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

use std::time::Instant;
use wai_cells::Decomposition;

const USAGE: &str = "\
pillar_rays: cells of a room with a row of k triangular pillars below a convex chain of k
vertices (wai_gen::pillar_rays), k = 1..=K, against n^2 r^2 and n^2 r

Usage: pillar_rays [--max-k K]   (default 4)
";

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let mut max_k = 4u32;
    let mut it = args.iter();
    while let Some(a) = it.next() {
        match a.as_str() {
            "-h" | "--help" => {
                print!("{USAGE}");
                return;
            }
            "--max-k" => match it.next().and_then(|v| v.parse().ok()) {
                Some(k) if k >= 2 => max_k = k,
                _ => {
                    eprintln!("pillar_rays: --max-k needs an integer of at least 2\n{USAGE}");
                    std::process::exit(2);
                }
            },
            other => {
                eprintln!("pillar_rays: unknown argument {other:?}\n{USAGE}");
                std::process::exit(2);
            }
        }
    }
    println!("| k | n | r | holes | rays | cells | cells / n²r² | seconds |");
    println!("|--:|--:|--:|--:|--:|--:|--:|--:|");
    let mut points: Vec<(f64, f64, f64)> = Vec::new();
    for k in 1..=max_k {
        let map = wai_gen::pillar_rays(k);
        let t = Instant::now();
        let d = Decomposition::new(&map);
        let secs = t.elapsed().as_secs_f64();
        let c = d.counts();
        let (n, r) = (c.n as f64, c.r as f64);
        let cells = c.cells as f64;
        println!(
            "| {k} | {} | {} | {} | {} | {} | {:.4} | {secs:.1} |",
            c.n,
            c.r,
            map.hole_count(),
            d.arrangement().rays().len(),
            c.cells,
            cells / (n * n * r * r),
        );
        points.push(((n * n * r * r).ln(), (n * n * r).ln(), cells.ln()));
    }
    let slope = |x: &dyn Fn(&(f64, f64, f64)) -> f64| {
        let m = points.len() as f64;
        let (sx, sy) = points
            .iter()
            .fold((0.0, 0.0), |(a, b), p| (a + x(p), b + p.2));
        let (mx, my) = (sx / m, sy / m);
        let (num, den) = points.iter().fold((0.0, 0.0), |(a, b), p| {
            (a + (x(p) - mx) * (p.2 - my), b + (x(p) - mx) * (x(p) - mx))
        });
        num / den
    };
    println!();
    println!(
        "Least-squares slope of ln(cells) against ln(n²r²): {:.3}; against ln(n²r): {:.3} (k = 1..={max_k}).",
        slope(&|p| p.0),
        slope(&|p| p.1)
    );
}
