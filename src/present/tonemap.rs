//! What `ps30 tonemap` prints: L̄w, the operator, the cost and the pixel
//! cross-check, as text and JSON.

use crate::core::numbers::{number, plural, thousands};
use crate::jobs::tonemap::{Operator, ToneMapped, WhiteSource};
use crate::present::json as shape;

fn white_text(op: &Operator) -> String {
    match op.white_source {
        WhiteSource::Given => format!("white point {}", number(op.white)),
        WhiteSource::SceneMaximum => format!(
            "white point {} (the scene's largest luminance)",
            number(op.white)
        ),
        WhiteSource::NoPositiveLuminance => {
            "white point ∞ (no pixel has positive luminance)".to_string()
        }
    }
}

/// The text `ps30 tonemap` prints.
pub fn text(image: &str, t: &ToneMapped, written: Option<&str>) -> String {
    let op = &t.operator;
    let lum = &t.luminance;
    let c = &t.check;
    let mut s = format!(
        "{image}: {}×{}, L̄w {} (luminance pipeline; f64 reference {}, relative error {:.1e} of a {:.1e} bound: {})\n",
        t.width,
        t.height,
        number(lum.log_average),
        number(lum.reference_log_average),
        lum.relative_error,
        lum.relative_tolerance,
        if lum.all_agree() { "agree" } else { "DISAGREE" }
    );
    if lum.drawn_by != "emulator" {
        s.push_str(&format!("drawn on the {}\n", lum.drawn_by));
    }
    s.push_str(&format!(
        "key a = {}, {} → a/L̄w = {}, L_white = {}\n",
        number(op.key),
        white_text(op),
        number(op.scale()),
        number(op.white_scaled())
    ));
    s.push_str(&format!(
        "shader {}: {} slots, {} executed per pixel ({})\n",
        t.cost.shader,
        t.cost.slots,
        t.cost.executed_static.text(),
        crate::present::luminance::counted_text(&t.cost)
    ));
    s.push_str(&format!(
        "cross-check against the f64 reference: {} pixels, largest difference {:.1e} (its bound {:.1e}; at most {:.0}% of the bound anywhere): {}\n",
        thousands(c.checked_pixels),
        c.max_error,
        c.max_error_bound,
        100.0 * c.largest_bound_fraction,
        if c.agree() { "agree" } else { "DISAGREE" }
    ));
    s.push_str(&format!(
        "8-bit sRGB: {} in {} differ from the reference's by one code, each where the bound straddles a rounding boundary{}\n",
        plural(c.mismatched_8bit_channels, "channel value", "channel values"),
        plural(c.mismatched_8bit_pixels, "pixel", "pixels"),
        if c.unexplained_8bit > 0 {
            format!(
                "; {} NOT explained so",
                plural(c.unexplained_8bit, "difference is", "differences are")
            )
        } else {
            String::new()
        }
    ));
    if c.sign_ambiguous_pixels > 0 {
        s.push_str(&format!(
            "{} luminance is 0 to within f32 rounding (channels cancel), so either black or the scaled colour is right; {} of their codes differ from the reference's\n",
            plural(c.sign_ambiguous_pixels, "pixel's", "pixels'"),
            thousands(c.ambiguous_8bit)
        ));
    }
    if let Some((x, y, ch, e, r, lo, hi)) = c.first_outside {
        s.push_str(&format!(
            "{} channel values are outside their bound; the first: pixel ({x}, {y}) {}: emulated {e:.9}, reference {r:.9}, allowed [{lo:.9}, {hi:.9}]\n",
            thousands(c.outside_bound),
            ["R", "G", "B"][ch]
        ));
    }
    s.push_str(&format!(
        "pixels: {} clipped (a channel ≥ 1 before saturation), {} black (Lw = 0), {} with negative luminance (shown black){}\n",
        thousands(c.saturated_pixels),
        thousands(c.zero_luminance_pixels),
        thousands(c.negative_luminance_pixels),
        if c.nonfinite_pixels > 0 {
            format!(
                ", {} non-finite (not compared)",
                thousands(c.nonfinite_pixels)
            )
        } else {
            String::new()
        }
    ));
    if let Some(p) = written {
        s.push_str(&format!(
            "wrote {p} ({}×{}, 8-bit sRGB)\n",
            t.width, t.height
        ));
    }
    s
}

/// The JSON `ps30 tonemap --json` prints.
pub fn json(image: &str, t: &ToneMapped, written: Option<&str>) -> serde_json::Value {
    let op = &t.operator;
    let c = &t.check;
    serde_json::json!({
        "image": image,
        "width": t.width,
        "height": t.height,
        "output": written,
        "drawn_by": t.luminance.drawn_by,
        "log_average": shape::real(t.luminance.log_average),
        "reference_log_average": shape::real(t.luminance.reference_log_average),
        "log_average_relative_error": shape::real(t.luminance.relative_error),
        "log_average_relative_tolerance": shape::real(t.luminance.relative_tolerance),
        "luminance_agrees": t.luminance.all_agree(),
        "block": [t.luminance.block.0, t.luminance.block.1],
        "key": shape::real(op.key),
        "white": shape::real(op.white),
        "white_source": op.white_source,
        "white_scaled": shape::real(op.white_scaled()),
        "scale": shape::real(op.scale()),
        "pass": crate::present::luminance::pass_cost_json("tonemap", &t.cost),
        "pixels": c.pixels,
        "checked_pixels": c.checked_pixels,
        "nonfinite_pixels": c.nonfinite_pixels,
        "zero_luminance_pixels": c.zero_luminance_pixels,
        "negative_luminance_pixels": c.negative_luminance_pixels,
        "sign_ambiguous_pixels": c.sign_ambiguous_pixels,
        "saturated_pixels": c.saturated_pixels,
        "max_error": shape::real(c.max_error),
        "max_error_bound": shape::real(c.max_error_bound),
        "largest_bound_fraction": shape::real(c.largest_bound_fraction),
        "outside_bound": c.outside_bound,
        "mismatched_8bit_channels": c.mismatched_8bit_channels,
        "mismatched_8bit_pixels": c.mismatched_8bit_pixels,
        "unexplained_8bit": c.unexplained_8bit,
        "ambiguous_8bit": c.ambiguous_8bit,
        "agree": t.all_agree(),
    })
}
