//! Benchmarks of the workspace and their peers.
//!
//! - [`cgal`]: CGAL's visibility polygon (an external process built by
//!   `benches/peers/build.sh`) as an independent exact oracle and speed peer.
//! - [`viewpoints`]: seeded interior viewpoints.
//! - [`maps`]: maps for benchmarks beyond the generators' kinds.

pub mod cgal;
pub mod maps;
pub mod viewpoints;
