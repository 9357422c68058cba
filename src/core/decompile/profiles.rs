//! Which profile's HLSL a shader becomes, and the parts of the HLSL that
//! change with the profile of a pixel shader: the compile target (ps_2_x
//! bytecode is what the `ps_2_a` target writes, vs_2_x what `vs_2_a`
//! writes), the first line naming it, and ps_2_0's inputs, which carry no
//! usage (`dcl t0`, `dcl v1`): a texture coordinate `t#` is
//! `TEXCOORD#` and a colour `v#` is `COLOR#`, the registers
//! Microsoft's compiler gives those semantics back.
//!
//! ps_1_x is not here: Microsoft's compiler no longer writes ps_1_x from
//! HLSL (`D3DCompile` refuses the targets, X3539), so a ps_1_x shader's
//! HLSL is its lowering's, for ps_2_0 or larger (`ps1.rs`).

use super::{DecompileError, Target};
use crate::core::ir::InputDecl;
use crate::core::isa::RegFile;
use crate::core::profile::Profile;

/// The HLSL target a shader of `profile` is written for.
pub(crate) fn target(profile: Profile) -> Result<Target, DecompileError> {
    let name = match profile {
        Profile::Ps3_0 => "ps_3_0",
        Profile::Ps2_0 => "ps_2_0",
        // ps_2_x bytecode is what the ps_2_a and ps_2_b targets write; ps_2_a
        // has every ps_2_x instruction (predication, flow control, gradients)
        Profile::Ps2X | Profile::Ps2A | Profile::Ps2B => "ps_2_a",
        Profile::Vs2_0 => "vs_2_0",
        Profile::Vs2X | Profile::Vs2A => "vs_2_a",
        Profile::Vs3_0 => "vs_3_0",
        p => {
            return Err(DecompileError::Unsupported(format!(
                "a {p} shader: decompile reads ps_1_x, ps_2_0, ps_2_x, ps_3_0, vs_2_0, vs_2_x and vs_3_0"
            )))
        }
    };
    Ok(Target { profile: name })
}

/// The comment lines that open the HLSL: what was decompiled and, for a
/// target other than ps_3_0 (the compiler's default), the first line
/// `// oracle: target=…` that `tools/oracle/regen`'s harness reads to
/// compile the file for that target.
pub(crate) fn header(profile: Profile, target: Target) -> String {
    if target.profile == "ps_3_0" {
        return "// ps_3_0 shader decompiled by ps30\n".into();
    }
    let named = if profile.name() == target.profile {
        String::new()
    } else {
        format!(" (HLSL for {})", target.profile)
    };
    format!(
        "// oracle: target={}\n// {} shader decompiled by ps30{named}\n",
        target.profile,
        profile.name()
    )
}

/// The usage and usage index an input declaration stands for: its own, or
/// for ps_2_0/ps_2_x's `dcl t#` and `dcl v#` (no usage) `texcoord#` and
/// `color#`.
pub fn semantic(d: &InputDecl) -> (String, u32) {
    if !d.usage.is_empty() {
        return (d.usage.clone(), d.usage_index);
    }
    match d.reg.file {
        RegFile::Texture => ("texcoord".into(), d.reg.index),
        _ => ("color".into(), d.reg.index),
    }
}

/// The attribute an `if` block takes: `[branch]` on a vertex shader's
/// dynamic branch (`if_comp`, `if p0`), which Microsoft's compiler
/// otherwise flattens into a selection by arithmetic (`slt`, `mad`) that
/// rounds differently. A static branch on a `bool` stays a branch without
/// it (nested, the attribute is refused: X3524). Pixel shaders take none:
/// ps_3_0 keeps its branches, and for ps_2_x the compiler refuses
/// `[branch]` (X3528) and flattens with `cmp`, which selects exactly.
pub(crate) fn branch(
    shader: &crate::core::ir::Shader,
    x: &crate::core::ir::Instruction,
) -> &'static str {
    let on_bool = x.src.iter().any(|s| s.reg.file == RegFile::ConstBool);
    match shader.program().profile.stage() {
        crate::core::profile::Stage::Vertex if !on_bool => "[branch] ",
        _ => "",
    }
}
