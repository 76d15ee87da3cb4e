//! The search side of the claims: everything that runs the checkers of
//! `wai-lemmas` over many maps and keeps what they found.
//!
//! - [`stream`]: where maps come from ([`stream::Stream`]: generated kinds
//!   round robin with seed S + i, or a fixed list).
//! - [`summary`]: [`summary::run`], checkers over maps summed per claim
//!   (examined, violations with their maps, cases, counts, largest ratios),
//!   and the [`summary::Profile`] of where the time went.
//! - [`search`]: [`search::search`], a stream in parallel for a count or a
//!   time budget.
//! - [`record`]: [`record::RunRecord`], what a run found, as the JSON of
//!   `lemmas/last-run.json`.
//! - [`shard`]: one shard of a run (`wai check --shard I/N`); [`merge`]:
//!   the records of a run's shards added up into the run's record.
//! - [`caught`]: a checker's panic on a map caught and kept as a
//!   violation of its claim, so a run goes on.
//! - [`shrink`]: a counterexample made small; [`counterexample`]: the file
//!   format of `counterexamples/`; [`corpus`]: the fixed corpus;
//!   [`provenance`]: commit and date stamps.
//!
//! **Invariant:** the hunt reads measurements from the checkers' reports;
//! it never recomputes a claim's quantity itself.

pub mod caught;
pub mod climb;
pub mod corpus;
pub mod counterexample;
pub mod extremes;
pub mod json_read;
pub mod merge;
pub mod provenance;
pub mod record;
pub mod repository;
pub mod search;
pub mod shard;
pub mod shrink;
pub mod store;
pub mod stream;
pub mod summary;
pub mod target;

pub use search::{own_thread_pool, search, Limit, Outcome};
pub use shard::Shard;
pub use stream::{parse_kinds, KindSpec, MapKind, Stream};
pub use summary::{run, run_profiled, ClaimTally, FoundLargest, FoundViolation, Profile, Summary};
