//! REPEAT_BLOCK expansion: the macro the article imagines, made real.
//!
//! `BEGIN_REPEAT_BLOCK(n)` … `END_REPEAT_BLOCK` repeats its body `n` times;
//! blocks nest; `n` is a literal or a name bound on the command line
//! (`-D xsize=11`). The size of the expansion is computed before anything is
//! expanded, so a "macro bomb" is refused without allocating it.

use super::ast::{Count, Stmt};
use crate::core::diag::{Diagnostic, Diagnostics};
use crate::core::ir::{Origin, RepeatLink, Repetition, Span};
use std::collections::BTreeMap;
use std::sync::Arc;

/// Default cap on the statements an expansion may produce, and on the
/// repetitions it may make. ps_3_0 programs have at most 32,768 slots, so a
/// legitimate expansion is far below this; raise it with `--max-expanded`.
/// A kept comment block (a constant table: up to 32,767 tokens in one
/// statement) counts as many statements as instructions of its size would
/// ([`COMMENT_TOKENS_PER_STATEMENT`]), so that the cap bounds the bytes an
/// expansion writes, not only its lines.
pub const DEFAULT_MAX_EXPANDED: u64 = 100_000;

/// Tokens of a kept comment block that weigh one statement: a ps_3_0
/// instruction takes at most six (`texldd`: its token, a destination and
/// four sources).
pub const COMMENT_TOKENS_PER_STATEMENT: u64 = 6;

/// Deepest REPEAT_BLOCK nesting accepted (the article nests two).
pub const MAX_DEPTH: usize = 64;

/// One statement of the expanded program: which source statement, and in
/// which repetitions.
#[derive(Clone, Debug, PartialEq)]
pub struct Expanded {
    /// The index of the source statement.
    pub stmt: usize,
    /// Which repetitions it is in.
    pub origin: Origin,
}

/// What expanding a part of the source costs: statements produced (a
/// comment block weighing its tokens) and repetitions made. A block whose body produces nothing costs nothing and
/// is skipped, however large its count.
#[derive(Clone, Copy, Default)]
struct Size {
    statements: u64,
    repetitions: u64,
}

impl Size {
    fn add(self, other: Size) -> Size {
        Size {
            statements: self.statements.saturating_add(other.statements),
            repetitions: self.repetitions.saturating_add(other.repetitions),
        }
    }
}

enum Node {
    /// A statement's index and its weight (1, or a comment block's tokens).
    Leaf(usize, u64),
    Repeat {
        span: Span,
        count: u32,
        body: Vec<Node>,
        /// The whole block's expansion (count × body, plus its repetitions).
        size: Size,
    },
}

impl Node {
    fn size(&self) -> Size {
        match self {
            Node::Leaf(_, weight) => Size {
                statements: *weight,
                repetitions: 0,
            },
            Node::Repeat { size, .. } => *size,
        }
    }

    /// A block of `count` repetitions of `body`.
    fn repeat(span: Span, count: u32, body: Vec<Node>) -> Node {
        let inner = body.iter().fold(Size::default(), |a, n| a.add(n.size()));
        let count = u64::from(count);
        let size = if inner.statements == 0 {
            Size::default()
        } else {
            Size {
                statements: inner.statements.saturating_mul(count),
                repetitions: inner.repetitions.saturating_add(1).saturating_mul(count),
            }
        };
        Node::Repeat {
            span,
            count: count as u32,
            body,
            size,
        }
    }
}

/// Expands every REPEAT_BLOCK. `defines` binds names used as counts;
/// `max_expanded` caps both the statements produced and the repetitions
/// made, checked before anything is expanded.
pub fn expand(
    stmts: &[Stmt],
    defines: &BTreeMap<String, u64>,
    max_expanded: u64,
) -> Result<Vec<Expanded>, Diagnostics> {
    let top = block_tree(stmts, defines)?;
    let total = top.iter().fold(Size::default(), |a, n| a.add(n.size()));
    if let Some(d) = over_cap(&top, stmts, total, max_expanded) {
        let mut diags = Diagnostics::default();
        diags.push(d);
        return Err(diags);
    }
    let mut out = Vec::with_capacity(total.statements as usize);
    emit(&top, stmts, &None, &mut out);
    Ok(out)
}

/// The blocks of the source as a tree, checking balance and depth (an
/// explicit stack: no recursion on the source's nesting).
fn block_tree(stmts: &[Stmt], defines: &BTreeMap<String, u64>) -> Result<Vec<Node>, Diagnostics> {
    let mut diags = Diagnostics::default();
    let mut stack: Vec<(Span, u32, Vec<Node>)> = Vec::new();
    let mut top: Vec<Node> = Vec::new();
    let mut too_deep = false;
    for (i, stmt) in stmts.iter().enumerate() {
        match stmt {
            Stmt::RepeatBegin { count, span } => {
                let n = resolve(count, defines).unwrap_or_else(|d| {
                    diags.push(d);
                    0
                });
                if stack.len() == MAX_DEPTH && !too_deep {
                    too_deep = true;
                    diags.push(
                        Diagnostic::error(
                            *span,
                            format!("REPEAT_BLOCK nested more than {MAX_DEPTH} deep"),
                        )
                        .with_label(format!("block {} levels deep", MAX_DEPTH + 1))
                        .with_help("flatten the nesting: a block of n repetitions around a block of m is one block of n·m when nothing else sits between them"),
                    );
                }
                stack.push((*span, n, Vec::new()));
            }
            Stmt::RepeatEnd { span } => match stack.pop() {
                Some((bspan, count, body)) => {
                    let node = Node::repeat(bspan, count, body);
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
            _ => {
                let weight = match stmt {
                    Stmt::Comment { tokens, .. } => (tokens.len() as u64)
                        .div_ceil(COMMENT_TOKENS_PER_STATEMENT)
                        .max(1),
                    _ => 1,
                };
                match stack.last_mut() {
                    Some(parent) => parent.2.push(Node::Leaf(i, weight)),
                    None => top.push(Node::Leaf(i, weight)),
                }
            }
        }
    }
    // Report the outermost unclosed block first; a deep pile of unclosed
    // blocks is one problem, told once.
    if let Some((span, _, _)) = stack.first() {
        let more = stack.len() - 1;
        let mut d = Diagnostic::error(*span, "BEGIN_REPEAT_BLOCK is never closed")
            .with_label("opened here")
            .with_help("add END_REPEAT_BLOCK after the block's last line");
        if more > 0 {
            d = d.with_note(format!(
                "and {more} more block{} opened after it",
                if more == 1 { " is" } else { "s are" }
            ));
        }
        diags.push(d);
    }
    // Free the tree without recursing as deep as the source nests.
    if diags.has_errors() {
        drop_flat(top);
        drop_flat(
            stack
                .into_iter()
                .map(|(s, c, b)| Node::repeat(s, c, b))
                .collect(),
        );
        return Err(diags);
    }
    Ok(top)
}

/// Drops a tree of any depth with a loop instead of recursion.
fn drop_flat(mut nodes: Vec<Node>) {
    while let Some(n) = nodes.pop() {
        if let Node::Repeat { body, .. } = n {
            nodes.extend(body);
        }
    }
}

/// The error for an expansion over the cap, pointed at the block that
/// expands the most (or, without macros, at the first statement past it).
fn over_cap(top: &[Node], stmts: &[Stmt], total: Size, cap: u64) -> Option<Diagnostic> {
    let help = |n: u64| {
        format!("ps_3_0 shaders have at most 32,768 instruction slots; if you really need this, raise the cap with --max-expanded {n}")
    };
    let has_macro = top.iter().any(|n| matches!(n, Node::Repeat { .. }));
    if total.statements > cap && !has_macro {
        // The statement at which the running weight passes the cap.
        let mut weight = 0u64;
        let span = top
            .iter()
            .find_map(|n| match n {
                Node::Leaf(i, w) => {
                    weight = weight.saturating_add(*w);
                    (weight > cap).then(|| stmt_span(&stmts[*i]))
                }
                Node::Repeat { .. } => None,
            })
            .unwrap_or_default();
        return Some(
            Diagnostic::error(
                span,
                format!(
                    "the file has {} statements, over the cap of {cap}{}",
                    total.statements,
                    comment_note()
                ),
            )
            .with_label("the first statement past the cap")
            .with_help(help(total.statements)),
        );
    }
    let culprit = |key: fn(Size) -> u64| {
        top.iter()
            .filter_map(|n| match n {
                Node::Repeat { span, size, .. } => Some((key(*size), *span)),
                Node::Leaf(..) => None,
            })
            .max_by_key(|(s, _)| *s)
            .map(|(_, span)| span)
            .unwrap_or_default()
    };
    if total.statements > cap {
        let n = total.statements;
        return Some(
            Diagnostic::error(
                culprit(|s| s.statements),
                format!(
                    "REPEAT_BLOCK expansion would produce {n} statements, over the cap of {cap}{}",
                    comment_note()
                ),
            )
            .with_label("this block expands too far")
            .with_help(help(n)),
        );
    }
    if total.repetitions > cap {
        let n = total.repetitions;
        return Some(
            Diagnostic::error(
                culprit(|s| s.repetitions),
                format!("REPEAT_BLOCK expansion would make {n} repetitions, over the cap of {cap}"),
            )
            .with_label("this block repeats too often")
            .with_help(format!("the cap bounds repetitions as well as statements; raise it with --max-expanded {n}")),
        );
    }
    None
}

/// How the cap's messages say that comment blocks weigh their tokens.
fn comment_note() -> String {
    format!(" (a kept comment block counts one per {COMMENT_TOKENS_PER_STATEMENT} tokens)")
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

fn stmt_span(stmt: &Stmt) -> Span {
    match stmt {
        Stmt::Instr(instr) => instr.span,
        Stmt::Version { span, .. } => *span,
        Stmt::RepeatBegin { span, .. } | Stmt::RepeatEnd { span } | Stmt::Comment { span, .. } => {
            *span
        }
    }
}

/// Writes the expansion; blocks that produce nothing are skipped. Recursion
/// is bounded by [`MAX_DEPTH`].
fn emit(nodes: &[Node], stmts: &[Stmt], outer: &Option<Arc<RepeatLink>>, out: &mut Vec<Expanded>) {
    for node in nodes {
        match node {
            Node::Leaf(i, _) => out.push(Expanded {
                stmt: *i,
                origin: Origin {
                    span: stmt_span(&stmts[*i]),
                    repeat: outer.clone(),
                },
            }),
            Node::Repeat {
                span,
                count,
                body,
                size,
            } => {
                if size.statements == 0 {
                    continue;
                }
                for index in 0..*count {
                    let link = Some(Arc::new(RepeatLink {
                        repetition: Repetition {
                            macro_span: *span,
                            index,
                            count: *count,
                        },
                        outer: outer.clone(),
                    }));
                    emit(body, stmts, &link, out);
                }
            }
        }
    }
}
