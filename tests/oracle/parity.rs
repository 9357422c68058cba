//! Microsoft parity for every profile ps30 reads besides ps_3_0 (ps_1_1–
//! ps_1_4, ps_2_0, ps_2_x, vs_2_0, vs_2_x, vs_3_0): the same four measures the ps_3_0
//! tests hold — acceptance with Microsoft's first code, the bytes ps30
//! writes, the listing of Microsoft's bytecode, the slot count with its
//! texture/arithmetic split — on the per-profile probes
//! (`asm/profiles/<profile>/`) and on the shaders Microsoft's HLSL compiler
//! wrote for each target (`hlsl/gen_profiles/NAME__<target>.hlsl`).
//!
//! Every disagreement left is listed in [`GAPS`] with its cause; the test
//! fails when a listed one agrees (take it off) or an unlisted one appears,
//! and prints the agreement per profile and measure.

use super::*;
use std::collections::BTreeMap;

/// The profiles measured here (ps_3_0 is the other oracle tests').
const PROFILES: [&str; 9] = [
    "ps_1_1", "ps_1_2", "ps_1_3", "ps_1_4", "ps_2_0", "ps_2_x", "vs_2_0", "vs_2_x", "vs_3_0",
];

/// Known disagreements: (`measure:SET/REL`, cause).
const GAPS: &[(&str, &str)] = &[];

/// One measure's result on one input.
struct Outcome {
    /// `accept`, `bytes`, `listing` or `slots`.
    measure: &'static str,
    /// The profile or HLSL target it counts under.
    profile: String,
    /// `SET/REL` of the fixture.
    name: String,
    /// What differs, if anything.
    differs: Option<String>,
}

fn listing_of(fxo: &[u8], dis: &str) -> Option<String> {
    let text = dis.strip_suffix('\0').unwrap_or(dis);
    match listing::ps30_listing(fxo) {
        Ok(ours) if ours == text => None,
        Ok(ours) => Some(listing::first_difference(&ours, text)),
        Err(why) => Some(why),
    }
}

fn slots_of(name: &str, bytes: &[u8], dis: &str) -> Option<String> {
    let Some(want) = slots::listing_count(dis) else {
        return Some("Microsoft's listing has no slot line".into());
    };
    match slots::ps30_count(name, bytes) {
        Ok(c) if c == want.1 && c.listing_line() == want.0 => None,
        Ok(c) => Some(format!(
            "ps30 `{}`, Microsoft `{}`",
            c.listing_line(),
            want.0
        )),
        Err(e) => Some(e),
    }
}

/// The four measures on one assembly probe of `profile`.
fn probe_outcomes(profile: &str, f: &Fixture, out: &mut Vec<Outcome>) {
    let mut push = |measure, differs| {
        out.push(Outcome {
            measure,
            profile: profile.to_string(),
            name: f.name(),
            differs,
        })
    };
    push("accept", accept::disagreement(f));
    if !f.accepted() {
        return;
    }
    if let Some(fxo) = &f.fxo {
        let bytes = match bytes::ps30_assemble(&f.rel, f.source.clone()) {
            Ok(ours) => bytes::first_difference(&ours, &bytes::tokens(fxo)),
            Err(e) => Some(e),
        };
        push("bytes", bytes);
        if let Some(dis) = &f.dis {
            push("listing", listing_of(fxo, dis));
            push("slots", slots_of(&f.rel, fxo, dis));
        }
    }
}

/// Listing and slots of one HLSL-compiled shader of `target`, and that its
/// bytecode loads.
fn compiled_outcomes(target: &str, f: &Fixture, out: &mut Vec<Outcome>) {
    let (Some(fxo), Some(dis)) = (&f.fxo, &f.dis) else {
        return;
    };
    let mut push = |measure, differs| {
        out.push(Outcome {
            measure,
            profile: format!("{target} (HLSL)"),
            name: f.name(),
            differs,
        })
    };
    push("listing", listing_of(fxo, dis));
    push("slots", slots_of(&format!("{}.fxo", f.name()), fxo, dis));
}

fn outcomes() -> Vec<Outcome> {
    let mut out = Vec::new();
    for p in PROFILES {
        for f in profile_fixtures(p) {
            probe_outcomes(p, &f, &mut out);
        }
    }
    for (target, f) in target_fixtures() {
        compiled_outcomes(&target, &f, &mut out);
    }
    out
}

#[test]
fn every_profile_agrees_with_microsoft_but_its_listed_gaps() {
    let all = outcomes();
    let mut table: BTreeMap<(String, &str), (usize, usize)> = BTreeMap::new();
    let mut unlisted = Vec::new();
    let mut fixed = Vec::new();
    for o in &all {
        let key = format!("{}:{}", o.measure, o.name);
        let listed = GAPS.iter().any(|(k, _)| *k == key);
        let e = table.entry((o.profile.clone(), o.measure)).or_default();
        e.1 += 1;
        match (&o.differs, listed) {
            (None, false) => e.0 += 1,
            (None, true) => fixed.push(key),
            (Some(d), false) => unlisted.push(format!("{key}: {d}")),
            (Some(_), true) => {}
        }
    }
    let summary: Vec<String> = table
        .iter()
        .map(|((p, m), (ok, n))| format!("{p} {m}: {ok} of {n}"))
        .collect();
    println!("{}", summary.join("\n"));
    assert!(all.len() > 500, "the profile fixtures are missing");
    assert!(
        fixed.is_empty(),
        "listed gaps that now agree (take them off GAPS): {fixed:?}"
    );
    assert!(
        unlisted.is_empty(),
        "{} disagreements with Microsoft not in GAPS:\n{}\n\nagreement:\n{}",
        unlisted.len(),
        unlisted.join("\n"),
        summary.join("\n")
    );
}
