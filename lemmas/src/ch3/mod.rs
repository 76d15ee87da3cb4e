//! The checkers of chapter 3's claims (the Guibas–Motwani–Raghavan scheme),
//! one module per claim id, and what several of them share.

pub mod a3_6;
pub mod c3_8;
pub mod d3_5;
pub mod l3_1a;
pub mod l3_1b;
pub mod l3_1c;
pub mod l3_5;
pub mod l3_7;
pub mod l3_7t;
pub mod r3_4;
pub mod t3_10;
pub mod t3_2;
pub mod t3_3a;
pub mod t3_3b;
pub mod t3_9a;
pub mod t3_9b;
pub mod t3_9c;

use wai_map::Map;
use wai_study::Study;
use wai_visibility::VisibilityPolygon;

use crate::framework::Report;

/// Runs a per-polygon check of claim `id` on V_p of each of the study's
/// sampled viewpoints ([`wai_study::sample::VIEWPOINTS`] of them, computed
/// once per study), summing the reports (L3.1a–c, D3.5).
pub fn over_sampled_polygons(
    id: &'static str,
    study: &Study<'_>,
    check: fn(&Map, &VisibilityPolygon) -> Report,
) -> Report {
    let mut report = Report::new(id);
    for vp in study.sampled_polygons(wai_study::sample::VIEWPOINTS).iter() {
        report.absorb(check(study.map(), vp));
    }
    report
}
