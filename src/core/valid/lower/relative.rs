//! Relative addressing as each profile allows it, measured with Microsoft's
//! assembler: ps_3_0 indexes inputs with `aL` (`v[aL + n]`); vs_2_0 and
//! vs_2_x index float constants with `aL` or one component of `a0`
//! (`c[aL + n]`, `c[a0.x + n]`); vs_3_0 adds `v[aL + n]` and the
//! destination `o[aL + n]`. Any other register written with `[…]` is the
//! assembler's "invalid register `r[...]`" (X2005).

use super::{foreign_register, R};
use crate::core::diag::{codes, Diagnostic};
use crate::core::front::ast::{RegAst, RelAst};
use crate::core::ir::{Reg, RelIndex};
use crate::core::isa::RegFile;
use crate::core::profile::{Profile, Stage};

/// Whether `file` may be indexed in `profile` (as a source, or as the
/// destination `o[aL + n]`).
fn indexable(file: RegFile, profile: Profile) -> bool {
    match profile {
        Profile::Ps3_0 => file == RegFile::Input,
        Profile::Vs3_0 => matches!(file, RegFile::Const | RegFile::Input | RegFile::Output),
        p if p.stage() == Stage::Vertex => file == RegFile::Const,
        _ => false,
    }
}

/// The assembler's grammar: an index on a register the profile cannot
/// index, or a swizzle on `aL`, is refused before any rule of the
/// validator.
pub(super) fn grammar(r: &RegAst, reg: Reg, profile: Profile) -> R<()> {
    let Some(rel) = &r.relative else {
        return Ok(());
    };
    if rel.index_reg == "aL" {
        if let Some(span) = rel.index_swizzle {
            return Err(Diagnostic::coded(
                codes::SCALAR,
                span,
                "aL is a scalar register: no swizzle",
            )
            .with_label("remove the swizzle"));
        }
    }
    if indexable(reg.file, profile) {
        return Ok(());
    }
    let allowed = match profile {
        Profile::Ps3_0 => "only v[aL + n] is indexable",
        Profile::Vs3_0 => "only c[a0.x + n], c[aL + n], v[aL + n] and o[aL + n] are indexable",
        p if p.stage() == Stage::Vertex => "only c[a0.x + n] and c[aL + n] are indexable",
        _ => "this profile indexes no register",
    };
    Err(Diagnostic::coded(
        codes::REGISTER,
        rel.span,
        format!(
            "`{}` registers cannot be relatively addressed in {profile}",
            reg.file.info().name
        ),
    )
    .with_label(allowed))
}

/// The index register of `rel`: `aL`, or `a0` with one component in a
/// vertex profile.
fn index_register(rel: &RelAst, profile: Profile) -> R<RelIndex> {
    if rel.index_reg == "aL" {
        return Ok(RelIndex::Loop);
    }
    if rel.index_reg == "a0" && profile.stage() == Stage::Vertex {
        return rel.index_component.map(RelIndex::Addr).ok_or_else(|| {
            Diagnostic::coded(
                codes::RELATIVE_COMPONENT,
                rel.span,
                "the address register indexes with one component",
            )
            .with_label("write a0.x, a0.y, a0.z or a0.w")
        });
    }
    let d = Diagnostic::coded(
        codes::REGISTER,
        rel.span,
        format!("`{}` cannot index registers in {profile}", rel.index_reg),
    );
    let d = match profile.stage() {
        Stage::Vertex => d.with_label("expected aL or a0.x … a0.w"),
        _ => d.with_label("expected aL"),
    };
    Err(
        match foreign_register(rel.index_reg.trim_end_matches(char::is_numeric)) {
            Some(why) if profile == Profile::Ps3_0 => d.with_help(why),
            _ => d,
        },
    )
}

/// The index of a relatively addressed operand and the register number its
/// token carries (the base plus the offsets), or `None` for a plain one.
pub(super) fn index(r: &RegAst, reg: Reg, profile: Profile) -> R<Option<(RelIndex, u32)>> {
    let Some(rel) = &r.relative else {
        return Ok(None);
    };
    let index = index_register(rel, profile)?;
    if index != RelIndex::Loop {
        let refused = match reg.file {
            RegFile::Input => Some((codes::INPUT_RELATIVE_AL, "inputs are indexed by aL only")),
            RegFile::Output => Some((codes::OUTPUT_RELATIVE_AL, "outputs are indexed by aL only")),
            _ => None,
        };
        if let Some((code, text)) = refused {
            return Err(Diagnostic::coded(code, rel.span, text)
                .with_label("expected aL")
                .with_help(format!(
                    "index {} inside `loop aL, i#` … `endloop`",
                    reg.file.info().name
                )));
        }
    }
    // Microsoft's assembler takes a base past the file's end (`v[aL + 10]`
    // is `v10[aL]`: what the index adds may bring it back; a read that lands
    // outside the file is undefined) and keeps what the token can number:
    // the 11-bit register number, and for float constants the register
    // types CONST…CONST4 above it (c0–c8191). A larger base wraps
    // (measured: `c[a0.x + 8195]` is `c3[a0.x]`, `v[aL + 2048]` is
    // `v0[aL]`).
    let total = i64::from(reg.index)
        .saturating_add(rel.offset)
        .rem_euclid(i64::from(reg.file.token_registers()));
    Ok(Some((index, total as u32)))
}
