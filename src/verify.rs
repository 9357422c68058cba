//! `ps30 verify`: every figure the article states, recomputed by ps30 from
//! the article's own listings (bundled in the binary), side by side.
//!
//! Each claim pairs the article's figure (a literal: it is what the article
//! printed) with the value ps30 computes from the shaders through the front
//! end and the cost model. Nothing here copies an expected value into the
//! computation.

use crate::cost::{self, Analysis, Environment, Profile};
use crate::front::{self, Options};
use serde::Serialize;

/// The article's listings, as transcribed in `asm/article/`.
pub const PASS1_LOOP: (&str, &str) = (
    "asm/article/lum_pass1_loop.psh",
    include_str!("../asm/article/lum_pass1_loop.psh"),
);
pub const PASS1_UNROLLED: (&str, &str) = (
    "asm/article/lum_pass1_unrolled.psh",
    include_str!("../asm/article/lum_pass1_unrolled.psh"),
);
pub const PASS2: (&str, &str) = (
    "asm/article/lum_pass2.psh",
    include_str!("../asm/article/lum_pass2.psh"),
);

/// The corrected listings (`asm/corrected/`), each change explained in its header.
pub const CORRECTED_LOOP: (&str, &str) = (
    "asm/corrected/lum_pass1_loop.psh",
    include_str!("../asm/corrected/lum_pass1_loop.psh"),
);
pub const CORRECTED_UNROLLED: (&str, &str) = (
    "asm/corrected/lum_pass1_unrolled.psh",
    include_str!("../asm/corrected/lum_pass1_unrolled.psh"),
);
pub const CORRECTED_PASS2: (&str, &str) = (
    "asm/corrected/lum_pass2.psh",
    include_str!("../asm/corrected/lum_pass2.psh"),
);

/// Bundled shaders by short name (`article:loop`, `corrected:pass2`, ...).
pub fn bundled(name: &str) -> Option<(&'static str, &'static str)> {
    Some(match name {
        "article:loop" => PASS1_LOOP,
        "article:unrolled" => PASS1_UNROLLED,
        "article:pass2" => PASS2,
        "corrected:loop" => CORRECTED_LOOP,
        "corrected:unrolled" => CORRECTED_UNROLLED,
        "corrected:pass2" => CORRECTED_PASS2,
        _ => return None,
    })
}

/// One stated figure and ps30's value for it.
#[derive(Clone, Debug, Serialize)]
pub struct Claim {
    pub claim: String,
    /// What the article prints.
    pub article: String,
    /// What ps30 computes.
    pub ps30: String,
    pub agrees: bool,
    /// How ps30 got its number.
    pub how: String,
}

fn claim(
    claim: &str,
    article: impl ToString,
    ps30: impl ToString,
    agrees: bool,
    how: &str,
) -> Claim {
    Claim {
        claim: claim.to_string(),
        article: article.to_string(),
        ps30: ps30.to_string(),
        agrees,
        how: how.to_string(),
    }
}

fn env(ints: &[(u32, i32)]) -> Environment {
    let mut e = Environment::default();
    for &(r, v) in ints {
        e.ints.insert(r, [v, 0, 0, 0]);
    }
    e
}

/// Loads and analyses one bundled listing.
pub fn analyse_listing(
    (name, text): (&str, &str),
    defines: &[(&str, u64)],
    ints: &[(u32, i32)],
) -> Result<(front::Loaded, Analysis), String> {
    let mut opts = Options::default();
    for (k, v) in defines {
        opts.defines.insert(k.to_string(), *v);
    }
    let loaded = front::load_str(name, text, &opts).map_err(|e| e.diagnostics.render(&e.file))?;
    let a = cost::analyse(&loaded.shader, &loaded.file, &env(ints), &Profile::ps_3_0())
        .map_err(|e| e.to_string())?;
    Ok((loaded, a))
}

/// The largest count for the first REPEAT_BLOCK of a listing whose shader
/// still fits the profile's slot limit, found by re-assembling the listing
/// with other counts (slots grow with the count, so a binary search works).
pub fn largest_fitting_repeat(
    (name, text): (&str, &str),
    profile: &Profile,
) -> Result<(u64, u64), String> {
    let (stmts, _) = front::parse::parse(text);
    let span = stmts
        .iter()
        .find_map(|s| match s {
            front::ast::Stmt::RepeatBegin { count, .. } => Some(count.span()),
            _ => None,
        })
        .ok_or("no REPEAT_BLOCK in the listing")?;
    let slots_with = |n: u64| -> Result<u64, String> {
        let mut t = String::with_capacity(text.len());
        t.push_str(&text[..span.start as usize]);
        t.push_str(&n.to_string());
        t.push_str(&text[span.end as usize..]);
        let loaded = front::load_str(name, &t, &Options::default()).map_err(|e| e.to_string())?;
        Ok(loaded.shader.info().total_slots as u64)
    };
    let (mut lo, mut hi) = (0u64, 1u64);
    while slots_with(hi)? <= profile.max_slots {
        lo = hi;
        hi *= 2;
        if hi > 1 << 20 {
            return Err("slot count does not grow with the repetition count".into());
        }
    }
    while hi - lo > 1 {
        let mid = (lo + hi) / 2;
        if slots_with(mid)? <= profile.max_slots {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Ok((lo, slots_with(lo)?))
}

fn ceil_div(a: u64, b: u64) -> u64 {
    a.div_ceil(b)
}

/// Every claim of the article, computed.
pub fn article_claims() -> Result<Vec<Claim>, String> {
    let profile = Profile::ps_3_0();
    let mut out = Vec::new();

    // The rep/rep loop over 128×56 blocks.
    let (_, a) = analyse_listing(PASS1_LOOP, &[], &[(1, 128), (2, 56)])?;
    let outer = a.loops.first().ok_or("loop listing has no loop")?;
    let inner = a.loops.get(1).ok_or("loop listing has no inner loop")?;
    out.push(claim(
        "loop version: cycles per x pixel",
        9,
        inner.cost_per_iteration.max,
        inner.cost_per_iteration.max == 9,
        "cost of one iteration of `rep i1`, its rep and endrep included",
    ));
    out.push(claim(
        "loop version: cycles to increment a y line",
        6,
        outer.own_cost_per_iteration.max,
        outer.own_cost_per_iteration.max == 6,
        "one iteration of `rep i2` outside the x loop: rep, mad, endrep",
    ));
    out.push(claim(
        "loop version: cycles for a 128×56 block",
        "64,853",
        crate::report::thousands(a.executed.max),
        a.executed == cost::Range::exact(64_853),
        "executed slots with i1 = 128, i2 = 56",
    ));
    out.push(claim(
        "loop version: 128×56 fits the executed limit",
        "yes (≤ 65,535)",
        format!(
            "{} of {}",
            crate::report::thousands(a.executed.max),
            crate::report::thousands(profile.max_executed)
        ),
        a.executed.max <= profile.max_executed,
        "executed slots against the ps_3_0 profile",
    ));

    // The unrolled variant over 125×128 blocks.
    let (loaded, a) = analyse_listing(PASS1_UNROLLED, &[], &[(2, 128)])?;
    let y = a.loops.first().ok_or("unrolled listing has no loop")?;
    // Cost per sample: executed slots of the instructions inside the macro,
    // divided by the number of samples (runs of one macro instruction).
    let ins = loaded.shader.instructions();
    let in_macro: Vec<usize> = (0..ins.len())
        .filter(|&i| !ins[i].origin.repeats.is_empty())
        .collect();
    let macro_executed: u64 = in_macro
        .iter()
        .map(|&i| a.executions[i].max * loaded.shader.info().slots[i] as u64)
        .sum();
    let samples: u64 = in_macro
        .iter()
        .filter(|&&i| ins[i].op == crate::isa::Opcode::TexLd)
        .map(|&i| a.executions[i].max)
        .sum();
    let per_sample = macro_executed.checked_div(samples).unwrap_or(0);
    out.push(claim(
        "unrolled: cycles per log-luminance sample",
        4,
        per_sample,
        per_sample == 4 && macro_executed == 4 * samples,
        "executed slots inside the REPEAT_BLOCK ÷ texld executions",
    ));
    out.push(claim(
        "unrolled: cycles per y line",
        506,
        y.cost_per_iteration.max,
        y.cost_per_iteration == cost::Range::exact(506),
        "one iteration of `rep i2`: rep, 125 × 4, mad, endrep",
    ));
    out.push(claim(
        "unrolled: cycles for a 125×128 block",
        "64,773",
        crate::report::thousands(a.executed.max),
        a.executed == cost::Range::exact(64_773),
        "executed slots with i2 = 128",
    ));
    out.push(claim(
        "unrolled: 125 repetitions fit in 512 slots",
        "yes (≤ 512)",
        format!("{} slots", a.slots),
        a.slots <= profile.max_slots,
        "static slots of the expanded shader",
    ));
    let (largest, slots_at) = largest_fitting_repeat(PASS1_UNROLLED, &profile)?;
    out.push(claim(
        "unrolled: largest repetition count within 512 slots",
        125,
        format!("{largest} ({slots_at} slots)"),
        largest == 125,
        "re-assembled with other counts, binary search on slots ≤ 512",
    ));
    let rows_fit = (0..=255u32).rev().find(|&rows| {
        analyse_listing(PASS1_UNROLLED, &[], &[(2, rows as i32)])
            .is_ok_and(|(_, a)| a.executed.max <= profile.max_executed)
    });
    out.push(claim(
        "unrolled: 128 lines fit the executed limit",
        "yes",
        format!("up to {} lines", rows_fit.unwrap_or(0)),
        rows_fit.is_some_and(|r| r >= 128),
        "largest i2 whose executed count is ≤ 65,535",
    ));

    // Frame tiling for 1280×1024.
    let (w, h) = (1280u64, 1024u64);
    let t1 = (ceil_div(w, 128), ceil_div(h, 56));
    out.push(claim(
        "1280×1024 with 128×56 blocks: intermediate target",
        "10×19",
        format!("{}×{}", t1.0, t1.1),
        t1 == (10, 19),
        "⌈1280/128⌉ × ⌈1024/56⌉",
    ));
    let t2 = (ceil_div(w, 125), ceil_div(h, 128));
    out.push(claim(
        "1280×1024 with 125×128 blocks: intermediate target",
        "11×8",
        format!("{}×{}", t2.0, t2.1),
        t2 == (11, 8),
        "⌈1280/125⌉ × ⌈1024/128⌉",
    ));

    // The second pass for the 11×8 target.
    let (_, a) = analyse_listing(PASS2, &[("xsize", t2.0), ("ysize", t2.1)], &[])?;
    out.push(claim(
        "pass 2 fully unrolled for 11×8 fits in 512 slots",
        "yes (≤ 512)",
        format!(
            "{} slots, {} executed",
            a.slots,
            crate::report::thousands(a.executed.max)
        ),
        a.slots <= profile.max_slots && a.executed.max <= profile.max_executed,
        "pass-2 listing with -D xsize=11 -D ysize=8",
    ));
    Ok(out)
}

/// The claims as a Markdown table.
pub fn claims_markdown(claims: &[Claim]) -> String {
    let mut s = String::from(
        "| claim | article | ps30 | agrees | how ps30 computes it |\n|---|---|---|---|---|\n",
    );
    for c in claims {
        s.push_str(&format!(
            "| {} | {} | {} | {} | {} |\n",
            c.claim,
            c.article,
            c.ps30,
            if c.agrees { "yes" } else { "**NO**" },
            c.how
        ));
    }
    s
}

/// The claims as a plain-text table for the terminal.
pub fn claims_text(claims: &[Claim]) -> String {
    let w0 = claims
        .iter()
        .map(|c| c.claim.chars().count())
        .max()
        .unwrap_or(5);
    let w1 = claims
        .iter()
        .map(|c| c.article.chars().count())
        .max()
        .unwrap_or(7)
        .max(7);
    let w2 = claims
        .iter()
        .map(|c| c.ps30.chars().count())
        .max()
        .unwrap_or(4)
        .max(4);
    let mut s = format!(
        "{:<w0$}  {:<w1$}  {:<w2$}  agrees\n",
        "claim", "article", "ps30"
    );
    for c in claims {
        s.push_str(&format!(
            "{:<w0$}  {:<w1$}  {:<w2$}  {}\n",
            c.claim,
            c.article,
            c.ps30,
            if c.agrees { "yes" } else { "NO" }
        ));
    }
    s
}
