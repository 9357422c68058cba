//! Oracle fixtures: ps_1_1–ps_1_4 (`corpus/asm/profiles/ps_1_*`, written by
//! `tools/oracle/ps1_probes.py`). `parity` holds ps30's acceptance, bytes,
//! listing and slot count to Microsoft's on these probes; here, what only
//! ps_1_x needs besides: which instruction exists in which version (the
//! instruction table's column against Microsoft's grammar, which refuses an
//! instruction a version lacks as a syntax error, X2000), and that the
//! listing reads back — ps30 assembling `D3DDisassemble`'s text writes the
//! bytes Microsoft assembled from the source.

use super::*;
use ps30::core::isa::Opcode;
use ps30::core::load::{self, Options};
use ps30::core::profile::Profile;

const PS1: [Profile; 4] = [
    Profile::Ps1_1,
    Profile::Ps1_2,
    Profile::Ps1_3,
    Profile::Ps1_4,
];

#[test]
fn each_ps_1_x_instruction_exists_where_microsofts_grammar_has_it() {
    let mut wrong = Vec::new();
    let mut seen = 0;
    for p in PS1 {
        for f in profile_fixtures(p.name()) {
            // op-NAME.psh, NAME a mnemonic alone (op-texld-dz and the like
            // probe a form, not the instruction).
            let Some(name) = f
                .rel
                .rsplit('/')
                .next()
                .and_then(|n| n.strip_prefix("op-"))
                .and_then(|n| n.strip_suffix(".psh"))
            else {
                continue;
            };
            let Some(op) = Opcode::from_mnemonic_in(name, false, p) else {
                continue;
            };
            seen += 1;
            let table = op.profiles().has(p);
            let microsoft = f.error_code().as_deref() != Some("X2000");
            if table != microsoft {
                wrong.push(format!(
                    "{}: the table says {}, Microsoft {:?}",
                    f.name(),
                    if table { "available" } else { "absent" },
                    f.error_code()
                ));
            }
        }
    }
    assert!(seen >= 80, "only {seen} instruction probes");
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

#[test]
fn ps30_reads_microsofts_ps_1_x_listing_back_to_microsofts_bytes() {
    let mut wrong = Vec::new();
    let mut seen = 0;
    for p in PS1 {
        for f in profile_fixtures(p.name()) {
            let (Some(fxo), Some(dis)) = (&f.fxo, &f.dis) else {
                continue;
            };
            seen += 1;
            let text = dis.trim_end_matches('\0');
            let options = Options::default();
            let got = load::source_file("listing", text.as_bytes().to_vec(), &options)
                .map_err(|e| e.to_string())
                .and_then(|file| {
                    load::assemble(file, &options).map_err(|e| {
                        e.diagnostics
                            .items
                            .first()
                            .map_or(String::new(), |d| d.message.clone())
                    })
                });
            let want = bytes_of(fxo);
            match got {
                Ok(tokens) if tokens.1 == want => {}
                Ok(tokens) => wrong.push(format!("{}: {:08x?}", f.name(), tokens.1)),
                Err(e) => wrong.push(format!("{}: refused: {e}", f.name())),
            }
        }
    }
    assert!(seen >= 200, "only {seen} accepted ps_1_x probes");
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

fn bytes_of(fxo: &[u8]) -> Vec<u32> {
    fxo.chunks_exact(4)
        .map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]))
        .collect()
}
