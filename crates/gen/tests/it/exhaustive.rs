//! The exhaustive mode: counts against OEIS, every map valid, the local
//! growth test against the global simplicity test.

use crate::common::check_valid;
use std::collections::HashSet;
use wai_gen::{exhaustive_polyomino_maps, has_simple_boundary, polyominoes, Cell, Symmetry};

/// OEIS A001168 (fixed polyominoes) minus those with a hole (the 4 fixed
/// heptominoes around one hole at k = 7; at k = 8 the count is our own,
/// cross-checked by the free count below).
const FIXED_SIMPLE: [usize; 8] = [1, 2, 6, 19, 63, 216, 756, 2684];
/// OEIS A000104: free polyominoes without holes.
const FREE_SIMPLE: [usize; 8] = [1, 1, 2, 5, 12, 35, 107, 363];

#[test]
fn counts_match_oeis() {
    for k in 1..=8 {
        assert_eq!(
            polyominoes(k, Symmetry::Fixed).len(),
            FIXED_SIMPLE[k - 1],
            "fixed k={k}"
        );
        assert_eq!(
            polyominoes(k, Symmetry::Free).len(),
            FREE_SIMPLE[k - 1],
            "free k={k}"
        );
    }
}

#[test]
fn every_map_up_to_seven_cells_is_valid_and_distinct() {
    let mut seen = HashSet::new();
    let mut count = 0;
    for m in exhaustive_polyomino_maps(7, Symmetry::Fixed) {
        check_valid(&m);
        assert!(m.is_orthogonal());
        assert!(
            seen.insert(m.vertices().to_vec()),
            "duplicate {:?}",
            m.vertices()
        );
        count += 1;
    }
    assert_eq!(count, FIXED_SIMPLE[..7].iter().sum::<usize>());
}

#[test]
fn pinch_and_hole_are_rejected() {
    let pinch: [Cell; 2] = [(0, 0), (1, 1)];
    assert!(!has_simple_boundary(&pinch));
    // The heptomino around a hole: a 3×3 ring missing one corner.
    let holed: [Cell; 7] = [(0, 0), (1, 0), (0, 1), (0, 2), (1, 2), (2, 2), (2, 1)];
    assert!(!has_simple_boundary(&holed));
    let ring8: [Cell; 8] = [
        (0, 0),
        (1, 0),
        (2, 0),
        (0, 1),
        (2, 1),
        (0, 2),
        (1, 2),
        (2, 2),
    ];
    assert!(!has_simple_boundary(&ring8));
    let l: [Cell; 3] = [(0, 0), (1, 0), (0, 1)];
    assert!(has_simple_boundary(&l));
    assert!(!has_simple_boundary(&[]));
    assert!(!has_simple_boundary(&[(0, 0), (2, 0)]));
}

/// The boundary's vertex count matches `Polyomino::vertex_count`.
#[test]
fn vertex_counts_agree() {
    for k in 1..=6 {
        for p in polyominoes(k, Symmetry::Free) {
            assert_eq!(p.to_map().n(), p.vertex_count(), "{:?}", p.cells());
        }
    }
}

/// Differential: the local test used by random growth agrees with the
/// global simplicity test on every neighbour of every polyomino of up to 6
/// cells.
#[test]
fn local_growth_test_agrees_with_global_test() {
    let mut examined = 0;
    for k in 1..=6 {
        for p in polyominoes(k, Symmetry::Fixed) {
            let set: HashSet<Cell> = p.cells().iter().copied().collect();
            for &(x, y) in p.cells() {
                for c in [(x + 1, y), (x - 1, y), (x, y + 1), (x, y - 1)] {
                    if set.contains(&c) {
                        continue;
                    }
                    let mut bigger: Vec<Cell> = p.cells().to_vec();
                    bigger.push(c);
                    assert_eq!(
                        p.can_add(c),
                        has_simple_boundary(&bigger),
                        "{:?} + {c:?}",
                        p.cells()
                    );
                    examined += 1;
                }
            }
        }
    }
    assert!(examined > 3000, "{examined}");
}
