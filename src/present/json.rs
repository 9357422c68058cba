//! The shapes every command's `--json` shares, written once: count ranges,
//! real numbers, diagnostics, costs and limits. `docs/json-schema/ps30.json`
//! describes them (and each command's output) as a JSON Schema, and
//! `tests/json_schema.rs` holds every command's output to it.
//!
//! * A count that can depend on data is always `{"min": n, "max": n}`, even
//!   when exact (`min == max`).
//! * A real number that is not finite (NaN, ±∞) is `null`; the field's
//!   description says what `null` means there. An f32 a person gave or a
//!   table sets (δ, constants, a brightness) is written with the shortest
//!   decimal that reads back to the same f32 (`0.0001`, not
//!   `0.00009999999747378752`); an f32 the emulator computed is written
//!   exactly (every f32 is an f64), to be compared with an f64 reference.
//! * Limits are `{"name", "slots", "executed"}` (a whole profile adds
//!   `rep_count` and `loop_nesting`), never `max_slots` beside a count.
//! * Problems are `diagnostics`: objects with `severity`, `message`, where
//!   (`file`, `line`, `column`) and `count` — identical problems at several
//!   places are one object with their count and line range. An error
//!   carries `code`, Microsoft's `X####` for the same refusal; `strict` marks
//!   a warning for a documented rule Microsoft's assembler does not
//!   enforce, an error under `--strict`.

use crate::core::cost::{Profile, Range};
use crate::core::diag::{Diagnostic, SourceFile};
use serde_json::{json, Value};

/// A count range: always `{"min", "max"}`.
pub fn range(r: Range) -> Value {
    json!({"min": r.min, "max": r.max})
}

/// A real number, `null` when not finite.
pub fn real(v: f64) -> Value {
    if v.is_finite() {
        json!(v)
    } else {
        Value::Null
    }
}

/// An f32 as the shortest decimal that reads back to it, `null` when not
/// finite.
pub fn real32(v: f32) -> Value {
    if !v.is_finite() {
        return Value::Null;
    }
    // f32's Display is the shortest round-trip decimal; read as f64 it is
    // the number a person wrote (0.0001), not the f32's binary value.
    let shortest: f64 = v.to_string().parse().unwrap_or(v as f64);
    json!(shortest)
}

/// Four f32 components.
pub fn real32x4(v: [f32; 4]) -> Value {
    Value::Array(v.iter().map(|&x| real32(x)).collect())
}

/// A profile's limits: `{"name", "slots", "executed"}`.
pub fn limits(p: &Profile) -> Value {
    json!({"name": p.name, "slots": p.max_slots, "executed": p.max_executed})
}

/// Diagnostics of one source, identical ones grouped (see
/// [`crate::core::diag::Diagnostics::grouped`]).
pub fn diagnostics(kind: &str, file: &SourceFile, items: &[Diagnostic]) -> Vec<Value> {
    crate::core::diag::group(items)
        .iter()
        .map(|d| diagnostic(kind, Some(file), d))
        .collect()
}

/// One diagnostic of a `kind` (`validation`, `unset_constant`, …; the
/// schema lists them). Without a file (a problem of the command line, not
/// of a source) `file`, `line`, `column` and `lines` are null.
pub fn diagnostic(kind: &str, file: Option<&SourceFile>, d: &Diagnostic) -> Value {
    let place = file.map(|f| (f.name.clone(), f.line_col(d.span.start), d.line_range(f)));
    json!({
        "severity": match d.severity {
            crate::core::diag::Severity::Error => "error",
            crate::core::diag::Severity::Warning => "warning",
        },
        "kind": kind,
        "message": d.message,
        "code": d.code,
        "strict": d.strict,
        "label": d.label,
        "help": d.help,
        "notes": d.notes,
        "file": place.as_ref().map(|p| p.0.clone()),
        "line": place.as_ref().map(|p| p.1 .0),
        "column": place.as_ref().map(|p| p.1 .1),
        "count": d.count(),
        "lines": place.as_ref().map(|p| json!({"first": p.2 .0, "last": p.2 .1})),
    })
}

/// Draw findings of a shader (divergent gradients, LOD far from level 0),
/// grouped, in the shape of [`diagnostic`] with their `kind`.
pub fn findings(shader: &str, found: &[crate::core::emu::findings::Finding]) -> Vec<Value> {
    crate::core::emu::findings::grouped(found)
        .iter()
        .map(|g| {
            let f = g.first;
            json!({
                "severity": "warning",
                "kind": f.kind,
                "message": f.message,
                "code": null,
                "strict": false,
                "label": f.label,
                "help": f.help,
                "notes": [],
                "file": shader,
                "line": f.site.line,
                "column": f.site.column,
                "count": g.count,
                "lines": {"first": g.lines.0, "last": g.lines.1},
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn f32_values_print_as_written() {
        assert_eq!(real32(1e-4).to_string(), "0.0001");
        assert_eq!(real32(0.27).to_string(), "0.27");
        assert_eq!(real32(f32::NEG_INFINITY), Value::Null);
        assert_eq!(real(f64::NAN), Value::Null);
        assert_eq!(range(Range::exact(7)), json!({"min": 7, "max": 7}));
    }
}
