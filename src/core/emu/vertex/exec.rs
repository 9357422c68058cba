//! One vertex through the validated IR: registers, the address register,
//! flow control with the cost model's counting rule, and each instruction's
//! vertex-shader form.

use super::{VertexDraw, VertexError};
use crate::core::emu::layered::finite_coordinate;
use crate::core::emu::math;
use crate::core::emu::sample::{Sampler, UNBOUND};
use crate::core::float_rules::{flush, FloatRules};
use crate::core::ir::{Dst, Instruction, RelIndex, Shader, Src, SrcMod};
use crate::core::isa::{Compare, Opcode, RegFile, SlotTable};

/// Rows of the output block: o0–o11, oPos, oD0–oD1, oT0–oT7, oFog, oPts.
pub const OUTPUT_ROWS: usize = 25;

/// The row of output register `file`/`index`, `None` for other files or an
/// index past the file.
pub fn output_row(file: RegFile, index: u32) -> Option<usize> {
    let i = index as usize;
    match file {
        RegFile::Output if i < 12 => Some(i),
        RegFile::PosOut => Some(12),
        RegFile::AttrOut if i < 2 => Some(13 + i),
        RegFile::TexCoordOut if i < 8 => Some(15 + i),
        RegFile::FogOut => Some(23),
        RegFile::PointSizeOut => Some(24),
        _ => None,
    }
}

/// How deep `call` may nest (vs_2_0 … vs_3_0: four levels).
const CALL_DEPTH: usize = 4;

/// What every vertex of a draw shares: the shader, its constants with the
/// `def`s applied, the samplers and the rules.
pub(super) struct State<'s, 'a> {
    shader: &'s Shader,
    consts: Vec<[f32; 4]>,
    ints: [[i32; 4]; 16],
    bools: [bool; 16],
    samplers: [Option<Sampler<'a>>; 4],
    rules: FloatRules,
    limit: u64,
}

/// Temporaries a vertex runs with: more than any profile allows (vs_3_0
/// has 32, which validation holds shaders to), for the bound shader of
/// `ps30 decompile --verify` (`jobs/decompile/bound.rs`), whose shadow
/// registers reach r127, as the pixel emulator's do.
const TEMPS: usize = 128;

/// One vertex's registers.
struct Regs {
    r: [[f32; 4]; TEMPS],
    v: [[f32; 4]; 16],
    o: [[f32; 4]; OUTPUT_ROWS],
    a0: [i32; 4],
    al: i32,
    p: [bool; 4],
}

/// An open `rep` or `loop`: its first instruction, its end, the iterations
/// left, and for `loop` the step and the `aL` of the loop around it.
struct Frame {
    start: usize,
    end: usize,
    left: i32,
    step: i32,
    outer_al: Option<i32>,
}

impl<'s, 'a> State<'s, 'a> {
    /// The shared state of a draw.
    pub(super) fn new(
        shader: &'s Shader,
        draw: &VertexDraw,
        samplers: [Option<Sampler<'a>>; 4],
    ) -> Self {
        let rules = draw.float_rules;
        let (mut consts, ints, bools) = super::effective_constants(shader, &draw.constants);
        if rules.flush_denormals() {
            consts.iter_mut().flatten().for_each(|x| *x = flush(*x));
        }
        State {
            shader,
            consts,
            ints,
            bools,
            samplers,
            rules,
            limit: draw.max_executed_per_vertex,
        }
    }

    /// Runs vertex `vertex` with inputs `v`: its output rows and executed
    /// slots. Each time an instruction's slots are charged, its entry of
    /// `runs` (by instruction index) counts one; an empty `runs` counts
    /// nothing.
    pub(super) fn run_vertex(
        &self,
        vertex: usize,
        mut v: [[f32; 4]; 16],
        runs: &mut [u64],
    ) -> Result<([[f32; 4]; OUTPUT_ROWS], u64), VertexError> {
        let mut ran = |i: usize| {
            if let Some(n) = runs.get_mut(i) {
                *n += 1;
            }
        };
        if self.rules.flush_denormals() {
            v.iter_mut().flatten().for_each(|x| *x = flush(*x));
        }
        let mut g = Regs {
            r: [[0.0; 4]; TEMPS],
            v,
            o: [[0.0; 4]; OUTPUT_ROWS],
            a0: [0; 4],
            al: 0,
            p: [false; 4],
        };
        let ins = self.shader.instructions();
        let info = self.shader.info();
        let mut pc = 0usize;
        let mut calls: Vec<usize> = Vec::new();
        let mut frames: Vec<Frame> = Vec::new();
        let mut executed = 0u64;
        while pc < ins.len() && !(pc == info.main_end as usize && calls.is_empty()) {
            let x = &ins[pc];
            let slots = u64::from(info.slots(pc, SlotTable::default()));
            if x.op != Opcode::Label {
                ran(pc);
                executed += slots;
                if executed > self.limit {
                    return Err(VertexError::ExecutedLimit {
                        vertex,
                        limit: self.limit,
                    });
                }
            }
            let matching = |i: usize| {
                info.matching
                    .get(i)
                    .copied()
                    .flatten()
                    .map_or(ins.len(), |m| m as usize)
            };
            pc = match x.op {
                Opcode::Label | Opcode::Ret => match calls.pop() {
                    Some(back) => back,
                    None => break,
                },
                Opcode::Call | Opcode::CallNz => {
                    let taken = x.op == Opcode::Call || self.condition(&g, &x.src[1]);
                    if !taken {
                        pc + 1
                    } else if calls.len() >= CALL_DEPTH {
                        return Err(VertexError::CallDepth { vertex, index: pc });
                    } else {
                        calls.push(pc + 1);
                        let label = x.src[0].reg.index;
                        info.labels
                            .get(&label)
                            .map_or(ins.len(), |&l| l as usize + 1)
                    }
                }
                Opcode::If | Opcode::Ifc => {
                    let taken = match x.op {
                        Opcode::If => self.condition(&g, &x.src[0]),
                        _ => self.compare(&g, x, 0),
                    };
                    let target = matching(pc);
                    match (taken, ins.get(target).map(|t| t.op)) {
                        (true, _) => pc + 1,
                        // the else-branch passes its `else`, which is charged
                        (false, Some(Opcode::Else)) => {
                            ran(target);
                            executed += u64::from(info.slots(target, SlotTable::default()));
                            target + 1
                        }
                        (false, _) => target,
                    }
                }
                Opcode::Else => matching(pc),
                Opcode::Rep | Opcode::Loop => {
                    let int = self.ints[x.src.last().map_or(0, |s| s.reg.index as usize) & 15];
                    let end = matching(pc);
                    if int[0] <= 0 {
                        end + 1
                    } else {
                        let looped = x.op == Opcode::Loop;
                        frames.push(Frame {
                            start: pc + 1,
                            end,
                            left: int[0],
                            step: if looped { int[2] } else { 0 },
                            outer_al: looped.then_some(g.al),
                        });
                        if looped {
                            g.al = int[1];
                        }
                        pc + 1
                    }
                }
                Opcode::EndRep | Opcode::EndLoop => {
                    let Some(f) = frames.last_mut() else { break };
                    f.left -= 1;
                    if f.left > 0 {
                        g.al = g.al.wrapping_add(f.step);
                        // the next iteration's rep/loop is charged with it
                        ran(f.start - 1);
                        executed += u64::from(info.slots(f.start - 1, SlotTable::default()));
                        f.start
                    } else {
                        leave(&mut frames, &mut g)
                    }
                }
                Opcode::Break | Opcode::BreakC | Opcode::BreakP => {
                    let taken = match x.op {
                        Opcode::Break => true,
                        Opcode::BreakC => self.compare(&g, x, 0),
                        _ => self.condition(&g, &x.src[0]),
                    };
                    if taken {
                        leave(&mut frames, &mut g)
                    } else {
                        pc + 1
                    }
                }
                _ => {
                    self.arithmetic(&mut g, x)?;
                    pc + 1
                }
            };
        }
        Ok((g.o, executed))
    }

    /// `b#` or `p0.c`, with `!`.
    fn condition(&self, g: &Regs, s: &Src) -> bool {
        let v = match s.reg.file {
            RegFile::ConstBool => self.bools[s.reg.index as usize & 15],
            _ => g.p[s.swizzle.0[0] as usize & 3],
        };
        v != (s.modifier == SrcMod::Not)
    }

    /// `if_cmp` / `break_cmp` on the first components of sources `k`, `k+1`.
    fn compare(&self, g: &Regs, x: &Instruction, k: usize) -> bool {
        let a = self.read(g, &x.src[k])[0];
        let b = self.read(g, &x.src[k + 1])[0];
        x.compare.is_some_and(|c| c.eval(a, b))
    }

    /// Source `s` with its relative addressing, swizzle and modifier.
    fn read(&self, g: &Regs, s: &Src) -> [f32; 4] {
        self.read_offset(g, s, 0)
    }

    /// [`Self::read`] of the register `k` after `s`'s (matrix rows).
    fn read_offset(&self, g: &Regs, s: &Src, k: u32) -> [f32; 4] {
        let index = match s.relative {
            None => i64::from(s.reg.index + k),
            Some(RelIndex::Loop) => i64::from(s.reg.index + k) + i64::from(g.al),
            Some(RelIndex::Addr(c)) => i64::from(s.reg.index + k) + i64::from(g.a0[c as usize & 3]),
        };
        let at = |rows: &[[f32; 4]]| {
            usize::try_from(index)
                .ok()
                .and_then(|i| rows.get(i))
                .copied()
                .unwrap_or([0.0; 4])
        };
        let raw = match s.reg.file {
            RegFile::Temp => at(&g.r),
            RegFile::Input => at(&g.v),
            RegFile::Const => at(&self.consts),
            RegFile::ConstInt => self.ints[index as usize & 15].map(|i| i as f32),
            RegFile::LoopCounter => [g.al as f32; 4],
            RegFile::Address => g.a0.map(|i| i as f32),
            _ => [0.0; 4],
        };
        let (and, xor) = match s.modifier {
            SrcMod::Neg => (!0, 0x8000_0000),
            SrcMod::Abs => (0x7fff_ffff, 0),
            SrcMod::NegAbs => (0x7fff_ffff, 0x8000_0000),
            _ => (!0, 0),
        };
        std::array::from_fn(|c| math::modify(raw[s.swizzle.0[c] as usize & 3], and, xor))
    }

    /// Writes `value` to `d` (its mask, `_sat`, predication), the result
    /// flushed first under the `hardware` rules.
    fn write(&self, g: &mut Regs, x: &Instruction, d: &Dst, value: [f32; 4], mask: u8) {
        let mask = mask & d.mask.0;
        for c in 0..4 {
            if mask & 1 << c == 0 {
                continue;
            }
            if let Some(pr) = x.predicate {
                if g.p[pr.swizzle.0[c] as usize & 3] == pr.negate {
                    continue;
                }
            }
            let mut v = value[c];
            if self.rules.flush_denormals() {
                v = flush(v);
            }
            if x.sat {
                v = math::sat(v);
            }
            let index = match d.relative {
                Some(RelIndex::Loop) => i64::from(d.reg.index) + i64::from(g.al),
                _ => i64::from(d.reg.index),
            };
            let Ok(index) = u32::try_from(index) else {
                continue;
            };
            let slot = match d.reg.file {
                RegFile::Temp => g.r.get_mut(index as usize),
                RegFile::Address => {
                    g.a0[c] = math::mova(v);
                    continue;
                }
                RegFile::Predicate => {
                    g.p[c] = v != 0.0;
                    continue;
                }
                f => output_row(f, index).map(|r| &mut g.o[r]),
            };
            if let Some(row) = slot {
                row[c] = v;
            }
        }
    }

    /// Every instruction that is not flow control.
    fn arithmetic(&self, g: &mut Regs, x: &Instruction) -> Result<(), VertexError> {
        let Some(d) = x.dst else {
            return Ok(());
        };
        let src = |k: usize| x.src.get(k).map_or([0.0; 4], |s| self.read(g, s));
        let rules = self.rules;
        let mul = |a: f32, b: f32| {
            if rules.zero_mul() {
                math::zmul(a, b)
            } else {
                a * b
            }
        };
        let fl = |v: f32| if rules.flush_denormals() { flush(v) } else { v };
        let dot = |a: [f32; 4], b: [f32; 4], n: usize| {
            (1..n).fold(fl(mul(a[0], b[0])), |s, c| fl(s + fl(mul(a[c], b[c]))))
        };
        let map = |a: [f32; 4], f: &dyn Fn(f32) -> f32| a.map(f);
        let zip = |a: [f32; 4], b: [f32; 4], f: &dyn Fn(f32, f32) -> f32| {
            std::array::from_fn::<f32, 4, _>(|c| f(a[c], b[c]))
        };
        let scalar = |v: f32| [v; 4];
        let d3d9 = rules.d3d9_specials();
        let (value, mask): ([f32; 4], u8) = match x.op {
            Opcode::Mov | Opcode::Mova => (src(0), 15),
            Opcode::Add => (zip(src(0), src(1), &|a, b| a + b), 15),
            Opcode::Sub => (zip(src(0), src(1), &|a, b| a - b), 15),
            Opcode::Mul => (zip(src(0), src(1), &mul), 15),
            Opcode::Mad => {
                let (a, b, c) = (src(0), src(1), src(2));
                (std::array::from_fn(|k| self.mad(a[k], b[k], c[k])), 15)
            }
            Opcode::Lrp => {
                let (a, b, c) = (src(0), src(1), src(2));
                (std::array::from_fn(|k| self.lrp(a[k], b[k], c[k])), 15)
            }
            Opcode::Rcp => (scalar(math::rcp(src(0)[0])), 15),
            Opcode::Rsq => (
                scalar(if d3d9 {
                    math::rsq(src(0)[0])
                } else {
                    math::ieee_rsq(src(0)[0])
                }),
                15,
            ),
            // expp in vs_2_0 and later is exp at (at least) 10 bits: ps30
            // computes it in full precision, as MS `expp---vs` allows.
            Opcode::Exp | Opcode::Expp => (scalar(math::exp(src(0)[0])), 15),
            Opcode::Log | Opcode::Logp => (
                scalar(if d3d9 {
                    math::log(src(0)[0])
                } else {
                    math::ieee_log(src(0)[0])
                }),
                15,
            ),
            Opcode::Dp3 => (scalar(dot(src(0), src(1), 3)), 15),
            Opcode::Dp4 => (scalar(dot(src(0), src(1), 4)), 15),
            Opcode::Min => (zip(src(0), src(1), &math::min), 15),
            Opcode::Max => (zip(src(0), src(1), &math::max), 15),
            Opcode::Slt => (zip(src(0), src(1), &|a, b| f32::from(u8::from(a < b))), 15),
            Opcode::Sge => (zip(src(0), src(1), &|a, b| f32::from(u8::from(a >= b))), 15),
            Opcode::Sgn => (map(src(0), &sgn), 15),
            Opcode::Frc => (
                map(src(0), &|v| {
                    if d3d9 {
                        math::frc(v)
                    } else {
                        math::ieee_frc(v)
                    }
                }),
                15,
            ),
            Opcode::Abs => (map(src(0), &f32::abs), 15),
            Opcode::Pow => {
                let f = if d3d9 { math::pow } else { math::ieee_pow };
                (scalar(f(src(0)[0], src(1)[0])), 15)
            }
            Opcode::Crs => {
                let (a, b) = (src(0), src(1));
                let v = std::array::from_fn(|c| {
                    let (i, j) = ((c + 1) % 3, (c + 2) % 3);
                    a[i] * b[j] - a[j] * b[i]
                });
                (v, 0b0111)
            }
            Opcode::Nrm => (self.nrm(src(0)), 15),
            Opcode::SinCos => {
                let a = src(0)[0];
                ([a.cos(), a.sin(), 0.0, 0.0], 0b0011)
            }
            Opcode::Lit => (lit(src(0)), 15),
            Opcode::Dst => {
                let (a, b) = (src(0), src(1));
                ([1.0, mul(a[1], b[1]), a[2], b[3]], 15)
            }
            Opcode::M4x4 | Opcode::M4x3 | Opcode::M3x4 | Opcode::M3x3 | Opcode::M3x2 => {
                let (rows, dims) = x.op.matrix_shape().unwrap_or((4, 4));
                let a = src(0);
                let mut v = [0.0; 4];
                for (k, out) in v.iter_mut().enumerate().take(rows as usize) {
                    *out = dot(a, self.read_offset(g, &x.src[1], k as u32), dims as usize);
                }
                (v, (1u8 << rows) - 1)
            }
            Opcode::Setp => {
                let (a, b) = (src(0), src(1));
                let c = x.compare.unwrap_or(Compare::Eq);
                (
                    std::array::from_fn(|k| f32::from(u8::from(c.eval(a[k], b[k])))),
                    15,
                )
            }
            Opcode::TexLdL => (self.texldl(src(0), &x.src[1]), 15),
            // no vertex profile has cmp; the bound shader of `ps30
            // decompile --verify` (`jobs/decompile/bound.rs`) selects with it
            Opcode::Cmp => {
                let (a, b, c) = (src(0), src(1), src(2));
                (std::array::from_fn(|k| math::cmp(a[k], b[k], c[k])), 15)
            }
            _ => return Ok(()),
        };
        self.write(g, x, &d, value, mask);
        Ok(())
    }

    /// `mad` under the rules, as `emu/arith.rs` computes it.
    fn mad(&self, a: f32, b: f32, c: f32) -> f32 {
        if self.rules.flush_denormals() {
            flush(math::zmul(a, b)) + c
        } else if self.rules.zero_mul() {
            math::zmul(a, b) + c
        } else {
            math::mad(a, b, c)
        }
    }

    /// `lrp` under the rules, as `emu/arith.rs` computes it.
    fn lrp(&self, a: f32, b: f32, c: f32) -> f32 {
        if self.rules.flush_denormals() {
            flush(math::zmul(a, b)) + flush(math::zmul(1.0 - a, c))
        } else if self.rules.zero_mul() {
            math::zmul(a, b) + math::zmul(1.0 - a, c)
        } else {
            math::lrp(a, b, c)
        }
    }

    /// `nrm` under the rules, as `emu/arith.rs` computes it.
    fn nrm(&self, a: [f32; 4]) -> [f32; 4] {
        let rules = self.rules;
        let len2 = if rules.flush_denormals() {
            flush(flush(flush(a[0] * a[0]) + flush(a[1] * a[1])) + flush(a[2] * a[2]))
        } else {
            a[0] * a[0] + a[1] * a[1] + a[2] * a[2]
        };
        let scale = if rules.d3d9_specials() {
            math::nrm_scale(len2)
        } else {
            math::ieee_nrm_scale(len2)
        };
        a.map(|v| {
            if rules.zero_mul() {
                math::zmul(v, scale)
            } else {
                v * scale
            }
        })
    }

    /// `texldl`: the sampler's level of detail `coordinate.w` plus its LOD
    /// bias (MS `texldl---vs`), the sampled value through the sampler's
    /// swizzle; an unbound sampler reads (0, 0, 0, 1).
    fn texldl(&self, p: [f32; 4], s: &Src) -> [f32; 4] {
        let value = match self
            .samplers
            .get(s.reg.index as usize)
            .and_then(|x| x.as_ref())
        {
            None => UNBOUND,
            Some(sm) => {
                let lod = p[3] + sm.bias();
                let q = p.map(finite_coordinate);
                let mut v = if sm.is_3d() {
                    sm.sample_3d([q[0], q[1], q[2]], lod)
                } else {
                    sm.sample_lod(q[0], q[1], lod)
                };
                if self.rules.flush_denormals() {
                    v = v.map(flush);
                }
                v
            }
        };
        std::array::from_fn(|c| value[s.swizzle.0[c] as usize & 3])
    }
}

/// Leaves the innermost `rep`/`loop` (its `aL` restored): the instruction
/// after its end.
fn leave(frames: &mut Vec<Frame>, g: &mut Regs) -> usize {
    match frames.pop() {
        Some(f) => {
            if let Some(al) = f.outer_al {
                g.al = al;
            }
            f.end + 1
        }
        None => usize::MAX,
    }
}

/// `sgn`: −1, 0 or 1 (MS `sgn---vs`); a NaN gives 0, as neither test holds.
fn sgn(v: f32) -> f32 {
    if v < 0.0 {
        -1.0
    } else if v > 0.0 {
        1.0
    } else {
        0.0
    }
}

/// `lit` (MS `lit---vs`): x = 1, w = 1; y = src.x where src.x > 0, else 0;
/// z = src.y ^ power where src.x > 0 and src.y > 0, else 0, the power
/// src.w clamped to ±127.9961.
fn lit(s: [f32; 4]) -> [f32; 4] {
    const MAX_POWER: f32 = 127.9961;
    let power = s[3].clamp(-MAX_POWER, MAX_POWER);
    let mut out = [1.0, 0.0, 0.0, 1.0];
    if s[0] > 0.0 {
        out[1] = s[0];
        if s[1] > 0.0 {
            out[2] = s[1].powf(power);
        }
    }
    out
}
