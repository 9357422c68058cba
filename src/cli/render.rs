//! `ps30 render`: runs a draw list a user wrote (JSON) — clears, draws with
//! blending and write masks, mip-chain reductions — and writes its targets.

use super::args::{ExecArgs, InputArgs};
use super::io::{check_output_dir, eprint, print_json, say};
use super::ui::Ui;
use super::{BadInput, Outcome};
use ps30::core::emu::findings::diagnostic;
use ps30::core::image::{encode_exr, encode_png_rgb8, RenderTarget};
use ps30::core::numbers::plural;
use ps30::core::output::{self, Batch};
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
    /// The history of one pixel, `X,Y` or `TARGET:X,Y` (without a target,
    /// the target of the list's last draw): every step that changes it,
    /// each primitive that reaches it with the pixel shader's inputs and
    /// outputs, texkill, the alpha and depth tests and the blend. May be
    /// given more than once.
    #[arg(long, value_name = "[TARGET:]X,Y")]
    pixel: Vec<String>,
    /// Refuse a list with more steps than this.
    #[arg(long, value_name = "N", default_value_t = 10_000, value_parser = clap::value_parser!(u64).range(1..=1_000_000))]
    max_steps: u64,
    /// Refuse a list whose steps touch more pixels than this in all (a clear
    /// or draw its target, a mip reduction its levels; each step at least
    /// 4,096), before any step runs.
    #[arg(long, value_name = "N", default_value_t = render::ListBudget::MAX_PIXELS, value_parser = clap::value_parser!(u64).range(1..))]
    max_list_pixels: u64,
    /// Stop the list at the draw that makes all draws together execute more
    /// instruction slots than this.
    #[arg(long, value_name = "N", default_value_t = render::ListBudget::MAX_EXECUTED, value_parser = clap::value_parser!(u64).range(1..))]
    max_list_executed: u64,
    /// With --every-step: refuse a list whose written files could stage more
    /// bytes than this (an upper bound computed before any step runs).
    #[arg(long, value_name = "BYTES", default_value_t = 1 << 30, value_parser = clap::value_parser!(u64).range(1..))]
    max_staged_bytes: u64,
    /// Who runs each draw's shader, and the float rules of the draws that
    /// name none. On a GPU the shaders run translated; clears, blending,
    /// write masks, alpha test, clip planes and mip reductions stay ps30's
    /// output merger.
    #[command(flatten)]
    backend: super::args::BackendArgs,
    #[command(flatten)]
    exec: ExecArgs,
    #[command(flatten)]
    input: InputArgs,
}

/// The files of `-o DIR`, staged together and renamed all at once at the
/// end, so a failed run leaves none of them; none may be an input.
struct Outputs<'a> {
    dir: &'a Path,
    batch: Batch,
    inputs: Vec<&'a Path>,
    written: Vec<String>,
}

impl Outputs<'_> {
    /// Stages `STEM.exr` and `STEM.png` for a target.
    fn target(&mut self, stem: &str, t: &RenderTarget) -> Result<(), BadInput> {
        let exr = self.dir.join(format!("{stem}.exr"));
        let png = self.dir.join(format!("{stem}.png"));
        for path in [&exr, &png] {
            output::check(path, &self.inputs).map_err(BadInput)?;
        }
        self.batch.write_bytes(&exr, &encode_exr(&exr, t)?)?;
        let preview = encode_png_rgb8(&png, t.width, t.height, &show::preview(t))?;
        self.batch.write_bytes(&png, &preview)?;
        self.written
            .extend([exr.display().to_string(), png.display().to_string()]);
        Ok(())
    }
}

/// `--pixel`'s `[TARGET:]X,Y` in `list`: without a target, the target of
/// the list's last draw (its first target when it draws nothing).
fn watched_pixel(list: &render::DrawList, text: &str) -> Result<render::history::Pixel, BadInput> {
    let bad = |why: String| BadInput(format!("--pixel {text}: {why}"));
    let (name, xy) = match text.rsplit_once(':') {
        Some((n, xy)) => (Some(n), xy),
        None => (None, text),
    };
    let target = match name {
        Some(n) => list.target(n).ok_or_else(|| {
            let names: Vec<&str> = list.targets.iter().map(|t| t.name.as_str()).collect();
            bad(format!(
                "no target named `{n}` (the list has {})",
                ps30::core::numbers::list(&names)
            ))
        })?,
        None => list
            .steps
            .iter()
            .rev()
            .find_map(|s| match s {
                render::Step::Draw(d) => Some(d.target),
                _ => None,
            })
            .unwrap_or(0),
    };
    let coords: Vec<Option<u32>> = xy.split(',').map(|c| c.trim().parse().ok()).collect();
    let [Some(x), Some(y)] = coords[..] else {
        return Err(bad(
            "give the pixel as X,Y or TARGET:X,Y (column, row)".into()
        ));
    };
    if list.targets.is_empty() {
        return Err(bad("the list has no target".into()));
    }
    Ok(render::history::Pixel { target, x, y })
}

/// The recorder of the `--pixel` pixels; `None` when there are none.
fn recorder(
    list: &render::DrawList,
    pixels: &[String],
) -> Result<Option<render::history::Recorder>, BadInput> {
    if pixels.is_empty() {
        return Ok(None);
    }
    let pixels = pixels
        .iter()
        .map(|p| watched_pixel(list, p))
        .collect::<Result<Vec<_>, _>>()?;
    let recorder = render::history::Recorder::new(list, &pixels).map_err(BadInput)?;
    Ok(Some(recorder))
}

pub fn run(args: Args, ui: &Ui) -> super::Result {
    super::bound_threads(args.exec.threads())?;
    if let Some(dir) = &args.output {
        check_output_dir(dir)?;
    }
    let limits = file::FileLimits {
        max_pixels: args.exec.max_pixels,
        max_steps: args.max_steps as usize,
        max_input_bytes: args.input.max_input_bytes,
    };
    let loaded = file::read(&args.list, &limits)?;
    let list = &loaded.list;
    if !ui.quiet {
        for w in &loaded.warnings {
            eprint(&format!("warning: {w}\n"));
        }
    }
    let mut outputs = match &args.output {
        Some(dir) => Some(Outputs {
            dir,
            batch: Batch::new(dir)?,
            inputs: std::iter::once(args.list.as_path())
                .chain(loaded.sources.iter().map(PathBuf::as_path))
                .collect(),
            written: Vec::new(),
        }),
        None => None,
    };
    let name = args.list.display().to_string();
    if !args.exec.json {
        let count = |n: usize, one, many| plural(n as u64, one, many);
        let mut head = format!(
            "{name}: {}, {}, {}, {}\n",
            count(list.targets.len(), "target", "targets"),
            count(list.textures.len(), "texture", "textures"),
            count(list.shaders.len(), "shader", "shaders"),
            count(list.steps.len(), "step", "steps")
        );
        if let Some(d) = &loaded.description {
            head.push_str(&format!("  {d}\n"));
        }
        say(ui, &head)?;
    }
    let settings = render::Settings {
        threads: args.exec.threads(),
        limits: args.exec.limits(),
        budget: render::ListBudget {
            max_pixels: args.max_list_pixels,
            max_executed: args.max_list_executed,
        },
        float_rules: args.backend.rules(),
        backend: args.backend.open()?,
    };
    if args.every_step {
        let staged = render::staged_bytes_every_step(list);
        if staged > args.max_staged_bytes {
            return Err(BadInput(format!(
                "{name}: writing every target after every step could stage {} bytes, over the cap of {} (raise it with --max-staged-bytes {staged}, or drop --every-step)",
                ps30::core::numbers::thousands(staged),
                ps30::core::numbers::thousands(args.max_staged_bytes)
            )));
        }
    }
    let mut recorder = recorder(list, &args.pixel)?;
    let mut failure: Option<BadInput> = None;
    let bar = std::cell::RefCell::new(ui.bar("steps", list.steps.len() as u64));
    let mut observe = |r: &StepReport, states: &[TargetState]| {
        bar.borrow_mut()
            .set(None, r.index as u64 + 1, list.steps.len() as u64);
        if let (StepDetail::Draw { findings, .. }, render::Step::Draw(d)) =
            (&r.detail, &list.steps[r.index])
        {
            if !ui.quiet {
                let shader = &list.shaders[d.shader].loaded.file;
                let all: Vec<_> = findings.iter().map(diagnostic).collect();
                for d in ps30::core::diag::group(&all) {
                    eprint(&d.render_styled(shader, ui.color_stderr));
                }
            }
        }
        if !args.exec.json {
            let _ = say(ui, &show::step_line(list, r));
        }
        if let (true, Some(out), None) = (args.every_step, outputs.as_mut(), &failure) {
            // The step's target, and a draw's oC1–oC3 targets.
            for t in render::changed_targets(&list.steps[r.index]) {
                let name = &list.targets[t].name;
                let stem = format!("{:03}-{name}", r.index);
                if let Err(e) = out.target(&stem, &states[t].target) {
                    failure = Some(e);
                    break;
                }
            }
        }
    };
    let (reports, states) =
        render::run_with_history(list, &settings, &mut observe, recorder.as_mut())?;
    let histories = recorder.map_or_else(Vec::new, |r| r.histories());
    drop(bar);
    if let Some(e) = failure {
        return Err(e);
    }
    let mut written = Vec::new();
    if let Some(mut out) = outputs {
        for (spec, st) in list.targets.iter().zip(&states) {
            out.target(&spec.name, &st.target)?;
        }
        out.batch.commit()?;
        written = out.written;
    }
    let agree = reports.iter().all(|r| match &r.detail {
        StepDetail::Draw { counts_agree, .. } => *counts_agree,
        _ => true,
    });
    if args.exec.json {
        let mut v = show::json(
            &name,
            loaded.description.as_deref(),
            list,
            &reports,
            &states,
            &written,
        );
        if !histories.is_empty() {
            v["pixels"] = ps30::present::history::json(&histories);
        }
        print_json(&v)?;
    } else {
        say(ui, &show::targets_text(list, &states))?;
        for h in &histories {
            say(ui, &ps30::present::history::text(h))?;
        }
        if let (false, Some(dir)) = (ui.quiet || written.is_empty(), &args.output) {
            say(
                ui,
                &format!("wrote {} files in {}\n", written.len(), dir.display()),
            )?;
        }
    }
    Ok(Outcome::from_ok(agree))
}
