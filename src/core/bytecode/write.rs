//! The writer: assembly statements → [`Module`] → tokens, exactly the tokens
//! Microsoft's assembler emits for the same program.
//!
//! [`assemble`] encodes the statements REPEAT_BLOCK expansion produced, in
//! the order they stand (ps30 keeps source order: Wine's own writer moves
//! declarations and definitions to the top, but whether Microsoft's does is
//! not documented, none of Wine's vectors mixes them, and source order is
//! what makes a listing assemble back to the tokens it came from). It is the
//! encoder alone, like an assembler run with validation off: it refuses only
//! what has no encoding (an unknown mnemonic or register, a modifier no bit
//! carries); whether the program follows the
//! ps_3_0 rules is validation's verdict, which `ps30 asm` requires first.
//! [`encode`] lays a module out as tokens.

use super::{
    dest_token, relative_token, source_token, Dest, Extra, Instr, Item, ItemKind, Module, Source,
    CENTROID, COMMENT, END, PP, SAT,
};
use crate::core::diag::{codes, Diagnostic, Diagnostics};
use crate::core::front::ast::{InstrAst, OperandAst, RegAst, Stmt};
use crate::core::front::repeat::Expanded;
use crate::core::ir::{Reg, RelIndex, Span, SrcMod};
use crate::core::isa::{Class, Compare, Opcode, Operand, USAGES};
use crate::core::profile::Profile;
use crate::core::valid::register::{resolve_reg, swizzle, write_mask};
use std::collections::HashMap;

type R<T> = Result<T, Diagnostic>;

/// The tokens of a module: version, items, end.
pub fn encode(module: &Module) -> Vec<u32> {
    let mut out = vec![module.profile.version_token()];
    for item in &module.items {
        match &item.kind {
            ItemKind::Comment(body) => {
                out.push(COMMENT | (body.len() as u32) << 16);
                out.extend(body);
            }
            ItemKind::Instr(i) => instruction_tokens(i, &mut out),
        }
    }
    out.push(END);
    out
}

/// The tokens as bytes, little-endian.
pub fn to_bytes(tokens: &[u32]) -> Vec<u8> {
    tokens.iter().flat_map(|t| t.to_le_bytes()).collect()
}

fn instruction_tokens(i: &Instr, out: &mut Vec<u32>) {
    let row = i.op.info();
    let control = i.compare.map_or(row.control, Compare::code) as u32;
    out.push(
        row.code as u32
            | control << 16
            | i.operand_tokens() << 24
            | u32::from(i.predicate.is_some()) << 28,
    );
    if let Extra::Decl {
        usage,
        index,
        texture,
    } = i.extra
    {
        out.push(0x8000_0000 | usage as u32 | (index as u32) << 16 | (texture as u32) << 27);
    }
    if let Some(d) = &i.dst {
        out.push(dest_token(d));
        out.extend(d.relative.map(relative_token));
    }
    let mut source = |s: &Source| {
        out.push(source_token(s));
        out.extend(s.relative.map(relative_token));
    };
    if let Some(p) = &i.predicate {
        source(p);
    }
    i.src.iter().for_each(&mut source);
    match i.extra {
        Extra::Float(v) => out.extend(v),
        Extra::Int(v) => out.extend(v.map(|x| x as u32)),
        Extra::Bool(b) => out.push(u32::from(b)),
        Extra::None | Extra::Decl { .. } => {}
    }
}

/// Encodes expanded statements. Every statement that has no encoding is an
/// error (each distinct statement is reported once).
pub fn assemble(stmts: &[Stmt], expanded: &[Expanded]) -> Result<Module, Diagnostics> {
    let mut diags = Diagnostics::default();
    let mut items = Vec::with_capacity(expanded.len());
    let mut cache: HashMap<usize, Option<ItemKind>> = HashMap::new();
    let mut token = 1u32;
    let profile = expanded
        .first()
        .and_then(|e| crate::core::valid::checked_profile(&stmts[e.stmt]))
        .unwrap_or_default();
    for (n, e) in expanded.iter().enumerate() {
        let kind = match &stmts[e.stmt] {
            s @ Stmt::Version { .. }
                if n == 0 && crate::core::valid::checked_profile(s).is_some() =>
            {
                continue
            }
            Stmt::Version { text, span, .. } => {
                diags.push(version_error(text, *span, n == 0));
                continue;
            }
            _ if n == 0 => {
                diags.push(
                    Diagnostic::error(e.origin.span, "the version token must come first")
                        .with_label("expected `ps_3_0` before this"),
                );
                continue;
            }
            Stmt::RepeatBegin { .. } | Stmt::RepeatEnd { .. } => continue,
            Stmt::Comment { tokens, .. } => Some(ItemKind::Comment(tokens.clone())),
            Stmt::Instr(ast) => cache
                .entry(e.stmt)
                .or_insert_with(|| match instruction(ast, profile) {
                    Ok(i) => Some(ItemKind::Instr(i)),
                    Err(d) => {
                        diags.push(d);
                        None
                    }
                })
                .clone(),
        };
        let Some(kind) = kind else { continue };
        let len = match &kind {
            ItemKind::Comment(body) => body.len() as u32,
            ItemKind::Instr(i) => i.operand_tokens(),
        };
        items.push(Item { token, kind });
        token = token.saturating_add(1 + len);
    }
    if expanded.is_empty() {
        diags.push(Diagnostic::error(
            Span::default(),
            "nothing to assemble: no version line",
        ));
    }
    match diags.has_errors() {
        true => Err(diags),
        false => Ok(Module { profile, items }),
    }
}

fn version_error(text: &str, span: Span, first: bool) -> Diagnostic {
    if first {
        Diagnostic::error(
            span,
            format!("`{text}`: ps30 writes ps_2_0, ps_2_x, ps_3_0, vs_2_0, vs_2_x and vs_3_0"),
        )
        .with_label("not a profile ps30 writes")
    } else {
        Diagnostic::error(span, "a second version line")
            .with_label("the version token comes once, first")
    }
}

fn cannot(span: Span, message: impl Into<String>) -> Diagnostic {
    Diagnostic::coded(codes::SYNTAX, span, message).with_label("no encoding in ps_3_0 bytecode")
}

/// One statement's instruction.
fn instruction(ast: &InstrAst, p: Profile) -> R<Instr> {
    let predicate = ast.predicate.as_ref().map(|r| source(r, p)).transpose()?;
    let mut instr = match ast.base.as_str() {
        "dcl" => declaration(ast, p)?,
        "def" | "defi" | "defb" => definition(ast, p)?,
        _ => operation(ast, p)?,
    };
    instr.predicate = predicate;
    Ok(instr)
}

/// The result modifiers and comparison of a mnemonic's suffixes; `kind`
/// takes any other suffix (a declaration's usage), or refuses it.
fn suffixes(ast: &InstrAst, mut kind: impl FnMut(&str, Span) -> R<()>) -> R<(u8, Option<Compare>)> {
    let mut result = 0;
    let mut compare = None;
    for (s, span) in &ast.suffixes {
        match (s.as_str(), Compare::from_suffix(s)) {
            ("sat", _) => result |= SAT,
            ("pp", _) => result |= PP,
            ("centroid", _) => result |= CENTROID,
            (_, Some(c)) if compare.is_none() => compare = Some(c),
            _ => kind(s, *span)?,
        }
    }
    Ok((result, compare))
}

/// An arithmetic, texture or flow-control instruction.
fn operation(ast: &InstrAst, p: Profile) -> R<Instr> {
    let (result, compare) = suffixes(ast, |s, span| {
        Err(cannot(span, format!("`_{s}` is not a ps_3_0 modifier")))
    })?;
    let op = Opcode::from_mnemonic(&ast.base, compare.is_some())
        .filter(|op| op.class() != Class::Declaration)
        .ok_or_else(|| cannot(ast.base_span, format!("unknown instruction `{}`", ast.base)))?;
    let row = op.info_in(p);
    if compare.is_some() != row.comparison {
        return Err(cannot(
            ast.base_span,
            format!(
                "`{}` with a comparison suffix it does not take, or without one it needs",
                row.mnemonic
            ),
        ));
    }
    if ast.operands.len() != row.operands.len() {
        return Err(cannot(
            ast.span,
            format!(
                "`{}` has {} operands, not {}",
                row.mnemonic,
                row.operands.len(),
                ast.operands.len()
            ),
        ));
    }
    let mut instr = Instr {
        op,
        compare,
        predicate: None,
        dst: None,
        src: Vec::new(),
        extra: Extra::None,
    };
    for (kind, operand) in row.operands.iter().zip(&ast.operands) {
        let OperandAst::Reg(reg) = operand else {
            return Err(cannot(
                operand.span(),
                "a literal where the instruction takes a register",
            ));
        };
        match kind {
            Operand::Dst | Operand::PredDst | Operand::KillSrc => {
                instr.dst = Some(dest(reg, result, p)?)
            }
            _ => instr.src.push(source(reg, p)?),
        }
    }
    if result != 0 && instr.dst.is_none() {
        return Err(cannot(
            ast.base_span,
            format!(
                "`{}` has no destination to carry its result modifier",
                row.mnemonic
            ),
        ));
    }
    if op == Opcode::Sub {
        sub_as_add(&mut instr);
    }
    Ok(instr)
}

/// Microsoft's assembler writes no `sub`: `sub a, b, c` becomes `add a, b,
/// -c`, the second source's negation turned around (`-c` gives `c`, `c_abs`
/// gives `-c_abs`), and ps30 writes the tokens it writes. (The reader still
/// reads D3DSIO_SUB from other tools.)
pub fn sub_as_add(instr: &mut Instr) {
    instr.op = Opcode::Add;
    if let Some(s) = instr.src.get_mut(1) {
        s.modifier = match s.modifier {
            SrcMod::None => SrcMod::Neg,
            SrcMod::Neg => SrcMod::None,
            SrcMod::Abs => SrcMod::NegAbs,
            SrcMod::NegAbs => SrcMod::Abs,
            other => other,
        };
    }
}

/// `dcl_<usage><n>`, `dcl_2d`, `dcl` with their register.
fn declaration(ast: &InstrAst, p: Profile) -> R<Instr> {
    let (mut usage, mut index, mut texture, mut seen) = (0u8, 0u8, 0u8, false);
    let (result, compare) = suffixes(ast, |s, span| {
        if seen {
            return Err(cannot(span, format!("a second declaration kind `_{s}`")));
        }
        seen = true;
        texture = match s {
            "1d" => 1,
            "2d" => 2,
            "cube" => 3,
            "volume" => 4,
            _ => 0,
        };
        if texture == 0 {
            let name = s.trim_end_matches(|c: char| c.is_ascii_digit());
            let digits = &s[name.len()..];
            let n = match digits {
                "" => Some(0),
                d => d.parse::<u8>().ok().filter(|n| *n <= 15),
            };
            match (USAGES.iter().position(|u| *u == name), n) {
                (Some(code), Some(n)) => (usage, index) = (code as u8, n),
                _ => {
                    return Err(cannot(
                        span,
                        format!(
                            "`_{s}` is not a declaration usage (index 0 to 15) or sampler type"
                        ),
                    ))
                }
            }
        }
        Ok(())
    })?;
    if let Some(c) = compare {
        return Err(cannot(
            ast.base_span,
            format!("`dcl` with the comparison `_{}`", c.suffix()),
        ));
    }
    let [OperandAst::Reg(reg)] = ast.operands.as_slice() else {
        return Err(cannot(ast.span, "a declaration names one register"));
    };
    Ok(Instr {
        op: Opcode::Dcl,
        compare: None,
        predicate: None,
        dst: Some(dest(reg, result, p)?),
        src: Vec::new(),
        extra: Extra::Decl {
            usage,
            index,
            texture,
        },
    })
}

/// `def`, `defi`, `defb`.
fn definition(ast: &InstrAst, p: Profile) -> R<Instr> {
    let (result, compare) = suffixes(ast, |s, span| {
        Err(cannot(span, format!("`_{s}` on a definition")))
    })?;
    let (op, values) = match ast.base.as_str() {
        "def" => (Opcode::Def, 4),
        "defi" => (Opcode::DefI, 4),
        _ => (Opcode::DefB, 1),
    };
    if compare.is_some() || ast.operands.len() != values + 1 {
        return Err(cannot(
            ast.span,
            format!("`{}` is a register and {values} values", ast.base),
        ));
    }
    let OperandAst::Reg(reg) = &ast.operands[0] else {
        return Err(cannot(
            ast.operands[0].span(),
            "the defined register comes first",
        ));
    };
    let dst = dest(reg, result, p)?;
    let literal = &ast.operands[1..];
    let extra = match op {
        Opcode::DefB => match literal[0] {
            OperandAst::Bool { value, .. } => Extra::Bool(value),
            ref other => return Err(cannot(other.span(), "`defb` takes true or false")),
        },
        _ => {
            let mut v = [0u32; 4];
            for (slot, operand) in v.iter_mut().zip(literal) {
                *slot = number(operand, op == Opcode::DefI)?;
            }
            if op == Opcode::DefI {
                Extra::Int(v.map(|x| x as i32))
            } else {
                Extra::Float(v)
            }
        }
    };
    Ok(Instr {
        op,
        compare: None,
        predicate: None,
        dst: Some(dst),
        src: Vec::new(),
        extra,
    })
}

/// A literal as its token: a float rounded to single precision as
/// validation rounds it, or a 32-bit integer.
fn number(operand: &OperandAst, integer: bool) -> R<u32> {
    let OperandAst::Number {
        value,
        integer: written_int,
        special: _,
        span,
    } = *operand
    else {
        return Err(cannot(operand.span(), "a number is expected here"));
    };
    if integer {
        // Up to 2^32 - 1, the low 32 bits, as Microsoft's assembler keeps
        // them (`4294967295` is -1).
        if !written_int || value < i32::MIN as f64 || value > u32::MAX as f64 {
            return Err(cannot(span, "`defi` takes 32-bit integers"));
        }
        return Ok(if value < 0.0 {
            value as i32 as u32
        } else {
            value as u32
        });
    }
    // Out of range is infinity, as Microsoft's assembler writes it (`def
    // c0, 1e39` is `1.#INF` in its listing); a spelled NaN keeps its bits.
    Ok(crate::core::front::ast::single(value).to_bits())
}

/// A register in destination format.
fn dest(reg: &RegAst, result: u8, p: Profile) -> R<Dest> {
    if reg.negate || reg.not || reg.abs {
        return Err(cannot(
            reg.span,
            "a destination takes no `-`, `!` or `_abs`",
        ));
    }
    let (reg_, relative) = indexed(reg, p)?;
    Ok(Dest {
        reg: reg_,
        mask: write_mask(reg)?,
        relative,
        result,
    })
}

/// The register of an operand with its relative addressing folded in: the
/// number the token carries (base plus offsets) and the index register.
fn indexed(reg: &RegAst, p: Profile) -> R<(Reg, Option<RelIndex>)> {
    let base = resolve_reg(reg, p)?;
    let Some(rel) = &reg.relative else {
        return Ok((base, None));
    };
    let index = match (rel.index_reg.as_str(), rel.index_component) {
        ("aL", _) if rel.index_swizzle.is_none() => RelIndex::Loop,
        ("a0", Some(c)) => RelIndex::Addr(c),
        _ => {
            return Err(cannot(
                rel.span,
                "the index register is aL or one component of a0",
            ))
        }
    };
    let numbered = base.file.info().numbered;
    if !numbered && rel.offset != 0 {
        return Err(cannot(rel.span, "this register takes no offset"));
    }
    // A base past what the token numbers wraps, as Microsoft's assembler
    // writes it (`c[a0.x + 8195]` is `c3[a0.x]`, `v[aL + 2048]` `v0[aL]`).
    let number = (base.index as i64)
        .saturating_add(rel.offset)
        .rem_euclid(i64::from(base.file.token_registers()));
    let reg = Reg {
        file: base.file,
        index: number as u32,
    };
    Ok((reg, Some(index)))
}

/// A register in source format.
fn source(reg: &RegAst, p: Profile) -> R<Source> {
    let modifier = match (reg.negate, reg.abs, reg.not) {
        (false, false, false) => SrcMod::None,
        (true, false, false) => SrcMod::Neg,
        (false, true, false) => SrcMod::Abs,
        (true, true, false) => SrcMod::NegAbs,
        (false, false, true) => SrcMod::Not,
        _ => return Err(cannot(reg.span, "`!` together with `_abs`")),
    };
    let (reg_, relative) = indexed(reg, p)?;
    Ok(Source {
        reg: reg_,
        relative,
        swizzle: swizzle(reg)?,
        modifier,
    })
}
