//! Scalar semantics of ps_3_0 arithmetic, special values included.
//!
//! These functions are the single place where the emulator decides what an
//! instruction computes for one lane; the executor maps them over lanes. Each
//! special-value rule names the Microsoft page it follows (pages under
//! learn.microsoft.com/windows/win32/direct3dhlsl/, tags as in
//! `ps_3_0-facts.md` §1). Everything is `f32`: ps_3_0 full precision is IEEE
//! single precision, and `_pp` (partial precision, "implementations may
//! ignore it", MS-MOD) is ignored, i.e. computed in full precision too.
//!
//! The functions without a prefix are the `d3d9` float rules
//! (`core/float_rules.rs`); `ieee_*` are the `ieee` set's, and [`zmul`] the
//! product of `d3d9-zero-mul`.

/// Largest finite f32 (FLT_MAX).
pub const FLT_MAX: f32 = f32::MAX;

/// The largest f32 below 1.0 (`frc` results stay in [0, 1)).
const BELOW_ONE: f32 = 1.0 - f32::EPSILON / 2.0;

/// Applies a source modifier given as `(and, xor)` masks on the bits: `abs`
/// clears the sign bit, `neg` flips it (so `-0.0` and NaN payloads behave like
/// IEEE negation and fabs). Source modifiers: MS "Source Register Modifiers"
/// (dx9-graphics-reference-asm-ps-registers-modifiers-source).
#[inline(always)]
pub fn modify(x: f32, and: u32, xor: u32) -> f32 {
    f32::from_bits((x.to_bits() & and) ^ xor)
}

/// `_sat`: clamp to [0, 1] (MS "Instruction Modifiers", MS-MOD). NaN
/// saturates to 0 because `f32::max` returns the non-NaN operand (the D3D10
/// rule; D3D9 does not say).
#[inline(always)]
#[allow(clippy::manual_clamp)] // f32::clamp would keep NaN
pub fn sat(x: f32) -> f32 {
    x.max(0.0).min(1.0)
}

/// `rcp`: 1/x. "A source of 0.0 yields infinity"; 1.0 gives exactly 1.0
/// (MS `rcp---ps`). IEEE division: -0.0 gives -infinity (the sign for -0.0 is
/// UNCONFIRMED in the docs; we keep IEEE).
#[inline(always)]
pub fn rcp(x: f32) -> f32 {
    1.0 / x
}

/// `rsq`: 1/sqrt(|x|), the absolute value taken first; 0.0 gives +infinity
/// (MS `rsq---ps`).
#[inline(always)]
pub fn rsq(x: f32) -> f32 {
    1.0 / x.abs().sqrt()
}

/// `exp`: 2^x (MS `exp---ps`). Overflow gives +infinity, as IEEE.
#[inline(always)]
pub fn exp(x: f32) -> f32 {
    x.exp2()
}

/// `log`: log2(|x|), the sign bit ignored; log(0) = -FLT_MAX, not -infinity
/// (MS `log---ps`); +inf gives +inf, NaN stays NaN.
///
/// log2 itself is [`log2`], a branch-free f32 port of fdlibm's `e_log2f.c`
/// (FreeBSD msun) so that the lane loop vectorises and results do not depend
/// on the platform's libm.
#[inline(always)]
pub fn log(x: f32) -> f32 {
    let v = x.abs();
    let bits = v.to_bits();
    let r = log2(v);
    if bits == 0 {
        -FLT_MAX
    } else if bits >= 0x7f80_0000 {
        v
    } else {
        r
    }
}

/// log2 of a positive, finite, non-zero f32 (other inputs give garbage; see
/// [`log`]). Error below 1 ulp (checked against f64 in the tests).
///
/// Algorithm and constants from FreeBSD msun `e_log2f.c` and `k_logf.h`:
///
/// > Copyright (C) 1993 by Sun Microsystems, Inc. All rights reserved.
/// > Developed at SunPro, a Sun Microsystems, Inc. business. Permission to
/// > use, copy, modify, and distribute this software is freely granted,
/// > provided that this notice is preserved.
#[inline(always)]
pub fn log2(x: f32) -> f32 {
    // Exact bit patterns (`from_bits` folds at compile time).
    let two25 = f32::from_bits(0x4c00_0000); // 2^25
    let ivln2hi = f32::from_bits(0x3fb8_b000); // 1/ln 2, high part
    let ivln2lo = f32::from_bits(0xb938_9ad4); // 1/ln 2, low part
                                               // |(log(1+s)-log(1-s))/s - Lg(s)| < 2**-34.24
    let lg1 = f32::from_bits(0x3f2a_aaaa); // 0xaaaaaa.0p-24
    let lg2 = f32::from_bits(0x3ecc_ce13); // 0xccce13.0p-25
    let lg3 = f32::from_bits(0x3e91_e9ee); // 0x91e9ee.0p-25
    let lg4 = f32::from_bits(0x3e78_9e26); // 0xf89e26.0p-26
    let sub = x.to_bits() < 0x0080_0000;
    let x = if sub { x * two25 } else { x };
    let hx = x.to_bits();
    let mut k = (hx >> 23) as i32 - 127 - if sub { 25 } else { 0 };
    let m = hx & 0x007f_ffff;
    // Normalise the mantissa to [sqrt(2)/2, sqrt(2)).
    let i = (m + 0x004a_fb0d) & 0x0080_0000;
    let xm = f32::from_bits(m | (i ^ 0x3f80_0000));
    k += (i >> 23) as i32;
    let y = k as f32;
    let f = xm - 1.0;
    let hfsq = 0.5 * f * f;
    // k_log1pf
    let s = f / (2.0 + f);
    let z = s * s;
    let w = z * z;
    let t1 = w * (lg2 + w * lg4);
    let t2 = z * (lg1 + w * lg3);
    let r = s * (hfsq + (t2 + t1));
    // Split f - hfsq into hi + lo to keep the product with 1/ln 2 exact.
    let hi = f32::from_bits((f - hfsq).to_bits() & 0xffff_f000);
    let lo = (f - hi) - hfsq + r;
    (lo + hi) * ivln2lo + lo * ivln2hi + hi * ivln2hi + y
}

/// `pow`: |a|^b (MS `pow---ps`). The page does not define 0^0 or 0^negative
/// (UNCONFIRMED); we use `powf`, which gives 0^0 = 1, 0^-y = +inf, 0^+y = 0.
/// These match the page's suggested expansion exp(b·log(a)) with
/// log(0) = -FLT_MAX — an inference, not a documented rule.
#[inline(always)]
pub fn pow(a: f32, b: f32) -> f32 {
    a.abs().powf(b)
}

/// `mova`: the address register's integer, x rounded to the nearest
/// integer with halves to even (0.5 → 0, 1.5 → 2, 2.5 → 2, −0.5 → 0,
/// −1.5 → −2), then converted saturating, NaN to 0 (Rust's `as`). The one
/// statement of the rule: the vertex stage computes by it and the
/// translation (`translate/vertex.rs`) emits naga's `round` (WGSL's and
/// SPIR-V's RoundEven) before the same conversion. Microsoft's `mova` page
/// says only "rounded to nearest" for vs_2_0 and later; vkd3d's
/// `non-const-indexing.shader_test`, recorded on Windows, indexes a
/// constant array by `mova` of 0.5 (element 0), 1.4 (element 1) and 1.5
/// (element 2), which rounding halves away from zero (1 for 0.5) and
/// truncation (1 for 1.5) both contradict and round-half-to-even fits.
pub fn mova(x: f32) -> i32 {
    x.round_ties_even() as i32
}

/// `frc`: x - floor(x), "result in [0,1)" (MS `frc---ps`). For tiny negative x
/// the f32 subtraction rounds to 1.0; we return the largest f32 below 1.0 so
/// the documented range holds.
#[inline(always)]
pub fn frc(x: f32) -> f32 {
    let f = x - x.floor();
    if f >= 1.0 {
        BELOW_ONE
    } else {
        f
    }
}

/// `cmp`: a >= 0 ? b : c per component (MS `cmp---ps`). IEEE comparison:
/// -0.0 >= 0 is true, NaN >= 0 is false (the docs do not say, UNCONFIRMED).
#[inline(always)]
pub fn cmp(a: f32, b: f32, c: f32) -> f32 {
    if a >= 0.0 {
        b
    } else {
        c
    }
}

/// `min`: the NaN rule is UNCONFIRMED for D3D9; `f32::min` returns the
/// non-NaN operand (IEEE minNum, the D3D10 rule).
#[inline(always)]
pub fn min(a: f32, b: f32) -> f32 {
    a.min(b)
}

/// `max`: see [`min`].
#[inline(always)]
pub fn max(a: f32, b: f32) -> f32 {
    a.max(b)
}

/// `lrp`: a·b + (1 - a)·c evaluated as written (MS `lrp---ps`).
#[inline(always)]
pub fn lrp(a: f32, b: f32, c: f32) -> f32 {
    a * b + (1.0 - a) * c
}

/// `mad`: a·b + c as a separate f32 multiply and add (two roundings). D3D9
/// does not say whether mad is fused; unfused is what a plain `mul` + `add`
/// sequence gives and what Rust computes without `mul_add`.
#[inline(always)]
pub fn mad(a: f32, b: f32, c: f32) -> f32 {
    a * b + c
}

/// The `nrm` scale for f = x²+y²+z²: (f != 0) ? 1/sqrt(f) : FLT_MAX
/// (MS `nrm---ps`); the destination is src·scale on all four components, w
/// included, so a zero xyz gives 0 in xyz and w·FLT_MAX in w.
#[inline(always)]
pub fn nrm_scale(f: f32) -> f32 {
    if f != 0.0 {
        1.0 / f.sqrt()
    } else {
        FLT_MAX
    }
}

/// `log` under the `ieee` rules: log2(x), −∞ at ±0, NaN below 0.
#[inline(always)]
pub fn ieee_log(x: f32) -> f32 {
    if x > 0.0 && x.is_finite() {
        log2(x)
    } else if x == 0.0 {
        f32::NEG_INFINITY
    } else if x == f32::INFINITY {
        x
    } else {
        f32::NAN
    }
}

/// `rsq` under the `ieee` rules: 1/sqrt(x), NaN below 0.
#[inline(always)]
pub fn ieee_rsq(x: f32) -> f32 {
    1.0 / x.sqrt()
}

/// `pow` under the `ieee` rules: IEEE 754's powr(a, b) = exp(b·log a),
/// defined for a ≥ 0: NaN for a < 0, for pow(0, 0), pow(∞, 0) and
/// pow(1, ±∞); elsewhere as `powf`.
#[inline(always)]
pub fn ieee_pow(a: f32, b: f32) -> f32 {
    let undefined = a < 0.0
        || a.is_nan()
        || b.is_nan()
        || (a == 0.0 || a == f32::INFINITY) && b == 0.0
        || a == 1.0 && b.is_infinite();
    if undefined {
        f32::NAN
    } else {
        a.powf(b)
    }
}

/// The `nrm` scale under the `ieee` rules: 1/sqrt(f) (+∞ for 0).
#[inline(always)]
pub fn ieee_nrm_scale(f: f32) -> f32 {
    1.0 / f.sqrt()
}

/// `frc` under the `ieee` rules: x − floor(x), which rounds to 1.0 for
/// tiny negative x.
#[inline(always)]
pub fn ieee_frc(x: f32) -> f32 {
    x - x.floor()
}

/// `a · b` under `d3d9-zero-mul`: 0 when either factor is 0 (0 × ∞ = 0).
#[inline(always)]
pub fn zmul(a: f32, b: f32) -> f32 {
    use crate::core::float_rules::zero_mul_operand as z;
    z(a, b) * z(b, a)
}
