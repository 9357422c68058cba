//! `ps30 tonemap`: the article's operator, run in the emulator, into an
//! 8-bit sRGB PNG, cross-checked pixel by pixel.

use super::args::{parse_key, parse_white, BackendArgs, ExecArgs, InputArgs};
use super::io::{check_output_path, print_json, say, shader_source};
use super::ui::Ui;
use super::Outcome;
use ps30::core::image::{self, write_png_rgb8};
use ps30::jobs::tonemap::{self, Settings};
use std::path::{Path, PathBuf};

#[derive(clap::Args)]
pub struct Args {
    image: PathBuf,
    /// Write the tone-mapped image here as an 8-bit sRGB PNG (atomically).
    #[arg(short, long)]
    output: Option<PathBuf>,
    /// The key a: the scene's log-average luminance L̄w is mapped to a.
    #[arg(long, default_value_t = tonemap::DEFAULT_KEY, value_parser = parse_key, allow_negative_numbers = true)]
    key: f64,
    /// White point: the HDR luminance shown as pure white (default: the scene's largest; inf: none).
    #[arg(long, value_name = "W", value_parser = parse_white, allow_negative_numbers = true)]
    white: Option<f64>,
    /// Tone-mapping shader (file, or the bundled tonemap:reinhard) with the same inputs.
    #[arg(long, default_value = "tonemap:reinhard")]
    shader: String,
    #[command(flatten)]
    exec: ExecArgs,
    #[command(flatten)]
    draw: BackendArgs,
    #[command(flatten)]
    input: InputArgs,
}

pub fn run(args: Args, ui: &Ui) -> super::Result {
    super::bound_threads(args.exec.threads())?;
    if let Some(out) = &args.output {
        let shader = Path::new(&args.shader);
        check_output_path(out, &[&args.image, shader])?;
    }
    let shader = shader_source(&args.shader, args.input.max_input_bytes)?;
    let img = image::load(&args.image, &args.exec.image_limits())?;
    let settings = Settings {
        key: args.key,
        white: args.white,
        threads: args.exec.threads(),
        band_rows: 0,
        shader,
        limits: args.exec.limits(),
        backend: args.draw.open()?,
        float_rules: args.draw.rules(),
    };
    let result = {
        let bar = std::cell::RefCell::new(ui.bar("tone mapping", img.height as u64));
        tonemap::run(&img, &settings, &|done, total| {
            bar.borrow_mut().set(None, done, total)
        })?
    };
    let written = match &args.output {
        Some(out) => {
            write_png_rgb8(out, result.width, result.height, &result.srgb8())?;
            Some(out.display().to_string())
        }
        None => None,
    };
    let name = args.image.display().to_string();
    let ok = result.all_agree();
    if args.exec.json {
        print_json(&ps30::present::tonemap::json(
            &name,
            &result,
            written.as_deref(),
        ))?;
    } else if !(ui.quiet && ok) {
        say(
            ui,
            &ps30::present::tonemap::text(&name, &result, written.as_deref()),
        )?;
    }
    Ok(Outcome::from_ok(ok))
}
