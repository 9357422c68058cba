//! `ps30 plan`: candidate configurations for a frame, measured and ranked.
//!
//! # Which candidates
//!
//! For each pass-1 form the profile allows (unrolled, loop):
//!
//! * widths: the widest that fits (unrolled: the slot limit; loop: the rep
//!   count), capped at the frame width; the narrowest widths that cover the
//!   frame with the same number of columns and with up to three more
//!   (⌈W/k⌉, least padding for k columns); and the two largest widths that
//!   divide the frame exactly (no padding in x);
//! * heights, for each width: the tallest that fits the executed limit and
//!   the rep-count range (capped at the frame height), and the smallest
//!   height with as many block rows (⌈H/⌈H/tallest⌉⌉, least padding);
//! * the article's two choices (loop 128×56, unrolled 125×128), whenever
//!   they fit the profile.
//!
//! # The figures
//!
//! Pass 1's slots and executed instructions per pixel come from the cost
//! model on the generated listing (`fit.rs`'s `Fitter`); pass 2 is the
//! first of unrolled / row loop / nested loops that fits. The frame's total
//! is Σ over passes of executed per pixel × target pixels: pass 1 ×
//! nx·ny, pass 2 × 1. When no pass-2 form fits, the plan needs a third pass,
//! which ps30 does not generate: such candidates show 3 passes and no total.
//!
//! # The recommendation
//!
//! The rule: among candidates that finish in two passes, the fewest executed
//! instructions for the frame; ties go to fewer padded samples, then to the
//! unrolled form, then to the wider block.
//!
//! # The approximate alternative
//!
//! Beside the exact forms, the plan lists the mip-chain method
//! (`jobs::studies::mip_luminance`): log-luminance encoded into
//! 8-bit alpha over a chosen range, averaged by the mip chain. It is not
//! ranked with the others — it trades accuracy for a single cheap pass —
//! so it comes with its predicted error instead ([`MipCandidate`]): the
//! quantisation bound (n + 1 half-codes for n levels after the base, times
//! the range in stops), and the most the frame's odd sides can move the
//! mean (½·Σ|w − 1/N| times the range). What clamping costs depends on the
//! frame's content; the plan only says which luminances clamp.

use super::asm::{Pass1Form, Pass2Form};
use super::fit::{balanced, Fitter};
use super::GenError;
use crate::core::cost::Profile;
use crate::core::numbers::thousands;
use serde::Serialize;
use std::collections::BTreeMap;

/// The article's choices, as (form, block): what it printed.
pub const ARTICLE_CHOICES: [(Pass1Form, (u32, u32)); 2] = [
    (Pass1Form::Loop, (128, 56)),
    (Pass1Form::Unrolled, (125, 128)),
];

/// The largest value an f16 render target holds.
pub const F16_MAX: f64 = 65_504.0;

/// The largest |log2(δ + L)| a frame stored in f16 can produce: black gives
/// log2 δ, the brightest f16 texel log2(δ + 65,504).
pub fn largest_term(delta: f64) -> f64 {
    delta.log2().abs().max((delta + F16_MAX).log2().abs())
}

/// Whether an f16 target holds every possible sum of `samples` terms.
pub fn f16_holds(samples: u64, delta: f64) -> bool {
    samples as f64 * largest_term(delta) <= F16_MAX
}

/// One configuration for the frame.
#[derive(Clone, Debug, Serialize)]
pub struct Candidate {
    /// `unrolled-125x128`.
    pub name: String,
    /// `unrolled` or `loop`.
    pub variant: Pass1Form,
    /// Pass-1 block, texels per line × lines.
    pub block: [u32; 2],
    /// The pass-1 target, blocks across × blocks down (⌈W / bw⌉ × ⌈H / bh⌉).
    pub targets: [u32; 2],
    /// 2, or 3 when no pass-2 listing fits (the third pass is not generated).
    pub passes: u32,
    /// Per pass: [pass 1, pass 2]; pass 2 is null with 3 passes.
    pub slots: [Option<u64>; 2],
    /// Per pass: [pass 1, pass 2]; pass 2 is null with 3 passes.
    pub executed_per_pixel: [Option<u64>; 2],
    /// The pass-2 listing that fits (`unrolled`, `row loop`, `nested loops`);
    /// null with 3 passes.
    pub pass2_form: Option<Pass2Form>,
    /// Σ executed per pixel × target pixels over the two passes (null with 3).
    pub total_executed: Option<u64>,
    /// Texels read outside the frame with BORDER addressing.
    pub padded_samples: u64,
    /// Of those, the ones a last-column shader avoids (the padding in x).
    pub padded_samples_x: u64,
    /// What the padding does to L̄w when pass 2 does not correct it:
    /// 2^(P·log2 δ / N). The generated pass 2 corrects it exactly.
    pub uncorrected_factor: f64,
    /// Whether an f16 target can hold every block sum.
    pub f16_safe: bool,
    /// Why the candidate is in the table.
    pub listed_as: Vec<String>,
    /// One of the article's two choices.
    pub article: bool,
    /// Why pass 2 needs a third pass, when it does.
    pub note: Option<String>,
}

impl Candidate {
    /// `unrolled 125×128 → 11×8`: form, block and pass-1 target, for messages.
    pub fn label(&self) -> String {
        format!(
            "{} {}×{} → {}×{}",
            self.variant.name(),
            self.block[0],
            self.block[1],
            self.targets[0],
            self.targets[1]
        )
    }
}

/// The mip-chain method for the frame, with its predicted error.
#[derive(Clone, Debug, Serialize)]
pub struct MipCandidate {
    /// `mips-alpha8-8-8`: the method and its range.
    pub name: String,
    /// [2^−min, 2^max] as (min, max): luminances outside clamp.
    pub range: (f64, f64),
    /// The chain's levels after the base (the 1 × 1 is the last).
    pub levels: u32,
    /// The encoding shader (`asm/mip-luminance/encode.psh`): slots and
    /// executed instructions per pixel, from the cost model.
    pub slots: u64,
    /// Executed instructions per pixel of the encoding shader.
    pub executed_per_pixel: u64,
    /// Executed instructions for the frame: the encoding at every pixel; the
    /// mip generation is fixed-function and not counted.
    pub total_executed: u64,
    /// The quantisation bound on log2 L̄w, in stops: (n + 1)·½/255·(min + max).
    pub quantisation_stops: f64,
    /// The most the frame's odd sides can move log2 L̄w, in stops:
    /// ½·Σ|w − 1/N|·(min + max) (0 for power-of-two sides).
    pub odd_sides_stops: f64,
    /// Both together as a relative error of L̄w: 2^(sum) − 1.
    pub predicted_relative_error: f64,
}

/// The mip-chain candidate for a frame and a range.
pub fn mip_candidate(frame: (u32, u32), range: (f64, f64)) -> Result<MipCandidate, GenError> {
    use crate::core::cost::{analyse, Environment};
    use crate::core::image::weight_bound;
    use crate::core::image::{full_chain_levels, OddSides};
    let b = crate::jobs::bundled::MIP_LUMINANCE_ENCODE;
    let loaded = crate::core::load::load_str(b.path, b.text, &Default::default())
        .map_err(|e| GenError(e.to_string()))?;
    let a = analyse(
        &loaded.shader,
        &loaded.file,
        &Environment::default(),
        &Profile::ps_3_0(),
    )
    .map_err(|e| GenError(e.to_string()))?;
    let (w, h) = frame;
    let levels = full_chain_levels(w, h) - 1;
    let stops = range.0 + range.1;
    let quantisation_stops = (levels as f64 + 1.0) * 0.5 / 255.0 * stops;
    let odd_sides_stops = weight_bound(w, h, OddSides::Fold) * stops;
    Ok(MipCandidate {
        name: format!("mips-alpha8-{}-{}", range.0, range.1),
        range,
        levels,
        slots: a.slots,
        executed_per_pixel: a.executed.max,
        total_executed: a.executed.max * w as u64 * h as u64,
        quantisation_stops,
        odd_sides_stops,
        predicted_relative_error: (quantisation_stops + odd_sides_stops).exp2() - 1.0,
    })
}

/// The range the plan's mip-chain candidate uses unless told otherwise:
/// [2^−8, 2^8].
pub const DEFAULT_LOG_RANGE: (f64, f64) = (8.0, 8.0);

/// A ranked plan.
#[derive(Clone, Debug, Serialize)]
pub struct Plan {
    /// The frame planned for, width × height in pixels.
    pub frame: [u32; 2],
    /// The limits every candidate was fitted to.
    pub profile: Profile,
    /// δ of log2(δ + L), the offset that keeps black pixels finite.
    pub delta: f64,
    /// Best first.
    pub candidates: Vec<Candidate>,
    /// The name of the recommended candidate.
    pub recommended: Option<String>,
    /// The ranking rule, in words ([`RULE`]).
    pub rule: String,
    /// Why the recommended candidate wins, in numbers (or why none is
    /// recommended).
    pub why: String,
    /// Forms or article choices the profile rules out, and why.
    pub notes: Vec<String>,
    /// The mip-chain method: approximate, listed with its predicted error,
    /// not ranked.
    pub approximate: MipCandidate,
}

/// The recommendation rule, as the plan states it.
pub const RULE: &str = "among candidates that finish in two passes, the fewest executed instructions for the whole frame; ties go to fewer padded samples, then to the unrolled form, then to the wider block";

fn rank_key(c: &Candidate) -> (u32, u64, u64, u8, std::cmp::Reverse<u32>, u32) {
    (
        c.passes,
        c.total_executed.unwrap_or(u64::MAX),
        c.padded_samples,
        match c.variant {
            Pass1Form::Unrolled => 0,
            Pass1Form::Loop => 1,
        },
        std::cmp::Reverse(c.block[0]),
        c.block[1],
    )
}

/// The two largest divisors of `w` that are at most `cap`.
fn largest_divisors(w: u32, cap: u32) -> Vec<u32> {
    let mut out = Vec::new();
    let mut d = cap.min(w);
    while d >= 1 && out.len() < 2 {
        if w.is_multiple_of(d) {
            out.push(d);
        }
        d -= 1;
    }
    out
}

/// Measures one configuration; `Ok(None)` when pass 1 does not fit.
pub fn candidate(
    fitter: &mut Fitter<'_>,
    frame: (u32, u32),
    delta: f64,
    form: Pass1Form,
    block: (u32, u32),
) -> Result<Option<Candidate>, GenError> {
    let (w, h) = frame;
    let (bw, bh) = block;
    let Some(p1) = fitter.pass1(form, bw, bh)? else {
        return Ok(None);
    };
    if !p1.fits() {
        return Ok(None);
    }
    let (nx, ny) = (w.div_ceil(bw), h.div_ceil(bh));
    let outcome = fitter.pass2(nx, ny)?;
    let covered = (nx as u64 * bw as u64) * (ny as u64 * bh as u64);
    let n = w as u64 * h as u64;
    let padded = covered - n;
    let padded_y = w as u64 * (ny as u64 * bh as u64) - n;
    let factor = (padded as f64 * delta.log2() / n as f64).exp2();
    let pass_count = nx as u64 * ny as u64;
    let (passes, p2, total, note) = match &outcome.choice {
        Some(c) => (
            2,
            Some(c),
            Some(p1.executed * pass_count + c.executed),
            None,
        ),
        None => (
            3,
            None,
            None,
            Some(format!(
                "no pass-2 listing for a {nx}×{ny} target fits ({}): a third pass would be needed, which ps30 does not generate",
                outcome.rejected.join("; ")
            )),
        ),
    };
    Ok(Some(Candidate {
        name: format!("{}-{bw}x{bh}", form.name()),
        variant: form,
        block: [bw, bh],
        targets: [nx, ny],
        passes,
        slots: [Some(p1.slots), p2.map(|c| c.slots)],
        executed_per_pixel: [Some(p1.executed), p2.map(|c| c.executed)],
        pass2_form: p2.map(|c| c.form),
        total_executed: total,
        padded_samples: padded,
        padded_samples_x: padded - padded_y,
        uncorrected_factor: factor,
        f16_safe: f16_holds(bw as u64 * bh as u64, delta),
        listed_as: Vec::new(),
        article: false,
        note,
    }))
}

/// Every candidate of one form, measured, unranked; with notes on what the
/// profile rules out.
pub fn candidates(
    fitter: &mut Fitter<'_>,
    frame: (u32, u32),
    delta: f64,
    form: Pass1Form,
    notes: &mut Vec<String>,
) -> Result<Vec<Candidate>, GenError> {
    let (w, h) = frame;
    let mut blocks: BTreeMap<(u32, u32), Vec<String>> = BTreeMap::new();
    match fitter.widest(form, w)? {
        None => {
            let why = fitter
                .pass1_unwritable(form, 1, 1)
                .or_else(|| {
                    fitter
                        .pass1(form, 1, 1)
                        .ok()
                        .flatten()
                        .map(|c| c.problems.join("; "))
                })
                .unwrap_or_default();
            notes.push(format!(
                "the {} form does not fit this profile even for a 1×1 block: {why}",
                form.name()
            ));
        }
        Some(w_max) => {
            let mut widths: Vec<(u32, String)> = vec![(w_max, "widest".into())];
            let k0 = w.div_ceil(w_max);
            for k in k0..k0 + 4 {
                let bw = w.div_ceil(k);
                // Only when it really takes k columns (tiny frames repeat).
                if w.div_ceil(bw) == k {
                    widths.push((bw, format!("{k} columns")));
                }
            }
            for d in largest_divisors(w, w_max) {
                widths.push((d, format!("divides {w}")));
            }
            // One label per width: the first reason it was listed.
            let mut seen = std::collections::BTreeSet::new();
            widths.retain(|(bw, _)| seen.insert(*bw));
            for (bw, why_w) in widths {
                if bw == 0 {
                    continue;
                }
                let Some(tallest) = fitter.tallest(form, bw, h)? else {
                    continue;
                };
                let short = balanced(h, tallest);
                blocks
                    .entry((bw, tallest))
                    .or_default()
                    .push(format!("{why_w} × tallest"));
                if short != tallest {
                    blocks
                        .entry((bw, short))
                        .or_default()
                        .push(format!("{why_w} × {} rows", h.div_ceil(short)));
                }
            }
        }
    }
    let mut out = Vec::new();
    let article: Vec<(u32, u32)> = ARTICLE_CHOICES
        .iter()
        .filter(|(f, _)| *f == form)
        .map(|&(_, b)| b)
        .collect();
    for &b in &article {
        blocks.entry(b).or_default().push("the article's".into());
    }
    for (block, why) in blocks {
        match candidate(fitter, frame, delta, form, block)? {
            Some(mut c) => {
                c.article = article.contains(&block);
                let mut why = why;
                why.dedup();
                c.listed_as = why;
                out.push(c);
            }
            None if article.contains(&block) => {
                let reason = fitter
                    .pass1_unwritable(form, block.0, block.1)
                    .or_else(|| {
                        fitter
                            .pass1(form, block.0, block.1)
                            .ok()
                            .flatten()
                            .map(|c| c.problems.join("; "))
                    })
                    .unwrap_or_default();
                notes.push(format!(
                    "the article's {} {}×{} does not fit this profile: {reason}",
                    form.name(),
                    block.0,
                    block.1
                ));
            }
            None => {}
        }
    }
    Ok(out)
}

/// Plans a frame under a profile, with the mip-chain candidate over
/// [`DEFAULT_LOG_RANGE`].
pub fn plan(frame: (u32, u32), profile: &Profile, delta: f64) -> Result<Plan, GenError> {
    plan_with_range(frame, profile, delta, DEFAULT_LOG_RANGE)
}

/// [`plan`] with the mip-chain candidate over [2^−min, 2^max].
pub fn plan_with_range(
    frame: (u32, u32),
    profile: &Profile,
    delta: f64,
    log_range: (f64, f64),
) -> Result<Plan, GenError> {
    // The forms and the mip-chain method are measured side by side, each
    // form with a fitter of its own; notes and errors keep the forms' order.
    let form = |form| {
        let mut notes = Vec::new();
        candidates(&mut Fitter::new(profile), frame, delta, form, &mut notes).map(|c| (c, notes))
    };
    let (unrolled, (looped, approximate)) = rayon::join(
        || form(Pass1Form::Unrolled),
        || rayon::join(|| form(Pass1Form::Loop), || mip_candidate(frame, log_range)),
    );
    let (mut all, mut notes) = unrolled?;
    let (more, more_notes) = looped?;
    all.extend(more);
    notes.extend(more_notes);
    let approximate = approximate?;
    all.sort_by_key(rank_key);
    let recommended = all.iter().find(|c| c.passes == 2);
    let why = match recommended {
        None if all.is_empty() => "no configuration fits this profile".to_string(),
        None => "every candidate needs a third pass, which ps30 does not generate".to_string(),
        Some(r) => why(r, &all),
    };
    Ok(Plan {
        frame: [frame.0, frame.1],
        profile: profile.clone(),
        delta,
        recommended: recommended.map(|c| c.name.clone()),
        candidates: all,
        rule: RULE.to_string(),
        why,
        notes,
        approximate,
    })
}

/// One sentence: why `r` wins, against the article's best choice.
fn why(r: &Candidate, all: &[Candidate]) -> String {
    let total = r.total_executed.unwrap_or(0);
    let mut s = format!(
        "{} executes the fewest instructions for the frame, {}",
        r.label(),
        thousands(total)
    );
    let article = all
        .iter()
        .filter(|c| c.article && c.passes == 2)
        .min_by_key(|c| rank_key(c));
    match article {
        Some(a) if a.name == r.name => s.push_str(" — it is the article's own choice"),
        Some(a) => {
            let at = a.total_executed.unwrap_or(0);
            s.push_str(&format!(
                ", {:.1}% fewer than the article's best, {} ({})",
                100.0 * (at as f64 - total as f64) / at as f64,
                a.label(),
                thousands(at)
            ));
            if r.padded_samples < a.padded_samples {
                s.push_str(&format!(
                    ", because its blocks cover the frame with {} padded samples instead of {}",
                    thousands(r.padded_samples),
                    thousands(a.padded_samples)
                ));
            } else if r.targets[0] * r.targets[1] < a.targets[0] * a.targets[1] {
                s.push_str(
                    ", because fewer, larger blocks pay the per-line and set-up cost fewer times",
                );
            }
        }
        None => {}
    }
    s.push('.');
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn divisors() {
        assert_eq!(largest_divisors(1280, 255), vec![160, 128]);
        assert_eq!(largest_divisors(7, 5), vec![1]);
    }

    #[test]
    fn f16_bound() {
        // δ = 1e-4: log2(δ + 65,504) = 16.0 outweighs |log2 δ| = 13.3.
        assert!((largest_term(1e-4) - 16.0).abs() < 1e-3);
        assert!(f16_holds(4_094, 1e-4));
        assert!(!f16_holds(4_095, 1e-4));
    }
}
