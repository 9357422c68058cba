//! A D3D9 token encoder for tests: a loaded program back to the DWORD
//! token stream Microsoft's assembler writes, so that tests can compare what
//! ps30 understood with token arrays written by others (Wine's assembler
//! vectors in tests/wine_vectors.rs, the shaders of Wine's Direct3D 9 tests
//! in tests/conformance.rs).
//!
//! Written from the DDK's instruction-token, source- and
//! destination-parameter-token and relative-addressing pages and the
//! D3DSPR_* / D3DSIO_* values of d3d9types.h, independent of the crate.

// Not every test crate that includes this module uses every function.
#![allow(dead_code)]

use ps30::core::ir::{Dst, Instruction, Program, Src, SrcMod, Swizzle};
use ps30::core::isa::{Compare, Opcode, RegFile, SamplerType};

pub fn opcode_number(op: Opcode) -> (u32, u32) {
    // (D3DSIO_* opcode, control bits that select the variant)
    match op {
        Opcode::Nop => (0x00, 0),
        Opcode::Mov => (0x01, 0),
        Opcode::Add => (0x02, 0),
        Opcode::Sub => (0x03, 0),
        Opcode::Mad => (0x04, 0),
        Opcode::Mul => (0x05, 0),
        Opcode::Rcp => (0x06, 0),
        Opcode::Rsq => (0x07, 0),
        Opcode::Dp3 => (0x08, 0),
        Opcode::Dp4 => (0x09, 0),
        Opcode::Min => (0x0a, 0),
        Opcode::Max => (0x0b, 0),
        Opcode::Exp => (0x0e, 0),
        Opcode::Log => (0x0f, 0),
        Opcode::Lrp => (0x12, 0),
        Opcode::Frc => (0x13, 0),
        Opcode::M4x4 => (0x14, 0),
        Opcode::M4x3 => (0x15, 0),
        Opcode::M3x4 => (0x16, 0),
        Opcode::M3x3 => (0x17, 0),
        Opcode::M3x2 => (0x18, 0),
        Opcode::Call => (0x19, 0),
        Opcode::CallNz => (0x1a, 0),
        Opcode::Loop => (0x1b, 0),
        Opcode::Ret => (0x1c, 0),
        Opcode::EndLoop => (0x1d, 0),
        Opcode::Label => (0x1e, 0),
        Opcode::Pow => (0x20, 0),
        Opcode::Crs => (0x21, 0),
        Opcode::Abs => (0x23, 0),
        Opcode::Nrm => (0x24, 0),
        Opcode::SinCos => (0x25, 0),
        Opcode::Rep => (0x26, 0),
        Opcode::EndRep => (0x27, 0),
        Opcode::If => (0x28, 0),
        Opcode::Ifc => (0x29, 0),
        Opcode::Else => (0x2a, 0),
        Opcode::EndIf => (0x2b, 0),
        Opcode::Break => (0x2c, 0),
        Opcode::BreakC => (0x2d, 0),
        Opcode::TexKill => (0x41, 0),
        Opcode::TexLd => (0x42, 0),
        Opcode::TexLdP => (0x42, 1),
        Opcode::TexLdB => (0x42, 2),
        Opcode::Cmp => (0x58, 0),
        Opcode::Dp2Add => (0x5a, 0),
        Opcode::Dsx => (0x5b, 0),
        Opcode::Dsy => (0x5c, 0),
        Opcode::TexLdD => (0x5d, 0),
        Opcode::Setp => (0x5e, 0),
        Opcode::TexLdL => (0x5f, 0),
        Opcode::BreakP => (0x60, 0),
        Opcode::Def | Opcode::DefI | Opcode::DefB | Opcode::Dcl => {
            unreachable!("declarations are not instructions")
        }
    }
}

pub fn compare_bits(c: Compare) -> u32 {
    match c {
        Compare::Gt => 1,
        Compare::Eq => 2,
        Compare::Ge => 3,
        Compare::Lt => 4,
        Compare::Ne => 5,
        Compare::Le => 6,
    }
}

/// D3DSPR_* register type and register number.
pub fn register(file: RegFile, index: u32) -> (u32, u32) {
    match file {
        RegFile::Temp => (0, index),
        RegFile::Input => (1, index),
        RegFile::Const => (2, index),
        RegFile::ConstInt => (7, index),
        RegFile::ColorOut => (8, index),
        RegFile::DepthOut => (9, 0),
        RegFile::Sampler => (10, index),
        RegFile::ConstBool => (14, index),
        RegFile::LoopCounter => (15, 0),
        RegFile::Position => (17, 0),
        RegFile::Face => (17, 1),
        RegFile::Label => (18, index),
        RegFile::Predicate => (19, 0),
    }
}

pub fn parameter(file: RegFile, index: u32) -> u32 {
    let (ty, n) = register(file, index);
    0x8000_0000 | ((ty & 7) << 28) | ((ty & 0x18) << 8) | n
}

pub fn swizzle_bits(s: Swizzle) -> u32 {
    s.0.iter()
        .enumerate()
        .map(|(i, &c)| (c as u32) << (2 * i))
        .sum()
}

pub fn destination(d: &Dst, modifiers: u32) -> u32 {
    parameter(d.reg.file, d.reg.index) | (d.mask.0 as u32) << 16 | modifiers << 20
}

pub fn source(s: &Src) -> Vec<u32> {
    let modifier = match s.modifier {
        SrcMod::None => 0,
        SrcMod::Neg => 1,
        SrcMod::Abs => 11,
        SrcMod::NegAbs => 12,
        SrcMod::Not => 13,
    };
    let mut t = parameter(s.reg.file, s.reg.index) | swizzle_bits(s.swizzle) << 16 | modifier << 24;
    if s.relative {
        // The relative-address token names aL, identity swizzle.
        t |= 1 << 13;
        vec![t, parameter(RegFile::LoopCounter, 0) | 0xe4 << 16]
    } else {
        vec![t]
    }
}

pub fn encode_instruction(ins: &Instruction) -> Vec<u32> {
    let (opcode, mut control) = opcode_number(ins.op);
    if let Some(c) = ins.compare {
        control = compare_bits(c);
    }
    let modifiers = ins.sat as u32 | (ins.pp as u32) << 1 | (ins.centroid as u32) << 2;
    let mut params = Vec::new();
    if let Some(d) = &ins.dst {
        params.push(destination(d, modifiers));
    }
    if let Some(p) = &ins.predicate {
        params.push(
            parameter(RegFile::Predicate, 0)
                | swizzle_bits(p.swizzle) << 16
                | if p.negate { 13 << 24 } else { 0 },
        );
    }
    for s in &ins.src {
        params.extend(source(s));
    }
    let token = opcode
        | control << 16
        | (params.len() as u32) << 24
        | (ins.predicate.is_some() as u32) << 28;
    let mut out = vec![token];
    out.extend(params);
    out
}

/// D3DDECLUSAGE values, in order (d3d9types.h): the instruction table's
/// usage list is in that order.
pub const USAGE_CODES: &[&str] = ps30::core::isa::USAGES;

pub fn encode_declarations(p: &Program) -> Vec<u32> {
    let mut out = Vec::new();
    for d in &p.inputs {
        let usage = match d.reg.file {
            RegFile::Input => {
                let code = USAGE_CODES
                    .iter()
                    .position(|u| *u == d.usage)
                    .expect("known usage") as u32;
                code | d.usage_index << 16
            }
            _ => 0,
        };
        let modifiers = (d.pp as u32) << 1 | (d.centroid as u32) << 2;
        let dst = parameter(d.reg.file, d.reg.index) | (d.mask.0 as u32) << 16 | modifiers << 20;
        out.extend([0x0200_001f, 0x8000_0000 | usage, dst]);
    }
    for d in &p.samplers {
        let ty = match d.ty {
            SamplerType::Tex2d => 2,
            SamplerType::Cube => 3,
            SamplerType::Volume => 4,
        };
        out.extend([
            0x0200_001f,
            0x8000_0000 | ty << 27,
            parameter(RegFile::Sampler, d.index) | 0xf << 16,
        ]);
    }
    for d in &p.float_defs {
        out.extend([0x0500_0051, parameter(RegFile::Const, d.index) | 0xf << 16]);
        out.extend(d.value.map(f32::to_bits));
    }
    for d in &p.int_defs {
        out.extend([
            0x0500_0030,
            parameter(RegFile::ConstInt, d.index) | 0xf << 16,
        ]);
        out.extend(d.value.map(|v| v as u32));
    }
    for d in &p.bool_defs {
        out.extend([
            0x0200_002f,
            parameter(RegFile::ConstBool, d.index) | 0xf << 16,
            d.value as u32,
        ]);
    }
    out
}

pub fn encode(p: &Program) -> Vec<u32> {
    let mut out = vec![0xffff_0300];
    out.extend(encode_declarations(p));
    for ins in &p.instructions {
        out.extend(encode_instruction(ins));
    }
    out.push(0x0000_ffff);
    out
}

/// The instruction tokens of a stream: without version, end, dcl and def*.
pub fn instruction_tokens(tokens: &[u32]) -> Vec<u32> {
    let body = &tokens[1..tokens.len() - 1];
    let mut out = Vec::new();
    let mut i = 0;
    while i < body.len() {
        let len = ((body[i] >> 24) & 0xf) as usize;
        let op = body[i] & 0xffff;
        if !matches!(op, 0x1f | 0x2f | 0x30 | 0x51) {
            out.extend_from_slice(&body[i..=i + len]);
        }
        i += len + 1;
    }
    out
}

pub fn hex(tokens: &[u32]) -> String {
    let t: Vec<String> = tokens.iter().map(|t| format!("{t:08x}")).collect();
    t.join(" ")
}
