//! The comment block that opens every translated file: which shader it
//! came from, under which float rules, and what an application binds where
//! (from [`Interface`], the same description the lowering used).

use super::interface::{self, Interface};
use super::{Target, Translation};
use crate::core::float_rules::RULES;

/// Registers as a short list: `c0, c1, c3…c5`.
fn registers(prefix: &str, regs: &[u32]) -> String {
    let mut out: Vec<String> = Vec::new();
    let mut i = 0;
    while i < regs.len() {
        let mut j = i;
        while j + 1 < regs.len() && regs[j + 1] == regs[j] + 1 {
            j += 1;
        }
        out.push(match j - i {
            0 => format!("{prefix}{}", regs[i]),
            1 => format!("{prefix}{}, {prefix}{}", regs[i], regs[j]),
            _ => format!("{prefix}{}…{prefix}{}", regs[i], regs[j]),
        });
        i = j + 1;
    }
    if out.is_empty() {
        "none".into()
    } else {
        out.join(", ")
    }
}

/// The header's lines, without comment markers.
pub fn lines(source: &str, t: &Translation, target: Target) -> Vec<String> {
    let i: &Interface = &t.interface;
    let mut l = vec![
        format!(
            "{source}: Direct3D 9 {}, translated by ps30 to {}",
            i.profile,
            target.describe()
        ),
        format!(
            "float rules: {} (ps30 translate --float-rules; the emulator follows the same rules)",
            t.rules
        ),
    ];
    if t.rules.d3d9_specials() {
        for r in RULES.iter().take(RULES.len() - 1) {
            l.push(format!("  {}: {}", r.instruction, r.d3d9));
        }
    }
    if t.rules.zero_mul() {
        l.push(
            "  products with a zero factor are 0 (mul, mad, lrp, dp2add, dp3, dp4, m#x#, nrm)"
                .into(),
        );
    }
    if t.rules.flush_denormals() {
        l.push("  denormals read from constants and inputs, written by any instruction, or made by a product or sum inside mad, lrp and the dot products, are zeros of their sign".into());
    }
    l.push(format!("entry point: fragment `{}`", t.entry_name()));
    l.push(String::new());
    l.push(format!(
        "group 0, binding {}: uniform `ps30` (Ps30Constants, {} bytes)",
        interface::CONSTANTS_BINDING,
        interface::CONSTANTS_SIZE
    ));
    l.push(format!(
        "  c# at byte 16·# (SetPixelShaderConstantF); this shader reads {}{}",
        registers("c", &i.floats_read),
        own("c", &i.float_defs)
    ));
    l.push(format!(
        "  i# at byte {} + 16·# (SetPixelShaderConstantI); reads {}{}",
        interface::INTS_OFFSET,
        registers("i", &i.ints_read),
        own("i", &i.int_defs)
    ));
    l.push(format!(
        "  b# at byte {} + 16·#, true when nonzero (SetPixelShaderConstantB); reads {}{}",
        interface::BOOLS_OFFSET,
        registers("b", &i.bools_read),
        own("b", &i.bool_defs)
    ));
    l.push(format!(
        "  s# state at byte {} + {}·# (Ps30Sampler: lod bias, border colour, MIRRORONCE and BORDER emulation; all zero for plain sampler states)",
        interface::SAMPLERS_OFFSET,
        interface::SAMPLER_STATE_SIZE
    ));
    for s in &i.samplers {
        l.push(format!(
            "group 0, binding {}: s{}'s texture ({}), binding {}: its sampler",
            s.texture_binding,
            s.register,
            match s.ty {
                crate::core::isa::SamplerType::Tex2d => "2D",
                crate::core::isa::SamplerType::Cube => "cube",
                crate::core::isa::SamplerType::Volume => "volume",
            },
            s.sampler_binding
        ));
    }
    for v in &i.inputs {
        l.push(format!(
            "@location({}): {} (dcl_{}{}{}{})",
            v.location,
            v.spelled
                .clone()
                .unwrap_or_else(|| format!("v{}", v.register)),
            v.usage,
            v.usage_index,
            if v.centroid { ", centroid" } else { "" },
            if v.clamped { ", clamped to [0, 1]" } else { "" }
        ));
    }
    if i.position {
        l.push("vPos: @builtin(position).xy - 0.5 (Direct3D 9 pixel centres are integers)".into());
    }
    if i.face {
        l.push("vFace: +1 front-facing, -1 back-facing (@builtin(front_facing))".into());
    }
    for o in &i.outputs {
        l.push(format!("@location({o}) out: oC{o}"));
    }
    if i.depth {
        l.push("@builtin(frag_depth) out: oDepth".into());
    }
    if i.kills {
        l.push("texkill marks the pixel; it is discarded after the shader ends (Direct3D 9 keeps running it)".into());
    }
    for n in &t.notes {
        l.push(format!("note: {n}"));
    }
    l
}

fn own(prefix: &str, defs: &[u32]) -> String {
    if defs.is_empty() {
        String::new()
    } else {
        format!(
            "; defines {} itself (values set by the application are ignored there)",
            registers(prefix, defs)
        )
    }
}

/// The header as `//` comments, ending with a blank line.
pub fn comment(source: &str, t: &Translation, target: Target) -> String {
    let mut s = String::new();
    for line in lines(source, t, target) {
        if line.is_empty() {
            s.push_str("//\n");
        } else {
            s.push_str("// ");
            s.push_str(&line);
            s.push('\n');
        }
    }
    s.push('\n');
    s
}

#[cfg(test)]
mod tests {
    use super::registers;

    #[test]
    fn register_lists_collapse_runs() {
        assert_eq!(registers("c", &[0, 1, 3, 4, 5, 9]), "c0, c1, c3…c5, c9");
        assert_eq!(registers("i", &[]), "none");
    }
}
