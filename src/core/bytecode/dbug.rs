//! The debug information fxc stores in a comment block (`DBUG`) when a
//! shader is compiled with `D3DCOMPILE_DEBUG`: which source line each
//! instruction came from and which HLSL variable components each
//! instruction writes.
//!
//! `D3DDisassemble` turns it into `#line` lines and `// name<i,j>` notes, and
//! ps30's listing must print the same text, so the block is decoded here.
//! The layout was read off `d3dcompiler_47.dll`'s output; every offset
//! counts bytes from the start of the block, just after `DBUG`:
//!
//! * a 40-byte header: its own size (40), the creator string's offset, a
//!   word that is 0 in every sample, the file count and the file table's
//!   offset, the instruction count and the line table's offset, the
//!   variable count and the variable table's offset, and the offset of the
//!   entry point's name;
//! * the file table: one string offset per file (the name the compiler was
//!   given, or one a `#line` directive set);
//! * the line table: 8 bytes per instruction, in stream order (`def` and
//!   `dcl` included): the source line in the low 16 bits and the file's
//!   index in the high 16 bits (0xFFFF, line 0, for an instruction of no
//!   source line), then the instruction's byte offset in the shader (the
//!   version token at 0);
//! * the variable table: 20 bytes per variable: the offset of the function
//!   whose parameter it is (0 for a global, a local or a return value), the
//!   name's offset, the offset of a type described as in the constant table
//!   (not needed here, so not followed), the record count and the records'
//!   offset;
//! * records: 12 bytes each: the index of an instruction writing the
//!   variable, then four 16-bit numbers, one per register component x, y,
//!   z, w: the variable's component (counted over its flattened leaves)
//!   that the written register component holds, or 0xFFFF for none.
//!
//! The block comes from the file, so it is decoded as hostile, with the
//! constant table's checked reads: every offset and count is checked
//! before use, strings must end inside the block, and the bytes decoded in
//! all may not exceed a fixed multiple of the block's size. Microsoft's
//! disassembler trusts the block (an offset out of range crashes it); ps30
//! writes a listing without the block's notes instead (see
//! [`microsoft`](super::microsoft)).

use super::ctab::{err, CtabError, Decoder};
use std::collections::HashMap;
use std::fmt::Write;

/// The comment block's FOURCC, `DBUG`.
pub const DBUG: u32 = u32::from_le_bytes(*b"DBUG");

/// The line table's file index of an instruction that has no source line.
pub const NO_FILE: u16 = 0xFFFF;

/// The component number of a register component that holds no component
/// of the variable.
pub const NO_COMPONENT: u16 = 0xFFFF;

/// A decoded `DBUG` block.
#[derive(Clone, Debug, PartialEq)]
pub struct DebugInfo {
    /// Who wrote it (`Microsoft (R) HLSL Shader Compiler …`), if its
    /// offset leads to a string.
    pub creator: Option<String>,
    /// The source files' names, indexed by [`SourceLine::file`].
    pub files: Vec<String>,
    /// One entry per instruction, in stream order.
    pub lines: Vec<SourceLine>,
    /// The variables whose writes are recorded.
    pub variables: Vec<Variable>,
    /// The entry point's name (`main`).
    pub entry: String,
}

/// Where one instruction came from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SourceLine {
    /// Index into [`DebugInfo::files`] (not checked), or [`NO_FILE`].
    pub file: u16,
    /// The line number in that file (0 with [`NO_FILE`]).
    pub line: u16,
    /// The instruction's byte offset in the shader (version token at 0).
    pub offset: u32,
}

/// One variable and the instructions that write it.
#[derive(Clone, Debug, PartialEq)]
pub struct Variable {
    /// The function whose parameter it is; empty for anything else.
    pub scope: String,
    /// Its HLSL name.
    pub name: String,
    /// The instructions writing it.
    pub writes: Vec<VarWrite>,
}

/// One instruction's write to a variable.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct VarWrite {
    /// The instruction's index in stream order (the line table's index).
    pub instruction: u32,
    /// Per register component x, y, z, w: the variable component it holds,
    /// or [`NO_COMPONENT`].
    pub components: [u16; 4],
}

type R<T> = Result<T, CtabError>;

/// Checks that `count` entries of `size` bytes at the offset in the dword
/// at `at` lie inside the block, and returns that offset.
fn table(d: &Decoder, at: usize, count: usize, size: usize, what: &str) -> R<usize> {
    let offset = d.dword(at, "the header")? as usize;
    let end = (offset as u64).saturating_add(count as u64 * size as u64);
    if end > d.bytes.len() as u64 {
        return err(
            at,
            format!(
                "{count} {what} of {size} bytes at offset {offset} run past the end of the block ({} bytes)",
                d.bytes.len()
            ),
        );
    }
    Ok(offset)
}

/// Decodes a block: the comment body after its `DBUG` token. Errors name
/// the byte offset (from just after `DBUG`) of the first bad field.
pub fn decode(block: &[u32]) -> R<DebugInfo> {
    let bytes: Vec<u8> = block.iter().flat_map(|t| t.to_le_bytes()).collect();
    let mut d = Decoder::new(&bytes);
    // D3DDisassemble never reads the creator: a bad one loses only itself
    let creator = d.string_at(4, "the creator").ok();
    let file_count = d.dword(12, "the header")? as usize;
    let file_table = table(&d, 16, file_count, 4, "file names")?;
    let files = (0..file_count)
        .map(|i| d.string_at(file_table + 4 * i, "a file name"))
        .collect::<R<Vec<_>>>()?;
    let line_count = d.dword(20, "the header")? as usize;
    let line_table = table(&d, 24, line_count, 8, "line entries")?;
    d.spend(8 * line_count, line_table)?;
    let lines = (0..line_count)
        .map(|i| source_line(&d, line_table + 8 * i))
        .collect::<R<Vec<_>>>()?;
    let var_count = d.dword(28, "the header")? as usize;
    let var_table = table(&d, 32, var_count, 20, "variables")?;
    let variables = (0..var_count)
        .map(|i| variable(&mut d, var_table + 20 * i))
        .collect::<R<Vec<_>>>()?;
    let entry = d.string_at(36, "the entry point's name")?;
    Ok(DebugInfo {
        creator,
        files,
        lines,
        variables,
        entry,
    })
}

/// One line-table entry at `at`. A file index past the file table is kept:
/// `D3DDisassemble` writes no `#line` for it but counts it as a change of
/// file.
fn source_line(d: &Decoder, at: usize) -> R<SourceLine> {
    Ok(SourceLine {
        line: d.word(at, "a line entry")?,
        file: d.word(at + 2, "a line entry")?,
        offset: d.dword(at + 4, "a line entry")?,
    })
}

/// One variable-table entry at `at` with its records.
fn variable(d: &mut Decoder, at: usize) -> R<Variable> {
    d.spend(20, at)?;
    let scope = d.string_at(at, "a variable's function")?;
    let name = d.string_at(at + 4, "a variable's name")?;
    let count = d.dword(at + 12, "a variable")? as usize;
    let records = table(d, at + 16, count, 12, "records")?;
    d.spend(12 * count, records)?;
    let writes = (0..count)
        .map(|i| {
            let r = records + 12 * i;
            let mut components = [NO_COMPONENT; 4];
            for (k, c) in components.iter_mut().enumerate() {
                *c = d.word(r + 4 + 2 * k, "a record")?;
            }
            Ok(VarWrite {
                instruction: d.dword(r, "a record")?,
                components,
            })
        })
        .collect::<R<Vec<_>>>()?;
    Ok(Variable {
        scope,
        name,
        writes,
    })
}

impl DebugInfo {
    /// The source line of each instruction that has one, by the
    /// instruction's byte offset (the first entry for an offset wins).
    pub fn lines_by_offset(&self) -> HashMap<u32, SourceLine> {
        let mut map = HashMap::new();
        for l in self.lines.iter().filter(|l| l.file != NO_FILE) {
            map.entry(l.offset).or_insert(*l);
        }
        map
    }

    /// The `  // name<i,j>` notes `D3DDisassemble` writes after an
    /// instruction, by the instruction's index in stream order. A parameter
    /// of the entry point is named bare, any other variable `function::name`
    /// (`::name` when it belongs to no function); the numbers are the
    /// variable components the register's x, y, z, w hold, in that order.
    /// Microsoft's compiler records at most one variable per instruction in
    /// every sample seen; where a block records several, their notes follow
    /// one another after one `//`, separated by a space (a guess: no
    /// compiler output seen shows Microsoft's spelling).
    pub fn notes(&self) -> HashMap<u32, String> {
        let mut map: HashMap<u32, String> = HashMap::new();
        for v in &self.variables {
            let name = if v.scope == self.entry {
                v.name.clone()
            } else {
                format!("{}::{}", v.scope, v.name)
            };
            for w in &v.writes {
                let held: Vec<String> = w
                    .components
                    .iter()
                    .filter(|&&c| c != NO_COMPONENT)
                    .map(u16::to_string)
                    .collect();
                if held.is_empty() {
                    continue;
                }
                let out = map.entry(w.instruction).or_default();
                out.push_str(if out.is_empty() { "  // " } else { " " });
                let _ = write!(out, "{name}<{}>", held.join(","));
            }
        }
        map
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn words(bytes: &[u8]) -> Vec<u32> {
        bytes
            .chunks(4)
            .map(|c| {
                let mut b = [0u8; 4];
                b[..c.len()].copy_from_slice(c);
                u32::from_le_bytes(b)
            })
            .collect()
    }

    /// A block with one file, two instructions and one variable.
    fn sample() -> Vec<u8> {
        let mut b = Vec::new();
        for w in [40u32, 0, 0, 1, 52, 2, 56, 1, 72, 44] {
            b.extend(w.to_le_bytes());
        }
        b.extend(b"a.h\0main\0\0\0\0"); // 40: "a.h", 44: "main", pad to 52
        b.extend(40u32.to_le_bytes()); // 52: file table
        for w in [0xFFFF_0000u32, 4, 7, 12] {
            b.extend(w.to_le_bytes()); // 56: line table
        }
        for w in [0u32, 96, 0, 1, 100] {
            b.extend(w.to_le_bytes()); // 72: variable table
        }
        b.extend([0u8; 4]); // 92
        b.extend(b"x\0\0\0"); // 96: name
        b.extend(1u32.to_le_bytes()); // 100: record
        for c in [NO_COMPONENT, 0, NO_COMPONENT, NO_COMPONENT] {
            b.extend(c.to_le_bytes());
        }
        b
    }

    #[test]
    fn decodes_lines_and_notes() {
        let info = decode(&words(&sample())).unwrap();
        assert_eq!(info.files, vec!["a.h".to_string()]);
        assert_eq!(info.entry, "main");
        let lines = info.lines_by_offset();
        assert_eq!(lines.get(&4), None);
        assert_eq!(lines.get(&12).map(|l| l.line), Some(7));
        let notes = info.notes();
        assert_eq!(notes.get(&1).map(String::as_str), Some("  // ::x<0>"));
        assert_eq!(notes.get(&0), None);
    }

    #[test]
    fn every_truncation_and_bad_offset_is_an_error_not_a_panic() {
        let good = sample();
        for len in 0..good.len() {
            let _ = decode(&words(&good[..len]));
        }
        for at in (0..good.len()).step_by(4) {
            for bad in [0xFFFF_FFF0u32, 0x7FFF_FFFF, 1000, 3] {
                let mut b = good.clone();
                b[at..at + 4].copy_from_slice(&bad.to_le_bytes());
                let _ = decode(&words(&b));
            }
        }
        let mut b = good.clone();
        b[16..20].copy_from_slice(&0xFFFF_FFF0u32.to_le_bytes());
        let e = decode(&words(&b)).unwrap_err();
        assert_eq!(e.offset, 16);
        let mut b = good;
        b[76..80].copy_from_slice(&200u32.to_le_bytes());
        assert_eq!(decode(&words(&b)).unwrap_err().offset, 76);
    }
}
