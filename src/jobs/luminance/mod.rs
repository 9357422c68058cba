//! The luminance pipeline of the article, run in the emulator and
//! cross-checked against the f64 CPU reference.
//!
//! Pass 1 draws a `⌈W/bw⌉ × ⌈H/bh⌉` target; each pixel sums log2|δ + L| over
//! one `bw × bh` block of the image (BORDER addressing returns black outside
//! the image). Pass 2 draws a 1×1 target that sums pass 1's target, divides
//! by N = W·H and converts back with `exp`. Both passes are ordinary ps_3_0
//! shaders loaded through the front end, so the article's listings, the
//! corrected ones and generated ones all run through the same path.
//!
//! # Tolerances
//!
//! Every comparison has a bound derived from the arithmetic, computed per
//! block by [`pass1_bounds`]:
//!
//! * each term: the shader computes δ + L with `dp4` in f32 — four products
//!   and three additions, each rounded (relative error u = 2⁻²⁴), plus the
//!   f32 rounding of the weights 0.27, 0.67, 0.06 and of √δ and its square:
//!   |dp4 − (δ + L)| ≤ 8u·A with A = 0.27|R| + 0.67|G| + 0.06|B| + δ, hence
//!   |Δlog2| ≤ 8u·A / (|δ + L|·ln 2) (first order; a term whose bound
//!   reaches |δ + L|/2 is ill-conditioned and reported as such), plus the
//!   emulator's log2 error (< 1 ulp of the result);
//! * the accumulation: each `add` rounds the running sum, so the sum is off
//!   by at most u·Σₖ|Sₖ| over the partial sums Sₖ in the shader's order;
//! * storage: an f16 target rounds the block sum to half precision
//!   (≤ ½ ulp₁₆), an f32 target stores it exactly;
//! * pass 2 adds its own accumulation bound, the rounding of 1/N and of the
//!   product (2u relative), and `exp`'s error (≤ 1 ulp) and storage.
//!
//! The bounds are first order in u; the factor (1 + n·u) that covers the
//! second-order terms is applied explicitly where the sums are formed.

use crate::core::cost::{self, Environment, Profile, Range};
use crate::core::diag::SourceFile;
use crate::core::emu::{self, Address, Constants, Draw, Filter, LinearInput, SamplerState};
use crate::core::float_rules::FloatRules;
use crate::core::gpu::TargetKind;
use crate::core::image::{HdrImage, RenderTarget, TargetFormat, Texture};
use crate::core::isa::Opcode;
use crate::core::load::{self, Options};
use crate::jobs::backend::{self, Backend, DrawError};
pub mod reference;

use reference::{BlockFold, Policy, Tiling, AHEAD_RUN};
use serde::Serialize;

/// f32 unit roundoff.
const U32: f64 = f32::EPSILON as f64 / 2.0;

/// A shader source to run: assembly text, or a compiled shader as its
/// listing ([`load::source_file`]).
#[derive(Clone, Debug)]
pub struct ShaderSource {
    /// The source, named: text, or a compiled shader's listing.
    pub file: SourceFile,
}

impl ShaderSource {
    /// Assembly text.
    pub fn new(name: impl Into<String>, text: impl Into<String>) -> ShaderSource {
        ShaderSource {
            file: SourceFile::new(name, text),
        }
    }

    /// Any source, text or compiled.
    pub fn from_file(file: SourceFile) -> ShaderSource {
        ShaderSource { file }
    }

    /// The source's name (a bundled name or the file's path).
    pub fn name(&self) -> &str {
        &self.file.name
    }
}

/// Settings of one pipeline run.
#[derive(Clone, Debug)]
pub struct Settings {
    /// Pixels per pass-1 block, (width, height): the article's 125 × 128 by
    /// default.
    pub block: (u32, u32),
    /// δ of log2(δ + L), set in the shader's constants.
    pub delta: f32,
    /// The pass-1 target's format (R32F by default).
    pub format: TargetFormat,
    /// How the reference treats negative and non-finite luminance; the
    /// default, `Abs`, is what the `log` instruction computes.
    pub policy: Policy,
    /// Worker threads for the emulator (`None`: all cores).
    pub threads: Option<usize>,
    /// The emulator's bounds (executed slots per pixel, target size).
    pub limits: emu::EmuLimits,
    /// Who draws the passes.
    pub backend: Backend,
    /// The special values of the arithmetic.
    pub float_rules: FloatRules,
}

impl Default for Settings {
    fn default() -> Settings {
        Settings {
            block: (125, 128),
            delta: reference::DEFAULT_DELTA as f32,
            format: TargetFormat::R32F,
            policy: Policy::ABS,
            threads: None,
            limits: emu::EmuLimits::default(),
            backend: Backend::Emulator,
            float_rules: FloatRules::Hardware,
        }
    }
}

/// Why a pipeline run could not be made (not a disagreement: those are
/// results).
#[derive(Debug)]
pub enum PipelineError {
    /// A shader does not load; its diagnostics are inside.
    Source(crate::core::diag::SourceError),
    /// The cost model cannot analyse a pass.
    Cost(String),
    /// A pass's draw failed, on the emulator or on a GPU.
    Draw(DrawError),
    /// The f64 reference cannot be computed for the block layout.
    Reference(String),
    /// The shader and the requested block do not fit together.
    Mismatch(String),
}

impl std::fmt::Display for PipelineError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            PipelineError::Source(e) => write!(f, "{e}"),
            PipelineError::Cost(e) | PipelineError::Reference(e) | PipelineError::Mismatch(e) => {
                f.write_str(e)
            }
            PipelineError::Draw(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for PipelineError {}

/// The float constants the pipeline sets for pass 1 (c0, c1, c3, and c2 =
/// 0) and pass 2 (c0, c1), and the integer constants of pass 1 (i1, i2,
/// and i0 = 0): a shader that reads any other one reads a register nobody
/// set (see [`crate::core::audit`]).
const PASS1_FLOATS: [u32; 4] = [0, 1, 2, 3];
const PASS1_INTS: [u32; 3] = [0, 1, 2];
const PASS2_FLOATS: [u32; 2] = [0, 1];

/// Loads a shader through the front end, with `-D` style defines, and
/// refuses one that reads a constant the pass does not set.
fn load(
    src: &ShaderSource,
    defines: &[(&str, u64)],
    given: &crate::core::audit::Given,
) -> Result<load::Loaded, PipelineError> {
    let mut opts = Options::default();
    for (k, v) in defines {
        opts.defines.insert(k.to_string(), *v);
    }
    let loaded = load::load(src.file.clone(), &opts).map_err(PipelineError::Source)?;
    refuse_unset(&loaded, given).map_err(PipelineError::Mismatch)?;
    Ok(loaded)
}

/// An error naming the registers `loaded` reads that `given` does not set
/// and the shader does not define.
pub fn refuse_unset(
    loaded: &load::Loaded,
    given: &crate::core::audit::Given,
) -> Result<(), String> {
    use crate::core::audit;
    let found = audit::audit(&loaded.shader, &loaded.defines_used, given);
    let unset = audit::unset_names(&found);
    if unset.is_empty() {
        return Ok(());
    }
    let set: Vec<String> = given
        .floats
        .iter()
        .map(|c| format!("c{c}"))
        .chain(given.ints.iter().map(|i| format!("i{i}")))
        .chain(given.bools.iter().map(|b| format!("b{b}")))
        .collect();
    let set: Vec<&str> = set.iter().map(String::as_str).collect();
    Err(format!(
        "{} reads {}, which this pass does not set (it sets {}) and the shader does not define",
        loaded.file.name,
        crate::core::numbers::list(&unset),
        crate::core::numbers::list(&set)
    ))
}

/// One pass's cost: static analysis next to what the emulator counted.
#[derive(Clone, Debug, Serialize)]
pub struct PassCost {
    /// The shader's name.
    pub shader: String,
    /// Instruction slots, from the cost model.
    pub slots: u64,
    /// Executed slots per pixel from the cost model.
    pub executed_static: Range,
    /// Executed slots per pixel the emulator counted (min, max over
    /// pixels); `None` when a GPU drew the pass (it counts nothing).
    pub executed_emulated: Option<Range>,
    /// Warnings from the draw's quads (divergent gradients, a level of
    /// detail far from level 0 on a texture that has only level 0): see
    /// [`crate::jobs::profile`].
    pub findings: Vec<crate::core::emu::findings::Finding>,
    /// Whether every pixel's count lies in the static range (true when
    /// nothing was counted).
    pub counts_agree: bool,
    /// Whether the slots and the executed count fit the ps_3_0 limits.
    pub within_limits: bool,
}

/// The cross-check of one pass-1 block.
#[derive(Clone, Debug, Serialize)]
pub struct BlockCheck {
    /// Block column, from the left.
    pub x: u32,
    /// Block row, from the top.
    pub y: u32,
    /// What the emulated target holds.
    pub emulated: f64,
    /// The f64 reference sum of log2|δ + L| over the block (BORDER padding).
    pub reference: f64,
    /// |emulated − reference|.
    pub difference: f64,
    /// The derived bound on |emulated − reference|.
    pub tolerance: f64,
    /// Whether `difference` is within a finite `tolerance`, or both sides are
    /// the same special value.
    pub agree: bool,
    /// The target format cannot hold the block's sum (f16 beyond ±65504).
    pub overflow: bool,
}

/// A scalar comparison with its derived bound.
#[derive(Clone, Debug, Serialize)]
pub struct Comparison {
    /// The value the passes produced.
    pub emulated: f64,
    /// The value computed in f64.
    pub reference: f64,
    /// |emulated − reference|; 0 when both are the same special value, ∞ when
    /// only one is non-finite or they differ.
    pub difference: f64,
    /// The derived bound on `difference` (0 for non-finite values).
    pub tolerance: f64,
    /// Whether `difference` is within a finite `tolerance`, or both sides are
    /// the same special value.
    pub agree: bool,
}

impl Comparison {
    fn new(emulated: f64, reference: f64, tolerance: f64) -> Comparison {
        if !(emulated.is_finite() && reference.is_finite()) {
            // Non-finite pixels make non-finite sums on the GPU and in the
            // reference alike: they agree only if they are the same special
            // value (both NaN, or the same infinity).
            let same = (emulated.is_nan() && reference.is_nan()) || emulated == reference;
            return Comparison {
                emulated,
                reference,
                difference: if same { 0.0 } else { f64::INFINITY },
                tolerance: 0.0,
                agree: same,
            };
        }
        let difference = (emulated - reference).abs();
        Comparison {
            emulated,
            reference,
            difference,
            tolerance,
            // A value the target format cannot hold (f16 overflow) has no
            // finite bound: that is a disagreement, never a pass.
            agree: difference <= tolerance && tolerance.is_finite(),
        }
    }
}

/// Everything a run computed.
#[derive(Clone, Debug, Serialize)]
pub struct LuminanceRun {
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
    /// Pixels per pass-1 block, (width, height).
    pub block: (u32, u32),
    /// The pass-1 target's size in blocks, (⌈W / bw⌉, ⌈H / bh⌉).
    pub targets: (u32, u32),
    /// The pass-1 target's format.
    pub target_format: TargetFormat,
    /// δ of log2(δ + L), as the shaders received it.
    pub delta: f32,
    /// Texels read outside the image (BORDER returns black: log2(δ) each).
    pub padded_samples: u64,
    /// Pass 1's cost (every column, or all but the last).
    pub pass1: PassCost,
    /// The last column's pass-1 shader, when one draws it
    /// ([`run_with_last_column`]); `None` with BORDER padding in x.
    pub pass1_last: Option<PassCost>,
    /// Pass 2's cost.
    pub pass2: PassCost,
    /// Every pass-1 block against its f64 sum, row by row from the top left.
    pub blocks: Vec<BlockCheck>,
    /// Pass 2's output against its formula applied in f64 to the stored
    /// pass-1 target.
    pub pass2_check: Comparison,
    /// Emulated L̄w against the pass-1 reference pushed through pass 2's
    /// formula (with and without padding correction as the shader does it).
    pub log_average: f64,
    /// The true L̄w of the image: every pixel once, no padding.
    pub reference_log_average: f64,
    /// |L̄w − reference| / reference.
    pub relative_error: f64,
    /// Derived bound on the relative error if the shaders are right.
    pub relative_tolerance: f64,
    /// Whether L̄w is within [`LuminanceRun::relative_tolerance`] of the reference.
    pub agree: bool,
    /// What BORDER padding does to L̄w when nobody corrects for it: the
    /// factor 2^(P·log2(δ)/N).
    pub padding_factor: f64,
    /// Pixels whose term is too ill-conditioned to bound (δ + L near 0).
    pub ill_conditioned: u64,
    /// Non-finite pixels in the image.
    pub nonfinite_pixels: u64,
    /// Pixels with negative luminance in the image.
    pub negative_pixels: u64,
    /// Who drew the passes: `emulator`, or `GPU: <device>`.
    pub drawn_by: String,
}

/// The largest derived bound on L̄w's relative error for which the
/// cross-check still means something: beyond 1%, the f32 rounding the bound
/// allows (long sums, heavy BORDER padding against few real pixels) could
/// hide a result that is plainly wrong, so the run is called unfit for the
/// image instead of "agree".
pub const FIT_TOLERANCE: f64 = 0.01;

impl LuminanceRun {
    /// Whether the method can be checked on this image at all: the derived
    /// bound is finite and at most [`FIT_TOLERANCE`].
    pub fn fit(&self) -> bool {
        self.relative_tolerance.is_finite() && self.relative_tolerance <= FIT_TOLERANCE
    }

    /// Every pass fits the ps_3_0 limits (slots and executed).
    pub fn within_limits(&self) -> bool {
        self.pass1.within_limits
            && self.pass1_last.as_ref().is_none_or(|p| p.within_limits)
            && self.pass2.within_limits
    }

    /// Whether every pass-1 block is within its bound.
    pub fn blocks_agree(&self) -> bool {
        self.blocks.iter().all(|b| b.agree)
    }

    /// Whether L̄w is a usable number (non-finite pixels make it NaN or ∞).
    pub fn finite(&self) -> bool {
        self.log_average.is_finite()
    }

    /// Everything agrees: blocks, pass 2 and L̄w, and the counts.
    pub fn all_agree(&self) -> bool {
        self.blocks_agree()
            && self.pass2_check.agree
            && self.agree
            && self.pass1.counts_agree
            && self.pass1_last.as_ref().is_none_or(|p| p.counts_agree)
            && self.pass2.counts_agree
    }
}

/// Per-block error bounds of pass 1 in the shader's order (row by row,
/// left to right), with the number of ill-conditioned terms.
pub fn pass1_bounds(
    image: &HdrImage,
    block: (u32, u32),
    delta: f64,
    policy: Policy,
) -> (Vec<Vec<f64>>, u64) {
    pass1_bounds_last_width(image, block, block.0, delta, policy)
}

/// [`pass1_bounds`] when the last column of blocks reads only `last_width`
/// texels per line (see [`run_with_last_column`]).
pub fn pass1_bounds_last_width(
    image: &HdrImage,
    block: (u32, u32),
    last_width: u32,
    delta: f64,
    policy: Policy,
) -> (Vec<Vec<f64>>, u64) {
    let tiling = Tiling {
        block_width: block.0,
        block_height: block.1,
        last_width,
    };
    match reference::fold_blocks(image, delta, policy, tiling, |_, _| BoundFold::new(delta)) {
        Ok((_, folds)) => bounds_of(tiling, folds),
        Err(_) => (Vec::new(), 0),
    }
}

/// The bounds and the ill-conditioned count of every block's fold.
fn bounds_of(tiling: Tiling, folds: Vec<Vec<BoundFold>>) -> (Vec<Vec<f64>>, u64) {
    let nx = folds.first().map_or(0, |r| r.len() as u32);
    let mut ill = 0;
    let bounds = folds
        .into_iter()
        .map(|row| {
            row.into_iter()
                .enumerate()
                .map(|(bx, f)| {
                    ill += f.ill;
                    let n = tiling.read(bx as u32, nx) as f64 * tiling.block_height as f64;
                    (f.terms + U32 * f.accumulation) * (1.0 + n * U32)
                })
                .collect()
        })
        .collect();
    (bounds, ill)
}

/// One block's pass-1 bound, folded over its texels in the shader's order:
/// the running f32 sum's partial sums, and each term's own error.
#[derive(Clone, Copy)]
struct BoundFold {
    delta: f64,
    partial: f64,
    accumulation: f64,
    terms: f64,
    ill: u64,
}

impl BoundFold {
    fn new(delta: f64) -> BoundFold {
        BoundFold {
            delta,
            partial: 0.0,
            accumulation: 0.0,
            terms: 0.0,
            ill: 0,
        }
    }

    /// Adds a term `t` with its own bound `e`; a pixel the policy skips
    /// (`kept` false, `t` +0) adds +0 to each sum (see
    /// [`BlockFold::pixel`]): selections, not a branch, so the running sums
    /// stay in registers.
    #[inline(always)]
    fn add(&mut self, t: f64, e: f64, kept: bool) {
        self.partial += t;
        self.accumulation += if kept { self.partial.abs() } else { 0.0 };
        self.terms += if kept { e } else { 0.0 };
    }

    /// A padding texel: black, the term log2(delta).
    fn add_padding(&mut self, count: u32) {
        let padded_term = self.delta.log2();
        let e = 8.0 * U32 / std::f64::consts::LN_2 + ulp32(padded_term);
        for _ in 0..count {
            self.add(padded_term, e, true);
        }
    }
}

/// What [`BoundFold`] works out ahead for a run of pixels: each term's own
/// error bound, and whether the term is ill-conditioned.
#[derive(Default)]
struct BoundRun {
    e: [f64; AHEAD_RUN],
    ill: [bool; AHEAD_RUN],
}

/// The f32 pass's error bound on the term `t` of pixel `p` (the luminance
/// dot product's rounding carried through `log2`, plus the rounding of the
/// term itself), and whether the term is ill-conditioned (the dot
/// product's error reaches half of δ + L).
#[inline(always)]
fn term_bound(delta: f64, p: [f32; 4], t: f64) -> (f64, bool) {
    let l = crate::core::image::luminance(p);
    let a = 0.27 * (p[0] as f64).abs()
        + 0.67 * (p[1] as f64).abs()
        + 0.06 * (p[2] as f64).abs()
        + delta;
    let x_exact = (delta + l).abs();
    let abs_err = 8.0 * U32 * a;
    let ill = t.is_finite() & (abs_err >= x_exact / 2.0);
    (abs_err / (x_exact * std::f64::consts::LN_2) + ulp32(t), ill)
}

/// [`BlockFold::ahead`]'s loop for [`BoundFold`]: one pixel's bound after
/// another, no branch, so the compiler makes it a vector loop. It takes
/// `delta`, not the fold: a fold whose address went to a call out of line
/// would keep its running sums in memory instead of registers.
#[inline(always)]
fn bound_run(delta: f64, pixels: &[[f32; 4]], terms: &[f64], run: &mut BoundRun) {
    // Skipped pixels (NaN terms) get a bound too, which `pixel` drops.
    let runs = run.e.iter_mut().zip(&mut run.ill);
    for ((&p, &t), (e, ill)) in pixels.iter().zip(terms).zip(runs) {
        (*e, *ill) = term_bound(delta, p, t);
    }
}

/// [`bound_run`] compiled for AVX2 (four f64 lanes where the portable build
/// has two). Same values: Rust fuses no multiply and add.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn bound_run_avx2(delta: f64, pixels: &[[f32; 4]], terms: &[f64], run: &mut BoundRun) {
    bound_run(delta, pixels, terms, run)
}

impl BlockFold for BoundFold {
    type Run = BoundRun;

    #[inline]
    fn ahead(&self, pixels: &[[f32; 4]], terms: &[f64], run: &mut BoundRun) {
        let delta = self.delta;
        #[cfg(target_arch = "x86_64")]
        if std::arch::is_x86_feature_detected!("avx2") {
            // SAFETY: the CPU supports AVX2 (checked just above).
            return unsafe { bound_run_avx2(delta, pixels, terms, run) };
        }
        bound_run(delta, pixels, terms, run)
    }

    #[inline]
    fn pixel(&mut self, run: &BoundRun, i: usize, term: Option<f64>) {
        let kept = term.is_some();
        self.ill += u64::from(kept & run.ill[i]);
        self.add(term.unwrap_or(0.0), run.e[i], kept);
    }

    fn end_row(&mut self, padding: u32) {
        self.add_padding(padding);
    }

    fn rows_below(&mut self, rows: u32, read: u32) {
        for _ in 0..rows {
            self.add_padding(read);
        }
    }
}

/// One unit in the last place of an f32 near `x`.
#[inline(always)]
fn ulp32(x: f64) -> f64 {
    let a = (x.abs() as f32).max(f32::MIN_POSITIVE);
    (f32::from_bits(a.to_bits() + 1) - a) as f64
}

/// Half a unit in the last place of an f16 near `x` (the storage error).
fn half_ulp16(x: f64) -> f64 {
    let a = half::f16::from_f64(x.abs());
    if a.is_infinite() {
        return f64::INFINITY;
    }
    let next = half::f16::from_bits(a.to_bits() + 1);
    (next.to_f64() - a.to_f64()) / 2.0
}

fn storage_bound(format: TargetFormat, value: f64) -> f64 {
    match format.encoding() {
        crate::core::image::Encoding::Float => 0.0,
        crate::core::image::Encoding::Half => half_ulp16(value),
        // Pass-1 sums are far outside [0, 1]: an 8-bit target cannot hold them.
        crate::core::image::Encoding::Unorm8 => f64::INFINITY,
    }
}

/// The texture coordinate the application gives pixel (x, y) of a target
/// whose pixels each cover a `bw × bh` block of a `w × h` texture: the centre
/// of the block's top-left texel, ((x·bw + ½)/w, (y·bh + ½)/h).
pub fn block_start(w: u32, h: u32, bw: u32, bh: u32) -> LinearInput {
    LinearInput {
        base: [0.5 / w as f32, 0.5 / h as f32, 0.0, 0.0],
        ddx: [bw as f32 / w as f32, 0.0, 0.0, 0.0],
        ddy: [0.0, bh as f32 / h as f32, 0.0, 0.0],
    }
}

fn sampler(texture: Texture<'_>) -> (u32, emu::TextureLevels<'_>, SamplerState) {
    (
        0,
        texture.into(),
        SamplerState {
            address_u: Address::Border,
            address_v: Address::Border,
            address_w: Address::Border,
            border: [0.0; 4],
            ..SamplerState::filtered(Filter::Point)
        },
    )
}

/// Runs a draw on the run's backend and stores oC0 into a target of the
/// run's format.
fn draw_into(
    loaded: &load::Loaded,
    draw: &Draw,
    format: TargetFormat,
    backend: &Backend,
    threads: Option<usize>,
) -> Result<(RenderTarget, Option<Range>, Vec<emu::findings::Finding>), PipelineError> {
    let out = backend::draw(
        backend,
        &loaded.shader,
        &loaded.file,
        draw,
        TargetKind::Format(format),
        threads,
    )
    .map_err(PipelineError::Draw)?;
    let mut target = RenderTarget::new(out.width, out.height, format);
    if let Some(color) = &out.color {
        for (i, v) in color.iter().enumerate() {
            target.store(i as u32 % out.width, i as u32 / out.width, *v);
        }
    }
    Ok((target, out.executed, out.findings))
}

/// The cost model's analysis of a loaded pass under `env`.
fn analyse(loaded: &load::Loaded, env: &Environment) -> Result<cost::Analysis, PipelineError> {
    cost::analyse(&loaded.shader, &loaded.file, env, &Profile::ps_3_0())
        .map_err(|e| PipelineError::Cost(e.to_string()))
}

/// A pass's cost: its static analysis `a` beside what the draw executed.
fn pass_cost(
    loaded: &load::Loaded,
    a: &cost::Analysis,
    emulated: Option<Range>,
    findings: Vec<crate::core::emu::findings::Finding>,
) -> PassCost {
    PassCost {
        shader: loaded.file.name.clone(),
        slots: a.slots,
        executed_static: a.executed,
        executed_emulated: emulated,
        findings,
        counts_agree: emulated.is_none_or(|e| a.executed.min <= e.min && e.max <= a.executed.max),
        within_limits: a.verdict == cost::Verdict::Within,
    }
}

/// Runs pass 1 and pass 2 on an image and cross-checks every step.
pub fn run(
    image: &HdrImage,
    pass1: &ShaderSource,
    pass2: &ShaderSource,
    s: &Settings,
) -> Result<LuminanceRun, PipelineError> {
    run_impl(image, pass1, None, pass2, s)
}

/// [`run`] with the article's alternative to BORDER padding in x: `pass1`
/// draws every column of blocks but the last, and `last` draws the last
/// column, reading only the frame's real width there
/// (`W − (nx − 1)·bw` texels per line, its `i1` or REPEAT_BLOCK count). Two
/// draws into one `nx × ny` target; only the bottom row of blocks is padded
/// (in y), and pass 2's correction c0.y counts only that padding.
pub fn run_with_last_column(
    image: &HdrImage,
    pass1: &ShaderSource,
    last: &ShaderSource,
    pass2: &ShaderSource,
    s: &Settings,
) -> Result<LuminanceRun, PipelineError> {
    run_impl(image, pass1, Some(last), pass2, s)
}

/// Loads a pass-1 shader and checks that it reads `bw × bh` texels with
/// i1 = bw, i2 = bh; returns it with its analysis under those counts.
fn load_pass1(
    src: &ShaderSource,
    bw: u32,
    bh: u32,
) -> Result<(load::Loaded, cost::Analysis), PipelineError> {
    let l1 = load(
        src,
        &[("bw", bw as u64), ("bh", bh as u64)],
        &crate::core::audit::Given::registers(&PASS1_FLOATS, &PASS1_INTS, &[]),
    )?;
    let mut env1 = Environment::default();
    env1.ints.insert(1, [bw as i32, 0, 0, 0]);
    env1.ints.insert(2, [bh as i32, 0, 0, 0]);
    let static1 = analyse(&l1, &env1)?;
    let reads: u64 = l1
        .shader
        .instructions()
        .iter()
        .zip(&static1.executions)
        .filter(|(i, _)| i.op == Opcode::TexLd)
        .map(|(_, e)| e.max)
        .sum();
    if reads != bw as u64 * bh as u64 {
        return Err(PipelineError::Mismatch(format!(
            "{} reads {reads} texels per pixel with i1 = {bw}, i2 = {bh}, but a {bw}×{bh} block has {}; an unrolled shader fixes the block width to its REPEAT_BLOCK count",
            src.name(),
            bw as u64 * bh as u64
        )));
    }
    Ok((l1, static1))
}

/// The geometry of one run: the frame, its blocks and the padding.
struct Geometry {
    w: u32,
    h: u32,
    bw: u32,
    bh: u32,
    nx: u32,
    ny: u32,
    /// Texels per line the last column reads: the real width with a
    /// last-column shader, the whole block with BORDER padding.
    last_w: u32,
    /// Samples of the padding (log2 δ each).
    padded: u64,
    n_pixels: f64,
}

impl Geometry {
    fn new(image: &HdrImage, block: (u32, u32), last_column: bool) -> Result<Self, PipelineError> {
        let (bw, bh) = block;
        if bw == 0 || bh == 0 {
            return Err(PipelineError::Mismatch(
                "block sides must be at least 1".into(),
            ));
        }
        let (w, h) = (image.width, image.height);
        if w == 0 || h == 0 {
            return Err(PipelineError::Mismatch("the image is empty".into()));
        }
        let (nx, ny) = (w.div_ceil(bw), h.div_ceil(bh));
        let last_w = if last_column { w - (nx - 1) * bw } else { bw };
        let padded = ((nx - 1) as u64 * bw as u64 + last_w as u64) * (ny as u64 * bh as u64)
            - w as u64 * h as u64;
        Ok(Geometry {
            w,
            h,
            bw,
            bh,
            nx,
            ny,
            last_w,
            padded,
            n_pixels: w as f64 * h as f64,
        })
    }

    /// Pass 1's constants for a draw whose blocks read `read` texels per
    /// line.
    fn pass1_constants(&self, delta: f32, read: u32) -> Constants {
        Constants {
            float: vec![
                [0.0; 4],
                [1.0 / self.w as f32, 1.0 / self.h as f32, 0.0, 1.0],
                [0.0; 4],
                [0.27, 0.67, 0.06, delta.sqrt()],
            ],
            int: vec![[0; 4], [read as i32, 0, 0, 0], [self.bh as i32, 0, 0, 0]],
            bool: Vec::new(),
        }
    }
}

fn run_impl(
    image: &HdrImage,
    pass1: &ShaderSource,
    last: Option<&ShaderSource>,
    pass2: &ShaderSource,
    s: &Settings,
) -> Result<LuminanceRun, PipelineError> {
    let g = Geometry::new(image, s.block, last.is_some())?;
    let delta = s.delta as f64;
    // Pass 1 and the f64 reference do not depend on each other: they share
    // the run's threads.
    let (drawn, references) = emu::on_threads(s.threads.unwrap_or(0), || {
        rayon::join(
            || {
                let drawn = run_pass1(image, &g, pass1, last, s);
                crate::core::phases::mark("luminance: pass 1 drawn");
                drawn
            },
            || {
                let references = block_references(image, &g, s);
                crate::core::phases::mark("luminance: f64 reference");
                references
            },
        )
    })
    .map_err(|e| PipelineError::Draw(DrawError::Emu(e)))?;
    let (t1, pass1_cost, pass1_last) = drawn?;
    let (blocks, ill, true_ref) = check_blocks(&g, &t1, references?, s);
    let (pass2_cost, log_average, pass2_check, rel2) = run_pass2(&g, &t1, pass2, s)?;
    crate::core::phases::mark("luminance: pass 2 drawn");

    // End to end: the emulated L̄w against the true L̄w of the image (every
    // pixel once, no padding). If the shaders are right, the difference
    // comes only from the block bounds and pass 2's own rounding.
    let block_bound: f64 = blocks.iter().map(|b| b.tolerance).sum();
    let relative_tolerance = std::f64::consts::LN_2 * block_bound / g.n_pixels + rel2;
    let end_to_end = Comparison::new(
        log_average,
        true_ref.log_average,
        relative_tolerance * true_ref.log_average.abs(),
    );
    let relative_error = end_to_end.difference / true_ref.log_average.abs();
    let padding_factor = (g.padded as f64 * delta.log2() / g.n_pixels).exp2();
    Ok(LuminanceRun {
        width: g.w,
        height: g.h,
        block: s.block,
        targets: (g.nx, g.ny),
        target_format: s.format,
        delta: s.delta,
        padded_samples: g.padded,
        pass1: pass1_cost,
        pass1_last,
        pass2: pass2_cost,
        blocks,
        pass2_check,
        log_average,
        reference_log_average: true_ref.log_average,
        relative_error,
        relative_tolerance,
        agree: end_to_end.agree,
        padding_factor,
        ill_conditioned: ill,
        nonfinite_pixels: true_ref.nonfinite_pixels,
        negative_pixels: true_ref.negative_pixels,
        drawn_by: s.backend.describe(),
    })
}

/// Pass 1: one draw over every column (BORDER padding), or one over the
/// first nx − 1 columns and one over the last. Returns the `nx × ny`
/// target, the cost of `pass1` and that of the last-column shader.
fn run_pass1(
    image: &HdrImage,
    g: &Geometry,
    pass1: &ShaderSource,
    last: Option<&ShaderSource>,
    s: &Settings,
) -> Result<(RenderTarget, PassCost, Option<PassCost>), PipelineError> {
    let (w, h, bw, bh, nx, ny) = (g.w, g.h, g.bw, g.bh, g.nx, g.ny);
    let (l1, static1) = load_pass1(pass1, bw, bh)?;
    let main_cols = if last.is_some() { nx - 1 } else { nx };
    let texture = Texture {
        width: w,
        height: h,
        texels: &image.pixels,
    };
    let mut t1 = RenderTarget::new(nx, ny, s.format);
    let mut emulated1 = Some(Range::ZERO);
    let mut findings1 = Vec::new();
    if main_cols > 0 {
        let mut d1 = Draw::new(main_cols, ny);
        d1.float_rules = s.float_rules;
        d1.limits = s.limits;
        d1.record_lod = true;
        d1.inputs.push((0, block_start(w, h, bw, bh)));
        d1.constants = g.pass1_constants(s.delta, bw);
        d1.samplers.push(sampler(texture));
        let (t, e, f) = draw_into(&l1, &d1, s.format, &s.backend, s.threads)?;
        for y in 0..ny {
            for x in 0..main_cols {
                t1.store(x, y, t.texel(x, y));
            }
        }
        emulated1 = e;
        findings1 = f;
    }
    let mut pass1_cost = pass_cost(&l1, &static1, emulated1, findings1);
    if main_cols == 0 {
        // A frame no wider than one block: the last-column shader draws the
        // only column and `pass1` never runs, so there is no count to compare.
        pass1_cost.counts_agree = true;
    }
    let pass1_last = match last {
        Some(src) => Some(run_last_column(texture, g, src, &mut t1, s)?),
        None => None,
    };
    Ok((t1, pass1_cost, pass1_last))
}

/// The last column of pass 1 with its own shader, reading `last_w` texels
/// per line, into column nx − 1 of `t1`; returns its cost.
fn run_last_column(
    texture: Texture,
    g: &Geometry,
    src: &ShaderSource,
    t1: &mut RenderTarget,
    s: &Settings,
) -> Result<PassCost, PipelineError> {
    let (ll, static_last) = load_pass1(src, g.last_w, g.bh)?;
    let mut dl = Draw::new(1, g.ny);
    dl.float_rules = s.float_rules;
    dl.limits = s.limits;
    dl.record_lod = true;
    let mut input = block_start(g.w, g.h, g.bw, g.bh);
    input.base[0] = (((g.nx - 1) as f64 * g.bw as f64 + 0.5) / g.w as f64) as f32;
    dl.inputs.push((0, input));
    dl.constants = g.pass1_constants(s.delta, g.last_w);
    dl.samplers.push(sampler(texture));
    let (t, e, f) = draw_into(&ll, &dl, s.format, &s.backend, s.threads)?;
    for y in 0..g.ny {
        t1.store(g.nx - 1, y, t.texel(0, y));
    }
    Ok(pass_cost(&ll, &static_last, e, f))
}

/// The f64 reference of every block of pass 1 with its bound, and the whole
/// image's (one scan computes them all).
struct BlockReferences {
    whole: reference::Reference,
    sums: reference::BlockSums,
    bounds: Vec<Vec<f64>>,
    ill: u64,
}

fn block_references(
    image: &HdrImage,
    g: &Geometry,
    s: &Settings,
) -> Result<BlockReferences, PipelineError> {
    let delta = s.delta as f64;
    let tiling = Tiling {
        block_width: g.bw,
        block_height: g.bh,
        last_width: g.last_w,
    };
    let (whole, sums, folds) =
        reference::fold_blocks_with_sums(image, delta, s.policy, tiling, |_, _| {
            BoundFold::new(delta)
        })
        .map_err(|e| PipelineError::Reference(e.to_string()))?;
    let (bounds, ill) = bounds_of(tiling, folds);
    Ok(BlockReferences {
        whole,
        sums,
        bounds,
        ill,
    })
}

/// Every block of pass 1's target against its f64 reference and bound;
/// also returns the number of ill-conditioned terms and the whole image's
/// reference.
fn check_blocks(
    g: &Geometry,
    t1: &RenderTarget,
    r: BlockReferences,
    s: &Settings,
) -> (Vec<BlockCheck>, u64, reference::Reference) {
    let BlockReferences {
        whole,
        sums: refs,
        bounds,
        ill,
    } = r;
    let mut blocks = Vec::with_capacity((g.nx * g.ny) as usize);
    for by in 0..g.ny {
        for bx in 0..g.nx {
            let emulated = t1.texel(bx, by)[0] as f64;
            let reference = refs.sums[by as usize][bx as usize];
            let tol = bounds[by as usize][bx as usize] + storage_bound(s.format, reference);
            let c = Comparison::new(emulated, reference, tol);
            let overflow = reference.is_finite() && !storage_bound(s.format, reference).is_finite();
            blocks.push(BlockCheck {
                x: bx,
                y: by,
                emulated,
                reference,
                difference: c.difference,
                tolerance: c.tolerance,
                agree: c.agree,
                overflow,
            });
        }
    }
    (blocks, ill, whole)
}

/// Pass 2 over pass 1's target: its cost, the emulated L̄w, and its check
/// against pass 2's formula in f64 with that check's relative bound.
fn run_pass2(
    g: &Geometry,
    t1: &RenderTarget,
    pass2: &ShaderSource,
    s: &Settings,
) -> Result<(PassCost, f64, Comparison, f64), PipelineError> {
    let (nx, ny) = (g.nx, g.ny);
    let l2 = load(
        pass2,
        &[("xsize", nx as u64), ("ysize", ny as u64)],
        &crate::core::audit::Given::registers(&PASS2_FLOATS, &[], &[]),
    )?;
    let mut d2 = Draw::new(1, 1);
    d2.float_rules = s.float_rules;
    d2.limits = s.limits;
    d2.inputs.push((
        0,
        LinearInput::constant([0.5 / nx as f32, 0.5 / ny as f32, 0.0, 0.0]),
    ));
    let correction = -(g.padded as f64) * ((s.delta as f64).log2()) / g.n_pixels;
    d2.constants = Constants {
        float: vec![
            [(1.0 / g.n_pixels) as f32, correction as f32, 0.0, 0.0],
            [1.0 / nx as f32, 1.0 / ny as f32, 0.0, 1.0],
        ],
        int: Vec::new(),
        bool: Vec::new(),
    };
    d2.samplers.push(sampler(t1.as_texture()));
    d2.record_lod = true;
    let (t2, emulated2, findings2) = draw_into(&l2, &d2, s.format, &s.backend, s.threads)?;
    let static2 = analyse(&l2, &Environment::default())?;
    let pass2_cost = pass_cost(&l2, &static2, emulated2, findings2);
    let log_average = t2.texel(0, 0)[0] as f64;
    let applied = if reads_c0y(&l2) { correction } else { 0.0 };
    let (check, rel2) = pass2_check(g, t1, applied, log_average, s.format);
    Ok((pass2_cost, log_average, check, rel2))
}

/// Pass 2 on its own: the emulated L̄w against pass 2's formula applied
/// in f64 to the stored pass-1 values (sum in pass 2's order, then the
/// padding correction `applied` if the shader reads c0.y, then 1/N and
/// exp2). Returns the comparison and its relative bound.
fn pass2_check(
    g: &Geometry,
    t1: &RenderTarget,
    applied: f64,
    log_average: f64,
    format: TargetFormat,
) -> (Comparison, f64) {
    let mut partial = 0f64;
    let mut accumulation = 0f64;
    for by in 0..g.ny {
        for bx in 0..g.nx {
            partial += t1.texel(bx, by)[0] as f64;
            accumulation += partial.abs();
        }
    }
    let mean2 = partial / g.n_pixels + applied;
    let expected2 = mean2.exp2();
    // Sum rounding; 1/N and the product (2u relative), the mad's addition
    // (u), exp's result (≤ 1 ulp, 2u relative), storage.
    let rel2 = std::f64::consts::LN_2
        * (U32 * accumulation * (1.0 + (g.nx * g.ny) as f64 * U32) / g.n_pixels
            + 2.0 * U32 * (partial / g.n_pixels).abs()
            + U32 * mean2.abs())
        + 2.0 * U32
        + storage_bound(format, expected2) / expected2.max(f64::MIN_POSITIVE);
    (
        Comparison::new(log_average, expected2, rel2 * expected2),
        rel2,
    )
}

/// Whether a pass-2 shader reads c0.y, the padding correction. The
/// article's listing multiplies by c0.x only.
fn reads_c0y(l: &load::Loaded) -> bool {
    l.shader.instructions().iter().any(|i| {
        i.src.iter().any(|s| {
            s.reg.file == crate::core::isa::RegFile::Const
                && s.reg.index == 0
                && s.swizzle.0.contains(&1)
        })
    })
}

/// One pass of any shader over a texture: what `ps30 run` does.
#[derive(Clone, Debug)]
pub struct PassSetup {
    /// The render target, width × height in pixels.
    pub target: (u32, u32),
    /// The application's constants.
    pub constants: Constants,
    /// s0's sampler state.
    pub sampler: SamplerState,
    /// The format the target stores.
    pub format: TargetFormat,
    /// Emulator threads; `None` for every core.
    pub threads: Option<usize>,
    /// The emulator's bounds (executed slots per pixel, target size).
    pub limits: emu::EmuLimits,
    /// Who draws the pass.
    pub backend: Backend,
    /// The special values of the arithmetic.
    pub float_rules: FloatRules,
    /// Textures bound to samplers besides the image (`run --inputs`): a
    /// texture on s0 takes the image's place there.
    pub textures: Vec<(u32, crate::core::image::TextureFile, SamplerState)>,
    /// Input values by slot (`run --input`, `core/pixel_inputs.rs`): one
    /// given for the coordinates' input takes the image's place there.
    pub inputs: Vec<(u32, LinearInput)>,
}

/// What one pass produced.
#[derive(Clone, Debug)]
pub struct PassOutput {
    /// The target bound to oC0, as its format stores it.
    pub target: RenderTarget,
    /// Every output register the shader writes, with the statistics of
    /// what the target stores.
    pub outputs: Vec<crate::jobs::outputs::OutputRegister>,
    /// Its cost: static, and counted where the emulator drew it.
    pub cost: PassCost,
    /// Who drew it: `emulator`, or `GPU: <device>`.
    pub drawn_by: String,
}

/// Runs `loaded` over a `target` whose pixel (x, y) gets v0 = the start of
/// its block of `image` (see [`block_start`]) and s0 = `image`.
pub fn run_pass(
    loaded: &load::Loaded,
    image: Option<&HdrImage>,
    setup: &PassSetup,
) -> Result<PassOutput, PipelineError> {
    let (tw, th) = setup.target;
    // Without an image, v0 runs over the target's own texel centres.
    let (iw, ih) = image.map_or((tw, th), |i| (i.width, i.height));
    let mut draw = Draw::new(tw, th);
    draw.limits = setup.limits;
    draw.float_rules = setup.float_rules;
    let program = loaded.shader.program();
    // v0 in ps_3_0, t0 in ps_2_x (core/pixel_inputs.rs).
    if let Some(coordinates) = crate::core::pixel_inputs::declared_coordinates(program) {
        draw.inputs.push((
            coordinates,
            block_start(iw, ih, iw.div_ceil(tw), ih.div_ceil(th)),
        ));
    }
    for (at, value) in &setup.inputs {
        draw.inputs.retain(|(s, _)| s != at);
        draw.inputs.push((*at, *value));
    }
    draw.constants = setup.constants.clone();
    let given_s0 = setup.textures.iter().any(|(s, _, _)| *s == 0);
    if let (Some(image), false, true) = (
        image,
        given_s0,
        loaded.shader.program().sampler_type(0).is_some(),
    ) {
        draw.samplers
            .push((0, image.as_texture().into(), setup.sampler));
    }
    for (s, file, state) in &setup.textures {
        draw.samplers.push((*s, file.into(), *state));
    }
    draw.record_lod = true;
    let (target, emulated, findings) =
        draw_into(loaded, &draw, setup.format, &setup.backend, setup.threads)?;
    // A draw sets every constant: what the application did not set is 0 /
    // false, for the cost model as for the emulator.
    let mut env = Environment::default();
    for i in 0..16 {
        let int = setup.constants.int.get(i).copied().unwrap_or([0; 4]);
        env.ints.insert(i as u32, int);
        env.bools.insert(
            i as u32,
            setup.constants.bool.get(i).copied().unwrap_or(false),
        );
    }
    let cost = pass_cost(loaded, &analyse(loaded, &env)?, emulated, findings);
    let outputs = crate::jobs::outputs::summarise(&loaded.shader, &target);
    Ok(PassOutput {
        target,
        outputs,
        cost,
        drawn_by: setup.backend.describe(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Pixels that reach every branch of the bound and of the reference's
    /// scan: ordinary, dark, zero (both signs), negative, huge, subnormal,
    /// infinite (both signs) and NaN channels.
    pub(super) fn awkward_pixels() -> Vec<[f32; 4]> {
        let values = [
            0.0,
            -0.0,
            1e-4,
            0.18,
            1.0,
            -0.5,
            65504.0,
            3.0e38,
            f32::MIN_POSITIVE / 8.0,
            -1e-4,
            f32::INFINITY,
            f32::NEG_INFINITY,
            f32::NAN,
        ];
        let mut pixels = Vec::new();
        for &r in &values {
            for &g in &values {
                for &b in &values[..5] {
                    pixels.push([r, g, b, 1.0]);
                }
            }
        }
        pixels
    }

    /// A run's bounds are the bits the formula gives one pixel at a time
    /// in scalar code, in the portable loop and in its AVX2 copy alike.
    #[test]
    fn bounds_worked_out_ahead_are_the_formula_bit_for_bit() {
        let delta = 1e-4;
        let pixels = awkward_pixels();
        let terms: Vec<Option<f64>> = pixels
            .iter()
            .enumerate()
            .map(|(i, &p)| {
                // Every seventh pixel skipped, as the Skip policy does.
                (i % 7 != 3).then(|| Policy::ABS.term(crate::core::image::luminance(p), delta))?
            })
            .collect();
        // As a band holds them: NaN where the pixel is skipped.
        let plain: Vec<f64> = terms.iter().map(|t| t.unwrap_or(f64::NAN)).collect();
        let mut checked = 0;
        let runs = pixels.chunks(AHEAD_RUN).zip(terms.chunks(AHEAD_RUN));
        for ((pixels, terms), plain) in runs.zip(plain.chunks(AHEAD_RUN)) {
            let mut portable = BoundRun::default();
            bound_run(delta, pixels, plain, &mut portable);
            let mut runs = vec![portable];
            #[cfg(target_arch = "x86_64")]
            if std::arch::is_x86_feature_detected!("avx2") {
                let mut wide = BoundRun::default();
                // SAFETY: the CPU supports AVX2 (checked just above).
                unsafe { bound_run_avx2(delta, pixels, plain, &mut wide) };
                runs.push(wide);
            }
            for (i, (&p, &term)) in pixels.iter().zip(terms).enumerate() {
                let Some(t) = term else { continue };
                // One pixel alone, called out of line (no vector code).
                let scalar: fn(f64, [f32; 4], f64) -> (f64, bool) = term_bound;
                let (e, ill) = std::hint::black_box(scalar)(delta, p, t);
                for run in &runs {
                    // Same bits, or both NaN: Rust leaves a NaN's sign and
                    // payload unspecified (vector code gives other ones than
                    // scalar code), and no output shows them.
                    let same = run.e[i].to_bits() == e.to_bits() || run.e[i].is_nan() && e.is_nan();
                    assert!(same, "pixel {p:?}: {} against {e}", run.e[i]);
                    assert_eq!(run.ill[i], ill, "pixel {p:?}");
                    checked += 1;
                }
            }
        }
        assert!(checked >= 500, "only {checked} bounds compared");
    }

    /// Folds `terms` (NaN where skipped) over `pixels` as a band's blocks
    /// are folded: runs worked out ahead, then pixel by pixel.
    fn fold_bound(delta: f64, pixels: &[[f32; 4]], terms: &[Option<f64>]) -> BoundFold {
        let mut fold = BoundFold::new(delta);
        for (pixels, terms) in pixels.chunks(AHEAD_RUN).zip(terms.chunks(AHEAD_RUN)) {
            let plain: Vec<f64> = terms.iter().map(|t| t.unwrap_or(f64::NAN)).collect();
            let mut run = BoundRun::default();
            fold.ahead(pixels, &plain, &mut run);
            for (i, &t) in terms.iter().enumerate() {
                fold.pixel(&run, i, t);
            }
        }
        fold
    }

    /// The fold adds +0 for a skipped pixel instead of branching around it:
    /// the bound over pixels with some skipped is the bound over the kept
    /// ones alone, bit for bit.
    #[test]
    fn a_skipped_pixel_leaves_the_bound_as_it_was() {
        let delta = 1e-4;
        let term = |p| Policy::ABS.term(crate::core::image::luminance(p), delta);
        // Finite terms only, so that every sum compares by its bits.
        let pixels: Vec<[f32; 4]> = awkward_pixels()
            .into_iter()
            .filter(|&p| term(p).is_some_and(f64::is_finite))
            .collect();
        let with_skips: Vec<Option<f64>> = pixels
            .iter()
            .enumerate()
            .map(|(i, &p)| if i % 5 == 2 { None } else { term(p) })
            .collect();
        let kept: Vec<[f32; 4]> = pixels
            .iter()
            .zip(&with_skips)
            .filter(|(_, t)| t.is_some())
            .map(|(&p, _)| p)
            .collect();
        let kept_terms: Vec<Option<f64>> =
            with_skips.iter().copied().filter(Option::is_some).collect();
        assert!(kept.len() >= 100 && kept.len() < pixels.len());
        let a = fold_bound(delta, &pixels, &with_skips);
        let b = fold_bound(delta, &kept, &kept_terms);
        let bits = |f: &BoundFold| [f.partial, f.accumulation, f.terms].map(f64::to_bits);
        assert_eq!(bits(&a), bits(&b));
        assert_eq!(a.ill, b.ill);
        assert!(a.accumulation > 0.0 && a.terms > 0.0);
    }
}
