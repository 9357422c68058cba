//! ps_1_1–ps_1_4 as HLSL for ps_2_0 (or a larger ps_2_x/ps_3_0 target).
//!
//! Microsoft's compiler writes no ps_1_x from HLSL any more (X3539), so a
//! ps_1_x shader cannot come back as HLSL for its own profile. What can
//! come back is the program ps30 runs for it: the lowering of
//! `core::ps1::run`, IR of ps_2_0's kind in which every ps_1_x rule is
//! arithmetic (constants clamped to [−1, 1], each result to the register
//! range ±PixelShader1xMaxValue, modifiers, shifts, co-issue, `r0`
//! saturated). That IR is decompiled as any ps_2_0 shader is, with three
//! differences, all here:
//!
//! * the target is ps_2_0 where the lowered program fits its budgets
//!   ([`target`]), else the lowest of ps_2_a, ps_2_b and ps_3_0 that does;
//! * the colour inputs are saturated at the top of `main`: ps_1_x reads
//!   `v#` in [0, 1] where it enters, and the recompiled shader may receive
//!   raw values (ps_3_0's `COLOR` inputs are not clamped);
//! * the header says which rules the arithmetic spells and the register
//!   range used (`--ps1-max-value`).
//!
//! The range clamps, a `max` and a `min` in the lowering, are written
//! `clamp(x, lo, hi)` where the `max` folds into the `min`
//! ([`clamp_of`]); the compiler writes `clamp` back as that `max` and
//! `min`.

use super::{DecompileError, Target};
use crate::core::ir::Shader;
use crate::core::isa::{Class, Opcode, RegFile};

/// What differs in the HLSL of a ps_1_x shader.
pub(crate) struct Plan {
    /// The profile the HLSL is compiled for.
    pub target: Target,
    /// The comment lines that open the HLSL.
    pub header: String,
}

/// ps_2_0's budgets (Microsoft's ps_2_0 page: 64 arithmetic and 32 texture
/// instruction slots, texture reads at most four levels dependent).
const PS_2_0_ARITHMETIC: usize = 64;
const PS_2_0_TEXTURE: usize = 32;
const PS_2_0_DEPENDENT: usize = 4;

/// The lowering of `shader` (a ps_1_x shader) and how its HLSL differs.
pub(crate) fn plan(shader: &Shader) -> Result<(&Shader, Plan), DecompileError> {
    let p = shader.program().profile;
    let lowered = shader.runnable().map_err(|why| {
        DecompileError::Unsupported(format!(
            "a {p} shader that ps30 does not run: {why}, so no HLSL could be shown to compute it"
        ))
    })?;
    let target = target(lowered);
    // the register range is `c9.x` of the lowering (`core::ps1::run`)
    let max = lowered
        .program()
        .float_def(9)
        .map_or(crate::core::ps1::run::DEFAULT_MAX_VALUE, |v| v[0]);
    let header = format!(
        "// oracle: target={t}\n// {p} shader decompiled by ps30 (HLSL for {t})\n\
         // ps_1_x rules as arithmetic: constants clamped to [-1, 1] once, colour inputs to \
         [0, 1],\n// every result to [-{m}, {m}] (PixelShader1xMaxValue {m}), r0 saturated as \
         the pixel's colour\n",
        t = target.profile,
        m = super::names::literal(max),
    ) + &bump_note(lowered);
    Ok((lowered, Plan { target, header }))
}

/// A header line naming the bump-environment constants where the lowering
/// reads them (`texbem`, `texbeml`, `bem`: stage n's matrix in c(12 + n),
/// its luminance scale and offset in c(18 + n), `core::ps1::run`), so
/// that a reader knows which draw state feeds each `c#` the HLSL declares.
fn bump_note(lowered: &Shader) -> String {
    let reads = |from: u32| {
        lowered.instructions().iter().any(|x| {
            x.src
                .iter()
                .any(|s| s.reg.file == RegFile::Const && (from..from + 6).contains(&s.reg.index))
        })
    };
    let mut note = String::new();
    if reads(12) {
        note += "// c12 + n: stage n's bump-environment matrix (D3DTSS_BUMPENVMAT00, 01, 10, 11)\n";
    }
    if reads(18) {
        note += "// c18 + n: stage n's (D3DTSS_BUMPENVLSCALE, D3DTSS_BUMPENVLOFFSET, 0, 0)\n";
    }
    note
}

/// ps_2_0 where the lowered program's instructions fit ps_2_0's slots and
/// its texture reads its dependency levels; otherwise ps_2_a (512 slots,
/// no limit on dependent reads), which holds every ps_1_x program's
/// lowering.
fn target(lowered: &Shader) -> Target {
    let (mut arithmetic, mut texture) = (0, 0);
    for x in lowered.instructions() {
        match x.op {
            Opcode::Nop => {}
            Opcode::TexLd => texture += 1,
            op if op.class() == Class::Texture && op != Opcode::TexKill => texture += 1,
            _ => arithmetic += 1,
        }
    }
    let fits = arithmetic <= PS_2_0_ARITHMETIC
        && texture <= PS_2_0_TEXTURE
        && dependency(lowered) <= PS_2_0_DEPENDENT;
    Target {
        profile: if fits { "ps_2_0" } else { "ps_2_a" },
    }
}

/// The deepest chain of texture reads whose coordinate depends on an
/// earlier read (1: reads at interpolated coordinates only).
fn dependency(lowered: &Shader) -> usize {
    // level of the value each temporary holds: 0 computed from inputs
    // and constants only, n after a chain of n reads
    let mut level = std::collections::BTreeMap::<u32, usize>::new();
    let mut deepest = 0;
    for x in lowered.instructions() {
        let read = x
            .src
            .iter()
            .filter(|s| s.reg.file == RegFile::Temp)
            .map(|s| level.get(&s.reg.index).copied().unwrap_or(0))
            .max()
            .unwrap_or(0);
        let here = if x.op == Opcode::TexLd {
            read + 1
        } else {
            read
        };
        deepest = deepest.max(here);
        if let Some(d) = x.dst.filter(|d| d.reg.file == RegFile::Temp) {
            let kept = level.get(&d.reg.index).copied().unwrap_or(0);
            let full = d.mask.count() == 4;
            level.insert(d.reg.index, if full { here } else { here.max(kept) });
        }
    }
    deepest
}

/// The statements that saturate the colour inputs (`v#` → parameter name
/// in `inputs`; ps_1_x has no other `v#`) where `main` starts.
pub(crate) fn saturated_inputs(inputs: &std::collections::BTreeMap<u32, String>) -> Vec<String> {
    inputs
        .values()
        .map(|n| format!("{n} = saturate({n});"))
        .collect()
}

/// Drops from the temporaries' declaration (`float4 r0 = 0, r16 = 0, …;`
/// among `lines`) those no other line names: the lowering's scratch
/// registers whose every value was folded into its reader.
pub(crate) fn prune_temporaries(lines: &mut [String]) {
    let Some(k) = lines.iter().position(|l| {
        let t = l.trim_start().trim_start_matches("precise ");
        t.starts_with("float4 r") && t.ends_with(" = 0;")
    }) else {
        return;
    };
    let line = lines[k].clone();
    let (head, list) = match line.split_once("float4 ") {
        Some(x) => x,
        None => return,
    };
    let used: Vec<&str> = list
        .trim_end_matches(';')
        .split(", ")
        .filter(|d| {
            let name = d.trim_end_matches(" = 0");
            lines
                .iter()
                .enumerate()
                .any(|(i, l)| i != k && names_register(l, name))
        })
        .collect();
    if !used.is_empty() {
        lines[k] = format!("{head}float4 {};", used.join(", "));
    }
}

/// Whether `line` names register `name` (`r1`, not `r16`).
fn names_register(line: &str, name: &str) -> bool {
    let word = |c: char| c.is_ascii_alphanumeric() || c == '_';
    line.match_indices(name).any(|(i, _)| {
        let before = line[..i].chars().next_back();
        let after = line[i + name.len()..].chars().next();
        !before.is_some_and(word) && !after.is_some_and(word)
    })
}

/// `clamp(x, lo, hi)` for `min(max(x, lo), hi)` (`a` the `min`'s first
/// operand, `b` its second) where `lo` and `hi` are literals.
pub(crate) fn clamp_of(a: &str, b: &str) -> Option<String> {
    let inner = a.strip_prefix("max(")?.strip_suffix(')')?;
    // the `max(` must close at the end: its parentheses balance before it
    let mut depth = 0i32;
    let mut split = None;
    for (i, ch) in inner.char_indices() {
        match ch {
            '(' => depth += 1,
            ')' => depth -= 1,
            ',' if depth == 0 => split = Some(i),
            _ => {}
        }
        if depth < 0 {
            return None;
        }
    }
    let (x, lo) = inner.split_at(split?);
    let lo = lo.trim_start_matches(',').trim();
    let (lo, hi) = (lo.parse::<f32>().ok()?, b.parse::<f32>().ok()?);
    if depth != 0 {
        return None;
    }
    Some(clamped_literal(x, lo, hi).unwrap_or_else(|| {
        format!(
            "clamp({x}, {}, {})",
            super::names::literal(lo),
            super::names::literal(hi)
        )
    }))
}

/// A literal (`0.5`, `float4(1.0, 0.5, 0.25, 0.0)`: a `def`) clamped to
/// [`lo`, `hi`] when decompiling: the same bits the compiler's `max` and
/// `min` give it, written once.
fn clamped_literal(x: &str, lo: f32, hi: f32) -> Option<String> {
    let one = |t: &str| {
        let v = t.trim().parse::<f32>().ok()?;
        Some(super::names::literal(v.max(lo).min(hi)))
    };
    if let Some(v) = one(x) {
        return Some(v);
    }
    let (head, rest) = x.split_once('(')?;
    let inner = rest.strip_suffix(')')?;
    if !matches!(head, "float2" | "float3" | "float4") {
        return None;
    }
    let parts: Option<Vec<String>> = inner.split(',').map(one).collect();
    Some(format!("{head}({})", parts?.join(", ")))
}

#[cfg(test)]
mod tests {
    use super::{clamp_of, prune_temporaries};

    #[test]
    fn temporaries_no_statement_names_are_not_declared() {
        let mut lines: Vec<String> = [
            "    precise float4 r0 = 0, r1 = 0, r16 = 0, r24 = 0;",
            "    r16 = clamp(c0, -1.0, 1.0);",
            "    r0 = r16 * 2.0;",
        ]
        .map(String::from)
        .to_vec();
        prune_temporaries(&mut lines);
        assert_eq!(lines[0], "    precise float4 r0 = 0, r16 = 0;");
    }

    #[test]
    fn a_max_inside_a_min_is_a_clamp_only_when_it_is_whole() {
        assert_eq!(
            clamp_of("max(r0 * 2.0, -8.0)", "8.0").as_deref(),
            Some("clamp(r0 * 2.0, -8.0, 8.0)")
        );
        assert_eq!(
            clamp_of("max(min(a, 1.0), -1.0)", "1.0").as_deref(),
            Some("clamp(min(a, 1.0), -1.0, 1.0)")
        );
        // `max(a, b) + max(c, d)`: the first `max(` closes before the end
        assert_eq!(clamp_of("max(a, -1.0) + max(c, 1.0)", "1.0"), None);
        assert_eq!(clamp_of("max(a, b)", "1.0"), None);
        // a `def` is clamped when decompiling, to the bits max and min give
        assert_eq!(
            clamp_of("max(float4(1.5, -0.0, -3.0, 0.25), -1.0)", "1.0").as_deref(),
            Some("float4(1.0, -0.0, -1.0, 0.25)")
        );
        assert_eq!(clamp_of("max(-9.5, -8.0)", "8.0").as_deref(), Some("-8.0"));
        assert_eq!(clamp_of("max(a, -1.0)", "c0"), None);
    }
}
