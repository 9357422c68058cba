//! The ps_3_0 instruction set as one table: the single source of truth.
//! The rows of the other profiles sit in the same table (the vertex-shader
//! instructions, ps_1_x's texture-addressing family), each with the profiles
//! that have it ([`Opcode::profiles`]).
//!
//! The parser looks mnemonics up here, the validator reads each row's operand
//! shape and rules, the cost model reads the slot columns, the emulator
//! dispatches on [`Opcode`] and the writer prints [`OpInfo::mnemonic`]. Adding
//! an instruction means one row in [`TABLE`] plus its semantics in the emulator.
//!
//! # Two slot tables
//!
//! Every row carries two slot counts, and [`SlotTable`] names them:
//!
//! * **Microsoft's count** ([`OpInfo::fxc_slots`], [`SlotTable::Fxc`], the
//!   default everywhere): what Microsoft's tools print, the
//!   `// approximately N instruction slots used (T texture, A arithmetic)`
//!   line that `D3DDisassemble` (and so `fxc`) ends a listing with. It was
//!   measured with `d3dcompiler_47.dll`, one instruction added to a shader at
//!   a time, on 2D, cube and volume samplers, predicated or not, inside
//!   `if`/`rep`/`loop` and in subroutines; a few hundred shaders compiled by
//!   Microsoft's HLSL compiler confirm it. Users compare ps30's number with
//!   this one.
//! * **The documented table** ([`OpInfo::slots`], [`OpInfo::cube_slots`],
//!   [`SlotTable::Documented`]): the "Instruction slots" column of the ps_3_0
//!   instruction page of Microsoft's documentation
//!   (learn.microsoft.com/windows/win32/direct3dhlsl/
//!   dx9-graphics-reference-asm-ps-instructions-ps-3-0).
//!
//! They differ on seven rows, the documented table always the higher: `nop`
//! (1, Microsoft's tools 0), `lrp` (2, 1), `texkill` (2, 1), `texldp` (3, 1),
//! `texldb` (6, 1), and on a cube sampler `texld` (4, 1) and `texldl` (5, 2)
//! — Microsoft's tools ignore the sampler type. Every other row, flow control
//! included, is the same in both (`if b#` costs 3 in both, although the
//! `if bool` page says "one instruction slot").
//!
//! # The counting rule
//!
//! Both tables count the same way, and it is additive: a shader's slots are
//! the sum over every instruction token — main, every subroutine body, each
//! `ret` (the one ending main too, when the shader has one: Microsoft's HLSL
//! compiler never writes it) — of the row's count, plus one for a predicated
//! instruction (the `setp_comp` page; Microsoft's tools count that slot as
//! arithmetic). `def`, `defi`, `defb`, `dcl` and `label` cost nothing. No
//! instruction costs more inside flow control or a subroutine, and nothing
//! depends on neighbours. [`OpInfo::count`] is that rule for one instruction;
//! [`SlotCount`] adds them up and splits them into texture and arithmetic
//! slots as the listing does (see [`OpInfo::count`]).

use crate::core::profile::{Profile, ProfileSet};
use std::fmt;

/// Every ps_3_0 operation ps30 knows. Declarations and constant definitions
/// are included so that one table covers every mnemonic a ps_3_0 file may use.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Opcode {
    /// `nop`: no operation.
    Nop,
    /// `mov`: copy.
    Mov,
    /// `add`: a + b.
    Add,
    /// `sub`: a - b.
    Sub,
    /// `mad`: a * b + c.
    Mad,
    /// `mul`: a * b.
    Mul,
    /// `rcp`: 1 / x (x = 0 gives infinity).
    Rcp,
    /// `rsq`: 1 / sqrt(|x|) (x = 0 gives infinity).
    Rsq,
    /// `dp3`: 3-component dot product.
    Dp3,
    /// `dp4`: 4-component dot product.
    Dp4,
    /// `min`: component-wise minimum.
    Min,
    /// `max`: component-wise maximum.
    Max,
    /// `exp`: 2^x.
    Exp,
    /// `log`: log2(|x|) (x = 0 gives -FLT_MAX).
    Log,
    /// `lrp`: a * b + (1 - a) * c.
    Lrp,
    /// `frc`: x - floor(x).
    Frc,
    /// `m4x4`: four dp4 with src1..src1+3.
    M4x4,
    /// `m4x3`: three dp4 with src1..src1+2.
    M4x3,
    /// `m3x4`: four dp3 with src1..src1+3.
    M3x4,
    /// `m3x3`: three dp3 with src1..src1+2.
    M3x3,
    /// `m3x2`: two dp3 with src1..src1+1.
    M3x2,
    /// `pow`: |a|^b.
    Pow,
    /// `crs`: cross product.
    Crs,
    /// `abs`: |x|.
    Abs,
    /// `nrm`: normalise xyz (zero length scales by FLT_MAX).
    Nrm,
    /// `sincos`: x = cos, y = sin.
    SinCos,
    /// `cmp`: a >= 0 ? b : c.
    Cmp,
    /// `dp2add`: a.x*b.x + a.y*b.y + c.
    Dp2Add,
    /// `dsx`: screen-space x derivative.
    Dsx,
    /// `dsy`: screen-space y derivative.
    Dsy,
    /// `texkill`: discard the pixel if any of x, y, z < 0.
    TexKill,
    /// `texld`: sample with implicit gradients.
    TexLd,
    /// `texldp`: sample after dividing by w.
    TexLdP,
    /// `texldb`: sample with LOD bias w.
    TexLdB,
    /// `texldl`: sample at explicit LOD w.
    TexLdL,
    /// `texldd`: sample with explicit gradients.
    TexLdD,
    /// `setp`: p0.c = a.c `op` b.c.
    Setp,
    /// `call`: call a subroutine.
    Call,
    /// `callnz`: call if the condition holds.
    CallNz,
    /// `loop`: loop i.x times, aL from i.y by i.z.
    Loop,
    /// `ret`: return (ends main).
    Ret,
    /// `endloop`: end of loop.
    EndLoop,
    /// `label`: subroutine entry.
    Label,
    /// `rep`: repeat i.x times.
    Rep,
    /// `endrep`: end of rep.
    EndRep,
    /// `if`: branch on b# or p0.c.
    If,
    /// `if`: branch on a comparison.
    Ifc,
    /// `else`: else branch.
    Else,
    /// `endif`: end of if.
    EndIf,
    /// `break`: leave the innermost rep/loop.
    Break,
    /// `break`: break if the comparison holds.
    BreakC,
    /// `breakp`: break if p0.c holds.
    BreakP,
    /// `def`: define a float constant.
    Def,
    /// `defi`: define an integer constant.
    DefI,
    /// `defb`: define a boolean constant.
    DefB,
    /// `dcl`: declare an input or sampler.
    Dcl,
    /// `mova`: a0 = round(x) (vertex shaders).
    Mova,
    /// `lit`: the lighting coefficients (vertex shaders).
    Lit,
    /// `dst`: the distance vector (vertex shaders).
    Dst,
    /// `expp`: 2^x at partial precision (vertex shaders).
    Expp,
    /// `logp`: log2(|x|) at partial precision (vertex shaders).
    Logp,
    /// `slt`: 1 where a < b, else 0 (vertex shaders).
    Slt,
    /// `sge`: 1 where a >= b, else 0 (vertex shaders).
    Sge,
    /// `sgn`: the sign, -1, 0 or 1 (vertex shaders).
    Sgn,
    // The ps_1_x instructions (their rows say which of ps_1_1–ps_1_4).
    /// `tex`: sample stage # at its texture coordinates into `t#` (ps_1_1–ps_1_3).
    Tex,
    /// `texcoord`: a texture coordinate as a colour into `t#` (ps_1_1–ps_1_3).
    TexCoord,
    /// `texcrd`: a texture coordinate into `r#` (ps_1_4).
    TexCrd,
    /// `texbem`: bump-environment-mapped sample (ps_1_1–ps_1_3).
    TexBem,
    /// `texbeml`: `texbem` with luminance (ps_1_1–ps_1_3).
    TexBemL,
    /// `texreg2ar`: sample at the source's alpha and red (ps_1_1–ps_1_3).
    TexReg2Ar,
    /// `texreg2gb`: sample at the source's green and blue (ps_1_1–ps_1_3).
    TexReg2Gb,
    /// `texreg2rgb`: sample at the source's red, green, blue (ps_1_2, ps_1_3).
    TexReg2Rgb,
    /// `texm3x2pad`: first row of a 3×2 matrix multiply (ps_1_1–ps_1_3).
    TexM3x2Pad,
    /// `texm3x2tex`: last row of a 3×2 multiply, then sample (ps_1_1–ps_1_3).
    TexM3x2Tex,
    /// `texm3x2depth`: last row of a 3×2 multiply as depth (ps_1_3).
    TexM3x2Depth,
    /// `texm3x3pad`: a row of a 3×3 matrix multiply (ps_1_1–ps_1_3).
    TexM3x3Pad,
    /// `texm3x3tex`: last row of a 3×3 multiply, then sample (ps_1_1–ps_1_3).
    TexM3x3Tex,
    /// `texm3x3spec`: 3×3 multiply, reflect by a constant eye ray, sample.
    TexM3x3Spec,
    /// `texm3x3vspec`: 3×3 multiply, reflect by the rows' eye ray, sample.
    TexM3x3VSpec,
    /// `texm3x3`: last row of a 3×3 multiply, no sample (ps_1_2, ps_1_3).
    TexM3x3,
    /// `texdp3`: a dot product of a coordinate and a register (ps_1_2, ps_1_3).
    TexDp3,
    /// `texdp3tex`: sample at a dot product (ps_1_2, ps_1_3).
    TexDp3Tex,
    /// `texdepth`: r5's r / g as the pixel's depth (ps_1_4).
    TexDepth,
    /// `bem`: bump-environment transform of a coordinate (ps_1_4).
    Bem,
    /// `phase`: ends ps_1_4's first phase.
    Phase,
    /// `cnd`: a > 0.5 ? b : c.
    Cnd,
}

/// What an instruction is, for accounting and for validation rules.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Class {
    /// Arithmetic on float registers.
    Arithmetic,
    /// Texture sampling or texkill.
    Texture,
    /// Flow control (if, rep, loop, call, break, ret, label, ...).
    Flow,
    /// Declarations and constant definitions: no slots, never executed.
    Declaration,
}

/// The kind of one operand position in an instruction's shape.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Operand {
    /// A destination register with an optional write mask.
    Dst,
    /// A float source register with optional modifiers and swizzle.
    Src,
    /// A float source that must use a replicate swizzle (`.x`, `.y`, ...).
    ScalarSrc,
    /// A sampler register `s#` (no modifiers).
    Sampler,
    /// An integer constant register `i#` (rep, loop).
    IntReg,
    /// The loop counter `aL` as the first operand of `loop`.
    LoopCounter,
    /// A label `l#`.
    Label,
    /// A boolean condition: `[!]b#` or `[!]p0.c`.
    Condition,
    /// The predicate register `p0` (optionally masked) as a destination.
    PredDst,
    /// The texkill operand: a register written like a destination.
    KillSrc,
    /// Four float literals (`def`).
    FloatLits,
    /// Four integer literals (`defi`).
    IntLits,
    /// One boolean literal (`defb`).
    BoolLit,
}

/// One row of the instruction table.
#[derive(Clone, Copy, Debug)]
pub struct OpInfo {
    /// The operation.
    pub op: Opcode,
    /// Canonical lower-case mnemonic as the writer prints it.
    pub mnemonic: &'static str,
    /// The D3DSIO_* opcode of the instruction token (d3d9types.h), bits 0–15.
    pub code: u16,
    /// The opcode-specific control (bits 16–23) that selects this row among
    /// rows sharing a code: 1 for `texldp`, 2 for `texldb`, else 0 (the
    /// comparison of `ifc`, `breakc` and `setp` goes there too, from
    /// [`Compare::code`]).
    pub control: u8,
    /// Instruction slots in the documented table (the ps_3_0 instruction
    /// page's column; [`SlotTable::Documented`]).
    pub slots: u32,
    /// The documented slots when the sampler operand is a cube map, if
    /// different.
    pub cube_slots: Option<u32>,
    /// Instruction slots as Microsoft's tools count them ([`SlotTable::Fxc`]):
    /// the change in the `// approximately N instruction slots used` line of
    /// `D3DDisassemble`'s listing when one such instruction is added. It
    /// differs from the documented table for `nop`, `lrp`, `texkill`,
    /// `texldp`, `texldb` and cube samplers, and ignores the sampler type.
    pub fxc_slots: u32,
    /// What kind of instruction it is.
    pub class: Class,
    /// Operand shape, in order.
    pub operands: &'static [Operand],
    /// Whether `_sat` is allowed.
    pub allows_sat: bool,
    /// Whether the instruction takes a comparison suffix (`_gt` ...). `Some(true)`:
    /// required; `Some(false)`: never; `None` is not used.
    pub comparison: bool,
    /// Whether a `(p0)` predicate prefix is allowed (arithmetic and texture).
    pub predicable: bool,
    /// One-line meaning, printed by `ps30 check --explain` style output and docs.
    pub summary: &'static str,
}

/// Which per-instruction slot table a count uses (see the module docs).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum SlotTable {
    /// Microsoft's count: what `D3DDisassemble` and `fxc` print.
    #[default]
    Fxc,
    /// The ps_3_0 instruction page's "Instruction slots" column.
    Documented,
}

impl SlotTable {
    /// Both tables, Microsoft's first.
    pub const ALL: [SlotTable; 2] = [SlotTable::Fxc, SlotTable::Documented];

    /// The name `--slots` takes and JSON prints (`fxc`, `documented`).
    pub fn name(self) -> &'static str {
        match self {
            SlotTable::Fxc => "fxc",
            SlotTable::Documented => "documented",
        }
    }

    /// The table of a name, if it is one.
    pub fn from_name(s: &str) -> Option<SlotTable> {
        SlotTable::ALL.into_iter().find(|t| t.name() == s)
    }

    /// How output names the table in prose.
    pub fn title(self) -> &'static str {
        match self {
            SlotTable::Fxc => "Microsoft's count",
            SlotTable::Documented => "documented table",
        }
    }
}

impl fmt::Display for SlotTable {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// Slots split as Microsoft's listing splits them: texture and arithmetic
/// (flow control counts as arithmetic). Counts add up instruction by
/// instruction (the module's counting rule).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, serde::Serialize)]
pub struct SlotCount {
    /// Texture slots: the sampling part of the texld family.
    pub texture: u32,
    /// Every other slot.
    pub arithmetic: u32,
}

impl SlotCount {
    /// Texture plus arithmetic.
    pub fn total(self) -> u32 {
        self.texture + self.arithmetic
    }

    /// The sum of two counts.
    pub fn plus(self, o: SlotCount) -> SlotCount {
        SlotCount {
            texture: self.texture + o.texture,
            arithmetic: self.arithmetic + o.arithmetic,
        }
    }

    /// The slot line `D3DDisassemble` ends a listing with, for this count
    /// under Microsoft's table: `// approximately N instruction slots used`,
    /// "slot" for exactly one, and ` (T texture, A arithmetic)` only when
    /// there is a texture slot.
    pub fn listing_line(self) -> String {
        let n = self.total();
        let noun = if n == 1 { "slot" } else { "slots" };
        let mut s = format!("// approximately {n} instruction {noun} used");
        if self.texture > 0 {
            s.push_str(&format!(
                " ({} texture, {} arithmetic)",
                self.texture, self.arithmetic
            ));
        }
        s
    }
}

impl std::iter::Sum for SlotCount {
    fn sum<I: Iterator<Item = SlotCount>>(iter: I) -> SlotCount {
        iter.fold(SlotCount::default(), SlotCount::plus)
    }
}

impl OpInfo {
    /// The slots of one instruction of this row under `table`, split into
    /// texture and arithmetic: the row's count (the documented table's cube
    /// count when `cube`, a sampler declared a cube map; Microsoft's tools
    /// ignore it), one more arithmetic slot when `predicated`. The texld
    /// family counts its sampling as texture slots — under Microsoft's table
    /// `texld`, `texldp` and `texldb` 1, `texldl` 2, `texldd` 1 (its other 2
    /// are arithmetic), as the listing's split shows; under the documented
    /// table the whole row. `texkill` is arithmetic in Microsoft's split and
    /// texture in the documented class. This is the one place either table
    /// is read.
    pub fn count(&self, table: SlotTable, cube: bool, predicated: bool) -> SlotCount {
        let (base, texture) = match table {
            SlotTable::Fxc => {
                let texture = match self.op {
                    Opcode::TexLd | Opcode::TexLdP | Opcode::TexLdB | Opcode::TexLdD => 1,
                    Opcode::TexLdL => 2,
                    // ps_1_x: every texture-addressing instruction is one
                    // texture slot but texdepth (arithmetic, as texkill).
                    op if op.is_ps1_only() && self.class == Class::Texture => {
                        u32::from(op != Opcode::TexDepth)
                    }
                    _ => 0,
                };
                (self.fxc_slots, texture)
            }
            SlotTable::Documented => {
                let base = match self.cube_slots {
                    Some(c) if cube => c,
                    _ => self.slots,
                };
                (
                    base,
                    if self.class == Class::Texture {
                        base
                    } else {
                        0
                    },
                )
            }
        };
        SlotCount {
            texture,
            arithmetic: base - texture + u32::from(predicated),
        }
    }

    /// The documented table's static slots of one instruction of this row
    /// ([`OpInfo::count`] under [`SlotTable::Documented`], as a total).
    pub fn slots_of(&self, cube: bool, predicated: bool) -> u32 {
        self.count(SlotTable::Documented, cube, predicated).total()
    }

    /// Microsoft's slots of one instruction of this row
    /// ([`OpInfo::count`] under [`SlotTable::Fxc`], as a total).
    pub fn fxc_slots_of(&self, predicated: bool) -> u32 {
        self.count(SlotTable::Fxc, false, predicated).total()
    }

    /// Microsoft's split of one instruction of this row as (texture,
    /// arithmetic) ([`OpInfo::count`] under [`SlotTable::Fxc`]).
    pub fn fxc_split_of(&self, predicated: bool) -> (u32, u32) {
        let c = self.count(SlotTable::Fxc, false, predicated);
        (c.texture, c.arithmetic)
    }
}

use Operand as O;

const DS: &[Operand] = &[O::Dst, O::Src];
const DSS: &[Operand] = &[O::Dst, O::Src, O::Src];
const DSSS: &[Operand] = &[O::Dst, O::Src, O::Src, O::Src];
const DSCALAR: &[Operand] = &[O::Dst, O::ScalarSrc];
const TEX: &[Operand] = &[O::Dst, O::Src, O::Sampler];
const DST: &[Operand] = &[O::Dst];
const NONE: &[Operand] = &[];

macro_rules! row {
    ($op:ident, $m:literal, $code:literal / $control:literal, $slots:expr, $cube:expr, fxc = $fxc:expr, $class:ident, $ops:expr, sat=$sat:literal, cmp=$cmp:literal, pred=$pred:literal, $sum:literal) => {
        OpInfo {
            op: Opcode::$op,
            mnemonic: $m,
            code: $code,
            control: $control,
            slots: $slots,
            cube_slots: $cube,
            fxc_slots: $fxc,
            class: Class::$class,
            operands: $ops,
            allows_sat: $sat,
            comparison: $cmp,
            predicable: $pred,
            summary: $sum,
        }
    };
}

/// The instruction table, one row per operation: mnemonic, D3DSIO_* code /
/// control (d3d9types.h; the bytecode reader and writer take them from
/// here), slots, cube slots, class, operands, modifiers, summary.
#[rustfmt::skip]
pub const TABLE: &[OpInfo] = &[
    row!(Nop, "nop", 0x00/0, 1, None, fxc = 0, Arithmetic, NONE, sat = false, cmp = false, pred = false, "no operation"),
    row!(Mov, "mov", 0x01/0, 1, None, fxc = 1, Arithmetic, DS, sat = true, cmp = false, pred = true, "copy"),
    row!(Add, "add", 0x02/0, 1, None, fxc = 1, Arithmetic, DSS, sat = true, cmp = false, pred = true, "a + b"),
    row!(Sub, "sub", 0x03/0, 1, None, fxc = 1, Arithmetic, DSS, sat = true, cmp = false, pred = true, "a - b"),
    row!(Mad, "mad", 0x04/0, 1, None, fxc = 1, Arithmetic, DSSS, sat = true, cmp = false, pred = true, "a * b + c"),
    row!(Mul, "mul", 0x05/0, 1, None, fxc = 1, Arithmetic, DSS, sat = true, cmp = false, pred = true, "a * b"),
    row!(Rcp, "rcp", 0x06/0, 1, None, fxc = 1, Arithmetic, DSCALAR, sat = true, cmp = false, pred = true, "1 / x (x = 0 gives infinity)"),
    row!(Rsq, "rsq", 0x07/0, 1, None, fxc = 1, Arithmetic, DSCALAR, sat = true, cmp = false, pred = true, "1 / sqrt(|x|) (x = 0 gives infinity)"),
    row!(Dp3, "dp3", 0x08/0, 1, None, fxc = 1, Arithmetic, DSS, sat = true, cmp = false, pred = true, "3-component dot product"),
    row!(Dp4, "dp4", 0x09/0, 1, None, fxc = 1, Arithmetic, DSS, sat = true, cmp = false, pred = true, "4-component dot product"),
    row!(Min, "min", 0x0A/0, 1, None, fxc = 1, Arithmetic, DSS, sat = true, cmp = false, pred = true, "component-wise minimum"),
    row!(Max, "max", 0x0B/0, 1, None, fxc = 1, Arithmetic, DSS, sat = true, cmp = false, pred = true, "component-wise maximum"),
    row!(Exp, "exp", 0x0E/0, 1, None, fxc = 1, Arithmetic, DSCALAR, sat = true, cmp = false, pred = true, "2^x"),
    row!(Log, "log", 0x0F/0, 1, None, fxc = 1, Arithmetic, DSCALAR, sat = true, cmp = false, pred = true, "log2(|x|) (x = 0 gives -FLT_MAX)"),
    row!(Lrp, "lrp", 0x12/0, 2, None, fxc = 1, Arithmetic, DSSS, sat = true, cmp = false, pred = true, "a * b + (1 - a) * c"),
    row!(Frc, "frc", 0x13/0, 1, None, fxc = 1, Arithmetic, DS, sat = false, cmp = false, pred = true, "x - floor(x)"),
    row!(M4x4, "m4x4", 0x14/0, 4, None, fxc = 4, Arithmetic, DSS, sat = true, cmp = false, pred = true, "four dp4 with src1..src1+3"),
    row!(M4x3, "m4x3", 0x15/0, 3, None, fxc = 3, Arithmetic, DSS, sat = true, cmp = false, pred = true, "three dp4 with src1..src1+2"),
    row!(M3x4, "m3x4", 0x16/0, 4, None, fxc = 4, Arithmetic, DSS, sat = true, cmp = false, pred = true, "four dp3 with src1..src1+3"),
    row!(M3x3, "m3x3", 0x17/0, 3, None, fxc = 3, Arithmetic, DSS, sat = true, cmp = false, pred = true, "three dp3 with src1..src1+2"),
    row!(M3x2, "m3x2", 0x18/0, 2, None, fxc = 2, Arithmetic, DSS, sat = true, cmp = false, pred = true, "two dp3 with src1..src1+1"),
    row!(Pow, "pow", 0x20/0, 3, None, fxc = 3, Arithmetic, &[O::Dst, O::ScalarSrc, O::ScalarSrc], sat = true, cmp = false, pred = true, "|a|^b"),
    row!(Crs, "crs", 0x21/0, 2, None, fxc = 2, Arithmetic, DSS, sat = true, cmp = false, pred = true, "cross product"),
    row!(Abs, "abs", 0x23/0, 1, None, fxc = 1, Arithmetic, DS, sat = true, cmp = false, pred = true, "|x|"),
    row!(Nrm, "nrm", 0x24/0, 3, None, fxc = 3, Arithmetic, DS, sat = true, cmp = false, pred = true, "normalise xyz (zero length scales by FLT_MAX)"),
    row!(SinCos, "sincos", 0x25/0, 8, None, fxc = 8, Arithmetic, DSCALAR, sat = false, cmp = false, pred = true, "x = cos, y = sin"),
    row!(Cmp, "cmp", 0x58/0, 1, None, fxc = 1, Arithmetic, DSSS, sat = true, cmp = false, pred = true, "a >= 0 ? b : c"),
    row!(Dp2Add, "dp2add", 0x5A/0, 2, None, fxc = 2, Arithmetic, &[O::Dst, O::Src, O::Src, O::ScalarSrc], sat = true, cmp = false, pred = true, "a.x*b.x + a.y*b.y + c"),
    row!(Dsx, "dsx", 0x5B/0, 2, None, fxc = 2, Arithmetic, DS, sat = true, cmp = false, pred = true, "screen-space x derivative"),
    row!(Dsy, "dsy", 0x5C/0, 2, None, fxc = 2, Arithmetic, DS, sat = true, cmp = false, pred = true, "screen-space y derivative"),
    row!(TexKill, "texkill", 0x41/0, 2, None, fxc = 1, Texture, &[O::KillSrc], sat = false, cmp = false, pred = true, "discard the pixel if any of x, y, z < 0"),
    row!(TexLd, "texld", 0x42/0, 1, Some(4), fxc = 1, Texture, TEX, sat = false, cmp = false, pred = true, "sample with implicit gradients"),
    row!(TexLdP, "texldp", 0x42/1, 3, Some(4), fxc = 1, Texture, TEX, sat = false, cmp = false, pred = true, "sample after dividing by w"),
    row!(TexLdB, "texldb", 0x42/2, 6, None, fxc = 1, Texture, TEX, sat = false, cmp = false, pred = true, "sample with LOD bias w"),
    row!(TexLdL, "texldl", 0x5F/0, 2, Some(5), fxc = 2, Texture, TEX, sat = false, cmp = false, pred = true, "sample at explicit LOD w"),
    row!(TexLdD, "texldd", 0x5D/0, 3, None, fxc = 3, Texture, &[O::Dst, O::Src, O::Sampler, O::Src, O::Src], sat = false, cmp = false, pred = true, "sample with explicit gradients"),
    row!(Setp, "setp", 0x5E/0, 1, None, fxc = 1, Arithmetic, &[O::PredDst, O::Src, O::Src], sat = false, cmp = true, pred = false, "p0.c = a.c <op> b.c"),
    row!(Call, "call", 0x19/0, 2, None, fxc = 2, Flow, &[O::Label], sat = false, cmp = false, pred = false, "call a subroutine"),
    row!(CallNz, "callnz", 0x1A/0, 3, None, fxc = 3, Flow, &[O::Label, O::Condition], sat = false, cmp = false, pred = false, "call if the condition holds"),
    row!(Loop, "loop", 0x1B/0, 3, None, fxc = 3, Flow, &[O::LoopCounter, O::IntReg], sat = false, cmp = false, pred = false, "loop i.x times, aL from i.y by i.z"),
    row!(Ret, "ret", 0x1C/0, 1, None, fxc = 1, Flow, NONE, sat = false, cmp = false, pred = false, "return (ends main)"),
    row!(EndLoop, "endloop", 0x1D/0, 2, None, fxc = 2, Flow, NONE, sat = false, cmp = false, pred = false, "end of loop"),
    row!(Label, "label", 0x1E/0, 0, None, fxc = 0, Flow, &[O::Label], sat = false, cmp = false, pred = false, "subroutine entry"),
    row!(Rep, "rep", 0x26/0, 3, None, fxc = 3, Flow, &[O::IntReg], sat = false, cmp = false, pred = false, "repeat i.x times"),
    row!(EndRep, "endrep", 0x27/0, 2, None, fxc = 2, Flow, NONE, sat = false, cmp = false, pred = false, "end of rep"),
    row!(If, "if", 0x28/0, 3, None, fxc = 3, Flow, &[O::Condition], sat = false, cmp = false, pred = false, "branch on b# or p0.c"),
    row!(Ifc, "if", 0x29/0, 3, None, fxc = 3, Flow, &[O::ScalarSrc, O::ScalarSrc], sat = false, cmp = true, pred = false, "branch on a comparison"),
    row!(Else, "else", 0x2A/0, 1, None, fxc = 1, Flow, NONE, sat = false, cmp = false, pred = false, "else branch"),
    row!(EndIf, "endif", 0x2B/0, 1, None, fxc = 1, Flow, NONE, sat = false, cmp = false, pred = false, "end of if"),
    row!(Break, "break", 0x2C/0, 1, None, fxc = 1, Flow, NONE, sat = false, cmp = false, pred = false, "leave the innermost rep/loop"),
    row!(BreakC, "break", 0x2D/0, 3, None, fxc = 3, Flow, &[O::ScalarSrc, O::ScalarSrc], sat = false, cmp = true, pred = false, "break if the comparison holds"),
    row!(BreakP, "breakp", 0x60/0, 3, None, fxc = 3, Flow, &[O::Condition], sat = false, cmp = false, pred = false, "break if p0.c holds"),
    row!(Def, "def", 0x51/0, 0, None, fxc = 0, Declaration, &[O::Dst, O::FloatLits], sat = false, cmp = false, pred = false, "define a float constant"),
    row!(DefI, "defi", 0x30/0, 0, None, fxc = 0, Declaration, &[O::Dst, O::IntLits], sat = false, cmp = false, pred = false, "define an integer constant"),
    row!(DefB, "defb", 0x2F/0, 0, None, fxc = 0, Declaration, &[O::Dst, O::BoolLit], sat = false, cmp = false, pred = false, "define a boolean constant"),
    row!(Dcl, "dcl", 0x1F/0, 0, None, fxc = 0, Declaration, NONE, sat = false, cmp = false, pred = false, "declare an input or sampler"),
    // The vertex-shader instructions: the documented slots are the vs_2_0
    // instruction page's column; Microsoft's count is 1 for each (measured).
    row!(Mova, "mova", 0x2E/0, 1, None, fxc = 1, Arithmetic, DS, sat = false, cmp = false, pred = true, "a0 = round(x)"),
    row!(Lit, "lit", 0x10/0, 3, None, fxc = 1, Arithmetic, DS, sat = true, cmp = false, pred = true, "lighting coefficients"),
    row!(Dst, "dst", 0x11/0, 1, None, fxc = 1, Arithmetic, DSS, sat = true, cmp = false, pred = true, "distance vector"),
    row!(Expp, "expp", 0x4E/0, 1, None, fxc = 1, Arithmetic, DSCALAR, sat = true, cmp = false, pred = true, "2^x, partial precision"),
    row!(Logp, "logp", 0x4F/0, 1, None, fxc = 1, Arithmetic, DSCALAR, sat = true, cmp = false, pred = true, "log2(|x|), partial precision"),
    row!(Slt, "slt", 0x0C/0, 1, None, fxc = 1, Arithmetic, DSS, sat = true, cmp = false, pred = true, "1 where a < b, else 0"),
    row!(Sge, "sge", 0x0D/0, 1, None, fxc = 1, Arithmetic, DSS, sat = true, cmp = false, pred = true, "1 where a >= b, else 0"),
    row!(Sgn, "sgn", 0x22/0, 3, None, fxc = 1, Arithmetic, DSSS, sat = true, cmp = false, pred = true, "sign: -1, 0 or 1"),
    // The ps_1_x instructions. Microsoft's count is measured (one probe per
    // instruction under tests/oracle/corpus/asm/profiles/ps_1_*); the
    // documented column repeats it, the ps_3_0 page having no such rows.
    // `tex` and ps_1_4's `texld` share 0x42, `texcoord` and `texcrd` 0x40:
    // the profile tells them apart (`Opcode::from_code_in`).
    row!(Tex, "tex", 0x42/0, 1, None, fxc = 1, Texture, DST, sat = false, cmp = false, pred = false, "sample stage # into t#"),
    row!(TexCoord, "texcoord", 0x40/0, 1, None, fxc = 1, Texture, DST, sat = false, cmp = false, pred = false, "texture coordinate # as a colour into t#"),
    row!(TexCrd, "texcrd", 0x40/0, 1, None, fxc = 1, Texture, DS, sat = false, cmp = false, pred = false, "texture coordinate into r#"),
    row!(TexBem, "texbem", 0x43/0, 1, None, fxc = 1, Texture, DS, sat = false, cmp = false, pred = false, "sample at a bump-mapped coordinate"),
    row!(TexBemL, "texbeml", 0x44/0, 1, None, fxc = 1, Texture, DS, sat = false, cmp = false, pred = false, "texbem with luminance"),
    row!(TexReg2Ar, "texreg2ar", 0x45/0, 1, None, fxc = 1, Texture, DS, sat = false, cmp = false, pred = false, "sample at (a, r) of a register"),
    row!(TexReg2Gb, "texreg2gb", 0x46/0, 1, None, fxc = 1, Texture, DS, sat = false, cmp = false, pred = false, "sample at (g, b) of a register"),
    row!(TexReg2Rgb, "texreg2rgb", 0x52/0, 1, None, fxc = 1, Texture, DS, sat = false, cmp = false, pred = false, "sample at (r, g, b) of a register"),
    row!(TexM3x2Pad, "texm3x2pad", 0x47/0, 1, None, fxc = 1, Texture, DS, sat = false, cmp = false, pred = false, "first row of a 3x2 matrix multiply"),
    row!(TexM3x2Tex, "texm3x2tex", 0x48/0, 1, None, fxc = 1, Texture, DS, sat = false, cmp = false, pred = false, "last row of a 3x2 multiply, then sample"),
    row!(TexM3x2Depth, "texm3x2depth", 0x54/0, 1, None, fxc = 1, Texture, DS, sat = false, cmp = false, pred = false, "3x2 multiply as the pixel's depth"),
    row!(TexM3x3Pad, "texm3x3pad", 0x49/0, 1, None, fxc = 1, Texture, DS, sat = false, cmp = false, pred = false, "a row of a 3x3 matrix multiply"),
    row!(TexM3x3Tex, "texm3x3tex", 0x4A/0, 1, None, fxc = 1, Texture, DS, sat = false, cmp = false, pred = false, "last row of a 3x3 multiply, then sample"),
    row!(TexM3x3Spec, "texm3x3spec", 0x4C/0, 1, None, fxc = 1, Texture, DSS, sat = false, cmp = false, pred = false, "3x3 multiply, reflect by a constant eye ray, sample"),
    row!(TexM3x3VSpec, "texm3x3vspec", 0x4D/0, 1, None, fxc = 1, Texture, DS, sat = false, cmp = false, pred = false, "3x3 multiply, reflect by the rows' eye ray, sample"),
    row!(TexM3x3, "texm3x3", 0x56/0, 1, None, fxc = 1, Texture, DS, sat = false, cmp = false, pred = false, "last row of a 3x3 multiply, no sample"),
    row!(TexDp3, "texdp3", 0x55/0, 1, None, fxc = 1, Texture, DS, sat = false, cmp = false, pred = false, "dot product of a coordinate and a register"),
    row!(TexDp3Tex, "texdp3tex", 0x53/0, 1, None, fxc = 1, Texture, DS, sat = false, cmp = false, pred = false, "sample at a dot product"),
    row!(TexDepth, "texdepth", 0x57/0, 1, None, fxc = 1, Texture, DST, sat = false, cmp = false, pred = false, "r5.r / r5.g as the pixel's depth"),
    row!(Bem, "bem", 0x59/0, 1, None, fxc = 1, Arithmetic, DSS, sat = false, cmp = false, pred = false, "bump-environment transform"),
    row!(Phase, "phase", 0xFFFD/0, 0, None, fxc = 0, Declaration, NONE, sat = false, cmp = false, pred = false, "end of the first phase"),
    row!(Cnd, "cnd", 0x50/0, 1, None, fxc = 1, Arithmetic, DSSS, sat = true, cmp = false, pred = false, "a > 0.5 ? b : c"),
];

impl Opcode {
    /// The table row of this opcode.
    pub fn info(self) -> &'static OpInfo {
        // The table is ordered like the enum; the test below keeps it so.
        &TABLE[self as usize]
    }

    /// The row as `profile` has it: the table's, except for the operand
    /// shapes that differ by profile: `sincos` takes two more sources
    /// (constant registers) before the 3_0 profiles.
    pub fn info_in(self, profile: Profile) -> OpInfo {
        let mut row = *self.info();
        let three = matches!(profile, Profile::Ps3_0 | Profile::Vs3_0);
        match self {
            Opcode::SinCos if !three => {
                row.operands = &[O::Dst, O::ScalarSrc, O::Src, O::Src];
            }
            // ps_1_4's texld: a coordinate, no sampler (the stage is the
            // destination's number).
            Opcode::TexLd if profile == Profile::Ps1_4 => row.operands = DS,
            _ => {}
        }
        row
    }

    /// The profiles this instruction exists in: the table's availability
    /// column, grouped by the profile that brought each instruction in.
    /// Measured for the profiles Microsoft's assembler reads (one probe per
    /// instruction and profile under `tests/oracle/corpus/asm/profiles/`,
    /// which `tests/oracle/profiles.rs` holds this column to); `ps_2_a` and
    /// `vs_2_a` follow their `ps_2_x`/`vs_2_x` capabilities, `ps_2_b` has
    /// ps_2_0's instructions and `texldd` (what Microsoft's HLSL compiler
    /// writes for those targets: `tests/oracle/corpus/hlsl/gen_profiles/`),
    /// and ps_1_x has the arithmetic it shares with ps_2_0 (`cmp` and `dp4`
    /// from ps_1_2), `texkill`, ps_1_4's `texld` (a coordinate and no
    /// sampler: [`Opcode::info_in`]) and rows of its own, from `tex` to `cnd`
    /// ([`Opcode::is_ps1_only`]; measured by the probes of
    /// `asm/profiles/ps_1_*`, held by `tests/oracle/ps1x.rs`). The compiler
    /// writes no flow control at all for ps_2_a and ps_2_b (X3528), although
    /// their capabilities allow it in assembly.
    ///
    /// Across every profile that has an instruction, Microsoft's count of
    /// its slots is the same (measured: the `fxc_slots` column holds for
    /// each probe), except that `sincos` takes three sources (two constant
    /// registers) in ps_2_0, ps_2_x, vs_2_0 and vs_2_x and one in the 3_0
    /// profiles.
    pub fn profiles(self) -> ProfileSet {
        use Profile::*;
        use ProfileSet as S;
        // ps_2_0's arithmetic, which every vertex profile also has.
        const SHARED: S = S::of(&[Ps2_0, Ps2A, Ps2B, Ps2X, Ps3_0, Vs2_0, Vs2A, Vs2X, Vs3_0]);
        const PS2: S = S::of(&[Ps2_0, Ps2A, Ps2B, Ps2X, Ps3_0]);
        // What ps_2_x's capabilities add (flow control, predication, gradients).
        const PS2X: S = S::of(&[Ps2A, Ps2X, Ps3_0]);
        // Static flow control: every vertex profile from vs_2_0.
        const STATIC: S = PS2X.or(S::of(&[Vs2_0, Vs2A, Vs2X, Vs3_0]));
        // Predication and dynamic flow control: vs_2_x's capabilities.
        const DYNAMIC: S = PS2X.or(S::of(&[Vs2A, Vs2X, Vs3_0]));
        // The vertex-shader instructions.
        const VS: S = S::of(&[Vs1_1, Vs2_0, Vs2A, Vs2X, Vs3_0]);
        // ps_1_x, by the version that brought each instruction in.
        const PS1: S = S::of(&[Ps1_1, Ps1_2, Ps1_3, Ps1_4]);
        const PS11: S = S::of(&[Ps1_1, Ps1_2, Ps1_3]);
        const PS12: S = S::of(&[Ps1_2, Ps1_3]);
        match self {
            Opcode::Mov
            | Opcode::Add
            | Opcode::Sub
            | Opcode::Mad
            | Opcode::Mul
            | Opcode::Dp3
            | Opcode::Lrp
            | Opcode::Nop
            | Opcode::Def => SHARED.or(PS1),
            Opcode::Dp4 => SHARED.or(S::of(&[Ps1_2, Ps1_3, Ps1_4])),
            Opcode::Cmp => PS2.or(S::of(&[Ps1_2, Ps1_3, Ps1_4])),
            Opcode::TexKill => PS2.or(PS1),
            Opcode::TexLd => PS2.or(S::of(&[Ps1_4])),
            Opcode::Cnd => PS1,
            Opcode::Tex
            | Opcode::TexCoord
            | Opcode::TexBem
            | Opcode::TexBemL
            | Opcode::TexReg2Ar
            | Opcode::TexReg2Gb
            | Opcode::TexM3x2Pad
            | Opcode::TexM3x2Tex
            | Opcode::TexM3x3Pad
            | Opcode::TexM3x3Tex
            | Opcode::TexM3x3Spec
            | Opcode::TexM3x3VSpec => PS11,
            Opcode::TexReg2Rgb | Opcode::TexM3x3 | Opcode::TexDp3 | Opcode::TexDp3Tex => PS12,
            Opcode::TexM3x2Depth => S::of(&[Ps1_3]),
            Opcode::TexCrd | Opcode::TexDepth | Opcode::Bem | Opcode::Phase => S::of(&[Ps1_4]),
            Opcode::TexLdP | Opcode::TexLdB => PS2,
            Opcode::Dp2Add => PS2,
            Opcode::Dsx | Opcode::Dsy => PS2X,
            // Microsoft's compiler writes texldd for ps_2_b (tex2Dgrad), not dsx.
            Opcode::TexLdD => PS2X.or(S::of(&[Ps2B])),
            Opcode::TexLdL => S::of(&[Ps3_0, Vs3_0]),
            Opcode::Loop | Opcode::EndLoop => S::of(&[Ps3_0, Vs2_0, Vs2A, Vs2X, Vs3_0]),
            Opcode::Call
            | Opcode::CallNz
            | Opcode::Ret
            | Opcode::Label
            | Opcode::Rep
            | Opcode::EndRep
            | Opcode::If
            | Opcode::Else
            | Opcode::EndIf
            | Opcode::DefI
            | Opcode::DefB => STATIC,
            Opcode::Ifc | Opcode::Break | Opcode::BreakC | Opcode::BreakP | Opcode::Setp => DYNAMIC,
            op if op.is_vertex_only() => VS,
            _ => SHARED,
        }
    }

    /// The instructions only ps_1_x has (`tex`, `texcoord`, `texcrd`, the
    /// `texm3x*` family, `bem`, `phase`, `cnd`, …): no mnemonic or opcode
    /// lookup outside ps_1_x finds them ([`Opcode::from_mnemonic_in`],
    /// [`Opcode::from_code_in`] do in ps_1_x).
    pub fn is_ps1_only(self) -> bool {
        self >= Opcode::Tex
    }

    /// The instructions only vertex shaders have (`mova`, `lit`, `dst`,
    /// `expp`, `logp`, `slt`, `sge`, `sgn`).
    pub fn is_vertex_only(self) -> bool {
        matches!(
            self,
            Opcode::Mova
                | Opcode::Lit
                | Opcode::Dst
                | Opcode::Expp
                | Opcode::Logp
                | Opcode::Slt
                | Opcode::Sge
                | Opcode::Sgn
        )
    }

    /// For the matrix instructions (m4x4 … m3x2): how many consecutive
    /// registers they read from `src1` (the rows, one per result
    /// component) and the width of each dot product, as (rows, width).
    pub fn matrix_shape(self) -> Option<(u32, u32)> {
        match self {
            Opcode::M4x4 => Some((4, 4)),
            Opcode::M4x3 => Some((3, 4)),
            Opcode::M3x4 => Some((4, 3)),
            Opcode::M3x3 => Some((3, 3)),
            Opcode::M3x2 => Some((2, 3)),
            _ => None,
        }
    }

    /// Looks up a base mnemonic (no suffixes), with whether a comparison
    /// suffix was given (it selects `ifc` and `breakc`).
    pub fn from_mnemonic(base: &str, has_comparison: bool) -> Option<Opcode> {
        if has_comparison && base == "if" {
            return Some(Opcode::Ifc);
        }
        if has_comparison && base == "break" {
            return Some(Opcode::BreakC);
        }
        TABLE
            .iter()
            .find(|r| {
                r.mnemonic == base
                    && !matches!(r.op, Opcode::Ifc | Opcode::BreakC)
                    && !r.op.is_ps1_only()
            })
            .map(|r| r.op)
    }

    /// Looks up a base mnemonic as `profile` spells it: in ps_1_x the rows
    /// of ps_1_x (`texld` is ps_1_4's, `tex` ps_1_1–ps_1_3's), elsewhere
    /// [`Opcode::from_mnemonic`]. Whether the profile has the instruction
    /// is [`Opcode::profiles`].
    pub fn from_mnemonic_in(base: &str, has_comparison: bool, profile: Profile) -> Option<Opcode> {
        if !profile.is_ps1() {
            return Opcode::from_mnemonic(base, has_comparison);
        }
        TABLE
            .iter()
            .find(|r| r.mnemonic == base && (r.op.is_ps1_only() || r.op.profiles().has(profile)))
            .map(|r| r.op)
            .or_else(|| Opcode::from_mnemonic(base, has_comparison))
    }

    /// The row of an instruction token's code in `profile`: in ps_1_x the
    /// profile's own row of a shared code (0x42 is `tex` in ps_1_1–ps_1_3
    /// and `texld` in ps_1_4, 0x40 `texcoord` or `texcrd`), elsewhere
    /// [`Opcode::from_code`].
    pub fn from_code_in(code: u16, control: u8, profile: Profile) -> Option<Opcode> {
        if !profile.is_ps1() {
            return Opcode::from_code(code, control);
        }
        TABLE
            .iter()
            .find(|r| r.code == code && r.op.profiles().has(profile))
            .or_else(|| {
                TABLE
                    .iter()
                    .find(|r| r.code == code && r.control == control)
            })
            .map(|r| r.op)
    }

    /// What kind of instruction it is.
    pub fn class(self) -> Class {
        self.info().class
    }

    /// The row of an instruction token's D3DSIO_* code and control: `texld`,
    /// `texldp` and `texldb` share 0x42 and differ in the control; the
    /// comparison in the control of `ifc`, `breakc` and `setp` selects no row.
    pub fn from_code(code: u16, control: u8) -> Option<Opcode> {
        let mut rows = TABLE
            .iter()
            .filter(|r| r.code == code && !r.op.is_ps1_only())
            .peekable();
        let first = rows.peek().map(|r| r.op)?;
        match rows.find(|r| r.control == control) {
            Some(r) => Some(r.op),
            None if code != 0x42 => Some(first),
            None => None,
        }
    }

    /// Whether this opcode opens a block closed later (rep, loop, if).
    pub fn opens_block(self) -> bool {
        matches!(self, Opcode::Rep | Opcode::Loop | Opcode::If | Opcode::Ifc)
    }
}

impl fmt::Display for Opcode {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.info().mnemonic)
    }
}

/// Comparison suffixes of `if_comp`, `break_comp` and `setp_comp`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Compare {
    /// `_gt`: a > b.
    Gt,
    /// `_lt`: a < b.
    Lt,
    /// `_ge`: a ≥ b.
    Ge,
    /// `_le`: a ≤ b.
    Le,
    /// `_eq`: a = b.
    Eq,
    /// `_ne`: a ≠ b (true for NaN).
    Ne,
}

impl Compare {
    /// Every comparison, in suffix order.
    pub const ALL: [Compare; 6] = [
        Compare::Gt,
        Compare::Lt,
        Compare::Ge,
        Compare::Le,
        Compare::Eq,
        Compare::Ne,
    ];

    /// The suffix without its underscore (`gt`).
    pub fn suffix(self) -> &'static str {
        match self {
            Compare::Gt => "gt",
            Compare::Lt => "lt",
            Compare::Ge => "ge",
            Compare::Le => "le",
            Compare::Eq => "eq",
            Compare::Ne => "ne",
        }
    }

    /// The comparison as the control bits of an instruction token
    /// (D3DSPC_*: GT 1, EQ 2, GE 3, LT 4, NE 5, LE 6; d3d9types.h).
    pub fn code(self) -> u8 {
        match self {
            Compare::Gt => 1,
            Compare::Eq => 2,
            Compare::Ge => 3,
            Compare::Lt => 4,
            Compare::Ne => 5,
            Compare::Le => 6,
        }
    }

    /// The comparison of an instruction token's control bits, if they name one.
    pub fn from_code(code: u8) -> Option<Compare> {
        Compare::ALL.into_iter().find(|c| c.code() == code)
    }

    /// The comparison of a suffix (`gt`, lower case as Microsoft's
    /// assembler reads it), if it is one.
    pub fn from_suffix(s: &str) -> Option<Compare> {
        Compare::ALL.into_iter().find(|c| c.suffix() == s)
    }

    /// Evaluates the comparison on two floats (IEEE semantics: NaN compares
    /// false except for `ne`).
    pub fn eval(self, a: f32, b: f32) -> bool {
        match self {
            Compare::Gt => a > b,
            Compare::Lt => a < b,
            Compare::Ge => a >= b,
            Compare::Le => a <= b,
            Compare::Eq => a == b,
            Compare::Ne => a != b,
        }
    }
}

/// Register files of ps_3_0 (Microsoft's ps_3_0 register page).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum RegFile {
    /// `r#`, 32 temporaries.
    Temp,
    /// `v#`, 10 interpolated inputs.
    Input,
    /// `c#`, 224 float constants.
    Const,
    /// `i#`, 16 integer constants.
    ConstInt,
    /// `b#`, 16 boolean constants.
    ConstBool,
    /// `s#`, 16 samplers.
    Sampler,
    /// `p0`, the predicate register.
    Predicate,
    /// `oC#`, 4 colour outputs.
    ColorOut,
    /// `oDepth`.
    DepthOut,
    /// `aL`, the loop counter.
    LoopCounter,
    /// `vPos`, the pixel position.
    Position,
    /// `vFace`, the face sign.
    Face,
    /// `l#`, labels.
    Label,
    /// `t#`, texture coordinates (ps_2_0, ps_2_x).
    Texture,
    /// `a0`, the address register (vertex shaders).
    Address,
    /// `oD#`, colour outputs of vs_1_1–vs_2_x.
    AttrOut,
    /// `oT#`, texture-coordinate outputs of vs_1_1–vs_2_x.
    TexCoordOut,
    /// `o#`, the outputs of vs_3_0.
    Output,
    /// `oPos`, the position output of vs_1_1–vs_2_x.
    PosOut,
    /// `oFog`, the fog output of vs_1_1–vs_2_x.
    FogOut,
    /// `oPts`, the point-size output of vs_1_1–vs_2_x.
    PointSizeOut,
}

/// Static facts about a register file.
#[derive(Clone, Copy, Debug)]
pub struct RegFileInfo {
    /// The register file.
    pub file: RegFile,
    /// How it is spelled (the prefix before the number, or the whole name).
    pub name: &'static str,
    /// Number of registers.
    pub count: u32,
    /// Whether the file is numbered (`r0`) or a single named register (`vPos`).
    pub numbered: bool,
    /// Whether a shader may read it.
    pub readable: bool,
    /// Whether a shader may write it.
    pub writable: bool,
    /// Distinct registers of this file one instruction may read (read ports).
    pub read_ports: u32,
    /// The D3DSPR_* register type of its parameter tokens (d3d9types.h).
    pub token_type: u8,
    /// The register number a token carries for a single named register
    /// (`vFace` is MISCTYPE number 1); numbered files carry their index.
    pub token_number: u32,
}

/// The register files, from Microsoft's ps_3_0 register page, with their
/// D3DSPR_* token types (TEMP 0, INPUT 1, CONST 2, CONSTINT 7, COLOROUT 8,
/// DEPTHOUT 9, SAMPLER 10, CONSTBOOL 14, LOOP 15, MISCTYPE 17, LABEL 18,
/// PREDICATE 19).
#[rustfmt::skip]
pub const REG_FILES: &[RegFileInfo] = &[
    RegFileInfo { file: RegFile::Temp, name: "r", count: 32, numbered: true, readable: true, writable: true, read_ports: 3, token_type: 0, token_number: 0 },
    RegFileInfo { file: RegFile::Input, name: "v", count: 10, numbered: true, readable: true, writable: false, read_ports: 1, token_type: 1, token_number: 0 },
    RegFileInfo { file: RegFile::Const, name: "c", count: 224, numbered: true, readable: true, writable: false, read_ports: 1, token_type: 2, token_number: 0 },
    RegFileInfo { file: RegFile::ConstInt, name: "i", count: 16, numbered: true, readable: true, writable: false, read_ports: 1, token_type: 7, token_number: 0 },
    RegFileInfo { file: RegFile::ConstBool, name: "b", count: 16, numbered: true, readable: true, writable: false, read_ports: 1, token_type: 14, token_number: 0 },
    RegFileInfo { file: RegFile::Sampler, name: "s", count: 16, numbered: true, readable: true, writable: false, read_ports: 1, token_type: 10, token_number: 0 },
    RegFileInfo { file: RegFile::Predicate, name: "p", count: 1, numbered: true, readable: true, writable: true, read_ports: 1, token_type: 19, token_number: 0 },
    RegFileInfo { file: RegFile::ColorOut, name: "oC", count: 4, numbered: true, readable: false, writable: true, read_ports: 0, token_type: 8, token_number: 0 },
    RegFileInfo { file: RegFile::DepthOut, name: "oDepth", count: 1, numbered: false, readable: false, writable: true, read_ports: 0, token_type: 9, token_number: 0 },
    RegFileInfo { file: RegFile::LoopCounter, name: "aL", count: 1, numbered: false, readable: true, writable: false, read_ports: 1, token_type: 15, token_number: 0 },
    RegFileInfo { file: RegFile::Position, name: "vPos", count: 1, numbered: false, readable: true, writable: false, read_ports: 1, token_type: 17, token_number: 0 },
    RegFileInfo { file: RegFile::Face, name: "vFace", count: 1, numbered: false, readable: true, writable: false, read_ports: 1, token_type: 17, token_number: 1 },
    RegFileInfo { file: RegFile::Label, name: "l", count: 2048, numbered: true, readable: false, writable: false, read_ports: 1, token_type: 18, token_number: 0 },
    // The files other profiles add (counts: the most any profile has; a
    // profile's own is Profile::count). TEXTURE and ADDR share type 3,
    // TEXCRDOUT and OUTPUT type 6: the stage tells them apart.
    RegFileInfo { file: RegFile::Texture, name: "t", count: 8, numbered: true, readable: true, writable: false, read_ports: 1, token_type: 3, token_number: 0 },
    RegFileInfo { file: RegFile::Address, name: "a", count: 1, numbered: true, readable: true, writable: true, read_ports: 1, token_type: 3, token_number: 0 },
    RegFileInfo { file: RegFile::AttrOut, name: "oD", count: 2, numbered: true, readable: false, writable: true, read_ports: 0, token_type: 5, token_number: 0 },
    RegFileInfo { file: RegFile::TexCoordOut, name: "oT", count: 8, numbered: true, readable: false, writable: true, read_ports: 0, token_type: 6, token_number: 0 },
    RegFileInfo { file: RegFile::Output, name: "o", count: 12, numbered: true, readable: false, writable: true, read_ports: 0, token_type: 6, token_number: 0 },
    RegFileInfo { file: RegFile::PosOut, name: "oPos", count: 1, numbered: false, readable: false, writable: true, read_ports: 0, token_type: 4, token_number: 0 },
    RegFileInfo { file: RegFile::FogOut, name: "oFog", count: 1, numbered: false, readable: false, writable: true, read_ports: 0, token_type: 4, token_number: 1 },
    RegFileInfo { file: RegFile::PointSizeOut, name: "oPts", count: 1, numbered: false, readable: false, writable: true, read_ports: 0, token_type: 4, token_number: 2 },
];

/// The files ps_3_0 has: the first thirteen rows.
const PS_3_0_FILES: usize = 13;

/// The D3DSPR_* register types of float constants: CONST numbers c0–c2047
/// and CONST2, CONST3 and CONST4 the next 2048 each (c2048–c8191), as
/// Microsoft's assembler writes a vertex shader's large constant file (the
/// token's register number is 11 bits).
pub const CONST_TOKEN_TYPES: [u8; 4] = [2, 11, 12, 13];

impl RegFile {
    /// The facts of this register file.
    pub fn info(self) -> &'static RegFileInfo {
        &REG_FILES[self as usize]
    }

    /// The register a parameter token names: its D3DSPR_* type and number.
    /// `None` for types ps_3_0 does not have and numbers a single named
    /// register does not use.
    pub fn from_token(token_type: u8, number: u32) -> Option<(RegFile, u32)> {
        RegFile::from_token_in(token_type, number, Profile::Ps3_0)
    }

    /// The register a parameter token names in `profile`: as
    /// [`RegFile::from_token`], among the files the profile has.
    pub fn from_token_in(token_type: u8, number: u32, profile: Profile) -> Option<(RegFile, u32)> {
        if let Some(bank) = CONST_TOKEN_TYPES[1..].iter().position(|&t| t == token_type) {
            let index = number + 2048 * (bank as u32 + 1);
            return (profile.count(RegFile::Const) > 0).then_some((RegFile::Const, index));
        }
        REG_FILES
            .iter()
            .filter(|f| profile.count(f.file) > 0)
            .find_map(|f| match f.numbered {
                true if f.token_type == token_type => Some((f.file, number)),
                false if f.token_type == token_type && f.token_number == number => {
                    Some((f.file, 0))
                }
                _ => None,
            })
    }

    /// How many registers of this file a token can number, which is where
    /// a relative base wraps: 8192 float constants through
    /// [`CONST_TOKEN_TYPES`], 2048 (the 11-bit register number) of any
    /// other file.
    pub fn token_registers(self) -> u32 {
        match self {
            RegFile::Const => 2048 * CONST_TOKEN_TYPES.len() as u32,
            _ => 2048,
        }
    }

    /// Parses a register name (prefix and number already split). Names are
    /// spelled as Microsoft's assembler reads them, case included (`oC`,
    /// `vPos`, `aL`: `C0` and `oc0` are invalid registers there).
    pub fn lookup(prefix: &str) -> Option<RegFile> {
        REG_FILES[..PS_3_0_FILES]
            .iter()
            .find(|f| f.name == prefix)
            .map(|f| f.file)
    }

    /// Parses a register name of any profile's files (see [`RegFile::lookup`]).
    pub fn lookup_any(prefix: &str) -> Option<RegFile> {
        REG_FILES.iter().find(|f| f.name == prefix).map(|f| f.file)
    }
}

/// A profile's register files, by [`RegFile`] (here, beside the files,
/// so that `profile.rs` needs nothing of this module).
impl Profile {
    /// How many registers of `file` a shader of this profile may name (0:
    /// the profile has no such file), from [`Profile::registers`]. For
    /// ps_3_0 these are the instruction table's counts.
    pub fn count(self, file: RegFile) -> u32 {
        let r = self.registers();
        let pixel = self.stage() == crate::core::profile::Stage::Pixel;
        let vs3 = self == Profile::Vs3_0;
        let legacy_vs = !pixel && !vs3;
        let flow = Opcode::Label.profiles().has(self);
        match file {
            RegFile::Temp => r.temps,
            RegFile::Input => r.inputs,
            // Microsoft's assembler takes any float constant a vertex
            // token can number (measured: c8191 through CONST4, c8192 is
            // X2005): the count is a device's, not the profile's.
            RegFile::Const if !pixel => RegFile::Const.token_registers(),
            RegFile::Const => r.float_consts,
            RegFile::ConstInt => r.int_consts,
            RegFile::ConstBool => r.bool_consts,
            RegFile::Sampler => r.samplers,
            RegFile::Predicate => u32::from(r.predicate),
            RegFile::ColorOut => r.colour_outputs,
            RegFile::DepthOut => u32::from(pixel),
            RegFile::LoopCounter => u32::from(r.loop_counter),
            RegFile::Position | RegFile::Face => u32::from(self == Profile::Ps3_0),
            RegFile::Label => u32::from(flow) * 2048,
            RegFile::Texture => r.texcoords,
            RegFile::Address => u32::from(r.address),
            RegFile::AttrOut => u32::from(legacy_vs) * 2,
            RegFile::TexCoordOut => u32::from(legacy_vs) * 8,
            RegFile::Output => u32::from(vs3) * r.outputs,
            RegFile::PosOut | RegFile::FogOut | RegFile::PointSizeOut => u32::from(legacy_vs),
        }
    }

    /// Whether ps30 runs shaders of this profile: the pixel shaders ps_1_1–
    /// ps_1_4 (through their lowering, `core/ps1/run.rs`; a shader using
    /// what it does not lower is refused by name), ps_2_0, ps_2_x (and the
    /// ps_2_a/ps_2_b shaders compiled to it) and ps_3_0 in the emulator,
    /// the GPU backend, `render` and `compare`; vs_2_0, vs_2_x and vs_3_0 in
    /// the vertex stage (`emu::vertex`, `run --vertices`).
    pub fn runs(self) -> bool {
        matches!(
            self,
            Profile::Ps1_1
                | Profile::Ps1_2
                | Profile::Ps1_3
                | Profile::Ps1_4
                | Profile::Ps2_0
                | Profile::Ps2X
                | Profile::Ps2A
                | Profile::Ps2B
                | Profile::Ps3_0
                | Profile::Vs2_0
                | Profile::Vs2X
                | Profile::Vs3_0
        )
    }
}

/// Sampler dimensions a `dcl_*` may declare.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SamplerType {
    /// `dcl_2d`: a 2D texture.
    Tex2d,
    /// `dcl_cube`: a cube map.
    Cube,
    /// `dcl_volume`: a volume texture.
    Volume,
}

impl SamplerType {
    /// The D3DSAMPLER_TEXTURE_TYPE of a `dcl` token (2D 2, CUBE 3, VOLUME 4;
    /// 1 is the 1D type ps_3_0 does not have).
    pub fn code(self) -> u8 {
        match self {
            SamplerType::Tex2d => 2,
            SamplerType::Cube => 3,
            SamplerType::Volume => 4,
        }
    }

    /// The `dcl_` suffix (`2d`, `cube`, `volume`).
    pub fn suffix(self) -> &'static str {
        match self {
            SamplerType::Tex2d => "2d",
            SamplerType::Cube => "cube",
            SamplerType::Volume => "volume",
        }
    }
}

/// Input usages of `dcl_<usage>[n]`, in D3DDECLUSAGE order (the index is
/// the usage code a `dcl` token carries).
pub const USAGES: &[&str] = &[
    "position",
    "blendweight",
    "blendindices",
    "normal",
    "psize",
    "texcoord",
    "tangent",
    "binormal",
    "tessfactor",
    "positiont",
    "color",
    "fog",
    "depth",
    "sample",
];

/// Flow-control limits of ps_3_0 (Microsoft's "Flow Control Limitations"):
/// `rep`/`loop` nested at most this deep.
pub const MAX_LOOP_NESTING: u32 = 4;
/// `call`/`callnz` nested at most this deep.
pub const MAX_CALL_NESTING: u32 = 4;
/// Static flow control nested at most this deep (Microsoft's static nesting limit).
pub const MAX_STATIC_NESTING: u32 = 24;
/// Dynamic flow control (`if_comp`, `if p0`, `callnz p0`, …) nested at most this deep.
pub const MAX_DYNAMIC_NESTING: u32 = 24;
/// rep/loop iteration count range, i#.x in [0, 255].
pub const MAX_REP_COUNT: i32 = 255;

/// The instruction table as Markdown, with both slot columns (the README
/// embeds it; a test keeps the two identical).
pub fn markdown_table() -> String {
    let mut s = String::from(
        "| mnemonic | slots (Microsoft's count) | slots (documented) | class | meaning |\n|---|---|---|---|---|\n",
    );
    // The guide's list is ps_3_0's; the other profiles' are docs/profiles.md's.
    for r in TABLE.iter().filter(|r| r.op.profiles().has(Profile::Ps3_0)) {
        let name = if r.comparison {
            format!("{}_comp", r.mnemonic)
        } else {
            r.mnemonic.to_string()
        };
        let slots = match r.cube_slots {
            Some(c) => format!("{} ({c} cube)", r.slots),
            None => r.slots.to_string(),
        };
        let class = match r.class {
            Class::Arithmetic => "arithmetic",
            Class::Texture => "texture",
            Class::Flow => "flow control",
            Class::Declaration => "declaration",
        };
        s.push_str(&format!(
            "| `{name}` | {} | {slots} | {class} | {} |\n",
            r.fxc_slots, r.summary
        ));
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn table_is_ordered_like_the_enum() {
        for (i, row) in TABLE.iter().enumerate() {
            assert_eq!(
                row.op as usize, i,
                "row {} ({}) out of place",
                i, row.mnemonic
            );
        }
        for (i, f) in REG_FILES.iter().enumerate() {
            assert_eq!(f.file as usize, i, "register file {} out of place", f.name);
        }
    }

    #[test]
    fn the_slot_line_is_worded_as_d3ddisassemble_words_it() {
        // Lines of D3DDisassemble's listings: an empty shader, one `mov`,
        // one `texld` writing oC0, and a compiled blur.
        let line = |texture, arithmetic| {
            SlotCount {
                texture,
                arithmetic,
            }
            .listing_line()
        };
        assert_eq!(line(0, 0), "// approximately 0 instruction slots used");
        assert_eq!(line(0, 1), "// approximately 1 instruction slot used");
        assert_eq!(
            line(1, 0),
            "// approximately 1 instruction slot used (1 texture, 0 arithmetic)"
        );
        assert_eq!(
            line(18, 52),
            "// approximately 70 instruction slots used (18 texture, 52 arithmetic)"
        );
    }

    #[test]
    fn the_tables_differ_on_seven_rows_and_the_documented_one_is_never_lower() {
        let mut differ = Vec::new();
        // The documented table is the ps_3_0 page's.
        for r in TABLE.iter().filter(|r| r.op.profiles().has(Profile::Ps3_0)) {
            for (cube, predicated) in [(false, false), (true, false), (false, true), (true, true)] {
                let fxc = r.count(SlotTable::Fxc, cube, predicated).total();
                let doc = r.count(SlotTable::Documented, cube, predicated).total();
                assert!(doc >= fxc, "{}", r.mnemonic);
                if doc != fxc && !predicated {
                    differ.push(format!("{}{}", r.mnemonic, if cube { " cube" } else { "" }));
                }
            }
        }
        differ.dedup();
        assert_eq!(
            differ,
            [
                "nop",
                "nop cube",
                "lrp",
                "lrp cube",
                "texkill",
                "texkill cube",
                "texld cube",
                "texldp",
                "texldp cube",
                "texldb",
                "texldb cube",
                "texldl cube"
            ]
        );
    }

    #[test]
    fn mnemonics_resolve() {
        assert_eq!(Opcode::from_mnemonic("if", true), Some(Opcode::Ifc));
        // Lower case only, as Microsoft's assembler reads them.
        assert_eq!(Opcode::from_mnemonic("IF", true), None);
        assert_eq!(Opcode::from_mnemonic("if", false), Some(Opcode::If));
        assert_eq!(Opcode::from_mnemonic("break", true), Some(Opcode::BreakC));
        assert_eq!(Opcode::from_mnemonic("break", false), Some(Opcode::Break));
        assert_eq!(Opcode::from_mnemonic("texldl", false), Some(Opcode::TexLdL));
        assert_eq!(Opcode::from_mnemonic("TexLdL", false), None);
        // A vertex-shader instruction is a row, of the vertex profiles only.
        assert_eq!(Opcode::from_mnemonic("lit", false), Some(Opcode::Lit));
        assert!(!Opcode::Lit.profiles().has(Profile::Ps3_0));
        assert_eq!(Opcode::from_mnemonic("texcrd", false), None);
    }
}
