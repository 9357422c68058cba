//! The emulator against a GPU: the same draw on both, compared pixel by
//! pixel and channel by channel ([`stats`]), the luminance pipeline's L̄w
//! from both against the f64 reference, and per-instruction probes
//! ([`probe`]) that say which of the device's instructions differ from the
//! emulator's, and how — the evidence every explanation cites.
//!
//! A difference is explained when both backends stay inside the bound the
//! arithmetic allows (the luminance blocks and L̄w, the tone-mapped pixels:
//! the bounds `jobs/luminance` and `jobs/tonemap` derive), and the probes
//! name the instructions whose device results differ. A difference beyond
//! a bound is a finding, reported as such. [`all`] runs every bundled
//! shader on the bundled images for `reports/gpu-crosscheck.md`.

pub mod all;
pub mod draws;
pub mod explain;
pub mod probe;
pub mod stats;
pub mod vertices;

use crate::core::emu::{self, Draw};
use crate::core::gpu::{self, Gpu, GpuError, TargetKind};
use crate::core::image::HdrImage;
use crate::core::load::Loaded;
use crate::jobs::backend::Backend;
use crate::jobs::luminance::{self, LuminanceRun, PipelineError, ShaderSource};
use serde::Serialize;
use stats::ChannelStats;
use std::fmt;
use std::sync::Arc;

/// Why a comparison could not be made.
#[derive(Debug)]
pub enum CompareError {
    /// The emulator refused or could not finish the draw.
    Emu(emu::EmuError),
    /// The translation, the device or the read-back failed.
    Gpu(GpuError),
    /// The luminance pipeline failed on one of the backends.
    Pipeline(PipelineError),
    /// Anything else (a bundled shader or scene that does not load), as a sentence.
    Other(String),
}

impl fmt::Display for CompareError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            CompareError::Emu(e) => write!(f, "emulator: {e}"),
            CompareError::Gpu(e) => write!(f, "{e}"),
            CompareError::Pipeline(e) => write!(f, "{e}"),
            CompareError::Other(e) => f.write_str(e),
        }
    }
}

impl std::error::Error for CompareError {}

/// The value of every input at one pixel.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PixelInputs {
    /// Column, in pixels from the left.
    pub x: u32,
    /// Row, in pixels from the top.
    pub y: u32,
    /// `(register, value)`: each `v#` as the draw gives it, and vPos.
    pub values: Vec<(String, [f32; 4])>,
}

/// One draw on both backends.
#[derive(Clone, Debug, Serialize)]
pub struct DrawComparison {
    /// The shader's file name.
    pub shader: String,
    /// Target width in pixels.
    pub width: u32,
    /// Target height in pixels.
    pub height: u32,
    /// What the targets store: a D3D9 format, or `f32` (unrounded).
    pub target: String,
    /// The float rules both backends ran under (`d3d9`, `ieee`, `d3d9-zero-mul`, `hardware`).
    pub float_rules: String,
    /// One entry per written channel (`oC0.r` … `oDepth`).
    pub channels: Vec<ChannelStats>,
    /// Pixels killed on one backend only.
    pub killed_mismatches: u64,
    /// The inputs at every pixel named among the worst.
    pub worst_inputs: Vec<PixelInputs>,
    /// The instructions the shader uses (mnemonics), for the explanation.
    pub opcodes: Vec<String>,
    /// The draw's samplers whose filtering the device may do otherwise
    /// than the emulator ([`explain::filtering`]), one clause each.
    pub filtering: Vec<String>,
    /// Why the backends differ; set by [`explain`] once probes ran.
    pub explanation: Option<explain::Explanation>,
}

impl DrawComparison {
    /// Whether every stored channel is bit-identical and no pixel is killed on
    /// one backend only.
    pub fn all_identical(&self) -> bool {
        self.killed_mismatches == 0 && self.channels.iter().all(|c| c.all_identical())
    }

    /// The largest distance in ulps over every channel.
    pub fn max_ulp(&self) -> u64 {
        self.channels.iter().map(|c| c.max_ulp).max().unwrap_or(0)
    }

    /// NaN or ∞ on one backend only, over every channel.
    pub fn special_mismatches(&self) -> u64 {
        self.channels
            .iter()
            .map(|c| c.nan_mismatches + c.inf_mismatches)
            .sum()
    }
}

fn target_name(kind: TargetKind) -> String {
    match kind {
        TargetKind::Raw => "f32 (unrounded)".into(),
        TargetKind::Format(f) => f.d3d_name().into(),
    }
}

/// The channels a target stores: R32F and R16F only red, the two-channel
/// formats red and green.
fn stored_channels(kind: TargetKind) -> &'static [usize] {
    match kind {
        TargetKind::Raw => &[0, 1, 2, 3],
        TargetKind::Format(f) => &[0, 1, 2, 3][..f.channels()],
    }
}

/// Tone mapping of one image on both backends.
#[derive(Clone, Debug, Serialize)]
pub struct TonemapComparison {
    /// The image's name.
    pub image: String,
    /// The r, g, b channels of the linear result.
    pub draw: DrawComparison,
    /// Pixels tone-mapped.
    pub pixels: u64,
    /// Pixels within their derived bound of the f64 reference on the GPU.
    pub gpu_within: u64,
    /// Pixels within their derived bound of the f64 reference on the emulator.
    pub emulator_within: u64,
    /// Why the backends differ; set once probes ran.
    pub explanation: Option<explain::Explanation>,
}

/// Everything `ps30 compare --all` measured.
#[derive(Clone, Debug, Serialize)]
pub struct CrossCheck {
    /// The device both runs were compared on.
    pub device: gpu::DeviceInfo,
    /// The float rules every comparison ran under.
    pub float_rules: String,
    /// One per probed instruction ([`probe::run`]).
    pub probes: Vec<probe::Probe>,
    /// The luminance pipeline, one entry per image and pass set.
    pub luminance: Vec<LuminanceComparison>,
    /// Tone mapping, one entry per image.
    pub tonemap: Vec<TonemapComparison>,
    /// The light-model shaders on their synthetic G-buffer.
    pub lights: Vec<DrawComparison>,
}

/// Runs `draw` on the emulator and on `gpu` and compares what the targets
/// hold: the emulator's values stored as `target` stores them (rounded to
/// f16 for D3DFMT_A16B16G16R16F), the device's as it stored them.
pub fn compare_draw(
    gpu: &Gpu,
    loaded: &Loaded,
    draw: &Draw,
    target: TargetKind,
    threads: Option<usize>,
) -> Result<DrawComparison, CompareError> {
    let compiled = emu::compile(&loaded.shader).map_err(CompareError::Emu)?;
    let e = match threads {
        Some(t) => emu::run_with_threads(&compiled, draw, t),
        None => emu::run(&compiled, draw),
    }
    .map_err(CompareError::Emu)?;
    let g = gpu::run(gpu, &loaded.shader, draw, target).map_err(CompareError::Gpu)?;
    let store = |v: [f32; 4]| match target {
        TargetKind::Raw => v,
        TargetKind::Format(f) => f.round(v),
    };
    let w = draw.target_width;
    let mut channels = Vec::new();
    for k in 0..4 {
        let (Some(ec), Some(gc)) = (&e.color[k], &g.color[k]) else {
            // Written on neither, or (a write no pixel reached) on the
            // GPU's static list only: both targets hold their clear value.
            continue;
        };
        for &c in stored_channels(target) {
            let ev: Vec<f32> = ec.iter().map(|&v| store(v)[c]).collect();
            let gv: Vec<f32> = gc.iter().map(|v| v[c]).collect();
            let name = format!("oC{k}.{}", ["r", "g", "b", "a"][c]);
            channels.push(ChannelStats::of(name, w, &ev, &gv));
        }
    }
    if let (Some(ed), Some(gd)) = (&e.depth, &g.depth) {
        // The depth target holds oDepth clamped to [0, 1].
        let ev: Vec<f32> = ed.iter().map(|d| d.clamp(0.0, 1.0)).collect();
        channels.push(ChannelStats::of("oDepth".into(), w, &ev, gd));
    }
    let killed_mismatches = e
        .killed
        .iter()
        .zip(&g.killed)
        .filter(|(a, b)| a != b)
        .count() as u64;
    let mut pixels: Vec<(u32, u32)> = channels
        .iter()
        .flat_map(|c| c.worst.iter().map(|w| (w.x, w.y)))
        .collect();
    pixels.sort_unstable();
    pixels.dedup();
    let worst_inputs = pixels
        .into_iter()
        .map(|(x, y)| {
            let mut values: Vec<(String, [f32; 4])> = draw
                .inputs
                .iter()
                .map(|(v, input)| {
                    let profile = loaded.shader.program().profile;
                    (
                        crate::core::pixel_inputs::name(profile, *v),
                        input.at(x as f32, y as f32),
                    )
                })
                .collect();
            values.push(("vPos".into(), [x as f32, y as f32, 0.0, 0.0]));
            PixelInputs { x, y, values }
        })
        .collect();
    Ok(DrawComparison {
        shader: loaded.file.name.clone(),
        width: w,
        height: draw.target_height,
        target: target_name(target),
        float_rules: draw.float_rules.name().into(),
        channels,
        killed_mismatches,
        worst_inputs,
        opcodes: opcodes(&[&loaded.shader]),
        filtering: explain::filtering(draw),
        explanation: None,
    })
}

/// The mnemonics of the instructions `shaders` use, sorted.
pub fn opcodes(shaders: &[&crate::core::ir::Shader]) -> Vec<String> {
    let mut v: Vec<String> = shaders
        .iter()
        .flat_map(|s| s.instructions().iter().map(|i| i.op.to_string()))
        .collect();
    v.sort_unstable();
    v.dedup();
    v
}

/// L̄w from both backends and the f64 reference.
#[derive(Clone, Debug, Serialize)]
pub struct LogAverages {
    /// L̄w as the GPU computed it.
    pub gpu: f64,
    /// L̄w as the emulator computed it.
    pub emulator: f64,
    /// L̄w of the f64 reference.
    pub reference: f64,
    /// |GPU − reference| / |reference|.
    pub gpu_relative_error: f64,
    /// |emulator − reference| / |reference|.
    pub emulator_relative_error: f64,
    /// The derived bound on the relative error (the same for both: it
    /// assumes no evaluation order, fused or not).
    pub tolerance: f64,
}

/// The luminance pipeline on both backends.
#[derive(Clone, Debug, Serialize)]
pub struct LuminanceComparison {
    /// The image's name.
    pub image: String,
    /// The pass-1 shader's name.
    pub pass1: String,
    /// The shader of pass 1's last column, where the block width does not
    /// divide the image's (`None`: one shader for every column, BORDER
    /// padding in x).
    pub pass1_last: Option<String>,
    /// The pass-2 shader's name.
    pub pass2: String,
    /// Pixels per pass-1 block, (width, height).
    pub block: (u32, u32),
    /// The pass-1 target's size in blocks, (width, height).
    pub targets: (u32, u32),
    /// The pass-1 target's D3D9 format.
    pub target_format: String,
    /// The pass-1 target (block sums) and pass 2's 1×1, compared.
    pub blocks: ChannelStats,
    /// L̄w from both backends and the reference, with the derived bound.
    pub log_average: LogAverages,
    /// Blocks within their bound of the f64 reference on the GPU.
    pub gpu_blocks_within: usize,
    /// Blocks within their bound of the f64 reference on the emulator.
    pub emulator_blocks_within: usize,
    /// Whether the GPU's run agrees with the reference everywhere.
    pub gpu_agrees: bool,
    /// Whether the emulator's run agrees with the reference everywhere.
    pub emulator_agrees: bool,
    /// The instructions the passes use (mnemonics).
    pub opcodes: Vec<String>,
    /// Why the backends differ; set by [`explain`] once probes ran.
    pub explanation: Option<explain::Explanation>,
}

/// Runs the luminance passes on the emulator and on `gpu`.
pub fn compare_luminance(
    gpu: &Arc<Gpu>,
    image: (&str, &HdrImage),
    pass1: &ShaderSource,
    last: Option<&ShaderSource>,
    pass2: &ShaderSource,
    settings: &luminance::Settings,
) -> Result<LuminanceComparison, CompareError> {
    let run = |backend: Backend| -> Result<LuminanceRun, CompareError> {
        let s = luminance::Settings {
            backend,
            ..settings.clone()
        };
        match last {
            Some(l) => luminance::run_with_last_column(image.1, pass1, l, pass2, &s),
            None => luminance::run(image.1, pass1, pass2, &s),
        }
        .map_err(CompareError::Pipeline)
    };
    let e = run(Backend::Emulator)?;
    let g = run(Backend::Gpu(gpu.clone()))?;
    let ev: Vec<f32> = e.blocks.iter().map(|b| b.emulated as f32).collect();
    let gv: Vec<f32> = g.blocks.iter().map(|b| b.emulated as f32).collect();
    let blocks = ChannelStats::of("pass 1 block sums".into(), e.targets.0, &ev, &gv);
    let rel = |v: f64| (v - e.reference_log_average).abs() / e.reference_log_average.abs();
    let mut shaders = Vec::new();
    for (src, defines) in [
        (Some(pass1), vec![("bw", e.block.0), ("bh", e.block.1)]),
        (last, vec![]),
        (
            Some(pass2),
            vec![("xsize", e.targets.0), ("ysize", e.targets.1)],
        ),
    ] {
        if let Some(src) = src {
            let mut opts = crate::core::load::Options::default();
            for (k, v) in defines {
                opts.defines.insert(k.to_string(), v as u64);
            }
            let l = crate::core::load::load(src.file.clone(), &opts)
                .map_err(|e| CompareError::Other(e.to_string()))?;
            shaders.push(l.shader);
        }
    }
    Ok(LuminanceComparison {
        image: image.0.to_string(),
        pass1: pass1.name().to_string(),
        pass1_last: last.map(|l| l.name().to_string()),
        pass2: pass2.name().to_string(),
        block: e.block,
        targets: e.targets,
        target_format: e.target_format.d3d_name().into(),
        blocks,
        log_average: LogAverages {
            gpu: g.log_average,
            emulator: e.log_average,
            reference: e.reference_log_average,
            gpu_relative_error: rel(g.log_average),
            emulator_relative_error: rel(e.log_average),
            tolerance: e.relative_tolerance,
        },
        gpu_blocks_within: g.blocks.iter().filter(|b| b.agree).count(),
        emulator_blocks_within: e.blocks.iter().filter(|b| b.agree).count(),
        gpu_agrees: g.all_agree(),
        emulator_agrees: e.all_agree(),
        opcodes: opcodes(&shaders.iter().collect::<Vec<_>>()),
        explanation: None,
    })
}
