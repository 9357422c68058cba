//! A pixel shader's inputs as a draw supplies them: one numbering for every
//! profile ps30 runs.
//!
//! A draw gives each input as `(slot, value)`. In ps_3_0 the slot is the
//! input register's number (`v0`–`v9`). ps_2_0 and ps_2_x have two input
//! files — the colours `v0`, `v1` and the texture coordinates `t0`–`t7` —
//! ten registers in all, so they take the same ten slots: `v0` and `v1` are
//! slots 0 and 1, `t#` is slot 2 + #. The emulator's input rows, the
//! translation's input array and the GPU backend's input layers are
//! numbered by slot, so neither needs a second input file.
//!
//! Colours in ps_2_0 and ps_2_x are no ordinary floats: Microsoft's page on
//! the input colour register says they "have lower precision than most
//! registers, guaranteed to have 8 bits of unsigned data in the range
//! (0, +1)". ps30 keeps their full precision and clamps them to [0, 1] where
//! they enter the shader (NaN reads 0, as `_sat` gives), in both backends;
//! [`clamped`] names those slots. ps_3_0's `v#` are general interpolators
//! and are not clamped.
//!
//! An input component nothing upstream writes — the vertex shader writes
//! no such output, or not that component of it — reads what Direct3D 9
//! gives it ([`unwritten`]): (1, 1, 1, 1) in ps_2_0/ps_2_x's colour `v0`,
//! 0 everywhere else. Wine's `test_uninitialized_varyings`
//! (dlls/d3d9/tests/visual.c, run on Windows drivers) finds a vs_2_0 that
//! writes only `oPos` giving ps_2_0's `v0` white (0xffffffff) and one that
//! writes only `oD0.x` giving (x, 1, 1, 1); colour 1 and the texture
//! coordinates read 0 in r, g, b (x, y, z) with w 0 on some drivers and 1
//! on others (AMD's and NVIDIA's differ); ps_3_0's colours read no
//! consistent value. vkd3d's `uninitialized-varyings.shader_test`
//! (recorded on Windows) has the same: ps_2_0 `color0` (1, 1, 1, 1),
//! `texcoord0.xyz`, `texcoord3.xy`, `texcoord1.yz` 0. ps30 reads 0 where
//! drivers disagree. Without a vertex shader, a vertex without a diffuse
//! colour is white (the fixed-function pipeline's default diffuse), in
//! every profile.

use crate::core::ir::Program;
use crate::core::isa::RegFile;
use crate::core::profile::Profile;

/// How many input slots a pixel shader has.
pub const SLOTS: u32 = 10;

/// The first slot of `t0` in ps_2_0 and ps_2_x.
const TEXCOORD_BASE: u32 = 2;

/// Whether the profile's pixel inputs are ps_2_0's (`v0`, `v1`, `t0`–`t7`):
/// ps_1_x's are the same two colours and texture coordinates.
fn legacy(profile: Profile) -> bool {
    profile.is_ps1()
        || matches!(
            profile,
            Profile::Ps2_0 | Profile::Ps2X | Profile::Ps2A | Profile::Ps2B
        )
}

/// The slot of input register `file`/`index` in a pixel shader of
/// `profile`, or `None` for a register that is no input of it.
pub fn slot(profile: Profile, file: RegFile, index: u32) -> Option<u32> {
    match (legacy(profile), file) {
        (false, RegFile::Input) if index < SLOTS => Some(index),
        (true, RegFile::Input) if index < TEXCOORD_BASE => Some(index),
        (true, RegFile::Texture) if index < 8 => Some(TEXCOORD_BASE + index),
        _ => None,
    }
}

/// The value a pixel shader of `profile` reads in a component of the input
/// of semantic `usage``index` that nothing upstream writes (the module docs
/// give the sources): 1 in ps_2_0/ps_2_x's `color0`, and in `color0` of any
/// profile when `fixed_function` (no vertex shader: the default diffuse is
/// white); 0 otherwise.
pub fn unwritten(profile: Profile, usage: &str, index: u32, fixed_function: bool) -> f32 {
    let color0 = usage.eq_ignore_ascii_case("color") && index == 0;
    if color0 && (legacy(profile) || fixed_function) {
        1.0
    } else {
        0.0
    }
}

/// The register a slot stands for, as a shader of `profile` spells it
/// (`v3`; `t0` for slot 2 of a ps_2_0 shader).
pub fn name(profile: Profile, slot: u32) -> String {
    if legacy(profile) && slot >= TEXCOORD_BASE {
        format!("t{}", slot - TEXCOORD_BASE)
    } else {
        format!("v{slot}")
    }
}

/// The input `ps30 run` feeds with texture coordinates when it is given an
/// image: `v0` in ps_3_0, `t0` in ps_2_0 and ps_2_x.
pub fn coordinates(profile: Profile) -> u32 {
    if legacy(profile) {
        TEXCOORD_BASE
    } else {
        0
    }
}

/// The slot of [`coordinates`] if `program` declares it.
pub fn declared_coordinates(program: &Program) -> Option<u32> {
    let at = coordinates(program.profile);
    declared(program, at).then_some(at)
}

/// Whether `program` declares input slot `slot`.
pub fn declared(program: &Program, at: u32) -> bool {
    program
        .inputs
        .iter()
        .any(|d| slot(program.profile, d.reg.file, d.reg.index) == Some(at))
}

/// The slots whose values are clamped to [0, 1] on entry (bit per slot):
/// `v0` and `v1` of ps_2_0 and ps_2_x (see the module docs).
pub fn clamped(profile: Profile) -> u16 {
    if legacy(profile) {
        0b11
    } else {
        0
    }
}

/// The slot a person names: a register (`v0`, `t3`) or a semantic
/// (`texcoord3`, `color0`; `texcoord` is `texcoord0`). In ps_2_0 and ps_2_x
/// the semantics are the registers' own (`texcoordN` is `tN`, `colorN` is
/// `vN`); in ps_3_0 a semantic names the `v#` its `dcl_<usage>` declares.
pub fn resolve(program: &Program, text: &str) -> Result<u32, String> {
    let profile = program.profile;
    let number = |rest: &str| -> Option<u32> {
        if rest.is_empty() {
            Some(0)
        } else if rest.bytes().all(|b| b.is_ascii_digit()) && rest.len() <= 3 {
            rest.parse().ok()
        } else {
            None
        }
    };
    let lower = text.to_ascii_lowercase();
    let register = |file: RegFile, rest: &str| {
        let n = number(rest).filter(|_| !rest.is_empty())?;
        slot(profile, file, n)
    };
    if let Some(s) = lower
        .strip_prefix('v')
        .and_then(|r| register(RegFile::Input, r))
        .or_else(|| {
            lower
                .strip_prefix('t')
                .filter(|r| r.bytes().next().is_some_and(|b| b.is_ascii_digit()))
                .and_then(|r| register(RegFile::Texture, r))
        })
    {
        return Ok(s);
    }
    for usage in ["texcoord", "color"] {
        let Some(n) = lower.strip_prefix(usage).and_then(number) else {
            continue;
        };
        let found = if legacy(profile) {
            let file = if usage == "color" {
                RegFile::Input
            } else {
                RegFile::Texture
            };
            slot(profile, file, n)
        } else {
            program
                .inputs
                .iter()
                .find(|d| d.reg.file == RegFile::Input && d.usage == usage && d.usage_index == n)
                .and_then(|d| slot(profile, RegFile::Input, d.reg.index))
        };
        return found.ok_or_else(|| format!("the {profile} shader declares no input `{text}`"));
    }
    let registers = if legacy(profile) {
        "v0, v1, t0 … t7, texcoordN or colorN"
    } else {
        "v0 … v9 or a declared semantic such as texcoord0"
    };
    Err(format!(
        "`{text}` is no input of a {profile} shader ({registers})"
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ps_2_0_inputs_take_the_ten_slots() {
        let p = Profile::Ps2_0;
        assert_eq!(slot(p, RegFile::Input, 1), Some(1));
        assert_eq!(slot(p, RegFile::Input, 2), None);
        assert_eq!(slot(p, RegFile::Texture, 0), Some(2));
        assert_eq!(slot(p, RegFile::Texture, 7), Some(9));
        assert_eq!(slot(p, RegFile::Texture, 8), None);
        assert_eq!(name(p, 9), "t7");
        assert_eq!(name(p, 1), "v1");
        assert_eq!(slot(Profile::Ps3_0, RegFile::Texture, 0), None);
        assert_eq!(slot(Profile::Ps3_0, RegFile::Input, 9), Some(9));
        assert_eq!(clamped(Profile::Ps2X), 3);
        assert_eq!(clamped(Profile::Ps3_0), 0);
    }

    #[test]
    fn names_resolve_by_register_and_semantic() {
        let p = Program {
            profile: Profile::Ps2_0,
            ..Program::default()
        };
        assert_eq!(resolve(&p, "t3"), Ok(5));
        assert_eq!(resolve(&p, "texcoord3"), Ok(5));
        assert_eq!(resolve(&p, "TEXCOORD"), Ok(2));
        assert_eq!(resolve(&p, "color1"), Ok(1));
        assert_eq!(resolve(&p, "v0"), Ok(0));
        assert!(resolve(&p, "v2").is_err());
        assert!(resolve(&p, "texcoord8").is_err());
        let p3 = Program::default();
        assert_eq!(resolve(&p3, "v7"), Ok(7));
        assert!(resolve(&p3, "t0").is_err());
        assert!(resolve(&p3, "texcoord0").is_err());
    }
}
