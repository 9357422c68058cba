//! The assembly writer: prints a program as plain ps_3_0 assembly (no
//! macros), which the front end parses back to the same program.

use crate::core::ir::{Dst, Instruction, Program, Reg, RelIndex, Src, SrcMod};
use crate::core::isa::{Opcode, RegFile};
use std::fmt::Write;

/// Prints a whole program: version, declarations, definitions, then the
/// instructions indented by block depth.
pub fn write_program(p: &Program) -> String {
    let mut out = String::from("ps_3_0\n");
    for d in &p.inputs {
        let head = match d.reg.file {
            RegFile::Input => format!("dcl_{}{}", d.usage, d.usage_index),
            _ => "dcl".to_string(),
        };
        let mods = modifiers(d.centroid, d.pp);
        let _ = writeln!(out, "{head}{mods} {}{}", d.reg, d.mask);
    }
    for d in &p.samplers {
        let mods = modifiers(d.centroid, d.pp);
        let _ = writeln!(out, "dcl_{}{mods} s{}", d.ty.suffix(), d.index);
    }
    for d in &p.float_defs {
        let v = d.value.map(|x| format!("{x:?}"));
        let _ = writeln!(out, "def c{}, {}", d.index, v.join(", "));
    }
    for d in &p.int_defs {
        let v = d.value.map(|x| x.to_string());
        let _ = writeln!(out, "defi i{}, {}", d.index, v.join(", "));
    }
    for d in &p.bool_defs {
        let _ = writeln!(out, "defb b{}, {}", d.index, d.value);
    }
    let mut depth = 0usize;
    for ins in &p.instructions {
        if matches!(
            ins.op,
            Opcode::EndRep | Opcode::EndLoop | Opcode::EndIf | Opcode::Else | Opcode::Label
        ) {
            depth = depth.saturating_sub(1);
        }
        let _ = writeln!(out, "{}{}", "    ".repeat(depth), write_instruction(ins));
        if ins.op.opens_block() || matches!(ins.op, Opcode::Else | Opcode::Label) {
            depth += 1;
        }
        if ins.op == Opcode::Ret {
            depth = 0;
        }
    }
    out
}

/// `_centroid` and `_pp` of a declaration.
fn modifiers(centroid: bool, pp: bool) -> String {
    format!(
        "{}{}",
        if centroid { "_centroid" } else { "" },
        if pp { "_pp" } else { "" }
    )
}

/// Prints one instruction without comment or indentation.
pub fn write_instruction(ins: &Instruction) -> String {
    let mut s = String::new();
    if let Some(p) = &ins.predicate {
        let _ = write!(s, "({}p0{}) ", if p.negate { "!" } else { "" }, p.swizzle);
    }
    s.push_str(ins.op.info().mnemonic);
    if let Some(c) = ins.compare {
        let _ = write!(s, "_{}", c.suffix());
    }
    for (on, name) in [
        (ins.sat, "_sat"),
        (ins.pp, "_pp"),
        (ins.centroid, "_centroid"),
    ] {
        if on {
            s.push_str(name);
        }
    }
    let mut operands: Vec<String> = Vec::new();
    if let Some(d) = &ins.dst {
        operands.push(write_dst(d));
    }
    operands.extend(ins.src.iter().map(write_src));
    if !operands.is_empty() {
        s.push(' ');
        s.push_str(&operands.join(", "));
    }
    s
}

fn write_dst(d: &Dst) -> String {
    match d.relative {
        Some(index) => format!("{}{}", relative_reg(d.reg, index), d.mask),
        None => format!("{}{}", d.reg, d.mask),
    }
}

/// `v[aL + 2]`, `c[a0.x]`: a relatively addressed register as the parser
/// reads it (the offset is the register's number).
fn relative_reg(reg: Reg, index: RelIndex) -> String {
    let name = reg.file.info().name;
    match reg.index {
        0 => format!("{name}[{index}]"),
        n => format!("{name}[{index} + {n}]"),
    }
}

/// Prints a source operand with its modifiers.
pub fn write_src(s: &Src) -> String {
    let reg = match s.relative {
        Some(index) => relative_reg(s.reg, index),
        None => s.reg.to_string(),
    };
    match s.modifier {
        SrcMod::None => format!("{reg}{}", s.swizzle),
        SrcMod::Neg => format!("-{reg}{}", s.swizzle),
        SrcMod::Abs => format!("{reg}_abs{}", s.swizzle),
        SrcMod::NegAbs => format!("-{reg}_abs{}", s.swizzle),
        SrcMod::Not => format!("!{reg}{}", s.swizzle),
    }
}
