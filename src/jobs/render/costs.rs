//! What one draw's pixel shader cost over the pixels it ran on, gathered
//! primitive by primitive as the draw runs (for `ps30 profile --list`):
//! each covered pixel's own executed slots, and each 2×2 quad a primitive
//! reached — at a primitive's edges a quad of 1 to 3 covered pixels whose
//! other lanes run as helpers — with what it executed in lockstep, whether
//! it diverged, and the gradient sites summed over the primitives. A quad
//! two primitives share is counted once per primitive, as hardware runs it
//! once per primitive. What ran each instruction is summed over the
//! primitives too, for the costs per source line.

use crate::core::emu::{DrawOutput, GradientSite, InstructionCount};

/// One quad a primitive (or a full-screen draw) ran.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct QuadRun {
    /// Slots the quad executed in lockstep.
    pub executed: u64,
    /// The covered pixels' own slots, summed.
    pub own: u64,
    /// Covered pixels of the quad (1–4).
    pub pixels: u64,
    /// Some instruction ran with only part of the quad.
    pub divergent: bool,
}

/// The costs of step `step`'s pixel shader.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct DrawCosts {
    /// The draw step gathered.
    pub step: usize,
    /// Executed slots of each covered pixel, primitive after primitive.
    pub pixels: Vec<u64>,
    /// Each quad with a covered pixel, primitive after primitive.
    pub quads: Vec<QuadRun>,
    /// The gradient sites of the pixel shader, summed over its runs.
    pub gradients: Vec<GradientSite>,
    /// Primitives that ran the shader (a full-screen draw is one).
    pub primitives: u64,
    /// What ran each instruction of the shader (by its index), summed
    /// over the primitives.
    pub instructions: Vec<InstructionCount>,
    /// The step is running.
    pub(crate) active: bool,
}

/// Adds one run's gradient sites to those gathered so far.
pub(crate) fn add_sites(into: &mut [GradientSite], from: &[GradientSite]) {
    for (g, b) in into.iter_mut().zip(from) {
        g.quads += b.quads;
        g.divergent_quads += b.divergent_quads;
        g.executions += b.executions;
        g.divergent_executions += b.divergent_executions;
        if let Some((lo, hi)) = b.lod {
            g.lod = Some(g.lod.map_or((lo, hi), |(a, c)| (a.min(lo), c.max(hi))));
        }
    }
}

impl DrawCosts {
    /// Gathers the costs of draw step `step`.
    pub fn new(step: usize) -> DrawCosts {
        DrawCosts {
            step,
            ..DrawCosts::default()
        }
    }

    /// One run of the shader: `out` over a window whose `covered` pixels
    /// the primitive covers (`None`: every pixel, a full-screen draw).
    pub(crate) fn add(&mut self, covered: Option<&[bool]>, out: &DrawOutput) {
        let width = out.width as usize;
        let mut quads = vec![(0u64, 0u64); out.quad_executed.len()];
        for (i, &e) in out.executed.iter().enumerate() {
            if !covered.is_none_or(|c| c.get(i).copied().unwrap_or(false)) {
                continue;
            }
            self.pixels.push(e);
            let (x, y) = (i % width, i / width);
            if let Some(q) = quads.get_mut((y / 2) * out.quads_x as usize + x / 2) {
                q.0 += e;
                q.1 += 1;
            }
        }
        for (k, &(own, pixels)) in quads.iter().enumerate() {
            if pixels > 0 {
                self.quads.push(QuadRun {
                    executed: out.quad_executed[k],
                    own,
                    pixels,
                    divergent: out.quad_divergent.get(k).copied().unwrap_or(false),
                });
            }
        }
        if self.gradients.is_empty() {
            self.gradients = out.gradients.clone();
        } else {
            add_sites(&mut self.gradients, &out.gradients);
        }
        if self.instructions.len() < out.instructions.len() {
            self.instructions
                .resize(out.instructions.len(), InstructionCount::default());
        }
        for (c, b) in self.instructions.iter_mut().zip(&out.instructions) {
            c.add(b);
        }
        self.primitives += 1;
    }
}
