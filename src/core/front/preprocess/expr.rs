//! `#if` and `#elif` expressions: integers and character constants with
//! the operators Microsoft's preprocessor knows (`defined`, `! - +`,
//! `* /`, `+ -`, `<< >>`, `< > <= >=`, `== !=`, `& ^ |`, `&& ||`, `?:` and
//! parentheses; not `%`, `~`, `<<` or `>>`, which it refuses), computed in
//! 32-bit unsigned arithmetic with wrapping (`-1 > 0`, `0xffffffff == -1`
//! and `-7 / 2 == 2147483644` there), a division by zero an error even in
//! a branch whose value is not used. A name that is no macro reads as 0, as
//! in C; a character constant is one character (`'a'`), without escapes.

use super::{syntax, Kind, Tok};
use crate::core::diag::{codes, Diagnostic};
use crate::core::ir::Span;

/// Parentheses and unary operators nested deeper than this are refused
/// (a bound on the recursion).
const MAX_NESTING: usize = 256;

/// The value of the expression `toks` (macros expanded, spaces removed);
/// `line_end` is where an expression that stops short is reported.
pub(super) fn evaluate(
    toks: &[Tok],
    line_end: usize,
    defined: &dyn Fn(&str) -> bool,
) -> Result<u32, Diagnostic> {
    let mut e = Eval {
        toks,
        at: 0,
        line_end,
        defined,
        nesting: 0,
    };
    let v = e.ternary()?;
    match e.toks.get(e.at) {
        None => Ok(v),
        Some(t) => Err(e.unexpected(t)),
    }
}

struct Eval<'t> {
    toks: &'t [Tok],
    at: usize,
    line_end: usize,
    defined: &'t dyn Fn(&str) -> bool,
    nesting: usize,
}

/// Binary operators by precedence, loosest first.
const LEVELS: &[&[&str]] = &[
    &["||"],
    &["&&"],
    &["|"],
    &["^"],
    &["&"],
    &["==", "!="],
    &["<", ">", "<=", ">="],
    &["+", "-"],
    &["*", "/"],
];

impl Eval<'_> {
    fn peek(&self, op: &str) -> bool {
        self.toks
            .get(self.at)
            .is_some_and(|t| t.kind == Kind::Punct && t.text == op)
    }

    fn unexpected(&self, t: &Tok) -> Diagnostic {
        let what = match t.kind {
            Kind::Str => "string constant".to_string(),
            _ => format!("token '{}'", t.text),
        };
        syntax(t.span(), format!("unexpected {what} in the #if expression"))
    }

    fn end(&self) -> Diagnostic {
        syntax(
            Span::new(self.line_end, self.line_end),
            "unexpected end of line: the #if expression stops short",
        )
    }

    fn expect(&mut self, op: &str) -> Result<(), Diagnostic> {
        if self.peek(op) {
            self.at += 1;
            return Ok(());
        }
        Err(self
            .toks
            .get(self.at)
            .map_or_else(|| self.end(), |t| self.unexpected(t)))
    }

    /// `c ? a : b`.
    fn ternary(&mut self) -> Result<u32, Diagnostic> {
        let c = self.binary(0)?;
        if !self.peek("?") {
            return Ok(c);
        }
        self.at += 1;
        let a = self.ternary()?;
        self.expect(":")?;
        let b = self.ternary()?;
        Ok(if c != 0 { a } else { b })
    }

    fn binary(&mut self, level: usize) -> Result<u32, Diagnostic> {
        let Some(ops) = LEVELS.get(level) else {
            return self.unary();
        };
        let mut left = self.binary(level + 1)?;
        while let Some(op) = ops.iter().find(|op| self.peek(op)) {
            let at = self.toks[self.at].span();
            self.at += 1;
            let right = self.binary(level + 1)?;
            left = apply(op, left, right).ok_or_else(|| division_by_zero(at))?;
        }
        Ok(left)
    }

    fn unary(&mut self) -> Result<u32, Diagnostic> {
        let Some(t) = self.toks.get(self.at) else {
            return Err(self.end());
        };
        self.nesting += 1;
        if self.nesting > MAX_NESTING {
            return Err(syntax(t.span(), "the #if expression nests too deeply"));
        }
        let v = match (t.kind, t.text.as_str()) {
            (Kind::Punct, "!" | "-" | "+") => {
                self.at += 1;
                let v = self.unary()?;
                match t.text.as_str() {
                    "!" => u32::from(v == 0),
                    "-" => v.wrapping_neg(),
                    _ => v,
                }
            }
            (Kind::Punct, "(") => {
                self.at += 1;
                let v = self.ternary()?;
                self.expect(")")?;
                v
            }
            (Kind::Number, text) => {
                self.at += 1;
                number(text).ok_or_else(|| syntax(t.span(), format!("unexpected number '{text}': the preprocessor reads integers of up to 32 bits")))?
            }
            (Kind::Str, text) if text.starts_with('\'') => {
                self.at += 1;
                character(text).ok_or_else(|| self.unexpected(t))?
            }
            (Kind::Ident, "defined") => {
                self.at += 1;
                self.defined_operand()?
            }
            (Kind::Ident, _) => {
                self.at += 1;
                0
            }
            _ => return Err(self.unexpected(t)),
        };
        self.nesting -= 1;
        Ok(v)
    }

    /// `NAME` or `( NAME )` after `defined`.
    fn defined_operand(&mut self) -> Result<u32, Diagnostic> {
        let paren = self.peek("(");
        if paren {
            self.at += 1;
        }
        let t = self.toks.get(self.at).ok_or_else(|| self.end())?;
        if t.kind != Kind::Ident {
            return Err(self.unexpected(t));
        }
        self.at += 1;
        if paren {
            self.expect(")")?;
        }
        Ok(u32::from((self.defined)(&t.text)))
    }
}

fn apply(op: &str, a: u32, b: u32) -> Option<u32> {
    Some(match op {
        "||" => u32::from(a != 0 || b != 0),
        "&&" => u32::from(a != 0 && b != 0),
        "|" => a | b,
        "^" => a ^ b,
        "&" => a & b,
        "==" => u32::from(a == b),
        "!=" => u32::from(a != b),
        "<" => u32::from(a < b),
        ">" => u32::from(a > b),
        "<=" => u32::from(a <= b),
        ">=" => u32::from(a >= b),
        "+" => a.wrapping_add(b),
        "-" => a.wrapping_sub(b),
        "*" => a.wrapping_mul(b),
        _ if b == 0 => return None,
        _ => a / b,
    })
}

fn division_by_zero(at: Span) -> Diagnostic {
    Diagnostic::coded(
        codes::PREPROCESSOR_DIVIDE_BY_ZERO,
        at,
        "division by zero in the #if expression",
    )
    .with_label("the divisor is 0")
}

/// A decimal, octal (`010`) or hexadecimal (`0x10`) integer with optional
/// `u`/`l` suffixes, of at most 32 bits; `None` for anything else (a float).
fn number(text: &str) -> Option<u32> {
    let digits = text.trim_end_matches(['u', 'U', 'l', 'L']);
    if let Some(hex) = digits.strip_prefix("0x").or(digits.strip_prefix("0X")) {
        u32::from_str_radix(hex, 16).ok()
    } else if digits.len() > 1 && digits.starts_with('0') {
        u32::from_str_radix(&digits[1..], 8).ok()
    } else {
        digits.parse::<u32>().ok()
    }
}

/// A character constant: one character other than a backslash (`'a'`;
/// Microsoft's preprocessor refuses escapes and longer constants).
fn character(text: &str) -> Option<u32> {
    let inner = text.strip_prefix('\'')?.strip_suffix('\'')?;
    let mut chars = inner.chars();
    match (chars.next()?, chars.next()) {
        ('\\', _) | (_, Some(_)) => None,
        (c, None) => Some(c as u32),
    }
}
