//! Translation of a validated [`Shader`] into the emulator's own micro-ops.
//!
//! The IR is built for diagnostics and analysis (spans, `Vec` operands,
//! register files). Executing it directly would mean decoding every operand of
//! every instruction again on each loop iteration. Instead, [`compile`] walks
//! the program once and produces a flat `Vec` of small `Copy` micro-ops
//! (wasmi-style): registers become row offsets into one register array, jump
//! targets become instruction indices, swizzles and source modifiers become a
//! few packed bits, and every op carries its static slot cost from
//! [`Info::slots`] for executed-slot counting.
//!
//! Register layout (rows of [`super::LANES`] lane values, one row per register
//! component, component `c` of a register with base row `b` at `b + c`):
//!
//! | rows | contents | lifetime |
//! |---|---|---|
//! | 0..4 | zeros (out-of-range `v[aL + n]`) | constant |
//! | constant block | every `c#` the program reads (sorted, so matrix ranges are contiguous) and `vFace` | filled once per worker |
//! | reset block | every `r#` used, `oC0..oC3`, `oDepth`, `aL` | zeroed per batch |
//! | input block | `v0..v9` (ps_2_x: `v0`, `v1`, `t0..t7`, by [`slot`]), `vPos` | filled per batch |

use super::{EmuError, GradientSite};
use crate::core::ir::{Dst, Info, Instruction, Program, Shader, Span, Src, SrcMod, Swizzle};
use crate::core::isa::{Compare, Opcode, RegFile, SamplerType, SlotTable};
use crate::core::pixel_inputs::{self, slot};
use std::collections::{BTreeSet, HashMap};

/// A source operand: a row base, a packed swizzle and modifier bits.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SrcOp {
    /// Base row of the register (component x).
    pub row: u16,
    /// Swizzle, two bits per output component (x in bits 0-1).
    pub swz: u8,
    /// Bits 0-1: modifier (0 none, 1 neg, 2 abs, 3 neg-abs); bit 2: relative
    /// `v[aL + n]` addressing.
    pub flags: u8,
}

impl SrcOp {
    const RELATIVE: u8 = 4;

    /// The input component read for output component `c`.
    #[inline(always)]
    pub fn comp(self, c: usize) -> usize {
        ((self.swz >> (2 * c)) & 3) as usize
    }

    #[inline(always)]
    pub fn relative(self) -> bool {
        self.flags & Self::RELATIVE != 0
    }

    /// `(and, xor)` masks applying the modifier to the bits of an f32:
    /// abs clears the sign bit, neg flips it.
    #[inline(always)]
    pub fn mod_bits(self) -> (u32, u32) {
        match self.flags & 3 {
            0 => (!0, 0),
            1 => (!0, 0x8000_0000),
            2 => (0x7fff_ffff, 0),
            _ => (0x7fff_ffff, 0x8000_0000),
        }
    }
}

/// A destination: row base, write mask and flags, predicate swizzle.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DstOp {
    /// Base row of the register.
    pub row: u16,
    /// Bits 0-3: write mask; 4: `_sat`; 5: predicated; 6: predicate negated;
    /// 7: the register is an output (`oC#`, `oDepth`).
    pub flags: u8,
    /// Predicate swizzle, two bits per component.
    pub pswz: u8,
}

impl DstOp {
    pub const SAT: u8 = 16;
    pub const PRED: u8 = 32;
    pub const PRED_NOT: u8 = 64;
    pub const OUTPUT: u8 = 128;

    #[inline(always)]
    pub fn mask(self) -> u8 {
        self.flags & 15
    }

    #[inline(always)]
    pub fn sat(self) -> bool {
        self.flags & Self::SAT != 0
    }

    #[inline(always)]
    pub fn predicated(self) -> bool {
        self.flags & Self::PRED != 0
    }

    #[inline(always)]
    pub fn pred_not(self) -> bool {
        self.flags & Self::PRED_NOT != 0
    }

    #[inline(always)]
    pub fn output(self) -> bool {
        self.flags & Self::OUTPUT != 0
    }

    /// The predicate channel guarding component `c`.
    #[inline(always)]
    pub fn pred_comp(self, c: usize) -> usize {
        ((self.pswz >> (2 * c)) & 3) as usize
    }
}

/// A sampler operand: `s#` and the swizzle applied to the sampled result.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SamplerOp {
    pub index: u8,
    pub swz: u8,
}

/// A jump target: an op index stored as two `u16` halves so that the op enum
/// keeps an alignment of 2 (and a size of 18 bytes).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Pc([u16; 2]);

impl Pc {
    fn new(pc: u32) -> Pc {
        Pc([pc as u16, (pc >> 16) as u16])
    }

    #[inline(always)]
    pub fn get(self) -> usize {
        (self.0[0] as u32 | (self.0[1] as u32) << 16) as usize
    }
}

/// A flow-control condition: `[!]b#` (uniform) or `[!]p0.c` (per lane).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Cond {
    Bool { index: u8, not: bool },
    Pred { chan: u8, not: bool },
}

/// Which member of the texld family (they differ only in how the coordinate
/// and LOD are formed).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TexKind {
    Ld,
    LdP,
    LdB,
    LdL,
}

/// One micro-op. Arithmetic ops carry their operands; flow ops carry resolved
/// jump targets.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Op {
    Nop,
    Mov {
        d: DstOp,
        a: SrcOp,
    },
    Add {
        d: DstOp,
        a: SrcOp,
        b: SrcOp,
    },
    Sub {
        d: DstOp,
        a: SrcOp,
        b: SrcOp,
    },
    Mad {
        d: DstOp,
        a: SrcOp,
        b: SrcOp,
        c: SrcOp,
    },
    Mul {
        d: DstOp,
        a: SrcOp,
        b: SrcOp,
    },
    Rcp {
        d: DstOp,
        a: SrcOp,
    },
    Rsq {
        d: DstOp,
        a: SrcOp,
    },
    Dp3 {
        d: DstOp,
        a: SrcOp,
        b: SrcOp,
    },
    Dp4 {
        d: DstOp,
        a: SrcOp,
        b: SrcOp,
    },
    Min {
        d: DstOp,
        a: SrcOp,
        b: SrcOp,
    },
    Max {
        d: DstOp,
        a: SrcOp,
        b: SrcOp,
    },
    Exp {
        d: DstOp,
        a: SrcOp,
    },
    Log {
        d: DstOp,
        a: SrcOp,
    },
    Lrp {
        d: DstOp,
        a: SrcOp,
        b: SrcOp,
        c: SrcOp,
    },
    Frc {
        d: DstOp,
        a: SrcOp,
    },
    /// `m4x4` … `m3x2`: `n` dot products of `dims` components with rows
    /// `b`, `b + 1`, ….
    Mat {
        d: DstOp,
        a: SrcOp,
        b: SrcOp,
        n: u8,
        dims: u8,
    },
    Pow {
        d: DstOp,
        a: SrcOp,
        b: SrcOp,
    },
    Crs {
        d: DstOp,
        a: SrcOp,
        b: SrcOp,
    },
    Abs {
        d: DstOp,
        a: SrcOp,
    },
    Nrm {
        d: DstOp,
        a: SrcOp,
    },
    SinCos {
        d: DstOp,
        a: SrcOp,
    },
    Cmp {
        d: DstOp,
        a: SrcOp,
        b: SrcOp,
        c: SrcOp,
    },
    Dp2Add {
        d: DstOp,
        a: SrcOp,
        b: SrcOp,
        c: SrcOp,
    },
    /// `site`: index into [`Compiled::sites`].
    Dsx {
        d: DstOp,
        a: SrcOp,
        site: u16,
    },
    Dsy {
        d: DstOp,
        a: SrcOp,
        site: u16,
    },
    /// `texkill`: `d.row` is the tested register, `d.mask` its components.
    TexKill {
        d: DstOp,
    },
    /// `site`: index into [`Compiled::sites`] (`u16::MAX` for texldl, which
    /// takes no gradients).
    Tex {
        d: DstOp,
        a: SrcOp,
        s: SamplerOp,
        kind: TexKind,
        site: u16,
    },
    /// `texldd`: the gradient sources live in [`Compiled::grads`].
    TexD {
        d: DstOp,
        a: SrcOp,
        s: SamplerOp,
        grads: u16,
    },
    /// `setp_cmp p0.mask, a, b`: `d.mask` is the p0 mask.
    Setp {
        d: DstOp,
        a: SrcOp,
        b: SrcOp,
        cmp: Compare,
    },
    /// `if b#` / `if p0.c`; `target` is the `else` (or `endif`).
    If {
        cond: Cond,
        target: Pc,
    },
    /// `if_cmp a, b`; `target` is the `else` (or `endif`).
    Ifc {
        cmp: Compare,
        a: SrcOp,
        b: SrcOp,
        target: Pc,
    },
    /// `target` is the `endif`.
    Else {
        target: Pc,
    },
    EndIf,
    /// `end` is the `endrep`.
    Rep {
        int: u8,
        end: Pc,
    },
    /// `start` is the `rep`.
    EndRep {
        start: Pc,
    },
    Loop {
        int: u8,
        end: Pc,
    },
    EndLoop {
        start: Pc,
    },
    Break,
    BreakC {
        cmp: Compare,
        a: SrcOp,
        b: SrcOp,
    },
    BreakP {
        chan: u8,
        not: bool,
    },
    /// `target` is the first op after the `label`.
    Call {
        target: Pc,
    },
    CallNz {
        cond: Cond,
        target: Pc,
    },
    Ret,
    /// A `label` reached by falling through, and the sentinel after the last
    /// instruction: the end of the current function (or of the shader).
    Label,
}

/// A micro-op with its static slot cost.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MicroOp {
    /// The operation.
    pub op: Op,
    /// Slots charged to every lane that executes the op ([`Info::slots`]).
    pub slots: u8,
}

/// Where the special registers live in the row array.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Layout {
    /// Total number of rows.
    pub rows: usize,
    /// `(first row, c#)` for every constant register in the constant block.
    pub consts: Vec<(u16, u32)>,
    pub face: u16,
    /// Rows zeroed at the start of each batch.
    pub reset: std::ops::Range<usize>,
    /// `v0`; `v#` is at `input + 4 * #`.
    pub input: u16,
    pub pos: u16,
    /// `oC0`; `oC#` at `output + 4 * #`, `oDepth` at `output + 16`.
    pub output: u16,
    pub al: u16,
}

/// A compiled shader: micro-ops plus what a draw must supply.
#[derive(Clone, Debug, PartialEq)]
pub struct Compiled {
    pub(crate) ops: Vec<MicroOp>,
    /// `(ddx, ddy)` sources of each `texldd`.
    pub(crate) grads: Vec<(SrcOp, SrcOp)>,
    /// Gradient sites: one per source statement (span) of a `dsx`, `dsy`,
    /// `texld`, `texldp` or `texldb` (REPEAT_BLOCK copies share one), with
    /// zero counts.
    pub(crate) sites: Vec<GradientSite>,
    pub(crate) layout: Layout,
    pub(crate) float_defs: Vec<(u32, [f32; 4])>,
    pub(crate) int_defs: Vec<(u32, [i32; 4])>,
    pub(crate) bool_defs: Vec<(u32, bool)>,
    /// Declared sampler types by `s#`.
    pub(crate) samplers: [Option<SamplerType>; 16],
    /// Input slots the program declares or reads directly
    /// ([`pixel_inputs`]: `v#` in ps_3_0, `v#` and `t#` in ps_2_x).
    pub(crate) inputs: u16,
    /// Input slots clamped to [0, 1] on entry ([`pixel_inputs::clamped`]).
    pub(crate) clamped: u16,
    /// The shader's profile, which names its input slots.
    pub(crate) profile: crate::core::profile::Profile,
    /// Whether any op reads `aL` as a float source (the aL rows are kept up to
    /// date only then).
    pub(crate) reads_al: bool,
    /// Which outputs the program writes at all (bit i = oC#, bit 4 = oDepth).
    pub(crate) outputs: u8,
    /// `i#` used by rep / by loop (bit per register).
    pub(crate) rep_ints: u16,
    pub(crate) loop_ints: u16,
}

impl Compiled {
    /// Number of micro-ops (instructions plus the end sentinel).
    pub fn op_count(&self) -> usize {
        self.ops.len()
    }

    /// Size of one micro-op in bytes.
    pub fn op_size() -> usize {
        std::mem::size_of::<MicroOp>()
    }

    /// Whether the program writes `oC#` (`index` < 4) or `oDepth` (4) anywhere.
    pub fn writes_output(&self, index: usize) -> bool {
        index < 5 && self.outputs & (1 << index) != 0
    }
}

/// Number of registers of each numbered file. Validation keeps a shader's
/// temporaries to its profile's count; the bound shader of `ps30 decompile
/// --verify` (`jobs/decompile/bound.rs`) keeps shadow registers up to r127.
const TEMPS: u32 = 128;
const INPUTS: u32 = 10;
const CONSTS: u32 = 224;

fn malformed(index: usize, reason: impl Into<String>) -> EmuError {
    EmuError::Malformed {
        index,
        reason: reason.into(),
    }
}

fn pack_swizzle(s: Swizzle) -> u8 {
    s.0.iter()
        .enumerate()
        .fold(0, |acc, (i, &c)| acc | ((c & 3) << (2 * i)))
}

/// Registers the program touches, gathered before rows are assigned.
#[derive(Default)]
struct Usage {
    temps: BTreeSet<u32>,
    consts: BTreeSet<u32>,
}

/// How many consecutive registers a matrix instruction reads from `src1`,
/// and its dot-product width ([`Opcode::matrix_shape`]).
fn matrix_rows(op: Opcode) -> Option<(u8, u8)> {
    op.matrix_shape().map(|(r, w)| (r as u8, w as u8))
}

/// Pass 1: which temps and constants are used (with matrix ranges).
fn usage(ins: &[Instruction]) -> Result<Usage, EmuError> {
    let mut usage = Usage::default();
    for (i, x) in ins.iter().enumerate() {
        let span = matrix_rows(x.op);
        for (k, s) in x.src.iter().enumerate() {
            let count = match span {
                Some((n, _)) if k == 1 => n as u32,
                _ => 1,
            };
            for r in 0..count {
                let idx = s.reg.index + r;
                match s.reg.file {
                    RegFile::Temp if idx < TEMPS => usage.temps.insert(idx),
                    RegFile::Const if idx < CONSTS => usage.consts.insert(idx),
                    RegFile::Temp | RegFile::Const => {
                        return Err(malformed(i, format!("register {} out of range", s.reg)))
                    }
                    _ => false,
                };
            }
        }
        if let Some(d) = &x.dst {
            if d.reg.file == RegFile::Temp && d.reg.index < TEMPS {
                usage.temps.insert(d.reg.index);
            }
        }
    }
    Ok(usage)
}

/// The row assignment: the layout, and the base row of every used `r#` and
/// `c#` (see the module docs for the order of the blocks).
struct Rows {
    layout: Layout,
    temp_row: [u16; TEMPS as usize],
    const_row: [u16; CONSTS as usize],
}

fn assign_rows(usage: &Usage) -> Result<Rows, EmuError> {
    let mut row: usize = 4; // zero register
    let mut const_row = [0u16; CONSTS as usize];
    let mut consts = Vec::new();
    for &c in &usage.consts {
        const_row[c as usize] = row as u16;
        consts.push((row as u16, c));
        row += 4;
    }
    let face = row as u16;
    row += 4;
    let reset_start = row;
    let mut temp_row = [0u16; TEMPS as usize];
    for &t in &usage.temps {
        temp_row[t as usize] = row as u16;
        row += 4;
    }
    let output = row as u16;
    row += 20;
    let al = row as u16;
    row += 4;
    let reset = reset_start..row;
    let input = row as u16;
    row += 4 * INPUTS as usize;
    let pos = row as u16;
    row += 4;
    if row > u16::MAX as usize {
        return Err(malformed(0, "too many registers"));
    }
    Ok(Rows {
        layout: Layout {
            rows: row,
            consts,
            face,
            reset,
            input,
            pos,
            output,
            al,
        },
        temp_row,
        const_row,
    })
}

/// Pass 2's state: the row assignment, what the ops reveal about the program
/// (outputs, inputs, `aL` reads, loop integers) and the side tables the ops
/// index (texldd gradients, gradient sites).
struct Builder<'a> {
    info: &'a Info,
    profile: crate::core::profile::Profile,
    ins: &'a [Instruction],
    layout: Layout,
    temp_row: [u16; TEMPS as usize],
    const_row: [u16; CONSTS as usize],
    reads_al: bool,
    outputs: u8,
    inputs: u16,
    /// Declared sampler types by `s#`.
    samplers: [Option<SamplerType>; 16],
    grads: Vec<(SrcOp, SrcOp)>,
    sites: Vec<GradientSite>,
    site_of_span: HashMap<Span, u16>,
    /// The lexical count of open loops, which checks `break` placement.
    open_loops: u32,
    rep_ints: u16,
    loop_ints: u16,
}

/// Source operand `k` of instruction `i`.
fn operand(i: usize, x: &Instruction, k: usize) -> Result<&Src, EmuError> {
    x.src
        .get(k)
        .ok_or_else(|| malformed(i, format!("missing source operand {}", k)))
}

impl Builder<'_> {
    fn src(&mut self, i: usize, s: &Src) -> Result<SrcOp, EmuError> {
        let idx = s.reg.index;
        let row = match s.reg.file {
            RegFile::Temp if idx < TEMPS => self.temp_row[idx as usize],
            RegFile::Const if idx < CONSTS => self.const_row[idx as usize],
            // A relative base may lie past v9: the read lands inside v0 … v9
            // or reads 0 (Worker::row).
            RegFile::Input if s.relative.is_some() => self.layout.input + 4 * idx as u16,
            RegFile::Input | RegFile::Texture => {
                let v = slot(self.profile, s.reg.file, idx)
                    .ok_or_else(|| malformed(i, format!("{} is no input here", s.reg)))?;
                self.inputs |= 1 << v;
                self.layout.input + 4 * v as u16
            }
            RegFile::Position => self.layout.pos,
            RegFile::Face => self.layout.face,
            RegFile::LoopCounter => {
                self.reads_al = true;
                self.layout.al
            }
            _ => return Err(malformed(i, format!("{} cannot be read here", s.reg))),
        };
        if s.relative.is_some() && s.reg.file != RegFile::Input {
            return Err(malformed(
                i,
                format!("relative addressing of {} (only v# allowed)", s.reg),
            ));
        }
        let modifier = match s.modifier {
            SrcMod::None => 0,
            SrcMod::Neg => 1,
            SrcMod::Abs => 2,
            SrcMod::NegAbs => 3,
            SrcMod::Not => return Err(malformed(i, "'!' on a float source")),
        };
        Ok(SrcOp {
            row,
            swz: pack_swizzle(s.swizzle),
            flags: modifier
                | if s.relative.is_some() {
                    SrcOp::RELATIVE
                } else {
                    0
                },
        })
    }

    /// Source operand `k` of instruction `i`, compiled.
    fn src_at(&mut self, i: usize, x: &Instruction, k: usize) -> Result<SrcOp, EmuError> {
        self.src(i, operand(i, x, k)?)
    }

    fn dst(&mut self, i: usize, ins: &Instruction) -> Result<DstOp, EmuError> {
        let d: &Dst = ins
            .dst
            .as_ref()
            .ok_or_else(|| malformed(i, "missing destination"))?;
        let idx = d.reg.index;
        let (row, output) = match d.reg.file {
            RegFile::Temp if idx < TEMPS => (self.temp_row[idx as usize], false),
            RegFile::ColorOut if idx < 4 => {
                self.outputs |= 1 << idx;
                (self.layout.output + 4 * idx as u16, true)
            }
            RegFile::DepthOut => {
                self.outputs |= 1 << 4;
                (self.layout.output + 16, true)
            }
            // setp's p0: the row is unused, p0 lives in lane masks.
            RegFile::Predicate if ins.op == Opcode::Setp => (0, false),
            // texkill reads its "destination".
            RegFile::Input | RegFile::Texture if ins.op == Opcode::TexKill => {
                let v = slot(self.profile, d.reg.file, idx)
                    .ok_or_else(|| malformed(i, format!("{} is no input here", d.reg)))?;
                self.inputs |= 1 << v;
                (self.layout.input + 4 * v as u16, false)
            }
            _ => return Err(malformed(i, format!("{} cannot be written here", d.reg))),
        };
        if ins.op == Opcode::Setp && d.reg.file != RegFile::Predicate {
            return Err(malformed(i, "setp must write p0"));
        }
        let mut flags = d.mask.0 & 15;
        if ins.sat {
            flags |= DstOp::SAT;
        }
        if output {
            flags |= DstOp::OUTPUT;
        }
        let mut pswz = pack_swizzle(Swizzle::IDENTITY);
        if let Some(p) = ins.predicate {
            flags |= DstOp::PRED;
            if p.negate {
                flags |= DstOp::PRED_NOT;
            }
            pswz = pack_swizzle(p.swizzle);
        }
        Ok(DstOp { row, flags, pswz })
    }

    fn target(&self, i: usize, want: &[Opcode], ins: &[Instruction]) -> Result<Pc, EmuError> {
        let t = self
            .info
            .matching
            .get(i)
            .copied()
            .flatten()
            .ok_or_else(|| malformed(i, "block has no matching instruction"))?;
        match ins.get(t as usize) {
            Some(m) if want.contains(&m.op) => Ok(Pc::new(t)),
            _ => Err(malformed(i, "block matches the wrong instruction")),
        }
    }

    fn label(&self, i: usize, s: Option<&Src>) -> Result<Pc, EmuError> {
        let s = s
            .filter(|s| s.reg.file == RegFile::Label)
            .ok_or_else(|| malformed(i, "missing label operand"))?;
        let at = self
            .info
            .labels
            .get(&s.reg.index)
            .copied()
            .filter(|&at| self.ins.get(at as usize).map(|x| x.op) == Some(Opcode::Label))
            .ok_or_else(|| malformed(i, format!("label l{} is not defined", s.reg.index)))?;
        Ok(Pc::new(at + 1))
    }

    /// The gradient site of instruction `i`: one per source statement, shared
    /// by its REPEAT_BLOCK copies.
    fn site(&mut self, i: usize, x: &Instruction) -> Result<u16, EmuError> {
        if let Some(&k) = self.site_of_span.get(&x.origin.span) {
            return Ok(k);
        }
        let k = u16::try_from(self.sites.len())
            .ok()
            .filter(|&k| k != u16::MAX)
            .ok_or_else(|| malformed(i, "too many gradient instructions"))?;
        let sampler = x
            .src
            .iter()
            .find(|s| s.reg.file == RegFile::Sampler)
            .map(|s| s.reg.index);
        self.sites.push(GradientSite {
            instruction: i,
            span: x.origin.span,
            op: x.op,
            sampler,
            temp_source: x.src.first().is_some_and(|s| s.reg.file == RegFile::Temp),
            quads: 0,
            divergent_quads: 0,
            executions: 0,
            divergent_executions: 0,
            lod: None,
        });
        self.site_of_span.insert(x.origin.span, k);
        Ok(k)
    }

    /// The micro-op of instruction `i`, one method per instruction family.
    fn op(&mut self, i: usize, x: &Instruction) -> Result<Op, EmuError> {
        match x.op {
            Opcode::Nop => Ok(Op::Nop),
            Opcode::Mov
            | Opcode::Rcp
            | Opcode::Rsq
            | Opcode::Exp
            | Opcode::Log
            | Opcode::Frc
            | Opcode::Abs
            | Opcode::Nrm
            | Opcode::SinCos
            | Opcode::Dsx
            | Opcode::Dsy => self.unary(i, x),
            Opcode::Add
            | Opcode::Sub
            | Opcode::Mul
            | Opcode::Dp3
            | Opcode::Dp4
            | Opcode::Min
            | Opcode::Max
            | Opcode::Pow
            | Opcode::Crs => self.binary(i, x),
            Opcode::M4x4 | Opcode::M4x3 | Opcode::M3x4 | Opcode::M3x3 | Opcode::M3x2 => {
                self.matrix(i, x)
            }
            Opcode::Mad | Opcode::Lrp | Opcode::Cmp | Opcode::Dp2Add => self.ternary(i, x),
            Opcode::TexKill => {
                let d = self.dst(i, x)?;
                if d.output() {
                    return Err(malformed(i, "texkill of an output register"));
                }
                Ok(Op::TexKill { d })
            }
            Opcode::TexLd | Opcode::TexLdP | Opcode::TexLdB | Opcode::TexLdL | Opcode::TexLdD => {
                self.texture(i, x)
            }
            Opcode::Setp => {
                let d = self.dst(i, x)?;
                let a = self.src_at(i, x, 0)?;
                let s1 = self.src_at(i, x, 1)?;
                let cmp = x
                    .compare
                    .ok_or_else(|| malformed(i, "setp without comparison"))?;
                Ok(Op::Setp { d, a, b: s1, cmp })
            }
            Opcode::If | Opcode::Ifc | Opcode::Else | Opcode::EndIf => self.branch(i, x),
            Opcode::Rep | Opcode::Loop | Opcode::EndRep | Opcode::EndLoop => self.looping(i, x),
            Opcode::Break | Opcode::BreakC | Opcode::BreakP => self.breaking(i, x),
            Opcode::Call | Opcode::CallNz | Opcode::Ret | Opcode::Label => self.subroutine(i, x),
            Opcode::Def | Opcode::DefI | Opcode::DefB | Opcode::Dcl => Err(malformed(
                i,
                "declarations belong in Program's lists, not in instructions",
            )),
            Opcode::Mova
            | Opcode::Lit
            | Opcode::Dst
            | Opcode::Expp
            | Opcode::Logp
            | Opcode::Slt
            | Opcode::Sge
            | Opcode::Sgn => Err(malformed(
                i,
                "a vertex-shader instruction: the emulator runs ps_3_0",
            )),
            Opcode::Tex
            | Opcode::TexCoord
            | Opcode::TexCrd
            | Opcode::TexBem
            | Opcode::TexBemL
            | Opcode::TexReg2Ar
            | Opcode::TexReg2Gb
            | Opcode::TexReg2Rgb
            | Opcode::TexM3x2Pad
            | Opcode::TexM3x2Tex
            | Opcode::TexM3x2Depth
            | Opcode::TexM3x3Pad
            | Opcode::TexM3x3Tex
            | Opcode::TexM3x3Spec
            | Opcode::TexM3x3VSpec
            | Opcode::TexM3x3
            | Opcode::TexDp3
            | Opcode::TexDp3Tex
            | Opcode::TexDepth
            | Opcode::Bem
            | Opcode::Phase
            | Opcode::Cnd => Err(malformed(
                i,
                "a ps_1_x instruction: ps_1_x runs as its lowering (`core/ps1/run.rs`)",
            )),
        }
    }

    /// One source: `mov`, `rcp`, `rsq`, `exp`, `log`, `frc`, `abs`, `nrm`,
    /// `sincos`, `dsx`, `dsy`.
    fn unary(&mut self, i: usize, x: &Instruction) -> Result<Op, EmuError> {
        let d = self.dst(i, x)?;
        let a = self.src_at(i, x, 0)?;
        Ok(match x.op {
            Opcode::Mov => Op::Mov { d, a },
            Opcode::Rcp => Op::Rcp { d, a },
            Opcode::Rsq => Op::Rsq { d, a },
            Opcode::Exp => Op::Exp { d, a },
            Opcode::Log => Op::Log { d, a },
            Opcode::Frc => Op::Frc { d, a },
            Opcode::Abs => Op::Abs { d, a },
            Opcode::Nrm => Op::Nrm { d, a },
            Opcode::SinCos => Op::SinCos { d, a },
            Opcode::Dsx => Op::Dsx {
                d,
                a,
                site: self.site(i, x)?,
            },
            _ => Op::Dsy {
                d,
                a,
                site: self.site(i, x)?,
            },
        })
    }

    /// Two sources: `add`, `sub`, `mul`, `dp3`, `dp4`, `min`, `max`, `pow`,
    /// `crs`.
    fn binary(&mut self, i: usize, x: &Instruction) -> Result<Op, EmuError> {
        let d = self.dst(i, x)?;
        let a = self.src_at(i, x, 0)?;
        let s1 = self.src_at(i, x, 1)?;
        Ok(match x.op {
            Opcode::Add => Op::Add { d, a, b: s1 },
            Opcode::Sub => Op::Sub { d, a, b: s1 },
            Opcode::Mul => Op::Mul { d, a, b: s1 },
            Opcode::Dp3 => Op::Dp3 { d, a, b: s1 },
            Opcode::Dp4 => Op::Dp4 { d, a, b: s1 },
            Opcode::Min => Op::Min { d, a, b: s1 },
            Opcode::Max => Op::Max { d, a, b: s1 },
            Opcode::Pow => Op::Pow { d, a, b: s1 },
            _ => Op::Crs { d, a, b: s1 },
        })
    }

    /// `m4x4` … `m3x2`: the matrix operand's rows must all exist.
    fn matrix(&mut self, i: usize, x: &Instruction) -> Result<Op, EmuError> {
        let (rows, dims) = matrix_rows(x.op).unwrap_or((4, 4));
        let d = self.dst(i, x)?;
        let a = self.src_at(i, x, 0)?;
        let m = operand(i, x, 1)?;
        if m.relative.is_some() {
            return Err(malformed(i, "relative matrix operand"));
        }
        let last = m.reg.index + rows as u32 - 1;
        let exists = match m.reg.file {
            RegFile::Temp => last < TEMPS,
            RegFile::Const => last < CONSTS,
            // Every row an input of the same file (t# rows are not v#).
            RegFile::Input | RegFile::Texture => slot(self.profile, m.reg.file, last).is_some(),
            _ => false,
        };
        if !exists {
            return Err(malformed(
                i,
                format!("matrix rows {}..+{} do not exist", m.reg, rows),
            ));
        }
        let s1 = self.src(i, m)?;
        Ok(Op::Mat {
            d,
            a,
            b: s1,
            n: rows,
            dims,
        })
    }

    /// Three sources: `mad`, `lrp`, `cmp`, `dp2add`.
    fn ternary(&mut self, i: usize, x: &Instruction) -> Result<Op, EmuError> {
        let d = self.dst(i, x)?;
        let a = self.src_at(i, x, 0)?;
        let s1 = self.src_at(i, x, 1)?;
        let c = self.src_at(i, x, 2)?;
        Ok(match x.op {
            Opcode::Mad => Op::Mad { d, a, b: s1, c },
            Opcode::Lrp => Op::Lrp { d, a, b: s1, c },
            Opcode::Cmp => Op::Cmp { d, a, b: s1, c },
            _ => Op::Dp2Add { d, a, b: s1, c },
        })
    }

    /// The texld family: a declared sampler, then gradients (`texldd`) or a
    /// gradient site (all but `texldl`).
    fn texture(&mut self, i: usize, x: &Instruction) -> Result<Op, EmuError> {
        let d = self.dst(i, x)?;
        let a = self.src_at(i, x, 0)?;
        let sv = operand(i, x, 1)?;
        if sv.reg.file != RegFile::Sampler || sv.reg.index >= 16 {
            return Err(malformed(i, "expected a sampler s# as second operand"));
        }
        if self.samplers[sv.reg.index as usize].is_none() {
            return Err(EmuError::MissingSamplerDecl {
                index: i,
                sampler: sv.reg.index,
            });
        }
        let s = SamplerOp {
            index: sv.reg.index as u8,
            swz: pack_swizzle(sv.swizzle),
        };
        match x.op {
            Opcode::TexLdD => {
                let dx = self.src_at(i, x, 2)?;
                let dy = self.src_at(i, x, 3)?;
                let g =
                    u16::try_from(self.grads.len()).map_err(|_| malformed(i, "too many texldd"))?;
                self.grads.push((dx, dy));
                Ok(Op::TexD { d, a, s, grads: g })
            }
            op => {
                let kind = match op {
                    Opcode::TexLd => TexKind::Ld,
                    Opcode::TexLdP => TexKind::LdP,
                    Opcode::TexLdB => TexKind::LdB,
                    _ => TexKind::LdL,
                };
                let site = if kind == TexKind::LdL {
                    u16::MAX
                } else {
                    self.site(i, x)?
                };
                Ok(Op::Tex {
                    d,
                    a,
                    s,
                    kind,
                    site,
                })
            }
        }
    }

    /// `if`, `if_comp`, `else`, `endif`: jumps to the matching instruction.
    fn branch(&mut self, i: usize, x: &Instruction) -> Result<Op, EmuError> {
        let ins = self.ins;
        Ok(match x.op {
            Opcode::If => Op::If {
                cond: cond(i, x.src.first())?,
                target: self.target(i, &[Opcode::Else, Opcode::EndIf], ins)?,
            },
            Opcode::Ifc => Op::Ifc {
                cmp: x
                    .compare
                    .ok_or_else(|| malformed(i, "if_comp without comparison"))?,
                a: self.src_at(i, x, 0)?,
                b: self.src_at(i, x, 1)?,
                target: self.target(i, &[Opcode::Else, Opcode::EndIf], ins)?,
            },
            Opcode::Else => Op::Else {
                target: self.target(i, &[Opcode::EndIf], ins)?,
            },
            _ => Op::EndIf,
        })
    }

    /// `rep`, `loop` and their ends: the loop integers used, the open-loop
    /// count and the matching instruction.
    fn looping(&mut self, i: usize, x: &Instruction) -> Result<Op, EmuError> {
        let ins = self.ins;
        Ok(match x.op {
            Opcode::Rep => {
                self.open_loops += 1;
                let int = int_reg(i, x.src.first())?;
                self.rep_ints |= 1 << int;
                Op::Rep {
                    int,
                    end: self.target(i, &[Opcode::EndRep], ins)?,
                }
            }
            Opcode::Loop => {
                self.open_loops += 1;
                let int = x
                    .src
                    .iter()
                    .find(|s| s.reg.file == RegFile::ConstInt)
                    .ok_or_else(|| malformed(i, "loop without i#"))?;
                let int = int_reg(i, Some(int))?;
                self.loop_ints |= 1 << int;
                Op::Loop {
                    int,
                    end: self.target(i, &[Opcode::EndLoop], ins)?,
                }
            }
            _ => {
                self.open_loops = self.open_loops.saturating_sub(1);
                let want = if x.op == Opcode::EndRep {
                    Opcode::Rep
                } else {
                    Opcode::Loop
                };
                let start = self.target(i, &[want], ins)?;
                if x.op == Opcode::EndRep {
                    Op::EndRep { start }
                } else {
                    Op::EndLoop { start }
                }
            }
        })
    }

    /// `break`, `break_comp`, `breakp`: only inside a loop.
    fn breaking(&mut self, i: usize, x: &Instruction) -> Result<Op, EmuError> {
        if self.open_loops == 0 {
            return Err(malformed(i, "break outside rep/loop"));
        }
        Ok(match x.op {
            Opcode::Break => Op::Break,
            Opcode::BreakC => Op::BreakC {
                cmp: x
                    .compare
                    .ok_or_else(|| malformed(i, "break_comp without comparison"))?,
                a: self.src_at(i, x, 0)?,
                b: self.src_at(i, x, 1)?,
            },
            _ => match cond(i, x.src.first())? {
                Cond::Pred { chan, not } => Op::BreakP { chan, not },
                Cond::Bool { .. } => return Err(malformed(i, "breakp needs p0")),
            },
        })
    }

    /// `call`, `callnz`, `ret`, `label` (which closes every lexical loop).
    fn subroutine(&mut self, i: usize, x: &Instruction) -> Result<Op, EmuError> {
        Ok(match x.op {
            Opcode::Call => Op::Call {
                target: self.label(i, x.src.first())?,
            },
            Opcode::CallNz => Op::CallNz {
                target: self.label(i, x.src.first())?,
                cond: cond(i, x.src.get(1))?,
            },
            Opcode::Ret => Op::Ret,
            _ => {
                self.open_loops = 0;
                Op::Label
            }
        })
    }
}

fn cond(i: usize, s: Option<&Src>) -> Result<Cond, EmuError> {
    let s = s.ok_or_else(|| malformed(i, "missing condition"))?;
    let not = s.modifier == SrcMod::Not;
    match s.reg.file {
        RegFile::ConstBool if s.reg.index < 16 => Ok(Cond::Bool {
            index: s.reg.index as u8,
            not,
        }),
        RegFile::Predicate => Ok(Cond::Pred {
            chan: s.swizzle.0[0] & 3,
            not,
        }),
        _ => Err(malformed(i, format!("{} is not a condition", s.reg))),
    }
}

fn int_reg(i: usize, s: Option<&Src>) -> Result<u8, EmuError> {
    match s {
        Some(s) if s.reg.file == RegFile::ConstInt && s.reg.index < 16 => Ok(s.reg.index as u8),
        _ => Err(malformed(i, "expected an integer constant register i#")),
    }
}

/// Declared sampler types by `s#`.
fn declared_samplers(program: &Program) -> [Option<SamplerType>; 16] {
    let mut samplers = [None; 16];
    for d in &program.samplers {
        if d.index < 16 {
            samplers[d.index as usize] = Some(d.ty);
        }
    }
    samplers
}

/// The input slots declared by `dcl` (bit per slot).
fn declared_inputs(program: &Program) -> u16 {
    let mut declared = 0u16;
    for d in &program.inputs {
        if let Some(v) = slot(program.profile, d.reg.file, d.reg.index) {
            declared |= 1 << v;
        }
    }
    declared
}

/// Compiles a validated shader into micro-ops.
///
/// The IR has been validated, so errors here mean the IR and its [`Info`] do
/// not agree (or use something the emulator cannot represent); they are
/// reported as [`EmuError::Malformed`] / [`EmuError::MissingSamplerDecl`],
/// never as panics. Each micro-op charges its instruction's slots under
/// Microsoft's table (the default [`SlotTable`]), the table the cost model's
/// executed counts use unless told otherwise; [`compile_under`] takes the other.
pub fn compile(shader: &Shader) -> Result<Compiled, EmuError> {
    compile_under(shader, SlotTable::default())
}

/// [`compile`], each micro-op charging its instruction's slots under `table`.
pub fn compile_under(shader: &Shader, table: SlotTable) -> Result<Compiled, EmuError> {
    let shader = shader.runnable().map_err(|why| EmuError::Refused {
        profile: shader.program().profile,
        reason: why.to_string(),
    })?;
    let program = shader.program();
    let pixel = program.profile.stage() == crate::core::profile::Stage::Pixel;
    if !program.profile.runs() || !pixel {
        return Err(EmuError::NotRun {
            profile: program.profile,
        });
    }
    let info = shader.info();
    let ins = shader.instructions();
    let n = ins.len();
    if info.slots.len() != n || info.matching.len() != n {
        return Err(malformed(
            0,
            "Info does not describe every instruction (slots/matching length)",
        ));
    }
    if n >= u32::MAX as usize / 2 {
        return Err(malformed(0, "program too long"));
    }

    let rows = assign_rows(&usage(ins)?)?;
    let mut b = Builder {
        info,
        profile: program.profile,
        ins,
        layout: rows.layout,
        temp_row: rows.temp_row,
        const_row: rows.const_row,
        reads_al: false,
        outputs: 0,
        inputs: declared_inputs(program),
        samplers: declared_samplers(program),
        grads: Vec::new(),
        sites: Vec::new(),
        site_of_span: HashMap::new(),
        open_loops: 0,
        rep_ints: 0,
        loop_ints: 0,
    };

    // Pass 2: ops, then the end sentinel.
    let mut ops = Vec::with_capacity(n + 1);
    for (i, x) in ins.iter().enumerate() {
        let cost = info.slots(i, table);
        let slots =
            u8::try_from(cost).map_err(|_| malformed(i, format!("slot cost {cost} too large")))?;
        let op = b.op(i, x)?;
        ops.push(MicroOp { op, slots });
    }
    ops.push(MicroOp {
        op: Op::Label,
        slots: 0,
    });

    let float_defs = program
        .float_defs
        .iter()
        .filter(|d| d.index < CONSTS)
        .map(|d| (d.index, d.value))
        .collect();
    let int_defs = program
        .int_defs
        .iter()
        .filter(|d| d.index < 16)
        .map(|d| (d.index, d.value))
        .collect();
    let bool_defs = program
        .bool_defs
        .iter()
        .filter(|d| d.index < 16)
        .map(|d| (d.index, d.value))
        .collect();

    Ok(Compiled {
        ops,
        grads: b.grads,
        sites: b.sites,
        layout: b.layout,
        float_defs,
        int_defs,
        bool_defs,
        samplers: b.samplers,
        inputs: b.inputs,
        clamped: pixel_inputs::clamped(program.profile),
        profile: program.profile,
        reads_al: b.reads_al,
        outputs: b.outputs,
        rep_ints: b.rep_ints,
        loop_ints: b.loop_ints,
    })
}
