//! Claim T4.2 (Theorem 4.2, the main theorem of chapter 4): two different
//! valid embeddings of the same skeleton whose embedded skeleton polygons
//! overlap have mutually invisible witnesses — no witness of one sees any
//! witness of the other.
//!
//! ## Trust
//! Exhaustive and exact over whole witness regions, not sampled points.
//! Every pair of valid embeddings of every skeleton is tested for interior
//! overlap of h(V◇) and h'(V◇) ([`wai_embed::interiors_overlap`], exact
//! and complete); the witness regions are the class's cells of every
//! dimension at each embedding's v0 (Def 4.1 with Lemma 3.5, which L3.5
//! checks); whether any point of one sees any point of the other is
//! decided by the search over lines of [`wai_embed::Sightlines`], complete
//! because visibility is open (see its doc). A "visible" verdict carries
//! two exact points re-checked by `wai_exact::sees`; on maps of at most
//! [`CROSS_CHECK_MAX_N`] vertices every verdict is also reached by the
//! second, independent method (cuts and sweeps from points), and a
//! disagreement is reported as a violation (of our code) — the counts
//! `cross-checked` and `visible` say how many.

use serde_json::{json, Value};
use wai_embed::{Mutual, Sightlines, Witnesses};

use crate::framework::{Checker, Report, Violation};
use wai_study::Study;
use wai_study::{Embedded, OverlappingPair};

const ID: &str = "T4.2";

/// The checker of this claim.
pub const CHECKER: Checker = Checker::new(ID, check_study);

/// Maps up to this many vertices have every verdict cross-checked. The
/// whole corpus (`wai check --maps corpus`) is below it: there the cross-check
/// adds about 18 % to T4.2's time (87 s against 74 s, 66,634 pairs).
pub const CROSS_CHECK_MAX_N: usize = 1000;

/// Checks T4.2 on every overlapping pair of valid embeddings of a map.
fn check_study(study: &Study<'_>) -> Report {
    let cross = (study.map().n() <= CROSS_CHECK_MAX_N).then(|| study.sightlines());
    check_pairs(
        ID,
        study.overlapping_pairs().iter(),
        study.embeddings(),
        study.witnesses(),
        cross,
    )
}

/// The check proper, shared with T4.3 (which passes its own id and the
/// pairs whose kernels overlap): each pair's witnesses must not see each
/// other; with `cross`, each verdict is reached a second time by the
/// independent method and the two must agree.
pub fn check_pairs<'p>(
    id: &'static str,
    pairs: impl Iterator<Item = &'p OverlappingPair>,
    embeddings: &[Vec<Embedded>],
    witnesses: &[Vec<Witnesses>],
    cross: Option<&Sightlines<'_>>,
) -> Report {
    let mut report = Report::new(id);
    for pair in pairs {
        report.examined += 1;
        let ws = &witnesses[pair.class];
        let data = |extra: Value| {
            let h = &embeddings[pair.class];
            json!({
                "class": pair.class,
                "origins": [h[pair.a].embedding.origin, h[pair.b].embedding.origin],
                "witness_cells": [ws[pair.a].cells.len(), ws[pair.b].cells.len()],
                "kernels_overlap": pair.kernels_overlap,
                "detail": extra,
            })
        };
        if let Some(sl) = cross {
            report.count("cross-checked", 1);
            let second = sl.regions_by_points(&ws[pair.a].pieces(), &ws[pair.b].pieces());
            if second.is_visible() != pair.sight.is_visible() {
                report.violations.push(Violation::with_data(
                    format!(
                        "the two mutual-visibility methods disagree on embeddings {} and {} of skeleton {} (a bug in our code)",
                        pair.a, pair.b, pair.class
                    ),
                    data(json!({
                        "by_lines": describe(&pair.sight),
                        "by_points": describe(&second),
                    })),
                ));
                continue;
            }
        }
        if let Mutual::Visible { from, to } = &pair.sight {
            report.count("visible", 1);
            report.violations.push(Violation::with_data(
                format!(
                    "witness {from} of one embedding of skeleton {} sees witness {to} of an overlapping one",
                    pair.class
                ),
                data(json!({ "from": from.to_string(), "to": to.to_string() })),
            ));
        }
    }
    report
}

fn describe(m: &Mutual) -> Value {
    match m {
        Mutual::Visible { from, to } => json!({ "visible": [from.to_string(), to.to_string()] }),
        Mutual::Invisible { tested } => json!({ "invisible": { "sight_lines_tested": tested } }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use wai_embed::WitnessCell;

    #[test]
    fn holds_on_the_overlap_fan_and_every_verdict_is_cross_checked() {
        let map = wai_gen::family("overlap-fan", &[1]).unwrap();
        let study = Study::new(&map);
        let report = CHECKER.run(&study);
        assert!(report.examined > 0);
        assert_eq!(report.counts.get("cross-checked"), Some(&report.examined));
        assert!(report.violations.is_empty(), "{:?}", report.violations);
    }

    #[test]
    fn planted_visible_witnesses_are_reported() {
        // The overlap fan's first overlapping pair, with the second
        // embedding's witness region replaced by a cell the first region
        // sees: the checker must report it, with a certificate.
        let map = wai_gen::family("overlap-fan", &[1]).unwrap();
        let study = Study::new(&map);
        let pair = study.overlapping_pairs()[0].clone();
        let mut witnesses = study.witnesses().to_vec();
        let own = witnesses[pair.class][pair.a].cells[0].clone();
        let wai_embed::CellRef::Face(f) = own.cell else {
            panic!("the fan's witnesses are 2-cells")
        };
        // A 2-cell beside the first witness cell: the two see each other.
        let d = study.decomposition();
        let arr = d.arrangement();
        let beside = arr
            .face_half_edges(f)
            .into_iter()
            .map(|h| arr.half_edge(arr.half_edge(h).twin).face)
            .find(|&g| g != arr.outer_face())
            .expect("a witness cell has a neighbouring cell");
        let near = WitnessCell {
            cell: wai_embed::CellRef::Face(beside),
            piece: wai_embed::piece_of(d, wai_embed::CellRef::Face(beside)),
            point: d.representative(beside).clone(),
        };
        witnesses[pair.class][pair.b].cells = vec![near];
        let mut planted = pair.clone();
        planted.sight = study.sightlines().regions_by_lines(
            &witnesses[pair.class][pair.a].pieces(),
            &witnesses[pair.class][pair.b].pieces(),
        );
        let report = check_pairs(
            ID,
            [planted].iter(),
            study.embeddings(),
            &witnesses,
            Some(study.sightlines()),
        );
        assert_eq!(report.examined, 1);
        assert_eq!(report.violations.len(), 1, "{:?}", report.violations);
        assert!(report.violations[0].what.contains("sees witness"));
    }
}
