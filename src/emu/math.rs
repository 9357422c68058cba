//! Scalar semantics of ps_3_0 arithmetic, special values included.
//!
//! These functions are the single place where the emulator decides what an
//! instruction computes for one lane; the executor maps them over lanes. Each
//! special-value rule names the Microsoft page it follows (pages under
//! learn.microsoft.com/windows/win32/direct3dhlsl/, tags as in
//! `ps_3_0-facts.md` §1). Everything is `f32`: ps_3_0 full precision is IEEE
//! single precision, and `_pp` (partial precision, "implementations may
//! ignore it", MS-MOD) is ignored, i.e. computed in full precision too.

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
/// (MS `log---ps`).
#[inline(always)]
pub fn log(x: f32) -> f32 {
    let v = x.abs();
    if v == 0.0 {
        -FLT_MAX
    } else {
        v.log2()
    }
}

/// `pow`: |a|^b (MS `pow---ps`). The page does not define 0^0 or 0^negative
/// (UNCONFIRMED); we use `powf`, which gives 0^0 = 1, 0^-y = +inf, 0^+y = 0.
/// These match the page's suggested expansion exp(b·log(a)) with
/// log(0) = -FLT_MAX — an inference, not a documented rule.
#[inline(always)]
pub fn pow(a: f32, b: f32) -> f32 {
    a.abs().powf(b)
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
