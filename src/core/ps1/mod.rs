//! ps_1_1–ps_1_4: the Direct3D 8-era pixel shaders, read, checked, counted,
//! assembled and listed as Microsoft's tools do.
//!
//! ps_1_x is another instruction set under the same token layout, so it has
//! its own path beside the ps_2_0–ps_3_0 stages rather than special cases
//! in each of them: its texture instructions write `t#` (ps_1_1–ps_1_3) or
//! come in two phases split by `phase` (ps_1_4); two instructions may be
//! co-issued (`+`, bit 30 of the second's token); sources take `_bias`,
//! `_bx2`, `_x2`, `1-` and ps_1_4's `_dz`/`_dw`; destinations take a shift
//! (`_x2` … `_d8`); instruction tokens carry no length, so a reader must
//! know each instruction's operands. The instructions themselves are rows
//! of the one table, [`crate::core::isa`] (`Opcode::profiles` says which
//! version has which).
//!
//! * [`text`] reads assembly into a [`Program`] (Microsoft's grammar errors,
//!   X2000 and X2005, with their places);
//! * [`rules`] holds a program to the rules `D3DAssemble` enforces, with
//!   its codes (the ones its probes showed: `tests/oracle/corpus/asm/
//!   profiles/ps_1_*`);
//! * [`tokens`] writes a program as Microsoft's tokens and reads tokens
//!   back, every token checked;
//! * [`listing`] prints a program as `D3DDisassemble` does, byte for byte.
//!
//! [`load`] runs them in order for [`crate::core::load`], and gives the rest
//! of ps30 a [`Shader`] whose instructions carry the operations, registers
//! and slots (what `check` and `profile` read); the ps_1_x modifiers stay in
//! the [`Program`]. What the emulator and the translation execute is
//! [`run`]'s lowering of the program, which the shader carries
//! ([`ir::Shader::runnable`]).
//!
//! Slots are Microsoft's count: one per instruction but `def`, `phase` and
//! `nop` (none), the second of a co-issued pair costing nothing; the
//! texture instructions are texture slots except `texkill` and `texdepth`
//! (arithmetic in the listing's split, as `texkill` is in ps_2_0).

pub mod listing;
pub mod rules;
pub mod run;
pub mod text;
pub mod tokens;

use crate::core::diag::{Diagnostics, SourceFile};
use crate::core::ir::{self, Reg, Span, Swizzle, WriteMask};
use crate::core::isa::{Class, Opcode, SlotCount, SlotTable};
use crate::core::profile::Profile;

/// A source modifier of ps_1_x, by its D3DSPSM_* code (bits 24–27 of a
/// source token).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Modifier {
    /// None.
    None,
    /// `-r0`.
    Neg,
    /// `r0_bias`: x - 0.5.
    Bias,
    /// `-r0_bias`.
    BiasNeg,
    /// `r0_bx2`: 2x - 1.
    Bx2,
    /// `-r0_bx2`.
    Bx2Neg,
    /// `1-r0`.
    Comp,
    /// `r0_x2` (ps_1_4).
    X2,
    /// `-r0_x2` (ps_1_4).
    X2Neg,
    /// `r0_dz` (`_db`): divide by z (ps_1_4 `texld`, `texcrd`).
    Dz,
    /// `t0_dw` (`_da`): divide by w (ps_1_4 `texld`, `texcrd`).
    Dw,
}

impl Modifier {
    /// Every modifier, in code order.
    pub const ALL: [Modifier; 11] = [
        Modifier::None,
        Modifier::Neg,
        Modifier::Bias,
        Modifier::BiasNeg,
        Modifier::Bx2,
        Modifier::Bx2Neg,
        Modifier::Comp,
        Modifier::X2,
        Modifier::X2Neg,
        Modifier::Dz,
        Modifier::Dw,
    ];

    /// The 4-bit code of a source token.
    pub fn code(self) -> u32 {
        self as u32
    }

    /// The modifier of a code, if ps_1_x has one.
    pub fn from_code(code: u32) -> Option<Modifier> {
        Modifier::ALL.get(code as usize).copied()
    }

    /// Whether the source is negated.
    pub fn negated(self) -> bool {
        matches!(
            self,
            Modifier::Neg | Modifier::BiasNeg | Modifier::Bx2Neg | Modifier::X2Neg
        )
    }

    /// The suffix after the register (`_bias`), as Microsoft prints it.
    pub fn suffix(self) -> &'static str {
        match self {
            Modifier::Bias | Modifier::BiasNeg => "_bias",
            Modifier::Bx2 | Modifier::Bx2Neg => "_bx2",
            Modifier::X2 | Modifier::X2Neg => "_x2",
            Modifier::Dz => "_dz",
            Modifier::Dw => "_dw",
            Modifier::None | Modifier::Neg | Modifier::Comp => "",
        }
    }
}

/// A destination: register, write mask, shift and `_sat`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Dest {
    /// The register written.
    pub reg: Reg,
    /// The components written.
    pub mask: WriteMask,
    /// The result shift as a power of two: 1 `_x2`, 2 `_x4`, 3 `_x8`, -1
    /// `_d2`, -2 `_d4`, -3 `_d8` (bits 24–27 of the token, four-bit signed).
    pub shift: i8,
    /// `_sat`.
    pub sat: bool,
    /// Where the operand is written (empty for a read token).
    pub span: Span,
}

/// A source: register, selector or swizzle, modifier.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Source {
    /// The register read.
    pub reg: Reg,
    /// Which component each of x, y, z, w reads.
    pub swizzle: Swizzle,
    /// The source modifier.
    pub modifier: Modifier,
    /// Where the operand is written (empty for a read token).
    pub span: Span,
}

/// One instruction (`def` and `phase` included).
#[derive(Clone, Debug, PartialEq)]
pub struct Instr {
    /// The operation.
    pub op: Opcode,
    /// Whether it is co-issued with the instruction before it (`+`).
    pub coissue: bool,
    /// The destination (`texkill`'s register too, written as one).
    pub dst: Option<Dest>,
    /// The sources in order.
    pub src: Vec<Source>,
    /// `def`'s four values, as their bits.
    pub def: Option<[u32; 4]>,
    /// The whole statement.
    pub span: Span,
    /// The mnemonic.
    pub base_span: Span,
}

/// A ps_1_x shader: its version and its instructions in order.
#[derive(Clone, Debug, PartialEq)]
pub struct Program {
    /// ps_1_1, ps_1_2, ps_1_3 or ps_1_4.
    pub profile: Profile,
    /// The instructions, `def`s and `phase` included.
    pub instrs: Vec<Instr>,
}

impl Instr {
    /// Microsoft's slots of this instruction: nothing for `def`, `phase`,
    /// `nop` and the second of a co-issued pair; otherwise the row's count
    /// and split.
    pub fn slots(&self) -> SlotCount {
        if self.coissue || self.op.class() == Class::Declaration {
            return SlotCount::default();
        }
        self.op.info().count(SlotTable::Fxc, false, false)
    }
}

impl Program {
    /// Microsoft's slot count of the whole shader (both phases of ps_1_4).
    pub fn slots(&self) -> SlotCount {
        self.instrs.iter().map(Instr::slots).sum()
    }
}

/// What [`load`] makes of a ps_1_x source: the program and a [`Shader`] of
/// it for the stages that count.
#[derive(Clone, Debug)]
pub struct Loaded {
    /// The program with every ps_1_x detail.
    pub program: Program,
    /// The validated shader (operations, registers, slots).
    pub shader: ir::Shader,
}

/// Parses and checks a ps_1_x source, gathering every diagnostic; the
/// profile is the one its version line names.
/// The shader carries its lowering for the emulator, the range of its
/// registers `max_value` (D3DCAPS9.PixelShader1xMaxValue).
pub fn load(file: &SourceFile, profile: Profile, max_value: f32) -> Result<Loaded, Diagnostics> {
    let program = text::parse(&file.text, profile)?;
    rules::check(&program)?;
    let lowered = run::lower(&program, file, max_value);
    let mut shader = shader_of(&program);
    if let Ok(l) = &lowered {
        // What a draw feeds and binds is the lowering's: the same names.
        let (inputs, samplers) = (l.program().inputs.clone(), l.program().samplers.clone());
        shader = shader.with_declarations(inputs, samplers);
    }
    let shader = shader.running_as(lowered);
    Ok(Loaded { program, shader })
}

/// The IR of a checked program: each instruction but `def` with its
/// operation, `_sat`, registers, write mask, swizzle, negation and span,
/// and its slots; `def`s as float constants. The other ps_1_x modifiers
/// are no part of the IR (nothing that reads it runs ps_1_x).
fn shader_of(program: &Program) -> ir::Shader {
    let mut p = ir::Program {
        profile: program.profile,
        ..ir::Program::default()
    };
    let mut slots = Vec::new();
    for i in &program.instrs {
        let origin = ir::Origin {
            span: i.span,
            repeat: None,
        };
        if let Some(bits) = i.def {
            p.float_defs.push(ir::FloatDef {
                index: i.dst.map_or(0, |d| d.reg.index),
                value: bits.map(f32::from_bits),
                origin,
            });
            continue;
        }
        let count = i.slots();
        slots.push(ir::Slots {
            fxc: count,
            documented: count,
        });
        p.instructions.push(ir::Instruction {
            op: i.op,
            sat: i.dst.is_some_and(|d| d.sat),
            pp: false,
            centroid: false,
            compare: None,
            predicate: None,
            dst: i.dst.map(|d| ir::Dst {
                reg: d.reg,
                mask: d.mask,
                relative: None,
            }),
            src: i
                .src
                .iter()
                .map(|s| ir::Src {
                    reg: s.reg,
                    relative: None,
                    swizzle: s.swizzle,
                    modifier: if s.modifier.negated() {
                        ir::SrcMod::Neg
                    } else {
                        ir::SrcMod::None
                    },
                })
                .collect(),
            origin,
        });
    }
    let n = p.instructions.len();
    let info = ir::Info {
        matching: vec![None; n],
        labels: Default::default(),
        main_end: n as u32,
        slots,
    };
    ir::Shader::new_validated(p, info)
}
