//! `wai gen`: generate a map — a thesis family, a random kind or a seeded
//! chapter 4/5 layout — as JSON; `--list` names them all.

use std::path::PathBuf;

use wai_map::json::to_json;

use crate::failure::Failure;
use crate::output::output;

#[derive(clap::Args, Debug)]
pub struct Args {
    /// A thesis family by id (see --list).
    #[arg(long, conflicts_with_all = ["random", "layout"], required_unless_present_any = ["random", "layout", "list"])]
    pub family: Option<String>,
    /// A family parameter; repeat for families with several.
    #[arg(long = "param")]
    pub params: Vec<u32>,
    /// A random kind by id (see --list).
    #[arg(long, conflicts_with = "layout")]
    pub random: Option<String>,
    /// A seeded chapter 4 layout by id (see --list): repeated rooms whose
    /// embeddings overlap.
    #[arg(long)]
    pub layout: Option<String>,
    /// Vertex count target for random kinds.
    #[arg(long, default_value_t = 20, value_parser = crate::options::count, allow_negative_numbers = true)]
    pub n: usize,
    /// Holes asked of a random kind with holes (fewer where they do not fit).
    #[arg(long, default_value_t = 4, value_parser = crate::options::count, allow_negative_numbers = true)]
    pub holes: usize,
    /// Seed for random kinds and layouts (the same seed gives the same map).
    #[arg(long, default_value_t = 0, value_parser = crate::options::count_u64, allow_negative_numbers = true)]
    pub seed: u64,
    /// Output file; standard output if absent.
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// List the families and random kinds.
    #[arg(long)]
    pub list: bool,
}

pub fn run(args: &Args) -> Result<(), Failure> {
    if args.list {
        out!("{}", catalogue());
        return Ok(());
    }
    let map = match (&args.family, &args.random, &args.layout) {
        (Some(family), _, _) => wai_gen::family(family, &args.params),
        (None, Some(kind), _) if wai_gen::HOLED_KINDS.iter().any(|k| k.id == kind) => {
            wai_gen::random_with_holes(kind, args.n, args.holes, args.seed)
        }
        (None, Some(kind), _) => wai_gen::random(kind, args.n, args.seed),
        (None, None, Some(id)) => wai_gen::layout(id, args.seed),
        (None, None, None) => {
            return Err(Failure::usage(
                "give --family ID, --random KIND or --layout ID (see --list)",
            ))
        }
    }
    .map_err(|e| Failure::usage(e.to_string()))?;
    output(args.out.as_deref(), &to_json(&map))?;
    if let Some(out) = &args.out {
        eprintln!(
            "wrote {} (n = {}, r = {}, holes = {})",
            out.display(),
            map.n(),
            map.r(),
            map.hole_count()
        );
    }
    Ok(())
}

/// The families and random kinds, for `gen --list`.
fn catalogue() -> String {
    let mut s = String::from("Thesis families (gen --family ID --param P ...):\n");
    for f in wai_gen::FAMILIES {
        s.push_str(&format!(
            "  {:<20} {}\n  {:<20} n = {}, r = {}; {} [{}]\n",
            f.id,
            f.params,
            "",
            f.n,
            f.r,
            f.reference,
            f.claims.join(", ")
        ));
    }
    s.push_str("\nRandom kinds (gen --random KIND --n N --seed S):\n");
    for k in wai_gen::RANDOM_KINDS {
        s.push_str(&format!(
            "  {:<20} {} (n from {} to {}; vertices: {})\n",
            k.id, k.method, k.min_n, k.max_n, k.vertices
        ));
    }
    s.push_str("\nRandom kinds with holes (gen --random KIND --n N --holes H --seed S):\n");
    for k in wai_gen::HOLED_KINDS {
        s.push_str(&format!(
            "  {:<20} {} (n from {} to {})\n",
            k.id, k.method, k.min_n, k.max_n
        ));
    }
    s.push_str("\nChapter 4 and 5 layouts (gen --layout ID --seed S):\n");
    for l in wai_gen::LAYOUTS {
        s.push_str(&format!("  {:<20} {}\n", l.id, l.shows));
    }
    s
}
