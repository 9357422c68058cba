//! ps_1_x assembly text to a [`Program`]: Microsoft's grammar for these
//! versions, with its refusals (X2000 for what the grammar does not hold,
//! X2005 for a register the version lacks, X2012 for a complement with
//! another modifier, X2003 and X2004 for masks and swizzles).
//!
//! One statement a line: an optional `+` (co-issue), the mnemonic with its
//! modifiers (`_x2`, `_x4`, `_x8`, `_d2`, `_d4`, `_d8`, then `_sat`: the
//! other order, or `_pp`, is refused), then the operands. A source is
//! `[-][1-]REG[_bias|_bx2|_x2|_dz|_db|_dw|_da][.sel]`; `_db` is `_dz` and
//! `_da` is `_dw`, as Microsoft's listing shows.

use super::{Dest, Instr, Modifier, Program, Source};
use crate::core::diag::{codes, Diagnostic, Diagnostics};
use crate::core::front::{ast, parse};
use crate::core::ir::{Reg, Span, Swizzle, WriteMask};
use crate::core::isa::{Opcode, Operand, RegFile};
use crate::core::profile::Profile;

type R<T> = Result<T, Diagnostic>;

/// Parses a ps_1_x source whose version line names `profile`: every
/// statement after the version line, or every error of the grammar.
pub fn parse(text: &str, profile: Profile) -> Result<Program, Diagnostics> {
    let (prepared, to_source, mut diags) = parse::prepare(text);
    let mut instrs = Vec::new();
    let mut seen_version = false;
    let mut start = 0;
    for line in prepared.split_inclusive('\n') {
        let at = start;
        start += line.len();
        let code = parse::strip_comment(line.trim_end_matches(['\n', '\r']));
        let lead = code.len() - code.trim_start().len();
        let code = code.trim();
        if code.is_empty() {
            continue;
        }
        if !seen_version {
            seen_version = true;
            continue;
        }
        match statement(code, at + lead, profile) {
            Ok(i) => instrs.push(i),
            Err(mut d) => {
                d.map_spans(&*to_source);
                diags.push(d);
            }
        }
    }
    for i in &mut instrs {
        remap(i, &*to_source);
    }
    if diags.has_errors() {
        diags.sort();
        return Err(diags);
    }
    Ok(Program { profile, instrs })
}

fn remap(i: &mut Instr, f: &dyn Fn(Span) -> Span) {
    i.span = f(i.span);
    i.base_span = f(i.base_span);
    if let Some(d) = &mut i.dst {
        d.span = f(d.span);
    }
    for s in &mut i.src {
        s.span = f(s.span);
    }
}

fn syntax(span: Span, what: &str) -> Diagnostic {
    Diagnostic::coded(
        codes::SYNTAX,
        span,
        format!("syntax error: unexpected token '{what}'"),
    )
}

/// One statement (trimmed, starting at byte `at` of the text).
fn statement(code: &str, at: usize, profile: Profile) -> R<Instr> {
    let span = Span::new(at, at + code.len());
    let (coissue, rest, rest_at) = match code.strip_prefix('+') {
        Some(r) => {
            let trimmed = r.trim_start();
            (true, trimmed, at + code.len() - trimmed.len())
        }
        None => (false, code, at),
    };
    let word_len = rest
        .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .unwrap_or(rest.len());
    let word = &rest[..word_len];
    let base_span = Span::new(rest_at, rest_at + word_len);
    if word.is_empty() {
        return Err(syntax(span, code));
    }
    let mut parts = word.split('_');
    let base = parts.next().unwrap_or_default();
    let op = Opcode::from_mnemonic_in(base, false, profile)
        .filter(|op| op.profiles().has(profile))
        .ok_or_else(|| {
            syntax(base_span, word).with_help(format!("`{base}` is not a {profile} instruction"))
        })?;
    let (shift, sat) = instruction_modifiers(parts.collect(), op).ok_or_else(|| {
        syntax(base_span, word).with_help("ps_1_x modifiers: _x2 _x4 _x8 _d2 _d4 _d8, then _sat")
    })?;
    let shape = op.info_in(profile).operands;
    let operands = split_operands(&rest[word_len..], rest_at + word_len);
    let mut instr = Instr {
        op,
        coissue,
        dst: None,
        src: Vec::new(),
        def: None,
        span,
        base_span,
    };
    let expected = shape.len() + if op == Opcode::Def { 3 } else { 0 };
    if operands.len() != expected {
        let place = operands.get(expected).map_or(span, |o| o.1);
        return Err(syntax(place, word).with_help(format!(
            "`{base}` takes {expected} operands, {} given",
            operands.len()
        )));
    }
    for (kind, (text, place)) in shape.iter().zip(&operands) {
        match kind {
            Operand::Dst | Operand::KillSrc => {
                instr.dst = Some(dest(text, *place, profile, shift, sat)?)
            }
            Operand::FloatLits => {}
            _ => instr.src.push(source(text, *place, profile)?),
        }
    }
    if op == Opcode::Def {
        let mut bits = [0u32; 4];
        for (b, (text, place)) in bits.iter_mut().zip(&operands[1..]) {
            *b = number(text, *place)?.to_bits();
        }
        instr.def = Some(bits);
    }
    Ok(instr)
}

/// The shift and `_sat` of the mnemonic's suffixes, in Microsoft's order
/// (shift first); `None` for anything else, or for either on `def` or
/// `phase`.
fn instruction_modifiers(suffixes: Vec<&str>, op: Opcode) -> Option<(i8, bool)> {
    let mut shift = 0i8;
    let mut sat = false;
    for s in suffixes {
        let k = match s {
            "x2" => 1,
            "x4" => 2,
            "x8" => 3,
            "d2" => -1,
            "d4" => -2,
            "d8" => -3,
            "sat" if !sat => {
                sat = true;
                continue;
            }
            _ => return None,
        };
        if shift != 0 || sat {
            return None;
        }
        shift = k;
    }
    // The grammar takes them on any instruction with a destination; the
    // rules refuse them on texture instructions (X5042, X5043, X5128, X5129).
    let declaration = op.info().class == crate::core::isa::Class::Declaration;
    (!(declaration && (sat || shift != 0))).then_some((shift, sat))
}

/// The operands after the mnemonic, each trimmed with its place.
fn split_operands(rest: &str, at: usize) -> Vec<(String, Span)> {
    if rest.trim().is_empty() {
        return Vec::new();
    }
    let mut out = Vec::new();
    let mut start = 0;
    for piece in rest.split(',') {
        let lead = piece.len() - piece.trim_start().len();
        let t = piece.trim();
        let s = at + start + lead;
        out.push((t.to_string(), Span::new(s, s + t.len())));
        start += piece.len() + 1;
    }
    out
}

/// A register name and number (`r0`, `t3`): its file among ps_1_x's and
/// index, when the version has it.
fn register(text: &str, place: Span, profile: Profile) -> R<(Reg, String)> {
    let invalid = || {
        Diagnostic::coded(codes::REGISTER, place, format!("invalid register '{text}'"))
            .with_help(format!("{profile} has {}", register_files(profile)))
    };
    let name_len = text
        .find(|c: char| !c.is_ascii_alphabetic())
        .unwrap_or(text.len());
    let digits = text[name_len..]
        .find(|c: char| !c.is_ascii_digit())
        .map_or(text.len(), |d| name_len + d);
    let file = match &text[..name_len] {
        "r" => RegFile::Temp,
        "c" => RegFile::Const,
        "t" => RegFile::Texture,
        "v" => RegFile::Input,
        _ => return Err(invalid()),
    };
    let index: u32 = text[name_len..digits].parse().map_err(|_| invalid())?;
    if index >= profile.count(file) {
        return Err(invalid());
    }
    Ok((Reg { file, index }, text[digits..].to_string()))
}

/// The register files of a ps_1_x version, for help text.
fn register_files(profile: Profile) -> String {
    let n = |f| profile.count(f);
    format!(
        "r0–r{}, c0–c{}, t0–t{}, v0–v1",
        n(RegFile::Temp) - 1,
        n(RegFile::Const) - 1,
        n(RegFile::Texture) - 1
    )
}

fn dest(text: &str, place: Span, profile: Profile, shift: i8, sat: bool) -> R<Dest> {
    let (body, sel) = split_selector(text);
    let (reg, rest) = register(body.trim(), place, profile)?;
    if !rest.is_empty() {
        return Err(Diagnostic::coded(
            codes::REGISTER,
            place,
            format!("invalid register '{body}'"),
        ));
    }
    let mask = match sel {
        None => WriteMask::ALL,
        Some(s) => mask(s)
            .ok_or_else(|| Diagnostic::coded(codes::MASK, place, format!("invalid mask '{s}'")))?,
    };
    Ok(Dest {
        reg,
        mask,
        shift,
        sat,
        span: place,
    })
}

fn split_selector(text: &str) -> (&str, Option<&str>) {
    match text.rsplit_once('.') {
        Some((a, b)) => (a, Some(b)),
        None => (text, None),
    }
}

/// A component letter: `xyzw` or `rgba`, with which set it is from.
fn component(c: char) -> Option<(u8, bool)> {
    match c {
        'x' | 'y' | 'z' | 'w' => Some(("xyzw".find(c)? as u8, false)),
        'r' | 'g' | 'b' | 'a' => Some(("rgba".find(c)? as u8, true)),
        _ => None,
    }
}

fn mask(s: &str) -> Option<WriteMask> {
    let mut bits = 0u8;
    let mut last: Option<u8> = None;
    let mut set = None;
    for c in s.chars() {
        let (k, rgba) = component(c)?;
        if last.is_some_and(|l| l >= k) || set.is_some_and(|r| r != rgba) {
            return None;
        }
        set = Some(rgba);
        last = Some(k);
        bits |= 1 << k;
    }
    (bits != 0).then_some(WriteMask(bits))
}

fn swizzle(s: &str) -> Option<Swizzle> {
    let mut comps = Vec::new();
    let mut set = None;
    for c in s.chars() {
        let (k, rgba) = component(c)?;
        if set.is_some_and(|r| r != rgba) {
            return None;
        }
        set = Some(rgba);
        comps.push(k);
    }
    let last = *comps.last()?;
    if comps.len() > 4 {
        return None;
    }
    comps.resize(4, last);
    Some(Swizzle([comps[0], comps[1], comps[2], comps[3]]))
}

fn source(text: &str, place: Span, profile: Profile) -> R<Source> {
    let (negate, rest) = match text.strip_prefix('-') {
        Some(r) => (true, r.trim_start()),
        None => (false, text),
    };
    let (complement, rest) = match rest.strip_prefix('1') {
        Some(r) if r.trim_start().starts_with('-') => (true, r.trim_start()[1..].trim_start()),
        _ => (false, rest),
    };
    if negate && complement {
        return Err(syntax(place, text));
    }
    let (body, sel) = split_selector(rest);
    let (reg, suffix) = register(body.trim(), place, profile)?;
    let modifier = match (suffix.as_str(), negate) {
        ("", false) if complement => Modifier::Comp,
        ("", false) => Modifier::None,
        ("", true) => Modifier::Neg,
        (_, _) if complement => {
            return Err(Diagnostic::coded(
                codes::COMPLEMENT_WITH_MODIFIER,
                place,
                "complement cannot be used with other modifiers",
            ))
        }
        ("_bias", n) => [Modifier::Bias, Modifier::BiasNeg][usize::from(n)],
        ("_bx2", n) => [Modifier::Bx2, Modifier::Bx2Neg][usize::from(n)],
        ("_x2", n) => [Modifier::X2, Modifier::X2Neg][usize::from(n)],
        ("_dz" | "_db", false) => Modifier::Dz,
        ("_dw" | "_da", false) => Modifier::Dw,
        _ => {
            return Err(Diagnostic::coded(
                codes::REGISTER,
                place,
                format!("invalid register '{body}'"),
            ))
        }
    };
    let swizzle = match sel {
        None => Swizzle::IDENTITY,
        Some(s) => swizzle(s).ok_or_else(|| {
            Diagnostic::coded(codes::SWIZZLE, place, format!("invalid swizzle '{s}'"))
        })?,
    };
    Ok(Source {
        reg,
        swizzle,
        modifier,
        span: place,
    })
}

/// A `def` value: a decimal number, `f` suffix allowed, rounded to single
/// precision.
fn number(text: &str, place: Span) -> R<f32> {
    let t = text.strip_suffix(['f', 'F']).unwrap_or(text);
    t.parse::<f64>()
        .ok()
        .filter(|v| v.is_finite())
        .map(ast::single)
        .ok_or_else(|| syntax(place, text).with_help("`def` takes four numbers"))
}
