//! What `ps30 profile` prints: costs per pixel and per quad with
//! histograms, divergence, gradient sites and findings, and (`--lines`)
//! what each source line cost, as text and JSON.

use crate::core::audit;
use crate::core::cost::Range;
use crate::core::emu::findings::diagnostic;
use crate::core::emu::findings::{Finding, SiteSummary};
use crate::core::emu::lines::LineRuns;
use crate::core::numbers::{decimal, thousands};
use crate::jobs::profile::list::ListProfile;
use crate::jobs::profile::{CostStats, ProfileRun, QuadCosts};
use crate::present::json;
use serde_json::{json, Value};

fn histogram_text(s: &mut String, title: &str, stats: &CostStats) {
    let most = stats
        .histogram
        .iter()
        .map(|b| b.count)
        .max()
        .unwrap_or(0)
        .max(1);
    s.push_str(&format!("{title}\n"));
    for b in &stats.histogram {
        let range = if b.lo == b.hi {
            thousands(b.lo)
        } else {
            format!("{}–{}", thousands(b.lo), thousands(b.hi))
        };
        let bar = "█".repeat(((b.count * 40).div_ceil(most)) as usize);
        s.push_str(&format!(
            "  {range:>13}  {:>9}  {bar}\n",
            thousands(b.count)
        ));
    }
}

/// The cost table, the divergence line and the per-quad histogram.
fn costs_text(s: &mut String, c: &QuadCosts) {
    s.push_str(&format!(
        "{:<22}{:>10}{:>12}{:>10}\n",
        "executed slots", "min", "mean", "max"
    ));
    for (name, st) in [("  per pixel", &c.per_pixel), ("  per quad", &c.per_quad)] {
        s.push_str(&format!(
            "{name:<22}{:>10}{:>12}{:>10}\n",
            thousands(st.min),
            decimal(st.mean, 2),
            thousands(st.max)
        ));
    }
    s.push_str(&format!(
        "divergent quads: {} of {} ({:.1}%); pixels' own slots are {:.1}% of what their quads executed{}\n",
        thousands(c.divergent_quads),
        thousands(c.quads),
        100.0 * c.divergent_quads as f64 / c.quads.max(1) as f64,
        100.0 * c.lockstep_efficiency,
        if c.divergent_quads > 0 {
            format!(" ({:.1}% in the divergent ones)", 100.0 * c.divergent_efficiency)
        } else {
            String::new()
        }
    ));
    histogram_text(s, "slots per quad   quads", &c.per_quad);
}

/// What each source line cost (`profile --lines`), under a heading that
/// names the shader: `quads` adds the columns of a pixel shader's helper
/// lanes and 2×2 quads, which a vertex shader has not.
pub fn lines_text(heading: &str, lines: &[LineRuns], quads: bool) -> String {
    let mut s = format!("{heading}, per source line:\n");
    if lines.is_empty() {
        s.push_str("  (not counted)\n");
        return s;
    }
    let width = lines
        .iter()
        .map(|l| l.text.chars().count())
        .max()
        .unwrap_or(6)
        .clamp(6, 40);
    let mut row = |cells: [&str; 9]| {
        let [line, text, slots, runs, executed, helpers, quad, divergent, lockstep] = cells;
        s.push_str(&format!(
            "{line:>5}  {text:<width$}  {slots:>5}  {runs:>9}  {executed:>9}"
        ));
        if quads {
            s.push_str(&format!(
                "  {helpers:>9}  {quad:>9}  {divergent:>9}  {lockstep:>9}"
            ));
        }
        s.push('\n');
    };
    row([
        "line",
        "source",
        "slots",
        "runs",
        "executed",
        "helpers",
        "quads",
        "divergent",
        "lockstep",
    ]);
    for l in lines {
        let text: String = l.text.chars().take(width).collect();
        row([
            &l.line.to_string(),
            &text,
            &thousands(l.slots),
            &thousands(l.runs),
            &thousands(l.executed),
            &thousands(l.helpers),
            &thousands(l.quads),
            &thousands(l.divergent),
            &thousands(l.lockstep),
        ]);
    }
    s.push_str(if quads { PIXEL_LINES } else { VERTEX_LINES });
    s.push('\n');
    s
}

/// What the columns of a pixel shader's lines count.
const PIXEL_LINES: &str = "(runs: by the pixels drawn; executed: runs × slots; helpers: runs by helper lanes; quads: runs by 2×2 quads in lockstep, divergent: with only part of the quad; lockstep: quads × slots)";

/// What the columns of a vertex shader's lines count.
const VERTEX_LINES: &str = "(runs: by the vertices; executed: runs × slots)";

/// `text` and then, a blank line apart, `more`.
pub fn then(text: &str, more: &str) -> String {
    let gap = if text.ends_with("\n\n") { "" } else { "\n" };
    format!("{text}{gap}{more}")
}

/// The findings as warnings, or the line saying there are none.
fn findings_text(s: &mut String, file: &crate::core::diag::SourceFile, findings: &[Finding]) {
    if findings.is_empty() {
        s.push_str("gradients: no gradient of a temporary ran in a divergent quad; no LOD far from level 0\n");
    } else {
        let all: Vec<_> = findings.iter().map(diagnostic).collect();
        for d in crate::core::diag::group(&all) {
            s.push_str(&d.render(file));
        }
    }
}

/// The text form of `ps30 profile` (findings rendered as warnings).
pub fn text(r: &ProfileRun) -> String {
    let c = &r.costs;
    let mut s = format!("{} on {}\n", r.file.name, r.input);
    s.push_str(&format!(
        "static paths (cost model): shortest {}, longest {} executed slots per pixel; emulated {}–{}{}\n",
        thousands(r.static_executed.min),
        thousands(r.static_executed.max),
        thousands(c.per_pixel.min),
        thousands(c.per_pixel.max),
        if r.counts_agree { " (within)" } else { " (OUTSIDE the static range)" }
    ));
    if !r.within_limits {
        let p = crate::core::cost::Profile::ps_3_0();
        s.push_str(&format!(
            "OVER the ps_3_0 limits of {} slots and {} executed per pixel (ps30 check says where)\n",
            thousands(p.max_slots),
            thousands(p.max_executed)
        ));
    }
    costs_text(&mut s, c);
    if let Some(m) = &r.models {
        let all: u64 = m.iter().map(|x| x.0).sum();
        let ok: u64 = m.iter().map(|x| x.1).sum();
        s.push_str(&format!(
            "light models against the CPU computation: {} of {} pixels match bit for bit (model 0: {}/{}, 1: {}/{}, 2: {}/{})\n",
            thousands(ok),
            thousands(all),
            m[0].1, m[0].0, m[1].1, m[1].0, m[2].1, m[2].0
        ));
    }
    findings_text(&mut s, &r.file, &r.findings);
    s
}

/// The JSON form of `ps30 profile`: the costs, the gradient sites, and
/// every diagnostic (validation, the constants audit, the draw's findings),
/// grouped.
pub fn to_json(r: &ProfileRun, found: &[audit::Finding]) -> Value {
    let mut diagnostics = json::diagnostics("validation", &r.file, &r.warnings.items);
    diagnostics.extend(
        found
            .iter()
            .map(|f| json::diagnostic(f.kind.name(), f.span.map(|_| &r.file), &f.diagnostic())),
    );
    diagnostics.extend(json::findings(&r.file.name, &r.findings));
    let mut j = json!({
        "shader": r.file.name,
        "input": r.input,
        "target": [r.width, r.height],
        "gradients": sites_json(&r.gradients),
        "lines": r.lines,
        "models": r.models.map(|m| m.iter().map(|&(n, ok)| json!({"pixels": n, "match": ok})).collect::<Vec<_>>()),
        "problem": r.problem(),
        "diagnostics": diagnostics,
    });
    add_costs(
        &mut j,
        r.static_executed,
        (r.counts_agree, r.within_limits),
        &r.costs,
    );
    j
}

/// The cost fields `profile` and `profile --list` share, added to `j`:
/// the static and emulated executed counts, whether they agree and fit
/// the limits, and the per-pixel and per-quad statistics.
fn add_costs(j: &mut Value, executed: Range, (agree, within): (bool, bool), costs: &QuadCosts) {
    let fields = json!({
        "executed": json::range(executed),
        "executed_emulated": {"min": costs.per_pixel.min, "max": costs.per_pixel.max},
        "counts_agree": agree,
        "within_limits": within,
        "per_pixel": stats_json(&costs.per_pixel),
        "per_quad": stats_json(&costs.per_quad),
        "quads": costs.quads,
        "divergent_quads": costs.divergent_quads,
        "lockstep_efficiency": json::real(costs.lockstep_efficiency),
        "divergent_efficiency": json::real(costs.divergent_efficiency),
    });
    if let (Some(j), Value::Object(fields)) = (j.as_object_mut(), fields) {
        j.extend(fields);
    }
}

fn stats_json(s: &CostStats) -> Value {
    json!({
        "count": s.count,
        "min": s.min,
        "mean": json::real(s.mean),
        "max": s.max,
        "histogram": s.histogram,
    })
}

fn sites_json(sites: &[SiteSummary]) -> Value {
    sites
        .iter()
        .map(|g| {
            json!({
                "line": g.line,
                "column": g.column,
                "op": g.op,
                "sampler": g.sampler,
                "temp_source": g.temp_source,
                "quads": g.quads,
                "divergent_quads": g.divergent_quads,
                "executions": g.executions,
                "divergent_executions": g.divergent_executions,
                "lod": g.lod.map(|(lo, hi)| json!({"min": json::real32(lo), "max": json::real32(hi)})),
            })
        })
        .collect()
}

/// The text form of `ps30 profile --list`: the draw, its pixel shader's
/// costs over every primitive's quads, its gradients, its vertex shader's
/// runs.
pub fn list_text(list: &str, p: &ListProfile) -> String {
    let c = &p.costs;
    let what = if p.geometry {
        crate::core::numbers::plural(p.primitives, "primitive", "primitives")
    } else {
        "a full-screen quad".to_string()
    };
    let mut s = format!(
        "{list}: step {}, {} over {what} ({} covered pixels in {} quads)\n",
        p.step,
        p.shader,
        thousands(c.per_pixel.count),
        thousands(c.quads)
    );
    s.push_str(&format!(
        "static paths (cost model): shortest {}, longest {} executed slots per pixel; emulated {}–{}{}\n",
        thousands(p.static_executed.min),
        thousands(p.static_executed.max),
        thousands(c.per_pixel.min),
        thousands(c.per_pixel.max),
        if p.counts_agree { " (within)" } else { " (OUTSIDE the static range)" }
    ));
    if !p.within_limits {
        s.push_str("OVER the shader's limits (ps30 check says where)\n");
    }
    costs_text(&mut s, c);
    s.push_str(&format!(
        "quads at primitive edges: {} of {}, with {} helper lanes (run for gradients only)\n",
        thousands(p.edge_quads),
        thousands(c.quads),
        thousands(p.helper_lanes)
    ));
    findings_text(&mut s, &p.file, &p.findings);
    match &p.vertex {
        None => {}
        Some((name, Err(e))) => s.push_str(&format!("vertex shader {name}: not profiled: {e}\n")),
        Some((name, Ok(v))) => {
            let lo = v.executed.iter().min().copied().unwrap_or(0);
            let hi = v.executed.iter().max().copied().unwrap_or(0);
            let total: u64 = v.executed.iter().sum();
            s.push_str(&format!(
                "vertex shader {name} ({}): {} runs, {lo}–{hi} executed slots each ({} in all); the cost model: {}–{}{}\n",
                v.profile,
                thousands(v.executed.len() as u64),
                thousands(total),
                v.model.min,
                v.model.max,
                match (v.within_limits, v.counts_agree) {
                    (true, true) => " (within)",
                    (false, _) => ", OVER a limit",
                    (true, false) => " (a vertex OUTSIDE the model's range)",
                }
            ));
        }
    }
    s
}

/// `ps30 profile --list --lines`' tables: the pixel shader's lines over
/// every primitive's quads, then the vertex shader's over its runs.
pub fn list_lines_text(p: &ListProfile) -> String {
    let mut s = lines_text(&p.shader, &p.lines, true);
    if let Some((name, Ok(v))) = &p.vertex {
        s = then(&s, &lines_text(name, &v.lines, false));
    }
    s
}

/// The JSON form of `ps30 profile --list`.
pub fn list_json(list: &str, p: &ListProfile) -> Value {
    let vertex = p.vertex.as_ref().map(|(name, v)| match v {
        Ok(v) => {
            let mut j = crate::present::vertices::profile_json(name, v);
            j["runs"] = json!(v.executed.len());
            j
        }
        Err(e) => json!({"shader": name, "error": e}),
    });
    let mut j = json!({
        "list": list,
        "step": p.step,
        "shader": p.shader,
        "geometry": p.geometry,
        "primitives": p.primitives,
        "edge_quads": p.edge_quads,
        "helper_lanes": p.helper_lanes,
        "gradients": sites_json(&p.gradients),
        "lines": p.lines,
        "diagnostics": json::findings(&p.file.name, &p.findings),
        "vertex_shader": vertex,
        "problem": p.problem(),
    });
    add_costs(
        &mut j,
        p.static_executed,
        (p.counts_agree, p.within_limits),
        &p.costs,
    );
    j
}
