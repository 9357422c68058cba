//! Tone mapping: the article's operator (Reinhard's global photographic
//! operator) run as ps_3_0 assembly in the emulator over a whole image, with
//! L̄w from the luminance pipeline, cross-checked pixel by pixel against an
//! f64 CPU reference, and encoded to 8-bit sRGB for display.
//!
//! The operator, from the article's equations (2.2.3) and (2.2.4):
//!
//! ```text
//! L  = (a / L̄w) · Lw                 Lw = 0.27 R + 0.67 G + 0.06 B
//! Ld = L · (1 + L / L_white²) / (1 + L)
//! colour = (R, G, B) · Ld / Lw        (Lw ≤ 0: black), saturated to [0, 1]
//! ```
//!
//! with the key `a` (0.18 by default) and the white point `W` given in the
//! image's luminance units (by default the scene's largest luminance), so
//! that `L_white = (a / L̄w) · W` and a pixel with `Lw = W` maps to `Ld = 1`.
//! The shader is `asm/tonemap/reinhard.psh`; its header explains every
//! constant and what was fixed from the article's HLSL.
//!
//! # The cross-check and its bound
//!
//! [`reference_pixel`] evaluates the operator as written above in f64 (not
//! in the shader's rearranged form). Every emulated channel must lie within
//! a bound of it derived from the shader's f32 arithmetic, evaluated per
//! pixel by [`channel_bounds`] as a running error analysis along the
//! shader's instruction sequence. Each step's computed value is tracked as
//! an exact value `v` (f64) and a bound `e` on how far the f32 value can be
//! from it:
//!
//! * application constants (`a`, `1/(a·W²)`, the luminance weights) are
//!   rounded to f32 once: `e` is that rounding, known exactly;
//! * `mul`, `add` and each half of the unfused `mad` round their result:
//!   `e' = e_in + u·(|v| + e_in)`, u = 2⁻²⁴, with the propagated input
//!   error `e_in` (`|x|·e_y + |y|·e_x + e_x·e_y` for a product); a fused mad
//!   rounds less, so the bound covers both;
//! * `dp3` with any evaluation order: `γ₃·Σ|ŵᵢcᵢ|` (Higham, "Accuracy and
//!   Stability of Numerical Algorithms", §3.1), γ₃ = 3u/(1 − 3u), plus the
//!   weights' own rounding `Σ|cᵢ|·|ŵᵢ − wᵢ|`;
//! * `rcp`: Microsoft requires "at least 1.0/(2²²) absolute error over the
//!   range (1.0, 2.0)" with mantissa and exponent handled separately; the
//!   result of a mantissa in (1, 2) lies in (0.5, 1), so the *relative*
//!   error is at most 2⁻²² / 0.5 = 2⁻²¹. For an input known to within e of
//!   x, `e' = e / (|x|·(|x| − e)) + 2⁻²¹ / (|x| − e)` (unbounded if e ≥ |x|).
//!   The emulator's rcp is IEEE 1/x (error ≤ u), well inside;
//! * every step adds 2⁻¹⁵⁰ for f32 underflow and 2⁻⁵²·|v| for the f64
//!   evaluation of `v` itself;
//! * `cmp` selects exactly; when `e ≥ |Lw|` the sign of the computed
//!   luminance is not certain and the bound is the hull of black and the
//!   colour for every luminance in `(0, Lw + e]` ("sign-ambiguous" pixels);
//! * `_sat` is monotone: the allowed interval is `[sat(r − e), sat(r + e)]`
//!   around the reference `r`, so a channel far above 1 must be exactly 1.
//!
//! The 8-bit codes of the emulated and reference channels are compared too.
//! A code may differ only by 1 and only where the allowed interval straddles
//! a rounding boundary of the sRGB encoding; such channels are counted and
//! reported, never absorbed by a wider bound.

use crate::core::cost::{self, Environment, Profile, Range};
use crate::core::emu::{Address, Constants, Draw, Filter, LinearInput, SamplerState};
use crate::core::image::LUMINANCE_WEIGHTS;
use crate::core::image::{HdrImage, RenderTarget, TargetFormat};
use crate::core::load::{self, Options};
use crate::jobs::backend::{Backend, Drawn};
use crate::jobs::luminance::{self, LuminanceRun, PassCost, ShaderSource};
use serde::Serialize;

/// The key value the article (after Reinhard) suggests.
pub const DEFAULT_KEY: f64 = 0.18;

/// f32 unit roundoff, 2⁻²⁴.
const U: f64 = f32::EPSILON as f64 / 2.0;
/// Half the smallest f32 subnormal: the absolute error of an underflowing
/// f32 result.
const ETA: f64 = 7.006_492_321_624_085e-46; // 2^-150
/// Relative error of `rcp` allowed by Microsoft's precision statement.
const RCP: f64 = 4.768_371_582_031_25e-7; // 2^-21
/// Slack for the f64 evaluation of each exact value.
const F64: f64 = f64::EPSILON; // 2^-52

/// Settings of a tone-mapping run.
#[derive(Clone, Debug)]
pub struct Settings {
    /// The key a.
    pub key: f64,
    /// The white point in the image's luminance units; `None`: the scene's
    /// largest luminance. `f64::INFINITY` gives Ld = L / (1 + L).
    pub white: Option<f64>,
    /// Emulator threads (`None`: all cores).
    pub threads: Option<usize>,
    /// Rows per draw (the image is drawn in bands of this many rows, for
    /// progress and bounded memory; results do not depend on it). 0 picks
    /// about 256 K pixels per band on the emulator; on a GPU a quarter of
    /// the frame, or the device's
    /// [`Backend::band_rows`](crate::jobs::backend::Backend::band_rows) if
    /// fewer, each band drawn while the one before is checked.
    pub band_rows: u32,
    /// The tone-mapping shader: [`TONEMAP_REINHARD`](crate::jobs::bundled::TONEMAP_REINHARD) by default, or any shader with
    /// the same inputs (v0, s0, s1, c0–c2), which is then checked against
    /// the same reference.
    pub shader: ShaderSource,
    /// The emulator's bounds, for the luminance passes and the tone map.
    pub limits: crate::core::emu::EmuLimits,
    /// Who draws the luminance passes and the tone map.
    pub backend: crate::jobs::backend::Backend,
    /// The special values of the arithmetic.
    pub float_rules: crate::core::float_rules::FloatRules,
}

impl Default for Settings {
    fn default() -> Settings {
        Settings {
            key: DEFAULT_KEY,
            white: None,
            threads: None,
            band_rows: 0,
            shader: ShaderSource::new(
                crate::jobs::bundled::TONEMAP_REINHARD.path,
                crate::jobs::bundled::TONEMAP_REINHARD.text,
            ),
            limits: crate::core::emu::EmuLimits::default(),
            backend: Default::default(),
            float_rules: Default::default(),
        }
    }
}

/// Why a tone-mapping run could not be made.
#[derive(Debug)]
pub enum TonemapError {
    /// The key or white point is unusable.
    BadValue(String),
    /// The luminance pipeline could not run.
    Pipeline(luminance::PipelineError),
    /// The pipeline ran but its L̄w cannot scale anything; the image has
    /// `non_finite` NaN or infinite pixels.
    LogAverage {
        /// L̄w as the pipeline gave it (0, negative, NaN or ∞).
        value: f64,
        /// NaN or infinite pixels in the image.
        non_finite: u64,
    },
    /// The draw failed, on the emulator or on a GPU.
    Draw(crate::jobs::backend::DrawError),
    /// The tone-mapping shader does not load (its diagnostics are inside).
    Source(crate::core::diag::SourceError),
    /// The shader cannot run with the operator's inputs.
    Shader(String),
    /// The caller's sink refused a band (a file could not be written).
    Output(crate::core::output::ForeignError),
}

impl std::fmt::Display for TonemapError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            TonemapError::BadValue(m) | TonemapError::Shader(m) => f.write_str(m),
            TonemapError::Pipeline(e) => write!(f, "luminance pipeline: {e}"),
            TonemapError::LogAverage { value, non_finite: 0 } => write!(
                f,
                "the luminance pipeline gave L̄w = {value}, which cannot scale the image (it needs a positive finite value); every pixel is finite, so the shader's f32 arithmetic overflowed or underflowed on this image's values"
            ),
            TonemapError::LogAverage { value, non_finite } => write!(
                f,
                "the luminance pipeline gave L̄w = {value}, which cannot scale the image (it needs a positive finite value): {non_finite} pixels are NaN or infinite"
            ),
            TonemapError::Draw(e) => write!(f, "{e}"),
            TonemapError::Source(e) => write!(f, "{e}"),
            TonemapError::Output(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for TonemapError {}

/// Where the white point came from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum WhiteSource {
    /// Given by the caller.
    Given,
    /// The scene's largest finite luminance (the article's default).
    SceneMaximum,
    /// The scene has no positive luminance, so nothing can white out; W = ∞.
    NoPositiveLuminance,
}

/// The operator's parameters as the shader receives them.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct Operator {
    /// The key a.
    pub key: f64,
    /// The white point W, in the image's luminance units (may be ∞).
    pub white: f64,
    /// Where the white point came from.
    pub white_source: WhiteSource,
    /// L̄w exactly as the shader samples it (the f32 in pass 2's target).
    pub log_average: f64,
}

impl Operator {
    /// k = a / L̄w, the scale from world luminance to L.
    pub fn scale(&self) -> f64 {
        self.key / self.log_average
    }

    /// L_white in the units of L: (a / L̄w) · W.
    pub fn white_scaled(&self) -> f64 {
        self.scale() * self.white
    }

    /// c0.y = 1 / (a · W²), exactly (0 for W = ∞).
    pub fn c0y(&self) -> f64 {
        1.0 / (self.key * self.white * self.white)
    }

    /// The float constants c0, c1, c2 the shader reads.
    pub fn constants(&self) -> [[f32; 4]; 3] {
        [
            [self.key as f32, self.c0y() as f32, 0.0, 1.0],
            [
                LUMINANCE_WEIGHTS[0] as f32,
                LUMINANCE_WEIGHTS[1] as f32,
                LUMINANCE_WEIGHTS[2] as f32,
                0.0,
            ],
            [0.5, 0.5, 0.0, 0.0],
        ]
    }
}

/// Refuses keys and white points the shader cannot use: both must be
/// positive (W may be ∞), and a, 1 / (a · W²) must be normal f32 values (or
/// exactly 0 for W = ∞) so that their f32 rounding is a relative error.
pub fn check_values(key: f64, white: Option<f64>) -> Result<(), TonemapError> {
    let normal32 = |v: f64| v.is_finite() && v >= f32::MIN_POSITIVE as f64 && v <= f32::MAX as f64;
    if !(key > 0.0 && key.is_finite()) {
        return Err(TonemapError::BadValue(format!(
            "the key must be a positive finite number (the article suggests 0.18), not {key}"
        )));
    }
    if !normal32(key) {
        return Err(TonemapError::BadValue(format!(
            "the key {key} is outside the range of a normal f32"
        )));
    }
    if let Some(w) = white {
        if w.is_nan() || w <= 0.0 {
            return Err(TonemapError::BadValue(format!(
                "the white point must be a positive luminance (or inf), not {w}"
            )));
        }
        let c = 1.0 / (key * w * w);
        if w.is_finite() && !normal32(c) {
            return Err(TonemapError::BadValue(format!(
                "white point {w:e} with key {key} gives 1/(a·W²) = {c:e}, outside the range of a normal f32"
            )));
        }
    }
    Ok(())
}

/// The operator in f64, as the article writes it, for one pixel: the linear
/// colour before saturation. Pixels with Lw ≤ 0 (or NaN) are black.
pub fn reference_unsaturated(op: &Operator, pixel: [f32; 4]) -> [f64; 3] {
    unsaturated(&Terms::of(op), pixel, crate::core::image::luminance(pixel))
}

/// The operator's values that do not depend on the pixel, each computed as
/// the per-pixel formulas would compute it, once per image.
#[derive(Clone, Copy, Debug)]
struct Terms {
    /// k = a / L̄w.
    scale: f64,
    /// L_white².
    white2: f64,
    /// The shader's k = a · (1 / L̄w) with its bound ([`factor`]).
    k: Bounded,
    /// The shader's L̄w · c0.y with its bound.
    wz: Bounded,
}

impl Terms {
    fn of(op: &Operator) -> Terms {
        let lwhite = op.white_scaled();
        let lw = Bounded::exact(op.log_average);
        Terms {
            scale: op.scale(),
            white2: lwhite * lwhite,
            k: lw.rcp().mul(Bounded::constant(op.key)), // rcp r0.y; mul r0.y
            wz: lw.mul(Bounded::constant(op.c0y())),    // mul r0.z, r0.x, c0.y
        }
    }
}

/// [`reference_unsaturated`] with the operator's terms and the pixel's
/// luminance `lw` ([`crate::core::image::luminance`]) at hand.
fn unsaturated(t: &Terms, pixel: [f32; 4], lw: f64) -> [f64; 3] {
    let c = [pixel[0] as f64, pixel[1] as f64, pixel[2] as f64];
    // NaN fails `> 0` and is black too.
    if lw.is_nan() || lw <= 0.0 {
        return [0.0; 3];
    }
    let l = t.scale * lw;
    let ld = l * (1.0 + l / t.white2) / (1.0 + l);
    c.map(|ch| ch / lw * ld)
}

/// `_sat` in f64, NaN to 0 as the emulator does.
fn sat(x: f64) -> f64 {
    if x.is_nan() {
        0.0
    } else {
        x.clamp(0.0, 1.0)
    }
}

/// The reference's displayable linear colour of one pixel.
pub fn reference_pixel(op: &Operator, pixel: [f32; 4]) -> [f64; 3] {
    reference_unsaturated(op, pixel).map(sat)
}

/// A value the shader computes: exact value `v` and a bound `e` on the
/// distance of the f32 result from it.
#[derive(Clone, Copy, Debug)]
struct Bounded {
    v: f64,
    e: f64,
}

impl Bounded {
    fn exact(v: f64) -> Bounded {
        Bounded { v, e: 0.0 }
    }

    /// An application constant rounded to f32.
    fn constant(v: f64) -> Bounded {
        Bounded {
            v,
            e: ((v as f32) as f64 - v).abs(),
        }
    }

    /// One rounded f32 operation whose exact result is `v`, with propagated
    /// input error `e_in`.
    fn rounded(v: f64, e_in: f64) -> Bounded {
        Bounded {
            v,
            e: e_in + U * (v.abs() + e_in) + ETA + F64 * v.abs(),
        }
    }

    fn mul(self, o: Bounded) -> Bounded {
        let v = self.v * o.v;
        Bounded::rounded(v, self.v.abs() * o.e + o.v.abs() * self.e + self.e * o.e)
    }

    fn add(self, o: Bounded) -> Bounded {
        Bounded::rounded(self.v + o.v, self.e + o.e)
    }

    fn rcp(self) -> Bounded {
        let v = 1.0 / self.v;
        let m = self.v.abs() - self.e;
        if m.is_nan() || m <= 0.0 {
            return Bounded {
                v,
                e: f64::INFINITY,
            };
        }
        Bounded {
            v,
            e: self.e / (self.v.abs() * m) + RCP / m + ETA + F64 * v.abs(),
        }
    }
}

/// `dp3 r2.x, r1, c1`: the luminance with its bound (any evaluation order).
fn dp3(c: [f64; 3]) -> Bounded {
    let gamma3 = 3.0 * U / (1.0 - 3.0 * U);
    let mut v = 0.0;
    let mut magnitude = 0.0;
    let mut weights = 0.0;
    let mut nonzero = 0.0;
    for (ch, w) in c.iter().zip(LUMINANCE_WEIGHTS) {
        let w32 = (w as f32) as f64;
        v += w * ch;
        magnitude += (w32 * ch).abs();
        weights += ch.abs() * (w32 - w).abs();
        if *ch != 0.0 {
            nonzero += 1.0;
        }
    }
    // Each product and addition of a non-zero value can underflow.
    let underflow = if nonzero > 0.0 {
        (nonzero + 2.0) * ETA
    } else {
        0.0
    };
    Bounded {
        v,
        e: gamma3 * magnitude + weights + underflow + F64 * magnitude,
    }
}

/// What the shader's per-pixel factor Ld / Lw comes to, for a luminance
/// known as `lum`.
fn factor(t: &Terms, lum: Bounded) -> Bounded {
    let one = Bounded::exact(1.0);
    let l = lum.mul(t.k); //                 mul r2.y, r2.x, r0.y
    let n = lum.mul(t.wz).add(one); //       mad r2.z, r2.x, r0.z, c0.w
    let d = l.add(one).rcp(); //             add r2.w; rcp r2.w
    n.mul(d).mul(t.k) //                     mul r2.z ×2
}

/// The interval each emulated channel must lie in, and whether the pixel's
/// luminance sign was uncertain. `None` for non-finite pixels (not checked).
pub fn channel_bounds(op: &Operator, pixel: [f32; 4]) -> Option<([(f64, f64); 3], bool)> {
    let lw = crate::core::image::luminance(pixel);
    bounds_and_reference(&Terms::of(op), pixel, lw)
        .map(|(bounds, ambiguous, _)| (bounds, ambiguous))
}

/// Each channel's allowed interval, whether the luminance sign was
/// uncertain, and the reference's unsaturated colour.
type Checked = ([(f64, f64); 3], bool, [f64; 3]);

/// [`channel_bounds`], and the reference's unsaturated colour it is built
/// around, with the operator's terms and the pixel's luminance `lw` at hand.
fn bounds_and_reference(t: &Terms, pixel: [f32; 4], lw: f64) -> Option<Checked> {
    let c = [pixel[0] as f64, pixel[1] as f64, pixel[2] as f64];
    if c.iter().any(|v| !v.is_finite()) {
        return None;
    }
    let lum = dp3(c);
    let raw = unsaturated(t, pixel, lw);
    if lum.v + lum.e <= 0.0 {
        // The computed luminance is ≤ 0 for certain: cmp selects 0.
        return Some(([(0.0, 0.0); 3], false, raw));
    }
    if lum.v - lum.e > 0.0 {
        let s = factor(t, lum);
        let out = std::array::from_fn(|i| {
            let b = Bounded::exact(c[i]).mul(s);
            (sat(raw[i] - b.e), sat(raw[i] + b.e))
        });
        return Some((out, false, raw));
    }
    // Sign uncertain: black, or the colour for any luminance in (0, hi].
    let hi = lum.v + lum.e;
    let s = factor(
        t,
        Bounded {
            v: hi / 2.0,
            e: hi / 2.0,
        },
    );
    let out = std::array::from_fn(|i| {
        let b = Bounded::exact(c[i]).mul(s);
        let lo = (b.v - b.e).min(0.0).min(raw[i]);
        let up = (b.v + b.e).max(0.0).max(raw[i]);
        (sat(lo), sat(up))
    });
    Some((out, true, raw))
}

/// The standard sRGB transfer function (IEC 61966-2-1) of a linear value in
/// [0, 1].
pub fn srgb_encode(linear: f64) -> f64 {
    if linear <= 0.003_130_8 {
        12.92 * linear
    } else {
        1.055 * linear.powf(1.0 / 2.4) - 0.055
    }
}

/// A linear value as an 8-bit sRGB code: clamped to [0, 1] (NaN to 0),
/// encoded, rounded to the nearest code — the number of
/// [`srgb8_thresholds`] at or below it, which is [`srgb8_by_formula`]'s code
/// without a `powf`, counted in one step (a table of 4,096 buckets of [0, 1]).
pub fn srgb8(linear: f64) -> u8 {
    let x = sat(linear);
    let t = Srgb8Buckets::get();
    // Exact: a power-of-two scale, and truncation is floor for x ≥ 0.
    let b = (x * SRGB8_BUCKETS as f64) as usize;
    t.base[b] + (x >= t.next[b]) as u8
}

/// Buckets [`srgb8`] cuts [0, 1] into: each is narrower than the gap
/// between two thresholds (the encoding is steepest at 0, 12.92 · 255 ≈
/// 3295 codes per unit, so thresholds lie at least 1/3295 apart), so it
/// holds at most one threshold.
const SRGB8_BUCKETS: usize = 4096;

/// For bucket `b` = [b / 4096, (b + 1) / 4096): the code of its lower end
/// and the one threshold inside it (∞ if none), so that the code of any x
/// in it is `base[b] + (x ≥ next[b])`. Bucket 4096 is x = 1 alone.
struct Srgb8Buckets {
    base: [u8; SRGB8_BUCKETS + 1],
    next: [f64; SRGB8_BUCKETS + 1],
}

impl Srgb8Buckets {
    fn get() -> &'static Srgb8Buckets {
        static TABLE: std::sync::OnceLock<Srgb8Buckets> = std::sync::OnceLock::new();
        TABLE.get_or_init(|| {
            let thresholds = srgb8_thresholds();
            let edge = |b: usize| b as f64 / SRGB8_BUCKETS as f64;
            let mut t = Srgb8Buckets {
                base: [0; SRGB8_BUCKETS + 1],
                next: [f64::INFINITY; SRGB8_BUCKETS + 1],
            };
            for b in 0..=SRGB8_BUCKETS {
                let below = thresholds.partition_point(|&th| th <= edge(b));
                t.base[b] = below as u8;
                let inside = thresholds[below..]
                    .iter()
                    .take_while(|&&th| b < SRGB8_BUCKETS && th < edge(b + 1));
                assert!(inside.clone().count() <= 1, "two thresholds in bucket {b}");
                if let Some(&th) = inside.last() {
                    t.next[b] = th;
                }
            }
            t
        })
    }
}

/// The definition [`srgb8`] follows: encode, scale, round.
pub fn srgb8_by_formula(linear: f64) -> u8 {
    (srgb_encode(sat(linear)) * 255.0).round() as u8
}

/// `t[k − 1]` is the smallest f64 in [0, 1] that [`srgb8_by_formula`] maps
/// to code `k` or above. The encoding is monotone (its two pieces meet
/// 2.9e-8 apart, far from a rounding boundary; tested by a dense sweep), so
/// the code of `x` is the number of thresholds at or below it. Each one is
/// found by bisection over the bit patterns of [0, 1] (ordered like the
/// values), 62 evaluations of the formula.
pub fn srgb8_thresholds() -> &'static [f64; 255] {
    static TABLE: std::sync::OnceLock<[f64; 255]> = std::sync::OnceLock::new();
    TABLE.get_or_init(|| {
        std::array::from_fn(|k| {
            let code = k as u8 + 1;
            // Invariant: code(lo) < code ≤ code(hi).
            let (mut lo, mut hi) = (0f64.to_bits(), 1f64.to_bits());
            while hi - lo > 1 {
                let mid = lo + (hi - lo) / 2;
                if srgb8_by_formula(f64::from_bits(mid)) >= code {
                    hi = mid;
                } else {
                    lo = mid;
                }
            }
            f64::from_bits(hi)
        })
    })
}

/// Linear RGBA (row-major) to packed 8-bit sRGB RGB, alpha dropped; pixels
/// are independent, so they are encoded in parallel on rayon's current pool.
pub fn to_srgb8(linear: &[[f32; 4]]) -> Vec<u8> {
    use rayon::prelude::*;
    let mut out = vec![0u8; 3 * linear.len()];
    out.par_chunks_mut(3)
        .zip(linear.par_iter())
        .for_each(|(rgb, p)| {
            for c in 0..3 {
                rgb[c] = srgb8(p[c] as f64);
            }
        });
    out
}

/// Counts and extremes of the per-pixel cross-check.
#[derive(Clone, Debug, Default, Serialize)]
pub struct Crosscheck {
    /// Pixels in the image.
    pub pixels: u64,
    /// Pixels compared (all but the non-finite ones).
    pub checked_pixels: u64,
    /// Non-finite pixels (not compared).
    pub nonfinite_pixels: u64,
    /// Pixels with Lw exactly 0 (shown black).
    pub zero_luminance_pixels: u64,
    /// Pixels with Lw < 0 (shown black).
    pub negative_luminance_pixels: u64,
    /// Pixels whose computed luminance could have either sign.
    pub sign_ambiguous_pixels: u64,
    /// Pixels with a channel at or above 1 before saturation (clipped).
    pub saturated_pixels: u64,
    /// Largest |emulated − reference| over all channels.
    pub max_error: f64,
    /// The bound at that channel.
    pub max_error_bound: f64,
    /// Largest |emulated − reference| / bound over channels with a bound > 0.
    pub largest_bound_fraction: f64,
    /// Channels outside their bound (must be 0).
    pub outside_bound: u64,
    /// Channels whose 8-bit codes differ.
    pub mismatched_8bit_channels: u64,
    /// Pixels with at least one differing 8-bit code.
    pub mismatched_8bit_pixels: u64,
    /// Differing codes not explained by a bound straddling a rounding
    /// boundary, or differing by more than 1 (must be 0).
    pub unexplained_8bit: u64,
    /// Differing codes of sign-ambiguous pixels, where f32 cannot tell
    /// whether the luminance is positive: black and the scaled colour are
    /// both within the bound (counted apart from the rounding cases).
    pub ambiguous_8bit: u64,
    /// The first channel outside its bound, for the report:
    /// (x, y, channel, emulated, reference, low, high).
    pub first_outside: Option<(u32, u32, usize, f64, f64, f64, f64)>,
}

impl Crosscheck {
    /// Whether every channel is within its bound and every differing 8-bit
    /// code is explained.
    pub fn agree(&self) -> bool {
        self.outside_bound == 0 && self.unexplained_8bit == 0
    }
}

/// Pixels per task of [`crosscheck`].
const CHECK_CHUNK: usize = 1 << 14;

/// Compares the emulated output with the reference, pixel by pixel, in
/// chunks on rayon's current pool, merged in order (the same result for any
/// thread count).
pub fn crosscheck(op: &Operator, image: &HdrImage, emulated: &[[f32; 4]]) -> Crosscheck {
    let mut r = crosscheck_from(op, &image.pixels, emulated, 0, image.width.max(1) as usize);
    r.pixels = image.pixels.len() as u64;
    r
}

/// [`crosscheck`] of the pixels from index `first` on (rows `w` wide), in
/// chunks on rayon's current pool. Merging such parts in order gives what
/// one left-to-right scan gives, so a whole image may be checked a band at
/// a time (`pixels` is left 0).
fn crosscheck_from(
    op: &Operator,
    pixels: &[[f32; 4]],
    emulated: &[[f32; 4]],
    first: usize,
    w: usize,
) -> Crosscheck {
    use rayon::prelude::*;
    let terms = Terms::of(op);
    let parts: Vec<Crosscheck> = pixels
        .par_chunks(CHECK_CHUNK)
        .zip(emulated.par_chunks(CHECK_CHUNK))
        .enumerate()
        .map(|(k, (p, e))| crosscheck_chunk(&terms, p, e, first + k * CHECK_CHUNK, w))
        .collect();
    let mut r = Crosscheck::default();
    for part in parts {
        r.merge(part);
    }
    r
}

impl Crosscheck {
    /// Adds a later chunk's counts, keeping extremes as a left-to-right scan
    /// does (a later maximum only when strictly larger, the first outlier).
    fn merge(&mut self, o: Crosscheck) {
        self.checked_pixels += o.checked_pixels;
        self.nonfinite_pixels += o.nonfinite_pixels;
        self.zero_luminance_pixels += o.zero_luminance_pixels;
        self.negative_luminance_pixels += o.negative_luminance_pixels;
        self.sign_ambiguous_pixels += o.sign_ambiguous_pixels;
        self.saturated_pixels += o.saturated_pixels;
        if o.max_error > self.max_error {
            self.max_error = o.max_error;
            self.max_error_bound = o.max_error_bound;
        }
        self.largest_bound_fraction = self.largest_bound_fraction.max(o.largest_bound_fraction);
        self.outside_bound += o.outside_bound;
        self.mismatched_8bit_channels += o.mismatched_8bit_channels;
        self.mismatched_8bit_pixels += o.mismatched_8bit_pixels;
        self.unexplained_8bit += o.unexplained_8bit;
        self.ambiguous_8bit += o.ambiguous_8bit;
        self.first_outside = self.first_outside.or(o.first_outside);
    }
}

/// [`crosscheck`] over the pixels from index `first` on (rows `w` wide).
fn crosscheck_chunk(
    terms: &Terms,
    pixels: &[[f32; 4]],
    emulated: &[[f32; 4]],
    first: usize,
    w: usize,
) -> Crosscheck {
    let mut r = Crosscheck::default();
    for (j, (&p, o)) in pixels.iter().zip(emulated).enumerate() {
        let i = first + j;
        let lw = crate::core::image::luminance(p);
        let Some((bounds, ambiguous, raw)) = bounds_and_reference(terms, p, lw) else {
            r.nonfinite_pixels += 1;
            continue;
        };
        r.checked_pixels += 1;
        r.sign_ambiguous_pixels += ambiguous as u64;
        if lw == 0.0 {
            r.zero_luminance_pixels += 1;
        } else if lw < 0.0 {
            r.negative_luminance_pixels += 1;
        }
        if raw.iter().any(|&v| v >= 1.0) {
            r.saturated_pixels += 1;
        }
        let mut mismatched = false;
        for ch in 0..3 {
            let e = o[ch] as f64;
            let reference = sat(raw[ch]);
            let (lo, hi) = bounds[ch];
            let err = (e - reference).abs();
            let bound = (reference - lo).max(hi - reference);
            if err > r.max_error {
                r.max_error = err;
                r.max_error_bound = bound;
            }
            if bound > 0.0 {
                r.largest_bound_fraction = r.largest_bound_fraction.max(err / bound);
            }
            // `!(…)` so that NaN counts as outside.
            if !(lo <= e && e <= hi) {
                r.outside_bound += 1;
                if r.first_outside.is_none() {
                    r.first_outside =
                        Some(((i % w) as u32, (i / w) as u32, ch, e, reference, lo, hi));
                }
            }
            let (ce, cr) = (srgb8(e), srgb8(reference));
            if ce != cr && ambiguous {
                // Black and the colour are both right: no rounding rule.
                r.ambiguous_8bit += 1;
            } else if ce != cr {
                mismatched = true;
                r.mismatched_8bit_channels += 1;
                if ce.abs_diff(cr) > 1 || srgb8(lo) == srgb8(hi) {
                    r.unexplained_8bit += 1;
                }
            }
        }
        r.mismatched_8bit_pixels += mismatched as u64;
    }
    r
}

/// Everything a tone-mapping run produced.
#[derive(Clone, Debug)]
pub struct ToneMapped {
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
    /// The luminance pipeline's run that gave L̄w (and its own cross-check).
    pub luminance: LuminanceRun,
    /// The key, white point and L̄w the shader ran with.
    pub operator: Operator,
    /// The tone-mapping pass's cost.
    pub cost: PassCost,
    /// The per-pixel cross-check against the f64 operator.
    pub check: Crosscheck,
}

impl ToneMapped {
    /// The pipeline's L̄w, the emulator's counts and the per-pixel
    /// cross-check all agree.
    pub fn all_agree(&self) -> bool {
        self.luminance.all_agree()
            && self.luminance.fit()
            && self.luminance.within_limits()
            && self.cost.counts_agree
            && self.cost.within_limits
            && self.check.agree()
    }
}

/// The largest finite luminance of an image (`None` if no pixel has a
/// finite one).
pub fn max_luminance(image: &HdrImage) -> Option<f64> {
    use rayon::prelude::*;
    image
        .pixels
        .par_iter()
        .map(|&p| crate::core::image::luminance(p))
        .filter(|l| l.is_finite())
        .reduce_with(f64::max)
}

/// The white point the operator uses: the given one, or the scene's
/// largest luminance (∞ if nothing in the scene is positive).
pub fn white_point(image: &HdrImage, given: Option<f64>) -> (f64, WhiteSource) {
    match given {
        Some(w) => (w, WhiteSource::Given),
        None => match max_luminance(image) {
            Some(m) if m > 0.0 => (m, WhiteSource::SceneMaximum),
            _ => (f64::INFINITY, WhiteSource::NoPositiveLuminance),
        },
    }
}

/// Receives the tone-mapped image a band of whole rows at a time, top band
/// first: the shader's oC0 per pixel, row-major, linear, saturated. An error
/// ends the run ([`TonemapError::Output`]).
pub type Sink<'a> = dyn FnMut(&[[f32; 4]]) -> Result<(), crate::core::output::ForeignError> + 'a;

/// [`run_into`], keeping the whole tone-mapped image (row-major RGBA):
/// for callers that need it all at once.
pub fn run(
    image: &HdrImage,
    settings: &Settings,
    progress: &dyn Fn(u64, u64),
) -> Result<(ToneMapped, Vec<[f32; 4]>), TonemapError> {
    let mut linear = Vec::with_capacity(image.pixels.len());
    let result = run_into(image, settings, progress, &mut |band| {
        linear.extend_from_slice(band);
        Ok(())
    })?;
    Ok((result, linear))
}

/// Computes L̄w with the luminance passes planned for the image's size
/// ([`crate::jobs::blocks::planned`]: generated shaders, R32F),
/// then runs the tone-mapping shader over the image in bands of rows,
/// cross-checks each band and hands it to `sink`, which keeps what it needs
/// (a file written band by band holds no more than a band).
/// `progress(done, total)` is called after each band.
pub fn run_into(
    image: &HdrImage,
    settings: &Settings,
    progress: &dyn Fn(u64, u64),
    sink: &mut Sink<'_>,
) -> Result<ToneMapped, TonemapError> {
    check_values(settings.key, settings.white)?;
    let delta = luminance::reference::DEFAULT_DELTA;
    let planned = crate::jobs::blocks::planned(image.width, image.height, delta)
        .map_err(|e| TonemapError::Shader(e.to_string()))?;
    let luminance = luminance::run(
        image,
        &planned.pass1,
        &planned.pass2,
        &luminance::Settings {
            block: planned.block(),
            threads: settings.threads,
            limits: settings.limits,
            backend: settings.backend.clone(),
            float_rules: settings.float_rules,
            ..luminance::Settings::default()
        },
    )
    .map_err(TonemapError::Pipeline)?;
    let lw32 = luminance.log_average as f32;
    if !(lw32.is_finite() && lw32 > 0.0) {
        return Err(TonemapError::LogAverage {
            value: luminance.log_average,
            non_finite: image.stats().non_finite,
        });
    }
    let (white, white_source) = white_point(image, settings.white);
    crate::core::phases::mark("tonemap: white point");
    check_values(settings.key, Some(white))?;
    let op = Operator {
        key: settings.key,
        white,
        white_source,
        log_average: lw32 as f64,
    };
    let w = image.width.max(1) as usize;
    let mut check = Crosscheck {
        pixels: image.pixels.len() as u64,
        ..Crosscheck::default()
    };
    let mut done = 0;
    let cost = emulate(image, &op, settings, progress, &mut |band| {
        let pixels = &image.pixels[done..done + band.len()];
        check.merge(crosscheck_from(&op, pixels, band, done, w));
        crate::core::phases::mark("tonemap: band checked");
        done += band.len();
        sink(band).map_err(TonemapError::Output)
    })?;
    Ok(ToneMapped {
        width: image.width,
        height: image.height,
        luminance,
        operator: op,
        cost,
        check,
    })
}

/// Bands a GPU reads a frame back in at least (when each fits the device):
/// the first is waited for, the others read back while the one before is
/// checked. Eight rather than four: the device reads the bands back through
/// two band-sized buffers used in turn (`gpu::Prepared::draw_in_bands`), so
/// smaller bands pin less host memory — about 30 ms per 133 MB on an NVIDIA
/// H200 — and leave less of the last band's check after the last read.
const GPU_BANDS: u32 = 8;

/// What [`emulate`] hands each band of rows to, top band first.
pub type BandSink<'a> = dyn FnMut(&[[f32; 4]]) -> Result<(), TonemapError> + 'a;

/// Runs the shader over the image with the operator's constants: pass 2's
/// 1×1 R32F target holding L̄w on s1, the image on s0. Each band of rows
/// goes to `band` as it is drawn, top band first.
pub fn emulate(
    image: &HdrImage,
    op: &Operator,
    settings: &Settings,
    progress: &dyn Fn(u64, u64),
    band: &mut BandSink<'_>,
) -> Result<PassCost, TonemapError> {
    let src = &settings.shader;
    let loaded = load::load(src.file.clone(), &Options::default()).map_err(TonemapError::Source)?;
    luminance::refuse_unset(
        &loaded,
        &crate::core::audit::Given::registers(&[0, 1, 2], &[], &[]),
    )
    .map_err(TonemapError::Shader)?;
    let analysis = cost::analyse(
        &loaded.shader,
        &loaded.file,
        &Environment::default(),
        &Profile::ps_3_0(),
    )
    .map_err(|e| TonemapError::Shader(e.to_string()))?;

    let mut lw_target = RenderTarget::new(1, 1, TargetFormat::R32F);
    lw_target.store(0, 0, [op.log_average as f32, 0.0, 0.0, 0.0]);
    let clamp = SamplerState {
        address_u: Address::Clamp,
        address_v: Address::Clamp,
        address_w: Address::Clamp,
        border: [0.0; 4],
        ..SamplerState::filtered(Filter::Point)
    };
    let (w, h) = (image.width, image.height);
    let band_rows = match (settings.band_rows, &settings.backend) {
        (0, Backend::Emulator) => ((1u32 << 18) / w.max(1)).max(2),
        // An eighth of the frame at most: one band is checked on the CPU
        // while the next is read back.
        (0, gpu) => gpu.band_rows(w, 1).min(h.div_ceil(GPU_BANDS).max(1)),
        (n, _) => n,
    };
    let band_draw = |y0: u32, rows: u32| {
        let mut draw = Draw::new(w, rows);
        draw.limits = settings.limits;
        draw.float_rules = settings.float_rules;
        // The image was admitted by its own pixel cap; a band of it is not a
        // new target to refuse.
        draw.limits.max_target_pixels = draw.limits.max_target_pixels.max(w as u64 * rows as u64);
        // Texel centres: v0 = ((x + ½)/W, (y0 + y + ½)/H).
        draw.inputs.push((
            0,
            LinearInput {
                base: [
                    (0.5 / w as f64) as f32,
                    ((y0 as f64 + 0.5) / h as f64) as f32,
                    0.0,
                    0.0,
                ],
                ddx: [(1.0 / w as f64) as f32, 0.0, 0.0, 0.0],
                ddy: [0.0, (1.0 / h as f64) as f32, 0.0, 0.0],
            },
        ));
        draw.constants = Constants {
            float: op.constants().to_vec(),
            int: Vec::new(),
            bool: Vec::new(),
        };
        draw.samplers.push((0, image.as_texture().into(), clamp));
        draw.samplers
            .push((1, lw_target.as_texture().into(), clamp));
        draw
    };
    let draw_band = |y0: u32, rows: u32| {
        crate::jobs::backend::draw(
            &settings.backend,
            &loaded.shader,
            &loaded.file,
            &band_draw(y0, rows),
            crate::core::gpu::TargetKind::Raw,
            settings.threads,
        )
        .map_err(TonemapError::Draw)
    };
    let mut executed: Option<Range> = None;
    let mut take = |y0: u32, rows: u32, out: Drawn| {
        match out.color {
            Some(c) => band(&c)?,
            None => {
                return Err(TonemapError::Shader(format!(
                    "{} never writes oC0",
                    src.name()
                )))
            }
        }
        executed = match (executed, out.executed) {
            (Some(a), Some(b)) => Some(Range {
                min: a.min.min(b.min),
                max: a.max.max(b.max),
            }),
            (None, b) => b,
            (a, None) => a,
        };
        progress((y0 + rows) as u64, h as u64);
        Ok(())
    };
    let bands: Vec<(u32, u32)> = (0..h)
        .step_by(band_rows.max(1) as usize)
        .map(|y0| (y0, band_rows.min(h - y0)))
        .collect();
    if matches!(settings.backend, Backend::Emulator) {
        for &(y0, rows) in &bands {
            take(y0, rows, draw_band(y0, rows)?)?;
        }
    } else {
        on_device(settings, &loaded, &band_draw, (w, h), band_rows, &mut take)?;
    }
    let cost = PassCost {
        shader: src.name().to_string(),
        slots: analysis.slots,
        executed_static: analysis.executed,
        executed_emulated: executed,
        counts_agree: executed
            .is_none_or(|e| analysis.executed.min <= e.min && e.max <= analysis.executed.max),
        within_limits: analysis.verdict == cost::Verdict::Within,
        findings: Vec::new(),
    };
    Ok(cost)
}

/// [`emulate`] on a GPU: the device draws as much of the frame at once as it
/// takes (all of a 3840×2160 one) and reads it back `band_rows` rows at a
/// time, on a thread of its own, while this thread hands band k to `take`
/// (which checks it), in order: one translation, one texture lookup, one set
/// of inputs and one draw per device-sized part of the frame.
fn on_device<'d>(
    settings: &Settings,
    loaded: &load::Loaded,
    band_draw: &(dyn Fn(u32, u32) -> Draw<'d> + Sync),
    (w, h): (u32, u32),
    band_rows: u32,
    take: &mut dyn FnMut(u32, u32, Drawn) -> Result<(), TonemapError>,
) -> Result<(), TonemapError> {
    let draw_rows = match settings.band_rows {
        0 => settings.backend.band_rows(w, 1),
        n => n,
    };
    std::thread::scope(|s| {
        let (tx, rx) = std::sync::mpsc::sync_channel(1);
        s.spawn(move || {
            for y0 in (0..h).step_by(draw_rows.max(1) as usize) {
                let part = band_draw(y0, draw_rows.min(h - y0));
                let mut open = true;
                let drawn = crate::jobs::backend::draw_in_bands(
                    &settings.backend,
                    &loaded.shader,
                    &loaded.file,
                    &part,
                    crate::core::gpu::TargetKind::Raw,
                    settings.threads,
                    band_rows,
                    &mut |y, drawn| {
                        open = tx.send((y0 + y, drawn.height, Ok(drawn))).is_ok();
                        open
                    },
                );
                if let Err(e) = drawn {
                    let _ = tx.send((y0, 0, Err(TonemapError::Draw(e))));
                    break;
                }
                if !open {
                    break;
                }
            }
        });
        for (y0, rows, drawn) in rx {
            take(y0, rows, drawn?)?;
        }
        Ok(())
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn op(white: f64) -> Operator {
        Operator {
            key: 0.18,
            white,
            white_source: WhiteSource::Given,
            log_average: 0.09,
        }
    }

    #[test]
    fn srgb_encoding_ends_and_breakpoint() {
        assert_eq!(srgb8(0.0), 0);
        assert_eq!(srgb8(1.0), 255);
        assert_eq!(srgb8(2.0), 255);
        assert_eq!(srgb8(-1.0), 0);
        assert_eq!(srgb8(f64::NAN), 0);
        // Middle grey 0.18 is sRGB 118 (0.4614 · 255 = 117.66).
        assert_eq!(srgb8(0.18), 118);
        // The standard's two pieces meet 2.9e-8 apart (the power piece is
        // the lower): far from any 8-bit rounding boundary (code 10.31).
        let below = srgb_encode(0.003_130_8);
        let above = srgb_encode(0.003_130_8 + 1e-12);
        assert!((above - below).abs() < 1e-7);
        // So the 8-bit codes are monotone: a dense sweep of [0, 1].
        let mut last = 0;
        for i in 0..=1_000_000 {
            let c = srgb8(i as f64 / 1e6);
            assert!(c >= last, "code {c} after {last} at {i}");
            last = c;
        }
    }

    /// The table gives the formula's code at and just below every
    /// threshold and every bucket edge, and on every 64th f32 in [0, 1]
    /// (16.6 million values).
    #[test]
    fn srgb_table_codes_are_the_formulas() {
        for (k, &t) in srgb8_thresholds().iter().enumerate() {
            let below = f64::from_bits(t.to_bits() - 1);
            assert_eq!(srgb8_by_formula(t), k as u8 + 1, "at {t}");
            assert_eq!(srgb8_by_formula(below), k as u8, "below {t}");
            assert_eq!((srgb8(t), srgb8(below)), (k as u8 + 1, k as u8));
        }
        for b in 0..=SRGB8_BUCKETS {
            let edge = b as f64 / SRGB8_BUCKETS as f64;
            for x in [edge, f64::from_bits(edge.to_bits().saturating_sub(1))] {
                assert_eq!(srgb8(x), srgb8_by_formula(x), "at {x}");
            }
        }
        for bits in (0..=1f32.to_bits()).step_by(64) {
            let x = f32::from_bits(bits) as f64;
            assert_eq!(srgb8(x), srgb8_by_formula(x), "at {x}");
        }
        for x in [f64::NAN, -1.0, -0.0, 2.0, f64::INFINITY] {
            assert_eq!(srgb8(x), srgb8_by_formula(x), "at {x}");
        }
    }

    #[test]
    fn a_pixel_at_the_white_point_is_white() {
        let o = op(50.0);
        // Grey pixel with Lw = W: R = G = B = 50 (the weights sum to 1).
        let out = reference_unsaturated(&o, [50.0, 50.0, 50.0, 1.0]);
        for c in out {
            assert!((c - 1.0).abs() < 1e-12, "{c}");
        }
    }

    #[test]
    fn infinite_white_point_is_l_over_one_plus_l() {
        let o = op(f64::INFINITY);
        let out = reference_unsaturated(&o, [0.5, 0.5, 0.5, 1.0]);
        let l = 0.18 / 0.09 * 0.5;
        assert!((out[0] - l / (1.0 + l)).abs() < 1e-15);
        assert_eq!(o.c0y(), 0.0);
    }

    #[test]
    fn black_and_negative_pixels_are_black_with_a_zero_bound() {
        let o = op(10.0);
        for p in [[0.0, 0.0, 0.0, 1.0], [-0.5, -0.1, 0.2, 1.0]] {
            assert_eq!(reference_pixel(&o, p), [0.0; 3]);
            let (b, ambiguous) = channel_bounds(&o, p).unwrap();
            assert!(!ambiguous);
            assert_eq!(b, [(0.0, 0.0); 3]);
        }
    }

    #[test]
    fn cancelling_channels_make_the_sign_ambiguous() {
        // 0.27·R + 0.06·B = 0 in exact arithmetic with R = 0.06·t, B = −0.27·t
        // only up to rounding; a luminance tiny against the channels' size.
        let o = op(10.0);
        let p = [0.06f32, 0.0, -0.27, 1.0];
        let (b, ambiguous) = channel_bounds(&o, p).unwrap();
        assert!(ambiguous);
        // Black is always allowed, and the R channel may show up to about k·R.
        assert_eq!(b[2], (0.0, 0.0));
        assert!(b[0].0 == 0.0 && b[0].1 > 0.1);
    }

    #[test]
    fn ordinary_pixels_get_a_tight_bound() {
        let o = op(10.0);
        let (b, ambiguous) = channel_bounds(&o, [0.05, 0.04, 0.03, 1.0]).unwrap();
        assert!(!ambiguous);
        let r = reference_pixel(&o, [0.05, 0.04, 0.03, 1.0]);
        for (ch, (lo, hi)) in b.iter().enumerate() {
            assert!(*lo < r[ch] && r[ch] < *hi);
            // A few rcp errors (2^-21) and roundings: well under 1e-5 relative.
            assert!((hi - lo) / r[ch] < 1e-5, "{lo} {hi} {}", r[ch]);
        }
    }

    #[test]
    fn bad_values_are_refused() {
        assert!(check_values(0.0, None).is_err());
        assert!(check_values(f64::NAN, None).is_err());
        assert!(check_values(-0.18, None).is_err());
        assert!(check_values(f64::INFINITY, None).is_err());
        assert!(check_values(0.18, Some(-1.0)).is_err());
        assert!(check_values(0.18, Some(0.0)).is_err());
        assert!(check_values(0.18, Some(f64::NAN)).is_err());
        assert!(check_values(0.18, Some(1e-30)).is_err());
        assert!(check_values(0.18, Some(f64::INFINITY)).is_ok());
        assert!(check_values(0.18, Some(100.0)).is_ok());
    }
}
