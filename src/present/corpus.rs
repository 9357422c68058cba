//! Corpus mode's output: one line per file (a table line, or one JSON
//! object per line with `--json`) as results arrive, and the summary the run
//! ends with (see [`crate::jobs::corpus`]).

use crate::core::numbers::{plural, thousands};
use crate::jobs::corpus::{FileResult, Status, Summary};

/// One file as a table line: its status (`ok`, `over`, or the code of its
/// error, `refused` without one), the file, and what the command found or
/// the first error.
pub fn line(r: &FileResult) -> String {
    let status = match r.status {
        Status::Accepted => "ok".to_string(),
        Status::Over => "over".to_string(),
        Status::Refused => r.code.clone().unwrap_or_else(|| "refused".into()),
    };
    let mut facts: Vec<String> = r
        .facts
        .iter()
        .map(|(k, v)| format!("{k} {}", fact(v)))
        .collect();
    if !r.over.is_empty() {
        facts.push(format!("over {}", r.over.join(", ")));
    }
    if let Some(o) = &r.output {
        facts.push(format!("-> {o}"));
    }
    let detail = match (&r.error, r.status) {
        (Some(e), Status::Refused) => e.clone(),
        _ => facts.join(", "),
    };
    format!("{status:<7} {}  {detail}\n", r.path)
}

/// A fact's value as text: a string as it is, a number with thousands
/// separators, a range `{"min", "max"}` as `n` or `min–max`.
fn fact(v: &serde_json::Value) -> String {
    let n = |v: &serde_json::Value| v.as_u64().map(thousands);
    match v {
        serde_json::Value::String(s) => s.clone(),
        serde_json::Value::Object(o) => {
            match (o.get("min").and_then(n), o.get("max").and_then(n)) {
                (Some(a), Some(b)) if a == b => a,
                (Some(a), Some(b)) => format!("{a}–{b}"),
                _ => v.to_string(),
            }
        }
        other => n(other).unwrap_or_else(|| other.to_string()),
    }
}

/// One file as one line of JSON.
pub fn json_line(r: &FileResult) -> String {
    let mut s = serde_json::to_string(r).unwrap_or_default();
    s.push('\n');
    s
}

/// The summary as text: the counts, refusals by code, files over each
/// limit, and the most frequent diagnostics.
pub fn summary_text(s: &Summary) -> String {
    let n = |v: u64| thousands(v);
    let mut out = format!(
        "{}: {} accepted, {} over a limit, {} refused\n",
        plural(s.files, "file", "files"),
        n(s.accepted),
        n(s.over),
        n(s.refused)
    );
    if !s.refused_by_code.is_empty() {
        let by: Vec<String> = s
            .refused_by_code
            .iter()
            .map(|(c, k)| match c.as_str() {
                "none" => format!("without a code {}", n(*k)),
                _ => format!("{c} {}", n(*k)),
            })
            .collect();
        out.push_str(&format!("refused by code: {}\n", by.join(", ")));
    }
    if !s.over_by_limit.is_empty() {
        let by: Vec<String> = s
            .over_by_limit
            .iter()
            .map(|(l, k)| format!("{l} {}", n(*k)))
            .collect();
        out.push_str(&format!("over the limit of: {}\n", by.join(", ")));
    }
    if !s.most_frequent.is_empty() {
        out.push_str("most frequent diagnostics:\n");
        for (text, k) in &s.most_frequent {
            out.push_str(&format!("{:>7}  {text}\n", n(*k)));
        }
    }
    out
}

/// The summary as the last JSON line: `{"summary": {…}}`.
pub fn summary_json(s: &Summary) -> String {
    let mut out = serde_json::to_string(&serde_json::json!({ "summary": s })).unwrap_or_default();
    out.push('\n');
    out
}
