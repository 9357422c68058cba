//! Why two backends differ: each comparison's differences traced to the
//! instructions whose probes ([`super::probe`]) show the device computing
//! something else than the emulator, and judged against the bound the
//! arithmetic allows. A difference the bounds hold and the probes account
//! for is explained; one beyond a bound, or a NaN/∞ on one side only that
//! no rule accounts for, is a finding.

use super::probe::Probe;
use super::{CrossCheck, DrawComparison, LuminanceComparison, TonemapComparison};
use crate::core::numbers::thousands;
use serde::Serialize;

/// A verdict in words.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Explanation {
    /// Nothing explains it: a bound is broken, or a special value differs.
    pub finding: bool,
    /// Explained by something the device does that Direct3D 9 hardware
    /// need not (flushing subnormals, storing f16 toward zero): the
    /// results differ beyond rounding, and the cause is known.
    pub device: bool,
    /// The explanation, in sentences citing the probes.
    pub text: String,
}

/// The mnemonic a probe exercises (`log`, `mad`, …).
fn probe_op(p: &Probe) -> &str {
    p.instruction.split_whitespace().next().unwrap_or("")
}

/// One short clause per probed instruction of `ops` whose ordinary inputs
/// give different results on the device (the probe table has the rest).
pub fn device_differences(ops: &[&str], probes: &[Probe]) -> Vec<String> {
    probes
        .iter()
        .filter(|p| ops.contains(&probe_op(p)) && !p.ordinary_identical())
        .map(|p| {
            format!(
                "the device's `{}` differs from the emulator's by up to {} ulp on ordinary inputs ({} Vulkan's precision; the emulator within {} ulp of exact)",
                probe_op(p),
                thousands(p.max_ulp),
                if p.gpu_outside_spec == 0 { "within" } else { "OUTSIDE" },
                thousands(p.emulator_max_ulp_exact)
            )
        })
        .collect()
}

/// Whether the probes show the device flushing subnormals.
pub fn flushes_subnormals(probes: &[Probe]) -> bool {
    probes
        .iter()
        .any(|p| p.subnormal_differ > 0 && p.subnormal_as_zero == p.subnormal_differ)
}

fn ordinary_clause(p: &Probe) -> String {
    let op = probe_op(p);
    let mut s = format!(
        "`{op}` gives other bits for {} of {} ordinary inputs, at most {} ulp apart (|Δ| ≤ {:.1e}); \
         the device is within {} ulp of the correctly rounded result (absolute error ≤ {:.1e}), the emulator within {} ulp ({:.1e})",
        thousands(p.ordinary - p.ordinary_identical),
        thousands(p.ordinary),
        thousands(p.max_ulp),
        p.max_abs,
        thousands(p.gpu_max_ulp_exact),
        p.gpu_max_abs_exact,
        thousands(p.emulator_max_ulp_exact),
        p.emulator_max_abs_exact
    );
    s.push_str(&orders_clause(p));
    s.push_str(&spec_clause(p));
    s
}

/// Which evaluation order the device's results match, where the orders
/// give different results (fused or not, left to right or pairwise); empty
/// for instructions with one order.
fn orders_clause(p: &Probe) -> String {
    if p.orders.is_empty() {
        return String::new();
    }
    let matches: Vec<String> = p
        .orders
        .iter()
        .map(|(n, _, m)| format!("{n} {}", thousands(*m)))
        .collect();
    format!(
        " (where the orders differ, {} inputs, the device matches: {})",
        thousands(p.orders[0].1),
        matches.join(", ")
    )
}

/// Whether the device meets Vulkan's precision for the instruction.
fn spec_clause(p: &Probe) -> String {
    if p.gpu_outside_spec == 0 {
        format!(": within Vulkan's precision ({})", p.spec)
    } else {
        format!(
            ": OUTSIDE Vulkan's precision ({}) on {} inputs",
            p.spec,
            thousands(p.gpu_outside_spec)
        )
    }
}

/// What one probe says about the device.
pub fn describe_probe(p: &Probe) -> String {
    let op = probe_op(p);
    let mut parts = Vec::new();
    if p.ordinary_identical() {
        let mut s = format!("ordinary inputs: all {} identical", thousands(p.ordinary));
        s.push_str(&orders_clause(p));
        parts.push(s);
    } else {
        parts.push(ordinary_clause(p));
    }
    if p.subnormal_differ > 0 {
        parts.push(format!(
            "subnormals: {} of {} differ, {} of them as if every subnormal operand and result were 0",
            thousands(p.subnormal_differ),
            thousands(p.subnormal),
            thousands(p.subnormal_as_zero)
        ));
    }
    for (input, e, g) in p.specials.iter().take(3) {
        parts.push(format!(
            "`{op}` of ({}): emulator {e:e}, device {g:e}",
            input
                .iter()
                .map(|v| format!("{v:e}"))
                .collect::<Vec<_>>()
                .join(", ")
        ));
    }
    if p.specials.len() > 3 {
        parts.push(format!(
            "{} more special inputs differ",
            p.specials.len() - 3
        ));
    }
    parts.join("; ")
}

fn joined(clauses: &[String]) -> String {
    if clauses.is_empty() {
        "no probed instruction of these shaders differs on this device".into()
    } else {
        clauses.join("; ")
    }
}

/// The luminance pipeline.
pub fn luminance(c: &LuminanceComparison, probes: &[Probe]) -> Explanation {
    let n = c.blocks.pixels as usize;
    let ops: Vec<&str> = c.opcodes.iter().map(String::as_str).collect();
    let same_lw = c.log_average.gpu.to_bits() == c.log_average.emulator.to_bits();
    if c.blocks.all_identical() && same_lw {
        return Explanation {
            finding: false,
            device: false,
            text: "bit-identical: every block sum and L̄w".into(),
        };
    }
    if c.blocks.f16_saturations > 0
        && c.blocks.f16_saturations == c.blocks.inf_mismatches + c.blocks.nan_mismatches
    {
        return Explanation {
            finding: false,
            device: true,
            text: format!(
                "{} block sums beyond ±65,504 are stored in the f16 target as ±65,504 (the device rounds \
                 toward zero, which Vulkan allows for colour attachments), where the emulator rounds to nearest (the \
                 Direct3D 10 rule; Direct3D 9 does not say) and stores ±∞ (the finite sums differ by up to {} ulp, one half-step, for the same reason); so L̄w is {:.4} × the true value on the device and {:.4} × on the \
                 emulator — finding 3 (an f16 target cannot hold the sums) holds on both, with a different wrong \
                 answer",
                thousands(c.blocks.f16_saturations),
                thousands(c.blocks.max_ulp),
                c.log_average.gpu / c.log_average.reference,
                c.log_average.emulator / c.log_average.reference
            ),
        };
    }
    let both_agree = c.gpu_agrees && c.emulator_agrees;
    let same_verdict =
        c.gpu_blocks_within == c.emulator_blocks_within && c.gpu_agrees == c.emulator_agrees;
    let why = joined(&device_differences(&ops, probes));
    if both_agree {
        return Explanation {
            finding: false,
            device: false,
            text: format!(
                "rounding: both backends are within the derived bound at all {n} blocks and for L̄w (relative error {:.1e} and {:.1e} of a {:.1e} bound); {why}",
                c.log_average.gpu_relative_error, c.log_average.emulator_relative_error, c.log_average.tolerance
            ),
        };
    }
    if same_verdict {
        return Explanation {
            finding: false,
            device: false,
            text: format!(
                "both backends disagree with the f64 reference in the same way ({} of {n} blocks within their bound on each; L̄w {:.4} × and {:.4} × the true value): the shaders' own error, not the device's; {why}",
                c.gpu_blocks_within,
                c.log_average.gpu / c.log_average.reference,
                c.log_average.emulator / c.log_average.reference
            ),
        };
    }
    Explanation {
        finding: true,
        device: false,
        text: format!(
            "FINDING: the device has {} of {n} blocks within their bound, the emulator {}; L̄w relative error {:.1e} against {:.1e} (bound {:.1e}); {why}",
            c.gpu_blocks_within,
            c.emulator_blocks_within,
            c.log_average.gpu_relative_error,
            c.log_average.emulator_relative_error,
            c.log_average.tolerance
        ),
    }
}

/// Tone mapping of one image.
pub fn tonemap(c: &TonemapComparison, probes: &[Probe]) -> Explanation {
    let ops: Vec<&str> = c.draw.opcodes.iter().map(String::as_str).collect();
    if c.draw.all_identical() {
        return Explanation {
            finding: false,
            device: false,
            text: "bit-identical".into(),
        };
    }
    let why = joined(&device_differences(&ops, probes));
    if c.gpu_within == c.emulator_within && c.draw.special_mismatches() == 0 {
        Explanation {
            finding: false,
            device: false,
            text: format!(
                "rounding: {} of {} pixels within their derived bound of the f64 reference on both backends; {why}",
                thousands(c.gpu_within),
                thousands(c.pixels)
            ),
        }
    } else {
        Explanation {
            finding: true,
            device: false,
            text: format!(
                "FINDING: {} pixels within their bound on the device, {} on the emulator, {} NaN/∞ on one side only; {why}",
                thousands(c.gpu_within),
                thousands(c.emulator_within),
                c.draw.special_mismatches()
            ),
        }
    }
}

/// One clause per sampler of `draw` whose filtering Vulkan lets a device
/// do otherwise than the emulator: linear filtering (the device may weigh
/// taps with as few as 4 sub-texel bits, `subTexelPrecisionBits`; the
/// emulator weighs in f32, so each axis's weight may be off by 2⁻⁵),
/// and MIPFILTER LINEAR (frac(λ) quantised likewise). A cube map's faces
/// are clamped at their edges on both backends (the GPU backend samples
/// them as a 2D array, `translate/cube.rs`).
pub fn filtering(draw: &crate::core::emu::Draw) -> Vec<String> {
    use crate::core::emu::{Filter, MipFilter, TextureLevels};
    let mut out = Vec::new();
    for (k, tex, state) in &draw.samplers {
        let linear = state.mag_filter == Filter::Linear || state.min_filter == Filter::Linear;
        let blend = state.mip_filter == MipFilter::Linear && tex.len() > 1;
        if !linear && !blend {
            continue;
        }
        let (kind, axes) = match tex {
            TextureLevels::Cube(_) => ("cube", 2),
            TextureLevels::Volume(_) => ("volume", 3),
            _ => ("2D", 2),
        };
        let mut parts = Vec::new();
        if linear {
            parts.push(format!(
                "filters linearly on {axes} axes (a sample may move by up to {axes}·2⁻⁵ of its texels' range)"
            ));
        }
        if blend {
            parts.push("blends mip levels by a quantised frac(λ)".to_string());
        }
        out.push(format!(
            "s{k} ({kind}) {} — the device's filter weights need only 4 sub-texel bits in Vulkan",
            parts.join(", ")
        ));
    }
    out
}

/// A draw without a reference (the light models).
pub fn draw(c: &DrawComparison, probes: &[Probe]) -> Explanation {
    let ops: Vec<&str> = c.opcodes.iter().map(String::as_str).collect();
    if c.all_identical() {
        return Explanation {
            finding: false,
            device: false,
            text: "bit-identical".into(),
        };
    }
    let differing: u64 = c.channels.iter().map(|ch| ch.pixels - ch.identical).sum();
    let flushed: u64 = c.channels.iter().map(|ch| ch.subnormal_flushes).sum();
    let mut clauses = device_differences(&ops, probes);
    let flushes_inside = flushes_subnormals(probes) && c.float_rules != "hardware";
    if flushes_inside {
        // A subnormal product inside `mad` or a dot product vanishes on
        // such a device before the add: a normal result moves.
        clauses.push(format!(
            "the device flushes subnormals (the probes show it), inside instructions too: a subnormal product in `mad` or a dot product is 0 before the add, where the float rules {} keep it; `--float-rules hardware` flushes it on both backends",
            c.float_rules
        ));
    }
    let rest = differing - flushed;
    if rest > 0 && c.max_ulp() == 0 {
        // Values 0 ulp apart that are not identical are +0 and −0.
        clauses.push("they are zeros of opposite sign: the device need not keep the sign of a zero (a SPIR-V module without SignedZeroInfNanPreserve lets its compiler drop it)".into());
    }
    clauses.extend(c.filtering.iter().cloned());
    let mut parts = Vec::new();
    if flushed > 0 {
        parts.push(format!(
            "{} channel values are subnormal on one backend and 0 on the other{}",
            thousands(flushed),
            if flushes_subnormals(probes) {
                " — the device flushes subnormals to zero (the probes show it), the emulator keeps them as IEEE does; Direct3D 9 does not say which"
            } else {
                ""
            }
        ));
    }
    if rest > 0 {
        parts.push(format!(
            "{} other values differ, at most {} ulp: {}",
            thousands(rest),
            thousands(c.max_ulp()),
            joined(&clauses)
        ));
    }
    let finding = c.special_mismatches() > 0
        || c.killed_mismatches > 0
        || (rest > 0 && clauses.is_empty())
        || (flushed > 0 && !flushes_subnormals(probes));
    let device = (flushed > 0 || (rest > 0 && flushes_inside)) && !finding;
    let mut text = parts.join("; ");
    if finding {
        text = format!(
            "FINDING: {text} ({} NaN/∞ on one side only, {} pixels killed on one side only)",
            c.special_mismatches(),
            c.killed_mismatches
        );
    }
    Explanation {
        finding,
        device,
        text,
    }
}

/// Whether nothing in the set is a finding.
pub fn all_explained(x: &CrossCheck) -> bool {
    let ok = |e: &Option<Explanation>| e.as_ref().is_some_and(|e| !e.finding);
    x.luminance.iter().all(|c| ok(&c.explanation))
        && x.tonemap.iter().all(|c| ok(&c.explanation))
        && x.lights.iter().all(|c| ok(&c.explanation))
}
