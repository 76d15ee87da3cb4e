//! Bounded property tests of every checker (tests in CI stay bounded): small generated maps, fixed case counts, so `cargo test`
//! searches a little on every run while `wai check` and `cargo fuzz` search
//! at length.
//!
//! For every registered checker, on maps of the random kinds with at most
//! 12 vertices (proptest) and of the chapter 4/5 layouts (which reach the
//! premises the random maps miss):
//! - the report is for the checker's claim and has no more violations than
//!   instances examined;
//! - it reports no violation other than the known failures;
//! - checking the same map twice gives the same report (determinism).
//!
//! quickcheck drives the shrinker: whatever it returns is a valid map on
//! which the predicate still holds, with no more vertices than it started
//! with.

use proptest::prelude::*;
use wai_map::Map;
use wai_study::Study;

/// Every checker's laws on one map; the first broken one as an error.
fn laws(map: &Map) -> Result<(), String> {
    let study = Study::new(map);
    let again = Study::new(map);
    for checker in wai_lemmas::checkers() {
        // `run` holds the report to the checker's declarations.
        let report = checker.run(&study);
        if let Some(v) = checker.counterexamples(&report).next() {
            return Err(format!(
                "{} violated on {}: {}\n{}",
                report.claim,
                map.name().unwrap_or("a map"),
                v.what,
                wai_map::json::to_json(map)
            ));
        }
        if checker.run(&again) != report {
            return Err(format!("{}: two runs differ", checker.id));
        }
    }
    Ok(())
}

/// A map of a random kind with at most 12 vertices.
fn small_map() -> impl Strategy<Value = Map> {
    (0..wai_gen::RANDOM_KINDS.len(), 4usize..=12, any::<u64>()).prop_map(|(k, n, seed)| {
        let kind = &wai_gen::RANDOM_KINDS[k];
        let n = n.clamp(kind.min_n, 12);
        wai_gen::random(kind.id, n, seed)
            .expect("n within the kind's range")
            .with_name(format!("{} n={n} seed={seed}", kind.id))
    })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 12, ..ProptestConfig::default() })]

    #[test]
    fn every_checker_holds_on_small_random_maps(map in small_map()) {
        laws(&map).map_err(TestCaseError::fail)?;
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 5, ..ProptestConfig::default() })]

    #[test]
    fn every_checker_holds_on_the_layouts(k in 0..wai_gen::LAYOUTS.len(), seed in any::<u64>()) {
        let layout = &wai_gen::LAYOUTS[k];
        let map = (layout.generate)(seed).with_name(format!("{} seed={seed}", layout.id));
        laws(&map).map_err(TestCaseError::fail)?;
    }
}

#[test]
fn shrinking_keeps_the_predicate_and_validity() {
    fn prop(m: wai_gen::ArbMap) -> bool {
        let map = m.0;
        let reflex = |m: &Map| m.r() >= 1;
        if !reflex(&map) {
            return true;
        }
        let s = wai_hunt::shrink::shrink(&map, reflex, 500);
        reflex(&s.map)
            && s.map.n() <= map.n()
            && Map::from_ring(s.map.vertices().to_vec()).is_ok()
            && s.from_n == map.n()
    }
    quickcheck::QuickCheck::new()
        .tests(40)
        .quickcheck(prop as fn(wai_gen::ArbMap) -> bool);
}
