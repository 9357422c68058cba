//! Gradients under dynamic flow control, found statically.
//!
//! Pixels run in 2×2 quads so that `dsx`/`dsy` and the mip selection of
//! `texld`, `texldb` and `texldp` can difference a register between
//! neighbours at the same point of execution. Where the pixels of a quad may
//! have taken different paths, that difference is undefined. Microsoft's
//! "Interaction of Per-Pixel Flow Control With Screen Gradients" (facts sheet
//! §5) makes it illegal to use texld/texldb/texldp with a *temporary*
//! coordinate, or dsx/dsy of a temporary, inside flow control whose
//! condition can vary per pixel — predication included — and says the
//! validator enforces it even where the condition looks uniform. Inputs
//! (`v#`) are interpolated for every pixel of the quad, so they are fine
//! anywhere; `texldl` and `texldd` take no implicit gradients.
//!
//! Where an instruction can run with part of its quad, statically:
//! * it is predicated (`(p0) texld …`);
//! * it lies inside `if_comp` or `if p0.c` (either side);
//! * it lies inside a rep/loop that pixels can leave at different
//!   iterations: one with a `break_comp` or `breakp` of its own, or a `break`
//!   inside a dynamic `if` below it (the whole body counts: from the second
//!   iteration on, pixels that left are missing);
//! * it follows, in the same function, a `ret` that runs under dynamic flow
//!   control (those pixels have left for good);
//! * it is in a subroutine called under dynamic flow control, or by
//!   `callnz l#, p0.c`.
//!
//! `if b#`, `callnz l#, b#` and rep/loop counts are uniform over a draw.
//!
//! **Warning when measured, error when assembled.** Microsoft's assembler
//! refuses such a shader (X6077), and so does `ps30 asm` (a warning that
//! carries Microsoft's code is an error when bytecode is written, and under
//! `--strict`); elsewhere ps30 reports a warning with the place and the
//! reason, so the shader can still be measured with `ps30 check` and run
//! with `ps30 profile`,
//! whose quads show what the undefined gradients actually do (see
//! `crate::core::emu` and the README).

use crate::core::diag::{codes, Diagnostic, SourceFile};
use crate::core::ir::{Info, Instruction, Program};
use crate::core::isa::{Opcode, RegFile};
use std::ops::Range;

/// Why an instruction may run with only part of its quad.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Dynamic {
    /// The instruction itself is predicated.
    Predicated,
    /// Inside the dynamic `if` at this instruction index.
    InIf(usize),
    /// Inside the loop at `.0`, which pixels can leave through the exit at `.1`.
    InLoop(usize, usize),
    /// After the `ret` at this index, which pixels may have taken early.
    AfterRet(usize),
    /// In a subroutine called from the dynamic call at this index.
    Called(usize),
}

/// For every instruction, whether (and why) its quad may be divergent when
/// it runs. `info` must come from a program that validated without errors.
pub fn dynamic_context(p: &Program, info: &Info) -> Vec<Option<Dynamic>> {
    let ins = &p.instructions;
    let ranges = functions(ins.len(), info);
    let loop_exit = loop_exits(ins, &ranges);
    let (mut why, calls) = local_context(ins, &ranges, &loop_exit);
    mark_called(&mut why, &ranges, &calls);
    why
}

/// A function: `None` for main or the label's number, and its instructions.
type Function = (Option<u32>, Range<usize>);

/// Functions: main and each label's body, as index ranges.
fn functions(n: usize, info: &Info) -> Vec<Function> {
    let mut starts: Vec<(Option<u32>, usize)> = vec![(None, 0)];
    for (&label, &at) in &info.labels {
        starts.push((Some(label), at as usize + 1));
    }
    starts.sort_by_key(|&(_, s)| s);
    let mut ranges: Vec<Function> = Vec::new();
    for (k, &(label, start)) in starts.iter().enumerate() {
        let end = match starts.get(k + 1) {
            // The next function starts after its label; stop before it.
            Some(&(_, next)) => next.saturating_sub(1),
            None => n,
        };
        let end = if label.is_none() {
            (info.main_end as usize).min(end)
        } else {
            end
        };
        ranges.push((label, start.min(end)..end));
    }
    ranges
}

/// Whether `x` is an `if` whose condition can vary per pixel (`if_comp`,
/// `if p0.c`).
fn dynamic_if(x: &Instruction) -> bool {
    x.op == Opcode::Ifc
        || x.src
            .first()
            .is_some_and(|s| s.reg.file == RegFile::Predicate)
}

/// Loops that pixels can leave at different iterations: for each loop's
/// index, its first such exit.
fn loop_exits(ins: &[Instruction], ranges: &[Function]) -> Vec<Option<usize>> {
    let mut loop_exit: Vec<Option<usize>> = vec![None; ins.len()];
    for (_, range) in ranges {
        // Stack of (opcode, index, dynamic).
        let mut stack: Vec<(Opcode, usize, bool)> = Vec::new();
        for i in range.clone() {
            let op = ins[i].op;
            match op {
                Opcode::Rep | Opcode::Loop => stack.push((op, i, false)),
                Opcode::If | Opcode::Ifc => stack.push((op, i, dynamic_if(&ins[i]))),
                Opcode::EndIf | Opcode::EndRep | Opcode::EndLoop => {
                    stack.pop();
                }
                // Microsoft's validator counts every loop with a break of
                // any kind (X6077: "loop/rep with break*"), a plain `break`
                // included, though only a conditional one lets the pixels
                // of a quad leave at different iterations.
                Opcode::Break | Opcode::BreakC | Opcode::BreakP => {
                    let mut dynamic = true;
                    for &(o, at, d) in stack.iter().rev() {
                        if matches!(o, Opcode::Rep | Opcode::Loop) {
                            if dynamic && loop_exit[at].is_none() {
                                loop_exit[at] = Some(i);
                            }
                            break;
                        }
                        dynamic |= d;
                    }
                }
                _ => {}
            }
        }
    }
    loop_exit
}

/// Call sites: those that may run with part of a quad `(index, label)`, and
/// the others `(index, label, calling function)`.
#[derive(Default)]
struct Calls {
    dynamic: Vec<(usize, u32)>,
    fixed: Vec<(usize, u32, Option<u32>)>,
}

/// Local context of each instruction (its own predicate, the blocks around
/// it, an earlier dynamic `ret`), and the call sites.
fn local_context(
    ins: &[Instruction],
    ranges: &[Function],
    loop_exit: &[Option<usize>],
) -> (Vec<Option<Dynamic>>, Calls) {
    let mut why: Vec<Option<Dynamic>> = vec![None; ins.len()];
    let mut calls = Calls::default();
    for (label, range) in ranges {
        let mut stack: Vec<(usize, Option<Dynamic>)> = Vec::new();
        let mut after_ret: Option<usize> = None;
        for i in range.clone() {
            let x = &ins[i];
            let enclosing = stack
                .iter()
                .rev()
                .find_map(|&(_, d)| d)
                .or(after_ret.map(Dynamic::AfterRet));
            match x.op {
                Opcode::EndIf | Opcode::EndRep | Opcode::EndLoop => {
                    stack.pop();
                }
                _ => {}
            }
            let own = if x.predicate.is_some() {
                Some(Dynamic::Predicated)
            } else {
                None
            };
            why[i] = own.or(enclosing);
            match x.op {
                Opcode::Rep | Opcode::Loop => {
                    stack.push((i, loop_exit[i].map(|e| Dynamic::InLoop(i, e))));
                }
                Opcode::If | Opcode::Ifc => {
                    stack.push((i, dynamic_if(x).then_some(Dynamic::InIf(i))));
                }
                Opcode::Ret if enclosing.is_some() => {
                    after_ret.get_or_insert(i);
                }
                Opcode::Call | Opcode::CallNz => {
                    let target = x.src.first().map(|s| s.reg.index);
                    let pred = x.op == Opcode::CallNz
                        && x.src
                            .get(1)
                            .is_some_and(|s| s.reg.file == RegFile::Predicate);
                    if let Some(t) = target {
                        if pred || why[i].is_some() {
                            calls.dynamic.push((i, t));
                        } else {
                            calls.fixed.push((i, t, *label));
                        }
                    }
                }
                _ => {}
            }
        }
    }
    (why, calls)
}

/// Subroutines reached from a dynamic call, transitively: every instruction
/// of theirs without a reason of its own gets the call.
fn mark_called(why: &mut [Option<Dynamic>], ranges: &[Function], calls: &Calls) {
    let mut called: std::collections::BTreeMap<u32, usize> = Default::default();
    let mut work: Vec<(u32, usize)> = calls.dynamic.iter().map(|&(i, t)| (t, i)).collect();
    while let Some((label, call)) = work.pop() {
        if called.contains_key(&label) {
            continue;
        }
        called.insert(label, call);
        for &(_, t, from) in &calls.fixed {
            if from == Some(label) && !called.contains_key(&t) {
                work.push((t, call));
            }
        }
    }
    for (label, range) in ranges {
        if let Some(&call) = label.and_then(|l| called.get(&l)) {
            for w in &mut why[range.clone()] {
                w.get_or_insert(Dynamic::Called(call));
            }
        }
    }
}

/// Warnings for gradient instructions that may run with part of a quad.
pub fn warnings(p: &Program, info: &Info, file: &SourceFile) -> Vec<Diagnostic> {
    let ctx = dynamic_context(p, info);
    let mut out = Vec::new();
    for (i, x) in p.instructions.iter().enumerate() {
        let Some(why) = ctx[i] else { continue };
        let temp = x.src.first().is_some_and(|s| s.reg.file == RegFile::Temp);
        let (what, help) = match x.op {
            Opcode::TexLd | Opcode::TexLdB | Opcode::TexLdP if temp => (
                format!(
                    "`{}` with a temporary coordinate under dynamic flow control: its mip level is undefined",
                    x.op
                ),
                "sample with texldl (explicit LOD, e.g. w = 0 for the top level) or texldd with gradients computed before the branch",
            ),
            Opcode::Dsx | Opcode::Dsy if temp => (
                format!("`{}` of a temporary under dynamic flow control is undefined", x.op),
                "take dsx/dsy before the branch and keep the result in a temporary",
            ),
            _ => continue,
        };
        let span = x.origin.span;
        let mut d = Diagnostic::warning(span, what)
            .with_code(codes::GRADIENT_IN_FLOW)
            .with_label("gradients need all four pixels of the 2×2 quad here")
            .with_help(help)
            .with_note("Microsoft's assembler refuses this, and so does ps30 asm; ps30 warns elsewhere so the shader can still be measured and run (ps30 profile counts the quads that hit it)");
        let at = |k: usize| p.instructions[k].origin.span;
        d = match why {
            Dynamic::Predicated => {
                d.with_note("the instruction is predicated: pixels of a quad can differ in p0")
            }
            Dynamic::InIf(k) => {
                d.with_secondary(at(k), "the pixels of a quad can go different ways here")
            }
            Dynamic::InLoop(l, e) => d
                .with_secondary(
                    at(l),
                    "a loop that pixels can leave at different iterations",
                )
                .with_secondary(at(e), "through this exit"),
            Dynamic::AfterRet(r) => d.with_secondary(at(r), "pixels may have returned early here"),
            Dynamic::Called(c) => d.with_secondary(
                at(c),
                "the subroutine is called under dynamic flow control here",
            ),
        };
        out.push(d.in_origin(&x.origin, file));
    }
    out
}
