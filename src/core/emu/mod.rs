//! The emulator: runs a validated ps_3_0 shader over every pixel of a render
//! target on the CPU, giving per-pixel outputs, texkill results and executed
//! instruction-slot counts.
//!
//! It exists so ps30 can measure and check shaders without a Direct3D 9
//! device: the luminance pipeline renders through it, and the executed-slot
//! counts it reports must agree with the static cost model.
//!
//! How it works:
//! * [`compile()`] turns a [`crate::core::ir::Shader`] into a flat list of small
//!   `Copy` micro-ops ([`MicroOp`], 20 bytes) once: registers become row
//!   offsets, jumps become op indices, every op carries its slot cost.
//! * The executor runs [`LANES`] pixels in lockstep: lanes `4k..4k+3` are one
//!   2×2 quad (top-left, top-right, bottom-left, bottom-right), quads are
//!   taken in row-major order over the quad grid, 16 quads per batch (fewer
//!   on small targets, so that they still split over threads); ops compute
//!   only the lanes up to the batch's last quad in the target.
//!   Registers are structure-of-arrays (one row of lane values per register
//!   component). Divergent flow control uses per-lane execution masks (`u64`
//!   bit sets); when every live lane is active, ops run without any mask
//!   checks.
//! * Batches are independent, so [`run_with_threads`] spreads them over a
//!   rayon pool; results are bit-identical for any thread count.
//!
//! Executed-slot rule (must match the static cost model): every executed
//! instruction charges its static slots ([`crate::core::ir::Info::slots`]) to every
//! lane executing it; `rep`/`loop` are charged once per iteration and
//! `endrep`/`endloop` once per completed iteration; a rep/loop with zero
//! iterations charges its own slots once; `if`/`endif` (and `else`) are
//! charged to every lane that reaches them (both paths pass `else`); a
//! `break` charges its own slots and a lane leaving through it does not reach
//! (nor pay for) that iteration's `endrep`; `call`/`callnz` charge themselves,
//! the callee and its `ret`; `label` costs 0; `ret` in main ends the lane.
//! Lanes masked off pay nothing.
//!
//! Quads (see [`DrawOutput`]): a quad runs in lockstep, so it pays every
//! executed op once if any of its four lanes — helpers included — executes
//! it: [`DrawOutput::quad_executed`] is that count, the per-pixel counts
//! above are each lane's own path. A quad is *divergent* at an op when some
//! but not all four of its lanes execute it; [`DrawOutput::quad_divergent`]
//! marks quads that were, and [`DrawOutput::gradients`] counts, per source
//! statement of `dsx`, `dsy`, `texld`, `texldp`, `texldb`, the quads that
//! ran it divergently — where the gradient reads neighbours that are not at
//! the same point of execution (undefined in Direct3D for temporaries).
//! Predication masks writes, not execution: a predicated op runs in every
//! lane, so it never makes a quad divergent here (the validator still warns
//! about predicated gradient instructions, as Microsoft's rejects them).
//! Level-of-detail selection for the texld family is described in
//! `texop.rs` and `sample.rs`.
//!
//! Semantic choices where the documentation is silent are listed beside the
//! functions in `math.rs` and `sample.rs`, and here:
//! * `texkill` marks the pixel discarded; the lane keeps executing and
//!   paying (as in the static cost model, and as D3D9's texkill only flags
//!   the pixel), and stays a valid neighbour for `dsx`/`dsy`. A discarded
//!   pixel's colours and depth are reported as zero.
//! * pixels outside the target that share a quad with pixels inside it run
//!   as helper lanes (as on hardware): they execute with their own flow
//!   control so `dsx`/`dsy` see real neighbour values, but they are never
//!   counted or reported, and one that exceeds the executed limit is dropped
//!   rather than failing the draw. A pixel's results therefore do not depend
//!   on the other quads of its batch.
//! * `dsx`/`dsy` are coarse: one difference per quad (top-right − top-left,
//!   bottom-left − top-left), reading whatever the neighbour lane holds (its
//!   last value if it is masked off or killed).
//! * The sampler swizzle of texld (`s0.yzxw`) reorders the sampled result.
//! * `texkill` tests the x, y, z and w components that its operand's mask
//!   selects (ps_2_0 and later test w too; ps_1_x stopped at xyz).
//! * `_pp` is ignored (computed in full f32 precision, which MS-MOD allows).
//! * rep/loop integer constants outside Microsoft's ranges (count and loop
//!   start 0..=255, step −128..=127) are refused with
//!   [`EmuError::InvalidIntConstant`], as the cost model refuses them.
//! * `log` and texel addressing are implemented here in plain f32 so they
//!   are identical on every platform; `exp`, `pow`, `sincos` use Rust's
//!   `f32` functions (the platform libm), whose last bit may differ between
//!   platforms.

mod arith;
mod compile;
mod exec;
pub mod findings;
mod layered;
pub mod lines;
mod math;
mod planes;
mod quad;
mod sample;
#[cfg(test)]
mod testasm;
#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_layered;
#[cfg(test)]
mod tests_ps1;
#[cfg(test)]
mod tests_sampling;
mod texop;
mod texop3;
pub mod vertex;

pub use compile::{compile, compile_under, Compiled, MicroOp};

use crate::core::isa::SamplerType;
use exec::{BatchOut, Worker};
use planes::Planes;
use rayon::prelude::*;
use sample::Sampler;
use std::fmt;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex, OnceLock};

/// Lanes per batch: 16 quads of 2×2 pixels.
pub const LANES: usize = 64;
const QUADS_PER_BATCH: u64 = (LANES / 4) as u64;
/// Batches run between two merges of their counts, in batch order.
const CHUNK: u64 = 1024;

/// An interpolated input varying linearly over the target:
/// `v#(x, y) = base + x·ddx + y·ddy` for integer pixel coordinates (D3D9 pixel
/// centres are integers, facts sheet §2), evaluated in f32 as
/// `(base + x·ddx) + y·ddy`.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct LinearInput {
    /// The value at pixel (0, 0).
    pub base: [f32; 4],
    /// The change from one pixel to the next in x.
    pub ddx: [f32; 4],
    /// The change from one row to the next in y.
    pub ddy: [f32; 4],
}

impl LinearInput {
    /// The same value at every pixel.
    pub fn constant(value: [f32; 4]) -> LinearInput {
        LinearInput {
            base: value,
            ..LinearInput::default()
        }
    }

    /// Value at pixel `(x, y)`.
    pub fn at(&self, x: f32, y: f32) -> [f32; 4] {
        std::array::from_fn(|c| self.base[c] + x * self.ddx[c] + y * self.ddy[c])
    }
}

/// Constants set by the application (SetPixelShaderConstantF/I/B). Missing
/// entries are zero / false; the shader's `def`/`defi`/`defb` override them.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Constants {
    /// `c0..`, at most 224.
    pub float: Vec<[f32; 4]>,
    /// `i0..`, at most 16.
    pub int: Vec<[i32; 4]>,
    /// `b0..`, at most 16.
    pub bool: Vec<bool>,
}

/// Texture filter within one mip level (D3DSAMP_MAGFILTER / MINFILTER).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Filter {
    /// The nearest texel.
    #[default]
    Point,
    /// Bilinear: the four nearest texels, weighted.
    Linear,
}

/// Filter between mip levels (D3DSAMP_MIPFILTER).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum MipFilter {
    /// Mipmapping disabled: every sample reads the base level (Direct3D's
    /// default).
    #[default]
    None,
    /// The nearest level: round(LOD).
    Point,
    /// Blend the two nearest levels by frac(LOD).
    Linear,
}

/// D3DTEXTUREADDRESS modes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Address {
    /// Repeat the texture (D3DTADDRESS_WRAP).
    Wrap,
    /// Mirror it at every edge.
    Mirror,
    /// The edge texel beyond the edges.
    Clamp,
    /// The border colour beyond the edges (the default here: the luminance pass pads with it).
    #[default]
    Border,
    /// Mirror once about 0, then clamp.
    MirrorOnce,
}

/// Sampler state of one `s#`. The default is the luminance pass's: point
/// filtering, BORDER addressing, border colour (0, 0, 0, 0), no mip
/// filtering, no LOD bias, MAXMIPLEVEL 0 — Direct3D's defaults except for the
/// addressing (Direct3D's own default is WRAP).
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct SamplerState {
    /// D3DSAMP_MAGFILTER: used when the LOD is ≤ 0.
    pub mag_filter: Filter,
    /// D3DSAMP_MINFILTER: used when the LOD is > 0.
    pub min_filter: Filter,
    /// D3DSAMP_MIPFILTER.
    pub mip_filter: MipFilter,
    /// D3DSAMP_MIPMAPLODBIAS, added to every LOD.
    pub mip_lod_bias: f32,
    /// D3DSAMP_MAXMIPLEVEL: the most detailed level allowed (0 = level 0);
    /// LODs below it are raised to it.
    pub max_mip_level: u32,
    /// Addressing in u (D3DSAMP_ADDRESSU).
    pub address_u: Address,
    /// Addressing in v (D3DSAMP_ADDRESSV).
    pub address_v: Address,
    /// Addressing in w (D3DSAMP_ADDRESSW), read by volume textures only.
    pub address_w: Address,
    /// The border colour (D3DSAMP_BORDERCOLOR) for BORDER addressing.
    pub border: [f32; 4],
}

impl SamplerState {
    /// The same filter for magnification and minification, no mips.
    pub fn filtered(filter: Filter) -> SamplerState {
        SamplerState {
            mag_filter: filter,
            min_filter: filter,
            ..SamplerState::default()
        }
    }
}

/// Textures are the image module's read-only texel views (one mip level,
/// RGBA f32, row 0 at the top).
pub use crate::core::image::Texture;

/// A texture with its mip levels (see [`crate::core::image::MipChain`]).
pub use crate::core::image::MipChain;

/// Cube and volume textures (see [`crate::core::image::CubeMap`]).
pub use crate::core::image::{CubeMap, VolumeChain};

/// What a sampler reads: one level, or a mip chain.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TextureLevels<'a> {
    /// A texture without mips (D3D9 `Levels = 1`).
    Single(Texture<'a>),
    /// A texture with its mip levels (box-filtered or authored).
    Chain(&'a MipChain),
    /// A cube texture: six square faces with their mip levels (`dcl_cube`).
    Cube(&'a CubeMap),
    /// A volume texture with its 3D mip levels (`dcl_volume`).
    Volume(&'a VolumeChain),
}

impl<'a> From<Texture<'a>> for TextureLevels<'a> {
    fn from(t: Texture<'a>) -> Self {
        TextureLevels::Single(t)
    }
}

impl<'a> From<&'a MipChain> for TextureLevels<'a> {
    fn from(c: &'a MipChain) -> Self {
        TextureLevels::Chain(c)
    }
}

impl<'a> From<&'a crate::core::image::TextureFile> for TextureLevels<'a> {
    fn from(t: &'a crate::core::image::TextureFile) -> Self {
        use crate::core::image::TextureFile;
        match t {
            TextureFile::Flat(c) => TextureLevels::Chain(c),
            TextureFile::Cube(c) => TextureLevels::Cube(c),
            TextureFile::Volume(v) => TextureLevels::Volume(v),
        }
    }
}

impl<'a> TextureLevels<'a> {
    /// Every level, level 0 first (a cube's +X face; a volume's first
    /// slice of each level).
    pub fn views(&self) -> Vec<Texture<'a>> {
        match *self {
            TextureLevels::Single(t) => vec![t],
            TextureLevels::Chain(c) => c.views(),
            TextureLevels::Cube(c) => c.face(0).views(),
            TextureLevels::Volume(v) => (0..v.len()).filter_map(|i| v.slice(i, 0)).collect(),
        }
    }

    /// Number of levels.
    pub fn len(&self) -> usize {
        match self {
            TextureLevels::Single(_) => 1,
            TextureLevels::Chain(c) => c.len(),
            TextureLevels::Cube(c) => c.face(0).len(),
            TextureLevels::Volume(v) => v.len(),
        }
    }

    /// The sampler declaration this texture answers (`dcl_2d`, `dcl_cube`,
    /// `dcl_volume`).
    pub fn sampler_type(&self) -> SamplerType {
        match self {
            TextureLevels::Single(_) | TextureLevels::Chain(_) => SamplerType::Tex2d,
            TextureLevels::Cube(_) => SamplerType::Cube,
            TextureLevels::Volume(_) => SamplerType::Volume,
        }
    }

    /// Always false: every binding has level 0.
    pub fn is_empty(&self) -> bool {
        false
    }
}

/// Safety limits of a draw.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct EmuLimits {
    /// Executed instruction slots allowed per pixel; exceeding it is
    /// [`EmuError::ExecutedLimit`].
    pub max_executed_per_pixel: u64,
    /// Largest `width × height` accepted.
    pub max_target_pixels: u64,
    /// Executed instruction slots allowed for the whole draw, every pixel
    /// together; exceeding it is [`EmuError::TotalExecutedLimit`].
    pub max_executed_total: u64,
}

impl EmuLimits {
    /// Default of `max_executed_per_pixel`: 152 times the 65,535 of ps_3_0.
    pub const MAX_EXECUTED_PER_PIXEL: u64 = 10_000_000;
    /// Default of `max_target_pixels`: 2048×2048.
    pub const MAX_TARGET_PIXELS: u64 = 1 << 22;
    /// Default of `max_executed_total`: a few seconds of emulation on two
    /// cores for the slowest instructions measured (see the README).
    pub const MAX_EXECUTED_TOTAL: u64 = 500_000_000;
}

impl Default for EmuLimits {
    fn default() -> EmuLimits {
        EmuLimits {
            max_executed_per_pixel: EmuLimits::MAX_EXECUTED_PER_PIXEL,
            max_target_pixels: EmuLimits::MAX_TARGET_PIXELS,
            max_executed_total: EmuLimits::MAX_EXECUTED_TOTAL,
        }
    }
}

/// Everything one draw needs besides the compiled shader.
#[derive(Clone, Debug, PartialEq)]
pub struct Draw<'a> {
    /// The render target's width in pixels.
    pub target_width: u32,
    /// The render target's height in pixels.
    pub target_height: u32,
    /// `(v#, value)`; every input the shader declares must be supplied.
    pub inputs: Vec<(u32, LinearInput)>,
    /// The constants the application sets (`def`s in the shader override them).
    pub constants: Constants,
    /// `(s#, texture, state)`; a declared but unbound sampler reads
    /// (0, 0, 0, 1). A [`Texture`] or a `&`[`MipChain`] converts with `.into()`.
    pub samplers: Vec<(u32, TextureLevels<'a>, SamplerState)>,
    /// Bounds on the work of the draw.
    pub limits: EmuLimits,
    /// Record the range of levels of detail each texld/texldp/texldb
    /// computes ([`GradientSite::lod`]). Off by default: on a single-level
    /// texture the LOD changes nothing, and computing it for every quad of
    /// every execution costs about 9% of the instructions of a texture-bound
    /// shader such as the luminance pass. Divergence counts are always kept.
    pub record_lod: bool,
    /// Count, per instruction, the lanes and quads that ran it
    /// ([`DrawOutput::instructions`]), for `ps30 profile`'s costs per
    /// source line. Off by default: a draw that does not ask pays one
    /// predictable branch per executed op.
    pub count_instructions: bool,
    /// The special values of the arithmetic (`ps30 … --float-rules`),
    /// shared with the translation that `core/gpu` draws.
    pub float_rules: crate::core::float_rules::FloatRules,
    /// Which side of the primitive the draw shows: the sign of `vFace`.
    pub face: Face,
    /// A primitive's pixels: which pixels of the target it covers and its
    /// inputs' values at every pixel of their quads ([`PixelInputs`]).
    /// `None` (the default): every pixel is covered and the inputs are
    /// [`Draw::inputs`]' planes.
    pub pixels: Option<&'a PixelInputs>,
}

/// The pixels of one primitive and its inputs' values at each of them: what
/// a draw of geometry hands the pixel shader, where interpolation with
/// perspective is no plane over the target.
///
/// The draw's `target_width × target_height` is a window of the render
/// target whose pixel (0, 0) is the render target's pixel `origin`; both
/// coordinates of `origin` are even, so that the window's 2×2 quads are the
/// render target's. Only `covered` pixels are reported; the other pixels of
/// a quad with a covered pixel run as helper lanes, with their own values
/// from `values` (the primitive's interpolation extended past its edges, as
/// hardware computes it), so that `dsx`/`dsy` and the texld family's level
/// of detail see at a primitive's edge what they see on hardware.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct PixelInputs {
    /// The render-target pixel of the window's pixel (0, 0); even
    /// coordinates. `vPos` is `origin + (x, y)`.
    pub origin: (u32, u32),
    /// `target_width × target_height` flags, row-major: the pixels the
    /// primitive covers.
    pub covered: Vec<bool>,
    /// `(slot, values)`: every pixel of the window's quad grid, `2·⌈w/2⌉ ×
    /// 2·⌈h/2⌉` values row-major (a window of odd width or height has its
    /// last column or row outside it, helpers only).
    pub values: Vec<(u32, Vec<[f32; 4]>)>,
    /// The render-target pixel of every pixel of the quad grid, laid out
    /// as `values`, where the draw's pixels are not one window of the
    /// target but several primitives' windows packed side by side (each at
    /// even offsets, so that their quads stay quads): `vPos` is then the
    /// pixel's entry here and `origin` is not read. `None`: `vPos` is
    /// `origin + (x, y)`.
    pub positions: Option<Vec<(u32, u32)>>,
}

impl PixelInputs {
    /// The width of the quad grid the values are laid out in.
    pub fn grid_width(width: u32) -> usize {
        2 * width.div_ceil(2) as usize
    }
}

/// The facing of the primitive a draw rasterises, as `vFace` reports it.
///
/// Microsoft's ps_3_0 register page: vFace "will eventually contain the
/// primitive area", but in ps_3_0 only its sign is valid — negative for a
/// back face (counter-clockwise on screen), positive otherwise. The
/// emulator gives +1 or −1 in every component; anything that depends on
/// more than the sign is undefined in D3D9.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Face {
    /// Clockwise on screen (D3D9's front face): vFace = +1.
    #[default]
    Front,
    /// Counter-clockwise on screen: vFace = −1.
    Back,
}

impl Face {
    /// The value every component of `vFace` holds.
    pub fn value(self) -> f32 {
        match self {
            Face::Front => 1.0,
            Face::Back => -1.0,
        }
    }
}

impl<'a> Draw<'a> {
    /// A draw over a `width × height` target with nothing bound.
    pub fn new(width: u32, height: u32) -> Draw<'a> {
        Draw {
            target_width: width,
            target_height: height,
            inputs: Vec::new(),
            constants: Constants::default(),
            samplers: Vec::new(),
            limits: EmuLimits::default(),
            record_lod: false,
            count_instructions: false,
            float_rules: crate::core::float_rules::FloatRules::Hardware,
            face: Face::Front,
            pixels: None,
        }
    }
}

/// Per-pixel results, row-major (`index = y · width + x`).
#[derive(Clone, Debug, PartialEq)]
pub struct DrawOutput {
    /// The target's width in pixels.
    pub width: u32,
    /// The target's height in pixels.
    pub height: u32,
    /// One entry per `oC0..oC3`; `None` if no pixel executed a write to it.
    pub color: Vec<Option<Vec<[f32; 4]>>>,
    /// `oDepth`, `None` if no pixel executed a write to it.
    pub depth: Option<Vec<f32>>,
    /// Pixels discarded by `texkill`.
    pub killed: Vec<bool>,
    /// Executed instruction slots per pixel.
    pub executed: Vec<u64>,
    /// Quads per row: quad (qx, qy) covers pixels 2qx..2qx+1 × 2qy..2qy+1,
    /// and is entry `qy · quads_x + qx` of the per-quad vectors.
    pub quads_x: u32,
    /// Executed instruction slots per quad: every executed op charged once
    /// to each quad with at least one lane (helper lanes included) executing
    /// it — what a quad running in lockstep pays.
    pub quad_executed: Vec<u64>,
    /// Quads that ran some op with some but not all four of their lanes.
    pub quad_divergent: Vec<bool>,
    /// What the quads saw at each gradient instruction (dsx, dsy, texld,
    /// texldp, texldb), one entry per source statement.
    pub gradients: Vec<GradientSite>,
    /// What ran each instruction of the program (by its index), over
    /// every batch; empty unless [`Draw::count_instructions`].
    pub instructions: Vec<InstructionCount>,
}

impl DrawOutput {
    /// A `w × h` output whose values came from elsewhere (a GPU), which
    /// counts nothing: no executed slots, quads, gradients or per-line
    /// counts.
    pub fn uncounted(
        (w, h): (u32, u32),
        color: Vec<Option<Vec<[f32; 4]>>>,
        depth: Option<Vec<f32>>,
        killed: Vec<bool>,
    ) -> Self {
        DrawOutput {
            width: w,
            height: h,
            color,
            depth,
            killed,
            executed: vec![0; w as usize * h as usize],
            quads_x: w.div_ceil(2),
            quad_executed: Vec::new(),
            quad_divergent: Vec::new(),
            gradients: Vec::new(),
            instructions: Vec::new(),
        }
    }
}

/// What ran one instruction over a draw ([`Draw::count_instructions`]).
///
/// Each time the executor charges the instruction's slots — an `if`'s
/// lanes as they enter, `else` by the lanes of both sides, a `rep` or
/// `loop` again on each further iteration, as the cost model counts it —
/// the lanes charged are counted here, so that Σ `pixels` × slots over
/// the instructions is the covered pixels' executed slots and Σ `quads` ×
/// slots the quads' lockstep slots.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct InstructionCount {
    /// Runs by lanes the draw reports (pixels inside the target, or
    /// covered by the primitive).
    pub pixels: u64,
    /// Runs by helper lanes (the rest of their quads).
    pub helpers: u64,
    /// Runs by 2×2 quads in lockstep: each time a quad ran it with at
    /// least one lane.
    pub quads: u64,
    /// Of those, the runs with some but not all four lanes of the quad.
    pub divergent: u64,
}

impl InstructionCount {
    /// Adds `other`'s counts to these.
    pub fn add(&mut self, other: &InstructionCount) {
        self.pixels += other.pixels;
        self.helpers += other.helpers;
        self.quads += other.quads;
        self.divergent += other.divergent;
    }
}

/// One gradient-using source statement and what the quads did there.
///
/// A quad *executes it divergently* when some but not all of its four lanes
/// (helpers included) run it: the neighbour values the gradient needs are
/// then whatever the inactive lanes' registers hold, which Direct3D leaves
/// undefined for temporaries (facts sheet §5). Counts are over quads that
/// touch the target.
#[derive(Clone, Debug, PartialEq)]
pub struct GradientSite {
    /// Index of its (first) instruction in the program.
    pub instruction: usize,
    /// Where it is in the source.
    pub span: crate::core::ir::Span,
    /// The instruction.
    pub op: crate::core::isa::Opcode,
    /// The sampler of texld/texldp/texldb.
    pub sampler: Option<u32>,
    /// Whether the differenced operand (coordinate or dsx/dsy source) is a
    /// temporary `r#` — only then is a divergent execution undefined; inputs
    /// are interpolated for every pixel of the quad.
    pub temp_source: bool,
    /// Quads that executed it at least once.
    pub quads: u64,
    /// Quads that executed it divergently at least once.
    pub divergent_quads: u64,
    /// Quad-executions (a quad in a loop counts once per iteration).
    pub executions: u64,
    /// Quad-executions with some but not all four lanes active.
    pub divergent_executions: u64,
    /// Smallest and largest level of detail its executions computed (after
    /// D3DSAMP_MIPMAPLODBIAS and texldb's bias, before MAXMIPLEVEL and the
    /// chain's length clamp it); `None` for dsx/dsy, unbound samplers, sites
    /// never executed and draws without [`Draw::record_lod`]. −∞ means a
    /// zero gradient.
    pub lod: Option<(f32, f32)>,
}

/// Why a compile or a draw failed. The fields of each variant are what its
/// message names (see its `Display`).
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
#[allow(missing_docs)]
pub enum EmuError {
    /// The shader is of a profile ps30 checks and lists but does not run
    /// (every profile but ps_3_0).
    NotRun {
        profile: crate::core::profile::Profile,
    },
    /// A shader of a profile ps30 runs uses something it does not run yet
    /// (`reason` names it and its place).
    Refused {
        profile: crate::core::profile::Profile,
        reason: String,
    },
    /// The IR and its `Info` disagree, or use something the emulator cannot
    /// represent (`index` is the instruction).
    Malformed { index: usize, reason: String },
    /// A texture instruction samples an `s#` without `dcl_*`.
    MissingSamplerDecl { index: usize, sampler: u32 },
    /// The target has more pixels than the limit allows.
    TargetTooLarge { width: u32, height: u32, limit: u64 },
    /// A pixel ran more executed slots than the limit allows.
    ExecutedLimit {
        x: u32,
        y: u32,
        executed: u64,
        limit: u64,
    },
    /// The draw as a whole (a target of `pixels` pixels) ran more executed
    /// slots than the limit allows.
    TotalExecutedLimit { limit: u64, pixels: u64 },
    /// The target's memory could not be had (`bytes` asked for).
    OutOfMemory { bytes: u64 },
    /// `call`/`callnz` nested deeper than ps_3_0's 4 levels.
    CallDepth { x: u32, y: u32, index: usize },
    /// The shader declares an input (slot `input`, spelled `register`:
    /// `core/pixel_inputs.rs`) but the draw does not supply it.
    MissingInput { input: u32, register: String },
    /// The draw supplies an input slot the shader does not declare.
    InputNotDeclared { input: u32, register: String },
    /// The draw binds an `s#` the shader does not declare.
    SamplerNotDeclared { sampler: u32 },
    /// The same `v#` or `s#` given twice.
    DuplicateBinding { what: &'static str, index: u32 },
    /// A bound texture cannot be sampled (e.g. no texels).
    InvalidTexture { sampler: u32, reason: String },
    /// The texture bound is not of the declared sampler type (a 2D
    /// texture on `dcl_cube`, …).
    SamplerTypeMismatch {
        sampler: u32,
        declared: SamplerType,
        bound: SamplerType,
    },
    /// More constants given than ps_3_0 has registers.
    TooManyConstants {
        kind: &'static str,
        given: usize,
        max: usize,
    },
    /// An `i#` used by rep/loop is outside Microsoft's ranges.
    InvalidIntConstant { register: u32, reason: String },
    /// The thread pool could not be started.
    ThreadPool(String),
    /// A primitive's [`PixelInputs`] do not fit the draw's window.
    BadPixelInputs { reason: String },
}

impl fmt::Display for EmuError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            EmuError::NotRun { profile } => write!(
                f,
                "a {profile} shader: ps30 runs ps_1_1–ps_1_4, ps_2_0, ps_2_x and ps_3_0 pixel shaders ({profile} is read, checked, counted, assembled and listed: check, asm, disasm)"
            ),
            EmuError::Refused { profile, reason } => {
                write!(f, "a {profile} shader: {reason}")
            }
            EmuError::Malformed { index, reason } => {
                write!(f, "instruction {}: cannot emulate: {}", index, reason)
            }
            EmuError::MissingSamplerDecl { index, sampler } => write!(
                f,
                "instruction {}: sampler s{} is used but not declared with dcl_2d/dcl_cube/dcl_volume",
                index, sampler
            ),
            EmuError::TargetTooLarge {
                width,
                height,
                limit,
            } => write!(
                f,
                "render target {}x{} has more than {} pixels (raise the limit with --max-target-pixels)",
                width, height, limit
            ),
            EmuError::ExecutedLimit {
                x,
                y,
                executed,
                limit,
            } => write!(
                f,
                "pixel ({}, {}) executed {} instruction slots, more than the limit of {} (raise it with --max-executed-per-pixel)",
                x, y, executed, limit
            ),
            EmuError::TotalExecutedLimit { limit, pixels } => write!(
                f,
                "the draw over {} pixels executed more than {} instruction slots in all (raise the limit with --max-executed-total)",
                crate::core::numbers::thousands(*pixels),
                crate::core::numbers::thousands(*limit)
            ),
            EmuError::OutOfMemory { bytes } => write!(
                f,
                "the draw's outputs need {} bytes, more than this machine can give (lower the target size)",
                crate::core::numbers::thousands(*bytes)
            ),
            EmuError::CallDepth { x, y, index } => write!(
                f,
                "pixel ({}, {}): call at instruction {} nests deeper than 4 calls",
                x, y, index
            ),
            EmuError::MissingInput { input, register } => write!(
                f,
                "the shader declares {} but the draw supplies no value for it (input slot {})",
                register, input
            ),
            EmuError::InputNotDeclared { input, register } => write!(
                f,
                "the draw supplies {} but the shader does not declare it (input slot {})",
                register, input
            ),
            EmuError::SamplerNotDeclared { sampler } => write!(
                f,
                "the draw binds a texture to s{} but the shader does not declare it",
                sampler
            ),
            EmuError::DuplicateBinding { what, index } => {
                write!(f, "the draw gives {}{} more than once", what, index)
            }
            EmuError::InvalidTexture { sampler, reason } => {
                write!(f, "texture bound to s{}: {}", sampler, reason)
            }
            EmuError::SamplerTypeMismatch {
                sampler,
                declared,
                bound,
            } => write!(
                f,
                "s{} is declared dcl_{} but the draw binds a {} texture to it",
                sampler,
                declared.suffix(),
                match bound {
                    SamplerType::Tex2d => "2D",
                    SamplerType::Cube => "cube",
                    SamplerType::Volume => "volume",
                }
            ),
            EmuError::TooManyConstants { kind, given, max } => write!(
                f,
                "{} {} constants given, at most {} exist",
                given, kind, max
            ),
            EmuError::InvalidIntConstant { register, reason } => {
                write!(f, "i{} used by rep/loop: {}", register, reason)
            }
            EmuError::ThreadPool(e) => write!(f, "cannot start worker threads: {}", e),
            EmuError::BadPixelInputs { reason } => {
                write!(f, "a primitive's per-pixel inputs: {reason}")
            }
        }
    }
}

impl std::error::Error for EmuError {}

/// A draw resolved against a compiled shader: everything batches share.
pub(crate) struct RunCtx<'c, 'a> {
    pub compiled: &'c Compiled,
    pub ints: [[i32; 4]; 16],
    /// Bit i = `b#`.
    pub bools: u16,
    /// Values of the constant rows, in [`compile::Layout::consts`] order.
    pub consts: Vec<[f32; 4]>,
    pub samplers: [Option<Sampler<'a>>; 16],
    pub inputs: [Option<LinearInput>; 10],
    pub width: u64,
    pub height: u64,
    /// Quads per row of the quad grid.
    pub quads_x: u64,
    pub quads: u64,
    /// Quads per batch: [`QUADS_PER_BATCH`], fewer when the target has
    /// fewer full batches than there are threads ([`batch_quads`]).
    pub batch_quads: u64,
    pub cap: u64,
    pub record_lod: bool,
    /// [`Draw::count_instructions`].
    pub count_instructions: bool,
    /// The value of every component of `vFace`.
    pub face: f32,
    /// The draw's float rules.
    pub rules: crate::core::float_rules::FloatRules,
    /// A primitive's coverage and per-pixel inputs ([`Draw::pixels`]).
    pub pixels: Option<&'a PixelInputs>,
}

impl<'c, 'a> RunCtx<'c, 'a> {
    fn new(
        compiled: &'c Compiled,
        draw: &Draw<'a>,
        threads: usize,
    ) -> Result<RunCtx<'c, 'a>, EmuError> {
        let (w, h) = (draw.target_width as u64, draw.target_height as u64);
        if w * h > draw.limits.max_target_pixels {
            return Err(EmuError::TargetTooLarge {
                width: draw.target_width,
                height: draw.target_height,
                limit: draw.limits.max_target_pixels,
            });
        }
        let c = &draw.constants;
        for (kind, given, max) in [
            ("float", c.float.len(), 224),
            ("integer", c.int.len(), 16),
            ("boolean", c.bool.len(), 16),
        ] {
            if given > max {
                return Err(EmuError::TooManyConstants { kind, given, max });
            }
        }
        // def/defi/defb override the application's values (MS def---ps).
        let mut floats = [[0.0f32; 4]; 224];
        floats[..c.float.len()].copy_from_slice(&c.float);
        for &(i, v) in &compiled.float_defs {
            floats[i as usize] = v;
        }
        if draw.float_rules.flush_denormals() {
            // `hardware`: a denormal constant reads as a zero.
            for v in floats.iter_mut().flatten() {
                *v = crate::core::float_rules::flush(*v);
            }
        }
        let ints = int_constants(compiled, c)?;
        let mut bools = 0u16;
        for (i, &b) in c.bool.iter().enumerate() {
            bools |= (b as u16) << i;
        }
        for &(i, b) in &compiled.bool_defs {
            bools = bools & !(1 << i) | (b as u16) << i;
        }
        let consts = compiled
            .layout
            .consts
            .iter()
            .map(|&(_, c)| floats[c as usize])
            .collect();
        let inputs = bind_inputs(compiled, draw)?;
        let samplers = bind_samplers(compiled, draw)?;
        let quads_x = w.div_ceil(2);
        let quads = quads_x * h.div_ceil(2);
        Ok(RunCtx {
            compiled,
            ints,
            bools,
            consts,
            samplers,
            inputs,
            width: w,
            height: h,
            quads_x,
            quads,
            batch_quads: batch_quads(quads, threads),
            cap: draw.limits.max_executed_per_pixel,
            record_lod: draw.record_lod,
            count_instructions: draw.count_instructions,
            face: draw.face.value(),
            rules: draw.float_rules,
            pixels: draw.pixels,
        })
    }

    fn batches(&self) -> u64 {
        self.quads.div_ceil(self.batch_quads)
    }

    /// Pixel of `lane` in `batch`, and whether it lies inside the target.
    #[inline]
    pub fn lane_pixel(&self, batch: u64, lane: usize) -> (u64, u64, bool) {
        let q = (lane / 4) as u64;
        let quad = batch * self.batch_quads + q;
        let (qx, qy) = (quad % self.quads_x.max(1), quad / self.quads_x.max(1));
        let x = 2 * qx + (lane & 1) as u64;
        let y = 2 * qy + ((lane >> 1) & 1) as u64;
        let inside = q < self.batch_quads && quad < self.quads;
        let inside = inside && x < self.width && y < self.height;
        let covered = match self.pixels {
            None => true,
            Some(p) => inside && p.covered[(y * self.width + x) as usize],
        };
        (x, y, inside && covered)
    }
}

/// Quads per batch for a target of `quads` quads on `threads` threads: full
/// batches, unless that leaves a thread without work; then one batch per
/// thread, in multiples of 2 quads (8 lanes, which vectorise without a
/// remainder; see `Worker::span`). Pass 1 of the luminance job draws 6×4
/// quads: one batch of 16 and one of 8 on one thread, two of 12 on two; a
/// 10×8 target (5×4 quads) two of 10 on two threads, where multiples of 4
/// quads would give 12 and 8 and the draw would last as long as its larger
/// batch. The batches a draw is cut into change no result (pixels are
/// independent).
fn batch_quads(quads: u64, threads: usize) -> u64 {
    quads
        .div_ceil(threads.max(1) as u64)
        .next_multiple_of(2)
        .clamp(2, QUADS_PER_BATCH)
}

/// The integer constants (the draw's, then `defi`), each one a rep or loop
/// uses checked for its range.
fn int_constants(compiled: &Compiled, c: &Constants) -> Result<[[i32; 4]; 16], EmuError> {
    let mut ints = [[0i32; 4]; 16];
    ints[..c.int.len()].copy_from_slice(&c.int);
    for &(i, v) in &compiled.int_defs {
        ints[i as usize] = v;
    }
    for i in 0..16u32 {
        let v = ints[i as usize];
        let problem = if compiled.rep_ints & (1 << i) != 0 || compiled.loop_ints & (1 << i) != 0 {
            crate::core::cost::int_constant_problem(
                if compiled.loop_ints & (1 << i) != 0 {
                    crate::core::isa::Opcode::Loop
                } else {
                    crate::core::isa::Opcode::Rep
                },
                v,
            )
        } else {
            None
        };
        if let Some(reason) = problem {
            return Err(EmuError::InvalidIntConstant {
                register: i,
                reason,
            });
        }
    }
    Ok(ints)
}

/// The draw's `v#` values: each declared input exactly once, nothing else.
fn bind_inputs(compiled: &Compiled, draw: &Draw) -> Result<[Option<LinearInput>; 10], EmuError> {
    let mut inputs = [None; 10];
    let per_pixel = draw.pixels.map_or(&[][..], |p| &p.values[..]);
    let mut given = 0u16;
    let slots = draw
        .inputs
        .iter()
        .map(|&(v, value)| (v, Some(value)))
        .chain(per_pixel.iter().map(|(v, _)| (*v, None)));
    for (v, value) in slots {
        let register = || crate::core::pixel_inputs::name(compiled.profile, v);
        if v >= 10 || compiled.inputs & (1 << v) == 0 {
            return Err(EmuError::InputNotDeclared {
                input: v,
                register: register(),
            });
        }
        if given & (1 << v) != 0 {
            return Err(EmuError::DuplicateBinding {
                what: "v",
                index: v,
            });
        }
        given |= 1 << v;
        inputs[v as usize] = value;
    }
    if let Some(p) = draw.pixels {
        check_pixels(p, draw.target_width, draw.target_height)?;
    }
    for v in 0..10u32 {
        if compiled.inputs & (1 << v) != 0 && given & (1 << v) == 0 {
            return Err(EmuError::MissingInput {
                input: v,
                register: crate::core::pixel_inputs::name(compiled.profile, v),
            });
        }
    }
    Ok(inputs)
}

/// A primitive's pixels laid out as [`PixelInputs`] says for a `w × h` window.
fn check_pixels(p: &PixelInputs, w: u32, h: u32) -> Result<(), EmuError> {
    let grid = PixelInputs::grid_width(w) * PixelInputs::grid_width(h);
    let bad = |reason: String| Err(EmuError::BadPixelInputs { reason });
    if !p.origin.0.is_multiple_of(2) || !p.origin.1.is_multiple_of(2) {
        return bad(format!("origin {:?} is not on the quad grid", p.origin));
    }
    if p.covered.len() != w as usize * h as usize {
        return bad(format!(
            "{} coverage flags for a {w}x{h} window",
            p.covered.len()
        ));
    }
    if let Some((v, values)) = p.values.iter().find(|(_, v)| v.len() != grid) {
        return bad(format!(
            "slot {v} has {} values for a quad grid of {grid}",
            values.len()
        ));
    }
    if let Some(n) = p.positions.as_ref().map(Vec::len).filter(|&n| n != grid) {
        return bad(format!("{n} positions for a quad grid of {grid}"));
    }
    Ok(())
}

/// The draw's textures as samplers: each on an `s#` declared with its type, once.
fn bind_samplers<'a>(
    compiled: &Compiled,
    draw: &Draw<'a>,
) -> Result<[Option<Sampler<'a>>; 16], EmuError> {
    let mut samplers: [Option<Sampler<'a>>; 16] = std::array::from_fn(|_| None);
    for (s, tex, state) in &draw.samplers {
        let ty = match compiled.samplers.get(*s as usize).copied().flatten() {
            Some(ty) => ty,
            None => return Err(EmuError::SamplerNotDeclared { sampler: *s }),
        };
        if ty != tex.sampler_type() {
            return Err(EmuError::SamplerTypeMismatch {
                sampler: *s,
                declared: ty,
                bound: tex.sampler_type(),
            });
        }
        let sm = Sampler::new(tex, state).map_err(|reason| EmuError::InvalidTexture {
            sampler: *s,
            reason,
        })?;
        if samplers[*s as usize].replace(sm).is_some() {
            return Err(EmuError::DuplicateBinding {
                what: "s",
                index: *s,
            });
        }
    }
    Ok(samplers)
}

/// Checks a draw against a compiled shader as [`run`] does before any pixel
/// runs — target size, constants, `i#` ranges for rep/loop, inputs and
/// samplers supplied as declared, texture shapes — so that another backend
/// (`core/gpu`) refuses exactly what the emulator refuses.
pub fn check(compiled: &Compiled, draw: &Draw) -> Result<(), EmuError> {
    RunCtx::new(compiled, draw, 1).map(|_| ())
}

/// Runs a draw on the current rayon pool (the global one outside any other).
pub fn run(compiled: &Compiled, draw: &Draw) -> Result<DrawOutput, EmuError> {
    run_with_threads(compiled, draw, 0)
}

/// Runs a draw on `threads` worker threads (`0`: the current rayon pool;
/// see [`on_threads`]). Results, executed counts and errors are the same
/// for every thread count: pixels are independent, and when several batches
/// fail, the error of the first failing batch is reported.
pub fn run_with_threads(
    compiled: &Compiled,
    draw: &Draw,
    threads: usize,
) -> Result<DrawOutput, EmuError> {
    let workers = match threads {
        0 => rayon::current_num_threads(),
        n => n,
    };
    let ctx = RunCtx::new(compiled, draw, workers)?;
    let n = (ctx.width * ctx.height) as usize;
    let q = ctx.quads as usize;
    let color = (0..4)
        .map(|i| {
            compiled
                .writes_output(i)
                .then(|| filled(n, [0.0; 4]))
                .transpose()
        })
        .collect::<Result<_, _>>()?;
    let mut out = DrawOutput {
        width: draw.target_width,
        height: draw.target_height,
        color,
        depth: compiled
            .writes_output(4)
            .then(|| filled(n, 0.0))
            .transpose()?,
        killed: filled(n, false)?,
        executed: filled(n, 0)?,
        quads_x: ctx.quads_x as u32,
        quad_executed: filled(q, 0)?,
        quad_divergent: filled(q, false)?,
        gradients: compiled.sites.clone(),
        instructions: Vec::new(),
    };
    if draw.count_instructions {
        out.instructions = filled(compiled.ops.len(), InstructionCount::default())?;
    }
    let batches = ctx.batches();
    let mut total = Total::new(&ctx, draw.limits.max_executed_total);
    let mut gradients = std::mem::take(&mut out.gradients);
    let mut instructions = std::mem::take(&mut out.instructions);
    let planes = Planes::new(&mut out);
    let all = || -> Result<u8, EmuError> {
        let mut written = 0u8;
        let mut start = 0;
        while start < batches {
            let end = (start + CHUNK).min(batches);
            // Batches after the first failure stop early; the ones before
            // it always finish, so the reported error does not depend on
            // scheduling.
            // Once the batches done (in any order) are over the total
            // limit, the rest are skipped: the draw fails either way.
            let first_err = AtomicU64::new(u64::MAX);
            let results: Vec<Option<Result<BatchOut, EmuError>>> = (start..end)
                .into_par_iter()
                .map_init(
                    || Worker::new(&ctx),
                    |w, b| {
                        if b > first_err.load(Ordering::Relaxed) || total.over() {
                            return None;
                        }
                        let r = w.run(b, &planes);
                        match &r {
                            Ok(out) => total.race(out),
                            Err(_) => {
                                first_err.fetch_min(b, Ordering::Relaxed);
                            }
                        }
                        Some(r)
                    },
                )
                .collect();
            for r in results {
                match r {
                    Some(Ok(r)) => {
                        total.add(&r)?;
                        written |= r.written;
                        merge_sites(&mut gradients, &r);
                        for (c, b) in instructions.iter_mut().zip(&r.instructions) {
                            c.add(b);
                        }
                    }
                    Some(Err(e)) => return Err(e),
                    // Skipped: only after a failure or over the limit.
                    None => return Err(total.error()),
                }
            }
            start = end;
        }
        Ok(written)
    };
    let written = on_threads(threads, all)??;
    out.gradients = gradients;
    out.instructions = instructions;
    for (i, c) in out.color.iter_mut().enumerate() {
        if written & (1 << i) == 0 {
            *c = None;
        }
    }
    if written & 16 == 0 {
        out.depth = None;
    }
    Ok(out)
}

/// A vector of `n` copies of `value`, or [`EmuError::OutOfMemory`] when the
/// memory cannot be had (instead of aborting the process).
fn filled<T: Clone>(n: usize, value: T) -> Result<Vec<T>, EmuError> {
    let mut v = Vec::new();
    v.try_reserve_exact(n).map_err(|_| EmuError::OutOfMemory {
        bytes: (n as u64).saturating_mul(std::mem::size_of::<T>() as u64),
    })?;
    v.resize(n, value);
    Ok(v)
}

/// The draw's executed slots so far (helper lanes included: they are work
/// too). A draw fails exactly when the sum over all its batches is over the
/// limit, whatever the thread count; the message names nothing that
/// depends on which batches ran first.
struct Total {
    limit: u64,
    /// Batches merged so far, in batch order.
    executed: u64,
    /// Batches finished so far, in any order (shared by the workers).
    finished: AtomicU64,
    pixels: u64,
}

impl Total {
    fn new(ctx: &RunCtx, limit: u64) -> Total {
        Total {
            limit,
            executed: 0,
            finished: AtomicU64::new(0),
            pixels: ctx.width * ctx.height,
        }
    }

    /// A worker finished a batch.
    fn race(&self, r: &BatchOut) {
        let _ = self
            .finished
            .fetch_update(Ordering::Relaxed, Ordering::Relaxed, |v| {
                Some(v.saturating_add(r.executed))
            });
    }

    /// Whether the batches finished so far are already over the limit.
    fn over(&self) -> bool {
        self.finished.load(Ordering::Relaxed) > self.limit
    }

    fn error(&self) -> EmuError {
        EmuError::TotalExecutedLimit {
            limit: self.limit,
            pixels: self.pixels,
        }
    }

    /// Merges a batch.
    fn add(&mut self, r: &BatchOut) -> Result<(), EmuError> {
        self.executed = self.executed.saturating_add(r.executed);
        if self.executed > self.limit {
            return Err(self.error());
        }
        Ok(())
    }
}

/// Runs `f` on a rayon pool of `threads` threads: the current one when it
/// has that many (or `threads` is 0), so that a caller's other work on the
/// same pool shares its threads with the draw instead of adding to them;
/// otherwise a pool of its own.
pub fn on_threads<T: Send>(threads: usize, f: impl FnOnce() -> T + Send) -> Result<T, EmuError> {
    if threads == 0 || threads == rayon::current_num_threads() {
        Ok(f())
    } else {
        Ok(pool(threads)?.install(f))
    }
}

/// A rayon pool with `threads` threads, built once per thread count and kept
/// (building one costs more than a small draw).
fn pool(threads: usize) -> Result<Arc<rayon::ThreadPool>, EmuError> {
    type Pools = Mutex<Vec<(usize, Arc<rayon::ThreadPool>)>>;
    static POOLS: OnceLock<Pools> = OnceLock::new();
    let pools = POOLS.get_or_init(|| Mutex::new(Vec::new()));
    let mut pools = pools.lock().unwrap_or_else(|e| e.into_inner());
    if let Some((_, p)) = pools.iter().find(|(n, _)| *n == threads) {
        return Ok(p.clone());
    }
    let p = Arc::new(
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .map_err(|e| EmuError::ThreadPool(e.to_string()))?,
    );
    pools.push((threads, p.clone()));
    Ok(p)
}

/// Adds what a batch's gradient sites saw to the draw's.
fn merge_sites(gradients: &mut [GradientSite], r: &BatchOut) {
    for (g, b) in gradients.iter_mut().zip(&r.sites) {
        g.quads += b.quads.count_ones() as u64;
        g.divergent_quads += b.divergent.count_ones() as u64;
        g.executions += b.executions;
        g.divergent_executions += b.divergent_executions;
        if b.lod_min <= b.lod_max {
            g.lod = Some(match g.lod {
                Some((lo, hi)) => (lo.min(b.lod_min), hi.max(b.lod_max)),
                None => (b.lod_min, b.lod_max),
            });
        }
    }
}
