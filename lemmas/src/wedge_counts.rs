//! Kernel and wedge edges counted per class and per embedding (Def 5.2),
//! from [`crate::Study::cell_edges`]: what the bound claims L5.1, L5.2 and
//! T5.16 measure. An edge on both a kernel line and a wedge line counts as
//! both a kernel edge and a wedge edge; an edge on neither (O5.3's known
//! gap) as neither.

use rug::Rational;
use serde_json::json;
use wai_embed::wedge::CellEdgeKind;

use crate::driver::{Checker, Report, Violation};
use crate::{sample, Study};

/// A bound claim measured on the Def 5.2 counts: its id, the measurement
/// (report and largest ratio against a given ceiling) and its ceiling.
#[derive(Debug, Clone, Copy)]
pub struct EdgeBound {
    pub id: &'static str,
    pub check_with_ratio: fn(&Study<'_>, &Rational) -> (Report, Rational),
    pub ceiling: fn() -> Rational,
}

impl Checker for EdgeBound {
    fn id(&self) -> &'static str {
        self.id
    }
    fn check_study(&self, study: &Study<'_>) -> Report {
        (self.check_with_ratio)(study, &(self.ceiling)()).0
    }
}

/// The test every [`EdgeBound`] passes: on `convex-niches` k = 2 it
/// examines the map once with a positive ratio under its ceiling, and
/// reports a violation against a ceiling of half that ratio.
#[cfg(test)]
pub(crate) fn assert_measures_and_can_fail(bound: &EdgeBound) {
    let map = wai_gen::family("convex-niches", &[2]).unwrap();
    let study = Study::new(&map);
    let (report, ratio) = (bound.check_with_ratio)(&study, &(bound.ceiling)());
    assert_eq!(
        (report.examined, report.violations.len()),
        (1, 0),
        "{}",
        bound.id
    );
    assert!(ratio > 0, "{}", bound.id);
    let (report, _) = (bound.check_with_ratio)(&study, &(ratio / 2));
    assert_eq!(report.violations.len(), 1, "{}", bound.id);
    assert!(report.violations[0].what.contains("above the ceiling"));
}

/// Kernel edges K and wedge edges W of one class, and W_j by embedding
/// index (of the class's embeddings).
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct EdgeCounts {
    pub kernel: usize,
    pub wedge: usize,
    pub wedge_by_embedding: std::collections::BTreeMap<usize, usize>,
}

/// The counts of every class.
pub fn counts(classes: &[Vec<crate::study::CellEdges>]) -> Vec<EdgeCounts> {
    classes
        .iter()
        .map(|cells| {
            let mut c = EdgeCounts::default();
            for cell in cells {
                for k in &cell.kinds {
                    let (kernel, wedge) = match k {
                        CellEdgeKind::Kernel => (1, 0),
                        CellEdgeKind::Wedge => (0, 1),
                        CellEdgeKind::Both => (1, 1),
                        CellEdgeKind::Neither => (0, 0),
                    };
                    c.kernel += kernel;
                    c.wedge += wedge;
                    *c.wedge_by_embedding.entry(cell.embedding).or_default() += wedge;
                }
            }
            c
        })
        .collect()
}

/// One bound claim's verdict on a map: the largest ratio over its
/// instances (`(ratio, where)`), one examined instance per map, a
/// violation above `ceiling`.
pub fn ratio_report(
    id: &'static str,
    map: &wai_map::Map,
    largest: Option<(Rational, serde_json::Value)>,
    ceiling: &Rational,
) -> (Report, Rational) {
    let mut report = Report::new(id);
    let Some((ratio, at)) = largest else {
        return (report, Rational::new());
    };
    report.measure(ratio.clone(), at.clone());
    report.record((ratio > *ceiling).then(|| {
        Violation::with_data(
            format!(
                "{id}: map {}: ratio {ratio} (≈ {:.4}) above the ceiling {ceiling}",
                sample::map_name(map),
                ratio.to_f64()
            ),
            json!({
                "map": sample::map_name(map),
                "ratio": ratio.to_string(),
                "ceiling": ceiling.to_string(),
                "at": at,
            }),
        )
    }));
    (report, ratio)
}
