//! The integration tests of `wai-lemmas`: the claims registry against
//! `shared/CLAIMS.md`, the stored maps of `counterexamples/` and the
//! figures they show, and the chapter 5 checkers on the layouts that reach
//! their premises.

mod counterexamples;
mod figures;
mod interweave;
mod registry;

use std::path::PathBuf;

/// `shared/` sits next to the repository root (CI clones it the same way).
const SHARED: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../../shared");

/// Reads a file of `shared/`, failing the test with a clear message if it is
/// missing: a registry check must never pass vacuously.
fn read_shared(name: &str) -> String {
    let path = PathBuf::from(SHARED).join(name);
    match std::fs::read_to_string(&path) {
        Ok(text) => text,
        Err(e) => panic!(
            "cannot read {} ({e}): the registry tests need shared/{name} next to the \
             repository root; without it nothing is checked",
            path.display()
        ),
    }
}
