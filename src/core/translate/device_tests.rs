//! `Entry::Geometry` for a whole draw in one render pass: the device runs
//! the draw's depth and stencil tests and keeps its primitives in order
//! itself, so the entry point must hand it what the CPU's tests would have
//! read — `texkill` as a discard, the depth in the surface's stored form —
//! and count what the per-primitive path counts on the CPU.
//!
//! * **Counts.** Each covered pixel adds one to its triangle's first
//!   counter and, killed, one to its second (`ps30_counts`, group
//!   [`COUNTS_GROUP`], an array of `2 × triangles` atomics indexed by
//!   `@builtin(primitive_index)`). Helper invocations make no atomic
//!   writes (Vulkan 1.3, "Helper Invocations"), so only covered pixels
//!   count.
//! * **Depth.** A D16 or D24 surface stores `k = round(z·(2ᵇ − 1))`, half
//!   away from zero (`core/raster/depth.rs`, in f64). The shader computes
//!   the same `k` exactly in f32 and writes `k·2⁻ᵇ` as the fragment's depth
//!   into a 32-bit float surface: a power-of-two scale of an integer below
//!   2²⁴, so stored exactly, and ordered and equal exactly as the `k` are,
//!   which is all a depth comparison reads. The exact `k`: with
//!   `A = z·2ᵇ` (exact), `z·(2ᵇ − 1) = ⌊A⌋ + (f − z)` where `f = A − ⌊A⌋`
//!   (exact); `f − z` lies in (−1, 1), so `k = ⌊A⌋ + [f − ½ ≥ z] −
//!   [f + ½ < z]`. For `A ≥ 1`, `f` is a multiple of 2⁻²³ below 1 and both
//!   `f ± ½` are exact; for `A < 1`, `k` is 1 exactly when `A − ½ ≥ z`
//!   (exact for `A ≥ ¼`; below that both tests are false, as they must be).
//!   A D32F surface stores z itself. NaN stores 0 and z is clamped to
//!   [0, 1] first, as the CPU's store does.

use super::builder::{Expr, Fb};
use super::interface;
use naga::{
    AddressSpace, ArraySize, BinaryOperator, Binding, Expression, GlobalVariable, Handle,
    MathFunction, Module, ResourceBinding, Scalar, Span, Statement, StorageAccess, StructMember,
    Type, TypeInner,
};

/// The bind group of the counters.
pub const COUNTS_GROUP: u32 = 1;

/// The counters' binding in [`COUNTS_GROUP`].
pub const COUNTS_BINDING: u32 = 0;

/// How the draw's depth-stencil surface stores a depth.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DepthStore {
    /// An unsigned normalised integer of this many bits (16 or 24).
    Unorm(u8),
    /// A 32-bit float (D3DFMT_D32F_LOCKABLE).
    Float,
}

/// What the device tests itself in a draw of one render pass.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DeviceTests {
    /// The depth surface's stored form, where the draw has one: the entry
    /// point writes `@builtin(frag_depth)` in it.
    pub depth: Option<DepthStore>,
    /// The alpha test, where the draw has one that can fail.
    pub alpha: Option<AlphaDiscard>,
}

/// The alpha test as the entry point runs it on oC0's alpha `a`: `x = a`
/// (float targets) or `x = roundEven(a · scale)` in f32 (fixed-point
/// ones), then `x func reference`, and a discard where that fails. This is
/// `AlphaTest::compared` and `CmpFunc::passes` of the draw list's pixel
/// state, operation for operation: f32 multiplication is correctly rounded
/// on Vulkan (1.3, "Precision and Operation of SPIR-V Instructions") and
/// `round` is WGSL's half-to-even. The comparison is made on integers,
/// not floats, so that a device that treats subnormals as zero in float
/// comparisons, or a compiler that rewrites `!(x < r)` as `x ≥ r`, cannot
/// change it: for floats that are not NaN, `key(x) = ±(bits(x) & 0x7fffffff)`
/// (the sign taken from the sign bit) orders exactly as the floats do,
/// −0 = +0 included; a NaN `x` passes only `NOTEQUAL`, as an unordered
/// comparison does on the CPU.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct AlphaDiscard {
    /// The scale of a fixed-point comparison (255 or 32767), `None` for
    /// the float alpha itself.
    pub scale: Option<u32>,
    /// The bits of the f32 the alpha is compared against.
    pub reference: u32,
    /// The comparison that passes (`x op reference`); `None` for
    /// D3DCMP_NEVER, which no pixel passes.
    pub func: Option<BinaryOperator>,
}

/// [`AlphaDiscard`]'s order key of the f32 with bits `bits`.
pub fn order_key(bits: u32) -> i32 {
    let magnitude = (bits & 0x7fff_ffff) as i32;
    if bits >> 31 == 1 {
        -magnitude
    } else {
        magnitude
    }
}

/// After the counts: discards a pixel whose oC0 (`oc0`, the shader's
/// output variable) fails `alpha` ([`AlphaDiscard`] gives the arithmetic).
fn alpha_discard(fb: &mut Fb, oc0: Handle<GlobalVariable>, alpha: AlphaDiscard) {
    let Some(op) = alpha.func else {
        fb.push(Statement::Kill);
        return;
    };
    let p = fb.add(Expression::GlobalVariable(oc0));
    let colour = fb.load(p);
    let mut x = fb.index(colour, 3);
    if let Some(scale) = alpha.scale {
        let scale = fb.f32(scale as f32);
        let scaled = fb.binary(BinaryOperator::Multiply, x, scale);
        x = fb.math(MathFunction::Round, &[scaled]);
    }
    let bits = fb.add(Expression::As {
        expr: x,
        kind: naga::ScalarKind::Uint,
        convert: None,
    });
    let mask = fb.u32(0x7fff_ffff);
    let magnitude = fb.binary(BinaryOperator::And, bits, mask);
    let infinity = fb.u32(0x7f80_0000);
    let nan = fb.binary(BinaryOperator::Greater, magnitude, infinity);
    let sign_mask = fb.u32(0x8000_0000);
    let sign = fb.binary(BinaryOperator::And, bits, sign_mask);
    let zero = fb.u32(0);
    let negative = fb.binary(BinaryOperator::NotEqual, sign, zero);
    let signed = fb.add(Expression::As {
        expr: magnitude,
        kind: naga::ScalarKind::Sint,
        convert: None,
    });
    let minus = fb.negate(signed);
    let key = fb.select(negative, minus, signed);
    let reference = fb.i32(order_key(alpha.reference));
    let ordered = fb.binary(op, key, reference);
    let unordered = fb.bool(op == BinaryOperator::NotEqual);
    let passes = fb.select(nan, unordered, ordered);
    let fails = fb.not(passes);
    fb.if_then(fails, |fb| fb.push(Statement::Kill));
}

/// The counters' global: `array<atomic<u32>>` in storage.
pub(super) fn counts(m: &mut Module) -> Handle<GlobalVariable> {
    let mut ty = |inner| m.types.insert(Type { name: None, inner }, Span::UNDEFINED);
    let atomic = ty(TypeInner::Atomic(Scalar::U32));
    let array = ty(TypeInner::Array {
        base: atomic,
        size: ArraySize::Dynamic,
        stride: 4,
    });
    m.global_variables.append(
        GlobalVariable {
            name: Some("ps30_counts".into()),
            space: AddressSpace::Storage {
                access: StorageAccess::LOAD | StorageAccess::STORE,
            },
            binding: Some(ResourceBinding {
                group: COUNTS_GROUP,
                binding: COUNTS_BINDING,
            }),
            ty: array,
            init: None,
            memory_decorations: Default::default(),
        },
        Span::UNDEFINED,
    )
}

/// After `ps_main`: counts the pixel for triangle `primitive` and, where
/// the shader's `killed` flag (if it kills) is set, counts it again and
/// discards it; then discards it where its oC0 (the variable, where the
/// shader writes one) fails the alpha test ([`alpha_discard`]).
pub(super) fn count_and_kill(
    fb: &mut Fb,
    counts: Handle<GlobalVariable>,
    primitive: Expr,
    killed: Option<Handle<GlobalVariable>>,
    alpha: Option<(Handle<GlobalVariable>, AlphaDiscard)>,
) {
    let add = |fb: &mut Fb, second: bool| {
        let base = fb.add(Expression::GlobalVariable(counts));
        let two = fb.u32(2);
        let first = fb.binary(BinaryOperator::Multiply, primitive, two);
        let index = match second {
            true => {
                let one = fb.u32(1);
                fb.binary(BinaryOperator::Add, first, one)
            }
            false => first,
        };
        let pointer = fb.add(Expression::Access { base, index });
        let value = fb.u32(1);
        fb.push(Statement::Atomic {
            pointer,
            fun: naga::AtomicFunction::Add,
            value,
            result: None,
        });
    };
    add(fb, false);
    if let Some(k) = killed {
        let p = fb.add(Expression::GlobalVariable(k));
        let killed = fb.load(p);
        fb.if_then(killed, |fb| {
            add(fb, true);
            fb.push(Statement::Kill);
        });
    }
    if let Some((oc0, a)) = alpha {
        alpha_discard(fb, oc0, a);
    }
}

/// The depth `z` (f32) as `store` keeps it, in the form the module docs
/// give (an exact power-of-two scale of the stored integer).
pub(super) fn stored_depth(fb: &mut Fb, z: Expr, store: DepthStore) -> Expr {
    let nan = fb.add(Expression::Relational {
        fun: naga::RelationalFunction::IsNan,
        argument: z,
    });
    let zero = fb.f32(0.0);
    let z = fb.select(nan, zero, z);
    let z = fb.math(MathFunction::Saturate, &[z]);
    let DepthStore::Unorm(bits) = store else {
        return z;
    };
    let scale = fb.f32((2.0f64).powi(i32::from(bits)) as f32);
    let a = fb.binary(BinaryOperator::Multiply, z, scale);
    let whole = fb.math(MathFunction::Floor, &[a]);
    let f = fb.binary(BinaryOperator::Subtract, a, whole);
    let half = fb.f32(0.5);
    let below = fb.binary(BinaryOperator::Subtract, f, half);
    let above = fb.binary(BinaryOperator::Add, f, half);
    let up = fb.binary(BinaryOperator::GreaterEqual, below, z);
    let down = fb.binary(BinaryOperator::Less, above, z);
    let (one, none) = (fb.f32(1.0), fb.f32(0.0));
    let plus = fb.select(up, one, none);
    let (one, none) = (fb.f32(1.0), fb.f32(0.0));
    let minus = fb.select(down, one, none);
    let k = fb.binary(BinaryOperator::Add, whole, plus);
    let k = fb.binary(BinaryOperator::Subtract, k, minus);
    let unit = fb.f32((2.0f64).powi(-i32::from(bits)) as f32);
    fb.binary(BinaryOperator::Multiply, k, unit)
}

/// The one-pass entry point's outputs after the colours (appended to
/// `members` and `values` from byte `offset`; returns the next offset):
/// `@location(4)` = 1.0, a pixel the device wrote, and the depth as
/// `tests` stores it in `@builtin(frag_depth)` (`oDepth` where written,
/// else the rasterised z).
/// `odepth` is the shader's `oDepth` variable, if it writes one; `f32` the
/// module's float type.
pub(super) fn outputs(
    fb: &mut Fb,
    (tests, f32, odepth): (DeviceTests, Handle<Type>, Option<Handle<GlobalVariable>>),
    position: Expr,
    (members, values): (&mut Vec<StructMember>, &mut Vec<Expr>),
    mut offset: u32,
) -> u32 {
    members.push(StructMember {
        name: Some("written".into()),
        ty: f32,
        binding: Some(Binding::Location {
            location: interface::GEOMETRY_FLAGS_LOCATION,
            interpolation: None,
            sampling: None,
            blend_src: None,
            per_primitive: false,
        }),
        offset,
    });
    values.push(fb.f32(1.0));
    offset += 4;
    if let Some(store) = tests.depth {
        let z = match odepth {
            Some(o) => {
                let p = fb.add(Expression::GlobalVariable(o));
                let d = fb.load(p);
                fb.index(d, 0)
            }
            None => fb.index(position, 2),
        };
        members.push(StructMember {
            name: Some("depth".into()),
            ty: f32,
            binding: Some(Binding::BuiltIn(naga::BuiltIn::FragDepth)),
            offset,
        });
        values.push(stored_depth(fb, z, store));
        offset += 4;
    }
    offset
}

#[cfg(test)]
mod tests {
    /// [`super::order_key`] orders every pair of non-NaN floats as `<`,
    /// `==` and `>` do, signed zeros, subnormals and infinities included.
    #[test]
    fn the_alpha_tests_integer_key_orders_as_the_floats() {
        let v = [
            f32::NEG_INFINITY,
            -3e38,
            -1.0,
            -1e-40,
            -f32::from_bits(1),
            -0.0,
            0.0,
            f32::from_bits(1),
            1e-40,
            f32::MIN_POSITIVE,
            128.0 / 255.0,
            1.0,
            16448.0,
            3e38,
            f32::INFINITY,
        ];
        for a in v {
            for b in v {
                let (ka, kb) = (super::order_key(a.to_bits()), super::order_key(b.to_bits()));
                assert_eq!(ka.cmp(&kb), a.partial_cmp(&b).unwrap(), "{a:e} vs {b:e}");
            }
        }
    }

    /// [`super::stored_depth`]'s arithmetic, step for step in f32.
    fn shader_k(z: f32, bits: i32) -> f32 {
        let z = if z.is_nan() { 0.0 } else { z.clamp(0.0, 1.0) };
        let a = z * 2f32.powi(bits);
        let whole = a.floor();
        let f = a - whole;
        let up = f - 0.5 >= z;
        let down = f + 0.5 < z;
        whole + f32::from(u8::from(up)) - f32::from(u8::from(down))
    }

    /// `core/raster/depth.rs`'s rounding of the f32 depth, in f64.
    fn stored_k(z: f32, bits: i32) -> f64 {
        let z = if z.is_nan() {
            0.0
        } else {
            f64::from(z).clamp(0.0, 1.0)
        };
        (z * (2f64.powi(bits) - 1.0)).round()
    }

    /// Every f32 next to each exact half `(n + ½)/(2ᵇ − 1)` and each
    /// integer level, where a rounding error would show, and a sweep of
    /// the whole range: the shader's k is the stored one.
    #[test]
    fn the_shader_rounds_a_depth_as_the_surface_stores_it() {
        for bits in [16, 24] {
            let max = 2f64.powi(bits) - 1.0;
            let mut zs: Vec<f32> = vec![0.0, 1.0, -0.5, 2.0, f32::NAN, 1e-30, 0.5];
            let step = (max as u64 / 5000).max(1);
            for n in (0..max as u64)
                .step_by(step as usize)
                .chain([0, 1, 2, max as u64 - 1])
            {
                for c in [(n as f64 + 0.5) / max, n as f64 / max] {
                    let z = c as f32;
                    zs.extend([z, z.next_up(), z.next_down()]);
                }
            }
            for z in zs {
                assert_eq!(
                    f64::from(shader_k(z, bits)),
                    stored_k(z, bits),
                    "z = {z:e} ({:#x}), {bits} bits",
                    z.to_bits()
                );
            }
        }
    }
}
