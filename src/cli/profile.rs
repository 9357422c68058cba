//! `ps30 profile`: per-pixel and per-quad costs over an image or the
//! light-model G-buffer, divergence, and gradients that rely on undefined
//! behaviour.

use super::args::{
    given_with, parse_finite, parse_size, read_inputs, with_inputs, ConstantArgs, ExecArgs,
    InputArgs, MipFilterArg, SamplerArgs, SourceArgs,
};
use super::io::{audit, load_shader, print_json, say};
use super::ui::Ui;
use super::{BadInput, Outcome};
use ps30::core::emu::SamplerState;
use ps30::core::image;
use ps30::jobs::profile::{floats_set_by, profile_loaded, Input, Setup};
use ps30::present::profile::{lines_text, text, then, to_json};

#[derive(clap::Args)]
pub struct Args {
    /// The shader: a file (assembly or bytecode), `-` for standard input, or a
    /// bundled name such as lights:select (`ps30 shaders` lists them).
    #[arg(value_name = "SHADER", required_unless_present = "list")]
    shader: Option<String>,
    /// Run on the synthetic G-buffer of the light-model shaders (asm/lights/), WxH pixels.
    #[arg(long, value_name = "WxH", value_parser = parse_size, conflicts_with_all = ["image", "target"], required_unless_present_any = ["image", "vertices", "list"])]
    gbuffer: Option<(u32, u32)>,
    /// Profile a draw of this draw list (see `ps30 render --help`) as the list draws it:
    /// its pixel shader over every primitive's 2×2 quads, and its vertex shader's runs.
    #[arg(long, value_name = "LIST", conflicts_with_all = ["shader", "image", "gbuffer", "vertices", "inputs"])]
    list: Option<std::path::PathBuf>,
    /// With --list: the step to profile (from 0; a draw). The list's last draw by default.
    #[arg(long, value_name = "N", requires = "list")]
    step: Option<usize>,
    /// Run a vertex shader over the vertices of this JSON file (see `ps30 run --vertices`):
    /// its slots, and each vertex's executed count against the cost model's.
    #[arg(long, value_name = "FILE", conflicts_with_all = ["image", "gbuffer"])]
    vertices: Option<std::path::PathBuf>,
    /// Image sampled by s0 (OpenEXR, Radiance .hdr or PFM); pixel (x, y) of the target gets
    /// v0.xy = the centre of the top-left texel of its block of the image, as in `ps30 run`.
    #[arg(long, value_name = "IMAGE", requires = "target")]
    image: Option<std::path::PathBuf>,
    /// Render-target size WxH (with --image).
    #[arg(long, value_name = "WxH", value_parser = parse_size, requires = "image")]
    target: Option<(u32, u32)>,
    #[command(flatten)]
    source: SourceArgs,
    #[command(flatten)]
    constants: ConstantArgs,
    #[command(flatten)]
    sampler: SamplerArgs,
    /// Give s0 a full box-filtered mip chain (with --image).
    #[arg(long)]
    mips: bool,
    /// s0's MIPFILTER.
    #[arg(long, value_enum, default_value = "none")]
    mip_filter: MipFilterArg,
    /// s0's MIPMAPLODBIAS, added to every level of detail.
    #[arg(long, value_name = "B", default_value_t = 0.0, allow_negative_numbers = true, value_parser = parse_finite)]
    lod_bias: f32,
    /// Special values: hardware (the default), d3d9, ieee, or d3d9-zero-mul.
    #[arg(long, value_enum, default_value = "hardware")]
    float_rules: super::args::FloatRulesArg,
    /// s0's MAXMIPLEVEL (the most detailed level allowed).
    #[arg(long, value_name = "N", default_value_t = 0)]
    max_mip_level: u32,
    /// Constants, textures and sampler states from a file in the draw-list step format (see
    /// `ps30 run --inputs`); its textures replace what --image binds on the same sampler.
    #[arg(long, value_name = "FILE")]
    inputs: Option<std::path::PathBuf>,
    /// Histogram bins.
    #[arg(long, value_name = "N", default_value_t = 12, value_parser = clap::value_parser!(u64).range(1..=1000))]
    bins: u64,
    /// Also print what each source line cost: its runs and executed slots,
    /// and for a pixel shader its helper-lane runs, its runs by 2×2 quads
    /// in lockstep and how many of those split the quad (`--json` always
    /// gives them, as `lines`)
    #[arg(long)]
    lines: bool,
    #[command(flatten)]
    exec: ExecArgs,
    #[command(flatten)]
    input: InputArgs,
}

impl Args {
    /// s0's sampler state from the flags.
    fn sampler(&self) -> SamplerState {
        SamplerState {
            mip_filter: self.mip_filter.into(),
            mip_lod_bias: self.lod_bias,
            max_mip_level: self.max_mip_level,
            ..self.sampler.state()
        }
    }

    fn input(&self) -> Result<Input, BadInput> {
        Ok(match (self.gbuffer, &self.image, self.target) {
            (Some((w, h)), _, _) => Input::GBuffer(w, h),
            (None, Some(path), Some(target)) => Input::Image {
                image: image::load(path, &self.exec.image_limits())?,
                name: path.display().to_string(),
                target,
                sampler: self.sampler(),
                mips: self.mips,
            },
            _ => {
                return Err(BadInput(
                    "give --gbuffer WxH, or --image IMG with --target WxH".into(),
                ))
            }
        })
    }
}

/// Validator warnings to stderr, the report to stdout; exit 1 when the run
/// found a problem.
pub fn run(args: Args, ui: &Ui) -> super::Result {
    super::bound_threads(args.exec.threads())?;
    if let Some(path) = &args.list {
        return list(&args, path, ui);
    }
    let shader = args
        .shader
        .as_deref()
        .ok_or_else(|| BadInput("give a SHADER, or --list LIST".into()))?;
    let loaded = load_shader(ui, shader, &args.source, &args.input)?;
    if let Some(path) = &args.vertices {
        return vertices(&args, shader, path, &loaded, ui);
    }
    let input = args.input()?;
    let resolved = args.constants.resolve(loaded.constants.as_ref())?;
    let inputs = read_inputs(args.inputs.as_deref())?;
    let mut given = given_with(&resolved, &args.source, &inputs);
    given.preset_floats.extend(floats_set_by(&input));
    let found = audit(ui, &loaded, &given, true)?;
    let (constants, textures) = with_inputs(&resolved, inputs);
    let setup = Setup {
        input,
        textures,
        defines: args.source.define.clone(),
        constants,
        bins: args.bins as usize,
        threads: args.exec.threads(),
        limits: args.exec.limits(),
        float_rules: args.float_rules.into(),
    };
    let r = {
        let _spinner = ui.spinner("running the shader");
        profile_loaded(loaded, &setup).map_err(BadInput)?
    };
    if args.exec.json {
        print_json(&to_json(&r, &found))?;
    } else {
        let mut out = text(&r);
        if args.lines {
            out = then(&out, &lines_text(&r.file.name, &r.lines, true));
        }
        say(ui, &out)?;
    }
    Ok(Outcome::from_ok(!r.problem()))
}

/// `--list`: one draw of a draw list, as the list draws it.
fn list(args: &Args, path: &std::path::Path, ui: &Ui) -> super::Result {
    let limits = ps30::jobs::render::file::FileLimits {
        max_pixels: args.exec.max_pixels,
        max_input_bytes: args.input.max_input_bytes,
        ..Default::default()
    };
    let loaded = ps30::jobs::render::file::read(path, &limits)?;
    if !ui.quiet {
        for w in &loaded.warnings {
            super::io::eprint(&format!("warning: {w}\n"));
        }
    }
    let settings = ps30::jobs::render::Settings {
        threads: args.exec.threads(),
        limits: args.exec.limits(),
        budget: Default::default(),
        float_rules: args.float_rules.into(),
        backend: ps30::jobs::backend::Backend::Emulator,
    };
    let name = path.display().to_string();
    let p = {
        let _spinner = ui.spinner("running the list");
        ps30::jobs::profile::list::profile_list(
            &loaded.list,
            args.step,
            &settings,
            args.bins as usize,
        )
        .map_err(|e| BadInput(format!("{name}: {e}")))?
    };
    if args.exec.json {
        print_json(&ps30::present::profile::list_json(&name, &p))?;
    } else {
        let mut out = ps30::present::profile::list_text(&name, &p);
        if args.lines {
            out = then(&out, &ps30::present::profile::list_lines_text(&p));
        }
        say(ui, &out)?;
    }
    Ok(Outcome::from_ok(!p.problem()))
}

/// `--vertices`: a vertex shader's costs over a vertex list.
fn vertices(
    args: &Args,
    shader: &str,
    path: &std::path::Path,
    loaded: &ps30::core::load::Loaded,
    ui: &Ui,
) -> super::Result {
    let list = ps30::jobs::vertices::read(path).map_err(BadInput)?;
    let resolved = args.constants.resolve(loaded.constants.as_ref())?;
    let inputs = read_inputs(args.inputs.as_deref())?;
    // as `run --vertices` does: nothing is counted on constants nobody set
    audit(
        ui,
        loaded,
        &given_with(&resolved, &args.source, &inputs),
        true,
    )?;
    let (constants, textures) = with_inputs(&resolved, inputs);
    let p = ps30::jobs::vertices::profile(
        &loaded.shader,
        &loaded.file,
        constants,
        &textures,
        &list,
        args.float_rules.into(),
        args.exec.limits().max_executed_per_pixel,
    )
    .map_err(|e| BadInput(format!("{shader}: {e}")))?;
    if args.exec.json {
        print_json(&ps30::present::vertices::profile_json(shader, &p))?;
    } else {
        let mut out = ps30::present::vertices::profile_text(shader, &p);
        if args.lines {
            out = then(&out, &lines_text(shader, &p.lines, false));
        }
        say(ui, &out)?;
    }
    Ok(Outcome::from_ok(p.within_limits && p.counts_agree))
}
