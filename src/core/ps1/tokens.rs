//! A ps_1_x [`Program`] as Microsoft's tokens, and tokens back.
//!
//! The layout is ps_2_0's ([`crate::core::bytecode`]) with what ps_1_x
//! adds and lacks: an instruction token holds only its opcode and, in bit
//! 30, co-issue (no length: the reader takes each instruction's operands
//! from its row in the profile); `phase` is the token `0x0000FFFD` alone; a
//! destination carries a shift in bits 24–27 (four-bit signed: 1 `_x2` …
//! 15 `_d2`, 13 `_d8`); a source modifier is any D3DSPSM_* code up to 10
//! ([`Modifier`]). Reading checks every token before use and names the
//! byte of the first that is not a ps_1_x token.

use super::{Dest, Instr, Modifier, Program, Source};
use crate::core::bytecode::{register_token, ReadError, COMMENT, END};
use crate::core::ir::{Reg, Span, Swizzle, WriteMask};
use crate::core::isa::{Opcode, Operand, RegFile};
use crate::core::profile::Profile;

/// The token of `phase`.
pub const PHASE: u32 = 0x0000_FFFD;

/// The tokens of a program, version and end token included.
pub fn encode(p: &Program) -> Vec<u32> {
    let mut out = vec![p.profile.version_token()];
    for i in &p.instrs {
        out.push(u32::from(i.op.info().code) | u32::from(i.coissue) << 30);
        if let Some(d) = &i.dst {
            out.push(dest_token(d));
        }
        out.extend(i.src.iter().map(source_token));
        if let Some(bits) = i.def {
            out.extend(bits);
        }
    }
    out.push(END);
    out
}

/// A destination token.
pub fn dest_token(d: &Dest) -> u32 {
    register_token(d.reg)
        | u32::from(d.mask.0) << 16
        | u32::from(d.sat) << 20
        | ((d.shift as u32) & 0xF) << 24
}

/// A source token.
pub fn source_token(s: &Source) -> u32 {
    let swizzle: u32 = (0..4)
        .map(|i| (u32::from(s.swizzle.0[i]) & 3) << (2 * i))
        .sum();
    register_token(s.reg) | swizzle << 16 | s.modifier.code() << 24
}

/// Whether the first token of `bytes` is a ps_1_x version token.
pub fn is_ps1(bytes: &[u8]) -> bool {
    bytes.len() >= 4
        && Profile::from_token(u32::from_le_bytes([bytes[0], bytes[1], bytes[2], bytes[3]]))
            .is_some_and(Profile::is_ps1)
}

/// Reads a ps_1_x token stream (at most `max_items` instructions).
pub fn decode(bytes: &[u8], max_items: u64) -> Result<Program, ReadError> {
    if !bytes.len().is_multiple_of(4) {
        let at = bytes.len() / 4 * 4;
        return Err(ReadError::at(
            at,
            format!("{} bytes: not whole tokens", bytes.len()),
        ));
    }
    let tokens: Vec<u32> = bytes
        .chunks_exact(4)
        .map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]))
        .collect();
    let profile = tokens
        .first()
        .and_then(|&v| Profile::from_token(v))
        .filter(|p| p.is_ps1())
        .ok_or_else(|| ReadError::at(0, "not a ps_1_x version token"))?;
    let mut r = Reader {
        tokens: &tokens,
        at: 1,
        profile,
    };
    let mut instrs = Vec::new();
    loop {
        let t = r.next("the end token")?;
        if t == END {
            break;
        }
        if t & 0xFFFF == COMMENT && t & 0x8000_0000 == 0 {
            let n = (t >> 16 & 0x7FFF) as usize;
            if r.at + n > tokens.len() {
                return Err(ReadError::at(
                    (r.at - 1) * 4,
                    format!("comment of {n} tokens runs past the end"),
                ));
            }
            r.at += n;
            continue;
        }
        if instrs.len() as u64 >= max_items {
            return Err(ReadError::at(
                (r.at - 1) * 4,
                format!("more than {max_items} instructions"),
            ));
        }
        instrs.push(r.instruction(t)?);
    }
    if r.at != tokens.len() {
        return Err(ReadError::at(r.at * 4, "tokens after the end token"));
    }
    Ok(Program { profile, instrs })
}

struct Reader<'t> {
    tokens: &'t [u32],
    at: usize,
    profile: Profile,
}

impl Reader<'_> {
    fn next(&mut self, what: &str) -> Result<u32, ReadError> {
        let t = self.tokens.get(self.at).copied().ok_or_else(|| {
            ReadError::at(
                self.at * 4,
                format!("the stream ends where {what} should be"),
            )
        })?;
        self.at += 1;
        Ok(t)
    }

    fn instruction(&mut self, t: u32) -> Result<Instr, ReadError> {
        let byte = (self.at - 1) * 4;
        let code = (t & 0xFFFF) as u16;
        let op = Opcode::from_code_in(code, 0, self.profile)
            .filter(|op| op.profiles().has(self.profile))
            .ok_or_else(|| {
                ReadError::at(
                    byte,
                    format!("opcode {code:#x} is no {} instruction", self.profile),
                )
            })?;
        if t & !0x4000_FFFF != 0 || (op == Opcode::Phase && t != PHASE) {
            return Err(ReadError::at(
                byte,
                format!("instruction token {t:#010x} has bits ps_1_x does not use"),
            ));
        }
        let mut i = Instr {
            op,
            coissue: t & 0x4000_0000 != 0,
            dst: None,
            src: Vec::new(),
            def: None,
            span: Span::default(),
            base_span: Span::default(),
        };
        for kind in op.info_in(self.profile).operands {
            match kind {
                Operand::Dst | Operand::KillSrc => i.dst = Some(self.dest()?),
                Operand::FloatLits => {
                    let mut bits = [0u32; 4];
                    for b in &mut bits {
                        *b = self.next("a def value")?;
                    }
                    i.def = Some(bits);
                }
                _ => i.src.push(self.source()?),
            }
        }
        Ok(i)
    }

    fn register(&self, t: u32, byte: usize) -> Result<Reg, ReadError> {
        if t & 0x8000_0000 == 0 {
            return Err(ReadError::at(
                byte,
                format!("parameter token {t:#010x} lacks bit 31"),
            ));
        }
        let ty = (t >> 28 & 7 | t >> 8 & 0x18) as u8;
        let (file, index) = RegFile::from_token_in(ty, t & 0x7FF, self.profile)
            .filter(|(f, n)| *n < self.profile.count(*f))
            .ok_or_else(|| {
                ReadError::at(
                    byte,
                    format!(
                        "parameter token {t:#010x} names no {} register",
                        self.profile
                    ),
                )
            })?;
        if t & 0x2000 != 0 {
            return Err(ReadError::at(byte, "relative addressing: not in ps_1_x"));
        }
        Ok(Reg { file, index })
    }

    fn dest(&mut self) -> Result<Dest, ReadError> {
        let t = self.next("a destination")?;
        let byte = (self.at - 1) * 4;
        let reg = self.register(t, byte)?;
        if t >> 20 & 0xE != 0 || t & 0xC000 != 0 {
            return Err(ReadError::at(
                byte,
                format!("destination {t:#010x} has modifiers ps_1_x does not have"),
            ));
        }
        let shift = ((t >> 24 & 0xF) as i8) << 4 >> 4;
        Ok(Dest {
            reg,
            mask: WriteMask((t >> 16 & 0xF) as u8),
            shift,
            sat: t >> 20 & 1 != 0,
            span: Span::default(),
        })
    }

    fn source(&mut self) -> Result<Source, ReadError> {
        let t = self.next("a source")?;
        let byte = (self.at - 1) * 4;
        let reg = self.register(t, byte)?;
        let modifier = Modifier::from_code(t >> 24 & 0xF).ok_or_else(|| {
            ReadError::at(
                byte,
                format!("source {t:#010x} has a modifier ps_1_x does not have"),
            )
        })?;
        if t & 0xC000 != 0 {
            return Err(ReadError::at(
                byte,
                format!("source {t:#010x} has reserved bits set"),
            ));
        }
        let s = t >> 16 & 0xFF;
        Ok(Source {
            reg,
            swizzle: Swizzle([0, 1, 2, 3].map(|i| (s >> (2 * i) & 3) as u8)),
            modifier,
            span: Span::default(),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn bytes(t: &[u32]) -> Vec<u8> {
        t.iter().flat_map(|w| w.to_le_bytes()).collect()
    }

    /// Microsoft's tokens for a ps_1_1 shader with a texture instruction, a
    /// shift, `_sat`, `1-` and `_bx2` sources and a co-issued pair (the
    /// oracle's `pair-mods` probe, trimmed of its defs).
    const STREAM: [u32; 14] = [
        0xffff0101, 0x00000042, 0xb00f0000, 0x00000005, 0x81070000, 0x84e40000, 0x86e40001,
        0x40000002, 0x80180000, 0x82e40001, 0x81e40000, 0x0000fffd, 0x0000ffff, 0,
    ];

    #[test]
    fn tokens_read_and_write_back_the_same() {
        let t = &STREAM[..11];
        let mut whole = t.to_vec();
        whole.push(END);
        let p = decode(&bytes(&whole), 100).unwrap();
        assert_eq!(p.instrs.len(), 3);
        assert!(p.instrs[2].coissue);
        assert_eq!(p.instrs[1].dst.unwrap().shift, 1);
        assert_eq!(p.instrs[1].src[1].modifier, Modifier::Comp);
        assert_eq!(encode(&p), whole);
    }

    #[test]
    fn malformed_streams_are_refused_at_their_byte() {
        let cases: [(&[u32], &str, usize); 8] = [
            (&[0xffff0101, 0x00000001], "ends where a destination", 8),
            (&[0xffff0101, 0x00001234, END], "no ps_1_1 instruction", 4),
            (
                &[
                    0xffff0101, 0x00000059, 0x80030000, 0xa0e40000, 0x80e40000, END,
                ],
                "no ps_1_1 instruction",
                4,
            ),
            (
                &[0xffff0101, 0x00000001, 0x800f0002, 0xa0e40000, END],
                "names no ps_1_1 register",
                8,
            ),
            (
                &[0xffff0101, 0x00000001, 0x800f0000, 0x8be40001, END],
                "a modifier ps_1_x does not have",
                12,
            ),
            (
                &[0xffff0104, 0x0100fffd, END],
                "bits ps_1_x does not use",
                4,
            ),
            (&[0xffff0101, 0x7ffffffe, END], "runs past the end", 4),
            (&[0xffff0101, END, END], "after the end token", 8),
        ];
        for (t, message, byte) in cases {
            let e = decode(&bytes(t), 100).unwrap_err();
            assert!(e.message.contains(message), "{e}: expected {message}");
            assert_eq!(e.byte, byte, "{e}");
        }
    }

    #[test]
    fn every_cut_and_changed_byte_is_read_or_refused_without_panic() {
        let whole = bytes(&STREAM[..13]);
        for n in 0..whole.len() {
            let _ = decode(&whole[..n], 100);
            for v in [0u8, 0x40, 0x80, 0xff] {
                let mut b = whole.clone();
                b[n] = v;
                if let Ok(p) = decode(&b, 100) {
                    // What reads writes back to the same tokens.
                    assert_eq!(bytes(&encode(&p)), b, "byte {n} = {v:#x}");
                }
            }
        }
    }
}
