//! ps_2_x under a device's capabilities, and the source-swizzle rules of
//! ps_2_0 and ps_2_x.
//!
//! `D3DAssemble` checks a `ps_2_x` file against every capability on
//! ([`Ps2xCaps::ASSEMBLER`]); a device may have fewer (`D3DPSHADERCAPS2_0`:
//! no predication, no gradient instructions, ps_2_0's swizzles, dependent
//! reads and texture limit, 12–32 temporaries, 96–512 slots, shallower flow
//! control). [`check`] holds a validated program to the capabilities a
//! person names (`ps30 check --caps`), refusing with the code Microsoft's
//! assembler gives for the same thing where the profile lacks it (measured
//! on ps_2_0 and ps_2_x probes): an instruction that needs a capability is
//! X2000, as in ps_2_0; a swizzle X5202; a temporary X2005; slots X5234 and
//! X5617; texture instructions X5607; dependent reads X5775; flow control
//! with a depth of 0 X5190; deeper nesting than the depths, counted
//! through calls as [`super::nesting`] counts it, X5493 (loops), X5843
//! (calls) and X5849 (dynamic `if`; X5846 on `p0`, X5880 for a
//! `break_comp`, X6048 for a `callnz p0`).
//!
//! [`swizzles`] is the part every ps_2_0 and ps_2_x shader obeys (measured
//! with `D3DAssemble`): no source swizzle on a texture instruction (X5198,
//! ps_2_x included), and in ps_2_0 only the swizzles `.xyzw`, `.yzxw`,
//! `.zxyw`, `.wzyx` and the four replicates (X5202).

use crate::core::diag::{codes, Diagnostic, Diagnostics, SourceFile};
use crate::core::ir::{Info, Instruction, Program, Span, Swizzle};
use crate::core::isa::{Opcode, RegFile};
use crate::core::profile::{Profile, Ps2xCaps};

/// The source swizzles ps_2_0 allows (and ps_2_x without the arbitrary
/// swizzle capability): Microsoft's X5202 text lists them.
const PS_2_0_SWIZZLES: [[u8; 4]; 8] = [
    [0, 1, 2, 3],
    [0, 0, 0, 0],
    [1, 1, 1, 1],
    [2, 2, 2, 2],
    [3, 3, 3, 3],
    [1, 2, 0, 3],
    [2, 0, 1, 3],
    [3, 2, 1, 0],
];

fn spelled(s: Swizzle) -> String {
    s.0.iter()
        .map(|&c| ['x', 'y', 'z', 'w'][c as usize & 3])
        .collect()
}

/// Whether the instruction is one of the texld family.
fn texture(op: Opcode) -> bool {
    matches!(
        op,
        Opcode::TexLd | Opcode::TexLdP | Opcode::TexLdB | Opcode::TexLdD
    )
}

/// The source-swizzle rules of ps_2_0 and ps_2_x (see the module docs);
/// `arbitrary`: the capability that lifts ps_2_0's list.
pub fn swizzles(p: &Program, arbitrary: bool, diags: &mut Diagnostics) {
    for ins in &p.instructions {
        for (k, s) in ins.src.iter().enumerate() {
            let span = ins.origin.span;
            if texture(ins.op) && k < 2 && s.swizzle != Swizzle::IDENTITY {
                let which = if k == 0 { "first" } else { "second" };
                diags.push(Diagnostic::coded(
                    codes::TEX_SOURCE_SWIZZLE,
                    span,
                    format!(
                        "`{}`: no source swizzle on a texture instruction (the {which} source has .{})",
                        ins.op,
                        spelled(s.swizzle)
                    ),
                ));
                continue;
            }
            let plain = matches!(
                s.reg.file,
                RegFile::ConstBool
                    | RegFile::ConstInt
                    | RegFile::Predicate
                    | RegFile::Label
                    | RegFile::Sampler
            );
            if !arbitrary && !plain && !texture(ins.op) && !PS_2_0_SWIZZLES.contains(&s.swizzle.0) {
                diags.push(Diagnostic::coded(
                    codes::PS2_SWIZZLE,
                    span,
                    format!(
                        "source swizzle .{} needs arbitrary swizzles; {} allows .xyzw, .yzxw, .zxyw, .wzyx and replicates",
                        spelled(s.swizzle),
                        p.profile
                    ),
                ));
            }
        }
    }
}

/// What an instruction asks of the capabilities.
fn needs(ins: &Instruction) -> (bool, bool) {
    let predicate = ins.predicate.is_some()
        || ins.op == Opcode::Setp
        || ins.op == Opcode::BreakP
        || ins.src.iter().any(|s| s.reg.file == RegFile::Predicate);
    let gradient = matches!(ins.op, Opcode::Dsx | Opcode::Dsy | Opcode::TexLdD);
    (predicate, gradient)
}

/// Whether a flow instruction is dynamic flow control (`if_comp`, `if p0`,
/// `break`, `break_comp`, `breakp`, `callnz p0`), and whether it is static
/// flow control (`rep`, `if b#`, `call`, `callnz b#`). A plain `break` is
/// dynamic although it tests nothing: Direct3D 9 lists it among the
/// instructions `DynamicFlowControlDepth` enables ("if, break, and
/// breakc"), and Microsoft's assembler refuses it where a profile has
/// static flow control only (vs_2_0's `rep` with a `break` is X5655).
fn flow(ins: &Instruction) -> (bool, bool) {
    let on_predicate = ins.src.iter().any(|s| s.reg.file == RegFile::Predicate);
    match ins.op {
        Opcode::Ifc | Opcode::Break | Opcode::BreakC | Opcode::BreakP => (true, false),
        Opcode::If | Opcode::CallNz => (on_predicate, !on_predicate),
        Opcode::Rep | Opcode::Call => (false, true),
        _ => (false, false),
    }
}

/// Holds a validated ps_2_x program to `caps` (see the module docs). The
/// slot counts are Microsoft's (the listing's, with `texkill` a texture
/// slot), as [`super::limits`] counts them.
pub fn check(p: &Program, info: &Info, caps: Ps2xCaps, file: &SourceFile) -> Diagnostics {
    let mut diags = Diagnostics::default();
    if !matches!(p.profile, Profile::Ps2X) {
        return diags;
    }
    let end = Span::new(file.text.len(), file.text.len());
    for ins in &p.instructions {
        let span = ins.origin.span;
        let (predicate, gradient) = needs(ins);
        for (need, have, what) in [
            (predicate, caps.predication, "predication"),
            (gradient, caps.gradients, "gradients"),
        ] {
            if need && !have {
                diags.push(Diagnostic::coded(
                    codes::SYNTAX,
                    span,
                    format!(
                        "{}`{}` needs the {what} capability",
                        if ins.predicate.is_some() && what == "predication" {
                            "a predicated "
                        } else {
                            ""
                        },
                        ins.op
                    ),
                ));
            }
        }
        let (dynamic, stat) = flow(ins);
        for (is, depth, what) in [
            (dynamic, caps.dynamic_flow_depth, "dynamic"),
            (stat, caps.static_flow_depth, "static"),
        ] {
            if is && depth == 0 {
                diags.push(Diagnostic::coded(
                    codes::PS_UNSUPPORTED,
                    span,
                    format!("`{}` needs {what} flow control (a depth of 0)", ins.op),
                ));
            }
        }
        for s in ins.src.iter().map(|s| s.reg).chain(ins.dst.map(|d| d.reg)) {
            if s.file == RegFile::Temp && s.index >= caps.temps {
                diags.push(Diagnostic::coded(
                    codes::REGISTER,
                    span,
                    format!(
                        "register `r{}` is out of range: {} temporaries",
                        s.index, caps.temps
                    ),
                ));
            }
        }
    }
    if let Some(d) = super::nesting::check(p, super::nesting::Limits::under(caps), file) {
        diags.push(d);
    }
    swizzles(p, caps.arbitrary_swizzle, &mut diags);
    super::limits::slots_under(p, info, caps, end, &mut diags);
    if !caps.no_dependent_read_limit {
        super::limits::dependent_reads(p, 4, &mut diags, file);
    }
    diags
}
