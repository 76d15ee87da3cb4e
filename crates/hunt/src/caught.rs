//! A checker that panics on a map is a finding, not the end of a run: the
//! panic is caught and turned into a violation of the checker's claim,
//! with the panic's message and place, so that the search stores the map
//! (shrunk, with its replay command) and goes on with the next map.
//!
//! A checker panics on a checker bug ([`Checker::run`]: an inconsistent
//! report) or on a bug in a structure it reads (a study stage). Either way
//! the map is worth keeping: it is the smallest evidence of the bug.
//!
//! The panics caught here are not printed by the default hook (a shrink
//! can meet thousands); [`run_caught`] installs, once, a hook that keeps
//! the message and place of a panic on a thread inside it and passes every
//! other panic to the hook that was there before.

use std::cell::{Cell, RefCell};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::Once;

use wai_lemmas::{Checker, Report, Violation};
use wai_study::Study;

/// The `data["kind"]` of a violation made from a panic.
pub const PANIC_KIND: &str = "panic";

thread_local! {
    /// True while this thread runs a checker inside [`run_caught`].
    static CATCHING: Cell<bool> = const { Cell::new(false) };
    /// The message and place of the last panic caught on this thread.
    static LAST: RefCell<Option<String>> = const { RefCell::new(None) };
}

static HOOK: Once = Once::new();

fn install_hook() {
    HOOK.call_once(|| {
        let before = std::panic::take_hook();
        std::panic::set_hook(Box::new(move |info| {
            if CATCHING.with(Cell::get) {
                let message = info
                    .payload()
                    .downcast_ref::<&str>()
                    .map(|s| (*s).to_owned())
                    .or_else(|| info.payload().downcast_ref::<String>().cloned())
                    .unwrap_or_else(|| "a panic without a message".to_owned());
                let place = info
                    .location()
                    .map_or(String::new(), |l| format!(" at {}:{}", l.file(), l.line()));
                LAST.with(|last| *last.borrow_mut() = Some(format!("{message}{place}")));
            } else {
                before(info);
            }
        }));
    });
}

/// `checker` on `study`, a panic caught and returned as a one-instance
/// report whose one violation ([`PANIC_KIND`]) says what panicked where.
pub fn run_caught(checker: &Checker, study: &Study<'_>) -> Report {
    install_hook();
    let was = CATCHING.with(|c| c.replace(true));
    let result = catch_unwind(AssertUnwindSafe(|| checker.run(study)));
    CATCHING.with(|c| c.set(was));
    match result {
        Ok(report) => report,
        Err(payload) => {
            // The hook's message with its place; from the payload when the
            // panic was on another thread (a parallel loop of the study on
            // a shared pool), which rayon carries back here.
            let message = LAST
                .with(|last| last.borrow_mut().take())
                .or_else(|| payload.downcast_ref::<&str>().map(|s| (*s).to_owned()))
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "a panic without a message".to_owned());
            panic_report(checker.id, &message)
        }
    }
}

/// [`run_caught`] on `map` alone (a study of its own).
pub fn check_map_caught(checker: &Checker, map: &wai_map::Map) -> Report {
    run_caught(checker, &Study::new(map))
}

/// The report of a checker of claim `claim` that panicked with `message`.
fn panic_report(claim: &'static str, message: &str) -> Report {
    let mut report = Report::new(claim);
    report.record(Some(Violation::with_data(
        format!("the checker panicked: {message}"),
        serde_json::json!({ "kind": PANIC_KIND, "message": message }),
    )));
    report
}

/// True if `violation` was made from a panic.
pub fn is_panic(violation: &Violation) -> bool {
    violation.kind() == Some(PANIC_KIND)
}

#[cfg(test)]
mod tests {
    use super::*;

    const PANICS_ON_SQUARES: Checker = Checker::new("T3.2", |study| {
        assert!(study.map().n() != 4, "planted: a square");
        Report::new("T3.2")
    });

    #[test]
    fn a_panic_on_a_pool_thread_keeps_its_message() {
        const IN_PARALLEL: Checker = Checker::new("T3.2", |_| {
            use rayon::prelude::*;
            (0..256u32)
                .into_par_iter()
                .for_each(|i| assert!(i % 97 != 96, "planted: a parallel loop at {i}"));
            Report::new("T3.2")
        });
        let square = wai_gen::family("corridor-niches", &[1]).expect("family");
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(3)
            .build()
            .unwrap();
        let report = pool.install(|| check_map_caught(&IN_PARALLEL, &square));
        assert_eq!(report.violations.len(), 1);
        let what = &report.violations[0].what;
        assert!(what.contains("planted: a parallel loop at"), "{what}");
    }

    #[test]
    fn a_panic_becomes_a_violation_with_its_message_and_place() {
        let square = wai_gen::family("corridor-niches", &[1]).expect("family");
        let triangle = wai_map::Map::from_ring(vec![
            wai_exact::Point::new(0, 0),
            wai_exact::Point::new(4, 0),
            wai_exact::Point::new(0, 4),
        ])
        .expect("a triangle")
        .0;
        let quiet = check_map_caught(&PANICS_ON_SQUARES, &triangle);
        assert!(quiet.violations.is_empty());
        let square_map = wai_map::Map::from_ring(vec![
            wai_exact::Point::new(0, 0),
            wai_exact::Point::new(4, 0),
            wai_exact::Point::new(4, 4),
            wai_exact::Point::new(0, 4),
        ])
        .expect("a square")
        .0;
        let report = check_map_caught(&PANICS_ON_SQUARES, &square_map);
        assert_eq!((report.examined, report.violations.len()), (1, 1));
        let v = &report.violations[0];
        assert!(is_panic(v));
        assert!(v.what.contains("planted: a square"), "{}", v.what);
        assert!(v.what.contains("caught.rs:"), "{}", v.what);
        // Not a known failure of any checker: a counterexample.
        assert_eq!(PANICS_ON_SQUARES.counterexamples(&report).count(), 1);
        // The thread goes on, and a real checker still runs on it.
        let real = wai_lemmas::ch3::t3_3a::CHECKER.check_map(&square);
        assert!(real.examined > 0);
    }
}
