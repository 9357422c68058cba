//! ps_1_x as the emulator and the translation run it: a checked
//! [`Program`] lowered into IR operations of ps_2_0's kind, with every
//! ps_1_x rule spelled out as arithmetic, so that neither backend needs a
//! second instruction set.
//!
//! The rules, each from Microsoft's ps_1_x reference pages (the register
//! page "ps_1_1__ps_1_2__ps_1_3__ps_1_4 Registers", the source- and
//! instruction-modifier pages, and each instruction's page):
//!
//! * **Ranges.** `c#` reads as [-1, 1] ("Constant register: -1 to +1",
//!   values set by `SetPixelShaderConstantF` and `def` alike; Wine's
//!   `constant_clamp_ps_test`, dlls/d3d9/tests/visual.c, holds Windows to
//!   clamped constants in ps_1_x and unclamped ones in ps_2_0); `v#` reads
//!   as [0, 1] ("Color
//!   register: 0 to 1"; the emulator clamps them where they enter, as for
//!   ps_2_0); every register a ps_1_x instruction writes holds
//!   [-PixelShader1xMaxValue, +PixelShader1xMaxValue] (D3DCAPS9's
//!   `PixelShader1xMaxValue`: "implementations must allow data within this
//!   range to pass through pixel processing unmodified"), so each result is
//!   clamped to it; ps30 takes it as a cap, [`DEFAULT_MAX_VALUE`] unless
//!   told.
//! * **Source modifiers** (before the instruction reads the value, on the
//!   selected components): `_bias` x − 0.5, `_bx2` 2x − 1, `1-` 1 − x,
//!   `_x2` 2x, each negated after where `-` stands with it.
//! * **Instruction modifiers**, in order: the shift (`_x2` ×2, `_x4` ×4,
//!   `_x8` ×8, `_d2` ÷2, `_d4` ÷4, `_d8` ÷8), then `_sat` ([0, 1]), then
//!   the register range.
//! * **Co-issue.** The two instructions of a pair execute together: both
//!   read their sources before either writes (each writes its own
//!   components, colour or alpha).
//! * `cnd`: `src0 > 0.5 ? src1 : src2` per component (ps_1_1–ps_1_3 read
//!   `r0.a` as src0), as `0.5 - src0 >= 0 ? src2 : src1` (exact: a
//!   difference of two floats is 0 only where they are equal). `cmp`:
//!   `src0 >= 0 ? src1 : src2`. `lrp`: `src0·src1 + (1 − src0)·src2`.
//! * `tex t#` samples stage # at texture coordinate # into `t#`;
//!   `texcoord t#` writes the coordinate clamped to [0, 1] with alpha 1
//!   ("UVW1"); `texkill` discards the pixel where any of x, y, z (not w) is
//!   below 0, of the coordinate (`t#`) or of `r#` (ps_1_4 phase 2).
//! * ps_1_4: `texld r#, src` samples stage # (the destination's number) at
//!   `src` (a coordinate `t#` or, after `phase`, an `r#`), `texcrd` copies
//!   a coordinate; `_dz`/`_dw` divide x and y by z or w; `texdepth r5`
//!   writes r5.r / r5.g as the pixel's depth (1 where r5.g is 0), clamped
//!   to [0, 1]; `phase` changes nothing at run time (the validator already
//!   refuses what reads an alpha it dropped).
//! * `r0` at the end is the pixel's colour, saturated: vkd3d's
//!   `ps1-sampler.shader_test` (lines 49–52, recorded on Windows) reads 0
//!   where a ps_1_4 shader leaves −0.3 in r0 of a float target, and
//!   vkd3d-shader writes ps_1_x's r0 to the colour output with `_sat`.
//!
//! * The texture-address instructions: `texreg2ar`/`texreg2gb`/`texreg2rgb`
//!   sample stage # at (a, r), (g, b), (r, g, b) of their source;
//!   `texm3x2pad`/`texm3x3pad` take the dot product of coordinate # (xyz)
//!   with the source's rgb as one row, `texm3x2tex`/`texm3x3tex` the last
//!   row and sample stage # at the rows (u, v, and w where the texture has
//!   it), `texm3x3` writes (rows, 1), `texdp3` writes the product in every
//!   component and `texdp3tex` samples at (product, 0).
//!
//! * `texm3x2depth`: z / w of its two rows (z the pad's) as the depth, 1
//!   where w is 0, saturated as `texdepth`'s is (its page: "Be sure to
//!   clamp z/w to be in the range of (0-1)"). `texm3x3spec` and
//!   `texm3x3vspec` reflect the eye ray E about the rows N, R =
//!   2·[(N·E)/(N·N)]·N − E (their pages), and sample stage # at R; E is the
//!   constant register (read as [-1, 1]) or, for vspec, the w components of
//!   the three rows' coordinates. The quotient is `rcp` then `mul`.
//! * Bump-environment mapping, with stage state D3DTSS_BUMPENVMAT00 … 11,
//!   BUMPENVLSCALE and BUMPENVLOFFSET ([`BumpEnv`], 0.0 by default as the
//!   D3DTEXTURESTAGESTATETYPE page gives them): `texbem t(m), t(n)` samples
//!   stage m at u' = u + M00·t(n).r + M10·t(n).g, v' = v + M01·t(n).r +
//!   M11·t(n).g (texbem's page; u, v coordinate m, M stage m's, the
//!   destination's); `texbeml` then multiplies rgb by t(n).b·LSCALE +
//!   LOFFSET of stage m, alpha as sampled, nothing saturated (texbeml's
//!   page, whose formula has no clamp); `bem dst.rg, src0, src1` (ps_1_4)
//!   writes dst.r = src0.r + M00·src1.r + M10·src1.g, dst.g = src0.g +
//!   M01·src1.r + M11·src1.g with stage n's matrix, n the destination
//!   register's number (bem's page), then the result modifiers and range as
//!   any arithmetic. The perturbation is read signed, as the register holds
//!   it. Wine's `texbem_test` (dlls/d3d9/tests/visual.c), run on Windows,
//!   holds the page's orientation: with M01 = 0.5, M10 = -0.5 a signed
//!   dv = -0.5 moves u by +0.25 onto its white spot (the DirectX 8 page's
//!   comment, u = u1 + mat00·r + mat01·g, would read black there).
//!
//! Register plan of the lowered shader: ps_1_x's `r#` are `r0`–`r5`,
//! ps_1_1–ps_1_3's `t#` as registers `r8`–`r11`, the rows of a texm sequence `r12`,
//! the clamped copies of
//! `c0`–`c7` `r16`–`r23`, scratch `r24`–`r31`; `c8`–`c11` hold the numbers
//! the rules need; `c12`–`c17` stage 0–5's bump matrix and `c18`–`c23`
//! their luminance scale and offset, which the draw sets from its stage
//! state ([`bump_constants`]; unset, Direct3D 9's 0). Inputs keep their names (`t#` coordinates, `v#`
//! colours), so draws feed them as ps_2_0's. Slots: the first operation of
//! each instruction carries its slots, the rest none, so executed counts
//! are the ps_1_x program's.

use super::{Dest, Instr, Modifier, Program, Source};
use crate::core::diag::SourceFile;
use crate::core::ir::{
    self, Dst, FloatDef, InputDecl, Instruction, Origin, Reg, SamplerDecl, Src, SrcMod, Swizzle,
    WriteMask,
};
use crate::core::isa::{Opcode, RegFile, SamplerType, SlotCount};
use crate::core::profile::Profile;
use std::collections::BTreeSet;

/// D3DCAPS9.PixelShader1xMaxValue unless told otherwise: 8, the least a
/// device that runs ps_1_4 has (`texcrd`'s page: "for pixel shader version
/// 1_4, D3DCAPS9.PixelShader1xMaxValue must be a minimum of eight"; the cap's
/// page: at least 1 for any pixel-shader hardware). Devices may report
/// more; `--ps1-max-value` sets it.
pub const DEFAULT_MAX_VALUE: f32 = 8.0;

/// ps_1_1–ps_1_3's `t#` as registers: `r8`–`r11`.
const TEX_BASE: u32 = 8;
/// The clamped copies of `c0`–`c7`: `r16`–`r23`.
const CONST_BASE: u32 = 16;
/// The result of the first and of the second instruction of a pair.
const RESULT: [u32; 2] = [24, 25];
/// The rows of a texm sequence, one component each.
const ROWS: u32 = 12;
/// Modified sources (three) and one more scratch register.
const SOURCE: u32 = 26;
const SPARE: u32 = 29;
/// `c8` = (0.5, 1, 2, 0), `c9` = (max, −max, −1, 0), `c10` = (2, 4, 8, 1),
/// `c11` = (1/2, 1/4, 1/8, 1).
const K: u32 = 8;
const RANGE: u32 = 9;
const UP: u32 = 10;
const DOWN: u32 = 11;
/// `c12`–`c17`: stage #'s bump-environment matrix (M00, M01, M10, M11);
/// `c18`–`c23`: its luminance (LSCALE, LOFFSET, 0, 0). The draw fills
/// them ([`bump_constants`]); unset they read 0, Direct3D 9's defaults.
pub const BUMP_MATRIX: u32 = 12;
/// See [`BUMP_MATRIX`].
pub const BUMP_LUMINANCE: u32 = 18;
/// Texture stages that carry bump-environment state for ps_1_x: ps_1_4's
/// six (`r0`–`r5`); ps_1_1–ps_1_3 use the first four.
pub const BUMP_STAGES: u32 = 6;

/// One texture stage's bump-environment state (D3DTEXTURESTAGESTATETYPE):
/// D3DTSS_BUMPENVMAT00/01/10/11, D3DTSS_BUMPENVLSCALE and
/// D3DTSS_BUMPENVLOFFSET. Each defaults to 0.0 (Microsoft's
/// D3DTEXTURESTAGESTATETYPE page and the managed TextureState pages).
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct BumpEnv {
    /// M00, M01, M10, M11.
    pub matrix: [f32; 4],
    /// D3DTSS_BUMPENVLSCALE.
    pub lscale: f32,
    /// D3DTSS_BUMPENVLOFFSET.
    pub loffset: f32,
}

/// The two constants a draw sets for `stage`'s state (`None` past
/// [`BUMP_STAGES`]): `(register, value)` for the matrix and the luminance.
pub fn bump_constants(stage: u32, env: &BumpEnv) -> Option<[(u32, [f32; 4]); 2]> {
    (stage < BUMP_STAGES).then(|| {
        [
            (BUMP_MATRIX + stage, env.matrix),
            (BUMP_LUMINANCE + stage, [env.lscale, env.loffset, 0.0, 0.0]),
        ]
    })
}

/// Lowers a checked program; `Err` names the first thing ps30 does not run
/// and its line in `file`.
pub fn lower(program: &Program, file: &SourceFile, max_value: f32) -> Result<ir::Shader, String> {
    let mut l = Lower {
        profile: program.profile,
        new: program.profile == Profile::Ps1_4,
        out: Vec::new(),
        slots: Vec::new(),
        charge: SlotCount::default(),
        origin: Origin::default(),
        inputs: BTreeSet::new(),
        samplers: BTreeSet::new(),
        pending: None,
        row: 0,
    };
    l.clamp_constants(program);
    for (i, x) in program.instrs.iter().enumerate() {
        if x.op == Opcode::Def {
            continue;
        }
        l.origin = Origin::at(x.span);
        if matches!(x.op, Opcode::Phase | Opcode::Nop) {
            // Nothing happens; a `nop` of the lowering stands for it, so
            // that per-line counts find every instruction.
            l.charge = SlotCount::default();
            l.nop();
            continue;
        }
        l.charge = x.slots();
        let paired = program.instrs.get(i + 1).is_some_and(|n| n.coissue);
        l.instruction(x, paired).map_err(|what| {
            format!(
                "{what} (line {}): ps30 does not run it yet",
                file.line_of(x.span.start)
            )
        })?;
    }
    l.flush();
    l.origin = Origin::default();
    l.emit(
        Opcode::Mov,
        true,
        Dst {
            reg: reg(RegFile::ColorOut, 0),
            relative: None,
            mask: WriteMask::ALL,
        },
        vec![Src::plain(reg(RegFile::Temp, 0))],
    );
    Ok(l.finish(program, max_value))
}

fn reg(file: RegFile, index: u32) -> Reg {
    Reg { file, index }
}

fn temp(index: u32, mask: u8) -> Dst {
    Dst {
        reg: reg(RegFile::Temp, index),
        relative: None,
        mask: WriteMask(mask),
    }
}

/// Component `c` of a constant, replicated.
fn k(index: u32, c: u8) -> Src {
    Src {
        swizzle: Swizzle::replicate(c),
        ..Src::plain(reg(RegFile::Const, index))
    }
}

/// Component `c` of what `s` selects, replicated.
fn pick(s: Src, c: u8) -> Src {
    Src {
        swizzle: Swizzle::replicate(s.swizzle.0[usize::from(c)]),
        ..s
    }
}

fn neg(s: Src) -> Src {
    Src {
        modifier: match s.modifier {
            SrcMod::Neg => SrcMod::None,
            _ => SrcMod::Neg,
        },
        ..s
    }
}

struct Lower {
    profile: Profile,
    new: bool,
    out: Vec<Instruction>,
    slots: Vec<ir::Slots>,
    /// The slots the next operation carries.
    charge: SlotCount,
    origin: Origin,
    /// Input registers read (`t#`, `v#`), samplers sampled.
    inputs: BTreeSet<(RegFile, u32)>,
    samplers: BTreeSet<u32>,
    /// The first instruction of a pair, computed, its write held back until
    /// the second has read its sources.
    pending: Option<(Dest, u32, Origin)>,
    /// The next row of a texm sequence.
    row: u8,
}

impl Lower {
    fn emit(&mut self, op: Opcode, sat: bool, dst: Dst, src: Vec<Src>) {
        let charge = std::mem::take(&mut self.charge);
        self.slots.push(ir::Slots {
            fxc: charge,
            documented: charge,
        });
        self.out.push(Instruction {
            op,
            sat,
            pp: false,
            centroid: false,
            compare: None,
            predicate: None,
            dst: Some(dst),
            src,
            origin: self.origin.clone(),
        });
    }

    fn nop(&mut self) {
        self.slots.push(ir::Slots::default());
        self.out.push(Instruction {
            op: Opcode::Nop,
            sat: false,
            pp: false,
            centroid: false,
            compare: None,
            predicate: None,
            dst: None,
            src: Vec::new(),
            origin: self.origin.clone(),
        });
    }

    /// `c#` as ps_1_x reads it: a copy clamped to [-1, 1], made once at the
    /// start for every constant the program reads.
    fn clamp_constants(&mut self, program: &Program) {
        let read: BTreeSet<u32> = program
            .instrs
            .iter()
            .flat_map(|x| x.src.iter())
            .filter(|s| s.reg.file == RegFile::Const)
            .map(|s| s.reg.index)
            .collect();
        for n in read {
            let c = Src::plain(reg(RegFile::Const, n));
            let t = Src::plain(reg(RegFile::Temp, CONST_BASE + n));
            self.emit(
                Opcode::Max,
                false,
                temp(CONST_BASE + n, 15),
                vec![c, k(RANGE, 2)],
            );
            self.emit(
                Opcode::Min,
                false,
                temp(CONST_BASE + n, 15),
                vec![t, k(K, 1)],
            );
        }
    }

    /// Where a ps_1_x register lives in the lowered shader, read as a value.
    fn value(&mut self, r: Reg) -> Reg {
        match r.file {
            RegFile::Texture if !self.new => reg(RegFile::Temp, TEX_BASE + r.index),
            RegFile::Const => reg(RegFile::Temp, CONST_BASE + r.index),
            RegFile::Texture | RegFile::Input => {
                self.inputs.insert((r.file, r.index));
                r
            }
            _ => r,
        }
    }

    /// A texture coordinate `t#` as an input.
    fn coordinate(&mut self, n: u32) -> Src {
        self.inputs.insert((RegFile::Texture, n));
        Src::plain(reg(RegFile::Texture, n))
    }

    /// A source with its modifier applied (into scratch `into` where it
    /// has one beyond negation).
    fn read(&mut self, s: &Source, into: u32) -> Src {
        let base = Src {
            reg: self.value(s.reg),
            relative: None,
            swizzle: s.swizzle,
            modifier: SrcMod::None,
        };
        let t = temp(into, 15);
        let (op, src) = match s.modifier {
            Modifier::None | Modifier::Dz | Modifier::Dw => return base,
            Modifier::Neg => return neg(base),
            Modifier::Bias | Modifier::BiasNeg => (Opcode::Add, vec![base, neg(k(K, 0))]),
            Modifier::Bx2 | Modifier::Bx2Neg => (Opcode::Mad, vec![base, k(K, 2), neg(k(K, 1))]),
            Modifier::Comp => (Opcode::Add, vec![neg(base), k(K, 1)]),
            Modifier::X2 | Modifier::X2Neg => (Opcode::Add, vec![base, base]),
        };
        self.emit(op, false, t, src);
        let out = Src::plain(t.reg);
        if s.modifier.negated() {
            neg(out)
        } else {
            out
        }
    }

    /// The register a ps_1_x destination names, in the lowered shader.
    fn target(&self, d: &Dest) -> Dst {
        let index = match d.reg.file {
            RegFile::Texture => TEX_BASE + d.reg.index,
            _ => d.reg.index,
        };
        temp(index, d.mask.0)
    }

    /// Writes result `r` to `d`: shift, `_sat`, the register range.
    fn write(&mut self, d: &Dest, r: u32) {
        let rs = Src::plain(reg(RegFile::Temp, r));
        let to = self.target(d);
        if d.shift != 0 {
            let factor = match d.shift {
                s @ 1..=3 => k(UP, s as u8 - 1),
                s => k(DOWN, (-s).clamp(1, 3) as u8 - 1),
            };
            self.emit(Opcode::Mul, false, temp(r, d.mask.0), vec![rs, factor]);
        }
        if d.sat {
            self.emit(Opcode::Mov, true, to, vec![rs]);
        } else {
            self.emit(Opcode::Max, false, temp(r, d.mask.0), vec![rs, k(RANGE, 1)]);
            self.emit(Opcode::Min, false, to, vec![rs, k(RANGE, 0)]);
        }
    }

    /// Writes the held-back first instruction of a pair.
    fn flush(&mut self) {
        if let Some((d, r, origin)) = self.pending.take() {
            let here = std::mem::replace(&mut self.origin, origin);
            self.write(&d, r);
            self.origin = here;
        }
    }

    /// One instruction; `paired`: the next is co-issued with it.
    fn instruction(&mut self, x: &Instr, paired: bool) -> Result<(), String> {
        let second = x.coissue && self.pending.is_some();
        if !x.coissue {
            self.flush();
        }
        let r = RESULT[usize::from(second)];
        let d = x
            .dst
            .ok_or_else(|| format!("`{}` without a destination", x.op.info().mnemonic))?;
        match x.op {
            Opcode::Tex => self.tex(&d, r),
            Opcode::TexCoord => {
                let c = self.coordinate(d.reg.index);
                self.emit(Opcode::Mov, true, temp(r, 7), vec![c]);
                self.emit(Opcode::Mov, false, temp(r, 8), vec![k(K, 1)]);
                self.write(
                    &Dest {
                        mask: WriteMask::ALL,
                        ..d
                    },
                    r,
                );
            }
            Opcode::TexKill => {
                let reg = match d.reg.file {
                    RegFile::Temp => d.reg,
                    _ => {
                        self.inputs.insert((RegFile::Texture, d.reg.index));
                        d.reg
                    }
                };
                let dst = Dst {
                    reg,
                    relative: None,
                    mask: WriteMask(7),
                };
                self.emit(Opcode::TexKill, false, dst, Vec::new());
            }
            Opcode::TexLd | Opcode::TexCrd => self.texld(x, &d, r)?,
            Opcode::TexDepth => {
                let r5 = |c: u8| Src {
                    swizzle: Swizzle::replicate(c),
                    ..Src::plain(reg(RegFile::Temp, 5))
                };
                self.depth(r5(0), r5(1));
            }
            Opcode::TexReg2Ar | Opcode::TexReg2Gb | Opcode::TexReg2Rgb => self.texreg(x, &d, r)?,
            Opcode::TexBem | Opcode::TexBemL => self.texbem(x, &d, r)?,
            Opcode::TexDp3
            | Opcode::TexDp3Tex
            | Opcode::TexM3x2Pad
            | Opcode::TexM3x2Tex
            | Opcode::TexM3x2Depth
            | Opcode::TexM3x3Pad
            | Opcode::TexM3x3Tex
            | Opcode::TexM3x3Spec
            | Opcode::TexM3x3VSpec
            | Opcode::TexM3x3 => self.matrix_row(x, &d, r)?,
            op if op.class() == crate::core::isa::Class::Texture => {
                return Err(format!("`{}`", op.info().mnemonic));
            }
            _ => {
                self.arithmetic(x, &d, r)?;
                if x.coissue || !paired {
                    self.write(&d, r);
                } else {
                    self.pending = Some((d, r, self.origin.clone()));
                }
                return Ok(());
            }
        }
        Ok(())
    }

    /// `tex t#`: sample stage # at coordinate #.
    fn tex(&mut self, d: &Dest, r: u32) {
        let n = d.reg.index;
        let c = self.coordinate(n);
        self.sample(r, 15, c, n);
        self.write(
            &Dest {
                mask: WriteMask::ALL,
                ..*d
            },
            r,
        );
    }

    fn sample(&mut self, r: u32, mask: u8, coordinate: Src, stage: u32) {
        self.samplers.insert(stage);
        let s = Src::plain(reg(RegFile::Sampler, stage));
        self.emit(Opcode::TexLd, false, temp(r, mask), vec![coordinate, s]);
    }

    /// ps_1_4's `texld` and `texcrd`, `_dz`/`_dw` included.
    /// (The validator holds `_dz` to texld's `r#` and a `texcrd` with `_dw`
    /// to `.rg`, so only x and y of a divided coordinate are ever read.)
    fn texld(&mut self, x: &Instr, d: &Dest, r: u32) -> Result<(), String> {
        let s = x.src.first().ok_or("`texld` without a source")?;
        let mut c = Src {
            reg: self.value(s.reg),
            relative: None,
            swizzle: s.swizzle,
            modifier: SrcMod::None,
        };
        if matches!(s.modifier, Modifier::Dz | Modifier::Dw) {
            let by = if s.modifier == Modifier::Dz { 2 } else { 3 };
            let divisor = Src {
                swizzle: Swizzle::replicate(c.swizzle.0[by]),
                ..c
            };
            self.emit(Opcode::Rcp, false, temp(SPARE, 1), vec![divisor]);
            let inv = Src {
                swizzle: Swizzle::replicate(0),
                ..Src::plain(reg(RegFile::Temp, SPARE))
            };
            self.emit(Opcode::Mov, false, temp(SOURCE, 15), vec![c]);
            self.emit(Opcode::Mul, false, temp(SOURCE, 3), vec![c, inv]);
            c = Src::plain(reg(RegFile::Temp, SOURCE));
        }
        if x.op == Opcode::TexLd {
            self.sample(r, 15, c, d.reg.index);
        } else {
            self.emit(Opcode::Mov, false, temp(r, 15), vec![c]);
        }
        self.write(d, r);
        Ok(())
    }

    /// `texreg2ar`, `texreg2gb`, `texreg2rgb`: sample stage # (the
    /// destination's number) at (a, r), (g, b) or (r, g, b) of the source
    /// register.
    fn texreg(&mut self, x: &Instr, d: &Dest, r: u32) -> Result<(), String> {
        let s = x
            .src
            .first()
            .ok_or("a texture-address instruction without a source")?;
        let from = self.read(s, SOURCE);
        let pick: [u8; 4] = match x.op {
            Opcode::TexReg2Ar => [3, 0, 0, 0],
            Opcode::TexReg2Gb => [1, 2, 2, 2],
            _ => [0, 1, 2, 2],
        };
        let coordinate = Src {
            swizzle: Swizzle(pick.map(|c| from.swizzle.0[c as usize])),
            ..from
        };
        self.sample(r, 15, coordinate, d.reg.index);
        self.write(
            &Dest {
                mask: WriteMask::ALL,
                ..*d
            },
            r,
        );
        Ok(())
    }

    /// The texm and texdp3 family: one dot product of texture coordinate
    /// # (the destination's number, xyz) with the source register's rgb
    /// per instruction. `texm3x2pad`/`texm3x3pad` keep theirs in the next
    /// component of the row register; `texm3x2tex`/`texm3x3tex` sample the
    /// destination's stage at the rows, `texm3x3` writes (rows, 1),
    /// `texdp3` the product in every component, `texdp3tex` samples at
    /// (product, 0).
    fn matrix_row(&mut self, x: &Instr, d: &Dest, r: u32) -> Result<(), String> {
        let s = x
            .src
            .first()
            .ok_or("a texture-address instruction without a source")?;
        let from = self.read(s, SOURCE);
        let n = d.reg.index;
        let c = self.coordinate(n);
        let rows = Src::plain(reg(RegFile::Temp, ROWS));
        let whole = Dest {
            mask: WriteMask::ALL,
            ..*d
        };
        match x.op {
            Opcode::TexDp3 => {
                self.emit(Opcode::Dp3, false, temp(r, 15), vec![c, from]);
                self.write(&whole, r);
                return Ok(());
            }
            Opcode::TexDp3Tex => {
                self.emit(Opcode::Dp3, false, temp(ROWS, 1), vec![c, from]);
                self.emit(Opcode::Mov, false, temp(ROWS, 2), vec![k(K, 3)]);
                self.sample(r, 15, rows, n);
                self.write(&whole, r);
                return Ok(());
            }
            _ => {}
        }
        let row = self.row.min(2);
        self.emit(Opcode::Dp3, false, temp(ROWS, 1 << row), vec![c, from]);
        if matches!(x.op, Opcode::TexM3x2Pad | Opcode::TexM3x3Pad) {
            self.row += 1;
            return Ok(());
        }
        self.row = 0;
        let row = |c: u8| Src {
            swizzle: Swizzle::replicate(c),
            ..rows
        };
        match x.op {
            Opcode::TexM3x2Depth => {
                self.depth(row(0), row(1));
                return Ok(());
            }
            Opcode::TexM3x3Spec | Opcode::TexM3x3VSpec => {
                let eye = self.eye(x, n)?;
                self.reflect(eye);
                self.sample(r, 15, rows, n);
                self.write(&whole, r);
                return Ok(());
            }
            _ => {}
        }
        if x.op == Opcode::TexM3x3 {
            self.emit(Opcode::Mov, false, temp(r, 7), vec![rows]);
            self.emit(Opcode::Mov, false, temp(r, 8), vec![k(K, 1)]);
        } else {
            if x.op == Opcode::TexM3x2Tex {
                self.emit(Opcode::Mov, false, temp(ROWS, 4), vec![k(K, 3)]);
            }
            self.sample(r, 15, rows, n);
        }
        self.write(&whole, r);
        Ok(())
    }

    /// `num / den` (1 where `den` is 0), saturated, as the pixel's depth:
    /// `texdepth` (r5.r / r5.g) and `texm3x2depth` (z / w of its rows).
    fn depth(&mut self, num: Src, den: Src) {
        let t = Src {
            swizzle: Swizzle::replicate(0),
            ..Src::plain(reg(RegFile::Temp, SPARE))
        };
        self.emit(Opcode::Rcp, false, temp(SPARE, 1), vec![den]);
        self.emit(Opcode::Mul, false, temp(SPARE, 1), vec![num, t]);
        let zero = Src {
            modifier: SrcMod::NegAbs,
            ..den
        };
        self.emit(Opcode::Cmp, false, temp(SPARE, 1), vec![zero, k(K, 1), t]);
        let depth = Dst {
            reg: reg(RegFile::DepthOut, 0),
            relative: None,
            mask: WriteMask(1),
        };
        self.emit(Opcode::Mov, true, depth, vec![t]);
    }

    /// `into.xy = add.xy + by.r·(M00, M01) + by.g·(M10, M11)`, the matrix
    /// stage `stage`'s bump-environment state ([`BUMP_MATRIX`]).
    fn bump(&mut self, stage: u32, add: Src, by: Src, into: Dst) -> Result<(), String> {
        if stage >= BUMP_STAGES {
            return Err(format!("bump-environment state of stage {stage}"));
        }
        let m = |sw: [u8; 4]| Src {
            swizzle: Swizzle(sw),
            ..Src::plain(reg(RegFile::Const, BUMP_MATRIX + stage))
        };
        let xy = Dst {
            mask: WriteMask(into.mask.0 & 3),
            ..into
        };
        let first = pick(by, 0);
        self.emit(Opcode::Mad, false, xy, vec![first, m([0, 1, 0, 1]), add]);
        let second = pick(by, 1);
        let sum = Src::plain(into.reg);
        self.emit(Opcode::Mad, false, xy, vec![second, m([2, 3, 2, 3]), sum]);
        Ok(())
    }

    /// `texbem t(m), t(n)` and `texbeml`: sample stage m at its coordinate
    /// moved by t(n)'s (r, g) through stage m's matrix; `texbeml` then
    /// scales the colour's rgb by t(n).b · LSCALE + LOFFSET (alpha as
    /// sampled).
    fn texbem(&mut self, x: &Instr, d: &Dest, r: u32) -> Result<(), String> {
        let s = x.src.first().ok_or("`texbem` without a source")?;
        let from = self.read(s, SOURCE);
        let m = d.reg.index;
        let c = self.coordinate(m);
        let at = Src::plain(reg(RegFile::Temp, SPARE));
        self.emit(Opcode::Mov, false, temp(SPARE, 15), vec![c]);
        self.bump(m, at, from, temp(SPARE, 3))?;
        self.sample(r, 15, at, m);
        if x.op == Opcode::TexBemL {
            let lum = |c: u8| Src {
                swizzle: Swizzle::replicate(c),
                ..Src::plain(reg(RegFile::Const, BUMP_LUMINANCE + m))
            };
            let l = vec![pick(from, 2), lum(0), lum(1)];
            self.emit(Opcode::Mad, false, temp(SPARE, 1), l);
            let rs = Src::plain(reg(RegFile::Temp, r));
            let by = pick(at, 0);
            self.emit(Opcode::Mul, false, temp(r, 7), vec![rs, by]);
        }
        let whole = Dest {
            mask: WriteMask::ALL,
            ..*d
        };
        self.write(&whole, r);
        Ok(())
    }

    /// The eye ray of `texm3x3spec` (its constant, read as [-1, 1]) or of
    /// `texm3x3vspec` (the w of coordinates n − 2, n − 1 and n), in
    /// scratch `SOURCE + 1`.
    fn eye(&mut self, x: &Instr, n: u32) -> Result<Src, String> {
        if x.op == Opcode::TexM3x3Spec {
            let c = x.src.get(1).ok_or("`texm3x3spec` without its eye ray")?;
            return Ok(self.read(c, SOURCE + 1));
        }
        let first = n.checked_sub(2).ok_or("`texm3x3vspec` below stage 2")?;
        for (i, stage) in (first..=n).enumerate() {
            let w = pick(self.coordinate(stage), 3);
            self.emit(Opcode::Mov, false, temp(SOURCE + 1, 1 << i), vec![w]);
        }
        Ok(Src::plain(reg(RegFile::Temp, SOURCE + 1)))
    }

    /// The rows N (xyz of the row register) become R = 2·[(N·E)/(N·N)]·N − E,
    /// the quotient as ps_2_0 spells one (`rcp`, `mul`).
    fn reflect(&mut self, eye: Src) {
        let rows = Src::plain(reg(RegFile::Temp, ROWS));
        let t = |c: u8| Src {
            swizzle: Swizzle::replicate(c),
            ..Src::plain(reg(RegFile::Temp, SPARE))
        };
        self.emit(Opcode::Dp3, false, temp(SPARE, 1), vec![rows, eye]);
        self.emit(Opcode::Dp3, false, temp(SPARE, 2), vec![rows, rows]);
        self.emit(Opcode::Rcp, false, temp(SPARE, 2), vec![t(1)]);
        self.emit(Opcode::Mul, false, temp(SPARE, 1), vec![t(0), t(1)]);
        self.emit(Opcode::Add, false, temp(SPARE, 1), vec![t(0), t(0)]);
        self.emit(
            Opcode::Mad,
            false,
            temp(ROWS, 7),
            vec![rows, t(0), neg(eye)],
        );
    }

    /// An arithmetic instruction computed into scratch `r` (not written).
    fn arithmetic(&mut self, x: &Instr, d: &Dest, r: u32) -> Result<(), String> {
        let src: Vec<Src> = x
            .src
            .iter()
            .enumerate()
            .map(|(i, s)| self.read(s, SOURCE + i as u32))
            .collect();
        let into = temp(r, d.mask.0);
        match x.op {
            Opcode::Mov
            | Opcode::Add
            | Opcode::Sub
            | Opcode::Mul
            | Opcode::Mad
            | Opcode::Dp3
            | Opcode::Dp4
            | Opcode::Lrp
            | Opcode::Cmp => self.emit(x.op, false, into, src),
            Opcode::Cnd => {
                let [s0, s1, s2] = <[Src; 3]>::try_from(src).map_err(|_| "`cnd` operands")?;
                self.emit(Opcode::Add, false, temp(SPARE, 15), vec![neg(s0), k(K, 0)]);
                let t = Src::plain(reg(RegFile::Temp, SPARE));
                self.emit(Opcode::Cmp, false, into, vec![t, s2, s1]);
            }
            Opcode::Bem => {
                let [s0, s1] = <[Src; 2]>::try_from(src).map_err(|_| "`bem` operands")?;
                self.bump(d.reg.index, s0, s1, into)?;
            }
            op => return Err(format!("`{}`", op.info().mnemonic)),
        }
        Ok(())
    }

    fn finish(self, program: &Program, max_value: f32) -> ir::Shader {
        let mut p = ir::Program {
            profile: self.profile,
            instructions: self.out,
            ..ir::Program::default()
        };
        for x in &program.instrs {
            if let (Some(bits), Some(d)) = (x.def, x.dst) {
                p.float_defs.push(FloatDef {
                    index: d.reg.index,
                    value: bits.map(f32::from_bits),
                    origin: Origin::at(x.span),
                });
            }
        }
        for (index, value) in [
            (K, [0.5, 1.0, 2.0, 0.0]),
            (RANGE, [max_value, -max_value, -1.0, 0.0]),
            (UP, [2.0, 4.0, 8.0, 1.0]),
            (DOWN, [0.5, 0.25, 0.125, 1.0]),
        ] {
            p.float_defs.push(FloatDef {
                index,
                value,
                origin: Origin::default(),
            });
        }
        p.inputs = declarations(&self.inputs);
        p.samplers = self
            .samplers
            .iter()
            .map(|&index| SamplerDecl {
                index,
                ty: SamplerType::Tex2d,
                centroid: false,
                pp: false,
                origin: Origin::default(),
            })
            .collect();
        let n = p.instructions.len();
        let info = ir::Info {
            matching: vec![None; n],
            labels: Default::default(),
            main_end: n as u32,
            slots: self.slots,
        };
        ir::Shader::new_validated(p, info)
    }
}

/// The inputs a ps_1_x shader reads, as ps_2_0 would declare them.
pub fn declarations(inputs: &BTreeSet<(RegFile, u32)>) -> Vec<InputDecl> {
    inputs
        .iter()
        .map(|&(file, index)| InputDecl {
            reg: reg(file, index),
            usage: if file == RegFile::Input {
                "color"
            } else {
                "texcoord"
            }
            .into(),
            usage_index: index,
            mask: WriteMask::ALL,
            centroid: false,
            pp: false,
            origin: Origin::default(),
        })
        .collect()
}
