//! The integration tests, one test binary: each file in `tests/` is a module
//! of this crate, so the library and its dependencies are linked into one
//! executable instead of one per file (a clean `cargo test` spends its time
//! compiling, and 28 test crates each compiled and linked the whole crate
//! again). `tests/common/` holds what several files share. Run one file's
//! tests with `cargo test --test suite FILE::`, e.g. `cargo test --test suite
//! conformance::`. `Cargo.toml` turns off the discovery of separate test
//! binaries (`autotests = false`); `layering.rs` checks that every file in
//! `tests/` is declared here.

mod common;

mod bench_goals;
mod bytecode;
mod cli;
mod cli_gpu;
mod cli_ux;
mod conformance;
mod corpus;
mod corpus_mode;
mod cost;
mod d3d9_conformance;
mod d3d9_conformance_ps2;
mod damaged_inputs;
mod decompile;
mod docs;
mod draw_conformance;
mod draw_conformance_raster;
mod draw_gpu;
mod gen;
mod gpu;
mod gpu_layered;
mod guide_tables;
mod hostile;
mod json_schema;
mod layering;
mod lights;
mod luminance;
mod malformed;
mod oracle;
mod pixel_history;
mod profile_list;
mod ps1_run;
mod quads;
mod reference_values;
mod render;
mod reports;
mod roundtrip;
mod shader_test;
mod studies;
mod textures;
mod tonemap;
mod translate;
mod ux;
mod validation;
mod vertex_gpu;
mod vertex_shaders;
mod wine_vectors;
