//! Integration tests of `wai-gen`: one binary.

mod bytes;
mod common;
mod exhaustive;
mod families;
mod holes;
mod random;
mod strategies;
