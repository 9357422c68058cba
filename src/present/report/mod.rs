//! The figures and Markdown pages `ps30 verify` writes into `reports/`
//! beside the article-claims table and the luminance cross-check
//! (`crate::jobs::verify` writes those two):
//!
//! * `README.md` — the index;
//! * `budgets.md` + `figures/budgets.png` — every bundled shader's slots and
//!   executed instructions against the ps_3_0 limits;
//! * `luminance-blocks.md` + `figures/blocks-*.png` — heat maps of pass 1's
//!   per-block log-luminance and of its per-block error against the f64
//!   reference, for the corrected and the article's shaders;
//! * `tonemap.md` + `figures/tonemap-*.png` — every bundled image
//!   tone-mapped by the shader in the emulator, with its cross-check.
//!
//! Reproducible: no timestamps, no absolute paths, no thread-count
//! dependence (the emulator is bit-identical for any thread count), numbers
//! printed with fixed precision, PNGs from deterministic rasterisation. Two
//! runs on the same inputs give the same bytes (tests/reports.rs).

pub mod claims;
pub mod figures;
pub mod generated;
pub mod gpu;

use crate::core::image::encode_png_rgb8;
use crate::core::image::HdrImage;
use crate::core::numbers::number;
use crate::core::numbers::thousands;
use crate::core::output::Batch;
use crate::jobs::assets;
use crate::jobs::luminance::{self, LuminanceRun, ShaderSource};
use crate::jobs::tonemap;
use crate::jobs::verify;
use figures::{box_downscale, BarChart, HeatMap};
use serde::Serialize;
use std::path::Path;

/// The bundled images (compiled in: [`crate::jobs::assets`]).
pub use crate::jobs::assets::IMAGES;

/// Widest tone-mapped preview, in pixels (keeps `reports/` at a few MB).
pub const PREVIEW_WIDTH: u32 = 512;

/// Colours of the budget chart: slots, executed (two viridis samples).
const SLOTS_COLOR: [u8; 3] = [62, 73, 137];
const EXECUTED_COLOR: [u8; 3] = [53, 183, 121];

/// One shader's budget.
#[derive(Clone, Debug, Serialize)]
pub struct Budget {
    /// `name (file)`: the bundled name and the listing's path.
    pub shader: String,
    /// The constants it was measured with.
    pub constants: String,
    /// Instruction slots, from the cost model.
    pub slots: u64,
    /// Executed instructions per pixel (the longest path), from the cost model.
    pub executed: u64,
    /// The limits it was measured against.
    pub limits: crate::core::cost::Profile,
}

/// One heat map of pass-1 blocks.
#[derive(Clone, Debug, Serialize)]
pub struct BlockFigure {
    /// The PNG's file name under `figures/` (`blocks-log-luminance.png`).
    pub file: String,
    /// The pass-1 shader's bundled name.
    pub pass1: String,
    /// The pass-2 shader's bundled name.
    pub pass2: String,
    /// What a cell shows.
    pub quantity: String,
    /// The values at the two ends of the colour map.
    pub range: (f64, f64),
    /// Blocks in the pass-1 target.
    pub blocks: usize,
    /// Blocks whose emulated sum is within its bound of the f64 reference.
    pub blocks_agreeing: usize,
}

/// One tone-mapped image.
#[derive(Clone, Debug, Serialize)]
pub struct TonemapRow {
    /// The image's file name.
    pub image: String,
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// L̄w as the emulated luminance passes computed it.
    pub log_average: f64,
    /// L̄w of the f64 reference.
    pub reference_log_average: f64,
    /// Whether the luminance passes agree with the reference everywhere.
    pub luminance_agrees: bool,
    /// The key a.
    pub key: f64,
    /// `None` when infinite.
    pub white: Option<f64>,
    /// Where the white point came from.
    pub white_source: tonemap::WhiteSource,
    /// k = a / L̄w, the scale from world luminance to L.
    pub scale: f64,
    /// The tone-mapping shader's instruction slots.
    pub slots: u64,
    /// Its executed instructions per pixel (the emulator's count where it ran).
    pub executed_per_pixel: u64,
    /// Largest |emulated − reference| over all channels.
    pub max_error: f64,
    /// The bound at that channel.
    pub max_error_bound: f64,
    /// Largest |emulated − reference| / bound over channels with a bound > 0.
    pub largest_bound_fraction: f64,
    /// Channels outside their bound (must be 0).
    pub outside_bound: u64,
    /// Channels whose 8-bit codes differ from the reference's.
    pub mismatched_8bit_channels: u64,
    /// Pixels with at least one differing 8-bit code.
    pub mismatched_8bit_pixels: u64,
    /// Differing codes no rounding boundary inside the bound explains (must be 0).
    pub unexplained_8bit: u64,
    /// Pixels with Lw < 0 (shown black).
    pub negative_luminance_pixels: u64,
    /// Pixels with Lw exactly 0 (shown black).
    pub zero_luminance_pixels: u64,
    /// Pixels whose computed luminance could have either sign.
    pub sign_ambiguous_pixels: u64,
    /// Pixels with a channel at or above 1 before saturation.
    pub clipped_pixels: u64,
    /// Whether the whole run agrees ([`tonemap::ToneMapped::all_agree`]):
    /// luminance, limits, counts and the per-pixel check.
    pub agree: bool,
    /// The preview PNG, relative to the reports directory.
    pub preview: String,
    /// The preview's size in pixels, (width, height), at most [`PREVIEW_WIDTH`] wide.
    pub preview_size: (u32, u32),
}

/// What [`generate`] wrote.
#[derive(Clone, Debug, Serialize)]
pub struct Generated {
    /// Files written, relative to the reports directory, in order.
    pub files: Vec<String>,
    /// Every bundled shader's budget, as charted.
    pub budgets: Vec<Budget>,
    /// The block heat maps, one per figure.
    pub block_figures: Vec<BlockFigure>,
    /// One row per bundled image.
    pub tonemap: Vec<TonemapRow>,
}

impl Generated {
    /// Every tone-mapping cross-check agrees and every budget fits.
    pub fn all_agree(&self) -> bool {
        self.tonemap.iter().all(|r| r.agree)
            && self
                .budgets
                .iter()
                .all(|b| b.slots <= b.limits.max_slots && b.executed <= b.limits.max_executed)
    }
}

fn bundled(name: &str) -> Result<ShaderSource, String> {
    let (n, t) =
        crate::jobs::bundled::listing(name).ok_or_else(|| format!("no bundled shader {name}"))?;
    Ok(ShaderSource::new(n, t))
}

/// Stages the figures and pages for `dir` in `batch` (the caller commits
/// it: all files or none), from the bundled images compiled into the binary
/// ([`crate::jobs::assets`]). `progress(stage, done, total)` is called as stages
/// finish.
pub fn generate(
    batch: &mut Batch,
    dir: &Path,
    threads: Option<usize>,
    progress: &dyn Fn(&str, u64, u64),
) -> Result<Generated, String> {
    let figures = dir.join("figures");
    batch.directory(&figures)?;
    let total = 3 + IMAGES.len() as u64;
    let mut out = Generated {
        files: Vec::new(),
        budgets: Vec::new(),
        block_figures: Vec::new(),
        tonemap: Vec::new(),
    };
    let write = |batch: &mut Batch, out: &mut Generated, name: &str, text: &str| {
        batch.write_bytes(&dir.join(name), text.as_bytes())?;
        out.files.push(name.to_string());
        Ok::<(), String>(())
    };
    let write_png = |batch: &mut Batch, out: &mut Generated, name: &str, c: &figures::Canvas| {
        let path = figures.join(name);
        let png = encode_png_rgb8(&path, c.width, c.height, &c.rgb).map_err(|e| e.to_string())?;
        batch.write_bytes(&path, &png)?;
        out.files.push(format!("figures/{name}"));
        Ok::<(), String>(())
    };

    progress("shader budgets", 0, total);
    out.budgets = budgets()?;
    let groups: Vec<Vec<f64>> = out
        .budgets
        .iter()
        .map(|b| {
            vec![
                b.slots as f64 / b.limits.max_slots as f64,
                b.executed as f64 / b.limits.max_executed as f64,
            ]
        })
        .collect();
    // The bundled name of each row (`article:loop`), the path left to the page.
    let rows: Vec<String> = out
        .budgets
        .iter()
        .map(|b| b.shader.split(" (").next().unwrap_or(&b.shader).to_string())
        .collect();
    let chart = BarChart {
        labels: figures::Labels {
            title: "Bundled shaders against the ps_3_0 budgets",
            x: "share of the limit (512 slots; 65,535 executed per pixel)",
            y: "shader",
        },
        rows: &rows,
        groups: &groups,
        bars: &[
            ("instruction slots", SLOTS_COLOR),
            ("executed per pixel", EXECUTED_COLOR),
        ],
        max_fraction: 1.25,
        width: 900,
    };
    write_png(batch, &mut out, "budgets.png", &chart.render()?)?;
    let page = budgets_page(&out.budgets);
    write(batch, &mut out, "budgets.md", &page)?;

    progress("per-block heat maps", 1, total);
    let cross = assets::load(verify::CROSSCHECK_IMAGE)?;
    let runs = [
        ("corrected:unrolled", "corrected:pass2"),
        ("article:unrolled", "article:pass2"),
    ]
    .map(
        |(p1, p2)| -> Result<(String, String, LuminanceRun), String> {
            let settings = luminance::Settings {
                threads,
                ..luminance::Settings::default()
            };
            let run = luminance::run(&cross, &bundled(p1)?, &bundled(p2)?, &settings)
                .map_err(|e| e.to_string())?;
            Ok((p1.to_string(), p2.to_string(), run))
        },
    );
    let runs: Vec<(String, String, LuminanceRun)> = runs.into_iter().collect::<Result<_, _>>()?;
    let (figs, canvases) = block_figures(&cross, &runs)?;
    for (f, c) in figs.iter().zip(&canvases) {
        write_png(batch, &mut out, &f.file, c)?;
    }
    out.block_figures = figs;
    let page = blocks_page(&cross, &runs, &out.block_figures);
    write(batch, &mut out, "luminance-blocks.md", &page)?;

    for (i, name) in IMAGES.iter().enumerate() {
        progress(&format!("tone mapping {name}"), 2 + i as u64, total);
        let rel = format!("assets/hdr/{name}");
        let img = assets::load(&rel)?;
        let settings = tonemap::Settings {
            threads,
            ..tonemap::Settings::default()
        };
        let (t, linear) =
            tonemap::run(&img, &settings, &|_, _| {}).map_err(|e| format!("{rel}: {e}"))?;
        let (pw, ph, small) = box_downscale(t.width, t.height, &linear, PREVIEW_WIDTH);
        let file = format!("tonemap-{}.png", name.replace('.', "-"));
        let canvas = figures::Canvas {
            width: pw,
            height: ph,
            rgb: tonemap::to_srgb8(&small),
        };
        write_png(batch, &mut out, &file, &canvas)?;
        out.tonemap.push(tonemap_row(&rel, &t, &file, (pw, ph)));
    }
    progress("pages", 2 + IMAGES.len() as u64, total);
    let page = tonemap_page(&out.tonemap);
    write(batch, &mut out, "tonemap.md", &page)?;
    let page = index_page(&out);
    write(batch, &mut out, "README.md", &page)?;
    progress("done", total, total);
    Ok(out)
}

/// The bundled shaders measured with the constants the article uses.
pub fn budgets() -> Result<Vec<Budget>, String> {
    #[allow(clippy::type_complexity)]
    let list: [(&str, (&str, &str), &[(&str, u64)], &[(u32, i32)], &str); 7] = [
        (
            "article:loop",
            crate::jobs::bundled::ARTICLE_LOOP.listing(),
            &[],
            &[(1, 128), (2, 56)],
            "i1 = 128, i2 = 56",
        ),
        (
            "article:unrolled",
            crate::jobs::bundled::ARTICLE_UNROLLED.listing(),
            &[],
            &[(2, 128)],
            "i2 = 128",
        ),
        (
            "article:pass2",
            crate::jobs::bundled::ARTICLE_PASS2.listing(),
            &[("xsize", 11), ("ysize", 8)],
            &[],
            "xsize = 11, ysize = 8",
        ),
        (
            "corrected:loop",
            crate::jobs::bundled::CORRECTED_LOOP.listing(),
            &[],
            &[(1, 128), (2, 56)],
            "i1 = 128, i2 = 56",
        ),
        (
            "corrected:unrolled",
            crate::jobs::bundled::CORRECTED_UNROLLED.listing(),
            &[],
            &[(2, 128)],
            "i2 = 128",
        ),
        (
            "corrected:pass2",
            crate::jobs::bundled::CORRECTED_PASS2.listing(),
            &[("xsize", 11), ("ysize", 8)],
            &[],
            "xsize = 11, ysize = 8",
        ),
        (
            "tonemap",
            crate::jobs::bundled::TONEMAP_REINHARD.listing(),
            &[],
            &[],
            "none",
        ),
    ];
    list.iter()
        .map(|(name, listing, defines, ints, constants)| {
            let (_, a) = verify::analyse_listing(*listing, defines, ints)?;
            Ok(Budget {
                shader: format!("{name} ({})", listing.0),
                constants: constants.to_string(),
                slots: a.slots,
                executed: a.executed.max,
                limits: a.profile.clone(),
            })
        })
        .collect()
}

fn budgets_page(budgets: &[Budget]) -> String {
    let mut s = String::from(
        "# Instruction budgets of the bundled shaders\n\n\
         Generated by `ps30 verify`. ps_3_0 guarantees 512 instruction slots; the article's \
         hardware executes at most 65,535 instructions per pixel. Each shader is measured by ps30's \
         cost model with the constants the article uses (the emulator counts the same executed \
         instructions, see the cross-checks).\n\n\
         ![Bar chart: slots and executed instructions of each shader as a share of the ps_3_0 \
         limits](figures/budgets.png)\n\n\
         *Bars, top to bottom: one pair per row of the table below — slots (blue), then executed \
         instructions per pixel (green) — as a share of the limit. Ticks and grey lines every 25 %, \
         the red line is the limit (100 %); a bar past it would turn red. The axis ends at 125 %.*\n\n\
         | row | shader | constants | slots | share of 512 | executed per pixel | share of 65,535 |\n\
         |---|---|---|---|---|---|---|\n",
    );
    for (i, b) in budgets.iter().enumerate() {
        s.push_str(&format!(
            "| {} | {} | {} | {} | {:.1} % | {} | {:.1} % |\n",
            i + 1,
            b.shader,
            b.constants,
            b.slots,
            100.0 * b.slots as f64 / b.limits.max_slots as f64,
            thousands(b.executed),
            100.0 * b.executed as f64 / b.limits.max_executed as f64
        ));
    }
    s
}

/// Boundaries of blocks of `block` over `size` pixels, in image pixels.
fn edges(size: u32, block: u32) -> Vec<f64> {
    let n = size.div_ceil(block);
    (0..=n).map(|k| (k * block).min(size) as f64).collect()
}

/// The size of a heat map of a `w × h` image: 640 pixels of map, the
/// image's aspect ratio, room for the title, axes and colour bar.
fn heat_map_size(w: u32, h: u32) -> (u32, u32) {
    (
        640 + 150 + 70,
        (640.0 * h as f64 / w as f64).round() as u32 + 90,
    )
}

/// log10(difference / bound), the error heat maps' quantity.
fn log_ratio(b: &luminance::BlockCheck) -> f64 {
    (b.difference / b.tolerance).log10()
}

/// Mean log2(δ + L) over each block's real pixels (padding removed).
fn block_means(image: &HdrImage, run: &LuminanceRun) -> Vec<f64> {
    let (bw, bh) = run.block;
    let padded_term = (run.delta as f64).log2();
    run.blocks
        .iter()
        .map(|b| {
            let rw = ((b.x + 1) * bw).min(image.width) - b.x * bw;
            let rh = ((b.y + 1) * bh).min(image.height) - b.y * bh;
            let real = rw as f64 * rh as f64;
            let padded = bw as f64 * bh as f64 - real;
            (b.emulated - padded * padded_term) / real
        })
        .collect()
}

fn block_figures(
    image: &HdrImage,
    runs: &[(String, String, LuminanceRun)],
) -> Result<(Vec<BlockFigure>, Vec<figures::Canvas>), String> {
    let mut figs = Vec::new();
    let mut canvases = Vec::new();
    let Some((p1, p2, first)) = runs.first() else {
        return Ok((figs, canvases));
    };
    let xe = edges(image.width, first.block.0);
    let ye = edges(image.height, first.block.1);
    let agreeing = |r: &LuminanceRun| r.blocks.iter().filter(|b| b.agree).count();

    let means = block_means(image, first);
    let lo = means.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = means.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let range = ((lo * 10.0).floor() / 10.0, (hi * 10.0).ceil() / 10.0);
    let size = heat_map_size(image.width, image.height);
    let title = format!(
        "Mean log2(δ + L) per {}×{} block ({})",
        first.block.0, first.block.1, p1
    );
    canvases.push(
        HeatMap {
            labels: figures::Labels {
                title: &title,
                x: "x (image pixels)",
                y: "y (image pixels)",
            },
            colorbar: "mean log2(δ + L) over the block",
            values: &means,
            x_edges: &xe,
            y_edges: &ye,
            range,
            marks: &[],
            flagged: &[],
            size,
        }
        .render()?,
    );
    figs.push(BlockFigure {
        file: "blocks-log-luminance.png".into(),
        pass1: p1.clone(),
        pass2: p2.clone(),
        quantity: "mean log2(δ + L) over the block's pixels".into(),
        range,
        blocks: first.blocks.len(),
        blocks_agreeing: agreeing(first),
    });

    // One shared scale for the error maps: whole decades around every value.
    let all: Vec<f64> = runs
        .iter()
        .flat_map(|(_, _, r)| r.blocks.iter().map(log_ratio))
        .filter(|v| v.is_finite())
        .collect();
    let lo = all.iter().copied().fold(0.0, f64::min).floor();
    let hi = all.iter().copied().fold(0.0, f64::max).ceil().max(1.0);
    for (p1, p2, r) in runs {
        let values: Vec<f64> = r
            .blocks
            .iter()
            .map(|b| {
                let v = log_ratio(b);
                // An exact match (difference 0) is the bottom of the scale.
                if v == f64::NEG_INFINITY {
                    lo
                } else {
                    v
                }
            })
            .collect();
        let flagged: Vec<bool> = r.blocks.iter().map(|b| !b.agree).collect();
        let title = format!("Block error against its bound: {p1} + {p2}");
        canvases.push(
            HeatMap {
                labels: figures::Labels {
                    title: &title,
                    x: "x (image pixels)",
                    y: "y (image pixels)",
                },
                colorbar: "log10(|emulated − reference| / bound); 0: the bound",
                values: &values,
                x_edges: &xe,
                y_edges: &ye,
                range: (lo, hi),
                marks: &[0.0],
                flagged: &flagged,
                size,
            }
            .render()?,
        );
        figs.push(BlockFigure {
            file: format!("blocks-error-{}.png", p1.split(':').next().unwrap_or("run")),
            pass1: p1.clone(),
            pass2: p2.clone(),
            quantity: "log10(|emulated − reference| / bound) per block".into(),
            range: (lo, hi),
            blocks: r.blocks.len(),
            blocks_agreeing: agreeing(r),
        });
    }
    Ok((figs, canvases))
}

fn blocks_page(
    image: &HdrImage,
    runs: &[(String, String, LuminanceRun)],
    figs: &[BlockFigure],
) -> String {
    let Some((_, _, first)) = runs.first() else {
        return String::new();
    };
    let (bw, bh) = first.block;
    let mut s = format!(
        "# Pass 1, block by block\n\n\
         Generated by `ps30 verify` from `{img}` ({w}×{h}, the article's frame size): pass 1 \
         with {bw}×{bh} blocks writes a {nx}×{ny} R32F target, one sum of log2|δ + L| per block \
         (δ = {delta}). Each heat map has one cell per block, drawn at half the image's scale so \
         the cells keep the blocks' shape (the last column covers only {last} pixels of the image). \
         Grid lines separate the blocks; the strip under each map is its colour scale, left end to \
         right end as the caption says.\n\n",
        img = verify::CROSSCHECK_IMAGE,
        w = image.width,
        h = image.height,
        nx = first.targets.0,
        ny = first.targets.1,
        delta = first.delta,
        last = image.width - (first.targets.0 - 1) * bw,
    );
    for f in figs {
        if f.file == "blocks-log-luminance.png" {
            s.push_str(&format!(
                "## Log-luminance per block\n\n![Heat map of the mean log2 luminance of each block]\
                 (figures/{})\n\n*The {} and {} run: the emulated block sum with the padded \
                 texels' log2(δ) removed, divided by the block's pixel count — the mean \
                 log2(δ + L) of the block. Colour scale from {:.1} (dark purple, left) to {:.1} \
                 (yellow, right), i.e. a geometric-mean luminance from {} to {}.*\n\n",
                f.file,
                f.pass1,
                f.pass2,
                f.range.0,
                f.range.1,
                number(f.range.0.exp2()),
                number(f.range.1.exp2())
            ));
        }
    }
    s.push_str(
        "## Emulator against reference, per block\n\n\
         Each cell is log10(|emulated − reference| / bound) for one block: the emulated pass-1 sum \
         against the f64 reference's sum over the same texels, as a share of the block's bound \
         derived from the f32 arithmetic (`src/jobs/luminance/mod.rs`). Both maps share one scale; the tick \
         inside the legend marks 0, where the difference equals the bound. Blocks beyond their \
         bound (disagreeing) are also framed in red. A difference of exactly 0 is drawn at the \
         left end.\n\n\
         | map | pass 1 + pass 2 | blocks within their bound | scale (left → right) |\n|---|---|---|---|\n",
    );
    for f in figs.iter().filter(|f| f.file != "blocks-log-luminance.png") {
        s.push_str(&format!(
            "| ![{} per-block error](figures/{}) | {} + {} | {} of {} | {:.0} → {:.0} |\n",
            f.pass1, f.file, f.pass1, f.pass2, f.blocks_agreeing, f.blocks, f.range.0, f.range.1
        ));
    }
    for (p1, _, r) in runs {
        let col0 = r.blocks.iter().filter(|b| b.x == 0);
        let col0_ok = col0.clone().filter(|b| b.agree).count();
        let rest_ok = r.blocks.iter().filter(|b| b.x > 0 && b.agree).count();
        s.push_str(&format!(
            "\n{p1}: {col0_ok} of {} blocks of column 0 and {rest_ok} of {} other blocks are within their bound.",
            col0.count(),
            r.blocks.len() - r.targets.1 as usize
        ));
    }
    s.push_str(
        "\n\nThe article's line-end `mad` sends u back to the frame's left edge, so every block \
         right of column 0 sums column 0's texels from its second line on (finding 1 in \
         [luminance-crosscheck.md](luminance-crosscheck.md)); the corrected pass 1 keeps each \
         block's own start.\n",
    );
    s
}

fn tonemap_row(image: &str, t: &tonemap::ToneMapped, file: &str, size: (u32, u32)) -> TonemapRow {
    let c = &t.check;
    let op = &t.operator;
    TonemapRow {
        image: image.to_string(),
        width: t.width,
        height: t.height,
        log_average: t.luminance.log_average,
        reference_log_average: t.luminance.reference_log_average,
        luminance_agrees: t.luminance.all_agree(),
        key: op.key,
        white: op.white.is_finite().then_some(op.white),
        white_source: op.white_source,
        scale: op.scale(),
        slots: t.cost.slots,
        executed_per_pixel: t
            .cost
            .executed_emulated
            .unwrap_or(t.cost.executed_static)
            .max,
        max_error: c.max_error,
        max_error_bound: c.max_error_bound,
        largest_bound_fraction: c.largest_bound_fraction,
        outside_bound: c.outside_bound,
        mismatched_8bit_channels: c.mismatched_8bit_channels,
        mismatched_8bit_pixels: c.mismatched_8bit_pixels,
        unexplained_8bit: c.unexplained_8bit,
        negative_luminance_pixels: c.negative_luminance_pixels,
        zero_luminance_pixels: c.zero_luminance_pixels,
        sign_ambiguous_pixels: c.sign_ambiguous_pixels,
        clipped_pixels: c.saturated_pixels,
        agree: t.all_agree(),
        preview: format!("figures/{file}"),
        preview_size: size,
    }
}

fn tonemap_page(rows: &[TonemapRow]) -> String {
    let (slots, executed) = rows
        .first()
        .map(|r| (r.slots, r.executed_per_pixel))
        .unwrap_or((0, 0));
    let mut s = format!(
        "# Tone mapping with the article's operator, in ps_3_0\n\n\
         Generated by `ps30 verify`. `{shader}` ({slots} slots, {executed} executed per pixel) runs \
         in ps30's emulator over each bundled image at full size: L = (a / L̄w)·Lw, \
         Ld = L·(1 + L / L_white²) / (1 + L), colour scaled by Ld / Lw, saturated. L̄w comes from \
         the corrected luminance passes (125×128 blocks, R32F) and is sampled by the shader from \
         pass 2's 1×1 target, as in the article's HLSL. The key is a = {key} and the white point \
         the scene's largest luminance, the article's defaults. Pixels whose luminance is not \
         positive are black.\n\n\
         Every pixel is compared with the f64 reference of the operator; each channel must lie \
         within a bound derived from the shader's f32 arithmetic (dp3, mul, mad, Microsoft's rcp \
         precision, _sat; see `src/jobs/tonemap/mod.rs`). The 8-bit sRGB codes are compared too: a code may \
         differ by one only where the bound straddles a rounding boundary, and such channels are \
         counted here, not hidden.\n\n\
         | image | size | L̄w emulated | L̄w f64 reference | white point | a / L̄w | largest difference | its bound | most of a bound used | 8-bit codes off by one (pixels) | negative-luminance pixels | clipped pixels | agrees |\n\
         |---|---|---|---|---|---|---|---|---|---|---|---|---|\n",
        shader = crate::jobs::bundled::TONEMAP_REINHARD.listing().0,
        key = rows.first().map(|r| number(r.key)).unwrap_or_default(),
    );
    for r in rows {
        s.push_str(&format!(
            "| `{}` | {}×{} | {} | {} | {} | {} | {:.1e} | {:.1e} | {:.0} % | {} ({}) | {} | {} | {} |\n",
            r.image,
            r.width,
            r.height,
            number(r.log_average),
            number(r.reference_log_average),
            r.white.map(number).unwrap_or_else(|| "∞".into()),
            number(r.scale),
            r.max_error,
            r.max_error_bound,
            100.0 * r.largest_bound_fraction,
            thousands(r.mismatched_8bit_channels),
            thousands(r.mismatched_8bit_pixels),
            thousands(r.negative_luminance_pixels),
            thousands(r.clipped_pixels),
            if r.agree { "yes" } else { "**NO**" }
        ));
    }
    s.push_str(&format!(
        "\n\"Clipped\" pixels have a channel at or above 1 before saturation: with the white \
         point at the scene's maximum only the brightest pixel reaches Ld = 1, but a saturated \
         colour (a blue sky, an orange wall in sunlight) has a channel above its luminance.\n\n\
         ## Previews\n\n\
         The emulator's linear output, box-filtered in linear light by an integer factor to at \
         most {PREVIEW_WIDTH} pixels wide (every output pixel is the mean of the f×f pixels it \
         covers, f = ⌈width / {PREVIEW_WIDTH}⌉), then encoded with the sRGB transfer function \
         and rounded to 8 bits, as a D3D9 A8R8G8B8 target with D3DRS_SRGBWRITEENABLE would store \
         it. `ps30 tonemap IMG -o OUT.png` writes the full-size image.\n\n"
    ));
    for r in rows {
        s.push_str(&format!(
            "### `{}`\n\n![{} tone-mapped]({})\n\n*{}×{} preview of {}×{}; L̄w = {}, white point {}.*\n\n",
            r.image,
            r.image,
            r.preview,
            r.preview_size.0,
            r.preview_size.1,
            r.width,
            r.height,
            number(r.log_average),
            r.white.map(number).unwrap_or_else(|| "∞".into()),
        ));
    }
    s.push_str(
        "The dark speck in the sun of `city.exr` is in the data: the pixels around the sun's core \
         hold near-zero or slightly negative luminance (lossy DWAB compression ringing next to values \
         of 30,000), which the operator shows black.\n",
    );
    s
}

fn index_page(g: &Generated) -> String {
    let ok = g.tonemap.iter().filter(|r| r.agree).count();
    format!(
        "# Reports\n\n\
         Written by `ps30 verify` (`cargo run --release -- verify`); the same inputs give the same \
         bytes, so regenerating them in a clean checkout changes nothing.\n\n\
         | report | what it shows |\n|---|---|\n\
         | [article-claims.md](article-claims.md) | every figure the article states (cycles, slots, \
         target sizes), recomputed from its listings |\n\
         | [luminance-crosscheck.md](luminance-crosscheck.md) | the article's and the corrected \
         luminance shaders run in the emulator against the f64 reference, and ps30's three \
         findings |\n\
         | [luminance-blocks.md](luminance-blocks.md) | heat maps: per-block log-luminance, and \
         per-block error against the reference for the corrected and the article's pass 1 |\n\
         | [budgets.md](budgets.md) | a chart of every bundled shader's slots and executed \
         instructions against the ps_3_0 limits |\n\
         | [tonemap.md](tonemap.md) | the article's tone-mapping operator as ps_3_0 assembly, run \
         on every bundled image ({ok} of {n} agree with the reference), with previews |\n\n\
         Figures are in [figures/](figures/): {files}.\n\n\
         Written by `ps30 study NAME`, one command each (their figures are in `figures/` too):\n\n\
         | report | what it shows |\n|---|---|\n\
         | [mip-luminance.md](mip-luminance.md) | log-luminance in 8-bit alpha averaged by the mip \
         chain, on every bundled image, against the truth and the article's two passes (`ps30 study \
         mip-luminance`) |\n\
         | [log-lights.md](log-lights.md) | lights as exp2(−light) multiplied into RGBA8, against raw \
         RGBA8 and A16B16G16R16F accumulation (`ps30 study log-lights`) |\n\
         | [article-chain.md](article-chain.md) | the article's chain: lights added into \
         A16B16G16R16F, L̄w, tone map (`ps30 study article-chain`) |\n\n\
         [gpu-crosscheck.md](gpu-crosscheck.md) is not written by `verify`: `ps30 compare --all` \
         writes it on the GPU it finds (the page names the device), every bundled shader on the \
         emulator and on that device. The committed page is an NVIDIA H100's; \
         [gpu-crosscheck-llvmpipe.md](gpu-crosscheck-llvmpipe.md) is the same command's page on \
         Mesa's llvmpipe (`--reports DIR` and a rename), for comparison.\n",
        n = g.tonemap.len(),
        files = g
            .files
            .iter()
            .filter_map(|f| f.strip_prefix("figures/"))
            .map(|f| format!("`{f}`"))
            .collect::<Vec<_>>()
            .join(", ")
    )
}
