//! Kernel and wedge edges counted per class and per embedding (Def 5.2),
//! from [`crate::Study::cell_edges`]: what the bound claims L5.1, L5.2 and
//! T5.16 measure. An edge on both a kernel line and a wedge line counts as
//! both a kernel edge and a wedge edge; an edge on neither (O5.3's known
//! gap) as neither.

use wai_embed::wedge::CellEdgeKind;

/// Kernel edges K and wedge edges W of one class, and W_j by embedding
/// index (of the class's embeddings).
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct EdgeCounts {
    pub kernel: usize,
    pub wedge: usize,
    pub wedge_by_embedding: std::collections::BTreeMap<usize, usize>,
}

/// The counts of every class.
pub fn counts(classes: &[Vec<crate::CellEdges>]) -> Vec<EdgeCounts> {
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
