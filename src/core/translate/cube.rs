//! Cube maps sampled as Direct3D 9 hardware samples them, on a device whose
//! cube sampling is seamless.
//!
//! Every Vulkan device filters a cube view across face edges (Vulkan's
//! "Cube Map Edge Handling"; turning it off needs an extension wgpu does not
//! expose), where Direct3D 9 hardware filters each face alone and clamps at
//! its edge. Where the sampler's [`SamplerSpec`](super::SamplerSpec) asks
//! for `faces`, the GPU backend binds the cube's six faces as a 2D array
//! (D3DCUBEMAP_FACES order, which is the layer order) with CLAMP, and the
//! shader does what the emulator does (`core/emu/layered.rs`), in the same
//! operations and order:
//!
//! * the face is the major axis of the direction, ties to z, then y (the
//!   precedence Direct3D 11.3 states), its sign the sign bit of the major
//!   component;
//! * (sc, tc, ma) from Direct3D's cube-map table, s = (sc/|ma| + 1)·½ and
//!   t = (tc/|ma| + 1)·½;
//! * `texldd`'s direction gradients become face gradients by the quotient
//!   rule, ∂s = (∂sc − (sc/|ma|)·∂ma′)/(2·|ma|), ∂ma′ the gradient of the
//!   major component with the face's sign;
//! * `texld`, `texldp` and `texldb` take the quad's coarse differences of
//!   (s, t) as explicit gradients (scaled by 2^bias), which are the
//!   emulator's within a quad whose pixels share a face (a quad across a
//!   face edge is projected on its top-left pixel's face by the emulator,
//!   and differenced per pixel here). Explicit, because llvmpipe takes
//!   the last level of a 2D array (and of a volume) where the implicit
//!   derivatives are zero, where Direct3D 9 and Vulkan take level 0;
//! * `texldl` takes src0.w, as on any texture.

use super::builder::Expr;
use super::lower::Lower;
use naga::{
    BinaryOperator as B, DerivativeAxis, DerivativeControl, Expression, MathFunction as M,
    SampleLevel, VectorSize,
};

/// Which face a direction selects, as expressions.
#[derive(Clone, Copy)]
struct Axis {
    /// The direction's z is the major axis.
    is_z: Expr,
    /// Its y is (when z is not).
    is_y: Expr,
    /// The major component's sign bit is set: the negative face.
    negative: Expr,
}

/// A direction on its face.
pub(super) struct Face {
    axis: Axis,
    /// The face as a layer index, 0 (+X) … 5 (−Z).
    pub layer: Expr,
    /// |ma|, the major component's magnitude.
    m: Expr,
    /// (sc/|ma|, tc/|ma|).
    q: (Expr, Expr),
    /// (s, t) as a 2D coordinate of the face.
    pub st: Expr,
}

impl Lower<'_> {
    /// The face of direction `d` (a vec3 whose components are finite) and
    /// its (s, t).
    pub(super) fn cube_face(&mut self, d: Expr) -> Face {
        let [x, y, z] = [0, 1, 2].map(|c| self.comp(d, c));
        let [ax, ay, az] = [x, y, z].map(|v| self.fb.math(M::Abs, &[v]));
        let z_over_x = self.fb.binary(B::GreaterEqual, az, ax);
        let z_over_y = self.fb.binary(B::GreaterEqual, az, ay);
        let is_z = self.fb.binary(B::LogicalAnd, z_over_x, z_over_y);
        let is_y = self.fb.binary(B::GreaterEqual, ay, ax);
        let major = self.pick(is_z, is_y, [x, y, z]);
        let bits = self.fb.add(Expression::As {
            expr: major,
            kind: naga::ScalarKind::Uint,
            convert: None,
        });
        let sign = self.fb.u32(0x7fff_ffff);
        let negative = self.fb.binary(B::Greater, bits, sign);
        let [i0, i1, i2] = [0, 2, 4].map(|v| self.fb.u32(v));
        let first = self.pick(is_z, is_y, [i0, i1, i2]);
        let (zero, one) = (self.fb.u32(0), self.fb.u32(1));
        let side = self.fb.select(negative, one, zero);
        let layer = self.fb.binary(B::Add, first, side);
        let axis = Axis {
            is_z,
            is_y,
            negative,
        };
        let m = self.fb.math(M::Abs, &[major]);
        let (sc, tc, _) = self.face_axes(axis, d);
        let q = (
            self.fb.binary(B::Divide, sc, m),
            self.fb.binary(B::Divide, tc, m),
        );
        let (one, half) = (self.fb.f32(1.0), self.fb.f32(0.5));
        let [s, t] = [q.0, q.1].map(|v| {
            let v = self.fb.binary(B::Add, v, one);
            self.fb.binary(B::Multiply, v, half)
        });
        let st = self.fb.add(Expression::Compose {
            ty: self.cx.t.vec2,
            components: vec![s, t],
        });
        Face {
            axis,
            layer,
            m,
            q,
            st,
        }
    }

    /// The face gradient (∂s, ∂t), a vec2, of the direction gradient `g`
    /// (a vec3) at the direction whose face is `face` (the quotient rule of
    /// the module docs).
    pub(super) fn cube_gradient(&mut self, face: &Face, g: Expr) -> Expr {
        let (dsc, dtc, dma) = self.face_axes(face.axis, g);
        let flipped = self.fb.negate(dma);
        let dm = self.fb.select(face.axis.negative, flipped, dma);
        let two = self.fb.f32(2.0);
        let twice_m = self.fb.binary(B::Multiply, two, face.m);
        let [ds, dt] = [(dsc, face.q.0), (dtc, face.q.1)].map(|(dc, q)| {
            let moved = self.fb.binary(B::Multiply, q, dm);
            let diff = self.fb.binary(B::Subtract, dc, moved);
            self.fb.binary(B::Divide, diff, twice_m)
        });
        self.fb.add(Expression::Compose {
            ty: self.cx.t.vec2,
            components: vec![ds, dt],
        })
    }

    /// The implicit level of `texld`, `texldp` and `texldb` on `face`: the
    /// quad's coarse differences of (s, t) as explicit gradients, scaled by
    /// 2^`bias` where there is one (λ = log2 of their length, plus the bias).
    pub(super) fn face_gradients(&mut self, face: &Face, bias: Option<Expr>) -> SampleLevel {
        let [x, y] = [DerivativeAxis::X, DerivativeAxis::Y].map(|axis| {
            self.fb.add(Expression::Derivative {
                axis,
                ctrl: DerivativeControl::Coarse,
                expr: face.st,
            })
        });
        match bias {
            Some(b) => {
                let scale = self.fb.math(M::Exp2, &[b]);
                let scale = self.fb.splat(scale, VectorSize::Bi);
                SampleLevel::Gradient {
                    x: self.fb.binary(B::Multiply, x, scale),
                    y: self.fb.binary(B::Multiply, y, scale),
                }
            }
            None => SampleLevel::Gradient { x, y },
        }
    }

    /// (sc, tc, ma) of the vec3 `v` on the face of `axis` (Direct3D's table: +X (−z,
    /// −y, x), −X (z, −y, x), +Y (x, z, y), −Y (x, −z, y), +Z (x, −y, z),
    /// −Z (−x, −y, z)).
    fn face_axes(&mut self, axis: Axis, v: Expr) -> (Expr, Expr, Expr) {
        let [x, y, z] = [0, 1, 2].map(|c| self.comp(v, c));
        let [nx, ny, nz] = [x, y, z].map(|c| self.fb.negate(c));
        let neg = axis.negative;
        let sc_x = self.fb.select(neg, z, nz);
        let tc_y = self.fb.select(neg, nz, z);
        let sc_z = self.fb.select(neg, nx, x);
        let sc = self.pick(axis.is_z, axis.is_y, [sc_x, x, sc_z]);
        let tc = self.pick(axis.is_z, axis.is_y, [ny, tc_y, ny]);
        let ma = self.pick(axis.is_z, axis.is_y, [x, y, z]);
        (sc, tc, ma)
    }

    /// `[on x, on y, on z][major axis]`.
    fn pick(&mut self, is_z: Expr, is_y: Expr, [on_x, on_y, on_z]: [Expr; 3]) -> Expr {
        let xy = self.fb.select(is_y, on_y, on_x);
        self.fb.select(is_z, on_z, xy)
    }
}
