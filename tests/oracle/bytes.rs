//! Oracle fixtures: bytes (see `tests/oracle.rs`).

#[allow(unused_imports)]
use super::*;
