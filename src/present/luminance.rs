//! What `ps30 luminance` and `ps30 run` print: the passes' costs, the
//! cross-check and its findings, as text and JSON.

use crate::core::audit;
use crate::core::cost::Profile;
use crate::core::emu::findings::{grouped, Finding};
use crate::core::image::Written;
use crate::core::load::Loaded;
use crate::core::numbers::{decimal, number_grouped, plural, thousands};
use crate::jobs::luminance::{
    BlockCheck, Comparison, LuminanceRun, PassCost, PassOutput, FIT_TOLERANCE,
};
use crate::jobs::outputs::OutputRegister;
use crate::present::json;
use std::path::Path;

/// How a run's block and shaders were chosen.
#[derive(Clone, Debug, PartialEq)]
pub enum Choice {
    /// `--block WxH`.
    Given,
    /// The block the pass-1 shader was written for (its header, or the
    /// article's for a bundled listing).
    FromShader,
    /// No shader named: the planner's recommendation for the image's size
    /// (`label`), with generated shaders.
    Planned {
        /// The candidate (`unrolled 117×128 → 11×8`).
        label: String,
        /// Why the planner chose it.
        why: String,
    },
}

impl Choice {
    fn text(&self) -> String {
        match self {
            Choice::Given => "the block given with --block".to_string(),
            Choice::FromShader => "the block the pass-1 shader was written for".to_string(),
            Choice::Planned { label, .. } => format!(
                "planned for the image (ps30 plan: {label}), shaders generated for it (ps30 unroll)"
            ),
        }
    }

    fn json(&self) -> serde_json::Value {
        match self {
            Choice::Given => serde_json::json!({"source": "given"}),
            Choice::FromShader => serde_json::json!({"source": "shader"}),
            Choice::Planned { label, why } => {
                serde_json::json!({"source": "planned", "candidate": label, "why": why})
            }
        }
    }
}

/// The JSON form of a run (`ps30 luminance --json`).
pub fn run_json(image: &str, r: &LuminanceRun, choice: &Choice) -> serde_json::Value {
    serde_json::json!({
        "image": image,
        "block_choice": choice.json(),
        "fit": r.fit(),
        "within_limits": r.within_limits(),
        "width": r.width,
        "height": r.height,
        "drawn_by": r.drawn_by,
        "log_average": json::real(r.log_average),
        "reference_log_average": json::real(r.reference_log_average),
        "relative_error": json::real(r.relative_error),
        "relative_tolerance": json::real(r.relative_tolerance),
        "agree": r.all_agree(),
        "finite": r.finite(),
        "log_average_agrees": r.agree,
        "blocks_agree": r.blocks_agree(),
        "target_format": r.target_format.d3d_name(),
        "delta": json::real32(r.delta),
        "block": [r.block.0, r.block.1],
        "targets": [r.targets.0, r.targets.1],
        "padded_samples": r.padded_samples,
        "padding_factor": json::real(r.padding_factor),
        "passes": std::iter::once(("pass1", &r.pass1))
            .chain(r.pass1_last.iter().map(|p| ("pass1_last", p)))
            .chain(std::iter::once(("pass2", &r.pass2)))
            .map(|(role, p)| pass_cost_json(role, p))
            .collect::<Vec<_>>(),
        "pass2_check": comparison_json(&r.pass2_check),
        "ill_conditioned_pixels": r.ill_conditioned,
        "negative_pixels": r.negative_pixels,
        "nonfinite_pixels": r.nonfinite_pixels,
        "blocks": r.blocks.iter().map(|b| serde_json::json!({
            "x": b.x,
            "y": b.y,
            "emulated": json::real(b.emulated),
            "reference": json::real(b.reference),
            "difference": json::real(b.difference),
            "tolerance": json::real(b.tolerance),
            "agree": b.agree,
            "overflow": b.overflow,
        })).collect::<Vec<_>>(),
    })
}

/// A scalar comparison.
pub fn comparison_json(c: &Comparison) -> serde_json::Value {
    serde_json::json!({
        "emulated": json::real(c.emulated),
        "reference": json::real(c.reference),
        "difference": json::real(c.difference),
        "tolerance": json::real(c.tolerance),
        "agree": c.agree,
    })
}

/// One pass's cost in the shared shape: the cost model's count next to
/// the emulator's, the limits, and the draw's findings (grouped).
pub fn pass_cost_json(role: &str, p: &PassCost) -> serde_json::Value {
    serde_json::json!({
        "role": role,
        "shader": p.shader,
        "slots": p.slots,
        "executed": json::range(p.executed_static),
        "executed_emulated": p.executed_emulated.map(json::range),
        "counts_agree": p.counts_agree,
        "within_limits": p.within_limits,
        "diagnostics": json::findings(&p.shader, &p.findings),
    })
}

/// `  OVER the ps_3_0 limits: …` when a pass does not fit, else nothing.
fn limits_text(p: &PassCost) -> String {
    if p.within_limits {
        return String::new();
    }
    let profile = Profile::ps_3_0();
    let mut over = Vec::new();
    if p.slots > profile.max_slots {
        over.push(format!(
            "{} slots, {} allowed",
            thousands(p.slots),
            thousands(profile.max_slots)
        ));
    }
    if p.executed_static.max > profile.max_executed {
        over.push(format!(
            "{} executed per pixel, {} allowed ({} over)",
            p.executed_static.text(),
            thousands(profile.max_executed),
            thousands(p.executed_static.max - profile.max_executed)
        ));
    }
    format!(
        "  OVER the {} limits: {}; a GPU would refuse or cut short this pass\n",
        profile.name,
        over.join("; ")
    )
}

/// `emulator counted 64,774, same`, or what a GPU run says instead.
pub fn counted_text(p: &PassCost) -> String {
    match p.executed_emulated {
        Some(r) => format!(
            "emulator counted {}{}",
            r.text(),
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
        p.executed_static.text(),
        counted_text(p)
    );
    s.push_str(&limits_text(p));
    s.push_str(&findings_text(&p.shader, &p.findings));
    s
}

/// One `  warning: file:line:col: …` line per group of identical findings,
/// with the count and the lines when there are several.
pub fn findings_text(shader: &str, findings: &[Finding]) -> String {
    grouped(findings)
        .iter()
        .map(|g| {
            let f = g.first;
            let place = if g.count == 1 {
                format!("{shader}:{}:{}", f.site.line, f.site.column)
            } else {
                format!(
                    "{shader}:{}:{} and {} ({} in all, lines {}–{})",
                    f.site.line,
                    f.site.column,
                    plural(g.count as u64 - 1, "more place", "more places"),
                    thousands(g.count as u64),
                    g.lines.0,
                    g.lines.1
                )
            };
            format!("  warning: {place}: {} ({})\n", f.message, f.label)
        })
        .collect()
}

/// The lines on pass 1's blocks: how many agree, the worst, non-finite
/// pixels, overflowing sums and the disagreeing blocks.
fn blocks_text(r: &LuminanceRun) -> String {
    let mut s = String::new();
    let agreeing = r.blocks.iter().filter(|b| b.agree).count();
    let worst = r
        .blocks
        .iter()
        .max_by(|a, b| (a.difference / a.tolerance).total_cmp(&(b.difference / b.tolerance)));
    s.push_str(&format!(
        "blocks: {} of {} agree with the f64 reference",
        thousands(agreeing as u64),
        thousands(r.blocks.len() as u64)
    ));
    if let Some(w) = worst {
        s.push_str(&format!(
            " (largest difference/tolerance: {:.3} at block {},{}: {} vs {}, tolerance {})",
            w.difference / w.tolerance,
            w.x,
            w.y,
            decimal(w.emulated, 4),
            decimal(w.reference, 4),
            decimal(w.tolerance, 3)
        ));
    }
    s.push('\n');
    let bad: Vec<&BlockCheck> = r.blocks.iter().filter(|b| !b.agree).collect();
    if r.nonfinite_pixels > 0 {
        s.push_str(&format!(
            "{} NaN or infinite: their blocks and L̄w are not finite, on a GPU as in the reference\n",
            plural(r.nonfinite_pixels, "pixel is", "pixels are")
        ));
    }
    let overflowed = r.blocks.iter().filter(|b| b.overflow).count();
    if overflowed > 0 {
        s.push_str(&format!(
            "{} {} (beyond ±65,504): the target cannot hold {}\n",
            plural(
                overflowed as u64,
                "block sum overflows",
                "block sums overflow"
            ),
            r.target_format.d3d_name(),
            if overflowed == 1 { "it" } else { "them" }
        ));
    }
    if !bad.is_empty() {
        s.push_str("disagreeing blocks (column, row: emulated vs reference, difference):\n");
        for b in bad.iter().take(12) {
            s.push_str(&format!(
                "  {:>3},{:<3} {:>15} vs {:>15}  {:>13}\n",
                b.x,
                b.y,
                decimal(b.emulated, 3),
                decimal(b.reference, 3),
                decimal(b.difference, 3)
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
    s
}

/// The text form of a run (`ps30 luminance`).
pub fn run_text(image: &str, r: &LuminanceRun, choice: &Choice) -> String {
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
    s.push_str(&format!("blocks: {}\n", choice.text()));
    if r.drawn_by != "emulator" {
        s.push_str(&format!("drawn on the {}\n", r.drawn_by));
    }
    s.push_str(&pass_line("pass 1", &r.pass1));
    if let Some(p) = &r.pass1_last {
        s.push_str(&pass_line("pass 1 (last column)", p));
    }
    s.push_str(&pass_line("pass 2", &r.pass2));
    s.push_str(&blocks_text(r));
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
        match (r.fit(), r.agree) {
            (false, _) => "NOT CHECKED, the bound is too wide (see below)",
            (true, true) => "agree",
            (true, false) => "DISAGREE",
        }
    ));
    if r.padded_samples > 0 {
        s.push_str(&format!(
            "padding: {} read outside the image; left uncorrected they scale L̄w by {:.4}\n",
            plural(r.padded_samples, "sample", "samples"),
            r.padding_factor
        ));
    }
    if !r.fit() {
        s.push_str(&format!(
            "UNFIT for this image: the derived bound allows L̄w to be off by {:.0}% (the cross-check needs at most {:.0}% to mean anything): {} against {} in {}×{} blocks; let ps30 plan the blocks (no --pass1) or give a smaller --block\n",
            100.0 * r.relative_tolerance,
            100.0 * FIT_TOLERANCE,
            plural(r.width as u64 * r.height as u64, "real pixel", "real pixels"),
            plural(r.padded_samples, "padded sample", "padded samples"),
            r.block.0,
            r.block.1
        ));
    }
    if !r.within_limits() {
        s.push_str("verdict: the passes EXCEED the ps_3_0 limits (see above)\n");
    }
    if r.ill_conditioned > 0 {
        s.push_str(&format!(
            "note: {} δ + L so close to 0 that f32 cannot bound {} term\n",
            plural(r.ill_conditioned, "pixel has", "pixels have"),
            if r.ill_conditioned == 1 {
                "its"
            } else {
                "their"
            }
        ));
    }
    s
}

/// The text form of `ps30 run`.
pub fn pass_text(image: &str, out: &PassOutput, written: Option<(&Path, &Written)>) -> String {
    let t = &out.target;
    let mut s = format!(
        "{} over {image} → {}×{} target ({})\n",
        out.cost.shader,
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
            e.text(),
            out.cost.executed_static.text(),
            if out.cost.counts_agree {
                ", same"
            } else {
                ", DIFFERENT"
            }
        ),
        None => format!(
            "slots {}, executed per pixel {} (cost model; not counted: drawn on the GPU)\n",
            out.cost.slots,
            out.cost.executed_static.text()
        ),
    });
    s.push_str(&limits_text(&out.cost));
    s.push_str(&findings_text(&out.cost.shader, &out.cost.findings));
    s.push_str(&outputs_text(&out.outputs, t.format.d3d_name()));
    if let Some((path, w)) = written {
        s.push_str(&format!("wrote {} ({}", path.display(), w.format.name()));
        if w.clamped > 0 {
            s.push_str(&format!(
                "; {} outside [0, 1] clamped",
                plural(w.clamped, "value", "values")
            ));
        }
        s.push_str(")\n");
    }
    s
}

/// One line per stored channel (`oC0.r: min …, max …, mean …`), and what
/// the shader writes that the target does not keep.
fn outputs_text(outputs: &[OutputRegister], format: &str) -> String {
    let mut s = String::new();
    let value = |v: Option<f64>| v.map_or("none".to_string(), number_grouped);
    for o in outputs {
        for c in &o.stored {
            s.push_str(&format!(
                "{}.{}: min {}, max {}, mean {}",
                o.register,
                c.channel,
                value(c.min),
                value(c.max),
                value(c.mean)
            ));
            if c.non_finite > 0 {
                s.push_str(&format!(
                    " (finite texels; {} NaN or infinite)",
                    thousands(c.non_finite)
                ));
            }
            s.push('\n');
        }
        if !o.dropped.is_empty() {
            s.push_str(&format!(
                "{}.{}: written by the shader, not stored by {format}\n",
                o.register, o.dropped
            ));
        }
        if o.stored.is_empty() && o.dropped.is_empty() {
            s.push_str(&format!(
                "{}{}: written by the shader; `ps30 run` binds a target to oC0 only\n",
                o.register,
                if o.written.is_empty() {
                    String::new()
                } else {
                    format!(".{}", o.written)
                }
            ));
        }
    }
    if outputs.is_empty() {
        s.push_str("the shader writes no output register\n");
    }
    s
}

/// The JSON form of `ps30 run`; per-texel values only when `texels`.
pub fn pass_json(
    loaded: &Loaded,
    found: &[audit::Finding],
    out: &PassOutput,
    texels: bool,
) -> serde_json::Value {
    let t = &out.target;
    let mut diagnostics = crate::present::check::diagnostics_json(loaded, found);
    diagnostics.extend(json::findings(&out.cost.shader, &out.cost.findings));
    let mut v = serde_json::json!({
        "shader": out.cost.shader,
        "target": [t.width, t.height],
        "target_format": t.format.d3d_name(),
        "drawn_by": out.drawn_by,
        "pass": pass_cost_json("pass", &out.cost),
        "outputs": out.outputs.iter().map(|o| serde_json::json!({
            "register": o.register,
            "written": o.written,
            "dropped": o.dropped,
            "stored": o.stored.iter().map(|c| serde_json::json!({
                "channel": c.channel.to_string(),
                "min": c.min,
                "max": c.max,
                "mean": c.mean,
                "non_finite": c.non_finite,
            })).collect::<Vec<_>>(),
        })).collect::<Vec<_>>(),
        "diagnostics": diagnostics,
    });
    if texels {
        v["texels"] = t
            .texels
            .iter()
            .map(|p| json::real32x4(*p))
            .collect::<Vec<_>>()
            .into();
    }
    v
}
