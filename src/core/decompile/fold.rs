//! Which values are folded into their reader: a temporary written by one
//! instruction and read by exactly one later instruction of the same
//! straight run of code (no flow control between), through one operand,
//! and dead after that read (overwritten before any other read, or the end
//! of `main`) is not given a statement of its own; the reader takes the
//! expression. Its operands must not change between the two, so the
//! value is the same; the instructions the compiler chooses for it may not
//! be, which the corpus test (`tests/decompile.rs`) measures.

use super::expr::{lanes, matrix_rows};
use crate::core::ir::{Instruction, Shader};
use crate::core::isa::{Class, Opcode, RegFile};
use std::collections::{BTreeMap, BTreeSet};

/// Whether `op` ends a straight run of code: flow control.
fn flow(op: Opcode) -> bool {
    op.class() == Class::Flow
}

/// Registers (file, index) → component bits `ins` reads.
fn reads(shader: &Shader, ins: &Instruction) -> BTreeMap<(RegFile, u32), u8> {
    let sampler = ins
        .src
        .iter()
        .find(|s| s.reg.file == RegFile::Sampler)
        .and_then(|s| shader.program().sampler_type(s.reg.index));
    let mut out: BTreeMap<(RegFile, u32), u8> = BTreeMap::new();
    for (k, s) in ins.src.iter().enumerate() {
        let bits = lanes(ins, k, sampler)
            .iter()
            .fold(0u8, |b, &p| b | 1 << s.swizzle.0[p]);
        let rows = if k == 1 {
            matrix_rows(ins.op).unwrap_or(1)
        } else {
            1
        };
        for r in 0..rows {
            *out.entry((s.reg.file, s.reg.index + r)).or_default() |= bits;
        }
        // `c[a0.x + n]` reads a0 too: a value must not move past a `mova`
        if let Some(crate::core::ir::RelIndex::Addr(c)) = s.relative {
            *out.entry((RegFile::Address, 0)).or_default() |= 1 << c;
        }
    }
    if ins.op == Opcode::TexKill {
        if let Some(d) = ins.dst {
            *out.entry((d.reg.file, d.reg.index)).or_default() |= d.mask.0;
        }
    }
    out
}

/// The operands of `ins` that read temporary `r`.
fn operands_reading(ins: &Instruction, r: u32) -> usize {
    ins.src
        .iter()
        .filter(|s| s.reg.file == RegFile::Temp && s.reg.index == r)
        .count()
}

/// Whether `ins` may take a folded value: it renders each operand once.
fn takes_folds(ins: &Instruction) -> bool {
    let mask = ins.dst.map_or(0, |d| d.mask.0);
    !(matches!(
        ins.op,
        Opcode::TexKill | Opcode::M4x4 | Opcode::M4x3 | Opcode::M3x4 | Opcode::M3x3 | Opcode::M3x2
    ) || (ins.op == Opcode::Nrm && mask & 8 != 0)
        || (ins.op == Opcode::SinCos && mask & 3 == 3)
        || flow(ins.op))
}

/// Instruction A → instruction B for every value A writes that B takes.
pub(crate) fn plan(
    shader: &Shader,
    ins: &[Instruction],
    range: std::ops::Range<usize>,
    is_main: bool,
) -> BTreeMap<usize, usize> {
    let mut out = BTreeMap::new();
    for a in range.clone() {
        let x = &ins[a];
        let Some(d) = x.dst else { continue };
        if d.reg.file != RegFile::Temp
            || x.predicate.is_some()
            || flow(x.op)
            || matches!(x.op, Opcode::TexKill | Opcode::Setp)
        {
            continue;
        }
        if let Some(b) = reader(shader, ins, a, range.end, is_main) {
            out.insert(a, b);
        }
    }
    // a value folded into a value that is folded in turn moves to the last
    // reader of the chain: its operands must hold until there (later
    // entries first, so each chain is followed through kept entries only)
    let keys: Vec<usize> = out.keys().rev().copied().collect();
    for a in keys {
        let mut last = out[&a];
        while let Some(&next) = out.get(&last) {
            last = next;
        }
        let operands: BTreeSet<(RegFile, u32)> = reads(shader, &ins[a]).into_keys().collect();
        let changed = ins[a + 1..last].iter().any(|y| {
            y.dst
                .is_some_and(|w| operands.contains(&(w.reg.file, w.reg.index)))
        });
        if changed {
            out.remove(&a);
        }
    }
    out
}

/// The one reader of what instruction `a` writes, if the value can move there.
fn reader(
    shader: &Shader,
    ins: &[Instruction],
    a: usize,
    end: usize,
    is_main: bool,
) -> Option<usize> {
    let x = &ins[a];
    let d = x.dst?;
    let r = d.reg.index;
    let operands: BTreeSet<(RegFile, u32)> = reads(shader, x).into_keys().collect();
    let mut b = None;
    for (i, y) in ins.iter().enumerate().take(end).skip(a + 1) {
        if flow(y.op) {
            return None;
        }
        let read = reads(shader, y)
            .get(&(RegFile::Temp, r))
            .copied()
            .unwrap_or(0);
        if read & d.mask.0 != 0 {
            if read & !d.mask.0 != 0 || operands_reading(y, r) != 1 || !takes_folds(y) {
                return None;
            }
            b = Some(i);
            break;
        }
        if let Some(w) = y.dst {
            if operands.contains(&(w.reg.file, w.reg.index))
                || (w.reg.file == RegFile::Temp && w.reg.index == r)
            {
                return None;
            }
        }
    }
    let b = b?;
    // dead after b: overwritten before any read, or the end of main
    let mut live = d.mask.0;
    if let Some(w) = ins[b]
        .dst
        .filter(|w| w.reg.file == RegFile::Temp && w.reg.index == r && ins[b].predicate.is_none())
    {
        live &= !w.mask.0;
    }
    for y in ins.iter().take(end).skip(b + 1) {
        if live == 0 {
            break;
        }
        if y.op == Opcode::Ret && is_main {
            return Some(b);
        }
        if flow(y.op) {
            return None;
        }
        if reads(shader, y)
            .get(&(RegFile::Temp, r))
            .copied()
            .unwrap_or(0)
            & live
            != 0
        {
            return None;
        }
        if let Some(w) = y
            .dst
            .filter(|w| w.reg.file == RegFile::Temp && w.reg.index == r && y.predicate.is_none())
        {
            live &= !w.mask.0;
        }
    }
    (live == 0 || is_main).then_some(b)
}
