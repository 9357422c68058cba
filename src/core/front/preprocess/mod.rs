//! The C preprocessor that Microsoft's assembler runs before it reads a
//! line: `#define` (object-like and function-like, with `#` and `##`),
//! `#undef`, `#if`/`#ifdef`/`#ifndef`/`#elif`/`#else`/`#endif`, `#error`,
//! `#pragma` (ignored with a warning), `#include` (refused: there is no
//! include handler, as with `D3DAssemble` called without one) and `#line`
//! (left for the parser, which reads it as a position).
//!
//! Why here: shaders written by hand and the tools of the Direct3D 9 era use
//! macros, and `D3DAssemble` accepts them. The preprocessed text keeps the
//! source's lines (a directive or a line skipped by `#if` becomes an empty
//! line; a macro's arguments spread over several lines leave those lines
//! empty), and [`Preprocessed::span`] maps every place in it back to the
//! source: text copied from the source maps byte for byte, text a macro
//! produced maps to the whole invocation (name to closing parenthesis), which
//! is where Microsoft reports an error inside an expansion too.
//!
//! What Microsoft's preprocessor does differently from a C compiler's, read
//! from `D3DAssemble`'s answers (`tests/oracle/corpus/asm/rules/preprocessor/`):
//! `;` starts a comment on directive lines too; `#if` computes in 32-bit
//! unsigned arithmetic without `%`, `~`, `<<` or `>>` (see [`expr`]); a
//! function-like macro needs at least one parameter; a lone `#` is an
//! error, not C's null directive. Codes are Microsoft's.
//!
//! Work is bounded by the input: every expansion draws on a budget of output
//! bytes proportional to the input, and a hide set per token stops recursion.

use std::collections::HashMap;

use crate::core::diag::{codes, Diagnostic, Diagnostics};
use crate::core::ir::Span;

/// Output a whole file's expansions may write: this many bytes per input
/// byte, plus [`EXPANSION_SLACK`].
const EXPANSION_PER_BYTE: usize = 64;
/// Output any file may expand to, whatever its size.
const EXPANSION_SLACK: usize = 1 << 20;

/// The text the assembler reads after the preprocessor, with the map back
/// to the source.
#[derive(Debug)]
pub struct Preprocessed {
    /// The preprocessed text: as many lines as the source.
    pub text: String,
    /// Where each run of the text came from, in order of `out`.
    pieces: Vec<Piece>,
}

/// A run of the preprocessed text and where it came from.
#[derive(Clone, Copy, Debug)]
struct Piece {
    /// First byte in the preprocessed text.
    out: usize,
    /// Its length.
    len: usize,
    origin: Origin,
}

/// Where a token came from.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Origin {
    /// Copied from the source, starting at this byte.
    Source(usize),
    /// Written by the expansion of the macro invoked here.
    Macro(Span),
}

impl Preprocessed {
    /// The source span of a span of the preprocessed text.
    pub fn span(&self, span: Span) -> Span {
        let (a, b) = (span.start as usize, span.end as usize);
        let start = self.place(a, false);
        if b <= a {
            return Span::new(start, start);
        }
        let end = self.place(b - 1, true);
        Span::new(start, end.max(start))
    }

    /// The source byte of preprocessed byte `at` (one past it with `end`).
    fn place(&self, at: usize, end: bool) -> usize {
        let i = self.pieces.partition_point(|p| p.out + p.len <= at);
        let Some(p) = self.pieces.get(i).or(self.pieces.last()) else {
            return at;
        };
        match p.origin {
            Origin::Source(s) => s + at.saturating_sub(p.out).min(p.len) + usize::from(end),
            Origin::Macro(inv) if end => inv.end as usize,
            Origin::Macro(inv) => inv.start as usize,
        }
    }
}

/// Whether the text (comments blanked) holds a preprocessor directive other
/// than `#line`, or the built-in macro `__LINE__`: only then is there
/// anything for [`preprocess`] to do.
pub fn needed(text: &str) -> bool {
    text.contains("__LINE__")
        || text.lines().any(|line| {
            let t = line.trim_start();
            t.starts_with('#') && !is_line(t)
        })
}

/// Whether a directive line (trimmed at the start) is `#line`, which the
/// parser reads.
fn is_line(t: &str) -> bool {
    let rest = t[1..].trim_start();
    rest.strip_prefix("line")
        .is_some_and(|r| !r.starts_with(|c: char| c.is_ascii_alphanumeric() || c == '_'))
}

/// The kinds of preprocessing tokens.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Kind {
    Ident,
    Number,
    Str,
    Space,
    Newline,
    Comment,
    Hash,
    Paste,
    Punct,
}

/// One preprocessing token.
#[derive(Clone, Debug)]
struct Tok {
    kind: Kind,
    text: String,
    origin: Origin,
    /// Macros whose expansion wrote this token: they are not expanded again
    /// in it (C's hide set).
    hide: Vec<u32>,
}

impl Tok {
    fn is(&self, kind: Kind, text: &str) -> bool {
        self.kind == kind && self.text == text
    }

    /// Where the token is in the source.
    fn span(&self) -> Span {
        match self.origin {
            Origin::Source(s) => Span::new(s, s + self.text.len()),
            Origin::Macro(span) => span,
        }
    }
}

/// Splits `text` (a piece of the source at byte `base`) into tokens; a
/// `;` or `//` comment is one token to the end of its line.
fn lex(text: &str, base: usize, out: &mut Vec<Tok>) {
    let bytes = text.as_bytes();
    let mut i = 0;
    while i < bytes.len() {
        let c = bytes[i];
        let rest = &text[i..];
        let (kind, len) = if c == b';' || rest.starts_with("//") {
            (Kind::Comment, rest.find('\n').unwrap_or(rest.len()))
        } else if c == b'\n' {
            (Kind::Newline, 1)
        } else if matches!(c, b' ' | b'\t' | b'\r') {
            let n = rest
                .bytes()
                .take_while(|b| matches!(b, b' ' | b'\t' | b'\r'))
                .count();
            (Kind::Space, n)
        } else if c.is_ascii_alphabetic() || c == b'_' {
            (Kind::Ident, ident_len(rest))
        } else if c.is_ascii_digit()
            || (c == b'.' && bytes.get(i + 1).is_some_and(u8::is_ascii_digit))
        {
            (Kind::Number, number_len(rest))
        } else if c == b'"' || c == b'\'' {
            let close = rest[1..].find(c as char).map_or(rest.len(), |e| e + 2);
            (Kind::Str, close)
        } else if rest.starts_with("##") {
            (Kind::Paste, 2)
        } else if ["&&", "||", "==", "!=", "<=", ">=", "<<", ">>"]
            .iter()
            .any(|op| rest.starts_with(op))
        {
            (Kind::Punct, 2)
        } else if c == b'#' {
            (Kind::Hash, 1)
        } else {
            (Kind::Punct, rest.chars().next().map_or(1, char::len_utf8))
        };
        out.push(Tok {
            kind,
            text: rest[..len].to_string(),
            origin: Origin::Source(base + i),
            hide: Vec::new(),
        });
        i += len;
    }
}

fn ident_len(s: &str) -> usize {
    s.bytes()
        .take_while(|b| b.is_ascii_alphanumeric() || *b == b'_')
        .count()
}

/// A C pp-number: digits, letters, `_`, `.`, and a sign after an exponent.
fn number_len(s: &str) -> usize {
    let b = s.as_bytes();
    let mut i = 0;
    while i < b.len() {
        let exp_sign = i > 0 && matches!(b[i], b'+' | b'-') && matches!(b[i - 1], b'e' | b'E');
        if !(b[i].is_ascii_alphanumeric() || b[i] == b'_' || b[i] == b'.' || exp_sign) {
            break;
        }
        i += 1;
    }
    i
}

/// A macro's definition.
#[derive(Clone, Debug)]
struct Macro {
    /// Parameter names of a function-like macro.
    params: Option<Vec<String>>,
    /// The replacement, spaces at both ends removed.
    body: Vec<Tok>,
    /// Its identity in hide sets.
    id: u32,
    /// Where the name was defined.
    at: Span,
}

impl Macro {
    /// Whether two definitions say the same (a redefinition that is not a
    /// change warrants no warning).
    fn same(&self, other: &Macro) -> bool {
        let words = |m: &Macro| m.body.iter().map(|t| t.text.clone()).collect::<Vec<_>>();
        self.params == other.params && words(self) == words(other)
    }
}

/// One `#if` group being read.
#[derive(Debug)]
struct Group {
    /// Whether the lines around the group are read.
    outer: bool,
    /// Whether a branch of the group was taken already.
    taken: bool,
    /// Whether the current branch is read.
    active: bool,
    /// Whether `#else` was seen.
    seen_else: bool,
}

/// The preprocessor's state over one file.
struct Pre<'s> {
    source: &'s str,
    macros: HashMap<String, Macro>,
    next_id: u32,
    groups: Vec<Group>,
    /// Start byte of each source line, for `__LINE__`.
    line_starts: Vec<usize>,
    /// Output bytes expansions may still write.
    budget: usize,
    /// How deeply macro arguments are being expanded inside each other.
    depth: usize,
    diags: Diagnostics,
}

/// Runs the preprocessor over `text` (comments already blanked).
pub fn preprocess(text: &str) -> (Preprocessed, Diagnostics) {
    let mut pre = Pre {
        source: text,
        macros: HashMap::new(),
        next_id: 0,
        groups: Vec::new(),
        line_starts: std::iter::once(0)
            .chain(text.match_indices('\n').map(|(i, _)| i + 1))
            .collect(),
        budget: text.len().saturating_mul(EXPANSION_PER_BYTE) + EXPANSION_SLACK,
        depth: 0,
        diags: Diagnostics::default(),
    };
    let mut out = Vec::new();
    let mut code = Vec::new();
    for (start, end) in logical_lines(text) {
        let first = text[start..end].trim_start();
        if first.starts_with('#') && !is_line(first) {
            let expanded = pre.expand(std::mem::take(&mut code), false);
            out.extend(expanded);
            pre.directive(start, end);
            push_newlines(&text[start..end], start, &mut out);
        } else if pre.active() {
            lex_logical(&text[start..end], start, &mut code);
        } else {
            push_newlines(&text[start..end], start, &mut out);
        }
    }
    let expanded = pre.expand(code, false);
    out.extend(expanded);
    if !pre.groups.is_empty() {
        let at = text.len();
        pre.diags.push(
            Diagnostic::coded(
                codes::PREPROCESSOR_EOF,
                Span::new(at, at),
                "unexpected end of file: an #if is not closed",
            )
            .with_label("the file ends here")
            .with_help("close every #if, #ifdef and #ifndef with #endif"),
        );
    }
    (assemble(out), pre.diags)
}

/// The logical lines of the text, as byte ranges that include their line
/// ends: physical lines joined where one ends with `\`.
fn logical_lines(text: &str) -> Vec<(usize, usize)> {
    let mut lines = Vec::new();
    let mut start = 0;
    let mut at = 0;
    for line in text.split_inclusive('\n') {
        at += line.len();
        if !line.trim_end_matches(['\n', '\r']).ends_with('\\') || at == text.len() {
            lines.push((start, at));
            start = at;
        }
    }
    if start < text.len() {
        lines.push((start, text.len()));
    }
    lines
}

/// Tokens of a logical code line: its pieces between `\` line joins, then
/// the line ends the joins removed, so that lines stay where they were.
fn lex_logical(line: &str, base: usize, out: &mut Vec<Tok>) {
    let mut newlines = Vec::new();
    let mut at = 0;
    for piece in line.split_inclusive('\n') {
        let body = piece.trim_end_matches(['\n', '\r']);
        let joined = body.ends_with('\\') && at + piece.len() < line.len();
        if joined {
            lex(&body[..body.len() - 1], base + at, out);
            push_newlines(piece, base + at, &mut newlines);
        } else {
            lex(piece, base + at, out);
        }
        at += piece.len();
    }
    out.extend(newlines);
}

/// Only the line ends of a piece of the source (a directive, a skipped
/// line), so that the lines below stay where they are.
fn push_newlines(text: &str, base: usize, out: &mut Vec<Tok>) {
    for (i, _) in text.match_indices('\n') {
        out.push(Tok {
            kind: Kind::Newline,
            text: "\n".into(),
            origin: Origin::Source(base + i),
            hide: Vec::new(),
        });
    }
}

/// The preprocessed text and its map from the tokens.
fn assemble(toks: Vec<Tok>) -> Preprocessed {
    let mut text = String::new();
    let mut pieces: Vec<Piece> = Vec::new();
    for t in toks {
        let out = text.len();
        text.push_str(&t.text);
        let len = t.text.len();
        if let Some(last) = pieces.last_mut() {
            let follows = match (last.origin, t.origin) {
                (Origin::Source(a), Origin::Source(b)) => a + last.len == b,
                (Origin::Macro(a), Origin::Macro(b)) => a == b,
                _ => false,
            };
            if follows {
                last.len += len;
                continue;
            }
        }
        pieces.push(Piece {
            out,
            len,
            origin: t.origin,
        });
    }
    Preprocessed { text, pieces }
}

impl Pre<'_> {
    fn active(&self) -> bool {
        self.groups.last().is_none_or(|g| g.active)
    }

    /// One directive line, `start..end` in the source.
    fn directive(&mut self, start: usize, end: usize) {
        let mut toks = Vec::new();
        lex_logical(&self.source[start..end], start, &mut toks);
        toks.retain(|t| !matches!(t.kind, Kind::Comment | Kind::Newline));
        let hash = toks
            .iter()
            .position(|t| t.kind == Kind::Hash || t.kind == Kind::Paste);
        let mut rest: Vec<Tok> = toks.split_off(hash.map_or(0, |h| h + 1));
        trim(&mut rest);
        let line_end = rest.last().map_or(end, |t| t.span().end as usize);
        if rest.is_empty() {
            if self.active() {
                let at = toks.last().map_or(start, |t| t.span().end as usize);
                self.diags.push(syntax(
                    Span::new(at, at),
                    "a `#` alone on a line is no directive",
                ));
            }
            return;
        }
        let name = rest.remove(0);
        trim(&mut rest);
        let args = rest;
        match name.text.as_str() {
            "if" | "ifdef" | "ifndef" => self.open(&name, args, line_end),
            "elif" | "else" | "endif" => self.branch(&name, args, line_end),
            _ if !self.active() => {}
            "define" => self.define(&name, args, line_end),
            "undef" => {
                if let Some(n) = self.one_name(&name, &args, line_end) {
                    self.macros.remove(&n);
                }
            }
            "error" => {
                let words: String = args.iter().map(|t| t.text.as_str()).collect();
                self.diags.push(
                    Diagnostic::error(name.span(), format!("#error: {words}"))
                        .with_label("the shader stops itself here"),
                );
            }
            "pragma" => {
                let what = args.first().map_or("", |t| t.text.as_str());
                let at = args.first().map_or(name.span(), Tok::span);
                self.diags.push(
                    Diagnostic::warning(at, format!("'{what}': unknown pragma ignored"))
                        .with_code(codes::UNKNOWN_PRAGMA),
                );
            }
            "include" => self.diags.push(
                Diagnostic::coded(codes::INCLUDE, name.span(), "#include needs an include handler, and the assembler has none")
                    .with_label("nothing is included")
                    .with_help("paste the included file in place of this line"),
            ),
            other => self.diags.push(
                Diagnostic::coded(codes::PREPROCESSOR, name.span(), format!("invalid preprocessor command '{other}'"))
                    .with_label("not a directive")
                    .with_help("the directives are #define, #undef, #if, #ifdef, #ifndef, #elif, #else, #endif, #error, #include, #line and #pragma; write comments with // or ;"),
            ),
        }
    }

    /// `#if`, `#ifdef`, `#ifndef`.
    fn open(&mut self, name: &Tok, args: Vec<Tok>, line_end: usize) {
        let outer = self.active();
        let value = if !outer {
            false
        } else if name.text == "if" {
            self.condition(args, line_end)
        } else {
            let defined = self
                .one_name(name, &args, line_end)
                .is_some_and(|n| self.macros.contains_key(&n));
            defined == (name.text == "ifdef")
        };
        self.groups.push(Group {
            outer,
            taken: value,
            active: value,
            seen_else: false,
        });
    }

    /// `#elif`, `#else`, `#endif`.
    fn branch(&mut self, name: &Tok, args: Vec<Tok>, line_end: usize) {
        let Some(group) = self.groups.last() else {
            let (code, what) = match name.text.as_str() {
                "elif" => (codes::UNEXPECTED_ELIF, "#elif"),
                "else" => (codes::UNEXPECTED_ELSE, "#else"),
                _ => (codes::UNEXPECTED_ENDIF, "#endif"),
            };
            self.diags.push(
                Diagnostic::coded(
                    code,
                    name.span(),
                    format!("unexpected {what}: no #if is open"),
                )
                .with_label("nothing to continue or close"),
            );
            return;
        };
        let (outer, taken, seen_else) = (group.outer, group.taken, group.seen_else);
        match name.text.as_str() {
            "endif" => {
                if outer {
                    self.no_more(&args);
                }
                self.groups.pop();
            }
            _ if seen_else => {
                let code = if name.text == "elif" {
                    codes::ELIF_AFTER_ELSE
                } else {
                    codes::ELSE_AFTER_ELSE
                };
                self.diags.push(
                    Diagnostic::coded(
                        code,
                        name.span(),
                        format!("unexpected #{} following #else", name.text),
                    )
                    .with_label("the group already has its #else"),
                );
            }
            "else" => {
                let g = self.groups.last_mut().expect("checked above");
                g.active = outer && !taken;
                g.taken = true;
                g.seen_else = true;
            }
            _ => {
                let value = outer && !taken && self.condition(args, line_end);
                let g = self.groups.last_mut().expect("checked above");
                g.active = value;
                g.taken |= value;
            }
        }
    }

    /// An error for anything after a directive that takes nothing more.
    fn no_more(&mut self, args: &[Tok]) {
        if let Some(t) = args.first() {
            self.diags
                .push(syntax(t.span(), format!("unexpected token '{}'", t.text)));
        }
    }

    /// The one macro name a directive takes (`#undef N`, `#ifdef N`).
    fn one_name(&mut self, name: &Tok, args: &[Tok], line_end: usize) -> Option<String> {
        match args.first() {
            Some(t) if t.kind == Kind::Ident => {
                let rest: Vec<Tok> = args[1..]
                    .iter()
                    .filter(|t| t.kind != Kind::Space)
                    .cloned()
                    .collect();
                self.no_more(&rest);
                Some(t.text.clone())
            }
            Some(t) => {
                self.diags.push(syntax(
                    t.span(),
                    format!("#{} takes a macro name, not '{}'", name.text, t.text),
                ));
                None
            }
            None => {
                self.diags.push(syntax(
                    Span::new(line_end, line_end),
                    format!("#{} takes a macro name", name.text),
                ));
                None
            }
        }
    }

    /// `#define NAME body` or `#define NAME(a, b) body`.
    fn define(&mut self, name: &Tok, mut args: Vec<Tok>, line_end: usize) {
        let Some(first) = args.first().cloned() else {
            self.diags.push(syntax(
                Span::new(line_end, line_end),
                "#define takes a macro name",
            ));
            return;
        };
        if first.kind != Kind::Ident {
            self.diags.push(syntax(
                first.span(),
                format!("a macro name is an identifier, not '{}'", first.text),
            ));
            return;
        }
        args.remove(0);
        let params = if args.first().is_some_and(|t| t.is(Kind::Punct, "(")) {
            match self.params(&mut args, line_end) {
                Some(p) => Some(p),
                None => return,
            }
        } else {
            None
        };
        trim(&mut args);
        let id = self.next_id;
        self.next_id += 1;
        let new = Macro {
            params,
            body: args,
            id,
            at: first.span(),
        };
        if let Some(old) = self.macros.get(&first.text) {
            if !old.same(&new) {
                self.diags.push(
                    Diagnostic::warning(
                        name.span().to(first.span()),
                        format!("'{}': macro redefinition", first.text),
                    )
                    .with_code(codes::MACRO_REDEFINED)
                    .with_secondary(old.at, "defined before here"),
                );
            }
        }
        self.macros.insert(first.text, new);
    }

    /// The parameter list of a function-like macro (`args` starts at its
    /// `(`; what follows the `)` is left in `args`).
    fn params(&mut self, args: &mut Vec<Tok>, line_end: usize) -> Option<Vec<String>> {
        let mut names: Vec<String> = Vec::new();
        let mut i = 1;
        let mut want_name = true;
        loop {
            let Some(t) = args.get(i) else {
                self.diags.push(syntax(
                    Span::new(line_end, line_end),
                    "the parameter list is not closed",
                ));
                return None;
            };
            match (t.kind, want_name) {
                (Kind::Space, _) => {}
                (Kind::Ident, true) => {
                    if names.contains(&t.text) {
                        self.diags.push(
                            Diagnostic::coded(
                                codes::MACRO_PARAMETER_TWICE,
                                t.span(),
                                format!("duplicate macro parameter '{}'", t.text),
                            )
                            .with_label("named twice"),
                        );
                        return None;
                    }
                    names.push(t.text.clone());
                    want_name = false;
                }
                (Kind::Punct, false) if t.text == "," => want_name = true,
                (Kind::Punct, false) if t.text == ")" => break,
                _ => {
                    let why = if t.text == ")" && names.is_empty() {
                        "a function-like macro takes at least one parameter here".to_string()
                    } else {
                        format!("unexpected token '{}' in the parameter list", t.text)
                    };
                    self.diags.push(syntax(t.span(), why));
                    return None;
                }
            }
            i += 1;
        }
        args.drain(..=i);
        Some(names)
    }

    /// The value of an `#if`/`#elif` expression.
    fn condition(&mut self, args: Vec<Tok>, line_end: usize) -> bool {
        let toks: Vec<Tok> = self
            .expand(args, true)
            .into_iter()
            .filter(|t| !matches!(t.kind, Kind::Space | Kind::Newline | Kind::Comment))
            .collect();
        let defined = |n: &str| self.macros.contains_key(n);
        match expr::evaluate(&toks, line_end, &defined) {
            Ok(v) => v != 0,
            Err(d) => {
                self.diags.push(d);
                false
            }
        }
    }
}

/// Without spaces at either end.
fn trim(toks: &mut Vec<Tok>) {
    while toks.last().is_some_and(|t| t.kind == Kind::Space) {
        toks.pop();
    }
    let lead = toks.iter().take_while(|t| t.kind == Kind::Space).count();
    toks.drain(..lead);
}

/// A preprocessor syntax error (Microsoft's X1500).
fn syntax(span: Span, message: impl Into<String>) -> Diagnostic {
    Diagnostic::coded(codes::PREPROCESSOR_SYNTAX, span, message.into())
}

mod expand;
mod expr;

#[cfg(test)]
mod tests {
    use super::*;

    fn run(text: &str) -> (Preprocessed, Diagnostics) {
        preprocess(text)
    }

    #[test]
    fn lines_stay_where_they_are() {
        let src = "#define M(a) mul a, a, a\nps_3_0\n#if 0\nbogus\n#endif\nM(\nr0)\nmov oC0, r0\n";
        let (pre, diags) = run(src);
        assert!(diags.items.is_empty(), "{diags:?}");
        assert_eq!(pre.text, "\nps_3_0\n\n\n\nmul r0, r0, r0\n\nmov oC0, r0\n");
        assert_eq!(pre.text.lines().count(), src.lines().count());
    }

    #[test]
    fn places_map_back_to_the_source() {
        let src = "#define X c0\nps_3_0\nmov oC0, X\n";
        let (pre, _) = run(src);
        // `mov` is copied: byte for byte.
        let mov = pre.text.find("mov").unwrap();
        assert_eq!(
            pre.span(Span::new(mov, mov + 3)),
            Span::new(src.find("mov").unwrap(), src.find("mov").unwrap() + 3)
        );
        // `c0` came from the macro: the whole call, `X`.
        let c0 = pre.text.rfind("c0").unwrap();
        let x = src.rfind('X').unwrap();
        assert_eq!(pre.span(Span::new(c0, c0 + 2)), Span::new(x, x + 1));
        // A span from copied text into an expansion ends with the call.
        assert_eq!(pre.span(Span::new(mov, c0 + 2)).end as usize, x + 1);
    }

    #[test]
    fn a_function_call_maps_to_name_through_parenthesis() {
        let src = "#define M(a) a\nps_3_0\nmov oC0, M(bogus)\n";
        let (pre, _) = run(src);
        let at = pre.text.find("bogus").unwrap();
        let call = src.find("M(bogus)").unwrap();
        assert_eq!(
            pre.span(Span::new(at, at + 5)),
            Span::new(call, call + "M(bogus)".len())
        );
    }

    #[test]
    fn recursion_stops_at_the_hide_set() {
        let (pre, diags) = run("#define X Y\n#define Y X\nX\n");
        assert!(diags.items.is_empty());
        assert_eq!(pre.text.trim(), "X");
    }

    #[test]
    fn exponential_macros_stop_at_the_budget() {
        let mut src = String::from("#define A0 x\n");
        for i in 1..60 {
            src.push_str(&format!("#define A{i} A{p} A{p}\n", p = i - 1));
        }
        src.push_str("A59\n");
        let (pre, diags) = run(&src);
        assert!(
            diags
                .items
                .iter()
                .any(|d| d.message.contains("grows past the limit")),
            "{diags:?}"
        );
        assert!(pre.text.len() <= src.len() * EXPANSION_PER_BYTE + EXPANSION_SLACK + src.len());
    }

    #[test]
    fn deep_nesting_is_bounded() {
        let depth = 20_000;
        let src = format!(
            "#define M(a) a\n{}c0{}\n#if {}1{}\n#endif\n",
            "M(".repeat(depth),
            ")".repeat(depth),
            "(".repeat(depth),
            ")".repeat(depth)
        );
        let (_, diags) = run(&src);
        assert!(
            diags
                .items
                .iter()
                .any(|d| d.message.contains("nests too deeply")),
            "{diags:?}"
        );
    }

    #[test]
    fn if_arithmetic_is_32_bit_unsigned() {
        for (expr, value) in [
            ("-1 > 0", true),
            ("0xffffffff == -1", true),
            ("-7 / 2 == 2147483644", true),
            ("2147483647 + 1 > 0", true),
            ("(1 ? 2 : 3) == 2", true),
            ("defined(Q)", true),
            ("defined Z", false),
            ("'a' == 97", true),
        ] {
            let (pre, diags) = run(&format!("#define Q\n#if {expr}\nyes\n#else\nno\n#endif\n"));
            assert!(diags.items.is_empty(), "{expr}: {diags:?}");
            assert_eq!(pre.text.trim(), if value { "yes" } else { "no" }, "{expr}");
        }
        for (expr, code) in [
            ("1 % 2", codes::PREPROCESSOR_SYNTAX),
            ("~0", codes::PREPROCESSOR_SYNTAX),
            ("1 << 2", codes::PREPROCESSOR_SYNTAX),
            ("0 && 1/0", codes::PREPROCESSOR_DIVIDE_BY_ZERO),
            ("4294967296", codes::PREPROCESSOR_SYNTAX),
            ("1 +", codes::PREPROCESSOR_SYNTAX),
        ] {
            let (_, diags) = run(&format!("#if {expr}\n#endif\n"));
            assert_eq!(
                diags.items.first().and_then(|d| d.code),
                Some(code),
                "{expr}"
            );
        }
    }

    #[test]
    fn stringize_and_paste() {
        let (pre, _) = run("#define S(a) #a\n#define P(a, b) a ## b\nS( x   y )\nP(r, 1)\n");
        assert_eq!(pre.text, "\n\n\"x y\"\nr1\n");
    }

    proptest::proptest! {
        /// Any text of directives, macro calls and punctuation: no panic,
        /// the source's line count kept, every mapped place inside the
        /// source.
        #[test]
        fn any_text_keeps_lines_and_maps_inside(parts in proptest::collection::vec(proptest::sample::select(vec![
            "#define A B\n", "#define B(x) x##x A\n", "#define C(a,b) #a b\n", "#if A\n", "#if 1/0\n",
            "#ifdef B\n", "#elif 1\n", "#else\n", "#endif\n", "#undef A\n", "#error e\n", "#\n",
            "#include x\n", "A", "B(", "C(", ")", ",", "(", " ", "\\\n", "\n", "; c\n", "mov r0, c0",
            "__LINE__", "##", "#", "'a'", "\"s\"", "é",
        ]), 0..60)) {
            let src: String = parts.concat();
            let (pre, _) = preprocess(&src);
            proptest::prop_assert_eq!(pre.text.matches('\n').count(), src.matches('\n').count());
            for i in 0..=pre.text.len() {
                for j in [i, (i + 3).min(pre.text.len())] {
                    let s = pre.span(Span::new(i, j));
                    proptest::prop_assert!(s.start <= s.end && s.end as usize <= src.len() + 1, "{:?}", s);
                }
            }
        }
    }
}
