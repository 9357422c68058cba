//! What `ps30 check` prints: the text breakdown of an analysis and its JSON
//! form.

use crate::core::cost::{Analysis, Verdict};
use crate::core::numbers::{range_json, range_text, thousands};
use serde_json::{json, Value};

/// The text breakdown of `ps30 check`.
pub fn check_text(name: &str, a: &Analysis) -> String {
    let mut out = String::new();
    let p = &a.profile;
    out.push_str(&format!(
        "{name}: profile {} ({} slots, {} executed)\n\n",
        p.name,
        thousands(p.max_slots),
        thousands(p.max_executed)
    ));
    let width = a
        .lines
        .iter()
        .map(|l| l.text.chars().count())
        .max()
        .unwrap_or(6)
        .clamp(6, 48);
    out.push_str(&format!(
        "{:>5}  {:<width$}  {:>6}  {:>11}  {:>11}\n",
        "line", "source", "slots", "runs", "executed"
    ));
    for l in &a.lines {
        let text: String = l.text.chars().take(width).collect();
        out.push_str(&format!(
            "{:>5}  {:<width$}  {:>6}  {:>11}  {:>11}\n",
            l.line,
            text,
            thousands(l.slots),
            range_text(l.executions),
            range_text(l.executed)
        ));
    }
    if !a.loops.is_empty() {
        out.push_str(&format!(
            "\n{:>5}  {:<14}  {:>10}  {:>8}  {:>13}  {:>8}  {:>11}\n",
            "line", "loop", "iterations", "entries", "per iteration", "own", "total"
        ));
        for l in &a.loops {
            out.push_str(&format!(
                "{:>5}  {:<14}  {:>10}  {:>8}  {:>13}  {:>8}  {:>11}\n",
                l.line,
                l.header,
                range_text(l.iterations),
                range_text(l.entries),
                range_text(l.cost_per_iteration),
                range_text(l.own_cost_per_iteration),
                range_text(l.total)
            ));
        }
        out.push_str("(per iteration: one pass of the body with its own rep/endrep; own: excluding nested loops)\n");
    }
    out.push('\n');
    let slot_ok = a.slots <= p.max_slots;
    out.push_str(&format!(
        "slots     {:>11} / {:<8} {}\n",
        thousands(a.slots),
        thousands(p.max_slots),
        budget_text(a.slots, a.slots, p.max_slots)
    ));
    out.push_str(&format!(
        "executed  {:>11} / {:<8} {}\n",
        range_text(a.executed),
        thousands(p.max_executed),
        budget_text(a.executed.min, a.executed.max, p.max_executed)
    ));
    for r in &a.reasons {
        out.push_str(&format!("  note: {r}\n"));
    }
    out.push_str(match (a.verdict, slot_ok) {
        (Verdict::Within, _) => "verdict: within limits\n",
        (Verdict::MayExceed, _) => "verdict: MAY EXCEED the executed limit on some data\n",
        (Verdict::Exceeds, _) => "verdict: EXCEEDS the limits\n",
    });
    out
}

fn budget_text(min: u64, max: u64, limit: u64) -> String {
    if max <= limit {
        format!("ok ({} to spare)", thousands(limit - max))
    } else if min == u64::MAX {
        // Saturated: at least this much over, no honest percentage.
        format!("OVER by more than {}", thousands(u64::MAX - 1 - limit))
    } else if min > limit {
        format!(
            "OVER by {} ({:.1}%)",
            thousands(min - limit),
            (min - limit) as f64 * 100.0 / limit as f64
        )
    } else {
        let more = if max == u64::MAX { "more than " } else { "" };
        format!(
            "longest path OVER by {more}{}",
            thousands(max - u64::from(max == u64::MAX) - limit)
        )
    }
}

/// The JSON form of `ps30 check`.
pub fn check_json(name: &str, a: &Analysis, warnings: &[String]) -> Value {
    json!({
        "file": name,
        "profile": a.profile.name,
        "slots": a.slots,
        "executed": if a.executed.is_exact() { json!(a.executed.min) } else { Value::Null },
        "executed_min": a.executed.min,
        "executed_max": a.executed.max,
        // u64::MAX is "at least this many": the count saturated.
        "executed_saturated": a.executed.max == u64::MAX,
        "data_dependent": a.data_dependent,
        "reasons": a.reasons,
        "max_slots": a.profile.max_slots,
        "max_executed": a.profile.max_executed,
        "within_limits": a.verdict == Verdict::Within,
        "verdict": a.verdict,
        "loops": a.loops.iter().map(|l| json!({
            "line": l.line,
            "header": l.header,
            "iterations": range_json(l.iterations),
            "entries": range_json(l.entries),
            "cost_per_iteration": range_json(l.cost_per_iteration),
            "own_cost_per_iteration": range_json(l.own_cost_per_iteration),
            "total": range_json(l.total),
        })).collect::<Vec<_>>(),
        "lines": a.lines.iter().map(|l| json!({
            "line": l.line,
            "source": l.text,
            "slots": l.slots,
            "executions": range_json(l.executions),
            "executed": range_json(l.executed),
        })).collect::<Vec<_>>(),
        "warnings": warnings,
    })
}
