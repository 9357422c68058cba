//! The rounding bound of every value a shader writes, derived from its own
//! arithmetic: `--verify`'s tolerance.
//!
//! Two shaders that compute the same real-valued function may still round
//! differently (a `mad` split into `mul` and `add`, a sum regrouped, `lrp`
//! expanded). Each computed value `x` then lies within a bound `E` of the
//! exact value of the function; two programs agree up to `E₁ + E₂`. The
//! bound of each value is computed by running a *bound shader* in the
//! emulator on the same draw: the original instructions (so flow control,
//! selections and texture reads see the same values), and beside every
//! value-writing instruction a few more that write, into a shadow register,
//! a first-order forward error bound of its result (`u` = 2⁻²⁴, the unit
//! roundoff of an f32 operation rounded to nearest; `|x|` the value's
//! magnitude, `e` an operand's bound):
//!
//! * inputs, constants, literals: `e = 0` (both shaders read the same bits);
//! * `add`: `e_a + e_b + u·|d|` (the two operands' errors, one rounding);
//! * `mul`: `|a|·e_b + |b|·e_a + e_a·e_b + u·|d|`;
//! * `mad` (two roundings, the emulator's unfused `mad`):
//!   `|a|·e_b + |b|·e_a + e_a·e_b + e_c + 2u·(|a|·|b| + |c|)`;
//! * `dp2add`/`dp3`/`dp4` of n products summed in any order:
//!   `Σ(|aᵢ|·e_bᵢ + |bᵢ|·e_aᵢ + e_aᵢ·e_bᵢ) + (n+1)·u·Σ|aᵢ|·|bᵢ|` (γₙ ≤ (n+1)·u
//!   is the classical bound of a sum of n products, Higham §3.1, with one u
//!   to spare for `dp2add`'s third term);
//! * `lrp` (`a·b + (1−a)·c` as written): the product rule on both terms
//!   plus `4u·(|a|·|b| + (1+|a|)·|c|)` for its four roundings;
//! * `min`/`max`/`mov`/`_sat`/`abs`: 1-Lipschitz, `max(e_a, e_b)` or `e_a`;
//! * `cmp a, b, c`: when `|a| > e_a` the exact `a` has the computed sign and
//!   the selected operand's bound holds; otherwise either may be the exact
//!   one, and `e_b + e_c + |b − c|` holds;
//! * `rcp`, `rsq` (relative input error δ = `e_a/|a|` < 1):
//!   `|d|·δ/(1−δ)` (since `(1−δ)^(−1)−1` and `(1−δ)^(−½)−1` are both at most
//!   `δ/(1−δ)`), plus `u·|d|` (`rcp`) or `2u·|d|` (`rsq`, a square root and a
//!   division);
//! * `exp` (`2^a`): `|d|·(2^e_a − 1)`, bounded by `|d|·e_a` for `e_a ≤ 1`
//!   (2^e − 1 is convex and equals e at 0 and 1) and `|d|·2^e_a` above, plus
//!   `2u·|d|` (libm's `exp2f`, within one ulp);
//! * `log` (`log2|a|`): `−log2(1−δ) ≤ δ/((1−δ)·ln 2)` plus `2u·|d|` (fdlibm's
//!   `log2f`, within one ulp, the emulator's tests);
//! * `pow` (`|a|^b = 2^(b·log2|a|)`): the `log` bound `e_L`, then the
//!   product's `e_P = |b|·e_L + |L|·e_b + e_L·e_b`, then the `exp` bound;
//! * `nrm`: `‖x/‖x‖ − y/‖y‖‖ ≤ 2‖x − y‖/‖x‖`, with `‖x − y‖ ≤ Σ eᵢ`, plus
//!   `6u` for the emulator's dot, `rsq` and product;
//! * `expp`, `logp` (vertex shaders): the `exp` and `log` rules. Both
//!   shaders' are full-precision `exp`/`log` in the emulator (which
//!   computes the partial-precision instructions in full, as Microsoft's
//!   `expp`/`logp` pages allow), and the compiler writes the decompiled
//!   `exp2`/`log2` as `exp`/`log`;
//! * `dst` (`(1, a.y·b.y, a.z, b.w)`): 0, the `mul` rule, `e_az`, `e_bw`;
//! * `lit` (`(1, max(a.x, 0), a.x > 0 ∧ a.y > 0 ? a.y^w : 0, 1)` with `w`
//!   the clamp of `a.w` to ±127.9961): 0 for x and w, `e_ax` for y
//!   (`max(·, 0)` is 1-Lipschitz); for z the `pow` rule with `|a.w|` and
//!   `e_aw` (the clamp is 1-Lipschitz and shrinks) where `a.x` and `a.y`
//!   are farther than their bounds from 0 and positive, 0 where one is
//!   farther than its bound below 0 (or exactly 0 with no bound), and
//!   unbounded where a condition could go either way. The compiler writes
//!   the decompiled `lit(x, y, w)` as `lit` again (the corpus's `lit` shaders);
//! * `m4x4`, `m4x3`, `m3x4`, `m3x3`, `m3x2`: row `k` is a `dp4` (`dp3`) of
//!   the vector with the `k`-th register of the matrix, so each row takes
//!   the dot product's rule; the compiler writes them back as `dp4`s
//!   (`mul`), which take the same rule;
//! * `sincos`: both functions are 1-Lipschitz: `e_a + 2u`;
//! * `frc`: `e_a` when `a` is farther than `e_a` from every integer (no jump
//!   in between), 1 otherwise (both results lie in [0, 1));
//! * texture reads: 0 when the coordinates (and, in the quad, the
//!   neighbours' coordinates that make the level of detail) carry no error,
//!   since both shaders then sample at the same bits; unbounded otherwise
//!   (vertex shaders' `texldl`: 0 at exact coordinates and level, no quad);
//! * `slt`/`sge` (vertex shaders; 0 or 1): 0 unless `|a − b| ≤ e_a + e_b`
//!   (and that bound is not 0), where the other shader may have chosen the
//!   other value: 1; `sgn` (−1, 0 or 1): 0 unless `|a| ≤ e_a`, then 2;
//! * `dsx`/`dsy`: `u·|d|` when the quad's operand carries no error,
//!   unbounded otherwise;
//! * a branch (`if_comp`, `break_comp`), `setp` or `texkill` whose operands
//!   lie within their bounds of the threshold could go either way in the
//!   other shader: every output of that pixel is then unbounded.
//! * any other instruction: unbounded.
//!
//! "Unbounded" is [`UNBOUNDED`] (2¹⁰⁰), a value no difference is compared
//! with: a differing value whose bound reaches it is not explained (so a
//! true bound that large fails too). The rules hold for normal results: a
//! product that underflows below 2⁻¹²⁶ errs by up to 2⁻¹⁵⁰ absolutely, not
//! `u·|d|` (a product rounded to 0 is taken as exact), and the bound's own
//! `u·|d|` is subnormal, so imprecise, for `|d|` below about 2⁻¹⁰². Both
//! make the bound smaller, so a difference there fails rather than passes. The
//! bound shader computes its own arithmetic in f32, every step a sum or
//! product of non-negative values (each rounding relative error ≤ u), so
//! along a chain of N ≤ 2¹⁴ operations the computed bound is within a
//! factor (1+u)ᴺ < 1 + 2⁻¹⁰ of the exact one: [`SLACK`] covers it.
//!
//! The registers: the original's temporaries keep their numbers, outputs
//! become temporaries from 32 on (a pixel shader's `oC0`–`oC3` and `oDepth`
//! 32–36; a vertex shader's by their row in the vertex stage's output
//! block, 32–56), each value register `t` has its bound in `60 + t`, and
//! 120–124 are scratch; both emulators run temporaries up to 127 for this
//! (and the vertex stage runs `cmp` for it). Three free constant registers
//! (from c223 down, read and defined by neither shader) hold the
//! literals. A vertex shader that reads constants at a run-time index
//! (`c[a0.x + n]`) could read those three: its verification's draws hold
//! the same literals at those registers ([`literals`]), so the original,
//! the recompiled shader and both bound shaders read the same values
//! wherever the index lands. One that writes `o[aL]` gets no bound shader
//! (the output has no shadow register): its verification stays bit for
//! bit.
//!
//! The same derivation holds for vertex shaders, which compute in the same
//! f32 arithmetic in the emulator (`emu::vertex` shares `emu::math`); only
//! the quad is missing. Register 125 is the `lit` rule's scratch.

use crate::core::emu::vertex::output_row;
use crate::core::ir::{
    Dst, Info, Instruction, Origin, Program, Reg, Shader, Slots, Src, SrcMod, Swizzle, WriteMask,
};
use crate::core::isa::{Class, Opcode, RegFile};
use std::collections::BTreeSet;

/// 2⁻²⁴: the unit roundoff of an f32 operation.
const U: f32 = 1.0 / 16_777_216.0;

/// A bound that explains nothing: 2¹⁰⁰.
pub const UNBOUNDED: f32 = 1.267_650_6e30;

/// The factor the bound shader's own rounding needs (see the module text).
pub const SLACK: f32 = 1.0 + 1.0 / 1024.0;

const OUT_BASE: u32 = 32;
const ERR_BASE: u32 = 60;
const RES: u32 = 120;
const ERR: u32 = 121;
const T: u32 = 122;
const T2: u32 = 123;
const POISON: u32 = 124;
const SCRATCH: u32 = 125;

/// The literal registers: `k[0]` = (0, 1, 2, UNBOUNDED), `k[1]` = (u, 2u,
/// 3u, 4u), `k[2]` = (5u, 6u, 1/ln 2 rounded up, 0).
struct K([u32; 3]);

fn temp(index: u32) -> Reg {
    Reg {
        file: RegFile::Temp,
        index,
    }
}

fn src(reg: Reg, swizzle: Swizzle) -> Src {
    Src {
        reg,
        relative: None,
        swizzle,
        modifier: SrcMod::None,
    }
}

fn abs(s: &Src) -> Src {
    Src {
        modifier: SrcMod::Abs,
        ..*s
    }
}

fn neg(s: Src) -> Src {
    let modifier = match s.modifier {
        SrcMod::None => SrcMod::Neg,
        SrcMod::Neg => SrcMod::None,
        SrcMod::Abs => SrcMod::NegAbs,
        SrcMod::NegAbs | SrcMod::Not => SrcMod::Abs,
    };
    Src { modifier, ..s }
}

/// Scratch register `r` read at component `c` for every lane.
fn at(r: u32, c: u8) -> Src {
    src(temp(r), Swizzle::replicate(c))
}

/// Scratch register `r` read lane for lane.
fn lane(r: u32) -> Src {
    src(temp(r), Swizzle::IDENTITY)
}

/// The register a value of the original lives in inside the bound shader
/// (a vertex output by its row in the vertex stage's output block, 0–24).
fn value_reg(reg: Reg) -> Option<u32> {
    match reg.file {
        RegFile::Temp => Some(reg.index),
        RegFile::ColorOut => Some(OUT_BASE + reg.index),
        RegFile::DepthOut => Some(OUT_BASE + 4),
        f => output_row(f, reg.index).map(|r| OUT_BASE + r as u32),
    }
}

/// Builds the bound shader's instruction list.
struct Builder {
    k: K,
    /// A vertex shader's: no quads (texture reads at exact coordinates
    /// only, no gradients).
    vertex: bool,
    out: Vec<Instruction>,
    slots: Vec<Slots>,
}

impl Builder {
    fn konst(&self, row: usize, c: u8) -> Src {
        src(
            Reg {
                file: RegFile::Const,
                index: self.k.0[row],
            },
            Swizzle::replicate(c),
        )
    }

    fn zero(&self) -> Src {
        self.konst(0, 0)
    }

    fn u(&self, n: u8) -> Src {
        match n {
            1..=4 => self.konst(1, n - 1),
            5 | 6 => self.konst(2, n - 5),
            _ => self.konst(0, 3),
        }
    }

    /// The bound of source `s` (0 for anything but a temporary).
    fn err(&self, s: &Src) -> Src {
        match s.reg.file {
            RegFile::Temp if s.relative.is_none() => src(temp(ERR_BASE + s.reg.index), s.swizzle),
            _ => self.zero(),
        }
    }

    fn emit(&mut self, op: Opcode, dst: u32, mask: WriteMask, src: Vec<Src>) {
        self.out.push(Instruction {
            op,
            sat: false,
            pp: false,
            centroid: false,
            compare: None,
            predicate: None,
            dst: Some(Dst {
                reg: temp(dst),
                relative: None,
                mask,
            }),
            src,
            origin: Origin::default(),
        });
        self.slots.push(Slots::default());
    }

    fn copy(&mut self, x: Instruction, slots: Slots) {
        self.out.push(x);
        self.slots.push(slots);
    }

    /// `POISON.x = max(POISON.x, UNBOUNDED)` where the value in `T2.x`
    /// with its bound in `T2.y` may lie on either side of 0.
    fn decision(&mut self) {
        let x = WriteMask(1);
        self.emit(Opcode::Add, T, x, vec![at(T2, 1), neg(abs(&at(T2, 0)))]);
        let big = self.konst(0, 3);
        self.emit(Opcode::Cmp, T, x, vec![at(T, 0), big, self.zero()]);
        self.emit(
            Opcode::Cmp,
            T,
            x,
            vec![neg(at(T2, 1)), self.zero(), at(T, 0)],
        );
        self.emit(Opcode::Max, POISON, x, vec![at(POISON, 0), at(T, 0)]);
    }

    /// A comparison of `a` with `b` at one component each.
    fn compare(&mut self, a: Src, b: Src) {
        let (ea, eb) = (self.err(&a), self.err(&b));
        self.emit(Opcode::Add, T2, WriteMask(1), vec![a, neg(b)]);
        self.emit(Opcode::Add, T2, WriteMask(2), vec![ea, eb]);
        self.decision();
    }
}

/// The component `c` of a source's swizzle, replicated.
fn pick(s: &Src, c: usize) -> Src {
    Src {
        swizzle: Swizzle::replicate(s.swizzle.0[c]),
        ..*s
    }
}

/// Three constant registers none of `shaders` defines or reads directly.
pub fn free_constants(shaders: &[&Shader]) -> Option<[u32; 3]> {
    let mut used: BTreeSet<u32> = BTreeSet::new();
    for p in shaders.iter().map(|s| s.program()) {
        used.extend(p.float_defs.iter().map(|d| d.index));
        for x in &p.instructions {
            for s in &x.src {
                if s.reg.file == RegFile::Const {
                    for r in 0..4 {
                        used.insert(s.reg.index + r);
                    }
                }
            }
        }
    }
    let free: Vec<u32> = (0..224)
        .rev()
        .filter(|r| !used.contains(r))
        .take(3)
        .collect();
    (free.len() == 3).then(|| [free[0], free[1], free[2]])
}

/// The literals a bound shader defines at the registers `k`
/// ([`free_constants`]): a vertex shader's draw sets the same values there,
/// so that a run-time index reaching one reads the same in the original
/// and its bound shader.
pub fn literals(k: [u32; 3]) -> [(u32, [f32; 4]); 3] {
    let kv = [
        [0.0, 1.0, 2.0, UNBOUNDED],
        [U, 2.0 * U, 3.0 * U, 4.0 * U],
        [5.0 * U, 6.0 * U, 1.442_695_1, 0.0],
    ];
    [0, 1, 2].map(|i| (k[i], kv[i]))
}

/// The bound shader of `shader`: its outputs are the bounds of the
/// original's outputs, pixel for pixel (vertex for vertex). `None` for a
/// shader the analysis does not cover: no free constant registers, or a
/// vertex shader that writes an output at a run-time index (`o[aL]`,
/// which has no shadow register).
pub fn bound_shader(shader: &Shader) -> Option<Shader> {
    bound_shader_at(shader, free_constants(&[shader])?)
}

/// [`bound_shader`] with its literals at the registers `k`. A vertex
/// shader that reads constants at a run-time index (`c[a0.x + n]`) may
/// reach them: its draws must hold [`literals`] there.
pub fn bound_shader_at(shader: &Shader, k: [u32; 3]) -> Option<Shader> {
    let p = shader.program();
    let vertex = p.profile.stage() == crate::core::profile::Stage::Vertex;
    let relative = |x: &Instruction| x.dst.is_some_and(|d| d.relative.is_some());
    if vertex && p.instructions.iter().any(relative) {
        return None;
    }
    let k = K(k);
    let mut b = Builder {
        k,
        vertex,
        out: Vec::new(),
        slots: Vec::new(),
    };
    let info = shader.info();
    let main_end = info.main_end as usize;
    let outputs: BTreeSet<(u32, Reg)> = p
        .instructions
        .iter()
        .filter_map(|x| x.dst)
        .filter(|d| d.reg.file != RegFile::Temp)
        .filter_map(|d| value_reg(d.reg).map(|v| (v, d.reg)))
        .collect();
    for (i, x) in p.instructions.iter().enumerate() {
        let slots = info.slots.get(i).copied().unwrap_or_default();
        let ends_main = i == main_end || (x.op == Opcode::Ret && i < main_end);
        if ends_main {
            finish(&mut b, &outputs);
        }
        instruction(&mut b, x, slots)?;
    }
    if main_end >= p.instructions.len() {
        finish(&mut b, &outputs);
    }
    let mut program = Program {
        instructions: b.out,
        ..p.clone()
    };
    for (index, value) in literals(b.k.0) {
        program.float_defs.push(crate::core::ir::FloatDef {
            index,
            value,
            origin: Origin::default(),
        });
    }
    let info = structure(&program, b.slots)?;
    Some(Shader::new_validated(program, info))
}

/// Writes each output's bound (plus the poison of uncertain decisions):
/// `outputs` holds each output register with its shadow register.
fn finish(b: &mut Builder, outputs: &BTreeSet<(u32, Reg)>) {
    for &(v, reg) in outputs {
        let mask = if reg.file == RegFile::DepthOut {
            WriteMask(1)
        } else {
            WriteMask::ALL
        };
        b.out.push(Instruction {
            op: Opcode::Add,
            sat: false,
            pp: false,
            centroid: false,
            compare: None,
            predicate: None,
            dst: Some(Dst {
                reg,
                relative: None,
                mask,
            }),
            src: vec![lane(ERR_BASE + v), at(POISON, 0)],
            origin: Origin::default(),
        });
        b.slots.push(Slots::default());
    }
}

/// The block structure of the bound shader (what validation finds).
fn structure(p: &Program, slots: Vec<Slots>) -> Option<Info> {
    let ins = &p.instructions;
    let mut matching = vec![None; ins.len()];
    let mut labels = std::collections::BTreeMap::new();
    let mut stack: Vec<usize> = Vec::new();
    for (i, x) in ins.iter().enumerate() {
        match x.op {
            Opcode::Rep | Opcode::Loop | Opcode::If | Opcode::Ifc => stack.push(i),
            Opcode::Else => {
                let open = stack.pop()?;
                matching[open] = Some(i as u32);
                stack.push(i);
            }
            Opcode::EndIf | Opcode::EndRep | Opcode::EndLoop => {
                let open = stack.pop()?;
                matching[open] = Some(i as u32);
                if x.op != Opcode::EndIf {
                    matching[i] = Some(open as u32);
                }
            }
            Opcode::Label => {
                labels.insert(x.src.first()?.reg.index, i as u32);
            }
            _ => {}
        }
    }
    let main_end = ins
        .iter()
        .position(|x| x.op == Opcode::Label)
        .unwrap_or(ins.len()) as u32;
    stack.is_empty().then_some(Info {
        matching,
        labels,
        main_end,
        slots,
    })
}

/// One instruction of the original and its bound.
fn instruction(b: &mut Builder, x: &Instruction, slots: Slots) -> Option<()> {
    match x.op {
        Opcode::TexKill => {
            let d = x.dst?;
            let s = Src {
                reg: d.reg,
                relative: None,
                swizzle: Swizzle::IDENTITY,
                modifier: SrcMod::None,
            };
            for c in (0..4).filter(|&c| d.mask.has(c)) {
                let (v, e) = (pick(&s, c), b.err(&pick(&s, c)));
                b.emit(Opcode::Mov, T2, WriteMask(1), vec![v]);
                b.emit(Opcode::Mov, T2, WriteMask(2), vec![e]);
                b.decision();
            }
            return Some(());
        }
        Opcode::Ifc | Opcode::BreakC => {
            b.compare(x.src.first()?.to_owned(), x.src.get(1)?.to_owned());
            b.copy(x.clone(), slots);
            return Some(());
        }
        Opcode::Setp => {
            let d = x.dst?;
            for c in (0..4).filter(|&c| d.mask.has(c)) {
                b.compare(pick(x.src.first()?, c), pick(x.src.get(1)?, c));
            }
            b.copy(x.clone(), slots);
            return Some(());
        }
        _ => {}
    }
    let class = x.op.info().class;
    let Some(d) = x
        .dst
        .filter(|_| matches!(class, Class::Arithmetic | Class::Texture))
    else {
        b.copy(x.clone(), slots);
        return Some(());
    };
    let Some(v) = value_reg(d.reg).filter(|_| d.relative.is_none()) else {
        // an address register or a vertex output: nothing the pixel outputs read
        b.copy(x.clone(), slots);
        return Some(());
    };
    let mut res = x.clone();
    res.predicate = None;
    res.dst = Some(Dst {
        reg: temp(RES),
        relative: None,
        mask: d.mask,
    });
    b.copy(res, slots);
    let mask = d.mask;
    error_of(b, x, mask);
    let big = b.konst(0, 3);
    let mut keep = Instruction {
        op: Opcode::Min,
        sat: false,
        pp: false,
        centroid: false,
        compare: None,
        predicate: x.predicate,
        dst: Some(Dst {
            reg: temp(ERR_BASE + v),
            relative: None,
            mask,
        }),
        src: vec![lane(ERR), big],
        origin: Origin::default(),
    };
    b.copy(keep.clone(), Slots::default());
    keep.op = Opcode::Mov;
    keep.dst = Some(Dst {
        reg: temp(v),
        relative: None,
        mask,
    });
    keep.src = vec![lane(RES)];
    b.copy(keep, Slots::default());
    Some(())
}

/// `ERR` (at the lanes of `m`) = the bound of `x`'s result, whose value
/// is in `RES`.
fn error_of(b: &mut Builder, x: &Instruction, m: WriteMask) {
    use Opcode::*;
    let s = |k: usize| x.src.get(k).copied().unwrap_or(Src::plain(temp(RES)));
    let (mut a, mut bb, c) = (s(0), s(1), s(2));
    let mut d = abs(&lane(RES));
    // A scalar instruction reads its sources' first swizzle component and
    // writes one value to every lane: its bound is worked out at x and then
    // copied to the lanes written.
    let scalar = matches!(x.op, Rcp | Rsq | Log | Logp | Exp | Expp | Pow | SinCos);
    let wide = m;
    let m = if scalar {
        a = pick(&a, 0);
        bb = pick(&bb, 0);
        d = abs(&at(RES, (0..4).find(|&c| wide.has(c)).unwrap_or(0) as u8));
        WriteMask(1)
    } else {
        m
    };
    let (ea, eb, ec) = (b.err(&a), b.err(&bb), b.err(&c));
    let (e, t, t2) = (ERR, T, T2);
    match x.op {
        Mov | Abs => b.emit(Mov, e, m, vec![ea]),
        Add => {
            b.emit(Add, e, m, vec![ea, eb]);
            b.emit(Mad, e, m, vec![d, b.u(1), lane(e)]);
        }
        Mul | Mad => {
            let third = if x.op == Mad { ec } else { b.zero() };
            b.emit(Mad, e, m, vec![ea, eb, third]);
            b.emit(Mad, e, m, vec![abs(&a), eb, lane(e)]);
            b.emit(Mad, e, m, vec![abs(&bb), ea, lane(e)]);
            if x.op == Mad {
                b.emit(Mad, t, m, vec![abs(&a), abs(&bb), abs(&c)]);
                b.emit(Mad, e, m, vec![lane(t), b.u(2), lane(e)]);
            } else {
                b.emit(Mad, e, m, vec![d, b.u(1), lane(e)]);
            }
        }
        Dp3 | Dp4 | Dp2Add => dot(b, x.op, [a, bb, c], m),
        Min | Max => b.emit(Max, e, m, vec![ea, eb]),
        Cmp => {
            b.emit(Cmp, e, m, vec![a, eb, ec]);
            b.emit(Add, t2, m, vec![bb, neg(c)]);
            b.emit(Add, t, m, vec![eb, ec]);
            b.emit(Add, t, m, vec![lane(t), abs(&lane(t2))]);
            b.emit(Add, t2, m, vec![ea, neg(abs(&a))]);
            b.emit(Cmp, t, m, vec![lane(t2), lane(t), lane(e)]);
            b.emit(Cmp, e, m, vec![neg(ea), lane(e), lane(t)]);
        }
        Rcp | Rsq | Log | Logp => relative(b, x.op, a, d, m),
        Exp | Expp => {
            b.emit(Mov, t, m, vec![ea]);
            exp_factor(b, m);
            b.emit(Mul, e, m, vec![d, lane(t)]);
            b.emit(Mad, e, m, vec![d, b.u(2), lane(e)]);
        }
        Pow => pow(b, a, bb, d, m),
        Dst => dst(b, a, bb, m),
        Lit => lit(b, a, m),
        M4x4 | M4x3 | M3x4 | M3x3 | M3x2 => matrix(b, x.op, a, bb, m),
        Lrp => lrp(b, [a, bb, c], m),
        Frc => {
            // distance to the nearest integer, less e_a: > 0 means no jump
            b.emit(Add, t, m, vec![b.konst(0, 1), neg(lane(RES))]);
            b.emit(Min, t, m, vec![lane(t), lane(RES)]);
            b.emit(Add, t, m, vec![lane(t), neg(ea)]);
            b.emit(Cmp, e, m, vec![neg(lane(t)), b.konst(0, 1), ea]);
            b.emit(Cmp, e, m, vec![neg(ea), b.zero(), lane(e)]);
        }
        Nrm => {
            let sum = if m.has(3) { Dp4 } else { Dp3 };
            b.emit(sum, t, m, vec![ea, b.konst(0, 1)]);
            b.emit(sum, t2, m, vec![a, a]);
            let f = (0..4).find(|&c| m.has(c)).unwrap_or(0) as u8;
            b.emit(Rsq, t2, m, vec![at(t2, f)]);
            b.emit(Mul, t, m, vec![lane(t), lane(t2)]);
            b.emit(Mad, e, m, vec![lane(t), b.konst(0, 2), b.u(6)]);
        }
        SinCos => b.emit(Add, e, m, vec![ea, b.u(2)]),
        TexLd | TexLdP | TexLdB | TexLdL | TexLdD => {
            // the coordinates' (and gradients') bounds, summed over the quad
            b.emit(Dp4, t, WriteMask(1), vec![ea, b.konst(0, 1)]);
            for g in [2, 3] {
                if let Some(s) = x.src.get(g) {
                    let eg = b.err(s);
                    b.emit(Dp4, t2, WriteMask(1), vec![eg, b.konst(0, 1)]);
                    b.emit(Add, t, WriteMask(1), vec![at(t, 0), at(t2, 0)]);
                }
            }
            if b.vertex {
                // texldl at explicit levels: no quad, no gradients
                let big = b.konst(0, 3);
                b.emit(Cmp, e, m, vec![neg(at(t, 0)), b.zero(), big]);
            } else {
                quad_exact(b, m, true, vec![]);
            }
        }
        Slt | Sge => {
            // 0 or 1: exact unless a and b lie within their bounds of
            // each other, where the other shader may choose the other one
            b.emit(Add, t2, m, vec![a, neg(bb)]);
            b.emit(Add, t, m, vec![ea, eb]);
            uncertain(b, m, 1);
        }
        Sgn => {
            // −1, 0 or 1: exact unless |a| ≤ e_a
            b.emit(Mov, t2, m, vec![a]);
            b.emit(Mov, t, m, vec![ea]);
            uncertain(b, m, 2);
        }
        Dsx | Dsy => {
            b.emit(Mov, t, m, vec![ea]);
            quad_exact(b, m, false, vec![d, b.u(1)]);
        }
        _ => {
            let big = b.konst(0, 3);
            b.emit(Mov, e, m, vec![big]);
        }
    }
    if scalar {
        b.emit(Mov, e, wide, vec![at(e, 0)]);
    }
}

/// `ERR` (lanes of `m`) = `jump` where the value in `T2` lies within its
/// bound in `T` of 0 (and that bound is not 0), 0 elsewhere: the bound of
/// a step function whose values are `jump` apart.
fn uncertain(b: &mut Builder, m: WriteMask, jump: u8) {
    use Opcode::*;
    b.emit(Add, T2, m, vec![lane(T), neg(abs(&lane(T2)))]);
    b.emit(Cmp, ERR, m, vec![lane(T2), b.konst(0, jump), b.zero()]);
    b.emit(Cmp, ERR, m, vec![neg(lane(T)), b.zero(), lane(ERR)]);
}

/// The bound of a dot product (`dp2add`'s third term included).
fn dot(b: &mut Builder, op: Opcode, [a, bb, c]: [Src; 3], m: WriteMask) {
    use Opcode::*;
    let (ea, eb, ec) = (b.err(&a), b.err(&bb), b.err(&c));
    let (e, t) = (ERR, T);
    let (n, third) = match op {
        Dp3 => (4, vec![]),
        Dp4 => (5, vec![]),
        _ => (3, vec![b.zero()]),
    };
    let with = |v: Vec<Src>| v.into_iter().chain(third.clone()).collect::<Vec<_>>();
    b.emit(op, e, m, with(vec![ea, eb]));
    b.emit(op, t, m, with(vec![abs(&a), eb]));
    b.emit(Add, e, m, vec![lane(e), lane(t)]);
    b.emit(op, t, m, with(vec![abs(&bb), ea]));
    b.emit(Add, e, m, vec![lane(e), lane(t)]);
    b.emit(op, t, m, with(vec![abs(&a), abs(&bb)]));
    if op == Dp2Add {
        b.emit(Add, e, m, vec![lane(e), ec]);
        b.emit(Add, t, m, vec![lane(t), abs(&c)]);
    }
    b.emit(Mad, e, m, vec![lane(t), b.u(n), lane(e)]);
}

/// The bound of `lrp` as the emulator evaluates it.
fn lrp(b: &mut Builder, [a, bb, c]: [Src; 3], m: WriteMask) {
    use Opcode::*;
    let (ea, eb, ec) = (b.err(&a), b.err(&bb), b.err(&c));
    let (e, t, t2) = (ERR, T, T2);
    b.emit(Mul, e, m, vec![ea, eb]);
    b.emit(Mad, e, m, vec![abs(&a), eb, lane(e)]);
    b.emit(Mad, e, m, vec![abs(&bb), ea, lane(e)]);
    b.emit(Mad, e, m, vec![ea, ec, lane(e)]);
    b.emit(Mad, e, m, vec![abs(&c), ea, lane(e)]);
    b.emit(Add, t, m, vec![b.konst(0, 1), neg(a)]);
    b.emit(Mad, e, m, vec![abs(&lane(t)), ec, lane(e)]);
    b.emit(Add, t2, m, vec![b.konst(0, 1), abs(&a)]);
    b.emit(Mul, t2, m, vec![lane(t2), abs(&c)]);
    b.emit(Mad, t2, m, vec![abs(&a), abs(&bb), lane(t2)]);
    b.emit(Mad, e, m, vec![lane(t2), b.u(4), lane(e)]);
}

/// `ERR` (lanes of `m`) = `u·|d|` (the product of the two `tail`
/// sources; 0 for an empty `tail`) where the bound in `T` and its
/// neighbours' in the quad are 0, unbounded elsewhere. `scalar`: the bound
/// is the one value `T.x` for every lane.
fn quad_exact(b: &mut Builder, m: WriteMask, scalar: bool, tail: Vec<Src>) {
    use Opcode::*;
    let (mt, read) = if scalar {
        (WriteMask(1), at(T, 0))
    } else {
        (m, lane(T))
    };
    let read2 = Src {
        reg: temp(T2),
        ..read
    };
    b.emit(Dsx, T2, mt, vec![read]);
    b.emit(Add, T, mt, vec![abs(&read), abs(&read2)]);
    b.emit(Dsy, T2, mt, vec![read]);
    b.emit(Add, T, mt, vec![read, abs(&read2)]);
    let exact = if tail.len() == 2 {
        b.emit(Mul, ERR, m, tail);
        lane(ERR)
    } else {
        b.zero()
    };
    let big = b.konst(0, 3);
    b.emit(Cmp, ERR, m, vec![neg(read), exact, big]);
}

/// `T.x` = a bound of `2^T.x − 1` for `T.x` ≥ 0: `T.x` up to 1, `2^T.x`
/// above (`m` is x: the scalar instructions' lane).
fn exp_factor(b: &mut Builder, m: WriteMask) {
    use Opcode::*;
    b.emit(Exp, T2, m, vec![at(T, 0)]);
    b.emit(Add, ERR, m, vec![b.konst(0, 1), neg(lane(T))]);
    b.emit(Cmp, T, m, vec![lane(ERR), lane(T), lane(T2)]);
}

/// The bound of `rcp`, `rsq`, `log` and `logp` from the relative error of
/// their operand (see the module text); `d` is the result's magnitude.
fn relative(b: &mut Builder, op: Opcode, a: Src, d: Src, m: WriteMask) {
    use Opcode::*;
    let (ea, e, t) = (b.err(&a), ERR, T);
    // δ/(1−δ) = e_a/(|a| − e_a); negative (→ unbounded) when e_a > |a|
    b.emit(Add, t, m, vec![abs(&a), neg(ea)]);
    b.emit(Rcp, t, m, vec![lane(t)]);
    b.emit(Mul, t, m, vec![ea, lane(t)]);
    if matches!(op, Log | Logp) {
        b.emit(Mul, e, m, vec![lane(t), b.konst(2, 2)]);
        b.emit(Mad, e, m, vec![d, b.u(2), lane(e)]);
    } else {
        b.emit(Mul, e, m, vec![lane(t), d]);
        let n = if op == Rcp { 1 } else { 2 };
        b.emit(Mad, e, m, vec![d, b.u(n), lane(e)]);
    }
    let big = b.konst(0, 3);
    b.emit(Cmp, e, m, vec![lane(t), lane(e), big]);
}

/// The bound of `dst a, b` = (1, a.y·b.y, a.z, b.w): 0, the product rule
/// with one rounding, and the two copied operands' bounds.
fn dst(b: &mut Builder, a: Src, bb: Src, m: WriteMask) {
    use Opcode::*;
    let (ea, eb) = (b.err(&a), b.err(&bb));
    let lanes = |k: u8| WriteMask(m.0 & k);
    let (x, y, z, w) = (lanes(1), lanes(2), lanes(4), lanes(8));
    let e = ERR;
    if x.0 != 0 {
        b.emit(Mov, e, x, vec![b.zero()]);
    }
    if y.0 != 0 {
        b.emit(Mad, e, y, vec![ea, eb, b.zero()]);
        b.emit(Mad, e, y, vec![abs(&a), eb, lane(e)]);
        b.emit(Mad, e, y, vec![abs(&bb), ea, lane(e)]);
        b.emit(Mad, e, y, vec![abs(&lane(RES)), b.u(1), lane(e)]);
    }
    if z.0 != 0 {
        b.emit(Mov, e, z, vec![ea]);
    }
    if w.0 != 0 {
        b.emit(Mov, e, w, vec![eb]);
    }
}

/// The bound of `lit a` = (1, max(a.x, 0), a.x > 0 && a.y > 0 ?
/// a.y^clamp(a.w) : 0, 1): 0 for x and w; `e_ax` for y (`max(·, 0)` is
/// 1-Lipschitz); for z the `pow` rule where both conditions are certain
/// (each operand farther than its bound from 0, or exact), 0 where the
/// result is 0 for certain, and unbounded where a condition could go
/// either way (the clamp of the exponent to ±127.9961 is 1-Lipschitz and
/// only shrinks it, so `|a.w|` and `e_aw` bound the exponent and its error).
fn lit(b: &mut Builder, a: Src, m: WriteMask) {
    use Opcode::*;
    let (sx, sy, sw) = (pick(&a, 0), pick(&a, 1), pick(&a, 3));
    let (ex, ey) = (b.err(&sx), b.err(&sy));
    let one = WriteMask(1);
    if m.has(2) {
        pow(b, sy, sw, abs(&at(RES, 2)), one);
        b.emit(Mov, SCRATCH, one, vec![at(ERR, 0)]);
        // z's bound where certainly positive (min(a.x − e, a.y − e) > 0)
        b.emit(Add, T, one, vec![sx, neg(ex)]);
        b.emit(Add, T2, one, vec![sy, neg(ey)]);
        b.emit(Min, T, one, vec![at(T, 0), at(T2, 0)]);
        b.emit(
            Cmp,
            SCRATCH,
            one,
            vec![neg(at(T, 0)), b.zero(), at(SCRATCH, 0)],
        );
        for (s, e) in [(sx, ex), (sy, ey)] {
            b.emit(Mov, T2, one, vec![s]);
            b.emit(Mov, T, one, vec![e]);
            uncertain(b, one, 3);
            b.emit(Max, SCRATCH, one, vec![at(SCRATCH, 0), at(ERR, 0)]);
        }
        b.emit(Mov, ERR, WriteMask(4), vec![at(SCRATCH, 0)]);
    }
    let ends = WriteMask(m.0 & 0b1001);
    if ends.0 != 0 {
        b.emit(Mov, ERR, ends, vec![b.zero()]);
    }
    if m.has(1) {
        b.emit(Mov, ERR, WriteMask(2), vec![ex]);
    }
}

/// The bound of `m4x4` and its kind: row `k` of the result is a `dp4`
/// (`dp3` for `m3x#`) of `a` with the register `k` after `rows`, and gets
/// the dot product's rule. The compiler writes the same rows as `dp4`s
/// (`mul(M, v)`: `skin.vsh`'s `m4x4` comes back as four), which get the
/// same rule each.
fn matrix(b: &mut Builder, op: Opcode, a: Src, rows: Src, m: WriteMask) {
    let (n, dims) = op.matrix_shape().unwrap_or((4, 4));
    let each = if dims == 4 { Opcode::Dp4 } else { Opcode::Dp3 };
    for k in 0..n {
        let lane_k = WriteMask(m.0 & (1 << k));
        if lane_k.0 == 0 {
            continue;
        }
        let row = Src {
            reg: Reg {
                index: rows.reg.index + k,
                ..rows.reg
            },
            ..rows
        };
        dot(b, each, [a, row, b.zero()], lane_k);
    }
}

/// The bound of `pow a, b` (see the module text); `d` is the result's
/// magnitude.
fn pow(b: &mut Builder, a: Src, e: Src, d: Src, m: WriteMask) {
    use Opcode::*;
    let (ea, eb) = (b.err(&a), b.err(&e));
    // e_L = e_a / (|a| − e_a) / ln 2, unbounded when e_a ≥ |a|
    b.emit(Add, T, m, vec![abs(&a), neg(ea)]);
    b.emit(Rcp, T2, m, vec![lane(T)]);
    b.emit(Mul, T2, m, vec![ea, lane(T2)]);
    b.emit(Mul, T2, m, vec![lane(T2), b.konst(2, 2)]);
    let big = b.konst(0, 3);
    b.emit(Cmp, T2, m, vec![neg(lane(T)), big, lane(T2)]);
    b.emit(Cmp, T2, m, vec![neg(ea), b.zero(), lane(T2)]);
    // e_P = |b|·e_L + |L|·e_b + e_L·e_b
    b.emit(Mul, ERR, m, vec![lane(T2), eb]);
    b.emit(Mad, ERR, m, vec![abs(&e), lane(T2), lane(ERR)]);
    b.emit(Log, T, m, vec![a]);
    b.emit(Mad, T, m, vec![abs(&lane(T)), eb, lane(ERR)]);
    exp_factor(b, m);
    b.emit(Mul, ERR, m, vec![d, lane(T)]);
    b.emit(Mad, ERR, m, vec![d, b.u(2), lane(ERR)]);
}
