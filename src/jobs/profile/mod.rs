//! `ps30 profile`: what a shader costs quad by quad over an image, and where
//! it relies on something Direct3D leaves undefined.
//!
//! One draw in the emulator gives, per pixel, the executed slots of its own
//! path and, per 2×2 quad, the slots the quad executed in lockstep — every
//! instruction any of its four pixels ran (see [`crate::core::emu`]). From them:
//!
//! * min / mean / max and a histogram of slots per pixel and per quad, next
//!   to the static shortest and longest paths of the cost model (what Arm's
//!   Mali Offline Compiler reports as shortest/longest path);
//! * the divergent quads (some instruction ran with only part of the quad)
//!   and the *lockstep efficiency*: the pixels' own slots as a share of what
//!   their quads executed, Σ pixel slots / Σ (quad slots × pixels of the
//!   quad in the target);
//! * what each source line cost: its runs by pixels and by helper lanes,
//!   by quads in lockstep and how many of those split the quad
//!   ([`crate::core::emu::lines`], from the emulator's counts per instruction);
//! * findings:
//!   - **divergent gradient**: a `dsx`/`dsy` of a temporary, or a
//!     `texld`/`texldp`/`texldb` with a temporary coordinate, that some quad
//!     ran with only part of its pixels — the gradient read neighbours that
//!     were not at the same point (undefined in Direct3D); with the source
//!     line and the number of quads;
//!   - **LOD far from level 0**: a `texld`/`texldp`/`texldb` whose largest
//!     level of detail (gradients, MIPMAPLODBIAS and texldb's w) is at least
//!     [`LOD_WARNING`](crate::core::emu::findings::LOD_WARNING) while its sampler can only read the base level (the
//!     texture has one level, or MIPFILTER is NONE): the shader gets level 0
//!     only because nothing else exists — on a mipmapped texture the same
//!     instruction would read level ⌊λ + ½⌋. With point sampling a λ ≥ 1
//!     also means neighbouring pixels skip texels. The luminance pass is the
//!     example: its neighbours read blocks 125 × 128 texels apart, λ = 7.
//!
//! Exit status of the command: 1 when the shader does not fit the ps_3_0
//! limits, when a divergent-gradient finding exists,
//! when emulated counts leave the cost model's range, or (G-buffer input)
//! when a pixel differs from the CPU computation; LOD findings are
//! warnings only.

use crate::core::cost::{self, Environment, Profile, Range};
use crate::core::diag::SourceFile;
use crate::core::emu::findings::{findings, Finding, FindingKind, SiteSummary};
use crate::core::emu::{self, Constants, Draw, DrawOutput, MipChain, SamplerState, TextureLevels};
use crate::core::image::HdrImage;
use crate::core::load::{self, Options};
use crate::core::numbers::thousands;
use crate::jobs::render::costs::QuadRun;
use serde::Serialize;

pub mod list;

/// Min, mean, max and a histogram of a list of slot counts.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct CostStats {
    /// How many values (pixels or quads).
    pub count: u64,
    /// The smallest value; 0 for an empty list.
    pub min: u64,
    /// The arithmetic mean; 0 for an empty list.
    pub mean: f64,
    /// The largest value; 0 for an empty list.
    pub max: u64,
    /// Bins `lo..=hi` with their counts, in order; one bin per distinct
    /// value when there are at most as many values as bins requested.
    pub histogram: Vec<Bin>,
}

/// One histogram bin: the values from `lo` to `hi`, both included.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct Bin {
    /// Smallest value in the bin.
    pub lo: u64,
    /// Largest value in the bin (`lo` when the bin holds one value).
    pub hi: u64,
    /// How many values fall in it.
    pub count: u64,
}

impl CostStats {
    /// Statistics of `values` with at most `bins` histogram bins (at least 1).
    pub fn of(values: &[u64], bins: usize) -> CostStats {
        let bins = bins.max(1);
        let count = values.len() as u64;
        let min = values.iter().copied().min().unwrap_or(0);
        let max = values.iter().copied().max().unwrap_or(0);
        let sum: u128 = values.iter().map(|&v| v as u128).sum();
        let mean = if count == 0 {
            0.0
        } else {
            sum as f64 / count as f64
        };
        let mut distinct: Vec<u64> = values.to_vec();
        distinct.sort_unstable();
        distinct.dedup();
        let histogram = if distinct.len() <= bins {
            distinct
                .iter()
                .map(|&v| Bin {
                    lo: v,
                    hi: v,
                    count: values.iter().filter(|&&x| x == v).count() as u64,
                })
                .collect()
        } else {
            let span = max - min + 1;
            let width = span.div_ceil(bins as u64);
            let n = span.div_ceil(width) as usize;
            let mut h: Vec<Bin> = (0..n as u64)
                .map(|k| Bin {
                    lo: min + k * width,
                    hi: (min + (k + 1) * width - 1).min(max),
                    count: 0,
                })
                .collect();
            for &v in values {
                h[((v - min) / width) as usize].count += 1;
            }
            h
        };
        CostStats {
            count,
            min,
            mean,
            max,
            histogram,
        }
    }
}

/// Per-pixel and per-quad costs of one draw.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct QuadCosts {
    /// Executed slots per pixel, each on its own path.
    pub per_pixel: CostStats,
    /// Executed slots per 2×2 quad in lockstep: every slot any of its pixels ran.
    pub per_quad: CostStats,
    /// Quads the draw covered (partial ones at odd target sides included).
    pub quads: u64,
    /// Quads where some instruction ran with only part of the quad.
    pub divergent_quads: u64,
    /// Σ pixel slots / Σ (quad slots × the quad's pixels in the target).
    pub lockstep_efficiency: f64,
    /// The same over divergent quads only (1 when there are none).
    pub divergent_efficiency: f64,
}

/// The costs of a draw's output, with `bins` histogram bins.
pub fn quad_costs(out: &DrawOutput, bins: usize) -> QuadCosts {
    let (w, h) = (out.width as u64, out.height as u64);
    let qx = out.quads_x as u64;
    let mut quads: Vec<QuadRun> = out
        .quad_executed
        .iter()
        .zip(&out.quad_divergent)
        .map(|(&executed, &divergent)| QuadRun {
            executed,
            own: 0,
            pixels: 0,
            divergent,
        })
        .collect();
    for y in 0..h {
        for x in 0..w {
            if let Some(q) = quads.get_mut(((y / 2) * qx + x / 2) as usize) {
                q.own += out.executed[(y * w + x) as usize];
                q.pixels += 1;
            }
        }
    }
    costs_of(&out.executed, &quads, bins)
}

/// The costs of `pixels`' own executed slots and the `quads` they ran in,
/// with `bins` histogram bins.
pub fn costs_of(pixels: &[u64], quads: &[QuadRun], bins: usize) -> QuadCosts {
    let ratio = |pick: &dyn Fn(&QuadRun) -> bool| {
        let (mut num, mut den) = (0u128, 0u128);
        for q in quads.iter().filter(|q| pick(q)) {
            num += q.own as u128;
            den += q.executed as u128 * q.pixels as u128;
        }
        if den == 0 {
            1.0
        } else {
            num as f64 / den as f64
        }
    };
    let executed: Vec<u64> = quads.iter().map(|q| q.executed).collect();
    QuadCosts {
        per_pixel: CostStats::of(pixels, bins),
        per_quad: CostStats::of(&executed, bins),
        quads: quads.len() as u64,
        divergent_quads: quads.iter().filter(|q| q.divergent).count() as u64,
        lockstep_efficiency: ratio(&|_| true),
        divergent_efficiency: ratio(&|q| q.divergent),
    }
}

/// What `ps30 profile` ran on.
#[derive(Clone, Debug)]
pub enum Input {
    /// The synthetic G-buffer of [`crate::jobs::scenes::lights`], `w × h`.
    GBuffer(u32, u32),
    /// An image sampled by s0, v0 = the start of each pixel's block of it
    /// (as `ps30 run`), into a `target`.
    Image {
        /// The image, sampled through s0.
        image: HdrImage,
        /// Its name, for the report.
        name: String,
        /// The render target, width × height in pixels.
        target: (u32, u32),
        /// s0's sampler state.
        sampler: SamplerState,
        /// Build a full box-filtered mip chain for s0.
        mips: bool,
    },
}

/// Binds `textures` (`--inputs`) to their samplers, in place of what the
/// input bound there.
fn bind_textures<'a>(
    draw: &mut emu::Draw<'a>,
    textures: &'a [(u32, crate::core::image::TextureFile, SamplerState)],
) {
    draw.samplers
        .retain(|(s, _, _)| !textures.iter().any(|(t, _, _)| t == s));
    for (s, file, state) in textures {
        draw.samplers.push((*s, file.into(), *state));
    }
}

/// Everything `ps30 profile` needs besides the shader.
#[derive(Clone, Debug)]
pub struct Setup {
    /// What the shader runs on.
    pub input: Input,
    /// `-D NAME=N`: the numbers the source names (REPEAT_BLOCK counts).
    pub defines: Vec<(String, u64)>,
    /// The application's constants (`--const`), besides those the input sets.
    pub constants: Constants,
    /// Histogram bins asked for (at least 1 is used).
    pub bins: usize,
    /// Textures bound besides the input's (`--inputs`); one on a sampler
    /// the input binds takes its place.
    pub textures: Vec<(u32, crate::core::image::TextureFile, SamplerState)>,
    /// Emulator threads; `None` for every core.
    pub threads: Option<usize>,
    /// The emulator's bounds (executed slots per pixel, target size).
    pub limits: emu::EmuLimits,
    /// The float rules the draw computes by (`--float-rules`): costs follow
    /// the values where a branch reads a special one.
    pub float_rules: crate::core::float_rules::FloatRules,
}

/// The float constants the input sets itself: the G-buffer scene sets c4
/// (see [`Scene::material_scale`](crate::jobs::scenes::lights::Scene::material_scale)),
/// an image sets none.
pub fn floats_set_by(input: &Input) -> &'static [u32] {
    match input {
        Input::GBuffer(..) => &[4],
        Input::Image { .. } => &[],
    }
}

/// The result of `ps30 profile`.
#[derive(Clone, Debug)]
pub struct ProfileRun {
    /// The shader's source, for diagnostics.
    pub file: SourceFile,
    /// What it ran on, in words (`memorial (512×768, 1 level) → 4×6 target`).
    pub input: String,
    /// Target width in pixels.
    pub width: u32,
    /// Target height in pixels.
    pub height: u32,
    /// The cost model's shortest and longest executed count per pixel.
    pub static_executed: Range,
    /// The static slots and executed count fit the ps_3_0 limits.
    pub within_limits: bool,
    /// Whether every pixel's emulated count lies inside [`ProfileRun::static_executed`].
    pub counts_agree: bool,
    /// Per-pixel and per-quad costs, with lockstep efficiency.
    pub costs: QuadCosts,
    /// What each source line cost ([`emu::lines`]).
    pub lines: Vec<emu::lines::LineRuns>,
    /// Every instruction that takes a gradient, with how often quads ran it
    /// divergently.
    pub gradients: Vec<SiteSummary>,
    /// Divergent-gradient and LOD findings (module docs).
    pub findings: Vec<Finding>,
    /// Warnings the validator gave.
    pub warnings: crate::core::diag::Diagnostics,
    /// G-buffer input: pixels per light model and how many match the CPU.
    pub models: Option<[(u64, u64); crate::jobs::scenes::lights::MODELS]>,
}

impl ProfileRun {
    /// Whether the run found a problem (see the module docs).
    pub fn problem(&self) -> bool {
        !self.counts_agree
            || !self.within_limits
            || self
                .findings
                .iter()
                .any(|f| f.kind == FindingKind::DivergentGradient)
            || self
                .models
                .is_some_and(|m| m.iter().any(|&(n, ok)| n != ok))
    }
}

/// Runs `ps30 profile` on assembly text.
pub fn profile(name: &str, text: &str, setup: &Setup) -> Result<ProfileRun, String> {
    profile_file(SourceFile::new(name, text), setup)
}

/// Runs `ps30 profile` on any source, text or compiled (loaded with
/// `setup.defines`); a source that does not load gives its diagnostics as
/// the error (the command line loads the shader itself, reporting as it
/// does everywhere, and calls [`profile_loaded`]).
pub fn profile_file(file: SourceFile, setup: &Setup) -> Result<ProfileRun, String> {
    let mut opts = Options::default();
    for (k, v) in &setup.defines {
        opts.defines.insert(k.clone(), *v);
    }
    let loaded =
        load::load(file, &opts).map_err(|e| format!("{}\n{e}", e.diagnostics.render(&e.file)))?;
    profile_loaded(loaded, setup)
}

/// Runs `ps30 profile` on a loaded shader.
pub fn profile_loaded(loaded: load::Loaded, setup: &Setup) -> Result<ProfileRun, String> {
    let compiled = emu::compile(&loaded.shader).map_err(|e| e.to_string())?;
    let env = environment(&setup.constants);
    let analysis = cost::analyse(&loaded.shader, &loaded.file, &env, &Profile::ps_3_0())
        .map_err(|e| e.to_string())?;
    let run = |draw: &Draw| -> Result<DrawOutput, String> {
        match setup.threads {
            Some(t) => emu::run_with_threads(&compiled, draw, t),
            None => emu::run(&compiled, draw),
        }
        .map_err(|e| format!("emulator: {e}"))
    };
    let scene;
    let chain;
    let (out, draw, input, models) = match &setup.input {
        Input::GBuffer(w, h) => {
            let pixels = u64::from(*w) * u64::from(*h);
            if pixels > setup.limits.max_target_pixels {
                return Err(emu::EmuError::TargetTooLarge {
                    width: *w,
                    height: *h,
                    limit: setup.limits.max_target_pixels,
                }
                .to_string());
            }
            scene =
                crate::jobs::scenes::lights::Scene::synthetic(*w, *h).map_err(|e| e.to_string())?;
            let mut draw = gbuffer_draw(&loaded.file.name, &loaded, setup, &scene)?;
            bind_textures(&mut draw, &setup.textures);
            let out = run(&draw)?;
            let models = crate::jobs::scenes::lights::compare(&scene, &out);
            let counts = scene.pixels_per_model();
            let input = format!(
                "the synthetic G-buffer {w}×{h} (light models 0 / 1 / 2: {} / {} / {} pixels)",
                thousands(counts[0]),
                thousands(counts[1]),
                thousands(counts[2])
            );
            (out, draw, input, Some(models))
        }
        Input::Image {
            image,
            name: image_name,
            target,
            sampler,
            mips,
        } => {
            chain = if *mips {
                Some(MipChain::build(image.as_texture(), None)?)
            } else {
                None
            };
            let mut draw = image_draw(&loaded, setup, image, *target, *sampler, chain.as_ref());
            bind_textures(&mut draw, &setup.textures);
            let out = run(&draw)?;
            let levels = chain.as_ref().map_or(1, |c| c.len());
            let (tw, th) = *target;
            let input = format!(
                "{image_name} ({}×{}, {} level{}) → {tw}×{th} target",
                image.width,
                image.height,
                levels,
                if levels == 1 { "" } else { "s" }
            );
            (out, draw, input, None)
        }
    };
    let costs = quad_costs(&out, setup.bins);
    let counts_agree = analysis.executed.min <= costs.per_pixel.min
        && costs.per_pixel.max <= analysis.executed.max;
    let found = findings(&out, &draw, &loaded.file);
    let gradients = out
        .gradients
        .iter()
        .map(|g| SiteSummary::new(g, &loaded.file))
        .collect();
    let lines = emu::lines::pixel_lines(&loaded.shader, &loaded.file, &out.instructions);
    Ok(ProfileRun {
        input,
        width: out.width,
        height: out.height,
        static_executed: analysis.executed,
        within_limits: analysis.verdict == cost::Verdict::Within,
        counts_agree,
        costs,
        lines,
        gradients,
        findings: found,
        warnings: loaded.warnings,
        models,
        file: loaded.file,
    })
}

/// The cost model's environment: the draw's integer and boolean constants.
fn environment(constants: &Constants) -> Environment {
    let mut env = Environment::default();
    for (i, v) in constants.int.iter().enumerate() {
        env.ints.insert(i as u32, *v);
    }
    for (i, v) in constants.bool.iter().enumerate() {
        env.bools.insert(i as u32, *v);
    }
    env
}

/// The draw over the synthetic G-buffer `scene`, for a light-model shader.
fn gbuffer_draw<'s>(
    name: &str,
    loaded: &load::Loaded,
    setup: &Setup,
    scene: &'s crate::jobs::scenes::lights::Scene,
) -> Result<Draw<'s>, String> {
    crate::jobs::scenes::lights::Scene::check_constants(loaded.shader.program())
        .map_err(|e| format!("{name}: not a light-model shader for the G-buffer scene: {e}"))?;
    let mut draw = scene.draw();
    draw.record_lod = true;
    draw.count_instructions = true;
    draw.limits = setup.limits;
    draw.float_rules = setup.float_rules;
    // The command line's constants, except c4, which the scene sets.
    let mut floats = setup.constants.float.clone();
    floats.resize(floats.len().max(5), [0.0; 4]);
    floats[4] = scene.material_scale();
    draw.constants = Constants {
        float: floats,
        ..setup.constants.clone()
    };
    Ok(draw)
}

/// The draw of `image` into a `target`: v0 at each pixel's block of the
/// image (when the shader declares v0), s0 the image or its mip `chain`
/// (when the shader declares s0).
fn image_draw<'i>(
    loaded: &load::Loaded,
    setup: &Setup,
    image: &'i HdrImage,
    (tw, th): (u32, u32),
    sampler: SamplerState,
    chain: Option<&'i MipChain>,
) -> Draw<'i> {
    let mut draw = Draw::new(tw, th);
    // v0 in ps_3_0, t0 in ps_2_x.
    if let Some(at) = crate::core::pixel_inputs::declared_coordinates(loaded.shader.program()) {
        draw.inputs.push((
            at,
            crate::jobs::luminance::block_start(
                image.width,
                image.height,
                image.width.div_ceil(tw),
                image.height.div_ceil(th),
            ),
        ));
    }
    draw.constants = setup.constants.clone();
    draw.record_lod = true;
    draw.count_instructions = true;
    draw.limits = setup.limits;
    draw.float_rules = setup.float_rules;
    if loaded.shader.program().sampler_type(0).is_some() {
        let tex: TextureLevels = match chain {
            Some(c) => c.into(),
            None => image.as_texture().into(),
        };
        draw.samplers.push((0, tex, sampler));
    }
    draw
}

// ----- the command line ----------------------------------------------------------
//
// The arguments live here rather than in `main.rs` so that the binary only
// names the subcommand; the value parsers follow `main.rs`'s.
