//! The texld family and the sampler state WebGPU cannot express.
//!
//! | instruction | naga sample | level of detail |
//! |---|---|---|
//! | `texld`  | `textureSampleBias` | implicit, + `lod.x` (D3DSAMP_MIPMAPLODBIAS) |
//! | `texldp` | `textureSampleBias` on xy/w (xyz/w) | implicit from the divided coordinate, + `lod.x` |
//! | `texldb` | `textureSampleBias` | implicit, + src0.w + `lod.x` |
//! | `texldl` | `textureSampleLevel` | src0.w + `lod.y` |
//! | `texldd` | `textureSampleGrad` | from src2/src3, scaled by `lod.z` = 2^bias |
//!
//! (`lod`, `mirror_once`, `border_mode`, `border`: the `Ps30Sampler` of
//! `interface.rs`, filled by the application or by `core/gpu`.) Implicit
//! gradients are the device's — coarse or fine as it chooses, where the
//! emulator always takes one coarse difference per quad. The sampler's
//! swizzle (`s0.yzxw`) reorders the sampled value, as in the emulator.
//!
//! MIRRORONCE has no WebGPU address mode: the shader takes |u| on the axes
//! `mirror_once` marks and the sampler clamps to the edge (|u| then clamp
//! is the mode's definition). A BORDER colour other than the three WebGPU
//! offers is added by the shader: the sampler returns transparent black
//! outside, and `ps30_border` adds `border · (1 − w)`, w the weight of the
//! taps inside the texture on the marked axes (1 or 0 for point sampling;
//! the bilinear weights on level 0 for linear).
//!
//! A non-finite coordinate is replaced before the lookup (+∞ by 2, −∞ by
//! −1, NaN by 0, per axis) as the emulator does: under CLAMP a lookup at
//! ±∞ reads the edge texel, as Direct3D 9 hardware does, where Vulkan
//! leaves it undefined (docs/textures.md, "Non-finite coordinates").
//!
//! Each piece is emitted only where the sampler's [`SamplerSpec`] asks for
//! it (`specialise.rs`): without `lod` the levels come unbiased (`texld` an
//! implicit sample, `texldd` its gradients unscaled), without `mirror_once`
//! or `border` the coordinate and the value go untouched.

use super::builder::Expr;
use super::cube::Face;
use super::lower::Lower;
use super::specialise::{SamplerSpec, Specialisation};
use super::TranslateError;
use crate::core::ir::Instruction;
use crate::core::isa::{Opcode, SamplerType};
use naga::{BinaryOperator as B, Expression, MathFunction as M, SampleLevel, VectorSize};

/// Members of `Ps30Sampler`.
const LOD: u32 = 0;
const BORDER: u32 = 1;
const MIRROR_ONCE: u32 = 2;
const BORDER_MODE: u32 = 3;

impl Lower<'_> {
    /// A pointer to `ps30.s[k]`.
    fn sampler_state(&mut self, k: u32) -> Expr {
        let s = self.cx.block(&mut self.fb, 3);
        self.fb.index(s, k)
    }

    fn state_member(&mut self, k: u32, member: u32) -> Expr {
        let s = self.sampler_state(k);
        let p = self.fb.index(s, member);
        self.fb.load(p)
    }

    /// texld, texldp, texldb, texldl, texldd.
    pub fn texture(&mut self, ins: &Instruction) -> Result<(), TranslateError> {
        let s = *ins
            .src
            .get(1)
            .ok_or(TranslateError::Internal("texld without a sampler"))?;
        let k = s.reg.index;
        let tex = *self
            .cx
            .textures
            .get(&k)
            .ok_or(TranslateError::Internal("a sampler without a declaration"))?;
        let dims = if tex.ty == SamplerType::Tex2d { 2 } else { 3 };
        let a = self.src(ins, 0)?;
        let coord = if ins.op == Opcode::TexLdP {
            let w = self.comp(a, 3);
            let w4 = self.splat4(w);
            self.fb.binary(B::Divide, a, w4)
        } else {
            a
        };
        let coord = self.first(coord, dims);
        let mut coord = self.finite_coordinate(coord, dims);
        let spec = self.cx.spec.sampler(k);
        // A cube map bound as its faces: the face and its (s, t) found here.
        let face = (tex.ty == SamplerType::Cube && spec.faces).then(|| self.cube_face(coord));
        if tex.ty != SamplerType::Cube && spec.mirror_once {
            coord = self.mirror_once(k, coord, dims);
        }
        let level = self.level(ins, k, a, dims, spec, face.as_ref())?;
        let image = self.cx.var(&mut self.fb, tex.image);
        let sampler = self.cx.var(&mut self.fb, tex.sampler);
        let mut value = self.fb.add(Expression::ImageSample {
            image,
            sampler,
            gather: None,
            coordinate: face.as_ref().map_or(coord, |f| f.st),
            array_index: face.as_ref().map(|f| f.layer),
            offset: None,
            level,
            depth_ref: None,
            clamp_to_edge: false,
        });
        if tex.ty != SamplerType::Cube && spec.border {
            value = self.border(k, value, coord, dims, image);
        }
        if s.swizzle != crate::core::ir::Swizzle::IDENTITY {
            value = self.fb.add(Expression::Swizzle {
                size: VectorSize::Quad,
                vector: value,
                pattern: s.swizzle.0.map(|c| {
                    [
                        naga::SwizzleComponent::X,
                        naga::SwizzleComponent::Y,
                        naga::SwizzleComponent::Z,
                        naga::SwizzleComponent::W,
                    ][c as usize & 3]
                }),
            });
        }
        self.write(ins, value, 0b1111)
    }

    /// The sample's level of detail: the instruction's, with the sampler's
    /// bias from its record where `spec.lod` asks for it. On a cube bound as
    /// its faces, `texldd`'s gradients are taken to `face`, and the
    /// implicit level comes from the quad's coarse differences of (s, t)
    /// given as gradients (`cube.rs` says why).
    fn level(
        &mut self,
        ins: &Instruction,
        k: u32,
        a: Expr,
        dims: u32,
        spec: SamplerSpec,
        face: Option<&Face>,
    ) -> Result<SampleLevel, TranslateError> {
        let lod = spec.lod.then(|| self.state_member(k, LOD));
        // Adds component `c` of the record's `lod` to `v`, where read.
        let biased = |l: &mut Self, v: Expr, c: u32| match lod {
            Some(lod) => {
                let bias = l.comp(lod, c);
                l.fb.binary(B::Add, v, bias)
            }
            None => v,
        };
        if let (Some(f), Opcode::TexLd | Opcode::TexLdP | Opcode::TexLdB) = (face, ins.op) {
            // The quad's coarse differences of (s, t), scaled by 2^bias.
            let bias = if ins.op == Opcode::TexLdB {
                let w = self.comp(a, 3);
                Some(biased(self, w, 0))
            } else {
                lod.map(|lod| self.comp(lod, 0))
            };
            return Ok(self.face_gradients(f, bias));
        }
        Ok(match ins.op {
            Opcode::TexLdL => {
                let w = self.comp(a, 3);
                SampleLevel::Exact(biased(self, w, 1))
            }
            Opcode::TexLdB => {
                let w = self.comp(a, 3);
                SampleLevel::Bias(biased(self, w, 0))
            }
            Opcode::TexLdD => {
                let (gx, gy) = (self.src(ins, 2)?, self.src(ins, 3)?);
                let (gx, gy) = (self.first(gx, dims), self.first(gy, dims));
                let ((gx, gy), dims) = match face {
                    Some(f) => ((self.cube_gradient(f, gx), self.cube_gradient(f, gy)), 2),
                    None => ((gx, gy), dims),
                };
                match lod {
                    Some(lod) => {
                        let scale = self.comp(lod, 2);
                        let size = if dims == 2 {
                            VectorSize::Bi
                        } else {
                            VectorSize::Tri
                        };
                        let scale = self.fb.splat(scale, size);
                        SampleLevel::Gradient {
                            x: self.fb.binary(B::Multiply, gx, scale),
                            y: self.fb.binary(B::Multiply, gy, scale),
                        }
                    }
                    None => SampleLevel::Gradient { x: gx, y: gy },
                }
            }
            _ => match lod {
                Some(lod) => SampleLevel::Bias(self.comp(lod, 0)),
                None => SampleLevel::Auto,
            },
        })
    }

    /// The coordinate with +∞ replaced by 2, −∞ by −1 and NaN by 0 on each
    /// axis, as the emulator addresses it (`core/emu/sample.rs`,
    /// `finite_coordinate`): Vulkan leaves a lookup at a non-finite
    /// coordinate undefined. Tested on the bits, so that no float
    /// optimisation of the device's compiler can assume the values finite.
    fn finite_coordinate(&mut self, coord: Expr, dims: u32) -> Expr {
        let size = if dims == 2 {
            VectorSize::Bi
        } else {
            VectorSize::Tri
        };
        let bits = self.fb.add(Expression::As {
            expr: coord,
            kind: naga::ScalarKind::Uint,
            convert: None,
        });
        let splat_u = |l: &mut Self, v: u32| {
            let v = l.fb.u32(v);
            l.fb.splat(v, size)
        };
        let (abs_mask, inf) = (splat_u(self, 0x7fff_ffff), splat_u(self, 0x7f80_0000));
        let magnitude = self.fb.binary(B::And, bits, abs_mask);
        let is_nan = self.fb.binary(B::Greater, magnitude, inf);
        let is_inf = self.fb.binary(B::Equal, magnitude, inf);
        let negative = self.fb.binary(B::Greater, bits, abs_mask);
        let splat_f = |l: &mut Self, v: f32| {
            let v = l.fb.f32(v);
            l.fb.splat(v, size)
        };
        let (near, far, zero) = (splat_f(self, -1.0), splat_f(self, 2.0), splat_f(self, 0.0));
        let edge = self.fb.select(negative, near, far);
        let coord = self.fb.select(is_inf, edge, coord);
        self.fb.select(is_nan, zero, coord)
    }

    /// MIRRORONCE on the marked axes: |coordinate|.
    fn mirror_once(&mut self, k: u32, coord: Expr, dims: u32) -> Expr {
        let flags = self.state_member(k, MIRROR_ONCE);
        let flags = self.first(flags, dims);
        let size = if dims == 2 {
            VectorSize::Bi
        } else {
            VectorSize::Tri
        };
        let zero = self.fb.u32(0);
        let zero = self.fb.splat(zero, size);
        let on = self.fb.binary(B::NotEqual, flags, zero);
        let mirrored = self.fb.math(M::Abs, &[coord]);
        self.fb.select(on, mirrored, coord)
    }

    /// Adds the emulated border colour: a call of `ps30_border` (see the
    /// module docs and [`border_function`]).
    fn border(&mut self, k: u32, value: Expr, coord: Expr, dims: u32, image: Expr) -> Expr {
        let mode = self.state_member(k, BORDER_MODE);
        let colour = self.state_member(k, BORDER);
        let level = self.fb.i32(0);
        let size = self.fb.add(Expression::ImageQuery {
            image,
            query: naga::ImageQuery::Size { level: Some(level) },
        });
        let size = self.fb.add(Expression::As {
            expr: size,
            kind: naga::ScalarKind::Float,
            convert: Some(4),
        });
        let (coord, size) = if dims == 2 {
            let (zero, one) = (self.fb.f32(0.0), self.fb.f32(1.0));
            let parts = |l: &mut Self, v: Expr, last: Expr| {
                let (x, y) = (l.comp(v, 0), l.comp(v, 1));
                l.fb.add(Expression::Compose {
                    ty: l.cx.t.vec3,
                    components: vec![x, y, last],
                })
            };
            (parts(self, coord, zero), parts(self, size, one))
        } else {
            (coord, size)
        };
        let Some(function) = self.cx.border else {
            return value;
        };
        let result = self.fb.call_result(function);
        self.fb.push(naga::Statement::Call {
            function,
            arguments: vec![value, coord, size, mode, colour],
            result: Some(result),
        });
        result
    }
}

/// Adds `ps30_border` to the module when a 2D or volume sampler may need
/// it (a cube map never samples its border; `spec` may rule it out).
pub(super) fn add_border_function(
    m: &mut naga::Module,
    shader: &crate::core::ir::Shader,
    t: &super::module::Types,
    spec: &Specialisation,
) -> Option<naga::Handle<naga::Function>> {
    let needed = shader
        .program()
        .samplers
        .iter()
        .any(|d| d.ty != SamplerType::Cube && spec.sampler(d.index).border);
    needed.then(|| {
        m.functions
            .append(border_function(t), naga::Span::UNDEFINED)
    })
}

/// `ps30_border(value, coord, size, mode, colour)`: `value` when
/// `mode.w` is 0, else `value + colour · (1 − w)` with w the weight of the
/// taps inside the texture on the axes `mode.xyz` marks (point:
/// 0 ≤ c < 1; linear: taps t0 = ⌊c·n − ½⌋ and t0 + 1 with weights 1 − f
/// and f, each counted when it lies in [0, n)).
fn border_function(t: &super::module::Types) -> naga::Function {
    let mut fb = super::builder::Fb::new("ps30_border");
    let args = [
        ("value", t.vec4),
        ("coord", t.vec3),
        ("size", t.vec3),
        ("mode", t.uvec4),
        ("colour", t.vec4),
    ];
    for (name, ty) in args {
        fb.f.arguments.push(naga::FunctionArgument {
            name: Some(name.into()),
            ty,
            binding: None,
        });
    }
    fb.f.result = Some(naga::FunctionResult {
        ty: t.vec4,
        binding: None,
    });
    let [value, coord, size, mode, colour] =
        std::array::from_fn(|k| fb.add(Expression::FunctionArgument(k as u32)));
    let filter = fb.index(mode, 3);
    let uzero = fb.u32(0);
    let off = fb.binary(B::Equal, filter, uzero);
    fb.if_then(off, |fb| {
        fb.push(naga::Statement::Return { value: Some(value) })
    });
    let (zero, one, half) = (fb.f32(0.0), fb.f32(1.0), fb.f32(0.5));
    let utwo = fb.u32(2);
    let linear = fb.binary(B::Equal, filter, utwo);
    let mut inside = one;
    for axis in 0..3 {
        let c = fb.index(coord, axis);
        let n = fb.index(size, axis);
        // Point: the texel floor(c·n) is inside when 0 ≤ c < 1.
        let ge0 = fb.binary(B::GreaterEqual, c, zero);
        let lt1 = fb.binary(B::Less, c, one);
        let point_in = fb.binary(B::LogicalAnd, ge0, lt1);
        let point_w = fb.select(point_in, one, zero);
        // Linear: taps t0 and t0 + 1 with weights 1 − f and f.
        let cn = fb.binary(B::Multiply, c, n);
        let t = fb.binary(B::Subtract, cn, half);
        let t0 = fb.math(M::Floor, &[t]);
        let f = fb.binary(B::Subtract, t, t0);
        let t1 = fb.binary(B::Add, t0, one);
        let w0 = fb.binary(B::Subtract, one, f);
        let in0 = tap_inside(&mut fb, t0, n);
        let in1 = tap_inside(&mut fb, t1, n);
        let w0 = fb.select(in0, w0, zero);
        let w1 = fb.select(in1, f, zero);
        let linear_w = fb.binary(B::Add, w0, w1);
        let w = fb.select(linear, linear_w, point_w);
        let flag = fb.index(mode, axis);
        let marked = fb.binary(B::NotEqual, flag, uzero);
        let w = fb.select(marked, w, one);
        inside = fb.binary(B::Multiply, inside, w);
    }
    let outside = fb.binary(B::Subtract, one, inside);
    let outside = fb.splat(outside, VectorSize::Quad);
    let add = fb.binary(B::Multiply, colour, outside);
    let with = fb.binary(B::Add, value, add);
    fb.push(naga::Statement::Return { value: Some(with) });
    fb.finish()
}

/// Whether texel index `t` (a float) lies in [0, n).
fn tap_inside(fb: &mut super::builder::Fb, t: Expr, n: Expr) -> Expr {
    let zero = fb.f32(0.0);
    let ge0 = fb.binary(B::GreaterEqual, t, zero);
    let ltn = fb.binary(B::Less, t, n);
    fb.binary(B::LogicalAnd, ge0, ltn)
}
