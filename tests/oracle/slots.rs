//! Oracle fixtures: slots (see `tests/oracle.rs`).

#[allow(unused_imports)]
use super::*;
