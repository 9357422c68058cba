//! `ps30 compare`: the emulator against a GPU — one draw, the luminance
//! pipeline, tone mapping, or everything bundled (`--all`, which writes
//! `reports/gpu-crosscheck.md`).

use super::args::{
    given_with, parse_delta, parse_float4, parse_size, read_inputs, with_inputs, AddressArg,
    ConstantArgs, FilterArg, FloatRulesArg, FormatArg, InputArgs, SourceArgs,
};
use super::io::{audit, eprint, load_shader, print_json, say, shader_source};
use super::ui::Ui;
use super::{BadInput, Outcome};
use ps30::core::emu::{Draw, SamplerState};
use ps30::core::gpu::{Gpu, TargetKind};
use ps30::core::image::{self, ImageLimits};
use ps30::jobs::compare::{self, all, explain};
use ps30::jobs::luminance::{self, block_start};
use ps30::present::compare as show;
use std::path::PathBuf;
use std::sync::Arc;

#[derive(clap::Args)]
pub struct Args {
    /// Shader file or bundled name for one draw (with --image and --target).
    shader: Option<String>,
    /// The image the draw samples (s0) or the pipeline runs on.
    #[arg(long)]
    image: Option<PathBuf>,
    /// Constants, textures and sampler states for the draw from a file in the draw-list step
    /// format (see `ps30 run --inputs`); --image is optional then.
    #[arg(long, value_name = "FILE", conflicts_with_all = ["luminance", "tonemap", "all"])]
    inputs: Option<PathBuf>,
    /// Render-target size WxH of the draw.
    #[arg(long, value_name = "WxH", value_parser = parse_size)]
    target: Option<(u32, u32)>,
    /// An input's value for the draw, as `ps30 run --input` takes it (v0, t1, texcoord1,
    /// color0 = texcoord[,Z,W] or X[,Y,Z,W]); --image is optional then.
    #[arg(long = "input", value_name = "NAME=texcoord[,Z,W]|X,Y,Z,W", conflicts_with_all = ["luminance", "tonemap", "all"])]
    input_values: Vec<String>,
    /// Run the vertex shader SHADER over the vertices of this JSON file (the `ps30 run
    /// --vertices` format) on both backends and compare every output component.
    #[arg(long, value_name = "FILE", conflicts_with_all = ["luminance", "tonemap", "all", "image", "target"])]
    vertices: Option<PathBuf>,
    /// Run the draw list FILE (`ps30 render`'s format) on both backends and compare every
    /// draw's targets after it; a draw of geometry also by the pixels each primitive covers.
    #[arg(long, value_name = "FILE", conflicts_with_all = ["shader", "luminance", "tonemap", "all", "image", "target", "vertices", "inputs"])]
    list: Option<PathBuf>,
    /// Compare the luminance pipeline on --image instead of one draw.
    #[arg(long, conflicts_with_all = ["shader", "tonemap", "all"])]
    luminance: bool,
    /// Compare tone mapping on --image instead of one draw.
    #[arg(long, conflicts_with_all = ["shader", "luminance", "all"])]
    tonemap: bool,
    /// Every bundled shader on the bundled images; writes gpu-crosscheck.md to --reports.
    #[arg(long, conflicts_with_all = ["shader", "luminance", "tonemap", "image"])]
    all: bool,
    /// Where --all writes gpu-crosscheck.md.
    #[arg(long, default_value = "reports", requires = "all")]
    reports: PathBuf,
    /// Where --all finds the bundled images.
    #[arg(long, default_value = "assets/hdr", requires = "all")]
    images: PathBuf,
    /// Pass-1 shader for --luminance.
    #[arg(long, default_value = "corrected:unrolled")]
    pass1: String,
    /// Pass-2 shader for --luminance.
    #[arg(long, default_value = "corrected:pass2")]
    pass2: String,
    /// Block size WxH for --luminance.
    #[arg(long, value_name = "WxH", value_parser = parse_size, default_value = "125x128")]
    block: (u32, u32),
    /// The δ of log(δ + L) for --luminance.
    #[arg(long, default_value_t = 1e-4, value_parser = parse_delta)]
    delta: f32,
    #[command(flatten)]
    source: SourceArgs,
    #[command(flatten)]
    input: InputArgs,
    #[command(flatten)]
    constants: ConstantArgs,
    /// s0's MAGFILTER and MINFILTER (one draw): point (nearest texel) or linear (bilinear).
    #[arg(long, value_enum, default_value = "point")]
    filter: FilterArg,
    /// s0's ADDRESSU and ADDRESSV (one draw): what a read outside [0, 1] returns.
    #[arg(long, value_enum, default_value = "border")]
    address: AddressArg,
    /// Border colour R,G,B,A for --address border.
    #[arg(long, value_parser = parse_float4, default_value = "0,0,0,0")]
    border: [f32; 4],
    /// Stop the emulator's pixel that executes more instruction slots than
    /// this (one draw). Raise it to compare a shader whose loops run longer
    /// than the default allows: the GPU draws it regardless, and shows what
    /// its driver does with such loops.
    #[arg(long, value_name = "N", default_value_t = ps30::core::emu::EmuLimits::MAX_EXECUTED_PER_PIXEL, value_parser = clap::value_parser!(u64).range(1..))]
    max_executed_per_pixel: u64,
    /// Stop the emulator's draw that executes more instruction slots than this, all pixels together (one draw).
    #[arg(long, value_name = "N", default_value_t = ps30::core::emu::EmuLimits::MAX_EXECUTED_TOTAL, value_parser = clap::value_parser!(u64).range(1..))]
    max_executed_total: u64,
    /// The draw's target: f32 (D3DFMT_R32F), f16 (D3DFMT_A16B16G16R16F); without it, unrounded f32.
    #[arg(long, value_enum)]
    target_format: Option<FormatArg>,
    /// Special values: hardware (the default), d3d9, ieee, or d3d9-zero-mul.
    #[arg(long, value_enum, default_value = "hardware")]
    float_rules: FloatRulesArg,
    /// Print JSON instead of text.
    #[arg(long)]
    json: bool,
}

pub fn run(args: Args, ui: &Ui) -> super::Result {
    if !args.all && !args.luminance && !args.tonemap && args.shader.is_none() && args.list.is_none()
    {
        return Err(BadInput(
            "give a SHADER (with --image and --target), --list, --luminance, --tonemap or --all"
                .into(),
        ));
    }
    if args.all {
        return run_all(&args, ui);
    }
    let gpu = Arc::new(Gpu::open()?);
    if !ui.quiet && !args.json {
        eprint(&format!("device: {}\n", gpu.info().line()));
    }
    if let Some(path) = &args.vertices {
        return vertices(&args, ui, &gpu, path);
    }
    if let Some(path) = &args.list {
        return list(&args, ui, &gpu, path);
    }
    if (args.inputs.is_some() || !args.input_values.is_empty()) && args.image.is_none() {
        return one_draw(&args, ui, &gpu, None);
    }
    let path = args
        .image
        .clone()
        .ok_or_else(|| BadInput("--image is needed".into()))?;
    let img = image::load(&path, &ImageLimits::default())?;
    let name = path.display().to_string();
    if args.luminance {
        let settings = luminance::Settings {
            block: args.block,
            delta: args.delta,
            float_rules: args.float_rules.into(),
            ..Default::default()
        };
        let (p1, p2) = (
            shader_source(&args.pass1, args.input.max_input_bytes)?,
            shader_source(&args.pass2, args.input.max_input_bytes)?,
        );
        let c = {
            let _s = ui.spinner("running both passes on both backends, and the probes");
            let mut c = compare::compare_luminance(&gpu, (&name, &img), &p1, None, &p2, &settings)?;
            c.explanation = Some(explain::luminance(&c, &compare::probe::run(&gpu)?));
            c
        };
        if args.json {
            print_json(&show::luminance_json(gpu.info(), &c))?;
        } else {
            say(ui, &show::luminance_text(&c))?;
        }
        return Ok(Outcome::from_ok(
            c.explanation.as_ref().is_some_and(|e| !e.finding),
        ));
    }
    if args.tonemap {
        let c = {
            let _s = ui.spinner("tone mapping on both backends, and the probes");
            let mut c = all::compare_tonemap(&gpu, &name, &img)?;
            c.explanation = Some(explain::tonemap(&c, &compare::probe::run(&gpu)?));
            c
        };
        if args.json {
            print_json(&show::tonemap_json(gpu.info(), &c))?;
        } else {
            say(ui, &show::tonemap_text(&c))?;
        }
        return Ok(Outcome::from_ok(
            c.explanation.as_ref().is_some_and(|e| !e.finding),
        ));
    }
    one_draw(&args, ui, &gpu, Some(&img))
}

/// One draw of SHADER on both backends, sampling the image on s0 and what
/// `--inputs` binds.
fn one_draw(args: &Args, ui: &Ui, gpu: &Arc<Gpu>, img: Option<&image::HdrImage>) -> super::Result {
    let spec = args.shader.as_deref().unwrap_or_default();
    let (tw, th) = args
        .target
        .ok_or_else(|| BadInput("--target WxH is needed for one draw".into()))?;
    let loaded = load_shader(ui, spec, &args.source, &args.input)?;
    let program = loaded.shader.program();
    let mut draw = Draw::new(tw, th);
    draw.float_rules = args.float_rules.into();
    draw.limits.max_executed_per_pixel = args.max_executed_per_pixel;
    draw.limits.max_executed_total = args.max_executed_total;
    // v0 in ps_3_0, t0 in ps_2_x.
    if let Some(at) = ps30::core::pixel_inputs::declared_coordinates(program) {
        let (iw, ih) = img.map_or((tw, th), |i| (i.width, i.height));
        draw.inputs
            .push((at, block_start(iw, ih, iw.div_ceil(tw), ih.div_ceil(th))));
    }
    let inputs = read_inputs(args.inputs.as_deref())?;
    let mut values = match &inputs {
        Some(i) => ps30::jobs::render::input_values::resolve_all(program, &i.inputs, (tw, th))
            .map_err(|e| BadInput(format!("--inputs: {e}")))?,
        None => Vec::new(),
    };
    for text in &args.input_values {
        values.push(
            ps30::jobs::render::input_values::parse(program, text, (tw, th))
                .map_err(|e| BadInput(format!("--input {e}")))?,
        );
    }
    for (at, value) in values {
        draw.inputs.retain(|(s, _)| *s != at);
        draw.inputs.push((at, value));
    }
    let resolved = args.constants.resolve(loaded.constants.as_ref())?;
    audit(
        ui,
        &loaded,
        &given_with(&resolved, &args.source, &inputs),
        true,
    )?;
    let (constants, textures) = with_inputs(&resolved, inputs);
    draw.constants = constants;
    let address = args.address.into();
    let given_s0 = textures.iter().any(|(s, _, _)| *s == 0);
    if let (Some(img), true, false) = (img, program.sampler_type(0).is_some(), given_s0) {
        draw.samplers.push((
            0,
            img.as_texture().into(),
            SamplerState {
                address_u: address,
                address_v: address,
                address_w: address,
                border: args.border,
                ..SamplerState::filtered(args.filter.into())
            },
        ));
    }
    for (s, file, state) in &textures {
        draw.samplers.push((*s, file.into(), *state));
    }
    let target = args
        .target_format
        .map_or(TargetKind::Raw, |f| TargetKind::Format(f.into()));
    let c = {
        let _s = ui.spinner("drawing on both backends, and the probes");
        let mut c = compare::compare_draw(gpu, &loaded, &draw, target, None)?;
        c.explanation = Some(explain::draw(&c, &compare::probe::run(gpu)?));
        c
    };
    if args.json {
        print_json(&show::draw_json(gpu.info(), &c))?;
    } else {
        say(ui, &show::draw_text(&c))?;
    }
    Ok(Outcome::from_ok(
        c.special_mismatches() == 0 && c.killed_mismatches == 0,
    ))
}

fn run_all(args: &Args, ui: &Ui) -> super::Result {
    let path = args.reports.join("gpu-crosscheck.md");
    // The folder is created when missing, as every --reports DIR is.
    super::io::check_output_dir(&args.reports)?;
    if args.reports.is_dir() {
        super::io::check_output_path(&path, &[])?;
    }
    let gpu = Arc::new(Gpu::open()?);
    // The device is printed first, on stdout, so a log of the run says
    // where it ran.
    if !args.json {
        say(ui, &format!("device: {}\n", gpu.info().line()))?;
    }
    let names: Vec<&str> = ps30::present::report::IMAGES.to_vec();
    let result = {
        let bar = std::cell::RefCell::new(ui.bar("comparing", 1));
        all::run(&gpu, &args.images, &names, &|step, total, what| {
            bar.borrow_mut().set(Some(what), step as u64, total as u64)
        })?
    };
    let page = ps30::present::report::gpu::page(&result);
    let mut batch = ps30::core::output::Batch::new(&args.reports)?;
    batch.write_bytes(&path, page.as_bytes())?;
    batch.commit()?;
    if args.json {
        print_json(&result)?;
    } else {
        say(ui, &show::all_text(&result))?;
        if !ui.quiet {
            say(ui, &format!("wrote {}\n", path.display()))?;
        }
    }
    Ok(Outcome::from_ok(
        ps30::jobs::compare::explain::all_explained(&result),
    ))
}

/// `compare --list FILE`: a draw list on both backends.
fn list(args: &Args, ui: &Ui, gpu: &Arc<Gpu>, path: &std::path::Path) -> super::Result {
    let limits = ps30::jobs::render::file::FileLimits {
        max_input_bytes: args.input.max_input_bytes,
        ..Default::default()
    };
    let loaded = ps30::jobs::render::file::read(path, &limits)?;
    let settings = ps30::jobs::render::Settings {
        limits: ps30::core::emu::EmuLimits {
            max_executed_per_pixel: args.max_executed_per_pixel,
            max_executed_total: args.max_executed_total,
            ..Default::default()
        },
        float_rules: args.float_rules.into(),
        ..Default::default()
    };
    let c = {
        let _s = ui.spinner("running the list on both backends, and the probes");
        let probes = compare::probe::run(gpu)?;
        compare::draws::compare_list(gpu, &loaded.list, &settings, &probes)?
    };
    if args.json {
        print_json(&show::list_json(gpu.info(), &c))?;
    } else {
        let draws = match c.steps.len() {
            1 => "1 draw".to_string(),
            n => format!("{n} draws"),
        };
        say(ui, &format!("{}: {draws}\n", path.display()))?;
        say(ui, &show::list_text(&c))?;
    }
    Ok(Outcome::from_ok(c.explained()))
}

/// `compare VS --vertices FILE`: the vertex shader on both backends.
fn vertices(args: &Args, ui: &Ui, gpu: &Arc<Gpu>, path: &std::path::Path) -> super::Result {
    let spec = args.shader.as_deref().unwrap_or_default();
    let list = ps30::jobs::vertices::read(path).map_err(BadInput)?;
    let loaded = load_shader(ui, spec, &args.source, &args.input)?;
    let profile = loaded.shader.program().profile;
    if !ps30::core::emu::vertex::runs(profile) {
        return Err(BadInput(format!(
            "{spec}: a {profile} shader; --vertices runs vertex shaders (vs_2_0, vs_2_x, vs_3_0)"
        )));
    }
    let resolved = args.constants.resolve(loaded.constants.as_ref())?;
    let inputs = read_inputs(args.inputs.as_deref())?;
    // as `run --vertices` does: nothing runs on constants nobody set
    audit(
        ui,
        &loaded,
        &given_with(&resolved, &args.source, &inputs),
        true,
    )?;
    let (constants, textures) = with_inputs(&resolved, inputs);
    let draw = ps30::core::emu::vertex::VertexDraw {
        constants,
        samplers: textures
            .iter()
            .map(|(s, t, state)| (*s, t.into(), *state))
            .collect(),
        float_rules: args.float_rules.into(),
        max_executed_per_vertex: args.max_executed_per_pixel,
    };
    let c = {
        let _s = ui.spinner("running the vertices on both backends, and the probes");
        let probes = compare::probe::run(gpu)?;
        compare::vertices::explained(gpu, &loaded, &draw, &list, &probes)?
    };
    if args.json {
        print_json(&show::draw_json(gpu.info(), &c))?;
    } else {
        say(ui, &show::vertices_text(&c))?;
    }
    Ok(Outcome::from_ok(
        c.explanation.as_ref().is_some_and(|e| !e.finding),
    ))
}
