//! The syntax tree of an assembly file, as written: nothing is resolved yet,
//! every node keeps the byte span it was parsed from.

use crate::core::ir::Span;

/// One statement per source line.
#[derive(Clone, Debug, PartialEq)]
pub enum Stmt {
    /// `ps_3_0` / `ps.3.0` (or another version, rejected by the validator).
    Version {
        text: String,
        major: u32,
        minor: u32,
        span: Span,
    },
    Instr(InstrAst),
    /// `BEGIN_REPEAT_BLOCK(n)` (also spelled `BEGIN REPEAT BLOCK(n)`).
    RepeatBegin {
        count: Count,
        span: Span,
    },
    /// `END_REPEAT_BLOCK` (also `END REPEAT BLOCK`).
    RepeatEnd {
        span: Span,
    },
    /// A comment block of a compiled shader, kept token for token: a
    /// `//#comment` line and its `//#+` continuation lines, each token in
    /// hexadecimal (the constant table `CTAB` is one). Validation ignores
    /// it; the bytecode writer emits it where it stands.
    Comment {
        tokens: Vec<u32>,
        span: Span,
    },
}

/// A REPEAT_BLOCK count: a literal or a name bound with `-D name=value`.
#[derive(Clone, Debug, PartialEq)]
pub enum Count {
    Literal { value: u64, span: Span },
    Name { name: String, span: Span },
}

impl Count {
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
    pub base: String,
    pub base_span: Span,
    /// `_`-separated suffixes, lower-cased (`sat`, `pp`, `gt`, `texcoord0`, `2d`).
    pub suffixes: Vec<(String, Span)>,
    pub operands: Vec<OperandAst>,
    /// The whole statement.
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq)]
pub enum OperandAst {
    Reg(RegAst),
    /// A numeric literal (`1.0f`, `-3`, `1e-4`).
    Number {
        value: f64,
        /// Whether it was written without a fraction or exponent.
        integer: bool,
        span: Span,
    },
    /// `true` / `false`.
    Bool {
        value: bool,
        span: Span,
    },
}

impl OperandAst {
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
    pub name: String,
    /// Number after the name, if any (`r12` → 12).
    pub index: Option<u64>,
    pub name_span: Span,
    /// `[aL + n]`.
    pub relative: Option<RelAst>,
    /// `_abs`.
    pub abs: bool,
    /// Letters after the `.` (swizzle or write mask), lower-cased.
    pub components: Option<(String, Span)>,
    pub span: Span,
}

/// `[aL + n + m]` after a register name.
#[derive(Clone, Debug, PartialEq)]
pub struct RelAst {
    /// The index register as written (`aL`).
    pub index_reg: String,
    /// Swizzle written on the index register, which ps_3_0 forbids.
    pub index_swizzle: Option<Span>,
    /// Sum of the constant offsets.
    pub offset: i64,
    pub span: Span,
}
