//! The scaling sweep: grow each thesis family and random and orthogonal
//! maps, decompose each exactly, and write CSV plus SVG plots — cells
//! against r, max |EC| against n + r², decomposition time against N, the
//! localizer's overlay time and size against N(n + r²) and its median
//! query time against m and A — with fitted log–log slopes, the commit and
//! the date on every plot.
//!
//! `cargo run --release -p wai-benches --bin sweep -- [--out DIR] [--quick]`

#![allow(
    clippy::float_arithmetic,
    reason = "plots, fits and timings are output only"
)]

// The allocator of every binary of the workspace (see Cargo.toml).
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

use plotters::prelude::*;
use std::io::Write;
use std::path::PathBuf;
use std::time::Instant;
use wai_cells::Decomposition;
use wai_localize::Localizer;
use wai_map::Map;

/// One decomposed map.
struct Row {
    series: String,
    param: u32,
    n: usize,
    r: usize,
    rays: usize,
    cells: usize,
    total: usize,
    classes: usize,
    max_ec: usize,
    largest_class_cells: usize,
    seconds: f64,
    /// The localizer's overlays (Alg 3.14 steps 18–23), after the
    /// decomposition: seconds, and size (cells placed plus trapezoid label
    /// entries, the structure's memory in units).
    overlay_seconds: f64,
    overlay_size: usize,
    /// Median query time (Alg 3.13) over random views, microseconds; the
    /// views' mean vertex count m and mean answer count A.
    query_us: f64,
    mean_m: f64,
    mean_a: f64,
}

/// Views from `count` random points (denominators 1 to 8) and the median
/// over them of the mean time of `reps` queries, with the mean m and A.
fn query_times(map: &Map, loc: &Localizer, count: usize, reps: u32) -> (f64, f64, f64) {
    let views = wai_benches::viewpoints::robot_views(map, count, 1);
    if views.is_empty() {
        return (0.0, 0.0, 0.0);
    }
    let mut times: Vec<f64> = Vec::with_capacity(views.len());
    let mut answers = 0usize;
    for v in &views {
        let t = Instant::now();
        for _ in 0..reps {
            answers += std::hint::black_box(loc.localize(v)).placements.len();
        }
        times.push(t.elapsed().as_secs_f64() * 1e6 / f64::from(reps));
    }
    times.sort_by(f64::total_cmp);
    let k = views.len() as f64;
    let m = views.iter().map(|v| v.vertices().len()).sum::<usize>() as f64 / k;
    (
        times[times.len() / 2],
        m,
        answers as f64 / (k * f64::from(reps)),
    )
}

fn series(quick: bool) -> Vec<(String, Vec<(u32, Map)>)> {
    let fam = |id: &str, params: &[u32]| {
        let maps = params
            .iter()
            .map(|&k| {
                (
                    k,
                    wai_gen::family(id, &[k]).expect("family parameters are valid"),
                )
            })
            .collect();
        (id.to_string(), maps)
    };
    let rnd = |kind: &str, ns: &[u32]| {
        let maps = ns
            .iter()
            .map(|&n| {
                (
                    n,
                    wai_gen::random(kind, n as usize, 1).expect("random kind sizes are valid"),
                )
            })
            .collect();
        (kind.to_string(), maps)
    };
    if quick {
        return vec![
            fam("corridor-niches", &[1, 2, 4, 8]),
            fam("comb-convex-chain", &[2, 3, 4, 6]),
            rnd("random-simple-star", &[10, 20, 40]),
            rnd("random-orthogonal", &[10, 20, 40]),
        ];
    }
    vec![
        fam("corridor-niches", &[1, 2, 4, 8, 16, 32]),
        fam(
            "comb-convex-chain",
            &[2, 3, 4, 6, 8, 11, 16, 23, 32, 45, 64],
        ),
        fam("overlap-fan", &[0, 1, 2, 3]),
        fam("convex-niches", &[1, 2, 3, 4, 6]),
        rnd("random-simple-star", &[10, 20, 40, 80, 160]),
        rnd("random-orthogonal", &[10, 20, 40, 80, 160, 320]),
    ]
}

/// Least-squares slope of log y against log x.
fn slope(points: &[(f64, f64)]) -> Option<f64> {
    let pts: Vec<(f64, f64)> = points
        .iter()
        .filter(|(x, y)| *x > 0.0 && *y > 0.0)
        .map(|(x, y)| (x.ln(), y.ln()))
        .collect();
    if pts.len() < 2 {
        return None;
    }
    let m = pts.len() as f64;
    let (sx, sy) = pts.iter().fold((0.0, 0.0), |(a, b), (x, y)| (a + x, b + y));
    let (mx, my) = (sx / m, sy / m);
    let (num, den) = pts.iter().fold((0.0, 0.0), |(n, d), (x, y)| {
        (n + (x - mx) * (y - my), d + (x - mx) * (x - mx))
    });
    (den > 0.0).then(|| num / den)
}

fn stamp() -> String {
    let commit = std::process::Command::new("git")
        .args(["rev-parse", "--short", "HEAD"])
        .output()
        .ok()
        .filter(|o| o.status.success())
        .map(|o| String::from_utf8_lossy(&o.stdout).trim().to_string())
        .unwrap_or_else(|| "unknown".into());
    let days = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map(|d| d.as_secs() / 86_400)
        .unwrap_or(0) as i64;
    // Civil date from days since 1970-01-01 (Howard Hinnant's algorithm).
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z - era * 146_097;
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = doy - (153 * mp + 2) / 5 + 1;
    let m = if mp < 10 { mp + 3 } else { mp - 9 };
    let y = yoe + era * 400 + i64::from(m <= 2);
    format!("commit {commit}, {y:04}-{m:02}-{d:02}")
}

/// A log–log scatter plot, one colour per series, with each series' slope in
/// the legend.
fn plot(
    path: &PathBuf,
    title: &str,
    xl: &str,
    yl: &str,
    data: &[(String, Vec<(f64, f64)>)],
    foot: &str,
) -> Result<(), String> {
    let all: Vec<(f64, f64)> = data
        .iter()
        .flat_map(|(_, p)| p.iter().copied())
        .filter(|(x, y)| *x > 0.0 && *y > 0.0)
        .collect();
    if all.is_empty() {
        return Ok(());
    }
    let (x0, x1) = all.iter().fold((f64::MAX, f64::MIN), |(a, b), (x, _)| {
        (a.min(*x), b.max(*x))
    });
    let (y0, y1) = all.iter().fold((f64::MAX, f64::MIN), |(a, b), (_, y)| {
        (a.min(*y), b.max(*y))
    });
    let root = SVGBackend::new(path, (900, 640)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| e.to_string())?;
    let (main, footer) = root.split_vertically(610);
    footer
        .draw(&Text::new(
            foot.to_string(),
            (10, 5),
            ("sans-serif", 14).into_font(),
        ))
        .map_err(|e| e.to_string())?;
    let mut chart = ChartBuilder::on(&main)
        .caption(title, ("sans-serif", 20))
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(60)
        .build_cartesian_2d(
            (x0 * 0.8..x1 * 1.25).log_scale(),
            (y0 * 0.8..y1 * 1.25).log_scale(),
        )
        .map_err(|e| e.to_string())?;
    chart
        .configure_mesh()
        .x_desc(xl)
        .y_desc(yl)
        .draw()
        .map_err(|e| e.to_string())?;
    for (i, (name, pts)) in data.iter().enumerate() {
        let colour = Palette99::pick(i).to_rgba();
        let label = match slope(pts) {
            Some(s) => format!("{name} (slope {s:.2})"),
            None => name.clone(),
        };
        chart
            .draw_series(LineSeries::new(pts.iter().copied(), colour.stroke_width(2)).point_size(3))
            .map_err(|e| e.to_string())?
            .label(label)
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 16, y)], colour.stroke_width(2))
            });
    }
    chart
        .configure_series_labels()
        .border_style(BLACK)
        .background_style(WHITE.mix(0.9))
        .position(SeriesLabelPosition::UpperLeft)
        .draw()
        .map_err(|e| e.to_string())?;
    root.present().map_err(|e| e.to_string())
}

const USAGE: &str = "\
sweep: grow each thesis family and random maps, decompose each exactly, and
write CSV plus SVG plots with fitted log-log slopes

usage: sweep [--out DIR] [--quick]
  --out DIR   where the CSV and plots go (default target/sweep)
  --quick     the reduced series CI runs
  -h, --help  this text";

fn main() {
    let args: Vec<String> = std::env::args().collect();
    if args.iter().any(|a| a == "-h" || a == "--help") {
        println!("{USAGE}");
        return;
    }
    let quick = args.iter().any(|a| a == "--quick");
    let out = args
        .iter()
        .position(|a| a == "--out")
        .and_then(|i| args.get(i + 1))
        .map_or_else(|| PathBuf::from("target/sweep"), PathBuf::from);
    std::fs::create_dir_all(&out).expect("output folder");
    let mut rows: Vec<Row> = Vec::new();
    let all = series(quick);
    let total: usize = all.iter().map(|(_, m)| m.len()).sum();
    let mut done = 0;
    for (name, maps) in &all {
        for (param, map) in maps {
            done += 1;
            eprint!(
                "\rsweep: {done}/{total} {name} {param} (n = {}, r = {})…        ",
                map.n(),
                map.r()
            );
            let t = Instant::now();
            let d = Decomposition::new(map);
            let seconds = t.elapsed().as_secs_f64();
            let c = d.counts();
            let t = Instant::now();
            let loc = Localizer::from_decomposition(&d);
            let overlay_seconds = t.elapsed().as_secs_f64();
            let overlay_size = (0..loc.classes())
                .map(|k| {
                    let o = loc.overlay(k);
                    o.items.len()
                        + o.slabs
                            .iter()
                            .flat_map(|s| &s.labels)
                            .map(Vec::len)
                            .sum::<usize>()
                })
                .sum();
            let (query_us, mean_m, mean_a) = query_times(map, &loc, 50, 20);
            rows.push(Row {
                series: name.clone(),
                param: *param,
                n: c.n,
                r: c.r,
                rays: c.rays,
                cells: c.cells,
                total: c.total_complexity,
                classes: c.classes,
                max_ec: c.max_class_complexity,
                largest_class_cells: d.classes().iter().map(Vec::len).max().unwrap_or(0),
                seconds,
                overlay_seconds,
                overlay_size,
                query_us,
                mean_m,
                mean_a,
            });
        }
    }
    eprintln!();
    let csv = out.join("sweep.csv");
    let mut f = std::fs::File::create(&csv).expect("csv file");
    writeln!(f, "series,param,n,r,rays,cells,total_complexity,classes,max_class_complexity,largest_class_cells,seconds,overlay_seconds,overlay_size,query_us,mean_m,mean_a").unwrap();
    for r in &rows {
        writeln!(
            f,
            "{},{},{},{},{},{},{},{},{},{},{:.6},{:.6},{},{:.3},{:.1},{:.2}",
            r.series,
            r.param,
            r.n,
            r.r,
            r.rays,
            r.cells,
            r.total,
            r.classes,
            r.max_ec,
            r.largest_class_cells,
            r.seconds,
            r.overlay_seconds,
            r.overlay_size,
            r.query_us,
            r.mean_m,
            r.mean_a
        )
        .unwrap();
    }
    let names: Vec<String> = all.iter().map(|(n, _)| n.clone()).collect();
    let by = |f: &dyn Fn(&Row) -> (f64, f64)| -> Vec<(String, Vec<(f64, f64)>)> {
        names
            .iter()
            .map(|s| {
                (
                    s.clone(),
                    rows.iter().filter(|r| &r.series == s).map(f).collect(),
                )
            })
            .collect()
    };
    let foot = stamp();
    let plots = [
        (
            "cells_vs_r.svg",
            "cells against r",
            "r (reflex vertices)",
            "cells",
            by(&|r: &Row| (r.r as f64, r.cells as f64)),
        ),
        (
            "cells_vs_n2r.svg",
            "cells against n²r (Thm 3.9: O(n²r), tight for comb-convex-chain)",
            "n²r",
            "cells",
            by(&|r: &Row| ((r.n * r.n * r.r) as f64, r.cells as f64)),
        ),
        (
            "max_ec_vs_n_r2.svg",
            "max |EC| against n + r² (Thm 5.17)",
            "n + r²",
            "max |EC|",
            by(&|r: &Row| ((r.n + r.r * r.r) as f64, r.max_ec as f64)),
        ),
        (
            "largest_class_vs_r.svg",
            "cells of the largest class against r (Lemma 3.7: linear for corridor-niches)",
            "r",
            "cells in the largest class",
            by(&|r: &Row| (r.r as f64, r.largest_class_cells as f64)),
        ),
        (
            "time_vs_total.svg",
            "decomposition time against N",
            "N (total complexity)",
            "seconds",
            by(&|r: &Row| (r.total as f64, r.seconds)),
        ),
        (
            "overlay_time_vs_bound.svg",
            "localizer overlays: time against N(n + r²) (C5.18)",
            "N(n + r²)",
            "seconds",
            by(&|r: &Row| ((r.total * (r.n + r.r * r.r)) as f64, r.overlay_seconds)),
        ),
        (
            "overlay_size_vs_bound.svg",
            "localizer overlays: cells placed + trapezoid labels against N(n + r²) (C5.18)",
            "N(n + r²)",
            "size (entries)",
            by(&|r: &Row| ((r.total * (r.n + r.r * r.r)) as f64, r.overlay_size as f64)),
        ),
        (
            "query_vs_m.svg",
            "localization query: median time against the views' mean m (Thm 3.12: O(m + log n + A))",
            "mean m (vertices of V)",
            "median query µs",
            by(&|r: &Row| (r.mean_m, r.query_us)),
        ),
        (
            "query_vs_a.svg",
            "localization query: median time against the mean answer count A",
            "mean A",
            "median query µs",
            by(&|r: &Row| (r.mean_a, r.query_us)),
        ),
    ];
    println!("wrote {}", csv.display());
    for (file, title, xl, yl, data) in &plots {
        let path = out.join(file);
        match plot(&path, title, xl, yl, data, &foot) {
            Ok(()) => println!("wrote {}", path.display()),
            Err(e) => eprintln!("sweep: {}: {e}", path.display()),
        }
        for (name, pts) in data {
            if let Some(s) = slope(pts) {
                // The slope over the three largest maps shows the asymptote
                // once lower-order terms fade.
                let tail = slope(&pts[pts.len().saturating_sub(3)..]).unwrap_or(s);
                println!(
                    "  {file}: {name}: fitted log-log slope {s:.3} (largest three: {tail:.3})"
                );
            }
        }
    }
}
