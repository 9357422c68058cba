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
//! * `blocks` → `gen`, `luminance`
//! * `tonemap` → `blocks`, `luminance`
//! * `profile` → `scenes`, `luminance`
//! * `studies` → `render`, `luminance`, `tonemap`, `scenes`
//! * `render` → `scenes` (its synthetic textures)
//! * `shader_test` → `render` (its draws)
//! * `compare` → `luminance`, `tonemap`, `gen`, `scenes` (the shaders it draws twice)
//!
//! [`assets`] holds the bundled HDR images, compiled in like the shaders of
//! [`bundled`], so that an installed binary needs no source tree.
//!
//! [`blocks`] chooses the luminance passes' blocks for an image (the
//! planner's, with generated shaders, or a named shader's own).
//!
//! [`conformance`] (the draws of the conformance corpus) uses no other job;
//! [`outputs`] (what a pass wrote, channel by channel) only the core.

pub mod assets;
pub mod backend;
pub mod blocks;
pub mod bundled;
pub mod compare;
pub mod conformance;
pub mod corpus;
pub mod decompile;
pub mod gen;
pub mod luminance;
pub mod outputs;
pub mod profile;
pub mod render;
pub mod scenes;
pub mod shader_test;
pub mod studies;
pub mod tonemap;
pub mod verify;
pub mod vertices;
