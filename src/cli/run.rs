//! `ps30 run`: one pass of any shader over an image into a render target.

use super::args::{
    constants, parse_float4, parse_float_const, AddressArg, ConstantArgs, ExecArgs, FilterArg,
    FormatArg, InputArgs, SourceArgs,
};
use super::io::{check_output_path, color_stderr, print_json, say, shader_source};
use super::ui::Ui;
use super::{BadInput, Outcome};
use ps30::core::diag::SourceFile;
use ps30::core::emu::SamplerState;
use ps30::core::image::{self, write_exr, write_pfm};
use ps30::core::load;
use ps30::jobs::luminance::{run_pass, PassSetup};
use ps30::present::luminance::{pass_json, pass_text};
use std::path::{Path, PathBuf};

#[derive(clap::Args)]
pub struct Args {
    /// Shader file or bundled name (see `ps30 luminance --help`).
    shader: String,
    #[arg(long)]
    image: PathBuf,
    /// Render-target size WxH.
    #[arg(long, value_name = "WxH", value_parser = super::args::parse_size)]
    target: (u32, u32),
    #[command(flatten)]
    source: SourceArgs,
    #[command(flatten)]
    constants: ConstantArgs,
    /// Float constant set by the application, e.g. --const c3=0.27,0.67,0.06,0.01.
    #[arg(long = "const", value_name = "cN=X[,Y,Z,W]", value_parser = parse_float_const)]
    floats: Vec<(u32, [f32; 4])>,
    #[arg(long, value_enum, default_value = "point")]
    filter: FilterArg,
    #[arg(long, value_enum, default_value = "border")]
    address: AddressArg,
    /// Border colour R,G,B,A for --address border.
    #[arg(long, value_parser = parse_float4, default_value = "0,0,0,0")]
    border: [f32; 4],
    #[arg(long, value_enum, default_value = "f32")]
    target_format: FormatArg,
    /// Write the target here (.exr or .pfm), atomically.
    #[arg(short, long)]
    output: Option<PathBuf>,
    #[command(flatten)]
    exec: ExecArgs,
    #[command(flatten)]
    input: InputArgs,
}

pub fn run(args: Args, ui: &Ui) -> super::Result {
    super::bound_threads(args.exec.threads())?;
    if let Some(path) = &args.output {
        check_output_path(path, &[&args.image, Path::new(&args.shader)])?;
    }
    let src = shader_source(&args.shader, args.input.max_input_bytes)?;
    let file = SourceFile::new(src.name.clone(), src.text);
    let loaded = load::load(file, &args.source.options()).map_err(|e| {
        e.diagnostics.emit(&e.file, color_stderr());
        BadInput(e.to_string())
    })?;
    let img = image::load(&args.image, &args.exec.image_limits())?;
    let address = args.address.into();
    let setup = PassSetup {
        target: args.target,
        constants: constants(&args.floats, &args.constants.ints, &args.constants.bools),
        sampler: SamplerState {
            address_u: address,
            address_v: address,
            border: args.border,
            ..SamplerState::filtered(args.filter.into())
        },
        format: args.target_format.into(),
        threads: args.exec.threads(),
        limits: args.exec.limits(),
    };
    let out = {
        let _spinner = ui.spinner("running the shader");
        run_pass(&loaded, &img, &setup)?
    };
    if let Some(path) = &args.output {
        let is_pfm = path
            .extension()
            .is_some_and(|e| e.eq_ignore_ascii_case("pfm"));
        if is_pfm {
            write_pfm(path, &out.target)?;
        } else {
            write_exr(path, &out.target)?;
        }
    }
    if args.exec.json {
        print_json(&pass_json(&out))?;
    } else {
        let text = pass_text(
            &loaded.file.name,
            &args.image.display().to_string(),
            &out,
            args.output.as_deref().filter(|_| !ui.quiet),
        );
        say(ui, &text)?;
    }
    Ok(Outcome::from_ok(
        out.cost.within_limits && out.cost.counts_agree,
    ))
}
