//! What `ps30 plan` prints: the candidates as a table with the
//! recommendation, and the same as JSON.

use crate::core::numbers::thousands;
use crate::jobs::gen::plan::{largest_term, Candidate, MipCandidate, Plan, F16_MAX};
use crate::jobs::gen::profile_text;

fn factor_text(f: f64) -> String {
    if f == 1.0 {
        "× 1".into()
    } else if f == 0.0 {
        "× 0".into()
    } else if f < 1e-3 {
        format!("× {f:.1e}")
    } else {
        format!("× {f:.4}")
    }
}

/// The plan as a text table.
pub fn plan_text(p: &Plan) -> String {
    let (w, h) = (p.frame[0], p.frame[1]);
    let mut s = format!(
        "plan for a {w}×{h} frame ({} pixels); profile {}: {}; δ = {}\n\n",
        thousands(w as u64 * h as u64),
        p.profile.name,
        profile_text(&p.profile),
        p.delta as f32
    );
    s.push_str(&table(&candidate_rows(p), &[1, 2, 3, 7, 14]));
    s.push('\n');
    s.push_str(&recommendation_text(p));
    s
}

/// The header row and one row per candidate (the recommended one marked
/// `*`).
fn candidate_rows(p: &Plan) -> Vec<Vec<String>> {
    let header = [
        "#",
        "variant",
        "block",
        "targets",
        "passes",
        "slots",
        "executed/px",
        "pass 2",
        "slots",
        "executed/px",
        "frame total",
        "padded",
        "uncorrected",
        "f16",
        "listed as",
    ];
    let mut rows: Vec<Vec<String>> = vec![header.iter().map(|s| s.to_string()).collect()];
    let opt = |v: Option<u64>| v.map_or("—".to_string(), thousands);
    for (i, c) in p.candidates.iter().enumerate() {
        let mark = if Some(&c.name) == p.recommended.as_ref() {
            "*"
        } else {
            ""
        };
        rows.push(vec![
            format!("{}{mark}", i + 1),
            c.variant.name().to_string(),
            format!("{}×{}", c.block[0], c.block[1]),
            format!("{}×{}", c.targets[0], c.targets[1]),
            c.passes.to_string(),
            opt(c.slots[0]),
            opt(c.executed_per_pixel[0]),
            c.pass2_form
                .map_or("(3rd pass)".to_string(), |f| f.name().to_string()),
            opt(c.slots[1]),
            opt(c.executed_per_pixel[1]),
            opt(c.total_executed),
            thousands(c.padded_samples),
            factor_text(c.uncorrected_factor),
            if c.f16_safe { "yes" } else { "no" }.to_string(),
            c.listed_as.join("; "),
        ]);
    }
    rows
}

/// `rows` as aligned columns: the columns in `left` left-aligned, the
/// others (numbers) right-aligned.
fn table(rows: &[Vec<String>], left: &[usize]) -> String {
    let mut s = String::new();
    let cols = rows.first().map_or(0, |r| r.len());
    let widths: Vec<usize> = (0..cols)
        .map(|i| rows.iter().map(|r| r[i].chars().count()).max().unwrap_or(0))
        .collect();
    for r in rows {
        let mut line = String::new();
        for (i, cell) in r.iter().enumerate() {
            let pad = widths[i] - cell.chars().count();
            if i > 0 {
                line.push_str("  ");
            }
            if left.contains(&i) {
                line.push_str(cell);
                if i + 1 < cols {
                    line.push_str(&" ".repeat(pad));
                }
            } else {
                line.push_str(&" ".repeat(pad));
                line.push_str(cell);
            }
        }
        s.push_str(line.trim_end());
        s.push('\n');
    }
    s
}

/// The recommendation, the rule and why, what the columns mean, and the
/// notes.
fn recommendation_text(p: &Plan) -> String {
    let mut s = String::new();
    match p
        .recommended
        .as_ref()
        .and_then(|n| p.candidates.iter().find(|c| &c.name == n))
    {
        Some(r) => s.push_str(&format!("recommended (*): {}\n", r.label())),
        None => s.push_str("recommended: none\n"),
    }
    s.push_str(&format!("rule: {}\n", p.rule));
    s.push_str(&format!("why: {}\n", p.why));
    s.push_str(&format!(
        "\ncolumns: slots and executed/px of pass 1 and of pass 2 (from the cost model on the generated listings); \
frame total = pass 1 × {} target pixels + pass 2 × 1; padded = texels read outside the frame (BORDER: log2 δ each); \
uncorrected = what they do to L̄w if pass 2 does not subtract them (the generated pass 2 does, exactly, with c0.y); \
f16 = whether a D3DFMT_A16B16G16R16F target holds every block sum (block samples × {:.2} ≤ 65,504, i.e. at most {} samples; otherwise use R32F); \
listed as = why the width × why the height: widest (that fits), k columns (the narrowest width covering the frame with k columns), divides W; \
tallest (that fits), r rows (the smallest height covering the frame with r rows); the article's (its two choices)\n",
        "nx·ny",
        largest_term(p.delta),
        thousands((F16_MAX / largest_term(p.delta)).floor() as u64)
    ));
    let x_padding: Vec<&Candidate> = p
        .candidates
        .iter()
        .filter(|c| c.padded_samples_x > 0 && c.passes == 2)
        .collect();
    if !x_padding.is_empty() {
        s.push_str("last column: `ps30 unroll` also writes a shader for the last column of blocks that reads only the frame's real width, which removes the padding in x (e.g. ");
        let examples: Vec<String> = x_padding
            .iter()
            .take(2)
            .map(|c| {
                format!(
                    "{}: {} of its {} padded samples",
                    c.name,
                    thousands(c.padded_samples_x),
                    thousands(c.padded_samples)
                )
            })
            .collect();
        s.push_str(&examples.join("; "));
        s.push_str(") at the cost of a second pass-1 draw\n");
    }
    for c in p.candidates.iter().filter(|c| c.passes == 3).take(3) {
        if let Some(n) = &c.note {
            s.push_str(&format!("{}: {n}\n", c.name));
        }
    }
    for n in &p.notes {
        s.push_str(&format!("note: {n}\n"));
    }
    s.push_str(&mip_text(&p.approximate));
    s
}

/// The mip-chain alternative: its cost and predicted error.
fn mip_text(m: &MipCandidate) -> String {
    format!(
        "\napproximate alternative (not ranked): log-luminance in 8-bit alpha over [2^−{min}, 2^{max}], \
         averaged by the mip chain ({levels} levels to 1×1)\n  \
         asm/mip-luminance/encode.psh: {slots} slots, {per} executed per pixel, {total} for the frame \
         (the mip generation is fixed-function, not counted)\n  \
         predicted error of L̄w, worst case: {q:.3} stops from 8-bit steps ({n} half-codes of {stops} \
         stops / 255){odd}: {rel:.1} % in all; luminances outside the range clamp (not predictable \
         without the frame; `ps30 study mip-luminance` measures real frames)\n",
        min = m.range.0,
        max = m.range.1,
        levels = m.levels,
        slots = m.slots,
        per = m.executed_per_pixel,
        total = thousands(m.total_executed),
        q = m.quantisation_stops,
        n = m.levels + 1,
        stops = m.range.0 + m.range.1,
        odd = if m.odd_sides_stops > 0.0 {
            format!(
                " + {:.3} stops from the frame's odd sides (unequal weights in the chain, for a frame \
                 at the top of the range where the chain weighs most and at the bottom elsewhere)",
                m.odd_sides_stops
            )
        } else {
            ", no odd sides".to_string()
        },
        rel = 100.0 * m.predicted_relative_error,
    )
}

/// The plan as JSON.
pub fn plan_json(p: &Plan) -> serde_json::Value {
    serde_json::to_value(p).unwrap_or(serde_json::Value::Null)
}
