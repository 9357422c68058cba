//! `ps30 decompile`'s output: the verdict of `--verify` as text, and the
//! whole result as JSON (`docs/json-schema/ps30.json`, `decompile`).

use crate::core::decompile::Decompiled;
use crate::jobs::decompile::{Kind, Verdict};
use serde_json::{json, Value};

/// The verdict as comment lines that can follow the HLSL.
pub fn verdict_text(v: &Verdict) -> String {
    let mut out = String::new();
    match v.kind {
        Kind::Refused => {
            out.push_str("// verify: FAILED: Microsoft's compiler refused the HLSL\n");
            for line in v.compiler_messages.lines() {
                out.push_str(&format!("//   {line}\n"));
            }
            return out;
        }
        Kind::Identical => out.push_str(&format!(
            "// verify: identical: {} values of {} draws of {} {}, bit for bit\n",
            v.values,
            v.draws,
            v.pixels,
            unit(v)
        )),
        Kind::WithinBound => {
            out.push_str(&format!(
                "// verify: equivalent within the derived rounding bound: {} of {} values differ \
                 (the largest by {}), each by no more than the bound of both shaders' arithmetic\n",
                v.differing,
                v.values,
                ulps(v.max_ulp)
            ));
            if let Some(w) = &v.worst {
                out.push_str(&divergence(w, v));
            }
        }
        Kind::Different => {
            out.push_str(&format!(
                "// verify: FAILED: {} of {} values differ, {} beyond the derived rounding bound; \
                 the largest by {}\n",
                v.differing,
                v.values,
                v.unexplained,
                ulps(v.max_ulp)
            ));
            if let Some(w) = &v.first_unexplained {
                out.push_str(&format!(
                    "//   first beyond the bound: {}",
                    &divergence(w, v)[5..]
                ));
            }
            if let Some(w) = &v.worst {
                out.push_str(&format!("//   largest: {}", &divergence(w, v)[5..]));
            }
        }
    }
    if !v.explained_by.is_empty() {
        out.push_str(&format!("//   roundings: {}\n", v.explained_by.join("; ")));
    }
    if !v.changed_instructions.is_empty() {
        out.push_str(&format!(
            "//   the compiler changed: {}\n",
            v.changed_instructions.join(", ")
        ));
    }
    out
}

/// One differing value as a comment line.
fn divergence(w: &crate::jobs::decompile::Divergence, v: &Verdict) -> String {
    let bound = match w.bound {
        Some(e) => format!("bound {e:e}"),
        None => "no bound derived".into(),
    };
    let at = if v.stage == crate::core::profile::Stage::Vertex {
        format!("vertex {}", w.x)
    } else {
        format!("pixel ({}, {})", w.x, w.y)
    };
    format!(
        "//   draw {} {at} {}: original {:e}, recompiled {:e}, difference {:e}, {bound}\n",
        w.draw,
        w.output,
        w.original,
        w.recompiled,
        (w.original - w.recompiled).abs()
    )
}

/// What a draw is made of: pixels, or vertices.
fn unit(v: &Verdict) -> &'static str {
    if v.stage == crate::core::profile::Stage::Vertex {
        "vertices"
    } else {
        "pixels"
    }
}

fn ulps(n: u64) -> String {
    if n == u64::MAX {
        "a NaN or infinity against a number".into()
    } else {
        format!("{n} ulp")
    }
}

/// The JSON of `ps30 decompile --json`.
pub fn json(source: &str, d: &Decompiled, verdict: Option<&Verdict>) -> Value {
    json!({
        "source": source,
        "target": d.target.profile,
        "instructions": d.instructions,
        "statements": d.statements,
        "named_uniforms": d.named_uniforms,
        "hlsl": d.hlsl,
        "verify": verdict,
    })
}
