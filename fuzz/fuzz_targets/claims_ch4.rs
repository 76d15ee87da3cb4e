//! Bytes → a small valid map (`wai_gen::bytes`) → every checker of a
//! chapter 4 claim (`wai_lemmas::checkers_of_chapter(4)`, through
//! `wai_hunt::run`).
//!
//! Law: no violation other than the known failures
//! (declared by its checker). A violation writes its replay file to
//! `fuzz/artifacts/replay/` and panics naming the claim (`wai_fuzz::check_claims`).
//! With `WAI_PLANT=<name>` the planted checker of that name replaces the
//! real one of its claim when the claim is of chapter 4.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| wai_fuzz::check_claims(4, data));
