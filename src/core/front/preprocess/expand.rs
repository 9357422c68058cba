//! Macro expansion: C's algorithm with a hide set per token, so that a
//! macro is never expanded inside its own expansion, and a rescan that may
//! take a function-like macro's arguments from the text after it.

use super::{lex, trim, Kind, Origin, Pre, Tok};
use crate::core::diag::{codes, Diagnostic};
use crate::core::ir::Span;

/// Arguments nested inside arguments deeper than this are not expanded (a
/// bound on the recursion; real shaders nest a few levels).
const MAX_ARGUMENT_DEPTH: usize = 64;

impl Pre<'_> {
    /// The tokens with every macro expanded; in an `#if` line (`in_if`) the
    /// operand of `defined` is kept as written.
    pub(super) fn expand(&mut self, toks: Vec<Tok>, in_if: bool) -> Vec<Tok> {
        let mut input = toks;
        input.reverse();
        let mut out = Vec::with_capacity(input.len());
        while let Some(t) = input.pop() {
            if t.kind != Kind::Ident {
                out.push(t);
                continue;
            }
            if in_if && t.text == "defined" {
                out.push(t);
                keep_defined_operand(&mut input, &mut out);
                continue;
            }
            if t.text == "__LINE__" {
                let at = t.span().start as usize;
                let line = self.line_starts.partition_point(|&s| s <= at);
                out.push(Tok {
                    kind: Kind::Number,
                    text: line.to_string(),
                    ..t
                });
                continue;
            }
            let Some(m) = self.macros.get(&t.text).filter(|m| !t.hide.contains(&m.id)) else {
                out.push(t);
                continue;
            };
            let m = m.clone();
            let (args, origin, newlines) = match &m.params {
                None => (Vec::new(), Origin::Macro(t.span()), Vec::new()),
                Some(params) => match self.arguments(&t, params.len(), &mut input) {
                    Ok(call) => call,
                    Err(kept) => {
                        out.push(t);
                        out.extend(kept);
                        continue;
                    }
                },
            };
            let mut hide = t.hide.clone();
            hide.push(m.id);
            let replacement = self.substitute(&m, args, origin, &hide);
            let size: usize = replacement.iter().map(|r| r.text.len()).sum();
            if size > self.budget {
                self.over_budget(&t);
                out.push(t);
                out.extend(newlines);
                continue;
            }
            self.budget -= size;
            input.extend(newlines.into_iter().rev());
            input.extend(replacement.into_iter().rev());
        }
        out
    }

    /// The arguments of a call of function-like macro `name` (taking
    /// `count`), read from `input`: the arguments, where the call is, and
    /// the line ends inside it. `Err` holds what to keep after the name
    /// when there is no call (no `(` follows) or a wrong one.
    #[allow(clippy::type_complexity)]
    fn arguments(
        &mut self,
        name: &Tok,
        count: usize,
        input: &mut Vec<Tok>,
    ) -> Result<(Vec<Vec<Tok>>, Origin, Vec<Tok>), Vec<Tok>> {
        let mut read = Vec::new();
        while input
            .last()
            .is_some_and(|t| matches!(t.kind, Kind::Space | Kind::Newline))
        {
            read.extend(input.pop());
        }
        if !input.last().is_some_and(|t| t.is(Kind::Punct, "(")) {
            input.extend(read.into_iter().rev());
            return Err(Vec::new());
        }
        let mut newlines: Vec<Tok> = read
            .into_iter()
            .filter(|t| t.kind == Kind::Newline)
            .collect();
        input.pop();
        let mut args = vec![Vec::new()];
        let mut depth = 1;
        let close = loop {
            let Some(t) = input.pop() else {
                self.diags.push(
                    Diagnostic::coded(
                        codes::MACRO_CALL_UNCLOSED,
                        name.span(),
                        format!(
                            "unexpected end of file in the arguments of macro '{}'",
                            name.text
                        ),
                    )
                    .with_label("this call's `(` is never closed"),
                );
                return Err(newlines);
            };
            match t.text.as_str() {
                "(" if t.kind == Kind::Punct => depth += 1,
                ")" if t.kind == Kind::Punct => {
                    depth -= 1;
                    if depth == 0 {
                        break t;
                    }
                }
                "," if t.kind == Kind::Punct && depth == 1 => {
                    args.push(Vec::new());
                    continue;
                }
                _ => {}
            }
            if t.kind == Kind::Newline {
                newlines.push(t);
                continue;
            }
            args.last_mut().expect("one at least").push(t);
        };
        if args.len() != count {
            self.diags.push(
                Diagnostic::coded(
                    codes::MACRO_ARGUMENTS,
                    name.span(),
                    format!(
                        "macro '{}' takes {count} argument{}, this call gives {}",
                        name.text,
                        if count == 1 { "" } else { "s" },
                        args.len()
                    ),
                )
                .with_label("wrong number of arguments"),
            );
            return Err(newlines);
        }
        let origin = match (name.origin, close.origin) {
            (Origin::Macro(s), _) => Origin::Macro(s),
            (Origin::Source(a), Origin::Source(b)) => {
                Origin::Macro(Span::new(a, b + close.text.len()))
            }
            (Origin::Source(a), Origin::Macro(s)) => Origin::Macro(Span::new(a, s.end as usize)),
        };
        Ok((args, origin, newlines))
    }

    /// The body of `m` with its parameters replaced by `args` (expanded,
    /// or as written beside `#` and `##`), tokens pasted, every token
    /// marked as written by this call.
    fn substitute(
        &mut self,
        m: &super::Macro,
        args: Vec<Vec<Tok>>,
        origin: Origin,
        hide: &[u32],
    ) -> Vec<Tok> {
        let params = m.params.as_deref().unwrap_or(&[]);
        let param = |t: &Tok| {
            (t.kind == Kind::Ident)
                .then(|| params.iter().position(|p| *p == t.text))
                .flatten()
        };
        let body = &m.body;
        let solid = |i: usize| body.get(i).filter(|t| t.kind != Kind::Space);
        let mut out: Vec<Tok> = Vec::new();
        let mut i = 0;
        while i < body.len() {
            let t = &body[i];
            let next = (i + 1..body.len()).find(|&j| body[j].kind != Kind::Space);
            if t.kind == Kind::Hash && !params.is_empty() {
                if let Some(p) = next.and_then(|j| param(&body[j])) {
                    out.push(stringize(&args[p], t));
                    i = next.expect("found") + 1;
                    continue;
                }
            }
            match param(t) {
                Some(p) => {
                    let mut arg = args[p].clone();
                    trim(&mut arg);
                    let before = (0..i)
                        .rev()
                        .find_map(solid)
                        .is_some_and(|b| b.kind == Kind::Paste);
                    let after = next.is_some_and(|j| body[j].kind == Kind::Paste);
                    if before || after || self.depth >= MAX_ARGUMENT_DEPTH {
                        out.extend(arg);
                    } else {
                        self.depth += 1;
                        let expanded = self.expand(arg, false);
                        self.depth -= 1;
                        out.extend(expanded);
                    }
                }
                None => out.push(t.clone()),
            }
            i += 1;
        }
        let mut out = paste(out);
        for t in &mut out {
            t.origin = origin;
            t.hide.extend_from_slice(hide);
        }
        out
    }

    fn over_budget(&mut self, at: &Tok) {
        if self.budget == usize::MAX {
            return;
        }
        self.diags.push(
            Diagnostic::error(at.span(), "macro expansion grows past the limit")
                .with_label("this expansion would make the file too large")
                .with_note(format!(
                    "a file's macros may write at most {} bytes per byte of the file (plus 1 MiB)",
                    super::EXPANSION_PER_BYTE
                )),
        );
        // Reported once: later expansions stop silently.
        self.budget = 0;
    }
}

/// Copies `defined NAME` or `defined ( NAME )`'s operand unexpanded.
fn keep_defined_operand(input: &mut Vec<Tok>, out: &mut Vec<Tok>) {
    let mut open = false;
    while let Some(t) = input.pop() {
        let stop = match t.kind {
            Kind::Space => false,
            Kind::Punct if t.text == "(" && !open => {
                open = true;
                false
            }
            Kind::Ident => !open,
            Kind::Punct if t.text == ")" && open => true,
            _ => {
                input.push(t);
                return;
            }
        };
        out.push(t);
        if stop {
            return;
        }
    }
}

/// `#param`: the argument as a string literal (spaces between its words
/// made one, quotes and backslashes inside its strings escaped).
fn stringize(arg: &[Tok], hash: &Tok) -> Tok {
    let mut text = String::from("\"");
    let mut gap = false;
    for t in arg {
        if matches!(t.kind, Kind::Space | Kind::Newline) {
            gap = text.len() > 1;
            continue;
        }
        if gap {
            text.push(' ');
            gap = false;
        }
        for c in t.text.chars() {
            if matches!(c, '"' | '\\') && t.kind == Kind::Str {
                text.push('\\');
            }
            text.push(c);
        }
    }
    text.push('"');
    Tok {
        kind: Kind::Str,
        text,
        origin: hash.origin,
        hide: Vec::new(),
    }
}

/// `a ## b`: the two tokens beside each `##` joined into what the joined
/// text reads as.
fn paste(toks: Vec<Tok>) -> Vec<Tok> {
    if !toks.iter().any(|t| t.kind == Kind::Paste) {
        return toks;
    }
    let mut out: Vec<Tok> = Vec::with_capacity(toks.len());
    let mut iter = toks.into_iter().peekable();
    while let Some(t) = iter.next() {
        if t.kind != Kind::Paste {
            out.push(t);
            continue;
        }
        while out.last().is_some_and(|l| l.kind == Kind::Space) {
            out.pop();
        }
        while iter.peek().is_some_and(|n| n.kind == Kind::Space) {
            iter.next();
        }
        let (Some(left), Some(right)) = (out.pop(), iter.next()) else {
            continue;
        };
        let mut joined = Vec::new();
        lex(&format!("{}{}", left.text, right.text), 0, &mut joined);
        out.extend(joined.into_iter().map(|j| Tok {
            origin: left.origin,
            hide: left.hide.clone(),
            ..j
        }));
    }
    out
}
