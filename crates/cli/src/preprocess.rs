//! `wai preprocess`: Alg 3.14 — decompose a map, overlay each class's
//! cells, and save the structure (versioned JSON) for `wai localize`.

use std::path::PathBuf;

use crate::failure::Failure;
use crate::input::load_with_holes;
use crate::localize::preprocessed;

#[derive(clap::Args, Debug)]
pub struct Args {
    #[arg(help = crate::input::MAP_HELP)]
    pub map: PathBuf,
    /// Output file.
    #[arg(short, long)]
    pub out: PathBuf,
    #[command(flatten)]
    pub memory: crate::budget::MemoryArgs,
    #[command(flatten)]
    pub format: crate::input::FormatArg,
}

pub fn run(args: &Args) -> Result<(), Failure> {
    let (path, out) = (&args.map, &args.out);
    let loaded = load_with_holes(path, args.format)?;
    let loc = preprocessed(path, &loaded.map, &args.memory)?;
    let text = wai_localize::file::to_json(&loc);
    std::fs::write(out, &text).map_err(|e| Failure::io(format!("{}: {e}", out.display())))?;
    let (cells, traps) = (loc.cells(), loc.trapezoids());
    outln!(
        "{}: {} classes, {cells} cells of every dimension, {traps} trapezoids; {} bytes written to {}",
        path.display(),
        loc.classes(),
        text.len(),
        out.display()
    );
    Ok(())
}
