//! `ps30 verify`: every figure the article states, recomputed by ps30 from
//! the article's own listings (bundled in the binary), side by side.
//!
//! Each claim pairs the article's figure (a literal: it is what the article
//! printed) with the value ps30 computes from the shaders through the front
//! end and the cost model. Nothing here copies an expected value into the
//! computation.

use crate::core::cost::{self, Analysis, Environment, Profile};
use crate::core::load::{self, Options};
use crate::core::numbers::thousands;
use crate::jobs::bundled::{ARTICLE_LOOP, ARTICLE_PASS2, ARTICLE_UNROLLED};
use serde::Serialize;

/// One stated figure and ps30's value for it.
#[derive(Clone, Debug, Serialize)]
pub struct Claim {
    /// What is claimed (`loop version: cycles for a 128×56 block`).
    pub claim: String,
    /// What the article prints.
    pub article: String,
    /// What ps30 computes.
    pub ps30: String,
    /// Whether ps30's value is the article's.
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
) -> Result<(load::Loaded, Analysis), String> {
    let mut opts = Options::default();
    for (k, v) in defines {
        opts.defines.insert(k.to_string(), *v);
    }
    let loaded = load::load_str(name, text, &opts).map_err(|e| e.diagnostics.render(&e.file))?;
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
    let (stmts, _) = crate::core::front::parse::parse(text);
    let span = stmts
        .iter()
        .find_map(|s| match s {
            crate::core::front::ast::Stmt::RepeatBegin { count, .. } => Some(count.span()),
            _ => None,
        })
        .ok_or("no REPEAT_BLOCK in the listing")?;
    let slots_with = |n: u64| -> Result<u64, String> {
        let mut t = String::with_capacity(text.len());
        t.push_str(&text[..span.start as usize]);
        t.push_str(&n.to_string());
        t.push_str(&text[span.end as usize..]);
        let loaded = load::load_str(name, &t, &Options::default()).map_err(|e| e.to_string())?;
        Ok(u64::from(
            loaded.shader.info().total(profile.slot_table).total(),
        ))
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
    let mut out = loop_claims(&profile)?;
    out.extend(unrolled_claims(&profile)?);
    let (tiling, t2) = tiling_claims();
    out.extend(tiling);
    out.extend(pass2_claims(&profile, t2)?);
    Ok(out)
}

/// The rep/rep loop over 128×56 blocks.
fn loop_claims(profile: &Profile) -> Result<Vec<Claim>, String> {
    let mut out = Vec::new();
    let (_, a) = analyse_listing(ARTICLE_LOOP.listing(), &[], &[(1, 128), (2, 56)])?;
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
        thousands(a.executed.max),
        a.executed == cost::Range::exact(64_853),
        "executed slots with i1 = 128, i2 = 56",
    ));
    out.push(claim(
        "loop version: 128×56 fits the executed limit",
        "yes (≤ 65,535)",
        format!(
            "{} of {}",
            thousands(a.executed.max),
            thousands(profile.max_executed)
        ),
        a.executed.max <= profile.max_executed,
        "executed slots against the ps_3_0 profile",
    ));
    Ok(out)
}

/// The unrolled variant over 125×128 blocks.
fn unrolled_claims(profile: &Profile) -> Result<Vec<Claim>, String> {
    let mut out = Vec::new();
    let (loaded, a) = analyse_listing(ARTICLE_UNROLLED.listing(), &[], &[(2, 128)])?;
    let y = a.loops.first().ok_or("unrolled listing has no loop")?;
    let (per_sample, macro_executed, samples) = per_sample(&loaded, &a);
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
        thousands(a.executed.max),
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
    let (largest, slots_at) = largest_fitting_repeat(ARTICLE_UNROLLED.listing(), profile)?;
    out.push(claim(
        "unrolled: largest repetition count within 512 slots",
        125,
        format!("{largest} ({slots_at} slots)"),
        largest == 125,
        "re-assembled with other counts, binary search on slots ≤ 512",
    ));
    // The listing is assembled once; only the loop count changes.
    let rows_fit = (0..=255u32).rev().find(|&rows| {
        cost::analyse(
            &loaded.shader,
            &loaded.file,
            &env(&[(2, rows as i32)]),
            profile,
        )
        .is_ok_and(|a| a.executed.max <= profile.max_executed)
    });
    out.push(claim(
        "unrolled: 128 lines fit the executed limit",
        "yes",
        format!(
            "up to {}",
            crate::core::numbers::plural(rows_fit.unwrap_or(0) as u64, "line", "lines")
        ),
        rows_fit.is_some_and(|r| r >= 128),
        "largest i2 whose executed count is ≤ 65,535",
    ));
    Ok(out)
}

/// Cost per sample of the unrolled listing: executed slots of the
/// instructions inside the macro, divided by the number of samples (runs of
/// one macro instruction). Returns it with the two figures it divides.
fn per_sample(loaded: &load::Loaded, a: &Analysis) -> (u64, u64, u64) {
    let ins = loaded.shader.instructions();
    let in_macro: Vec<usize> = (0..ins.len())
        .filter(|&i| ins[i].origin.repeat.is_some())
        .collect();
    let macro_executed: u64 = in_macro
        .iter()
        .map(|&i| {
            a.executions[i].max * u64::from(loaded.shader.info().slots(i, a.profile.slot_table))
        })
        .sum();
    let samples: u64 = in_macro
        .iter()
        .filter(|&&i| ins[i].op == crate::core::isa::Opcode::TexLd)
        .map(|&i| a.executions[i].max)
        .sum();
    let per_sample = macro_executed.checked_div(samples).unwrap_or(0);
    (per_sample, macro_executed, samples)
}

/// Frame tiling for 1280×1024; also returns the 125×128 blocks' target.
fn tiling_claims() -> (Vec<Claim>, (u64, u64)) {
    let mut out = Vec::new();
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
    (out, t2)
}

/// The second pass for the 11×8 target `t2`.
fn pass2_claims(profile: &Profile, t2: (u64, u64)) -> Result<Vec<Claim>, String> {
    let mut out = Vec::new();
    let (_, a) = analyse_listing(
        ARTICLE_PASS2.listing(),
        &[("xsize", t2.0), ("ysize", t2.1)],
        &[],
    )?;
    out.push(claim(
        "pass 2 fully unrolled for 11×8 fits in 512 slots",
        "yes (≤ 512)",
        format!("{} slots, {} executed", a.slots, thousands(a.executed.max)),
        a.slots <= profile.max_slots && a.executed.max <= profile.max_executed,
        "pass-2 listing with -D xsize=11 -D ysize=8",
    ));
    Ok(out)
}

/// The image `verify` cross-checks on: the article's frame size.
pub const CROSSCHECK_IMAGE: &str = "assets/hdr/courtyard_1280x1024.exr";

/// One configuration of the cross-check and what ps30 expects of it.
#[derive(Clone, Debug, Serialize)]
pub struct CrossRow {
    /// The pass-1 shader's bundled name (`article:unrolled`, `corrected:loop`).
    pub pass1: String,
    /// The pass-2 shader's bundled name.
    pub pass2: String,
    /// Pixels per pass-1 block, (width, height).
    pub block: (u32, u32),
    /// The pass-1 target's D3D9 format (`D3DFMT_R32F`, `D3DFMT_A16B16G16R16F`).
    pub format: &'static str,
    /// Blocks whose emulated sum is within its bound of the f64 reference.
    pub blocks_agreeing: usize,
    /// Blocks in the pass-1 target.
    pub blocks: usize,
    /// Blocks whose sum the target format cannot hold.
    pub overflowed: usize,
    /// L̄w as the emulator computed it.
    pub log_average: f64,
    /// L̄w of the f64 reference.
    pub reference_log_average: f64,
    /// (L̄w − reference) / reference.
    pub relative_error: f64,
    /// The derived bound on |relative_error|.
    pub relative_tolerance: f64,
    /// Whether the run agrees everywhere: blocks, pass 2, L̄w and the counts.
    pub agree: bool,
    /// Whether ps30 expects this configuration to agree.
    pub expected_to_agree: bool,
    /// What the run shows, in numbers.
    pub finding: String,
}

impl CrossRow {
    /// Whether the run came out as ps30 expected: agreeing where it should,
    /// disagreeing where the configuration is known to fail.
    pub fn as_expected(&self) -> bool {
        self.agree == self.expected_to_agree
    }
}

/// Runs the article's shaders and the corrected ones on the bundled image
/// and says what each run shows.
pub fn crosscheck(image: &crate::core::image::HdrImage) -> Result<Vec<CrossRow>, String> {
    use crate::core::image::TargetFormat;
    use crate::jobs::luminance::{run, Settings, ShaderSource};
    // (pass 1, pass 2, block, target format, expected to agree)
    #[allow(clippy::type_complexity)]
    let configs: [(&str, &str, (u32, u32), TargetFormat, bool); 6] = [
        (
            "corrected:unrolled",
            "corrected:pass2",
            (125, 128),
            TargetFormat::R32F,
            true,
        ),
        (
            "corrected:loop",
            "corrected:pass2",
            (128, 56),
            TargetFormat::R32F,
            true,
        ),
        (
            "article:unrolled",
            "article:pass2",
            (125, 128),
            TargetFormat::R32F,
            false,
        ),
        (
            "article:loop",
            "article:pass2",
            (128, 56),
            TargetFormat::R32F,
            false,
        ),
        (
            "corrected:unrolled",
            "article:pass2",
            (125, 128),
            TargetFormat::R32F,
            false,
        ),
        (
            "corrected:unrolled",
            "corrected:pass2",
            (125, 128),
            TargetFormat::Rgba16F,
            false,
        ),
    ];
    let mut rows = Vec::new();
    for (p1, p2, block, format, expected) in configs {
        let src = |n: &str| {
            let (name, text) = crate::jobs::bundled::listing(n).expect("bundled shader");
            ShaderSource::new(name, text)
        };
        let settings = Settings {
            block,
            format,
            ..Settings::default()
        };
        let r = run(image, &src(p1), &src(p2), &settings).map_err(|e| e.to_string())?;
        let agreeing = r.blocks.iter().filter(|b| b.agree).count();
        let overflowed = r.blocks.iter().filter(|b| b.overflow).count();
        let finding = if r.all_agree() {
            format!(
                "every block within its bound (largest difference {:.0}% of it); L̄w off by {:.1e} of a {:.1e} bound",
                100.0 * r.blocks.iter().map(|b| b.difference / b.tolerance).fold(0.0, f64::max),
                r.relative_error,
                r.relative_tolerance
            )
        } else if overflowed > 0 {
            format!(
                "{overflowed} of {} block sums are beyond ±65,504 and become infinite in {}; L̄w = {} (finding 3)",
                r.blocks.len(),
                format.d3d_name(),
                r.log_average
            )
        } else if r.blocks_agree() {
            format!(
                "blocks all agree, but L̄w = {:.4} × the true value; the BORDER padding ({} samples of log2 δ) predicts × {:.4} (finding 2)",
                r.log_average / r.reference_log_average,
                thousands(r.padded_samples),
                r.padding_factor
            )
        } else {
            let col0 = r.blocks.iter().filter(|b| b.x == 0);
            let col0_ok = col0.clone().filter(|b| b.agree).count();
            let right_bad = r.blocks.iter().filter(|b| b.x > 0 && !b.agree).count();
            format!(
                "{right_bad} of {} blocks right of column 0 disagree (column 0: {col0_ok} of {} agree); L̄w = {:.4} × the true value (finding 1)",
                r.blocks.iter().filter(|b| b.x > 0).count(),
                col0.count(),
                r.log_average / r.reference_log_average
            )
        };
        rows.push(CrossRow {
            pass1: p1.to_string(),
            pass2: p2.to_string(),
            block,
            format: format.d3d_name(),
            blocks_agreeing: agreeing,
            blocks: r.blocks.len(),
            overflowed,
            log_average: r.log_average,
            reference_log_average: r.reference_log_average,
            relative_error: r.relative_error,
            relative_tolerance: r.relative_tolerance,
            agree: r.all_agree(),
            expected_to_agree: expected,
            finding,
        });
    }
    Ok(rows)
}

/// Where the committed generated shaders live (see [`crate::jobs::gen::set`]).
pub const GENERATED_DIR: &str = "asm/generated";

/// The article's planning claims, recomputed by the generator and the
/// planner (`ps30 unroll`, `ps30 plan`) for the article's 1280×1024 frame:
/// the intermediate targets of its two block choices, with the executed
/// counts of the generated (corrected) listings, and the fitted unroll.
pub fn planning_claims(set: &crate::jobs::gen::set::GeneratedSet) -> Result<Vec<Claim>, String> {
    use crate::jobs::gen::Pass1Form;
    let frame = (1280, 1024);
    let (_, bundle, plan) = set
        .frames
        .iter()
        .find(|(f, _, _)| *f == frame)
        .ok_or("the generated set has no 1280×1024 frame")?;
    let mut out = Vec::new();
    let find = |form: Pass1Form, block: [u32; 2]| {
        plan.candidates
            .iter()
            .find(|c| c.variant == form && c.block == block)
    };
    for (form, block, targets, executed, how) in [
        (
            Pass1Form::Loop,
            [128, 56],
            [10, 19],
            64_853u64,
            "`ps30 plan --frame 1280x1024`: the loop candidate 128 wide (a width dividing 1280) at its tallest fitting height",
        ),
        (
            Pass1Form::Unrolled,
            [125, 128],
            [11, 8],
            64_773,
            "`ps30 plan --frame 1280x1024`: the widest unroll at the smallest height with as many block rows as the tallest",
        ),
    ] {
        let c = find(form, block);
        let ps30 = match c {
            Some(c) => format!(
                "{}×{}, {} executed",
                c.targets[0],
                c.targets[1],
                c.executed_per_pixel[0].map_or("—".into(), thousands)
            ),
            None => "not among the candidates".into(),
        };
        let listed_by_rule = c.is_some_and(|c| c.listed_as.iter().any(|l| l != "the article's"));
        out.push(claim(
            &format!(
                "plan 1280×1024: {} {}×{} blocks → targets",
                form.name(),
                block[0],
                block[1]
            ),
            format!(
                "{}×{}, {} cycles",
                targets[0],
                targets[1],
                thousands(executed)
            ),
            ps30,
            c.is_some_and(|c| {
                c.targets == targets
                    && c.executed_per_pixel[0] == Some(executed)
                    && c.passes == 2
                    && listed_by_rule
            }),
            how,
        ));
    }
    let fitted = bundle
        .configs
        .iter()
        .find(|c| c.form == Pass1Form::Unrolled)
        .ok_or("no fitted unrolled configuration at 1280×1024")?;
    let fitted_shader = bundle
        .shaders
        .iter()
        .find(|g| g.file == fitted.pass1)
        .ok_or("the fitted unrolled shader is missing")?;
    out.push(claim(
        "unroll --fit: widest unroll within 512 slots",
        125,
        format!(
            "{} ({} slots, line-end fix included)",
            fitted.block[0], fitted_shader.slots
        ),
        fitted.block[0] == 125 && fitted_shader.slots <= 512,
        "`ps30 unroll --fit`: binary search over the generated listing's slots (cost model)",
    ));
    out.push(claim(
        "unroll --fit 1280×1024: block height",
        128,
        format!(
            "{} ({} executed)",
            fitted.block[1],
            thousands(fitted_shader.executed)
        ),
        fitted.block[1] == 128 && fitted_shader.executed == 64_773,
        "tallest block within 65,535 executed (129 lines), lowered to the smallest height with as many block rows (1024 = 8 × 128)",
    ));
    let pass2 = fitted
        .pass2
        .as_ref()
        .and_then(|f| bundle.shaders.iter().find(|g| &g.file == f));
    out.push(claim(
        "unroll --fit 1280×1024: pass 2 fully unrolled for 11×8",
        "yes (≤ 512)",
        match pass2 {
            Some(g) => format!("{}, {} slots", g.form, g.slots),
            None => "no pass 2".into(),
        },
        pass2.is_some_and(|g| g.form == "unrolled" && g.slots <= 512 && g.size == [11, 8]),
        "the generated pass 2 for the fitted block's target (padding correction included)",
    ));
    Ok(out)
}
