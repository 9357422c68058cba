//! The limits a profile's assembler enforces and ps_3_0's does not: the
//! slot counts of ps_2_0 (64 arithmetic, 32 texture, 96 in all), ps_2_x
//! (its capabilities' slots) and vs_2_0/vs_2_x (256, and 16 static
//! flow-control instructions), and ps_2_0's levels of dependent texture
//! reads. The numbers are [`Profile::limits`]; the
//! codes and their order are Microsoft's assembler's (measured:
//! `tests/oracle/corpus/asm/profiles/*/limit-*.psh`).

use crate::core::diag::{codes, Diagnostic, Diagnostics, SourceFile};
use crate::core::ir::{Info, Program, Span};
use crate::core::isa::{Class, Opcode, RegFile, SlotTable};
use crate::core::profile::{Profile, Stage};

/// Checks the slot limits and the dependent-read levels of a program of a
/// profile other than ps_3_0 (whose limits the cost model reports).
pub fn check(p: &Program, info: &Info, diags: &mut Diagnostics, file: &SourceFile) {
    if p.profile == Profile::Ps3_0 {
        return;
    }
    // Microsoft's assembler names the end of the file for the counts.
    let end = Span::new(file.text.len(), file.text.len());
    let limits = p.profile.limits();
    if p.profile.stage() == Stage::Pixel {
        pixel_slots(p, info, limits, end, diags);
        if p.profile == Profile::Ps2_0 {
            colour_outputs(p, end, diags);
        }
        if let Some(levels) = limits.dependent_reads {
            dependent_reads(p, levels, diags, file);
        }
        return;
    }
    let count = info.total(SlotTable::Fxc);
    if let Some(max) = limits.slots.filter(|&m| count.total() > m) {
        diags.push(Diagnostic::coded(
            codes::VERTEX_SLOTS,
            end,
            format!(
                "{} instruction slots used; {} allows {max}",
                count.total(),
                p.profile
            ),
        ));
    }
    if matches!(p.profile, Profile::Vs2_0 | Profile::Vs2X) {
        static_flow_count(p, end, diags);
    }
}

/// vs_2_0 and vs_2_x run at most 16 static flow-control instructions
/// (Microsoft's "Flow Control Nesting Limits": `call`, `callnz b#`,
/// `if b#`, the `else` of an `if b#`, `loop` and `rep` count one each;
/// measured: 25 are X5520, which `D3DAssemble` returns as E_FAIL; ps_2_x
/// and vs_3_0 have no such count).
fn static_flow_count(p: &Program, end: Span, diags: &mut Diagnostics) {
    let on_bool = |i: &crate::core::ir::Instruction| {
        i.src
            .first()
            .is_some_and(|s| s.reg.file == RegFile::ConstBool)
    };
    let mut ifs: Vec<bool> = Vec::new();
    let mut count = 0u32;
    for i in &p.instructions {
        let counts = match i.op {
            Opcode::Call | Opcode::Loop | Opcode::Rep => true,
            Opcode::CallNz => !i.src.iter().any(|s| s.reg.file == RegFile::Predicate),
            Opcode::If | Opcode::Ifc => {
                ifs.push(i.op == Opcode::If && on_bool(i));
                ifs.last() == Some(&true)
            }
            Opcode::Else => ifs.last() == Some(&true),
            Opcode::EndIf => {
                ifs.pop();
                false
            }
            _ => false,
        };
        count += u32::from(counts);
    }
    if count > 16 {
        diags.push(Diagnostic::coded(
            codes::STATIC_FLOW_COUNT,
            end,
            format!(
                "{count} static flow-control instructions (call, callnz b#, if b#, its else, loop, rep); {} allows 16",
                p.profile
            ),
        ));
    }
}

/// A ps_2_x program's slots under capabilities other than the assembler's
/// (`core/valid/caps.rs`).
pub(super) fn slots_under(
    p: &Program,
    info: &Info,
    caps: crate::core::profile::Ps2xCaps,
    end: Span,
    diags: &mut Diagnostics,
) {
    pixel_slots(p, info, caps.limits(), end, diags);
}

/// A pixel shader's arithmetic, texture and total slots against `limits`.
fn pixel_slots(
    p: &Program,
    info: &Info,
    limits: crate::core::profile::Limits,
    end: Span,
    diags: &mut Diagnostics,
) {
    let mut count = info.total(SlotTable::Fxc);
    // The listing counts texkill as arithmetic; the ps_2_x limits count it
    // as a tex* instruction (measured: 33 texkill are X5607 in ps_2_0).
    let kills = p
        .instructions
        .iter()
        .filter(|i| i.op == Opcode::TexKill)
        .count() as u32;
    count.texture += kills;
    count.arithmetic = count.arithmetic.saturating_sub(kills);
    let over = |n: u32, max: Option<u32>| max.filter(|&m| n > m);
    let checks = [
        (
            codes::ARITHMETIC_SLOTS,
            "arithmetic",
            count.arithmetic,
            limits.arithmetic,
        ),
        (
            codes::TEXTURE_SLOTS,
            "texture",
            count.texture,
            limits.texture,
        ),
        (codes::TOTAL_SLOTS, "total", count.total(), limits.slots),
    ];
    for (code, what, n, max) in checks {
        if let Some(max) = over(n, max) {
            diags.push(Diagnostic::coded(
                code,
                end,
                format!(
                    "{n} {what} instruction slots used; {} allows {max}",
                    p.profile
                ),
            ));
        }
    }
}

/// ps_2_0's dependent reads, as Microsoft's assembler defines them (X5775's
/// own text): a texture instruction is dependent to the first order when it
/// reads a temporary (not a `t#`) or writes a temporary written before; to
/// order n when it reads or writes a temporary whose contents depend on an
/// instruction dependent to order n - 1. At most `levels - 1` orders.
pub(super) fn dependent_reads(
    p: &Program,
    levels: u32,
    diags: &mut Diagnostics,
    file: &SourceFile,
) {
    // For each temporary: whether it was written, and the highest order of
    // texture instruction its contents depend on.
    let mut written = [false; 32];
    let mut depends: [Option<u32>; 32] = [None; 32];
    let temp =
        |r: &crate::core::ir::Reg| (r.file == RegFile::Temp).then_some(r.index as usize % 32);
    for ins in &p.instructions {
        let reads: Vec<usize> = ins.src.iter().filter_map(|s| temp(&s.reg)).collect();
        let target = ins.dst.as_ref().and_then(|d| temp(&d.reg));
        let before = |r: usize| depends[r];
        if ins.op.class() == Class::Texture {
            let killed = ins.op == Opcode::TexKill;
            // texkill's operand is read, though it is written like a destination.
            let read_regs: Vec<usize> = reads
                .iter()
                .copied()
                .chain(target.filter(|_| killed))
                .collect();
            let mut order = u32::from(!read_regs.is_empty());
            if let Some(t) = target.filter(|_| !killed) {
                order = order.max(u32::from(written[t]));
            }
            for r in read_regs.iter().chain(target.iter()) {
                if let Some(k) = before(*r) {
                    order = order.max(k + 1);
                }
            }
            if order >= levels {
                diags.push(
                    Diagnostic::coded(
                        codes::DEPENDENT_READS,
                        ins.origin.span,
                        format!(
                            "a dependent texture read of order {order}; {} allows {}",
                            p.profile,
                            levels - 1
                        ),
                    )
                    .with_label("this read depends on too many reads before it")
                    .in_origin(&ins.origin, file),
                );
                return;
            }
            if let Some(t) = target.filter(|_| !killed) {
                depends[t] = Some(order);
                written[t] = true;
            }
            continue;
        }
        if let Some(t) = target {
            let from = reads.iter().filter_map(|&r| before(r)).max();
            let partial = ins.dst.as_ref().is_some_and(|d| d.mask.0 != 0xF);
            depends[t] = if partial { from.max(depends[t]) } else { from };
            written[t] = true;
        }
    }
}

/// ps_2_0 writes its colour outputs from oC0 up, without gaps (X5573).
fn colour_outputs(p: &Program, end: Span, diags: &mut Diagnostics) {
    let mut written = [false; 4];
    for d in p.instructions.iter().filter_map(|i| i.dst.as_ref()) {
        if d.reg.file == RegFile::ColorOut {
            written[d.reg.index as usize % 4] = true;
        }
    }
    if let Some(last) = written.iter().rposition(|&w| w) {
        if let Some(gap) = written[..last].iter().position(|&w| !w) {
            diags.push(
                Diagnostic::coded(
                    codes::COLOUR_OUTPUT_GAP,
                    end,
                    format!("the shader writes oC{last} but not oC{gap}"),
                )
                .with_help("a ps_2_0 shader that writes oCn writes every oC below it"),
            );
        }
    }
}
