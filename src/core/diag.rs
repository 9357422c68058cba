//! Compiler-style diagnostics for assembly sources.
//!
//! Every problem the front end or validator finds becomes a [`Diagnostic`]
//! with a byte span into a [`SourceFile`]. Rendering goes through
//! codespan-reporting, both to a plain string (tests compare it) and to a
//! colour terminal (the CLI), so a message always names `file:line:col`,
//! shows the source line and puts a caret under the span.
//!
//! A compiled shader has no lines: its [`SourceFile`] holds the listing it
//! disassembles to (what `ps30 disasm` prints, which the front end reads)
//! and anchors from listing offsets to tokens, so its diagnostics name the
//! file's token and byte offset instead of line:col and show the listing
//! line with the caret under the operand.
//!
//! Reporting stays linear in what is shown: duplicates are found through an
//! index, line numbers through the file's line table (built once), at most
//! [`MAX_SHOWN`] diagnostics are rendered (a last line says how many more
//! there were), and a line longer than [`MAX_LINE_SHOWN`] is not echoed.

pub mod codes;

use crate::core::ir::{Origin, Span};
use codespan_reporting::diagnostic::{Diagnostic as CsDiagnostic, Label};
use codespan_reporting::files::{self, Files};
use codespan_reporting::term::{self, Config};
use std::collections::BTreeMap;
use std::fmt;
use std::io::Write;
use std::ops::Range;

/// The most diagnostics rendered for one file; the rest are counted.
pub const MAX_SHOWN: usize = 50;

/// Longest source line (in bytes) echoed under a diagnostic; a longer one is
/// reported as `file:line:col` and the message only.
pub const MAX_LINE_SHOWN: usize = 500;

/// A piece of source text quoted in a message, cut to 40 characters.
pub fn excerpt(text: &str) -> String {
    const MAX: usize = 40;
    match text.char_indices().nth(MAX) {
        None => text.to_string(),
        Some((cut, _)) => format!("{}… ({} characters)", &text[..cut], text.chars().count()),
    }
}

/// A named source text; spans index into `text`.
#[derive(Clone, Debug)]
pub struct SourceFile {
    /// The name shown in diagnostics (a path, or a bundled shader's path).
    pub name: String,
    /// The text, as read up to its first NUL byte.
    pub text: String,
    line_starts: Vec<usize>,
    /// For a compiled shader (`text` is its listing): `(text offset, token
    /// index)` at each line and operand, in text order.
    tokens: Option<Vec<(u32, u32)>>,
    /// For a compiled shader: the CRC-32 of the bytes it was read from.
    bytecode_crc32: Option<u32>,
}

impl SourceFile {
    /// A source named `name`: its text up to the first NUL byte, as
    /// Microsoft's assembler reads it (the tools that dump shaders from
    /// running games end each file with one). A byte-order mark is kept: the
    /// parser refuses it where it stands, as Microsoft's assembler does.
    pub fn new(name: impl Into<String>, text: impl Into<String>) -> SourceFile {
        let mut text = text.into();
        if let Some(nul) = text.find('\0') {
            text.truncate(nul);
        }
        let mut line_starts = vec![0];
        line_starts.extend(text.match_indices('\n').map(|(i, _)| i + 1));
        SourceFile {
            name: name.into(),
            text,
            line_starts,
            tokens: None,
            bytecode_crc32: None,
        }
    }

    /// A compiled shader, as its listing with the token each part of the
    /// listing came from.
    pub fn compiled(
        name: impl Into<String>,
        listing: String,
        anchors: Vec<(u32, u32)>,
    ) -> SourceFile {
        SourceFile {
            tokens: Some(anchors),
            ..SourceFile::new(name, listing)
        }
    }

    /// This compiled shader, remembering the CRC-32 of the bytes it was read
    /// from ([`SourceFile::bytecode_crc32`]).
    pub fn with_bytecode_crc32(self, crc: u32) -> SourceFile {
        SourceFile {
            bytecode_crc32: Some(crc),
            ..self
        }
    }

    /// For a compiled shader: the CRC-32 of its bytes as given (see
    /// [`crate::core::bytecode::crc32`]); `None` for text.
    pub fn bytecode_crc32(&self) -> Option<u32> {
        self.bytecode_crc32
    }

    /// Whether this is a compiled shader's listing.
    pub fn is_compiled(&self) -> bool {
        self.tokens.is_some()
    }

    /// The token a listing offset came from (compiled shaders only).
    pub fn token_at(&self, offset: u32) -> Option<u32> {
        let anchors = self.tokens.as_ref()?;
        let i = anchors.partition_point(|&(at, _)| at <= offset);
        anchors.get(i.checked_sub(1)?).map(|&(_, token)| token)
    }

    /// Where an offset is, for a person: `name:line:col` in text, `name:
    /// token T (byte 0xB)` in a compiled shader.
    pub fn locate(&self, offset: u32) -> String {
        match self.token_at(offset) {
            Some(token) => format!(
                "{}: token {token} (byte {:#x})",
                self.name,
                token as usize * 4
            ),
            None => {
                let (line, col) = self.line_col(offset);
                format!("{}:{line}:{col}", self.name)
            }
        }
    }

    /// 1-based line and column (in characters) of a byte offset.
    pub fn line_col(&self, offset: u32) -> (usize, usize) {
        let offset = (offset as usize).min(self.text.len());
        let line = match self.line_starts.binary_search(&offset) {
            Ok(i) => i,
            Err(i) => i - 1,
        };
        let start = self.line_starts[line];
        let col = self.text[start..offset].chars().count() + 1;
        (line + 1, col)
    }

    /// 1-based line number of a byte offset.
    pub fn line_of(&self, offset: u32) -> usize {
        let offset = (offset as usize).min(self.text.len());
        match self.line_starts.binary_search(&offset) {
            Ok(i) => i + 1,
            Err(i) => i,
        }
    }

    /// The byte range of a 0-based line, line break included.
    fn line_bytes(&self, index: usize) -> Range<usize> {
        let start = self
            .line_starts
            .get(index)
            .copied()
            .unwrap_or(self.text.len());
        let end = self
            .line_starts
            .get(index + 1)
            .copied()
            .unwrap_or(self.text.len());
        start..end
    }

    /// The text of a 1-based line, without its line break.
    pub fn line_text(&self, line: usize) -> &str {
        let start = self.line_starts.get(line - 1).copied().unwrap_or(0);
        let end = self
            .line_starts
            .get(line)
            .copied()
            .unwrap_or(self.text.len());
        self.text[start..end].trim_end_matches(['\n', '\r'])
    }
}

/// The renderer reads lines through the table built once in
/// [`SourceFile::new`], instead of rebuilding it for every diagnostic.
impl<'a> Files<'a> for SourceFile {
    type FileId = ();
    type Name = &'a str;
    type Source = &'a str;

    fn name(&'a self, (): ()) -> Result<&'a str, files::Error> {
        Ok(&self.name)
    }

    fn source(&'a self, (): ()) -> Result<&'a str, files::Error> {
        Ok(&self.text)
    }

    fn line_index(&'a self, (): (), byte_index: usize) -> Result<usize, files::Error> {
        Ok(self
            .line_starts
            .binary_search(&byte_index)
            .unwrap_or_else(|next| next - 1))
    }

    fn line_range(&'a self, (): (), line_index: usize) -> Result<Range<usize>, files::Error> {
        if line_index > self.line_starts.len() {
            return Err(files::Error::LineTooLarge {
                given: line_index,
                max: self.line_starts.len() - 1,
            });
        }
        Ok(self.line_bytes(line_index))
    }
}

/// How bad a diagnostic is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Severity {
    /// The source is usable; something in it is probably not meant.
    Warning,
    /// The source cannot be used.
    Error,
}

/// One problem, with where it is and how to fix it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Diagnostic {
    /// Error or warning.
    pub severity: Severity,
    /// What is wrong, in one sentence.
    pub message: String,
    /// Where (byte offsets into the source).
    pub span: Span,
    /// Short text printed under the caret.
    pub label: String,
    /// Extra spans with their labels (e.g. "block opened here").
    pub secondary: Vec<(Span, String)>,
    /// One-line suggestion.
    pub help: Option<String>,
    /// Further notes (e.g. which REPEAT_BLOCK repetition).
    pub notes: Vec<String>,
    /// Other places with exactly the same problem (message, label and help),
    /// folded into this one by [`Diagnostics::grouped`]: one report, with
    /// the count and the lines, instead of one per unrolled copy.
    pub also: Vec<Span>,
    /// Microsoft's `X####` code for the same refusal (what `D3DAssemble`
    /// answers for the input), from the one table of [`codes`].
    pub code: Option<codes::Code>,
    /// A warning for a rule Microsoft's documentation states but its
    /// assembler does not enforce: `--strict` makes it an error.
    pub strict: bool,
}

impl Diagnostic {
    /// An error at `span`.
    pub fn error(span: Span, message: impl Into<String>) -> Diagnostic {
        Diagnostic {
            severity: Severity::Error,
            message: message.into(),
            span,
            label: String::new(),
            secondary: Vec::new(),
            help: None,
            notes: Vec::new(),
            also: Vec::new(),
            code: None,
            strict: false,
        }
    }

    /// An error at `span` that Microsoft refuses with `code`.
    pub fn coded(code: codes::Code, span: Span, message: impl Into<String>) -> Diagnostic {
        Diagnostic::error(span, message).with_code(code)
    }

    /// Every span of the diagnostic replaced by `f` of it (the
    /// preprocessor's map from the text it wrote back to the source).
    pub fn map_spans(&mut self, f: &dyn Fn(Span) -> Span) {
        self.span = f(self.span);
        for (span, _) in &mut self.secondary {
            *span = f(*span);
        }
        for span in &mut self.also {
            *span = f(*span);
        }
    }

    /// With Microsoft's code for the same refusal.
    pub fn with_code(mut self, code: codes::Code) -> Diagnostic {
        self.code = Some(code);
        self
    }

    /// With Microsoft's code unless one is already set (the code of a
    /// stage, for diagnostics its checks did not name more precisely).
    pub fn or_code(mut self, code: codes::Code) -> Diagnostic {
        self.code.get_or_insert(code);
        self
    }

    /// A warning for a documented rule that Microsoft's assembler does not
    /// enforce: what can go wrong at run time is in its notes, and
    /// `--strict` turns it into an error ([`Diagnostics::make_strict`]).
    pub fn documented_rule(span: Span, message: impl Into<String>) -> Diagnostic {
        Diagnostic {
            strict: true,
            ..Diagnostic::warning(span, message)
        }
    }

    /// A warning at `span`.
    pub fn warning(span: Span, message: impl Into<String>) -> Diagnostic {
        Diagnostic {
            severity: Severity::Warning,
            ..Diagnostic::error(span, message)
        }
    }

    /// With the text under the caret.
    pub fn with_label(mut self, label: impl Into<String>) -> Diagnostic {
        self.label = label.into();
        self
    }

    /// With a one-line suggestion.
    pub fn with_help(mut self, help: impl Into<String>) -> Diagnostic {
        self.help = Some(help.into());
        self
    }

    /// With one more note.
    pub fn with_note(mut self, note: impl Into<String>) -> Diagnostic {
        self.notes.push(note.into());
        self
    }

    /// With another place and its label.
    pub fn with_secondary(mut self, span: Span, label: impl Into<String>) -> Diagnostic {
        self.secondary.push((span, label.into()));
        self
    }

    /// Adds notes saying which REPEAT_BLOCK repetitions the problem is in.
    pub fn in_origin(mut self, origin: &Origin, file: &SourceFile) -> Diagnostic {
        for r in origin.repeats() {
            self.notes.push(format!(
                "in repetition {} of {} of the REPEAT_BLOCK at line {}",
                r.index + 1,
                r.count,
                file.line_of(r.macro_span.start)
            ));
        }
        self
    }

    fn to_codespan(&self, file: &SourceFile) -> CsDiagnostic<()> {
        let base = match self.severity {
            Severity::Error => CsDiagnostic::error(),
            Severity::Warning => CsDiagnostic::warning(),
        };
        let mut labels =
            vec![Label::primary((), self.span.range()).with_message(self.label.clone())];
        for (span, text) in &self.secondary {
            labels.push(Label::secondary((), span.range()).with_message(text.clone()));
        }
        let mut notes = self.notes.clone();
        notes.extend(self.also_note(file));
        if let Some(help) = &self.help {
            notes.push(format!("help: {help}"));
        }
        let base = match self.code {
            Some(code) => base.with_code(code),
            None => base,
        };
        base.with_message(self.message.clone())
            .with_labels(labels)
            .with_notes(notes)
    }

    /// Whether a line this diagnostic points at is too long to echo.
    fn has_long_line(&self, file: &SourceFile) -> bool {
        std::iter::once(self.span)
            .chain(self.secondary.iter().map(|(s, _)| *s))
            .any(|span| {
                let line = file.line_index((), span.start as usize).unwrap_or(0);
                file.line_bytes(line).len() > MAX_LINE_SHOWN
            })
    }

    /// Renders the diagnostic as plain text.
    pub fn render(&self, file: &SourceFile) -> String {
        self.render_styled(file, false)
    }

    /// Renders the diagnostic as text, with ANSI colours when `color` (for
    /// a terminal). The caller decides where it goes.
    pub fn render_styled(&self, file: &SourceFile, color: bool) -> String {
        let mut out = Vec::new();
        if color {
            self.write(file, &mut term::termcolor::Ansi::new(&mut out));
        } else {
            self.write(file, &mut term::termcolor::NoColor::new(&mut out));
        }
        String::from_utf8_lossy(&out).into_owned()
    }

    /// The note that lists the other places of a grouped diagnostic.
    fn also_note(&self, file: &SourceFile) -> Option<String> {
        if self.also.is_empty() {
            return None;
        }
        let (first, last) = self.line_range(file);
        Some(format!(
            "the same {} at {} (lines {first}–{last} in all)",
            match self.severity {
                Severity::Error => "error",
                Severity::Warning => "warning",
            },
            match self.also.len() {
                1 => "1 more place".to_string(),
                n => format!("{n} more places"),
            },
        ))
    }

    /// How many places this diagnostic stands for (1 unless grouped).
    pub fn count(&self) -> usize {
        1 + self.also.len()
    }

    /// The first and last line of every place it stands for.
    pub fn line_range(&self, file: &SourceFile) -> (usize, usize) {
        let lines = std::iter::once(self.span)
            .chain(self.also.iter().copied())
            .map(|s| file.line_of(s.start));
        lines.fold((usize::MAX, 0), |(lo, hi), l| (lo.min(l), hi.max(l)))
    }

    /// A diagnostic in a compiled shader: token and byte instead of
    /// line:col, and the listing line with a caret under the span.
    fn render_compiled(&self, file: &SourceFile) -> String {
        let mut out = format!("{self}\n  --> {}\n", file.locate(self.span.start));
        let snippet = |span: Span, label: &str| {
            let text = excerpt(file.line_text(file.line_of(span.start)));
            let (_, col) = file.line_col(span.start);
            let width = file.text[span.range()]
                .lines()
                .next()
                .map_or(0, |l| l.chars().count())
                .max(1);
            format!(
                "   |\n   | {text}\n   | {}{} {label}\n",
                " ".repeat(col - 1),
                "^".repeat(width)
            )
        };
        out.push_str(&snippet(self.span, &self.label));
        for (span, label) in &self.secondary {
            out.push_str(&format!("   = {label}: {}\n", file.locate(span.start)));
            out.push_str(&snippet(*span, ""));
        }
        for note in &self.notes {
            out.push_str(&format!("   = {note}\n"));
        }
        if let Some(help) = &self.help {
            out.push_str(&format!("   = help: {help}\n"));
        }
        out.push('\n');
        out
    }

    /// Writes the diagnostic to a (colour) stream: compiler-style with the
    /// source line, or as one line when that line is too long to echo.
    pub fn write(&self, file: &SourceFile, w: &mut dyn term::termcolor::WriteColor) {
        if file.is_compiled() {
            let _ = w.write_all(self.render_compiled(file).as_bytes());
            return;
        }
        if self.has_long_line(file)
            || term::emit_to_write_style(w, &Config::default(), file, &self.to_codespan(file))
                .is_err()
        {
            let _ = writeln!(w, "{}", self.fallback(file));
            if let Some(note) = self.also_note(file) {
                let _ = writeln!(w, "  = {note}");
            }
            if let Some(help) = &self.help {
                let _ = writeln!(w, "  = help: {help}");
            }
        }
    }

    /// `file:line:col: severity: message`, used when the renderer cannot be.
    fn fallback(&self, file: &SourceFile) -> String {
        format!("{}: {}", self.location(file), self)
    }

    /// `file:line:col` (a compiled shader: `file: token T (byte 0xB)`), for
    /// one-line summaries.
    pub fn location(&self, file: &SourceFile) -> String {
        file.locate(self.span.start)
    }
}

impl fmt::Display for Diagnostic {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let sev = match self.severity {
            Severity::Error => "error",
            Severity::Warning => "warning",
        };
        match self.code {
            Some(code) => write!(f, "{sev}[{code}]: {}", self.message),
            None => write!(f, "{sev}: {}", self.message),
        }
    }
}

/// All diagnostics of one source; errors make the source unusable.
#[derive(Clone, Debug, Default)]
pub struct Diagnostics {
    /// The diagnostics, in the order they were found (the same span and message once).
    pub items: Vec<Diagnostic>,
    /// Where each (span, message) already is in `items` (a B-tree: as
    /// small as a `Vec`, so results carrying diagnostics stay small).
    seen: BTreeMap<(Span, String), usize>,
}

impl Diagnostics {
    /// Adds `d`, unless the same problem at the same place is already there.
    pub fn push(&mut self, d: Diagnostic) {
        // The same problem in every repetition of a macro is reported once.
        let key = (d.span, d.message.clone());
        if let Some(&i) = self.seen.get(&key) {
            let existing = &mut self.items[i];
            if !existing.notes.iter().any(|n| n.starts_with("and in")) && d.notes != existing.notes
            {
                existing
                    .notes
                    .push("and in other repetitions of the same REPEAT_BLOCK".to_string());
            }
            return;
        }
        self.seen.insert(key, self.items.len());
        self.items.push(d);
    }

    /// Adds every diagnostic of `other`.
    pub fn extend(&mut self, other: Diagnostics) {
        for d in other.items {
            self.push(d);
        }
    }

    /// Whether any diagnostic is an error.
    pub fn has_errors(&self) -> bool {
        self.items.iter().any(|d| d.severity == Severity::Error)
    }

    /// The errors.
    pub fn errors(&self) -> impl Iterator<Item = &Diagnostic> {
        self.items.iter().filter(|d| d.severity == Severity::Error)
    }

    /// The warnings.
    pub fn warnings(&self) -> impl Iterator<Item = &Diagnostic> {
        self.items
            .iter()
            .filter(|d| d.severity == Severity::Warning)
    }

    /// `--strict`: every warning for a documented rule that Microsoft's
    /// assembler does not enforce becomes an error, and so does every
    /// warning Microsoft's assembler refuses ([`Diagnostics::make_refusals`]).
    pub fn make_strict(&mut self) {
        self.make_refusals();
        for d in &mut self.items {
            if d.strict && d.severity == Severity::Warning {
                d.severity = Severity::Error;
                d.notes
                    .push("an error under --strict: Microsoft's assembler accepts it".into());
            }
        }
    }

    /// Writing bytecode: a warning that carries Microsoft's code (one
    /// Microsoft's assembler refuses, which ps30 lets a shader be measured
    /// and run with) becomes an error.
    pub fn make_refusals(&mut self) {
        for d in &mut self.items {
            if d.code.is_some() && d.severity == Severity::Warning {
                d.severity = Severity::Error;
            }
        }
    }

    /// Whether any warning would be an error under `--strict`.
    pub fn has_strict(&self) -> bool {
        self.warnings().any(|d| d.strict || d.code.is_some())
    }

    /// Sorts by position so output reads top to bottom.
    pub fn sort(&mut self) {
        self.items.sort_by_key(|d| (d.span.start, d.severity));
        self.seen = self
            .items
            .iter()
            .enumerate()
            .map(|(i, d)| ((d.span, d.message.clone()), i))
            .collect();
    }

    /// The line after the first [`MAX_SHOWN`] diagnostics saying how many
    /// more there are, if any.
    fn not_shown(grouped: &[Diagnostic]) -> Option<String> {
        let rest = grouped.get(MAX_SHOWN..)?;
        let errors = rest
            .iter()
            .filter(|d| d.severity == Severity::Error)
            .count() as u64;
        let warnings = rest.len() as u64 - errors;
        let count = |n: u64, what: &str| match n {
            0 => None,
            1 => Some(format!("1 more {what}")),
            n => Some(format!(
                "{} more {what}s",
                crate::core::numbers::thousands(n)
            )),
        };
        let parts: Vec<String> = [count(errors, "error"), count(warnings, "warning")]
            .into_iter()
            .flatten()
            .collect();
        Some(format!(
            "... and {} not shown (only the first {MAX_SHOWN} are)\n",
            parts.join(" and ")
        ))
    }

    /// Renders the first [`MAX_SHOWN`] diagnostics as plain text (identical
    /// ones grouped), and a line counting the rest.
    pub fn render(&self, file: &SourceFile) -> String {
        let mut out = Vec::new();
        self.write(file, &mut term::termcolor::NoColor::new(&mut out));
        String::from_utf8_lossy(&out).into_owned()
    }

    /// Writes what [`Diagnostics::render`] renders to a (colour) stream.
    pub fn write(&self, file: &SourceFile, w: &mut dyn term::termcolor::WriteColor) {
        let grouped = self.grouped();
        for d in grouped.iter().take(MAX_SHOWN) {
            d.write(file, w);
        }
        if let Some(line) = Self::not_shown(&grouped) {
            let _ = w.write_all(line.as_bytes());
        }
    }

    /// What [`Diagnostics::render`] renders, with ANSI colours when `color`.
    pub fn render_styled(&self, file: &SourceFile, color: bool) -> String {
        let mut out = Vec::new();
        if color {
            self.write(file, &mut term::termcolor::Ansi::new(&mut out));
        } else {
            self.write(file, &mut term::termcolor::NoColor::new(&mut out));
        }
        String::from_utf8_lossy(&out).into_owned()
    }

    /// The diagnostics with identical ones — the same severity, message,
    /// label and help at different places, as the copies of one unrolled
    /// instruction give — folded into the first of them (its
    /// [`Diagnostic::also`] lists the others). Order is kept. Every command
    /// prints and serialises diagnostics through this, so one problem is one
    /// report, with its count and lines, in text and JSON alike.
    pub fn grouped(&self) -> Vec<Diagnostic> {
        group(&self.items)
    }

    /// Writes them to stderr, in colour when `color`, through one buffer.
    pub fn emit(&self, file: &SourceFile, color: bool) {
        use term::termcolor::{BufferedStandardStream, ColorChoice};
        let choice = if color {
            ColorChoice::Auto
        } else {
            ColorChoice::Never
        };
        let mut stream = BufferedStandardStream::stderr(choice);
        self.write(file, &mut stream);
        let _ = stream.flush();
    }
}

/// [`Diagnostics::grouped`] for any list of diagnostics.
pub fn group(items: &[Diagnostic]) -> Vec<Diagnostic> {
    let keys = items.iter().map(|d| {
        (
            d.severity,
            d.message.as_str(),
            d.label.as_str(),
            d.help.as_deref(),
        )
    });
    group_indices(keys)
        .into_iter()
        .map(|members| {
            let mut first = items[members[0]].clone();
            for &i in &members[1..] {
                first.also.push(items[i].span);
                first.also.extend(items[i].also.iter().copied());
            }
            first
        })
        .collect()
}

/// The rule that groups identical findings, for every kind of finding
/// (validator diagnostics here, draw findings in
/// [`crate::core::emu::findings`]): the indices of `keys` grouped by equal
/// key, each group in order and the groups in order of first appearance.
pub fn group_indices<K: Eq + std::hash::Hash>(keys: impl Iterator<Item = K>) -> Vec<Vec<usize>> {
    let mut groups: Vec<Vec<usize>> = Vec::new();
    let mut index: std::collections::HashMap<K, usize> = std::collections::HashMap::new();
    for (i, key) in keys.enumerate() {
        match index.get(&key) {
            Some(&g) => groups[g].push(i),
            None => {
                index.insert(key, groups.len());
                groups.push(vec![i]);
            }
        }
    }
    groups
}

/// A source that could not be turned into a shader, with its diagnostics.
#[derive(Clone, Debug)]
pub struct SourceError {
    /// The source.
    pub file: SourceFile,
    /// Why it is unusable (at least one error).
    pub diagnostics: Diagnostics,
}

impl fmt::Display for SourceError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let n = self.diagnostics.errors().count();
        match self.diagnostics.errors().next() {
            Some(first) => write!(
                f,
                "{}: {} ({} error{} in all)",
                first.location(&self.file),
                first,
                n,
                if n == 1 { "" } else { "s" }
            ),
            None => write!(f, "{}: invalid shader", self.file.name),
        }
    }
}

impl std::error::Error for SourceError {}
