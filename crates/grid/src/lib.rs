//! Occupancy grids to exact maps with holes.
//!
//! Robots keep their maps as occupancy grids: the ROS `map_server` pair of
//! an image (here PGM, as `map_saver` writes it) and a YAML file giving the
//! resolution (metres per cell), the origin (the world pose of the image's
//! lower-left corner), the thresholds and `negate`. [`import`] reads the
//! pair and returns a [`wai_map::Map`] in metres, in the grid's world frame
//! (so a pose reads the same as in ROS):
//!
//! 1. [`meta`]: the YAML file, every number read exactly from its text;
//! 2. [`pgm`]: the image;
//! 3. [`occupancy`]: each cell free or not by the `map_server` rule
//!    (trinary: free when its occupancy `(255 − x) / 255` — `x / 255` with
//!    `negate` — is below `free_thresh`), decided exactly; unknown and
//!    occupied cells are both obstacles;
//! 4. [`trace`]: the free 4-connected component that holds a given point
//!    (or the largest), made into a region whose boundary never touches
//!    itself at a corner (a free cell is given up at each such pinch), its
//!    enclosed obstacles below a given area filled (specks), and its
//!    boundary traced along cell edges: the outer ring and one hole per
//!    enclosed obstacle;
//! 5. [`simplify`] (optional): vertices dropped while the boundary stays
//!    within a stated tolerance and no two rings (or two parts of one)
//!    are simplified into each other, the map validated again.
//!
//! Every step says what it changed in the [`Report`].

pub mod meta;
pub mod occupancy;
pub mod pgm;
pub mod simplify;
pub mod trace;

mod error;
mod import;

pub use error::GridError;
pub use import::{import, import_parts, ImportOptions, Imported, Report};
