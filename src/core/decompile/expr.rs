//! One instruction's value as an HLSL expression: which components of each
//! source it reads (so that swizzles and write masks fold into the
//! narrowest expression), operands spelled through [`Names`], and the
//! operation as the HLSL that Microsoft's compiler turns back into it
//! (`lerp` for `lrp`, `normalize` for `nrm` where only x, y and z are
//! written, `saturate` for `_sat`, `clip` for `texkill`).

use super::names::{literal, FloatName, Names};
use super::DecompileError;
use crate::core::ir::{Instruction, Reg, RelIndex, Src, SrcMod};
use crate::core::isa::{Compare, Opcode, RegFile, SamplerType};
use std::cell::RefCell;
use std::collections::BTreeMap;

const AXES: [char; 4] = ['x', 'y', 'z', 'w'];

/// The swizzle positions (0 = x … 3 = w) of source `k` that `ins` reads.
pub(crate) fn lanes(ins: &Instruction, k: usize, sampler: Option<SamplerType>) -> Vec<usize> {
    let mask: Vec<usize> = match ins.dst {
        Some(d) => (0..4).filter(|&c| d.mask.has(c)).collect(),
        None => vec![0],
    };
    let dims = match sampler {
        Some(SamplerType::Tex2d) => 2,
        _ => 3,
    };
    match ins.op {
        Opcode::Dp3 | Opcode::Crs => vec![0, 1, 2],
        Opcode::Dp4 => vec![0, 1, 2, 3],
        Opcode::Dp2Add if k < 2 => vec![0, 1],
        Opcode::Nrm if mask.contains(&3) => vec![0, 1, 2, 3],
        Opcode::Nrm => vec![0, 1, 2],
        Opcode::Dp2Add
        | Opcode::Rcp
        | Opcode::Rsq
        | Opcode::Exp
        | Opcode::Log
        | Opcode::Pow
        | Opcode::SinCos
        | Opcode::Ifc
        | Opcode::BreakC
        | Opcode::If
        | Opcode::BreakP
        | Opcode::CallNz => vec![0],
        Opcode::M4x4 | Opcode::M4x3 => vec![0, 1, 2, 3],
        Opcode::M3x4 | Opcode::M3x3 | Opcode::M3x2 => vec![0, 1, 2],
        Opcode::TexLd if k == 0 => (0..dims).collect(),
        Opcode::TexLdD if k != 1 => (0..dims).collect(),
        Opcode::TexLdP | Opcode::TexLdB | Opcode::TexLdL if k == 0 => vec![0, 1, 2, 3],
        _ => mask,
    }
}

/// How many registers a matrix instruction's second source spans.
pub(crate) fn matrix_rows(op: Opcode) -> Option<u32> {
    match op {
        Opcode::M4x4 | Opcode::M3x4 => Some(4),
        Opcode::M4x3 | Opcode::M3x3 => Some(3),
        Opcode::M3x2 => Some(2),
        _ => None,
    }
}

/// The global through which a subroutine reads its caller's loop counter.
pub(crate) const CALLER_COUNTER: &str = "aL";

/// What expressions are spelled with: the names of registers.
pub(crate) struct Ctx<'a> {
    /// Constants, samplers and their declarations.
    pub names: &'a Names,
    /// Input register → parameter name.
    pub inputs: BTreeMap<u32, String>,
    /// ps_2_0/ps_2_x texture coordinate `t#` → parameter name.
    pub texcoords: BTreeMap<u32, String>,
    /// Inputs read as `v[aL + n]`, declared as arrays.
    pub input_arrays: Vec<super::InputArray>,
    /// The loop counters of the enclosing `loop`s, innermost last.
    pub counters: Vec<String>,
    /// For each of those, whether the HLSL counter counts from 0 where
    /// `aL` counts from `i#.y` (`vertex::uniform_loop`).
    pub from_zero: Vec<bool>,
    /// Whether a subroutine reads `aL` outside a loop of its own: the
    /// caller's counter then reaches it through the global `aL`, which every
    /// call made inside a loop sets first (HLSL functions see no caller's
    /// locals; the compiler inlines them all).
    pub caller_counter: bool,
    /// Values not written to their temporary because their one reader
    /// takes the expression itself (see [`super::fold`]): register → value.
    pub pending: RefCell<BTreeMap<u32, Pending>>,
    /// Whether `min(max(x, lo), hi)` of literals is written `clamp(x, lo,
    /// hi)` (a ps_1_x shader's range clamps, `ps1.rs`).
    pub clamps: bool,
}

/// A folded value waiting for its reader.
#[derive(Clone, Debug)]
pub(crate) struct Pending {
    /// The expression.
    pub text: String,
    /// Whether it is one value for every lane written.
    pub scalar: bool,
    /// The components it stands for, in order (its write mask).
    pub comps: Vec<u8>,
}

/// Whether `text` needs no parentheses to take a swizzle or a unary minus:
/// a name with swizzles and indices, a literal, or one call.
fn atomic(text: &str) -> bool {
    if text
        .chars()
        .all(|c| c.is_ascii_alphanumeric() || "._[]".contains(c))
    {
        return true;
    }
    let Some(open) = text.find('(') else {
        return false;
    };
    if !text[..open]
        .chars()
        .all(|c| c.is_ascii_alphanumeric() || c == '_')
        || !text.ends_with(')')
    {
        return false;
    }
    let mut depth = 0i32;
    for (i, c) in text.char_indices().skip(open) {
        match c {
            '(' => depth += 1,
            ')' => {
                depth -= 1;
                if depth == 0 && i + 1 != text.len() {
                    return false;
                }
            }
            _ => {}
        }
    }
    true
}

impl Pending {
    /// The value read at register components `comps`.
    fn read(&self, comps: &[u8]) -> Option<String> {
        if !comps.iter().all(|c| self.comps.contains(c)) {
            return None;
        }
        let base = if atomic(&self.text) {
            self.text.clone()
        } else {
            format!("({})", self.text)
        };
        if self.scalar {
            return Some(if comps.len() == 1 {
                base
            } else {
                format!("{base}.{}", "x".repeat(comps.len()))
            });
        }
        let at: Option<Vec<u8>> = comps
            .iter()
            .map(|c| self.comps.iter().position(|m| m == c).map(|p| p as u8))
            .collect();
        Some(swizzled(&base, self.comps.len() as u8, &at?))
    }
}

fn swizzle_text(comps: &[u8]) -> String {
    comps.iter().map(|&c| AXES[c as usize]).collect()
}

fn modify(text: String, m: SrcMod) -> String {
    let text = if m == SrcMod::Neg && !atomic(&text) {
        format!("({text})")
    } else {
        text
    };
    match m {
        SrcMod::None | SrcMod::Not => text,
        SrcMod::Neg => format!("-{text}"),
        SrcMod::Abs => format!("abs({text})"),
        SrcMod::NegAbs => format!("-abs({text})"),
    }
}

/// `float3(a, b, c)`, or the one literal.
pub(crate) fn vector_literal(values: &[f32]) -> String {
    let parts: Vec<String> = values.iter().map(|&v| literal(v)).collect();
    if parts.len() == 1 {
        parts[0].clone()
    } else {
        format!("float{}({})", parts.len(), parts.join(", "))
    }
}

/// `base.comps`, leaving out a swizzle that changes nothing.
fn swizzled(base: &str, width: u8, comps: &[u8]) -> String {
    let identity =
        comps.len() == width as usize && comps.iter().enumerate().all(|(i, &c)| c as usize == i);
    if identity {
        base.to_string()
    } else {
        format!("{base}.{}", swizzle_text(comps))
    }
}

impl Ctx<'_> {
    /// Source `s` read at swizzle positions `positions`, with its modifier.
    pub(crate) fn operand(&self, s: &Src, positions: &[usize]) -> Result<String, DecompileError> {
        let comps: Vec<u8> = positions.iter().map(|&p| s.swizzle.0[p]).collect();
        self.register_at(s.reg, s.relative, s.modifier, &comps)
    }

    /// [`Ctx::operand`] of a component-wise operation, where a source that
    /// reads one component for every lane is written once as a scalar
    /// (HLSL widens it, exactly) and a pending folded value is taken.
    pub(crate) fn lane_operand(
        &self,
        s: &Src,
        positions: &[usize],
    ) -> Result<String, DecompileError> {
        let comps: Vec<u8> = positions.iter().map(|&p| s.swizzle.0[p]).collect();
        if comps.len() > 1 && comps.iter().all(|&c| c == comps[0]) {
            return self.register_at(s.reg, s.relative, s.modifier, &comps[..1]);
        }
        self.register_at(s.reg, s.relative, s.modifier, &comps)
    }

    /// The name `aL` reads as here: the innermost loop's counter, or in a
    /// subroutine outside its own loops the caller's, through the global
    /// `aL` ([`Ctx::caller_counter`]).
    fn counter(&self) -> Option<String> {
        match self.counters.last() {
            Some(counter) => Some(counter.clone()),
            None => self.caller_counter.then(|| CALLER_COUNTER.to_string()),
        }
    }

    /// Register `reg` read at components `comps`, with modifier `m`
    /// (`relative`: indexed by the loop counter).
    pub(crate) fn register(
        &self,
        reg: Reg,
        relative: bool,
        m: SrcMod,
        comps: &[u8],
    ) -> Result<String, DecompileError> {
        self.register_at(reg, relative.then_some(RelIndex::Loop), m, comps)
    }

    /// [`Ctx::register`] indexed by `index` (`aL`, or a component of `a0`).
    pub(crate) fn register_at(
        &self,
        reg: Reg,
        index: Option<RelIndex>,
        m: SrcMod,
        comps: &[u8],
    ) -> Result<String, DecompileError> {
        let relative = index.is_some();
        let unsupported = |what: &str| Err(DecompileError::Unsupported(what.to_string()));
        let text = match reg.file {
            RegFile::Const if relative => {
                let Some((first, _, name)) = self
                    .names
                    .arrays
                    .iter()
                    .find(|(f, n, _)| reg.index >= *f && reg.index < f + n)
                else {
                    return Err(DecompileError::Unsupported(if reg.index >= 8192 {
                        format!(
                            "c[{} + {}] (a matrix row) is past c8191, the last constant \
                             register Microsoft's compiler binds (X4507: \"maximum constant \
                             register index (8192) exceeded\")",
                            index.map(|i| i.to_string()).unwrap_or_default(),
                            reg.index
                        )
                    } else {
                        "relative read outside an array".to_string()
                    }));
                };
                // the index is not aL itself in a loop over an int uniform,
                // nor (unknown) the caller's counter in a subroutine
                let index_from_zero =
                    index == Some(RelIndex::Loop) && self.from_zero.last().copied().unwrap_or(true);
                let counter = match index {
                    Some(RelIndex::Addr(c)) => format!("a0.{}", AXES[c as usize & 3]),
                    _ => match self.counter() {
                        Some(counter) => counter,
                        None => return unsupported("c[aL] outside a loop"),
                    },
                };
                let offset = reg.index - first;
                let index = if offset == 0 {
                    counter.clone()
                } else {
                    format!("{counter} + {offset}")
                };
                // an array based at a def reads through its function
                let read = match self.names.readers.get(name) {
                    Some(_) if index_from_zero => {
                        return unsupported(
                            "c[aL + n] starts at a def register, and the HLSL's counter here \
                             may not be aL: a loop over an int uniform counts from 0 where aL \
                             counts from i#.y (a subroutine's caller may be one), and only the \
                             compiler's own c[aL] reads follow aL",
                        )
                    }
                    Some(f) => format!("{f}({index})"),
                    None => format!("{name}[{index}]"),
                };
                swizzled(&read, 4, comps)
            }
            RegFile::Const => match self.names.floats.get(&reg.index) {
                Some(FloatName::Literal(v)) => {
                    let values: Vec<f32> = comps
                        .iter()
                        .map(|&c| {
                            let x = v[c as usize];
                            match m {
                                SrcMod::Neg => -x,
                                SrcMod::Abs => x.abs(),
                                SrcMod::NegAbs => -x.abs(),
                                _ => x,
                            }
                        })
                        .collect();
                    return Ok(vector_literal(&values));
                }
                Some(FloatName::Vector { base, width }) => swizzled(base, *width, comps),
                Some(FloatName::Column { base, column, .. }) => {
                    let parts: String = comps.iter().map(|&j| format!("_m{j}{column}")).collect();
                    format!("{base}.{parts}")
                }
                None => return unsupported("a constant register without a name"),
            },
            RegFile::Temp => {
                // a folded value is taken by the read of its own components;
                // the register's other components are read as they are
                let mut pending = self.pending.borrow_mut();
                let folded = pending.get(&reg.index).and_then(|p| p.read(comps));
                if folded.is_some() {
                    pending.remove(&reg.index);
                }
                folded.unwrap_or_else(|| swizzled(&format!("r{}", reg.index), 4, comps))
            }
            RegFile::Input if relative => {
                let Some(a) = self
                    .input_arrays
                    .iter()
                    .find(|a| reg.index >= a.first && reg.index < a.first + a.len)
                else {
                    return unsupported("v[aL + n] outside a run of declared inputs");
                };
                let Some(counter) = self.counter() else {
                    return unsupported("v[aL] outside a loop");
                };
                let offset = reg.index - a.first;
                let index = if offset == 0 {
                    counter
                } else {
                    format!("{counter} + {offset}")
                };
                swizzled(&format!("{}[{index}]", a.name), 4, comps)
            }
            RegFile::Input => match self.inputs.get(&reg.index) {
                Some(name) => swizzled(name, 4, comps),
                None => return unsupported("an input read without its declaration"),
            },
            RegFile::Position if comps.iter().all(|&c| c < 2) => swizzled("vpos", 2, comps),
            // vFace holds the face's sign in every component
            RegFile::Face if comps.len() == 1 => "vface".into(),
            RegFile::Face => format!("vface.{}", "x".repeat(comps.len())),
            RegFile::ColorOut => swizzled(&format!("oC{}", reg.index), 4, comps),
            RegFile::Texture => match self.texcoords.get(&reg.index) {
                Some(name) => swizzled(name, 4, comps),
                None => return unsupported("a texture coordinate read without its declaration"),
            },
            RegFile::Address => swizzled("a0", 4, comps),
            RegFile::Predicate => swizzled("p0", 4, comps),
            _ => return unsupported(&format!("reading {reg} at .{}", swizzle_text(comps))),
        };
        Ok(modify(text, m))
    }

    /// The boolean of a flow-control condition: `b#`, `p0.c` or `a op b`.
    pub(crate) fn condition(&self, ins: &Instruction) -> Result<String, DecompileError> {
        if let Some(c) = ins.compare {
            let a = self.operand(&ins.src[0], &[0])?;
            let b = self.operand(&ins.src[1], &[0])?;
            return Ok(format!("{a} {} {b}", compare(c)));
        }
        let s = ins
            .src
            .last()
            .ok_or_else(|| DecompileError::Unsupported("a condition without a source".into()))?;
        let text = match s.reg.file {
            RegFile::ConstBool => {
                self.names.bools.get(&s.reg.index).cloned().ok_or_else(|| {
                    DecompileError::Unsupported(format!("b{} unnamed", s.reg.index))
                })?
            }
            _ => self.operand(
                &Src {
                    modifier: SrcMod::None,
                    ..*s
                },
                &[0],
            )?,
        };
        Ok(if s.modifier == SrcMod::Not {
            format!("!{text}")
        } else {
            text
        })
    }
}

/// The HLSL comparison operator.
pub(crate) fn compare(c: Compare) -> &'static str {
    match c {
        Compare::Gt => ">",
        Compare::Lt => "<",
        Compare::Ge => ">=",
        Compare::Le => "<=",
        Compare::Eq => "==",
        Compare::Ne => "!=",
    }
}

/// The value `ins` writes, as an expression as wide as its write mask.
pub(crate) fn value(
    ctx: &Ctx,
    ins: &Instruction,
    sampler: Option<SamplerType>,
) -> Result<String, DecompileError> {
    let mask: Vec<usize> = ins
        .dst
        .map(|d| (0..4).filter(|&c| d.mask.has(c)).collect())
        .unwrap_or_default();
    let width = mask.len();
    let lanewise = componentwise(ins.op);
    let src = |k: usize| -> Result<String, DecompileError> {
        let s = ins.src.get(k).ok_or_else(|| {
            DecompileError::Unsupported(format!("{} without source {k}", ins.op.info().mnemonic))
        })?;
        if lanewise {
            ctx.lane_operand(s, &lanes(ins, k, sampler))
        } else {
            ctx.operand(s, &lanes(ins, k, sampler))
        }
    };
    let e = match ins.op {
        Opcode::Mov => src(0)?,
        Opcode::Add => binary(src(0)?, "+", src(1)?),
        Opcode::Sub => format!("{} - {}", src(0)?, src(1)?),
        Opcode::Mul => format!("{} * {}", src(0)?, src(1)?),
        Opcode::Mad => binary(format!("{} * {}", src(0)?, src(1)?), "+", src(2)?),
        Opcode::Min => {
            let (a, b) = (src(0)?, src(1)?);
            let clamp = ctx.clamps.then(|| super::ps1::clamp_of(&a, &b)).flatten();
            clamp.unwrap_or_else(|| format!("min({a}, {b})"))
        }
        Opcode::Max => format!("max({}, {})", src(0)?, src(1)?),
        Opcode::Abs => format!("abs({})", src(0)?),
        Opcode::Frc => format!("frac({})", src(0)?),
        // ps_1_x's `lrp` as its lowering computes it, one rounding per
        // operation, which `precise` keeps (the compiler expands `lerp`
        // into a different grouping whatever the variables are)
        Opcode::Lrp if ctx.clamps => {
            let (a, b, c) = (src(0)?, src(1)?, src(2)?);
            format!("({a} * {b} + (1.0 - {a}) * {c})")
        }
        Opcode::Lrp => format!("lerp({}, {}, {})", src(2)?, src(1)?, src(0)?),
        Opcode::Cmp => format!("{} >= 0.0 ? {} : {}", src(0)?, src(1)?, src(2)?),
        Opcode::Dsx => format!("ddx({})", src(0)?),
        Opcode::Dsy => format!("ddy({})", src(0)?),
        Opcode::Dp3 | Opcode::Dp4 => format!("dot({}, {})", src(0)?, src(1)?),
        Opcode::Dp2Add => format!("dot({}, {}) + {}", src(0)?, src(1)?, src(2)?),
        Opcode::Crs => {
            let c = format!("cross({}, {})", src(0)?, src(1)?);
            swizzled(&c, 3, &mask.iter().map(|&m| m as u8).collect::<Vec<_>>())
        }
        Opcode::Rcp => format!("1.0 / {}", src(0)?),
        Opcode::Rsq => format!("rsqrt({})", absolute(ins, &src(0)?)),
        Opcode::Exp => format!("exp2({})", src(0)?),
        Opcode::Log => format!("log2({})", absolute(ins, &src(0)?)),
        Opcode::Pow => format!("pow({}, {})", absolute(ins, &src(0)?), src(1)?),
        Opcode::Nrm if !mask.contains(&3) => {
            let n = format!("normalize({})", src(0)?);
            swizzled(&n, 3, &mask.iter().map(|&m| m as u8).collect::<Vec<_>>())
        }
        Opcode::Nrm => {
            let v = ctx.operand(&ins.src[0], &mask)?;
            let l = ctx.operand(&ins.src[0], &[0, 1, 2])?;
            format!("{v} * rsqrt(dot({l}, {l}))")
        }
        Opcode::SinCos => {
            let a = src(0)?;
            let parts: Vec<String> = mask
                .iter()
                .map(|&m| {
                    if m == 0 {
                        format!("cos({a})")
                    } else {
                        format!("sin({a})")
                    }
                })
                .collect();
            if parts.len() == 1 {
                parts[0].clone()
            } else {
                format!("float{}({})", parts.len(), parts.join(", "))
            }
        }
        Opcode::M4x4 | Opcode::M4x3 | Opcode::M3x4 | Opcode::M3x3 | Opcode::M3x2 => {
            matrix(ctx, ins, &mask)?
        }
        Opcode::TexLd | Opcode::TexLdP | Opcode::TexLdB | Opcode::TexLdL | Opcode::TexLdD => {
            texture(ctx, ins, &mask, sampler)?
        }
        Opcode::Setp => {
            let c = ins
                .compare
                .ok_or_else(|| DecompileError::Unsupported("setp without a comparison".into()))?;
            return Ok(format!("{} {} {}", src(0)?, compare(c), src(1)?));
        }
        op if super::vertex::handles(op) => {
            let operand = |k: usize, positions: &[usize]| {
                let s = ins.src.get(k).ok_or_else(|| {
                    DecompileError::Unsupported(format!(
                        "{} without source {k}",
                        op.info().mnemonic
                    ))
                })?;
                ctx.operand(s, positions)
            };
            super::vertex::value(ins, &mask, &operand, atomic)?
        }
        op => {
            return Err(DecompileError::Unsupported(format!(
                "{} as a value",
                op.info().mnemonic
            )))
        }
    };
    let _ = width;
    Ok(if ins.sat { format!("saturate({e})") } else { e })
}

/// Whether every lane of `op` reads the same lane of its sources.
pub(crate) fn componentwise(op: Opcode) -> bool {
    matches!(
        op,
        Opcode::Mov
            | Opcode::Add
            | Opcode::Sub
            | Opcode::Mul
            | Opcode::Mad
            | Opcode::Min
            | Opcode::Max
            | Opcode::Abs
            | Opcode::Frc
            | Opcode::Lrp
            | Opcode::Cmp
            | Opcode::Dsx
            | Opcode::Dsy
    )
}

/// Whether `ins` computes one value for all the lanes it writes.
pub(crate) fn scalar_value(ins: &Instruction, sampler: Option<SamplerType>) -> bool {
    let lanes_written = ins.dst.map_or(0, |d| d.mask.count());
    match ins.op {
        _ if lanes_written <= 1 => true,
        Opcode::Dp3
        | Opcode::Dp4
        | Opcode::Dp2Add
        | Opcode::Rcp
        | Opcode::Rsq
        | Opcode::Exp
        | Opcode::Log
        | Opcode::Pow => true,
        op if componentwise(op) => ins.src.iter().enumerate().all(|(k, s)| {
            let comps: Vec<u8> = lanes(ins, k, sampler)
                .iter()
                .map(|&p| s.swizzle.0[p])
                .collect();
            comps.iter().all(|&c| c == comps[0])
        }),
        _ => false,
    }
}

/// `a + b`, or `a - b` when `b` is negated (the same IEEE operation).
fn binary(a: String, op: &str, b: String) -> String {
    match (a.strip_prefix('-'), b.strip_prefix('-')) {
        (_, Some(rest)) if op == "+" => format!("{a} - {rest}"),
        // -a + b is b - a: IEEE addition commutes
        (Some(rest), None) if op == "+" && atomic(rest) && atomic(&b) => format!("{b} - {rest}"),
        _ => format!("{a} {op} {b}"),
    }
}

/// `x` for instructions that take the absolute value themselves (`rsq`,
/// `log`, `pow`'s base): `abs(x)` unless the source already has one.
fn absolute(ins: &Instruction, text: &str) -> String {
    if matches!(ins.src[0].modifier, SrcMod::Abs | SrcMod::NegAbs) {
        text.trim_start_matches('-').to_string()
    } else if let Ok(v) = text.parse::<f32>() {
        literal(v.abs())
    } else {
        format!("abs({text})")
    }
}

/// `m4x4` and its kind: one dot product per written component, with
/// rows `src1`, `src1 + 1`, ….
fn matrix(ctx: &Ctx, ins: &Instruction, mask: &[usize]) -> Result<String, DecompileError> {
    let rows = lanes(ins, 0, None);
    let a = ctx.operand(&ins.src[0], &rows)?;
    let n = matrix_rows(ins.op).unwrap_or(0);
    let m = ins.src[1];
    if m.swizzle == super::matrix::CHAIN {
        let (name, by_rows) = super::matrix::whole(ctx.names, m.reg.index, mask.len() as u8, n)
            .ok_or_else(|| DecompileError::Unsupported("a sum of matrix registers".into()))?;
        let a = if atomic(&a) { a } else { format!("({a})") };
        return Ok(if by_rows {
            format!("mul({a}, {name})")
        } else {
            format!("mul({name}, {a})")
        });
    }
    let whole =
        (m.reg.file == RegFile::Const && m.relative.is_none() && m.modifier == SrcMod::None)
            .then(|| super::matrix::whole(ctx.names, m.reg.index, rows.len() as u8, n))
            .flatten();
    if let Some((name, by_rows)) = whole.filter(|_| mask.iter().copied().eq(0..n as usize)) {
        let a = if atomic(&a) { a } else { format!("({a})") };
        return Ok(if by_rows {
            format!("mul({name}, {a})")
        } else {
            format!("mul({a}, {name})")
        });
    }
    let mut parts = Vec::new();
    for &m in mask {
        if m as u32 >= matrix_rows(ins.op).unwrap_or(0) {
            return Err(DecompileError::Unsupported(
                "a matrix instruction writing past its rows".into(),
            ));
        }
        let mut row = ins.src[1];
        row.reg.index += m as u32;
        parts.push(format!("dot({a}, {})", ctx.operand(&row, &rows)?));
    }
    Ok(if parts.len() == 1 {
        parts[0].clone()
    } else {
        format!("float{}({})", parts.len(), parts.join(", "))
    })
}

/// The texld family: `tex2D`, `tex2Dproj`, `tex2Dbias`, `tex2Dlod`,
/// `tex2Dgrad` and their cube and volume forms, swizzled by the sampler's
/// swizzle and the write mask.
fn texture(
    ctx: &Ctx,
    ins: &Instruction,
    mask: &[usize],
    sampler: Option<SamplerType>,
) -> Result<String, DecompileError> {
    let s = ins
        .src
        .get(1)
        .ok_or_else(|| DecompileError::Unsupported("texld without a sampler".into()))?;
    let name = ctx
        .names
        .samplers
        .get(&s.reg.index)
        .ok_or_else(|| DecompileError::Unsupported(format!("s{} undeclared", s.reg.index)))?;
    let kind = match sampler {
        Some(SamplerType::Cube) => "texCUBE",
        Some(SamplerType::Volume) => "tex3D",
        _ => "tex2D",
    };
    let coord = ctx.operand(&ins.src[0], &lanes(ins, 0, sampler))?;
    let call = match ins.op {
        Opcode::TexLd => format!("{kind}({name}, {coord})"),
        Opcode::TexLdP => format!("{kind}proj({name}, {coord})"),
        Opcode::TexLdB => format!("{kind}bias({name}, {coord})"),
        Opcode::TexLdL => format!("{kind}lod({name}, {coord})"),
        _ => {
            let g = lanes(ins, 2, sampler);
            let dx = ctx.operand(&ins.src[2], &g)?;
            let dy = ctx.operand(&ins.src[3], &g)?;
            format!("{kind}grad({name}, {coord}, {dx}, {dy})")
        }
    };
    let comps: Vec<u8> = mask.iter().map(|&m| s.swizzle.0[m]).collect();
    Ok(swizzled(&call, 4, &comps))
}
