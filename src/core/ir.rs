//! The validated program: the one intermediate representation every later
//! stage (cost model, emulator, writer, generator) reads.
//!
//! Rules of the IR:
//!
//! * [`Program::instructions`] holds executable instructions only, in source
//!   order, with every REPEAT_BLOCK already expanded. Declarations (`dcl_*`)
//!   and constant definitions (`def`, `defi`, `defb`) live in their own lists.
//! * Every instruction keeps its [`Origin`]: the byte span of the source text
//!   it came from and, when a REPEAT_BLOCK produced it, which repetition.
//! * Operands are resolved: register files and indices are checked, swizzles
//!   are four component indices, write masks are bit sets.
//! * A [`Shader`] (program + [`Info`]) can only be built by
//!   [`crate::core::valid::validate`], so holding one proves the program follows the
//!   ps_3_0 rules ps30 checks and that its blocks are balanced.

use crate::core::isa::{Compare, Opcode, RegFile, SamplerType, SlotCount, SlotTable};
use std::collections::BTreeMap;
use std::fmt;
use std::sync::Arc;

/// A byte range in a source file.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default, PartialOrd, Ord)]
pub struct Span {
    /// First byte of the span in the source.
    pub start: u32,
    /// One past its last byte.
    pub end: u32,
}

impl Span {
    /// The span of bytes `start..end`.
    pub fn new(start: usize, end: usize) -> Span {
        Span {
            start: start as u32,
            end: end as u32,
        }
    }

    /// The span as a range of byte offsets.
    pub fn range(self) -> std::ops::Range<usize> {
        self.start as usize..self.end as usize
    }

    /// The smallest span covering both.
    pub fn to(self, other: Span) -> Span {
        Span {
            start: self.start.min(other.start),
            end: self.end.max(other.end),
        }
    }
}

/// One level of REPEAT_BLOCK expansion an instruction sits in.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Repetition {
    /// Span of the `BEGIN_REPEAT_BLOCK(...)` line.
    pub macro_span: Span,
    /// 0-based repetition number.
    pub index: u32,
    /// How many repetitions the macro makes.
    pub count: u32,
}

/// Where an instruction came from.
#[derive(Clone, Debug, PartialEq, Eq, Hash, Default)]
pub struct Origin {
    /// Where in the source (the statement as written, inside any macro).
    pub span: Span,
    /// The innermost enclosing repetition, linked to the ones around it;
    /// `None` outside macros. Statements of one repetition share the chain,
    /// so an expansion holds one link per repetition made, not one copy of
    /// the whole chain per statement.
    pub repeat: Option<Arc<RepeatLink>>,
}

/// One repetition of a REPEAT_BLOCK and the repetition around it.
#[derive(Debug, PartialEq, Eq, Hash)]
pub struct RepeatLink {
    /// Which repetition of which REPEAT_BLOCK.
    pub repetition: Repetition,
    /// The repetition around it; `None` for an outermost REPEAT_BLOCK.
    pub outer: Option<Arc<RepeatLink>>,
}

impl Origin {
    /// An origin outside every macro.
    pub fn at(span: Span) -> Origin {
        Origin { span, repeat: None }
    }

    /// Enclosing repetitions, outermost first; empty outside macros.
    pub fn repeats(&self) -> Vec<Repetition> {
        let mut out = Vec::new();
        let mut link = self.repeat.as_deref();
        while let Some(l) = link {
            out.push(l.repetition);
            link = l.outer.as_deref();
        }
        out.reverse();
        out
    }
}

/// A register: file and number (`r3` is `Temp`, 3; `vPos` is `Position`, 0).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Reg {
    /// The register file (`r`, `v`, `c`, …).
    pub file: RegFile,
    /// The register number.
    pub index: u32,
}

impl fmt::Display for Reg {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let info = self.file.info();
        if info.numbered {
            write!(f, "{}{}", info.name, self.index)
        } else {
            f.write_str(info.name)
        }
    }
}

/// A source swizzle: for each output component, the input component read.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Swizzle(pub [u8; 4]);

impl Swizzle {
    /// `.xyzw`: every component from itself.
    pub const IDENTITY: Swizzle = Swizzle([0, 1, 2, 3]);

    /// `.x`, `.y`, `.z` or `.w` replicated (component `c`, 0 to 3).
    pub fn replicate(c: u8) -> Swizzle {
        Swizzle([c; 4])
    }

    /// Whether all four components read the same input component.
    pub fn is_replicate(self) -> bool {
        self.0.iter().all(|&c| c == self.0[0])
    }
}

impl fmt::Display for Swizzle {
    /// Prints the shortest form that parses back to the same swizzle
    /// (`.xyyy` prints as `.xy`); nothing for the identity.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if *self == Swizzle::IDENTITY {
            return Ok(());
        }
        let mut n = 4;
        while n > 1 && self.0[n - 1] == self.0[n - 2] {
            n -= 1;
        }
        f.write_str(".")?;
        for &c in &self.0[..n] {
            f.write_str(["x", "y", "z", "w"][c as usize])?;
        }
        Ok(())
    }
}

/// A destination write mask: bit 0 = x … bit 3 = w.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct WriteMask(pub u8);

impl WriteMask {
    /// `.xyzw`: every component written.
    pub const ALL: WriteMask = WriteMask(0b1111);

    /// Whether component `component` (0 = x … 3 = w) is written.
    pub fn has(self, component: usize) -> bool {
        self.0 & (1 << component) != 0
    }

    /// How many components are written.
    pub fn count(self) -> u32 {
        self.0.count_ones()
    }
}

impl fmt::Display for WriteMask {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if *self == WriteMask::ALL {
            return Ok(());
        }
        f.write_str(".")?;
        for (i, c) in ["x", "y", "z", "w"].iter().enumerate() {
            if self.has(i) {
                f.write_str(c)?;
            }
        }
        Ok(())
    }
}

/// Source modifiers allowed in ps_3_0.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum SrcMod {
    /// No modifier.
    #[default]
    None,
    /// `-r0`
    Neg,
    /// `r0_abs`
    Abs,
    /// `-r0_abs`
    NegAbs,
    /// `!b0`, `!p0.x` (conditions only)
    Not,
}

/// The register that indexes a relatively addressed operand: the number
/// read is the operand's `reg.index` plus the index register's value.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum RelIndex {
    /// `aL`, the loop counter (`v[aL + n]`, `c[aL + n]`, `o[aL + n]`).
    Loop,
    /// `a0.x` … `a0.w`: one component (0 = x … 3 = w) of the address
    /// register of vertex shaders (`c[a0.x + n]`).
    Addr(u8),
}

impl fmt::Display for RelIndex {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            RelIndex::Loop => f.write_str("aL"),
            RelIndex::Addr(c) => write!(f, "a0.{}", ["x", "y", "z", "w"][*c as usize & 3]),
        }
    }
}

/// A source operand.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Src {
    /// The register read.
    pub reg: Reg,
    /// `v[aL + n]`, `c[a0.x + n]`: the register number is `reg.index` plus
    /// the index register's value.
    pub relative: Option<RelIndex>,
    /// Which component each of x, y, z, w reads.
    pub swizzle: Swizzle,
    /// Negation and absolute value.
    pub modifier: SrcMod,
}

impl Src {
    /// `reg` with no swizzle, modifier or relative addressing.
    pub fn plain(reg: Reg) -> Src {
        Src {
            reg,
            relative: None,
            swizzle: Swizzle::IDENTITY,
            modifier: SrcMod::None,
        }
    }
}

/// A destination operand.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Dst {
    /// The register written.
    pub reg: Reg,
    /// `o[aL + n]` (vs_3_0 outputs): the register number is `reg.index + aL`.
    pub relative: Option<RelIndex>,
    /// The components written.
    pub mask: WriteMask,
}

/// A `(p0.c)` / `(!p0.c)` guard in front of an instruction.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Predicate {
    /// `!p0.c`: the guard is negated.
    pub negate: bool,
    /// The predicate channel (a replicate swizzle).
    pub swizzle: Swizzle,
}

/// One executable instruction.
///
/// Operand placement:
/// * arithmetic and texture instructions: `dst` and `src` as written; the
///   sampler of `texld*` is a source with file `Sampler`;
/// * `texkill r0`: the operand is `dst` (it is encoded as a destination) but
///   it is read, never written;
/// * `setp_*`: `dst` is `p0`;
/// * flow control: every operand (`i#`, `aL`, `b#`, `p0.c`, `l#`) is a source.
#[derive(Clone, Debug, PartialEq)]
pub struct Instruction {
    /// The operation.
    pub op: Opcode,
    /// `_sat`: the result is clamped to [0, 1].
    pub sat: bool,
    /// `_pp`: partial precision allowed.
    pub pp: bool,
    /// `_centroid` (texture instructions).
    pub centroid: bool,
    /// The comparison of `if_comp`, `break_comp`, `setp_comp`.
    pub compare: Option<Compare>,
    /// The `(p0.c)` guard, if any.
    pub predicate: Option<Predicate>,
    /// The destination (see the operand placement above).
    pub dst: Option<Dst>,
    /// The sources, in order.
    pub src: Vec<Src>,
    /// Where it came from.
    pub origin: Origin,
}

/// `def c#, x, y, z, w`
#[derive(Clone, Debug, PartialEq)]
pub struct FloatDef {
    /// The constant register number.
    pub index: u32,
    /// Its value.
    pub value: [f32; 4],
    /// Where it was defined.
    pub origin: Origin,
}

/// `defi i#, x, y, z, w`
#[derive(Clone, Debug, PartialEq)]
pub struct IntDef {
    /// The constant register number.
    pub index: u32,
    /// Its value.
    pub value: [i32; 4],
    /// Where it was defined.
    pub origin: Origin,
}

/// `defb b#, true|false`
#[derive(Clone, Debug, PartialEq)]
pub struct BoolDef {
    /// The constant register number.
    pub index: u32,
    /// Its value.
    pub value: bool,
    /// Where it was defined.
    pub origin: Origin,
}

/// `dcl_<usage><n> v#.mask` (or `dcl vPos.xy`, `dcl vFace`).
#[derive(Clone, Debug, PartialEq)]
pub struct InputDecl {
    /// The input register (`v#`, or vPos / vFace).
    pub reg: Reg,
    /// Usage name (`texcoord`, `color`, ...); empty for vPos / vFace.
    pub usage: String,
    /// The usage index (`texcoord1` → 1).
    pub usage_index: u32,
    /// The components declared.
    pub mask: WriteMask,
    /// `_centroid` interpolation.
    pub centroid: bool,
    /// `_pp`: partial precision allowed.
    pub pp: bool,
    /// Where it was declared.
    pub origin: Origin,
}

/// `dcl_2d s#`, `dcl_cube s#`, `dcl_volume s#`, with the `_centroid` and
/// `_pp` Microsoft's assembler accepts and encodes there (they change
/// nothing ps30 models, and are written back as they were given).
#[derive(Clone, Debug, PartialEq)]
pub struct SamplerDecl {
    /// The sampler number.
    pub index: u32,
    /// The texture type it samples.
    pub ty: SamplerType,
    /// `_centroid`, as written.
    pub centroid: bool,
    /// `_pp`, as written.
    pub pp: bool,
    /// Where it was declared.
    pub origin: Origin,
}

/// A parsed, expanded program. Build one with the front end; use it through
/// [`Shader`] once validated.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Program {
    /// The profile its version line names.
    pub profile: crate::core::profile::Profile,
    /// The executable instructions, in order.
    pub instructions: Vec<Instruction>,
    /// `def` statements.
    pub float_defs: Vec<FloatDef>,
    /// `defi` statements.
    pub int_defs: Vec<IntDef>,
    /// `defb` statements.
    pub bool_defs: Vec<BoolDef>,
    /// `dcl` of inputs.
    pub inputs: Vec<InputDecl>,
    /// `dcl_*` of samplers.
    pub samplers: Vec<SamplerDecl>,
}

impl Program {
    /// The `defi` value of `i#`, if the shader defines it (last one wins).
    pub fn int_def(&self, index: u32) -> Option<[i32; 4]> {
        self.int_defs
            .iter()
            .rev()
            .find(|d| d.index == index)
            .map(|d| d.value)
    }

    /// The `def` value of `c#`, if the shader defines it (last one wins).
    pub fn float_def(&self, index: u32) -> Option<[f32; 4]> {
        self.float_defs
            .iter()
            .rev()
            .find(|d| d.index == index)
            .map(|d| d.value)
    }

    /// The `defb` value of `b#`, if the shader defines it (last one wins).
    pub fn bool_def(&self, index: u32) -> Option<bool> {
        self.bool_defs
            .iter()
            .rev()
            .find(|d| d.index == index)
            .map(|d| d.value)
    }

    /// The declared type of sampler `s#`.
    pub fn sampler_type(&self, index: u32) -> Option<SamplerType> {
        self.samplers
            .iter()
            .find(|d| d.index == index)
            .map(|d| d.ty)
    }

    /// The slots of one of this program's instructions under both tables:
    /// [`crate::core::isa::OpInfo::count`] with its sampler's declared type
    /// and its predicate.
    pub fn slots_of(&self, ins: &Instruction) -> Slots {
        let cube = ins
            .src
            .iter()
            .find(|s| s.reg.file == RegFile::Sampler)
            .is_some_and(|s| self.sampler_type(s.reg.index) == Some(SamplerType::Cube));
        let row = ins.op.info();
        let predicated = ins.predicate.is_some();
        Slots {
            fxc: row.count(SlotTable::Fxc, cube, predicated),
            documented: row.count(SlotTable::Documented, cube, predicated),
        }
    }
}

/// One instruction's static slots under each table.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Slots {
    /// Microsoft's count.
    pub fxc: SlotCount,
    /// The documented table's.
    pub documented: SlotCount,
}

impl Slots {
    /// The count under `table`.
    pub fn under(self, table: SlotTable) -> SlotCount {
        match table {
            SlotTable::Fxc => self.fxc,
            SlotTable::Documented => self.documented,
        }
    }
}

/// Facts the validator established about a program's structure.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Info {
    /// For `rep`/`loop`: index of the matching `endrep`/`endloop`; for
    /// `endrep`/`endloop`: index of the matching `rep`/`loop`; for
    /// `if`/`ifc`: index of its `else` if any, else of its `endif`; for
    /// `else`: index of its `endif`; `None` elsewhere.
    pub matching: Vec<Option<u32>>,
    /// Label number → index of its `label` instruction.
    pub labels: BTreeMap<u32, u32>,
    /// Index one past the last instruction of the main program (the first
    /// `label`, or the end).
    pub main_end: u32,
    /// Static slots of each instruction under both tables (cube samplers and
    /// predication included).
    pub slots: Vec<Slots>,
}

impl Info {
    /// Instruction `i`'s static slots under `table`.
    pub fn slots(&self, i: usize, table: SlotTable) -> u32 {
        self.slots[i].under(table).total()
    }

    /// The program's static slots under `table`, split as Microsoft's
    /// listing splits them; [`SlotCount::total`] is the count.
    pub fn total(&self, table: SlotTable) -> SlotCount {
        self.slots.iter().map(|s| s.under(table)).sum()
    }
}

/// A program that passed validation, with its structural facts.
#[derive(Clone, Debug, PartialEq)]
pub struct Shader {
    program: Program,
    info: Info,
    /// What the emulator and the translation run in its place, if not
    /// itself: a ps_1_x shader's lowering (`core/ps1/run.rs`), or why it
    /// has none.
    runs_as: Option<Arc<Result<Shader, String>>>,
}

impl Shader {
    /// Only the validator builds shaders.
    pub(crate) fn new_validated(program: Program, info: Info) -> Shader {
        Shader {
            program,
            info,
            runs_as: None,
        }
    }

    /// This shader with the input and sampler declarations given.
    pub(crate) fn with_declarations(
        mut self,
        inputs: Vec<InputDecl>,
        samplers: Vec<SamplerDecl>,
    ) -> Shader {
        self.program.inputs = inputs;
        self.program.samplers = samplers;
        self
    }

    /// This shader, run as `lowered` (a ps_1_x shader as the IR the
    /// emulator executes), or refused with the reason `lowered` gives.
    pub(crate) fn running_as(mut self, lowered: Result<Shader, String>) -> Shader {
        self.runs_as = Some(Arc::new(lowered));
        self
    }

    /// The shader the emulator and the translation execute: this one, or
    /// the lowering of a ps_1_x shader (its instructions spelled as
    /// ps_2_0-like operations with the modifiers, clamps and co-issue made
    /// explicit; the same spans, the slots on the first operation of each
    /// instruction). `Err` says why a ps_1_x shader cannot run.
    pub fn runnable(&self) -> Result<&Shader, &str> {
        match self.runs_as.as_deref() {
            None => Ok(self),
            Some(Ok(s)) => Ok(s),
            Some(Err(why)) => Err(why),
        }
    }

    /// The program.
    pub fn program(&self) -> &Program {
        &self.program
    }

    /// What validation found out about its structure.
    pub fn info(&self) -> &Info {
        &self.info
    }

    /// The executable instructions.
    pub fn instructions(&self) -> &[Instruction] {
        &self.program.instructions
    }
}
