//! `sin` and `cos` as Microsoft's compiler lowers them, read back as the
//! call it lowered.
//!
//! `sincos` takes an angle in [−π, π]; for `sin(x)` the compiler first
//! brings x there with three instructions of its own,
//!
//! ```text
//! mad t, x, 1/(2π), 0.5      (0.159154937, 0.5)
//! frc t, t
//! mad t, t, 2π, −π           (6.28318548, −3.14159274)
//! sincos d, t.c
//! ```
//!
//! Written back as `sin(frac(x·0.159… + 0.5)·6.283… − 3.141…)`, the HLSL
//! makes the compiler reduce the already reduced angle a second time: two
//! more roundings in the argument, which a shader like a hash
//! (`frac(sin(x)·43758.5)`) multiplies by thousands. Where the three
//! instructions feed only `sincos`, the reduction is the compiler's, not
//! the shader's: they are read as `t = x`, and the compiler, given
//! `sin(t)`, writes the same three instructions again, bit for bit. (The
//! compiler may share the `frc` with another value's lanes, `frc r1.xz`:
//! that `frc` keeps the other lanes.)
//!
//! The match is strict: the constants' exact bits, no modifiers, no
//! `_sat`, no predicate, no flow control from the first `mad` to the last
//! `sincos` that reads the angle, no other instruction reading or writing
//! the angle's components in between, and no reader of them but `sincos`
//! until they are overwritten.

use crate::core::ir::{Dst, Instruction, Shader, SrcMod};
use crate::core::isa::{Class, Opcode, RegFile};

/// 1/(2π), ½, 2π and −π as the compiler writes them (f32 bits).
const ONE_OVER_TWO_PI: u32 = 0x3e22_f983;
const HALF: u32 = 0x3f00_0000;
const TWO_PI: u32 = 0x40c9_0fdb;
const MINUS_PI: u32 = 0xc049_0fdb;

/// The instructions of `shader` with each range reduction that feeds only
/// `sincos` read as a plain move of its angle: the first `mad` becomes
/// `mov t, x`, the `frc` and the second `mad` become `nop`.
pub(crate) fn read_back(shader: &Shader) -> Vec<Instruction> {
    let mut ins = shader.instructions().to_vec();
    let mut a = 0;
    while a < ins.len() {
        if let Some((frc, mad)) = reduction(shader, &ins, a) {
            let lanes = ins[a].dst.map_or(0, |d| d.mask.0);
            ins[a].op = Opcode::Mov;
            ins[a].src.truncate(1);
            // a `frc` shared with other lanes keeps working on those
            if let Some(w) = ins[frc].dst.as_mut().filter(|w| w.mask.0 != lanes) {
                w.mask.0 &= !lanes;
            } else {
                nop(&mut ins[frc]);
            }
            nop(&mut ins[mad]);
        }
        a += 1;
    }
    ins
}

/// `x` made a `nop`.
fn nop(x: &mut Instruction) {
    x.op = Opcode::Nop;
    x.dst = None;
    x.src.clear();
}

/// The `frc` and second `mad` of a reduction that starts at `a`.
fn reduction(shader: &Shader, ins: &[Instruction], a: usize) -> Option<(usize, usize)> {
    let first = &ins[a];
    let d = first.dst?;
    let plain = |x: &Instruction| !x.sat && x.predicate.is_none();
    if first.op != Opcode::Mad || !plain(first) || d.reg.file != RegFile::Temp {
        return None;
    }
    let lanes: Vec<usize> = (0..4).filter(|&c| d.mask.has(c)).collect();
    if !constant(shader, first, 1, &lanes, ONE_OVER_TWO_PI)
        || !constant(shader, first, 2, &lanes, HALF)
    {
        return None;
    }
    // the next two instructions that touch the angle's lanes
    let touches = |x: &Instruction| {
        x.dst
            .is_some_and(|w| w.reg == d.reg && w.mask.0 & d.mask.0 != 0)
            || reads_lanes(x, d.reg.index) & d.mask.0 != 0
    };
    let mut next = ins.iter().enumerate().skip(a + 1);
    // The next instruction that touches the lanes: `want` on them, reading
    // each lane from itself; `wider`: it may also work on other lanes (a
    // `frc` the compiler shares with another value's).
    let mut step = |want: Opcode, wider: bool| -> Option<usize> {
        let (i, x) = next.find(|(_, x)| x.op.class() == Class::Flow || touches(x))?;
        let written = x.dst.filter(|w| w.reg == d.reg)?.mask.0;
        let same = x.op == want
            && plain(x)
            && (written == d.mask.0 || wider && written & d.mask.0 == d.mask.0)
            && x.src[0].reg == d.reg
            && x.src[0].modifier == SrcMod::None
            && x.src[0].relative.is_none()
            && lanes.iter().all(|&p| x.src[0].swizzle.0[p] as usize == p);
        same.then_some(i)
    };
    let frc = step(Opcode::Frc, true)?;
    let mad = step(Opcode::Mad, false)?;
    if !constant(shader, &ins[mad], 1, &lanes, TWO_PI)
        || !constant(shader, &ins[mad], 2, &lanes, MINUS_PI)
    {
        return None;
    }
    only_sincos_reads(shader, ins, mad, d).then_some((frc, mad))
}

/// Whether source `k` of `x` is a `def` constant holding `bits` in every
/// component that `lanes` read.
fn constant(shader: &Shader, x: &Instruction, k: usize, lanes: &[usize], bits: u32) -> bool {
    let Some(s) = x.src.get(k) else { return false };
    if s.reg.file != RegFile::Const || s.relative.is_some() || s.modifier != SrcMod::None {
        return false;
    }
    let Some(value) = shader.program().float_def(s.reg.index) else {
        return false;
    };
    lanes
        .iter()
        .all(|&p| value[s.swizzle.0[p] as usize & 3].to_bits() == bits)
}

/// The components of temporary `r` that `x` reads (sources only).
fn reads_lanes(x: &Instruction, r: u32) -> u8 {
    let width = if x.op == Opcode::SinCos { 1 } else { 4 };
    x.src
        .iter()
        .filter(|s| s.reg.file == RegFile::Temp && s.reg.index == r)
        .fold(0u8, |bits, s| {
            (0..width).fold(bits, |b, p| b | 1 << (s.swizzle.0[p] & 3))
        })
}

/// Whether every read of the lanes `d` writes at `at`, until all are
/// overwritten, is a `sincos` of one of them, with no flow control first
/// (but the `ret` that ends a shader without subroutines).
fn only_sincos_reads(shader: &Shader, ins: &[Instruction], at: usize, d: Dst) -> bool {
    let mut live = d.mask.0;
    let mut read = false;
    let last = ins.len() - 1;
    for (i, x) in ins.iter().enumerate().skip(at + 1) {
        if live == 0 {
            break;
        }
        if x.op.class() == Class::Flow {
            let end = x.op == Opcode::Ret && i == last && shader.info().labels.is_empty();
            return end && read;
        }
        if reads_lanes(x, d.reg.index) & live != 0 {
            let s = &x.src[0];
            let sincos = x.op == Opcode::SinCos
                // ps_2_x and vs_2_x name their macro's constants (any registers)
                && x.src[1..].iter().all(|c| c.reg.file == RegFile::Const)
                && s.modifier == SrcMod::None
                && s.relative.is_none();
            if !sincos {
                return false;
            }
            read = true;
        }
        if let Some(w) = x.dst.filter(|w| w.reg == d.reg && x.predicate.is_none()) {
            live &= !w.mask.0;
        }
    }
    read
}
