//! `ps30 run`: one pass of any shader over an image into a render target,
//! or a vertex shader over a vertex list (`--vertices`, in `run/vertices.rs`).

mod vertices;

use super::args::{
    given_with, read_inputs, with_inputs, BackendArgs, ConstantArgs, ExecArgs, FormatArg,
    InputArgs, SamplerArgs, SourceArgs,
};
use super::io::{audit, load_shader, print_json, say};
use super::ui::Ui;
use super::{BadInput, Outcome};
use ps30::core::image;
use ps30::jobs::luminance::{run_pass, PassSetup};
use ps30::present::constants::{table_json, table_text};
use ps30::present::luminance::{pass_json, pass_text};
use serde_json::Value;
use std::path::{Path, PathBuf};

#[derive(clap::Args)]
pub struct Args {
    /// The shader: a file (assembly or bytecode), `-` for standard input, or a
    /// bundled name such as corrected:loop (`ps30 shaders` lists them).
    #[arg(value_name = "SHADER")]
    shader: String,
    /// The image s0 samples: OpenEXR, Radiance .hdr or PFM (v0 runs over its texel blocks).
    /// Needed unless --inputs, --input, --const or --vertices gives the draw something; without
    /// it, v0 (t0 in ps_2_x) runs over the target's own texel centres.
    #[arg(long, value_name = "IMAGE", required_unless_present_any = ["inputs", "input_values", "floats", "vertices"])]
    image: Option<PathBuf>,
    /// Run a vertex shader (vs_2_0, vs_2_x, vs_3_0) over the vertices of this JSON file:
    /// {"attributes": {"position0": [[x, y, z, w], ...], "texcoord0": [[u, v], ...]}}
    /// (docs/vertex-shaders.md); prints each vertex's outputs.
    #[arg(long, value_name = "FILE", conflicts_with_all = ["image", "target", "input_values"])]
    vertices: Option<PathBuf>,
    /// Constants, textures, sampler states and inputs (by register or semantic) from a file
    /// in the draw-list step format:
    /// {"constants": {"c0": [x, y, z, w]}, "samplers": {"s0": {"texture": "sky.dds", "filter": "linear"}}}.
    #[arg(long, value_name = "FILE")]
    inputs: Option<PathBuf>,
    /// Render-target size WxH.
    #[arg(long, value_name = "WxH", value_parser = super::args::parse_size, required_unless_present = "vertices")]
    target: Option<(u32, u32)>,
    /// An input's value, by register (v0, t1) or semantic (texcoord1, color0):
    /// `texcoord[,Z,W]` for the pixel centres in [0, 1] (z, w as given), or X[,Y,Z,W] at every pixel.
    /// With --image, v0 (ps_3_0) or t0 (ps_2_x) runs over its texel blocks unless given.
    #[arg(long = "input", value_name = "NAME=texcoord[,Z,W]|X,Y,Z,W")]
    input_values: Vec<String>,
    #[command(flatten)]
    source: SourceArgs,
    #[command(flatten)]
    constants: ConstantArgs,
    #[command(flatten)]
    sampler: SamplerArgs,
    /// Render-target format.
    #[arg(long, value_enum, default_value = "f32")]
    target_format: FormatArg,
    /// Write the target here (atomically), in the format its extension names: .exr, .pfm, .hdr or .png.
    #[arg(short, long, value_name = "FILE")]
    output: Option<PathBuf>,
    /// With --json: every texel of every written output (large).
    #[arg(long)]
    texels: bool,
    #[command(flatten)]
    exec: ExecArgs,
    #[command(flatten)]
    draw: BackendArgs,
    #[command(flatten)]
    input: InputArgs,
}

pub fn run(args: Args, ui: &Ui) -> super::Result {
    super::bound_threads(args.exec.threads())?;
    if let Some(path) = &args.vertices {
        return vertices::run(&args, path, ui);
    }
    let inputs = read_inputs(args.inputs.as_deref())?;
    if let Some(path) = &args.output {
        let mut sources: Vec<&Path> = vec![Path::new(&args.shader)];
        sources.extend(args.image.as_deref());
        sources.extend(args.inputs.as_deref());
        sources.extend(
            inputs
                .iter()
                .flat_map(|i| i.sources.iter().map(|p| p.as_path())),
        );
        super::io::check_image_output(path, &sources)?;
    }
    let loaded = load_shader(ui, &args.shader, &args.source, &args.input)?;
    let profile = loaded.shader.program().profile;
    if ps30::core::emu::vertex::runs(profile) {
        return Err(BadInput(format!(
            "{}: a {profile} shader: run it over a vertex list with --vertices FILE",
            args.shader
        )));
    }
    let resolved = args.constants.resolve(loaded.constants.as_ref())?;
    let found = audit(
        ui,
        &loaded,
        &given_with(&resolved, &args.source, &inputs),
        true,
    )?;
    let img = match &args.image {
        Some(path) => Some(image::load(path, &args.exec.image_limits())?),
        None => None,
    };
    let program = loaded.shader.program();
    let target = args
        .target
        .ok_or_else(|| BadInput("--target WxH: the render target's size is needed".into()))?;
    let mut values = match &inputs {
        Some(i) => ps30::jobs::render::input_values::resolve_all(program, &i.inputs, target)
            .map_err(|e| super::BadInput(format!("--inputs: {e}")))?,
        None => Vec::new(),
    };
    for t in &args.input_values {
        values.push(
            ps30::jobs::render::input_values::parse(program, t, target)
                .map_err(|e| super::BadInput(format!("--input {e}")))?,
        );
    }
    let (constants, textures) = with_inputs(&resolved, inputs);
    let setup = PassSetup {
        target,
        constants,
        textures,
        sampler: args.sampler.state(),
        format: args.target_format.into(),
        threads: args.exec.threads(),
        limits: args.exec.limits(),
        backend: args.draw.open()?,
        float_rules: args.draw.rules(),
        inputs: values,
    };
    let out = {
        let _spinner = ui.spinner("running the shader");
        run_pass(&loaded, img.as_ref(), &setup)?
    };
    let written = match &args.output {
        Some(path) => Some((path.as_path(), image::write_target(path, &out.target)?)),
        None => None,
    };
    if args.exec.json {
        let mut json = pass_json(&loaded, &found, &out, args.texels);
        json["constant_table"] = loaded.constants.as_ref().map_or(Value::Null, table_json);
        print_json(&json)?;
    } else {
        let mut text = pass_text(
            &args
                .image
                .as_ref()
                .or(args.inputs.as_ref())
                .map_or("the target's texel centres".into(), |p| {
                    p.display().to_string()
                }),
            &out,
            written.as_ref().map(|(p, w)| (*p, w)).filter(|_| !ui.quiet),
        );
        if let Some(t) = &loaded.constants {
            text.push_str(&table_text(t));
        }
        say(ui, &text)?;
    }
    Ok(Outcome::from_ok(
        out.cost.within_limits && out.cost.counts_agree,
    ))
}
