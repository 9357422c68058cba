//! `ps30 verify`: the article's claims, the luminance cross-check, the tone
//! mapping of every bundled image and the committed generated shaders, with
//! the pages of `reports/`.

use super::io::{check_output_dir, print_json, say};
use super::ui::Ui;
use super::{BadInput, Outcome};
use ps30::core::output::Batch;
use ps30::jobs::assets;
use ps30::jobs::gen::set::{self, GeneratedSet};
use ps30::jobs::verify::{self as claims, CROSSCHECK_IMAGE, GENERATED_DIR};
use ps30::present::report::{self, claims as pages, generated};
use ps30::present::verify::{json, text, Summary};
use std::path::{Path, PathBuf};

#[derive(clap::Args)]
pub struct Args {
    /// Directory for the reports.
    #[arg(long, default_value = "reports")]
    reports: PathBuf,
    /// Directory of the committed generated shaders to check (default:
    /// asm/generated, when the current directory has one).
    #[arg(long, value_name = "DIR")]
    generated: Option<PathBuf>,
    /// Rewrite the generated shaders instead of failing when they are stale.
    #[arg(long)]
    regenerate: bool,
    /// Print JSON instead of text.
    #[arg(long)]
    json: bool,
}

/// The directory of committed generated shaders to check: the one named,
/// else `asm/generated` of the current directory when there is one (a
/// checkout of the repository); `None` outside a checkout, where there is
/// nothing committed to check. `--regenerate` writes the default directory.
fn generated_dir(named: Option<&PathBuf>, regenerate: bool) -> Option<PathBuf> {
    let default = PathBuf::from(GENERATED_DIR);
    named
        .cloned()
        .or_else(|| (regenerate || default.is_dir()).then_some(default))
}

pub fn run(args: Args, ui: &Ui) -> super::Result {
    check_output_dir(&args.reports)?;
    if let Some(dir) = args.generated.as_ref().filter(|_| args.regenerate) {
        check_output_dir(dir)?;
    }
    let bar = std::cell::RefCell::new(ui.bar("article claims", 12));
    let mut found = claims::article_claims().map_err(BadInput)?;
    let set = set::generated_set()?;
    found.extend(claims::planning_claims(&set).map_err(BadInput)?);
    bar.borrow_mut().set(Some("luminance cross-check"), 1, 12);
    let img = assets::load(CROSSCHECK_IMAGE).map_err(BadInput)?;
    let rows = claims::crosscheck(&img).map_err(BadInput)?;
    let generated = generated_dir(args.generated.as_ref(), args.regenerate);
    let (stale, rewritten) = match &generated {
        Some(dir) => check_generated(dir, &set, args.regenerate)?,
        None => (Vec::new(), Vec::new()),
    };
    let pages = [
        args.reports.join("article-claims.md"),
        args.reports.join("luminance-crosscheck.md"),
        args.reports.join("generated-shaders.md"),
    ];
    let mut batch = Batch::new(&args.reports)?;
    for (path, text) in pages.iter().zip([
        pages::claims_report(&found),
        pages::crosscheck_report(&rows),
        generated::summary_report(&set),
    ]) {
        batch.write_bytes(path, text.as_bytes())?;
    }
    let figures = report::generate(&mut batch, &args.reports, None, &|stage, done, total| {
        bar.borrow_mut().set(Some(stage), done + 2, total + 2)
    })
    .map_err(BadInput)?;
    batch.commit()?;
    drop(bar);
    let summary = Summary {
        claims: &found,
        crosscheck: &rows,
        figures: &figures,
        set: &set,
        generated: generated.as_deref(),
        regenerated: args.regenerate,
        stale: &stale,
        rewritten: &rewritten,
        pages: [&pages[0], &pages[1], &pages[2]],
        reports: &args.reports,
    };
    let ok = summary.all_agree();
    if args.json {
        print_json(&json(&summary))?;
    } else if !(ui.quiet && ok) {
        say(ui, &text(&summary))?;
    }
    Ok(Outcome::from_ok(ok))
}

/// The committed generated shaders compared with what the generator writes
/// now (the stale files), or rewritten (`wrote …` / `removed …` lines) and
/// compared again.
fn check_generated(
    dir: &Path,
    set: &GeneratedSet,
    regenerate: bool,
) -> Result<(Vec<String>, Vec<String>), BadInput> {
    if !regenerate {
        return Ok((set::stale_files(dir, set), Vec::new()));
    }
    let (written, removed) = set::write_set(dir, set)?;
    let lines = written
        .into_iter()
        .map(|p| format!("wrote {p}"))
        .chain(removed.into_iter().map(|p| format!("removed {p}")))
        .collect();
    // What regeneration may not touch (files it did not write) stays a
    // problem, named.
    Ok((set::stale_files(dir, set), lines))
}
