//! Oracle fixtures: bytecode and round trips (see `tests/oracle.rs`).
//!
//! For every file Microsoft accepted: ps30 assembles an assembly probe to
//! exactly Microsoft's bytes; ps30's bytecode reader reads Microsoft's
//! bytecode; ps30 assembles Microsoft's listing of it to the instruction
//! tokens Microsoft's own assembler makes of that listing (its answer,
//! `REL.dis.fxo`, is a fixture); and those are the original's, but for the
//! payloads of NaN `def` values, which no listing spells. Comment blocks are left out of
//! the round trips: a listing carries the constant table of a compiled shader
//! as `//` text, which assembles to no comment.
//!
//! Each test gathers every failing file before it fails, one line per file
//! with the first token that differs, so one run shows the whole picture.

use super::*;
use ps30::core::bytecode::{self, read};
use ps30::core::load::{self, Options};

/// Little-endian tokens of a bytecode file (a trailing partial token is
/// dropped: the reader reports it; here the tokens are compared).
pub(super) fn tokens(bytes: &[u8]) -> Vec<u32> {
    bytes
        .chunks_exact(4)
        .map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]]))
        .collect()
}

/// The stream without its comment blocks: the version token, every
/// instruction token with its operands (walked by the length field of
/// ps_2_0 and later, so no operand is taken for a comment), the end token.
fn instruction_tokens(stream: &[u32]) -> Vec<u32> {
    let mut out = Vec::with_capacity(stream.len());
    let Some(&version) = stream.first() else {
        return out;
    };
    out.push(version);
    let mut at = 1;
    while let Some(&t) = stream.get(at) {
        if t == bytecode::END {
            out.push(t);
            break;
        }
        if t & 0xFFFF == bytecode::COMMENT {
            at += 1 + ((t >> 16) & 0x7FFF) as usize;
            continue;
        }
        let next = (at + 1 + ((t >> 24) & 0xF) as usize).min(stream.len());
        out.extend_from_slice(&stream[at..next]);
        at = next;
    }
    out
}

/// The positions of `def` literals in a stream of instruction tokens (as
/// [`instruction_tokens`] returns it).
fn def_literals(stream: &[u32]) -> Vec<usize> {
    let mut out = Vec::new();
    let mut at = 1;
    while let Some(&t) = stream.get(at) {
        if t == bytecode::END {
            break;
        }
        if t & 0xFFFF == 0x51 {
            out.extend((at + 2..at + 6).filter(|&i| i < stream.len()));
        }
        at += 1 + ((t >> 24) & 0xF) as usize;
    }
    out
}

/// Whether two instruction streams differ only in the payloads of NaN `def`
/// values: a listing spells every NaN as `1.#QNAN` or `-1.#IND`, so the
/// payload of the original cannot come back through it (Microsoft's own
/// assembler makes 0x7FE00000 and 0xFFC00000 of them).
fn only_nan_payloads_differ(a: &[u32], b: &[u32]) -> bool {
    let literals = def_literals(a);
    a.len() == b.len()
        && a.iter().zip(b).enumerate().all(|(i, (x, y))| {
            x == y
                || (literals.contains(&i)
                    && f32::from_bits(*x).is_nan()
                    && f32::from_bits(*y).is_nan())
        })
}

/// Where two token streams first differ, if they do.
pub(super) fn first_difference(ours: &[u32], theirs: &[u32]) -> Option<String> {
    let at = ours
        .iter()
        .zip(theirs)
        .position(|(a, b)| a != b)
        .or_else(|| (ours.len() != theirs.len()).then(|| ours.len().min(theirs.len())))?;
    let show = |t: Option<&u32>| t.map_or("(end)".to_string(), |t| format!("{t:#010x}"));
    Some(format!(
        "token {at}: ps30 {}, Microsoft {} ({} and {} tokens)",
        show(ours.get(at)),
        show(theirs.get(at)),
        ours.len(),
        theirs.len()
    ))
}

/// ps30's tokens for some source bytes, or its first diagnostic.
pub(super) fn ps30_assemble(name: &str, bytes: Vec<u8>) -> Result<Vec<u32>, String> {
    let options = Options::default();
    let file = load::source_file(name, bytes, &options).map_err(|e| e.to_string())?;
    match load::assemble(file, &options) {
        Ok((_, tokens)) => Ok(tokens),
        Err(e) => Err(e
            .diagnostics
            .items
            .first()
            .map_or("refused without a message".into(), |d| {
                format!("refused: {}", d.message)
            })),
    }
}

/// Microsoft's listing as text: the blob ends with a NUL, which is no part
/// of the listing (D3DAssemble reads up to it).
fn listing_bytes(dis: &str) -> Vec<u8> {
    dis.trim_end_matches('\0').as_bytes().to_vec()
}

/// Fails with every problem found, grouped under `what`.
fn report(what: &str, checked: usize, problems: Vec<String>) {
    assert!(checked > 0, "{what}: no accepted fixture to check");
    assert!(
        problems.is_empty(),
        "{what}: {} of {checked} fixtures fail:\n{}",
        problems.len(),
        problems.join("\n")
    );
}

fn accepted(set: &'static str) -> Vec<Fixture> {
    fixtures(set).into_iter().filter(|f| f.accepted()).collect()
}

#[test]
fn asm_bytecode_is_microsofts() {
    let all = accepted("asm");
    let mut problems = Vec::new();
    for f in &all {
        let Some(fxo) = &f.fxo else {
            problems.push(format!("{}: accepted but no .fxo fixture", f.name()));
            continue;
        };
        match ps30_assemble(&f.rel, f.source.clone()) {
            Ok(ours) => {
                if let Some(d) = first_difference(&ours, &tokens(fxo)) {
                    problems.push(format!("{}: {d}", f.name()));
                }
            }
            // A known gap is refused (tests/oracle.rs says why).
            Err(_) if known_gap(&f.name()) => {}
            Err(e) => problems.push(format!("{}: {e}", f.name())),
        }
    }
    report("ps30 asm against D3DAssemble", all.len(), problems);
}

#[test]
fn bytecode_reader_reads_microsofts() {
    let all: Vec<Fixture> = all().into_iter().filter(|f| f.accepted()).collect();
    let mut problems = Vec::new();
    for f in &all {
        let fxo = f.fxo.as_deref().unwrap_or_default();
        if let Err(e) = read::read(fxo, u64::MAX) {
            problems.push(format!("{}: {e}", f.name()));
        }
    }
    report(
        "the bytecode reader on Microsoft's bytecode",
        all.len(),
        problems,
    );
}

/// The accepted fixtures whose listing Microsoft's own assembler reads back
/// (D3DDisassemble writes `breakp p0.x` as `break p0.`, which no assembler
/// reads: such a listing is no round trip for either tool), and the number
/// of the others.
fn with_readable_listing() -> (Vec<Fixture>, usize) {
    let (ok, not): (Vec<Fixture>, Vec<Fixture>) = all()
        .into_iter()
        .filter(|f| f.accepted())
        .partition(|f| !matches!(f.redis, Some((rc, _)) if rc != 0));
    (ok, not.len())
}

#[test]
fn microsofts_listing_assembles_to_its_tokens_in_ps30() {
    let (all, _) = with_readable_listing();
    let mut problems = Vec::new();
    for f in &all {
        let (Some(fxo), Some(dis)) = (&f.fxo, &f.dis) else {
            problems.push(format!(
                "{}: accepted but no .fxo or .dis fixture",
                f.name()
            ));
            continue;
        };
        let name = format!("{}.dis", f.rel);
        // The same listing in both assemblers gives the same tokens (and,
        // the test below shows, the original's, NaN payloads aside).
        let back = match &f.redis {
            Some((_, Some(back))) => back,
            _ => fxo,
        };
        match ps30_assemble(&name, listing_bytes(dis)) {
            Ok(ours) => {
                let theirs = instruction_tokens(&tokens(back));
                if let Some(d) = first_difference(&instruction_tokens(&ours), &theirs) {
                    problems.push(format!("{}: {d}", f.name()));
                }
            }
            Err(e) => problems.push(format!("{}: the listing: {e}", f.name())),
        }
    }
    report("ps30 asm of D3DDisassemble's listing", all.len(), problems);
}

#[test]
fn microsofts_listing_assembles_to_its_tokens_in_microsofts_assembler() {
    let (all, unreadable) = with_readable_listing();
    let mut problems = Vec::new();
    for f in &all {
        let fxo = f.fxo.as_deref().unwrap_or_default();
        match &f.redis {
            Some((_, Some(back))) => {
                let theirs = instruction_tokens(&tokens(fxo));
                let ours = instruction_tokens(&tokens(back));
                if let Some(d) = first_difference(&ours, &theirs) {
                    if !only_nan_payloads_differ(&ours, &theirs) {
                        problems.push(format!("{}: {d}", f.name()));
                    }
                }
            }
            Some((_, None)) => problems.push(format!("{}: no .dis.fxo fixture", f.name())),
            None => problems.push(format!("{}: no .dis.rc fixture", f.name())),
        }
    }
    // The listings Microsoft cannot read back are few and known; a new kind
    // would show here first.
    assert!(
        unreadable <= all.len() / 100,
        "{unreadable} listings D3DAssemble refuses: more than the known `breakp` ones"
    );
    report(
        "D3DAssemble of D3DDisassemble's listing",
        all.len(),
        problems,
    );
}

#[test]
fn fixtures_hold_one_answer_each() {
    // What the harness writes: bytecode, listing and round trip for an
    // accepted file; an error and nothing else for a refused one, with its
    // X#### code unless the shader stopped itself (`#error` has none).
    // Anything else is a fixture not written by the harness.
    let all = all();
    let mut problems = Vec::new();
    for f in &all {
        let complete = f.fxo.is_some() && f.dis.is_some() && f.redis.is_some();
        if f.accepted() && !complete {
            problems.push(format!(
                "{}: accepted, but .fxo, .dis or .dis.rc is missing",
                f.name()
            ));
        }
        let own_error = f.err.as_deref().is_some_and(|e| e.contains("): error: "));
        if !f.accepted() && (f.fxo.is_some() || (f.error_code().is_none() && !own_error)) {
            problems.push(format!(
                "{}: refused, but with bytecode or without an error",
                f.name()
            ));
        }
    }
    report("the fixtures' shape", all.len(), problems);
}

#[test]
fn instruction_tokens_skip_comments_and_keep_operands() {
    // A comment of two tokens, then `def c0, ...` whose literal looks like a
    // comment token: it stays, as an operand.
    let stream = [
        0xFFFF_0300,
        0x0002_FFFE,
        1,
        2,
        0x0500_0051,
        0xA00F_0000,
        0x0001_FFFE,
        0,
        0,
        0,
        0x0000_FFFF,
    ];
    assert_eq!(
        instruction_tokens(&stream),
        [
            0xFFFF_0300,
            0x0500_0051,
            0xA00F_0000,
            0x0001_FFFE,
            0,
            0,
            0,
            0x0000_FFFF
        ]
    );
    assert_eq!(first_difference(&[1, 2], &[1, 2]), None);
    assert!(first_difference(&[1, 2], &[1, 3])
        .unwrap()
        .starts_with("token 1:"));
    assert!(first_difference(&[1], &[1, 3]).unwrap().contains("(end)"));
}
