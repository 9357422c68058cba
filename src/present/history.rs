//! What `ps30 render --pixel` prints: one watched pixel's history through a
//! draw list ([`crate::jobs::render::history`]) as text a person reads top
//! to bottom — each step that changed the target, each primitive that
//! reached the pixel with its inputs, outputs and tests, the blend and the
//! value after — and the same facts as JSON.

use crate::jobs::render::history::{BlendVerdict, Fragment, History, Named, StepHistory};
use serde_json::Value;

/// `(1, 0.5, 0, 1)`: every component exactly (the shortest text that
/// reads back to the same float).
fn vec4<T: std::fmt::Display>(v: &[T]) -> String {
    let parts: Vec<String> = v.iter().map(|c| c.to_string()).collect();
    format!("({})", parts.join(", "))
}

fn named(list: &[Named]) -> String {
    let parts: Vec<String> = list
        .iter()
        .map(|n| match n.register.as_str() {
            "vFace" | "oDepth" => format!("{} {}", n.register, n.value[0]),
            _ => format!("{} {}", n.register, vec4(&n.value)),
        })
        .collect();
    parts.join("  ")
}

/// The blend line: `ONE ONE ADD: (s) × (fs) + (d) × (fd) → (r)`.
fn blend_line(step: &StepHistory, b: &BlendVerdict) -> String {
    let merger = step.merger.unwrap_or_default();
    let eq = super::render::blend_text(&merger.blend);
    let body = match &b.terms {
        None => format!("{} replaces {}", vec4(&b.source), vec4(&b.dest)),
        Some(t) => {
            let factor = |f: &[Option<f64>; 4]| {
                let parts: Vec<String> = f
                    .iter()
                    .map(|x| x.map_or("-".into(), |x| x.to_string()))
                    .collect();
                format!("({})", parts.join(", "))
            };
            format!(
                "source {} × {}, destination {} × {}",
                vec4(&t.source),
                factor(&t.source_factor),
                vec4(&t.dest),
                factor(&t.dest_factor)
            )
        }
    };
    let mask = if merger.write == crate::core::merge::ColorWrite::ALL {
        String::new()
    } else {
        format!(", write {}", merger.write.letters())
    };
    format!("{eq}{mask}: {body} → {}", vec4(&b.result))
}

fn fate_text(f: &Fragment, output: usize) -> String {
    match f.fate {
        "written" => "written".into(),
        "helper" => "helper: ran for its quad's gradients, wrote nothing".into(),
        "killed" => "discarded by texkill".into(),
        "clipped" => format!(
            "removed by clip plane {}",
            f.clip_plane.map_or(String::new(), |p| p.to_string())
        ),
        "alpha_test" => "discarded by the alpha test".into(),
        "stencil_test" => "failed the stencil test".into(),
        "depth_test" => "failed the depth test".into(),
        "no_output" => format!("the shader wrote no oC{output}: the target is left alone"),
        other => other.to_string(),
    }
}

fn fragment_text(out: &mut String, step: &StepHistory, f: &Fragment) {
    let head = match &f.primitive {
        Some(p) => {
            let corners: Vec<String> = p
                .corners
                .iter()
                .map(|c| format!("({}, {})", c[0], c[1]))
                .collect();
            // 0 rather than −0 for a weight on an edge.
            let w: Vec<String> = p.weights[..p.corners.len()]
                .iter()
                .map(|w| (w + 0.0).to_string())
                .collect();
            let kind = if p.corners.len() == 2 {
                "line"
            } else {
                "triangle"
            };
            format!(
                "{kind} {} ({}; corners {}; weights {})",
                p.index,
                p.face,
                corners.join(" "),
                w.join(", ")
            )
        }
        None => "full-screen quad".into(),
    };
    let coverage = if f.helper { "helper" } else { "covered" };
    out.push_str(&format!(
        "    {head}: {coverage}, {} of its quad covered\n",
        f.quad_covered
    ));
    if !f.inputs.is_empty() {
        out.push_str(&format!("      in      {}\n", named(&f.inputs)));
    }
    if let Some(e) = f.executed {
        let outputs = if f.outputs.is_empty() {
            "nothing written".to_string()
        } else {
            named(&f.outputs)
        };
        out.push_str(&format!("      out     {outputs}; executed {e}\n"));
    }
    if let Some(a) = &f.alpha_test {
        out.push_str(&format!(
            "      alpha   {} (compared as {}) {} {}: {}\n",
            a.alpha,
            a.code,
            a.func,
            a.reference,
            if a.passed { "passed" } else { "failed" }
        ));
    }
    if let Some(st) = &f.stencil {
        out.push_str(&format!(
            "      stencil stored {}: {}; {:?} wrote {}\n",
            st.stored,
            if st.passed { "passed" } else { "failed" },
            st.op,
            st.written
        ));
    }
    if let Some(d) = &f.depth {
        out.push_str(&format!(
            "      depth   incoming {} ({}) {} stored {}: {}\n",
            d.z,
            d.from,
            d.func,
            d.stored,
            match (d.passed, d.written) {
                (true, true) => "passed, written",
                (true, false) => "passed, not written",
                _ => "failed",
            }
        ));
    }
    if let Some(b) = &f.blend {
        out.push_str(&format!("      blend   {}\n", blend_line(step, b)));
    }
    out.push_str(&format!(
        "      → {}\n",
        fate_text(f, step.output.unwrap_or(0))
    ));
}

/// The history as text.
pub fn text(h: &History) -> String {
    let mut out = format!(
        "pixel ({}, {}) of `{}` ({}), {} on the target:\n",
        h.x,
        h.y,
        h.target,
        h.format,
        crate::core::numbers::plural(h.steps.len() as u64, "step", "steps"),
    );
    for s in &h.steps {
        let change = format!("{} → {}", vec4(&s.before), vec4(&s.after));
        match s.kind {
            "draw" => {
                let what = if s.geometry {
                    "geometry"
                } else {
                    "full screen"
                };
                out.push_str(&format!(
                    "  {:>3}  draw   {} ({what}, oC{}): {change}\n",
                    s.step,
                    s.shader.as_deref().unwrap_or(""),
                    s.output.unwrap_or(0)
                ));
                if s.fragments.is_empty() {
                    out.push_str(&format!(
                        "    not covered: {}\n",
                        s.missed.as_deref().unwrap_or("no primitive reached it")
                    ));
                }
                for c in &s.clipped {
                    let vertices: Vec<String> = c.vertices.iter().map(|v| v.to_string()).collect();
                    let noun = if vertices.len() == 1 {
                        "vertex"
                    } else {
                        "vertices"
                    };
                    out.push_str(&format!(
                        "    clipped {} {} ({noun} {}) at {}: beyond the {}\n",
                        c.kind,
                        c.primitive,
                        vertices.join(", "),
                        vec4(&c.position),
                        c.planes.join(" and the ")
                    ));
                }
                for f in &s.fragments {
                    fragment_text(&mut out, s, f);
                }
            }
            kind => out.push_str(&format!("  {:>3}  {kind:<6} {change}\n", s.step)),
        }
    }
    out.push_str(&format!("  last: {}\n", vec4(&h.last)));
    out
}

/// The histories as JSON (non-finite numbers as null).
pub fn json(histories: &[History]) -> Value {
    serde_json::to_value(histories).unwrap_or(Value::Null)
}
