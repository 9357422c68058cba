//! What `ps30 luminance` and `ps30 run` print: the passes' costs, the
//! cross-check and its findings, as text and JSON.

use crate::core::emu::findings::Finding;
use crate::core::image::RenderTarget;
use crate::core::numbers::{range_json, range_text, thousands};
use crate::jobs::luminance::{BlockCheck, LuminanceRun, PassCost, PassOutput};

/// The JSON form of a run (`ps30 luminance --json`).
pub fn run_json(image: &str, r: &LuminanceRun) -> serde_json::Value {
    serde_json::json!({
        "image": image,
        "width": r.width,
        "height": r.height,
        "drawn_by": r.drawn_by,
        "log_average": r.log_average,
        "reference_log_average": r.reference_log_average,
        "relative_error": r.relative_error,
        "relative_tolerance": r.relative_tolerance,
        "agree": r.all_agree(),
        "finite": r.finite(),
        "log_average_agrees": r.agree,
        "blocks_agree": r.blocks_agree(),
        "target_format": r.target_format.d3d_name(),
        "delta": r.delta,
        "block": [r.block.0, r.block.1],
        "targets": [r.targets.0, r.targets.1],
        "padded_samples": r.padded_samples,
        "padding_factor": r.padding_factor,
        "executed_per_pixel": {
            "pass1": r.pass1.executed_emulated.map(range_json),
            "pass1_last": r.pass1_last.as_ref().and_then(|p| p.executed_emulated.map(range_json)),
            "pass2": r.pass2.executed_emulated.map(range_json),
        },
        "passes": [&r.pass1, &r.pass2],
        "pass1_last": &r.pass1_last,
        "pass2_check": &r.pass2_check,
        "ill_conditioned_pixels": r.ill_conditioned,
        "negative_pixels": r.negative_pixels,
        "nonfinite_pixels": r.nonfinite_pixels,
        "blocks": &r.blocks,
    })
}

/// `emulator counted 64,774, same`, or what a GPU run says instead.
pub fn counted_text(p: &PassCost) -> String {
    match p.executed_emulated {
        Some(r) => format!(
            "emulator counted {}{}",
            range_text(r),
            if p.counts_agree {
                ", same"
            } else {
                ", DIFFERENT"
            }
        ),
        None => "not counted: drawn on the GPU".into(),
    }
}

fn pass_line(label: &str, p: &PassCost) -> String {
    let mut s = format!(
        "{label} {}: {} slots, {} executed per pixel ({})\n",
        p.shader,
        p.slots,
        range_text(p.executed_static),
        counted_text(p)
    );
    s.push_str(&findings_text(&p.shader, &p.findings));
    s
}

/// One `  warning: file:line:col: …` line per finding.
fn findings_text(shader: &str, findings: &[Finding]) -> String {
    findings
        .iter()
        .map(|f| {
            format!(
                "  warning: {shader}:{}:{}: {} ({})\n",
                f.site.line, f.site.column, f.message, f.label
            )
        })
        .collect()
}

/// The text form of a run (`ps30 luminance`).
pub fn run_text(image: &str, r: &LuminanceRun) -> String {
    let mut s = format!(
        "{image}: {}×{}, blocks {}×{} → {}×{} target ({}), δ = {}\n",
        r.width,
        r.height,
        r.block.0,
        r.block.1,
        r.targets.0,
        r.targets.1,
        r.target_format.d3d_name(),
        r.delta
    );
    if r.drawn_by != "emulator" {
        s.push_str(&format!("drawn on the {}\n", r.drawn_by));
    }
    s.push_str(&pass_line("pass 1", &r.pass1));
    if let Some(p) = &r.pass1_last {
        s.push_str(&pass_line("pass 1 (last column)", p));
    }
    s.push_str(&pass_line("pass 2", &r.pass2));
    let agreeing = r.blocks.iter().filter(|b| b.agree).count();
    let worst = r
        .blocks
        .iter()
        .max_by(|a, b| (a.difference / a.tolerance).total_cmp(&(b.difference / b.tolerance)));
    s.push_str(&format!(
        "blocks: {agreeing} of {} agree with the f64 reference",
        r.blocks.len()
    ));
    if let Some(w) = worst {
        s.push_str(&format!(
            " (largest difference/tolerance: {:.3} at block {},{}: {:.4} vs {:.4}, tolerance {:.3})",
            w.difference / w.tolerance,
            w.x,
            w.y,
            w.emulated,
            w.reference,
            w.tolerance
        ));
    }
    s.push('\n');
    let bad: Vec<&BlockCheck> = r.blocks.iter().filter(|b| !b.agree).collect();
    if r.nonfinite_pixels > 0 {
        s.push_str(&format!(
            "{} pixels are NaN or infinite: their blocks and L̄w are not finite, on a GPU as in the reference\n",
            r.nonfinite_pixels
        ));
    }
    let overflowed = r.blocks.iter().filter(|b| b.overflow).count();
    if overflowed > 0 {
        s.push_str(&format!(
            "{overflowed} block sums overflow {} (beyond ±65,504): the target cannot hold them\n",
            r.target_format.d3d_name()
        ));
    }
    if !bad.is_empty() {
        s.push_str("disagreeing blocks (column, row: emulated vs reference, difference):\n");
        for b in bad.iter().take(12) {
            s.push_str(&format!(
                "  {:>3},{:<3} {:>14.3} vs {:>14.3}  {:>12.3}\n",
                b.x, b.y, b.emulated, b.reference, b.difference
            ));
        }
        if bad.len() > 12 {
            s.push_str(&format!("  … and {} more\n", bad.len() - 12));
        }
        let cols: std::collections::BTreeSet<u32> = bad.iter().map(|b| b.x).collect();
        if !cols.contains(&0) {
            s.push_str(
                "  every block of column 0 agrees: the error grows with the block's u offset\n",
            );
        }
    }
    s.push_str(&format!(
        "pass 2: L̄w {:.7} vs {:.7} from the stored pass-1 target ({})\n",
        r.pass2_check.emulated,
        r.pass2_check.reference,
        if r.pass2_check.agree {
            "agree"
        } else {
            "DISAGREE"
        }
    ));
    if !r.finite() {
        s.push_str(&format!(
            "L̄w: emulated {}, reference {}: not a usable luminance ({})\n",
            r.log_average,
            r.reference_log_average,
            if r.agree {
                "the emulator matches the reference"
            } else {
                "and they DISAGREE"
            }
        ));
        return s;
    }
    s.push_str(&format!(
        "L̄w: {} {:.7}, reference {:.7} (every pixel once), relative error {:.2e}, tolerance {:.2e}: {}\n",
        if r.drawn_by == "emulator" {
            "emulated"
        } else {
            "GPU"
        },
        r.log_average,
        r.reference_log_average,
        r.relative_error,
        r.relative_tolerance,
        if r.agree { "agree" } else { "DISAGREE" }
    ));
    if r.padded_samples > 0 {
        s.push_str(&format!(
            "padding: {} samples read outside the image; left uncorrected they scale L̄w by {:.4}\n",
            thousands(r.padded_samples),
            r.padding_factor
        ));
    }
    if r.ill_conditioned > 0 {
        s.push_str(&format!(
            "note: {} pixels have δ + L so close to 0 that f32 cannot bound their term\n",
            r.ill_conditioned
        ));
    }
    s
}

/// Summary statistics of oC0's red channel over a target.
fn red_stats(t: &RenderTarget) -> (f64, f64, f64) {
    let reds: Vec<f64> = t.texels.iter().map(|v| v[0] as f64).collect();
    let min = reds.iter().copied().fold(f64::INFINITY, f64::min);
    let max = reds.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let mean = reds.iter().sum::<f64>() / reds.len().max(1) as f64;
    (min, max, mean)
}

/// The text form of `ps30 run`.
pub fn pass_text(
    shader: &str,
    image: &str,
    out: &PassOutput,
    written: Option<&std::path::Path>,
) -> String {
    let t = &out.target;
    let (min, max, mean) = red_stats(t);
    let mut s = format!(
        "{shader} over {image} → {}×{} target ({})\n",
        t.width,
        t.height,
        t.format.d3d_name()
    );
    if out.drawn_by != "emulator" {
        s.push_str(&format!("drawn on the {}\n", out.drawn_by));
    }
    s.push_str(&match out.cost.executed_emulated {
        Some(e) => format!(
            "slots {}, executed per pixel {} (cost model: {}{})\n",
            out.cost.slots,
            range_text(e),
            range_text(out.cost.executed_static),
            if out.cost.counts_agree {
                ", same"
            } else {
                ", DIFFERENT"
            }
        ),
        None => format!(
            "slots {}, executed per pixel {} (cost model; not counted: drawn on the GPU)\n",
            out.cost.slots,
            range_text(out.cost.executed_static)
        ),
    });
    s.push_str(&findings_text(&out.cost.shader, &out.cost.findings));
    if !out.cost.within_limits {
        s.push_str("the shader does not fit the ps_3_0 limits (see ps30 check)\n");
    }
    s.push_str(&format!(
        "oC0.r: min {min:.6}, max {max:.6}, mean {mean:.6}\n"
    ));
    if let Some(p) = written {
        s.push_str(&format!("wrote {}\n", p.display()));
    }
    s
}

/// The JSON form of `ps30 run`.
pub fn pass_json(out: &PassOutput) -> serde_json::Value {
    let t = &out.target;
    let (min, max, mean) = red_stats(t);
    serde_json::json!({
        "target": [t.width, t.height],
        "target_format": t.format.d3d_name(),
        "drawn_by": out.drawn_by,
        "cost": &out.cost,
        "executed_per_pixel": out.cost.executed_emulated.map(range_json),
        "red": {"min": min, "max": max, "mean": mean},
        "texels": t.texels.iter().map(|v| v[0]).collect::<Vec<f32>>(),
    })
}
