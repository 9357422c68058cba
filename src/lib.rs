//! # ps30 — Direct3D 9 pixel shader 3.0 assembly you can parse, measure, run and generate
//!
//! ps30 reads ps_3_0 assembly (with a real `REPEAT_BLOCK` macro) and
//! compiled ps_3_0 bytecode, checks it against the ps_3_0 rules, counts its
//! instruction slots and executed instructions against the 512 / 65,535
//! budgets, runs it on HDR images and cross-checks the result against a CPU
//! reference; it writes bytecode back exactly as Microsoft's assembler does.
//! Draws meet in render targets of D3D9's formats through the output merger
//! (blending, write masks, clears), so lights accumulate and mip chains
//! reduce, as in the article's lighting phase and the alternatives it is
//! measured against.
//!
//! ```text
//! bytecode ──read──▶ tokens ──listing──┐            (and back: AST ──write──▶ tokens)
//!                                      ▼
//! asm text ──parse──▶ AST (spans) ──expand REPEAT_BLOCK──▶ AST ──validate──▶ Shader (Program + Info)
//!                                                                              │
//!                         ┌────────────────────┬────────────────────────────────┤
//!                         ▼                    ▼                                ▼
//!                    cost model      emulator (micro-ops,    naga lowering ──▶ WGSL, SPIR-V, GLSL,
//!                 (slots, executed,   64 lanes = 16 quads)      │          HLSL, MSL; asm printer
//!                  loop breakdown)           │  float rules     ▼
//!                                            │           GPU backend (wgpu, Vulkan)
//!                                            ▼
//!         images ──▶ output merger ──▶ render targets (8-bit, half, single; mip chains)
//!                                            │
//!                                            ▼
//!         draw lists, luminance passes, tone mapping, studies ──▶ cross-checks vs f64 references
//! ```
//!
//! The crate is built in levels, and imports point one way (`ARCHITECTURE.md`
//! at the top of the repository draws the whole map):
//!
//! * [`core`](mod@core) — the stages every job shares: the instruction table
//!   and IR, the front end and printer, bytecode in and out, validation, the
//!   cost model, the emulator, the float rules, the translation to naga
//!   (WGSL, SPIR-V, GLSL, HLSL, MSL), the GPU backend (wgpu, Vulkan), images
//!   and render targets, and the output merger;
//! * [`jobs`] — what ps30 does with them: the luminance pipeline with its
//!   reference, tone mapping, profiling, the generator and planner, scenes,
//!   draw lists, the studies of the alternatives, the article's claims, and
//!   the draws of the conformance corpus;
//! * [`present`] — text, JSON, Markdown pages and figures of those results.
//!
//! The command line (`src/main.rs` and `src/cli/`) sits on top and is not
//! part of the library.
//!
//! ```
//! use ps30::core::{cost, load};
//! let src = "ps_3_0\ndefi i0, 128, 0, 0, 0\nmov r0, c0\nrep i0\n  add r0, r0, r0\nendrep\nmov oC0, r0\n";
//! let loaded = load::load_str("example.psh", src, &load::Options::default()).unwrap();
//! let analysis = cost::analyse(&loaded.shader, &loaded.file, &cost::Environment::default(),
//!                              &cost::Profile::ps_3_0()).unwrap();
//! assert_eq!(analysis.slots, 8);                       // mov 1 + rep 3 + add 1 + endrep 2 + mov 1
//! assert_eq!(analysis.executed.max, 1 + 128 * 6 + 1);  // (3 + 1 + 2) per iteration
//! ```

// Diagnostics are large on purpose (message, label, help, notes) and only
// travel on the error path, where their size costs nothing measurable.
#![allow(clippy::result_large_err)]

pub mod core;
pub mod jobs;
pub mod present;
