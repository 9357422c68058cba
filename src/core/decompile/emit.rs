//! The statements of `main` and of each subroutine: one assignment per
//! written value, predication as a per-component choice, and the flow
//! control instructions as the structured HLSL they delimit (`if`/`else`,
//! `for` for `rep` and `loop`, `break`, calls of `label` functions).

use super::expr::{self, Ctx, Pending};
use super::fold;
use super::repeat;
use super::DecompileError;
use crate::core::ir::{Instruction, Shader};
use crate::core::isa::{Opcode, RegFile, SamplerType};

/// Lines of HLSL at an indentation.
pub(crate) struct Body {
    /// The lines written, indented.
    pub lines: Vec<String>,
    depth: usize,
    /// Nesting of `rep` counters (their names).
    reps: usize,
}

impl Body {
    pub(crate) fn new(depth: usize) -> Body {
        Body {
            lines: Vec::new(),
            depth,
            reps: 0,
        }
    }

    pub(crate) fn line(&mut self, text: impl Into<String>) {
        self.lines
            .push(format!("{}{}", "    ".repeat(self.depth), text.into()));
    }

    fn open(&mut self, text: String) {
        self.line(format!("{text} {{"));
        self.depth += 1;
    }

    fn close(&mut self) {
        self.depth = self.depth.saturating_sub(1);
        self.line("}");
    }
}

/// Names of loop counters by nesting depth.
const COUNTERS: [&str; 8] = ["i", "j", "k", "m", "i4", "j5", "k6", "m7"];

/// Writes instructions `range` of `ins` (the instructions of `shader` as
/// the decompiler reads them: `reduce::read_back`) into `body`.
pub(crate) fn statements(
    ctx: &mut Ctx,
    shader: &Shader,
    ins: &[Instruction],
    range: std::ops::Range<usize>,
    is_main: bool,
    body: &mut Body,
) -> Result<(), DecompileError> {
    // blocks written out several times in a row are one loop (`repeat.rs`);
    // values are folded within the code between them and within a block
    let depth = body.reps + ctx.counters.len();
    let mut at = range.start;
    for r in repeat::find(ins, range.clone(), depth) {
        straight(ctx, shader, ins, at..r.start, range.end, false, body)?;
        let n = format!("n{}", body.reps);
        body.reps += 1;
        body.open(format!(
            "[loop] for (int {n} = 0; {n} < {}; {n}++)",
            r.count
        ));
        statements(ctx, shader, ins, r.block(), false, body)?;
        body.reps -= 1;
        body.close();
        at = r.end();
    }
    straight(ctx, shader, ins, at..range.end, range.end, is_main, body)
}

/// Writes instructions `range`, folding values within it, where `end` is
/// the end of the function's code (a `ret` there is implied).
fn straight(
    ctx: &mut Ctx,
    shader: &Shader,
    ins: &[Instruction],
    range: std::ops::Range<usize>,
    end: usize,
    is_main: bool,
    body: &mut Body,
) -> Result<(), DecompileError> {
    let folds = fold::plan(shader, ins, range.clone(), is_main);
    for i in range {
        let x = &ins[i];
        let here = |e: DecompileError| e.at(i, x.op);
        if folds.contains_key(&i) {
            hold(ctx, shader, x).map_err(here)?;
            continue;
        }
        flow_or_value(ctx, shader, x, i + 1 == end, body).map_err(here)?;
    }
    Ok(())
}

/// The type of the sampler `x` reads, if it reads one.
fn sampler_of(shader: &Shader, x: &Instruction) -> Option<SamplerType> {
    x.src
        .iter()
        .find(|s| s.reg.file == RegFile::Sampler)
        .and_then(|s| shader.program().sampler_type(s.reg.index))
}

/// Keeps the value of `x` for its one reader instead of writing it.
fn hold(ctx: &Ctx, shader: &Shader, x: &Instruction) -> Result<(), DecompileError> {
    let d = x.dst.ok_or_else(|| {
        DecompileError::Unsupported("a folded value without a destination".into())
    })?;
    let sampler = sampler_of(shader, x);
    let text = expr::value(ctx, x, sampler)?;
    let pending = Pending {
        text,
        scalar: expr::scalar_value(x, sampler),
        comps: (0..4u8).filter(|&c| d.mask.has(c as usize)).collect(),
    };
    ctx.pending.borrow_mut().insert(d.reg.index, pending);
    Ok(())
}

fn flow_or_value(
    ctx: &mut Ctx,
    shader: &Shader,
    x: &Instruction,
    last: bool,
    body: &mut Body,
) -> Result<(), DecompileError> {
    match x.op {
        Opcode::Nop | Opcode::Label => {}
        Opcode::Ret if last => {}
        Opcode::Ret => body.line("return;"),
        Opcode::If | Opcode::Ifc => body.open(format!(
            "{}if ({})",
            super::profiles::branch(shader, x),
            ctx.condition(x)?
        )),
        Opcode::Else => {
            body.depth = body.depth.saturating_sub(1);
            body.line("} else {");
            body.depth += 1;
        }
        Opcode::EndIf => body.close(),
        Opcode::EndRep => {
            body.reps = body.reps.saturating_sub(1);
            body.close();
        }
        Opcode::EndLoop => {
            ctx.counters.pop();
            ctx.from_zero.pop();
            body.close();
        }
        Opcode::Break => body.line("break;"),
        Opcode::BreakC | Opcode::BreakP => body.line(format!("if ({}) break;", ctx.condition(x)?)),
        Opcode::Call | Opcode::CallNz => {
            // the callee reads this loop's counter through the global
            if let (true, Some(counter)) = (ctx.caller_counter, ctx.counters.last()) {
                body.line(format!("{} = {counter};", super::expr::CALLER_COUNTER));
            }
            let call = format!("label{}();", label(x)?);
            match x.op {
                Opcode::CallNz => body.line(format!("if ({}) {call}", ctx.condition(x)?)),
                _ => body.line(call),
            }
        }
        Opcode::Rep => {
            let count = int_register(ctx, x, 0)?;
            let n = format!("n{}", body.reps);
            body.reps += 1;
            body.open(format!("for (int {n} = 0; {n} < {count}.x; {n}++)"));
        }
        Opcode::Loop => {
            let counter = COUNTERS.get(ctx.counters.len()).copied();
            match super::vertex::uniform_loop(shader, x, &ctx.names.ints, counter)? {
                Some((head, name)) => {
                    ctx.counters.push(name);
                    ctx.from_zero.push(true);
                    body.open(head);
                }
                None => loop_header(ctx, x, body)?,
            }
        }
        Opcode::TexKill => {
            let d = x.dst.ok_or_else(|| {
                DecompileError::Unsupported("texkill without its register".into())
            })?;
            let comps: Vec<u8> = (0..4u8).filter(|&c| d.mask.has(c as usize)).collect();
            let v = ctx.register(d.reg, false, Default::default(), &comps)?;
            guarded(ctx, x, body, format!("clip({v});"))?;
        }
        _ => assignment(ctx, shader, x, body)?,
    }
    Ok(())
}

fn label(x: &Instruction) -> Result<u32, DecompileError> {
    x.src
        .iter()
        .find(|s| s.reg.file == RegFile::Label)
        .map(|s| s.reg.index)
        .ok_or_else(|| DecompileError::Unsupported("a call without a label".into()))
}

fn int_register(ctx: &Ctx, x: &Instruction, k: usize) -> Result<String, DecompileError> {
    let s = x
        .src
        .iter()
        .filter(|s| s.reg.file == RegFile::ConstInt)
        .nth(k)
        .ok_or_else(|| DecompileError::Unsupported("a loop without its i#".into()))?;
    ctx.names
        .ints
        .get(&s.reg.index)
        .cloned()
        .ok_or_else(|| DecompileError::Unsupported(format!("i{} unnamed", s.reg.index)))
}

/// `loop aL, i#`: `i#.x` iterations, aL from `i#.y` in steps of `i#.z`.
fn loop_header(ctx: &mut Ctx, x: &Instruction, body: &mut Body) -> Result<(), DecompileError> {
    let name = COUNTERS
        .get(ctx.counters.len())
        .ok_or_else(|| DecompileError::Unsupported("loops nested too deep".into()))?
        .to_string();
    let i = int_register(ctx, x, 0)?;
    let literal: Option<Vec<i32>> = i
        .strip_prefix("int4(")
        .and_then(|s| s.strip_suffix(')'))
        .and_then(|s| s.split(", ").map(|p| p.parse().ok()).collect());
    let head = match literal.as_deref() {
        Some(&[count, start, step, _]) if step > 0 => {
            let end = start as i64 + count.max(0) as i64 * step as i64;
            let inc = if step == 1 {
                format!("{name}++")
            } else {
                format!("{name} += {step}")
            };
            format!("for (int {name} = {start}; {name} < {end}; {inc})")
        }
        Some(&[count, start, step, _]) => {
            format!("for (int {name} = {start}, n{name} = 0; n{name} < {count}; n{name}++, {name} += {step})")
        }
        _ => format!(
            "for (int {name} = {i}.y, n{name} = 0; n{name} < {i}.x; n{name}++, {name} += {i}.z)"
        ),
    };
    ctx.counters.push(name);
    ctx.from_zero.push(false);
    body.open(head);
    Ok(())
}

/// An instruction that writes a register: `dst.mask = value;`, under its
/// predicate when it has one.
fn assignment(
    ctx: &Ctx,
    shader: &Shader,
    x: &Instruction,
    body: &mut Body,
) -> Result<(), DecompileError> {
    let d = x.dst.ok_or_else(|| {
        DecompileError::Unsupported(format!("{} without a destination", x.op.info().mnemonic))
    })?;
    let sampler = sampler_of(shader, x);
    let comps: Vec<u8> = (0..4u8).filter(|&c| d.mask.has(c as usize)).collect();
    let target = destination(d.reg, &comps)?;
    let value = expr::value(ctx, x, sampler)?;
    match x.predicate {
        None => body.line(format!("{target} = {value};")),
        Some(p) => {
            let lanes: Vec<u8> = comps.iter().map(|&c| p.swizzle.0[c as usize]).collect();
            let cond = predicate(ctx, &lanes)?;
            let cond = if p.negate { format!("!{cond}") } else { cond };
            body.line(format!("{target} = {cond} ? ({value}) : {target};"));
        }
    }
    Ok(())
}

/// A statement under the instruction's predicate, if any (texkill).
fn guarded(
    ctx: &Ctx,
    x: &Instruction,
    body: &mut Body,
    statement: String,
) -> Result<(), DecompileError> {
    match x.predicate {
        None => body.line(statement),
        Some(p) => {
            if !p.swizzle.is_replicate() {
                return Err(DecompileError::Unsupported(
                    "a predicated texkill with a mixed swizzle".into(),
                ));
            }
            let c = predicate(ctx, &[p.swizzle.0[0]])?;
            let not = if p.negate { "!" } else { "" };
            body.line(format!("if ({not}{c}) {statement}"));
        }
    }
    Ok(())
}

/// The predicate register `p0` read in `lanes`.
fn predicate(ctx: &Ctx, lanes: &[u8]) -> Result<String, DecompileError> {
    let p0 = crate::core::ir::Reg {
        file: RegFile::Predicate,
        index: 0,
    };
    ctx.register(p0, false, Default::default(), lanes)
}

/// The spelling of a written register with its mask.
fn destination(reg: crate::core::ir::Reg, comps: &[u8]) -> Result<String, DecompileError> {
    let base = match reg.file {
        RegFile::Temp => format!("r{}", reg.index),
        RegFile::ColorOut => format!("oC{}", reg.index),
        RegFile::DepthOut => return Ok("oDepth".into()),
        RegFile::Predicate => "p0".into(),
        _ => match super::vertex::variable(reg) {
            Some(name) => name,
            None => return Err(DecompileError::Unsupported(format!("writing {reg}"))),
        },
    };
    Ok(if comps.len() == 4 {
        base
    } else {
        format!(
            "{base}.{}",
            comps
                .iter()
                .map(|&c| ['x', 'y', 'z', 'w'][c as usize])
                .collect::<String>()
        )
    })
}
