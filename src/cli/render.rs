//! `ps30 render`: runs a draw list a user wrote (JSON) — clears, draws with
//! blending and write masks, mip-chain reductions — and writes its targets.

use super::args::ExecArgs;
use super::io::{print_json, say};
use super::ui::Ui;
use super::{BadInput, Outcome};
use ps30::core::emu::findings::diagnostic;
use ps30::core::image::{write_exr, write_png_rgb8, RenderTarget};
use ps30::jobs::render::{self, file, StepDetail, StepReport, TargetState};
use ps30::present::render as show;
use std::path::{Path, PathBuf};

#[derive(clap::Args)]
pub struct Args {
    /// The draw list (JSON; see `ps30 render --help`).
    list: PathBuf,
    /// Write every target at the end into DIR as NAME.exr (its exact stored
    /// values) and NAME.png (a preview); DIR is created if missing.
    #[arg(short, long, value_name = "DIR")]
    output: Option<PathBuf>,
    /// With -o: also write each target a step changes, after that step, as
    /// NNN-NAME.exr and NNN-NAME.png.
    #[arg(long, requires = "output")]
    every_step: bool,
    /// Refuse a list with more steps than this.
    #[arg(long, value_name = "N", default_value_t = 10_000, value_parser = clap::value_parser!(u64).range(1..=1_000_000))]
    max_steps: u64,
    #[command(flatten)]
    exec: ExecArgs,
}

/// Writes `NAME.exr` and `NAME.png` for a target; returns the two paths.
fn write_target(dir: &Path, stem: &str, t: &RenderTarget) -> Result<[String; 2], BadInput> {
    let exr = dir.join(format!("{stem}.exr"));
    let png = dir.join(format!("{stem}.png"));
    write_exr(&exr, t)?;
    write_png_rgb8(&png, t.width, t.height, &show::preview(t))?;
    Ok([exr.display().to_string(), png.display().to_string()])
}

pub fn run(args: Args, ui: &Ui) -> super::Result {
    let limits = file::FileLimits {
        max_pixels: args.exec.max_pixels,
        max_steps: args.max_steps as usize,
    };
    let loaded = file::read(&args.list, &limits)?;
    let list = &loaded.list;
    if let Some(dir) = &args.output {
        std::fs::create_dir_all(dir).map_err(|e| BadInput(format!("{}: {e}", dir.display())))?;
    }
    let name = args.list.display().to_string();
    if !args.exec.json {
        let mut head = format!(
            "{name}: {} targets, {} textures, {} shaders, {} steps\n",
            list.targets.len(),
            list.textures.len(),
            list.shaders.len(),
            list.steps.len()
        );
        if let Some(d) = &loaded.description {
            head.push_str(&format!("  {d}\n"));
        }
        say(ui, &head)?;
    }
    let settings = render::Settings {
        threads: args.exec.threads(),
        limits: args.exec.limits(),
    };
    let mut written: Vec<String> = Vec::new();
    let mut failure: Option<BadInput> = None;
    let bar = std::cell::RefCell::new(ui.bar("steps", list.steps.len() as u64));
    let mut observe = |r: &StepReport, states: &[TargetState]| {
        bar.borrow_mut()
            .set(None, r.index as u64 + 1, list.steps.len() as u64);
        if let StepDetail::Draw { findings, .. } = &r.detail {
            if !ui.quiet {
                let shader = match &list.steps[r.index] {
                    render::Step::Draw(d) => &list.shaders[d.shader].loaded.file,
                    _ => return,
                };
                for f in findings {
                    diagnostic(f).emit(shader, super::io::color_stderr());
                }
            }
        }
        if !args.exec.json {
            let _ = say(ui, &show::step_line(list, r));
        }
        if let (true, Some(dir), None) = (args.every_step, &args.output, &failure) {
            let t = list.target(&r.target).expect("the step's target exists");
            match write_target(
                dir,
                &format!("{:03}-{}", r.index, r.target),
                &states[t].target,
            ) {
                Ok(paths) => written.extend(paths),
                Err(e) => failure = Some(e),
            }
        }
    };
    let (reports, states) = render::run(list, &settings, &mut observe)?;
    drop(bar);
    if let Some(e) = failure {
        return Err(e);
    }
    if let Some(dir) = &args.output {
        for (spec, st) in list.targets.iter().zip(&states) {
            written.extend(write_target(dir, &spec.name, &st.target)?);
        }
    }
    let agree = reports.iter().all(|r| match &r.detail {
        StepDetail::Draw { counts_agree, .. } => *counts_agree,
        _ => true,
    });
    if args.exec.json {
        print_json(&show::json(
            &name,
            loaded.description.as_deref(),
            list,
            &reports,
            &states,
            &written,
        ))?;
    } else {
        say(ui, &show::targets_text(list, &states))?;
        if !ui.quiet && !written.is_empty() {
            say(
                ui,
                &format!(
                    "wrote {} files in {}\n",
                    written.len(),
                    args.output.as_deref().unwrap_or(Path::new(".")).display()
                ),
            )?;
        }
    }
    Ok(Outcome::from_ok(agree))
}
