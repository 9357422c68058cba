//! `ps30 tonemap`: the article's operator, run in the emulator, into an
//! 8-bit sRGB PNG, cross-checked pixel by pixel. The result is never held
//! whole in floating point: each band of rows is encoded as it is drawn.

use super::args::{opening_failed, parse_key, parse_white, BackendArgs, ExecArgs, InputArgs};
use super::io::{check_image_output, print_json, say, shader_source};
use super::ui::Ui;
use super::Outcome;
use ps30::core::image::{self, write_png_rgb8, HdrImage, ImageError, OutputFormat, RgbBands};
use ps30::jobs::tonemap::{self, Settings};
use std::path::{Path, PathBuf};

#[derive(clap::Args)]
pub struct Args {
    /// The HDR image: OpenEXR, Radiance .hdr or PFM.
    #[arg(value_name = "IMAGE")]
    image: PathBuf,
    /// Write the tone-mapped image here, atomically: .png as 8-bit sRGB; .exr, .pfm or
    /// .hdr as the shader's linear output (floats in [0, 1]).
    #[arg(short, long, value_name = "FILE")]
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
        check_image_output(out, &[&args.image, Path::new(&args.shader)])?;
    }
    let shader = shader_source(&args.shader, args.input.max_input_bytes)?;
    let (backend, img) = args
        .draw
        .open_beside(|| image::load(&args.image, &args.exec.image_limits()));
    let img = img?;
    ps30::core::phases::mark("image decoded");
    let settings = Settings {
        key: args.key,
        white: args.white,
        threads: args.exec.threads(),
        band_rows: 0,
        shader,
        limits: args.exec.limits(),
        backend: backend?,
        float_rules: args.draw.rules(),
    };
    let mut output = args
        .output
        .as_deref()
        .map(|out| Output::create(out, &img))
        .transpose()?;
    let result = {
        let bar = std::cell::RefCell::new(ui.bar("tone mapping", img.height as u64));
        let progress = |done, total| bar.borrow_mut().set(None, done, total);
        tonemap::run_into(&img, &settings, &progress, &mut |band| match &mut output {
            Some(out) => out.band(band),
            None => Ok(()),
        })
        .map_err(|e| opening_failed(&settings.backend, e))?
    };
    // The image is not needed any more: the PNG is encoded without it (after
    // a GPU's draws it is freed after the command ends).
    ps30::core::gpu::leave_at_exit(img);
    let written = match (output, &args.output) {
        (Some(out), Some(path)) => {
            out.finish(path, result.width, result.height)?;
            Some(path.display().to_string())
        }
        _ => None,
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

/// Where the tone-mapped bands go.
enum Output {
    /// The 8-bit sRGB samples (3 bytes a pixel), compressed into the PNG
    /// when complete, as one image (so the file is the same for any bands).
    Png(Vec<u8>),
    /// A floating-point file written band by band.
    Float(Box<RgbBands>),
}

impl Output {
    fn create(path: &Path, img: &HdrImage) -> Result<Output, ImageError> {
        Ok(match OutputFormat::of(path)? {
            OutputFormat::Png => Output::Png(Vec::with_capacity(3 * img.pixels.len())),
            _ => Output::Float(Box::new(RgbBands::create(path, img.width, img.height)?)),
        })
    }

    fn band(&mut self, band: &[[f32; 4]]) -> Result<(), image::ForeignError> {
        match self {
            Output::Png(rgb) => rgb.extend(tonemap::to_srgb8(band)),
            Output::Float(file) => file.write_rows(band)?,
        }
        Ok(())
    }

    fn finish(self, path: &Path, width: u32, height: u32) -> Result<(), ImageError> {
        match self {
            Output::Png(rgb) => write_png_rgb8(path, width, height, &rgb),
            Output::Float(file) => file.finish(),
        }
    }
}
