//! What a vertex shader's HLSL has that a pixel shader's has not: the
//! output registers (`oPos`, `oD#`, `oT#`, `oFog`, `oPts` of vs_2_0 and
//! vs_2_x, vs_3_0's declared `o#`) as variables returned in one `struct`
//! with their semantics, the address register `a0` and `mova`, and the
//! instructions only vertex shaders have (`slt`, `sge`, `sgn`, `lit`,
//! `dst`, `expp`, `logp`).
//!
//! **`mova`** rounds to the nearest integer (vs_2_0 and later), halves by
//! the emulator's rule ([`HALVES`]). HLSL has no operation that the
//! compiler turns into a bare `mova`: an array indexed by a float is
//! indexed by its floor (`frc`, `add`, `mova`), an `int` conversion
//! truncates (measured with the compiler). So the rounding is written out
//! as a function of the HLSL, `mova_round(x)`, on the magnitude (both
//! rules are symmetric about 0): `a = |x|`, `f = frac(a)`, `r = a − f`,
//! and `r + 1` where `f > ½`, or `f = ½` and the tie goes up (always for
//! halves away from zero; where `r` is odd for halves to even), with the
//! sign of `x`. Every step is exact for `a ≥ 0` (`frac` of a negative
//! value is not: −0.49999997 + 1 rounds to ½), so the value is the
//! emulator's for every float, 0.49999997 included (`floor(x + 0.5)`
//! rounds that one up). `a0` is a `float4`
//! holding the rounded value and `c[a0.x + n]` is `array[a0.x + k]`: the
//! compiler floors an integer, exactly, and writes its own `mova`, whose
//! rule then never meets a half. At 2²³ and beyond every float is an
//! integer far outside the register file.
//!
//! **`expp` and `logp`** are written `exp2` and `log2`: the full-precision
//! instructions the compiler writes for those meet the partial-precision
//! ones' precision, and the emulator computes both alike.

use super::names;
use super::DecompileError;
use crate::core::ir::{Instruction, Reg, Shader};
use crate::core::isa::{Opcode, RegFile};
use std::collections::BTreeSet;

/// Which way `mova` rounds a value halfway between two integers.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Halves {
    /// 0.5 → 1, −0.5 → −1, 2.5 → 3 (Rust's `f32::round`).
    AwayFromZero,
    /// 0.5 → 0, −0.5 → 0, 1.5 → 2, 2.5 → 2 (native Direct3D 9's).
    ToEven,
}

/// The rule the decompiled HLSL spells: the emulator's `mova`'s
/// (`emu::vertex`), so that the original and the recompiled shader index
/// the same registers (`tests/decompile.rs` runs `mova` at ±0.5, 1.5 and
/// 2.5 in the emulator and fails when the two part).
pub const HALVES: Halves = Halves::ToEven;

/// The name of the HLSL rounding function.
pub(crate) const ROUND: &str = "mova_round";

/// The rounding function `mova_round`, one overload per width of `mova`
/// the shader writes (none without `mova`).
pub(crate) fn rounding(shader: &Shader) -> String {
    let widths: BTreeSet<usize> = shader
        .instructions()
        .iter()
        .filter(|x| x.op == Opcode::Mova)
        .filter_map(|x| x.dst.map(|d| (0..4).filter(|&c| d.mask.has(c)).count()))
        .collect();
    let up = match HALVES {
        Halves::AwayFromZero => "f >= 0.5",
        Halves::ToEven => "f > 0.5 || f == 0.5 && frac(r * 0.5) != 0",
    };
    let rule = match HALVES {
        Halves::AwayFromZero => "halves away from zero",
        Halves::ToEven => "halves to even",
    };
    let mut text = String::new();
    for n in widths {
        let ty = if n == 1 {
            "float".to_string()
        } else {
            format!("float{n}")
        };
        text.push_str(&format!(
            "\n// mova's rounding: to the nearest integer, {rule}\n\
             {ty} {ROUND}({ty} x)\n{{\n    {ty} a = abs(x);\n    {ty} f = frac(a);\n    \
             {ty} r = a - f;\n    return sign(x) * (r + ({up} ? 1 : 0));\n}}\n"
        ));
    }
    text
}

/// Whether `file` is an output register file of a vertex shader.
pub(crate) fn is_output(file: RegFile) -> bool {
    matches!(
        file,
        RegFile::PosOut
            | RegFile::AttrOut
            | RegFile::TexCoordOut
            | RegFile::FogOut
            | RegFile::PointSizeOut
            | RegFile::Output
    )
}

/// The variable that holds a vertex output or the address register.
pub(crate) fn variable(reg: Reg) -> Option<String> {
    Some(match reg.file {
        RegFile::PosOut => "oPos".into(),
        RegFile::AttrOut => format!("oD{}", reg.index),
        RegFile::TexCoordOut => format!("oT{}", reg.index),
        RegFile::FogOut => "oFog".into(),
        RegFile::PointSizeOut => "oPts".into(),
        RegFile::Output => format!("o{}", reg.index),
        RegFile::Address => "a0".into(),
        _ => return None,
    })
}

/// One field of the output struct.
pub(crate) struct Field {
    /// The register variable it is copied from.
    pub register: String,
    /// `float4 texcoord0 : TEXCOORD0`.
    pub decl: String,
    /// The field's name.
    pub name: String,
    /// Whether it is a scalar (fog, point size), read from `.x`.
    pub scalar: bool,
}

/// The outputs a vertex shader writes (and vs_3_0's declared ones), as the
/// fields of its output struct, in register order.
pub(crate) fn fields(shader: &Shader) -> Result<Vec<Field>, DecompileError> {
    let p = shader.program();
    // a vertex shader has 256 float constants: a read past them is
    // (0, 0, 0, 0) in the emulator, whose constants drop a `def` there too;
    // HLSL binds a uniform there (`register(c256)`, which reads the same
    // zeros) but writes a `def` as its literal
    if let Some(c) = p.instructions.iter().flat_map(|i| i.src.iter()).find(|s| {
        s.reg.file == RegFile::Const && s.reg.index >= 256 && p.float_def(s.reg.index).is_some()
    }) {
        return Err(DecompileError::Unsupported(format!(
            "def c{0} is read: past the 256 constants of a vertex shader the def is \
             dropped and the read is (0, 0, 0, 0), while HLSL would write the def as its \
             literal (Direct3D 9's runtime refuses a def past the device's constants)",
            c.reg.index
        )));
    }
    let mut regs: BTreeSet<(u8, u32, RegFile)> = BTreeSet::new();
    let order = |f: RegFile| match f {
        RegFile::PosOut => 0,
        RegFile::AttrOut => 1,
        RegFile::TexCoordOut => 2,
        RegFile::FogOut => 3,
        RegFile::PointSizeOut => 4,
        _ => 5,
    };
    for ins in &p.instructions {
        if let Some(d) = ins.dst.filter(|d| is_output(d.reg.file)) {
            if d.relative.is_some() {
                return Err(DecompileError::Unsupported(format!(
                    "o[{} + {}] is written: an output chosen at run time, which HLSL \
                     cannot write (an output array indexed at run time is X3500, \"array \
                     reference cannot be used as an l-value; not natively addressable\", \
                     and X3531 in a [loop]; measured)",
                    d.relative.map(|r| r.to_string()).unwrap_or_default(),
                    d.reg.index
                )));
            }
            regs.insert((order(d.reg.file), d.reg.index, d.reg.file));
        }
    }
    for d in p.inputs.iter().filter(|d| d.reg.file == RegFile::Output) {
        regs.insert((5, d.reg.index, RegFile::Output));
    }
    let mut taken = BTreeSet::new();
    let mut out = Vec::new();
    for (_, index, file) in regs {
        let reg = Reg { file, index };
        let (usage, usage_index) = match file {
            RegFile::PosOut => ("position".to_string(), 0),
            RegFile::AttrOut => ("color".into(), index),
            RegFile::TexCoordOut => ("texcoord".into(), index),
            RegFile::FogOut => ("fog".into(), 0),
            RegFile::PointSizeOut => ("psize".into(), 0),
            _ => {
                let mut decls = p
                    .inputs
                    .iter()
                    .filter(|d| d.reg.file == RegFile::Output && d.reg.index == index);
                let Some(d) = decls.next() else {
                    return Err(DecompileError::Unsupported(format!(
                        "o{index} is written without a declaration (no semantic)"
                    )));
                };
                if decls.next().is_some() {
                    return Err(DecompileError::Unsupported(format!(
                        "o{index} holds two declarations (packed outputs)"
                    )));
                }
                (d.usage.to_ascii_lowercase(), d.usage_index)
            }
        };
        let scalar = usage == "fog" || usage == "psize";
        let name = names::identifier(&format!("{usage}{usage_index}"), &mut taken);
        let ty = if scalar { "float" } else { "float4" };
        out.push(Field {
            register: variable(reg).unwrap_or_default(),
            decl: format!("{ty} {name} : {}{usage_index}", usage.to_ascii_uppercase()),
            name,
            scalar,
        });
    }
    if out.is_empty() {
        return Err(DecompileError::Unsupported(
            "a vertex shader that writes no output".into(),
        ));
    }
    Ok(out)
}

/// The name of the output struct.
pub(crate) const STRUCT: &str = "VS_OUTPUT";

/// The struct's declaration.
pub(crate) fn declaration(fields: &[Field]) -> String {
    let mut s = format!("\nstruct {STRUCT}\n{{\n");
    for f in fields {
        s.push_str(&format!("    {};\n", f.decl));
    }
    s.push_str("};\n");
    s
}

/// The end of `main`: the registers copied into the struct and returned.
pub(crate) fn epilogue(fields: &[Field]) -> Vec<String> {
    let mut lines = vec![format!("{STRUCT} result;")];
    for f in fields {
        let x = if f.scalar { ".x" } else { "" };
        lines.push(format!("result.{} = {}{x};", f.name, f.register));
    }
    lines.push("return result;".into());
    lines
}

/// The declarations of the output registers (`precise` as the pixel
/// side's are) and `a0`, each starting at 0.
pub(crate) fn locals(fields: &[Field], address: bool, precise: &str) -> Vec<String> {
    let mut out = Vec::new();
    if !fields.is_empty() {
        let list: Vec<String> = fields
            .iter()
            .map(|f| format!("{} = 0", f.register))
            .collect();
        out.push(format!("{precise}float4 {};", list.join(", ")));
    }
    if address {
        out.push("float4 a0 = 0;".into());
    }
    out
}

/// Whether [`value`] writes `op`.
pub(crate) fn handles(op: Opcode) -> bool {
    matches!(
        op,
        Opcode::Mova
            | Opcode::Slt
            | Opcode::Sge
            | Opcode::Sgn
            | Opcode::Lit
            | Opcode::Dst
            | Opcode::Expp
            | Opcode::Logp
    )
}

/// Spells source `k` of an instruction read at some swizzle positions.
pub(crate) type Operand<'a> = &'a dyn Fn(usize, &[usize]) -> Result<String, DecompileError>;

/// Whether an expression needs no parentheses to take a swizzle
/// (`expr::atomic`, passed in: this module is below `expr`).
pub(crate) type Atomic = fn(&str) -> bool;

/// `x` in parentheses unless it is a name, a call or parenthesised.
fn wrapped(x: String, atomic: Atomic) -> String {
    let bracketed = x.starts_with('(') && atomic(&format!("f{x}"));
    if atomic(&x) || bracketed {
        x
    } else {
        format!("({x})")
    }
}

/// The components of a value read at several components, one expression
/// each: `r0.x`, `r0.y` from `r0.xy`, or `(e).x`, `(e).y`.
fn components(x: String, atomic: Atomic) -> Vec<String> {
    if let Some((base, sw)) = x.rsplit_once('.').filter(|(b, sw)| {
        sw.chars().all(|c| "xyzw".contains(c))
            && b.chars()
                .all(|c| c.is_ascii_alphanumeric() || "_[]".contains(c))
    }) {
        return sw.chars().map(|c| format!("{base}.{c}")).collect();
    }
    let x = wrapped(x, atomic);
    ["x", "y", "z"].iter().map(|c| format!("{x}.{c}")).collect()
}

/// `loop aL, i#` over an `int4` uniform in a vertex shader: `for (int i =
/// 0; i < n.x; i++)` (the head and the counter's name `counter`), which
/// the compiler writes back as `loop aL, i#` itself (aL then starts at
/// `i#.y` and steps by `i#.z`, which the runtime sets to 0 and 1 for an
/// `int` loop count). `None` for anything else.
pub(crate) fn uniform_loop(
    shader: &Shader,
    x: &Instruction,
    ints: &std::collections::BTreeMap<u32, String>,
    counter: Option<&str>,
) -> Result<Option<(String, String)>, DecompileError> {
    if shader.program().profile.stage() != crate::core::profile::Stage::Vertex {
        return Ok(None);
    }
    let Some(s) = x.src.iter().find(|s| s.reg.file == RegFile::ConstInt) else {
        return Ok(None);
    };
    let Some(n) = ints.get(&s.reg.index).filter(|n| !n.starts_with("int4(")) else {
        return Ok(None);
    };
    let name =
        counter.ok_or_else(|| DecompileError::Unsupported("loops nested too deep".into()))?;
    let head = format!("for (int {name} = 0; {name} < {n}.x; {name}++)");
    Ok(Some((head, name.to_string())))
}

/// The value of a vertex-only instruction, as wide as its write mask.
/// `operand(k, positions)` spells source `k` read at those swizzle
/// positions (`expr::Ctx::operand`).
pub(crate) fn value(
    ins: &Instruction,
    mask: &[usize],
    operand: Operand,
    atomic: Atomic,
) -> Result<String, DecompileError> {
    let src = |k: usize, positions: &[usize]| operand(k, positions);
    let swizzle: String = mask.iter().map(|&m| ['x', 'y', 'z', 'w'][m]).collect();
    Ok(match ins.op {
        Opcode::Mova => {
            format!("{ROUND}({})", src(0, mask)?)
        }
        Opcode::Slt => format!("{} < {} ? 1.0 : 0.0", src(0, mask)?, src(1, mask)?),
        Opcode::Sge => format!("{} >= {} ? 1.0 : 0.0", src(0, mask)?, src(1, mask)?),
        Opcode::Sgn => format!("sign({})", src(0, mask)?),
        Opcode::Expp => format!("exp2({})", src(0, &[0])?),
        Opcode::Logp => format!("log2(abs({}))", src(0, &[0])?),
        Opcode::Lit => {
            // lit reads x (n·l), y (n·h) and w (the power)
            let v = components(src(0, &[0, 1, 3])?, atomic);
            let call = format!("lit({})", v.join(", "));
            if mask.len() == 4 {
                call
            } else {
                format!("{call}.{swizzle}")
            }
        }
        Opcode::Dst => {
            let call = format!(
                "dst({}, {})",
                src(0, &[0, 1, 2, 3])?,
                src(1, &[0, 1, 2, 3])?
            );
            if mask.len() == 4 {
                call
            } else {
                format!("{call}.{swizzle}")
            }
        }
        op => {
            return Err(DecompileError::Unsupported(format!(
                "{} as a value",
                op.info().mnemonic
            )))
        }
    })
}
