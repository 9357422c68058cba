//! Oracle fixtures: listing (see `tests/oracle.rs`).

#[allow(unused_imports)]
use super::*;
