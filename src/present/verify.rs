//! What `ps30 verify` prints: the claims table, the cross-check rows, the
//! tone-mapping lines and the state of the generated shaders.

use crate::jobs::gen::set::GeneratedSet;
use crate::jobs::verify::{Claim, CrossRow, CROSSCHECK_IMAGE};
use crate::present::report::Generated;
use std::path::Path;

/// The claims as a plain-text table for the terminal.
pub fn claims_text(claims: &[Claim]) -> String {
    let w0 = claims
        .iter()
        .map(|c| c.claim.chars().count())
        .max()
        .unwrap_or(5);
    let w1 = claims
        .iter()
        .map(|c| c.article.chars().count())
        .max()
        .unwrap_or(7)
        .max(7);
    let w2 = claims
        .iter()
        .map(|c| c.ps30.chars().count())
        .max()
        .unwrap_or(4)
        .max(4);
    let mut s = format!(
        "{:<w0$}  {:<w1$}  {:<w2$}  agrees\n",
        "claim", "article", "ps30"
    );
    for c in claims {
        s.push_str(&format!(
            "{:<w0$}  {:<w1$}  {:<w2$}  {}\n",
            c.claim,
            c.article,
            c.ps30,
            if c.agrees { "yes" } else { "NO" }
        ));
    }
    s
}

/// Everything `ps30 verify` found, for its text and JSON output.
pub struct Summary<'a> {
    /// Every article claim with ps30's value.
    pub claims: &'a [Claim],
    /// The luminance cross-check on the bundled image.
    pub crosscheck: &'a [CrossRow],
    /// What the report pages and figures show.
    pub figures: &'a Generated,
    /// The committed generated shaders, rebuilt in memory.
    pub set: &'a GeneratedSet,
    /// The generated-shader directory checked; `None` outside a checkout
    /// (no `asm/generated` here and none named), where nothing is checked.
    pub generated: Option<&'a Path>,
    /// Whether `--regenerate` rewrote the stale files instead of failing.
    pub regenerated: bool,
    /// Files under [`Summary::generated`] that differ from what ps30 generates
    /// now (empty after a regeneration).
    pub stale: &'a [String],
    /// `wrote …` / `removed …` lines of a regeneration.
    pub rewritten: &'a [String],
    /// The pages verify wrote itself (claims, cross-check, generated shaders).
    pub pages: [&'a Path; 3],
    /// The reports directory the pages were written to.
    pub reports: &'a Path,
}

impl Summary<'_> {
    /// Every claim, cross-check row and figure as expected, nothing stale.
    pub fn all_agree(&self) -> bool {
        self.claims.iter().all(|c| c.agrees)
            && self.crosscheck.iter().all(|r| r.as_expected())
            && self.figures.all_agree()
            && self.stale.is_empty()
    }
}

/// The text `ps30 verify` prints: the claims, the cross-check rows, the
/// tone-mapping lines, the generated shaders' state and what was written.
pub fn text(s: &Summary) -> String {
    let claims = s.claims;
    let mut out = claims_text(claims);
    out.push_str(&format!(
        "\n{} of {} claims reproduced\n\ncross-check on {} ({}):\n",
        claims.iter().filter(|c| c.agrees).count(),
        claims.len(),
        CROSSCHECK_IMAGE,
        "emulated two-pass L̄w against the f64 reference"
    ));
    for r in s.crosscheck {
        out.push_str(&format!(
            "  {:<8} {} + {} {}×{} {}: {}\n",
            if r.as_expected() { "ok" } else { "UNEXPECTED" },
            r.pass1,
            r.pass2,
            r.block.0,
            r.block.1,
            r.format,
            r.finding
        ));
    }
    out.push_str(&tonemap_text(s.figures));
    let Some(dir) = s.generated else {
        out.push_str(&format!(
            "\ngenerated shaders: {} files for {} frame sizes: not checked (no asm/generated in the \
             current directory; run from a checkout, or name one with --generated DIR)\n",
            s.set.files.len(),
            s.set.frames.len(),
        ));
        out.push_str(&written_text(s));
        return out;
    };
    out.push_str(&format!(
        "\ngenerated shaders: {} files for {} frame sizes in {}: {}\n",
        s.set.files.len(),
        s.set.frames.len(),
        dir.display(),
        if s.regenerated {
            format!("regenerated ({} changed)", s.rewritten.len())
        } else if s.stale.is_empty() {
            "up to date".to_string()
        } else {
            crate::core::numbers::plural(s.stale.len() as u64, "PROBLEM", "PROBLEMS")
        }
    ));
    for r in s.rewritten.iter().chain(s.stale) {
        out.push_str(&format!("  {r}\n"));
    }
    out.push_str(&written_text(s));
    out
}

/// The lines naming the pages and figures written.
fn written_text(s: &Summary) -> String {
    let mut out = String::new();
    let [claims_path, cross_path, gen_path] = s.pages;
    out.push_str(&format!(
        "\nreports written to {}, {} and {}\n",
        claims_path.display(),
        cross_path.display(),
        gen_path.display()
    ));
    out.push_str(&format!(
        "figures and pages: {} (index: {})\n",
        s.figures.files.len(),
        s.reports.join("README.md").display()
    ));
    out
}

/// The JSON `ps30 verify --json` prints.
pub fn json(s: &Summary) -> serde_json::Value {
    serde_json::json!({
        "claims": s.claims,
        "crosscheck": s.crosscheck,
        "tonemap": s.figures.tonemap,
        "budgets": s.figures.budgets,
        "block_figures": s.figures.block_figures,
        "files": s.figures.files,
        "generated": {
            "directory": s.generated.map(|d| d.display().to_string()),
            "checked": s.generated.is_some(),
            "files": s.set.files.iter().map(|(f, _)| f).collect::<Vec<_>>(),
            "stale": s.stale,
            "rewritten": s.rewritten,
        },
        "all_agree": s.all_agree(),
    })
}

/// The tone-mapping lines of `ps30 verify`'s text output.
fn tonemap_text(g: &Generated) -> String {
    let mut s = String::from(
        "\ntone mapping (asm/tonemap/reinhard.psh in the emulator against the f64 reference, every pixel):\n",
    );
    for r in &g.tonemap {
        s.push_str(&format!(
            "  {:<8} {}: L̄w {:.6}, largest difference {:.1e} (bound there {:.1e}, at most {:.0}% of a bound), 8-bit codes off by one: {}\n",
            if r.agree { "ok" } else { "DISAGREE" },
            r.image,
            r.log_average,
            r.max_error,
            r.max_error_bound,
            100.0 * r.largest_bound_fraction,
            r.mismatched_8bit_channels
        ));
    }
    s
}
