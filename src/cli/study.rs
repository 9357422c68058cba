//! `ps30 study`: the alternatives to the article's methods, and the article's
//! own chain, each run in the emulator, measured against the f64 truth, and
//! written up as a report page.

use super::args::parse_size;
use super::io::{check_output_dir, check_output_path, print_json, say};
use super::ui::Ui;
use super::{BadInput, Outcome};
use ps30::core::image::encode_png_rgb8;
use ps30::core::output::Batch;
use ps30::jobs::assets::{self, IMAGES};
use ps30::jobs::render;
use ps30::jobs::studies::{article_chain, log_lights, mip_luminance};
use ps30::present::study::{self, Page};
use std::path::{Path, PathBuf};

/// Which study.
#[derive(Clone, Copy, clap::ValueEnum)]
pub enum Name {
    /// Log-luminance in 8-bit alpha averaged by the mip chain, on every
    /// bundled image, against the truth and the article's two passes.
    MipLuminance,
    /// Lights as exp2(-light) multiplied into RGBA8, against raw RGBA8 and
    /// A16B16G16R16F, for the brightness values 0.1, 1, 2, 3 and 1 to 8
    /// overlapping lights.
    LogLights,
    /// The article's chain: lights added into A16B16G16R16F, L̄w, tone map.
    ArticleChain,
}

#[derive(clap::Args)]
pub struct Args {
    #[arg(value_enum)]
    name: Name,
    /// Directory for the report page (NAME.md) and its figures (figures/).
    #[arg(long, value_name = "DIR", default_value = "reports")]
    reports: PathBuf,
    /// article-chain: write the tone-mapped frame here as an 8-bit sRGB PNG.
    #[arg(short, long)]
    output: Option<PathBuf>,
    /// article-chain: the G-buffer's size.
    #[arg(long, value_name = "WxH", value_parser = parse_size, default_value = "1280x1024")]
    size: (u32, u32),
    /// Threads for all of the command's work (default: all cores); results do not depend on it.
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=256))]
    threads: Option<u32>,
    /// Print JSON instead of text.
    #[arg(long)]
    json: bool,
}

/// Stages a page and its figures; returns what will be written.
fn stage_page(batch: &mut Batch, dir: &Path, page: &Page) -> Result<Vec<String>, BadInput> {
    let figures = dir.join("figures");
    batch.directory(&figures)?;
    let path = dir.join(&page.name);
    batch.write_bytes(&path, page.markdown.as_bytes())?;
    let mut written = vec![path.display().to_string()];
    for (name, canvas) in &page.figures {
        let p = figures.join(name);
        batch.write_bytes(
            &p,
            &encode_png_rgb8(&p, canvas.width, canvas.height, &canvas.rgb)?,
        )?;
        written.push(p.display().to_string());
    }
    Ok(written)
}

pub fn run(args: Args, ui: &Ui) -> super::Result {
    super::bound_threads(args.threads.map(|t| t as usize))?;
    if let Some(out) = &args.output {
        check_output_path(out, &[])?;
    }
    check_output_dir(&args.reports)?;
    let settings = render::Settings {
        threads: args.threads.map(|t| t as usize),
        limits: Default::default(),
        budget: Default::default(),
        float_rules: Default::default(),
        backend: Default::default(),
    };
    let bar = std::cell::RefCell::new(ui.bar("study", 1));
    let progress = |done: u64, total: u64| bar.borrow_mut().set(None, done, total);
    let (text, json, page, ok, png) = match args.name {
        Name::LogLights => {
            let s = log_lights::study(&settings, &progress).map_err(BadInput)?;
            (
                study::log_lights::text(&s),
                study::log_lights::json(&s),
                study::log_lights::page(&s).map_err(BadInput)?,
                s.all_agree(),
                None,
            )
        }
        Name::MipLuminance => {
            let mut images = Vec::new();
            for name in IMAGES {
                images.push((name.to_string(), assets::load(name).map_err(BadInput)?));
            }
            let s = mip_luminance::study(&images, 1e-4, &settings, &progress).map_err(BadInput)?;
            (
                study::mip_luminance::text(&s),
                study::mip_luminance::json(&s),
                study::mip_luminance::page(&s).map_err(BadInput)?,
                s.all_agree(),
                None,
            )
        }
        Name::ArticleChain => {
            let lights = article_chain::default_lights();
            let r = article_chain::run(
                args.size,
                &lights,
                &Default::default(),
                &settings,
                &progress,
            )
            .map_err(BadInput)?;
            let written = match &args.output {
                Some(out) => {
                    let png = encode_png_rgb8(
                        out,
                        r.width,
                        r.height,
                        &ps30::jobs::tonemap::to_srgb8(&r.tonemapped),
                    )?;
                    Some((out.display().to_string(), png))
                }
                None => None,
            };
            let shown = written.as_ref().map(|(name, _)| name.as_str());
            (
                study::article_chain::text(&r, shown),
                study::article_chain::json(&r, shown),
                study::article_chain::page(&r).map_err(BadInput)?,
                r.all_agree(),
                written,
            )
        }
    };
    drop(bar);
    let mut batch = Batch::new(&args.reports)?;
    let mut written = stage_page(&mut batch, &args.reports, &page)?;
    if let (Some(path), Some((name, bytes))) = (&args.output, &png) {
        // `-o` names a file of the user's anywhere, not one inside the reports folder.
        let dir = path
            .parent()
            .filter(|d| !d.as_os_str().is_empty())
            .unwrap_or(Path::new("."));
        batch.directory(dir)?;
        batch.write_bytes(&dir.join(path.file_name().unwrap_or_default()), bytes)?;
        written.push(name.clone());
    }
    batch.commit()?;
    if args.json {
        let mut v = json;
        v["report"] = serde_json::json!(written);
        print_json(&v)?;
    } else {
        say(ui, &text)?;
        if !ui.quiet {
            say(ui, &format!("report written: {}\n", written.join(", ")))?;
        }
    }
    Ok(Outcome::from_ok(ok))
}
