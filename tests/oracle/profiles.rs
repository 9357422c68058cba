//! Oracle fixtures: the shader profiles besides ps_3_0 (see `tests/oracle.rs`
//! and `tools/oracle/profile_probes.py`, which writes
//! `corpus/asm/profiles/<profile>/`).
//!
//! ps30 does not check these profiles yet; what it holds about them is held
//! here to Microsoft's assembler: which profiles a version line names
//! ([`Profile::assembles`]) and the token each writes, which instructions
//! exist in which profile (the instruction table's availability column), what
//! each costs there (Microsoft's count, the same column as ps_3_0's), the
//! register files' edges and the slot limits. Each test gathers every
//! disagreement and fails once, listing them all.

use super::slots::listing_count;
use super::*;
use ps30::core::isa::{Opcode, SlotCount};
use ps30::core::profile::{Profile, Stage};

/// The profiles Microsoft's assembler reads as a version line, each with its
/// probes.
const ASSEMBLED: [Profile; 6] = [
    Profile::Ps2_0,
    Profile::Ps2X,
    Profile::Ps3_0,
    Profile::Vs2_0,
    Profile::Vs2X,
    Profile::Vs3_0,
];

/// The instructions a probe's line uses, with whether it is predicated:
/// `None` for a mnemonic no row of the table has (the vertex-only `mova`,
/// `lit`, `dst`, `expp`, `logp`, `slt`, `sge`, `sgn`, which come with
/// vertex shaders).
fn opcode_of(line: &str) -> Option<(Option<Opcode>, bool)> {
    let (predicated, line) = match line.strip_prefix("(p0) ") {
        Some(rest) => (true, rest),
        None => (false, line),
    };
    let word = line.split_whitespace().next()?;
    let (base, suffix) = word.split_once('_').unwrap_or((word, ""));
    if matches!(word, "dcl" | "def") || word.starts_with("dcl_") {
        return None;
    }
    let compare = matches!(suffix, "gt" | "lt" | "ge" | "le" | "eq" | "ne");
    Some((Opcode::from_mnemonic(base, compare), predicated))
}

/// Whether the table says `profile` has every instruction of `body` in the
/// form written, and Microsoft's count of the body's slots there; `None`
/// when the body uses an instruction the table has no row for.
fn expected(profile: Profile, body: &[&str]) -> Option<(bool, SlotCount)> {
    let regs = profile.registers();
    let mut ok = true;
    let mut count = SlotCount::default();
    for line in body {
        let Some((op, predicated)) = opcode_of(line) else {
            continue;
        };
        let op = op?;
        ok &= op.profiles().has(profile);
        // p0 exists only where predication does; sincos has three sources
        // before the 3_0 profiles and one in them.
        ok &= !line.contains("p0") || regs.predicate;
        if op == Opcode::SinCos {
            let three = line.matches(',').count() == 3;
            let is3 = matches!(profile, Profile::Ps3_0 | Profile::Vs3_0);
            ok &= three != is3;
        }
        let (t, a) = op.info().fxc_split_of(predicated);
        count = count.plus(SlotCount {
            texture: t,
            arithmetic: a,
        });
    }
    Some((ok, count))
}

/// The lines of a probe that its profile's baseline does not have.
fn extra_lines<'a>(probe: &'a str, base: &str) -> Vec<&'a str> {
    let base: Vec<&str> = base.lines().collect();
    probe.lines().filter(|l| !base.contains(l)).collect()
}

#[test]
fn instruction_availability_and_slots_are_microsofts_in_every_profile() {
    let mut wrong = Vec::new();
    let mut seen = 0;
    for profile in ASSEMBLED {
        let all = profile_fixtures(profile.name());
        let base = all
            .iter()
            .find(|f| f.rel.ends_with("/base.psh"))
            .unwrap_or_else(|| panic!("{profile}: no base probe"));
        let (_, base_count) = listing_count(base.dis.as_deref().unwrap_or_default())
            .unwrap_or_else(|| panic!("{profile}: the base probe has no slot line"));
        let base_text = String::from_utf8_lossy(&base.source).into_owned();
        for f in all.iter().filter(|f| f.rel.contains("/op-")) {
            seen += 1;
            let text = String::from_utf8_lossy(&f.source).into_owned();
            let body = extra_lines(&text, &base_text);
            let Some((ok, count)) = expected(profile, &body) else {
                wrong.push(format!(
                    "{}: no row, and Microsoft says {:?}",
                    f.name(),
                    f.error_code()
                ));
                continue;
            };
            // `sgn` exists in every vertex profile; these probes write it
            // with operands Microsoft refuses by a rule of the instruction
            // (X5470, X5797), which the validator holds (oracle::parity).
            let sgn_rule = matches!(f.error_code().as_deref(), Some("X5470" | "X5797"));
            if ok && sgn_rule {
                continue;
            }
            if ok != f.accepted() {
                wrong.push(format!(
                    "{}: the table says {}, Microsoft {} it ({:?})",
                    f.name(),
                    if ok { "available" } else { "absent" },
                    if f.accepted() { "accepts" } else { "refuses" },
                    f.error_code()
                ));
                continue;
            }
            let Some((line, theirs)) = f.dis.as_deref().and_then(listing_count) else {
                continue;
            };
            let ours = base_count.plus(count);
            if ours != theirs {
                wrong.push(format!(
                    "{}: the table counts {ours:?}, Microsoft `{line}`",
                    f.name()
                ));
            }
        }
    }
    assert!(seen > 300, "only {seen} instruction probes");
    assert!(
        wrong.is_empty(),
        "{} of {seen} instruction probes disagree with D3DAssemble:\n{}",
        wrong.len(),
        wrong.join("\n")
    );
}

#[test]
fn version_lines_and_tokens_are_microsofts() {
    let mut wrong = Vec::new();
    for profile in Profile::ALL {
        let probes = profile_fixtures(profile.name());
        let Some(base) = probes.iter().find(|f| f.rel.ends_with("/base.psh")) else {
            wrong.push(format!("{profile}: no base probe"));
            continue;
        };
        if base.accepted() != profile.assembles() {
            wrong.push(format!("{}: assembles {}", base.name(), base.accepted()));
        }
        if !base.accepted() && base.error_code().as_deref() != Some("X2001") {
            wrong.push(format!(
                "{}: refused with {:?}",
                base.name(),
                base.error_code()
            ));
        }
        if let Some(fxo) = &base.fxo {
            let token = u32::from_le_bytes([fxo[0], fxo[1], fxo[2], fxo[3]]);
            if token != profile.version_token() || Profile::from_token(token) != Some(profile) {
                wrong.push(format!("{}: version token {token:#010x}", base.name()));
            }
            let first = base
                .dis
                .as_deref()
                .and_then(|d| d.split_whitespace().next());
            if first != Some(profile.name()) {
                wrong.push(format!("{}: listed as {first:?}", base.name()));
            }
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

/// `reg-<file><n>.psh`: the file's letters and the index.
fn register_probe(rel: &str) -> Option<(String, u32)> {
    let name = rel
        .rsplit('/')
        .next()?
        .strip_prefix("reg-")?
        .strip_suffix(".psh")?;
    let digits = name.find(|c: char| c.is_ascii_digit())?;
    Some((name[..digits].to_string(), name[digits..].parse().ok()?))
}

#[test]
fn register_files_end_where_microsofts_do() {
    let mut wrong = Vec::new();
    let mut seen = 0;
    for profile in ASSEMBLED {
        let regs = profile.registers();
        for f in profile_fixtures(profile.name()) {
            let Some((file, n)) = register_probe(&f.rel) else {
                continue;
            };
            seen += 1;
            let count = match file.as_str() {
                "r" => regs.temps,
                "t" => regs.texcoords,
                "v" => regs.inputs,
                "s" => regs.samplers,
                "oC" => regs.colour_outputs,
                // vertex shaders take any c# index (c256 accepted); pixel
                // shaders stop at their count
                "c" if profile.stage() == Stage::Vertex => u32::MAX,
                "c" => regs.float_consts,
                other => panic!("{}: no file {other}", f.name()),
            };
            // A refusal for another reason than the index (ps_2_0 writing
            // oC3 without oC0..oC2, X5573) is no register-file edge.
            let index_refused = !f.accepted() && f.error_code().as_deref() == Some("X2005");
            if (n >= count) != index_refused {
                wrong.push(format!(
                    "{}: {profile} has {count} {file}#, Microsoft {} it ({:?})",
                    f.name(),
                    if f.accepted() { "accepts" } else { "refuses" },
                    f.error_code()
                ));
            }
        }
    }
    assert!(seen >= 30, "only {seen} register probes");
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

#[test]
fn slot_limits_are_microsofts() {
    let mut wrong = Vec::new();
    let mut seen = 0;
    for profile in ASSEMBLED {
        let limits = profile.limits();
        for f in profile_fixtures(profile.name()) {
            let Some(rest) = f
                .rel
                .rsplit('/')
                .next()
                .and_then(|n| n.strip_prefix("limit-"))
            else {
                continue;
            };
            seen += 1;
            let (what, n) = rest.trim_end_matches(".psh").rsplit_once('-').unwrap();
            let n: u32 = n.parse().unwrap();
            let (limit, code) = match what {
                "arith" => (limits.arithmetic, "X5234"),
                "tex" => (limits.texture, "X5607"),
                "dependent" => (limits.dependent_reads, "X5775"),
                "slots" => (limits.slots, "X5755"),
                other => panic!("{}: no limit {other}", f.name()),
            };
            let over = limit.is_some_and(|l| n > l);
            let theirs = f.error_code();
            if over == f.accepted() || (over && theirs.as_deref() != Some(code)) {
                wrong.push(format!(
                    "{}: limit {limit:?}, Microsoft {} ({theirs:?})",
                    f.name(),
                    if f.accepted() { "accepts" } else { "refuses" }
                ));
            }
        }
    }
    assert!(seen >= 20, "only {seen} limit probes");
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

/// The instructions of a `D3DDisassemble` listing: each line's mnemonic
/// without its modifiers and comparison (`if_gt` is `ifc`), declarations
/// and definitions left out, with the line for messages.
fn listed_instructions(dis: &str) -> Vec<(String, Option<Opcode>)> {
    let mut out = Vec::new();
    let trim = |l: &str| {
        l.trim_matches(|c: char| c.is_whitespace() || c == '\0')
            .to_string()
    };
    for line in dis
        .lines()
        .map(trim)
        .skip_while(|l| l.starts_with("//") || l.is_empty())
        .skip(1)
    {
        if line.is_empty() || line.starts_with("//") {
            continue;
        }
        let line = line
            .strip_prefix("(p0) ")
            .or_else(|| line.strip_prefix("(!p0) "))
            .unwrap_or(&line);
        let word = line.split_whitespace().next().unwrap_or_default();
        let mut parts = word.split('_');
        let base = parts.next().unwrap_or_default();
        if matches!(base, "dcl" | "def" | "defi" | "defb") {
            continue;
        }
        let compare = parts.any(|p| matches!(p, "gt" | "lt" | "ge" | "le" | "eq" | "ne"));
        out.push((base.to_string(), Opcode::from_mnemonic(base, compare)));
    }
    out
}

#[test]
fn shaders_compiled_for_each_target_use_its_instructions_and_version() {
    let mut wrong = Vec::new();
    let mut compiled = 0;
    let all = target_fixtures();
    for (target, f) in &all {
        let profile = Profile::from_name(target).unwrap_or_else(|| panic!("{}: target", f.name()));
        let (Some(fxo), Some(dis)) = (&f.fxo, &f.dis) else {
            continue;
        };
        compiled += 1;
        let token = u32::from_le_bytes([fxo[0], fxo[1], fxo[2], fxo[3]]);
        if token != profile.version_token() {
            wrong.push(format!("{}: version token {token:#010x}", f.name()));
        }
        for (name, op) in listed_instructions(dis) {
            let known = op.is_some_and(|op| op.profiles().has(profile));
            if !known {
                wrong.push(format!(
                    "{}: `{name}` is not a {profile} instruction in the table",
                    f.name()
                ));
            }
        }
    }
    assert!(compiled >= 30, "only {compiled} of {} compiled", all.len());
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

#[test]
fn the_hlsl_compiler_refuses_ps_2_0_code_past_its_limits() {
    // X5608: "Compiled shader code uses too many arithmetic instruction
    // slots (325). Max. allowed by the target (ps_2_0) is 64."; five levels
    // of dependent reads are X5426 for ps_2_0 and X4018 for ps_2_b.
    let want = [
        ("long", "ps_2_0", "X5608"),
        ("dependent5", "ps_2_0", "X5426"),
        ("dependent5", "ps_2_b", "X4018"),
    ];
    let all = target_fixtures();
    for (name, target, code) in want {
        let rel = format!("gen_profiles/{name}__{target}.hlsl");
        let (_, f) = all
            .iter()
            .find(|(_, f)| f.rel == rel)
            .unwrap_or_else(|| panic!("{rel}"));
        assert_eq!(f.error_code().as_deref(), Some(code), "{rel}");
    }
    let p = Profile::Ps2_0.limits();
    assert_eq!(p.arithmetic, Some(64));
    assert_eq!(Profile::Ps2B.limits().dependent_reads, Some(4));
    assert_eq!(Profile::Ps2A.limits().dependent_reads, None);
    let a = all
        .iter()
        .find(|(_, f)| f.rel == "gen_profiles/dependent5__ps_2_a.hlsl");
    assert!(
        a.is_some_and(|(_, f)| f.accepted()),
        "ps_2_a reads five levels deep"
    );
}
