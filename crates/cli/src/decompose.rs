//! `wai decompose`: the visibility cell decomposition of a map, its counts,
//! and a picture of the cells coloured by equivalence class.

use crate::failure::{counted_bar, Failure};
use crate::input::load_with_holes;
use std::path::PathBuf;
use wai_cells::{visibility_rays, Decomposition};
use wai_render::{cells_svg, MapStyle};

#[derive(clap::Args, Debug)]
pub struct Args {
    #[arg(help = crate::input::MAP_HELP)]
    pub map: PathBuf,
    /// Print JSON instead of text.
    #[arg(long)]
    pub json: bool,
    /// Draw the cells coloured by class into this SVG file.
    #[arg(long)]
    pub svg: Option<PathBuf>,
    /// With --svg: highlight this class (an index printed by --json).
    #[arg(long, value_parser = crate::options::count, allow_negative_numbers = true)]
    pub class: Option<usize>,
    #[command(flatten)]
    pub memory: crate::budget::MemoryArgs,
    #[command(flatten)]
    pub format: crate::input::FormatArg,
}

pub fn run(args: &Args) -> Result<(), Failure> {
    let (path, opts) = (&args.map, args);
    let loaded = load_with_holes(path, args.format)?;
    let map = &loaded.map;
    // The time covers the whole decomposition, rays included.
    let start = std::time::Instant::now();
    // The stages before the walk have no count to show: a spinner names
    // the stage and the time it has taken, until the walk's bar starts.
    let stage = stage_spinner("visibility rays");
    let rays = visibility_rays(map);
    crate::budget::check_decomposition(map, &rays, &opts.memory)?;
    stage.set_message(format!(
        "arrangement of {} rays and the map's {} edges",
        rays.len(),
        map.n()
    ));
    let mut bar: Option<indicatif::ProgressBar> = None;
    let d = Decomposition::from_rays(map, rays, &mut |done, total| {
        let bar = bar.get_or_insert_with(|| {
            stage.finish_and_clear();
            counted_bar("skeletons of cells", "cells of every dimension")
        });
        bar.set_length(total as u64);
        bar.set_position(done as u64);
    });
    stage.finish_and_clear();
    if let Some(bar) = bar {
        bar.finish_and_clear();
    }
    let elapsed = start.elapsed();
    let c = d.counts();
    if let Some(k) = opts.class {
        if k >= d.classes().len() {
            return Err(Failure::usage(format!(
                "--class {k}: the map has {} classes (0 to {})",
                d.classes().len(),
                d.classes().len().saturating_sub(1)
            )));
        }
    }
    if opts.json {
        let sizes: Vec<usize> = d.classes().iter().map(Vec::len).collect();
        let complexity: Vec<usize> = (0..d.classes().len())
            .map(|i| d.class_complexity(i))
            .collect();
        let v = serde_json::json!({
            "name": map.name(),
            "n": c.n, "r": c.r, "rays": c.rays,
            "arrangement": {"vertices": c.vertices, "edges": c.edges},
            "cells": c.cells,
            "total_complexity": c.total_complexity,
            "classes": c.classes,
            "max_class_complexity": c.max_class_complexity,
            "assignment_conflicts": c.conflicts,
            "cells_by_dimension": {
                "2": {"kept": c.cells, "absorbed": 0},
                "1": {"kept": c.one_cells.kept, "absorbed": c.one_cells.absorbed},
                "0": {"kept": c.zero_cells.kept, "absorbed": c.zero_cells.absorbed},
            },
            "class_cells": sizes,
            "class_complexity": complexity,
            "seconds": elapsed.as_secs_f64(),
            "peak_memory_bytes": peak_memory_bytes(),
        });
        outln!("{}", serde_json::to_string_pretty(&v).expect("plain JSON"));
    } else {
        outln!(
            "map:                 {} (n = {}, r = {})",
            map.name().unwrap_or("-"),
            c.n,
            c.r
        );
        outln!("visibility rays:     {}", c.rays);
        outln!(
            "arrangement:         {} vertices, {} edges",
            c.vertices,
            c.edges
        );
        outln!("cells:               {} (2-cells)", c.cells);
        outln!(
            "1-cells, 0-cells:    {} and {} kept as cells of their own; {} and {} absorbed by a 2-cell",
            c.one_cells.kept, c.zero_cells.kept, c.one_cells.absorbed, c.zero_cells.absorbed
        );
        outln!("total complexity N:  {}", c.total_complexity);
        outln!("classes:             {}", c.classes);
        outln!("max |EC|:            {}", c.max_class_complexity);
        outln!("assignment conflicts:{:>4} (boundary pieces two rays assign to different sides; see `wai_cells::Conflict`)", c.conflicts);
        outln!("time:                {:.3} s", elapsed.as_secs_f64());
        match peak_memory_bytes() {
            Some(b) => outln!(
                "peak memory:         {} MiB (resident, whole process)",
                b.div_ceil(1 << 20)
            ),
            None => outln!("peak memory:         unknown (no /proc/self/status)"),
        }
    }
    if let Some(out) = opts.svg.as_deref() {
        let cells = cell_rings(&d);
        let caption = format!(
            "{} 2-cells, {} kept 1-cells and {} kept 0-cells in {} classes{}",
            c.cells,
            c.one_cells.kept,
            c.zero_cells.kept,
            c.classes,
            opts.class.map_or(String::new(), |k| format!(
                "; class {k} ({} cells) in red",
                d.classes()[k].len()
            ))
        );
        let lower = kept_lower_cells(&d);
        let svg = cells_svg(
            map,
            &cells,
            &lower,
            opts.class,
            &MapStyle::default(),
            &caption,
        );
        std::fs::write(out, svg).map_err(|e| Failure::io(format!("{}: {e}", out.display())))?;
    }
    Ok(())
}

/// The 2-cells of `d` as exact rings with their classes, to draw.
pub(crate) fn cell_rings(d: &Decomposition<'_>) -> Vec<(Vec<wai_exact::RatPoint>, usize)> {
    d.cells()
        .iter()
        .map(|&f| (d.arrangement().face_points(f), d.skeleton_of(f)))
        .collect()
}

/// The kept 1- and 0-cells of `d`, to draw.
pub(crate) fn kept_lower_cells(d: &Decomposition<'_>) -> Vec<wai_render::LowerDrawn> {
    let arr = d.arrangement();
    d.lower_cells()
        .iter()
        .filter(|l| l.absorbed_by.is_none())
        .map(|l| wai_render::LowerDrawn {
            points: match l.site {
                wai_cells::LowerSite::Edge(e) => vec![
                    arr.point(arr.half_edge(2 * e).origin).clone(),
                    arr.point(arr.dest(2 * e)).clone(),
                ],
                wai_cells::LowerSite::Vertex(v) => vec![arr.point(v).clone()],
            },
            class: l.class,
        })
        .collect()
}

/// The process's peak resident memory so far (`VmHWM` of
/// `/proc/self/status`, Linux), in bytes; `None` where it cannot be read.
fn peak_memory_bytes() -> Option<u64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    let kib: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kib * 1024)
}

/// A spinner on standard error with `what` and the time spent on it,
/// ticking on its own while a stage runs.
fn stage_spinner(what: &str) -> indicatif::ProgressBar {
    let spinner = indicatif::ProgressBar::new_spinner();
    spinner.set_style(
        indicatif::ProgressStyle::with_template("{spinner} {msg} ({elapsed})")
            .unwrap_or_else(|_| indicatif::ProgressStyle::default_spinner()),
    );
    spinner.set_message(what.to_owned());
    spinner.enable_steady_tick(std::time::Duration::from_millis(200));
    spinner
}
