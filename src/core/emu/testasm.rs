//! A tiny assembler for the emulator's unit tests.
//!
//! The real parser and validator live elsewhere and are not available to the
//! emulator's tests; this turns a few lines of ps_3_0 text into a [`Program`]
//! and derives the [`Info`] (block matching, labels, slots) the validator would
//! produce, so tests read like shaders. It accepts only well-formed input and
//! panics otherwise (tests only).

use crate::core::ir::{
    BoolDef, Dst, FloatDef, Info, InputDecl, Instruction, IntDef, Origin, Predicate, Program, Reg,
    SamplerDecl, Shader, Src, SrcMod, Swizzle, WriteMask,
};
use crate::core::isa::{Compare, Opcode, Operand, RegFile, SamplerType};

/// Builds [`Info`] from a flat instruction list, as the validator would:
/// block matching, label positions, `main_end`, and slots (table slots, cube
/// slots for cube samplers, +1 when predicated).
pub fn build_info(program: &Program) -> Info {
    let ins = &program.instructions;
    let mut matching = vec![None; ins.len()];
    let mut labels = std::collections::BTreeMap::new();
    let mut stack: Vec<usize> = Vec::new();
    let mut slots = Vec::with_capacity(ins.len());
    for (i, x) in ins.iter().enumerate() {
        match x.op {
            Opcode::Rep | Opcode::Loop | Opcode::If | Opcode::Ifc => stack.push(i),
            Opcode::Else => {
                let open = stack.pop().expect("else without if");
                matching[open] = Some(i as u32);
                stack.push(i);
            }
            Opcode::EndIf | Opcode::EndRep | Opcode::EndLoop => {
                let open = stack.pop().expect("unbalanced block");
                matching[open] = Some(i as u32);
                if x.op != Opcode::EndIf {
                    matching[i] = Some(open as u32);
                }
            }
            Opcode::Label => {
                labels.insert(x.src[0].reg.index, i as u32);
            }
            _ => {}
        }
        slots.push(program.slots_of(x));
    }
    assert!(stack.is_empty(), "unclosed block");
    let main_end = ins
        .iter()
        .position(|x| x.op == Opcode::Label)
        .unwrap_or(ins.len()) as u32;
    Info {
        matching,
        labels,
        main_end,
        slots,
    }
}

fn swizzle(s: &str) -> Swizzle {
    let mut out = [0u8; 4];
    let chars: Vec<u8> = s
        .chars()
        .map(|c| match c {
            'x' | 'r' => 0,
            'y' | 'g' => 1,
            'z' | 'b' => 2,
            'w' | 'a' => 3,
            _ => panic!("bad swizzle {s}"),
        })
        .collect();
    assert!(!chars.is_empty() && chars.len() <= 4, "bad swizzle {s}");
    for (i, o) in out.iter_mut().enumerate() {
        *o = chars[i.min(chars.len() - 1)];
    }
    Swizzle(out)
}

fn mask(s: &str) -> WriteMask {
    let sw = swizzle(s);
    let n = s.len();
    WriteMask(sw.0[..n].iter().fold(0, |m, &c| m | (1 << c)))
}

/// Parses a register name with optional `[aL + n]` relative part.
fn reg(s: &str) -> (Reg, bool) {
    let s = s.trim();
    if let Some(open) = s.find('[') {
        let (head, rest) = s.split_at(open);
        let inner = rest.trim_start_matches('[').trim_end_matches(']');
        let mut offset = 0;
        for part in inner.split('+') {
            let part = part.trim();
            if !part.eq_ignore_ascii_case("aL") {
                offset += part.parse::<u32>().expect("offset");
            }
        }
        let base = if head == "v" { 0 } else { reg(head).0.index };
        return (
            Reg {
                file: RegFile::Input,
                index: base + offset,
            },
            true,
        );
    }
    for (name, file) in [
        ("oDepth", RegFile::DepthOut),
        ("vPos", RegFile::Position),
        ("vFace", RegFile::Face),
        ("aL", RegFile::LoopCounter),
    ] {
        if s.eq_ignore_ascii_case(name) {
            return (Reg { file, index: 0 }, false);
        }
    }
    let split = s
        .find(|c: char| c.is_ascii_digit())
        .expect("register number");
    let (prefix, num) = s.split_at(split);
    let file = RegFile::lookup(prefix).unwrap_or_else(|| panic!("register {s}"));
    (
        Reg {
            file,
            index: num.parse().expect("register number"),
        },
        false,
    )
}

fn src(s: &str) -> Src {
    let mut s = s.trim();
    let mut modifier = SrcMod::None;
    if let Some(rest) = s.strip_prefix('-') {
        modifier = SrcMod::Neg;
        s = rest;
    } else if let Some(rest) = s.strip_prefix('!') {
        modifier = SrcMod::Not;
        s = rest;
    }
    // Swizzle after the last '.', outside brackets.
    let (body, sw) = match s.rfind('.') {
        Some(dot) if !s[dot..].contains(']') => (&s[..dot], Some(&s[dot + 1..])),
        _ => (s, None),
    };
    let body = match body.strip_suffix("_abs") {
        Some(b) => {
            modifier = if modifier == SrcMod::Neg {
                SrcMod::NegAbs
            } else {
                SrcMod::Abs
            };
            b
        }
        None => body,
    };
    let (reg, relative) = reg(body);
    Src {
        reg,
        relative: relative.then_some(crate::core::ir::RelIndex::Loop),
        swizzle: sw.map(swizzle).unwrap_or(Swizzle::IDENTITY),
        modifier,
    }
}

fn dst(s: &str) -> Dst {
    let s = s.trim();
    let (body, m) = match s.find('.') {
        Some(dot) => (&s[..dot], mask(&s[dot + 1..])),
        None => (s, WriteMask::ALL),
    };
    Dst {
        reg: reg(body).0,
        relative: None,
        mask: m,
    }
}

/// Assembles ps_3_0 text (one statement per line; `//` and `;` comments).
pub fn program(text: &str) -> Program {
    let mut p = Program::default();
    for line in text.lines() {
        let line = line.split("//").next().unwrap_or("");
        let line = line.split(';').next().unwrap_or("").trim();
        if line.is_empty() || line.starts_with("ps_3_0") {
            continue;
        }
        let (mut head, rest) = match line.find(char::is_whitespace) {
            Some(i) => (&line[..i], line[i..].trim()),
            None => (line, ""),
        };
        let mut rest = rest.to_string();
        let mut predicate = None;
        if head.starts_with('(') {
            let close = line.find(')').expect("predicate");
            let inner = &line[1..close];
            let (negate, inner) = match inner.strip_prefix('!') {
                Some(i) => (true, i),
                None => (false, inner),
            };
            let sw = inner.split('.').nth(1).map(swizzle);
            predicate = Some(Predicate {
                negate,
                swizzle: sw.unwrap_or(Swizzle::IDENTITY),
            });
            let after = line[close + 1..].trim();
            let i = after.find(char::is_whitespace).unwrap_or(after.len());
            head = &after[..i];
            rest = after[i..].trim().to_string();
        }
        let ops: Vec<&str> = if rest.is_empty() {
            vec![]
        } else {
            rest.split(',').map(str::trim).collect()
        };
        let mut parts = head.split('_');
        let base = parts.next().unwrap().to_ascii_lowercase();
        let suffixes: Vec<String> = parts.map(|s| s.to_ascii_lowercase()).collect();
        match base.as_str() {
            "def" => {
                let value = std::array::from_fn(|i| ops[1 + i].parse().expect("float"));
                p.float_defs.push(FloatDef {
                    index: reg(ops[0]).0.index,
                    value,
                    origin: Origin::default(),
                });
                continue;
            }
            "defi" => {
                let value = std::array::from_fn(|i| ops[1 + i].parse().expect("int"));
                p.int_defs.push(IntDef {
                    index: reg(ops[0]).0.index,
                    value,
                    origin: Origin::default(),
                });
                continue;
            }
            "defb" => {
                p.bool_defs.push(BoolDef {
                    index: reg(ops[0]).0.index,
                    value: ops[1] == "true",
                    origin: Origin::default(),
                });
                continue;
            }
            "dcl" => {
                let first = suffixes.first().map(String::as_str).unwrap_or("");
                let ty = match first {
                    "2d" => Some(SamplerType::Tex2d),
                    "cube" => Some(SamplerType::Cube),
                    "volume" => Some(SamplerType::Volume),
                    _ => None,
                };
                if let Some(ty) = ty {
                    p.samplers.push(SamplerDecl {
                        index: reg(ops[0]).0.index,
                        ty,
                        centroid: false,
                        pp: false,
                        origin: Origin::default(),
                    });
                } else {
                    let d = dst(ops[0]);
                    p.inputs.push(InputDecl {
                        reg: d.reg,
                        usage: first.trim_end_matches(|c: char| c.is_ascii_digit()).into(),
                        usage_index: 0,
                        mask: d.mask,
                        centroid: false,
                        pp: false,
                        origin: Origin::default(),
                    });
                }
                continue;
            }
            _ => {}
        }
        let mut compare = None;
        let mut sat = false;
        let mut pp = false;
        for s in &suffixes {
            match s.as_str() {
                "sat" => sat = true,
                "pp" => pp = true,
                other => compare = Some(Compare::from_suffix(other).expect("suffix")),
            }
        }
        let op = Opcode::from_mnemonic(&base, compare.is_some())
            .unwrap_or_else(|| panic!("unknown mnemonic {base}"));
        let mut ins = Instruction {
            op,
            sat,
            pp,
            centroid: false,
            compare,
            predicate,
            dst: None,
            src: vec![],
            origin: Origin::default(),
        };
        for (kind, text) in op.info().operands.iter().zip(&ops) {
            match kind {
                Operand::Dst | Operand::PredDst | Operand::KillSrc => ins.dst = Some(dst(text)),
                _ => ins.src.push(src(text)),
            }
        }
        assert_eq!(
            ops.len(),
            op.info().operands.len(),
            "operand count of {line}"
        );
        p.instructions.push(ins);
    }
    p
}

/// Assembles and wraps as a validated shader.
pub fn shader(text: &str) -> Shader {
    let p = program(text);
    let info = build_info(&p);
    Shader::new_validated(p, info)
}
