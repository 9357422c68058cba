//! The reader: bytes → [`Module`], for input that may lie.
//!
//! Every count is checked against what is left before anything is read or
//! allocated: the stream length against whole tokens, each instruction's
//! length field against the end of the stream and against the operands its
//! row of the instruction table needs, each comment's length against the
//! end, the number of items against a cap, and the constant table against
//! its own comment block ([`super::ctab`]). A stream that fails a check is a
//! [`ReadError`] naming the byte offset of the token at fault; nothing is
//! allocated from a size the input claims, only from what it holds.

use super::{
    modifier_from_code, version_name, Dest, Extra, Instr, Item, ItemKind, Module, ReadError,
    Source, CENTROID, COMMENT, CTAB, END, PP, SAT, VERSION_PS_3_0,
};
use crate::core::ir::{Reg, RelIndex, Swizzle, WriteMask};
use crate::core::isa::{Compare, Opcode, Operand, RegFile, REG_FILES};
use crate::core::profile::Profile;

/// Reads a ps_3_0 token stream. `max_items` caps the instructions and
/// comments (the same cap as REPEAT_BLOCK's expanded statements).
pub fn read(bytes: &[u8], max_items: u64) -> Result<Module, ReadError> {
    let tokens = Tokens::new(bytes)?;
    let profile = version(&tokens)?;
    let mut items = Vec::new();
    let mut at = 1;
    loop {
        let Some(t) = tokens.get(at) else {
            return Err(ReadError::at(
                bytes.len(),
                format!(
                    "the stream ends after {} bytes without an end token (0x0000ffff)",
                    bytes.len()
                ),
            )
            .with_help("the file is truncated, or not a whole shader"));
        };
        if t == END {
            break;
        }
        if items.len() as u64 >= max_items {
            return Err(ReadError::at(
                at * 4,
                format!("more than {max_items} instructions and comments"),
            )
            .with_help("raise the cap with --max-expanded"));
        }
        let (kind, next) = if t & 0xFFFF == COMMENT {
            comment(&tokens, at)?
        } else {
            let (instr, next) = instruction(&tokens, at, profile)?;
            (ItemKind::Instr(instr), next)
        };
        items.push(Item {
            token: at as u32,
            kind,
        });
        at = next;
    }
    let after = (at + 1) * 4;
    if after < bytes.len() {
        return Err(ReadError::at(
            after,
            format!(
                "{} bytes follow the end token at byte {:#x}",
                bytes.len() - after,
                at * 4
            ),
        )
        .with_help("a shader ends with its end token; the file holds something more"));
    }
    Ok(Module { profile, items })
}

/// The stream as little-endian tokens, read on demand (never copied).
struct Tokens<'a> {
    bytes: &'a [u8],
}

impl<'a> Tokens<'a> {
    fn new(bytes: &'a [u8]) -> Result<Tokens<'a>, ReadError> {
        if !bytes.len().is_multiple_of(4) {
            let last = bytes.len() - bytes.len() % 4;
            return Err(ReadError::at(
                last,
                format!(
                    "the stream is {} bytes long, not a whole number of 4-byte tokens",
                    bytes.len()
                ),
            )
            .with_help("the last token is cut off: the file is truncated"));
        }
        Ok(Tokens { bytes })
    }

    fn len(&self) -> usize {
        self.bytes.len() / 4
    }

    fn get(&self, i: usize) -> Option<u32> {
        let b = self.bytes.get(i.checked_mul(4)?..i.checked_mul(4)? + 4)?;
        Some(u32::from_le_bytes([b[0], b[1], b[2], b[3]]))
    }
}

/// The version token must be a profile ps30 reads ([`Profile::checked`]);
/// other shaders are named.
fn version(tokens: &Tokens) -> Result<Profile, ReadError> {
    let Some(v) = tokens.get(0) else {
        return Err(ReadError::at(0, "empty: no version token"));
    };
    if v == VERSION_PS_3_0 {
        return Ok(Profile::Ps3_0);
    }
    // ps_1_x has its own reader (core::ps1::tokens): no length fields, co-issue.
    if let Some(p) = Profile::from_token(v).filter(|p| p.checked() && !p.is_ps1()) {
        return Ok(p);
    }
    let message = match (version_name(v), v >> 16) {
        (Some(name), _) => format!("a {name} shader (version token {v:#010x})"),
        (None, 0xFEFF) => format!("a Direct3D effect (version token {v:#010x}), not a shader"),
        (None, _) => {
            format!("not a Direct3D 9 shader: the first token {v:#010x} is not a version token")
        }
    };
    let help = match Profile::from_token(v) {
        Some(p) if p.is_ps1() => format!(
            "{p} is another instruction set, read by core::ps1 (ps30 check, asm and disasm read it)"
        ),
        Some(p) => format!(
            "ps30 reads ps_1_1 to ps_3_0 and vs_2_0 to vs_3_0; it recognises {p} (docs/profiles.md) but does not read {p} shaders yet"
        ),
        None => "ps30 reads ps_1_1 to ps_3_0 and vs_2_0 to vs_3_0".to_string(),
    };
    Err(ReadError::at(0, message).with_help(help))
}

/// A comment token and its body. A `CTAB` body must decode.
fn comment(tokens: &Tokens, at: usize) -> Result<(ItemKind, usize), ReadError> {
    let t = tokens.get(at).unwrap_or_default();
    if t & 0x8000_0000 != 0 {
        return Err(ReadError::at(
            at * 4,
            format!("comment token {t:#010x} has bit 31 set"),
        ));
    }
    let len = ((t >> 16) & 0x7FFF) as usize;
    let start = at + 1;
    if start + len > tokens.len() {
        return Err(ReadError::at(
            at * 4,
            format!(
                "the comment claims {len} tokens ({} bytes); only {} bytes are left before the end of the stream",
                len * 4,
                (tokens.len() - start) * 4
            ),
        )
        .with_help("the comment's length field lies, or the file is truncated"));
    }
    let body: Vec<u32> = (start..start + len).filter_map(|i| tokens.get(i)).collect();
    if body.first() == Some(&CTAB) {
        super::ctab::decode(&body[1..]).map_err(|e| {
            ReadError::at(
                (start + 1) * 4 + e.offset,
                format!("constant table: {}", e.message),
            )
        })?;
    }
    Ok((ItemKind::Comment(body), start + len))
}

/// Instructions of other shader models, by D3DSIO_* code, for the message.
const FOREIGN: &[(u16, &str)] = &[
    (0x0C, "slt"),
    (0x0D, "sge"),
    (0x10, "lit"),
    (0x11, "dst"),
    (0x22, "sgn"),
    (0x2E, "mova"),
    (0x40, "texcoord"),
    (0x43, "texbem"),
    (0x44, "texbeml"),
    (0x45, "texreg2ar"),
    (0x46, "texreg2gb"),
    (0x47, "texm3x2pad"),
    (0x48, "texm3x2tex"),
    (0x49, "texm3x3pad"),
    (0x4A, "texm3x3tex"),
    (0x4C, "texm3x3spec"),
    (0x4D, "texm3x3vspec"),
    (0x4E, "expp"),
    (0x4F, "logp"),
    (0x50, "cnd"),
    (0x52, "texreg2rgb"),
    (0x53, "texdp3tex"),
    (0x54, "texm3x2depth"),
    (0x55, "texdp3"),
    (0x56, "texm3x3"),
    (0x57, "texdepth"),
    (0x59, "bem"),
    (0xFFFD, "phase"),
];

/// One instruction token and its operands; returns the index after it.
fn instruction(tokens: &Tokens, at: usize, profile: Profile) -> Result<(Instr, usize), ReadError> {
    let t = tokens.get(at).unwrap_or_default();
    let byte = at * 4;
    let code = (t & 0xFFFF) as u16;
    let control = ((t >> 16) & 0xFF) as u8;
    let len = ((t >> 24) & 0xF) as usize;
    let Some(op) = Opcode::from_code(code, control) else {
        let message = match FOREIGN.iter().find(|(c, _)| *c == code) {
            Some((_, name)) => format!("opcode {code:#x} ({name}) is not a ps_3_0 instruction"),
            None => format!("unknown opcode {code:#x} (instruction token {t:#010x})"),
        };
        return Err(ReadError::at(byte, message));
    };
    if !op.profiles().has(profile) {
        return Err(ReadError::at(
            byte,
            format!(
                "opcode {code:#x} ({}) is not a {profile} instruction",
                op.info().mnemonic
            ),
        ));
    }
    let row = op.info_in(profile);
    for (bit, what) in [
        (31, "bit 31, which an instruction token keeps clear"),
        (30, "the co-issue bit (ps_1_x only)"),
        (29, "reserved bit 29"),
    ] {
        if t & 1 << bit != 0 {
            return Err(ReadError::at(
                byte,
                format!("`{}` token {t:#010x} sets {what}", row.mnemonic),
            ));
        }
    }
    let compare = if row.comparison {
        Some(Compare::from_code(control).ok_or_else(|| {
            ReadError::at(
                byte,
                format!(
                    "`{}` with comparison code {control}, which is not 1 to 6",
                    row.mnemonic
                ),
            )
        })?)
    } else {
        if control != row.control {
            return Err(ReadError::at(
                byte,
                format!(
                    "`{}` with control bits {control:#x}, which it does not take",
                    row.mnemonic
                ),
            ));
        }
        None
    };
    if at + 1 + len > tokens.len() {
        return Err(ReadError::at(
            byte,
            format!(
                "`{}` claims {len} operand tokens, past the end of the stream ({} bytes)",
                row.mnemonic,
                tokens.len() * 4
            ),
        )
        .with_help("the length field lies, or the file is truncated"));
    }
    let mut ops = Operands {
        tokens,
        next: at + 1,
        end: at + 1 + len,
        byte,
        mnemonic: row.mnemonic,
        len,
        profile,
    };
    let predicated = t & 1 << 28 != 0;
    let instr = operands(op, predicated, compare, &mut ops)?;
    if ops.next != ops.end {
        return Err(ReadError::at(
            byte,
            format!(
                "the length field of `{}` says {len} operand tokens; its operands take {}",
                row.mnemonic,
                ops.next - at - 1
            ),
        ));
    }
    Ok((instr, ops.end))
}

/// The operand tokens of one instruction, with its length as the limit.
struct Operands<'a, 'b> {
    tokens: &'b Tokens<'a>,
    next: usize,
    end: usize,
    /// Byte offset of the instruction token.
    byte: usize,
    mnemonic: &'static str,
    len: usize,
    profile: Profile,
}

impl Operands<'_, '_> {
    /// The next token and its byte offset, within the instruction's length.
    fn take(&mut self) -> Result<(u32, usize), ReadError> {
        if self.next >= self.end {
            return Err(ReadError::at(
                self.byte,
                format!(
                    "the length field of `{}` says {} operand tokens; its operands need more",
                    self.mnemonic, self.len
                ),
            ));
        }
        let t = self.tokens.get(self.next).unwrap_or_default();
        self.next += 1;
        Ok((t, (self.next - 1) * 4))
    }

    fn dest(&mut self) -> Result<Dest, ReadError> {
        let (t, byte) = self.take()?;
        let mut d = dest(t, byte, self.profile)?;
        if t & 1 << 13 != 0 {
            d.relative = Some(self.index()?);
        }
        Ok(d)
    }

    fn source(&mut self) -> Result<Source, ReadError> {
        let (t, byte) = self.take()?;
        let mut s = source(t, byte, self.profile)?;
        if t & 1 << 13 != 0 {
            s.relative = Some(self.index()?);
        }
        Ok(s)
    }

    /// The relative-address token after a parameter: `aL`, or in vertex
    /// shaders one component of `a0` (its replicate swizzle).
    fn index(&mut self) -> Result<RelIndex, ReadError> {
        let (rel, byte) = self.take()?;
        if rel == super::relative_token(RelIndex::Loop) {
            return Ok(RelIndex::Loop);
        }
        let vertex = self.profile.stage() == crate::core::profile::Stage::Vertex;
        let addr = (0..4).find(|&c| rel == super::relative_token(RelIndex::Addr(c)));
        match addr {
            Some(c) if vertex => Ok(RelIndex::Addr(c)),
            _ if vertex => Err(ReadError::at(
                byte,
                format!("relative-address token {rel:#010x}: the index is aL (0xf0e40800) or one component of a0 (0xb0000000, 0xb0550000, 0xb0aa0000, 0xb0ff0000)"),
            )),
            _ => Err(ReadError::at(
                byte,
                format!("relative-address token {rel:#010x}: {} indexes with aL alone (0xf0e40800)", self.profile),
            )),
        }
    }
}

/// Reads the operands the instruction's row describes, in token order.
fn operands(
    op: Opcode,
    predicated: bool,
    compare: Option<Compare>,
    ops: &mut Operands,
) -> Result<Instr, ReadError> {
    let mut instr = Instr {
        op,
        compare,
        predicate: None,
        dst: None,
        src: Vec::new(),
        extra: Extra::None,
    };
    if op == Opcode::Dcl {
        let (usage, byte) = ops.take()?;
        instr.extra = declaration(usage, byte)?;
    }
    let shape = op.info_in(ops.profile).operands;
    let has_dst = matches!(
        shape.first(),
        Some(Operand::Dst | Operand::PredDst | Operand::KillSrc)
    ) || op == Opcode::Dcl;
    if has_dst {
        instr.dst = Some(ops.dest()?);
    }
    if predicated {
        instr.predicate = Some(ops.source()?);
    }
    for kind in shape.iter().skip(usize::from(has_dst && op != Opcode::Dcl)) {
        match kind {
            Operand::FloatLits | Operand::IntLits | Operand::BoolLit => {
                instr.extra = literals(*kind, ops)?;
            }
            _ => instr.src.push(ops.source()?),
        }
    }
    Ok(instr)
}

/// A `dcl` usage token.
fn declaration(t: u32, byte: usize) -> Result<Extra, ReadError> {
    let known = 0x8000_0000 | 0xF | 0xF << 16 | 0xF << 27;
    if t & 0x8000_0000 == 0 || t & !known != 0 {
        return Err(ReadError::at(
            byte,
            format!("`dcl` usage token {t:#010x} sets bits a declaration does not have"),
        ));
    }
    let (usage, index, texture) = (
        (t & 0xF) as u8,
        ((t >> 16) & 0xF) as u8,
        ((t >> 27) & 0xF) as u8,
    );
    if texture != 0 && (usage != 0 || index != 0) {
        return Err(ReadError::at(
            byte,
            format!("`dcl` usage token {t:#010x} names both a usage and a sampler type"),
        ));
    }
    if usage as usize >= crate::core::isa::USAGES.len() {
        return Err(ReadError::at(
            byte,
            format!("`dcl` with usage code {usage}, which D3DDECLUSAGE does not have"),
        ));
    }
    if texture > 4 {
        return Err(ReadError::at(
            byte,
            format!("`dcl` with sampler texture type {texture}, which does not exist"),
        ));
    }
    Ok(Extra::Decl {
        usage,
        index,
        texture,
    })
}

/// The literal tokens of `def`, `defi`, `defb`.
fn literals(kind: Operand, ops: &mut Operands) -> Result<Extra, ReadError> {
    if kind == Operand::BoolLit {
        let (t, byte) = ops.take()?;
        return match t {
            0 | 1 => Ok(Extra::Bool(t == 1)),
            _ => Err(ReadError::at(
                byte,
                format!("`defb` value {t:#x}: a boolean is 0 or 1"),
            )),
        };
    }
    let mut v = [0u32; 4];
    // Any 32-bit pattern: SetPixelShaderConstantF and `def` take NaNs with
    // any payload, denormals and -0 as they are.
    for slot in &mut v {
        let (t, _) = ops.take()?;
        *slot = t;
    }
    Ok(match kind {
        Operand::FloatLits => Extra::Float(v),
        _ => Extra::Int(v.map(|t| t as i32)),
    })
}

/// D3DSPR_* register types, for messages.
const REGISTER_TYPES: [&str; 20] = [
    "TEMP",
    "INPUT",
    "CONST",
    "ADDR/TEXTURE (a0, t#)",
    "RASTOUT",
    "ATTROUT",
    "OUTPUT (o#)",
    "CONSTINT",
    "COLOROUT",
    "DEPTHOUT",
    "SAMPLER",
    "CONST2",
    "CONST3",
    "CONST4",
    "CONSTBOOL",
    "LOOP",
    "TEMPFLOAT16",
    "MISCTYPE",
    "LABEL",
    "PREDICATE",
];

/// The register of a parameter token, in range unless `relative`.
fn register(t: u32, byte: usize, relative: bool, profile: Profile) -> Result<Reg, ReadError> {
    if t & 0x8000_0000 == 0 {
        return Err(ReadError::at(
            byte,
            format!("parameter token {t:#010x} has bit 31 clear"),
        ));
    }
    if t & 0xC000 != 0 {
        return Err(ReadError::at(
            byte,
            format!("parameter token {t:#010x} sets reserved bits 14–15"),
        ));
    }
    let ty = ((t >> 28) & 7 | (t >> 8) & 0x18) as u8;
    let number = t & 0x7FF;
    let Some((file, index)) = RegFile::from_token_in(ty, number, profile) else {
        let name = REGISTER_TYPES
            .get(ty as usize)
            .copied()
            .unwrap_or("undefined");
        let message = if REG_FILES
            .iter()
            .any(|f| f.token_type == ty && profile.count(f.file) > 0)
        {
            format!("register {number} of type {ty} ({name}) does not exist")
        } else {
            let stage = match profile {
                Profile::Ps3_0 => "pixel shaders 3.0",
                p => p.name(),
            };
            format!("register type {ty} ({name}) does not exist in {stage}")
        };
        return Err(ReadError::at(byte, message));
    };
    let info = file.info();
    let count = profile.count(file);
    if !relative && index >= count {
        return Err(ReadError::at(
            byte,
            format!(
                "{}{index} does not exist: {profile} has {0}0 to {0}{1}",
                info.name,
                count - 1
            ),
        ));
    }
    Ok(Reg { file, index })
}

/// A destination-format token.
fn dest(t: u32, byte: usize, profile: Profile) -> Result<Dest, ReadError> {
    let relative = t & 1 << 13 != 0;
    let reg = register(t, byte, relative, profile)?;
    if relative && !(profile == Profile::Vs3_0 && reg.file == RegFile::Output) {
        return Err(ReadError::at(
            byte,
            "a relatively addressed destination (o[aL] is vs_3_0 only)",
        ));
    }
    if (t >> 24) & 0xF != 0 {
        return Err(ReadError::at(
            byte,
            format!("destination {t:#010x} has a shift modifier (ps_1_x only)"),
        ));
    }
    let result = ((t >> 20) & 0xF) as u8;
    if result & !(SAT | PP | CENTROID) != 0 {
        return Err(ReadError::at(
            byte,
            format!("destination {t:#010x} has result modifier bits {result:#x}"),
        ));
    }
    let mask = ((t >> 16) & 0xF) as u8;
    if mask == 0 {
        return Err(ReadError::at(
            byte,
            format!("destination {t:#010x} writes no component (empty write mask)"),
        ));
    }
    Ok(Dest {
        reg,
        mask: WriteMask(mask),
        relative: None,
        result,
    })
}

/// A source-format token (its relative-address token is read by the caller).
fn source(t: u32, byte: usize, profile: Profile) -> Result<Source, ReadError> {
    let relative = t & 1 << 13 != 0;
    let reg = register(t, byte, relative, profile)?;
    let modifier = modifier_from_code(((t >> 24) & 0xF) as u8).map_err(|name| {
        ReadError::at(
            byte,
            format!("source {t:#010x} has the modifier {name}, which ps_3_0 does not have"),
        )
    })?;
    let s = (t >> 16) & 0xFF;
    let swizzle = Swizzle([0, 1, 2, 3].map(|i| ((s >> (2 * i)) & 3) as u8));
    Ok(Source {
        reg,
        relative: None,
        swizzle,
        modifier,
    })
}
