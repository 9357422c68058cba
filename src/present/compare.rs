//! What `ps30 compare` prints: the agreement table of a draw (per channel:
//! identical pixels, the ulp histogram, NaN/∞ disagreements, the worst
//! pixels with their inputs), the luminance pipeline's L̄w from both
//! backends and the f64 reference, tone mapping, and the summary of
//! `--all`.

use crate::core::gpu::DeviceInfo;
use crate::core::numbers::thousands;
use crate::jobs::compare::explain::Explanation;
use crate::jobs::compare::stats::{bucket_label, ChannelStats, BUCKETS};
use crate::jobs::compare::{CrossCheck, TonemapComparison};
use crate::jobs::compare::{DrawComparison, LuminanceComparison};

fn ulp_text(u: Option<u64>) -> String {
    match u {
        Some(u) => format!("{} ulp", thousands(u)),
        None => "NaN/∞ on one side".into(),
    }
}

/// The per-channel table: identical pixels, histogram, maximum, specials.
pub fn channel_table(channels: &[ChannelStats]) -> String {
    let mut s = format!("{:<18} {:>20}", "channel", "identical");
    for i in 0..BUCKETS.len() {
        s.push_str(&format!(" {:>9}", bucket_label(i)));
    }
    s.push_str(&format!(" {:>9} {:>6}\n", "max ulp", "NaN/∞"));
    for c in channels {
        s.push_str(&format!(
            "{:<18} {:>20}",
            c.channel,
            format!("{} of {}", thousands(c.identical), thousands(c.pixels))
        ));
        for n in c.histogram {
            s.push_str(&format!(" {:>9}", thousands(n)));
        }
        s.push_str(&format!(
            " {:>9} {:>6}\n",
            thousands(c.max_ulp),
            c.nan_mismatches + c.inf_mismatches
        ));
    }
    s.push_str("(columns between identical and max ulp: pixels per distance in ulp)\n");
    s
}

fn explanation_line(e: &Option<Explanation>) -> String {
    match e {
        Some(e) => format!("why: {}\n", e.text),
        None => String::new(),
    }
}

/// The text of one draw's comparison.
pub fn draw_text(c: &DrawComparison) -> String {
    let mut s = format!(
        "{}: {}×{} target ({}), float rules {}: emulator vs GPU\n",
        c.shader, c.width, c.height, c.target, c.float_rules
    );
    s.push_str(&channel_table(&c.channels));
    if c.killed_mismatches > 0 {
        s.push_str(&format!(
            "texkill: {} pixels killed on one backend only\n",
            thousands(c.killed_mismatches)
        ));
    }
    for ch in &c.channels {
        for w in &ch.worst {
            s.push_str(&format!(
                "  worst {} at ({}, {}): emulator {:e}, GPU {:e} ({})",
                ch.channel,
                w.x,
                w.y,
                w.emulator,
                w.gpu,
                ulp_text(w.ulp)
            ));
            if let Some(p) = c.worst_inputs.iter().find(|p| p.x == w.x && p.y == w.y) {
                s.push_str(&inputs_text(&p.values));
            }
            s.push('\n');
        }
    }
    s.push_str(&format!(
        "{}\n",
        if c.all_identical() {
            "every pixel bit-identical"
        } else {
            "the backends differ (see the table)"
        }
    ));
    s.push_str(&explanation_line(&c.explanation));
    s
}

/// `; v0 = (x, y, z, w), …`: the inputs of a worst pixel or vertex.
fn inputs_text(values: &[(String, [f32; 4])]) -> String {
    let inputs: Vec<String> = values
        .iter()
        .map(|(r, v)| format!("{r} = ({}, {}, {}, {})", v[0], v[1], v[2], v[3]))
        .collect();
    format!("; {}", inputs.join(", "))
}

/// The text of a vertex shader's comparison (`compare VS --vertices`):
/// one channel per output component, the worst vertices with their inputs.
pub fn vertices_text(c: &DrawComparison) -> String {
    let mut s = format!(
        "{}: {} vertices, {}, float rules {}: emulator vs GPU\n",
        c.shader, c.width, c.target, c.float_rules
    );
    s.push_str(&channel_table(&c.channels));
    for ch in &c.channels {
        for w in &ch.worst {
            s.push_str(&format!(
                "  worst {} at vertex {}: emulator {:e}, GPU {:e} ({})",
                ch.channel,
                w.x,
                w.emulator,
                w.gpu,
                ulp_text(w.ulp)
            ));
            if let Some(p) = c.worst_inputs.iter().find(|p| p.x == w.x) {
                s.push_str(&inputs_text(&p.values));
            }
            s.push('\n');
        }
    }
    s.push_str(if c.all_identical() {
        "every output bit-identical\n"
    } else {
        "the backends differ (see the table)\n"
    });
    s.push_str(&explanation_line(&c.explanation));
    s
}

/// `--json` of one draw's comparison: the device, the comparison and
/// whether every pixel is bit-identical.
pub fn draw_json(device: &DeviceInfo, c: &DrawComparison) -> serde_json::Value {
    serde_json::json!({ "device": device, "comparison": c, "all_identical": c.all_identical() })
}

/// The text of the luminance pipeline's comparison.
pub fn luminance_text(c: &LuminanceComparison) -> String {
    let l = &c.log_average;
    let mut s = format!(
        "{}: {} + {}, blocks {}×{} → {}×{} target: emulator vs GPU\n",
        c.image, c.pass1, c.pass2, c.block.0, c.block.1, c.targets.0, c.targets.1
    );
    s.push_str(&channel_table(std::slice::from_ref(&c.blocks)));
    for w in &c.blocks.worst {
        s.push_str(&format!(
            "  block ({}, {}): emulator {}, GPU {} ({})\n",
            w.x,
            w.y,
            w.emulator,
            w.gpu,
            ulp_text(w.ulp)
        ));
    }
    s.push_str(&format!(
        "blocks within their bound of the f64 reference: GPU {} of {n}, emulator {} of {n}\n",
        c.gpu_blocks_within,
        c.emulator_blocks_within,
        n = c.blocks.pixels
    ));
    s.push_str(&format!(
        "L̄w: GPU {:.7}, emulator {:.7}, f64 reference {:.7}; relative error GPU {:.2e}, emulator {:.2e}, bound {:.2e}\n",
        l.gpu, l.emulator, l.reference, l.gpu_relative_error, l.emulator_relative_error, l.tolerance
    ));
    s.push_str(&explanation_line(&c.explanation));
    s
}

/// `--json` of the luminance pipeline's comparison, with the device.
pub fn luminance_json(device: &DeviceInfo, c: &LuminanceComparison) -> serde_json::Value {
    serde_json::json!({ "device": device, "comparison": c })
}

/// The text of tone mapping's comparison.
pub fn tonemap_text(c: &TonemapComparison) -> String {
    let mut s = format!(
        "{}: tone mapping ({}), the emulator's L̄w on both backends\n",
        c.image, c.draw.shader
    );
    s.push_str(&channel_table(&c.draw.channels));
    s.push_str(&format!(
        "pixels within their bound of the f64 reference: GPU {} of {n}, emulator {} of {n}\n",
        thousands(c.gpu_within),
        thousands(c.emulator_within),
        n = thousands(c.pixels)
    ));
    s.push_str(&explanation_line(&c.explanation));
    s
}

/// `--json` of tone mapping's comparison, with the device.
pub fn tonemap_json(device: &DeviceInfo, c: &TonemapComparison) -> serde_json::Value {
    serde_json::json!({ "device": device, "comparison": c })
}

/// The summary `ps30 compare --all` prints.
pub fn all_text(x: &CrossCheck) -> String {
    let mut s = String::from("instruction probes (4,096 inputs each):\n");
    for p in &x.probes {
        s.push_str(&format!(
            "  {:<28} {}\n",
            p.instruction,
            crate::jobs::compare::explain::describe_probe(p)
        ));
    }
    let verdict = |e: &Option<Explanation>| match e {
        Some(e) if e.finding => "FINDING",
        Some(e) if e.device => "device",
        Some(_) => "explained",
        None => "",
    };
    s.push_str("luminance (blocks identical, max ulp; L̄w GPU / emulator / f64):\n");
    for c in &x.luminance {
        s.push_str(&format!(
            "  {:<9} {:<52} {:>3} of {:<3} {:>8}  {:.7} / {:.7} / {:.7}  {}\n",
            verdict(&c.explanation),
            format!(
                "{} {}{}",
                c.image,
                c.pass1,
                if c.target_format == "D3DFMT_R32F" {
                    String::new()
                } else {
                    format!(" ({})", c.target_format)
                }
            ),
            c.blocks.identical,
            c.blocks.pixels,
            thousands(c.blocks.max_ulp),
            c.log_average.gpu,
            c.log_average.emulator,
            c.log_average.reference,
            ""
        ));
    }
    s.push_str("tone mapping (identical r, g, b; max ulp):\n");
    for c in &x.tonemap {
        let ids: Vec<String> = c
            .draw
            .channels
            .iter()
            .map(|ch| thousands(ch.identical))
            .collect();
        s.push_str(&format!(
            "  {:<9} {:<26} {} of {} each; {}\n",
            verdict(&c.explanation),
            c.image,
            ids.join(" / "),
            thousands(c.pixels),
            thousands(c.draw.max_ulp())
        ));
    }
    s.push_str("light models on the synthetic G-buffer:\n");
    for c in &x.lights {
        s.push_str(&format!(
            "  {:<9} {:<26} max {} ulp\n",
            verdict(&c.explanation),
            c.shader,
            thousands(c.max_ulp())
        ));
    }
    s
}

/// The text of a draw list's comparison (`compare --list`): per draw, the
/// targets' table, the coverage of a draw of geometry, the worst pixels
/// and the explanation.
pub fn list_text(c: &crate::jobs::compare::draws::ListComparison) -> String {
    let mut s = String::new();
    for step in &c.steps {
        let d = &step.comparison;
        s.push_str(&format!(
            "steps[{}]: {} into a {}×{} {} target, float rules {}: emulator vs GPU\n",
            step.index, d.shader, d.width, d.height, d.target, d.float_rules
        ));
        s.push_str(&channel_table(&d.channels));
        if let Some(cov) = &step.coverage {
            s.push_str(&format!(
                "coverage: {} primitives; {} pixels covered on both, {} on the emulator only, {} on the GPU only\n",
                thousands(cov.primitives as u64),
                thousands(cov.both),
                thousands(cov.emulator_only),
                thousands(cov.gpu_only)
            ));
            for x in &cov.differences {
                let distance = match x.distance {
                    Some(v) => format!("{v:.4} pixel from its nearest edge"),
                    None => "not drawn by the emulator".into(),
                };
                s.push_str(&format!(
                    "  ({}, {}) primitive {}: {} only, {distance}\n",
                    x.x, x.y, x.primitive, x.covered_by
                ));
            }
        }
        for ch in &d.channels {
            for w in ch.worst.iter().take(2) {
                s.push_str(&format!(
                    "  worst {} at ({}, {}): emulator {:e}, GPU {:e} ({})\n",
                    ch.channel,
                    w.x,
                    w.y,
                    w.emulator,
                    w.gpu,
                    ulp_text(w.ulp)
                ));
            }
        }
        s.push_str(&explanation_line(&d.explanation));
    }
    s
}

/// `--json` of a draw list's comparison: the device and every draw.
pub fn list_json(
    device: &DeviceInfo,
    c: &crate::jobs::compare::draws::ListComparison,
) -> serde_json::Value {
    serde_json::json!({ "device": device, "steps": c.steps, "explained": c.explained() })
}
