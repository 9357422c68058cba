//! Naming a register in assembly: which register an operand names
//! (file and number, with what other shader models call it when ps_3_0 has
//! no such register), its swizzle and its write mask. Lowering and the
//! bytecode writer both read operands through these.

use crate::core::diag::{codes, Diagnostic};
use crate::core::front::ast::RegAst;
use crate::core::ir::Span;
use crate::core::ir::{Reg, Swizzle, WriteMask};
use crate::core::isa::{RegFile, REG_FILES};
use crate::core::profile::Profile;

type R<T> = Result<T, Diagnostic>;

/// Registers that other shader models have and ps_3_0 does not.
pub(super) fn foreign_register(name: &str) -> Option<&'static str> {
    match name.to_ascii_lowercase().as_str() {
        "t" => Some("t# registers are ps_2_x; in ps_3_0 texture coordinates arrive in v# (dcl_texcoord0 v0)"),
        "a" => Some("the address register a0 exists only in vertex shaders; ps_3_0 indexes with aL"),
        "o" | "ot" | "od" | "opos" | "ofog" | "opts" => Some("vertex-shader outputs do not exist in pixel shaders; write oC0…oC3 or oDepth"),
        _ => None,
    }
}

/// The register an operand names (file and number) in `profile`, or a
/// diagnostic: the file must be one the profile has, and the number below
/// the profile's count ([`Profile::count`]).
pub fn resolve_reg(r: &RegAst, profile: Profile) -> R<Reg> {
    let file = match RegFile::lookup_any(&r.name) {
        Some(f) if profile.count(f) > 0 => f,
        _ if profile == Profile::Ps3_0 => return Err(unknown_ps_3_0(r)),
        _ => {
            return Err(unknown_register(r)
                .with_label(format!("not a {profile} register"))
                .with_help(format!("{profile} registers: {}", register_list(profile))))
        }
    };
    let info = file.info();
    let index = match (info.numbered, r.index, &r.relative) {
        (true, Some(i), _) => i,
        (true, None, Some(_)) => 0,
        (true, None, None) => {
            return Err(Diagnostic::coded(
                codes::REGISTER,
                r.name_span,
                format!("register `{}` needs a number", r.name),
            )
            .with_label(format!("e.g. {}0", info.name)))
        }
        (false, Some(_), _) => {
            return Err(Diagnostic::coded(
                codes::REGISTER,
                r.name_span,
                format!("`{}` takes no number", info.name),
            )
            .with_label("remove the number"))
        }
        (false, None, _) => 0,
    };
    // A relative input's number is a base (`v10[aL]`, as Microsoft's
    // listing writes `v[aL + 10]`), checked where the offset is added.
    let relative_base = r.relative.is_some() && file == RegFile::Input;
    let count = profile.count(file);
    if index >= count as u64 && !relative_base {
        return Err(Diagnostic::coded(
            codes::REGISTER,
            r.name_span,
            format!("register `{}{}` is out of range", info.name, index),
        )
        .with_label(format!(
            "{profile} has {}{} to {}{}",
            info.name,
            0,
            info.name,
            count - 1
        )));
    }
    Ok(Reg {
        file,
        index: index as u32,
    })
}

/// The refusal of a name a profile has no register file for, to be labelled.
fn unknown_register(r: &RegAst) -> Diagnostic {
    Diagnostic::coded(
        codes::REGISTER,
        r.name_span,
        format!(
            "unknown register `{}{}`",
            r.name,
            r.index.map(|i| i.to_string()).unwrap_or_default()
        ),
    )
}

/// The refusal of a name ps_3_0 has no register file for.
fn unknown_ps_3_0(r: &RegAst) -> Diagnostic {
    let d = unknown_register(r).with_label("not a ps_3_0 register");
    match foreign_register(&r.name) {
        Some(why) => d.with_help(why),
        None => d.with_help("ps_3_0 registers: r0-r31, v0-v9, c0-c223, i0-i15, b0-b15, s0-s15, p0, oC0-oC3, oDepth, aL, vPos, vFace, l#"),
    }
}

/// The register files of a profile as a list (`r0-r11, v0-v1, …`).
pub fn register_list(profile: Profile) -> String {
    REG_FILES
        .iter()
        .filter_map(|f| {
            let n = profile.count(f.file);
            match (n, f.numbered) {
                (0, _) => None,
                (_, false) => Some(f.name.to_string()),
                (1, true) => Some(format!("{}0", f.name)),
                (n, true) => Some(format!("{}0-{}{}", f.name, f.name, n - 1)),
            }
        })
        .collect::<Vec<_>>()
        .join(", ")
}

fn component_index(c: char) -> Option<u8> {
    match c {
        'x' | 'r' => Some(0),
        'y' | 'g' => Some(1),
        'z' | 'b' => Some(2),
        'w' | 'a' => Some(3),
        _ => None,
    }
}

/// Checks letters are all from one set (xyzw or rgba) and returns indices.
/// `code`: Microsoft's code for a bad swizzle or a bad mask.
fn components(letters: &str, span: Span, code: codes::Code) -> R<Vec<u8>> {
    let mut out = Vec::new();
    for (i, c) in letters.chars().enumerate() {
        let Some(idx) = component_index(c) else {
            let at = Span::new(
                span.start as usize + i,
                span.start as usize + i + c.len_utf8(),
            );
            return Err(
                Diagnostic::coded(code, at, format!("`{c}` is not a component"))
                    .with_label("expected x, y, z, w (or r, g, b, a)"),
            );
        };
        out.push(idx);
    }
    // Microsoft's assembler reads each letter alone: `.xgba` is `.xyzw`.
    if out.len() > 4 {
        return Err(
            Diagnostic::coded(code, span, "more than four components").with_label("at most four")
        );
    }
    Ok(out)
}

/// The swizzle of a source operand (`.xyzw` when none is written).
pub fn swizzle(r: &RegAst) -> R<Swizzle> {
    let Some((letters, span)) = &r.components else {
        return Ok(Swizzle::IDENTITY);
    };
    let c = components(letters, *span, codes::SWIZZLE)?;
    let last = *c.last().unwrap_or(&3);
    let mut s = [last; 4];
    s[..c.len()].copy_from_slice(&c);
    Ok(Swizzle(s))
}

/// The write mask of a destination (`.xyzw` when none is written).
pub fn write_mask(r: &RegAst) -> R<WriteMask> {
    let Some((letters, span)) = &r.components else {
        return Ok(WriteMask::ALL);
    };
    let c = components(letters, *span, codes::MASK)?;
    let mut mask = 0u8;
    let mut last: i16 = -1;
    for &i in &c {
        if i as i16 <= last {
            return Err(Diagnostic::coded(codes::MASK, *span, format!("write mask `.{letters}` is not in x, y, z, w order"))
                .with_label("components must appear in order, each once")
                .with_help("a write mask lists components in xyzw order without repeats; to reorder, swizzle the source"));
        }
        last = i as i16;
        mask |= 1 << i;
    }
    Ok(WriteMask(mask))
}

pub(super) fn no_modifiers(r: &RegAst, what: &str) -> R<()> {
    if r.negate || r.abs || r.not {
        return Err(
            Diagnostic::error(r.span, format!("{what} takes no modifier"))
                .with_label("remove `-`, `!` or `_abs`"),
        );
    }
    if let Some(rel) = &r.relative {
        return Err(Diagnostic::coded(
            codes::REGISTER,
            rel.span,
            format!("{what} cannot be relatively addressed"),
        )
        .with_label("only sources v[aL + n] may be indexed"));
    }
    Ok(())
}
