//! `ps30 unroll`: the shaders for one frame — pass 1 in its forms, the
//! last-column variant, pass 2 — each checked and headed with its figures
//! and the constants the application must set; and `asm/generated/`, the
//! committed sets for six common frame sizes.

use super::asm::{self, Counts, Pass1Form, Pass2Form};
use super::fit::{balanced, Fitter};
use super::plan::{self, f16_holds};
use super::GenError;
use crate::core::cost::Profile;
use crate::core::numbers::{size, thousands};
use serde::Serialize;
use std::collections::BTreeMap;
use std::path::Path;

/// `1 line`, `128 lines`.
fn lines(n: u32) -> String {
    crate::core::numbers::plural(n as u64, "line", "lines")
}

/// What a generated shader is for.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Role {
    /// Pass 1 over every column of blocks (BORDER padding in x) or over all
    /// but the last.
    Pass1,
    /// Pass 1 over the last column of blocks, reading the real width only.
    LastColumn,
    /// The second pass: sums the pass-1 target and writes L̄w to one texel.
    Pass2,
}

/// One generated shader.
#[derive(Clone, Debug, Serialize)]
pub struct Generated {
    /// File name, e.g. `pass1_unrolled_125x128.psh`.
    pub file: String,
    /// What the shader is for.
    pub role: Role,
    /// `unrolled`, `loop`, `row loop`, `nested loops`.
    pub form: String,
    /// Pass 1: texels per line × lines; pass 2: the target it sums.
    pub size: [u32; 2],
    /// From the cost model on the text below.
    pub slots: u64,
    /// Executed instructions per pixel, from the cost model on the text below.
    pub executed: u64,
    /// The checked listing, header and constants included.
    pub text: String,
}

/// One way to run the frame with the generated shaders.
#[derive(Clone, Debug, Serialize)]
pub struct Config {
    /// The pass-1 form.
    pub form: Pass1Form,
    /// Pass-1 block, texels per line × lines.
    pub block: [u32; 2],
    /// The pass-1 target, blocks across × blocks down.
    pub targets: [u32; 2],
    /// File name of the pass-1 shader (every column, or all but the last).
    pub pass1: String,
    /// The last-column shader, when the frame width is not a multiple of
    /// the block width.
    pub last_column: Option<String>,
    /// None when no pass-2 listing fits (a third pass would be needed).
    pub pass2: Option<String>,
    /// Padded samples with BORDER addressing in every column.
    pub padded_border: u64,
    /// Padded samples with the last-column shader (the padding in y).
    pub padded_last_column: u64,
    /// pass 1 × nx·ny + pass 2 (BORDER form), when pass 2 exists.
    pub total_executed: Option<u64>,
}

/// How the pass-1 block is chosen.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BlockChoice {
    /// `--block WxH`, for every form.
    Given(u32, u32),
    /// `--fit`: unrolled — the widest unroll that fits the slot limit, the
    /// tallest block that fits the executed limit and the rep range, then
    /// the smallest height with as many block rows; loop — the plan's best
    /// loop block for the frame.
    Fit,
}

/// A request to `ps30 unroll`.
#[derive(Clone, Debug)]
pub struct Request {
    /// The frame, width × height in pixels.
    pub frame: (u32, u32),
    /// Pass-1 forms and how to choose each one's block.
    pub picks: Vec<(Pass1Form, BlockChoice)>,
    /// Keep REPEAT_BLOCK in the output instead of expanding it.
    pub macros: bool,
    /// δ of log2(δ + L), baked into the shaders.
    pub delta: f64,
    /// Also write each configuration's last-column shader where the frame
    /// width is not a multiple of the block width (`ps30 unroll` does; a
    /// caller that pads every column with BORDER needs none).
    pub last_columns: bool,
}

/// Everything `ps30 unroll` produced.
#[derive(Clone, Debug, Serialize)]
pub struct Bundle {
    /// The frame, width × height in pixels.
    pub frame: [u32; 2],
    /// The limits the shaders were fitted to and checked against.
    pub profile: Profile,
    /// δ of log2(δ + L), baked into the shaders.
    pub delta: f64,
    /// Every shader written.
    pub shaders: Vec<Generated>,
    /// The ways to run the frame with them, one per pass-1 form and block.
    pub configs: Vec<Config>,
    /// How each block was chosen, in numbers.
    pub notes: Vec<String>,
    /// What was asked for and does not fit (exit 1).
    pub problems: Vec<String>,
}

fn f32_text(v: f64) -> String {
    let f = v as f32;
    if f != 0.0 && f.abs() < 1e-3 {
        format!("{f:e}")
    } else {
        format!("{f}")
    }
}

/// The set-up and line stepping, for headers.
const CORRECTIONS: [&str; 3] = [
    "Corrections to the article's listings, found by ps30's emulator cross-check (asm/corrected/):",
    "  each line ends with u = the block's start u; the article reset u to 0, the frame's left edge;",
    "  r3.yzw = (dv, start u, du) comes from one mad that replaces the article's `mov r2.w, c1.x`, so the fix costs no slot.",
];

struct Frame {
    w: u32,
    h: u32,
    delta: f64,
}

impl Frame {
    fn n(&self) -> u64 {
        self.w as u64 * self.h as u64
    }
}

fn checked_lines(profile: &Profile, slots: u64, executed: u64) -> Vec<String> {
    vec![
        format!(
            "Checked by ps30 (front end and cost model) under profile {}: {}.",
            profile.name,
            super::profile_text(profile)
        ),
        format!(
            "  slots     {} of {}",
            thousands(slots),
            thousands(profile.max_slots)
        ),
        format!(
            "  executed  {} per pixel, of {}",
            thousands(executed),
            thousands(profile.max_executed)
        ),
    ]
}

/// What one pass-1 listing is: its form and role, the block it serves, the
/// texels per line it reads (`taps`: the block width, or what the last
/// column has left) and, for the last column, the main shader's file.
struct Pass1Spec<'a> {
    form: Pass1Form,
    role: Role,
    block: (u32, u32),
    taps: u32,
    main_file: Option<&'a str>,
}

/// Writes, checks and heads one pass-1 listing.
fn pass1_shader(
    fitter: &mut Fitter<'_>,
    fr: &Frame,
    spec: &Pass1Spec,
    macros: bool,
) -> Result<Result<Generated, String>, GenError> {
    let profile = fitter.profile().clone();
    let (form, role, taps) = (spec.form, spec.role, spec.taps);
    let rows = spec.block.1;
    let file = match role {
        Role::LastColumn => format!("pass1_last_{}_{taps}x{rows}.psh", form.name()),
        _ => format!("pass1_{}_{taps}x{rows}.psh", form.name()),
    };
    let body = asm::render(&asm::pass1(form, taps, rows, Counts::Defined), macros);
    let c = super::check(&file, &body, &profile)?;
    if !c.fits() {
        return Ok(Err(format!(
            "pass 1, {} form, {taps}×{rows}: {}",
            form.name(),
            c.problems.join("; ")
        )));
    }
    let mut h = vec![spec.title(fr)];
    h.push("Generated: edit ps30's generator (src/jobs/gen/), not this file.".into());
    h.push(String::new());
    h.extend(checked_lines(&profile, c.slots, c.executed));
    h.push(String::new());
    h.extend(spec.description(fr));
    h.push(String::new());
    h.extend(CORRECTIONS.iter().map(|s| s.to_string()));
    h.push(String::new());
    h.push(spec.target_format(fr));
    h.extend(spec.application_sets(fr));
    let text = headed(&file, &h, &body)?;
    Ok(Ok(Generated {
        file,
        role,
        form: form.name().to_string(),
        size: [taps, rows],
        slots: c.slots,
        executed: c.executed,
        text,
    }))
}

impl Pass1Spec<'_> {
    /// The header's first line.
    fn title(&self, fr: &Frame) -> String {
        let (bw, bh) = self.block;
        let (taps, rows) = (self.taps, bh);
        match self.role {
            Role::LastColumn => format!(
                "{HEADER} luminance pass 1 for the LAST column of {} blocks, {} form, reading {taps}×{rows} texels, for a {} frame",
                size(bw, bh),
                self.form.name(),
                size(fr.w, fr.h)
            ),
            _ => format!(
                "{HEADER} luminance pass 1, {} form, {} blocks, for a {} frame",
                self.form.name(),
                size(bw, bh),
                size(fr.w, fr.h)
            ),
        }
    }

    /// What each pixel of the target sums, and for the last column how it
    /// is drawn.
    fn description(&self, fr: &Frame) -> Vec<String> {
        let (bw, bh) = self.block;
        let (taps, rows) = (self.taps, bh);
        let (nx, ny) = (fr.w.div_ceil(bw), fr.h.div_ceil(bh));
        let walk = match self.form {
            Pass1Form::Unrolled => format!(
                "rep i2 over {rows} lines, the line's {taps} texels unrolled (texld, dp4, log, add each)"
            ),
            Pass1Form::Loop => {
                format!("rep i2 over {rows} lines, rep i1 over the line's {taps} texels")
            }
        };
        match self.role {
            Role::LastColumn => vec![
                format!(
                    "Each pixel of column {} of the {} target sums log2|delta + L| over the {taps} texels per line the frame still has there",
                    nx - 1,
                    size(nx, ny)
                ),
                format!(
                    "({} − {}·{bw} = {taps}), not {bw}: no BORDER padding in x. {walk}.",
                    fr.w,
                    nx - 1
                ),
                format!(
                    "This is the article's \"non-unrolled version for the last column\"{}.",
                    if self.form == Pass1Form::Unrolled {
                        " — unrolled here, because the non-unrolled one would exceed the executed limit"
                    } else {
                        ""
                    }
                ),
                if nx > 1 {
                    format!(
                        "Draw: a second draw over target column x = {} only (a {} quad), after {} has drawn columns 0 … {}.",
                        nx - 1,
                        size(1, ny),
                        self.main_file.unwrap_or("the main pass-1 shader"),
                        nx - 2
                    )
                } else {
                    "Draw: the only pass-1 draw (the frame is narrower than one block).".to_string()
                },
            ],
            _ => vec![format!(
                "Each pixel (x, y) of the {} target sums log2|delta + L| over one {} block: {walk}.",
                size(nx, ny),
                size(bw, bh)
            )],
        }
    }

    /// The target formats that hold every block sum.
    fn target_format(&self, fr: &Frame) -> String {
        let samples = self.taps as u64 * self.block.1 as u64;
        if f16_holds(samples, fr.delta) {
            format!(
                "Target format: R32F or A16B16G16R16F (|sum| ≤ {} × {:.2} ≤ 65,504).",
                thousands(samples),
                plan::largest_term(fr.delta)
            )
        } else {
            format!(
                "Target format: D3DFMT_R32F. An f16 target cannot hold every sum: {} samples × up to {:.2} exceeds 65,504.",
                thousands(samples),
                plan::largest_term(fr.delta)
            )
        }
    }

    /// The inputs, constants and sampler the application sets.
    fn application_sets(&self, fr: &Frame) -> Vec<String> {
        let (bw, bh) = self.block;
        let (taps, rows) = (self.taps, bh);
        let nx = fr.w.div_ceil(bw);
        let x0 = match self.role {
            Role::LastColumn => format!("{}·{bw}", nx - 1),
            _ => format!("x·{bw}"),
        };
        vec![
            "The application sets:".into(),
            format!(
                "  v0.xy = (({x0} + 0.5)/{}, (y·{bh} + 0.5)/{}) at target pixel (x, y): the centre of the block's top-left texel",
                fr.w, fr.h
            ),
            "  c0.z  = 0".into(),
            format!(
                "  c1    = (1/{}, 1/{}, 0, 1) = ({}, {}, 0, 1)",
                fr.w,
                fr.h,
                f32_text(1.0 / fr.w as f64),
                f32_text(1.0 / fr.h as f64)
            ),
            format!(
                "  c3    = (0.27, 0.67, 0.06, sqrt(delta)); delta = {} gives c3.w = {}",
                fr.delta as f32,
                f32_text((fr.delta as f32).sqrt() as f64)
            ),
            "  s0    = the frame: point filtering, BORDER addressing, border colour 0".into(),
            match self.form {
                Pass1Form::Unrolled => {
                    format!("  i2    = nothing to set: `defi i2, {rows}` in the shader")
                }
                Pass1Form::Loop => format!(
                    "  i1, i2 = nothing to set: `defi i1, {taps}` and `defi i2, {rows}` in the shader"
                ),
            },
        ]
    }
}

/// `body` under the comment header `h`. Each entry of `h` becomes one line
/// after `//`, and the front end takes a line's code to be what precedes
/// `//` (lines end at `\n` only), so an entry without a line break is a
/// comment whatever it says: the program, and so its figures (checked on
/// `body`), are unchanged.
fn headed(file: &str, h: &[String], body: &str) -> Result<String, GenError> {
    if let Some(l) = h.iter().find(|l| l.contains('\n')) {
        return Err(GenError(format!(
            "{file}: a header line holds a line break (a bug): {l:?}"
        )));
    }
    Ok(format!("{}{body}", asm::comment_block(h)))
}

/// Writes, checks and heads one pass-2 listing; `uses` lists (what, P) for
/// each configuration that reads this target, for the c0.y values.
fn pass2_shader(
    fitter: &mut Fitter<'_>,
    fr: &Frame,
    targets: (u32, u32),
    uses: &[(String, u64)],
    macros: bool,
) -> Result<Result<Generated, String>, GenError> {
    let profile = fitter.profile().clone();
    let (nx, ny) = targets;
    let outcome = fitter.pass2(nx, ny)?;
    let Some(choice) = outcome.choice else {
        return Ok(Err(format!(
            "pass 2 for a {} target: no listing fits ({}); a third pass would be needed, which ps30 does not generate",
            size(nx, ny),
            outcome.rejected.join("; ")
        )));
    };
    let file = format!("pass2_{nx}x{ny}.psh");
    let body = asm::render(&asm::pass2(choice.form, nx, ny), macros);
    let c = super::check(&file, &body, &profile)?;
    if !c.fits() || (c.slots, c.executed) != (choice.slots, choice.executed) {
        return Err(GenError(format!(
            "{file}: the pass-2 listing changed between the fit and the output"
        )));
    }
    let n = fr.n();
    let mut h = vec![
        format!(
            "{HEADER} luminance pass 2, {}, for the {} intermediate target of a {} frame",
            choice.form.name(),
            size(nx, ny),
            size(fr.w, fr.h)
        ),
        "Generated: edit ps30's generator (src/jobs/gen/), not this file.".into(),
        String::new(),
    ];
    h.extend(checked_lines(&profile, c.slots, c.executed));
    h.push(String::new());
    h.push(format!(
        "Sums pass 1's {} target row by row ({}), subtracts the BORDER padding and divides by N",
        size(nx, ny),
        match choice.form {
            Pass2Form::Unrolled => "fully unrolled, as the article's listing".to_string(),
            Pass2Form::RowLoop => format!(
                "rep i0 over {ny} rows, each row's {nx} texels unrolled: fully unrolled would not fit"
            ),
            Pass2Form::Nested => format!(
                "rep i0 over {ny} rows, rep i1 over {nx} texels: unrolled rows would not fit"
            ),
        }
    ));
    h.push("with one mad, then converts back with exp: oC0 = the log-average luminance.".into());
    h.push(String::new());
    h.push("Corrections to the article's listing, found by ps30's emulator cross-check (asm/corrected/):".into());
    h.push("  c0.y subtracts the padded samples' log2(delta) terms (the article kept them: L̄w × 0.505 at 1280×1024);".into());
    h.push(
        "  rows restart at the start u kept in r3.z (a texel centre), not at u = 0 (a texel edge)."
            .into(),
    );
    h.push(String::new());
    h.push("Draw: a 1×1 target. The application sets:".into());
    h.push(format!(
        "  v0.xy = (0.5/{nx}, 0.5/{ny}) = ({}, {}): the centre of texel (0, 0)",
        f32_text(0.5 / nx as f64),
        f32_text(0.5 / ny as f64)
    ));
    h.push(format!(
        "  c0    = (1/N, -P·log2(delta)/N, 0, 0), N = {}·{} = {} pixels, P = padded samples:",
        fr.w,
        fr.h,
        thousands(n)
    ));
    h.push(format!("          c0.x = {}", f32_text(1.0 / n as f64)));
    for (what, p) in uses {
        h.push(format!(
            "          c0.y = {} with {what} (P = {}, delta = {})",
            f32_text(-(*p as f64) * fr.delta.log2() / n as f64),
            thousands(*p),
            fr.delta as f32
        ));
    }
    h.push(format!(
        "  c1    = (1/{nx}, 1/{ny}, 0, 1) = ({}, {}, 0, 1)",
        f32_text(1.0 / nx as f64),
        f32_text(1.0 / ny as f64)
    ));
    h.push("  s0    = pass 1's target, point filtering".into());
    if choice.form != Pass2Form::Unrolled {
        h.push("  i0, i1 = nothing to set: defined in the shader (defi)".into());
    }
    let text = headed(&file, &h, &body)?;
    Ok(Ok(Generated {
        file,
        role: Role::Pass2,
        form: choice.form.name().to_string(),
        size: [nx, ny],
        slots: c.slots,
        executed: c.executed,
        text,
    }))
}

/// A pass-1 form and its block.
type Pick = (Pass1Form, (u32, u32));

/// The state of one `generate`: the fitter, the frame, and what is
/// gathered for the [`Bundle`] in order.
struct Generator<'p> {
    fitter: Fitter<'p>,
    fr: Frame,
    macros: bool,
    last_columns: bool,
    notes: Vec<String>,
    problems: Vec<String>,
    shaders: Vec<Generated>,
    configs: Vec<Config>,
    /// Pass-2 users: targets → (description, padded samples).
    pass2_uses: BTreeMap<(u32, u32), Vec<(String, u64)>>,
}

/// Generates the shaders a request asks for.
pub fn generate(req: &Request, profile: &Profile) -> Result<Bundle, GenError> {
    let mut g = Generator {
        fitter: Fitter::new(profile),
        fr: Frame {
            w: req.frame.0,
            h: req.frame.1,
            delta: req.delta,
        },
        macros: req.macros,
        last_columns: req.last_columns,
        notes: Vec::new(),
        problems: Vec::new(),
        shaders: Vec::new(),
        configs: Vec::new(),
        pass2_uses: BTreeMap::new(),
    };
    for (form, block) in g.choose_blocks(req)? {
        g.configure(form, block)?;
    }
    g.pass2_shaders()?;
    Ok(Bundle {
        frame: [g.fr.w, g.fr.h],
        profile: profile.clone(),
        delta: req.delta,
        shaders: g.shaders,
        configs: g.configs,
        notes: g.notes,
        problems: g.problems,
    })
}

impl Generator<'_> {
    /// The blocks a request asks for, one per form, with notes on how they
    /// were chosen; forms that cannot be fitted go to `problems`.
    fn choose_blocks(&mut self, req: &Request) -> Result<Vec<Pick>, GenError> {
        let mut out: Vec<Pick> = Vec::new();
        for &(form, choice) in &req.picks {
            let block = match choice {
                BlockChoice::Given(bw, bh) => match self.fitter.pass1_unwritable(form, bw, bh) {
                    Some(why) => {
                        self.problems
                            .push(format!("pass 1, {} form, {bw}×{bh}: {why}", form.name()));
                        None
                    }
                    None => Some((bw, bh)),
                },
                BlockChoice::Fit if form == Pass1Form::Unrolled => self.fit_unrolled(req.frame)?,
                BlockChoice::Fit => self.fit_loop(req, form)?,
            };
            // The same block asked for twice is generated once.
            if let Some(block) = block {
                if !out.contains(&(form, block)) {
                    out.push((form, block));
                }
            }
        }
        Ok(out)
    }

    /// `--fit` for the unrolled form: the widest unroll within the slot
    /// limit, the tallest block within the executed limit, then the
    /// smallest height with as many block rows.
    fn fit_unrolled(&mut self, (w, h): (u32, u32)) -> Result<Option<(u32, u32)>, GenError> {
        let form = Pass1Form::Unrolled;
        let fitter = &mut self.fitter;
        let Some(n) = fitter.widest(form, w)? else {
            self.problems.push(format!(
                "the unrolled form does not fit this profile even for one texel per line: {}",
                fitter
                    .pass1(form, 1, 1)?
                    .map(|c| c.problems.join("; "))
                    .or_else(|| fitter.pass1_unwritable(form, 1, 1))
                    .unwrap_or_default()
            ));
            return Ok(None);
        };
        let at = fitter.pass1(form, n, 1)?.map(|c| c.slots).unwrap_or(0);
        let mut why = format!(
            "widest unroll: {n} texels per line, {} slots of {}",
            thousands(at),
            thousands(fitter.profile().max_slots)
        );
        if n < w {
            match fitter.pass1(form, n + 1, 1)? {
                Some(c) => why.push_str(&format!(
                    "; {} would take {} slots",
                    n + 1,
                    thousands(c.slots)
                )),
                None => why.push_str(&format!(
                    "; {} {}",
                    n + 1,
                    fitter.pass1_unwritable(form, n + 1, 1).unwrap_or_default()
                )),
            }
        } else {
            why.push_str(" (the frame's whole width)");
        }
        self.notes.push(why);
        let Some(tall) = fitter.tallest(form, n, h)? else {
            self.problems
                .push(format!("no block {n} texels wide fits the executed limit"));
            return Ok(None);
        };
        let exec = |f: &mut Fitter<'_>, r: u32| -> Result<Option<u64>, GenError> {
            Ok(f.pass1(form, n, r)?.map(|c| c.executed))
        };
        let mut why = format!(
            "tallest block: {}, {} executed of {}",
            lines(tall),
            exec(fitter, tall)?.map_or("?".into(), thousands),
            thousands(fitter.profile().max_executed)
        );
        if tall < h {
            match exec(fitter, tall + 1)? {
                Some(e) => why.push_str(&format!(
                    "; {} would take {}",
                    lines(tall + 1),
                    thousands(e)
                )),
                None => why.push_str(&format!(
                    "; {}: {}",
                    lines(tall + 1),
                    fitter
                        .pass1_unwritable(form, n, tall + 1)
                        .unwrap_or_default()
                )),
            }
        } else {
            why.push_str(" (the frame's whole height)");
        }
        let short = balanced(h, tall);
        if short != tall {
            why.push_str(&format!(
                "; {} need {} block rows either way, so {} (padding {} instead of {})",
                lines(h),
                h.div_ceil(tall),
                lines(short),
                lines(h.div_ceil(short) * short - h),
                h.div_ceil(tall) * tall - h
            ));
        }
        self.notes.push(why);
        Ok(Some((n, short)))
    }

    /// `--fit` for the loop form: the plan's best loop block for the frame.
    fn fit_loop(&mut self, req: &Request, form: Pass1Form) -> Result<Option<(u32, u32)>, GenError> {
        let (w, h) = req.frame;
        let mut plan_notes = Vec::new();
        let mut cands = plan::candidates(
            &mut self.fitter,
            req.frame,
            req.delta,
            form,
            &mut plan_notes,
        )?;
        cands.sort_by_key(|c| {
            (
                c.passes,
                c.total_executed.unwrap_or(u64::MAX),
                c.padded_samples,
                std::cmp::Reverse(c.block[0]),
            )
        });
        match cands.first() {
            Some(c) => {
                self.notes.push(format!(
                    "loop form: the plan's best loop block for {}: {}×{} ({} executed for the frame{})",
                    size(w, h),
                    c.block[0],
                    c.block[1],
                    c.total_executed.map_or("—".into(), thousands),
                    if c.passes == 3 { ", 3 passes" } else { "" }
                ));
                Ok(Some((c.block[0], c.block[1])))
            }
            None => {
                self.problems.push(format!(
                    "the loop form does not fit this profile: {}",
                    plan_notes.join("; ")
                ));
                Ok(None)
            }
        }
    }

    /// Adds `shader` unless a shader of the same file is there already.
    fn add_shader(&mut self, shader: Generated) {
        if !self.shaders.iter().any(|s| s.file == shader.file) {
            self.shaders.push(shader);
        }
    }

    /// One configuration: pass 1 for `form` and `(bw, bh)`, its last-column
    /// shader when the width needs one (and the request wants them), and
    /// its use of a pass-2 target.
    fn configure(&mut self, form: Pass1Form, (bw, bh): (u32, u32)) -> Result<(), GenError> {
        let spec = Pass1Spec {
            form,
            role: Role::Pass1,
            block: (bw, bh),
            taps: bw,
            main_file: None,
        };
        let main = match pass1_shader(&mut self.fitter, &self.fr, &spec, self.macros)? {
            Ok(g) => g,
            Err(p) => {
                self.problems.push(p);
                return Ok(());
            }
        };
        self.add_shader(main.clone());
        let fr = &self.fr;
        let (nx, ny) = (fr.w.div_ceil(bw), fr.h.div_ceil(bh));
        let covered_y = ny as u64 * bh as u64;
        let padded_border = nx as u64 * bw as u64 * covered_y - fr.n();
        let padded_last = fr.w as u64 * covered_y - fr.n();
        let real = fr.w - (nx - 1) * bw;
        let last_file = if real < bw && self.last_columns {
            self.last_column(&main.file, (bw, bh), real)?
        } else {
            None
        };
        let uses = self.pass2_uses.entry((nx, ny)).or_default();
        uses.push((
            format!("{} {} blocks and BORDER padding", form.name(), size(bw, bh)),
            padded_border,
        ));
        if let Some(l) = &last_file {
            uses.push((
                format!("{} {} blocks and {l}", form.name(), size(bw, bh)),
                padded_last,
            ));
        }
        self.configs.push(Config {
            form,
            block: [bw, bh],
            targets: [nx, ny],
            pass1: main.file.clone(),
            last_column: last_file,
            pass2: None,
            padded_border,
            padded_last_column: padded_last,
            total_executed: None,
        });
        Ok(())
    }

    /// The last-column shader after `main_file`, reading `real` texels per
    /// line: the article's "non-unrolled version" first, the unrolled one
    /// when the loop would exceed the limits. Returns its file.
    fn last_column(
        &mut self,
        main_file: &str,
        block: (u32, u32),
        real: u32,
    ) -> Result<Option<String>, GenError> {
        let bh = block.1;
        let mut last = None;
        let mut why_not = Vec::new();
        for lf in [Pass1Form::Loop, Pass1Form::Unrolled] {
            if self.fitter.pass1_unwritable(lf, real, bh).is_some() {
                why_not.push(format!(
                    "{}: {}",
                    lf.name(),
                    self.fitter
                        .pass1_unwritable(lf, real, bh)
                        .unwrap_or_default()
                ));
                continue;
            }
            let spec = Pass1Spec {
                form: lf,
                role: Role::LastColumn,
                block,
                taps: real,
                main_file: Some(main_file),
            };
            match pass1_shader(&mut self.fitter, &self.fr, &spec, self.macros)? {
                Ok(g) => {
                    last = Some(g);
                    break;
                }
                Err(p) => why_not.push(p),
            }
        }
        match last {
            Some(g) => {
                if g.form != Pass1Form::Loop.name() {
                    self.notes.push(format!(
                        "last column of {}: the non-unrolled version does not fit ({}), so it is unrolled",
                        main_file,
                        why_not.join("; ")
                    ));
                }
                let file = g.file.clone();
                self.add_shader(g);
                Ok(Some(file))
            }
            None => {
                self.notes.push(format!(
                    "no last-column shader for {}: {}",
                    main_file,
                    why_not.join("; ")
                ));
                Ok(None)
            }
        }
    }

    /// One pass-2 shader per target the configurations use, and each
    /// configuration's executed total.
    fn pass2_shaders(&mut self) -> Result<(), GenError> {
        for (targets, uses) in &self.pass2_uses {
            match pass2_shader(&mut self.fitter, &self.fr, *targets, uses, self.macros)? {
                Ok(g) => {
                    for c in self
                        .configs
                        .iter_mut()
                        .filter(|c| (c.targets[0], c.targets[1]) == *targets)
                    {
                        c.pass2 = Some(g.file.clone());
                        let p1 = self
                            .shaders
                            .iter()
                            .find(|s| s.file == c.pass1)
                            .map_or(0, |s| s.executed);
                        c.total_executed =
                            Some(p1 * targets.0 as u64 * targets.1 as u64 + g.executed);
                    }
                    self.shaders.push(g);
                }
                Err(p) => self.problems.push(p),
            }
        }
        Ok(())
    }
}

/// The frame sizes whose shaders are kept in `asm/generated/`.
pub const FRAMES: [(u32, u32); 6] = [
    (640, 480),
    (1024, 768),
    (1280, 1024),
    (1920, 1080),
    (2560, 1440),
    (3840, 2160),
];

/// The δ the committed shaders' headers quote constants for.
pub const DEFAULT_DELTA: f64 = crate::jobs::luminance::reference::DEFAULT_DELTA;

/// The committed set for one frame: `ps30 unroll --fit --frame WxH` plus
/// the plan's recommended configuration when it differs, under the ps_3_0
/// profile.
pub fn frame_set(frame: (u32, u32)) -> Result<(Bundle, plan::Plan), GenError> {
    let profile = super::fitting_profile();
    let p = plan::plan(frame, &profile, DEFAULT_DELTA)?;
    let mut picks = vec![
        (Pass1Form::Unrolled, BlockChoice::Fit),
        (Pass1Form::Loop, BlockChoice::Fit),
    ];
    if let Some(r) = p
        .recommended
        .as_ref()
        .and_then(|n| p.candidates.iter().find(|c| &c.name == n))
    {
        picks.push((r.variant, BlockChoice::Given(r.block[0], r.block[1])));
    }
    let bundle = generate(
        &Request {
            frame,
            picks,
            macros: false,
            delta: DEFAULT_DELTA,
            last_columns: true,
        },
        &profile,
    )?;
    Ok((bundle, p))
}

/// The directory name of a frame's set: `1280x1024`.
pub fn frame_dir(frame: (u32, u32)) -> String {
    format!("{}x{}", frame.0, frame.1)
}

/// Every committed file: (path relative to `asm/generated/`, contents),
/// with the per-frame bundles and plans.
pub struct GeneratedSet {
    /// (path relative to `asm/generated/`, contents), sorted by path.
    pub files: Vec<(String, String)>,
    /// Per frame: its size, its bundle and its plan.
    pub frames: Vec<((u32, u32), Bundle, plan::Plan)>,
}

/// Builds the whole committed set in memory.
pub fn generated_set() -> Result<GeneratedSet, GenError> {
    let mut files = Vec::new();
    let mut frames = Vec::new();
    for frame in FRAMES {
        let (bundle, p) = frame_set(frame)?;
        if !bundle.problems.is_empty() {
            return Err(GenError(format!(
                "{}: {}",
                frame_dir(frame),
                bundle.problems.join("; ")
            )));
        }
        for g in &bundle.shaders {
            files.push((format!("{}/{}", frame_dir(frame), g.file), g.text.clone()));
        }
        frames.push((frame, bundle, p));
    }
    files.sort_unstable();
    Ok(GeneratedSet { files, frames })
}

/// The first words of every generated shader's header.
const HEADER: &str = "ps30 unroll:";

/// The start of the first line of every file the generator writes (the
/// header as a comment): regeneration removes only files that begin with it.
pub const MARK: &str = "// ps30 unroll:";

/// A generated file is a few kilobytes; a larger one is not one of them.
const MAX_GENERATED_BYTES: u64 = 1 << 20;

/// The text of a regular file (through links) of at most
/// [`MAX_GENERATED_BYTES`]; `None` for anything else (missing, a FIFO, a
/// device, too large, not UTF-8), which is never read.
fn read_regular(path: &Path) -> Option<String> {
    let meta = std::fs::metadata(path).ok()?;
    if !meta.is_file() || meta.len() > MAX_GENERATED_BYTES {
        return None;
    }
    std::fs::read_to_string(path).ok()
}

/// Whether `path` is a regular file (not a link) that the generator wrote,
/// by its first line.
fn written_by_generator(path: &Path) -> bool {
    std::fs::symlink_metadata(path).is_ok_and(|m| m.is_file())
        && read_regular(path).is_some_and(|t| t.starts_with(MARK))
}

/// Lists what differs between the committed set under `dir` and `set`:
/// stale or missing files, and `.psh` files the generator does not write.
pub fn stale_files(dir: &Path, set: &GeneratedSet) -> Vec<String> {
    let mut problems = Vec::new();
    for (rel, text) in &set.files {
        let path = dir.join(rel);
        match read_regular(&path) {
            Some(t) if &t == text => {}
            Some(_) => problems.push(format!(
                "{} is stale: the generator now writes something else (run `ps30 verify --regenerate`)",
                path.display()
            )),
            None if path.exists() => problems.push(format!(
                "{} is not a regular text file the generator could have written (replace it, or run `ps30 verify --regenerate`)",
                path.display()
            )),
            None => problems.push(format!(
                "{} is missing (run `ps30 verify --regenerate`)",
                path.display()
            )),
        }
    }
    for extra in existing_psh(dir) {
        if !set.files.iter().any(|(rel, _)| *rel == extra) {
            let path = dir.join(&extra);
            problems.push(if written_by_generator(&path) {
                format!("{} is not a file the generator writes now (run `ps30 verify --regenerate` to remove it)", path.display())
            } else {
                format!("{} is not a file the generator writes, nor one it wrote (remove it yourself)", path.display())
            });
        }
    }
    problems
}

/// `.psh` files under `dir`, one level of frame directories down, relative.
/// Directories reached through symbolic links are not looked into.
pub fn existing_psh(dir: &Path) -> Vec<String> {
    let mut out = Vec::new();
    let Ok(frames) = std::fs::read_dir(dir) else {
        return out;
    };
    for f in frames.flatten() {
        if !f.file_type().is_ok_and(|t| t.is_dir()) {
            continue;
        }
        let Ok(files) = std::fs::read_dir(f.path()) else {
            continue;
        };
        for e in files.flatten() {
            let name = e.file_name().to_string_lossy().into_owned();
            if name.ends_with(".psh") {
                out.push(format!("{}/{name}", f.file_name().to_string_lossy()));
            }
        }
    }
    out.sort_unstable();
    out
}

/// Rewrites the committed set under `dir`, all files or none (see
/// [`crate::core::output::Batch`]), then removes the `.psh` files the
/// generator no longer writes — only regular files whose first line is the
/// generator's [`MARK`], only in the frame directories the set writes into,
/// never through a symbolic link. Returns the paths written and removed.
pub fn write_set(dir: &Path, set: &GeneratedSet) -> Result<(Vec<String>, Vec<String>), String> {
    let mut batch = crate::core::output::Batch::new(dir)?;
    let mut frames: Vec<&str> = set
        .files
        .iter()
        .filter_map(|(rel, _)| rel.split('/').next())
        .collect();
    frames.dedup();
    for frame in &frames {
        let d = dir.join(frame);
        if std::fs::symlink_metadata(&d).is_ok_and(|m| m.file_type().is_symlink()) {
            return Err(format!(
                "{}: is a symbolic link; ps30 writes and removes generated shaders only in real directories",
                d.display()
            ));
        }
        batch.directory(&d)?;
    }
    let mut written = Vec::new();
    for (rel, text) in &set.files {
        let path = dir.join(rel);
        if read_regular(&path).as_deref() != Some(text.as_str()) {
            batch.write_bytes(&path, text.as_bytes())?;
            written.push(path.display().to_string());
        }
    }
    batch.commit()?;
    let mut removed = Vec::new();
    for extra in existing_psh(dir) {
        let in_frame = extra.split('/').next().is_some_and(|f| frames.contains(&f));
        let path = dir.join(&extra);
        if in_frame
            && !set.files.iter().any(|(rel, _)| *rel == extra)
            && written_by_generator(&path)
        {
            std::fs::remove_file(&path).map_err(|e| format!("{}: {e}", path.display()))?;
            removed.push(path.display().to_string());
        }
    }
    Ok((written, removed))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_header_is_comments_only() {
        let body = "ps_3_0\nmov oC0, c0\n";
        let h = [
            "title".to_string(),
            String::new(),
            "mov oC0, c1".to_string(),
        ];
        let text = headed("t.psh", &h, body).unwrap();
        assert_eq!(text, "// title\n//\n// mov oC0, c1\nps_3_0\nmov oC0, c0\n");
        let figures = |t: &str| {
            let c = super::super::check("t.psh", t, &Profile::ps_3_0()).unwrap();
            (c.slots, c.executed)
        };
        assert_eq!(figures(&text), figures(body));
        let broken = ["title\nmov oC0, c1".to_string()];
        let err = headed("t.psh", &broken, body).unwrap_err();
        assert!(err.0.contains("line break"), "{}", err.0);
    }
}
