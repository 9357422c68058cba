//! `ps30 luminance`: both passes on an HDR image, cross-checked.

use super::args::{
    opening_failed, parse_delta, parse_size, BackendArgs, ExecArgs, FormatArg, InputArgs,
};
use super::io::{print_json, say, shader_source};
use super::ui::Ui;
use super::{BadInput, Outcome};
use ps30::core::image;
use ps30::jobs::blocks;
use ps30::jobs::bundled::{self, Named};
use ps30::jobs::luminance::{self, reference::Policy, Settings, ShaderSource};
use ps30::present::luminance::{run_json, run_text, Choice};
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct Args {
    /// The HDR image: OpenEXR, Radiance .hdr or PFM.
    #[arg(value_name = "IMAGE")]
    image: PathBuf,
    /// Pass-1 shader (file or bundled name). Without it, ps30 plans the blocks for the
    /// image's size and generates both passes (`ps30 plan`, `ps30 unroll`).
    #[arg(long, value_name = "SHADER")]
    pass1: Option<String>,
    /// Pass-2 shader (file or bundled name; default with --pass1: corrected:pass2).
    #[arg(long, value_name = "SHADER", requires = "pass1")]
    pass2: Option<String>,
    /// A pass-1 shader for the last column of blocks that reads only the
    /// frame's real width there (see `ps30 unroll`); without it, BORDER
    /// addressing pads the last column.
    #[arg(long, value_name = "SHADER", requires = "pass1")]
    last_column: Option<String>,
    /// Block size WxH (default: what the pass-1 shader was written for: a generated
    /// shader's header, the article's block for a bundled listing).
    #[arg(long, value_name = "WxH", value_parser = parse_size, requires = "pass1")]
    block: Option<(u32, u32)>,
    /// The δ of log(δ + L).
    #[arg(long, value_name = "D", default_value_t = 1e-4, value_parser = parse_delta)]
    delta: f32,
    /// Render-target format.
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
    /// log2|δ + L|, what the `log` instruction computes.
    Abs,
    /// log2(δ + max(L, 0)).
    Clamp,
}

/// The shaders and block of a run, and how they were chosen.
struct Passes {
    pass1: ShaderSource,
    pass2: ShaderSource,
    last: Option<ShaderSource>,
    block: (u32, u32),
    choice: Choice,
}

impl Args {
    /// The planner's passes when none are named; else the named ones with
    /// the given block or the block the pass-1 shader was written for.
    fn passes(&self, width: u32, height: u32) -> Result<Passes, BadInput> {
        let Some(spec) = &self.pass1 else {
            let p = blocks::planned(width, height, self.delta as f64)?;
            return Ok(Passes {
                block: p.block(),
                choice: Choice::Planned {
                    label: p.candidate.label(),
                    why: p.why.clone(),
                },
                pass1: p.pass1,
                pass2: p.pass2,
                last: None,
            });
        };
        let pass1 = shader_source(spec, self.input.max_input_bytes)?;
        let name = match bundled::resolve(spec) {
            Named::Bundled(b) => Some(b.name),
            Named::File(_) => None,
        };
        let (block, choice) = match (self.block, blocks::block_of(&pass1.file.text, name)) {
            (Some(b), _) => (b, Choice::Given),
            (None, Some(b)) => (b, Choice::FromShader),
            (None, None) => {
                return Err(BadInput(format!(
                    "{spec}: give --block WxH; the shader states no block (only generated shaders and the bundled listings do)"
                )))
            }
        };
        Ok(Passes {
            pass1,
            pass2: shader_source(
                self.pass2.as_deref().unwrap_or("corrected:pass2"),
                self.input.max_input_bytes,
            )?,
            last: self
                .last_column
                .as_deref()
                .map(|s| shader_source(s, self.input.max_input_bytes))
                .transpose()?,
            block,
            choice,
        })
    }
}

pub fn run(args: Args, ui: &Ui) -> super::Result {
    super::bound_threads(args.exec.threads())?;
    // The passes need only the image's size: planning them runs beside the
    // decoding.
    // So does opening a GPU.
    let (backend, loaded) = args.draw.open_beside(|| {
        image::load_beside(&args.image, &args.exec.image_limits(), |w, h| {
            args.passes(w, h)
        })
    });
    let (img, passes) = loaded?;
    ps30::core::phases::mark("image decoded");
    let passes = passes?;
    let settings = Settings {
        block: passes.block,
        delta: args.delta,
        format: args.target_format.into(),
        policy: match args.negative {
            NegativeArg::Abs => Policy::ABS,
            NegativeArg::Clamp => Policy::CLAMP,
        },
        threads: args.exec.threads(),
        limits: args.exec.limits(),
        backend: backend?,
        float_rules: args.draw.rules(),
    };
    let run = {
        let _spinner = ui.spinner("running both passes");
        match &passes.last {
            Some(last) => {
                luminance::run_with_last_column(&img, &passes.pass1, last, &passes.pass2, &settings)
            }
            None => luminance::run(&img, &passes.pass1, &passes.pass2, &settings),
        }
        .map_err(|e| opening_failed(&settings.backend, e))?
    };
    let name = args.image.display().to_string();
    if args.exec.json {
        print_json(&run_json(&name, &run, &passes.choice))?;
    } else {
        say(ui, &run_text(&name, &run, &passes.choice))?;
    }
    // A non-finite L̄w is a problem even when the reference agrees; so is a
    // pass over the limits, and a bound too wide to tell anything.
    let ok = run.all_agree() && run.finite() && run.within_limits() && run.fit();
    // After a GPU's draws, the decoded image is freed after the command ends.
    ps30::core::gpu::leave_at_exit(img);
    Ok(Outcome::from_ok(ok))
}
