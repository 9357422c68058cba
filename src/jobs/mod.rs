//! The jobs: what ps30 does with the core stages.
//!
//! Each job has a folder of its own and computes results as plain data; how
//! those results are printed is the business of [`crate::present`].
//! [`bundled`] is the table of shaders shipped inside the binary, shared by
//! every job, and [`backend`] the one way a job draws (emulator or GPU).
//! Jobs import the core, [`bundled`] and [`backend`]; a job may use another
//! job only where the arrow below points (no cycles):
//!
//! * `verify` → `gen`, `luminance`, `tonemap`
//! * `gen` → `luminance`, `studies` (the plan lists the mip-chain method)
//! * `tonemap` → `luminance`
//! * `profile` → `scenes`, `luminance`
//! * `studies` → `render`, `luminance`, `tonemap`, `scenes`
//! * `render` → `scenes` (its synthetic textures)
//! * `compare` → `luminance`, `tonemap`, `gen`, `scenes` (the shaders it draws twice)
//!
//! [`conformance`] (the draws of the conformance corpus) uses no other job.

pub mod backend;
pub mod bundled;
pub mod compare;
pub mod conformance;
pub mod gen;
pub mod luminance;
pub mod profile;
pub mod render;
pub mod scenes;
pub mod studies;
pub mod tonemap;
pub mod verify;
