//! What a draw observed that the shader's author should hear about: gradients
//! taken in divergent quads, and levels of detail far above the only level a
//! sampler can read. Every job that runs a shader reports these the same way.

use super::{Draw, DrawOutput, GradientSite, MipFilter};
use crate::core::diag::{Diagnostic, SourceFile};
use crate::core::isa::Opcode;
use crate::core::numbers::{lod_text, thousands};
use serde::Serialize;
use serde_json::{json, Value};

/// A texld-family LOD at least this large, on a sampler that can only read
/// its base level, is reported: one whole level, neighbouring pixels two or
/// more texels apart.
pub const LOD_WARNING: f32 = 1.0;

/// What a finding is about.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum FindingKind {
    /// A gradient instruction ran with some lanes of a quad inactive on a temporary source: Direct3D leaves its result undefined.
    DivergentGradient,
    /// A texture instruction computes a LOD well above 0 but reads level 0 only (a texture without mips).
    LodFarFromLevel0,
}

/// One problem found in a draw, at a source statement.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Finding {
    /// What it is about.
    pub kind: FindingKind,
    /// Where, with the quads it saw.
    pub site: SiteSummary,
    /// What is wrong, in one sentence.
    pub message: String,
    /// Shown under the caret.
    pub label: String,
    /// How to fix it.
    pub help: String,
}

/// A gradient site without its span (serialisable).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SiteSummary {
    /// The source line (1-based).
    pub line: usize,
    /// The column (1-based).
    pub column: usize,
    /// The instruction's mnemonic.
    pub op: String,
    /// The sampler of texld/texldp/texldb.
    pub sampler: Option<u32>,
    /// Whether the differenced operand is a temporary `r#`.
    pub temp_source: bool,
    /// Quads that executed it at least once.
    pub quads: u64,
    /// Quads that executed it divergently at least once.
    pub divergent_quads: u64,
    /// Quad-executions (a quad in a loop counts once per iteration).
    pub executions: u64,
    /// Quad-executions with some but not all four lanes active.
    pub divergent_executions: u64,
    /// (min, max) LOD; infinities print as strings in JSON.
    #[serde(serialize_with = "lod_json")]
    pub lod: Option<(f32, f32)>,
    /// Where it is in the source.
    #[serde(skip)]
    pub span: crate::core::ir::Span,
}

fn lod_json<S: serde::Serializer>(lod: &Option<(f32, f32)>, s: S) -> Result<S::Ok, S::Error> {
    let f = |v: f32| -> Value {
        if v.is_finite() {
            json!(v)
        } else {
            json!(format!("{v}"))
        }
    };
    match lod {
        Some((lo, hi)) => json!({"min": f(*lo), "max": f(*hi)}).serialize(s),
        None => s.serialize_none(),
    }
}

impl SiteSummary {
    /// The summary of `g`, with its line and column in `file`.
    pub fn new(g: &GradientSite, file: &SourceFile) -> SiteSummary {
        let (line, column) = file.line_col(g.span.start);
        SiteSummary {
            line,
            column,
            op: g.op.to_string(),
            sampler: g.sampler,
            temp_source: g.temp_source,
            quads: g.quads,
            divergent_quads: g.divergent_quads,
            executions: g.executions,
            divergent_executions: g.divergent_executions,
            lod: g.lod,
            span: g.span,
        }
    }
}

/// The findings of a draw (see the module docs for the rules). `draw` must
/// be the draw that produced `out`.
pub fn findings(out: &DrawOutput, draw: &Draw, file: &SourceFile) -> Vec<Finding> {
    let mut found = Vec::new();
    for g in &out.gradients {
        let site = SiteSummary::new(g, file);
        if g.temp_source && g.divergent_quads > 0 {
            let what = match g.op {
                Opcode::Dsx | Opcode::Dsy => "its difference",
                _ => "its mip level",
            };
            found.push(Finding {
                kind: FindingKind::DivergentGradient,
                message: format!(
                    "`{}` ran in divergent quads: {what} came from neighbours that were not running it",
                    g.op
                ),
                label: format!(
                    "{} of {} quads ran it with only part of their pixels ({} of {} executions)",
                    thousands(g.divergent_quads),
                    thousands(g.quads),
                    thousands(g.divergent_executions),
                    thousands(g.executions)
                ),
                help: match g.op {
                    Opcode::Dsx | Opcode::Dsy => {
                        "take dsx/dsy before the branch, where every pixel of the quad runs it"
                            .to_string()
                    }
                    _ => "use texldl (explicit LOD) or texldd with gradients taken before the branch"
                        .to_string(),
                },
                site: site.clone(),
            });
        }
        let (Some((lo, hi)), Some(s)) = (g.lod, g.sampler) else {
            continue;
        };
        if !matches!(g.op, Opcode::TexLd | Opcode::TexLdP | Opcode::TexLdB) || hi < LOD_WARNING {
            continue;
        }
        let Some((_, tex, state)) = draw.samplers.iter().find(|(i, _, _)| *i == s) else {
            continue;
        };
        let base_only = if tex.len() == 1 {
            Some(format!("s{s} has one level"))
        } else if state.mip_filter == MipFilter::None {
            Some(format!("s{s}'s mip filter is NONE"))
        } else {
            None
        };
        let Some(why) = base_only else { continue };
        let range = if lod_text(lo) == lod_text(hi) {
            format!("LOD {}", lod_text(hi))
        } else {
            format!("LOD {} to {}", lod_text(lo), lod_text(hi))
        };
        found.push(Finding {
            kind: FindingKind::LodFarFromLevel0,
            message: format!(
                "`{}` computes {range} but reads level 0 only because {why}",
                g.op
            ),
            label: format!(
                "neighbouring pixels sample up to 2^{} = {:.0} texels apart",
                lod_text(hi),
                2f64.powf(hi as f64)
            ),
            help: format!(
                "on a mipmapped texture this would read level {}; if level 0 is meant, say so with texldl and w = 0",
                (hi + 0.5).floor().max(0.0)
            ),
            site,
        });
    }
    found
}

/// A finding as a compiler-style warning.
pub fn diagnostic(f: &Finding) -> Diagnostic {
    Diagnostic::warning(f.site.span, f.message.clone())
        .with_label(f.label.clone())
        .with_help(f.help.clone())
}

/// Identical findings (same kind, message, label and help) at several
/// places: the first, how many, and the first and last source line.
#[derive(Clone, Debug, PartialEq)]
pub struct FindingGroup<'a> {
    /// The first of the identical findings.
    pub first: &'a Finding,
    /// How many there are.
    pub count: usize,
    /// The first and last source line among them.
    pub lines: (usize, usize),
}

/// The findings grouped by [`crate::core::diag::group_indices`], the rule
/// every finding is grouped by: the 117 unrolled copies of one `texld`
/// are one finding with a count.
pub fn grouped(found: &[Finding]) -> Vec<FindingGroup<'_>> {
    let keys = found.iter().map(|f| {
        (
            f.kind,
            f.message.as_str(),
            f.label.as_str(),
            f.help.as_str(),
        )
    });
    crate::core::diag::group_indices(keys)
        .into_iter()
        .map(|members| {
            let lines = members.iter().map(|&i| found[i].site.line);
            FindingGroup {
                first: &found[members[0]],
                count: members.len(),
                lines: (lines.clone().min().unwrap_or(0), lines.max().unwrap_or(0)),
            }
        })
        .collect()
}
