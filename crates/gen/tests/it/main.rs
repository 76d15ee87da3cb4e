//! Integration tests of `wai-gen`: one binary (STYLE.md 11).

mod bytes;
mod common;
mod exhaustive;
mod families;
mod random;
mod strategies;
