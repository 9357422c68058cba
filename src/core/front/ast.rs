//! The syntax tree of an assembly file, as written: nothing is resolved yet,
//! every node keeps the byte span it was parsed from.

use crate::core::ir::Span;
pub use compact_str::CompactString;

/// One statement per source line.
#[derive(Clone, Debug, PartialEq)]
pub enum Stmt {
    /// `ps_3_0` / `ps.3.0` (or another version, rejected by the validator).
    Version {
        /// The version as written.
        text: String,
        /// Its major number (3).
        major: u32,
        /// Its minor number (0).
        minor: u32,
        /// Where it is.
        span: Span,
    },
    /// An instruction or declaration.
    Instr(InstrAst),
    /// `BEGIN_REPEAT_BLOCK(n)` (also spelled `BEGIN REPEAT BLOCK(n)`).
    RepeatBegin {
        /// How many repetitions.
        count: Count,
        /// Where it is.
        span: Span,
    },
    /// `END_REPEAT_BLOCK` (also `END REPEAT BLOCK`).
    RepeatEnd {
        /// Where it is.
        span: Span,
    },
    /// A comment block of a compiled shader, kept token for token: a
    /// `//#comment` line and its `//#+` continuation lines, each token in
    /// hexadecimal (the constant table `CTAB` is one). Validation ignores
    /// it; the bytecode writer emits it where it stands.
    Comment {
        /// The block's tokens (its first names it: `CTAB`, …).
        tokens: Vec<u32>,
        /// Where the block is.
        span: Span,
    },
}

impl Stmt {
    /// Every span of the statement replaced by `f` of it (the
    /// preprocessor's map from the text it wrote back to the source).
    pub fn map_spans(&mut self, f: &dyn Fn(Span) -> Span) {
        match self {
            Stmt::Version { span, .. } | Stmt::RepeatEnd { span } | Stmt::Comment { span, .. } => {
                *span = f(*span)
            }
            Stmt::RepeatBegin { count, span } => {
                *span = f(*span);
                match count {
                    Count::Literal { span, .. } | Count::Name { span, .. } => *span = f(*span),
                }
            }
            Stmt::Instr(i) => {
                i.base_span = f(i.base_span);
                i.span = f(i.span);
                for (_, span) in &mut i.suffixes {
                    *span = f(*span);
                }
                if let Some(p) = &mut i.predicate {
                    p.map_spans(f);
                }
                for op in &mut i.operands {
                    match op {
                        OperandAst::Reg(r) => r.map_spans(f),
                        OperandAst::Number { span, .. } | OperandAst::Bool { span, .. } => {
                            *span = f(*span)
                        }
                    }
                }
            }
        }
    }
}

/// A REPEAT_BLOCK count: a literal or a name bound with `-D name=value`.
#[derive(Clone, Debug, PartialEq)]
#[allow(missing_docs)] // value, name, span: as written, and where
pub enum Count {
    /// A number (`BEGIN_REPEAT_BLOCK(125)`).
    Literal { value: u64, span: Span },
    /// A name bound with `-D` (`BEGIN_REPEAT_BLOCK(xsize)`).
    Name { name: String, span: Span },
}

impl Count {
    /// Where the count is written.
    pub fn span(&self) -> Span {
        match self {
            Count::Literal { span, .. } | Count::Name { span, .. } => *span,
        }
    }
}

/// An instruction (or declaration) line.
#[derive(Clone, Debug, PartialEq)]
pub struct InstrAst {
    /// `(p0.x)` / `(!p0)` prefix.
    pub predicate: Option<RegAst>,
    /// Mnemonic before the first `_`, lower-cased (`texld`, `if`, `dcl`).
    pub base: CompactString,
    /// Where the mnemonic is.
    pub base_span: Span,
    /// `_`-separated suffixes, lower-cased (`sat`, `pp`, `gt`, `texcoord0`, `2d`).
    pub suffixes: Vec<(CompactString, Span)>,
    /// The operands, in order.
    pub operands: Vec<OperandAst>,
    /// The whole statement.
    pub span: Span,
}

/// One operand, as written.
#[derive(Clone, Debug, PartialEq)]
pub enum OperandAst {
    /// A register, with its modifiers.
    Reg(RegAst),
    /// A numeric literal (`1.0f`, `-3`, `1e-4`).
    Number {
        /// Its value.
        value: f64,
        /// Whether it was written without a fraction or exponent.
        integer: bool,
        /// Whether it was written as an infinity or NaN (`1.#INF`,
        /// `-1.#IND`): only these may be outside a float's range.
        special: bool,
        /// Where it is.
        span: Span,
    },
    /// `true` / `false`.
    Bool {
        /// Its value.
        value: bool,
        /// Where it is.
        span: Span,
    },
}

impl OperandAst {
    /// Where the operand is written.
    pub fn span(&self) -> Span {
        match self {
            OperandAst::Reg(r) => r.span,
            OperandAst::Number { span, .. } | OperandAst::Bool { span, .. } => *span,
        }
    }
}

/// A register operand with its modifiers, as written.
#[derive(Clone, Debug, PartialEq)]
pub struct RegAst {
    /// Leading `-`.
    pub negate: bool,
    /// Leading `!`.
    pub not: bool,
    /// Letters of the register name (`r`, `oC`, `vPos`, `aL`), as written.
    pub name: CompactString,
    /// Number after the name, if any (`r12` → 12).
    pub index: Option<u64>,
    /// Where the name and number are.
    pub name_span: Span,
    /// `[aL + n]`.
    pub relative: Option<RelAst>,
    /// `_abs`.
    pub abs: bool,
    /// Letters after the `.` (swizzle or write mask), lower-cased.
    pub components: Option<(CompactString, Span)>,
    /// The whole operand.
    pub span: Span,
}

impl RegAst {
    fn map_spans(&mut self, f: &dyn Fn(Span) -> Span) {
        self.name_span = f(self.name_span);
        self.span = f(self.span);
        if let Some((_, span)) = &mut self.components {
            *span = f(*span);
        }
        if let Some(rel) = &mut self.relative {
            rel.span = f(rel.span);
            if let Some(s) = &mut rel.index_swizzle {
                *s = f(*s);
            }
        }
    }
}

/// `[aL + n + m]` after a register name.
#[derive(Clone, Debug, PartialEq)]
pub struct RelAst {
    /// The index register as written (`aL`).
    pub index_reg: CompactString,
    /// Swizzle written on the index register, which ps_3_0 forbids.
    pub index_swizzle: Option<Span>,
    /// The component that swizzle selects when it is one letter (`a0.y`
    /// is 1), `None` for none or several.
    pub index_component: Option<u8>,
    /// Sum of the constant offsets.
    pub offset: i64,
    /// The whole `[…]`.
    pub span: Span,
}

/// A literal rounded to single precision, NaNs included bit for bit: the
/// sign and the top 22 bits of a NaN's payload are kept and the result is
/// a quiet NaN, as x86's conversion does (Rust's `as` leaves a NaN's
/// payload unspecified).
pub fn single(value: f64) -> f32 {
    if value.is_nan() {
        let bits = value.to_bits();
        let sign = ((bits >> 63) as u32) << 31;
        let payload = ((bits >> 29) as u32) & 0x007F_FFFF;
        return f32::from_bits(sign | 0x7FC0_0000 | payload);
    }
    value as f32
}
