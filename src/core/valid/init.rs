//! Reads of temporaries that no earlier code writes.
//!
//! Microsoft's ps_3_0 temporary-register page: "If a temporary register
//! uses components that are not defined in previous code, shader validation
//! will fail." ps30 reads "previous code" as program order, the way a
//! validator walking the tokens does: a component counts as defined once
//! any earlier instruction writes it — inside an `if` or a loop body too,
//! predicated or not — and a `call` counts as running its subroutine, so
//! what the subroutine (and what it calls) writes is defined after the call.
//! An accumulator read in a loop before the loop writes it is therefore
//! reported, as a `mov r0, c0` before the loop fixes it. Microsoft's
//! assembler enforces none of this, so each read is a warning (an error
//! under `--strict`).
//!
//! Which components an instruction reads follows its operation: per
//! component for the arithmetic ones (the source components the write mask
//! selects through the swizzle), the replicated component of scalar
//! sources, three or four for dot products and matrix rows (every row
//! register of `m#x#`), the coordinates a sampler's dimension needs (plus
//! w for `texldp`, `texldb`, `texldl`) and the xyz that `texkill` tests.

use crate::core::diag::{Diagnostic, Diagnostics, SourceFile};
use crate::core::ir::{Info, Instruction, Program, Src, WriteMask};
use crate::core::isa::{Opcode, RegFile, SamplerType};
use std::collections::BTreeMap;

/// Temporaries there are (r0 … r31).
const TEMPS: usize = 32;

/// Reports every read of a temporary component that no earlier code writes.
pub fn check(p: &Program, info: &Info, diags: &mut Diagnostics, file: &SourceFile) {
    let subs = subroutine_writes(p, info);
    let mut written = [0u8; TEMPS];
    for ins in &p.instructions {
        for (reg, need) in reads(p, ins) {
            let missing = need & !written[reg as usize];
            if missing != 0 {
                diags.push(
                    uninitialised(ins, reg, missing, written[reg as usize])
                        .in_origin(&ins.origin, file),
                );
                // Reported once: later reads of the same components are not.
                written[reg as usize] |= missing;
            }
        }
        if let Some(writes) = called(ins).and_then(|l| subs.get(&l)) {
            for (w, s) in written.iter_mut().zip(writes) {
                *w |= s;
            }
        }
        if let Some((reg, mask)) = write(ins) {
            written[reg as usize] |= mask;
        }
    }
}

fn uninitialised(ins: &Instruction, reg: u32, missing: u8, defined: u8) -> Diagnostic {
    let what = if defined == 0 {
        format!("r{reg} is read, but no earlier instruction writes it")
    } else {
        format!(
            "r{reg}{} is read, but earlier instructions write only r{reg}{}",
            dotted(missing),
            dotted(defined)
        )
    };
    Diagnostic::documented_rule(ins.origin.span, what)
        .with_label(format!("r{reg}{} undefined here", dotted(missing)))
        .with_note("undefined behaviour: the value read is whatever the register holds, which differs between GPUs and drivers; Microsoft's documentation forbids the read, its assembler accepts it")
        .with_help(format!(
            "write it first (e.g. `mov r{reg}, c0`)"
        ))
}

/// `.xyw` for a component mask.
fn dotted(mask: u8) -> String {
    let letters: String = "xyzw"
        .chars()
        .enumerate()
        .filter(|&(i, _)| mask & 1 << i != 0)
        .map(|(_, c)| c)
        .collect();
    format!(".{letters}")
}

/// The label a `call` or `callnz` calls.
fn called(ins: &Instruction) -> Option<u32> {
    matches!(ins.op, Opcode::Call | Opcode::CallNz).then(|| ins.src[0].reg.index)
}

/// The temporary an instruction writes, and which components.
fn write(ins: &Instruction) -> Option<(u32, u8)> {
    let d = ins.dst.as_ref()?;
    (d.reg.file == RegFile::Temp && ins.op != Opcode::TexKill && (d.reg.index as usize) < TEMPS)
        .then_some((d.reg.index, d.mask.0))
}

/// What each subroutine writes, the subroutines it calls included.
fn subroutine_writes(p: &Program, info: &Info) -> BTreeMap<u32, [u8; TEMPS]> {
    let n = p.instructions.len();
    let mut own: BTreeMap<u32, ([u8; TEMPS], Vec<u32>)> = BTreeMap::new();
    for (&label, &at) in &info.labels {
        let body = &p.instructions[(at as usize + 1).min(n)..];
        let end = body
            .iter()
            .position(|i| i.op == Opcode::Label)
            .unwrap_or(body.len());
        let mut writes = [0u8; TEMPS];
        let mut calls = Vec::new();
        for ins in &body[..end] {
            if let Some((r, m)) = write(ins) {
                writes[r as usize] |= m;
            }
            calls.extend(called(ins));
        }
        own.insert(label, (writes, calls));
    }
    own.keys()
        .map(|&label| {
            // Everything reachable from the label (validation refuses
            // recursion, but a cycle would only be walked once).
            let mut all = [0u8; TEMPS];
            let mut seen = vec![label];
            let mut todo = vec![label];
            while let Some(l) = todo.pop() {
                let Some((writes, calls)) = own.get(&l) else {
                    continue;
                };
                for (a, w) in all.iter_mut().zip(writes) {
                    *a |= w;
                }
                for &c in calls {
                    if !seen.contains(&c) {
                        seen.push(c);
                        todo.push(c);
                    }
                }
            }
            (label, all)
        })
        .collect()
}

/// The components of a source that the listed output components read
/// through its swizzle.
fn through(s: &Src, components: impl IntoIterator<Item = usize>) -> u8 {
    components
        .into_iter()
        .fold(0, |m, c| m | 1 << (s.swizzle.0[c] & 3))
}

/// The coordinate components a sampler's dimension needs.
fn dimension(p: &Program, ins: &Instruction) -> usize {
    let sampler = ins.src.iter().find(|s| s.reg.file == RegFile::Sampler);
    match sampler.and_then(|s| p.sampler_type(s.reg.index)) {
        Some(SamplerType::Cube | SamplerType::Volume) => 3,
        _ => 2,
    }
}

/// Which temporaries an instruction reads, and which components of each.
fn reads(p: &Program, ins: &Instruction) -> Vec<(u32, u8)> {
    let mut out = reads_of(p, ins, RegFile::Temp);
    out.retain(|&(r, _)| (r as usize) < TEMPS);
    out
}

/// Which registers of `file` an instruction reads (not relatively
/// addressed), and which components of each: what a declaration must
/// cover for an input, what earlier code must write for a temporary.
pub fn reads_of(p: &Program, ins: &Instruction, file: RegFile) -> Vec<(u32, u8)> {
    let mut out = Vec::new();
    let mask = ins.dst.map_or(WriteMask::ALL, |d| d.mask);
    let per_component = (0..4).filter(|&c| mask.has(c));
    if ins.op == Opcode::TexKill {
        if let Some(d) = ins.dst.filter(|d| d.reg.file == file) {
            out.push((d.reg.index, d.mask.0 & 0b0111));
        }
        return out;
    }
    let dims = dimension(p, ins);
    for (k, s) in ins.src.iter().enumerate() {
        if s.reg.file != file || s.relative.is_some() {
            continue;
        }
        let need = match ins.op {
            Opcode::Rcp
            | Opcode::Rsq
            | Opcode::Exp
            | Opcode::Log
            | Opcode::SinCos
            | Opcode::Pow => through(s, [0]),
            Opcode::Ifc | Opcode::BreakC => through(s, [0]),
            Opcode::Dp3 | Opcode::Crs => through(s, 0..3),
            Opcode::Dp4 => through(s, 0..4),
            Opcode::Dp2Add if k == 2 => through(s, [0]),
            Opcode::Dp2Add => through(s, 0..2),
            Opcode::Nrm => through(s, (0..3).chain(mask.has(3).then_some(3))),
            Opcode::M4x4 | Opcode::M4x3 | Opcode::M3x4 | Opcode::M3x3 | Opcode::M3x2 => {
                let (width, rows) = matrix(ins.op);
                if k == 1 {
                    // Every row register of the matrix, `width` components each.
                    let row = (1u8 << width) - 1;
                    out.extend((0..rows).map(|r| (s.reg.index + r, row)));
                    continue;
                }
                through(s, 0..width as usize)
            }
            Opcode::TexLd => through(s, 0..dims),
            Opcode::TexLdP | Opcode::TexLdB | Opcode::TexLdL if k == 0 => {
                through(s, (0..dims).chain([3]))
            }
            Opcode::TexLdD if k != 1 => through(s, 0..dims),
            _ => through(s, per_component.clone()),
        };
        out.push((s.reg.index, need));
    }
    out
}

/// (components per row, rows) of a matrix instruction.
fn matrix(op: Opcode) -> (u32, u32) {
    match op {
        Opcode::M4x4 => (4, 4),
        Opcode::M4x3 => (4, 3),
        Opcode::M3x4 => (3, 4),
        Opcode::M3x3 => (3, 3),
        _ => (3, 2),
    }
}
