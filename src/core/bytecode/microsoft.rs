//! The listing Microsoft's `D3DDisassemble` writes (flags 0), byte for byte.
//!
//! Users compare what `ps30 disasm` prints with the listing fxc gave them,
//! and diff tools compare listings of a game's shaders line by line, so
//! ps30's default listing is Microsoft's text exactly. Every rule here was
//! read off `d3dcompiler_47.dll`'s answers (the fixtures of
//! `tests/oracle/`), not off its documentation:
//!
//! * the constant table, if the shader has one, as
//!   [`ctab::listing_header`] writes it; every other comment block is left
//!   out;
//! * with a debug-information block ([`dbug`], shaders compiled with
//!   `D3DCOMPILE_DEBUG`), a blank line and `#line N "FILE"` before an
//!   instruction whose source file differs from the previous one's,
//!   `#line N` alone where the line moves by more than 2, and
//!   `  // name<i,j>` after an instruction (or `dcl`) that writes a
//!   variable: the variable components its destination's x, y, z, w hold;
//! * `    ps_3_0`, then one instruction per line, indented 4 spaces plus 2
//!   per open `if`/`rep`/`loop`/`else` (`else`, `endif`, `endrep` and
//!   `endloop` close one first; `label` and `ret` change nothing);
//! * `def` values as C's `%.9g` in Microsoft's C runtime ([`def_value`]);
//!   `defi` as integers, `defb` as `true`/`false`;
//! * `dcl` with the sampler type (`_2d`, `_cube`, `_volume`; no suffix for
//!   type 0, `_unknown` for any other) or the usage and its index
//!   (`dcl_texcoord`, `dcl_color1`; nothing for position 0);
//! * mnemonic suffixes in the order comparison, `_sat`, `_pp`, `_centroid`;
//! * sources as `-r0_abs.x`, relative ones as `v1[aL]` (the register the
//!   token names, with the loop counter in brackets); swizzles as four
//!   letters unless they are the identity (no suffix) or one letter
//!   repeated (`.x`); write masks as the letters they hold;
//! * `breakp`'s operand as `D3DDisassemble` prints it, as a destination
//!   (`break p0.` for `breakp p0.x`: its swizzle bits read as a write mask
//!   and result modifiers, its modifier as a shift);
//! * a blank line and `// approximately N instruction slots used`, with
//!   `(T texture, A arithmetic)` when T is not 0 and `slot` when N is 1,
//!   counted by [`OpInfo::fxc_split_of`](crate::core::isa::OpInfo::fxc_split_of).
//!
//! The text ends with that line's newline: the blob `D3DDisassemble`
//! returns holds one more byte, a NUL terminating the C string, which is
//! not part of the listing and is not printed.

use super::dbug::{self, SourceLine};
use super::{
    ctab, modifier_code, Dest, Extra, Instr, ItemKind, Module, Source, CENTROID, CTAB, PP, SAT,
};
use crate::core::ir::{SrcMod, Swizzle, WriteMask};
use crate::core::isa::{Opcode, RegFile, USAGES};
use crate::core::profile::{Profile, Stage};
use std::collections::HashMap;
use std::fmt::Write;

/// Microsoft's listing of a module.
pub fn listing(module: &Module) -> String {
    let mut out = module
        .items
        .iter()
        .find_map(|i| match &i.kind {
            ItemKind::Comment(body) if body.first() == Some(&CTAB) => {
                Some(ctab::listing_header(&body[1..], false))
            }
            _ => None,
        })
        .unwrap_or_default();
    let _ = writeln!(out, "    {}", module.profile);
    let mut debug = Debug::of(module);
    let mut depth = 0usize;
    let instrs = module.items.iter().filter_map(|i| match &i.kind {
        ItemKind::Instr(ins) => Some((i.token, ins)),
        ItemKind::Comment(_) => None,
    });
    for (index, (token, ins)) in instrs.enumerate() {
        if matches!(
            ins.op,
            Opcode::EndRep | Opcode::EndLoop | Opcode::EndIf | Opcode::Else
        ) {
            depth = depth.saturating_sub(1);
        }
        debug.line_directive(&mut out, token.wrapping_mul(4));
        out.push_str(&" ".repeat(4 + 2 * depth));
        out.push_str(&instruction_in(ins, module.profile));
        out.push_str(debug.note(index));
        out.push('\n');
        if ins.op.opens_block() || ins.op == Opcode::Else {
            depth += 1;
        }
    }
    let (texture, arithmetic) = slots(module);
    let total = texture + arithmetic;
    let _ = write!(
        out,
        "\n// approximately {total} instruction slot{} used",
        if total == 1 { "" } else { "s" }
    );
    if texture > 0 {
        let _ = write!(out, " ({texture} texture, {arithmetic} arithmetic)");
    }
    out.push('\n');
    out
}

/// What the listing takes from a debug-information block ([`dbug`]): the
/// source line of each instruction, the variable notes, and the last
/// `#line` position written.
#[derive(Default)]
struct Debug {
    lines: HashMap<u32, SourceLine>,
    notes: HashMap<u32, String>,
    names: Vec<String>,
    file: Option<u16>,
    line: u16,
}

impl Debug {
    /// The first `DBUG` block's contents; nothing if there is none or it
    /// does not decode (Microsoft's disassembler would follow its bad
    /// offsets; ps30 writes the listing without it).
    fn of(module: &Module) -> Debug {
        let info = module.items.iter().find_map(|i| match &i.kind {
            ItemKind::Comment(body) if body.first() == Some(&dbug::DBUG) => Some(body),
            _ => None,
        });
        match info.and_then(|body| dbug::decode(&body[1..]).ok()) {
            Some(info) => Debug {
                lines: info.lines_by_offset(),
                notes: info.notes(),
                names: info.files,
                file: None,
                line: 0,
            },
            None => Debug::default(),
        }
    }

    /// Writes `#line` before the instruction at byte `offset`, after a
    /// blank line, as `D3DDisassemble` does: with the file's name when the
    /// file changes (nothing for a file the table does not name), with the number alone when the line moves by more than
    /// 2 from the previous instruction's that had one.
    fn line_directive(&mut self, out: &mut String, offset: u32) {
        let Some(at) = self.lines.get(&offset) else {
            return;
        };
        if self.file != Some(at.file) {
            if let Some(name) = self.names.get(usize::from(at.file)) {
                let _ = writeln!(out, "\n#line {} \"{name}\"", at.line);
            }
        } else if at.line.abs_diff(self.line) > 2 {
            let _ = writeln!(out, "\n#line {}", at.line);
        }
        self.file = Some(at.file);
        self.line = at.line;
    }

    /// The notes after instruction number `index`, or nothing.
    fn note(&self, index: usize) -> &str {
        u32::try_from(index)
            .ok()
            .and_then(|i| self.notes.get(&i))
            .map_or("", String::as_str)
    }
}

/// The listing's slot count as (texture, arithmetic).
pub fn slots(module: &Module) -> (u32, u32) {
    module
        .items
        .iter()
        .filter_map(|i| match &i.kind {
            ItemKind::Instr(ins) => Some(ins.op.info().fxc_split_of(ins.predicate.is_some())),
            ItemKind::Comment(_) => None,
        })
        .fold((0, 0), |(t, a), (dt, da)| (t + dt, a + da))
}

/// One instruction as the listing writes it, without indentation.
pub fn instruction(ins: &Instr) -> String {
    instruction_in(ins, Profile::Ps3_0)
}

/// One instruction of a `profile` shader as the listing writes it.
pub fn instruction_in(ins: &Instr, profile: Profile) -> String {
    let mut line = String::new();
    if let Some(p) = &ins.predicate {
        let _ = write!(line, "({}) ", source(p));
    }
    if ins.op == Opcode::BreakP {
        if let Some(s) = ins.src.first() {
            line.push_str(&breakp(s));
            return line;
        }
    }
    line.push_str(&mnemonic(ins, profile));
    let mut operands: Vec<String> = Vec::new();
    operands.extend(ins.dst.as_ref().map(dest));
    operands.extend(ins.src.iter().map(source));
    match &ins.extra {
        Extra::Float(v) => operands.extend(v.iter().map(|&b| def_value(b))),
        Extra::Int(v) => operands.extend(v.iter().map(i32::to_string)),
        Extra::Bool(b) => operands.push(b.to_string()),
        Extra::None | Extra::Decl { .. } => {}
    }
    for (i, o) in operands.iter().enumerate() {
        line.push_str(if i == 0 { " " } else { ", " });
        line.push_str(o);
    }
    line
}

/// The mnemonic with its suffixes: comparison, declaration, result
/// modifiers.
fn mnemonic(ins: &Instr, profile: Profile) -> String {
    let mut m = ins.op.info().mnemonic.to_string();
    if let Some(c) = ins.compare {
        let _ = write!(m, "_{}", c.suffix());
    }
    if let (
        Extra::Decl {
            usage,
            index,
            texture,
        },
        Some(d),
    ) = (ins.extra, &ins.dst)
    {
        if d.reg.file == RegFile::Sampler {
            m.push_str(match texture {
                0 => "",
                2 => "_2d",
                3 => "_cube",
                4 => "_volume",
                _ => "_unknown",
            });
        } else if usage != 0 || index != 0 || profile.stage() == Stage::Vertex {
            let name = USAGES.get(usage as usize).copied().unwrap_or("unknown");
            let _ = write!(m, "_{name}");
            if index != 0 {
                let _ = write!(m, "{index}");
            }
        }
    }
    m.push_str(&result_suffixes(ins.dst.map_or(0, |d| d.result)));
    m
}

/// `_sat`, `_pp`, `_centroid`, in that order, for the bits set.
fn result_suffixes(result: u8) -> String {
    [(SAT, "_sat"), (PP, "_pp"), (CENTROID, "_centroid")]
        .iter()
        .filter(|(bit, _)| result & bit != 0)
        .map(|(_, name)| *name)
        .collect()
}

/// `breakp p0.x` as `D3DDisassemble` prints it: `break`, then the
/// source token read as a destination — the modifier bits as a shift, the
/// high swizzle bits as result modifiers, the low ones as a write mask.
fn breakp(s: &Source) -> String {
    let code: u8 = s
        .swizzle
        .0
        .iter()
        .enumerate()
        .map(|(i, &c)| (c & 3) << (2 * i))
        .sum();
    let shift = match modifier_code(s.modifier) {
        1 => "_x2",
        2 => "_x4",
        3 => "_x8",
        13 => "_d8",
        14 => "_d4",
        15 => "_d2",
        _ => "",
    };
    format!(
        "break{shift}{} {}{}",
        result_suffixes(code >> 4),
        s.reg,
        mask_text(WriteMask(code & 0xF))
    )
}

/// A destination: the register and its write mask.
pub fn dest(d: &Dest) -> String {
    let relative = d.relative.map(|i| format!("[{i}]")).unwrap_or_default();
    format!("{}{relative}{}", d.reg, mask_text(d.mask))
}

/// Nothing for a full mask, else `.` and the components written (only `.`
/// for none).
fn mask_text(mask: WriteMask) -> String {
    if mask == WriteMask::ALL {
        return String::new();
    }
    let letters: String = ["x", "y", "z", "w"]
        .iter()
        .enumerate()
        .filter(|(i, _)| mask.has(*i))
        .map(|(_, c)| *c)
        .collect();
    format!(".{letters}")
}

/// A source: `-c7[aL]_abs.y`, `!b0`, `r2.yzww`.
pub fn source(s: &Source) -> String {
    let (pre, abs) = match s.modifier {
        SrcMod::None => ("", ""),
        SrcMod::Neg => ("-", ""),
        SrcMod::Abs => ("", "_abs"),
        SrcMod::NegAbs => ("-", "_abs"),
        SrcMod::Not => ("!", ""),
    };
    let relative = s.relative.map(|i| format!("[{i}]")).unwrap_or_default();
    format!("{pre}{}{relative}{abs}{}", s.reg, swizzle_text(s.swizzle))
}

/// Nothing for the identity, one letter for a replicate, else all four.
pub fn swizzle_text(s: Swizzle) -> String {
    const LETTERS: [char; 4] = ['x', 'y', 'z', 'w'];
    if s == Swizzle::IDENTITY {
        return String::new();
    }
    let n = if s.is_replicate() { 1 } else { 4 };
    let mut out = String::from(".");
    out.extend(s.0[..n].iter().map(|&c| LETTERS[c as usize & 3]));
    out
}

/// A `def` value as `D3DDisassemble` prints it: C's `%.9g` of the value
/// widened to a double, in Microsoft's C runtime — nine significant
/// digits, halves rounded away from zero (the exact decimal value is
/// rounded, `1000000.625` → `1000000.63`), trailing zeros dropped, an
/// exponent of at least three digits past 1e9 and below 1e-4
/// (`1.00000001e-010`), `-0` kept, infinities `1.#INF` and `-1.#INF`, a NaN
/// with the sign bit set `-1.#IND`, any other NaN `1.#QNAN`.
pub fn def_value(bits: u32) -> String {
    let x = f32::from_bits(bits);
    let sign = if bits >> 31 == 1 { "-" } else { "" };
    if x.is_nan() {
        return if sign.is_empty() {
            "1.#QNAN"
        } else {
            "-1.#IND"
        }
        .to_string();
    }
    if x.is_infinite() {
        return format!("{sign}1.#INF");
    }
    if x == 0.0 {
        return format!("{sign}0");
    }
    let (digits, exponent) = nine_digits(f64::from(x.abs()));
    let text = if (-4..9).contains(&exponent) {
        // Fixed notation: the point after digit `exponent`, zeros ahead of
        // the digits when the value is below 1.
        let (padded, point) = if exponent >= 0 {
            (digits, exponent as usize + 1)
        } else {
            (
                format!("{}{digits}", "0".repeat(exponent.unsigned_abs() as usize)),
                1,
            )
        };
        join(&padded[..point], &padded[point..])
    } else {
        let e_sign = if exponent < 0 { '-' } else { '+' };
        format!(
            "{}e{e_sign}{:03}",
            join(&digits[..1], &digits[1..]),
            exponent.unsigned_abs()
        )
    };
    format!("{sign}{text}")
}

/// `int.frac` without the fraction's trailing zeros (and without the point
/// when nothing is left of it).
fn join(int: &str, frac: &str) -> String {
    let frac = frac.trim_end_matches('0');
    if frac.is_empty() {
        int.to_string()
    } else {
        format!("{int}.{frac}")
    }
}

/// The nine significant digits of a positive finite value, rounded half
/// away from zero from its exact decimal expansion, and the decimal
/// exponent of the first one. A float widened to a double has at most 112
/// significant decimal digits, so 120 digits of Rust's exact formatting
/// are the whole expansion.
fn nine_digits(v: f64) -> (String, i32) {
    let exact = format!("{v:.120e}");
    let (mantissa, exp) = exact.split_once('e').unwrap_or((&exact, "0"));
    let mut exponent: i32 = exp.parse().unwrap_or(0);
    let all: Vec<u8> = mantissa.bytes().filter(u8::is_ascii_digit).collect();
    let mut digits: Vec<u8> = all.iter().take(9).copied().collect();
    if all.get(9).is_some_and(|&d| d >= b'5') {
        let mut i = digits.len();
        loop {
            if i == 0 {
                // 999999999.5 and the like: one more digit in front.
                digits.insert(0, b'1');
                digits.pop();
                exponent += 1;
                break;
            }
            i -= 1;
            if digits[i] == b'9' {
                digits[i] = b'0';
            } else {
                digits[i] += 1;
                break;
            }
        }
    }
    (String::from_utf8_lossy(&digits).into_owned(), exponent)
}
