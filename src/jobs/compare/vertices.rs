//! A vertex shader on both backends: the emulator's vertex stage
//! (`emu::vertex`) against the translation's compute entry point on a
//! device (`gpu::run_vertices`), output register by output register and
//! component by component, with the pixel comparison's statistics
//! ([`super::stats`]) and explanations ([`super::explain::draw`]): a
//! vertex is a pixel of a one-row image, its outputs the channels.
//!
//! Vertex-only instructions are explained by the probed instruction they
//! compute with ([`probed_ops`]): `lit` by `pow`, `expp`/`logp` by
//! `exp`/`log`, `dst` by `mul`, the matrix instructions and `dp3` by `dp4`
//! (dot products of the same kind), `sub` by `add`.

use super::{explain, opcodes, CompareError, DrawComparison, PixelInputs};
use crate::core::emu::vertex::{self, VertexDraw, Vertices};
use crate::core::gpu::{self, Gpu};
use crate::core::ir::Shader;
use crate::core::isa::RegFile;
use crate::core::load::Loaded;
use stats::ChannelStats;

use super::stats;

/// The probed instruction each vertex-shader instruction computes with.
pub fn probed_ops(shader: &Shader) -> Vec<String> {
    let mut ops = opcodes(&[shader]);
    let extra: Vec<&str> = ops
        .iter()
        .filter_map(|op| match op.as_str() {
            "lit" => Some("pow"),
            "expp" => Some("exp"),
            "logp" => Some("log"),
            "dst" | "crs" => Some("mul"),
            "m4x4" | "m4x3" | "m3x4" | "m3x3" | "m3x2" | "dp3" => Some("dp4"),
            "sub" => Some("add"),
            _ => None,
        })
        .collect();
    ops.extend(extra.into_iter().map(String::from));
    ops.sort_unstable();
    ops.dedup();
    ops
}

/// Runs `loaded`'s vertex shader over `vertices` on the emulator and on
/// `gpu`, and compares every output component (unrounded f32 on both).
pub fn compare_vertices(
    gpu: &Gpu,
    loaded: &Loaded,
    draw: &VertexDraw,
    vertices: &Vertices,
) -> Result<DrawComparison, CompareError> {
    let shader = &loaded.shader;
    let e = vertex::run(shader, draw, vertices).map_err(|e| CompareError::Other(e.to_string()))?;
    let g = gpu::run_vertices(gpu, shader, draw, vertices).map_err(CompareError::Gpu)?;
    let n = vertices.count as u32;
    let mut channels = Vec::new();
    for (k, slot) in e.slots.iter().enumerate() {
        for (c, name) in ["x", "y", "z", "w"].iter().enumerate() {
            let ev: Vec<f32> = e.values.iter().map(|v| v[k][c]).collect();
            let gv: Vec<f32> = g.values.iter().map(|v| v[k][c]).collect();
            channels.push(ChannelStats::of(
                format!("{}.{name}", slot.register),
                n,
                &ev,
                &gv,
            ));
        }
    }
    let bound =
        vertex::check(shader, draw, vertices).map_err(|e| CompareError::Other(e.to_string()))?;
    let mut worst: Vec<u32> = channels
        .iter()
        .flat_map(|c| c.worst.iter().map(|w| w.x))
        .collect();
    worst.sort_unstable();
    worst.dedup();
    let worst_inputs = worst
        .into_iter()
        .map(|v| {
            let inputs = vertex::vertex_inputs(&bound, vertices, v as usize);
            let values = shader
                .program()
                .inputs
                .iter()
                .filter(|d| d.reg.file == RegFile::Input && d.reg.index < 16)
                .map(|d| (format!("v{}", d.reg.index), inputs[d.reg.index as usize]))
                .collect();
            PixelInputs { x: v, y: 0, values }
        })
        .collect();
    Ok(DrawComparison {
        shader: loaded.file.name.clone(),
        width: n,
        height: 1,
        target: "vertex outputs (f32, unrounded)".into(),
        float_rules: draw.float_rules.name().into(),
        channels,
        killed_mismatches: 0,
        worst_inputs,
        opcodes: probed_ops(shader),
        filtering: Vec::new(),
        explanation: None,
    })
}

/// [`compare_vertices`] with its explanation from `probes`.
pub fn explained(
    gpu: &Gpu,
    loaded: &Loaded,
    draw: &VertexDraw,
    vertices: &Vertices,
    probes: &[super::probe::Probe],
) -> Result<DrawComparison, CompareError> {
    let mut c = compare_vertices(gpu, loaded, draw, vertices)?;
    c.explanation = Some(explain::draw(&c, probes));
    Ok(c)
}
