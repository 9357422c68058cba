//! `mul` with a matrix of the constant table, read back from the dot
//! products the compiler makes of it.
//!
//! `mul(v, M)` with a column-major `M` (each register a column) is one
//! `dp4` (or `dp3`) of `v` with each register of `M` in turn, writing
//! `x`, `y`, `z`, `w` of one destination; `mul(M, v)` with a row-major `M`
//! (each register a row) is the same run. Where such a run reads every
//! register of a matrix the constant table declares, in order, it is read
//! as the matrix instruction of its shape (`m4x4`, `m4x3`, `m3x3`, …) and
//! written as `mul`: the same dot products, so the compiler, given the
//! `mul`, writes the same instructions again.

use super::names::{FloatName, Names};
use crate::core::ir::{Instruction, WriteMask};
use crate::core::isa::{Opcode, RegFile};

/// A whole matrix at constant registers `base`…`base + n − 1` of `width`
/// components each: its name and whether its registers are rows
/// (row-major, `mul(M, v)`) rather than columns (`mul(v, M)`).
pub(crate) fn whole(names: &Names, base: u32, width: u8, n: u32) -> Option<(String, bool)> {
    let name_of = |r: u32| -> Option<(String, bool, u32, u8)> {
        match names.floats.get(&r)? {
            FloatName::Column { base, column, rows } => {
                Some((base.clone(), false, *column as u32, *rows))
            }
            FloatName::Vector { base, width } => {
                let open = base.rfind('[')?;
                let row: u32 = base[open + 1..].strip_suffix(']')?.parse().ok()?;
                Some((base[..open].to_string(), true, row, *width))
            }
            FloatName::Literal(_) => None,
        }
    };
    let (matrix, rows, first, w) = name_of(base)?;
    if first != 0 || w != width {
        return None;
    }
    for k in 1..n {
        let (m, r, i, w) = name_of(base + k)?;
        if m != matrix || r != rows || i != k || w != width {
            return None;
        }
    }
    // the matrix has no register past the run
    if name_of(base + n).is_some_and(|(m, r, i, _)| m == matrix && r == rows && i == n) {
        return None;
    }
    // a row-major name `M[k]` must be a matrix's row, not an array element
    let declared = format!("x{width} {matrix} :");
    if rows
        && !names
            .decls
            .iter()
            .any(|d| d.starts_with("row_major ") && d.contains(&declared))
    {
        return None;
    }
    Some((matrix, rows))
}

/// The matrix instruction of `n` dot products of `width` components.
fn shape(width: u8, n: u32) -> Option<Opcode> {
    Some(match (width, n) {
        (4, 4) => Opcode::M4x4,
        (4, 3) => Opcode::M4x3,
        (3, 4) => Opcode::M3x4,
        (3, 3) => Opcode::M3x3,
        (3, 2) => Opcode::M3x2,
        _ => return None,
    })
}

/// `ins` with each run of dot products over a whole matrix read as one
/// matrix instruction (the others of the run become `nop`).
pub(crate) fn group(mut ins: Vec<Instruction>, names: &Names) -> Vec<Instruction> {
    let mut a = 0;
    while a < ins.len() {
        if let Some(n) = run(&ins, a, names) {
            let width = if ins[a].op == Opcode::Dp4 { 4 } else { 3 };
            if let Some(op) = shape(width, n) {
                ins[a].op = op;
                if let Some(d) = ins[a].dst.as_mut() {
                    d.mask = WriteMask((1u8 << n) - 1);
                }
                for x in &mut ins[a + 1..a + n as usize] {
                    x.op = Opcode::Nop;
                    x.dst = None;
                    x.src.clear();
                }
                a += n as usize;
                continue;
            }
        }
        a += 1;
    }
    ins
}

/// The length of the run of dot products over a whole matrix at `a`.
fn run(ins: &[Instruction], a: usize, names: &Names) -> Option<u32> {
    let first = &ins[a];
    let width = match first.op {
        Opcode::Dp4 => 4,
        Opcode::Dp3 => 3,
        _ => return None,
    };
    let d = first.dst?;
    let (v, m0) = (*first.src.first()?, *first.src.get(1)?);
    if m0.reg.file != RegFile::Const || v.relative.is_some() || v.reg == d.reg {
        return None;
    }
    let fits = |k: usize, x: &Instruction| {
        let Some(xd) = x.dst else { return false };
        let (Some(xv), Some(xm)) = (x.src.first(), x.src.get(1)) else {
            return false;
        };
        x.op == first.op
            && !x.sat
            && x.predicate.is_none()
            && xd.reg == d.reg
            && xd.relative.is_none()
            && xd.mask.0 == 1 << k
            && *xv == v
            && xm.reg.file == RegFile::Const
            && xm.reg.index == m0.reg.index + k as u32
            && xm.relative.is_none()
            && xm.modifier == crate::core::ir::SrcMod::None
            && xm.swizzle == crate::core::ir::Swizzle::IDENTITY
    };
    let n = ins[a..]
        .iter()
        .take(4)
        .enumerate()
        .take_while(|(k, x)| fits(*k, x))
        .count() as u32;
    (n >= 2 && whole(names, m0.reg.index, width, n).is_some()).then_some(n)
}
