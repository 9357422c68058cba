//! Oracle fixtures: listing text (see `tests/oracle.rs`). For every file
//! Microsoft accepted, `ps30 disasm` of its bytecode (the default listing)
//! is the text `D3DDisassemble` wrote for it, byte for byte.
//!
//! `D3DDisassemble` returns the listing as a C string: the blob (`REL.dis`)
//! ends with one NUL byte after the last line's newline. That byte ends the
//! string; it is not text, and ps30's listing stops before it. The test
//! checks that the blob ends so and compares everything before it.

use super::*;

/// Items `read` may expand to: far more than any fixture holds.
const MAX_ITEMS: u64 = 1 << 20;

/// ps30's default listing of `fxo`, or why there is none.
pub(super) fn ps30_listing(fxo: &[u8]) -> Result<String, String> {
    ps30::core::load::microsoft_listing(fxo, MAX_ITEMS).map_err(|e| {
        format!(
            "ps30 does not read the bytecode: {} at {}",
            e.message,
            e.place()
        )
    })
}

/// The first line where two texts differ: its number and both versions.
pub(super) fn first_difference(ours: &str, theirs: &str) -> String {
    let (a, b): (Vec<&str>, Vec<&str>) = (ours.split('\n').collect(), theirs.split('\n').collect());
    let n = a.len().max(b.len());
    (0..n)
        .find(|&i| a.get(i) != b.get(i))
        .map(|i| {
            let line = |v: &[&str]| {
                v.get(i)
                    .map_or("<end of text>".to_string(), |l| format!("{l:?}"))
            };
            format!("line {}: ps30 {} | Microsoft {}", i + 1, line(&a), line(&b))
        })
        .unwrap_or_else(|| "no line differs".to_string())
}

#[test]
fn default_disasm_is_microsofts_listing_byte_for_byte() {
    let mut failures = Vec::new();
    let mut checked = 0;
    for f in all() {
        let (Some(fxo), Some(dis)) = (&f.fxo, &f.dis) else {
            continue;
        };
        checked += 1;
        let Some(text) = dis.strip_suffix('\0') else {
            failures.push(format!(
                "{}: the .dis does not end with a NUL byte",
                f.name()
            ));
            continue;
        };
        match ps30_listing(fxo) {
            Ok(ours) if ours == text => {}
            Ok(ours) => failures.push(format!("{}: {}", f.name(), first_difference(&ours, text))),
            Err(why) => failures.push(format!("{}: {why}", f.name())),
        }
    }
    if root().join("corpus").is_dir() {
        assert!(
            checked > 0,
            "no fixture has a listing: run tools/oracle/regen"
        );
    }
    assert!(
        failures.is_empty(),
        "{} of {checked} listings differ from D3DDisassemble's:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

#[test]
fn the_command_prints_the_library_listing_and_nothing_after_it() {
    // The CLI's default output is the library's text as is: no NUL, no
    // extra newline, so the comparison above is what users see.
    let Some(f) = all()
        .into_iter()
        .find(|f| f.fxo.is_some() && f.dis.is_some())
    else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("a.fxo");
    std::fs::write(&path, f.fxo.as_ref().unwrap()).unwrap();
    let o = crate::common::bin::ps30(&["disasm", path.to_str().unwrap()], dir.path());
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let expected = f.dis.as_deref().unwrap().strip_suffix('\0').unwrap();
    assert_eq!(String::from_utf8_lossy(&o.stdout), expected, "{}", f.name());
}
