//! The proptest strategies and the quickcheck `Arbitrary` make valid maps,
//! and their shrinking stays valid and gets smaller.

use crate::common::check_valid;
use proptest::prelude::*;
use proptest::strategy::ValueTree;
use proptest::test_runner::TestRunner;
use quickcheck::{Arbitrary, Gen};
use wai_gen::{arb_map, arb_orthogonal_map, arb_polyomino, arb_simple_map, shrink_map, ArbMap};

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn arb_map_is_valid(m in arb_map()) {
        check_valid(&m);
    }

    #[test]
    fn arb_simple_map_is_valid(m in arb_simple_map()) {
        check_valid(&m);
    }

    #[test]
    fn arb_orthogonal_map_is_valid_and_orthogonal(m in arb_orthogonal_map()) {
        check_valid(&m);
        prop_assert!(m.is_orthogonal());
    }
}

/// Shrinking a polyomino tree to the end drops cells one at a time, each
/// step valid, down to a single cell when every value "fails".
#[test]
fn polyomino_tree_shrinks_to_one_cell() {
    let mut runner = TestRunner::deterministic();
    for _ in 0..20 {
        let mut tree = arb_polyomino().new_tree(&mut runner).unwrap();
        let mut len = tree.current().len();
        while tree.simplify() {
            let cur = tree.current();
            assert_eq!(cur.len() + 1, len);
            check_valid(&cur.to_map());
            len = cur.len();
        }
        assert_eq!(len, 1);
    }
}

/// The shrinking search of proptest finds a minimal failing orthogonal map:
/// "at least 8 vertices" fails first at 6 cells or fewer and shrinks to a
/// map with exactly 8 vertices.
#[test]
fn proptest_shrinks_to_a_minimal_counterexample() {
    let mut runner = TestRunner::deterministic();
    let result = runner.run(&arb_orthogonal_map(), |m| {
        prop_assert!(m.n() < 8);
        Ok(())
    });
    match result {
        Err(proptest::test_runner::TestError::Fail(_, m)) => {
            check_valid(&m);
            assert_eq!(m.n(), 8, "{:?}", m.vertices());
        }
        other => panic!("expected a failure, got {other:?}"),
    }
}

#[test]
fn quickcheck_maps_are_valid_and_shrink_validly() {
    let mut g = Gen::new(24);
    for _ in 0..300 {
        let ArbMap(m) = ArbMap::arbitrary(&mut g);
        check_valid(&m);
        for s in ArbMap(m.clone()).shrink().take(8) {
            check_valid(&s.0);
            let smaller_n = s.0.n() < m.n();
            let extent = |m: &wai_map::Map| {
                let v = m.vertices();
                let w = v.iter().map(|p| p.x).max().unwrap() - v.iter().map(|p| p.x).min().unwrap();
                let h = v.iter().map(|p| p.y).max().unwrap() - v.iter().map(|p| p.y).min().unwrap();
                (w, h)
            };
            let (ew, eh) = extent(&s.0);
            let (mw, mh) = extent(&m);
            let at_origin = s.0.vertices().iter().map(|p| p.x).min() == Some(0)
                && s.0.vertices().iter().map(|p| p.y).min() == Some(0);
            assert!(smaller_n || ew < mw || eh < mh || at_origin);
        }
    }
}

/// Repeated quickcheck shrinking of a map that always "fails" ends, at a
/// triangle or a map none of whose shrinks is valid.
#[test]
fn quickcheck_shrinking_terminates() {
    let mut g = Gen::new(16);
    for _ in 0..10 {
        let ArbMap(mut m) = ArbMap::arbitrary(&mut g);
        for _ in 0..10_000 {
            match shrink_map(&m).into_iter().next() {
                Some(s) => m = s,
                None => break,
            }
        }
        assert!(
            shrink_map(&m).is_empty(),
            "did not settle: {:?}",
            m.vertices()
        );
        check_valid(&m);
    }
}
