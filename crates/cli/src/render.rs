//! `wai render`: draw a map (holes too) as SVG, reflex vertices marked,
//! with a legend and a scale bar.

use std::path::PathBuf;

use wai_render::{map_svg, MapStyle, MapUnits};

use crate::failure::Failure;
use crate::input::load_with_holes;
use crate::output::output;

#[derive(clap::Args, Debug)]
pub struct Args {
    #[arg(help = crate::input::MAP_HELP)]
    pub map: PathBuf,
    /// Output SVG file; standard output if absent.
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Number the vertices.
    #[arg(long)]
    pub labels: bool,
    /// Pixels along the longer side.
    #[arg(long, default_value_t = 800)]
    pub size: u32,
    /// What the coordinates measure, for the scale bar: `auto` (lon/lat
    /// if the map lies within ±180, ±90 and spans under 0.1 — drawn in a
    /// local equirectangular projection with the bar in metres — else
    /// plain map units), `plain`, `m` or `lonlat`.
    #[arg(long, default_value = "auto", value_parser = ["auto", "plain", "m", "lonlat"])]
    pub units: String,
    #[command(flatten)]
    pub format: crate::input::FormatArg,
}

pub fn run(args: &Args) -> Result<(), Failure> {
    let loaded = load_with_holes(&args.map, args.format)?;
    let style = MapStyle {
        size: f64::from(args.size.clamp(50, 20_000)),
        vertex_labels: args.labels,
        units: match args.units.as_str() {
            "plain" => Some(MapUnits::Plain),
            "m" => Some(MapUnits::Metres),
            "lonlat" => Some(MapUnits::LonLat),
            _ => None,
        },
    };
    output(args.out.as_deref(), &map_svg(&loaded.map, &style))
}
