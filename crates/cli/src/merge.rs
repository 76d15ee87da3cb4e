//! `wai merge`: the records of a sharded run (`wai check --shard I/N
//! --record …`) added up into the record of the whole run
//! ([`wai_hunt::merge`]), written where the claims dashboard reads it.
//!
//! Exit codes: 0 every shard was there; 1 some shards are missing — the
//! record is written all the same, marked partial, and the missing shards
//! are named with the command that re-runs one; 2 bad usage; 3 a record
//! could not be read or written, or the records do not merge (different
//! commits or runs, a shard twice).

use std::path::PathBuf;

use wai_hunt::record::RunRecord;

use crate::Failure;

#[derive(clap::Args, Debug)]
pub struct Args {
    /// The shards' records (or earlier merges of some of them), in any
    /// order.
    #[arg(required = true, num_args = 1.., value_name = "RECORD")]
    pub records: Vec<PathBuf>,
    /// Write the merged record here (lemmas/last-run.json is the one the
    /// claims dashboard and README.md's table read).
    #[arg(long, value_name = "FILE")]
    pub record: Option<PathBuf>,
    /// Print the merged record as JSON instead of a summary.
    #[arg(long)]
    pub json: bool,
}

pub fn run(args: &Args) -> Result<(), Failure> {
    let mut records = Vec::new();
    for path in &args.records {
        let record = RunRecord::read(path).map_err(Failure::io)?;
        records.push((path.display().to_string(), record));
    }
    let merged = wai_hunt::merge::merge(&records).map_err(Failure::io)?;
    if let Some(path) = &args.record {
        merged.write(path).map_err(Failure::io)?;
    }
    let shards = merged
        .shards
        .as_ref()
        .expect("a merge always says which shards it holds");
    if args.json {
        outln!(
            "{}",
            serde_json::to_string_pretty(&merged.to_json()).expect("plain JSON values")
        );
    } else {
        outln!(
            "wai merge: {} of {} shards of `{}` at commit {}: {} maps, {} s of shard wall time",
            shards.present.len(),
            shards.count,
            shards.run,
            merged.commit,
            merged.maps,
            merged.seconds
        );
        outln!(
            "  {:>6} {:>10} {:>8}  {:<20} {:<20} counterexamples",
            "shard",
            "maps",
            "seconds",
            "started",
            "ended"
        );
        for s in &shards.present {
            outln!(
                "  {:>6} {:>10} {:>8}  {:<20} {:<20} {}",
                s.index,
                s.maps,
                s.seconds,
                s.started,
                s.ended,
                s.counterexamples.len()
            );
        }
        let found: u64 = merged.claims.iter().map(|c| c.violations).sum();
        outln!(
            "  {} claims, {} violations{}",
            merged.claims.len(),
            found,
            match &args.record {
                Some(p) => format!("; written to {}", p.display()),
                None => String::new(),
            }
        );
    }
    let missing = shards.missing();
    if missing.is_empty() {
        return Ok(());
    }
    let list: Vec<String> = missing.iter().map(u64::to_string).collect();
    let example = missing[0];
    Err(Failure {
        code: 1,
        message: format!(
            "PARTIAL: {} of {} shards missing ({}); the merge{} is marked partial. Re-run one \
             with `{} --shard {example}/{} --record …` and merge again with its record",
            missing.len(),
            shards.count,
            list.join(", "),
            args.record
                .as_ref()
                .map_or(String::new(), |p| format!(" written to {}", p.display())),
            shards.run,
            shards.count
        ),
    })
}
