//! The article's chain as text, JSON and the report page
//! `reports/article-chain.md` with a preview of the tone-mapped frame.

use super::{table, Page};
use crate::core::numbers::{number, thousands};
use crate::jobs::render::StepDetail;
use crate::jobs::studies::article_chain::ChainRun;
use crate::present::report::figures::{box_downscale, Canvas};
use crate::present::report::PREVIEW_WIDTH;

/// The command that reproduces the page.
pub const COMMAND: &str = "ps30 study article-chain";

fn lights_rows(r: &ChainRun) -> Vec<Vec<String>> {
    r.lights
        .iter()
        .zip(r.steps.iter().filter(|s| s.kind == "draw"))
        .enumerate()
        .map(|(i, (l, s))| {
            let f3 = |v: [f32; 3]| v.map(|c| number(c as f64)).join(", ");
            let cost = match &s.detail {
                StepDetail::Draw {
                    executed,
                    executed_static,
                    counts_agree,
                    ..
                } => format!(
                    "{} ({}{})",
                    // The studies draw on the emulator, which counts.
                    executed.map_or_else(|| "—".into(), |e| e.text()),
                    executed_static.text(),
                    if *counts_agree {
                        ", same"
                    } else {
                        ", DIFFERENT"
                    }
                ),
                _ => String::new(),
            };
            vec![(i + 1).to_string(), f3(l.direction), f3(l.color), cost]
        })
        .collect()
}

const LIGHTS_HEADER: [&str; 4] = [
    "light",
    "L (towards the light)",
    "colour",
    "executed per pixel (cost model)",
];

fn summary(r: &ChainRun) -> String {
    let t = &r.tonemap;
    let lum = &t.luminance;
    let c = &r.sum;
    format!(
        "accumulation: {} channels against the f64 sum of the lights: largest difference {:.2e} (relative {:.1e}), at most {:.0} % of its bound; outside: {}\n\
         lit buffer: luminance {} to {} (× {:.0})\n\
         L̄w by the luminance passes: {} (f64 reference {}, relative error {:.1e} of a {:.1e} bound: {})\n\
         tone map ({}): {} pixels, largest difference {:.1e} (its bound {:.1e}; at most {:.0} % of a bound): {}\n",
        thousands(c.channels),
        c.max_error,
        c.max_relative_error,
        100.0 * c.largest_fraction,
        c.outside,
        number(r.luminance_range.0),
        number(r.luminance_range.1),
        r.luminance_range.1 / r.luminance_range.0,
        number(lum.log_average),
        number(lum.reference_log_average),
        lum.relative_error,
        lum.relative_tolerance,
        if lum.all_agree() { "agree" } else { "DISAGREE" },
        t.cost.shader,
        thousands(t.check.checked_pixels),
        t.check.max_error,
        t.check.max_error_bound,
        100.0 * t.check.largest_bound_fraction,
        if t.check.agree() { "agree" } else { "DISAGREE" },
    )
}

/// What `ps30 study article-chain` prints.
pub fn text(r: &ChainRun, written: Option<&str>) -> String {
    let mut s = format!(
        "the article's chain: a {}×{} G-buffer (light models 0 / 1 / 2: {} / {} / {} pixels), {} lights of asm/lights/directional.psh added into D3DFMT_A16B16G16R16F (ONE, ONE), L̄w, tone map\n",
        r.width,
        r.height,
        thousands(r.models[0]),
        thousands(r.models[1]),
        thousands(r.models[2]),
        r.lights.len()
    );
    s.push_str(&super::text_table(
        &LIGHTS_HEADER,
        &lights_rows(r),
        &[1, 2, 3],
    ));
    s.push_str(&summary(r));
    if let Some(w) = written {
        s.push_str(&format!(
            "wrote {w} ({}×{}, 8-bit sRGB)\n",
            r.width, r.height
        ));
    }
    s
}

/// `--json` of the chain: sizes, lights, steps, sums and the tone-mapping
/// check; `written` is the PNG written, if any.
pub fn json(r: &ChainRun, written: Option<&str>) -> serde_json::Value {
    let t = &r.tonemap;
    serde_json::json!({
        "width": r.width,
        "height": r.height,
        "models": r.models,
        "lights": r.lights,
        "steps": r.steps,
        "accumulation": r.sum,
        "luminance_range": [r.luminance_range.0, r.luminance_range.1],
        "log_average": t.luminance.log_average,
        "reference_log_average": t.luminance.reference_log_average,
        "log_average_relative_error": t.luminance.relative_error,
        "log_average_tolerance": t.luminance.relative_tolerance,
        "tonemap": t.check,
        "output": written,
        "all_agree": r.all_agree(),
    })
}

fn preview(r: &ChainRun) -> Canvas {
    let t = &r.tonemap;
    let (w, h, px) = box_downscale(t.width, t.height, &r.tonemapped, PREVIEW_WIDTH);
    Canvas {
        width: w,
        height: h,
        rgb: crate::jobs::tonemap::to_srgb8(&px),
    }
}

/// The report page `article-chain.md` and its preview.
pub fn page(r: &ChainRun) -> Result<Page, String> {
    let p = preview(r);
    let mut m = format!(
        "# The article's chain, from G-buffer to display\n\n\
         Written by `{COMMAND}` (add `-o frame.png` for the full-size frame); the same inputs give the \
         same bytes.\n\n\
         The article's lighting phase: \"we create a D3DFMT_A16B16G16R16F render target and let every \
         light accumulate into it using standard additive blending\", then \"the HDR destination \
         lighting buffer has to be post-processed via tone-mapping\". ps30 draws it as a draw list: the \
         synthetic {w}×{h} G-buffer of `asm/lights/` (normals and a light-model ID per pixel), \
         {n} lights of `asm/lights/directional.psh` (the article's three light models, the light set \
         per draw) each added with ONE, ONE into a half-float target, RGB written; then L̄w of that \
         buffer by the corrected luminance passes, and the article's tone-mapping operator \
         (`asm/tonemap/reinhard.psh`, key 0.18, white point the buffer's largest luminance) into 8-bit \
         sRGB.\n\n",
        w = r.width,
        h = r.height,
        n = r.lights.len(),
    );
    m.push_str(&table(&LIGHTS_HEADER, &lights_rows(r)));
    m.push_str(&format!(
        "\n![The lit buffer, tone-mapped](figures/article-chain.png)\n\n\
         *The tone-mapped frame, box-filtered to {}×{} in linear light, 8-bit sRGB.*\n\n\
         ## Checks\n\n```text\n{}```\n\n\
         * **Accumulation.** Every channel of every pixel against the f64 sum of the lights' values \
           (each the f32 result of the shader's own operation order), within the rounding of the \
           blend in half floats: the source converted to half, then each sum rounded to half — half \
           the spacing of halves at each value, accumulated along the partial sums \
           (`src/jobs/studies/article_chain.rs`).\n\
         * **L̄w.** The luminance passes' own cross-check against the f64 log-average of the lit \
           buffer (`ps30 luminance`).\n\
         * **Tone map.** Every pixel within the bound derived from the shader's f32 arithmetic \
           (`ps30 tonemap`).\n",
        p.width,
        p.height,
        summary(r)
    ));
    Ok(Page {
        name: "article-chain.md".into(),
        markdown: m,
        figures: vec![("article-chain.png".into(), p)],
    })
}
