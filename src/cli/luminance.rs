//! `ps30 luminance`: both passes on an HDR image, cross-checked.

use super::args::{parse_delta, parse_size, BackendArgs, ExecArgs, FormatArg, InputArgs};
use super::io::{print_json, say, shader_source};
use super::ui::Ui;
use super::Outcome;
use ps30::core::image;
use ps30::jobs::luminance::{self, reference::Policy, Settings};
use ps30::present::luminance::{run_json, run_text};
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct Args {
    image: PathBuf,
    /// Pass-1 shader (file or bundled name).
    #[arg(long, default_value = "corrected:unrolled")]
    pass1: String,
    /// Pass-2 shader (file or bundled name).
    #[arg(long, default_value = "corrected:pass2")]
    pass2: String,
    /// A pass-1 shader for the last column of blocks that reads only the
    /// frame's real width there (see `ps30 unroll`); without it, BORDER
    /// addressing pads the last column.
    #[arg(long, value_name = "SHADER")]
    last_column: Option<String>,
    /// Block size WxH (an unrolled shader fixes W to its REPEAT_BLOCK count).
    #[arg(long, value_name = "WxH", value_parser = parse_size, default_value = "125x128")]
    block: (u32, u32),
    /// The δ of log(δ + L).
    #[arg(long, default_value_t = 1e-4, value_parser = parse_delta)]
    delta: f32,
    /// Render-target format: f32 (D3DFMT_R32F) or f16 (D3DFMT_A16B16G16R16F).
    #[arg(long, value_enum, default_value = "f32")]
    target_format: FormatArg,
    /// Reference policy for negative luminance: abs (what `log` does) or clamp.
    #[arg(long, value_enum, default_value = "abs")]
    negative: NegativeArg,
    #[command(flatten)]
    exec: ExecArgs,
    #[command(flatten)]
    draw: BackendArgs,
    #[command(flatten)]
    input: InputArgs,
}

/// Reference policy flag values.
#[derive(Clone, Copy, clap::ValueEnum)]
enum NegativeArg {
    Abs,
    Clamp,
}

pub fn run(args: Args, ui: &Ui) -> super::Result {
    super::bound_threads(args.exec.threads())?;
    let img = image::load(&args.image, &args.exec.image_limits())?;
    let settings = Settings {
        block: args.block,
        delta: args.delta,
        format: args.target_format.into(),
        policy: match args.negative {
            NegativeArg::Abs => Policy::ABS,
            NegativeArg::Clamp => Policy::CLAMP,
        },
        threads: args.exec.threads(),
        limits: args.exec.limits(),
        backend: args.draw.open()?,
        float_rules: args.draw.rules(),
    };
    let (pass1, pass2) = (
        shader_source(&args.pass1, args.input.max_input_bytes)?,
        shader_source(&args.pass2, args.input.max_input_bytes)?,
    );
    let run = {
        let _spinner = ui.spinner("running both passes");
        match &args.last_column {
            Some(last) => luminance::run_with_last_column(
                &img,
                &pass1,
                &shader_source(last, args.input.max_input_bytes)?,
                &pass2,
                &settings,
            )?,
            None => luminance::run(&img, &pass1, &pass2, &settings)?,
        }
    };
    let name = args.image.display().to_string();
    if args.exec.json {
        print_json(&run_json(&name, &run))?;
    } else {
        say(ui, &run_text(&name, &run))?;
    }
    // A non-finite L̄w is a problem even when the reference agrees.
    Ok(Outcome::from_ok(run.all_agree() && run.finite()))
}
