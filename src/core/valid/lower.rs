//! Lowering one statement: AST operands → resolved IR operands, checking
//! everything that can be checked from the statement alone (mnemonic,
//! modifiers, operand count and kinds, register ranges, swizzles, masks).

use crate::core::diag::{codes, Diagnostic};
use crate::core::front::ast::{InstrAst, OperandAst, RegAst};
use crate::core::ir::{
    BoolDef, Dst, FloatDef, InputDecl, Instruction, IntDef, Origin, Predicate, Reg, SamplerDecl,
    Span, Src, SrcMod, Swizzle, WriteMask,
};
use crate::core::isa::{Class, Compare, OpInfo, Opcode, Operand, RegFile, SamplerType, USAGES};
use crate::core::profile::Profile;

/// What one statement becomes.
#[derive(Clone, Debug)]
pub enum Lowered {
    /// An executable instruction.
    Instr(Instruction),
    /// An input declaration.
    Input(InputDecl),
    /// A sampler declaration.
    Sampler(SamplerDecl),
    /// A `def`.
    Float(FloatDef),
    /// A `defi`.
    Int(IntDef),
    /// A `defb`.
    Bool(BoolDef),
}

use super::register::{foreign_register, no_modifiers, resolve_reg, swizzle, write_mask};

mod decl;
mod relative;
use decl::{lower_dcl, lower_def};

type R<T> = Result<T, Diagnostic>;

/// Mnemonics of other shader models, with what to say about them.
const NOT_PS30: &[(&str, &str)] = &[
    ("lit", "lit is a vertex-shader instruction"),
    ("slt", "slt is a vertex-shader instruction; use setp or cmp"),
    ("sge", "sge is a vertex-shader instruction; use setp or cmp"),
    ("dst", "dst is a vertex-shader instruction"),
    ("expp", "expp is a vertex-shader instruction; use exp"),
    ("logp", "logp is a vertex-shader instruction; use log"),
    ("mova", "mova is a vertex-shader instruction"),
    ("sgn", "sgn is a vertex-shader instruction"),
    ("tex", "tex is ps_1_x; use texld"),
    ("texcoord", "texcoord is ps_1_x"),
    ("phase", "phase is ps_1_4 only"),
    ("bem", "bem is ps_1_4 only"),
    ("cnd", "cnd is ps_1_x; use cmp"),
];

/// Lowers one statement of the AST to the IR, or a diagnostic naming what is
/// wrong. The lowering's origin is left empty: a statement repeated by
/// REPEAT_BLOCK is lowered once, and the validator gives each copy its own.
pub fn lower(ast: &InstrAst, p: Profile) -> R<Lowered> {
    let lowered = match ast.base.as_str() {
        "dcl" => lower_dcl(ast, p),
        "def" | "defi" | "defb" => lower_def(ast, p),
        _ => lower_instruction(ast, p).map(Lowered::Instr),
    };
    // What a statement alone can get wrong is, unless a check names a
    // validator rule, what Microsoft's grammar refuses: a syntax error.
    lowered.map_err(|d| d.or_code(codes::SYNTAX))
}

/// `sgn`'s second and third sources are scratch temporaries of the
/// vertex profiles' macro: two different `r#` (X5470; X5797 in vs_3_0).
fn sgn_sources(src: &[Src], ast: &InstrAst, p: Profile) -> R<()> {
    let ok = match src {
        [_, a, b] => a.reg.file == RegFile::Temp && b.reg.file == RegFile::Temp && a.reg != b.reg,
        _ => true,
    };
    if ok {
        return Ok(());
    }
    let code = match p {
        Profile::Vs3_0 => codes::SGN_SCRATCH_3_0,
        _ => codes::SGN_SCRATCH,
    };
    Err(Diagnostic::coded(
        code,
        ast.span,
        "sgn's second and third sources must be two different temporaries r#",
    )
    .with_label("scratch registers of the sign computation"))
}

/// Microsoft's code for an instruction the profile lacks: its grammar's
/// syntax error (X2000) for most, its validator's for the few the
/// grammar takes (measured: `defb` and `if` in ps_2_0, X5190; `break` in
/// vs_2_0, X5655).
fn unavailable_code(op: Opcode, p: Profile) -> Option<codes::Code> {
    match (p, op) {
        (Profile::Ps2_0, Opcode::DefB | Opcode::If) => Some(codes::PS_UNSUPPORTED),
        (Profile::Vs2_0, Opcode::Break) => Some(codes::VS_UNSUPPORTED),
        _ => None,
    }
}

fn unknown_mnemonic(ast: &InstrAst) -> Diagnostic {
    let name = &ast.base;
    let d = Diagnostic::error(
        ast.base_span,
        format!("unknown instruction `{}`", crate::core::diag::excerpt(name)),
    );
    if let Some((_, why)) = NOT_PS30.iter().find(|(m, _)| m == name) {
        return d.with_label("not a ps_3_0 instruction").with_help(*why);
    }
    // No mnemonic is within two edits of a name more than two letters
    // longer than the longest one, so longer names are not compared.
    let longest = crate::core::isa::TABLE
        .iter()
        .filter(|r| !r.op.is_ps1_only())
        .map(|r| r.mnemonic.len())
        .max()
        .unwrap_or(0);
    let best = crate::core::isa::TABLE
        .iter()
        .filter(|r| name.len() <= longest + 2 && !r.op.is_ps1_only())
        .map(|r| (edit_distance(name, r.mnemonic), r.mnemonic))
        .min();
    match best {
        Some((dist, m)) if dist <= if name.len() <= 4 { 1 } else { 2 } => d
            .with_label("unknown mnemonic")
            .with_help(format!("did you mean `{m}`?")),
        _ => d
            .with_label("unknown mnemonic")
            .with_help("see the ps_3_0 instruction list in the README"),
    }
}

fn edit_distance(a: &str, b: &str) -> usize {
    // Two rows on the stack: the names compared here are at most a few
    // characters longer than the longest mnemonic (see the caller), so an
    // unknown mnemonic costs no allocation however many there are.
    const MAX: usize = 32;
    let mut chars = ['\0'; MAX];
    let mut len = 0;
    for (slot, c) in chars.iter_mut().zip(b.chars()) {
        *slot = c;
        len += 1;
    }
    let b = &chars[..len];
    let mut prev = [0usize; MAX + 1];
    let mut cur = [0usize; MAX + 1];
    for (j, p) in prev.iter_mut().enumerate().take(b.len() + 1) {
        *p = j;
    }
    for (i, ca) in a.chars().enumerate() {
        cur[0] = i + 1;
        for (j, cb) in b.iter().enumerate() {
            let sub = prev[j] + usize::from(ca != *cb);
            cur[j + 1] = sub.min(prev[j + 1] + 1).min(cur[j] + 1);
        }
        std::mem::swap(&mut prev, &mut cur);
    }
    prev[b.len()]
}

/// The modifiers written after an instruction's mnemonic.
struct Suffixes {
    sat: bool,
    pp: bool,
    centroid: bool,
    compare: Option<Compare>,
}

fn lower_instruction(ast: &InstrAst, p: Profile) -> R<Instruction> {
    let m = suffixes(ast)?;
    let op = opcode(ast, m.compare, p)?;
    let row = op.info_in(p);
    let info = &row;
    check_modifiers(ast, info, &m)?;
    let predicate = instruction_predicate(ast, info, p)?;
    check_operand_count(ast, info)?;
    grammar_of_operands(ast, info, p)?;
    let (dst, src) = operands(ast, info, p)?;
    if op == Opcode::Sgn {
        sgn_sources(&src, ast, p)?;
    }
    texture_sources(op, &src, ast)?;
    operand_rules(op, dst.as_ref(), &src, ast, p)?;
    depth_rules(op, dst.as_ref(), &src, ast)?;
    Ok(Instruction {
        op,
        sat: m.sat,
        pp: m.pp,
        centroid: m.centroid,
        compare: m.compare,
        predicate,
        dst,
        src,
        origin: Origin::default(),
    })
}

/// `_sat`, `_pp`, `_centroid` and at most one comparison; shift modifiers
/// and unknown suffixes are errors.
fn suffixes(ast: &InstrAst) -> R<Suffixes> {
    let mut m = Suffixes {
        sat: false,
        pp: false,
        centroid: false,
        compare: None,
    };
    for (s, span) in &ast.suffixes {
        match s.as_str() {
            "sat" => m.sat = true,
            "pp" => m.pp = true,
            "centroid" => m.centroid = true,
            "x2" | "x4" | "x8" | "d2" | "d4" | "d8" => {
                return Err(Diagnostic::error(*span, format!("shift modifier `_{s}` does not exist in ps_3_0"))
                    .with_label("ps_1_x only")
                    .with_help("multiply explicitly with mul"))
            }
            _ => match Compare::from_suffix(s) {
                Some(c) if m.compare.is_none() => m.compare = Some(c),
                Some(_) => return Err(Diagnostic::error(*span, "more than one comparison suffix")),
                None => {
                    return Err(Diagnostic::error(*span, format!("unknown instruction modifier `_{s}`"))
                        .with_label("unknown modifier")
                        .with_help("ps_3_0 modifiers are _sat, _pp, _centroid and the comparisons _gt _lt _ge _le _eq _ne"))
                }
            },
        }
    }
    Ok(m)
}

/// The instruction the mnemonic names, with a comparison suffix exactly when
/// it takes one.
fn opcode(ast: &InstrAst, compare: Option<Compare>, p: Profile) -> R<Opcode> {
    let op =
        Opcode::from_mnemonic(&ast.base, compare.is_some()).ok_or_else(|| unknown_mnemonic(ast))?;
    let info = op.info();
    if info.class == Class::Declaration {
        return Err(unknown_mnemonic(ast));
    }
    if !op.profiles().has(p) && p == Profile::Ps3_0 {
        return Err(unknown_mnemonic(ast));
    }
    if !op.profiles().has(p) {
        return Err(not_in_profile(ast, op, p));
    }
    if compare.is_some() && !info.comparison {
        let span = ast
            .suffixes
            .iter()
            .find(|(s, _)| Compare::from_suffix(s).is_some())
            .map(|s| s.1);
        return Err(Diagnostic::error(
            span.unwrap_or(ast.base_span),
            format!("`{}` takes no comparison suffix", info.mnemonic),
        ));
    }
    if info.comparison && compare.is_none() {
        return Err(Diagnostic::error(
            ast.base_span,
            format!("`{}` needs a comparison suffix", info.mnemonic),
        )
        .with_label("comparison missing")
        .with_help(format!(
            "write {}_gt, _lt, _ge, _le, _eq or _ne",
            info.mnemonic
        )));
    }
    Ok(op)
}

/// The refusal of an instruction `p` does not have (Microsoft's grammar is
/// the profile's: mostly a syntax error there, X2000 then X2023).
fn not_in_profile(ast: &InstrAst, op: Opcode, p: Profile) -> Diagnostic {
    let mnemonic = op.info().mnemonic;
    let has: Vec<&str> = Profile::ALL
        .into_iter()
        .filter(|q| op.profiles().has(*q) && q.checked())
        .map(Profile::name)
        .collect();
    let d = Diagnostic::error(
        ast.base_span,
        format!("`{mnemonic}` is not a {p} instruction"),
    )
    .with_label(format!("not in {p}"))
    .with_help(format!("{mnemonic} exists in {}", has.join(", ")));
    match unavailable_code(op, p) {
        Some(code) => d.with_code(code),
        None => d,
    }
}

/// `_sat` only where the table allows it, `_centroid` only on texture
/// instructions, `_pp` only where there is a destination.
fn check_modifiers(ast: &InstrAst, info: &OpInfo, m: &Suffixes) -> R<()> {
    let suffix_span = |name: &str| {
        ast.suffixes
            .iter()
            .find(|(s, _)| s == name)
            .map(|s| s.1)
            .unwrap_or(ast.base_span)
    };
    if m.sat && !info.allows_sat {
        let code = match info.class {
            Class::Texture => codes::SAT_TEXTURE,
            _ if info.mnemonic == "frc" => codes::SAT_FRC,
            _ if info.mnemonic == "sincos" => codes::SAT_SINCOS,
            _ if info.mnemonic == "setp" => codes::SAT_SETP,
            _ => codes::SYNTAX,
        };
        return Err(Diagnostic::coded(
            code,
            suffix_span("sat"),
            format!("`_sat` is not allowed on `{}`", info.mnemonic),
        )
        .with_label("not allowed here"));
    }
    // Microsoft's assembler reads `_centroid` on declarations only:
    // `texld_centroid` is a syntax error there (X2000), though the token
    // has the bit.
    if m.centroid {
        return Err(Diagnostic::coded(
            codes::SYNTAX,
            suffix_span("centroid"),
            "`_centroid` is only allowed on input declarations",
        )
        .with_label("not allowed here")
        .with_help("declare the input with _centroid instead, e.g. dcl_texcoord0_centroid v0"));
    }
    // Instruction modifiers act on the result written to the destination
    // (Microsoft's "Modifiers for ps_2_0 and above"), and the token that
    // carries them is the destination's: without one they mean nothing and
    // cannot be encoded.
    let has_dst = matches!(
        info.operands.first(),
        Some(Operand::Dst | Operand::PredDst | Operand::KillSrc)
    );
    if m.pp && !has_dst {
        return Err(Diagnostic::error(
            suffix_span("pp"),
            format!(
                "`_pp` is not allowed on `{}`: it has no destination",
                info.mnemonic
            ),
        )
        .with_label("nothing to write at partial precision"));
    }
    Ok(())
}

/// The `(p0.c)` / `(!p0.c)` prefix, on instructions that can be predicated.
fn instruction_predicate(ast: &InstrAst, info: &OpInfo, profile: Profile) -> R<Option<Predicate>> {
    let Some(p) = &ast.predicate else {
        return Ok(None);
    };
    // Microsoft refuses a predicate on setp (the predicate's own writer,
    // X5665) and on nop (which has no parameter to carry it, X5521).
    if info.mnemonic == "setp" {
        return Err(Diagnostic::coded(
            codes::PREDICATED_FLOW,
            p.span,
            "`setp` cannot be predicated",
        )
        .with_label("setp writes the predicate; it takes none")
        .with_help("mask what setp writes with its write mask instead"));
    }
    if info.mnemonic == "nop" {
        return Err(Diagnostic::coded(
            codes::PARAMETER_COUNT,
            p.span,
            "`nop` cannot be predicated",
        )
        .with_label("nothing to predicate"));
    }
    if !info.predicable {
        return Err(Diagnostic::coded(
            codes::PREDICATED_FLOW,
            p.span,
            format!("`{}` cannot be predicated", info.mnemonic),
        )
        .with_label("flow-control instructions take no predicate")
        .with_help("use if / breakp / callnz with p0 instead"));
    }
    let src = predicate_operand(p, false, profile)?;
    Ok(Some(Predicate {
        negate: src.modifier == SrcMod::Not,
        swizzle: src.swizzle,
    }))
}

/// As many operands as the instruction's shape has.
fn check_operand_count(ast: &InstrAst, info: &OpInfo) -> R<()> {
    let shape = info.operands;
    if ast.operands.len() != shape.len() {
        let span = if ast.operands.is_empty() {
            ast.span
        } else {
            ast.operands[0]
                .span()
                .to(ast.operands.last().unwrap().span())
        };
        return Err(Diagnostic::error(
            span,
            format!(
                "`{}` takes {} operand{}, found {}",
                info.mnemonic,
                shape.len(),
                if shape.len() == 1 { "" } else { "s" },
                ast.operands.len()
            ),
        )
        .with_label("wrong number of operands")
        .with_help(format!("form: {}", shape_text(info.mnemonic, shape))));
    }
    Ok(())
}

/// What Microsoft's assembler refuses while it reads the operands, before
/// its validator asks where each register may go: an unknown register, an
/// index on a register other than v# (`c[aL]` is the invalid register
/// `c[...]`), and components on a scalar register (aL, b#, oDepth, vFace; a
/// write mask on a destination, a swizzle on a source or on the index aL).
fn grammar_of_operands(ast: &InstrAst, info: &OpInfo, p: Profile) -> R<()> {
    for (kind, operand) in info.operands.iter().zip(&ast.operands) {
        let OperandAst::Reg(r) = operand else {
            continue;
        };
        let reg = resolve_reg(r, p)?;
        relative::grammar(r, reg, p)?;
        let scalar = matches!(
            reg.file,
            RegFile::LoopCounter | RegFile::ConstBool | RegFile::DepthOut | RegFile::Face
        );
        if let (true, Some((_, span))) = (scalar, &r.components) {
            let what = match kind {
                Operand::Dst | Operand::KillSrc | Operand::PredDst => "write mask",
                _ => "swizzle",
            };
            return Err(Diagnostic::coded(
                codes::SCALAR,
                *span,
                format!("`{reg}` is a scalar register: it takes no {what}"),
            )
            .with_label(format!("remove the {what}")));
        }
    }
    Ok(())
}

/// Each operand resolved as its place in the shape requires: the
/// destination (if any) and the sources in order.
fn operands(ast: &InstrAst, info: &OpInfo, p: Profile) -> R<(Option<Dst>, Vec<Src>)> {
    let mut dst = None;
    let mut src = Vec::with_capacity(ast.operands.len());
    for (pos, (kind, operand)) in info.operands.iter().zip(&ast.operands).enumerate() {
        let reg = match operand {
            OperandAst::Reg(r) => r,
            other => {
                return Err(Diagnostic::error(
                    other.span(),
                    format!(
                        "operand {} of `{}` must be a register",
                        pos + 1,
                        info.mnemonic
                    ),
                )
                .with_label("a literal is not allowed here")
                .with_help("put the value in a constant with def and use c#"))
            }
        };
        match kind {
            Operand::Dst | Operand::KillSrc => {
                let d = destination(reg, *kind, p)?;
                if info.mnemonic == "mova" && d.reg.file != RegFile::Address {
                    let code = match p {
                        Profile::Vs3_0 => codes::MOVA_DESTINATION_3_0,
                        _ => codes::MOVA_DESTINATION,
                    };
                    return Err(Diagnostic::coded(
                        code,
                        reg.span,
                        "mova writes the address register a0",
                    )
                    .with_label("expected a0"));
                }
                dst = Some(d);
            }
            Operand::PredDst => dst = Some(predicate_destination(reg, p)?),
            Operand::Src | Operand::ScalarSrc => {
                texture_operand(reg, pos, info, p)?;
                let s = float_source(reg, p).map_err(|d| source_code(d, pos, info))?;
                // vFace is a scalar register (dimension 1 in Microsoft's
                // ps_3_0 register table, and the operand of if_comp and
                // break_comp its page names): it needs no swizzle to be one.
                let scalar = s.swizzle.is_replicate() || s.reg.file == RegFile::Face;
                if *kind == Operand::ScalarSrc && !scalar {
                    let code = if info.mnemonic == "dp2add" {
                        codes::DP2ADD_REPLICATE
                    } else {
                        codes::REPLICATE
                    };
                    return Err(Diagnostic::coded(
                        code,
                        reg.span,
                        format!(
                            "`{}` needs a replicate swizzle on this source",
                            info.mnemonic
                        ),
                    )
                    .with_label("expected one component, e.g. .x or .w")
                    .with_help("scalar sources select one component: r0.x, c1.w"));
                }
                src.push(s);
            }
            Operand::Sampler => src.push(sampler_operand(reg, pos, info.mnemonic, p)?),
            Operand::IntReg => src.push(
                plain_of(reg, RegFile::ConstInt, "an integer constant i#", p)
                    .map_err(|d| d.or_code(codes::REP_OPERAND))?,
            ),
            Operand::LoopCounter => src.push(
                plain_of(reg, RegFile::LoopCounter, "the loop counter aL", p)
                    .map_err(|d| d.or_code(codes::LOOP_COUNTER))?,
            ),
            Operand::Label => src.push(plain_of(reg, RegFile::Label, "a label l#", p)?),
            Operand::Condition => {
                if info.mnemonic == "breakp" && resolve_reg(reg, p)?.file != RegFile::Predicate {
                    return Err(Diagnostic::coded(
                        codes::BREAKP_CONDITION,
                        reg.span,
                        "`breakp` tests the predicate register: p0.c or !p0.c",
                    )
                    .with_label("not p0")
                    .with_help("for a boolean b#, use if b# / break / endif"));
                }
                src.push(condition(reg, p).map_err(|d| condition_code(d, info))?)
            }
            Operand::FloatLits | Operand::IntLits | Operand::BoolLit => {
                unreachable!("only def rows use literal shapes")
            }
        }
    }
    Ok((dst, src))
}

/// The texld family reads its coordinate (operand 1) and texldd its
/// gradients (operands 3 and 4) from r#, v# or c# only; Microsoft checks
/// that before any other rule on them (vPos and vFace included).
fn texture_operand(reg: &RegAst, pos: usize, info: &OpInfo, p: Profile) -> R<()> {
    let code = match (info.class, pos, info.mnemonic) {
        (Class::Texture, 1, _) => codes::TEXLD_COORDINATE,
        (Class::Texture, 3 | 4, "texldd") => codes::TEXLDD_GRADIENT,
        _ => return Ok(()),
    };
    let r = resolve_reg(reg, p)?;
    if matches!(
        r.file,
        RegFile::Temp | RegFile::Input | RegFile::Const | RegFile::Texture
    ) {
        return Ok(());
    }
    Err(Diagnostic::coded(
        code,
        reg.name_span,
        format!("`{}` cannot read `{r}` here", info.mnemonic),
    )
    .with_label("expected r#, v# or c#"))
}

/// Microsoft's code for a bad float source of some instructions: `!` on a
/// texld source is its texld rule, `!` on the source that sub negates is
/// refused by the assembler itself.
fn source_code(d: Diagnostic, pos: usize, info: &OpInfo) -> Diagnostic {
    match (d.code, info.class, info.mnemonic, pos) {
        (Some(codes::SOURCE_MODIFIER), Class::Texture, ..) => {
            d.with_code(codes::TEXLD_SOURCE_MODIFIER)
        }
        (Some(codes::SOURCE_MODIFIER), _, "sub", 2) => d.with_code(codes::SUB_MODIFIER),
        _ => d,
    }
}

/// Microsoft's code for a bad condition depends on the instruction: a
/// predicate without a replicate swizzle is X5949 for `if`, X5793 for
/// `breakp`, X5946 for `callnz`; a modifier on it is X5690 for `if`.
fn condition_code(d: Diagnostic, info: &OpInfo) -> Diagnostic {
    let code = match (d.code, info.mnemonic) {
        (Some(codes::PREDICATE_REPLICATE), "breakp") => codes::REPLICATE,
        (Some(codes::PREDICATE_REPLICATE), "callnz") => codes::CALLNZ_REPLICATE,
        (Some(codes::PREDICATE_MODIFIER), "if") => codes::IF_MODIFIER,
        (Some(codes::CALLNZ_CONDITION), "if") => codes::IF_CONDITION,
        (Some(codes::CALLNZ_CONDITION), "breakp") => codes::BREAKP_CONDITION,
        _ => return d,
    };
    d.with_code(code)
}

/// setp's destination: p0 with a write mask.
fn predicate_destination(reg: &RegAst, p: Profile) -> R<Dst> {
    let r = resolve_reg(reg, p)?;
    if r.file != RegFile::Predicate {
        return Err(Diagnostic::coded(
            codes::SETP_DESTINATION,
            reg.span,
            "setp writes the predicate register p0",
        )
        .with_label("expected p0"));
    }
    no_modifiers(reg, "the predicate destination")?;
    Ok(Dst {
        reg: r,
        relative: None,
        mask: write_mask(reg)?,
    })
}

/// A sampler `s#` (operand `pos` of `mnemonic`), without modifiers.
fn sampler_operand(reg: &RegAst, pos: usize, mnemonic: &str, p: Profile) -> R<Src> {
    let r = resolve_reg(reg, p)?;
    if r.file != RegFile::Sampler {
        return Err(Diagnostic::coded(
            codes::TEXLD_SAMPLER,
            reg.span,
            format!("operand {} of `{}` must be a sampler s#", pos + 1, mnemonic),
        )
        .with_label("expected s0 … s15"));
    }
    if reg.negate || reg.abs || reg.not {
        return Err(Diagnostic::coded(
            codes::SAMPLER_SOURCE_MODIFIER,
            reg.span,
            "a sampler operand takes no modifier",
        )
        .with_label("remove the modifier"));
    }
    Ok(Src {
        reg: r,
        relative: None,
        swizzle: swizzle(reg)?,
        modifier: SrcMod::None,
    })
}

/// The texld family's coordinate and gradients take no `-` or `_abs`
/// (Microsoft's validator: "Negate or abs modifiers not permitted on source
/// parameters to texld*").
fn texture_sources(op: Opcode, src: &[Src], ast: &InstrAst) -> R<()> {
    if !matches!(
        op,
        Opcode::TexLd | Opcode::TexLdP | Opcode::TexLdB | Opcode::TexLdL | Opcode::TexLdD
    ) {
        return Ok(());
    }
    // The coordinate and texldd's gradients are r#, v# or c# (X5525,
    // X5526), or t# where the profile has them: vPos and vFace are refused.
    let plain = |s: &Src| {
        matches!(
            s.reg.file,
            RegFile::Temp | RegFile::Input | RegFile::Const | RegFile::Texture
        )
    };
    for (k, s) in src.iter().enumerate() {
        let code = match k {
            0 => codes::TEXLD_COORDINATE,
            2 | 3 => codes::TEXLDD_GRADIENT,
            _ => continue,
        };
        if !plain(s) {
            return Err(Diagnostic::coded(
                code,
                ast.operands.get(k + 1).map_or(ast.span, |o| o.span()),
                format!(
                    "`{}` reads its {} from r#, v# or c#, not `{}`",
                    op.info().mnemonic,
                    if k == 0 { "coordinate" } else { "gradients" },
                    s.reg
                ),
            )
            .with_label("not r#, v# or c#")
            .with_help("copy it into a temporary with mov first"));
        }
    }
    let bad = src
        .iter()
        .position(|s| s.reg.file != RegFile::Sampler && s.modifier != SrcMod::None);
    match bad {
        Some(k) => Err(Diagnostic::coded(
            codes::TEXLD_SOURCE_MODIFIER,
            ast.operands.get(k + 1).map_or(ast.span, |o| o.span()),
            format!("`{}` sources take no `-` or `_abs`", op.info().mnemonic),
        )
        .with_label("modifier not allowed here")
        .with_help("apply the modifier with mov into a temporary first")),
        None => Ok(()),
    }
}

/// Writes to oDepth, as Microsoft's validator takes them: the texture
/// loads, `rsq` and the four-row matrix products may not write it (X5758),
/// and the component-wise instructions must select one component of every
/// source with a replicate swizzle (X6062), since oDepth holds one value.
fn depth_rules(op: Opcode, dst: Option<&Dst>, src: &[Src], ast: &InstrAst) -> R<()> {
    if dst.is_none_or(|d| d.reg.file != RegFile::DepthOut) {
        return Ok(());
    }
    let mnemonic = op.info().mnemonic;
    let span = ast.operands.first().map_or(ast.span, |o| o.span());
    match op {
        Opcode::Rsq
        | Opcode::M3x4
        | Opcode::M4x4
        | Opcode::TexLd
        | Opcode::TexLdP
        | Opcode::TexLdB
        | Opcode::TexLdL
        | Opcode::TexLdD => Err(Diagnostic::coded(
            codes::DEPTH_WRITER,
            span,
            format!("`{mnemonic}` may not write oDepth"),
        )
        .with_label("oDepth written here")
        .with_help("compute into r# and copy one component with mov oDepth, r#.x")),
        Opcode::Abs
        | Opcode::Add
        | Opcode::Cmp
        | Opcode::Dsx
        | Opcode::Dsy
        | Opcode::Frc
        | Opcode::Lrp
        | Opcode::Mad
        | Opcode::Max
        | Opcode::Min
        | Opcode::Mov
        | Opcode::Mul
        | Opcode::Sub => match src.iter().position(|s| !s.swizzle.is_replicate()) {
            Some(k) => Err(Diagnostic::coded(
                codes::DEPTH_REPLICATE,
                ast.operands.get(k + 1).map_or(ast.span, |o| o.span()),
                format!("`{mnemonic}` writing oDepth must select one component of each source"),
            )
            .with_label("needs a replicate swizzle (.x, .y, .z or .w)")),
            None => Ok(()),
        },
        _ => Ok(()),
    }
}

/// Per-instruction operand rules of Microsoft's instruction pages (crs,
/// m#x#, nrm, pow, sincos): required write masks, unswizzled sources, and
/// destinations that may not alias a source.
fn operand_rules(
    op: Opcode,
    dst: Option<&Dst>,
    src: &[Src],
    ast: &InstrAst,
    profile: Profile,
) -> R<()> {
    let Some(d) = dst else { return Ok(()) };
    let rules = Rules {
        mnemonic: op.info().mnemonic,
        d,
        src,
        ast,
        profile,
    };
    match op {
        Opcode::SinCos => {
            rules.need_temp()?;
            rules.mask_must_be(&[0b0001, 0b0010, 0b0011], ".x, .y or .xy")?;
        }
        Opcode::Crs => rules.crs()?,
        Opcode::M3x2 | Opcode::M3x3 | Opcode::M4x3 | Opcode::M3x4 | Opcode::M4x4 => {
            let rows = match op {
                Opcode::M3x2 => 2,
                Opcode::M3x3 | Opcode::M4x3 => 3,
                _ => 4,
            };
            rules.matrix(rows)?;
        }
        Opcode::Nrm => {
            rules.mask_must_be(&[0b0111, 0b1111], ".xyz or .xyzw")?;
            rules.not_aliased(&[0], "its source")?;
        }
        Opcode::Dsx | Opcode::Dsy => rules.no_source_modifier()?,
        Opcode::Pow => {
            rules.not_aliased(&[1], "its exponent source")?;
        }
        _ => {}
    }
    Ok(())
}

/// One instruction's destination and sources, for [`operand_rules`].
struct Rules<'a> {
    mnemonic: &'static str,
    d: &'a Dst,
    src: &'a [Src],
    ast: &'a InstrAst,
    profile: Profile,
}

impl Rules<'_> {
    /// Operand `i`'s span (0 is the destination).
    fn span(&self, i: usize) -> Span {
        self.ast.operands.get(i).map_or(self.ast.span, |o| o.span())
    }

    fn need_temp(&self) -> R<()> {
        if self.d.reg.file != RegFile::Temp {
            let code = if self.mnemonic == "sincos" {
                codes::SINCOS_DESTINATION
            } else {
                codes::DESTINATION
            };
            return Err(Diagnostic::coded(
                code,
                self.span(0),
                format!("`{}` writes a temporary register r#", self.mnemonic),
            )
            .with_label("not a temporary")
            .with_help("compute into r# and copy it with mov"));
        }
        Ok(())
    }

    fn not_aliased(&self, sources: &[usize], what: &str) -> R<()> {
        for &i in sources {
            if self.src.get(i).is_some_and(|s| s.reg == self.d.reg) {
                let code = match self.mnemonic {
                    "crs" => codes::CRS_ALIAS,
                    "nrm" => codes::NRM_ALIAS,
                    "pow" => codes::POW_ALIAS,
                    _ => codes::MATRIX_ALIAS,
                };
                return Err(Diagnostic::coded(
                    code,
                    self.span(0),
                    format!("the destination of `{}` may not be {what}", self.mnemonic),
                )
                .with_label(format!("{} is also read here", self.d.reg))
                .with_secondary(self.span(i + 1), "same register")
                .with_help("write the result to another temporary"));
            }
        }
        Ok(())
    }

    fn mask_must_be(&self, allowed: &[u8], text: &str) -> R<()> {
        let d = self.d;
        if !allowed.contains(&d.mask.0) {
            let code = match self.mnemonic {
                "sincos" => codes::SINCOS_MASK,
                "crs" => codes::CRS_MASK,
                "nrm" => codes::NRM_MASK,
                _ => codes::MATRIX_MASK,
            };
            return Err(Diagnostic::coded(
                code,
                self.span(0),
                format!("`{}` needs the write mask {text}", self.mnemonic),
            )
            .with_label(format!(
                "mask is {}",
                if d.mask == WriteMask::ALL {
                    ".xyzw".to_string()
                } else {
                    d.mask.to_string()
                }
            )));
        }
        Ok(())
    }

    /// `dsx` / `dsy`: the rate of change of a source as written, without
    /// `-` or `_abs` (Microsoft refuses them, X5690).
    fn no_source_modifier(&self) -> R<()> {
        match self.src.iter().position(|s| s.modifier != SrcMod::None) {
            Some(i) => Err(Diagnostic::coded(
                codes::GRADIENT_MODIFIER,
                self.span(i + 1),
                format!("`{}` takes no `-` or `_abs` on its source", self.mnemonic),
            )
            .with_label("modifier not allowed here")
            .with_help("apply the modifier to the result instead")),
            None => Ok(()),
        }
    }

    /// `crs`: a temporary (or oC#) within .xyz, unswizzled sources, neither of them
    /// the destination.
    fn crs(&self) -> R<()> {
        // Microsoft's validator also lets crs write a colour output.
        if self.d.reg.file != RegFile::ColorOut {
            self.need_temp()?;
        }
        self.mask_must_be(
            &[0b0001, 0b0010, 0b0100, 0b0011, 0b0101, 0b0110, 0b0111],
            "within .xyz",
        )?;
        for (i, s) in self.src.iter().enumerate() {
            if s.swizzle != Swizzle::IDENTITY {
                return Err(Diagnostic::coded(
                    codes::CRS_SWIZZLE,
                    self.span(i + 1),
                    "`crs` sources take no swizzle",
                )
                .with_label("remove the swizzle"));
            }
        }
        self.not_aliased(&[0, 1], "one of its sources")
    }

    /// `m#x#` with `rows` matrix rows: the mask of `rows` components, a plain
    /// matrix operand that exists and does not hold the destination.
    fn matrix(&self, rows: u32) -> R<()> {
        let (d, mnemonic) = (self.d, self.mnemonic);
        let (mask, text): (u8, &str) = match rows {
            2 => (0b0011, ".xy"),
            3 => (0b0111, ".xyz"),
            _ => (0b1111, ".xyzw"),
        };
        self.mask_must_be(&[mask], text)?;
        let m = &self.src[1];
        if m.swizzle != Swizzle::IDENTITY || m.modifier != SrcMod::None {
            return Err(Diagnostic::coded(
                codes::MATRIX_MODIFIER,
                self.span(2),
                format!("the matrix operand of `{mnemonic}` takes no swizzle or modifier"),
            )
            .with_label("must be a plain register"));
        }
        self.not_aliased(&[0], "its vector source")?;
        if d.reg.file == m.reg.file && (m.reg.index..m.reg.index + rows).contains(&d.reg.index) {
            return Err(Diagnostic::coded(
                codes::MATRIX_ROWS_ALIAS,
                self.span(0),
                format!(
                    "the destination of `{mnemonic}` may not be one of the matrix rows {}…",
                    m.reg
                ),
            )
            .with_label("overlaps the matrix"));
        }
        // Every row is read as .xyz or .xyzw, and vPos has only .x and .y.
        // Microsoft's validator sees vPos and vFace as the two registers of
        // one file (misc 0 and 1 in the token): rows past those two are out
        // of range first (m3x3 vPos), two rows fail on vPos's .z (m3x2).
        if m.reg.file == RegFile::Position && rows <= 2 {
            return Err(Diagnostic::coded(
                codes::VPOS_ZW,
                self.span(2),
                format!("`{mnemonic}` reads .z of every matrix row, and vPos has no .z"),
            )
            .with_label("vPos has only .x and .y"));
        }
        // The rows must exist in the profile's file; a vertex shader's
        // float constants are not checked (measured: `m4x4 r0, v0, c8190`
        // is accepted in every vertex profile). Each profile has its code.
        let vertex_consts = m.reg.file == RegFile::Const
            && self.profile.stage() == crate::core::profile::Stage::Vertex;
        let count = self.profile.count(m.reg.file);
        if !vertex_consts && m.reg.index.saturating_add(rows) > count {
            let code = match self.profile {
                Profile::Ps2_0 | Profile::Ps2X => codes::PS2_MATRIX_RANGE,
                Profile::Vs2_0 | Profile::Vs2X => codes::VS2_MATRIX_RANGE,
                Profile::Vs3_0 => codes::VS3_MATRIX_RANGE,
                _ => codes::MATRIX_RANGE,
            };
            return Err(Diagnostic::coded(
                code,
                self.span(2),
                format!(
                    "the matrix {}…+{} runs past the last register",
                    m.reg,
                    rows - 1
                ),
            )
            .with_label("out of range"));
        }
        Ok(())
    }
}

fn shape_text(mnemonic: &str, shape: &[Operand]) -> String {
    let names: Vec<&str> = shape
        .iter()
        .map(|o| match o {
            Operand::Dst => "dst",
            Operand::Src => "src",
            Operand::ScalarSrc => "src.c",
            Operand::Sampler => "s#",
            Operand::IntReg => "i#",
            Operand::LoopCounter => "aL",
            Operand::Label => "l#",
            Operand::Condition => "[!]b# | [!]p0.c",
            Operand::PredDst => "p0",
            Operand::KillSrc => "src",
            Operand::FloatLits => "x, y, z, w",
            Operand::IntLits => "x, y, z, w",
            Operand::BoolLit => "true|false",
        })
        .collect();
    if names.is_empty() {
        mnemonic.to_string()
    } else {
        format!("{mnemonic} {}", names.join(", "))
    }
}

fn destination(r: &RegAst, kind: Operand, p: Profile) -> R<Dst> {
    let reg = resolve_reg(r, p)?;
    if reg.file == RegFile::Predicate {
        return Err(Diagnostic::coded(
            codes::PREDICATE_WRITE,
            r.name_span,
            "only setp writes the predicate register p0",
        )
        .with_label("not a destination here"));
    }
    if kind == Operand::KillSrc {
        // texkill reads x, y and z: Microsoft's validator finds vPos's
        // missing z before it asks what texkill may name.
        if reg.file == RegFile::Position {
            return Err(Diagnostic::coded(
                codes::VPOS_ZW,
                r.span,
                "texkill reads .xyz, and vPos has no .z",
            )
            .with_label("vPos has only .x and .y"));
        }
        if reg.file == RegFile::DepthOut {
            return Err(Diagnostic::coded(
                codes::TEXKILL_DEPTH,
                r.span,
                "texkill takes a temporary r#, an input v# or a colour output oC#, not oDepth",
            )
            .with_label("expected r#, v# or oC#"));
        }
        if !matches!(
            reg.file,
            RegFile::Temp | RegFile::Input | RegFile::ColorOut | RegFile::Texture
        ) {
            return Err(Diagnostic::coded(
                codes::DESTINATION,
                r.span,
                "texkill takes a temporary r#, an input v# or a colour output oC#",
            )
            .with_label("expected r#, v# or oC#"));
        }
    } else if !reg.file.info().writable {
        return Err(Diagnostic::coded(
            codes::DESTINATION,
            r.name_span,
            format!("`{reg}` cannot be written"),
        )
        .with_label("not a destination")
        .with_help("destinations are r#, oC# and oDepth (and p0 for setp)"));
    }
    // Microsoft's assembler refuses these itself (texkill's operand is a
    // destination in the token stream): `-` or `!` before it as a syntax
    // error, `_abs` after it with its own code.
    if r.negate || r.not {
        return Err(Diagnostic::error(r.span, "a destination takes no modifier")
            .with_label("remove the modifier"));
    }
    if r.abs {
        return Err(Diagnostic::coded(
            codes::DESTINATION_MODIFIER,
            r.span,
            "a destination takes no modifier",
        )
        .with_label("remove the modifier"));
    }
    let (reg, relative) = match &r.relative {
        Some(_) if reg.file == RegFile::Output => match relative::index(r, reg, p)? {
            Some((index, number)) => (
                Reg {
                    file: reg.file,
                    index: number,
                },
                Some(index),
            ),
            None => (reg, None),
        },
        Some(rel) => {
            return Err(Diagnostic::coded(
                codes::DESTINATION_RELATIVE,
                rel.span,
                "a destination cannot be relatively addressed",
            )
            .with_label("only vs_3_0's outputs o[aL + n] may be indexed"))
        }
        None => (reg, None),
    };
    Ok(Dst {
        reg,
        relative,
        mask: write_mask(r)?,
    })
}

fn source_modifier(r: &RegAst) -> SrcMod {
    match (r.negate, r.abs, r.not) {
        (_, _, true) => SrcMod::Not,
        (true, true, _) => SrcMod::NegAbs,
        (true, false, _) => SrcMod::Neg,
        (false, true, _) => SrcMod::Abs,
        _ => SrcMod::None,
    }
}

fn float_source(r: &RegAst, p: Profile) -> R<Src> {
    let reg = resolve_reg(r, p)?;
    match reg.file {
        RegFile::Temp
        | RegFile::Input
        | RegFile::Const
        | RegFile::Position
        | RegFile::Face
        | RegFile::Texture => {}
        RegFile::LoopCounter => {
            return Err(Diagnostic::coded(
                codes::SOURCE_REGISTER,
                r.span,
                "aL can only be used as an index",
            )
            .with_label("not a float source")
            .with_help("read inputs relative to the loop counter with v[aL + n]"))
        }
        _ => {
            // The assembler words the rule per stage (measured: `mov r0, a0`).
            let code = match p {
                Profile::Vs3_0 => codes::SOURCE_REGISTER_VS_3_0,
                Profile::Vs2_0 | Profile::Vs2X | Profile::Vs2A => codes::SOURCE_REGISTER_VS,
                _ => codes::SOURCE_REGISTER,
            };
            return Err(Diagnostic::coded(
                code,
                r.name_span,
                format!("`{reg}` cannot be read here"),
            )
            .with_label("not a float source")
            .with_help(if p.stage() == crate::core::profile::Stage::Vertex {
                "float sources are r#, v# and c# (a0 and aL only index: c[a0.x + n])"
            } else {
                "float sources are r#, v#, c#, vPos and vFace"
            }));
        }
    }
    if let (RegFile::Face, Some((_, span))) = (reg.file, &r.components) {
        return Err(Diagnostic::coded(
            codes::SCALAR,
            *span,
            "vFace is a scalar register: no swizzle",
        )
        .with_label("remove the swizzle"));
    }
    if r.not {
        return Err(Diagnostic::coded(
            codes::SOURCE_MODIFIER,
            r.span,
            "`!` only applies to b# and p0 conditions",
        )
        .with_label("use `-` to negate"));
    }
    let (index, relative) = match relative::index(r, reg, p)? {
        Some((index, number)) => (number, Some(index)),
        None => (reg.index, None),
    };
    Ok(Src {
        reg: Reg {
            file: reg.file,
            index,
        },
        relative,
        swizzle: swizzle(r)?,
        modifier: source_modifier(r),
    })
}

fn plain_of(r: &RegAst, file: RegFile, what: &str, p: Profile) -> R<Src> {
    let reg = resolve_reg(r, p)?;
    if reg.file != file {
        return Err(Diagnostic::error(r.span, format!("expected {what}"))
            .with_label(format!("`{reg}` is not {what}")));
    }
    no_modifiers(r, &format!("`{reg}`"))?;
    if r.components.is_some() {
        return Err(
            Diagnostic::coded(codes::SCALAR, r.span, format!("`{reg}` takes no swizzle"))
                .with_label("remove the swizzle"),
        );
    }
    Ok(Src::plain(reg))
}

fn predicate_operand(r: &RegAst, allow_full: bool, p: Profile) -> R<Src> {
    let reg = resolve_reg(r, p)?;
    if reg.file != RegFile::Predicate {
        return Err(
            Diagnostic::coded(codes::SYNTAX, r.span, "expected the predicate register p0")
                .with_label("expected p0 or !p0.c"),
        );
    }
    if r.negate || r.abs {
        return Err(Diagnostic::coded(
            codes::PREDICATE_MODIFIER,
            r.span,
            "a predicate takes only `!`",
        )
        .with_label("remove `-` or `_abs`"));
    }
    let s = swizzle(r)?;
    if !(s.is_replicate() || allow_full || s == Swizzle::IDENTITY) {
        return Err(Diagnostic::coded(
            codes::PREDICATE_SWIZZLE,
            r.span,
            "a predicate needs one component or none",
        )
        .with_label("e.g. p0.x"));
    }
    Ok(Src {
        reg,
        relative: None,
        swizzle: s,
        modifier: if r.not { SrcMod::Not } else { SrcMod::None },
    })
}

fn condition(r: &RegAst, p: Profile) -> R<Src> {
    let reg = resolve_reg(r, p)?;
    match reg.file {
        RegFile::ConstBool => {
            if r.negate || r.abs || r.components.is_some() || r.relative.is_some() {
                return Err(
                    Diagnostic::error(r.span, "a boolean condition is written b# or !b#")
                        .with_label("remove the modifier or swizzle"),
                );
            }
            Ok(Src {
                reg,
                relative: None,
                swizzle: Swizzle::IDENTITY,
                modifier: if r.not { SrcMod::Not } else { SrcMod::None },
            })
        }
        RegFile::Predicate => {
            let s = predicate_operand(r, false, p)?;
            if !s.swizzle.is_replicate() {
                return Err(Diagnostic::coded(
                    codes::PREDICATE_REPLICATE,
                    r.span,
                    "a predicate condition selects one component",
                )
                .with_label("write p0.x, p0.y, p0.z or p0.w"));
            }
            Ok(s)
        }
        _ => Err(Diagnostic::coded(
            codes::CALLNZ_CONDITION,
            r.span,
            "expected a condition: b#, !b#, p0.c or !p0.c",
        )
        .with_label("not a condition")),
    }
}

#[cfg(test)]
mod tests {
    use super::edit_distance;

    #[test]
    fn edit_distance_counts_insertions_deletions_and_substitutions() {
        assert_eq!(edit_distance("kitten", "sitting"), 3);
        assert_eq!(edit_distance("tex1d", "texld"), 1);
        assert_eq!(edit_distance("", "texldl"), 6);
        assert_eq!(edit_distance("texldl", ""), 6);
        assert_eq!(edit_distance("мov", "mov"), 1);
        assert_eq!(edit_distance("mov", "mov"), 0);
        // A long name against a short mnemonic: every extra letter counts.
        assert_eq!(edit_distance(&"x".repeat(40), "mov"), 40);
    }
}
