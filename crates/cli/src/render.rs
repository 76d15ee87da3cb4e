//! `wai render`: draw a map as SVG, reflex vertices marked.

use std::path::PathBuf;

use wai_render::{map_svg, MapStyle};

use crate::failure::Failure;
use crate::input::load;
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
    #[command(flatten)]
    pub format: crate::input::FormatArg,
}

pub fn run(args: &Args) -> Result<(), Failure> {
    let loaded = load(&args.map, args.format.format)?;
    let style = MapStyle {
        size: f64::from(args.size.clamp(50, 20_000)),
        vertex_labels: args.labels,
    };
    output(args.out.as_deref(), &map_svg(&loaded.map, &style))
}
