//! Oracle fixtures: slot counts (see `tests/oracle.rs`).
//!
//! For every fixture with a listing, the count `ps30 check` reports under
//! Microsoft's table ([`SlotTable::Fxc`]), with its texture/arithmetic split,
//! must be the one in the listing's `// approximately N instruction slots used
//! (T texture, A arithmetic)` line — for the bytecode Microsoft wrote (the
//! `.fxo`) and, for assembly probes, for the source ps30 reads itself. The
//! line ps30 would print for that count must be Microsoft's line, word for
//! word ("slot" for one, the split only with a texture slot). One assertion
//! lists every mismatch.

use super::*;
use ps30::core::isa::{SlotCount, SlotTable};
use ps30::core::load::{self, Options};

/// The slot line of a `D3DDisassemble` listing and the count it states.
pub(super) fn listing_count(dis: &str) -> Option<(String, SlotCount)> {
    let line = dis
        .lines()
        .map(str::trim_end)
        .find(|l| l.starts_with("// approximately "))?;
    let rest = &line["// approximately ".len()..];
    let (n, rest) = rest.split_once(' ')?;
    let total: u32 = n.parse().ok()?;
    let texture = match rest.split_once('(') {
        Some((_, split)) => split.split_once(" texture")?.0.parse().ok()?,
        None => 0,
    };
    let arithmetic = match rest.split_once(", ") {
        Some((_, a)) => a.split_once(" arithmetic")?.0.parse().ok()?,
        None => total.checked_sub(texture)?,
    };
    (texture + arithmetic == total).then(|| {
        (
            line.to_string(),
            SlotCount {
                texture,
                arithmetic,
            },
        )
    })
}

/// ps30's count under Microsoft's table of a shader given as bytes
/// (bytecode or text), loaded as `ps30 check` loads it.
pub(super) fn ps30_count(name: &str, bytes: &[u8]) -> Result<SlotCount, String> {
    let options = Options::default();
    let file = load::source_file(name, bytes.to_vec(), &options).map_err(|e| e.to_string())?;
    let loaded = load::load(file, &options).map_err(|e| {
        let first = e.diagnostics.errors().next().map(|d| d.message.clone());
        format!("ps30 refuses it ({})", first.unwrap_or_default())
    })?;
    Ok(loaded.shader.info().total(SlotTable::Fxc))
}

/// Compares one input's count with the listing's, adding what differs.
fn compare(
    what: &str,
    got: Result<SlotCount, String>,
    want: &(String, SlotCount),
    out: &mut Vec<String>,
) {
    match got {
        Ok(c) if c == want.1 && c.listing_line() == want.0 => {}
        Ok(c) => out.push(format!(
            "{what}: ps30 {} total ({} texture, {} arithmetic) as `{}`; Microsoft `{}`",
            c.total(),
            c.texture,
            c.arithmetic,
            c.listing_line(),
            want.0
        )),
        Err(e) => out.push(format!("{what}: {e}")),
    }
}

#[test]
fn the_microsoft_count_is_the_listings_slot_line() {
    let mut mismatches = Vec::new();
    let mut compared = 0;
    for f in all() {
        let (true, Some(dis), Some(fxo)) = (f.accepted(), &f.dis, &f.fxo) else {
            continue;
        };
        let Some(want) = listing_count(dis) else {
            mismatches.push(format!("{}: the listing has no slot line", f.name()));
            continue;
        };
        compared += 1;
        let name = f.name();
        compare(
            &format!("{name} (bytecode)"),
            ps30_count(&format!("{name}.fxo"), fxo),
            &want,
            &mut mismatches,
        );
        // A known gap's source is refused by ps30 (tests/oracle.rs says why).
        if f.set == "asm" && !known_gap(&name) {
            compare(
                &format!("{name} (source)"),
                ps30_count(&name, &f.source),
                &want,
                &mut mismatches,
            );
        }
    }
    assert!(
        mismatches.is_empty(),
        "{} of {compared} listings' slot counts differ from ps30's:\n{}",
        mismatches.len(),
        mismatches.join("\n")
    );
}

#[test]
fn the_slot_line_reader_reads_every_form() {
    let one = "    mov oC0, c0\n\n// approximately 1 instruction slot used\n \n";
    assert_eq!(
        listing_count(one).map(|c| c.1),
        Some(SlotCount {
            texture: 0,
            arithmetic: 1
        })
    );
    let split = "// approximately 70 instruction slots used (18 texture, 52 arithmetic)";
    let (line, count) = listing_count(split).unwrap();
    assert_eq!((count.texture, count.arithmetic), (18, 52));
    assert_eq!(count.listing_line(), line);
    assert_eq!(listing_count("ps_3_0\nmov oC0, c0\n"), None);
    assert_eq!(
        listing_count("// approximately 3 instruction slots used (1 texture, 1 arithmetic)"),
        None
    );
}
