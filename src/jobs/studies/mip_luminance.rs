//! Log-luminance in 8-bit destination alpha, averaged by the mip chain,
//! measured against the truth and against the article's two passes.
//!
//! The method (its shader and what ps30 chose where the source is silent
//! are in the header of `asm/mip-luminance/encode.psh`): every pixel writes
//! e = (log2|δ + L| + min)/(min + max), for luminances in
//! [2^−min, 2^max], to the alpha of a `D3DFMT_A8R8G8B8` target, where the
//! output merger clamps it to [0, 1] and quantises it to a code; the mip
//! chain averages the alpha down to 1 × 1, every level again in 8 bits; the
//! CPU decodes log2 L̄w = ē·(min + max) − min.
//!
//! # Where the error comes from
//!
//! Against the true L̄w = 2^mean(log2|δ + L|) (f64, every pixel once, the
//! article's δ), the result differs for three reasons, each measured here:
//!
//! 1. **Range**: pixels outside [2^−min, 2^max] are clamped — the f64 mean
//!    of the clamped, unquantised encodings (`ideal_uniform`) against the
//!    truth;
//! 2. **Odd sides**: a chain with odd sides does not weight every pixel
//!    1/N ([`crate::core::image::chain_weights`]) — the f64 weighted mean
//!    (`ideal_weighted`) against `ideal_uniform`;
//! 3. **8-bit steps**: the emulated result against `ideal_weighted`.
//!
//! # The quantisation bound
//!
//! Each pixel's stored code is within q = ½/255 of its encoding (the
//! FLOAT → UNORM rule rounds to the nearest code), plus the shader's own f32
//! error in e (below); each of the chain's levels after the base rounds its
//! averages to the nearest code, again within q. Averaging is a convex
//! combination (the weights of every level sum to 1), so each level's
//! rounding reaches the 1 × 1 result with weight 1 at most: with n levels
//! after the base,
//!
//! |ē − ideal_weighted| ≤ (n + 1)·q + s,
//!
//! s the largest shader error over the pixels: |Δ(δ + L)| ≤ 8u·A for the
//! `dp4` (A = 0.27|R| + 0.67|G| + 0.06|B| + δ, as the luminance passes'
//! bound), so |Δlog2| ≤ 8u·A/(|δ + L|·ln 2) + 1 ulp of the log; the `mad`
//! and the f32 constants 1/(min + max) and min/(min + max) add
//! 3u·(|log2| + min)/(min + max) + u. Pixels whose encoding lies clamped
//! beyond their error contribute no shader error. In log2 L̄w that is
//! (min + max) times the bound, and the relative error of L̄w is
//! 2^that − 1. The bound is worst case: roundings of both signs cancel in
//! practice — except that the FLOAT → UNORM rule rounds halves up, and a
//! 2 × 2 average of codes lands on a half in a quarter of the cases, so the
//! chain drifts upwards (the study shows by how much).

use crate::core::emu::{Address, Constants, SamplerState};
use crate::core::image::{chain_weights, weight_bound, HdrImage, OddSides, TargetFormat};
use crate::core::merge::{ColorWrite, OutputState};
use crate::jobs::luminance::{self, reference, ShaderSource};
use crate::jobs::render::{
    self, DrawList, DrawStep, ShaderSpec, Source, Step, TargetSpec, TextureData,
};
use serde::Serialize;

/// The ranges of the table: [2^−min, 2^max] as (min, max).
pub const RANGES: [(f64, f64); 4] = [(4.0, 4.0), (8.0, 8.0), (14.0, 16.0), (16.0, 16.0)];
/// Half-widths of the symmetric ranges swept for the figure, in stops.
pub const SWEEP: [f64; 12] = [
    2.0, 4.0, 6.0, 8.0, 10.0, 12.0, 14.0, 16.0, 18.0, 20.0, 24.0, 32.0,
];

const U: f64 = f32::EPSILON as f64 / 2.0;
const Q: f64 = 0.5 / 255.0;

/// The encoding's f32 constants c1 = (1/(min + max), min/(min + max)).
fn encode_constants(range: (f64, f64), delta: f32) -> Constants {
    let r = range.0 + range.1;
    Constants {
        float: vec![
            [0.27, 0.67, 0.06, delta.sqrt()],
            [(1.0 / r) as f32, (range.0 / r) as f32, 0.0, 0.0],
        ],
        ..Constants::default()
    }
}

/// The draw list: the encoding into the alpha of an A8R8G8B8 target (write
/// mask alpha only), then its mip chain.
pub fn draw_list(
    image: &HdrImage,
    range: (f64, f64),
    delta: f32,
    odd: OddSides,
) -> Result<DrawList, String> {
    let b = crate::jobs::bundled::MIP_LUMINANCE_ENCODE;
    let loaded = crate::core::load::load_str(b.path, b.text, &Default::default())
        .map_err(|e| e.to_string())?;
    let (w, h) = (image.width, image.height);
    Ok(DrawList {
        targets: vec![TargetSpec {
            name: "frame".into(),
            width: w,
            height: h,
            format: TargetFormat::A8R8G8B8,
        }],
        textures: vec![TextureData {
            name: "hdr".into(),
            width: w,
            height: h,
            texels: image.pixels.clone(),
            file: None,
        }],
        shaders: vec![ShaderSpec {
            name: b.path.into(),
            loaded,
        }],
        steps: vec![
            Step::Clear {
                target: 0,
                color: [0; 4],
            },
            Step::Draw(DrawStep {
                target: 0,
                shader: 0,
                inputs: vec![(0, render::texcoord(w, h))],
                constants: encode_constants(range, delta),
                samplers: vec![(
                    0,
                    Source::Texture(0),
                    SamplerState {
                        address_u: Address::Clamp,
                        address_v: Address::Clamp,
                        address_w: Address::Clamp,
                        ..SamplerState::default()
                    },
                )],
                output: OutputState {
                    write: ColorWrite(ColorWrite::ALPHA),
                    ..OutputState::default()
                },
                pixel: Default::default(),
                geometry: None,
            }),
            Step::Mips { target: 0, odd },
        ],
    })
}

/// One run of the method on one image with one range.
#[derive(Clone, Debug, Serialize)]
pub struct MipRun {
    /// The frame's name (a crop's names its size).
    pub image: String,
    /// Frame width in pixels.
    pub width: u32,
    /// Frame height in pixels.
    pub height: u32,
    /// [2^−min, 2^max].
    pub range: (f64, f64),
    /// How the chain reduced odd sides.
    pub odd: OddSides,
    /// Levels after the base.
    pub levels: u32,
    /// ē: the 1 × 1 alpha as stored, in [0, 1].
    pub encoded: f64,
    /// The method's L̄w: ē decoded, 2^(ē·(min + max) − min).
    pub log_average: f64,
    /// The true L̄w (f64, every pixel once).
    pub reference: f64,
    /// (L̄w − reference) / reference.
    pub relative_error: f64,
    /// Pixels below 2^−min (clamped).
    pub below: u64,
    /// Pixels above 2^max (clamped).
    pub above: u64,
    /// The f64 mean of the clamped encodings, uniform weights, decoded.
    pub ideal_uniform: f64,
    /// The same with the chain's weights, decoded.
    pub ideal_weighted: f64,
    /// ē − the weighted f64 mean of the encodings, in codes (1/255).
    pub quantisation_codes: f64,
    /// The derived bound on it, in codes.
    pub quantisation_bound_codes: f64,
    /// Whether the measured quantisation is within its bound.
    pub within_bound: bool,
    /// The relative error of L̄w the bound allows: 2^((min + max)·bound) − 1.
    pub relative_bound: f64,
}

/// What the shader computes before quantisation, exactly (f64), and a
/// bound on its f32 error (0 when clamped beyond it).
fn encoding(pixel: [f32; 4], range: (f64, f64), delta: f64) -> (f64, f64) {
    let r = range.0 + range.1;
    let l = crate::core::image::luminance(pixel);
    let log = (delta + l).abs().log2();
    let e = (log + range.0) / r;
    let a = 0.27 * (pixel[0] as f64).abs()
        + 0.67 * (pixel[1] as f64).abs()
        + 0.06 * (pixel[2] as f64).abs()
        + delta;
    let x = (delta + l).abs();
    let dlog = 8.0 * U * a / (x * std::f64::consts::LN_2) + 2.0 * U * log.abs().max(1.0);
    let err = dlog / r + 3.0 * U * (log.abs() + range.0) / r + U;
    let clamped = e + err < 0.0 || e - err > 1.0;
    (e.clamp(0.0, 1.0), if clamped { 0.0 } else { err })
}

/// Runs the method on `image` (named `name`) and measures it.
pub fn run(
    name: &str,
    image: &HdrImage,
    range: (f64, f64),
    odd: OddSides,
    delta: f32,
    settings: &render::Settings,
) -> Result<MipRun, String> {
    let list = draw_list(image, range, delta, odd)?;
    let (reports, _) = render::run(&list, settings, &mut |_, _| {}).map_err(|e| e.to_string())?;
    let (levels, encoded) = match reports.last().map(|r| &r.detail) {
        Some(render::StepDetail::Mips { levels, mean, .. }) => (*levels as u32 - 1, mean[3] as f64),
        _ => return Err("the draw list ends without its reduction".into()),
    };
    let (w, h) = (image.width, image.height);
    let chain_levels = levels + 1;
    let (wx, wy) = (
        chain_weights(w, chain_levels, odd),
        chain_weights(h, chain_levels, odd),
    );
    let d = delta as f64;
    let r = range.0 + range.1;
    let (mut uniform, mut weighted, mut shader, mut below, mut above) = (0f64, 0f64, 0f64, 0, 0);
    for y in 0..h {
        for x in 0..w {
            let p = image.pixel(x, y);
            let (e, err) = encoding(p, range, d);
            let raw = ((d + crate::core::image::luminance(p)).abs().log2() + range.0) / r;
            if raw < 0.0 {
                below += 1;
            } else if raw > 1.0 {
                above += 1;
            }
            uniform += e;
            weighted += wx[x as usize] * wy[y as usize] * e;
            shader = shader.max(err);
        }
    }
    uniform /= w as f64 * h as f64;
    let decode = |e: f64| (e * r - range.0).exp2();
    let truth = reference::log_average(image, d, reference::Policy::ABS).log_average;
    let log_average = decode(encoded);
    let bound = (levels as f64 + 1.0) * Q + shader;
    let quantisation = encoded - weighted;
    Ok(MipRun {
        image: name.to_string(),
        width: w,
        height: h,
        range,
        odd,
        levels,
        encoded,
        log_average,
        reference: truth,
        relative_error: (log_average - truth) / truth,
        below,
        above,
        ideal_uniform: decode(uniform),
        ideal_weighted: decode(weighted),
        quantisation_codes: quantisation * 255.0,
        quantisation_bound_codes: bound * 255.0,
        within_bound: quantisation.abs() <= bound,
        relative_bound: (r * bound).exp2() - 1.0,
    })
}

/// The article's two passes on the same image (corrected shaders, 125×128,
/// R32F): its L̄w and relative error against the same truth.
#[derive(Clone, Debug, Serialize)]
pub struct ArticleRun {
    /// The image's name.
    pub image: String,
    /// L̄w from the two passes.
    pub log_average: f64,
    /// The true L̄w (f64, every pixel once).
    pub reference: f64,
    /// (L̄w − reference) / reference.
    pub relative_error: f64,
    /// Whether the run agrees everywhere: blocks, pass 2, L̄w and the counts.
    pub agree: bool,
}

fn article(
    name: &str,
    image: &HdrImage,
    settings: &render::Settings,
) -> Result<ArticleRun, String> {
    let src = |n: &str| {
        let (p, t) = crate::jobs::bundled::listing(n).expect("bundled");
        ShaderSource::new(p, t)
    };
    let run = luminance::run(
        image,
        &src("corrected:unrolled"),
        &src("corrected:pass2"),
        &luminance::Settings {
            threads: settings.threads,
            limits: settings.limits,
            ..luminance::Settings::default()
        },
    )
    .map_err(|e| e.to_string())?;
    Ok(ArticleRun {
        image: name.to_string(),
        log_average: run.log_average,
        reference: run.reference_log_average,
        relative_error: (run.log_average - run.reference_log_average) / run.reference_log_average,
        agree: run.all_agree(),
    })
}

/// The top-left `w × h` of an image: frames whose mip chains have odd sides.
pub fn crop(image: &HdrImage, w: u32, h: u32) -> HdrImage {
    let pixels = (0..h.min(image.height))
        .flat_map(|y| (0..w.min(image.width)).map(move |x| (x, y)))
        .map(|(x, y)| image.pixel(x, y))
        .collect();
    HdrImage {
        width: w.min(image.width),
        height: h.min(image.height),
        pixels,
    }
}

/// The frames cropped from the article-sized image, for odd sides.
pub const CROPS: [(u32, u32); 2] = [(1000, 600), (640, 480)];
/// The image the crops and the range sweep use.
pub const SWEEP_IMAGE: &str = "courtyard_1280x1024.exr";
/// The range whose odd-side rules are compared.
pub const ODD_RANGE: (f64, f64) = (8.0, 8.0);

/// One frame of the study: its runs with every range, the article's result.
#[derive(Clone, Debug, Serialize)]
pub struct Frame {
    /// The frame's name (a crop's names its size).
    pub image: String,
    /// Frame width in pixels.
    pub width: u32,
    /// Frame height in pixels.
    pub height: u32,
    /// The article's two passes on the same frame.
    pub article: ArticleRun,
    /// One per [`RANGES`], odd sides folded.
    pub runs: Vec<MipRun>,
    /// [`ODD_RANGE`] with bilinear odd sides, for frames that have odd sides.
    pub bilinear: Option<MipRun>,
    /// ½·Σ|w − 1/N| of the folded chain: the most odd sides can move ē.
    pub weight_bound: f64,
}

/// The whole study.
#[derive(Clone, Debug, Serialize)]
pub struct Study {
    /// δ of log2(δ + L), the article's, in every run.
    pub delta: f32,
    /// Every image given, then [`SWEEP_IMAGE`] cropped to each of [`CROPS`].
    pub frames: Vec<Frame>,
    /// [`SWEEP_IMAGE`] with the symmetric ranges of [`SWEEP`].
    pub sweep: Vec<MipRun>,
}

impl Study {
    /// Every emulated result within its quantisation bound, and every
    /// article run agreeing with its own cross-check.
    pub fn all_agree(&self) -> bool {
        self.frames
            .iter()
            .all(|f| f.article.agree && f.runs.iter().chain(&f.bilinear).all(|r| r.within_bound))
            && self.sweep.iter().all(|r| r.within_bound)
    }
}

fn has_odd_sides(w: u32, h: u32) -> bool {
    let levels = crate::core::image::full_chain_levels(w, h);
    (0..levels).any(|i| {
        let (a, b) = ((w >> i).max(1), (h >> i).max(1));
        (a > 1 && a % 2 == 1) || (b > 1 && b % 2 == 1)
    })
}

/// Runs the study over `images` (name, image), adding the [`CROPS`] of
/// [`SWEEP_IMAGE`] when it is among them. `progress(done, total)`.
pub fn study(
    images: &[(String, HdrImage)],
    delta: f32,
    settings: &render::Settings,
    progress: &dyn Fn(u64, u64),
) -> Result<Study, String> {
    let mut frames_in: Vec<(String, HdrImage)> = images.to_vec();
    let sweep_source = images
        .iter()
        .find(|(n, _)| n == SWEEP_IMAGE)
        .map(|(_, i)| i);
    if let Some(img) = sweep_source {
        for (w, h) in CROPS {
            frames_in.push((format!("{SWEEP_IMAGE} cropped to {w}×{h}"), crop(img, w, h)));
        }
    }
    let total = (frames_in.len() * (RANGES.len() + 2) + SWEEP.len()) as u64;
    let mut done = 0u64;
    let mut tick = || {
        done += 1;
        progress(done, total);
    };
    let mut frames = Vec::new();
    for (name, img) in &frames_in {
        let article = article(name, img, settings)?;
        tick();
        let mut runs = Vec::new();
        for range in RANGES {
            runs.push(run(name, img, range, OddSides::Fold, delta, settings)?);
            tick();
        }
        let bilinear = if has_odd_sides(img.width, img.height) {
            Some(run(
                name,
                img,
                ODD_RANGE,
                OddSides::Bilinear,
                delta,
                settings,
            )?)
        } else {
            None
        };
        tick();
        frames.push(Frame {
            image: name.clone(),
            width: img.width,
            height: img.height,
            article,
            runs,
            bilinear,
            weight_bound: weight_bound(img.width, img.height, OddSides::Fold),
        });
    }
    let mut sweep = Vec::new();
    if let Some(img) = sweep_source {
        for half in SWEEP {
            sweep.push(run(
                SWEEP_IMAGE,
                img,
                (half, half),
                OddSides::Fold,
                delta,
                settings,
            )?);
            tick();
        }
    }
    Ok(Study {
        delta,
        frames,
        sweep,
    })
}
