//! The claims of the thesis and their checkers.
//!
//! Every claim of chapters 3–5 of the thesis "Where am I? Indoor
//! Localization Based on Range Measurements" that a program can test has an
//! id in the catalogue `CLAIMS.md` (`L3.1a`, `T4.2`, `T5.17`, …). This
//! crate holds that catalogue as data, [`CLAIMS`], and one checker per
//! claim.
//!
//! # Layers
//!
//! Imports run downward only:
//!
//! - [`registry`] (top): [`CLAIMS`], one [`Claim`] row per id with its
//!   [`Kind`] and its checker; lookups by id and chapter. [`planted`],
//!   checkers wrong on purpose, sits beside it.
//! - [`ch3`], [`ch4`], [`ch5`]: one module per claim, named after its id in
//!   lower case with `.` replaced by `_` (`ch4::t4_2`). Each states the
//!   claim in our own words with its citation, has a `## Trust` paragraph
//!   (exhaustive or sampled, what the verdict rests on), declares `pub
//!   const CHECKER` and has a planted-violation test proving it can fail.
//!   A chapter's modules may read each other; no chapter reads a later one.
//! - [`framework`] (bottom): [`Checker`], [`Report`], [`Violation`],
//!   [`Case`], [`Known`], [`Ceiling`] — what every checker is and returns.
//!
//! The structures the checkers read come from [`wai_study::Study`], built
//! once per map; the driver that runs checkers over streams of maps, shrinks
//! and records lives in `wai-hunt`.
//!
//! **Invariant:** a checker never mutates what it checks.
//!
//! **Invariant:** nothing passes vacuously. A report always carries
//! `examined`; a run names every claim whose count stayed 0. The
//! integration tests fail if [`CLAIMS`] and `CLAIMS.md` disagree.

pub mod ch3;
pub mod ch4;
pub mod ch5;
pub mod framework;
pub mod planted;
pub mod registry;

#[cfg(test)]
pub(crate) mod fixtures;

pub use framework::{Case, Ceiling, Checker, Known, Largest, Report, Rings, Violation};
pub use registry::{
    chapter_of, checker, checkers, checkers_of_chapter, claim, claims_without_checker, Claim, Kind,
    CLAIMS,
};
