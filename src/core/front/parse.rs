//! The nom parser: assembly text → [`Stmt`]s with byte spans.
//!
//! ps_3_0 assembly is line oriented: one statement per line, comments start
//! with `//` or `;`. One kind of comment line is read: `//#comment` (and its
//! `//#+` continuation lines) holds the tokens of a comment block of a
//! compiled shader, in hexadecimal, so that a listing keeps the constant
//! table and other blocks byte for byte (other assemblers skip the lines). Each line is read by a small recursive-descent reader
//! (`Cursor`) whose tokens are nom parsers; the reader turns a failed token
//! into a diagnostic that points at the exact column and says what was
//! expected. Parsing never stops at the first bad line: every line is read,
//! and all errors are returned together.

use super::ast::{CompactString, Count, InstrAst, OperandAst, RegAst, RelAst, Stmt};
use super::preprocess;
use crate::core::diag::{codes, excerpt, Diagnostic, Diagnostics};
use crate::core::ir::Span;
use nom::branch::alt;
use nom::bytes::complete::{tag, take_while, take_while1};
use nom::character::complete::{char, digit1, space0};
use nom::combinator::recognize;
use nom::number::complete::recognize_float;
use nom::sequence::pair;
use nom::{IResult, Parser};

type NomError<'a> = nom::error::Error<&'a str>;

/// The most statements [`parse`] reserves room for before it reads them.
const MAX_RESERVED_STATEMENTS: usize = 1 << 12;

/// Parses a whole source. Returns the statements of every line that parsed
/// and the diagnostics of every line that did not.
pub fn parse(text: &str) -> (Vec<Stmt>, Diagnostics) {
    let mut diags = Diagnostics::default();
    let blanked = blank(text, &mut diags);
    if !preprocess::needed(&blanked) {
        let (stmts, more) = parse_lines(&blanked);
        diags.extend(more);
        return (stmts, diags);
    }
    // Microsoft's assembler reads what its preprocessor writes; ps30 reads
    // the same text, and puts every place back where the source has it.
    let (pre, pre_diags) = preprocess::preprocess(&blanked);
    let (mut stmts, more) = parse_lines(&pre.text);
    let to_source = |span: Span| pre.span(span);
    for stmt in &mut stmts {
        stmt.map_spans(&to_source);
    }
    diags.extend(pre_diags);
    for mut d in more.items {
        d.map_spans(&to_source);
        diags.push(d);
    }
    (stmts, diags)
}

/// The text as Microsoft's assembler's grammar reads it, for a reader of
/// another instruction set (ps_1_x, `core::ps1`): comments blanked, the
/// preprocessor run where the text uses it, with a map from places in the
/// returned text back to the source. Line comments (`//`, `;`) are left for
/// the reader ([`strip_comment`]).
pub(crate) fn prepare(text: &str) -> (String, Box<dyn Fn(Span) -> Span>, Diagnostics) {
    let mut diags = Diagnostics::default();
    let blanked = blank(text, &mut diags).into_owned();
    if !preprocess::needed(&blanked) {
        return (blanked, Box::new(|s| s), diags);
    }
    let (pre, pre_diags) = preprocess::preprocess(&blanked);
    diags.extend(pre_diags);
    let text = pre.text.clone();
    (text, Box::new(move |s| pre.span(s)), diags)
}

/// The statements of text that needs no preprocessing (comments blanked),
/// and the diagnostics of every line that did not parse.
fn parse_lines(text: &str) -> (Vec<Stmt>, Diagnostics) {
    let mut diags = Diagnostics::default();
    // At most one statement per line: room for them at once rather than
    // copying the list as it grows (capped, so a file of empty lines does
    // not reserve room it will not use).
    let lines = text.bytes().filter(|&b| b == b'\n').count() + 1;
    let mut stmts = Vec::with_capacity(lines.min(MAX_RESERVED_STATEMENTS));
    let mut line_start = 0;
    // Whether the previous line was a comment-block line that `//#+` continues.
    let mut in_block = false;
    for line in text.split_inclusive('\n') {
        let raw = line.trim_end_matches(['\n', '\r']);
        let lead = raw.len() - raw.trim_start().len();
        if let Some(block) = comment_block_line(raw.trim(), line_start + lead) {
            match block {
                Ok(BlockLine { more, tokens, span }) => {
                    let extended = extend_comment_block(&mut stmts, more, in_block, tokens, span);
                    in_block = extended.is_ok();
                    if let Err(d) = extended {
                        diags.push(d);
                    }
                }
                Err(d) => {
                    in_block = false;
                    diags.push(d);
                }
            }
            line_start += line.len();
            continue;
        }
        in_block = false;
        let code = strip_comment(raw);
        let code = code.trim();
        // `#line N "file"` only renames places for Microsoft's
        // preprocessor, which reads it: nothing to assemble (the file name
        // may hold `;`, a comment elsewhere, so the raw line is read too).
        let code = if is_line_directive(raw.trim()) || is_line_directive(code) {
            ""
        } else {
            code
        };
        if let Some((at, c)) = code.char_indices().find(|&(_, c)| odd_char(c)) {
            let at = line_start + lead + at;
            diags.push(odd_char_error(c, Span::new(at, at + c.len_utf8()), at == 0));
            stmts.extend(macro_placeholder(
                code,
                Span::new(line_start + lead, line_start + lead + code.len()),
            ));
        } else if !code.is_empty() {
            let start = line_start + lead;
            let mut cursor = Cursor {
                text: code,
                rest: code,
                base: start,
            };
            // Statements follow each other on a line as Microsoft's
            // assembler reads them (`ps_3_0 mov oC0, c0`): one ends where
            // its operands do.
            loop {
                match cursor.statement() {
                    Ok(stmt) => stmts.push(stmt),
                    Err(d) => {
                        // A bad REPEAT_BLOCK line still opens or closes its
                        // block, so its partner line is not reported as
                        // unmatched too.
                        stmts.extend(macro_placeholder(
                            code,
                            Span::new(start, start + code.len()),
                        ));
                        diags.push(d);
                        break;
                    }
                }
                cursor.skip_space();
                if cursor.rest.is_empty() {
                    break;
                }
                let at = cursor.pos();
                cursor.text = cursor.rest;
                cursor.base = at;
            }
        }
        line_start += line.len();
    }
    // Whatever a line alone gets wrong, Microsoft's grammar refuses as a
    // syntax error unless the check named its code.
    for d in &mut diags.items {
        d.code.get_or_insert(codes::SYNTAX);
    }
    (stmts, diags)
}

/// The text as Microsoft's assembler reads it, byte for byte the same
/// length so that spans still index the source: `/* … */` comments (which
/// its preprocessor removes) blanked, vertical tabs and form feeds read as
/// spaces, and a carriage return that ends no CR LF pair read as a line end
/// (it accepts files with old Macintosh line ends). A `/*` never closed is
/// an error, as there.
fn blank<'t>(text: &'t str, diags: &mut Diagnostics) -> std::borrow::Cow<'t, str> {
    let needs = text.contains("/*")
        || text.bytes().enumerate().any(|(i, b)| {
            matches!(b, 0x0b | 0x0c) || (b == b'\r' && text.as_bytes().get(i + 1) != Some(&b'\n'))
        });
    if !needs {
        return std::borrow::Cow::Borrowed(text);
    }
    let mut out = text.as_bytes().to_vec();
    let mut i = 0;
    let mut line_comment = false;
    while i < out.len() {
        match out[i] {
            b'\n' => line_comment = false,
            b'\r' if out.get(i + 1) != Some(&b'\n') => {
                out[i] = b'\n';
                line_comment = false;
            }
            0x0b | 0x0c => out[i] = b' ',
            b'/' if !line_comment && out.get(i + 1) == Some(&b'/') => line_comment = true,
            b'/' if !line_comment && out.get(i + 1) == Some(&b'*') => {
                let end = text[i + 2..].find("*/").map(|e| i + 2 + e + 2);
                if end.is_none() {
                    diags.push(
                        Diagnostic::coded(
                            codes::UNCLOSED_COMMENT,
                            Span::new(i, i + 2),
                            "comment continues past the end of the file",
                        )
                        .with_label("this `/*` is never closed")
                        .with_help("close it with `*/`"),
                    );
                }
                for b in &mut out[i..end.unwrap_or(text.len())] {
                    if *b != b'\n' && *b != b'\r' {
                        *b = b' ';
                    }
                }
                i = end.unwrap_or(text.len());
                continue;
            }
            _ => {}
        }
        i += 1;
    }
    // Only ASCII bytes were replaced, by ASCII, and every byte of a comment
    // (whole characters) by spaces: still UTF-8.
    std::borrow::Cow::Owned(String::from_utf8(out).expect("blanking keeps UTF-8"))
}

/// The line that opens a kept comment block of a compiled shader, and the
/// line that continues it.
pub const COMMENT_BLOCK: &str = "//#comment";
/// The continuation line of a kept comment block.
pub const COMMENT_MORE: &str = "//#+";

/// Most tokens one comment block holds: its length field has 15 bits.
pub const MAX_COMMENT_TOKENS: usize = 0x7fff;

/// One `//#comment` or `//#+` line.
struct BlockLine {
    /// A `//#+` line: it continues the block above.
    more: bool,
    tokens: Vec<u32>,
    span: Span,
}

/// A `//#comment` or `//#+` line (trimmed, starting at `start`); `None`
/// for any other line.
fn comment_block_line(line: &str, start: usize) -> Option<Result<BlockLine, Diagnostic>> {
    let (more, rest) = if let Some(rest) = line.strip_prefix(COMMENT_BLOCK) {
        (false, rest)
    } else {
        (true, line.strip_prefix(COMMENT_MORE)?)
    };
    if rest.starts_with(|c: char| !c.is_whitespace()) {
        return None;
    }
    let span = Span::new(start, start + line.len());
    let mut tokens = Vec::new();
    let mut offset = start + line.len() - rest.len();
    for word in rest.split_inclusive(char::is_whitespace) {
        let hex = word.trim_end();
        let at = Span::new(offset, offset + hex.len());
        offset += word.len();
        if hex.is_empty() {
            continue;
        }
        let valid = hex.len() <= 8 && hex.chars().all(|c| c.is_ascii_hexdigit());
        match u32::from_str_radix(hex, 16) {
            Ok(t) if valid => tokens.push(t),
            _ => {
                return Some(Err(Diagnostic::error(
                    at,
                    format!("`{hex}` is not a 32-bit token in hexadecimal"),
                )
                .with_label("expected 1 to 8 hexadecimal digits")
                .with_help(format!(
                    "a kept comment block is written `{COMMENT_BLOCK} 43544142 …`, continued by `{COMMENT_MORE} …` lines"
                ))))
            }
        }
    }
    Some(Ok(BlockLine { more, tokens, span }))
}

/// Starts a comment block (`more` false), or adds a `//#+` line to the
/// block the previous line belongs to (`open`). Errors for a `//#+` line
/// with no block before it and for a block longer than a comment token can
/// say.
fn extend_comment_block(
    stmts: &mut Vec<Stmt>,
    more: bool,
    open: bool,
    tokens: Vec<u32>,
    span: Span,
) -> Result<(), Diagnostic> {
    let len = match stmts.last_mut() {
        Some(Stmt::Comment {
            tokens: block,
            span: block_span,
        }) if more && open => {
            block.extend(tokens);
            *block_span = block_span.to(span);
            block.len()
        }
        _ if more => {
            return Err(Diagnostic::error(
                span,
                format!("`{COMMENT_MORE}` continues a comment block, but none is open here"),
            )
            .with_label("no block to continue")
            .with_help(format!(
                "start the block with a `{COMMENT_BLOCK}` line just above"
            )))
        }
        _ => {
            let len = tokens.len();
            stmts.push(Stmt::Comment { tokens, span });
            len
        }
    };
    if len > MAX_COMMENT_TOKENS {
        return Err(Diagnostic::error(
            span,
            format!(
                "the comment block holds {len} tokens; a comment token can say at most {MAX_COMMENT_TOKENS}"
            ),
        )
        .with_label("too long"));
    }
    Ok(())
}

/// Whether `c` cannot be part of ps_3_0 assembly outside a comment: the
/// language is printable ASCII, spaces and tabs.
fn odd_char(c: char) -> bool {
    !(c == ' ' || c == '\t' || c.is_ascii_graphic())
}

/// The error for a character assembly cannot hold, naming it by code point
/// (and by name where it is a usual suspect: pasted text, a foreign line
/// ending, a look-alike letter).
fn odd_char_error(c: char, span: Span, file_start: bool) -> Diagnostic {
    let code = format!("U+{:04X}", c as u32);
    let (what, help) = match c {
        '\u{feff}' if file_start => (
            "a UTF-8 byte-order mark starts the file, and Microsoft's assembler refuses it (X2001: shader version expected)".to_string(),
            "save the file as UTF-8 without a byte-order mark (BOM), or as plain ASCII",
        ),
        '\r' => (
            "a carriage return (CR) that does not end a line: the file uses lone-CR line endings".to_string(),
            "ps30 reads LF or CR LF line endings; convert the file",
        ),
        '\0' => (
            "a NUL byte".to_string(),
            "the file holds binary data here; assembly is plain text",
        ),
        '\u{a0}' => (
            "a no-break space".to_string(),
            "replace it with an ordinary space (it often comes from pasted text)",
        ),
        '\u{200b}' | '\u{200c}' | '\u{200d}' | '\u{2060}' | '\u{feff}' => (
            "an invisible zero-width character".to_string(),
            "delete it (it often comes from pasted text)",
        ),
        '\u{0370}'..='\u{03ff}' | '\u{0400}'..='\u{04ff}' => (
            format!("the {} letter `{c}`", if (c as u32) < 0x400 { "Greek" } else { "Cyrillic" }),
            "type it as a Latin letter: mnemonics and registers are ASCII, and this one only looks like one",
        ),
        c if c.is_control() => (
            "a control character".to_string(),
            "assembly is plain text; delete it",
        ),
        c => (
            format!("the character `{c}`"),
            "ps_3_0 assembly is ASCII outside comments",
        ),
    };
    // A byte-order mark is where Microsoft's assembler looks for the
    // version: "shader version expected".
    let x = if c == '\u{feff}' && file_start {
        codes::VERSION
    } else {
        codes::SYNTAX
    };
    Diagnostic::coded(x, span, format!("unexpected {code}: {what}"))
        .with_label(format!("{code} here"))
        .with_help(help)
}

/// What a REPEAT_BLOCK line that did not parse stands for: a block of 0
/// repetitions opened, or a block closed.
fn macro_placeholder(code: &str, span: Span) -> Option<Stmt> {
    if repeat_keyword("begin").parse(code).is_ok() {
        Some(Stmt::RepeatBegin {
            count: Count::Literal { value: 0, span },
            span,
        })
    } else if repeat_keyword("end").parse(code).is_ok() {
        Some(Stmt::RepeatEnd { span })
    } else {
        None
    }
}

/// Whether a (trimmed) line is `#line N` or `#line N "FILE"`: Microsoft's
/// listings of shaders compiled with debug information hold such lines, and
/// its assembler's preprocessor takes them as a source position, which
/// assembles to nothing.
fn is_line_directive(line: &str) -> bool {
    let Some(rest) = line.strip_prefix("#line") else {
        return false;
    };
    let number = rest.trim_start();
    if number.len() == rest.len() {
        return false;
    }
    let digits = number.len()
        - number
            .trim_start_matches(|c: char| c.is_ascii_digit())
            .len();
    let file = number[digits..].trim();
    digits > 0
        && (file.is_empty()
            || (file.len() >= 2
                && file.starts_with('"')
                && file.ends_with('"')
                && !file[1..file.len() - 1].contains('"')))
}

/// The code part of a line: everything before `//` or `;`.
pub(crate) fn strip_comment(line: &str) -> &str {
    let cut = [line.find("//"), line.find(';')]
        .into_iter()
        .flatten()
        .min()
        .unwrap_or(line.len());
    &line[..cut]
}

fn is_ident_char(c: char) -> bool {
    c.is_ascii_alphanumeric() || c == '_'
}

/// Separators inside the article's spelling `BEGIN REPEAT BLOCK(n)`.
fn macro_sep(i: &str) -> IResult<&str, &str> {
    take_while1(|c: char| c == '_' || c == ' ' || c == '\t').parse(i)
}

/// `word` in any ASCII case. Every keyword of the language is ASCII; nom's
/// `tag_no_case` compares Unicode lowercase letter by letter, which was a
/// tenth of loading a long listing (and took `K`, the Kelvin sign, for `k`).
fn ascii_tag<'a>(word: &'static str) -> impl Fn(&'a str) -> IResult<&'a str, &'a str> {
    move |i: &'a str| match i.get(..word.len()) {
        Some(head) if head.eq_ignore_ascii_case(word) => Ok((&i[word.len()..], head)),
        _ => Err(nom::Err::Error(NomError::new(
            i,
            nom::error::ErrorKind::Tag,
        ))),
    }
}

fn repeat_keyword<'a>(
    word: &'static str,
) -> impl Parser<&'a str, Output = (), Error = NomError<'a>> {
    (
        ascii_tag(word),
        macro_sep,
        ascii_tag("repeat"),
        macro_sep,
        ascii_tag("block"),
    )
        .map(|_| ())
}

/// `ps_3_0`, `ps.3.0`, `vs_2_0`, `ps_2_x`... (other versions are read to be
/// refused by name)
fn version(i: &str) -> IResult<&str, (u32, u32)> {
    let sep = |i| alt((char('_'), char('.'))).parse(i);
    // Microsoft's assembler reads the language in lower case only (`PS_3_0`
    // is "shader version expected", `MOV` a syntax error): only REPEAT_BLOCK,
    // ps30's own, is read in any case.
    let (i, _) = alt((tag("ps"), tag("vs"))).parse(i)?;
    let (i, _) = sep(i)?;
    let (i, major) = digit1(i)?;
    let (i, _) = sep(i)?;
    // Any minor: digits, or `x`, `sw`, `a`, `b` (ps_2_x, vs_3_sw, ps_2_a).
    let (i, minor) = take_while1(|c: char| c.is_ascii_alphanumeric()).parse(i)?;
    let minor = minor.parse().unwrap_or(1);
    Ok((i, (major.parse().unwrap_or(0), minor)))
}

/// A reader over one line's code, producing spans relative to the file.
struct Cursor<'a> {
    /// The line's code (comment stripped, trimmed).
    text: &'a str,
    /// What is left to read.
    rest: &'a str,
    /// Byte offset of `text` in the file.
    base: usize,
}

impl<'a> Cursor<'a> {
    /// File offset of the current position.
    fn pos(&self) -> usize {
        self.base + (self.text.len() - self.rest.len())
    }

    fn span_from(&self, start: usize) -> Span {
        Span::new(start, self.pos())
    }

    /// Runs a nom parser at the current position; on success moves past what
    /// it read.
    fn eat<O>(
        &mut self,
        mut p: impl Parser<&'a str, Output = O, Error = NomError<'a>>,
    ) -> Option<O> {
        match p.parse(self.rest) {
            Ok((rest, out)) => {
                self.rest = rest;
                Some(out)
            }
            Err(_) => None,
        }
    }

    fn skip_space(&mut self) {
        self.eat(space0);
    }

    /// An error at the current position covering the next token.
    fn error_here(&self, message: impl Into<String>) -> Diagnostic {
        let tok_len = self
            .rest
            .char_indices()
            .find(|&(_, c)| c == ',' || c.is_whitespace())
            .map(|(i, _)| i)
            .unwrap_or(self.rest.len())
            .max(self.rest.chars().next().map_or(0, char::len_utf8));
        let start = self.pos();
        Diagnostic::error(Span::new(start, start + tok_len), message)
    }

    fn found(&self) -> String {
        match self.rest.split([',', ' ', '\t']).next() {
            Some(t) if !t.is_empty() => format!("found `{}`", excerpt(t)),
            _ => match self.rest.chars().next() {
                Some(c) => format!("found `{c}`"),
                None => "found the end of the line".to_string(),
            },
        }
    }

    fn statement(&mut self) -> Result<Stmt, Diagnostic> {
        let start = self.pos();
        if let Some((major, minor)) = self.eat(version) {
            if self.rest.trim().is_empty() || self.rest.starts_with([' ', '\t']) {
                let text = &self.text[..self.text.len() - self.rest.len()];
                return Ok(Stmt::Version {
                    text: text.to_string(),
                    major,
                    minor,
                    span: self.span_from(start),
                });
            }
            self.rest = self.text;
        }
        if self.eat(repeat_keyword("begin")).is_some() {
            return self.repeat_begin(start);
        }
        if self.eat(repeat_keyword("end")).is_some() {
            self.skip_space();
            if !self.rest.is_empty() {
                return Err(self
                    .error_here(format!(
                        "unexpected text after END_REPEAT_BLOCK: {}",
                        self.found()
                    ))
                    .with_label("nothing may follow END_REPEAT_BLOCK"));
            }
            return Ok(Stmt::RepeatEnd {
                span: self.span_from(start),
            });
        }
        self.instruction(start).map(Stmt::Instr)
    }

    fn repeat_begin(&mut self, start: usize) -> Result<Stmt, Diagnostic> {
        self.skip_space();
        if self.eat(char('(')).is_none() {
            return Err(self
                .error_here(format!(
                    "expected `(` after BEGIN_REPEAT_BLOCK, {}",
                    self.found()
                ))
                .with_help("write BEGIN_REPEAT_BLOCK(125) or BEGIN_REPEAT_BLOCK(name)"));
        }
        self.skip_space();
        let cstart = self.pos();
        let count = if let Some(digits) = self.eat(digit1) {
            let span = self.span_from(cstart);
            let value = digits.parse::<u64>().map_err(|_| {
                Diagnostic::error(span, "REPEAT_BLOCK count is too large")
                    .with_label("does not fit in 64 bits")
            })?;
            Count::Literal { value, span }
        } else if let Some(name) = self.eat(recognize(pair(
            take_while1(|c: char| c.is_ascii_alphabetic() || c == '_'),
            take_while(is_ident_char),
        ))) {
            Count::Name {
                name: name.to_string(),
                span: self.span_from(cstart),
            }
        } else {
            return Err(self
                .error_here(format!("expected a repetition count, {}", self.found()))
                .with_label("a non-negative integer or a name")
                .with_help(
                    "use a literal (BEGIN_REPEAT_BLOCK(125)) or a name bound with -D name=value",
                ));
        };
        self.skip_space();
        if self.eat(char(')')).is_none() {
            return Err(self
                .error_here(format!(
                    "expected `)` after the repetition count, {}",
                    self.found()
                ))
                .with_label("expected `)`"));
        }
        self.skip_space();
        if !self.rest.is_empty() {
            return Err(self.error_here(format!(
                "unexpected text after BEGIN_REPEAT_BLOCK(...): {}",
                self.found()
            )));
        }
        Ok(Stmt::RepeatBegin {
            count,
            span: self.span_from(start),
        })
    }

    fn instruction(&mut self, start: usize) -> Result<InstrAst, Diagnostic> {
        let predicate = if self.eat(char('(')).is_some() {
            self.skip_space();
            let reg = self.register()?;
            self.skip_space();
            if self.eat(char(')')).is_none() {
                return Err(self
                    .error_here(format!(
                        "expected `)` to close the predicate, {}",
                        self.found()
                    ))
                    .with_help("a predicate is written (p0), (p0.x) or (!p0.y)"));
            }
            self.skip_space();
            Some(reg)
        } else {
            None
        };
        let mstart = self.pos();
        let Some(mnemonic) = self.eat(recognize(pair(
            take_while1(|c: char| c.is_ascii_alphabetic()),
            take_while(is_ident_char),
        ))) else {
            if self.rest.starts_with('+') {
                return Err(self
                    .error_here("co-issue (`+`) does not exist in ps_3_0")
                    .with_code(codes::COISSUE)
                    .with_help("remove the `+`: ps_3_0 instructions are issued one at a time"));
            }
            if self.rest.starts_with('#') {
                return Err(self
                    .error_here("a `#` where an instruction goes")
                    .with_code(codes::PREPROCESSOR)
                    .with_help("a directive (#define, #if, …) stands at the start of its own line; write comments with // or ;"));
            }
            return Err(self
                .error_here(format!("expected an instruction, {}", self.found()))
                .with_label("not an instruction mnemonic"));
        };
        let mut parts = mnemonic.split('_');
        let base = CompactString::from(parts.next().unwrap_or_default());
        let base_span = Span::new(mstart, mstart + base.len());
        let mut suffixes = Vec::new();
        let mut off = mstart + base.len();
        for part in parts {
            off += 1;
            suffixes.push((
                CompactString::from(part),
                Span::new(off - 1, off + part.len()),
            ));
            off += part.len();
        }
        let mut operands = Vec::new();
        let before_space = self.rest.len();
        self.skip_space();
        let expected = operand_count(&base, !suffixes.is_empty());
        // Another statement follows when this one has its operands and the
        // next word is a mnemonic.
        let next_statement = |c: &Self, n: usize| {
            let word = c
                .rest
                .split(|ch: char| !is_ident_char(ch))
                .next()
                .unwrap_or("");
            let base = word.split('_').next().unwrap_or("");
            expected == Some(n)
                && c.rest.starts_with(|ch: char| ch.is_ascii_alphabetic())
                && operand_count(base, word.len() > base.len()).is_some()
        };
        if !self.rest.is_empty() && !next_statement(self, 0) {
            if self.rest.len() == before_space {
                return Err(self
                    .error_here(format!("unexpected character after `{mnemonic}`"))
                    .with_label("expected a space before the operands"));
            }
            let writes = writes_destination(&base, !suffixes.is_empty());
            loop {
                // A number where the destination goes (`texkill 1-r0`) is
                // a syntax error to Microsoft's grammar, not a complement.
                let at_destination = writes && operands.is_empty();
                operands.push(self.operand().map_err(|d| match d.code {
                    Some(codes::COMPLEMENT) if at_destination => d.with_code(codes::SYNTAX),
                    _ => d,
                })?);
                self.skip_space();
                if self.rest.is_empty() {
                    break;
                }
                if next_statement(self, operands.len()) {
                    break;
                }
                if self.eat(char(',')).is_none() {
                    return Err(self
                        .error_here(format!(
                            "expected `,` or the end of the line, {}",
                            self.found()
                        ))
                        .with_label("expected `,`"));
                }
                self.skip_space();
                if self.rest.is_empty() {
                    return Err(self
                        .error_here("expected an operand after `,`")
                        .with_label("operand missing"));
                }
            }
        }
        Ok(InstrAst {
            predicate,
            base,
            base_span,
            suffixes,
            operands,
            span: self.span_from(start),
        })
    }

    /// After the digits `text` (started at `start`), a hexadecimal integer
    /// (`0x10`), which Microsoft's assembler reads besides decimal numbers
    /// (the infinities and NaNs of its listings are [`Self::special_float`]).
    fn special_number(
        &mut self,
        text: &str,
        start: usize,
    ) -> Option<Result<OperandAst, Diagnostic>> {
        let negative = text.starts_with('-');
        let hex =
            matches!(text.trim_start_matches(['-', '+']), "0") && self.rest.starts_with(['x', 'X']);
        let (value, integer) = if hex {
            let digits = self.rest[1..]
                .find(|c: char| !c.is_ascii_hexdigit())
                .map_or(&self.rest[1..], |end| &self.rest[1..1 + end]);
            let value = u64::from_str_radix(digits, 16).ok()? as f64;
            self.rest = &self.rest[1 + digits.len()..];
            (if negative { -value } else { value }, true)
        } else {
            return None;
        };
        if self
            .rest
            .starts_with(|c: char| is_ident_char(c) || c == '.')
        {
            return Some(Err(self
                .error_here(format!("malformed number, {}", self.found()))
                .with_label("unexpected characters after the number")));
        }
        Some(Ok(OperandAst::Number {
            value,
            integer,
            special: false,
            span: self.span_from(start),
        }))
    }

    fn operand(&mut self) -> Result<OperandAst, Diagnostic> {
        let start = self.pos();
        // A number: optional sign, digits or a leading '.', optional f/h suffix.
        let looks_numeric = {
            let r = self.rest.strip_prefix(['-', '+']).unwrap_or(self.rest);
            r.starts_with(|c: char| c.is_ascii_digit()) || r.starts_with('.')
        };
        if looks_numeric {
            if let Some(value) = self.special_float() {
                return Ok(OperandAst::Number {
                    value,
                    integer: false,
                    special: true,
                    span: self.span_from(start),
                });
            }
            let Some(text) = self.eat(recognize_float::<&str, NomError>) else {
                return Err(self.error_here(format!("malformed number, {}", self.found())));
            };
            if let Some(n) = self.special_number(text, start) {
                return n;
            }
            // Microsoft's lexer reads C float literals: a number with a
            // point or an exponent may end in f or h (float, half); a
            // plain integer may not (`1f` is refused, `1.5h` is taken).
            let integer = !text.contains(['.', 'e', 'E']);
            if !integer {
                self.eat(alt((char('f'), char('F'), char('h'), char('H'))));
            }
            let span = self.span_from(start);
            if self.rest.trim_start().starts_with('-') {
                return Err(self
                    .error_here("`1-r#` (complement) does not exist in ps_3_0")
                    .with_code(codes::COMPLEMENT)
                    .with_help("compute 1 - x with add r#, c#, -r# and a constant of 1"));
            }
            if self
                .rest
                .starts_with(|c: char| is_ident_char(c) || c == '.')
            {
                return Err(self
                    .error_here(format!(
                        "malformed number `{}{}`",
                        text,
                        self.rest.split([',', ' ']).next().unwrap_or("")
                    ))
                    .with_label("unexpected characters after the number"));
            }
            let value: f64 = text.parse().map_err(|_| {
                Diagnostic::error(span, format!("malformed number `{text}`"))
                    .with_label("not a number")
            })?;
            return Ok(OperandAst::Number {
                value,
                integer,
                special: false,
                span,
            });
        }
        if let Some(word) = self.eat(alt((tag("true"), tag("false")))) {
            if !self.rest.starts_with(is_ident_char) {
                return Ok(OperandAst::Bool {
                    value: word == "true",
                    span: self.span_from(start),
                });
            }
            self.rest = &self.text[start - self.base..];
        }
        self.register().map(OperandAst::Reg)
    }

    /// The spellings of infinities and NaNs that Microsoft's C runtime
    /// prints and Microsoft's assembler reads back: `1.#INF`, `1.#QNAN`,
    /// `1.#SNAN`, `1.#IND` (exactly so, upper case), with an optional sign
    /// that flips the sign bit. The NaNs are the ones the assembler writes
    /// (`1.#QNAN` and `1.#SNAN` 0x7FE00000, `1.#IND` 0xFFC00000, as
    /// doubles whose conversion to single precision gives those bits; see
    /// [`super::ast::single`]).
    fn special_float(&mut self) -> Option<f64> {
        let (negative, rest) = match self.rest.as_bytes().first() {
            Some(b'-') => (true, &self.rest[1..]),
            Some(b'+') => (false, &self.rest[1..]),
            _ => (false, self.rest),
        };
        let rest = rest.strip_prefix("1.#")?;
        let (bits, len): (u64, usize) = [
            ("INF", 0x7FF0_0000_0000_0000),
            ("QNAN", 0x7FFC_0000_0000_0000),
            ("SNAN", 0x7FFC_0000_0000_0000),
            ("IND", 0xFFF8_0000_0000_0000),
        ]
        .iter()
        .find(|(word, _)| rest.starts_with(word))
        .map(|&(word, bits)| (bits, word.len()))?;
        if rest[len..].starts_with(|c: char| is_ident_char(c) || c == '.' || c == '#') {
            return None;
        }
        let used = self.rest.len() - rest.len() + len;
        self.rest = &self.rest[used..];
        let sign = if negative { 1u64 << 63 } else { 0 };
        Some(f64::from_bits(bits ^ sign))
    }

    /// `[-|!]name[index][\[aL + n\]][_abs][.components]`
    fn register(&mut self) -> Result<RegAst, Diagnostic> {
        let start = self.pos();
        let mut negate = false;
        let mut not = false;
        if self.eat(char('-')).is_some() {
            negate = true;
            self.skip_space();
        } else if self.eat(char('!')).is_some() {
            not = true;
            self.skip_space();
        }
        if self.rest.starts_with('-') || self.rest.starts_with('!') {
            return Err(self.error_here("only one `-` or `!` may precede a register"));
        }
        let nstart = self.pos();
        let Some(name) = self.eat(take_while1(|c: char| c.is_ascii_alphabetic())) else {
            return Err(self
                .error_here(format!("expected a register, {}", self.found()))
                .with_label("expected a register such as r0, v1, c2, s0, i0, b0 or p0"));
        };
        let digits = self.eat(digit1);
        let name_span = self.span_from(nstart);
        let index = match digits {
            Some(d) => Some(d.parse::<u64>().map_err(|_| {
                Diagnostic::coded(
                    codes::NUMBER_TOO_LONG,
                    name_span,
                    format!("register number `{d}` is too large"),
                )
            })?),
            None => None,
        };
        // `c0S`: Microsoft's lexer reads a whole word as the register's
        // name, and refuses it as one (X2005).
        if digits.is_some() && self.rest.starts_with(|c: char| c.is_ascii_alphanumeric()) {
            let tail = self
                .eat(take_while(|c: char| c.is_ascii_alphanumeric()))
                .unwrap_or_default();
            let span = self.span_from(nstart);
            return Err(Diagnostic::coded(
                codes::REGISTER,
                span,
                format!(
                    "`{name}{}{tail}` is no register",
                    digits.unwrap_or_default()
                ),
            )
            .with_label("letters after the register's number")
            .with_help("a swizzle or write mask goes after a `.`, e.g. r0.xy"));
        }
        // `c 1`: Microsoft's lexer reads the letters alone as a register
        // name, and refuses it as one (X2005), before any syntax error.
        let spaced_number = self
            .rest
            .trim_start_matches([' ', '\t'])
            .starts_with(|c: char| c.is_ascii_digit());
        let numbered = crate::core::isa::RegFile::lookup(name).is_some_and(|f| f.info().numbered);
        if digits.is_none() && numbered && spaced_number {
            return Err(Diagnostic::coded(
                codes::REGISTER,
                name_span,
                format!("`{name}` is no register: its number goes right after the letters"),
            )
            .with_label("a space between the letters and the number")
            .with_help(format!(
                "write {name}{}",
                self.rest
                    .trim_start()
                    .chars()
                    .take_while(char::is_ascii_digit)
                    .collect::<String>()
            )));
        }
        let relative = if self.rest.starts_with('[') {
            Some(self.relative()?)
        } else {
            None
        };
        let abs = self.eat_abs(codes::REGISTER)?;
        let components = if self.eat(char('.')).is_some() {
            let cstart = self.pos();
            let Some(letters) = self.eat(take_while1(|c: char| c.is_ascii_alphabetic())) else {
                return Err(self
                    .error_here(format!(
                        "expected swizzle or write-mask letters after `.`, {}",
                        self.found()
                    ))
                    .with_label("expected letters from xyzw or rgba"));
            };
            Some((CompactString::from(letters), self.span_from(cstart)))
        } else {
            None
        };
        if let Some((letters, cspan)) = &components {
            // Microsoft's lexer reads `.x_abs` as one swizzle word and
            // refuses it: `_abs` goes before the swizzle (`r1_abs.x`).
            if self.rest.starts_with('_') {
                let at = self.pos();
                let tail = self.eat(recognize(pair(char('_'), take_while(is_ident_char))));
                let tail = tail.unwrap_or_default();
                return Err(Diagnostic::coded(
                    codes::SWIZZLE,
                    Span {
                        start: cspan.start,
                        end: self.span_from(at).end,
                    },
                    format!("`{letters}{tail}` is not a swizzle: a modifier after the swizzle"),
                )
                .with_label("modifier written after the components")
                .with_help(format!(
                    "write `{tail}` before the `.`, e.g. r1{tail}.{letters}"
                )));
            }
        }
        if self.rest.starts_with(|c: char| c.is_ascii_alphanumeric()) {
            return Err(self.error_here(format!(
                "unexpected characters in register operand, {}",
                self.found()
            )));
        }
        Ok(RegAst {
            negate,
            not,
            name: name.into(),
            index,
            name_span,
            relative,
            abs,
            components,
            span: self.span_from(start),
        })
    }

    /// An optional `_abs`; any other `_suffix` on a source is an error:
    /// Microsoft's assembler reads a suffix written after the components as
    /// part of the swizzle (`r0.x_bias` is the swizzle `x_bias`, `code` is
    /// then [`codes::SWIZZLE`]) and one written before them as part of the
    /// register name ([`codes::REGISTER`]).
    fn eat_abs(&mut self, code: codes::Code) -> Result<bool, Diagnostic> {
        if !self.rest.starts_with('_') {
            return Ok(false);
        }
        let sstart = self.pos();
        let Some(word) = self.eat(recognize(pair(char('_'), take_while(is_ident_char)))) else {
            return Ok(false);
        };
        if word == "_abs" {
            return Ok(true);
        }
        Err(Diagnostic::coded(
            code,
            self.span_from(sstart),
            format!("source modifier `{word}` does not exist in ps_3_0"),
        )
        .with_label("not a ps_3_0 source modifier")
        .with_help("ps_3_0 sources take `-` (negate) and `_abs`; _bias, _bx2, _x2, _dz and _dw are ps_1_x only"))
    }

    /// `[aL]`, `[aL + 3]`, `[ aL + 1 + 2 ]`, and offsets before the index
    /// register, `[3 + a0.x]`, as Microsoft's assembler takes them: the terms
    /// are added, one of them the index register.
    fn relative(&mut self) -> Result<RelAst, Diagnostic> {
        let start = self.pos();
        self.eat(char('['));
        let mut offset: i64 = 0;
        loop {
            self.skip_space();
            if !self.rest.starts_with(|c: char| c.is_ascii_digit()) {
                break;
            }
            offset = offset.saturating_add(self.offset_term()?);
            self.skip_space();
            if self.eat(char('+')).is_none() {
                return Err(self
                    .error_here(format!(
                        "expected `+` and the index register after the offset, {}",
                        self.found()
                    ))
                    .with_label("expected `+ a0.x` or `+ aL`"));
            }
        }
        let Some(index_reg) = self.eat(take_while1(|c: char| c.is_ascii_alphanumeric())) else {
            return Err(self
                .error_here(format!(
                    "expected the index register aL inside `[...]`, {}",
                    self.found()
                ))
                .with_help("relative addressing in ps_3_0 is written v[aL + n]"));
        };
        let swz_start = self.pos();
        let mut index_component = None;
        let index_swizzle = if self.eat(char('.')).is_some() {
            let letters = self.eat(take_while(|c: char| c.is_ascii_alphabetic()));
            index_component = match letters.unwrap_or_default().to_ascii_lowercase().as_str() {
                "x" | "r" => Some(0),
                "y" | "g" => Some(1),
                "z" | "b" => Some(2),
                "w" | "a" => Some(3),
                _ => None,
            };
            Some(self.span_from(swz_start))
        } else {
            None
        };
        loop {
            self.skip_space();
            if self.eat(char(']')).is_some() {
                break;
            }
            if self.rest.starts_with('-') {
                return Err(self
                    .error_here("negative offsets are not allowed in relative addressing")
                    .with_help("write v[aL + n] with n >= 0"));
            }
            if self.eat(char('+')).is_none() {
                return Err(self
                    .error_here(format!(
                        "expected `+` or `]` in relative address, {}",
                        self.found()
                    ))
                    .with_label("expected `+ n` or `]`"));
            }
            self.skip_space();
            offset = offset.saturating_add(self.offset_term()?);
        }
        Ok(RelAst {
            index_reg: index_reg.into(),
            index_swizzle,
            index_component,
            offset,
            span: self.span_from(start),
        })
    }

    /// One integer term of a relative address.
    fn offset_term(&mut self) -> Result<i64, Diagnostic> {
        let dstart = self.pos();
        let Some(d) = self.eat(digit1) else {
            return Err(self
                .error_here(format!("expected an integer offset, {}", self.found()))
                .with_label("offsets are non-negative integers"));
        };
        // Microsoft's lexer refuses a number past 64 bits (X1004) and
        // its grammar one past 32 bits (a syntax error).
        let Ok(n) = d.parse::<u64>() else {
            return Err(Diagnostic::coded(
                codes::NUMBER_TOO_LONG,
                self.span_from(dstart),
                format!("offset `{d}` does not fit in 64 bits"),
            ));
        };
        if n > u64::from(u32::MAX) {
            return Err(Diagnostic::coded(
                codes::SYNTAX,
                self.span_from(dstart),
                format!("offset `{d}` does not fit in 32 bits"),
            )
            .with_label("too large"));
        }
        Ok(n as i64)
    }
}

/// How many operands a mnemonic takes (`suffixed`: written with a suffix,
/// which may be a comparison), when the instruction table knows it: where a
/// statement ends when another follows it on the line.
fn operand_count(base: &str, suffixed: bool) -> Option<usize> {
    match base {
        "dcl" => Some(1),
        "def" | "defi" => Some(5),
        "defb" => Some(2),
        _ => {
            let op = crate::core::isa::Opcode::from_mnemonic(base, suffixed)
                .or_else(|| crate::core::isa::Opcode::from_mnemonic(base, false))?;
            Some(op.info().operands.len())
        }
    }
}

/// Whether a mnemonic's first operand is a destination (texkill's included:
/// its token is one), when the instruction table knows the mnemonic.
fn writes_destination(base: &str, suffixed: bool) -> bool {
    use crate::core::isa::{Opcode, Operand};
    Opcode::from_mnemonic(base, suffixed)
        .or_else(|| Opcode::from_mnemonic(base, false))
        .is_some_and(|op| {
            matches!(
                op.info().operands.first(),
                Some(Operand::Dst | Operand::PredDst | Operand::KillSrc)
            )
        })
}

/// Parses only the tag used by other modules to recognise a version string.
pub fn is_version_line(s: &str) -> bool {
    matches!(version(s.trim()), Ok((rest, _)) if rest.is_empty())
}

/// The one error for a text whose first statement is not a version line
/// (`ps_3_0`), or that has no statement at all: such a text is not a shader
/// (a README, a C file, a shader missing its first line), and reporting every
/// line of it would bury the one thing to fix. `None` when the first
/// statement is a version line (of any shader model; validation judges it).
pub fn missing_version(text: &str) -> Option<Diagnostic> {
    let blanked = blank(text, &mut Diagnostics::default());
    let missing = if preprocess::needed(&blanked) {
        // The version line may come from a macro, or sit below directives.
        let (pre, _) = preprocess::preprocess(&blanked);
        missing_version_of(&pre.text).map(|mut d| {
            d.map_spans(&|span| pre.span(span));
            d
        })
    } else {
        missing_version_of(&blanked)
    };
    missing.map(|d| d.with_code(codes::VERSION))
}

fn missing_version_of(text: &str) -> Option<Diagnostic> {
    let mut line_start = 0;
    for line in text.split_inclusive('\n') {
        let code = strip_comment(line.trim_end_matches(['\n', '\r']));
        let lead = code.len() - code.trim_start().len();
        let code = code.trim();
        if !code.is_empty() {
            // A version line, or a line with a character assembly cannot
            // hold (the parser names it where it stands).
            let version_first = matches!(version(code), Ok((rest, _)) if rest.is_empty() || rest.starts_with([' ', '\t']));
            if version_first || code.chars().any(odd_char) {
                return None;
            }
            let start = line_start + lead;
            let first: String = code.chars().take(40).collect();
            let more = if first.len() < code.len() { "…" } else { "" };
            return Some(
                Diagnostic::error(Span::new(start, start), "missing version line")
                    .with_label("expected `ps_3_0` here")
                    .with_note(format!(
                        "the first statement is `{first}{more}`: this is not a ps_3_0 shader, or its first line is missing, so ps30 reads no further"
                    ))
                    .with_help("a ps_3_0 shader starts with the line `ps_3_0`"),
            );
        }
        line_start += line.len();
    }
    Some(
        Diagnostic::error(Span::new(0, 0), "missing version line")
            .with_label("expected `ps_3_0` here")
            .with_note("the text holds no statement, only comments or blank lines")
            .with_help("a ps_3_0 shader starts with the line `ps_3_0`"),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    fn one(src: &str) -> Stmt {
        let (stmts, diags) = parse(src);
        assert!(!diags.has_errors(), "{:?}", diags);
        assert_eq!(stmts.len(), 1);
        stmts.into_iter().next().unwrap()
    }

    #[test]
    fn line_directives_assemble_to_nothing() {
        let (stmts, diags) = parse("ps_3_0\n\n#line 17 \"C:\\a b;c.hlsl\"\n#line 3\nnop\n");
        assert!(!diags.has_errors(), "{diags:?}");
        assert_eq!(stmts.len(), 2);
        for bad in ["#line", "#line x", "#line 3 \"a", "#line3", "#line 3 a"] {
            assert!(!is_line_directive(bad), "{bad}");
        }
    }

    #[test]
    fn parses_an_instruction_with_modifiers() {
        let Stmt::Instr(i) = one("  (!p0.x) add_sat_pp r0.xw, -r1_abs.wxxx, c3 // comment") else {
            panic!()
        };
        assert_eq!(i.base, "add");
        assert_eq!(
            i.suffixes.iter().map(|s| s.0.as_str()).collect::<Vec<_>>(),
            ["sat", "pp"]
        );
        let p = i.predicate.unwrap();
        assert!(p.not);
        assert_eq!(p.components.unwrap().0, "x");
        assert_eq!(i.operands.len(), 3);
        let OperandAst::Reg(r) = &i.operands[1] else {
            panic!()
        };
        assert!(r.negate && r.abs);
        assert_eq!(r.components.as_ref().unwrap().0, "wxxx");
        assert_eq!(r.span, Span::new(28, 40));
    }

    #[test]
    fn parses_repeat_spellings() {
        assert!(matches!(
            one("BEGIN_REPEAT_BLOCK(125)"),
            Stmt::RepeatBegin {
                count: Count::Literal { value: 125, .. },
                ..
            }
        ));
        assert!(matches!(
            one("BEGIN REPEAT BLOCK(125) // x"),
            Stmt::RepeatBegin { .. }
        ));
        assert!(matches!(
            one("begin_repeat_block( ysize )"),
            Stmt::RepeatBegin {
                count: Count::Name { .. },
                ..
            }
        ));
        assert!(matches!(one("END REPEAT BLOCK"), Stmt::RepeatEnd { .. }));
        assert!(matches!(one("END_REPEAT_BLOCK"), Stmt::RepeatEnd { .. }));
        assert!(matches!(one("End_Repeat_Block"), Stmt::RepeatEnd { .. }));
        // Keywords are ASCII: the Kelvin sign, whose lowercase is `k`, does
        // not spell BLOCK: the line is refused.
        let (stmts, diags) = parse("END_REPEAT_BLOC\u{212A}");
        assert!(!matches!(stmts.first(), Some(Stmt::RepeatEnd { .. })));
        assert!(diags.has_errors());
    }

    #[test]
    fn parses_versions_numbers_and_relative_addressing() {
        assert!(matches!(
            one("ps.3.0"),
            Stmt::Version {
                major: 3,
                minor: 0,
                ..
            }
        ));
        let Stmt::Instr(i) = one("def c0, 1.0f, -2, .5, 1e-4") else {
            panic!()
        };
        assert_eq!(i.operands.len(), 5);
        assert!(
            matches!(i.operands[2], OperandAst::Number { value, integer: true, .. } if value == -2.0)
        );
        let Stmt::Instr(i) = one("mov r0, v[ aL + 1 + 3 ]") else {
            panic!()
        };
        let OperandAst::Reg(r) = &i.operands[1] else {
            panic!()
        };
        assert_eq!(r.relative.as_ref().unwrap().offset, 4);
    }

    #[test]
    fn reports_every_bad_line_with_its_column() {
        let (_, d) = parse("ps_3_0\nmov r0, r1_bx2\nadd r0 r1\nmov r0,\n");
        let errs: Vec<_> = d.errors().collect();
        assert_eq!(errs.len(), 3);
        assert_eq!(errs[0].span.start as usize, "ps_3_0\nmov r0, r1".len());
    }
}
