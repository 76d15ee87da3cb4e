//! `wai info`: validate a map and print its numbers (n, r, holes, area,
//! orthogonality, scale, bounding box). Maps with holes are read.

use std::path::PathBuf;

use rug::{Integer, Rational};
use wai_map::{format_exact, Loaded, Map};

use crate::failure::Failure;
use crate::input::load_with_holes;
use crate::output::unit;

#[derive(clap::Args, Debug)]
pub struct Args {
    #[arg(help = crate::input::MAP_HELP)]
    pub map: PathBuf,
    /// Print JSON instead of text.
    #[arg(long)]
    pub json: bool,
    #[command(flatten)]
    pub format: crate::input::FormatArg,
}

pub fn run(args: &Args) -> Result<(), Failure> {
    let loaded = load_with_holes(&args.map, args.format)?;
    if args.json {
        out!("{}", json(&loaded));
    } else {
        out!("{}", text(&loaded.map));
    }
    Ok(())
}

/// The exact area in input units.
fn area(map: &Map) -> Rational {
    let scale2 = Integer::from(map.scale() * map.scale());
    Rational::from((map.area_twice(), scale2 * 2u32))
}

/// The map's numbers as text (also printed by `wai demo`).
pub fn text(map: &Map) -> String {
    let (lo, hi) = map.bounding_box();
    let reflex: Vec<String> = map.reflex_vertices().iter().map(usize::to_string).collect();
    format!(
        "name:         {}\nvertices n:   {}\nreflex r:     {}  [{}]\narea:         {}\northogonal:   {}\nscale:        1/{} (coordinates are integers over this denominator)\nbounding box: ({}, {}) – ({}, {})\n",
        map.name().unwrap_or("-"),
        map.n(),
        map.r(),
        reflex.join(", "),
        format_exact(&area(map)),
        if map.is_orthogonal() { "yes" } else { "no" },
        map.scale(),
        unit(map, lo.x),
        unit(map, lo.y),
        unit(map, hi.x),
        unit(map, hi.y),
    ) + &holes_text(map)
}

/// The holes' line of [`text`]: nothing for a map without holes.
fn holes_text(map: &Map) -> String {
    if !map.has_holes() {
        return String::new();
    }
    let outer_reflex = map
        .reflex_vertices()
        .iter()
        .filter(|&&i| map.ring_of(i) == 0)
        .count();
    format!(
        "holes:        {} ({} of the n vertices on the outer ring, {} of the r reflex vertices; a hole's reflex vertices are its convex corners)\n",
        map.hole_count(),
        map.outer().len(),
        outer_reflex
    )
}

/// The map's numbers as JSON, with what reading it normalised.
fn json(loaded: &Loaded) -> String {
    let map = &loaded.map;
    let (lo, hi) = map.bounding_box();
    let v = serde_json::json!({
        "name": map.name(),
        "n": map.n(),
        "r": map.r(),
        "reflex_vertices": map.reflex_vertices(),
        "holes": map.hole_count(),
        "ring_sizes": (0..=map.hole_count()).map(|k| map.ring(k).len()).collect::<Vec<_>>(),
        "area": format_exact(&area(map)),
        "orthogonal": map.is_orthogonal(),
        "scale": map.scale().to_string(),
        "bounding_box": [[unit(map, lo.x), unit(map, lo.y)], [unit(map, hi.x), unit(map, hi.y)]],
        "normalisation": {
            "reversed": loaded.normalisation.reversed,
            "removed_collinear": loaded.normalisation.removed_collinear,
            "reversed_holes": loaded.normalisation.reversed_holes,
            "removed_collinear_holes": loaded.normalisation.removed_collinear_holes,
            "rounded": loaded.normalisation.rounded.as_ref().map(|r| serde_json::json!({
                "grid_bits": r.bits,
                "moved": r.moved,
                "largest": format_exact(&r.largest),
            })),
        },
    });
    format!(
        "{}\n",
        serde_json::to_string_pretty(&v).expect("plain JSON values")
    )
}
