//! A ps_1_x program as `D3DDisassemble` lists it, byte for byte: the
//! version, one instruction a line indented four spaces (a co-issued one
//! `  + `), `def` values as `%.9g` ([`microsoft::def_value`]), the shift
//! and then `_sat` after the mnemonic, sources as `-r0_bx2.w`, `1-v1`,
//! `t0_dw.xyww` (selectors in xyzw letters, as for ps_2_0), then a blank
//! line and the slot line with ps_1_x's count ([`Program::slots`]).
//!
//! The text reads back: Microsoft's assembler and ps30's reader take it
//! (`tests/oracle` holds both), so it is also the listing a compiled
//! ps_1_x shader is read as.

use super::{Dest, Instr, Modifier, Program, Source};
use crate::core::bytecode::microsoft;
use std::fmt::Write;

/// Microsoft's listing of a program.
pub fn listing(p: &Program) -> String {
    let mut out = format!("    {}\n", p.profile);
    for i in &p.instrs {
        out.push_str(if i.coissue { "  + " } else { "    " });
        out.push_str(&instruction(i));
        out.push('\n');
    }
    let _ = writeln!(out, "\n{}", p.slots().listing_line());
    out
}

/// One instruction as the listing prints it.
pub fn instruction(i: &Instr) -> String {
    let mut s = i.op.info().mnemonic.to_string();
    if let Some(d) = &i.dst {
        s.push_str(shift(d.shift));
        if d.sat {
            s.push_str("_sat");
        }
    }
    let mut operands: Vec<String> = i.dst.iter().map(dest).collect();
    operands.extend(i.src.iter().map(source));
    if let Some(bits) = i.def {
        operands.extend(bits.iter().map(|&b| microsoft::def_value(b)));
    }
    if !operands.is_empty() {
        s.push(' ');
        s.push_str(&operands.join(", "));
    }
    s
}

fn shift(k: i8) -> &'static str {
    match k {
        1 => "_x2",
        2 => "_x4",
        3 => "_x8",
        -1 => "_d2",
        -2 => "_d4",
        -3 => "_d8",
        _ => "",
    }
}

/// A destination: the register and the letters of its mask (none when
/// every component is written).
pub fn dest(d: &Dest) -> String {
    let mut s = d.reg.to_string();
    if d.mask.0 != 15 {
        s.push('.');
        s.extend(
            (0..4)
                .filter(|c| d.mask.0 & 1 << c != 0)
                .map(|c| b"xyzw"[c] as char),
        );
    }
    s
}

/// A source: `-`, `1-`, the register, the modifier's suffix, the selector.
pub fn source(s: &Source) -> String {
    let pre = match s.modifier {
        Modifier::Comp => "1-",
        m if m.negated() => "-",
        _ => "",
    };
    format!(
        "{pre}{}{}{}",
        s.reg,
        s.modifier.suffix(),
        microsoft::swizzle_text(s.swizzle)
    )
}
