//! "Log lights" measured: lights accumulated into an RGBA8 buffer as
//! exp2(−light) by multiplicative blending and recovered as −log2, against
//! the same lights added raw into RGBA8 (saturating at 1) and into
//! A16B16G16R16F — the comparison of "Prelighting & Log-Lights (Ver. 2)"
//! (Josh Ols, 2009), which shows brightness 0.1, 1, 2 and 3 and claims more
//! range and worse artefacts on dim lights.
//!
//! Every configuration is a draw list ([`crate::jobs::render`]) run in the
//! emulator: the shaders of `asm/log-lights/`, the output merger in the
//! target's precision. Each light is a ramp across a `WIDTH × 1` target,
//! `light(x) = b · u(x)` with `u(x) = (x + ½)/WIDTH` the pixel's texture
//! coordinate, so one draw covers every intensity from 0 to b. K lights
//! overlap completely: the true sum is `K · b · u(x)`, computed in f64 from
//! the f32 values the draws use.
//!
//! # Bounds, per pixel
//!
//! Each method's recovered value is compared with the true sum within a
//! bound derived from its arithmetic; a pixel past the method's range (raw
//! RGBA8 above 1; a log buffer whose product falls to one code or less) is
//! counted as out of range instead. u = 2⁻²⁴ (f32), q = ½/255 (half an 8-bit
//! code), and each light's f32 value `b · u(x)` is off by at most u of itself.
//!
//! * **RGBA8 raw** (`ONE, ONE`): every blend adds in f32 (u of the sum) and
//!   quantises the result (q): |error| ≤ Σₖ (q + u·Sₖ + u·ℓₖ) with Sₖ the
//!   partial sums, as long as the true sum stays ≤ 1 − K·q.
//! * **A16B16G16R16F** (`ONE, ONE`): the source is rounded to half (½ ulp of
//!   ℓₖ), then the sum (½ ulp of the partial sum): the bound runs along the
//!   partial sums, each half ulp taken at the largest value the stored sum
//!   can have.
//! * **RGBA8 log lights** (`DESTCOLOR, ZERO`): light k writes
//!   pₖ = exp2(−ℓₖ) — its argument off by u·ℓₖ, the result good to 2⁻²¹
//!   relative (Microsoft's `exp`: "21 bits of precision"; the emulator's f32
//!   exp2 is within one ulp) — and the blend multiplies in f32 (u) and
//!   quantises (q, absolute). Work in log2 units, E the error so far: the
//!   product before quantisation is P ≥ 2^−(Sₖ + Eₖ₋₁)·(1 − ρ), ρ = 2⁻²¹ + u,
//!   so the quantisation moves log2 P by at most −log2(1 − x),
//!   x = q·2^(Sₖ + Eₖ₋₁)/(1 − ρ), and the relative roundings by −log2(1 − ρ):
//!   Eₖ = Eₖ₋₁ + u·ℓₖ − log2(1 − ρ) − log2(1 − x). Reading the code back as
//!   f32 adds −log2(1 − u), and the recovery's `log` 2⁻²¹ of its result.
//!   When x ≥ ½ the pixel is out of range (the product is at most one code,
//!   1/255; at code 0 the recovery gives FLT_MAX).

use crate::core::image::TargetFormat;
use crate::core::merge::{BlendFactor, BlendOp, BlendState, ColorWrite, Equation, OutputState};
use crate::jobs::render::{self, DrawList, DrawStep, ShaderSpec, Source, Step, TargetSpec};
use serde::Serialize;

/// The brightness values of the article's figure 3.
pub const BRIGHTNESS: [f32; 4] = [0.1, 1.0, 2.0, 3.0];
/// Overlapping lights, each of brightness 1.
pub const OVERLAPS: [u32; 4] = [1, 2, 4, 8];
/// The brightness of the light swept for the error-against-intensity figure
/// (it reaches past the log buffer's range, about 8).
pub const SWEEP_BRIGHTNESS: f32 = 10.0;
/// Pixels across each ramp.
pub const WIDTH: u32 = 1024;
/// "Dim": true light at most this.
pub const DIM: f64 = 0.1;

const U: f64 = f32::EPSILON as f64 / 2.0;
const Q: f64 = 0.5 / 255.0;
/// `exp` and `log` precision: "21 bits".
const TRANSCENDENTAL: f64 = 1.0 / (1u64 << 21) as f64;

/// How the lights are stored.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub enum Method {
    /// Raw light, ONE/ONE into D3DFMT_A8R8G8B8.
    Rgba8,
    /// exp2(−light), DESTCOLOR/ZERO into D3DFMT_A8R8G8B8 cleared to white.
    LogRgba8,
    /// Raw light, ONE/ONE into D3DFMT_A16B16G16R16F.
    Half,
}

impl Method {
    /// Every method, in the order the tables list them.
    pub const ALL: [Method; 3] = [Method::Rgba8, Method::LogRgba8, Method::Half];

    /// The method as tables and figures name it.
    pub fn name(self) -> &'static str {
        match self {
            Method::Rgba8 => "RGBA8 raw",
            Method::LogRgba8 => "RGBA8 log lights",
            Method::Half => "A16B16G16R16F",
        }
    }

    fn format(self) -> TargetFormat {
        match self {
            Method::Rgba8 | Method::LogRgba8 => TargetFormat::A8R8G8B8,
            Method::Half => TargetFormat::Rgba16F,
        }
    }
}

/// One configuration, run: every pixel's true and recovered light.
#[derive(Clone, Debug, Serialize)]
pub struct Accumulation {
    /// How the lights are stored.
    pub method: Method,
    /// How many lights overlap (K).
    pub lights: u32,
    /// Each light's brightness b: its ramp runs from 0 to b.
    pub brightness: f32,
    /// The true sum at each pixel (f64).
    #[serde(skip)]
    pub truth: Vec<f64>,
    /// What the method gives back at each pixel (red channel).
    #[serde(skip)]
    pub recovered: Vec<f64>,
    /// The derived bound at each pixel; `None` past the method's range.
    #[serde(skip)]
    pub bound: Vec<Option<f64>>,
}

/// What one configuration shows, in numbers.
#[derive(Clone, Debug, Serialize)]
pub struct Summary {
    /// How the lights are stored.
    pub method: Method,
    /// How many lights overlap (K).
    pub lights: u32,
    /// Each light's brightness b.
    #[serde(serialize_with = "crate::core::numbers::serialize_f32_shortest")]
    pub brightness: f32,
    /// The largest true sum on the ramp.
    pub peak: f64,
    /// Largest |recovered − true| over the whole ramp.
    pub max_error: f64,
    /// Root mean square of the error over the ramp.
    pub rms_error: f64,
    /// Largest |error| where the true sum is at most [`DIM`].
    pub max_error_dim: f64,
    /// Distinct recovered values where the true sum is at most [`DIM`]
    /// (banding: fewer is coarser).
    pub levels_dim: usize,
    /// Pixels within the method's range.
    pub in_range: u64,
    /// Of [`Summary::in_range`], the pixels within their derived bound.
    pub within_bound: u64,
    /// The largest error / bound over pixels in range.
    pub largest_bound_fraction: f64,
    /// The smallest true sum that is out of range, if any.
    pub range_ends_at: Option<f64>,
}

impl Summary {
    /// Whether every pixel in range is within its bound.
    pub fn agree(&self) -> bool {
        self.within_bound == self.in_range
    }
}

/// One light's draw into `target`.
fn light_draw(target: usize, shader: usize, brightness: f32, output: OutputState) -> Step {
    Step::Draw(DrawStep {
        target,
        shader,
        inputs: vec![(0, render::texcoord(WIDTH, 1))],
        constants: crate::core::emu::Constants {
            float: vec![[brightness, 0.0, 0.0, 0.0]],
            ..Default::default()
        },
        samplers: Vec::new(),
        output,
        pixel: Default::default(),
        geometry: None,
    })
}

fn bundled_shader(b: crate::jobs::bundled::Bundled) -> Result<ShaderSpec, String> {
    let loaded = crate::core::load::load_str(b.path, b.text, &Default::default())
        .map_err(|e| e.to_string())?;
    Ok(ShaderSpec {
        name: b.path.to_string(),
        loaded,
    })
}

/// The draw list of one configuration: target 0 accumulates; for log
/// lights target 1 receives the recovery.
pub fn draw_list(method: Method, lights: u32, brightness: f32) -> Result<DrawList, String> {
    use crate::jobs::bundled::{LOG_LIGHTS_LIGHT, LOG_LIGHTS_LOG, LOG_LIGHTS_RECOVER};
    let target = |name: &str, format| TargetSpec {
        name: name.into(),
        width: WIDTH,
        height: 1,
        format,
    };
    let mut list = DrawList {
        targets: vec![target("lights", method.format())],
        textures: Vec::new(),
        shaders: Vec::new(),
        steps: Vec::new(),
    };
    let (shader, clear, equation, alpha) = match method {
        Method::LogRgba8 => (
            LOG_LIGHTS_LOG,
            [255; 4],
            Equation::MULTIPLY,
            Some(Equation {
                src: BlendFactor::DestAlpha,
                dest: BlendFactor::Zero,
                op: BlendOp::Add,
            }),
        ),
        _ => (LOG_LIGHTS_LIGHT, [0; 4], Equation::ADDITIVE, None),
    };
    list.shaders.push(bundled_shader(shader)?);
    let output = OutputState {
        blend: BlendState {
            alpha,
            ..BlendState::with(equation)
        },
        write: ColorWrite::ALL,
    };
    list.steps.push(Step::Clear {
        target: 0,
        color: clear,
    });
    for _ in 0..lights {
        list.steps.push(light_draw(0, 0, brightness, output));
    }
    if method == Method::LogRgba8 {
        list.targets
            .push(target("recovered", TargetFormat::A32B32G32R32F));
        list.shaders.push(bundled_shader(LOG_LIGHTS_RECOVER)?);
        list.steps.push(Step::Draw(DrawStep {
            target: 1,
            shader: 1,
            inputs: vec![(0, render::texcoord(WIDTH, 1))],
            constants: Default::default(),
            samplers: vec![(
                0,
                Source::Target(0),
                crate::core::emu::SamplerState {
                    address_u: crate::core::emu::Address::Clamp,
                    address_v: crate::core::emu::Address::Clamp,
                    address_w: crate::core::emu::Address::Clamp,
                    ..Default::default()
                },
            )],
            output: OutputState::default(),
            pixel: Default::default(),
            geometry: None,
        }));
    }
    Ok(list)
}

/// The light each draw adds at pixel x: the f32 values the draw uses, in f64.
fn light_at(brightness: f32, x: u32) -> f64 {
    let u = render::texcoord(WIDTH, 1).at(x as f32, 0.0)[0];
    brightness as f64 * u as f64
}

fn half_ulp16_up_to(v: f64) -> f64 {
    crate::core::image::Encoding::Half.max_rounding_error(v)
}

/// The derived bound for one pixel (see the module docs), `None` past the
/// method's range.
pub fn bound(method: Method, lights: u32, light: f64) -> Option<f64> {
    let mut b = 0f64;
    for k in 1..=lights {
        let partial = k as f64 * light;
        match method {
            Method::Rgba8 => {
                b += Q + U * (partial + light);
                if partial > 1.0 - lights as f64 * Q {
                    return None;
                }
            }
            Method::Half => {
                let src = half_ulp16_up_to(light * (1.0 + U)) + U * light;
                b += src + half_ulp16_up_to(partial + b + src);
            }
            Method::LogRgba8 => {
                let rho = TRANSCENDENTAL + U;
                let x = Q * (partial + b).exp2() / (1.0 - rho);
                if x >= 0.5 {
                    return None;
                }
                b += U * light - (1.0 - rho).log2() - (1.0 - x).log2();
            }
        }
    }
    if method == Method::LogRgba8 {
        b += -(1.0 - U).log2() + TRANSCENDENTAL * (lights as f64 * light + b);
    }
    b.is_finite().then_some(b)
}

/// Runs one configuration.
pub fn accumulate(
    method: Method,
    lights: u32,
    brightness: f32,
    settings: &render::Settings,
) -> Result<Accumulation, String> {
    let list = draw_list(method, lights, brightness)?;
    let (_, states) = render::run(&list, settings, &mut |_, _| {}).map_err(|e| e.to_string())?;
    let result = states.last().expect("a target");
    let recovered: Vec<f64> = result.target.texels.iter().map(|t| t[0] as f64).collect();
    let truth: Vec<f64> = (0..WIDTH)
        .map(|x| lights as f64 * light_at(brightness, x))
        .collect();
    let bound = (0..WIDTH)
        .map(|x| bound(method, lights, light_at(brightness, x)))
        .collect();
    Ok(Accumulation {
        method,
        lights,
        brightness,
        truth,
        recovered,
        bound,
    })
}

impl Accumulation {
    /// The numbers of one configuration.
    pub fn summary(&self) -> Summary {
        let n = self.truth.len().max(1) as f64;
        let mut s = Summary {
            method: self.method,
            lights: self.lights,
            brightness: self.brightness,
            peak: self.truth.iter().copied().fold(0.0, f64::max),
            max_error: 0.0,
            rms_error: 0.0,
            max_error_dim: 0.0,
            levels_dim: 0,
            in_range: 0,
            within_bound: 0,
            largest_bound_fraction: 0.0,
            range_ends_at: None,
        };
        let mut squares = 0f64;
        let mut dim_values: Vec<u64> = Vec::new();
        for ((&t, &r), b) in self.truth.iter().zip(&self.recovered).zip(&self.bound) {
            let e = (r - t).abs();
            s.max_error = s.max_error.max(e);
            squares += e * e;
            if t <= DIM {
                s.max_error_dim = s.max_error_dim.max(e);
                dim_values.push(r.to_bits());
            }
            match b {
                Some(b) => {
                    s.in_range += 1;
                    if e <= *b {
                        s.within_bound += 1;
                    }
                    s.largest_bound_fraction = s.largest_bound_fraction.max(e / b);
                }
                None => {
                    s.range_ends_at = Some(s.range_ends_at.map_or(t, |a: f64| a.min(t)));
                }
            }
        }
        s.rms_error = (squares / n).sqrt();
        dim_values.sort_unstable();
        dim_values.dedup();
        s.levels_dim = dim_values.len();
        s
    }
}

/// The whole study.
#[derive(Clone, Debug, Serialize)]
pub struct Study {
    /// Pixels across each ramp ([`WIDTH`]).
    pub width: u32,
    /// Every method at each of [`BRIGHTNESS`], one light.
    pub brightness: Vec<Summary>,
    /// Every method with each of [`OVERLAPS`] lights of brightness 1.
    pub overlaps: Vec<Summary>,
    /// Every method, one light of [`SWEEP_BRIGHTNESS`]: the figure's data.
    pub sweep: Vec<Accumulation>,
}

impl Study {
    /// Every pixel in range is within its bound, in every configuration.
    pub fn all_agree(&self) -> bool {
        self.brightness
            .iter()
            .chain(&self.overlaps)
            .all(Summary::agree)
            && self.sweep.iter().all(|a| a.summary().agree())
    }
}

/// Runs every configuration; `progress(done, total)` after each.
pub fn study(settings: &render::Settings, progress: &dyn Fn(u64, u64)) -> Result<Study, String> {
    let total = (Method::ALL.len() * (BRIGHTNESS.len() + OVERLAPS.len() + 1)) as u64;
    let mut done = 0;
    let mut step = || {
        done += 1;
        progress(done, total);
    };
    let mut out = Study {
        width: WIDTH,
        brightness: Vec::new(),
        overlaps: Vec::new(),
        sweep: Vec::new(),
    };
    for &b in &BRIGHTNESS {
        for m in Method::ALL {
            out.brightness
                .push(accumulate(m, 1, b, settings)?.summary());
            step();
        }
    }
    for &k in &OVERLAPS {
        for m in Method::ALL {
            out.overlaps
                .push(accumulate(m, k, 1.0, settings)?.summary());
            step();
        }
    }
    for m in Method::ALL {
        out.sweep
            .push(accumulate(m, 1, SWEEP_BRIGHTNESS, settings)?);
        step();
    }
    Ok(out)
}
