//! Every bundled shader on the bundled images, on the emulator and on one
//! GPU: what `ps30 compare --all` runs and `reports/gpu-crosscheck.md`
//! shows.
//!
//! * the instruction probes ([`super::probe`]);
//! * the luminance pipeline — the article's and the corrected listings
//!   (loop and unrolled) and the generated shaders for 1280×1024 (the
//!   plan's configurations, with and without their last-column shader) on
//!   `courtyard_1280x1024.exr`, and the corrected unrolled pair on every
//!   other bundled image;
//! * tone mapping on every bundled image: the same operator (the
//!   emulator's L̄w) on both backends, each checked against the f64
//!   reference within its per-pixel bound;
//! * the light-model shaders on their synthetic G-buffer.

use super::explain;
use super::probe;
use super::stats::ChannelStats;
use super::{
    compare_draw, compare_luminance, CompareError, CrossCheck, DrawComparison, TonemapComparison,
};
use crate::core::gpu::{Gpu, TargetKind};
use crate::core::image::{self, HdrImage, ImageLimits, TargetFormat};
use crate::core::load::{self, Options};
use crate::jobs::backend::Backend;
use crate::jobs::bundled;
use crate::jobs::luminance::{self, ShaderSource};
use crate::jobs::tonemap;
use std::path::Path;
use std::sync::Arc;

fn source(b: bundled::Bundled) -> ShaderSource {
    ShaderSource::new(b.path, b.text)
}

/// The image the article's frame size is: every pipeline variant runs on it.
pub const FRAME_IMAGE: &str = "courtyard_1280x1024.exr";

/// (pass 1, last column, pass 2, block, target format) on the frame image.
type Pipeline = (
    ShaderSource,
    Option<ShaderSource>,
    ShaderSource,
    (u32, u32),
    TargetFormat,
);

/// The pipelines run on the frame image: the article's and the corrected
/// listings (loop and unrolled; the corrected unrolled pair also into an
/// f16 target, finding 3) and the generated shaders for 1280×1024.
fn frame_pipelines() -> Result<Vec<Pipeline>, CompareError> {
    let (bundle, _) = crate::jobs::gen::set::frame_set((1280, 1024))
        .map_err(|e| CompareError::Other(format!("generated shaders: {e}")))?;
    let generated = |file: &str| -> Result<ShaderSource, CompareError> {
        bundle
            .shaders
            .iter()
            .find(|g| g.file == file)
            .map(|g| {
                ShaderSource::new(
                    format!("asm/generated/1280x1024/{}", g.file),
                    g.text.clone(),
                )
            })
            .ok_or_else(|| CompareError::Other(format!("no generated shader {file}")))
    };
    let f32 = TargetFormat::R32F;
    let (a1, a2) = (bundled::ARTICLE_LOOP, bundled::ARTICLE_PASS2);
    let (c1, c2) = (bundled::CORRECTED_LOOP, bundled::CORRECTED_PASS2);
    let unrolled = (125, 128);
    let mut pipelines: Vec<Pipeline> = vec![
        (source(a1), None, source(a2), (128, 56), f32),
        (
            source(bundled::ARTICLE_UNROLLED),
            None,
            source(a2),
            unrolled,
            f32,
        ),
        (source(c1), None, source(c2), (128, 56), f32),
        (
            source(bundled::CORRECTED_UNROLLED),
            None,
            source(c2),
            unrolled,
            f32,
        ),
        // Finding 3: an f16 target cannot hold the sums.
        (
            source(bundled::CORRECTED_UNROLLED),
            None,
            source(c2),
            unrolled,
            TargetFormat::Rgba16F,
        ),
    ];
    for c in &bundle.configs {
        let Some(pass2) = &c.pass2 else { continue };
        let block = (c.block[0], c.block[1]);
        let (p1, p2) = (generated(&c.pass1)?, generated(pass2)?);
        pipelines.push((p1.clone(), None, p2.clone(), block, f32));
        if let Some(last) = &c.last_column {
            pipelines.push((p1, Some(generated(last)?), p2, block, f32));
        }
    }
    Ok(pipelines)
}

fn load_image(images: &Path, name: &str) -> Result<HdrImage, CompareError> {
    image::load(&images.join(name), &ImageLimits::default())
        .map_err(|e| CompareError::Other(e.to_string()))
}

/// Runs the whole set. `images` is the folder of the bundled images and
/// `names` the files in it; `progress(step, total, what)` is called before
/// each step.
pub fn run(
    gpu: &Arc<Gpu>,
    images: &Path,
    names: &[&str],
    progress: &dyn Fn(usize, usize, &str),
) -> Result<CrossCheck, CompareError> {
    let settings = luminance::Settings {
        threads: None,
        ..luminance::Settings::default()
    };
    let pipelines = frame_pipelines()?;
    let others: Vec<&str> = names
        .iter()
        .copied()
        .filter(|n| *n != FRAME_IMAGE)
        .collect();
    let total = 1 + pipelines.len() + others.len() + names.len() + 2;
    let mut step = 0;
    let mut next = |what: &str| {
        progress(step, total, what);
        step += 1;
    };

    next("instruction probes");
    let probes = probe::run(gpu)?;

    let frame = load_image(images, FRAME_IMAGE)?;
    let mut lum = Vec::new();
    for (p1, last, p2, block, format) in &pipelines {
        next(&format!("luminance: {}", p1.name()));
        let s = luminance::Settings {
            block: *block,
            format: *format,
            ..settings.clone()
        };
        let image = (FRAME_IMAGE, &frame);
        lum.push(compare_luminance(gpu, image, p1, last.as_ref(), p2, &s)?);
    }
    let (c1, c2) = (
        source(bundled::CORRECTED_UNROLLED),
        source(bundled::CORRECTED_PASS2),
    );
    for name in &others {
        next(&format!("luminance: {name}"));
        let img = load_image(images, name)?;
        lum.push(compare_luminance(
            gpu,
            (name, &img),
            &c1,
            None,
            &c2,
            &settings,
        )?);
    }

    let mut tone = Vec::new();
    for name in names {
        next(&format!("tone mapping: {name}"));
        let img = if *name == FRAME_IMAGE {
            frame.clone()
        } else {
            load_image(images, name)?
        };
        tone.push(compare_tonemap(gpu, name, &img)?);
    }
    let mut lights = compare_lights(gpu, &mut next)?;

    for c in &mut lum {
        c.explanation = Some(explain::luminance(c, &probes));
    }
    for c in &mut tone {
        c.explanation = Some(explain::tonemap(c, &probes));
    }
    for c in &mut lights {
        c.explanation = Some(explain::draw(c, &probes));
    }
    Ok(CrossCheck {
        device: gpu.info().clone(),
        float_rules: settings.float_rules.name().into(),
        probes,
        luminance: lum,
        tonemap: tone,
        lights,
    })
}

/// The light-model shaders on their synthetic G-buffer, one step each.
fn compare_lights(
    gpu: &Arc<Gpu>,
    next: &mut dyn FnMut(&str),
) -> Result<Vec<DrawComparison>, CompareError> {
    let scene = crate::jobs::scenes::lights::Scene::synthetic(256, 256)
        .map_err(|e| CompareError::Other(e.0))?;
    let mut lights = Vec::new();
    for b in [bundled::LIGHTS_SELECT, bundled::LIGHTS_TEXLD] {
        next(b.name);
        let loaded = load::load_str(b.path, b.text, &Options::default())
            .map_err(|e| CompareError::Other(e.to_string()))?;
        lights.push(compare_draw(
            gpu,
            &loaded,
            &scene.draw(),
            TargetKind::Raw,
            None,
        )?);
    }
    Ok(lights)
}

/// Tone-maps `image` on both backends with the emulator's operator.
pub fn compare_tonemap(
    gpu: &Arc<Gpu>,
    name: &str,
    image: &HdrImage,
) -> Result<TonemapComparison, CompareError> {
    let settings = tonemap::Settings::default();
    let (e, e_linear) = tonemap::run(image, &settings, &|_, _| {})
        .map_err(|e| CompareError::Other(e.to_string()))?;
    let on_gpu = tonemap::Settings {
        backend: Backend::Gpu(gpu.clone()),
        band_rows: image.height,
        ..settings
    };
    let mut linear = Vec::with_capacity(image.pixels.len());
    tonemap::emulate(image, &e.operator, &on_gpu, &|_, _| {}, &mut |band| {
        linear.extend_from_slice(band);
        Ok(())
    })
    .map_err(|e| CompareError::Other(e.to_string()))?;
    let g_check = tonemap::crosscheck(&e.operator, image, &linear);
    let w = image.width;
    let channels = (0..3)
        .map(|c| {
            let ev: Vec<f32> = e_linear.iter().map(|v| v[c]).collect();
            let gv: Vec<f32> = linear.iter().map(|v| v[c]).collect();
            ChannelStats::of(format!("oC0.{}", ["r", "g", "b"][c]), w, &ev, &gv)
        })
        .collect();
    let pixels = e.check.pixels;
    Ok(TonemapComparison {
        image: name.to_string(),
        draw: DrawComparison {
            shader: e.cost.shader.clone(),
            width: image.width,
            height: image.height,
            target: "f32 (unrounded)".into(),
            float_rules: settings.float_rules.name().into(),
            channels,
            killed_mismatches: 0,
            worst_inputs: Vec::new(),
            opcodes: super::opcodes(&[&loaded_tonemap()?]),
            filtering: Vec::new(),
            explanation: None,
        },
        pixels,
        gpu_within: pixels - g_check.outside_bound,
        emulator_within: pixels - e.check.outside_bound,
        explanation: None,
    })
}

fn loaded_tonemap() -> Result<crate::core::ir::Shader, CompareError> {
    let b = bundled::TONEMAP_REINHARD;
    load::load_str(b.path, b.text, &Options::default())
        .map(|l| l.shader)
        .map_err(|e| CompareError::Other(e.to_string()))
}
