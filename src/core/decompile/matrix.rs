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
//! `mul`, writes the same instructions again. The dot products may name
//! the matrix first (`dp4 r1.x, c0, v0`, the compiler's spelling of
//! `mul(M, v)` with a row-major `M`).
//!
//! The other products are sums of the matrix's registers weighted by the
//! vector's components: `mul(v, M)` with a row-major `M` (and `mul(M, v)`
//! with a column-major one) is `mul r, M₁, v.y`, `mad r, v.x, M₀, r`,
//! `mad r, v.z, M₂, r`, `mad d, v.w, M₃, r` — one `mul` and a `mad` per
//! further register, in any order and with either operand first. Where
//! such a chain reads each register of a declared matrix once, weighted by
//! one vector's matching component, and its running sum is read by nothing
//! after it, it is read as one matrix instruction marked [`CHAIN`] and
//! written as the `mul`. A chain of products is a chain of these: each
//! `mul(v, A)` a value the next `mul` reads (`mul(mul(v, A), B)`).
//!
//! Either form, the same products are summed, so the compiler writes the
//! same instructions again (in its own order of the terms, which for a
//! hand-written chain may regroup the sum: `--verify` then measures it).

use super::names::{FloatName, Names};
use crate::core::ir::{Dst, Instruction, Src, SrcMod, Swizzle, WriteMask};
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
        if let Some(c) = chain(&ins, a, names) {
            let op = if c.n == 4 { Opcode::M4x4 } else { Opcode::M3x3 };
            let last = a + c.n as usize - 1;
            ins[a] = Instruction {
                op,
                sat: ins[last].sat,
                dst: Some(c.dst),
                src: vec![c.vector, c.matrix],
                ..ins[a].clone()
            };
            for x in &mut ins[a + 1..=last] {
                x.op = Opcode::Nop;
                x.dst = None;
                x.src.clear();
            }
            a = last + 1;
            continue;
        }
        if let Some(n) = run(&ins, a, names) {
            let width = if ins[a].op == Opcode::Dp4 { 4 } else { 3 };
            if let Some(op) = shape(width, n) {
                ins[a].op = op;
                if let Some(d) = ins[a].dst.as_mut() {
                    d.mask = WriteMask((1u8 << n) - 1);
                }
                if let Some((v, m)) = vector_and_matrix(&ins[a]) {
                    ins[a].src = vec![v, m];
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
    let (v, m0) = vector_and_matrix(first)?;
    if v.relative.is_some() || v.reg == d.reg {
        return None;
    }
    let fits = |k: usize, x: &Instruction| {
        let Some(xd) = x.dst else { return false };
        let Some((xv, xm)) = vector_and_matrix(x) else {
            return false;
        };
        x.op == first.op
            && !x.sat
            && x.predicate.is_none()
            && xd.reg == d.reg
            && xd.relative.is_none()
            && xd.mask.0 == 1 << k
            && xv == v
            && xm.reg.index == m0.reg.index + k as u32
            && plain_register(&xm)
    };
    let n = ins[a..]
        .iter()
        .take(4)
        .enumerate()
        .take_while(|(k, x)| fits(*k, x))
        .count() as u32;
    (n >= 2 && whole(names, m0.reg.index, width, n).is_some()).then_some(n)
}

/// The swizzle that marks a matrix instruction made of a [`chain`]: its
/// matrix operand read `.wzyx`, a swizzle the instruction set does not
/// allow there, so no shader's own matrix instruction has it.
pub(crate) const CHAIN: Swizzle = Swizzle([3, 2, 1, 0]);

/// Whether `s` is a constant register read whole: no index, modifier or
/// swizzle.
fn plain_register(s: &Src) -> bool {
    s.reg.file == RegFile::Const
        && s.relative.is_none()
        && s.modifier == SrcMod::None
        && s.swizzle == Swizzle::IDENTITY
}

/// A dot product's vector and matrix register, whichever operand the
/// matrix is (the second where both are constants).
fn vector_and_matrix(x: &Instruction) -> Option<(Src, Src)> {
    let (a, b) = (*x.src.first()?, *x.src.get(1)?);
    if b.reg.file == RegFile::Const {
        Some((a, b))
    } else if a.reg.file == RegFile::Const {
        Some((b, a))
    } else {
        None
    }
}

/// A [`chain`]: `n` registers from `matrix`, weighted by `vector`'s first
/// `n` components, summed into `dst`.
struct Chain {
    n: u32,
    vector: Src,
    matrix: Src,
    dst: Dst,
}

/// One term of a chain: the vector's register read at one component, and
/// the matrix register it weights (either operand order).
fn term(x: &Instruction) -> Option<(Src, u8, Src)> {
    let (a, b) = (*x.src.first()?, *x.src.get(1)?);
    let (v, m) = if plain_register(&b) { (a, b) } else { (b, a) };
    let one = v.swizzle.is_replicate()
        && v.modifier == SrcMod::None
        && v.relative.is_none()
        && plain_register(&m);
    one.then_some((v, v.swizzle.0[0], m))
}

/// The chain of `mul` and `mad`s at `a` that sums a whole matrix's
/// registers weighted by one vector's components (see the module text).
fn chain(ins: &[Instruction], a: usize, names: &Names) -> Option<Chain> {
    let first = &ins[a];
    let acc = first.dst?;
    let (v, _, _) = term(first)?;
    if first.op != Opcode::Mul
        || first.predicate.is_some()
        || acc.reg.file != RegFile::Temp
        || acc.relative.is_some()
        || v.reg == acc.reg
    {
        return None;
    }
    // the registers weighted by components x, y, z, w, and the last step
    let mut by = [None::<u32>; 4];
    let mut last = a;
    for (k, x) in ins.iter().enumerate().skip(a).take(4) {
        let Some((xv, c, m)) = term(x) else { break };
        let d = x.dst?;
        let adds = k == a
            || x.op == Opcode::Mad
                && x.src.get(2).is_some_and(|s| {
                    s.reg == acc.reg
                        && s.relative.is_none()
                        && s.modifier == SrcMod::None
                        && s.swizzle == Swizzle::IDENTITY
                });
        if !adds
            || x.predicate.is_some()
            || xv.reg != v.reg
            || d.mask != acc.mask
            || d.relative.is_some()
            || by[c as usize].is_some()
            || ins[last].sat
        {
            break;
        }
        by[c as usize] = Some(m.reg.index);
        last = k;
        if d.reg != acc.reg {
            break;
        }
    }
    let n = (last - a + 1) as u32;
    let base = by[0]?;
    let width = acc.mask.0.count_ones() as u8;
    let complete = (0..n as usize).all(|c| by[c] == Some(base + c as u32));
    let dst = ins[last].dst?;
    let sum_dead = dst.reg == acc.reg || dead_after(ins, last + 1, acc);
    (n >= 3
        && complete
        && acc.mask.0 == (1 << width) - 1
        && sum_dead
        && whole(names, base, width, n).is_some())
    .then(|| {
        let mut matrix = Src::plain(crate::core::ir::Reg {
            file: RegFile::Const,
            index: base,
        });
        matrix.swizzle = CHAIN;
        Chain {
            n,
            vector: Src::plain(v.reg),
            matrix,
            dst,
        }
    })
}

/// Whether nothing from `from` on reads `acc`'s register before writing
/// every component of it (flow control ends the search: read, for all it
/// knows).
fn dead_after(ins: &[Instruction], from: usize, acc: Dst) -> bool {
    let mut live = acc.mask.0;
    for y in &ins[from..] {
        if y.op.class() == crate::core::isa::Class::Flow || y.src.iter().any(|s| s.reg == acc.reg) {
            return false;
        }
        if let Some(w) = y.dst.filter(|w| w.reg == acc.reg && y.predicate.is_none()) {
            live &= !w.mask.0;
        }
        if live == 0 {
            return true;
        }
    }
    true
}
