//! `ps30 run VS --vertices FILE`: each vertex's outputs by register and
//! semantic, as a text table and as JSON.

use crate::core::emu::vertex::VertexOutput;
use crate::jobs::vertices::VertexProfile;
use crate::present::json::real32x4;
use serde_json::{json, Value};
use std::fmt::Write;

/// The text table: a header line, then one line per vertex and output.
pub fn text(shader: &str, profile: &str, out: &VertexOutput) -> String {
    let mut s = format!(
        "{shader}: {profile}, {} vertices, {} outputs\n\n",
        out.values.len(),
        out.slots.len()
    );
    let _ = writeln!(
        s,
        "{:>6}  {:<8}  {:<13}  {:>12}  {:>12}  {:>12}  {:>12}",
        "vertex", "register", "semantic", "x", "y", "z", "w"
    );
    for (v, values) in out.values.iter().enumerate() {
        for (slot, value) in out.slots.iter().zip(values) {
            let semantic = slot
                .semantic
                .as_ref()
                .map_or("-".to_string(), |a| a.to_string());
            let _ = writeln!(
                s,
                "{v:>6}  {:<8}  {:<13}  {:>12}  {:>12}  {:>12}  {:>12}",
                slot.register, semantic, value[0], value[1], value[2], value[3]
            );
        }
    }
    if out.executed.len() != out.values.len() {
        s.push_str("\nexecuted: not counted: run on the GPU\n");
        return s;
    }
    let total: u64 = out.executed.iter().sum();
    let most = out.executed.iter().max().copied().unwrap_or(0);
    let _ = writeln!(
        s,
        "\nexecuted: {total} instruction slots in all, at most {most} for one vertex"
    );
    s
}

/// The JSON: the shader, its profile, the output registers with their
/// semantics, and per vertex the slots it executed (`executed_emulated`,
/// null when a GPU ran it)
/// and its outputs (in the registers' order).
pub fn json(shader: &str, profile: &str, out: &VertexOutput) -> Value {
    let slots: Vec<Value> = out
        .slots
        .iter()
        .map(|s| {
            json!({
                "register": s.register,
                "semantic": s.semantic.as_ref().map(|a| a.to_string()),
            })
        })
        .collect();
    let vertices: Vec<Value> = out
        .values
        .iter()
        .enumerate()
        .map(|(i, values)| {
            // A GPU counts nothing: the field is null there.
            json!({
                "vertex": i,
                "executed_emulated": out.executed.get(i),
                "outputs": values.iter().map(|v| real32x4(*v)).collect::<Vec<_>>(),
            })
        })
        .collect();
    json!({
        "shader": shader,
        "profile": profile,
        "outputs": slots,
        "vertices": vertices,
    })
}

/// `ps30 profile VS --vertices FILE` as text.
pub fn profile_text(shader: &str, p: &VertexProfile) -> String {
    let n = p.executed.len();
    let (lo, hi) = (
        p.executed.iter().min().copied().unwrap_or(0),
        p.executed.iter().max().copied().unwrap_or(0),
    );
    let total: u64 = p.executed.iter().sum();
    let mut s = format!("{shader}: {} over {n} vertices\n\n", p.profile);
    let _ = writeln!(s, "slots               {} / {}", p.slots, p.max_slots);
    let model = if p.model.min == p.model.max {
        p.model.min.to_string()
    } else {
        format!("{} to {}", p.model.min, p.model.max)
    };
    let _ = writeln!(
        s,
        "executed per vertex {lo} to {hi} (the cost model: {model}; limit {})",
        p.max_executed
    );
    let _ = writeln!(s, "executed in all     {total}");
    let verdict = match (p.within_limits, p.counts_agree) {
        (true, true) => "within limits; every vertex's count is in the cost model's range",
        (false, true) => "over a limit",
        (_, false) => "a vertex's count is outside the cost model's range",
    };
    let _ = writeln!(s, "verdict: {verdict}");
    s
}

/// `ps30 profile VS --vertices FILE` as JSON.
pub fn profile_json(shader: &str, p: &VertexProfile) -> Value {
    json!({
        "shader": shader,
        "profile": p.profile,
        "slots": p.slots,
        "limits": {"name": p.profile, "slots": p.max_slots, "executed": p.max_executed},
        "executed": crate::present::json::range(p.model),
        "executed_emulated": p.executed,
        "within_limits": p.within_limits,
        "counts_agree": p.counts_agree,
        "lines": p.lines,
    })
}
