//! `ps30 run`: one pass of any shader over an image into a render target.

use super::args::{
    parse_float4, parse_float_const, AddressArg, BackendArgs, ConstRef, ConstantArgs, ExecArgs,
    FilterArg, FormatArg, InputArgs, Resolved, SourceArgs,
};
use super::io::{check_output_path, load_file, print_json, say};
use super::ui::Ui;
use super::Outcome;
use ps30::core::emu::SamplerState;
use ps30::core::image::{self, write_exr, write_pfm};
use ps30::jobs::luminance::{run_pass, PassSetup};
use ps30::present::constants::{table_json, table_text};
use ps30::present::luminance::{pass_json, pass_text};
use serde_json::Value;
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
    /// Float constant set by the application, by register or by its name in the
    /// shader's constant table, e.g. --const c3=0.27,0.67,0.06,0.01 or --const g_fKey=0.18.
    #[arg(long = "const", value_name = "cN|NAME=X[,Y,Z,W]", value_parser = parse_float_const)]
    floats: Vec<(ConstRef, Vec<f32>)>,
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
    draw: BackendArgs,
    #[command(flatten)]
    input: InputArgs,
}

pub fn run(args: Args, ui: &Ui) -> super::Result {
    super::bound_threads(args.exec.threads())?;
    if let Some(path) = &args.output {
        check_output_path(path, &[&args.image, Path::new(&args.shader)])?;
    }
    let loaded = load_file(
        &args.shader,
        &args.source.options(),
        args.input.max_input_bytes,
    )?;
    let img = image::load(&args.image, &args.exec.image_limits())?;
    let address = args.address.into();
    let setup = PassSetup {
        target: args.target,
        constants: Resolved::new(
            &args.floats,
            &args.constants.ints,
            &args.constants.bools,
            loaded.constants.as_ref(),
        )?
        .constants(),
        sampler: SamplerState {
            address_u: address,
            address_v: address,
            border: args.border,
            ..SamplerState::filtered(args.filter.into())
        },
        format: args.target_format.into(),
        threads: args.exec.threads(),
        limits: args.exec.limits(),
        backend: args.draw.open()?,
        float_rules: args.draw.rules(),
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
        let mut json = pass_json(&out);
        json["constant_table"] = loaded.constants.as_ref().map_or(Value::Null, table_json);
        print_json(&json)?;
    } else {
        let mut text = pass_text(
            &loaded.file.name,
            &args.image.display().to_string(),
            &out,
            args.output.as_deref().filter(|_| !ui.quiet),
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
