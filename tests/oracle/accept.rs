//! Acceptance parity with Microsoft's assembler: ps30 accepts an assembly
//! file exactly when `D3DAssemble` does, and when both refuse it, ps30's
//! first error carries the code of Microsoft's first error. Every
//! shader Microsoft's HLSL compiler wrote loads, as bytecode and as
//! `D3DDisassemble`'s listing of it.
//!
//! Each test gathers every disagreement and fails once, listing them all:
//! one wrong rule shows as the set of probes it breaks.

use super::{fixtures, known_gap, Fixture, KNOWN_GAPS};
use ps30::core::load::{self, Options};

/// ps30's verdict on a file's bytes: accepted, or refused with the code of
/// its first error (by position; `None` when that error has no code).
fn verdict(name: &str, bytes: &[u8]) -> Result<(), Option<String>> {
    let options = Options::default();
    let file = load::source_file(name, bytes.to_vec(), &options)
        .map_err(|e| e.code().map(String::from))?;
    match load::assemble(file, &options) {
        Ok(_) => Ok(()),
        Err(e) => Err(e
            .diagnostics
            .errors()
            .next()
            .and_then(|d| d.code)
            .map(String::from)),
    }
}

/// How ps30 and Microsoft differ on one fixture, if they do.
pub(super) fn disagreement(f: &Fixture) -> Option<String> {
    let ours = verdict(&f.name(), &f.source);
    let theirs = f.error_code();
    match (f.accepted(), ours) {
        (true, Ok(())) => None,
        (true, Err(code)) => Some(format!(
            "{}: Microsoft accepts it, ps30 refuses it ({})",
            f.name(),
            code.as_deref().unwrap_or("no code")
        )),
        (false, Ok(())) => Some(format!(
            "{}: Microsoft refuses it ({}), ps30 accepts it",
            f.name(),
            theirs.as_deref().unwrap_or("no code")
        )),
        (false, Err(code)) if code == theirs => None,
        (false, Err(code)) => Some(format!(
            "{}: both refuse it, Microsoft with {}, ps30 with {}",
            f.name(),
            theirs.as_deref().unwrap_or("no code"),
            code.as_deref().unwrap_or("no code")
        )),
    }
}

#[test]
fn assembly_is_accepted_and_refused_as_microsoft_does_with_its_codes() {
    let all = fixtures("asm");
    let refused = all.iter().filter(|f| !f.accepted()).count();
    assert!(
        refused > 0 && refused < all.len(),
        "the probes hold both accepted and refused files"
    );
    let (known, wrong): (Vec<String>, Vec<String>) = all
        .iter()
        .filter_map(disagreement)
        .partition(|w| known_gap(w.split(':').next().unwrap_or_default()));
    // Each known gap still disagrees: a fix must take it off the list.
    assert_eq!(
        known.len(),
        KNOWN_GAPS.len(),
        "a known gap now agrees (remove it from KNOWN_GAPS): {known:?}"
    );
    assert!(
        wrong.is_empty(),
        "{} of {} assembly fixtures disagree with D3DAssemble:\n{}",
        wrong.len(),
        all.len(),
        wrong.join("\n")
    );
}

#[test]
fn microsoft_compiled_shaders_load_as_bytecode_and_as_listings() {
    let mut wrong = Vec::new();
    let mut seen = 0;
    for f in fixtures("hlsl") {
        let Some(fxo) = &f.fxo else { continue };
        seen += 1;
        if let Err(code) = verdict(&format!("{}.fxo", f.name()), fxo) {
            wrong.push(format!("{}.fxo: refused ({code:?})", f.name()));
        }
        if let Some(dis) = &f.dis {
            if let Err(code) = verdict(&format!("{}.dis", f.name()), dis.as_bytes()) {
                wrong.push(format!("{}.dis: refused ({code:?})", f.name()));
            }
        }
    }
    assert!(seen > 0, "no compiled shader among the hlsl fixtures");
    assert!(
        wrong.is_empty(),
        "{} of {seen} compiled shaders do not load:\n{}",
        wrong.len(),
        wrong.join("\n")
    );
}
