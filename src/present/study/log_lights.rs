//! The log-lights study as text, JSON and the report page
//! `reports/log-lights.md` with its figure of error against light.

use super::{table, text_table, Page};
use crate::core::numbers::number;
use crate::jobs::studies::log_lights::{Method, Study, Summary, DIM, SWEEP_BRIGHTNESS, WIDTH};
use crate::present::report::figures::{Labels, LineChart, Series};

/// The command that reproduces the page.
pub const COMMAND: &str = "ps30 study log-lights";

/// Bins of the true light in the figure.
const BINS: usize = 100;

const COLORS: [[u8; 3]; 3] = [[214, 39, 40], [62, 73, 137], [53, 183, 121]];

fn color(m: Method) -> [u8; 3] {
    COLORS[Method::ALL.iter().position(|&x| x == m).unwrap_or(0)]
}

fn err(v: f64) -> String {
    if v >= 1e30 {
        "FLT_MAX".into()
    } else {
        format!("{v:.5}")
    }
}

fn row(s: &Summary, first: String) -> Vec<String> {
    vec![
        first,
        s.method.name().to_string(),
        number(s.peak),
        err(s.max_error),
        format!("{:.5}", s.rms_error),
        format!("{:.5}", s.max_error_dim),
        s.levels_dim.to_string(),
        format!("{} of {}", s.within_bound, s.in_range),
        s.range_ends_at.map_or("—".into(), number),
    ]
}

const HEADER: [&str; 9] = [
    "",
    "method",
    "peak",
    "max error",
    "rms error",
    "max error ≤ 0.1",
    "levels ≤ 0.1",
    "within bound",
    "out of range from",
];

/// The headline numbers: range and dim-light error of each method.
struct Headline {
    raw_range: Option<f64>,
    log_range: Option<f64>,
    half_range: Option<f64>,
    dim_raw: f64,
    dim_log: f64,
    levels_raw: usize,
    levels_log: usize,
}

fn headline(s: &Study) -> Headline {
    let sweep = |m: Method| s.sweep.iter().find(|a| a.method == m).map(|a| a.summary());
    let dim = |m: Method| {
        s.brightness
            .iter()
            .find(|x| x.method == m && x.brightness == 0.1)
            .map_or((0.0, 0), |x| (x.max_error_dim, x.levels_dim))
    };
    Headline {
        raw_range: sweep(Method::Rgba8).and_then(|x| x.range_ends_at),
        log_range: sweep(Method::LogRgba8).and_then(|x| x.range_ends_at),
        half_range: sweep(Method::Half).and_then(|x| x.range_ends_at),
        dim_raw: dim(Method::Rgba8).0,
        dim_log: dim(Method::LogRgba8).0,
        levels_raw: dim(Method::Rgba8).1,
        levels_log: dim(Method::LogRgba8).1,
    }
}

fn tables(s: &Study) -> (Vec<Vec<String>>, Vec<Vec<String>>) {
    let brightness = s
        .brightness
        .iter()
        .map(|x| row(x, format!("b = {}", number(x.brightness as f64))))
        .collect();
    let overlaps = s
        .overlaps
        .iter()
        .map(|x| row(x, format!("K = {}", x.lights)))
        .collect();
    (brightness, overlaps)
}

fn headline_text(h: &Headline) -> String {
    let range = |r: Option<f64>| {
        r.map_or(format!("beyond {}", number(SWEEP_BRIGHTNESS as f64)), |v| {
            format!("{:.2}", v)
        })
    };
    format!(
        "range (one light swept to {}): raw RGBA8 is right up to {}, log lights up to {}, A16B16G16R16F {}\n\
         dim lights (≤ {}): largest error {:.5} with log lights against {:.5} raw (× {:.2}); {} distinct levels against {}\n",
        number(SWEEP_BRIGHTNESS as f64),
        range(h.raw_range),
        range(h.log_range),
        range(h.half_range),
        DIM,
        h.dim_log,
        h.dim_raw,
        h.dim_log / h.dim_raw,
        h.levels_log,
        h.levels_raw
    )
}

/// What `ps30 study log-lights` prints.
pub fn text(s: &Study) -> String {
    let (b, o) = tables(s);
    let mut t = format!(
        "log lights against raw RGBA8 and A16B16G16R16F: each light a ramp b·(x + ½)/{WIDTH} over {WIDTH} pixels, K lights overlapping\n\n\
         one light of each brightness of the article's figure 3:\n"
    );
    t.push_str(&text_table(&HEADER, &b, &[0, 1]));
    t.push_str("\nK overlapping lights of brightness 1:\n");
    t.push_str(&text_table(&HEADER, &o, &[0, 1]));
    t.push('\n');
    t.push_str(&headline_text(&headline(s)));
    t.push_str(&format!(
        "every pixel in range within its derived bound: {}\n",
        if s.all_agree() { "yes" } else { "NO" }
    ));
    t
}

/// `--json` of the study: every summary, with the headline numbers.
pub fn json(s: &Study) -> serde_json::Value {
    let h = headline(s);
    serde_json::json!({
        "width": s.width,
        "brightness": s.brightness,
        "overlaps": s.overlaps,
        "sweep": s.sweep.iter().map(|a| a.summary()).collect::<Vec<_>>(),
        "range": {"raw": h.raw_range, "log": h.log_range, "half": h.half_range},
        "dim": {"raw": h.dim_raw, "log": h.dim_log, "levels_raw": h.levels_raw, "levels_log": h.levels_log},
        "all_agree": s.all_agree(),
    })
}

/// The figure: the largest |error| in each of [`BINS`] equal bins of the
/// true light, for one light swept to [`SWEEP_BRIGHTNESS`], log y from 10⁻⁶
/// to 10.
fn figure(s: &Study) -> Result<crate::present::report::figures::Canvas, String> {
    let width = SWEEP_BRIGHTNESS as f64 / BINS as f64;
    let series: Vec<Series> = s
        .sweep
        .iter()
        .map(|a| {
            let mut worst = vec![f64::NAN; BINS];
            for (&t, &r) in a.truth.iter().zip(&a.recovered) {
                let bin = ((t / width) as usize).min(BINS - 1);
                let e = (r - t).abs().max(1e-7);
                worst[bin] = if worst[bin].is_nan() {
                    e
                } else {
                    worst[bin].max(e)
                };
            }
            Series {
                name: a.method.name().to_string(),
                points: worst
                    .iter()
                    .enumerate()
                    .map(|(i, &e)| ((i as f64 + 0.5) * width, e))
                    .collect(),
                color: color(a.method),
            }
        })
        .collect();
    LineChart {
        labels: Labels {
            title: "Largest error of one light, by its true brightness",
            x: "true light (linear units)",
            y: "largest |recovered − true|",
        },
        series: &series,
        x_range: (0.0, SWEEP_BRIGHTNESS as f64),
        y_range: (1e-6, 10.0),
        log_y: true,
        hlines: &[],
        legend: plotters::chart::SeriesLabelPosition::MiddleRight,
        size: (760, 420),
    }
    .render()
}

/// The report page `log-lights.md` and its figure.
pub fn page(s: &Study) -> Result<Page, String> {
    let (b, o) = tables(s);
    let h = headline(s);
    let mut m = format!(
        "# Log lights against raw RGBA8 and half-float accumulation\n\n\
         Written by `{COMMAND}`; the same inputs give the same bytes.\n\n\
         \"Prelighting & Log-Lights (Ver. 2)\" (Josh Ols, 2009) accumulates a light pre-pass's lights \
         into an RGBA8 buffer as exp2(−light) with multiplicative blending (cleared to white, \
         `Blend(DST_COLOR, ZERO, DST_ALPHA, ZERO)`) and recovers them as −log2(value), against raw RGBA8 \
         accumulation that \"will soon saturate at 1.0\". It claims more range (\"only really providing \
         MDR\") and \"slightly worse artifacts on dim lights\". ps30 runs the three ways as draw lists \
         (`asm/log-lights/`, the output merger in the target's precision) and compares what comes back \
         with the true light.\n\n\
         Each light is a ramp across a {WIDTH}-pixel target, light(x) = b·(x + ½)/{WIDTH}, so one draw \
         holds every intensity from 0 to b; K lights overlap completely. Every pixel is checked against \
         a bound derived from the method's arithmetic (the module docs of \
         `src/jobs/studies/log_lights.rs`); pixels past a method's range — raw RGBA8 above 1, a log \
         buffer whose product falls to one code (1/255) or less — are counted as out of range instead.\n\n\
         ## In numbers\n\n\
         * **Range.** Raw RGBA8 is right up to {raw}; log lights up to {log} — log2(255) ≈ 7.99 is the \
           last light a code (1) can hold; A16B16G16R16F beyond the {sweep} swept (its largest finite \
           value is 65,504).\n\
         * **Dim lights.** Below {dim}, the largest error is {dl:.5} with log lights against {dr:.5} \
           raw, {ratio:.2} times as large: the 8-bit step of exp2(−x) near x = 0 is 1/(255·ln 2) in \
           light against 1/255 raw. The ramp from 0 to 0.1 comes back in {ll} distinct levels instead \
           of {lr} — coarser banding.\n\
         * **Bright and overlapping lights.** Each multiplicative blend quantises the product again, \
           and a code near 0 stands for a wide interval of light: with 8 lights of brightness 1 the log \
           buffer's error reaches {k8} near the top of its range, where A16B16G16R16F is within {h8}.\n\n\
         ![Error against the true light, one light swept to {sweep}](figures/log-lights-error.png)\n\n\
         *The largest |recovered − true| in each hundredth of the true light (x from 0 to {sweep}, \
         ticks every 1), log scale from 10⁻⁶ to 10 (ticks every decade). Red: raw RGBA8 (half a code \
         until it saturates at 1, then the missing light); blue: log lights (growing with the light, \
         leaving the chart past its range, where the buffer holds 0 and FLT_MAX comes back); green: \
         A16B16G16R16F (half an ulp of a half float; none at all where the ramp's values are \
         halves). Errors below 10⁻⁶ are drawn at the bottom.*\n\n\
         ## One light, the article's brightness values\n\n",
        raw = h.raw_range.map_or("—".into(), |v| format!("{v:.2}")),
        log = h.log_range.map_or("—".into(), |v| format!("{v:.2}")),
        sweep = number(SWEEP_BRIGHTNESS as f64),
        dim = DIM,
        dl = h.dim_log,
        dr = h.dim_raw,
        ratio = h.dim_log / h.dim_raw,
        ll = h.levels_log,
        lr = h.levels_raw,
        k8 = s
            .overlaps
            .iter()
            .find(|x| x.method == Method::LogRgba8 && x.lights == 8)
            .map_or("—".into(), |x| format!("{:.3}", x.max_error)),
        h8 = s
            .overlaps
            .iter()
            .find(|x| x.method == Method::Half && x.lights == 8)
            .map_or("—".into(), |x| format!("{:.4}", x.max_error)),
    );
    m.push_str(&table(&HEADER, &b));
    m.push_str("\n## K overlapping lights of brightness 1\n\n");
    m.push_str(&table(&HEADER, &o));
    m.push_str(
        "\n*peak: the largest true light on the ramp. max error: over the whole ramp, including \
         pixels out of range (FLT_MAX where the log buffer reached 0). levels ≤ 0.1: distinct \
         recovered values where the true light is at most 0.1. within bound: pixels in range \
         within their derived bound, of those in range. out of range from: the smallest true \
         light past the method's range.*\n",
    );
    Ok(Page {
        name: "log-lights.md".into(),
        markdown: m,
        figures: vec![("log-lights-error.png".into(), figure(s)?)],
    })
}
