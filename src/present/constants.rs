//! A shader's constant table as `check`, `run` and `disasm` show it: each
//! uniform's name, register, size, type and default, and how to set it, so
//! that a user with a compiled shader knows what to give on the command
//! line.

use crate::core::bytecode::ctab::{ConstantTable, RegisterSet};
use crate::core::bytecode::listing::float_text;
use serde_json::{json, Value};

/// The default of a constant's first register, as text (empty without one).
fn default_text(set: RegisterSet, words: Option<&Vec<u32>>) -> String {
    let Some(words) = words else {
        return String::new();
    };
    let values: Vec<String> = words
        .iter()
        .map(|&w| match set {
            RegisterSet::Float4 => float_text(f32::from_bits(w)),
            RegisterSet::Int4 => (w as i32).to_string(),
            RegisterSet::Bool => (w != 0).to_string(),
            RegisterSet::Sampler => String::new(),
        })
        .collect();
    match values.len() {
        0 => String::new(),
        1 => values[0].clone(),
        _ => format!("({})", values.join(", ")),
    }
}

/// The table as text: one line per constant, then how to set them.
pub fn table_text(t: &ConstantTable) -> String {
    let rows: Vec<[String; 5]> = t
        .constants
        .iter()
        .map(|c| {
            let defaults = c.register_defaults();
            let mut default = default_text(c.set, defaults.first());
            if defaults.len() > 1 {
                default.push_str(&format!(" … ({} registers)", defaults.len()));
            }
            [
                crate::core::bytecode::ctab::escape(&c.name),
                c.register(),
                c.count.to_string(),
                format!("{}{}", c.ty.hlsl(), c.ty.array()),
                default,
            ]
        })
        .collect();
    let head = ["name", "register", "size", "type", "default"];
    let width = |i: usize| {
        rows.iter()
            .map(|r| r[i].chars().count())
            .chain([head[i].len()])
            .max()
            .unwrap_or(0)
    };
    let (w0, w1, w2, w3) = (width(0), width(1), width(2), width(3));
    let mut out = format!(
        "constant table (CTAB) from {}, target {}: {} constant{}\n",
        crate::core::bytecode::ctab::escape(&t.creator),
        crate::core::bytecode::ctab::escape(&t.target),
        t.constants.len(),
        if t.constants.len() == 1 { "" } else { "s" }
    );
    for r in std::iter::once(head.map(String::from)).chain(rows) {
        let line = format!(
            "  {:<w0$}  {:<w1$}  {:>w2$}  {:<w3$}  {}",
            r[0], r[1], r[2], r[3], r[4]
        );
        out.push_str(line.trim_end());
        out.push('\n');
    }
    out.push_str("set them by name or by register: --const NAME=x,y,z,w (c#), --int NAME=… (i#), --bool NAME=… (b#)\n");
    out
}

/// The table as JSON: creator, target, version, flags and the constants
/// (each with its register spelled out).
pub fn table_json(t: &ConstantTable) -> Value {
    json!({
        "creator": t.creator,
        "target": t.target,
        "version": format!("{:#010x}", t.version),
        "flags": t.flags,
        "constants": t.constants.iter().map(|c| json!({
            "name": c.name,
            "register": c.register(),
            "register_set": c.set,
            "register_index": c.index,
            "register_count": c.count,
            "type": c.ty,
            "hlsl": format!("{}{}", c.ty.hlsl(), c.ty.array()),
            "default": c.default,
        })).collect::<Vec<_>>(),
    })
}
