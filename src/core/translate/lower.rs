//! Arithmetic: source operands (swizzle, `-`, `_abs`), destinations (write
//! mask, `_sat`, predication) and every arithmetic instruction of the ISA
//! table with the semantics the emulator gives it (`core/emu/math.rs`,
//! `arith.rs`), special values as the [`FloatRules`] say.
//!
//! Where the emulator fixes an evaluation order D3D9 leaves open, the
//! translation uses the target language's own function and leaves the
//! order to the device: `dot` for dp3/dp4 (the emulator adds left to
//! right), `cross` for crs, and `a * b + c` for mad, which a device may
//! fuse. `lrp` is written out as `a·b + (1 − a)·c`, the formula of its
//! page, rather than `mix`. `_pp` is ignored, as in the emulator.

use super::builder::{Expr, Fb};
use super::module::Ctx;
use super::TranslateError;
use crate::core::float_rules::{FloatRules, FLT_MAX};
use crate::core::ir::{Instruction, Reg, Src, SrcMod, Swizzle};
use crate::core::isa::{Compare, Opcode, RegFile};
use naga::{BinaryOperator as B, Expression, MathFunction as M, SwizzleComponent, VectorSize};

/// The largest f32 below 1 (`frc`'s upper end under the D3D9 rules).
const BELOW_ONE: f32 = 1.0 - f32::EPSILON / 2.0;

/// One function being lowered: the module context, the builder and the
/// float rules.
pub(super) struct Lower<'a> {
    pub cx: &'a Ctx,
    pub fb: Fb,
    pub rules: FloatRules,
    /// Counter for naming loop variables.
    pub loops: u32,
    /// Values already flushed (`hardware`): flushing them again is skipped.
    pub flushed: std::collections::HashSet<Expr>,
}

/// A result: a vec4, or a scalar replicated to every component.
#[derive(Clone, Copy)]
pub(super) enum Value {
    Vector(Expr),
    Scalar(Expr),
}

const XYZW: [SwizzleComponent; 4] = [
    SwizzleComponent::X,
    SwizzleComponent::Y,
    SwizzleComponent::Z,
    SwizzleComponent::W,
];

impl Lower<'_> {
    // ----- values ---------------------------------------------------------

    pub fn zero4(&mut self) -> Expr {
        self.fb.add(Expression::ZeroValue(self.cx.t.vec4))
    }

    /// +∞ (naga refuses non-finite literals: a bit cast of 0x7f800000).
    pub(super) fn infinity(&mut self) -> Expr {
        let bits = self.fb.u32(0x7f80_0000);
        self.fb.add(Expression::As {
            expr: bits,
            kind: naga::ScalarKind::Float,
            convert: None,
        })
    }

    /// Component `c` of a vector (through a swizzle: `r1.wwww.x` is `r1.w`).
    pub fn comp(&mut self, v: Expr, c: u32) -> Expr {
        self.component(Value::Vector(v), c)
    }

    /// The first `n` components of a vec4.
    pub fn first(&mut self, v: Expr, n: u32) -> Expr {
        let size = match n {
            2 => VectorSize::Bi,
            3 => VectorSize::Tri,
            _ => return v,
        };
        self.fb.add(Expression::Swizzle {
            size,
            vector: v,
            pattern: XYZW,
        })
    }

    pub fn splat4(&mut self, s: Expr) -> Expr {
        self.fb.splat(s, VectorSize::Quad)
    }

    pub fn compose4(&mut self, parts: [Expr; 4]) -> Expr {
        self.fb.add(Expression::Compose {
            ty: self.cx.t.vec4,
            components: parts.to_vec(),
        })
    }

    // ----- sources ------------------------------------------------------------

    /// A register's value as a vec4 (no swizzle, no modifier); under the
    /// `hardware` rules a constant's or an input's denormals read as zeros
    /// (temporaries and outputs were flushed when written).
    pub fn reg(&mut self, reg: Reg, relative: bool) -> Result<Expr, TranslateError> {
        let v = self.reg_raw(reg, relative)?;
        // A `def` without denormals needs no flush where it is read, nor a
        // constant the draw fixes (flushed as it became a literal), nor an
        // input the GPU backend flushed on the CPU.
        let cx = self.cx;
        let plain_def = reg.file == RegFile::Const
            && !relative
            && (cx.float_defs.contains_key(&reg.index)
                || cx.float_def_bits.contains_key(&reg.index))
            && !cx.float_defs_subnormal.contains(&reg.index);
        let fixed = reg.file == RegFile::Const && !relative && self.fixed_constant(reg).is_some();
        let flushed_input = reg.file == RegFile::Input && cx.spec.inputs_flushed();
        if self.rules.flush_denormals()
            && matches!(reg.file, RegFile::Const | RegFile::Input)
            && !plain_def
            && !fixed
            && !flushed_input
        {
            return Ok(self.flush(v, Some(VectorSize::Quad)));
        }
        Ok(v)
    }

    /// The bits of constant `reg` where the draw fixes them and no `def`
    /// sets it, flushed as the float rules say.
    fn fixed_constant(&self, reg: Reg) -> Option<[u32; 4]> {
        let cx = self.cx;
        if cx.float_defs.contains_key(&reg.index) || cx.float_def_bits.contains_key(&reg.index) {
            return None;
        }
        let bits = cx.spec.constant(reg.index)?;
        Some(if self.rules.flush_denormals() {
            bits.map(|b| crate::core::float_rules::flush(f32::from_bits(b)).to_bits())
        } else {
            bits
        })
    }

    /// A constant the draw fixes (`bits`, flushed): each finite component
    /// as a literal, except a zero that flushing made (a denormal the draw
    /// gave) and, under rules without the zero-multiply rule, every zero;
    /// those and ∞ and NaN are read from the constant block and flushed at
    /// run time. A denormal folded to a literal zero lets a device's
    /// compiler drop `x + 0` (Vulkan lets it; the H100's did), so the `add`
    /// probe of a denormal constant would measure that instead of the
    /// device's arithmetic; and a literal zero lets it fold `x · 0` to 0,
    /// which only the zero-multiply rule allows (Mesa's does it). The zeros
    /// a draw gives stay literals otherwise: pass 1 runs 7 to 15 times
    /// slower on llvmpipe with them read at run time.
    fn fixed_value(&mut self, reg: Reg, bits: [u32; 4]) -> Expr {
        let values = bits.map(f32::from_bits);
        let given = self.cx.spec.constant(reg.index).unwrap_or(bits);
        let folds = values.map(|x| x.is_finite());
        let zero_mul = self.rules.zero_mul();
        let folds: [bool; 4] = std::array::from_fn(|c| {
            folds[c] && (values[c] != 0.0 || (zero_mul && given[c] & 0x7FFF_FFFF == 0))
        });
        let foldable = |c: usize| folds[c];
        let from_block = if (0..4).all(foldable) {
            None
        } else {
            let c = self.cx.block(&mut self.fb, 0);
            let p = self.fb.index(c, reg.index);
            let v = self.fb.load(p);
            Some(match self.rules.flush_denormals() {
                true => self.flush(v, Some(VectorSize::Quad)),
                false => v,
            })
        };
        let components = (0..4)
            .map(|c| match from_block {
                Some(v) if !foldable(c) => self.fb.index(v, c as u32),
                _ => self.fb.f32(values[c]),
            })
            .collect();
        self.fb.add(Expression::Compose {
            ty: self.cx.t.vec4,
            components,
        })
    }

    /// Component `i` of `e` when it is an f32 literal (through
    /// compositions of scalars, splats, swizzles, component accesses,
    /// negation and `abs`).
    fn literal(&self, e: Expr, i: usize) -> Option<f32> {
        use naga::Literal;
        match &self.fb.f.expressions[e] {
            Expression::Literal(Literal::F32(x)) if i == 0 => Some(*x),
            // Four parts of a vec4 are its four scalars.
            Expression::Compose { ty, components }
                if *ty == self.cx.t.vec4 && components.len() == 4 =>
            {
                let c = *components.get(i)?;
                match self.fb.f.expressions[c] {
                    Expression::Literal(_) => self.literal(c, 0),
                    _ => None,
                }
            }
            Expression::Splat { value, .. } => self.literal(*value, 0),
            Expression::Swizzle {
                size,
                vector,
                pattern,
            } if i < *size as usize => self.literal(*vector, pattern[i] as usize),
            Expression::AccessIndex { base, index } if i == 0 => {
                self.literal(*base, *index as usize)
            }
            Expression::Unary {
                op: naga::UnaryOperator::Negate,
                expr,
            } => self.literal(*expr, i).map(|x| -x),
            Expression::Math {
                fun: M::Abs, arg, ..
            } => self.literal(*arg, i).map(f32::abs),
            _ => None,
        }
    }

    /// Whether each of the `n` components of `e` is a finite, positive
    /// literal: then the zero-multiply rule gives exactly the plain product
    /// (a zero factor times it is that zero, sign included; ∞ and NaN stay).
    fn positive_finite(&self, e: Expr, n: usize) -> bool {
        (0..n).all(|i| self.literal(e, i).is_some_and(|x| x.is_finite() && x > 0.0))
    }

    /// Whether `e` holds no denormal under the `hardware` rules: a result
    /// [`flush`](Self::flush) made, a literal without denormals, a
    /// temporary (flushed when written), an input flushed on the CPU, or a
    /// part, negation, `abs` or saturation of one of them.
    fn is_flushed(&self, e: Expr) -> bool {
        if self.flushed.contains(&e) {
            return true;
        }
        match &self.fb.f.expressions[e] {
            Expression::Literal(naga::Literal::F32(x)) => !x.is_subnormal(),
            Expression::Swizzle { vector, .. } => self.is_flushed(*vector),
            Expression::AccessIndex { base, .. } => self.is_flushed(*base),
            Expression::Splat { value, .. } => self.is_flushed(*value),
            Expression::Compose { components, .. } => {
                components.iter().all(|&c| self.is_flushed(c))
            }
            Expression::Unary {
                op: naga::UnaryOperator::Negate,
                expr,
            } => self.is_flushed(*expr),
            Expression::Math {
                fun: M::Abs | M::Saturate,
                arg,
                ..
            } => self.is_flushed(*arg),
            Expression::Load { pointer } => self.holds_flushed(*pointer),
            _ => false,
        }
    }

    /// Whether `pointer` points into a temporary, or into the inputs when
    /// they arrive flushed.
    fn holds_flushed(&self, pointer: Expr) -> bool {
        match &self.fb.f.expressions[pointer] {
            Expression::GlobalVariable(g) => {
                self.cx.temps.values().any(|t| t == g)
                    || (*g == self.cx.inputs && self.cx.spec.inputs_flushed())
            }
            Expression::AccessIndex { base, .. } => self.holds_flushed(*base),
            _ => false,
        }
    }

    /// `v` with denormals replaced by zeros of their sign (`hardware`),
    /// decided on the bits alone: `(bits & 0x7FFFFFFF) < 0x00800000` as
    /// unsigned integers, the sign bit kept. A float comparison
    /// `abs(v) < 2^-126` turned −∞ into −0 on llvmpipe (its compiler may
    /// assume finite values), and a device need not keep the sign of a
    /// zero it computes, so `v * 0` would not do either.
    pub(super) fn flush(&mut self, v: Expr, size: Option<VectorSize>) -> Expr {
        if self.is_flushed(v) {
            return v;
        }
        let splat = |fb: &mut Fb, x: Expr| match size {
            Some(size) => fb.splat(x, size),
            None => x,
        };
        // Signed integers: the magnitude's bits are never negative, and a
        // signed comparison is one instruction where an unsigned one is
        // not (x86's vector units have none).
        let magnitude = self.fb.i32(0x7FFF_FFFF);
        let magnitude = splat(&mut self.fb, magnitude);
        let smallest = self.fb.i32(0x0080_0000);
        let smallest = splat(&mut self.fb, smallest);
        let sign = self.fb.i32(i32::MIN);
        let sign = splat(&mut self.fb, sign);
        let bits = self.fb.add(Expression::As {
            expr: v,
            kind: naga::ScalarKind::Sint,
            convert: None,
        });
        let abs_bits = self.fb.binary(B::And, bits, magnitude);
        let small = self.fb.binary(B::Less, abs_bits, smallest);
        let sign_bits = self.fb.binary(B::And, bits, sign);
        let flushed = self.fb.select(small, sign_bits, bits);
        let out = self.fb.add(Expression::As {
            expr: flushed,
            kind: naga::ScalarKind::Float,
            convert: None,
        });
        self.flushed.insert(out);
        out
    }

    fn reg_raw(&mut self, reg: Reg, relative: bool) -> Result<Expr, TranslateError> {
        let cx = self.cx;
        let fixed = match reg.file {
            RegFile::Const if !relative => self.fixed_constant(reg),
            _ => None,
        };
        let fb = &mut self.fb;
        Ok(match reg.file {
            RegFile::Temp => {
                let g = *cx.temps.get(&reg.index).ok_or(TranslateError::Internal(
                    "a temporary missing from the register list",
                ))?;
                let p = cx.var(fb, g);
                fb.load(p)
            }
            RegFile::Input if relative => return Ok(self.relative_input(reg.index)),
            RegFile::Input if cx.vertex.is_some() => {
                let v = cx.var(fb, cx.inputs);
                let p = fb.index(v, reg.index);
                fb.load(p)
            }
            RegFile::Input | RegFile::Texture => {
                let slot = crate::core::pixel_inputs::slot(cx.profile, reg.file, reg.index)
                    .ok_or_else(|| TranslateError::Unsupported(format!("reading {reg}")))?;
                let v = cx.var(fb, cx.inputs);
                let p = fb.index(v, slot);
                fb.load(p)
            }
            RegFile::Const => match cx.float_defs.get(&reg.index) {
                Some(&c) => fb.add(Expression::Constant(c)),
                None if fixed.is_some() => {
                    let bits = fixed.unwrap_or_default();
                    return Ok(self.fixed_value(reg, bits));
                }
                None if cx.float_def_bits.contains_key(&reg.index) => {
                    let bits = cx.float_def_bits[&reg.index];
                    let components = bits.map(|b| fb.u32(b)).to_vec();
                    let ty = cx.t.uvec4;
                    let u = fb.add(Expression::Compose { ty, components });
                    fb.add(Expression::As {
                        expr: u,
                        kind: naga::ScalarKind::Float,
                        convert: None,
                    })
                }
                None => {
                    let c = cx.block(fb, 0);
                    let p = fb.index(c, reg.index);
                    fb.load(p)
                }
            },
            RegFile::Position => {
                let p = cx.var(fb, cx.pos);
                fb.load(p)
            }
            RegFile::Face => {
                let p = cx.var(fb, cx.face);
                fb.load(p)
            }
            RegFile::LoopCounter => {
                let al = self.al();
                let f = self.fb.add(Expression::As {
                    expr: al,
                    kind: naga::ScalarKind::Float,
                    convert: Some(4),
                });
                self.splat4(f)
            }
            _ => return Err(TranslateError::Unsupported(format!("reading {reg}"))),
        })
    }

    /// The current `aL`.
    pub fn al(&mut self) -> Expr {
        let p = self.cx.var(&mut self.fb, self.cx.al);
        self.fb.load(p)
    }

    /// `v[aL + n]`: zeros outside v0..v9, as the emulator reads them.
    fn relative_input(&mut self, n: u32) -> Expr {
        let al = self.al();
        let offset = self.fb.i32(n as i32);
        let i = self.fb.binary(B::Add, al, offset);
        let (lo, hi) = (self.fb.i32(0), self.fb.i32(9));
        let clamped = self.fb.math(M::Clamp, &[i, lo, hi]);
        let v = self.cx.var(&mut self.fb, self.cx.inputs);
        let p = self.fb.add(Expression::Access {
            base: v,
            index: clamped,
        });
        let value = self.fb.load(p);
        let inside = self.fb.binary(B::Equal, i, clamped);
        let zero = self.zero4();
        self.fb.select(inside, value, zero)
    }

    /// A source operand with its swizzle and modifier applied.
    pub fn read(&mut self, s: &Src) -> Result<Expr, TranslateError> {
        let v = match s.relative {
            Some(rel) if self.cx.vertex.is_some() => self.vertex_relative(s.reg, rel)?,
            // Past c255 (vs_2_0 assembles up to c8191): zeros, as the
            // emulator's vertex stage reads them.
            None if self.cx.vertex.is_some()
                && s.reg.file == RegFile::Const
                && s.reg.index >= super::module::VERTEX_FLOATS =>
            {
                self.zero4()
            }
            _ => self.reg(s.reg, s.relative.is_some())?,
        };
        Ok(self.modify(v, s.swizzle, s.modifier))
    }

    fn modify(&mut self, v: Expr, swizzle: Swizzle, modifier: SrcMod) -> Expr {
        let v = if swizzle == Swizzle::IDENTITY {
            v
        } else {
            self.fb.add(Expression::Swizzle {
                size: VectorSize::Quad,
                vector: v,
                pattern: swizzle.0.map(|c| XYZW[c as usize & 3]),
            })
        };
        match modifier {
            SrcMod::None | SrcMod::Not => v,
            SrcMod::Neg => self.fb.negate(v),
            SrcMod::Abs => self.fb.math(M::Abs, &[v]),
            SrcMod::NegAbs => {
                let a = self.fb.math(M::Abs, &[v]);
                self.fb.negate(a)
            }
        }
    }

    /// Source `k` of `ins`.
    pub fn src(&mut self, ins: &Instruction, k: usize) -> Result<Expr, TranslateError> {
        let s = ins
            .src
            .get(k)
            .ok_or(TranslateError::Internal("a missing source operand"))?;
        self.read(s)
    }

    /// The replicate component of source `k` (scalar instructions).
    pub fn scalar_src(&mut self, ins: &Instruction, k: usize) -> Result<Expr, TranslateError> {
        let v = self.src(ins, k)?;
        Ok(self.comp(v, 0))
    }

    // ----- destinations ---------------------------------------------------------

    /// Whether `(p0.c)` lets component `c` be written.
    pub(super) fn predicate(&mut self, ins: &Instruction, c: usize) -> Option<Expr> {
        let pred = ins.predicate?;
        let p = self.cx.var(&mut self.fb, self.cx.p0);
        let p = self.fb.load(p);
        let bit = self.comp(p, pred.swizzle.0[c] as u32);
        Some(if pred.negate { self.fb.not(bit) } else { bit })
    }

    /// Writes a vec4 result to the destination: `_sat`, the write mask
    /// (only components in `allowed`), and predication.
    pub fn write(
        &mut self,
        ins: &Instruction,
        value: Expr,
        allowed: u8,
    ) -> Result<(), TranslateError> {
        self.write_value(ins, Value::Vector(value), allowed)
    }

    /// Writes a scalar result replicated to the masked components.
    pub(super) fn write_scalar(
        &mut self,
        ins: &Instruction,
        s: Expr,
    ) -> Result<(), TranslateError> {
        self.write_value(ins, Value::Scalar(s), 0b1111)
    }

    /// Component `c` of a value; a swizzle is looked through, so that
    /// `r0.x = r1.wwww.x` reads `r1.w`.
    pub(super) fn component(&mut self, value: Value, c: u32) -> Expr {
        match value {
            Value::Scalar(s) => s,
            Value::Vector(v) => match self.fb.f.expressions[v] {
                Expression::Swizzle {
                    size: VectorSize::Quad,
                    vector,
                    pattern,
                } => self.fb.index(vector, pattern[c as usize] as u32),
                _ => self.fb.index(v, c),
            },
        }
    }

    pub(super) fn write_value(
        &mut self,
        ins: &Instruction,
        value: Value,
        allowed: u8,
    ) -> Result<(), TranslateError> {
        let d = ins
            .dst
            .ok_or(TranslateError::Internal("a missing destination"))?;
        let cx = self.cx;
        let g = match d.reg.file {
            RegFile::Temp => Some(*cx.temps.get(&d.reg.index).ok_or(TranslateError::Internal(
                "a temporary missing from the register list",
            ))?),
            RegFile::ColorOut if d.reg.index < 4 => Some(cx.outputs[d.reg.index as usize]),
            RegFile::DepthOut => Some(cx.depth),
            _ if cx.vertex.is_some() => None,
            _ => return Err(TranslateError::Unsupported(format!("writing {}", d.reg))),
        };
        let value = match (ins.sat, value) {
            (false, v) => v,
            (true, Value::Vector(v)) => Value::Vector(self.fb.math(M::Saturate, &[v])),
            (true, Value::Scalar(v)) => Value::Scalar(self.fb.math(M::Saturate, &[v])),
        };
        let value = match value {
            _ if !self.rules.flush_denormals() => value,
            Value::Vector(v) => Value::Vector(self.flush(v, Some(VectorSize::Quad))),
            Value::Scalar(v) => Value::Scalar(self.flush(v, None)),
        };
        let mask = d.mask.0 & allowed;
        let ptr = match g {
            Some(g) => cx.var(&mut self.fb, g),
            None if d.reg.file == RegFile::Address => {
                return self.write_address(ins, value, mask);
            }
            None => self.vertex_output(&d)?,
        };
        if mask == 0b1111 && ins.predicate.is_none() {
            let v = match value {
                Value::Vector(v) => v,
                Value::Scalar(s) => self.splat4(s),
            };
            self.fb.store(ptr, v);
            return Ok(());
        }
        for c in 0..4 {
            if mask & (1 << c) == 0 {
                continue;
            }
            let mut v = self.component(value, c as u32);
            if let Some(p) = self.predicate(ins, c) {
                let target = self.fb.index(ptr, c as u32);
                let old = self.fb.load(target);
                v = self.fb.select(p, v, old);
            }
            let target = self.fb.index(ptr, c as u32);
            self.fb.store(target, v);
        }
        Ok(())
    }

    // ----- the float rules ------------------------------------------------------

    /// `a · b` per component; under d3d9-zero-mul a zero factor gives 0, and
    /// under `hardware` a denormal product is a zero (inside `mad` and `lrp`
    /// too: the product is a result of its own, as in the emulator).
    pub fn mul(&mut self, a: Expr, b: Expr, size: Option<VectorSize>) -> Expr {
        let p = self.product(a, b, size);
        if self.rules.flush_denormals() {
            return self.flush(p, size);
        }
        p
    }

    /// `a · b` per component under the zero-multiply rule, unflushed.
    fn product(&mut self, a: Expr, b: Expr, size: Option<VectorSize>) -> Expr {
        let n = size.map_or(1, |s| s as usize);
        if !self.rules.zero_mul() || self.positive_finite(a, n) || self.positive_finite(b, n) {
            return self.fb.binary(B::Multiply, a, b);
        }
        let zero = self.fb.f32(0.0);
        let zero = match size {
            Some(size) => self.fb.splat(zero, size),
            None => zero,
        };
        let a_zero = self.fb.binary(B::Equal, a, zero);
        let b_zero = self.fb.binary(B::Equal, b, zero);
        let a2 = self.fb.select(b_zero, zero, a);
        let b2 = self.fb.select(a_zero, zero, b);
        self.fb.binary(B::Multiply, a2, b2)
    }

    /// `dot` of the first `n` components, under the zero-multiply rule; under
    /// `hardware` summed left to right with every denormal product and
    /// partial sum a zero, as the emulator computes it.
    fn dot(&mut self, a: Expr, b: Expr, n: u32) -> Expr {
        let (a, b) = (self.first(a, n), self.first(b, n));
        if self.rules.flush_denormals() {
            let size = [VectorSize::Bi, VectorSize::Tri, VectorSize::Quad][n as usize - 2];
            let p = self.mul(a, b, Some(size));
            let mut s = self.comp(p, 0);
            for c in 1..n {
                let pc = self.comp(p, c);
                let sum = self.fb.binary(B::Add, s, pc);
                s = self.flush(sum, None);
            }
            return s;
        }
        let plain = self.positive_finite(a, n as usize) || self.positive_finite(b, n as usize);
        let (a, b) = if self.rules.zero_mul() && !plain {
            let size = [VectorSize::Bi, VectorSize::Tri, VectorSize::Quad][n as usize - 2];
            let zero = self.fb.f32(0.0);
            let zero = self.fb.splat(zero, size);
            let a_zero = self.fb.binary(B::Equal, a, zero);
            let b_zero = self.fb.binary(B::Equal, b, zero);
            (
                self.fb.select(b_zero, zero, a),
                self.fb.select(a_zero, zero, b),
            )
        } else {
            (a, b)
        };
        self.fb.math(M::Dot, &[a, b])
    }

    /// `log`: d3d9 log2(|x|) with log(0) = −FLT_MAX; ieee log2(x).
    pub(super) fn log(&mut self, x: Expr) -> Expr {
        if !self.rules.d3d9_specials() {
            return self.fb.math(M::Log2, &[x]);
        }
        let a = self.fb.math(M::Abs, &[x]);
        let l = self.fb.math(M::Log2, &[a]);
        let zero = self.fb.f32(0.0);
        let is_zero = self.fb.binary(B::Equal, a, zero);
        let min = self.fb.f32(-FLT_MAX);
        self.fb.select(is_zero, min, l)
    }

    /// `rsq`: d3d9 1/sqrt(|x|) with rsq(0) = +∞; ieee inverseSqrt(x).
    fn rsq(&mut self, x: Expr) -> Expr {
        if !self.rules.d3d9_specials() {
            return self.fb.math(M::InverseSqrt, &[x]);
        }
        let a = self.fb.math(M::Abs, &[x]);
        let r = self.fb.math(M::InverseSqrt, &[a]);
        let zero = self.fb.f32(0.0);
        let is_zero = self.fb.binary(B::Equal, a, zero);
        let inf = self.infinity();
        self.fb.select(is_zero, inf, r)
    }

    /// `pow`: d3d9 |a|^b with pow(a, 0) = pow(1, b) = 1 and the zero base
    /// pinned (0 for b > 0, +∞ for b < 0); ieee `pow(a, b)`.
    fn pow(&mut self, a: Expr, b: Expr) -> Expr {
        if !self.rules.d3d9_specials() {
            return self.powr(a, b);
        }
        let x = self.fb.math(M::Abs, &[a]);
        let p = self.fb.math(M::Pow, &[x, b]);
        let p = self.zero_base(x, b, p);
        let (zero, one) = (self.fb.f32(0.0), self.fb.f32(1.0));
        let b_zero = self.fb.binary(B::Equal, b, zero);
        let x_one = self.fb.binary(B::Equal, x, one);
        let unit = self.fb.binary(B::LogicalOr, b_zero, x_one);
        self.fb.select(unit, one, p)
    }

    /// `p` = pow(x, b) with the zero base pinned where SPIR-V leaves it
    /// undefined: 0 for b > 0, +∞ for b < 0 (a NaN b left alone).
    fn zero_base(&mut self, x: Expr, b: Expr, p: Expr) -> Expr {
        let zero = self.fb.f32(0.0);
        let inf = self.infinity();
        let x_zero = self.fb.binary(B::Equal, x, zero);
        let b_positive = self.fb.binary(B::Greater, b, zero);
        let b_negative = self.fb.binary(B::Less, b, zero);
        let to_zero = self.fb.binary(B::LogicalAnd, x_zero, b_positive);
        let to_inf = self.fb.binary(B::LogicalAnd, x_zero, b_negative);
        let p = self.fb.select(to_zero, zero, p);
        self.fb.select(to_inf, inf, p)
    }

    /// IEEE's powr(a, b): `pow`, and NaN where powr is undefined (a < 0,
    /// a NaN operand, pow(0, 0), pow(∞, 0), pow(1, ±∞)) — WGSL leaves
    /// those to the device, and llvmpipe gives 0 for some.
    fn powr(&mut self, a: Expr, b: Expr) -> Expr {
        let p = self.fb.math(M::Pow, &[a, b]);
        let p = self.zero_base(a, b, p);
        let (zero, one) = (self.fb.f32(0.0), self.fb.f32(1.0));
        let inf = self.infinity();
        let nan_bits = self.fb.u32(0x7fc0_0000);
        let nan = self.fb.add(Expression::As {
            expr: nan_bits,
            kind: naga::ScalarKind::Float,
            convert: None,
        });
        let negative = self.fb.binary(B::Less, a, zero);
        let a_nan = self.fb.binary(B::NotEqual, a, a);
        let b_nan = self.fb.binary(B::NotEqual, b, b);
        let b_zero = self.fb.binary(B::Equal, b, zero);
        let a_zero = self.fb.binary(B::Equal, a, zero);
        let a_inf = self.fb.binary(B::Equal, a, inf);
        let a_edge = self.fb.binary(B::LogicalOr, a_zero, a_inf);
        let zero_power = self.fb.binary(B::LogicalAnd, a_edge, b_zero);
        let a_one = self.fb.binary(B::Equal, a, one);
        let b_abs = self.fb.math(M::Abs, &[b]);
        let b_inf = self.fb.binary(B::Equal, b_abs, inf);
        let one_inf = self.fb.binary(B::LogicalAnd, a_one, b_inf);
        let mut undefined = negative;
        for c in [a_nan, b_nan, zero_power, one_inf] {
            undefined = self.fb.binary(B::LogicalOr, undefined, c);
        }
        self.fb.select(undefined, nan, p)
    }

    /// `nrm`'s scale for f = x² + y² + z²: d3d9 FLT_MAX when f = 0.
    fn nrm_scale(&mut self, f: Expr) -> Expr {
        let r = self.fb.math(M::InverseSqrt, &[f]);
        if !self.rules.d3d9_specials() {
            return r;
        }
        let zero = self.fb.f32(0.0);
        let is_zero = self.fb.binary(B::Equal, f, zero);
        let max = self.fb.f32(FLT_MAX);
        self.fb.select(is_zero, max, r)
    }

    /// `frc`: x − floor(x), kept below 1 under the d3d9 rules.
    fn frc(&mut self, x: Expr) -> Expr {
        let fl = self.fb.math(M::Floor, &[x]);
        let f = self.fb.binary(B::Subtract, x, fl);
        if !self.rules.d3d9_specials() {
            return f;
        }
        let one = self.fb.f32(1.0);
        let ones = self.splat4(one);
        let below = self.fb.f32(BELOW_ONE);
        let below = self.splat4(below);
        let high = self.fb.binary(B::GreaterEqual, f, ones);
        self.fb.select(high, below, f)
    }

    // ----- instructions ---------------------------------------------------------

    /// Lowers one arithmetic, comparison or texture instruction.
    pub fn instruction(&mut self, ins: &Instruction) -> Result<(), TranslateError> {
        let quad = Some(VectorSize::Quad);
        match ins.op {
            Opcode::Nop => {}
            Opcode::Mov | Opcode::Abs => {
                let a = self.src(ins, 0)?;
                let v = if ins.op == Opcode::Abs {
                    self.fb.math(M::Abs, &[a])
                } else {
                    a
                };
                self.write(ins, v, 0b1111)?;
            }
            Opcode::Add | Opcode::Sub | Opcode::Min | Opcode::Max => {
                let (a, b) = (self.src(ins, 0)?, self.src(ins, 1)?);
                let v = match ins.op {
                    Opcode::Add => self.fb.binary(B::Add, a, b),
                    Opcode::Sub => self.fb.binary(B::Subtract, a, b),
                    Opcode::Min => self.fb.math(M::Min, &[a, b]),
                    _ => self.fb.math(M::Max, &[a, b]),
                };
                self.write(ins, v, 0b1111)?;
            }
            Opcode::Mul => {
                let (a, b) = (self.src(ins, 0)?, self.src(ins, 1)?);
                let v = self.mul(a, b, quad);
                self.write(ins, v, 0b1111)?;
            }
            Opcode::Mad => {
                let (a, b, c) = (self.src(ins, 0)?, self.src(ins, 1)?, self.src(ins, 2)?);
                let p = self.mul(a, b, quad);
                let v = self.fb.binary(B::Add, p, c);
                self.write(ins, v, 0b1111)?;
            }
            Opcode::Lrp => {
                let (a, b, c) = (self.src(ins, 0)?, self.src(ins, 1)?, self.src(ins, 2)?);
                let one = self.fb.f32(1.0);
                let ones = self.splat4(one);
                let rest = self.fb.binary(B::Subtract, ones, a);
                let ab = self.mul(a, b, quad);
                let rc = self.mul(rest, c, quad);
                let v = self.fb.binary(B::Add, ab, rc);
                self.write(ins, v, 0b1111)?;
            }
            Opcode::Rcp | Opcode::Rsq | Opcode::Exp | Opcode::Log => {
                let x = self.scalar_src(ins, 0)?;
                let v = match ins.op {
                    Opcode::Rcp => {
                        let one = self.fb.f32(1.0);
                        self.fb.binary(B::Divide, one, x)
                    }
                    Opcode::Rsq => self.rsq(x),
                    Opcode::Exp => self.fb.math(M::Exp2, &[x]),
                    _ => self.log(x),
                };
                self.write_scalar(ins, v)?;
            }
            Opcode::Pow => {
                let (a, b) = (self.scalar_src(ins, 0)?, self.scalar_src(ins, 1)?);
                let v = self.pow(a, b);
                self.write_scalar(ins, v)?;
            }
            Opcode::Frc => {
                let a = self.src(ins, 0)?;
                let v = self.frc(a);
                self.write(ins, v, 0b1111)?;
            }
            Opcode::Dp3 | Opcode::Dp4 => {
                let (a, b) = (self.src(ins, 0)?, self.src(ins, 1)?);
                let n = if ins.op == Opcode::Dp3 { 3 } else { 4 };
                let v = self.dot(a, b, n);
                self.write_scalar(ins, v)?;
            }
            Opcode::Dp2Add => {
                let (a, b) = (self.src(ins, 0)?, self.src(ins, 1)?);
                let c = self.scalar_src(ins, 2)?;
                let d = self.dot(a, b, 2);
                let v = self.fb.binary(B::Add, d, c);
                self.write_scalar(ins, v)?;
            }
            Opcode::M4x4 | Opcode::M4x3 | Opcode::M3x4 | Opcode::M3x3 | Opcode::M3x2 => {
                self.matrix(ins)?
            }
            Opcode::Crs => {
                let (a, b) = (self.src(ins, 0)?, self.src(ins, 1)?);
                let (a, b) = (self.first(a, 3), self.first(b, 3));
                let c = self.fb.math(M::Cross, &[a, b]);
                let zero = self.fb.f32(0.0);
                let parts = [self.comp(c, 0), self.comp(c, 1), self.comp(c, 2), zero];
                let v = self.compose4(parts);
                self.write(ins, v, 0b0111)?;
            }
            Opcode::Nrm => self.nrm(ins)?,
            Opcode::SinCos => {
                let x = self.scalar_src(ins, 0)?;
                let zero = self.fb.f32(0.0);
                let parts = [
                    self.fb.math(M::Cos, &[x]),
                    self.fb.math(M::Sin, &[x]),
                    zero,
                    zero,
                ];
                let v = self.compose4(parts);
                self.write(ins, v, 0b0011)?;
            }
            Opcode::Cmp => {
                let (a, b, c) = (self.src(ins, 0)?, self.src(ins, 1)?, self.src(ins, 2)?);
                let zero = self.zero4();
                let ge = self.fb.binary(B::GreaterEqual, a, zero);
                let v = self.fb.select(ge, b, c);
                self.write(ins, v, 0b1111)?;
            }
            Opcode::Dsx | Opcode::Dsy => {
                let a = self.src(ins, 0)?;
                let axis = if ins.op == Opcode::Dsx {
                    naga::DerivativeAxis::X
                } else {
                    naga::DerivativeAxis::Y
                };
                let v = self.fb.add(Expression::Derivative {
                    axis,
                    ctrl: naga::DerivativeControl::Coarse,
                    expr: a,
                });
                self.write(ins, v, 0b1111)?;
            }
            Opcode::Setp => self.setp(ins)?,
            Opcode::TexKill => self.texkill(ins)?,
            Opcode::TexLd | Opcode::TexLdP | Opcode::TexLdB | Opcode::TexLdL | Opcode::TexLdD => {
                self.texture(ins)?
            }
            op if self.cx.vertex.is_some() => self.vertex_instruction(ins, op)?,
            op => {
                return Err(TranslateError::Unsupported(format!(
                    "`{op}` outside the flow-control lowering"
                )))
            }
        }
        Ok(())
    }

    /// `m4x4` … `m3x2`: component k is the dot product with register src1 + k.
    fn matrix(&mut self, ins: &Instruction) -> Result<(), TranslateError> {
        let (rows, dims) = ins.op.matrix_shape().unwrap_or((4, 4));
        let a = self.src(ins, 0)?;
        let m = *ins
            .src
            .get(1)
            .ok_or(TranslateError::Internal("a missing matrix operand"))?;
        let zero = self.fb.f32(0.0);
        let mut parts = [zero; 4];
        for (k, part) in parts.iter_mut().enumerate().take(rows as usize) {
            let mut row = m;
            row.reg.index += k as u32;
            let r = self.read(&row)?;
            *part = self.dot(a, r, dims);
        }
        let v = self.compose4(parts);
        self.write(ins, v, (1u8 << rows) - 1)
    }

    /// `nrm`: src · scale(x² + y² + z²) on all four components.
    fn nrm(&mut self, ins: &Instruction) -> Result<(), TranslateError> {
        let a = self.src(ins, 0)?;
        let f = self.dot(a, a, 3);
        let s = self.nrm_scale(f);
        let s4 = self.splat4(s);
        let v = self.mul(a, s4, Some(VectorSize::Quad));
        self.write(ins, v, 0b1111)
    }

    /// The comparison of `a` and `b` (scalars or vectors).
    pub fn compare(&mut self, cmp: Compare, a: Expr, b: Expr) -> Expr {
        let op = match cmp {
            Compare::Gt => B::Greater,
            Compare::Lt => B::Less,
            Compare::Ge => B::GreaterEqual,
            Compare::Le => B::LessEqual,
            Compare::Eq => B::Equal,
            Compare::Ne => B::NotEqual,
        };
        self.fb.binary(op, a, b)
    }

    /// `setp_comp p0.mask, a, b`, predicated per component.
    fn setp(&mut self, ins: &Instruction) -> Result<(), TranslateError> {
        let cmp = ins
            .compare
            .ok_or(TranslateError::Internal("setp without a comparison"))?;
        let (a, b) = (self.src(ins, 0)?, self.src(ins, 1)?);
        let bits = self.compare(cmp, a, b);
        let mask = ins.dst.map_or(0b1111, |d| d.mask.0);
        let p0 = self.cx.var(&mut self.fb, self.cx.p0);
        for c in 0..4 {
            if mask & (1 << c) == 0 {
                continue;
            }
            let mut v = self.comp(bits, c as u32);
            if let Some(p) = self.predicate(ins, c) {
                let target = self.fb.index(p0, c as u32);
                let old = self.fb.load(target);
                v = self.fb.select(p, v, old);
            }
            let target = self.fb.index(p0, c as u32);
            self.fb.store(target, v);
        }
        Ok(())
    }

    /// `texkill`: the pixel is marked killed if any of the masked x, y, z,
    /// w is below zero (ps_2_0 and later test all four, as `emu/arith.rs`); it keeps running (D3D9 only flags it, and the
    /// emulator keeps it as a neighbour for gradients) and is discarded at
    /// the end.
    fn texkill(&mut self, ins: &Instruction) -> Result<(), TranslateError> {
        let d = ins
            .dst
            .ok_or(TranslateError::Internal("texkill without an operand"))?;
        let v = self.reg(d.reg, false)?;
        let zero = self.fb.f32(0.0);
        let mut any: Option<Expr> = None;
        for c in 0..4 {
            if !d.mask.has(c) {
                continue;
            }
            let x = self.comp(v, c as u32);
            let mut below = self.fb.binary(B::Less, x, zero);
            if let Some(p) = self.predicate(ins, c) {
                below = self.fb.binary(B::LogicalAnd, below, p);
            }
            any = Some(match any {
                Some(a) => self.fb.binary(B::LogicalOr, a, below),
                None => below,
            });
        }
        if let Some(kill) = any {
            let p = self.cx.var(&mut self.fb, self.cx.killed);
            let was = self.fb.load(p);
            let now = self.fb.binary(B::LogicalOr, was, kill);
            self.fb.store(p, now);
        }
        Ok(())
    }
}
