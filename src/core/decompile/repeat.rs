//! Repeated blocks: a straight run of code that is one block of
//! instructions written out [`MIN_COPIES`] or more times in a row, each copy
//! the same instructions on the same registers (a loop unrolled by hand or
//! by a generator, like the luminance shaders' `REPEAT_BLOCK(125)`), is
//! written as one `[loop] for` over the block.
//!
//! The loop is the shader's own structure, so it reads better than the
//! copies; it is also what lets Microsoft's compiler take the HLSL at all.
//! Given the copies as straight code, the compiler sees every texture read
//! of the run as independent of the arithmetic between them (each copy's
//! coordinate is the previous one plus a constant), schedules all of them
//! first and holds every result until its `dp4`: 125 values alive at once,
//! past ps_3_0's 32 temporaries (error X4505). In a `[loop]` one copy's
//! values are alive at a time. The loop runs the same instructions in the
//! same order on the same registers as the copies did, so the values are
//! the same; `tests/decompile.rs` recompiles and runs every such shader of
//! the corpus to show it.

use crate::core::ir::Instruction;
use crate::core::isa::{Class, Opcode};
use std::ops::Range;

/// The fewest copies of a block read as a loop.
pub(crate) const MIN_COPIES: usize = 4;

/// The longest block looked for, in instructions.
const MAX_BLOCK: usize = 64;

/// ps_3_0 nests `rep` and `loop` four deep.
const MAX_NESTING: usize = 4;

/// `count` copies of the block of `len` instructions at `start`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Repeat {
    /// The first instruction of the first copy.
    pub start: usize,
    /// Instructions in one copy.
    pub len: usize,
    /// Copies in a row.
    pub count: usize,
}

impl Repeat {
    /// The instructions of the first copy.
    pub(crate) fn block(&self) -> Range<usize> {
        self.start..self.start + self.len
    }

    /// One past the last copy's last instruction.
    pub(crate) fn end(&self) -> usize {
        self.start + self.len * self.count
    }
}

/// The same instruction, wherever it came from.
fn same(a: &Instruction, b: &Instruction) -> bool {
    a.op == b.op
        && a.sat == b.sat
        && a.pp == b.pp
        && a.centroid == b.centroid
        && a.compare == b.compare
        && a.predicate == b.predicate
        && a.dst == b.dst
        && a.src == b.src
}

/// Copies of `ins[at..at + len]` in a row from `at`, up to `end`.
fn copies(ins: &[Instruction], at: usize, len: usize, end: usize) -> usize {
    let mut n = 1;
    while at + (n + 1) * len <= end && (0..len).all(|k| same(&ins[at + k], &ins[at + n * len + k]))
    {
        n += 1;
    }
    n
}

/// The repeated blocks of `range`, in order and apart, where the loop
/// nesting at its start is `depth` (a block is read as a loop only where
/// one more loop fits ps_3_0's nesting).
pub(crate) fn find(ins: &[Instruction], range: Range<usize>, depth: usize) -> Vec<Repeat> {
    let mut out = Vec::new();
    let mut depth = depth;
    let mut i = range.start;
    while i < range.end {
        let op = ins[i].op;
        if op.class() == Class::Flow {
            match op {
                Opcode::Rep | Opcode::Loop => depth += 1,
                Opcode::EndRep | Opcode::EndLoop => depth = depth.saturating_sub(1),
                _ => {}
            }
            i += 1;
            continue;
        }
        let run_end = (i..range.end)
            .find(|&k| ins[k].op.class() == Class::Flow)
            .unwrap_or(range.end);
        if depth >= MAX_NESTING {
            i = run_end;
            continue;
        }
        match best(ins, i, run_end) {
            Some(r) => {
                i = r.end();
                out.push(r);
            }
            None => i += 1,
        }
    }
    out
}

/// The block repeated at `at` that covers the most instructions before
/// `end` (the shorter block where two cover as many).
fn best(ins: &[Instruction], at: usize, end: usize) -> Option<Repeat> {
    let longest = MAX_BLOCK.min((end - at) / MIN_COPIES);
    let mut best: Option<Repeat> = None;
    for len in 1..=longest {
        let count = copies(ins, at, len, end);
        if count >= MIN_COPIES && best.is_none_or(|b| len * count > b.len * b.count) {
            best = Some(Repeat {
                start: at,
                len,
                count,
            });
        }
    }
    best
}
