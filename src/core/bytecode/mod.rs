//! Direct3D 9 shader bytecode: the token stream `fxc /Fo` writes, games ship
//! and Wine's tests hold as arrays, read into the front end and written back
//! byte for byte.
//!
//! Real ps_3_0 shaders rarely exist as assembly text, so ps30 reads the
//! tokens too. A stream is [`read`] into a [`Module`] — hostile input is the
//! normal case, so every length, count and offset is checked before use and
//! a lying stream is an error naming its byte offset — and the module is
//! printed as an assembly [`listing`] in the style of fxc's, which the text
//! front end reads like any source: a compiled shader becomes the same AST
//! and the same validated [`Shader`](crate::core::ir::Shader) as its text,
//! and its diagnostics point into the listing and name token and byte.
//! [`write`](mod@write) is the other way: assembly statements (after REPEAT_BLOCK
//! expansion) to a module, and a module to exactly the tokens Microsoft's
//! assembler emits. [`ctab`] decodes the constant table fxc stores in a
//! comment block (names, registers, types, defaults).
//!
//! Reading accepts exactly what has a text form and writing emits exactly
//! what it reads, so bytes → listing → bytes is the identity; ps_3_0 rules
//! are judged afterwards by validation, as for text.
//!
//! # The token layout
//!
//! Little-endian 32-bit tokens (Microsoft's driver documentation,
//! learn.microsoft.com/windows-hardware/drivers/display: version-token,
//! instruction-token, destination- and source-parameter-token,
//! shader-relative-addressing, comment-token, end-token; register and
//! opcode numbers from d3d9types.h, kept in the rows of
//! [`crate::core::isa`]):
//!
//! * **version**, first: `0xFFFF0300` for ps_3_0 (bits 16–31 `0xFFFF` pixel,
//!   `0xFFFE` vertex; bits 8–15 major, 0–7 minor).
//! * **instruction**: bits 0–15 the D3DSIO_* opcode, 16–23 its control (the
//!   comparison of `if_comp`, `break_comp`, `setp_comp`; 1 `texldp`, 2
//!   `texldb`), 24–27 the number of tokens that follow, 28 predicated, 29
//!   reserved, 30 co-issue (ps_1_x), 31 zero. The tokens that follow, in
//!   order: the destination (if any); the predicate `p0` in source format
//!   when predicated (right after the destination, as Wine's tests of
//!   Microsoft's assembler show, not at the end as the page says); the
//!   sources, each followed by its relative-address token when it has one.
//!   `texkill`'s operand is in destination format. `dcl` is a usage token
//!   (bit 31 set; usage bits 0–3, usage index 16–19, sampler texture type
//!   27–30) then the declared register as a destination; `def`, `defi`,
//!   `defb` are the destination then 4 floats, 4 integers or 1 boolean.
//! * **parameter**: bit 31 set; bits 0–10 the register number; the D3DSPR_*
//!   type split across bits 28–30 (low three bits) and 11–12 (high two); 13
//!   relative addressing; 14–15 reserved. Destination: bits 16–19 write mask,
//!   20–23 result modifier (1 `_sat`, 2 `_pp`, 4 `_centroid`), 24–27 shift
//!   (ps_1_x). Source: bits 16–23 swizzle (two bits per component, x first;
//!   identity `0xE4`), 24–27 modifier (0 none, 1 `-`, 11 `_abs`, 12 `-…_abs`,
//!   13 `!`; the others are ps_1_x).
//! * **relative address**: one source-format token after the parameter,
//!   naming `aL` (`0xF0E40800`) in ps_3_0.
//! * **comment**: bits 0–15 `0xFFFE`, 16–30 the number of tokens of its body,
//!   which follows; fxc's constant table is one whose body starts with the
//!   four characters `CTAB`.
//! * **end**: `0x0000FFFF`, last.

pub mod ctab;
pub mod dbug;
pub mod listing;
pub mod microsoft;
pub mod read;
pub mod write;

use crate::core::ir::{Reg, RelIndex, SrcMod, Swizzle, WriteMask};
use crate::core::isa::{Compare, Opcode, RegFile, CONST_TOKEN_TYPES};
use std::fmt;

/// The version token of ps_3_0.
pub const VERSION_PS_3_0: u32 = 0xFFFF_0300;
/// The end token.
pub const END: u32 = 0x0000_FFFF;
/// The opcode of a comment token.
pub const COMMENT: u32 = 0xFFFE;
/// `CTAB` as the first token of a comment body (little-endian FourCC).
pub const CTAB: u32 = u32::from_le_bytes(*b"CTAB");

/// The CRC-32 of bytecode: the standard CRC-32 (IEEE 802.3, as zlib's
/// `crc32` computes it) of the bytes, the identifier shader-replacement
/// tools name a dumped shader by (eight hex digits, [`crc32_hex`]).
pub fn crc32(bytes: &[u8]) -> u32 {
    crc32fast::hash(bytes)
}

/// A CRC-32 as those tools write it in file names: eight lower-case hex
/// digits.
pub fn crc32_hex(crc: u32) -> String {
    format!("{crc:08x}")
}

/// Result-modifier bits of a destination token.
pub const SAT: u8 = 1;
/// `_pp`: partial precision (ps30 computes in full precision anyway).
pub const PP: u8 = 2;
/// `_centroid`: interpolate at the centroid (only on `dcl` of an input).
pub const CENTROID: u8 = 4;

/// A decoded ps_3_0 token stream: its items in stream order, between the
/// version token and the end token.
#[derive(Clone, Debug, PartialEq)]
pub struct Module {
    /// The profile of its version token.
    pub profile: crate::core::profile::Profile,
    /// Instructions and comments in stream order (neither the version nor the
    /// end token).
    pub items: Vec<Item>,
}

/// One instruction or comment, with the index of its first token in the
/// stream (the version token is token 0; its byte offset is 4 × token).
#[derive(Clone, Debug, PartialEq)]
pub struct Item {
    /// Index of the item's first token (the version token is token 0).
    pub token: u32,
    /// What the tokens decode to.
    pub kind: ItemKind,
}

/// What one item of a stream is.
#[derive(Clone, Debug, PartialEq)]
pub enum ItemKind {
    /// An instruction token and its operand tokens.
    Instr(Instr),
    /// A comment block's body, token for token.
    Comment(Vec<u32>),
}

/// One instruction (declarations and definitions included), its operands
/// decoded.
#[derive(Clone, Debug, PartialEq)]
pub struct Instr {
    /// The D3DSIO_* opcode (bits 0–15 of the instruction token).
    pub op: Opcode,
    /// The comparison of `if_comp`, `break_comp`, `setp_comp` (the control
    /// bits); `None` for every other opcode.
    pub compare: Option<Compare>,
    /// The predicate token of a predicated instruction.
    pub predicate: Option<Source>,
    /// The operand in destination format, with the result modifiers.
    pub dst: Option<Dest>,
    /// The source operands in order, relative addressing folded into each.
    pub src: Vec<Source>,
    /// The `dcl` usage token or the literals of `def`, `defi`, `defb`.
    pub extra: Extra,
}

/// The tokens an instruction carries besides its operands.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Extra {
    /// Nothing: every instruction but `dcl` and the `def`s.
    None,
    /// A `dcl` usage token: usage (bits 0–3), usage index (16–19), sampler
    /// texture type (27–30).
    Decl {
        /// D3DDECLUSAGE_* (0 position, 5 texcoord, 10 color, …).
        usage: u8,
        /// The usage index (`texcoord3` → 3).
        index: u8,
        /// D3DSTT_* of a sampler (2 2D, 3 cube, 4 volume); 0 for other registers.
        texture: u8,
    },
    /// `def`: four floats, as their bits.
    Float([u32; 4]),
    /// `defi`: four integers (loop count, start, step, unused).
    Int([i32; 4]),
    /// `defb`: 0 or 1.
    Bool(bool),
}

/// A destination-format parameter.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Dest {
    /// The register (file and number).
    pub reg: Reg,
    /// Which components are written (bits 16–19).
    pub mask: WriteMask,
    /// The index register of vs_3_0's `o[aL + n]`, whose token follows.
    pub relative: Option<RelIndex>,
    /// [`SAT`] | [`PP`] | [`CENTROID`].
    pub result: u8,
}

/// A source-format parameter. With `relative`, `reg.index` is the register
/// number the token carries (the base plus the offset of `v[aL + n]`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Source {
    /// The register (file and number).
    pub reg: Reg,
    /// The index register whose relative-address token (`aL`, `a0.x` …)
    /// follows the parameter, if any.
    pub relative: Option<RelIndex>,
    /// Which component each of x, y, z, w reads (bits 16–23).
    pub swizzle: Swizzle,
    /// Negation and absolute value (bits 24–27).
    pub modifier: SrcMod,
}

impl Instr {
    /// The number of tokens after the instruction token (its length field).
    pub fn operand_tokens(&self) -> u32 {
        let extra = match self.extra {
            Extra::None => 0,
            Extra::Decl { .. } | Extra::Bool(_) => 1,
            Extra::Float(_) | Extra::Int(_) => 4,
        };
        let sources: u32 = self
            .src
            .iter()
            .map(|s| 1 + u32::from(s.relative.is_some()))
            .sum();
        extra
            + self.dst.map_or(0, |d| 1 + u32::from(d.relative.is_some()))
            + self
                .predicate
                .map_or(0, |p| 1 + u32::from(p.relative.is_some()))
            + sources
    }
}

/// A source modifier as the 4-bit code of a source token.
pub fn modifier_code(m: SrcMod) -> u8 {
    match m {
        SrcMod::None => 0,
        SrcMod::Neg => 1,
        SrcMod::Abs => 11,
        SrcMod::NegAbs => 12,
        SrcMod::Not => 13,
    }
}

/// The source modifier of a 4-bit code, with the name of a code ps_3_0 does
/// not have (D3DSPSM_*) as the error.
pub fn modifier_from_code(code: u8) -> Result<SrcMod, &'static str> {
    const OTHERS: [&str; 11] = [
        "",
        "",
        "_bias",
        "-…_bias",
        "_bx2",
        "-…_bx2",
        "1 - …",
        "_x2",
        "-…_x2",
        "_dz",
        "_dw",
    ];
    match code {
        0 => Ok(SrcMod::None),
        1 => Ok(SrcMod::Neg),
        11 => Ok(SrcMod::Abs),
        12 => Ok(SrcMod::NegAbs),
        13 => Ok(SrcMod::Not),
        c => Err(OTHERS
            .get(c as usize)
            .copied()
            .unwrap_or("an undefined code")),
    }
}

/// The D3DSPR_* type and number a register's tokens carry.
pub fn register_token(reg: Reg) -> u32 {
    let info = reg.file.info();
    let (ty, number) = if reg.file == RegFile::Const {
        let bank = (reg.index / 2048) as usize % CONST_TOKEN_TYPES.len();
        (u32::from(CONST_TOKEN_TYPES[bank]), reg.index % 2048)
    } else if info.numbered {
        (info.token_type as u32, reg.index)
    } else {
        (info.token_type as u32, info.token_number)
    };
    0x8000_0000 | (ty & 7) << 28 | (ty & 0x18) << 8 | (number & 0x7ff)
}

/// A destination token.
pub fn dest_token(d: &Dest) -> u32 {
    register_token(d.reg)
        | (d.mask.0 as u32) << 16
        | (d.result as u32) << 20
        | u32::from(d.relative.is_some()) << 13
}

/// A source token (without its relative-address token).
pub fn source_token(s: &Source) -> u32 {
    let swizzle: u32 = s
        .swizzle
        .0
        .iter()
        .enumerate()
        .map(|(i, &c)| (c as u32 & 3) << (2 * i))
        .sum();
    register_token(s.reg)
        | swizzle << 16
        | (modifier_code(s.modifier) as u32) << 24
        | u32::from(s.relative.is_some()) << 13
}

/// The relative-address token of an index register: `aL` with the
/// identity swizzle, `a0` with the replicate swizzle of its component
/// (what Microsoft's assembler writes for `c[a0.y + n]`: 0xb0550000).
pub fn relative_token(index: RelIndex) -> u32 {
    match index {
        RelIndex::Loop => loop_counter_token(),
        RelIndex::Addr(c) => {
            let c = u32::from(c & 3);
            let replicate = c | c << 2 | c << 4 | c << 6;
            register_token(Reg {
                file: RegFile::Address,
                index: 0,
            }) | replicate << 16
        }
    }
}

/// The relative-address token of ps_3_0: `aL`, identity swizzle.
pub fn loop_counter_token() -> u32 {
    register_token(Reg {
        file: RegFile::LoopCounter,
        index: 0,
    }) | 0xE4 << 16
}

/// The name of a version token (`ps_3_0`, `vs_2_0`, `ps_2_x`, `ps_2_sw`),
/// or `None` when it is not a shader version.
pub fn version_name(token: u32) -> Option<String> {
    let kind = match token >> 16 {
        0xFFFF => "ps",
        0xFFFE => "vs",
        _ => return None,
    };
    let (major, minor) = ((token >> 8) & 0xFF, token & 0xFF);
    let minor = match minor {
        0xFF => "sw".to_string(),
        1 if major == 2 => "x".to_string(),
        m => m.to_string(),
    };
    Some(format!("{kind}_{major}_{minor}"))
}

/// A place in a byte stream that could not be read, and why.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ReadError {
    /// Byte offset of the token at fault.
    pub byte: usize,
    /// What is wrong, in one sentence.
    pub message: String,
    /// What to do about it, where there is something to say.
    pub help: Option<String>,
}

impl ReadError {
    pub(crate) fn at(byte: usize, message: impl Into<String>) -> ReadError {
        ReadError {
            byte,
            message: message.into(),
            help: None,
        }
    }

    pub(crate) fn with_help(mut self, help: impl Into<String>) -> ReadError {
        self.help = Some(help.into());
        self
    }

    /// `token T (byte 0xB)`: where the error is.
    pub fn place(&self) -> String {
        place(self.byte)
    }
}

/// `token T (byte 0xB)` for a byte offset.
pub fn place(byte: usize) -> String {
    format!("token {} (byte {byte:#x})", byte / 4)
}

impl fmt::Display for ReadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.place(), self.message)?;
        if let Some(h) = &self.help {
            write!(f, "; {h}")?;
        }
        Ok(())
    }
}

impl std::error::Error for ReadError {}

/// Whether bytes are compiled Direct3D 9 code rather than text: the high
/// half of their first token is `0xFFFF` (pixel shader), `0xFFFE` (vertex
/// shader) or `0xFEFF` (effect) — bytes no UTF-8 text holds. Detection is
/// by content, never by extension.
pub fn is_bytecode(bytes: &[u8]) -> bool {
    bytes.len() >= 4 && bytes[2] >= 0xFE && bytes[3] >= 0xFE
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn register_tokens_match_wines_worked_encodings() {
        let src = |file, index| {
            source_token(&Source {
                reg: Reg { file, index },
                relative: None,
                swizzle: Swizzle::IDENTITY,
                modifier: SrcMod::None,
            })
        };
        assert_eq!(src(RegFile::Temp, 0), 0x80e40000);
        assert_eq!(src(RegFile::Const, 0), 0xa0e40000);
        assert_eq!(src(RegFile::Input, 1), 0x90e40001);
        assert_eq!(src(RegFile::ConstInt, 0), 0xf0e40000);
        assert_eq!(src(RegFile::ConstBool, 0), 0xe0e40800);
        assert_eq!(src(RegFile::LoopCounter, 0), 0xf0e40800);
        assert_eq!(src(RegFile::Label, 0), 0xa0e41000);
        assert_eq!(src(RegFile::Sampler, 2), 0xa0e40802);
        assert_eq!(src(RegFile::Position, 0), 0x90e41000);
        assert_eq!(src(RegFile::Face, 0), 0x90e41001);
        let dst = |file, index| {
            dest_token(&Dest {
                reg: Reg { file, index },
                mask: WriteMask::ALL,
                relative: None,
                result: 0,
            })
        };
        assert_eq!(dst(RegFile::ColorOut, 3), 0x800f0803);
        assert_eq!(dst(RegFile::DepthOut, 0), 0x900f0800);
        assert_eq!(dst(RegFile::Predicate, 0), 0xb00f1000);
        assert_eq!(loop_counter_token(), 0xf0e40800);
        // Microsoft's assembler's tokens for c[a0.x], c[a0.z] (vs_2_0, vs_3_0).
        assert_eq!(relative_token(RelIndex::Addr(0)), 0xb0000000);
        assert_eq!(relative_token(RelIndex::Addr(2)), 0xb0aa0000);
    }

    #[test]
    fn versions_are_named() {
        assert_eq!(version_name(0xFFFF0300).as_deref(), Some("ps_3_0"));
        assert_eq!(version_name(0xFFFF0201).as_deref(), Some("ps_2_x"));
        assert_eq!(version_name(0xFFFE0300).as_deref(), Some("vs_3_0"));
        assert_eq!(version_name(0xFFFF0104).as_deref(), Some("ps_1_4"));
        assert_eq!(version_name(0xFFFE02FF).as_deref(), Some("vs_2_sw"));
        assert_eq!(version_name(0x4658_0201), None);
        assert!(is_bytecode(&0xFFFF0300u32.to_le_bytes()));
        assert!(!is_bytecode(b"ps_3_0\n"));
    }
}
