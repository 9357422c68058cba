//! `ps30 shader-test`'s output: a line per file with its probes' counts,
//! a line per probe that did not pass (and per failed or unsupported draw,
//! and where a file stopped), then the totals and the unsupported reasons.
//! `--json` is the job's [`Report`] as it is.

use crate::jobs::shader_test::{FileReport, Report, Verdict};

/// One file's lines.
pub fn file_text(f: &FileReport, verbose: bool) -> String {
    let mut out = String::new();
    let (p, x, u) = f.counts();
    if !f.ran && f.stopped.is_none() {
        out.push_str(&format!(
            "{}: no test lines for shader model 2.0 or 3.0\n",
            f.path
        ));
        return out;
    }
    let model = f
        .model
        .map(|m| format!(" (shader model {m})"))
        .unwrap_or_default();
    out.push_str(&format!(
        "{}{model}: {} probes: {p} passed, {x} failed, {u} unsupported\n",
        f.path,
        f.probes.len()
    ));
    for probe in &f.probes {
        match &probe.verdict {
            Verdict::Pass if verbose => {
                out.push_str(&format!("  {}: pass: {}\n", probe.line, probe.text.trim()))
            }
            Verdict::Pass => {}
            Verdict::Fail { detail } => out.push_str(&format!(
                "  {}: FAIL: {}: {detail}\n",
                probe.line,
                probe.text.trim()
            )),
            Verdict::Unsupported { reason } if verbose => out.push_str(&format!(
                "  {}: unsupported: {}: {reason}\n",
                probe.line,
                probe.text.trim()
            )),
            Verdict::Unsupported { .. } => {}
        }
    }
    for (line, note) in &f.notes {
        out.push_str(&format!("  {line}: {note}\n"));
    }
    if let Some(stop) = &f.stopped {
        out.push_str(&format!("  stopped: {stop}\n"));
    }
    out
}

/// The totals and the unsupported reasons, most first.
pub fn summary_text(r: &Report) -> String {
    let mut out = format!(
        "{} files ({} with test lines for shader model 2.0 or 3.0): {} probes passed, {} failed, {} unsupported\n",
        r.total_files,
        r.files_run,
        r.passed,
        r.failed,
        r.unsupported
    );
    for (reason, n) in &r.unsupported_reasons {
        out.push_str(&format!("  unsupported: {n} × {reason}\n"));
    }
    out
}
