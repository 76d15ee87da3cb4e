//! `wai embeddings`: the embeddings of every skeleton of a map (Def 3.11),
//! their witnesses and valid candidate edges (Def 4.1), and the pairs of
//! valid embeddings of one skeleton that overlap, with the exact verdict
//! on whether their witnesses see each other (Theorem 4.2).

use crate::failure::{counted_bar, Failure};
use crate::input::load_with_holes;
use crate::vis::show;
use std::path::{Path, PathBuf};
use wai_cells::{Decomposition, LowerSite};
use wai_embed::{CellRef, Mutual, Piece, Witnesses};
use wai_exact::QPoint;
use wai_map::Map;
use wai_render::{embeddings_svg, EmbeddingDrawn, MapStyle};
use wai_study::{Embedded, OverlappingPair, Study};

#[derive(clap::Args, Debug)]
pub struct Args {
    #[arg(help = crate::input::MAP_HELP)]
    pub map: PathBuf,
    /// Only this class (an index printed by `wai decompose --json`).
    #[arg(long, value_parser = crate::options::count, allow_negative_numbers = true)]
    pub class: Option<usize>,
    /// Print JSON instead of text.
    #[arg(long)]
    pub json: bool,
    /// Draw the embedded skeletons, kernels, witnesses and candidate
    /// edges of one class (--class, else the one with the most valid
    /// embeddings) into this SVG file.
    #[arg(long)]
    pub svg: Option<PathBuf>,
    #[command(flatten)]
    pub memory: crate::budget::MemoryArgs,
    #[command(flatten)]
    pub format: crate::input::FormatArg,
}

/// One class, read off the study: its embeddings (with their kernels),
/// witnesses and valid candidate edges, and its overlapping pairs.
struct ClassReport<'s> {
    class: usize,
    embeddings: &'s [Embedded],
    witnesses: &'s [Witnesses],
    valid_candidates: Vec<&'s [Vec<usize>]>,
    overlapping: Vec<&'s OverlappingPair>,
}

fn analyse<'s>(study: &'s Study<'_>, class: usize) -> ClassReport<'s> {
    let embeddings = &study.embeddings()[class];
    ClassReport {
        class,
        embeddings,
        witnesses: &study.witnesses()[class],
        valid_candidates: (0..embeddings.len())
            .map(|i| study.valid_candidates(class, i))
            .collect(),
        overlapping: study
            .overlapping_pairs()
            .iter()
            .filter(|p| p.class == class)
            .collect(),
    }
}

/// A piece's points in the map's input units.
fn piece_text(map: &Map, p: &Piece) -> Vec<String> {
    p.vertices()
        .iter()
        .map(|q| show(map, &q.to_rat_point()))
        .collect()
}

fn cell_name(d: &Decomposition<'_>, c: CellRef) -> String {
    match c {
        CellRef::Face(f) => format!("2-cell {f}"),
        CellRef::Lower(i) => match d.lower_cells()[i].site {
            LowerSite::Edge(e) => format!("1-cell on edge {e}"),
            LowerSite::Vertex(v) => format!("0-cell at vertex {v}"),
        },
    }
}

fn json_class(map: &Map, d: &Decomposition<'_>, r: &ClassReport) -> serde_json::Value {
    let v = map.vertices();
    let embeddings: Vec<_> = r
        .embeddings
        .iter()
        .zip(r.witnesses)
        .zip(&r.valid_candidates)
        .map(|((e, w), vc)| {
            let (h, kernel) = (&e.embedding, e.kernel());
            serde_json::json!({
                "origin": h.origin,
                "origin_point": show(map, &v[h.origin].into()),
                "map_vertices": h.vertices,
                "valid": w.is_valid(),
                "witness_cells": w.cells.iter().map(|c| serde_json::json!({
                    "cell": cell_name(d, c.cell),
                    "dimension": c.piece.dimension(),
                    "vertices": piece_text(map, &c.piece),
                    "point": show(map, &c.point),
                })).collect::<Vec<_>>(),
                "candidate_edges": h.candidates,
                "valid_candidate_edges": vc,
                "kernel": kernel.vertices().iter().map(|p| show(map, p)).collect::<Vec<_>>(),
            })
        })
        .collect();
    let pairs: Vec<_> = r
        .overlapping
        .iter()
        .map(|o| {
            let mut p = serde_json::json!({
                "a": o.a,
                "b": o.b,
                "kernels_overlap": o.kernels_overlap,
                "witnesses_see_each_other": o.sight.is_visible(),
            });
            match &o.sight {
                Mutual::Visible { from, to } => {
                    p["certificate"] = serde_json::json!([
                        show(map, &from.to_rat_point()),
                        show(map, &to.to_rat_point())
                    ]);
                }
                Mutual::Invisible { tested } => p["sight_lines_tested"] = serde_json::json!(tested),
            }
            p
        })
        .collect();
    serde_json::json!({
        "class": r.class,
        "embeddings": embeddings,
        "overlapping_pairs": pairs,
    })
}

fn text_class(map: &Map, d: &Decomposition<'_>, r: &ClassReport, out: &mut String) {
    use std::fmt::Write;
    let v = map.vertices();
    let key = &d.skeletons()[r.class];
    let valid = r.witnesses.iter().filter(|w| w.is_valid()).count();
    let _ = writeln!(
        out,
        "class {}: skeleton of {} vertices, {} artificial edges; {} embeddings, {valid} valid; {} overlapping valid pairs",
        r.class,
        key.offsets.len(),
        key.labels.iter().filter(|l| l.is_some()).count(),
        r.embeddings.len(),
        r.overlapping.len()
    );
    for ((e, w), vc) in r
        .embeddings
        .iter()
        .zip(r.witnesses)
        .zip(&r.valid_candidates)
    {
        let h = &e.embedding;
        let cells: Vec<String> = w.cells.iter().map(|c| cell_name(d, c.cell)).collect();
        let _ = writeln!(
            out,
            "  h(v0) = map vertex {} {}: {}",
            h.origin,
            show(map, &v[h.origin].into()),
            if w.is_valid() {
                format!("valid, witnesses: {}", cells.join(", "))
            } else {
                "no witness (not valid)".to_owned()
            }
        );
        for (i, cands) in h.candidates.iter().enumerate() {
            if !cands.is_empty() {
                let _ = writeln!(
                    out,
                    "    artificial edge {i}: candidate edges {cands:?}, valid {:?}",
                    vc[i]
                );
            }
        }
    }
    for o in &r.overlapping {
        let verdict = match &o.sight {
            Mutual::Visible { from, to } => format!(
                "witnesses SEE each other: {} sees {}",
                show(map, &from.to_rat_point()),
                show(map, &to.to_rat_point())
            ),
            Mutual::Invisible { tested } => {
                format!("witnesses do not see each other ({tested} sight lines tested)")
            }
        };
        let _ = writeln!(
            out,
            "  overlap: embeddings {} and {}{}; {verdict}",
            o.a,
            o.b,
            if o.kernels_overlap {
                ", kernels overlap too"
            } else {
                ""
            }
        );
    }
}

fn svg(map: &Map, r: &ClassReport, out: &Path) -> Result<(), Failure> {
    let drawn: Vec<EmbeddingDrawn> = r
        .embeddings
        .iter()
        .zip(r.witnesses)
        .zip(&r.valid_candidates)
        .map(|((e, w), vc)| (&e.embedding, e.kernel(), w, vc))
        .map(|(h, kernel, w, vc)| EmbeddingDrawn {
            origin: h.origin,
            polygon: h.polygon(map),
            kernel: kernel.vertices().to_vec(),
            witnesses: w
                .cells
                .iter()
                .map(|c| {
                    c.piece
                        .vertices()
                        .iter()
                        .map(QPoint::to_rat_point)
                        .collect()
                })
                .collect(),
            candidate_edges: h
                .candidates
                .iter()
                .zip(vc.iter())
                .flat_map(|(cs, valid)| cs.iter().map(|&e| (e, valid.contains(&e))))
                .collect(),
        })
        .collect();
    let seen = r
        .overlapping
        .iter()
        .filter(|o| o.sight.is_visible())
        .count();
    let caption = format!(
        "class {}: {} embeddings, {} valid, {} overlapping valid pairs ({seen} with witnesses that see each other)",
        r.class,
        r.embeddings.len(),
        r.witnesses.iter().filter(|w| w.is_valid()).count(),
        r.overlapping.len()
    );
    let picture = embeddings_svg(map, &drawn, &MapStyle::default(), &caption);
    std::fs::write(out, picture).map_err(|e| Failure::io(format!("{}: {e}", out.display())))
}

pub fn run(args: &Args) -> Result<(), Failure> {
    let opts = args;
    let loaded = load_with_holes(&args.map, args.format)?;
    let map = &loaded.map;
    let rays = wai_cells::visibility_rays(map);
    crate::budget::check_decomposition(map, &rays, &args.memory)?;
    let bar = counted_bar("skeletons of cells", "cells of every dimension");
    let d = Decomposition::from_rays(map, rays, &mut |done, total| {
        bar.set_length(total as u64);
        bar.set_position(done as u64);
    });
    bar.finish_and_clear();
    let classes = d.skeletons().len();
    if let Some(k) = opts.class {
        if k >= classes {
            return Err(Failure::usage(format!(
                "--class {k}: the map has {classes} classes (0 to {})",
                classes.saturating_sub(1)
            )));
        }
    }
    let study = Study::from_decomposition(d);
    let d = study.decomposition();
    let wanted: Vec<usize> = match opts.class {
        Some(k) => vec![k],
        None => (0..classes).collect(),
    };
    let reports: Vec<ClassReport> = wanted.iter().map(|&k| analyse(&study, k)).collect();
    if let Some(out) = opts.svg.as_deref() {
        // The class asked for, else the one with the most valid embeddings.
        let shown = reports
            .iter()
            .max_by_key(|r| {
                (
                    r.witnesses.iter().filter(|w| w.is_valid()).count(),
                    std::cmp::Reverse(r.class),
                )
            })
            .expect("a map has at least one class");
        svg(map, shown, out)?;
    }
    if opts.json {
        let v = serde_json::json!({
            "name": map.name(),
            "n": map.n(),
            "r": map.r(),
            "classes": reports.iter().map(|r| json_class(map, d, r)).collect::<Vec<_>>(),
        });
        outln!("{}", serde_json::to_string_pretty(&v).expect("plain JSON"));
        return Ok(());
    }
    let total: usize = reports.iter().map(|r| r.embeddings.len()).sum();
    let valid: usize = reports
        .iter()
        .map(|r| r.witnesses.iter().filter(|w| w.is_valid()).count())
        .sum();
    let pairs: usize = reports.iter().map(|r| r.overlapping.len()).sum();
    let kernel_pairs: usize = reports
        .iter()
        .map(|r| r.overlapping.iter().filter(|o| o.kernels_overlap).count())
        .sum();
    let seen: usize = reports
        .iter()
        .map(|r| {
            r.overlapping
                .iter()
                .filter(|o| o.sight.is_visible())
                .count()
        })
        .sum();
    outln!(
        "map: {} (n = {}, r = {}), {classes} classes",
        map.name().unwrap_or("-"),
        map.n(),
        map.r()
    );
    outln!(
        "{} classes shown: {total} embeddings, {valid} valid; {pairs} overlapping valid pairs of one skeleton ({kernel_pairs} with overlapping kernels), {seen} with witnesses that see each other",
        reports.len()
    );
    let mut out = String::new();
    for r in &reports {
        // Without --class, only skeletons with two or more embeddings.
        if opts.class.is_some() || r.embeddings.len() > 1 {
            text_class(map, d, r, &mut out);
        }
    }
    out!("{out}");
    Ok(())
}
