//! Oracle fixtures: accept (see `tests/oracle.rs`).

#[allow(unused_imports)]
use super::*;
