//! `ps30 profile`: what a shader costs quad by quad over an image, and where
//! it relies on something Direct3D leaves undefined.
//!
//! One draw in the emulator gives, per pixel, the executed slots of its own
//! path and, per 2×2 quad, the slots the quad executed in lockstep — every
//! instruction any of its four pixels ran (see [`crate::emu`]). From them:
//!
//! * min / mean / max and a histogram of slots per pixel and per quad, next
//!   to the static shortest and longest paths of the cost model (what Arm's
//!   Mali Offline Compiler reports as shortest/longest path);
//! * the divergent quads (some instruction ran with only part of the quad)
//!   and the *lockstep efficiency*: the pixels' own slots as a share of what
//!   their quads executed, Σ pixel slots / Σ (quad slots × pixels of the
//!   quad in the target);
//! * findings:
//!   - **divergent gradient**: a `dsx`/`dsy` of a temporary, or a
//!     `texld`/`texldp`/`texldb` with a temporary coordinate, that some quad
//!     ran with only part of its pixels — the gradient read neighbours that
//!     were not at the same point (undefined in Direct3D); with the source
//!     line and the number of quads;
//!   - **LOD far from level 0**: a `texld`/`texldp`/`texldb` whose largest
//!     level of detail (gradients, MIPMAPLODBIAS and texldb's w) is at least
//!     [`LOD_WARNING`] while its sampler can only read the base level (the
//!     texture has one level, or MIPFILTER is NONE): the shader gets level 0
//!     only because nothing else exists — on a mipmapped texture the same
//!     instruction would read level ⌊λ + ½⌋. With point sampling a λ ≥ 1
//!     also means neighbouring pixels skip texels. The luminance pass is the
//!     example: its neighbours read blocks 125 × 128 texels apart, λ = 7.
//!
//! Exit status of the command: 1 when a divergent-gradient finding exists,
//! when emulated counts leave the cost model's range, or (G-buffer input)
//! when a pixel differs from the CPU computation; LOD findings are
//! warnings only.

use crate::args::{
    parse_bool_const, parse_define, parse_finite, parse_float4, parse_float_const, parse_int_const,
    parse_size,
};
use crate::cost::{self, Environment, Profile, Range};
use crate::diag::{Diagnostic, SourceFile};
use crate::emu::{
    self, Address, Constants, Draw, DrawOutput, Filter, GradientSite, MipChain, MipFilter,
    SamplerState, TextureLevels,
};
use crate::front::{self, Options};
use crate::image::HdrImage;
use crate::isa::Opcode;
use serde::Serialize;
use serde_json::{json, Value};

/// A texld-family LOD at least this large, on a sampler that can only read
/// its base level, is reported: one whole level, neighbouring pixels two or
/// more texels apart.
pub const LOD_WARNING: f32 = 1.0;

/// Min, mean, max and a histogram of a list of slot counts.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct CostStats {
    pub count: u64,
    pub min: u64,
    pub mean: f64,
    pub max: u64,
    /// Bins `lo..=hi` with their counts, in order; one bin per distinct
    /// value when there are at most as many values as bins requested.
    pub histogram: Vec<Bin>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct Bin {
    pub lo: u64,
    pub hi: u64,
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
    pub per_pixel: CostStats,
    pub per_quad: CostStats,
    pub quads: u64,
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
    let mut own = vec![0u64; out.quad_executed.len()];
    let mut pixels = vec![0u64; out.quad_executed.len()];
    for y in 0..h {
        for x in 0..w {
            let q = ((y / 2) * qx + x / 2) as usize;
            if let (Some(o), Some(p)) = (own.get_mut(q), pixels.get_mut(q)) {
                *o += out.executed[(y * w + x) as usize];
                *p += 1;
            }
        }
    }
    let ratio = |pick: &dyn Fn(usize) -> bool| {
        let (mut num, mut den) = (0u128, 0u128);
        for (q, &cost) in out.quad_executed.iter().enumerate() {
            if pick(q) {
                num += own[q] as u128;
                den += cost as u128 * pixels[q] as u128;
            }
        }
        if den == 0 {
            1.0
        } else {
            num as f64 / den as f64
        }
    };
    QuadCosts {
        per_pixel: CostStats::of(&out.executed, bins),
        per_quad: CostStats::of(&out.quad_executed, bins),
        quads: out.quad_executed.len() as u64,
        divergent_quads: out.quad_divergent.iter().filter(|&&d| d).count() as u64,
        lockstep_efficiency: ratio(&|_| true),
        divergent_efficiency: ratio(&|q| out.quad_divergent[q]),
    }
}

/// What a finding is about.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum FindingKind {
    DivergentGradient,
    LodFarFromLevel0,
}

/// One problem found in a draw, at a source statement.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Finding {
    pub kind: FindingKind,
    pub site: SiteSummary,
    pub message: String,
    /// Shown under the caret.
    pub label: String,
    pub help: String,
}

/// A gradient site without its span (serialisable).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SiteSummary {
    pub line: usize,
    pub column: usize,
    pub op: String,
    pub sampler: Option<u32>,
    pub temp_source: bool,
    pub quads: u64,
    pub divergent_quads: u64,
    pub executions: u64,
    pub divergent_executions: u64,
    /// (min, max) LOD; infinities print as strings in JSON.
    #[serde(serialize_with = "lod_json")]
    pub lod: Option<(f32, f32)>,
    #[serde(skip)]
    pub span: crate::ir::Span,
}

fn lod_json<S: serde::Serializer>(lod: &Option<(f32, f32)>, s: S) -> Result<S::Ok, S::Error> {
    let f = |v: f32| -> Value {
        if v.is_finite() {
            json!(v)
        } else {
            json!(format!("{v}"))
        }
    };
    match lod {
        Some((lo, hi)) => json!({"min": f(*lo), "max": f(*hi)}).serialize(s),
        None => s.serialize_none(),
    }
}

impl SiteSummary {
    pub fn new(g: &GradientSite, file: &SourceFile) -> SiteSummary {
        let (line, column) = file.line_col(g.span.start);
        SiteSummary {
            line,
            column,
            op: g.op.to_string(),
            sampler: g.sampler,
            temp_source: g.temp_source,
            quads: g.quads,
            divergent_quads: g.divergent_quads,
            executions: g.executions,
            divergent_executions: g.divergent_executions,
            lod: g.lod,
            span: g.span,
        }
    }
}

fn lod_text(v: f32) -> String {
    if v.is_finite() {
        format!("{v:.2}")
    } else {
        format!("{v}")
    }
}

/// The findings of a draw (see the module docs for the rules). `draw` must
/// be the draw that produced `out`.
pub fn findings(out: &DrawOutput, draw: &Draw, file: &SourceFile) -> Vec<Finding> {
    let mut found = Vec::new();
    for g in &out.gradients {
        let site = SiteSummary::new(g, file);
        if g.temp_source && g.divergent_quads > 0 {
            let what = match g.op {
                Opcode::Dsx | Opcode::Dsy => "its difference",
                _ => "its mip level",
            };
            found.push(Finding {
                kind: FindingKind::DivergentGradient,
                message: format!(
                    "`{}` ran in divergent quads: {what} came from neighbours that were not running it",
                    g.op
                ),
                label: format!(
                    "{} of {} quads ran it with only part of their pixels ({} of {} executions)",
                    crate::report::thousands(g.divergent_quads),
                    crate::report::thousands(g.quads),
                    crate::report::thousands(g.divergent_executions),
                    crate::report::thousands(g.executions)
                ),
                help: match g.op {
                    Opcode::Dsx | Opcode::Dsy => {
                        "take dsx/dsy before the branch, where every pixel of the quad runs it"
                            .to_string()
                    }
                    _ => "use texldl (explicit LOD) or texldd with gradients taken before the branch"
                        .to_string(),
                },
                site: site.clone(),
            });
        }
        let (Some((lo, hi)), Some(s)) = (g.lod, g.sampler) else {
            continue;
        };
        if !matches!(g.op, Opcode::TexLd | Opcode::TexLdP | Opcode::TexLdB) || hi < LOD_WARNING {
            continue;
        }
        let Some((_, tex, state)) = draw.samplers.iter().find(|(i, _, _)| *i == s) else {
            continue;
        };
        let base_only = if tex.len() == 1 {
            Some(format!("s{s} has one level"))
        } else if state.mip_filter == MipFilter::None {
            Some(format!("s{s}'s mip filter is NONE"))
        } else {
            None
        };
        let Some(why) = base_only else { continue };
        let range = if lod_text(lo) == lod_text(hi) {
            format!("LOD {}", lod_text(hi))
        } else {
            format!("LOD {} to {}", lod_text(lo), lod_text(hi))
        };
        found.push(Finding {
            kind: FindingKind::LodFarFromLevel0,
            message: format!(
                "`{}` computes {range} but reads level 0 only because {why}",
                g.op
            ),
            label: format!(
                "neighbouring pixels sample up to 2^{} = {:.0} texels apart",
                lod_text(hi),
                2f64.powf(hi as f64)
            ),
            help: format!(
                "on a mipmapped texture this would read level {}; if level 0 is meant, say so with texldl and w = 0",
                (hi + 0.5).floor().max(0.0)
            ),
            site,
        });
    }
    found
}

/// A finding as a compiler-style warning.
pub fn diagnostic(f: &Finding) -> Diagnostic {
    Diagnostic::warning(f.site.span, f.message.clone())
        .with_label(f.label.clone())
        .with_help(f.help.clone())
}

/// A shader by bundled name (`corrected:unrolled`, `lights:texld`, …) or
/// file path.
pub fn shader_source(spec: &str) -> Result<(String, String), String> {
    if let Some((name, text)) =
        crate::verify::bundled(spec).or_else(|| crate::lights::bundled(spec))
    {
        return Ok((name.to_string(), text.to_string()));
    }
    let bytes = std::fs::read(spec).map_err(|e| format!("{spec}: {e}"))?;
    String::from_utf8(bytes)
        .map_err(|e| {
            format!(
                "{spec}: not UTF-8 text (invalid byte at offset {})",
                e.utf8_error().valid_up_to()
            )
        })
        .map(|t| (spec.to_string(), t))
}

/// What `ps30 profile` ran on.
#[derive(Clone, Debug)]
pub enum Input {
    /// The synthetic G-buffer of [`crate::lights`], `w × h`.
    GBuffer(u32, u32),
    /// An image sampled by s0, v0 = the start of each pixel's block of it
    /// (as `ps30 run`), into a `target`.
    Image {
        image: HdrImage,
        name: String,
        target: (u32, u32),
        sampler: SamplerState,
        /// Build a full box-filtered mip chain for s0.
        mips: bool,
    },
}

/// Everything `ps30 profile` needs besides the shader.
#[derive(Clone, Debug)]
pub struct Setup {
    pub input: Input,
    pub defines: Vec<(String, u64)>,
    pub constants: Constants,
    pub bins: usize,
    pub threads: Option<usize>,
}

/// The result of `ps30 profile`.
#[derive(Clone, Debug)]
pub struct ProfileRun {
    pub file: SourceFile,
    pub input: String,
    pub width: u32,
    pub height: u32,
    pub static_executed: Range,
    pub counts_agree: bool,
    pub costs: QuadCosts,
    pub gradients: Vec<SiteSummary>,
    pub findings: Vec<Finding>,
    /// Warnings the validator gave.
    pub warnings: crate::diag::Diagnostics,
    /// G-buffer input: pixels per light model and how many match the CPU.
    pub models: Option<[(u64, u64); crate::lights::MODELS]>,
}

impl ProfileRun {
    /// Whether the run found a problem (see the module docs).
    pub fn problem(&self) -> bool {
        !self.counts_agree
            || self
                .findings
                .iter()
                .any(|f| f.kind == FindingKind::DivergentGradient)
            || self
                .models
                .is_some_and(|m| m.iter().any(|&(n, ok)| n != ok))
    }
}

/// Runs `ps30 profile`.
pub fn profile(name: &str, text: &str, setup: &Setup) -> Result<ProfileRun, String> {
    let mut opts = Options::default();
    for (k, v) in &setup.defines {
        opts.defines.insert(k.clone(), *v);
    }
    let loaded = front::load_str(name, text, &opts)
        .map_err(|e| format!("{}\n{e}", e.diagnostics.render(&e.file)))?;
    let compiled = emu::compile(&loaded.shader).map_err(|e| e.to_string())?;
    let mut env = Environment::default();
    for (i, v) in setup.constants.int.iter().enumerate() {
        env.ints.insert(i as u32, *v);
    }
    for (i, v) in setup.constants.bool.iter().enumerate() {
        env.bools.insert(i as u32, *v);
    }
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
            scene = crate::lights::Scene::synthetic(*w, *h).map_err(|e| e.to_string())?;
            crate::lights::Scene::check_constants(loaded.shader.program())
                .map_err(|e| format!("{name}: not a light-model shader for this scene: {e}"))?;
            let mut draw = scene.draw();
            draw.record_lod = true;
            // The command line's constants, except c4, which the scene sets.
            let mut floats = setup.constants.float.clone();
            floats.resize(floats.len().max(5), [0.0; 4]);
            floats[4] = scene.material_scale();
            draw.constants = Constants {
                float: floats,
                ..setup.constants.clone()
            };
            let out = run(&draw)?;
            let models = crate::lights::compare(&scene, &out);
            let counts = scene.pixels_per_model();
            let input = format!(
                "the synthetic G-buffer {w}×{h} (light models 0 / 1 / 2: {} / {} / {} pixels)",
                crate::report::thousands(counts[0]),
                crate::report::thousands(counts[1]),
                crate::report::thousands(counts[2])
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
            let (tw, th) = *target;
            let mut draw = Draw::new(tw, th);
            if loaded
                .shader
                .program()
                .inputs
                .iter()
                .any(|d| d.reg.file == crate::isa::RegFile::Input && d.reg.index == 0)
            {
                draw.inputs.push((
                    0,
                    crate::pipeline::block_start(
                        image.width,
                        image.height,
                        image.width.div_ceil(tw),
                        image.height.div_ceil(th),
                    ),
                ));
            }
            draw.constants = setup.constants.clone();
            draw.record_lod = true;
            chain = if *mips {
                Some(MipChain::build(image.as_texture(), None)?)
            } else {
                None
            };
            if loaded.shader.program().sampler_type(0).is_some() {
                let tex: TextureLevels = match &chain {
                    Some(c) => c.into(),
                    None => image.as_texture().into(),
                };
                draw.samplers.push((0, tex, *sampler));
            }
            let out = run(&draw)?;
            let levels = chain.as_ref().map_or(1, |c| c.len());
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
    Ok(ProfileRun {
        input,
        width: out.width,
        height: out.height,
        static_executed: analysis.executed,
        counts_agree,
        costs,
        gradients,
        findings: found,
        warnings: loaded.warnings,
        models,
        file: loaded.file,
    })
}

fn histogram_text(s: &mut String, title: &str, stats: &CostStats) {
    let most = stats
        .histogram
        .iter()
        .map(|b| b.count)
        .max()
        .unwrap_or(0)
        .max(1);
    s.push_str(&format!("{title}\n"));
    for b in &stats.histogram {
        let range = if b.lo == b.hi {
            format!("{}", b.lo)
        } else {
            format!("{}–{}", b.lo, b.hi)
        };
        let bar = "█".repeat(((b.count * 40).div_ceil(most)) as usize);
        s.push_str(&format!(
            "  {range:>13}  {:>9}  {bar}\n",
            crate::report::thousands(b.count)
        ));
    }
}

/// The text form of `ps30 profile` (findings rendered as warnings).
pub fn text(r: &ProfileRun) -> String {
    let c = &r.costs;
    let mut s = format!("{} on {}\n", r.file.name, r.input);
    s.push_str(&format!(
        "static paths (cost model): shortest {}, longest {} executed slots per pixel; emulated {}–{}{}\n",
        crate::report::thousands(r.static_executed.min),
        crate::report::thousands(r.static_executed.max),
        crate::report::thousands(c.per_pixel.min),
        crate::report::thousands(c.per_pixel.max),
        if r.counts_agree { " (within)" } else { " (OUTSIDE the static range)" }
    ));
    s.push_str(&format!(
        "{:<22}{:>10}{:>12}{:>10}\n",
        "executed slots", "min", "mean", "max"
    ));
    for (name, st) in [("  per pixel", &c.per_pixel), ("  per quad", &c.per_quad)] {
        s.push_str(&format!(
            "{name:<22}{:>10}{:>12.2}{:>10}\n",
            crate::report::thousands(st.min),
            st.mean,
            crate::report::thousands(st.max)
        ));
    }
    s.push_str(&format!(
        "divergent quads: {} of {} ({:.1}%); pixels' own slots are {:.1}% of what their quads executed{}\n",
        crate::report::thousands(c.divergent_quads),
        crate::report::thousands(c.quads),
        100.0 * c.divergent_quads as f64 / c.quads.max(1) as f64,
        100.0 * c.lockstep_efficiency,
        if c.divergent_quads > 0 {
            format!(" ({:.1}% in the divergent ones)", 100.0 * c.divergent_efficiency)
        } else {
            String::new()
        }
    ));
    histogram_text(&mut s, "slots per quad   quads", &c.per_quad);
    if let Some(m) = &r.models {
        let all: u64 = m.iter().map(|x| x.0).sum();
        let ok: u64 = m.iter().map(|x| x.1).sum();
        s.push_str(&format!(
            "light models against the CPU computation: {} of {} pixels match bit for bit (model 0: {}/{}, 1: {}/{}, 2: {}/{})\n",
            crate::report::thousands(ok),
            crate::report::thousands(all),
            m[0].1, m[0].0, m[1].1, m[1].0, m[2].1, m[2].0
        ));
    }
    if r.findings.is_empty() {
        s.push_str("gradients: no gradient of a temporary ran in a divergent quad; no LOD far from level 0\n");
    } else {
        for f in &r.findings {
            s.push_str(&diagnostic(f).render(&r.file));
        }
    }
    s
}

/// The JSON form of `ps30 profile`.
pub fn to_json(r: &ProfileRun) -> Value {
    json!({
        "shader": r.file.name,
        "input": r.input,
        "target": [r.width, r.height],
        "static_executed": {"min": r.static_executed.min, "max": r.static_executed.max},
        "counts_agree": r.counts_agree,
        "per_pixel": r.costs.per_pixel,
        "per_quad": r.costs.per_quad,
        "quads": r.costs.quads,
        "divergent_quads": r.costs.divergent_quads,
        "lockstep_efficiency": r.costs.lockstep_efficiency,
        "divergent_efficiency": r.costs.divergent_efficiency,
        "gradients": r.gradients,
        "findings": r.findings,
        "warnings": r.warnings.items.iter().map(|w| json!({
            "line": r.file.line_of(w.span.start),
            "message": w.message,
        })).collect::<Vec<_>>(),
        "models": r.models.map(|m| m.iter().map(|&(n, ok)| json!({"pixels": n, "match": ok})).collect::<Vec<_>>()),
        "problem": r.problem(),
    })
}

/// Sampler state from the command line's flags.
pub fn sampler_state(
    filter: Filter,
    address: Address,
    border: [f32; 4],
    mip_filter: MipFilter,
    lod_bias: f32,
    max_mip_level: u32,
) -> SamplerState {
    SamplerState {
        mip_filter,
        mip_lod_bias: lod_bias,
        max_mip_level,
        address_u: address,
        address_v: address,
        border,
        ..SamplerState::filtered(filter)
    }
}

// ----- the command line ----------------------------------------------------------
//
// The arguments live here rather than in `main.rs` so that the binary only
// names the subcommand; the value parsers follow `main.rs`'s.

/// Filter flag values.
#[derive(Clone, Copy, Debug, clap::ValueEnum)]
pub enum FilterArg {
    Point,
    Linear,
}

/// Mip filter flag values.
#[derive(Clone, Copy, Debug, clap::ValueEnum)]
pub enum MipFilterArg {
    None,
    Point,
    Linear,
}

/// Address flag values.
#[derive(Clone, Copy, Debug, clap::ValueEnum)]
pub enum AddressArg {
    Border,
    Clamp,
    Wrap,
    Mirror,
    Mirroronce,
}

/// `ps30 profile`'s arguments.
#[derive(clap::Args, Debug)]
pub struct ProfileArgs {
    /// Shader file or bundled name (corrected:unrolled, lights:select, lights:texld, …).
    pub shader: String,
    /// Run on the synthetic G-buffer of the light-model shaders (asm/lights/), WxH pixels.
    #[arg(long, value_name = "WxH", value_parser = parse_size, conflicts_with_all = ["image", "target"], required_unless_present = "image")]
    pub gbuffer: Option<(u32, u32)>,
    /// Image sampled by s0; pixel (x, y) of the target gets v0.xy = the centre of the
    /// top-left texel of its block of the image, as in `ps30 run`.
    #[arg(long, requires = "target")]
    pub image: Option<std::path::PathBuf>,
    /// Render-target size WxH (with --image).
    #[arg(long, value_name = "WxH", value_parser = parse_size, requires = "image")]
    pub target: Option<(u32, u32)>,
    /// Bind a REPEAT_BLOCK count name, e.g. -D xsize=11.
    #[arg(short = 'D', value_name = "NAME=N", value_parser = parse_define)]
    pub define: Vec<(String, u64)>,
    /// Integer constant, e.g. --int i2=128 or --int i0=16,0,1,0.
    #[arg(long = "int", value_name = "iN=X[,Y,Z,W]", value_parser = parse_int_const)]
    pub ints: Vec<(u32, [i32; 4])>,
    /// Boolean constant, e.g. --bool b0=true.
    #[arg(long = "bool", value_name = "bN=true|false", value_parser = parse_bool_const)]
    pub bools: Vec<(u32, bool)>,
    /// Float constant, e.g. --const c3=0.27,0.67,0.06,0.01.
    #[arg(long = "const", value_name = "cN=X[,Y,Z,W]", value_parser = parse_float_const)]
    pub floats: Vec<(u32, [f32; 4])>,
    /// s0's MAGFILTER and MINFILTER (with --image).
    #[arg(long, value_enum, default_value = "point")]
    pub filter: FilterArg,
    /// s0's addressing (with --image).
    #[arg(long, value_enum, default_value = "border")]
    pub address: AddressArg,
    /// Border colour R,G,B,A for --address border.
    #[arg(long, value_parser = parse_float4, default_value = "0,0,0,0")]
    pub border: [f32; 4],
    /// Give s0 a full box-filtered mip chain (with --image).
    #[arg(long)]
    pub mips: bool,
    /// s0's MIPFILTER.
    #[arg(long, value_enum, default_value = "none")]
    pub mip_filter: MipFilterArg,
    /// s0's MIPMAPLODBIAS.
    #[arg(long, default_value_t = 0.0, allow_negative_numbers = true, value_parser = parse_finite)]
    pub lod_bias: f32,
    /// s0's MAXMIPLEVEL (the most detailed level allowed).
    #[arg(long, default_value_t = 0)]
    pub max_mip_level: u32,
    /// Histogram bins.
    #[arg(long, default_value_t = 12, value_parser = clap::value_parser!(u64).range(1..=1000))]
    pub bins: u64,
    /// Emulator threads (default: all cores).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=256))]
    pub threads: Option<u32>,
    /// Refuse images with more pixels than this.
    #[arg(long, default_value_t = 1 << 26)]
    pub max_pixels: u64,
    /// Print JSON instead of text.
    #[arg(long)]
    pub json: bool,
}

/// Runs `ps30 profile` from its arguments: validator warnings to stderr (in
/// colour when `color`), the report to stdout. Ok(true) when the run found a
/// problem (exit 1), Err for bad input (exit 2).
pub fn command(args: ProfileArgs, color: bool) -> Result<bool, String> {
    use std::io::Write;
    let (name, source) = shader_source(&args.shader)?;
    let mut constants = Constants::default();
    for (i, v) in &args.floats {
        let i = *i as usize;
        constants
            .float
            .resize(constants.float.len().max(i + 1), [0.0; 4]);
        constants.float[i] = *v;
    }
    for (i, v) in &args.ints {
        let i = *i as usize;
        constants.int.resize(constants.int.len().max(i + 1), [0; 4]);
        constants.int[i] = *v;
    }
    for (i, v) in &args.bools {
        let i = *i as usize;
        constants
            .bool
            .resize(constants.bool.len().max(i + 1), false);
        constants.bool[i] = *v;
    }
    let state = sampler_state(
        match args.filter {
            FilterArg::Point => Filter::Point,
            FilterArg::Linear => Filter::Linear,
        },
        match args.address {
            AddressArg::Border => Address::Border,
            AddressArg::Clamp => Address::Clamp,
            AddressArg::Wrap => Address::Wrap,
            AddressArg::Mirror => Address::Mirror,
            AddressArg::Mirroronce => Address::MirrorOnce,
        },
        args.border,
        match args.mip_filter {
            MipFilterArg::None => MipFilter::None,
            MipFilterArg::Point => MipFilter::Point,
            MipFilterArg::Linear => MipFilter::Linear,
        },
        args.lod_bias,
        args.max_mip_level,
    );
    let input = match (args.gbuffer, &args.image, args.target) {
        (Some((w, h)), _, _) => Input::GBuffer(w, h),
        (None, Some(path), Some(target)) => {
            let image = crate::image::load(
                path,
                &crate::image::ImageLimits {
                    max_pixels: args.max_pixels,
                },
            )
            .map_err(|e| e.to_string())?;
            Input::Image {
                image,
                name: path.display().to_string(),
                target,
                sampler: state,
                mips: args.mips,
            }
        }
        _ => return Err("give --gbuffer WxH, or --image IMG with --target WxH".into()),
    };
    let setup = Setup {
        input,
        defines: args.define.clone(),
        constants,
        bins: args.bins as usize,
        threads: args.threads.map(|t| t as usize),
    };
    let r = profile(&name, &source, &setup)?;
    for w in &r.warnings.items {
        w.emit(&r.file, color);
    }
    let out = if args.json {
        serde_json::to_string_pretty(&to_json(&r)).map_err(|e| e.to_string())? + "\n"
    } else {
        text(&r)
    };
    let mut stdout = std::io::stdout().lock();
    stdout
        .write_all(out.as_bytes())
        .and_then(|_| stdout.flush())
        .map_err(|e| e.to_string())?;
    Ok(r.problem())
}
