//! The disassembler: a [`Module`] as an assembly listing in the style of
//! fxc's, which the text front end reads back to the same tokens.
//!
//! The listing is what `ps30 disasm` prints and what every other command
//! parses when it is given a compiled shader, so diagnostics and per-line
//! costs of a `.fxo` point at its lines. fxc's shape is kept: the constant
//! table as a comment block of parameters and registers, `ps_3_0`, the
//! instructions indented by block, and the "approximately N instruction
//! slots used" line. What fxc's listing loses, ps30 keeps: each comment block
//! of the stream (the constant table too) is written where it stands as
//! `//#comment` lines holding its tokens in hexadecimal, which other
//! assemblers skip as comments and ps30 writes back token for token.
//! Constants are printed so that they parse back to the same bits.
//!
//! Alongside the text, [`Listing::anchors`] records which token each line
//! and each operand came from, so that a diagnostic in the listing can name
//! the token and byte of the file.

use super::{ctab, Dest, Extra, Instr, ItemKind, Module, Source, CENTROID, CTAB, PP, SAT};
use crate::core::front::parse::{COMMENT_BLOCK, COMMENT_MORE};
use crate::core::ir::{Reg, RelIndex, SrcMod, WriteMask};
use crate::core::isa::{Class, Opcode, RegFile, USAGES};
use crate::core::profile::Profile;
use std::fmt::Write;

/// A listing and where its parts came from.
#[derive(Clone, Debug, PartialEq)]
pub struct Listing {
    /// The assembly text, in the style of fxc's listings.
    pub text: String,
    /// `(text offset, token index)` at the start of each line and of each
    /// operand, in text order.
    pub anchors: Vec<(u32, u32)>,
}

/// Tokens per `//#comment` line.
const TOKENS_PER_LINE: usize = 8;

/// The listing of a module.
pub fn listing(module: &Module) -> Listing {
    let mut l = Builder {
        out: Listing {
            text: String::new(),
            anchors: Vec::new(),
        },
        profile: module.profile,
    };
    let table = module.items.iter().find_map(|i| match &i.kind {
        ItemKind::Comment(body) if body.first() == Some(&CTAB) => {
            ctab::decode(&body[1..]).ok().map(|_| &body[1..])
        }
        _ => None,
    });
    if let Some(body) = table {
        for line in ctab::listing_header(body, true).lines() {
            l.line(0, line);
        }
    }
    l.line(0, &format!("    {}", module.profile));
    let mut depth = 0usize;
    for item in &module.items {
        match &item.kind {
            ItemKind::Comment(body) => l.comment(item.token, body, table.is_some()),
            ItemKind::Instr(ins) => {
                if matches!(
                    ins.op,
                    Opcode::EndRep | Opcode::EndLoop | Opcode::EndIf | Opcode::Else
                ) {
                    depth = depth.saturating_sub(1);
                }
                if ins.op == Opcode::Label {
                    depth = 0;
                }
                l.instruction(item.token, ins, depth);
                if ins.op.opens_block() || matches!(ins.op, Opcode::Else | Opcode::Label) {
                    depth += 1;
                }
            }
        }
    }
    let (texture, arithmetic) = slots(module);
    let end = module
        .items
        .last()
        .map_or(1, |i| i.token + 1 + length(&i.kind));
    l.line(
        end,
        &format!(
            "\n// approximately {} instruction slots used ({texture} texture, {arithmetic} arithmetic)",
            texture + arithmetic
        ),
    );
    l.out
}

/// Tokens after an item's first token.
fn length(kind: &ItemKind) -> u32 {
    match kind {
        ItemKind::Comment(body) => body.len() as u32,
        ItemKind::Instr(i) => i.operand_tokens(),
    }
}

/// Static slots by fxc's split: texture instructions, and everything else
/// (flow control included). Cube samplers and predication are counted as
/// the validator counts them.
pub fn slots(module: &Module) -> (u32, u32) {
    let cube: Vec<u32> = module
        .items
        .iter()
        .filter_map(|i| match &i.kind {
            ItemKind::Instr(Instr {
                op: Opcode::Dcl,
                dst: Some(d),
                extra: Extra::Decl { texture: 3, .. },
                ..
            }) if d.reg.file == RegFile::Sampler => Some(d.reg.index),
            _ => None,
        })
        .collect();
    let (mut texture, mut arithmetic) = (0, 0);
    for item in &module.items {
        let ItemKind::Instr(ins) = &item.kind else {
            continue;
        };
        let row = ins.op.info();
        let on_cube = ins
            .src
            .iter()
            .any(|s| s.reg.file == RegFile::Sampler && cube.contains(&s.reg.index));
        let n = row.slots_of(on_cube, ins.predicate.is_some());
        match row.class {
            Class::Texture => texture += n,
            _ => arithmetic += n,
        }
    }
    (texture, arithmetic)
}

struct Builder {
    out: Listing,
    profile: Profile,
}

impl Builder {
    fn anchor(&mut self, token: u32) {
        self.out.anchors.push((self.out.text.len() as u32, token));
    }

    fn line(&mut self, token: u32, text: &str) {
        self.anchor(token);
        self.out.text.push_str(text);
        self.out.text.push('\n');
    }

    fn comment(&mut self, token: u32, body: &[u32], table_above: bool) {
        let what = match body.first() {
            Some(&CTAB) if table_above => "the constant table above (CTAB)".to_string(),
            Some(t) if t.to_le_bytes().iter().all(|b| b.is_ascii_alphanumeric()) => {
                format!(
                    "a comment block `{}`",
                    String::from_utf8_lossy(&t.to_le_bytes())
                )
            }
            _ => "a comment block".to_string(),
        };
        self.line(
            token,
            &format!("// {what}, {} tokens, kept as written:", body.len()),
        );
        if body.is_empty() {
            self.line(token, COMMENT_BLOCK);
        }
        for (n, chunk) in body.chunks(TOKENS_PER_LINE).enumerate() {
            let head = if n == 0 { COMMENT_BLOCK } else { COMMENT_MORE };
            let words: Vec<String> = chunk.iter().map(|t| format!("{t:08x}")).collect();
            let first = token + 1 + (n * TOKENS_PER_LINE) as u32;
            self.line(first, &format!("{head} {}", words.join(" ")));
        }
    }

    fn instruction(&mut self, token: u32, ins: &Instr, depth: usize) {
        self.anchor(token);
        let indent = 4 + 2 * depth;
        self.out.text.push_str(&" ".repeat(indent));
        let (line, anchors) = instruction_line(ins, token, self.profile);
        let start = self.out.text.len() as u32;
        self.out
            .anchors
            .extend(anchors.into_iter().map(|(at, t)| (start + at, t)));
        self.out.text.push_str(&line);
        self.out.text.push('\n');
    }
}

/// One instruction as assembly, e.g. `texld r0, v0, s0`.
pub fn instruction_text(ins: &Instr) -> String {
    instruction_line(ins, 0, Profile::Ps3_0).0
}

/// One instruction as assembly, with `(offset in the line, token)` for
/// each operand; `token` is the instruction token's index.
fn instruction_line(ins: &Instr, token: u32, profile: Profile) -> (String, Vec<(u32, u32)>) {
    let mut line = String::new();
    let mut anchors = Vec::new();
    // Token positions: [usage], dst, [predicate], sources (+ relative).
    let mut at = token + 1 + u32::from(matches!(ins.extra, Extra::Decl { .. }));
    let dst_at = at;
    at += ins.dst.map_or(0, |d| 1 + u32::from(d.relative.is_some()));
    if let Some(p) = &ins.predicate {
        anchors.push((line.len() as u32, at));
        let _ = write!(line, "({}) ", source_text(p));
        at += 1 + u32::from(p.relative.is_some());
    }
    line.push_str(&mnemonic(ins, profile));
    let mut operands: Vec<(u32, String)> = Vec::new();
    if let Some(d) = &ins.dst {
        operands.push((dst_at, dest_text(d)));
    }
    for s in &ins.src {
        operands.push((at, source_text(s)));
        at += 1 + u32::from(s.relative.is_some());
    }
    for (i, v) in literal_texts(&ins.extra).into_iter().enumerate() {
        operands.push((at + i as u32, v));
    }
    for (i, (t, text)) in operands.into_iter().enumerate() {
        line.push_str(if i == 0 { " " } else { ", " });
        anchors.push((line.len() as u32, t));
        line.push_str(&text);
    }
    (line, anchors)
}

/// The mnemonic with its suffixes: comparison, declaration kind, result
/// modifiers.
fn mnemonic(ins: &Instr, profile: Profile) -> String {
    let mut m = ins.op.info().mnemonic.to_string();
    if let Some(c) = ins.compare {
        let _ = write!(m, "_{}", c.suffix());
    }
    if let (
        Extra::Decl {
            usage,
            index,
            texture,
        },
        Some(d),
    ) = (ins.extra, &ins.dst)
    {
        match texture {
            1 => m.push_str("_1d"),
            2 => m.push_str("_2d"),
            3 => m.push_str("_cube"),
            4 => m.push_str("_volume"),
            // ps_2_0 and ps_2_x declare t# and v# without a usage.
            _ if usage != 0
                || index != 0
                || matches!(d.reg.file, RegFile::Input | RegFile::Output)
                    && !matches!(profile, Profile::Ps2_0 | Profile::Ps2X) =>
            {
                let _ = write!(m, "_{}", USAGES[usage as usize]);
                if index != 0 {
                    let _ = write!(m, "{index}");
                }
            }
            _ => {}
        }
    }
    let result = ins.dst.map_or(0, |d| d.result);
    for (bit, name) in [(SAT, "_sat"), (PP, "_pp"), (CENTROID, "_centroid")] {
        if result & bit != 0 {
            m.push_str(name);
        }
    }
    m
}

fn dest_text(d: &Dest) -> String {
    let reg = match d.relative {
        Some(index) => indexed_text(d.reg, index),
        None => d.reg.to_string(),
    };
    if d.mask == WriteMask::ALL {
        reg
    } else {
        format!("{reg}{}", d.mask)
    }
}

/// `v[aL + 2]`, `c[a0.x]`: a relatively addressed register as the parser
/// reads it.
fn indexed_text(reg: Reg, index: RelIndex) -> String {
    let name = reg.file.info().name;
    match (reg.file.info().numbered, reg.index) {
        (true, 0) | (false, _) => format!("{name}[{index}]"),
        (true, n) => format!("{name}[{index} + {n}]"),
    }
}

/// A source as the parser reads it: `-v[aL + 2]_abs.x`, `!b0`, `p0.z`.
pub fn source_text(s: &Source) -> String {
    let reg = match s.relative {
        Some(index) => indexed_text(s.reg, index),
        None => s.reg.to_string(),
    };
    let (pre, abs) = match s.modifier {
        SrcMod::None => ("", ""),
        SrcMod::Neg => ("-", ""),
        SrcMod::Abs => ("", "_abs"),
        SrcMod::NegAbs => ("-", "_abs"),
        SrcMod::Not => ("!", ""),
    };
    format!("{pre}{reg}{abs}{}", s.swizzle)
}

fn literal_texts(extra: &Extra) -> Vec<String> {
    match extra {
        Extra::Float(v) => v.iter().map(|&b| float_text(f32::from_bits(b))).collect(),
        Extra::Int(v) => v.iter().map(i32::to_string).collect(),
        Extra::Bool(b) => vec![b.to_string()],
        Extra::None | Extra::Decl { .. } => Vec::new(),
    }
}

/// The shortest decimal that the front end reads back to the same float
/// (it parses a double and rounds it to single precision), or the exact
/// value when the shortest one would round twice to a neighbour.
/// Infinities and the NaNs text can write are spelled as Microsoft's
/// assembler reads them ([`special_float_text`]); any other NaN (a payload
/// or a signalling NaN read from bytecode) as `D3DDisassemble` lists it,
/// `1.#QNAN` when positive and `-1.#IND` when negative — text cannot keep
/// its payload, so it reads back as one of those two.
pub fn float_text(x: f32) -> String {
    if let Some(special) = special_float_text(x.to_bits()) {
        return special.to_string();
    }
    if x.is_nan() {
        let negative = x.to_bits() >> 31 == 1;
        return if negative { "-1.#IND" } else { "1.#QNAN" }.to_string();
    }
    let short = x.to_string();
    match short.parse::<f64>() {
        Ok(v) if (v as f32).to_bits() == x.to_bits() => short,
        _ => (x as f64).to_string(),
    }
}

/// How the front end (like Microsoft's assembler) writes the floats that
/// are not numbers: `1.#INF` and `-1.#INF`, and the four NaNs its spellings
/// give (`1.#QNAN` 0x7FE00000, `-1.#QNAN` 0xFFE00000, `1.#IND` 0xFFC00000,
/// `-1.#IND` 0x7FC00000); `None` for finite values and every other NaN.
pub fn special_float_text(bits: u32) -> Option<&'static str> {
    Some(match bits {
        0x7F80_0000 => "1.#INF",
        0xFF80_0000 => "-1.#INF",
        0x7FE0_0000 => "1.#QNAN",
        0xFFE0_0000 => "-1.#QNAN",
        0xFFC0_0000 => "1.#IND",
        0x7FC0_0000 => "-1.#IND",
        _ => return None,
    })
}
