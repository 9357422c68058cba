//! What `ps30 render` prints — one line per step of a draw list and a
//! summary of every target — its JSON, and the preview image of a target.

use crate::core::image::{Encoding, RenderTarget};
use crate::core::merge::{BlendState, OutputState};
use crate::core::numbers::{number, thousands};
use crate::jobs::render::{DrawList, Step, StepDetail, StepReport, TargetState};
use serde_json::{json, Value};

/// `ONE ONE ADD` (and ` / alpha ZERO ONE ADD`), or `off`.
pub fn blend_text(b: &BlendState) -> String {
    if !b.enabled {
        return "off".into();
    }
    let eq = |e: &crate::core::merge::Equation| {
        format!(
            "{} {} {}",
            e.src.d3d_name(),
            e.dest.d3d_name(),
            e.op.d3d_name()
        )
    };
    let mut s = eq(&b.color);
    if let Some(a) = &b.alpha {
        s.push_str(&format!(", alpha {}", eq(a)));
    }
    if b.factor != [255; 4] {
        s.push_str(&format!(", factor {:?}", b.factor));
    }
    s
}

fn output_text(o: &OutputState) -> String {
    format!(
        "blend {}, write {}",
        blend_text(&o.blend),
        o.write.letters()
    )
}

/// A draw's executed slots per pixel as counted, beside the cost model's:
/// `executed 64 per pixel (cost model 64, same)`, or the cost model's
/// alone when a GPU drew (`cost model 64 per pixel (a GPU counts nothing)`).
pub fn executed_text(
    executed: Option<crate::core::cost::Range>,
    executed_static: crate::core::cost::Range,
    counts_agree: bool,
) -> String {
    match executed {
        Some(e) => format!(
            "executed {} per pixel (cost model {}{})",
            e.text(),
            executed_static.text(),
            if counts_agree {
                ", same"
            } else {
                ", DIFFERENT"
            }
        ),
        None => format!(
            "cost model {} per pixel (a GPU counts nothing)",
            executed_static.text()
        ),
    }
}

/// One line for a finished step.
pub fn step_line(list: &DrawList, r: &StepReport) -> String {
    let what = match (&r.detail, &list.steps[r.index]) {
        (StepDetail::Clear { color }, _) => format!("to the D3DCOLOR {color:?}"),
        (
            StepDetail::Draw {
                shader,
                executed_static,
                executed,
                counts_agree,
                merged,
                triangles,
                ..
            },
            Step::Draw(d),
        ) => format!(
            "{shader}: {}{} pixels written, {} discarded; {}; {}",
            triangles.map_or(String::new(), |n| format!(
                "{} triangle{}, ",
                thousands(n),
                if n == 1 { "" } else { "s" }
            )),
            thousands(merged.written),
            thousands(merged.killed),
            executed_text(*executed, *executed_static, *counts_agree),
            output_text(&d.output)
        ),
        (StepDetail::Mips { odd, levels, mean }, _) => format!(
            "{levels} levels ({}) → 1×1 = ({})",
            match odd {
                crate::core::image::OddSides::Fold => "fold",
                crate::core::image::OddSides::Bilinear => "bilinear",
            },
            mean.map(|c| number(c as f64)).join(", ")
        ),
        (StepDetail::Draw { .. }, _) => String::new(),
    };
    format!("{:>4}  {:<5}  {:<10}  {what}\n", r.index, r.kind, r.target)
}

/// Per stored channel: min, max, mean over the target.
pub fn channel_stats(t: &RenderTarget) -> Vec<(f64, f64, f64)> {
    (0..t.format.channels())
        .map(|c| {
            let mut lo = f64::INFINITY;
            let mut hi = f64::NEG_INFINITY;
            let mut sum = 0f64;
            for texel in &t.texels {
                let v = texel[c] as f64;
                lo = lo.min(v);
                hi = hi.max(v);
                sum += v;
            }
            (lo, hi, sum / t.texels.len().max(1) as f64)
        })
        .collect()
}

/// The summary of every target at the end.
pub fn targets_text(list: &DrawList, states: &[TargetState]) -> String {
    let mut s = String::from("targets:\n");
    for (spec, st) in list.targets.iter().zip(states) {
        s.push_str(&format!(
            "  {:<10}  {}×{} {}",
            spec.name,
            spec.width,
            spec.height,
            spec.format.d3d_name()
        ));
        for ((lo, hi, mean), ch) in channel_stats(&st.target)
            .into_iter()
            .zip(["R", "G", "B", "A"])
        {
            s.push_str(&format!(
                "  {ch} {}…{} (mean {})",
                number(lo),
                number(hi),
                number(mean)
            ));
        }
        s.push('\n');
    }
    s
}

/// The run as JSON: steps (with their findings) and targets.
pub fn json(
    file: &str,
    description: Option<&str>,
    list: &DrawList,
    reports: &[StepReport],
    states: &[TargetState],
    written: &[String],
) -> Value {
    let steps: Vec<Value> = reports
        .iter()
        .map(|r| {
            let mut v = serde_json::to_value(r).unwrap_or(Value::Null);
            if let (StepDetail::Draw { findings, .. }, Step::Draw(d)) =
                (&r.detail, &list.steps[r.index])
            {
                v["findings"] = serde_json::to_value(findings).unwrap_or(Value::Null);
                v["blend"] = json!(blend_text(&d.output.blend));
                v["write"] = json!(d.output.write.letters());
            }
            v
        })
        .collect();
    let targets: Vec<Value> = list
        .targets
        .iter()
        .zip(states)
        .map(|(spec, st)| {
            let stats: Vec<Value> = channel_stats(&st.target)
                .into_iter()
                .map(|(lo, hi, mean)| json!({"min": lo, "max": hi, "mean": mean}))
                .collect();
            json!({
                "name": spec.name,
                "width": spec.width,
                "height": spec.height,
                "format": spec.format.d3d_name(),
                "channels": stats,
            })
        })
        .collect();
    json!({
        "file": file,
        "description": description,
        "steps": steps,
        "targets": targets,
        "written": written,
    })
}

/// An 8-bit RGB preview of a target: an A8R8G8B8 target's R, G, B codes as
/// they are (display values); a float target's channels clamped to [0, 1]
/// and sRGB-encoded (what an sRGB back buffer shows of linear light). A
/// channel the format lacks shows its read-back value, 1.
pub fn preview(t: &RenderTarget) -> Vec<u8> {
    let unorm = t.format.encoding() == Encoding::Unorm8;
    t.texels
        .iter()
        .flat_map(|p| {
            [0, 1, 2].map(|c| {
                if unorm {
                    crate::core::image::unorm8(p[c])
                } else {
                    crate::jobs::tonemap::srgb8(p[c] as f64)
                }
            })
        })
        .collect()
}
