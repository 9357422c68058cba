//! The rules `D3DAssemble` holds ps_1_x shaders to, each with its code.
//!
//! A walk over the instructions in order, as Microsoft's validator goes:
//! where each instruction may stand (texture instructions first, `def`
//! before everything, ps_1_4's phases), its destination (register type,
//! write mask, shift), its sources (modifiers, selectors, what they read
//! and whether it was written), co-issue, and at the end the slot limits
//! (ps_1_1–ps_1_3: 8 arithmetic; ps_1_4: 6 texture and 8 arithmetic per
//! phase, co-issued pairs counting once) and that `r0` was written. Every
//! rule and code here was read from Microsoft's answers to the probes of
//! `tests/oracle/corpus/asm/profiles/ps_1_*` (`tests/oracle/ps1x.rs`
//! holds ps30 to them).

use super::{Instr, Modifier, Program, Source};
use crate::core::diag::codes::{self, Code};
use crate::core::diag::{Diagnostic, Diagnostics};
use crate::core::ir::{Reg, Span, Swizzle, WriteMask};
use crate::core::isa::{Class, Opcode, RegFile};
use crate::core::profile::Profile;

/// Checks a parsed program: every refusal, or nothing.
pub fn check(p: &Program) -> Result<(), Diagnostics> {
    let mut w = Walk::new(p);
    for (i, instr) in p.instrs.iter().enumerate() {
        w.instruction(i, instr);
    }
    w.finish();
    if w.diags.has_errors() {
        w.diags.sort();
        return Err(w.diags);
    }
    Ok(())
}

/// Component bits: x 1, y 2, z 4, w 8.
const ALPHA: u8 = 8;
const COLOUR: u8 = 7;

/// What the walk knows so far.
struct Walk<'p> {
    p: &'p Program,
    /// ps_1_4 (phases, texld/texcrd into r#).
    new: bool,
    diags: Diagnostics,
    /// Components written of each temporary and texture register.
    temps: [u8; 8],
    texture: [u8; 8],
    /// Temporaries whose alpha the phase marker dropped.
    alpha_lost: [bool; 8],
    /// Texture registers a texm*pad, texkill or texm3x2depth wrote.
    unreadable: [bool; 8],
    /// The highest texture register a texture instruction wrote.
    last_texture: Option<u32>,
    /// The texm sequence in progress: (next instruction's register, rows left).
    texm: Option<(u32, Opcode, u32)>,
    /// Whether an arithmetic instruction came in this phase.
    arithmetic_seen: bool,
    /// Whether any instruction but `def` came.
    body_seen: bool,
    /// Whether the phase marker came, and whether the shader has one.
    after_phase: bool,
    has_phase: bool,
    /// Registers a texture instruction wrote in this phase (ps_1_4).
    tex_written: [bool; 8],
    /// Slots of this phase: (texture, arithmetic).
    counts: (u32, u32),
    /// Whether a phase-1 texld used `_dz`, and where.
    dz_before_phase: bool,
    end: Span,
}

impl<'p> Walk<'p> {
    fn new(p: &'p Program) -> Walk<'p> {
        let end = p
            .instrs
            .iter()
            .map(|i| i.span.end)
            .max()
            .map_or(Span::default(), |e| {
                Span::new(e as usize + 1, e as usize + 1)
            });
        Walk {
            p,
            new: p.profile == Profile::Ps1_4,
            diags: Diagnostics::default(),
            temps: [0; 8],
            texture: [0; 8],
            alpha_lost: [false; 8],
            unreadable: [false; 8],
            last_texture: None,
            texm: None,
            arithmetic_seen: false,
            body_seen: false,
            after_phase: false,
            has_phase: p.instrs.iter().any(|i| i.op == Opcode::Phase),
            tex_written: [false; 8],
            counts: (0, 0),
            dz_before_phase: false,
            end,
        }
    }

    fn err(&mut self, code: Code, span: Span, message: impl Into<String>) {
        let mut d = Diagnostic::coded(code, span, message);
        if span == self.end {
            // Microsoft names the line after the last for what the whole
            // shader breaks; so does ps30, saying why.
            d = d.with_label("the end of the shader");
        }
        self.diags.push(d);
    }

    /// The code of a rule ps_1_1–ps_1_3 and ps_1_4 word apart.
    fn pick(&self, old: Code, new: Code) -> Code {
        if self.new {
            new
        } else {
            old
        }
    }

    fn instruction(&mut self, i: usize, x: &Instr) {
        if x.op == Opcode::Def {
            if self.body_seen {
                let code = self.pick(codes::PS1_DEF_LATE, codes::PS14_DEF_LATE);
                self.err(code, x.span, "`def` must come before every instruction");
            }
            return;
        }
        self.body_seen = true;
        if x.op == Opcode::Phase {
            self.phase(x);
            return;
        }
        let texture = x.op.class() == Class::Texture;
        if self.new {
            self.place_new(x, texture);
        } else {
            self.place_old(x, texture);
        }
        if !self.destination(x) {
            // Microsoft's validator takes nothing from an instruction whose
            // modifiers it refused: what it writes stays unwritten.
            return;
        }
        for (k, s) in x.src.iter().enumerate() {
            self.source(x, k, s);
        }
        self.reads(x);
        if x.coissue {
            self.coissue(i, x);
        }
        self.count(x, texture);
        self.writes(x, texture);
    }

    /// ps_1_1–ps_1_3: texture instructions first, each texture register once,
    /// in increasing order, texm sequences whole.
    fn place_old(&mut self, x: &Instr, texture: bool) {
        if let Some((next, _, _)) = self.texm {
            if !texm_continues(x.op) || x.dst.map(|d| d.reg.index) != Some(next) {
                self.err(
                    codes::PS1_TEXM_INCOMPLETE,
                    x.span,
                    "incomplete texm* sequence",
                );
                self.texm = None;
            }
        }
        if !texture {
            self.arithmetic_seen = true;
            return;
        }
        if self.arithmetic_seen {
            self.err(
                codes::PS1_TEX_AFTER_ARITHMETIC,
                x.span,
                "a tex* instruction after an arithmetic instruction",
            );
        }
        let Some(d) = x.dst.filter(|d| d.reg.file == RegFile::Texture) else {
            return;
        };
        let n = d.reg.index;
        if self.texture[n as usize] != 0 || self.unreadable[n as usize] {
            self.err(
                codes::PS1_TEX_TWICE,
                x.span,
                format!("t{n} already declared"),
            );
        } else if self.last_texture.is_some_and(|l| l > n) {
            self.err(
                codes::PS1_TEX_ORDER,
                x.span,
                "t# registers must appear in sequence",
            );
        }
        self.last_texture = Some(self.last_texture.map_or(n, |l| l.max(n)));
        self.texm = match (x.op, self.texm) {
            (Opcode::TexM3x2Pad, _) => Some((n + 1, x.op, 1)),
            (Opcode::TexM3x3Pad, None) => Some((n + 1, x.op, 2)),
            (Opcode::TexM3x3Pad, Some((_, op, 2))) => Some((n + 1, op, 1)),
            _ => None,
        };
    }

    /// ps_1_4: in each phase texture instructions first, each register once;
    /// texkill and texdepth after the marker when there is one, bem before.
    fn place_new(&mut self, x: &Instr, texture: bool) {
        if !texture {
            self.arithmetic_seen = true;
            if x.op == Opcode::Bem && self.after_phase {
                self.err(
                    codes::PS14_BEM_PLACE,
                    x.span,
                    "bem only before the phase marker",
                );
            }
            return;
        }
        if self.arithmetic_seen {
            self.err(
                codes::PS14_TEX_AFTER_ARITHMETIC,
                x.span,
                "a tex* instruction after an arithmetic instruction in one phase",
            );
        }
        let early = self.has_phase && !self.after_phase;
        if early && x.op == Opcode::TexKill {
            self.err(
                codes::PS14_TEXKILL_BEFORE_PHASE,
                x.span,
                "texkill before the phase marker",
            );
        }
        if early && x.op == Opcode::TexDepth {
            self.err(
                codes::PS14_TEXDEPTH_BEFORE_PHASE,
                x.span,
                "texdepth before the phase marker",
            );
        }
        if matches!(x.op, Opcode::TexLd | Opcode::TexCrd) {
            if let Some(d) = x.dst.filter(|d| d.reg.file == RegFile::Temp) {
                let n = d.reg.index as usize;
                if self.tex_written[n] {
                    self.err(
                        codes::PS14_TEX_TWICE,
                        x.span,
                        format!("r{n} is already a tex* destination in this phase"),
                    );
                }
                self.tex_written[n] = true;
            }
        }
        if x.op == Opcode::TexLd && !self.after_phase && self.has_phase {
            self.dz_before_phase |= x.src.iter().any(|s| s.modifier == Modifier::Dz);
        }
    }

    fn phase(&mut self, x: &Instr) {
        if self.after_phase {
            self.err(
                codes::PS14_PHASE_TWICE,
                x.span,
                "more than one phase marker",
            );
            return;
        }
        if self.dz_before_phase {
            self.err(
                codes::PS14_DZ_BEFORE_PHASE,
                x.span,
                "_dz before the phase marker: it is allowed after it only",
            );
        }
        let (t, a) = self.counts;
        if t > 6 {
            let m = format!("{t} tex* instruction slots before the phase marker; a phase allows 6");
            self.err(codes::PS14_TEXTURE_SLOTS_PHASE1, x.span, m);
        }
        if a > 8 {
            let m = format!(
                "{a} arithmetic instruction slots before the phase marker; a phase allows 8"
            );
            self.err(codes::PS14_ARITHMETIC_SLOTS_PHASE1, x.span, m);
        }
        self.after_phase = true;
        self.arithmetic_seen = false;
        self.tex_written = [false; 8];
        self.counts = (0, 0);
        for n in 0..8 {
            if self.temps[n] & ALPHA != 0 {
                self.alpha_lost[n] = true;
                self.temps[n] &= !ALPHA;
            }
        }
    }

    /// The destination's register, mask and modifiers; false when a
    /// texture instruction carries a modifier.
    fn destination(&mut self, x: &Instr) -> bool {
        let Some(d) = x.dst else { return true };
        let texture = x.op.class() == Class::Texture;
        if texture && (d.sat || d.shift != 0) {
            let code = match (self.new, d.sat) {
                (false, true) => codes::PS1_TEX_MODIFIER,
                (false, false) => codes::PS1_TEX_SHIFT,
                (true, true) => codes::PS14_TEX_MODIFIER,
                (true, false) => codes::PS14_TEX_SHIFT,
            };
            self.err(code, x.base_span, "no shift or _sat on a tex* instruction");
            return false;
        }
        let allowed = match (self.new, texture) {
            (true, _) => {
                d.reg.file == RegFile::Temp
                    || (x.op == Opcode::TexKill && d.reg.file == RegFile::Texture)
            }
            (false, true) => d.reg.file == RegFile::Texture,
            (false, false) => matches!(d.reg.file, RegFile::Temp | RegFile::Texture),
        };
        if !allowed {
            let code = self.pick(codes::PS1_DEST_TYPE, codes::PS14_DEST_TYPE);
            self.err(
                code,
                d.span,
                format!("{} cannot be a destination here", d.reg),
            );
            return true;
        }
        let m = d.mask.0;
        if self.new {
            self.destination_new(x, m, d.span);
        } else if x.op == Opcode::Dp3 && m != COLOUR && m != 15 {
            self.err(codes::PS1_DP3_MASK, d.span, "dp3 writes .rgb or .rgba");
        } else if !texture && !matches!(m, COLOUR | ALPHA | 15) {
            self.err(
                codes::PS1_MASK,
                d.span,
                "the write mask must be .rgb, .a or .rgba",
            );
        }
        if !self.new && !(-1..=2).contains(&d.shift) {
            self.err(
                codes::PS1_SHIFT,
                x.base_span,
                "ps_1_1–ps_1_3 shift by _x2, _x4 or _d2 only",
            );
        }
        true
    }

    fn destination_new(&mut self, x: &Instr, m: u8, span: Span) {
        match x.op {
            Opcode::TexCrd => {
                let dw = x.src.first().is_some_and(|s| s.modifier == Modifier::Dw);
                if dw && m != 3 {
                    self.err(
                        codes::PS14_TEXCRD_DW_MASK,
                        span,
                        "texcrd with _dw writes .rg",
                    );
                } else if !dw && m != COLOUR {
                    self.err(codes::PS14_TEXCRD_MASK, span, "texcrd writes .rgb");
                }
            }
            Opcode::Bem if m != 3 => self.err(codes::PS14_BEM_MASK, span, "bem writes .rg"),
            _ => {}
        }
    }

    /// One source's modifier, selector and register type.
    fn source(&mut self, x: &Instr, k: usize, s: &Source) {
        let tex_coord = matches!(x.op, Opcode::TexLd | Opcode::TexCrd);
        if s.reg.file == RegFile::Const && s.modifier != Modifier::None {
            let code = self.pick(codes::PS1_CONST_MODIFIER, codes::PS14_CONST_MODIFIER);
            self.err(code, s.span, "no modifier on a constant in ps_1_x");
        } else if !self.new
            && matches!(
                s.modifier,
                Modifier::X2 | Modifier::X2Neg | Modifier::Dz | Modifier::Dw
            )
        {
            self.err(
                codes::PS1_SOURCE_MODIFIER,
                s.span,
                "_x2, _dz and _dw are ps_1_4's",
            );
        }
        if tex_coord {
            self.texture_source(x, s);
            return;
        }
        if self.new && s.reg.file == RegFile::Texture && x.op != Opcode::TexKill {
            self.err(
                codes::PS14_TEXCOORD_IN_ARITHMETIC,
                s.span,
                "t# is for texld and texcrd in ps_1_4",
            );
        }
        if self.new && self.has_phase && !self.after_phase && s.reg.file == RegFile::Input {
            self.err(
                codes::PS14_COLOUR_BEFORE_PHASE,
                s.span,
                "v# before the phase marker",
            );
        }
        self.selector(x, s);
        if !self.new && x.op == Opcode::Cnd && k == 0 {
            let r0a = s.reg
                == Reg {
                    file: RegFile::Temp,
                    index: 0,
                }
                && s.swizzle == Swizzle([3; 4]);
            if !r0a {
                self.err(codes::PS1_CND_SOURCE, s.span, "cnd's first source is r0.a");
            }
        }
        let same = x.dst.is_some_and(|d| d.reg == s.reg);
        if same
            && matches!(self.p.profile, Profile::Ps1_2 | Profile::Ps1_3)
            && matches!(x.op, Opcode::Cmp | Opcode::Dp4)
        {
            self.err(
                codes::PS1_SOURCE_IS_DEST,
                s.span,
                "cmp and dp4 read no register they write",
            );
        }
    }

    /// A source of ps_1_4's texld or texcrd.
    fn texture_source(&mut self, x: &Instr, s: &Source) {
        let xyz = matches!(s.swizzle.0, [0, 1, 2, 3] | [0, 1, 2, 2]);
        let xyw = s.swizzle.0 == [0, 1, 3, 3];
        if x.op == Opcode::TexCrd && s.reg.file != RegFile::Texture {
            self.err(codes::PS14_TEXCRD_SOURCE, s.span, "texcrd reads t#");
            return;
        }
        if s.modifier == Modifier::Dz && s.reg.file != RegFile::Temp {
            self.err(codes::PS14_DZ_ON_TEXCOORD, s.span, "_dz on r# only");
        } else if s.modifier == Modifier::Dz && !xyz {
            self.err(codes::PS14_DZ_SELECTOR, s.span, "_dz with .xyz only");
        }
        match s.reg.file {
            RegFile::Texture if !(xyz || xyw) => self.err(
                codes::PS14_TEXCOORD_SELECTOR,
                s.span,
                "t# as a coordinate: .xyz or .xyw",
            ),
            RegFile::Temp if !xyz => self.err(
                codes::PS14_TEMP_SELECTOR,
                s.span,
                "r# as a coordinate: .xyz",
            ),
            _ => {}
        }
    }

    /// ps_1_1–ps_1_3 take the identity, `.a` and, writing alpha alone,
    /// `.b`; ps_1_4 the identity and any one component.
    fn selector(&mut self, x: &Instr, s: &Source) {
        let sw = s.swizzle.0;
        let replicate = sw.iter().all(|&c| c == sw[0]);
        if sw == [0, 1, 2, 3] || (self.new && replicate) || (replicate && sw[0] == 3) {
            return;
        }
        if self.new {
            self.err(codes::PS14_SELECTOR, s.span, "invalid source selector");
        } else if replicate && sw[0] == 2 {
            if x.dst.map(|d| d.mask.0) != Some(ALPHA) {
                self.err(
                    codes::PS1_BLUE_SELECTOR,
                    s.span,
                    ".b only where alpha alone is written",
                );
            }
        } else {
            self.err(codes::PS1_SWIZZLE, s.span, "invalid source swizzle");
        }
    }

    /// What the instruction reads, and whether it was written before.
    fn reads(&mut self, x: &Instr) {
        let mask = x.dst.map_or(WriteMask::ALL, |d| d.mask).0;
        let mut reads: Vec<(Reg, u8, Span)> = Vec::new();
        for s in &x.src {
            let comps = match x.op {
                Opcode::Dp4 => 15,
                Opcode::Dp3 => components(s.swizzle, COLOUR),
                _ if x.op.class() == Class::Texture => components(s.swizzle, COLOUR),
                _ => components(s.swizzle, mask),
            };
            reads.push((s.reg, comps, s.span));
        }
        match (x.op, x.dst) {
            (Opcode::TexKill, Some(d)) if self.new => reads.push((d.reg, COLOUR, d.span)),
            (Opcode::TexDepth, Some(d)) => reads.push((d.reg, 3, d.span)),
            _ => {}
        }
        for (reg, comps, span) in reads {
            self.read(reg, comps, span);
        }
    }

    fn read(&mut self, reg: Reg, comps: u8, span: Span) {
        let n = reg.index as usize;
        let written = match reg.file {
            RegFile::Temp => self.temps[n],
            RegFile::Texture if self.new => 15,
            RegFile::Texture => {
                if self.unreadable[n] {
                    self.err(
                        codes::PS1_PAD_READ,
                        span,
                        format!("t{n} holds no readable result"),
                    );
                    return;
                }
                self.texture[n]
            }
            _ => 15,
        };
        let missing = comps & !written;
        if missing == 0 {
            return;
        }
        let lost = self.new && reg.file == RegFile::Temp && self.alpha_lost[n] && missing == ALPHA;
        let code = match (self.new, lost) {
            (false, _) => codes::PS1_UNINITIALIZED,
            (true, true) => codes::PS14_ALPHA_AFTER_PHASE,
            (true, false) => codes::PS14_UNINITIALIZED,
        };
        self.err(
            code,
            span,
            format!("read of uninitialized components of {reg}"),
        );
    }

    fn coissue(&mut self, i: usize, x: &Instr) {
        let Some(prev) = i.checked_sub(1).map(|k| &self.p.instrs[k]) else {
            return;
        };
        let pm = prev.dst.map_or(0, |d| d.mask.0);
        let xm = x.dst.map_or(0, |d| d.mask.0);
        let same_reg = prev.dst.map(|d| d.reg) == x.dst.map(|d| d.reg);
        let span = x.span;
        if prev.coissue {
            let c = self.pick(codes::PS1_COISSUE_CHAIN, codes::PS14_COISSUE_CHAIN);
            return self.err(c, span, "co-issue on consecutive instructions");
        }
        if prev.op == Opcode::Nop || x.op == Opcode::Nop {
            let c = self.pick(codes::PS1_COISSUE_NOP, codes::PS14_COISSUE_NOP);
            return self.err(c, span, "nop cannot be co-issued");
        }
        let both = |m: u8| m & ALPHA != 0 && m & COLOUR != 0;
        if self.new {
            if both(pm) {
                self.err(
                    codes::PS14_COISSUE_FIRST_BOTH,
                    span,
                    "the first of the pair writes alpha and colour",
                );
            }
            if both(xm) {
                self.err(
                    codes::PS14_COISSUE_BOTH,
                    span,
                    "the co-issued instruction writes alpha and colour",
                );
            }
            if pm & xm != 0 {
                self.err(
                    codes::PS14_COISSUE_SAME,
                    span,
                    "both write the same components",
                );
            }
            if pm != ALPHA && xm != ALPHA {
                self.err(
                    codes::PS14_COISSUE_ALPHA,
                    span,
                    "one of the pair writes .a alone",
                );
            }
            return;
        }
        if pm == 15 {
            self.err(
                codes::PS1_COISSUE_FIRST_ALL,
                span,
                "the first of the pair writes every component",
            );
        }
        if xm == 15 {
            self.err(
                codes::PS1_COISSUE_ALL,
                span,
                "the co-issued instruction writes every component",
            );
        }
        if same_reg && pm & xm != 0 {
            self.err(
                codes::PS1_COISSUE_SAME,
                span,
                "both write the same components",
            );
        }
        if pm & xm & COLOUR != 0 {
            self.err(codes::PS1_COISSUE_COLOUR, span, "both write colour");
        }
        if pm & xm & ALPHA != 0 {
            self.err(codes::PS1_COISSUE_ALPHA, span, "both write alpha");
        }
    }

    fn count(&mut self, x: &Instr, texture: bool) {
        if texture {
            self.counts.0 += 1;
        } else if !x.coissue && x.op != Opcode::Nop {
            self.counts.1 += 1;
        }
    }

    fn writes(&mut self, x: &Instr, texture: bool) {
        let Some(d) = x.dst else { return };
        let n = d.reg.index as usize;
        match (d.reg.file, x.op) {
            (RegFile::Temp, Opcode::TexKill | Opcode::TexDepth) => {}
            (RegFile::Temp, _) => {
                self.temps[n] |= d.mask.0;
                if d.mask.0 & ALPHA != 0 {
                    self.alpha_lost[n] = false;
                }
            }
            (RegFile::Texture, op) if texture => {
                let hidden = matches!(
                    op,
                    Opcode::TexKill
                        | Opcode::TexM3x2Pad
                        | Opcode::TexM3x3Pad
                        | Opcode::TexM3x2Depth
                );
                self.unreadable[n] = hidden;
                if !hidden {
                    self.texture[n] = 15;
                }
            }
            (RegFile::Texture, _) => self.texture[n] |= d.mask.0,
            _ => {}
        }
    }

    fn finish(&mut self) {
        let end = self.end;
        if self.texm.is_some() {
            self.err(codes::PS1_TEXM_INCOMPLETE, end, "incomplete texm* sequence");
        }
        let (t, a) = self.counts;
        if self.new {
            let (tc, ac) = if self.after_phase {
                (
                    codes::PS14_TEXTURE_SLOTS_PHASE2,
                    codes::PS14_ARITHMETIC_SLOTS_PHASE2,
                )
            } else {
                (codes::PS14_TEXTURE_SLOTS, codes::PS14_ARITHMETIC_SLOTS)
            };
            if t > 6 {
                self.err(
                    tc,
                    end,
                    format!("{t} tex* instruction slots in a phase; 6 allowed"),
                );
            }
            if a > 8 {
                self.err(
                    ac,
                    end,
                    format!("{a} arithmetic instruction slots in a phase; 8 allowed"),
                );
            }
        } else if a > 8 {
            let m =
                format!("{a} arithmetic instruction slots (co-issued pairs count once); 8 allowed");
            self.err(codes::PS1_ARITHMETIC_SLOTS, end, m);
        }
        if self.temps[0] != 15 {
            let code = self.pick(codes::PS1_R0_UNWRITTEN, codes::PS14_R0_UNWRITTEN);
            self.err(code, end, "r0 must be written: it is the shader's colour");
        }
    }
}

/// The instructions that continue a texm sequence: the texm* family but
/// the first pad of a 3x2 multiply.
fn texm_continues(op: Opcode) -> bool {
    op.info().mnemonic.starts_with("texm") && op != Opcode::TexM3x2Pad
}

/// The components a swizzle reads for the written components `mask`.
fn components(s: Swizzle, mask: u8) -> u8 {
    (0..4)
        .filter(|c| mask & (1 << c) != 0)
        .fold(0, |acc, c| acc | 1 << s.0[c])
}
