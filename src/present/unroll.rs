//! What `ps30 unroll` prints before (or instead of) the shaders: the
//! generated files with their figures, the configurations and the problems.

use crate::core::numbers::{size, thousands};
use crate::jobs::gen::profile_text;
use crate::jobs::gen::set::{Bundle, Role};

/// The text summary of a bundle (what `ps30 unroll` prints before or
/// instead of the shaders).
pub fn summary_text(b: &Bundle) -> String {
    let mut s = format!(
        "ps30 unroll for a {} frame; profile {}: {}\n",
        size(b.frame[0], b.frame[1]),
        b.profile.name,
        profile_text(&b.profile)
    );
    for n in &b.notes {
        s.push_str(&format!("  {n}\n"));
    }
    s.push('\n');
    if b.shaders.is_empty() {
        s.push_str("no shader generated\n");
    }
    let wf = b
        .shaders
        .iter()
        .map(|g| g.file.chars().count())
        .max()
        .unwrap_or(4);
    if !b.shaders.is_empty() {
        s.push_str(&format!(
            "{:<wf$}  {:<11}  {:<12}  {:>9}  {:>6}  {:>11}\n",
            "file", "role", "form", "size", "slots", "executed/px"
        ));
    }
    for g in &b.shaders {
        s.push_str(&format!(
            "{:<wf$}  {:<11}  {:<12}  {:>9}  {:>6}  {:>11}\n",
            g.file,
            match g.role {
                Role::Pass1 => "pass 1",
                Role::LastColumn => "last column",
                Role::Pass2 => "pass 2",
            },
            g.form,
            size(g.size[0], g.size[1]),
            thousands(g.slots),
            thousands(g.executed)
        ));
    }
    for c in &b.configs {
        s.push_str(&format!(
            "\n{} {} blocks → {} target: {} + {}{}",
            c.form.name(),
            size(c.block[0], c.block[1]),
            size(c.targets[0], c.targets[1]),
            c.pass1,
            c.pass2
                .as_deref()
                .unwrap_or("(no pass 2: a third pass would be needed)"),
            match c.total_executed {
                Some(t) => format!(", {} executed for the frame", thousands(t)),
                None => String::new(),
            }
        ));
        s.push_str(&format!(
            "\n  padding: {} samples with BORDER addressing",
            thousands(c.padded_border)
        ));
        if let Some(l) = &c.last_column {
            s.push_str(&format!(
                ", {} when {l} draws the last column",
                thousands(c.padded_last_column)
            ));
        }
        s.push('\n');
    }
    for p in &b.problems {
        s.push_str(&format!("\ndoes not fit: {p}"));
    }
    if !b.problems.is_empty() {
        s.push('\n');
    }
    s
}
