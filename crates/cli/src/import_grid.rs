//! `wai import-grid`: an occupancy grid (the ROS `map_server` pair) traced
//! into an exact map with holes, in metres in the grid's frame.

use crate::failure::Failure;
use crate::output::output;
use rug::Rational;
use std::path::PathBuf;
use wai_grid::{import, ImportOptions};
use wai_map::{format_exact, parse_exact};

#[derive(clap::Args, Debug)]
pub struct Args {
    /// The grid's YAML file (`image`, `resolution`, `origin`,
    /// `occupied_thresh`, `free_thresh`, `negate`, `mode`); the PGM image it
    /// names is read from beside it.
    pub yaml: PathBuf,
    /// A point of the free space wanted, `x,y` in metres in the grid's frame
    /// (as ROS poses are): its free component is traced. Default: the
    /// largest free component.
    #[arg(long, value_name = "X,Y")]
    pub at: Option<String>,
    /// Fill enclosed obstacles of less than this area, in square metres
    /// (specks of sensor noise); larger ones become holes. Default 0: every
    /// enclosed obstacle is a hole.
    #[arg(long, value_name = "M2", default_value = "0")]
    pub min_hole_area: String,
    /// Drop boundary corners while the boundary stays within this many
    /// metres of the traced one (Douglas–Peucker, decided exactly). Default:
    /// keep every corner, the boundary exactly along cell edges.
    #[arg(long, value_name = "METRES")]
    pub simplify: Option<String>,
    /// Refuse grids of more cells than this (about 12 bytes each while
    /// tracing).
    #[arg(long, value_name = "CELLS", default_value_t = 200_000_000)]
    pub max_cells: u64,
    /// Write the map here (the JSON map format); default standard output.
    #[arg(long)]
    pub out: Option<PathBuf>,
}

fn number(option: &str, text: &str) -> Result<Rational, Failure> {
    parse_exact(text)
        .map_err(|e| Failure::usage(format!("--{option} {text:?}: not an exact number: {e}")))
}

pub fn run(args: &Args) -> Result<(), Failure> {
    let at = match &args.at {
        None => None,
        Some(text) => {
            let parts: Vec<&str> = text.split(',').map(str::trim).collect();
            let [x, y] = parts[..] else {
                return Err(Failure::usage(format!("--at {text:?}: expected x,y")));
            };
            Some((number("at", x)?, number("at", y)?))
        }
    };
    let min_hole_area = number("min-hole-area", &args.min_hole_area)?;
    if min_hole_area < 0 {
        return Err(Failure::usage("--min-hole-area: must be at least 0"));
    }
    let simplify = match &args.simplify {
        None => None,
        Some(t) => {
            let t = number("simplify", t)?;
            if t <= 0 {
                return Err(Failure::usage("--simplify: must be above 0"));
            }
            Some(t)
        }
    };
    let options = ImportOptions {
        at,
        min_hole_area,
        simplify,
        max_cells: args.max_cells,
    };
    let imported = import(&args.yaml, &options).map_err(|e| Failure::invalid(e.to_string()))?;
    let (map, r) = (&imported.map, &imported.report);
    let g = &r.region;
    eprintln!(
        "{}: {} × {} cells of {} m; {} free in {} component(s); the {} one: {} cells",
        args.yaml.display(),
        r.width,
        r.height,
        format_exact(&imported.meta.resolution),
        g.free_cells,
        g.components,
        if options.at.is_some() {
            "chosen"
        } else {
            "largest"
        },
        g.component_cells,
    );
    if g.pinch_cells > 0 {
        eprintln!(
            "note: {} free cell(s) given up where the boundary touched itself at a corner{}",
            g.pinch_cells,
            if g.split_off_cells > 0 {
                format!(", which split off {} cell(s)", g.split_off_cells)
            } else {
                String::new()
            }
        );
    }
    if g.specks_filled > 0 {
        eprintln!(
            "note: {} enclosed obstacle(s) below {} m² filled ({} cells)",
            g.specks_filled,
            format_exact(&options.min_hole_area),
            g.speck_cells
        );
    }
    if r.simplified_away > 0 {
        eprintln!(
            "note: simplified within {} m: {} of {} vertices removed",
            format_exact(options.simplify.as_ref().expect("simplified")),
            r.simplified_away,
            r.traced_vertices
        );
    }
    eprintln!(
        "map: {} cells, {} vertices (r = {}), {} hole(s), in metres",
        g.region_cells,
        map.n(),
        map.r(),
        map.hole_count()
    );
    output(args.out.as_deref(), &wai_map::json::to_json(map))
}
