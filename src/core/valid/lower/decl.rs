//! Lowering the declarations: `dcl` (inputs, outputs and samplers, by
//! profile) and `def`/`defi`/`defb`, with what each profile allows of them.

use super::*;

/// The modifiers written after `dcl`: `_centroid`, `_pp` and one usage or
/// sampler type (with its span).
struct DclSuffixes<'a> {
    centroid: bool,
    pp: bool,
    kind: Option<(&'a str, Span)>,
}

pub(super) fn lower_dcl(ast: &InstrAst, p: Profile) -> R<Lowered> {
    let sampler_kind = ast
        .suffixes
        .iter()
        .find(|(k, _)| matches!(k.as_str(), "2d" | "cube" | "volume"));
    if let (Some((k, span)), 0) = (sampler_kind, p.count(RegFile::Sampler)) {
        // Microsoft's grammar has no sampler declarations there (X2000).
        return Err(
            Diagnostic::error(*span, format!("`dcl_{k}`: {p} has no samplers"))
                .with_label("no sampler declaration in this profile"),
        );
    }
    let r = declared_operand(ast)?;
    let reg = resolve_reg(r, p)?;
    no_modifiers(r, "a declared register")?;
    let m = dcl_suffixes(ast)?;
    if p != Profile::Ps3_0 {
        if let Some(lowered) = profile_decl(r, reg, &m, p) {
            return lowered;
        }
    }
    match (reg.file, m.kind) {
        (RegFile::Sampler, Some((k, span))) => sampler_decl(r, reg, (k, span), &m),
        (RegFile::Sampler, None) => Err(Diagnostic::coded(
            codes::SAMPLER_TYPE,
            ast.base_span,
            "a sampler declaration needs a type",
        )
        .with_label("e.g. dcl_2d s0")
        .with_help("write dcl_2d, dcl_cube or dcl_volume")),
        (RegFile::Input, Some((k, span))) => input_decl(r, reg, (k, span), &m),
        (RegFile::Input, None) => Err(Diagnostic::coded(
            codes::DCL_USAGE,
            ast.base_span,
            "ps_3_0 input declarations need a usage",
        )
        .with_label("e.g. dcl_texcoord0 v0.xy")
        .with_help("write dcl_<usage><index> v#, such as dcl_texcoord0 v0 or dcl_color0 v1")),
        (RegFile::Position | RegFile::Face, None) => pos_face_decl(r, reg, &m),
        // Microsoft's assembler takes a usage on vPos (`dcl_texcoord0
        // vPos.xy`) and declares vPos; `dcl_position0 vPos` it refuses.
        (RegFile::Position, Some((k, _))) if !k.starts_with("position") => {
            pos_face_decl(r, reg, &m)
        }
        (RegFile::Position | RegFile::Face, Some((_, span))) => Err(Diagnostic::error(
            span,
            "vPos and vFace are declared with plain `dcl`",
        )
        .with_label("remove the usage")),
        (RegFile::ColorOut | RegFile::DepthOut, _) => Err(Diagnostic::coded(
            codes::DCL_REGISTER,
            r.span,
            "ps_3_0 cannot declare output registers",
        )
        .with_label("outputs need no declaration")),
        _ => Err(Diagnostic::coded(
            codes::DCL_REGISTER,
            r.span,
            format!("`{reg}` cannot be declared"),
        )
        .with_label("declare v#, s#, vPos or vFace")),
    }
}

/// A declaration's one operand: a register, with no predicate on the line.
fn declared_operand(ast: &InstrAst) -> R<&RegAst> {
    if ast.operands.len() != 1 {
        return Err(Diagnostic::error(
            ast.span,
            format!(
                "a declaration takes one register, found {}",
                ast.operands.len()
            ),
        )
        .with_label("one register"));
    }
    let OperandAst::Reg(r) = &ast.operands[0] else {
        return Err(Diagnostic::error(
            ast.operands[0].span(),
            "expected a register to declare",
        ));
    };
    if let Some(p) = &ast.predicate {
        return Err(Diagnostic::coded(
            codes::DCL_TOKENS,
            p.span,
            "declarations cannot be predicated",
        ));
    }
    Ok(r)
}

fn dcl_suffixes(ast: &InstrAst) -> R<DclSuffixes<'_>> {
    let mut m = DclSuffixes {
        centroid: false,
        pp: false,
        kind: None,
    };
    for (s, span) in &ast.suffixes {
        match s.as_str() {
            "centroid" => m.centroid = true,
            "pp" => m.pp = true,
            "sat" => {
                return Err(Diagnostic::error(
                    *span,
                    "`_sat` is not allowed on a declaration",
                ))
            }
            other if m.kind.is_none() => m.kind = Some((other, *span)),
            other => {
                return Err(Diagnostic::error(
                    *span,
                    format!("unexpected `_{other}` in declaration"),
                ))
            }
        }
    }
    Ok(m)
}

/// `dcl_2d` / `dcl_cube` / `dcl_volume s#` (type `k` at `span`), with its
/// `_centroid` / `_pp`.
fn sampler_decl(r: &RegAst, reg: Reg, (k, span): (&str, Span), m: &DclSuffixes) -> R<Lowered> {
    if m.centroid || m.pp {
        return Err(Diagnostic::coded(
            codes::SAMPLER_MODIFIER,
            span,
            "a sampler declaration takes no modifier",
        )
        .with_label("remove _centroid / _pp")
        .with_help("Microsoft's assembler refuses dcl_2d_centroid and dcl_2d_pp"));
    }
    let ty = match k {
        "2d" => SamplerType::Tex2d,
        "cube" => SamplerType::Cube,
        "volume" => SamplerType::Volume,
        "1d" => {
            return Err(
                Diagnostic::error(span, "1D samplers are not ps_3_0 sampler types")
                    .with_label("declare 2d, cube or volume")
                    .with_help("Microsoft lists dcl_2d, dcl_cube and dcl_volume only"),
            )
        }
        _ => {
            return Err(
                Diagnostic::error(span, format!("unknown sampler type `{k}`"))
                    .with_label("expected 2d, cube or volume"),
            )
        }
    };
    if r.components.is_some() {
        return Err(Diagnostic::coded(
            codes::SAMPLER_MASK,
            r.span,
            "sampler declarations take no write mask",
        ));
    }
    Ok(Lowered::Sampler(SamplerDecl {
        index: reg.index,
        ty,
        centroid: m.centroid,
        pp: m.pp,
        origin: Origin::default(),
    }))
}

/// `dcl_<usage><index> v#` (usage `k` at `span`).
fn input_decl(r: &RegAst, reg: Reg, (k, span): (&str, Span), m: &DclSuffixes) -> R<Lowered> {
    let name = k.trim_end_matches(|c: char| c.is_ascii_digit());
    let digits = &k[name.len()..];
    if !USAGES.contains(&name) {
        return Err(
            Diagnostic::error(span, format!("unknown input usage `{name}`"))
                .with_label("not a declaration usage")
                .with_help(
                    "usages: texcoord, color, normal, tangent, binormal, position, fog, depth, ...",
                ),
        );
    }
    let usage_index: u32 = if digits.is_empty() {
        0
    } else {
        digits.parse().unwrap_or(99)
    };
    if usage_index > 15 {
        return Err(
            Diagnostic::error(span, format!("usage index {usage_index} is out of range"))
                .with_label("0 … 15"),
        );
    }
    // Microsoft refuses these usages in a pixel shader: positiont and psize
    // at index 0 only (positiont15 and psize15 it takes), sample and
    // tessfactor at every index.
    let first = usage_index == 0;
    let refused = match name {
        "positiont" if first => Some(codes::DCL_POSITIONT),
        "psize" if first => Some(codes::DCL_PSIZE),
        "tessfactor" => Some(codes::DCL_TESSFACTOR),
        "sample" => Some(codes::DCL_SAMPLE),
        _ => None,
    };
    if let Some(code) = refused {
        return Err(Diagnostic::coded(
            code,
            span,
            format!("`{k}` is a vertex-pipeline usage: a pixel shader cannot declare it"),
        )
        .with_label("not a pixel shader input")
        .with_help("declare the value as a texcoord# input instead"));
    }
    // Not in Microsoft's dcl_usage page, but Windows' runtime
    // refuses it: Wine's dlls/d3d9/tests/visual.c,
    // test_position_index, expects D3DERR_INVALIDCALL from
    // CreatePixelShader for `dcl_position0 v0` and accepts
    // `dcl_position1 v0`.
    if name == "position" && usage_index == 0 {
        return Err(Diagnostic::error(
            span,
            "position0 cannot be a pixel shader input",
        )
        .with_label("Windows' runtime refuses this declaration")
        .with_help("the pixel's position is vPos; a copy of the vertex position needs another usage, such as position1 or texcoord"));
    }
    Ok(Lowered::Input(InputDecl {
        reg,
        usage: name.to_string(),
        usage_index,
        mask: write_mask(r)?,
        centroid: m.centroid,
        pp: m.pp,
        origin: Origin::default(),
    }))
}

/// The declarations the other profiles have and ps_3_0 has not, or `None`
/// where ps_3_0's rules apply: `dcl t#` / `dcl v#` without a usage in
/// ps_2_0 and ps_2_x; `dcl_<usage> v#` (and `o#` in vs_3_0) in vertex
/// shaders, with every usage.
fn profile_decl(r: &RegAst, reg: Reg, m: &DclSuffixes, p: Profile) -> Option<R<Lowered>> {
    let decl = |usage: &str, usage_index: u32| -> R<Lowered> {
        Ok(Lowered::Input(InputDecl {
            reg,
            usage: usage.to_string(),
            usage_index,
            mask: write_mask(r)?,
            centroid: m.centroid,
            pp: m.pp,
            origin: Origin::default(),
        }))
    };
    let vertex = p.stage() == crate::core::profile::Stage::Vertex;
    match (reg.file, m.kind) {
        (RegFile::Texture | RegFile::Input, None) if !vertex => Some(decl("", 0)),
        (RegFile::Input | RegFile::Output, Some((k, span))) if vertex => {
            let name = k.trim_end_matches(|c: char| c.is_ascii_digit());
            let index: u32 = k[name.len()..].parse().unwrap_or(0);
            Some(if !USAGES.contains(&name) {
                Err(Diagnostic::error(span, format!("unknown usage `{name}`"))
                    .with_label("not a declaration usage"))
            } else if index > 15 {
                Err(
                    Diagnostic::error(span, format!("usage index {index} is out of range"))
                        .with_label("0 … 15"),
                )
            } else {
                decl(name, index)
            })
        }
        (RegFile::Input | RegFile::Output, None) if vertex => Some(Err(Diagnostic::coded(
            codes::DCL_USAGE,
            r.span,
            format!("{p} declarations of `{reg}` need a usage"),
        )
        .with_label("e.g. dcl_position v0"))),
        _ => None,
    }
}

/// `dcl vPos.xy` / `dcl vFace`.
fn pos_face_decl(r: &RegAst, reg: Reg, m: &DclSuffixes) -> R<Lowered> {
    let mask = write_mask(r)?;
    if reg.file == RegFile::Position && (m.centroid || m.pp) {
        return Err(Diagnostic::coded(
            codes::VPOS_MODIFIER,
            r.span,
            "vPos is declared without `_centroid` or `_pp`",
        )
        .with_label("the pixel position takes no modifier"));
    }
    if reg.file == RegFile::Position && !matches!(mask.0, 1..=3) {
        return Err(Diagnostic::coded(
            codes::VPOS_MASK,
            r.span,
            "vPos is declared with .x, .y or .xy",
        )
        .with_label("z and w are undefined"));
    }
    if reg.file == RegFile::Face && mask != WriteMask::ALL {
        return Err(Diagnostic::coded(
            codes::SCALAR,
            r.span,
            "vFace is declared without a mask",
        ));
    }
    Ok(Lowered::Input(InputDecl {
        reg,
        usage: String::new(),
        usage_index: 0,
        mask,
        centroid: m.centroid,
        pp: m.pp,
        origin: Origin::default(),
    }))
}

pub(super) fn lower_def(ast: &InstrAst, p: Profile) -> R<Lowered> {
    let op = match ast.base.as_str() {
        "defi" => Opcode::DefI,
        "defb" => Opcode::DefB,
        _ => Opcode::Def,
    };
    if !op.profiles().has(p) && p != Profile::Ps3_0 {
        return Err(not_in_profile(ast, op, p));
    }
    if let Some((_, span)) = ast.suffixes.first() {
        return Err(Diagnostic::error(
            *span,
            format!("`{}` takes no modifier", ast.base),
        ));
    }
    if let Some(p) = &ast.predicate {
        return Err(Diagnostic::coded(
            codes::DWORD_COUNT,
            p.span,
            "definitions cannot be predicated",
        ));
    }
    let (file, nvalues, form) = match ast.base.as_str() {
        "def" => (RegFile::Const, 4, "def c#, x, y, z, w"),
        "defi" => (RegFile::ConstInt, 4, "defi i#, x, y, z, w"),
        _ => (RegFile::ConstBool, 1, "defb b#, true|false"),
    };
    if ast.operands.len() != nvalues + 1 {
        return Err(Diagnostic::error(
            ast.span,
            format!(
                "`{}` takes {} operands, found {}",
                ast.base,
                nvalues + 1,
                ast.operands.len()
            ),
        )
        .with_label("wrong number of operands")
        .with_help(format!("form: {form}")));
    }
    let OperandAst::Reg(r) = &ast.operands[0] else {
        return Err(Diagnostic::error(
            ast.operands[0].span(),
            format!("expected the register to define, form: {form}"),
        ));
    };
    let reg = resolve_reg(r, p)?;
    let code = match file {
        RegFile::Const => codes::DEF_DESTINATION,
        RegFile::ConstInt => codes::DEFI_DESTINATION,
        _ => codes::DEFB_DESTINATION,
    };
    if reg.file != file {
        return Err(Diagnostic::coded(
            code,
            r.span,
            format!("`{}` defines {} registers", ast.base, file.info().name),
        )
        .with_label(format!("`{reg}` is the wrong kind"))
        .with_help(format!("form: {form}")));
    }
    no_modifiers(r, "a defined register")?;
    if r.components.is_some() {
        return Err(Diagnostic::coded(
            code,
            r.span,
            "definitions write the whole register: no mask",
        )
        .with_label("remove the mask"));
    }
    let values = &ast.operands[1..];
    match file {
        RegFile::ConstBool => match &values[0] {
            OperandAst::Bool { value, .. } => Ok(Lowered::Bool(BoolDef {
                index: reg.index,
                value: *value,
                origin: Origin::default(),
            })),
            other => Err(Diagnostic::error(other.span(), "expected true or false")
                .with_label("not a boolean")),
        },
        _ => {
            let mut nums = [0f64; 4];
            for (slot, v) in nums.iter_mut().zip(values) {
                match v {
                    OperandAst::Number {
                        value,
                        integer,
                        special: _,
                        span,
                    } => {
                        if file == RegFile::ConstInt && !integer {
                            return Err(Diagnostic::error(*span, "defi takes integers")
                                .with_label("not an integer"));
                        }
                        // Microsoft's assembler keeps the low 32 bits of a
                        // number up to 2^32 - 1: 4294967295 is -1.
                        if file == RegFile::ConstInt
                            && (*value < i32::MIN as f64 || *value > u32::MAX as f64)
                        {
                            return Err(Diagnostic::error(
                                *span,
                                "integer does not fit in 32 bits",
                            )
                            .with_label("out of range"));
                        }
                        *slot = *value;
                    }
                    other => {
                        return Err(Diagnostic::error(other.span(), "expected a number")
                            .with_label("not a number"))
                    }
                }
            }
            Ok(if file == RegFile::Const {
                Lowered::Float(FloatDef {
                    index: reg.index,
                    value: nums.map(crate::core::front::ast::single),
                    origin: Origin::default(),
                })
            } else {
                Lowered::Int(IntDef {
                    index: reg.index,
                    value: nums.map(|v| v as i64 as i32),
                    origin: Origin::default(),
                })
            })
        }
    }
}
