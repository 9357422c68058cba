//! What `ps30 check` and `ps30 expand` print: the text breakdown of an
//! analysis and the JSON forms of both.

use crate::core::audit;
use crate::core::cost::{table_differences, Analysis, LineCost, Range, TableDifference, Verdict};
use crate::core::ir::Shader;
use crate::core::isa::{SlotCount, SlotTable};
use crate::core::load::Loaded;
use crate::core::numbers::thousands;
use crate::present::json;
use serde::Serialize;
use serde_json::{json, Value};

/// The text breakdown of `ps30 check`.
pub fn check_text(name: &str, shader: &Shader, a: &Analysis) -> String {
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
            l.executions.text(),
            l.executed.text()
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
                l.iterations.text(),
                l.entries.text(),
                l.cost_per_iteration.text(),
                l.own_cost_per_iteration.text(),
                l.total.text()
            ));
        }
        out.push_str("(per iteration: one pass of the body with its own rep/endrep; own: excluding nested loops)\n");
    }
    out.push('\n');
    let slot_ok = a.slots <= p.max_slots;
    out.push_str(&format!(
        "slots     {:>11} / {:<8} {}, {}\n",
        thousands(a.slots),
        thousands(p.max_slots),
        budget_text(a.slots, a.slots, p.max_slots),
        table_text(p.slot_table, a.split)
    ));
    if let Some(line) = other_table_line(shader, p.slot_table) {
        out.push_str(&format!("  {line}\n"));
    }
    out.push_str(&format!(
        "executed  {:>11} / {:<8} {}\n",
        a.executed.text(),
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

/// How the slot line names the table it counted with: Microsoft's count
/// with its split as the listing prints it, or the documented table.
fn table_text(table: SlotTable, split: SlotCount) -> String {
    match table {
        SlotTable::Fxc => format!(
            "Microsoft's count ({} texture, {} arithmetic)",
            split.texture, split.arithmetic
        ),
        SlotTable::Documented => "documented table".to_string(),
    }
}

/// The other table's count, when it differs for this shader, with the
/// instructions that make the difference:
/// `documented table: 37 slots (+4: 2 lrp +1 each, 1 texldb +5 …)`.
fn other_table_line(shader: &Shader, used: SlotTable) -> Option<String> {
    let diffs = table_differences(shader);
    if diffs.is_empty() {
        return None;
    }
    let other = match used {
        SlotTable::Fxc => SlotTable::Documented,
        SlotTable::Documented => SlotTable::Fxc,
    };
    // Differences are documented minus Microsoft's: flip them for the
    // other direction.
    let sign = if other == SlotTable::Documented {
        1
    } else {
        -1
    };
    let total: i64 = diffs.iter().map(|d| i64::from(d.count) * d.each).sum();
    let count = shader.info().total(other);
    let split = match other {
        SlotTable::Fxc => format!(
            "{} texture, {} arithmetic; ",
            count.texture, count.arithmetic
        ),
        SlotTable::Documented => String::new(),
    };
    let parts: Vec<String> = diffs.iter().map(|d| difference_text(d, sign)).collect();
    Some(format!(
        "{}: {} slots ({split}{:+}: {})",
        other.title(),
        thousands(u64::from(count.total())),
        sign * total,
        parts.join(", ")
    ))
}

/// One kind of difference: `1 texldb +5`, `2 lrp +1 each`.
fn difference_text(d: &TableDifference, sign: i64) -> String {
    let each = if d.count > 1 { " each" } else { "" };
    format!(
        "{} {} {:+}{each}",
        thousands(u64::from(d.count)),
        d.instruction,
        sign * d.each
    )
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

/// The short form `ps30 check --quiet` prints: the budgets (the other
/// slot table's count too, where it differs) and the verdict.
pub fn check_text_short(name: &str, shader: &Shader, a: &Analysis) -> String {
    let full = check_text(name, shader, a);
    let other = [SlotTable::Fxc, SlotTable::Documented].map(|t| format!("  {}:", t.title()));
    let tail: Vec<&str> = full
        .lines()
        .filter(|l| {
            l.starts_with("slots ")
                || l.starts_with("executed ")
                || l.starts_with("verdict")
                || other.iter().any(|o| l.starts_with(o.as_str()))
        })
        .collect();
    tail.join("\n") + "\n"
}

/// The audit findings and validator warnings of a loaded shader, as JSON
/// diagnostics (grouped).
pub fn diagnostics_json(loaded: &Loaded, found: &[audit::Finding]) -> Vec<Value> {
    let mut out = json::diagnostics("validation", &loaded.file, &loaded.warnings.items);
    out.extend(found.iter().map(|f| {
        let file = f.span.map(|_| &loaded.file);
        json::diagnostic(f.kind.name(), file, &f.diagnostic())
    }));
    out
}

/// The JSON form of `ps30 check`. `crc32` is the CRC-32 of the shader's
/// bytecode, when the caller has it (see the command's docs for which bytes).
pub fn check_json<'a>(
    loaded: &Loaded,
    a: &'a Analysis,
    found: &[audit::Finding],
    crc32: Option<u32>,
) -> CheckJson<'a> {
    let info = loaded.shader.info();
    let fxc = info.total(SlotTable::Fxc);
    let head = json!({
        "shader": loaded.file.name,
        "crc32": crc32.map(crate::core::bytecode::crc32_hex),
        "limits": json::limits(&a.profile),
        "slots": a.slots,
        "slot_table": a.profile.slot_table,
        "fxc_slots": {
            "total": fxc.total(),
            "texture": fxc.texture,
            "arithmetic": fxc.arithmetic,
        },
        "documented_slots": info.total(SlotTable::Documented).total(),
        "slot_differences": table_differences(&loaded.shader),
        "executed": json::range(a.executed),
        // u64::MAX is "at least this many": the count saturated.
        "executed_saturated": a.executed.max == u64::MAX,
        "data_dependent": a.data_dependent,
        "reasons": a.reasons,
        "within_limits": a.verdict == Verdict::Within,
        "verdict": a.verdict,
        "loops": a.loops.iter().map(|l| json!({
            "line": l.line,
            "header": l.header,
            "iterations": json::range(l.iterations),
            "entries": json::range(l.entries),
            "cost_per_iteration": json::range(l.cost_per_iteration),
            "own_cost_per_iteration": json::range(l.own_cost_per_iteration),
            "total": json::range(l.total),
        })).collect::<Vec<_>>(),
        "diagnostics": diagnostics_json(loaded, found),
    });
    CheckJson {
        head,
        lines: Lines(&a.lines),
    }
}

/// `check --json`: the analysis as one map, and beside it the per-line costs
/// (one entry per source line: most of the output for a long shader),
/// serialised straight from the analysis as they are written rather than
/// built as a tree of values first.
#[derive(Serialize)]
pub struct CheckJson<'a> {
    #[serde(flatten)]
    head: Value,
    lines: Lines<'a>,
}

impl CheckJson<'_> {
    /// Adds a field beside the analysis (`constant_table`).
    pub fn insert(&mut self, key: &str, value: Value) {
        self.head[key] = value;
    }
}

/// The per-line costs of `check --json`, each as
/// `{line, source, slots, executions, executed}`.
struct Lines<'a>(&'a [LineCost]);

impl Serialize for Lines<'_> {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        #[derive(Serialize)]
        struct Line<'a> {
            line: usize,
            source: &'a str,
            slots: u64,
            executions: Range,
            executed: Range,
        }
        s.collect_seq(self.0.iter().map(|l| Line {
            line: l.line,
            source: &l.text,
            slots: l.slots,
            executions: l.executions,
            executed: l.executed,
        }))
    }
}

/// The JSON form of `ps30 expand`.
pub fn expand_json(
    loaded: &Loaded,
    found: &[audit::Finding],
    output: Option<&std::path::Path>,
    assembly: &str,
) -> Value {
    json!({
        "shader": loaded.file.name,
        "slots": loaded.shader.info().total(SlotTable::Fxc).total(),
        "instructions": loaded.shader.instructions().len(),
        "output": output.map(|p| p.display().to_string()),
        "assembly": assembly,
        "diagnostics": diagnostics_json(loaded, found),
    })
}
