//! Where a study's time goes: each stage's own time, without the time of
//! the earlier stages it asked for, summed over the builds of the stage
//! (`wai check --profile`).
//!
//! A stage that asks for another while it is being built (the witnesses ask
//! for the embeddings, which ask for the decomposition) is charged only for
//! its own work: the timer keeps a stack of the stages under way and
//! subtracts each finished stage's time from the one below it. Readers that
//! are not stages (a claim checker) are charged the rest: their wall time
//! minus [`StageTimes::total`]'s growth while they ran.

use std::cell::RefCell;
use std::collections::BTreeMap;
use std::time::{Duration, Instant};

/// The name of a stage of the pipeline (`"decomposition"`, `"embeddings"`).
pub type Stage = &'static str;

/// Per stage: its own time and how many times it was built.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct StageTimes {
    /// By stage: (own time, builds).
    pub stages: BTreeMap<Stage, (Duration, u64)>,
}

impl StageTimes {
    /// The sum of every stage's own time: the wall time spent in stages.
    pub fn total(&self) -> Duration {
        self.stages.values().map(|(t, _)| *t).sum()
    }

    /// Adds another profile's times and builds to this one.
    pub fn absorb(&mut self, other: &StageTimes) {
        for (stage, (t, k)) in &other.stages {
            let mine = self.stages.entry(stage).or_default();
            mine.0 += *t;
            mine.1 += *k;
        }
    }
}

/// The timer of one study: the stages under way, innermost last, and the
/// totals so far.
///
/// The totals are a short list rather than a map: a study times some
/// stages once per pair of embeddings, and a lookup by the name's address
/// (stage names are literals) costs no string comparison.
#[derive(Debug, Default)]
pub(crate) struct Timer {
    /// (stage, start, time of the stages it asked for so far).
    open: RefCell<Vec<(Stage, Instant, Duration)>>,
    /// (stage, own time, builds), in order of first build.
    done: RefCell<Vec<(Stage, Duration, u64)>>,
}

/// The entry of `stage` in `done`, made if missing: found by the address
/// of the name first, then by its text (two copies of one literal).
fn entry(done: &mut Vec<(Stage, Duration, u64)>, stage: Stage) -> &mut (Stage, Duration, u64) {
    let same_literal =
        |s: &Stage| std::ptr::eq(s.as_ptr(), stage.as_ptr()) && s.len() == stage.len();
    let at = match done.iter().position(|e| same_literal(&e.0)) {
        Some(at) => at,
        None => match done.iter().position(|e| e.0 == stage) {
            Some(at) => at,
            None => {
                done.push((stage, Duration::ZERO, 0));
                done.len() - 1
            }
        },
    };
    &mut done[at]
}

impl Timer {
    /// Runs `build`, the work of `stage`, and charges it its own time.
    pub(crate) fn stage<T>(&self, stage: Stage, build: impl FnOnce() -> T) -> T {
        self.open
            .borrow_mut()
            .push((stage, Instant::now(), Duration::ZERO));
        let out = build();
        let mut open = self.open.borrow_mut();
        let (name, start, inner) = open.pop().expect("the stage pushed above");
        debug_assert_eq!(name, stage, "stages finish innermost first");
        let spent = start.elapsed();
        if let Some(parent) = open.last_mut() {
            parent.2 += spent;
        }
        let mut done = self.done.borrow_mut();
        let e = entry(&mut done, stage);
        e.1 += spent.saturating_sub(inner);
        e.2 += 1;
        out
    }

    /// The times so far.
    pub(crate) fn times(&self) -> StageTimes {
        let mut times = StageTimes::default();
        for &(stage, t, k) in self.done.borrow().iter() {
            let mine = times.stages.entry(stage).or_default();
            mine.0 += t;
            mine.1 += k;
        }
        times
    }

    /// The total own time of the stages finished so far.
    pub(crate) fn total(&self) -> Duration {
        self.done.borrow().iter().map(|e| e.1).sum()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_stage_is_charged_its_own_time_only() {
        let timer = Timer::default();
        let wait = |ms| std::thread::sleep(Duration::from_millis(ms));
        timer.stage("outer", || {
            wait(20);
            timer.stage("inner", || wait(30));
            timer.stage("inner", || wait(30));
        });
        let t = timer.times();
        let (outer, inner) = (t.stages["outer"], t.stages["inner"]);
        assert_eq!((outer.1, inner.1), (1, 2));
        assert!(inner.0 >= Duration::from_millis(60));
        // The outer stage's own time excludes the 60 ms of the inner ones.
        assert!(outer.0 >= Duration::from_millis(20) && outer.0 < Duration::from_millis(55));
        assert_eq!(timer.total(), outer.0 + inner.0);
    }
}
