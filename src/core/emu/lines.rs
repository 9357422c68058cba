//! What each source line cost in a run: the emulator's counts per
//! instruction ([`InstructionCount`], or a vertex stage's runs) gathered
//! line by line, as `ps30 check` gathers the cost model's counts.
//!
//! A line's instructions (several when a REPEAT_BLOCK repeats it) are
//! summed: `runs` by the pixels the draw reports (or the vertices),
//! `executed` = Σ runs × slots, so that the lines' `executed` add up to
//! the pixels' own executed slots; `quads` the 2×2 quads that ran the line
//! in lockstep (helper lanes included), `lockstep` = Σ quads × slots, which
//! add up to the quads' executed slots; `divergent` the quad runs with only
//! part of the quad, where the lanes of a quad disagreed.

use super::InstructionCount;
use crate::core::diag::SourceFile;
use crate::core::ir::Shader;
use crate::core::isa::SlotTable;
use serde::Serialize;
use std::collections::BTreeMap;

/// One source line's runs and slots over a draw (or a vertex list).
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize)]
pub struct LineRuns {
    /// The line (1-based).
    pub line: usize,
    /// Its first instruction's source text.
    pub text: String,
    /// Slots of one run of the line's instructions (Microsoft's count).
    pub slots: u64,
    /// Runs by reported pixels (or vertices), summed over its instructions.
    pub runs: u64,
    /// Σ runs × slots over its instructions.
    pub executed: u64,
    /// Runs by helper lanes.
    pub helpers: u64,
    /// Runs by 2×2 quads in lockstep (at least one lane running).
    pub quads: u64,
    /// Quad runs with some but not all four lanes running.
    pub divergent: u64,
    /// Σ quad runs × slots over its instructions.
    pub lockstep: u64,
}

/// The pixel shader's lines from `counts`, one per instruction by index
/// (a draw's [`super::DrawOutput::instructions`]); empty when
/// nothing was counted.
pub fn pixel_lines(
    shader: &Shader,
    file: &SourceFile,
    counts: &[InstructionCount],
) -> Vec<LineRuns> {
    if counts.is_empty() {
        return Vec::new();
    }
    let ran = ops_run(shader);
    gather(shader, file, |i| {
        ran.get(i)
            .and_then(|&op| counts.get(op))
            .copied()
            .unwrap_or_default()
    })
}

/// For each instruction of `shader`, the index of the operation the
/// emulator counts for it: its own, or for a ps_1_x shader the first
/// operation of its lowering with the instruction's span (every
/// instruction has one; ps_1_x has no flow control, so the operations of
/// one instruction all run as often).
fn ops_run(shader: &Shader) -> Vec<usize> {
    let n = shader.instructions().len();
    let Ok(run) = shader.runnable() else {
        return (0..n).collect();
    };
    if std::ptr::eq(run, shader) {
        return (0..n).collect();
    }
    let mut first = std::collections::HashMap::new();
    for (k, op) in run.instructions().iter().enumerate() {
        first.entry(op.origin.span).or_insert(k);
    }
    shader
        .instructions()
        .iter()
        .map(|ins| first.get(&ins.origin.span).copied().unwrap_or(usize::MAX))
        .collect()
}

/// A vertex shader's lines from `runs`, each instruction's runs over the
/// vertices (no quads: a vertex runs alone).
pub fn vertex_lines(shader: &Shader, file: &SourceFile, runs: &[u64]) -> Vec<LineRuns> {
    if runs.is_empty() {
        return Vec::new();
    }
    gather(shader, file, |i| InstructionCount {
        pixels: runs.get(i).copied().unwrap_or(0),
        ..InstructionCount::default()
    })
}

fn gather(
    shader: &Shader,
    file: &SourceFile,
    count: impl Fn(usize) -> InstructionCount,
) -> Vec<LineRuns> {
    let info = shader.info();
    let mut lines: BTreeMap<usize, LineRuns> = BTreeMap::new();
    for (i, ins) in shader.instructions().iter().enumerate() {
        let line = file.line_of(ins.origin.span.start);
        let slots = u64::from(info.slots(i, SlotTable::default()));
        let c = count(i);
        let entry = lines.entry(line).or_insert_with(|| LineRuns {
            line,
            text: file
                .text
                .get(ins.origin.span.range())
                .unwrap_or("")
                .to_string(),
            ..LineRuns::default()
        });
        entry.slots += slots;
        entry.runs += c.pixels;
        entry.executed += c.pixels * slots;
        entry.helpers += c.helpers;
        entry.quads += c.quads;
        entry.divergent += c.divergent;
        entry.lockstep += c.quads * slots;
    }
    lines.into_values().collect()
}
