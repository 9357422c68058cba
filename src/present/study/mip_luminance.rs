//! The mip-chain log-luminance study as text, JSON and the report page
//! `reports/mip-luminance.md` with its figures.

use super::{percent, table, text_table, Page};
use crate::core::image::{chain_weights, full_chain_levels, OddSides};
use crate::core::numbers::{number, size};
use crate::jobs::studies::mip_luminance::{Frame, MipRun, Study, CROPS, ODD_RANGE, SWEEP_IMAGE};
use crate::present::report::figures::{Canvas, Labels, LineChart, Series};

/// The command that reproduces the page.
pub const COMMAND: &str = "ps30 study mip-luminance";

fn range_text(r: (f64, f64)) -> String {
    format!("[2^−{}, 2^{}]", number(r.0), number(r.1))
}

fn odd_text(o: OddSides) -> &'static str {
    match o {
        OddSides::Fold => "fold",
        OddSides::Bilinear => "bilinear",
    }
}

const HEADER: [&str; 12] = [
    "frame",
    "size",
    "range",
    "odd sides",
    "L̄w (mips)",
    "L̄w (truth)",
    "error",
    "clamped",
    "error from clamping",
    "from odd sides",
    "8-bit drift (codes)",
    "bound (codes)",
];

fn row(f: &Frame, r: &MipRun) -> Vec<String> {
    vec![
        f.image.clone(),
        size(r.width, r.height),
        range_text(r.range),
        odd_text(r.odd).into(),
        number(r.log_average),
        number(r.reference),
        percent(r.relative_error),
        format!("{} / {}", r.below, r.above),
        percent(r.ideal_uniform / r.reference - 1.0),
        percent(r.ideal_weighted / r.ideal_uniform - 1.0),
        format!("{:+.2}", r.quantisation_codes),
        format!(
            "{:.2}{}",
            r.quantisation_bound_codes,
            if r.within_bound { "" } else { " EXCEEDED" }
        ),
    ]
}

fn rows(s: &Study) -> Vec<Vec<String>> {
    s.frames
        .iter()
        .flat_map(|f| f.runs.iter().chain(&f.bilinear).map(move |r| row(f, r)))
        .collect()
}

fn article_rows(s: &Study) -> Vec<Vec<String>> {
    s.frames
        .iter()
        .map(|f| {
            vec![
                f.image.clone(),
                size(f.width, f.height),
                number(f.article.log_average),
                number(f.article.reference),
                format!("{:+.1e}", f.article.relative_error),
                if f.article.agree { "yes" } else { "NO" }.into(),
            ]
        })
        .collect()
}

const ARTICLE_HEADER: [&str; 6] = [
    "frame",
    "size",
    "L̄w (two passes)",
    "L̄w (truth)",
    "error",
    "agrees",
];

/// The spread of the folded method's error with the default range over the
/// bundled frames (no crops), and of the article's.
fn spread(s: &Study) -> ((f64, f64), (f64, f64), (f64, f64)) {
    let mut m = (f64::INFINITY, f64::NEG_INFINITY);
    let mut a = m;
    let mut q = m;
    for f in s.frames.iter().filter(|f| !f.image.contains("cropped")) {
        for r in f.runs.iter().filter(|r| r.range == ODD_RANGE) {
            m = (m.0.min(r.relative_error), m.1.max(r.relative_error));
        }
        a = (
            a.0.min(f.article.relative_error.abs()),
            a.1.max(f.article.relative_error.abs()),
        );
    }
    for r in s
        .frames
        .iter()
        .flat_map(|f| f.runs.iter().chain(&f.bilinear))
        .chain(&s.sweep)
    {
        q = (q.0.min(r.quantisation_codes), q.1.max(r.quantisation_codes));
    }
    (m, a, q)
}

/// What `ps30 study mip-luminance` prints.
pub fn text(s: &Study) -> String {
    let ((m0, m1), (a0, a1), (q0, q1)) = spread(s);
    let mut t = format!(
        "log-luminance in 8-bit alpha, averaged by the mip chain (asm/mip-luminance/encode.psh, D3DFMT_A8R8G8B8, δ = {}), against the truth and the article's two passes\n\n",
        s.delta
    );
    t.push_str(&text_table(&HEADER, &rows(s), &[0, 1, 2, 3]));
    t.push_str("\nthe article's two passes (corrected shaders, 125×128 blocks, R32F) on the same frames:\n");
    t.push_str(&text_table(&ARTICLE_HEADER, &article_rows(s), &[0, 1, 5]));
    t.push_str(&format!(
        "\nwith {}: the mips are off by {} to {} on the bundled frames; the article's passes by {:.1e} to {:.1e}\n\
         8-bit drift: {:+.2} to {:+.2} codes{}; the derived bound is met everywhere: {}\n",
        range_text(ODD_RANGE),
        percent(m0),
        percent(m1),
        a0,
        a1,
        q0,
        q1,
        if q0 > 0.0 { ", always upwards (halves round up at every level)" } else { "" },
        if s.all_agree() { "yes" } else { "NO" }
    ));
    t
}

/// `--json` of the study: every frame and the range sweep.
pub fn json(s: &Study) -> serde_json::Value {
    serde_json::json!({
        "delta": s.delta,
        "frames": s.frames,
        "sweep": s.sweep,
        "all_agree": s.all_agree(),
    })
}

/// |relative error| against the range's half-width on the sweep image,
/// with the article's error as a dashed line.
fn ranges_figure(s: &Study) -> Result<Canvas, String> {
    let mips = Series {
        name: "mip chain, 8-bit alpha (the method)".into(),
        points: s
            .sweep
            .iter()
            .map(|r| (r.range.0, r.relative_error.abs()))
            .collect(),
        color: [62, 73, 137],
    };
    let weights_only = Series {
        name: "the chain's weights alone (f64)".into(),
        points: s
            .sweep
            .iter()
            .map(|r| (r.range.0, (r.ideal_weighted / r.reference - 1.0).abs()))
            .collect(),
        color: [53, 183, 121],
    };
    let article = s
        .frames
        .iter()
        .find(|f| f.image == SWEEP_IMAGE)
        .map_or(1e-5, |f| f.article.relative_error.abs());
    let series = [mips, weights_only];
    LineChart {
        labels: Labels {
            title: "Mip-chain L̄w against the encoded range (1280×1024 image)",
            x: "half-width of the log2 range (stops)",
            y: "|relative error of L̄w|",
        },
        series: &series,
        x_range: (0.0, 32.0),
        y_range: (1e-5, 10.0),
        log_y: true,
        hlines: &[(article, [214, 39, 40], "the article's two passes")],
        legend: plotters::chart::SeriesLabelPosition::UpperLeft,
        size: (760, 420),
    }
    .render()
}

/// Per-column weight × width of three chains.
fn weights_figure() -> Result<(Canvas, f64), String> {
    let curve = |w: u32, h: u32, odd: OddSides, color: [u8; 3]| {
        let levels = full_chain_levels(w, h);
        let wx = chain_weights(w, levels, odd);
        Series {
            name: format!(
                "{w}×{h}, {} odd sides",
                match odd {
                    OddSides::Fold => "folded",
                    OddSides::Bilinear => "bilinear",
                }
            ),
            points: wx
                .iter()
                .enumerate()
                .map(|(i, &v)| ((i as f64 + 0.5) / w as f64, v * w as f64))
                .collect(),
            color,
        }
    };
    let series = [
        curve(1280, 1024, OddSides::Fold, [62, 73, 137]),
        curve(1280, 1024, OddSides::Bilinear, [53, 183, 121]),
        curve(CROPS[0].0, CROPS[0].1, OddSides::Bilinear, [214, 39, 40]),
    ];
    let top = series
        .iter()
        .flat_map(|s| s.points.iter().map(|p| p.1))
        .fold(0.0, f64::max);
    let y_top = 10f64.powf(top.log10().ceil()).max(10.0);
    let c = LineChart {
        labels: Labels {
            title: "Column weights of three mip chains",
            x: "column, as a fraction of the width",
            y: "weight × width (1: every column alike)",
        },
        series: &series,
        x_range: (0.0, 1.0),
        y_range: (1e-2, y_top),
        log_y: true,
        hlines: &[(1.0, [0, 0, 0], "uniform weight")],
        legend: plotters::chart::SeriesLabelPosition::LowerMiddle,
        size: (760, 380),
    }
    .render()?;
    Ok((c, y_top))
}

/// The odd side lengths (above 1) a `w × h` chain passes through, largest first.
fn odd_sides(w: u32, h: u32) -> Vec<u32> {
    let mut out: Vec<u32> = (0..full_chain_levels(w, h))
        .flat_map(|i| [(w >> i).max(1), (h >> i).max(1)])
        .filter(|&v| v > 1 && v % 2 == 1)
        .collect();
    out.sort_unstable_by(|a, b| b.cmp(a));
    out.dedup();
    out
}

/// The report page `mip-luminance.md` and its figures.
pub fn page(s: &Study) -> Result<Page, String> {
    let ((m0, m1), (a0, a1), (q0, q1)) = spread(s);
    let (weights, y_top) = weights_figure()?;
    let odd = s.frames.iter().find(|f| f.image == SWEEP_IMAGE);
    let odd_effect = odd
        .and_then(|f| f.runs.iter().find(|r| r.range == ODD_RANGE))
        .map_or(0.0, |r| r.ideal_weighted / r.ideal_uniform - 1.0);
    let crop = s
        .frames
        .iter()
        .find(|f| f.image.contains("cropped") && f.width == CROPS[0].0);
    let crop_fold = crop
        .and_then(|f| f.runs.iter().find(|r| r.range == ODD_RANGE))
        .map_or(0.0, |r| r.relative_error);
    let crop_bilinear = crop
        .and_then(|f| f.bilinear.as_ref())
        .map_or(0.0, |r| r.relative_error);
    // Per uncropped frame: |mip error| / |article error| with the default range.
    let ratios = s
        .frames
        .iter()
        .filter(|f| !f.image.contains("cropped"))
        .filter_map(|f| {
            let r = f.runs.iter().find(|r| r.range == ODD_RANGE)?;
            Some(r.relative_error.abs() / f.article.relative_error.abs())
        })
        .fold((f64::INFINITY, 0f64), |(lo, hi), v| (lo.min(v), hi.max(v)));
    let narrow = s
        .frames
        .iter()
        .filter_map(|f| f.runs.first())
        .map(|r| r.relative_error)
        .fold(0.0, f64::max);
    let mut m = format!(
        "# Log-luminance in 8-bit alpha, averaged by the mip chain\n\n\
         Written by `{COMMAND}`; the same inputs give the same bytes.\n\n\
         A 2008 blog post proposes getting a frame's average log-luminance without a float buffer: \
         every pixel writes its log-luminance, encoded as `log2 L · invLogLumRange + logLumOffset` \
         for luminances in [2^−minLogLum, 2^maxLogLum], into the 8-bit destination alpha; generating \
         the mip chain averages it \"down to a 1×1 render target\"; the CPU inverts the encoding. \
         ps30 runs that as a draw list — `asm/mip-luminance/encode.psh` into a `D3DFMT_A8R8G8B8` target \
         with COLORWRITEENABLE = alpha, then the chain, every level in 8 bits — on every bundled image \
         and on two crops of the article-sized one whose chains have odd sides, and compares it with \
         the true L̄w (f64, δ = {delta}, every pixel once) and with the article's two passes.\n\n\
         ## In numbers\n\n\
         * **Against the article.** With {range} the mips are off by {m0} to {m1} on the bundled frames; \
           the article's two passes by {a0:.1e} to {a1:.1e}: {r0:.0} to {r1:.0} times closer, frame by \
           frame.\n\
         * **8-bit steps.** One code is (min + max)/255 stops: 16/255 = 0.063 stops = 4.4 % of L̄w for \
           {range}. The quantisation bound is (n + 1) half-codes for n levels after the base \
           (derivation in `src/jobs/studies/mip_luminance.rs`): 5.5 codes for an 11-level chain. \
           Measured: {q0:+.2} to {q1:+.2} codes{drift}.\n  \
           A wider range holds more of the scene but makes each code coarser; a narrower one clamps: \
           with [2^−4, 2^4] the error reaches {narrow}.\n\
         * **Odd sides.** 1280 = 5 · 256: the chain of the article's frame ends 5 → 2 → 1, and the \
           3-wide box at the edge gives each of the last three fifths of the columns ⅙ of the weight \
           and each of the first two fifths ¼. On `{SWEEP_IMAGE}` that alone moves L̄w by {odd_effect}. Cropped to \
           {cw}×{ch} (odd sides at {odd_sides}), the folded chain is off by {crop_fold}, \
           and a chain made by bilinear half-size draws — what D3DTEXF_LINEAR, the default \
           automatic-generation filter, does if a driver draws each level — by {crop_bilinear}: its \
           weights skip whole columns and rows.\n\n\
         ![Relative error of L̄w against the range's half-width](figures/mip-luminance-ranges.png)\n\n\
         *`{SWEEP_IMAGE}`, ranges [2^−h, 2^h] for h on the x axis (0 to 32 stops, ticks every 4). \
         |relative error of L̄w|, log scale from 10⁻⁵ to 10 (ticks every decade). Blue: the mip \
         method; green: the f64 weighted mean alone (clamping and odd sides, no 8-bit steps); dashed \
         red: the article's two passes on the same image.*\n\n\
         ![Column weights of three mip chains](figures/mip-luminance-weights.png)\n\n\
         *Weight of each column in the 1×1 result, times the width (1 = a fair share; the black \
         dashed line), against the column's position across the frame (0 to 1, ticks every 0.2); log \
         scale from 0.01 to {y_top} (ticks at 0.1, 1, 10), columns of weight 0 drawn at the bottom. \
         Blue: 1280 columns, folded odd sides; green: 1280 columns, bilinear; red: {cw} columns, \
         bilinear.*\n\n\
         ## Every run\n\n",
        delta = s.delta,
        range = range_text(ODD_RANGE),
        m0 = percent(m0),
        m1 = percent(m1),
        narrow = percent(narrow),
        drift = if q0 > 0.0 {
            ", always upwards — the FLOAT → UNORM rule rounds halves up, and a 2 × 2 average of \
             codes ends in .5 a quarter of the time, so every level drifts up; it does not average \
             out"
        } else {
            ""
        },
        r0 = ratios.0,
        r1 = ratios.1,
        odd_effect = percent(odd_effect),
        cw = CROPS[0].0,
        ch = CROPS[0].1,
        crop_fold = percent(crop_fold),
        odd_sides = odd_sides(CROPS[0].0, CROPS[0].1)
            .iter()
            .map(|v| v.to_string())
            .collect::<Vec<_>>()
            .join(", "),
        crop_bilinear = percent(crop_bilinear),
    );
    m.push_str(&table(&HEADER, &rows(s)));
    m.push_str(
        "\n*error: of L̄w against the truth. clamped: pixels below / above the range. error from \
         clamping: the f64 mean of the clamped encodings, every pixel weighted 1/N, against the \
         truth. from odd sides: the f64 mean with the chain's weights against that. 8-bit drift: the \
         emulated 1×1 alpha minus the weighted f64 mean, in codes (1/255); bound: the derived \
         bound on it.*\n\n## The article's two passes on the same frames\n\n",
    );
    m.push_str(&table(&ARTICLE_HEADER, &article_rows(s)));
    m.push_str("\n## The range sweep\n\n");
    let sweep_rows: Vec<Vec<String>> = s
        .sweep
        .iter()
        .map(|r| {
            vec![
                range_text(r.range),
                percent(r.relative_error),
                format!("{} / {}", r.below, r.above),
                format!("{:+.2}", r.quantisation_codes),
                format!("{:.1} %", 100.0 * r.relative_bound),
            ]
        })
        .collect();
    m.push_str(&table(
        &[
            "range",
            "error",
            "clamped",
            "8-bit drift (codes)",
            "bound on the 8-bit part",
        ],
        &sweep_rows,
    ));
    Ok(Page {
        name: "mip-luminance.md".into(),
        markdown: m,
        figures: vec![
            ("mip-luminance-ranges.png".into(), ranges_figure(s)?),
            ("mip-luminance-weights.png".into(), weights),
        ],
    })
}
