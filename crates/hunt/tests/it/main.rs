//! The integration tests of `wai-hunt`: the chapter 3 checkers run over
//! generated maps, the thesis families, small polyominoes and the R2V
//! floor plans, and bounded property tests of every checker and of the
//! shrinker.

mod cell_claims;
mod properties;
mod visibility_claims;
