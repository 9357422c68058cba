//! The article's chain end to end: a G-buffer lit by several lights of the
//! light-model shader, each added into a `D3DFMT_A16B16G16R16F` target with
//! `ONE, ONE` blending ("every light accumulates into it using standard
//! additive blending"), L̄w of the lit buffer by the luminance passes, and
//! the buffer tone-mapped by the article's operator into 8-bit sRGB.
//!
//! Every stage is checked against f64:
//!
//! * the accumulation: every channel of every pixel against the f64 sum of
//!   the lights' values, each light's value the f32 result of the shader's
//!   operation order ([`Scene::expected_light`]); the bound is the blend's own
//!   rounding in half floats: light k is converted to half (at most half the
//!   half spacing at its value) and added to the stored sum (half the
//!   spacing at the new sum), so with Pₖ the exact partial sums and Bₖ the
//!   bound so far, Bₖ = Bₖ₋₁ + ρ(ℓₖ) + ρ(Pₖ + Bₖ₋₁ + ρ(ℓₖ)), ρ =
//!   [`Encoding::max_rounding_error`] of half;
//! * L̄w: the luminance passes' own cross-check against the f64 log-average of
//!   the lit buffer ([`crate::jobs::luminance`]);
//! * the tone map: every pixel within its derived bound
//!   ([`crate::jobs::tonemap`]).

use crate::core::emu::{Address, Constants, SamplerState};
use crate::core::image::{Encoding, HdrImage, RenderTarget, TargetFormat};
use crate::core::merge::{BlendState, ColorWrite, Equation, OutputState};
use crate::jobs::render::{
    self, DrawList, DrawStep, ShaderSpec, Source, Step, StepReport, TargetSpec, TextureData,
};
use crate::jobs::scenes::lights::{material_state, Light, Scene, MATERIAL_SIZE};
use crate::jobs::tonemap::{self, ToneMapped};
use serde::Serialize;

/// The article's frame.
pub const SIZE: (u32, u32) = (1280, 1024);

/// Four lights: a bright warm key light, a blue fill, a white rim and a
/// very dim one — a range of intensities the tone map has to bring down.
pub fn default_lights() -> Vec<Light> {
    vec![
        Light::new([0.48, 0.6, 0.64], [12.0, 10.5, 8.0]),
        Light::new([-0.8, 0.0, 0.6], [0.25, 0.35, 0.9]),
        Light::new([0.0, -0.6, 0.8], [1.5, 1.5, 1.2]),
        Light::new([0.3, 0.3, 0.9], [0.01, 0.01, 0.012]),
    ]
}

/// The draw list: clear the light buffer, one additive draw per light
/// (RGB written; alpha stays 0).
pub fn draw_list(scene: &Scene, lights: &[Light]) -> Result<DrawList, String> {
    let b = crate::jobs::bundled::LIGHTS_DIRECTIONAL;
    let loaded = crate::core::load::load_str(b.path, b.text, &Default::default())
        .map_err(|e| e.to_string())?;
    let (w, h) = (scene.width, scene.height);
    let mut textures = vec![TextureData {
        name: "gbuffer".into(),
        width: w,
        height: h,
        texels: scene.gbuffer.clone(),
        file: None,
    }];
    for (m, texels) in scene.materials.iter().enumerate() {
        textures.push(TextureData {
            name: format!("material{m}"),
            width: MATERIAL_SIZE,
            height: MATERIAL_SIZE,
            texels: texels.clone(),
            file: None,
        });
    }
    let gbuffer_state = SamplerState {
        address_u: Address::Clamp,
        address_v: Address::Clamp,
        address_w: Address::Clamp,
        ..SamplerState::default()
    };
    let mut steps = vec![Step::Clear {
        target: 0,
        color: [0; 4],
    }];
    for light in lights {
        let c = light.constants();
        let mut samplers = vec![(0, Source::Texture(0), gbuffer_state)];
        for m in 0..3 {
            samplers.push((m as u32 + 1, Source::Texture(m + 1), material_state()));
        }
        steps.push(Step::Draw(DrawStep {
            target: 0,
            shader: 0,
            inputs: vec![(0, scene.texcoord())],
            constants: Constants {
                float: vec![
                    [0.0; 4],
                    [0.0; 4],
                    [0.0; 4],
                    [0.0; 4],
                    scene.material_scale(),
                    c[0],
                    c[1],
                    c[2],
                ],
                ..Constants::default()
            },
            samplers,
            output: OutputState {
                blend: BlendState::with(Equation::ADDITIVE),
                write: ColorWrite(ColorWrite::RED | ColorWrite::GREEN | ColorWrite::BLUE),
            },
            pixel: Default::default(),
            geometry: None,
        }));
    }
    Ok(DrawList {
        targets: vec![TargetSpec {
            name: "light".into(),
            width: w,
            height: h,
            format: TargetFormat::Rgba16F,
        }],
        textures,
        shaders: vec![ShaderSpec {
            name: b.path.into(),
            loaded,
        }],
        steps,
    })
}

/// The accumulation against the f64 sum of the lights.
#[derive(Clone, Debug, Default, Serialize)]
pub struct SumCheck {
    /// Channels compared (R, G, B of every pixel).
    pub channels: u64,
    /// Channels outside their bound.
    pub outside: u64,
    /// The largest |stored − f64 sum| over the channels.
    pub max_error: f64,
    /// The bound where the error is largest relative to its bound.
    pub bound_there: f64,
    /// The largest error / bound.
    pub largest_fraction: f64,
    /// The largest relative error (error / sum) over non-zero sums.
    pub max_relative_error: f64,
}

/// Compares the accumulated buffer with the f64 sum of the lights.
pub fn check_sum(scene: &Scene, lights: &[Light], buffer: &RenderTarget) -> SumCheck {
    let rho = |v: f64| Encoding::Half.max_rounding_error(v);
    let mut c = SumCheck::default();
    for y in 0..scene.height {
        for x in 0..scene.width {
            let values: Vec<[f32; 4]> = lights
                .iter()
                .map(|l| scene.expected_light(x, y, l))
                .collect();
            let stored = buffer.texel(x, y);
            for ch in 0..3 {
                let (mut sum, mut bound) = (0f64, 0f64);
                for v in &values {
                    let l = v[ch] as f64;
                    sum += l;
                    bound += rho(l) + rho(sum + bound + rho(l));
                }
                let e = (stored[ch] as f64 - sum).abs();
                c.channels += 1;
                if e > bound {
                    c.outside += 1;
                }
                if e > c.max_error {
                    c.max_error = e;
                }
                let f = if bound > 0.0 {
                    e / bound
                } else if e == 0.0 {
                    0.0
                } else {
                    f64::INFINITY
                };
                if f > c.largest_fraction {
                    c.largest_fraction = f;
                    c.bound_there = bound;
                }
                if sum > 0.0 {
                    c.max_relative_error = c.max_relative_error.max(e / sum);
                }
            }
        }
    }
    c
}

/// Everything the chain produced.
#[derive(Clone, Debug)]
pub struct ChainRun {
    /// Frame width in pixels.
    pub width: u32,
    /// Frame height in pixels.
    pub height: u32,
    /// The lights drawn, in order.
    pub lights: Vec<Light>,
    /// Pixels per light model.
    pub models: [u64; 3],
    /// Every step of the draw list, as it ran.
    pub steps: Vec<StepReport>,
    /// The accumulated lights against their f64 sum.
    pub sum: SumCheck,
    /// The lit buffer as it was stored.
    pub buffer: RenderTarget,
    /// The smallest and largest luminance in the buffer.
    pub luminance_range: (f64, f64),
    /// The lit buffer tone-mapped, with its check against the f64 operator.
    pub tonemap: ToneMapped,
    /// The tone-mapped buffer: linear, saturated RGBA, row-major.
    pub tonemapped: Vec<[f32; 4]>,
}

impl ChainRun {
    /// Every stage agrees with its reference and every draw with the cost model.
    pub fn all_agree(&self) -> bool {
        self.sum.outside == 0
            && self.tonemap.all_agree()
            && self.steps.iter().all(|s| match &s.detail {
                render::StepDetail::Draw { counts_agree, .. } => *counts_agree,
                _ => true,
            })
    }
}

/// Runs the chain on the synthetic G-buffer of `size` with `lights`.
pub fn run(
    size: (u32, u32),
    lights: &[Light],
    tone: &tonemap::Settings,
    settings: &render::Settings,
    progress: &dyn Fn(u64, u64),
) -> Result<ChainRun, String> {
    let scene = Scene::synthetic(size.0, size.1).map_err(|e| e.0)?;
    let list = draw_list(&scene, lights)?;
    let total = lights.len() as u64 + 3;
    let (steps, mut states) = render::run(&list, settings, &mut |r, _| {
        progress(r.index as u64 + 1, total)
    })
    .map_err(|e| e.to_string())?;
    let buffer = states.remove(0).target;
    let sum = check_sum(&scene, lights, &buffer);
    progress(total - 1, total);
    let image = HdrImage {
        width: buffer.width,
        height: buffer.height,
        pixels: buffer.texels.clone(),
    };
    let lum: Vec<f64> = image
        .pixels
        .iter()
        .map(|&p| crate::core::image::luminance(p))
        .collect();
    let luminance_range = (
        lum.iter().copied().fold(f64::INFINITY, f64::min),
        lum.iter().copied().fold(f64::NEG_INFINITY, f64::max),
    );
    let (tonemap, tonemapped) =
        tonemap::run(&image, tone, &|_, _| {}).map_err(|e| e.to_string())?;
    progress(total, total);
    Ok(ChainRun {
        width: size.0,
        height: size.1,
        lights: lights.to_vec(),
        models: scene.pixels_per_model(),
        steps,
        sum,
        buffer,
        luminance_range,
        tonemap,
        tonemapped,
    })
}
