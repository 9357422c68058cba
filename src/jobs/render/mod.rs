//! Draw lists: several draws meeting in render targets — each with its
//! shader, constants, textures, blend state and write mask — with clears and
//! mip-chain reductions between them, so that N lights can accumulate into
//! one target and a later draw can read the result. It is what the
//! article's lighting phase and its alternatives need, and what `ps30
//! render` runs from a file a user writes ([`file`](mod@file)).
//!
//! A [`DrawList`] is plain data: named targets (size and D3D9 format),
//! named textures (loaded images or synthetic inputs), and [`Step`]s. Every
//! draw covers its whole target (a full-screen quad: pixel (x, y) runs the
//! shader once, v# as given); the emulator runs the shader and the output
//! merger ([`crate::core::merge`]) writes its colours. A target can be bound
//! to a sampler of a later draw, never of a draw into itself (Direct3D 9
//! calls that set-up illegal, the article notes); after a [`Step::Mips`] it
//! is sampled with its mip chain, whose last level is the 1 × 1 reduction.
//!
//! The runner reports each step ([`StepReport`]) to an observer as it
//! finishes, with the targets as they are then, so a caller can write every
//! intermediate target without the runner keeping copies.

pub mod costs;
pub mod file;
mod floats;
pub mod geometry;
pub mod history;
pub mod input_values;
mod multisample;
pub mod pixel_state;
pub mod textures;

use crate::core::cost::{self, Profile, Range};
use crate::core::emu::{
    self, findings::Finding, Compiled, Constants, Draw, DrawOutput, EmuError, LinearInput,
    SamplerState, TextureLevels,
};
use crate::core::image::{MipChain, OddSides, RenderTarget, TargetFormat, Texture};
use crate::core::load;
use crate::core::merge::{self, MergeStats, OutputState};
use crate::jobs::backend;
use serde::Serialize;

/// A texture a draw list reads: an image or a synthetic input, owned.
#[derive(Clone, Debug, PartialEq)]
pub struct TextureData {
    /// The name steps and reports use for it.
    pub name: String,
    /// Width in texels.
    pub width: u32,
    /// Height in texels.
    pub height: u32,
    /// `width × height` texels, row-major, top row first (empty when
    /// `file` holds the texture).
    pub texels: Vec<[f32; 4]>,
    /// A texture file's levels, cube faces or volume slices (a DDS file
    /// with more than one level-0 image); samplers read it instead of
    /// `texels`.
    pub file: Option<crate::core::image::TextureFile>,
}

/// A render target of a draw list.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct TargetSpec {
    /// The name steps and reports use for it.
    pub name: String,
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// The D3D9 format it stores (each write is rounded to it).
    pub format: TargetFormat,
}

/// A shader a draw list runs, loaded once however many draws use it.
#[derive(Clone, Debug)]
pub struct ShaderSpec {
    /// The bundled name or the file it came from.
    pub name: String,
    /// The validated shader and its source.
    pub loaded: load::Loaded,
}

/// What a sampler reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Source {
    /// A texture of [`DrawList::textures`].
    Texture(usize),
    /// A target of [`DrawList::targets`], as it is when the draw runs.
    Target(usize),
}

/// One draw: a full-screen quad over `target`.
#[derive(Clone, Debug)]
pub struct DrawStep {
    /// Index into [`DrawList::targets`]: the target drawn over, whole.
    pub target: usize,
    /// Index into [`DrawList::shaders`].
    pub shader: usize,
    /// `(v#, value)`.
    pub inputs: Vec<(u32, LinearInput)>,
    /// The application's `c#`, `i#`, `b#`.
    pub constants: Constants,
    /// `(s#, what it reads, its sampler state)`.
    pub samplers: Vec<(u32, Source, SamplerState)>,
    /// Blend state and write mask of the output merger.
    pub output: OutputState,
    /// Float rules, alpha test, further targets, clip planes, flat
    /// shading ([`pixel_state`]); boxed, as most draws leave it default.
    pub pixel: Box<pixel_state::PixelState>,
    /// The vertices drawn ([`geometry`]); `None`: a full-screen quad.
    pub geometry: Option<Box<geometry::Geometry>>,
}

/// One step of a draw list.
#[derive(Clone, Debug)]
pub enum Step {
    /// `Clear(D3DCLEAR_TARGET)` with a D3DCOLOR (R, G, B, A bytes).
    Clear {
        /// Index into [`DrawList::targets`].
        target: usize,
        /// R, G, B, A bytes.
        color: [u8; 4],
    },
    /// A full-screen draw into one target.
    Draw(DrawStep),
    /// Build the target's full mip chain in its format (the reduction to
    /// 1 × 1); later draws sample it with its levels.
    Mips {
        /// Index into [`DrawList::targets`].
        target: usize,
        /// How levels with an odd side are reduced.
        odd: OddSides,
    },
}

/// A runnable draw list.
#[derive(Clone, Debug)]
pub struct DrawList {
    /// The render targets, by index; each starts black.
    pub targets: Vec<TargetSpec>,
    /// The textures, by index.
    pub textures: Vec<TextureData>,
    /// The shaders, by index.
    pub shaders: Vec<ShaderSpec>,
    /// What runs, in order.
    pub steps: Vec<Step>,
}

/// How a draw list runs.
#[derive(Clone, Debug, Default)]
pub struct Settings {
    /// Emulator threads (`None`: all cores).
    pub threads: Option<usize>,
    /// The emulator's bounds (executed slots per pixel, target size), for
    /// each draw.
    pub limits: emu::EmuLimits,
    /// The bounds of the whole list.
    pub budget: ListBudget,
    /// The float rules of draws that do not name their own.
    pub float_rules: crate::core::float_rules::FloatRules,
    /// Who runs each draw's shader: the emulator, or a GPU through the
    /// translation. Clears, blending, write masks, the pixel state and mip
    /// reductions are ps30's output merger on either.
    pub backend: crate::jobs::backend::Backend,
}

/// Bounds on a whole draw list's work, on top of each draw's
/// ([`emu::EmuLimits`]): a list of many steps, each within its own bounds,
/// can still ask for hours of work.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ListBudget {
    /// Pixels that all steps together touch: a clear or a draw its target's
    /// pixels, a mip reduction every level it writes, each step at least
    /// [`ListBudget::STEP_PIXELS`] for its fixed cost. Computed from the
    /// list before any step runs; a list over it is refused whole.
    pub max_pixels: u64,
    /// Instruction slots that all draws together execute. Not known before
    /// the draws run (it depends on the data): each draw runs under what is
    /// left of it, and the list stops at the draw that exceeds it.
    pub max_executed: u64,
}

impl ListBudget {
    /// Default [`ListBudget::max_pixels`]: 32 Mi pixels, e.g. thirty-two
    /// full-screen draws into a 1024 × 1024 target (on two cores, a draw
    /// of a short shader costs about a microsecond a pixel: tens of seconds).
    pub const MAX_PIXELS: u64 = 1 << 25;
    /// Default [`ListBudget::max_executed`]: four draws at the per-draw
    /// default of [`emu::EmuLimits::MAX_EXECUTED_TOTAL`].
    pub const MAX_EXECUTED: u64 = 4 * emu::EmuLimits::MAX_EXECUTED_TOTAL;
    /// The least a step counts in [`ListBudget::max_pixels`]: a step's fixed
    /// cost (setting up a draw, its cost analysis, a report) is that of
    /// shading about this many pixels.
    pub const STEP_PIXELS: u64 = 4096;
}

impl Default for ListBudget {
    fn default() -> ListBudget {
        ListBudget {
            max_pixels: ListBudget::MAX_PIXELS,
            max_executed: ListBudget::MAX_EXECUTED,
        }
    }
}

impl Step {
    /// The index of the target the step clears, reduces or draws into.
    pub fn target(&self) -> usize {
        match self {
            Step::Clear { target, .. } | Step::Mips { target, .. } => *target,
            Step::Draw(d) => d.target,
        }
    }
}

/// The pixels a list's steps touch together ([`ListBudget::max_pixels`]),
/// saturating.
pub fn pixel_work(list: &DrawList) -> u64 {
    list.steps.iter().fold(0u64, |total, step| {
        let t = &list.targets[step.target()];
        let mut pixels = u64::from(t.width) * u64::from(t.height);
        if let Step::Mips { .. } = step {
            // Every level below the first, each side halved (rounded up).
            let (mut w, mut h) = (u64::from(t.width), u64::from(t.height));
            pixels = 0;
            while w > 1 || h > 1 {
                w = w.div_ceil(2);
                h = h.div_ceil(2);
                pixels += w * h;
            }
        }
        total.saturating_add(pixels.max(ListBudget::STEP_PIXELS))
    })
}

/// An upper bound on the bytes that writing every target after every step
/// stages (`ps30 render --every-step`): its stored values as 32-bit floats
/// (the EXR, uncompressed) and an 8-bit RGB preview (the PNG), plus 4 KiB of
/// headers each.
pub fn staged_bytes_every_step(list: &DrawList) -> u64 {
    list.steps
        .iter()
        .flat_map(changed_targets)
        .fold(0u64, |total, t| {
            let t = &list.targets[t];
            let pixels = u64::from(t.width) * u64::from(t.height);
            let channels = t.format.channels() as u64;
            total.saturating_add(pixels * (4 * channels + 3) + 2 * 4096)
        })
}

/// The targets a step changes: the one it clears, reduces or draws into,
/// and a draw's oC1–oC3 targets.
pub fn changed_targets(step: &Step) -> Vec<usize> {
    let mut out = vec![step.target()];
    if let Step::Draw(d) = step {
        out.extend(d.pixel.outputs.iter().flatten().map(|&(t, _)| t));
    }
    out
}

/// What one step did.
#[derive(Clone, Debug, Serialize)]
pub struct StepReport {
    /// The step's index in [`DrawList::steps`].
    pub index: usize,
    /// `clear`, `draw` or `mips`.
    pub kind: &'static str,
    /// The name of the target it changed.
    pub target: String,
    /// What the step did, by kind.
    pub detail: StepDetail,
}

/// The kind-specific part of a [`StepReport`].
#[derive(Clone, Debug, Serialize)]
#[serde(untagged)]
pub enum StepDetail {
    /// A clear.
    Clear {
        /// R, G, B, A bytes.
        color: [u8; 4],
    },
    /// A draw.
    Draw {
        /// The shader's name.
        shader: String,
        /// Executed slots per pixel, from the cost model with the draw's
        /// integer and boolean constants (`executed` in JSON, as for every
        /// pass).
        #[serde(rename = "executed")]
        executed_static: Range,
        /// What the emulator counted (min, max over pixels); `None` when a
        /// GPU ran the shader (it counts nothing).
        #[serde(rename = "executed_emulated")]
        executed: Option<Range>,
        /// Whether every pixel's emulated count lies inside the static range
        /// (true when nothing was counted).
        counts_agree: bool,
        /// What the output merger wrote, blended and masked.
        merged: MergeStats,
        /// A draw of geometry: the triangles that reached the pixel
        /// shader (after assembly, clipping and culling; a point is two);
        /// absent for a full-screen draw.
        #[serde(skip_serializing_if = "Option::is_none")]
        triangles: Option<u64>,
        /// The emulator's findings about the draw's quads (divergent gradients,
        /// LOD far from level 0); not in JSON.
        #[serde(skip)]
        findings: Vec<Finding>,
    },
    /// A mip-chain reduction.
    Mips {
        /// How levels with an odd side were reduced.
        odd: OddSides,
        /// Levels in the chain, the base included.
        levels: usize,
        /// The 1 × 1 level: the reduction of the target.
        mean: [f32; 4],
    },
}

/// A target as it is during and after a run.
#[derive(Clone, Debug, PartialEq)]
pub struct TargetState {
    /// The target's texels, in its format.
    pub target: RenderTarget,
    /// The mip chain of its last [`Step::Mips`], until it is drawn into again.
    pub mips: Option<MipChain>,
    /// Its depth-stencil surface, once a draw of geometry tests depth.
    pub depth: Option<geometry::run::DepthBuffer>,
}

/// Why a draw list could not run (a result that disagrees is not an error).
#[derive(Debug)]
pub enum RenderError {
    /// Step `index`, and what went wrong there.
    Step {
        /// The step's index in [`DrawList::steps`].
        index: usize,
        /// What is wrong, in one sentence.
        message: String,
    },
    /// The emulator refused or could not finish a draw.
    Emu {
        /// The step's index in [`DrawList::steps`].
        index: usize,
        /// The emulator's error.
        error: EmuError,
    },
    /// The whole list is over its [`ListBudget`]: what, and which flag
    /// raises it.
    Budget(String),
    /// A shader the emulator cannot compile.
    Compile {
        /// The shader's name.
        shader: String,
        /// The emulator's error.
        error: EmuError,
    },
}

impl std::fmt::Display for RenderError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            RenderError::Step { index, message } => write!(f, "steps[{index}]: {message}"),
            RenderError::Emu { index, error } => write!(f, "steps[{index}]: emulator: {error}"),
            RenderError::Compile { shader, error } => write!(f, "{shader}: emulator: {error}"),
            RenderError::Budget(message) => f.write_str(message),
        }
    }
}

impl std::error::Error for RenderError {}

/// Runs every step in order. `observe` sees each step's report and every
/// target as it is after that step. Returns the reports and the targets at
/// the end.
pub fn run(
    list: &DrawList,
    settings: &Settings,
    observe: &mut dyn FnMut(&StepReport, &[TargetState]),
) -> Result<(Vec<StepReport>, Vec<TargetState>), RenderError> {
    run_with_history(list, settings, observe, None)
}

/// [`run`], recording the history of the pixels `history` watches
/// ([`history::Recorder`]) as the steps run.
pub fn run_with_history(
    list: &DrawList,
    settings: &Settings,
    observe: &mut dyn FnMut(&StepReport, &[TargetState]),
    history: Option<&mut history::Recorder>,
) -> Result<(Vec<StepReport>, Vec<TargetState>), RenderError> {
    let states: Vec<TargetState> = list
        .targets
        .iter()
        .map(|t| TargetState {
            target: RenderTarget::new(t.width, t.height, t.format),
            mips: None,
            depth: None,
        })
        .collect();
    run_on(list, settings, states, observe, history)
}

/// [`run`] on targets that already hold something (one per
/// [`DrawList::targets`], each of its size and format): the steps draw
/// over them rather than over black, as a device's surfaces keep what
/// earlier draws left (`ps30 shader-test` runs a file's draws this way),
/// recording the history of the pixels `history` watches.
pub fn run_on(
    list: &DrawList,
    settings: &Settings,
    mut states: Vec<TargetState>,
    observe: &mut dyn FnMut(&StepReport, &[TargetState]),
    mut history: Option<&mut history::Recorder>,
) -> Result<(Vec<StepReport>, Vec<TargetState>), RenderError> {
    let pixels = pixel_work(list);
    if pixels > settings.budget.max_pixels {
        return Err(RenderError::Budget(format!(
            "the list's steps touch {} pixels in all, over the budget of {} (raise it with --max-list-pixels {pixels})",
            crate::core::numbers::thousands(pixels),
            crate::core::numbers::thousands(settings.budget.max_pixels)
        )));
    }
    let fits = states.len() == list.targets.len()
        && states.iter().zip(&list.targets).all(|(s, t)| {
            (s.target.width, s.target.height, s.target.format) == (t.width, t.height, t.format)
        });
    if !fits {
        return Err(RenderError::Budget(
            "the targets given do not match the draw list's".into(),
        ));
    }
    let mut executed_left = settings.budget.max_executed;
    // Vertex shaders run in the vertex stage, through the IR.
    let compiled: Vec<Option<Compiled>> = list
        .shaders
        .iter()
        .map(|s| {
            let vertex =
                s.loaded.shader.program().profile.stage() == crate::core::profile::Stage::Vertex;
            (!vertex)
                .then(|| emu::compile(&s.loaded.shader))
                .transpose()
                .map_err(|error| RenderError::Compile {
                    shader: s.name.clone(),
                    error,
                })
        })
        .collect::<Result<_, _>>()?;
    let mut reports = Vec::with_capacity(list.steps.len());
    for (index, step) in list.steps.iter().enumerate() {
        if let Some(h) = history.as_deref_mut() {
            h.begin_step(list, index, &states);
        }
        let report = match step {
            Step::Clear { target, color } => {
                let state = &mut states[*target];
                merge::clear(&mut state.target, *color);
                state.mips = None;
                report(
                    index,
                    "clear",
                    list,
                    *target,
                    StepDetail::Clear { color: *color },
                )
            }
            Step::Mips { target, odd } => {
                let state = &mut states[*target];
                let chain = MipChain::reduce(state.target.as_texture(), state.target.format, *odd)
                    .map_err(|message| RenderError::Step { index, message })?;
                let detail = StepDetail::Mips {
                    odd: *odd,
                    levels: chain.len(),
                    mean: chain.last_texel(),
                };
                state.mips = Some(chain);
                report(index, "mips", list, *target, detail)
            }
            Step::Draw(d) => {
                let mut limits = settings.limits;
                let list_bound = limits.max_executed_total > executed_left;
                limits.max_executed_total = limits.max_executed_total.min(executed_left);
                let watch = history.as_deref_mut();
                let (detail, executed) = draw(
                    list,
                    compiled[d.shader].as_ref(),
                    d,
                    &mut states,
                    (settings, limits),
                    watch,
                )
                .map_err(|e| match e {
                            DrawFailure::Emu(EmuError::TotalExecutedLimit { .. }) if list_bound => {
                                RenderError::Budget(format!(
                                    "steps[{index}]: the list's draws execute more than {} instruction slots in all (raise it with --max-list-executed)",
                                    crate::core::numbers::thousands(settings.budget.max_executed)
                                ))
                            }
                            e => e.at(index),
                        })?;
                executed_left = executed_left.saturating_sub(executed);
                report(index, "draw", list, d.target, detail)
            }
        };
        if let Some(h) = history.as_deref_mut() {
            h.end_step(index, &states);
        }
        observe(&report, &states);
        reports.push(report);
    }
    Ok((reports, states))
}

fn report(
    index: usize,
    kind: &'static str,
    list: &DrawList,
    target: usize,
    detail: StepDetail,
) -> StepReport {
    StepReport {
        index,
        kind,
        target: list.targets[target].name.clone(),
        detail,
    }
}

/// A draw's failure before its step index is known.
pub(crate) enum DrawFailure {
    Message(String),
    Emu(EmuError),
}

impl DrawFailure {
    fn at(self, index: usize) -> RenderError {
        match self {
            DrawFailure::Message(message) => RenderError::Step { index, message },
            DrawFailure::Emu(error) => RenderError::Emu { index, error },
        }
    }
}

/// Runs one draw and merges its colours into its target; returns its report
/// and the instruction slots it executed, all pixels together.
fn draw(
    list: &DrawList,
    compiled: Option<&Compiled>,
    d: &DrawStep,
    states: &mut [TargetState],
    (settings, limits): (&Settings, emu::EmuLimits),
    mut watch: Option<&mut history::Recorder>,
) -> Result<(StepDetail, u64), DrawFailure> {
    let threads = settings.threads;
    let spec = &list.targets[d.target];
    let shader = &list.shaders[d.shader];
    let compiled = compiled.ok_or_else(|| {
        DrawFailure::Message(format!(
            "{} is a vertex shader, not a pixel shader",
            shader.name
        ))
    })?;
    if let Some(g) = &d.geometry {
        return geometry_draw(list, compiled, d, g, states, (settings, limits), watch);
    }
    let mut emu_draw = Draw::new(spec.width, spec.height);
    emu_draw.limits = limits;
    emu_draw.record_lod = true;
    emu_draw.count_instructions = watch
        .as_deref()
        .is_some_and(history::Recorder::counts_instructions);
    emu_draw.inputs = d.inputs.clone();
    if d.pixel.flat {
        pixel_state::flatten_inputs(shader.loaded.shader.program(), &mut emu_draw.inputs);
    }
    emu_draw.constants = d.constants.clone();
    emu_draw.float_rules = d.pixel.float_rules.unwrap_or(settings.float_rules);
    emu_draw.samplers = bind_samplers(list, d, &d.samplers, states)?;
    let mut out = backend::draw_output(
        &settings.backend,
        &shader.loaded.shader,
        compiled,
        &shader.loaded.file,
        &emu_draw,
        threads,
    )
    .map_err(|e| match e {
        backend::DrawError::Emu(e) => DrawFailure::Emu(e),
        other => DrawFailure::Message(other.to_string()),
    })?;
    let counted = matches!(settings.backend, backend::Backend::Emulator);
    if let Some(w) = watch.as_deref_mut() {
        w.full_screen(shader.loaded.shader.program(), &emu_draw, &out, &d.pixel);
    }
    let oc0 = out.color.first().and_then(|c| c.as_deref());
    let mut killed = out.killed.clone();
    d.pixel.apply(oc0, &mut killed, spec.width);
    out.killed = killed;
    let findings = if counted {
        emu::findings::findings(&out, &emu_draw, &shader.loaded.file)
    } else {
        Vec::new()
    };
    let executed_static = static_count(shader, &d.constants)?;
    let executed = counted.then(|| Range {
        min: out.executed.iter().copied().min().unwrap_or(0),
        max: out.executed.iter().copied().max().unwrap_or(0),
    });
    // A GPU counts nothing: the list's budget is charged the cost model's
    // upper bound for every pixel instead.
    let executed_total = if counted {
        out.executed.iter().fold(0u64, |a, &e| a.saturating_add(e))
    } else {
        executed_static
            .max
            .saturating_mul(u64::from(spec.width) * u64::from(spec.height))
    };
    drop(emu_draw);
    let state = &mut states[d.target];
    let merged = match out.color.first().and_then(|c| c.as_ref()) {
        Some(colors) => {
            if let Some(w) = watch.as_deref_mut() {
                w.before_merge(0, &state.target, colors);
            }
            let stats = merge::merge(&mut state.target, colors, &out.killed, &d.output)
                .map_err(|e| DrawFailure::Message(e.to_string()))?;
            if let Some(w) = watch.as_deref_mut() {
                w.after_merge(0, &state.target);
            }
            stats
        }
        // No oC0 written: the target is not updated.
        None => MergeStats {
            written: 0,
            killed: out.killed.iter().filter(|&&k| k).count() as u64,
        },
    };
    state.mips = None;
    // oC1–oC3 into their own targets: one blend state, each its own mask.
    for (k, bound) in d.pixel.outputs.iter().enumerate() {
        let (Some((t, write)), Some(colors)) =
            (bound, out.color.get(k + 1).and_then(|c| c.as_ref()))
        else {
            continue;
        };
        let state = &mut states[*t];
        let output = OutputState {
            blend: d.output.blend,
            write: *write,
        };
        if let Some(w) = watch.as_deref_mut() {
            w.before_merge(k + 1, &state.target, colors);
        }
        merge::merge(&mut state.target, colors, &out.killed, &output)
            .map_err(|e| DrawFailure::Message(format!("oC{}: {e}", k + 1)))?;
        if let Some(w) = watch.as_deref_mut() {
            w.after_merge(k + 1, &state.target);
        }
        state.mips = None;
    }
    let detail = draw_detail(shader, executed_static, executed, merged, None, findings);
    Ok((detail, executed_total))
}

/// The textures a draw's samplers read, as the emulator binds them.
pub(crate) fn bind_samplers<'s>(
    list: &'s DrawList,
    d: &DrawStep,
    samplers: &[(u32, Source, SamplerState)],
    states: &'s [TargetState],
) -> Result<Vec<(u32, TextureLevels<'s>, SamplerState)>, DrawFailure> {
    let spec = &list.targets[d.target];
    let mut out = Vec::with_capacity(samplers.len());
    for &(s, source, state) in samplers {
        let levels: TextureLevels<'_> = match source {
            Source::Texture(t) => {
                let t = &list.textures[t];
                match &t.file {
                    Some(file) => file.into(),
                    None => Texture {
                        width: t.width,
                        height: t.height,
                        texels: &t.texels,
                    }
                    .into(),
                }
            }
            Source::Target(t) if t == d.target => {
                return Err(DrawFailure::Message(format!(
                "s{s} samples `{}`, the target this draw renders to (Direct3D 9 does not allow it)",
                spec.name
            )))
            }
            Source::Target(t) => match &states[t].mips {
                Some(chain) => chain.into(),
                None => states[t].target.as_texture().into(),
            },
        };
        out.push((s, levels, state));
    }
    Ok(out)
}

/// A draw of geometry ([`geometry`]) and its report.
fn geometry_draw(
    list: &DrawList,
    compiled: &Compiled,
    d: &DrawStep,
    g: &geometry::Geometry,
    states: &mut [TargetState],
    (settings, limits): (&Settings, emu::EmuLimits),
    watch: Option<&mut history::Recorder>,
) -> Result<(StepDetail, u64), DrawFailure> {
    let shader = &list.shaders[d.shader];
    let drawn = geometry::run::draw(list, compiled, d, g, states, (settings, limits), watch)?;
    let executed_static = static_count(shader, &d.constants)?;
    let executed = drawn.executed.map(|(min, max)| Range { min, max });
    // A GPU counts nothing: the list's budget is charged the cost model's
    // longest path for every pixel it shaded, as for a full-screen draw.
    let total = match settings.backend {
        backend::Backend::Emulator => drawn.total,
        _ => executed_static.max.saturating_mul(drawn.shaded),
    };
    let summary = DrawOutput {
        gradients: drawn.gradients,
        ..DrawOutput::uncounted((0, 0), Vec::new(), None, Vec::new())
    };
    let mut draw = Draw::new(1, 1);
    draw.samplers = bind_samplers(list, d, &d.samplers, states)?;
    let findings = emu::findings::findings(&summary, &draw, &shader.loaded.file);
    let detail = draw_detail(
        shader,
        executed_static,
        executed,
        drawn.merged,
        Some(drawn.triangles),
        findings,
    );
    Ok((detail, total))
}

/// A draw's report: its counts beside the cost model's, what it merged,
/// the emulator's findings.
fn draw_detail(
    shader: &ShaderSpec,
    executed_static: Range,
    executed: Option<Range>,
    merged: MergeStats,
    triangles: Option<u64>,
    findings: Vec<Finding>,
) -> StepDetail {
    StepDetail::Draw {
        triangles,
        shader: shader.name.clone(),
        counts_agree: executed
            .is_none_or(|e| executed_static.min <= e.min && e.max <= executed_static.max),
        executed_static,
        executed,
        merged,
        findings,
    }
}

/// The cost model's executed range for a draw, under its constants.
fn static_count(shader: &ShaderSpec, c: &Constants) -> Result<Range, DrawFailure> {
    let a = cost::analyse(
        &shader.loaded.shader,
        &shader.loaded.file,
        &crate::jobs::backend::environment(c),
        &Profile::ps_3_0(),
    )
    .map_err(|e| DrawFailure::Message(format!("{}: {e}", shader.name)))?;
    Ok(a.executed)
}

/// The texture coordinate of pixel centres over a `w × h` target:
/// v = ((x + ½)/w, (y + ½)/h, 0, 0), the full-screen quad's usual mapping.
pub fn texcoord(w: u32, h: u32) -> LinearInput {
    let (w, h) = (w as f32, h as f32);
    LinearInput {
        base: [0.5 / w, 0.5 / h, 0.0, 0.0],
        ddx: [1.0 / w, 0.0, 0.0, 0.0],
        ddy: [0.0, 1.0 / h, 0.0, 0.0],
    }
}

impl DrawList {
    /// The index of the target named `name`.
    pub fn target(&self, name: &str) -> Option<usize> {
        self.targets.iter().position(|t| t.name == name)
    }
}
