//! The core stages: everything a shader passes through on its way from text
//! to numbers, and nothing that knows what a job does with them.
//!
//! One instruction table ([`isa`]) and one IR ([`ir`]) join the stages, as
//! in naga: the [`front`] end reads text into an AST and expands
//! REPEAT_BLOCK, [`valid`] lowers it and checks the ps_3_0 rules into an
//! [`ir::Shader`], and [`load`] runs the three in one call. [`bytecode`]
//! reads compiled shaders into a listing the front end reads like text, and
//! writes the tokens back. The [`cost`]
//! model and the [`emu`]lator take a validated shader, and so does the
//! [`translate`]ion to a naga module, which the [`gpu`] backend draws on a
//! Vulkan device; the emulator and the translation compute by the same
//! [`float_rules`]. [`image`] reads and writes the pixels they work on, in
//! the render-target formats of D3D9, and [`merge`] is the output merger
//! that puts a draw's colours into a target (blending, the colour write
//! mask, clears). [`diag`] renders every stage's errors,
//! [`numbers`] formats figures the same way everywhere, [`output`] writes
//! files atomically, and [`audit`] holds the constants a draw is given
//! against what its shader reads. Nothing here imports from `jobs` or `present`.

pub mod audit;
pub mod bytecode;
pub mod cost;
pub mod decltype;
pub mod decompile;
pub mod diag;
pub mod emu;
pub mod float_rules;
pub mod front;
pub mod gpu;
pub mod image;
pub mod input;
pub mod ir;
pub mod isa;
pub mod load;
pub mod merge;
pub mod numbers;
pub mod output;
pub mod phases;
pub mod pixel_inputs;
pub mod profile;
pub mod ps1;
pub mod raster;
pub mod translate;
pub mod valid;
