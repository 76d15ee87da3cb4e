//! `wai localize`: the exact reference localizer (Alg 3.13): every
//! position where the robot can be, given what it sees.

use crate::budget::MemoryArgs;
use crate::failure::counted_bar;
use crate::failure::Failure;
use crate::input::{load_bytes, read_bytes};
use crate::vis::{parse_viewpoint, show};
use rug::{Integer, Rational};
use serde_json::Value;
use std::path::{Path, PathBuf};
use wai_exact::RatPoint;
use wai_localize::{Localizer, RobotView};
use wai_map::{format_exact, parse_exact, Map};
use wai_render::Canvas;
use wai_visibility::VisibilityIndex;

/// Whether the bytes are a preprocessed file (its "format" field).
fn is_preprocessed(bytes: &[u8]) -> bool {
    serde_json::from_slice::<Value>(bytes)
        .ok()
        .and_then(|v| v.get("format").and_then(|f| f.as_str().map(str::to_string)))
        .is_some_and(|f| f == wai_localize::file::FORMAT)
}

/// A localizer from a map file (preprocessed now) or a preprocessed file,
/// read once (standard input too).
fn localizer(
    path: &Path,
    format: crate::input::FormatArg,
    limits: &MemoryArgs,
) -> Result<Localizer, Failure> {
    if let Some(map) = crate::input::generated(path)? {
        return preprocessed(path, &map, limits);
    }
    let bytes = read_bytes(path)?;
    if is_preprocessed(&bytes) {
        return wai_localize::file::from_json(&bytes)
            .map_err(|e| Failure::invalid(format!("{}: {e}", path.display())));
    }
    preprocessed(path, &load_bytes(path, &bytes, format)?.map, limits)
}

/// Alg 3.14 on `map`, read from `path`, saying so on stderr, with the
/// decomposition's progress; refused beforehand if its memory estimate is
/// above `limits`.
pub(crate) fn preprocessed(
    path: &Path,
    map: &Map,
    limits: &MemoryArgs,
) -> Result<Localizer, Failure> {
    eprintln!(
        "preprocessing {} (n = {}, r = {}) …",
        path.display(),
        map.n(),
        map.r()
    );
    let rays = wai_cells::visibility_rays(map);
    crate::budget::check_decomposition(map, &rays, limits)?;
    let bar = counted_bar("skeletons of cells", "cells of every dimension");
    let d = wai_cells::Decomposition::from_rays(map, rays, &mut |done, total| {
        bar.set_length(total as u64);
        bar.set_position(done as u64);
    });
    bar.finish_and_clear();
    Ok(Localizer::from_decomposition(&d))
}

/// Read V: a JSON array of [x, y] pairs, or an object with "vertices",
/// exact numbers in the map's input units, relative to the robot.
fn read_polygon(path: &Path, map: &Map) -> Result<RobotView, Failure> {
    let shown = path.display();
    let bytes = read_bytes(path)?;
    let root: Value = serde_json::from_slice(&bytes)
        .map_err(|e| Failure::invalid(format!("{shown}: not JSON: {e}")))?;
    let ring = root
        .as_array()
        .or_else(|| root.get("vertices").and_then(Value::as_array))
        .ok_or_else(|| {
            Failure::invalid(format!(
                "{shown}: expected an array of [x, y] pairs or an object with \"vertices\""
            ))
        })?;
    let mut pts = Vec::with_capacity(ring.len());
    for (i, v) in ring.iter().enumerate() {
        let pair = match v {
            Value::Array(p) if p.len() == 2 => p,
            _ => {
                return Err(Failure::invalid(format!(
                    "{shown}: vertex {i}: expected [x, y]"
                )))
            }
        };
        let mut c = [Rational::new(), Rational::new()];
        for (k, n) in pair.iter().enumerate() {
            let text = match n {
                Value::String(s) => s.clone(),
                Value::Number(x) => x.to_string(),
                _ => {
                    return Err(Failure::invalid(format!(
                        "{shown}: vertex {i}: coordinate {k} is not a number"
                    )))
                }
            };
            c[k] = parse_exact(&text).map_err(|e| {
                Failure::invalid(format!(
                    "{shown}: vertex {i}: {text:?} is not an exact number: {e}"
                ))
            })?;
        }
        let [x, y] = c;
        let s = map.scale();
        pts.push(RatPoint::from_rationals(x * s, y * s));
    }
    let view = RobotView::new(pts)
        .map_err(|e| Failure::invalid(format!("{shown}: not a visibility polygon: {e}")))?;
    for note in view.notes() {
        eprintln!("note: {shown}: {note}");
    }
    Ok(view)
}

fn pt_json(map: &Map, p: &RatPoint) -> Value {
    let den = Integer::from(p.hw() * map.scale());
    let c = |n: &Integer| Value::from(format_exact(&Rational::from((n.clone(), den.clone()))));
    Value::Array(vec![c(p.hx()), c(p.hy())])
}

/// The map, the polygon placed at every answer and the answers.
pub(crate) fn answers_svg(map: &Map, view: &RobotView, answer: &wai_localize::Answer) -> String {
    let mut c = Canvas::for_map(map, 800.0);
    c.polygon(map.vertices(), "#eef3fb", "#1f3b73", 1.5);
    for a in &answer.placements {
        c.polygon_rat(
            &view.placed_at(&a.position),
            "rgba(255,165,0,0.25)",
            "#d95f02",
            1.0,
        );
    }
    for a in &answer.placements {
        c.dot_rat(
            &a.position,
            5.0,
            "#d62728",
            &format!(
                "{} via map vertex {}",
                show(map, &a.position),
                a.origin_vertex
            ),
        );
    }
    c.legend(
        wai_render::Mark::area("#eef3fb", 1.0, "#1f3b73"),
        "map (walls and inside)",
    );
    if !answer.placements.is_empty() {
        c.legend(
            wai_render::Mark::area("rgb(255,165,0)", 0.25, "#d95f02"),
            "the robot's visibility polygon placed at an answer",
        );
        c.legend(
            wai_render::Mark::dot("#d62728", 5.0),
            &format!("answer: a position ({})", answer.placements.len()),
        );
    }
    let caption = format!(
        "{} answers{}",
        answer.placements.len(),
        answer
            .nowhere
            .as_ref()
            .map(|w| format!(": {w}"))
            .unwrap_or_default()
    );
    c.finish(map.name().unwrap_or("localize"), &caption)
}

#[derive(clap::Args, Debug)]
pub struct Args {
    /// A map file (preprocessed now), a file written by `wai preprocess`,
    /// or a generated map: `rooms:K`, `office:K[:SEED]`, `family:ID:P1,…`.
    pub map: PathBuf,
    /// Simulate the view at `x,y` (exact numbers in the map's units).
    #[arg(long, allow_hyphen_values = true)]
    pub at: Option<String>,
    /// A JSON file with the polygon: an array of [x, y] pairs (or an
    /// object with "vertices"), exact numbers in the map's units,
    /// relative to the robot, counter-clockwise.
    #[arg(long)]
    pub polygon: Option<PathBuf>,
    /// Print JSON: {"answers": [{"position": [x, y], "origin_vertex": i}], "class": k}
    /// (and "reason" when there is no answer).
    #[arg(long)]
    pub json: bool,
    /// Draw the map, the polygon at every answer and the answers into this SVG file.
    #[arg(long)]
    pub svg: Option<PathBuf>,
    #[command(flatten)]
    pub memory: MemoryArgs,
    #[command(flatten)]
    pub format: crate::input::FormatArg,
}

pub fn run(args: &Args) -> Result<(), Failure> {
    let opts = args;
    let loc = localizer(&args.map, args.format, &args.memory)?;
    let map = loc.map();
    let view = match (opts.at.as_deref(), opts.polygon.as_deref()) {
        (Some(at), None) => {
            let p = parse_viewpoint(at, map)?;
            let vp = VisibilityIndex::new(map)
                .visibility_polygon(&p)
                .map_err(|e| {
                    Failure::invalid(format!(
                        "--at: {}",
                        e.to_string().replace(&p.to_string(), &show(map, &p))
                    ))
                })?;
            RobotView::from_visibility(&vp)
        }
        (None, Some(file)) => read_polygon(file, map)?,
        _ => {
            return Err(Failure::usage(
                "give exactly one of --at x,y (simulate the view there) and --polygon V.json",
            ))
        }
    };
    let answer = loc.localize(&view);
    if let Some(out) = opts.svg.as_deref() {
        std::fs::write(out, answers_svg(map, &view, &answer))
            .map_err(|e| Failure::io(format!("{}: {e}", out.display())))?;
    }
    if opts.json {
        let answers: Vec<Value> = answer
            .placements
            .iter()
            .map(|a| serde_json::json!({"position": pt_json(map, &a.position), "origin_vertex": a.origin_vertex}))
            .collect();
        let mut v = serde_json::json!({"answers": answers, "class": answer.class});
        if let Some(w) = &answer.nowhere {
            v["reason"] = Value::from(w.to_string());
        }
        outln!("{}", serde_json::to_string_pretty(&v).expect("plain JSON"));
    } else {
        match &answer.nowhere {
            Some(w) => outln!("no position: {w}"),
            None => {
                outln!(
                    "{} position(s), class {}:",
                    answer.placements.len(),
                    answer.class.expect("found")
                );
                for a in &answer.placements {
                    outln!(
                        "  {}  (v0 at map vertex {})",
                        show(map, &a.position),
                        a.origin_vertex
                    );
                }
            }
        }
    }
    Ok(())
}
