//! The bottom layer of the claims crate: what every checker is and returns.
//! Nothing here knows a particular claim or the registry.
//!
//! - [`checker`]: [`Checker`] (a claim's id, its [`Case`]s, its [`Known`]
//!   failures, a bound's [`Ceiling`], and its check function).
//! - [`report`]: [`Report`], [`Violation`], [`Largest`]; the one bound
//!   mechanism, [`Report::hold_to`] (a ratio above the ceiling).

pub mod checker;
pub mod report;

pub use checker::{Case, Ceiling, Checker, Known, Rings};
pub use report::{over, Largest, Report, Violation};
