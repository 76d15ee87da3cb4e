//! The checkers of chapter 4's claims, one module per claim id.

pub mod c4_10;
pub mod c4_15;
pub mod c4_16;
pub mod c4_20;
pub mod l4_1;
pub mod l4_17;
pub mod l4_18;
pub mod l4_5;
pub mod l4_6;
pub mod l4_7;
pub mod l4_8;
pub mod l4_9;
pub mod t4_19;
pub mod t4_2;
pub mod t4_3;
