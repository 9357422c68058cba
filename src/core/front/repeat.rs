//! REPEAT_BLOCK expansion: the macro the article imagines, made real.
//!
//! `BEGIN_REPEAT_BLOCK(n)` … `END_REPEAT_BLOCK` repeats its body `n` times;
//! blocks nest; `n` is a literal or a name bound on the command line
//! (`-D xsize=11`). The size of the expansion is computed before anything is
//! expanded, so a "macro bomb" is refused without allocating it.

use super::ast::{Count, Stmt};
use crate::core::diag::{Diagnostic, Diagnostics};
use crate::core::ir::{Origin, Repetition, Span};
use std::collections::BTreeMap;

/// Default cap on the number of statements an expansion may produce.
/// ps_3_0 programs have at most 32,768 slots, so a legitimate expansion is
/// far below this; raise it with `--max-expanded`.
pub const DEFAULT_MAX_EXPANDED: u64 = 100_000;

/// One statement of the expanded program: which source statement, and in
/// which repetitions.
#[derive(Clone, Debug, PartialEq)]
pub struct Expanded {
    pub stmt: usize,
    pub origin: Origin,
}

enum Node {
    Leaf(usize),
    Repeat {
        span: Span,
        count: u32,
        body: Vec<Node>,
    },
}

/// Expands every REPEAT_BLOCK. `defines` binds names used as counts.
pub fn expand(
    stmts: &[Stmt],
    defines: &BTreeMap<String, u64>,
    max_expanded: u64,
) -> Result<Vec<Expanded>, Diagnostics> {
    let mut diags = Diagnostics::default();
    // Build the block tree, checking balance.
    let mut stack: Vec<(Span, u32, Vec<Node>)> = Vec::new();
    let mut top: Vec<Node> = Vec::new();
    for (i, stmt) in stmts.iter().enumerate() {
        match stmt {
            Stmt::RepeatBegin { count, span } => {
                let n = match resolve(count, defines) {
                    Ok(n) => n,
                    Err(d) => {
                        diags.push(d);
                        0
                    }
                };
                stack.push((*span, n, Vec::new()));
            }
            Stmt::RepeatEnd { span } => match stack.pop() {
                Some((bspan, count, body)) => {
                    let node = Node::Repeat {
                        span: bspan,
                        count,
                        body,
                    };
                    match stack.last_mut() {
                        Some(parent) => parent.2.push(node),
                        None => top.push(node),
                    }
                }
                None => diags.push(
                    Diagnostic::error(
                        *span,
                        "END_REPEAT_BLOCK without a matching BEGIN_REPEAT_BLOCK",
                    )
                    .with_label("nothing to close")
                    .with_help("remove this line or add BEGIN_REPEAT_BLOCK(n) before the block"),
                ),
            },
            _ => match stack.last_mut() {
                Some(parent) => parent.2.push(Node::Leaf(i)),
                None => top.push(Node::Leaf(i)),
            },
        }
    }
    for (span, _, _) in stack.iter().rev() {
        diags.push(
            Diagnostic::error(*span, "BEGIN_REPEAT_BLOCK is never closed")
                .with_label("opened here")
                .with_help("add END_REPEAT_BLOCK after the block's last line"),
        );
    }
    if diags.has_errors() {
        return Err(diags);
    }

    // Size before expanding: refuse bombs without allocating them.
    let total = size(&top);
    if total > max_expanded {
        let culprit = largest_repeat(&top);
        let span = culprit.unwrap_or_default();
        diags.push(
            Diagnostic::error(
                span,
                format!("REPEAT_BLOCK expansion would produce {total} statements, over the cap of {max_expanded}"),
            )
            .with_label("this block expands too far")
            .with_help(format!(
                "ps_3_0 shaders have at most 32,768 instruction slots; if you really need this, raise the cap with --max-expanded {total}"
            )),
        );
        return Err(diags);
    }
    let mut out = Vec::with_capacity(total as usize);
    let mut reps = Vec::new();
    emit(&top, stmts, &mut reps, &mut out);
    Ok(out)
}

fn resolve(count: &Count, defines: &BTreeMap<String, u64>) -> Result<u32, Diagnostic> {
    let (value, span) = match count {
        Count::Literal { value, span } => (*value, *span),
        Count::Name { name, span } => match defines.get(name) {
            Some(v) => (*v, *span),
            None => {
                return Err(Diagnostic::error(
                    *span,
                    format!("REPEAT_BLOCK count `{name}` is not defined"),
                )
                .with_label("unknown name")
                .with_help(format!("bind it on the command line, e.g. -D {name}=8")))
            }
        },
    };
    u32::try_from(value).map_err(|_| {
        Diagnostic::error(
            span,
            format!("REPEAT_BLOCK count {value} is absurdly large"),
        )
        .with_label("more than 4,294,967,295 repetitions")
    })
}

fn size(nodes: &[Node]) -> u64 {
    nodes.iter().fold(0u64, |acc, n| {
        acc.saturating_add(match n {
            Node::Leaf(_) => 1,
            Node::Repeat { count, body, .. } => (*count as u64).saturating_mul(size(body)),
        })
    })
}

/// The outermost repeat with the largest expansion (to point the error at).
fn largest_repeat(nodes: &[Node]) -> Option<Span> {
    nodes
        .iter()
        .filter_map(|n| match n {
            Node::Repeat { span, count, body } => {
                Some(((*count as u64).saturating_mul(size(body)), *span))
            }
            Node::Leaf(_) => None,
        })
        .max_by_key(|(s, _)| *s)
        .map(|(_, span)| span)
}

fn emit(nodes: &[Node], stmts: &[Stmt], reps: &mut Vec<Repetition>, out: &mut Vec<Expanded>) {
    for node in nodes {
        match node {
            Node::Leaf(i) => {
                let span = match &stmts[*i] {
                    Stmt::Instr(instr) => instr.span,
                    Stmt::Version { span, .. } => *span,
                    Stmt::RepeatBegin { span, .. }
                    | Stmt::RepeatEnd { span }
                    | Stmt::Comment { span, .. } => *span,
                };
                out.push(Expanded {
                    stmt: *i,
                    origin: Origin {
                        span,
                        repeats: reps.clone(),
                    },
                });
            }
            Node::Repeat { span, count, body } => {
                for index in 0..*count {
                    reps.push(Repetition {
                        macro_span: *span,
                        index,
                        count: *count,
                    });
                    emit(body, stmts, reps, out);
                    reps.pop();
                }
            }
        }
    }
}
