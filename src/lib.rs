//! # ps30 — Direct3D 9 pixel shader 3.0 assembly you can parse, measure, run and generate
//!
//! ps30 reads ps_3_0 assembly (with a real `REPEAT_BLOCK` macro), checks it
//! against the ps_3_0 rules, counts its instruction slots and executed
//! instructions against the 512 / 65,535 budgets, runs it on HDR images and
//! cross-checks the result against a CPU reference.
//!
//! ```text
//! asm text ──parse──▶ AST (spans) ──expand REPEAT_BLOCK──▶ AST ──validate──▶ Shader (Program + Info)
//!                                                                              │
//!                         ┌────────────────────┬────────────────────────────────┤
//!                         ▼                    ▼                                ▼
//!                    cost model      emulator (micro-ops,                  asm writer
//!                 (slots, executed,   64 lanes = 16 quads)
//!                  loop breakdown)           │
//!                                            ▼
//!         images ──▶ render targets (R32F / A16B16G16R16F) ──▶ luminance pipeline ──▶ cross-check
//!                                                                                 vs f64 reference
//! ```
//!
//! Modules, in the order data flows: [`front`] (parser, REPEAT_BLOCK),
//! [`valid`] (ps_3_0 rules → [`ir::Shader`]), [`cost`], [`emu`], [`image`],
//! [`reference`](mod@reference), [`pipeline`] (the luminance passes and their
//! cross-check), [`tonemap`], [`profile`] (quads and divergence) with
//! [`lights`] (its G-buffer scene), [`gen`] (`unroll` and `plan`), and
//! [`verify`] (the article's claims) with [`report_dir`] and [`figures`]
//! (the pages and PNGs of `reports/`); [`isa`] (the instruction table),
//! [`diag`], [`report`], [`writer`] and [`args`] serve them all.
//!
//! ```
//! use ps30::{cost, front};
//! let src = "ps_3_0\ndefi i0, 128, 0, 0, 0\nrep i0\n  add r0, r0, r0\nendrep\nmov oC0, r0\n";
//! let loaded = front::load_str("example.psh", src, &front::Options::default()).unwrap();
//! let analysis = cost::analyse(&loaded.shader, &loaded.file, &cost::Environment::default(),
//!                              &cost::Profile::ps_3_0()).unwrap();
//! assert_eq!(analysis.slots, 7);                       // rep 3 + add 1 + endrep 2 + mov 1
//! assert_eq!(analysis.executed.max, 128 * 6 + 1);      // (3 + 1 + 2) per iteration
//! ```

// Diagnostics are large on purpose (message, label, help, notes) and only
// travel on the error path, where their size costs nothing measurable.
#![allow(clippy::result_large_err)]

pub mod args;
pub mod cost;
pub mod diag;
pub mod emu;
pub mod figures;
pub mod front;
pub mod gen;
pub mod image;
pub mod ir;
pub mod isa;
pub mod lights;
pub mod pipeline;
pub mod profile;
pub mod reference;
pub mod report;
pub mod report_dir;
pub mod tonemap;
pub mod valid;
pub mod verify;
pub mod writer;
