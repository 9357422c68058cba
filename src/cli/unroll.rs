//! `ps30 unroll`: pass-1, last-column and pass-2 luminance shaders written
//! for a frame and a profile.

use super::args::{parse_delta, parse_size, ProfileArgs};
use super::io::{check_output_dir, eprint, print, print_json};
use super::ui::Ui;
use super::{BadInput, Outcome};
use ps30::core::output::Batch;
use ps30::jobs::gen::set::{self, BlockChoice, Bundle, Role};
use ps30::jobs::gen::Pass1Form;
use ps30::present::unroll::summary_text;
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct Args {
    /// Block size WxH (texels per line × lines) for every form.
    #[arg(long, value_name = "WxH", value_parser = parse_size, conflicts_with = "fit", required_unless_present = "fit")]
    block: Option<(u32, u32)>,
    /// Fit the block to the profile (see below).
    #[arg(long)]
    fit: bool,
    /// Frame size WxH: sets the intermediate target, pass 2, the last column and the constants.
    #[arg(long, value_name = "WxH", value_parser = parse_size, default_value = "1280x1024")]
    frame: (u32, u32),
    /// Which pass-1 forms to generate.
    #[arg(long, value_enum, default_value = "both")]
    form: FormsArg,
    /// Keep BEGIN_REPEAT_BLOCK/END_REPEAT_BLOCK instead of expanding them.
    #[arg(long = "macro")]
    macros: bool,
    /// Print only one shader's text.
    #[arg(long, value_enum)]
    only: Option<OnlyArg>,
    /// Write each shader (atomically) into this directory instead of printing it.
    #[arg(short, long, value_name = "DIR")]
    output: Option<PathBuf>,
    /// The δ of log(δ + L), for the constants quoted in the headers.
    #[arg(long, default_value_t = 1e-4, value_parser = parse_delta)]
    delta: f32,
    #[command(flatten)]
    profile: ProfileArgs,
    /// Print JSON (figures and texts) instead of text.
    #[arg(long)]
    json: bool,
}

/// `--form` values.
#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
enum FormsArg {
    Unrolled,
    Loop,
    Both,
}

/// `--only` values.
#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
enum OnlyArg {
    Pass1,
    LastColumn,
    Pass2,
}

pub fn run(args: Args, ui: &Ui) -> super::Result {
    if let Some(dir) = &args.output {
        check_output_dir(dir)?;
    }
    let choice = match args.block {
        Some((w, h)) => BlockChoice::Given(w, h),
        None => BlockChoice::Fit,
    };
    let forms = match args.form {
        FormsArg::Unrolled => vec![Pass1Form::Unrolled],
        FormsArg::Loop => vec![Pass1Form::Loop],
        FormsArg::Both => vec![Pass1Form::Unrolled, Pass1Form::Loop],
    };
    let bundle = set::generate(
        &set::Request {
            frame: args.frame,
            picks: forms.into_iter().map(|f| (f, choice)).collect(),
            macros: args.macros,
            delta: args.delta as f64,
            last_columns: true,
        },
        &args.profile.profile(),
    )?;
    let outcome = Outcome::from_ok(bundle.problems.is_empty());
    if let Some(kind) = args.only {
        print_only(&bundle, kind)?;
        return Ok(outcome);
    }
    if let Some(dir) = &args.output {
        let mut batch = Batch::new(dir)?;
        for g in &bundle.shaders {
            batch.write_bytes(&dir.join(&g.file), g.text.as_bytes())?;
        }
        batch.commit()?;
    }
    if args.json {
        print_json(&bundle)?;
    } else if ui.quiet && args.output.is_some() {
        // Quiet, with the files written: only what did not fit.
        for p in &bundle.problems {
            print(&format!("does not fit: {p}\n"))?;
        }
    } else {
        print(&summary_text(&bundle))?;
        match &args.output {
            Some(dir) => print(&format!(
                "\nwrote {} files to {}\n",
                bundle.shaders.len(),
                dir.display()
            ))?,
            None => {
                for g in &bundle.shaders {
                    print(&format!("\n// ---- {} ----\n{}", g.file, g.text))?;
                }
            }
        }
    }
    Ok(outcome)
}

/// `--only`: the one shader of that role, or bad input when none or several
/// match.
fn print_only(bundle: &Bundle, kind: OnlyArg) -> Result<(), BadInput> {
    let role = match kind {
        OnlyArg::Pass1 => Role::Pass1,
        OnlyArg::LastColumn => Role::LastColumn,
        OnlyArg::Pass2 => Role::Pass2,
    };
    let matching: Vec<_> = bundle.shaders.iter().filter(|g| g.role == role).collect();
    match matching.as_slice() {
        [one] => print(&one.text)?,
        [] => {
            eprint(&summary_text(bundle));
            return Err(BadInput(
                "no such shader was generated (see the summary above)".into(),
            ));
        }
        many => {
            return Err(BadInput(format!(
                "--only matches {} shaders ({}); choose one with --form unrolled or --form loop",
                many.len(),
                many.iter()
                    .map(|g| g.file.as_str())
                    .collect::<Vec<_>>()
                    .join(", ")
            )))
        }
    }
    for p in &bundle.problems {
        eprint(&format!("does not fit: {p}\n"));
    }
    Ok(())
}
