//! Vertex shaders run: vs_2_0, vs_2_x and vs_3_0 over a list of vertices.
//!
//! A vertex shader's lanes are vertices: there are no quads, no gradients
//! and no `texkill`, and every vertex has its own address register `a0`, so
//! a constant read `c[a0.x + n]` lands on a different register per vertex.
//! The pixel executor's rows (one register component for 64 lanes, the
//! register chosen when the shader is compiled) do not fit that, so this
//! stage interprets the validated IR one vertex at a time, with the same
//! scalar semantics (`emu/math.rs`), the same float rules
//! (`core/float_rules.rs`, applied as `emu/arith.rs` applies them) and the
//! same samplers (`emu/sample.rs`) for vs_3_0's `texldl`. Vertices are
//! independent, so they run in parallel and the result does not depend on
//! the thread count.
//!
//! Inputs `v#` are bound by their `dcl_<usage><index>` to the vertex list's
//! attributes of the same usage and index ([`Attribute`]); outputs are
//! vs_3_0's declared `o#` with their semantics, or the fixed registers of
//! vs_2_0/vs_2_x (`oPos`, `oD0`–`oD1`, `oT0`–`oT7`, `oFog`, `oPts`) with the
//! semantics Direct3D 9 gives them.
//!
//! Two choices where Direct3D 9 leaves the result open, both in
//! `docs/vertex-shaders.md`:
//!
//! * `mova` rounds to the nearest integer, halves to even
//!   (`emu/math.rs`'s `mova`, with the evidence): Microsoft's `mova` page
//!   says only "rounded to nearest" for vs_2_0 and later (vs_1_1 floors);
//!   Windows' own results (vkd3d's `non-const-indexing.shader_test`) settle
//!   the halves;
//! * a relative read past the register file (`c[a0.x + n]` outside c0–c255,
//!   `v[aL + n]` outside v0–v15) reads (0, 0, 0, 0), and a relative write
//!   past o0–o11 is dropped. Direct3D 9 leaves such reads undefined; Wine
//!   returns zeros for them when asked to check constant indices
//!   (`check_float_constants`, wined3d `shader_glsl_get_register_name`),
//!   which is what applications that depend on it saw on Windows drivers.

mod exec;

pub use exec::{output_row, OUTPUT_ROWS};

use super::sample::Sampler;
use super::{Constants, SamplerState, TextureLevels};
use crate::core::float_rules::FloatRules;
use crate::core::ir::Shader;
use crate::core::isa::RegFile;
use crate::core::profile::{Profile, Stage};
use rayon::prelude::*;
use std::fmt;

/// The float constant registers a draw may set (c0–c255: the vs_2_0 and
/// vs_3_0 minimum of `MaxVertexShaderConst`).
pub const VERTEX_CONSTANTS: usize = 256;

/// A vertex attribute by its declaration usage (D3DDECLUSAGE, spelled as
/// in `dcl_<usage>`: `position`, `texcoord`, `color`, …) and usage index.
#[derive(Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Attribute {
    /// The usage, lower case (`position`, `blendweight`, `texcoord`, …).
    pub usage: String,
    /// The usage index (`texcoord3` is 3).
    pub index: u32,
}

impl fmt::Display for Attribute {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}{}", self.usage, self.index)
    }
}

/// The vertices of a draw: `count` vertices, each attribute with one value
/// per vertex (components a format leaves out already filled as Direct3D 9
/// fills them: 0 for y and z, 1 for w).
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Vertices {
    /// How many vertices.
    pub count: usize,
    /// Each attribute's values, `count` of them.
    pub attributes: Vec<(Attribute, Vec<[f32; 4]>)>,
}

/// What a vertex draw binds besides the vertices.
#[derive(Clone, Debug)]
pub struct VertexDraw<'a> {
    /// Constants set by the application (SetVertexShaderConstantF/I/B),
    /// at most [`VERTEX_CONSTANTS`] floats; `def`/`defi`/`defb` override them.
    pub constants: Constants,
    /// vs_3_0's vertex textures (`s0`–`s3`), for `texldl`.
    pub samplers: Vec<(u32, TextureLevels<'a>, SamplerState)>,
    /// The float rules.
    pub float_rules: FloatRules,
    /// Executed instruction slots one vertex may run before the draw stops.
    pub max_executed_per_vertex: u64,
}

impl Default for VertexDraw<'_> {
    fn default() -> Self {
        VertexDraw {
            constants: Constants::default(),
            samplers: Vec::new(),
            float_rules: FloatRules::default(),
            max_executed_per_vertex: 1 << 20,
        }
    }
}

/// One output register of a vertex shader.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct OutputSlot {
    /// The register as written (`o0`, `oPos`, `oT1`, `oFog`).
    pub register: String,
    /// Its semantic: vs_3_0's `dcl_<usage><index> o#`, or the one the
    /// fixed registers of vs_2_0/vs_2_x carry (`oPos` position0, `oD1`
    /// color1, `oT3` texcoord3, `oFog` fog0, `oPts` psize0). `None` for an
    /// `o#` written but never declared.
    pub semantic: Option<Attribute>,
}

/// What a vertex draw computed.
#[derive(Clone, Debug, PartialEq)]
pub struct VertexOutput {
    /// The output registers, in register order.
    pub slots: Vec<OutputSlot>,
    /// Per vertex, the value of each slot (unwritten components are 0).
    pub values: Vec<Vec<[f32; 4]>>,
    /// Executed instruction slots per vertex (the cost model's rule).
    pub executed: Vec<u64>,
}

/// Why a vertex draw could not run.
#[derive(Clone, Debug, PartialEq)]
pub enum VertexError {
    /// The shader is not a vertex shader ps30 runs.
    NotRun(Profile),
    /// The shader declares an input the vertex list does not have.
    MissingAttribute {
        /// The input register (`v1`).
        register: String,
        /// Its declaration's usage and index.
        attribute: Attribute,
    },
    /// An attribute has a number of values other than the vertex count.
    AttributeLength {
        /// The attribute.
        attribute: Attribute,
        /// How many values it has.
        values: usize,
        /// The vertex count.
        count: usize,
    },
    /// More constants than the registers a draw may set.
    TooManyConstants {
        /// `float`, `int` or `bool`.
        kind: &'static str,
        /// How many were given.
        given: usize,
        /// The most there may be.
        max: usize,
    },
    /// A sampler binding cannot be used.
    Sampler {
        /// The `s#`.
        sampler: u32,
        /// Why.
        reason: String,
    },
    /// A vertex ran more executed slots than the limit.
    ExecutedLimit {
        /// The vertex (from 0).
        vertex: usize,
        /// The limit.
        limit: u64,
    },
    /// `call` nested deeper than the profile's four levels.
    CallDepth {
        /// The vertex (from 0).
        vertex: usize,
        /// The instruction (from 0).
        index: usize,
    },
}

impl fmt::Display for VertexError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            VertexError::NotRun(p) => write!(f, "a {p} shader: the vertex stage runs vs_2_0, vs_2_x and vs_3_0 shaders"),
            VertexError::MissingAttribute { register, attribute } => write!(
                f,
                "the shader reads {register} (dcl_{attribute}) and the vertex list has no {attribute}"
            ),
            VertexError::AttributeLength { attribute, values, count } => write!(
                f,
                "attribute {attribute} has {values} values for {count} vertices"
            ),
            VertexError::TooManyConstants { kind, given, max } => {
                write!(f, "{given} {kind} constants given; a vertex draw sets at most {max}")
            }
            VertexError::Sampler { sampler, reason } => write!(f, "sampler s{sampler}: {reason}"),
            VertexError::ExecutedLimit { vertex, limit } => write!(
                f,
                "vertex {vertex} ran more than {limit} executed instruction slots"
            ),
            VertexError::CallDepth { vertex, index } => write!(
                f,
                "vertex {vertex}: call at instruction {index} nests deeper than 4 levels"
            ),
        }
    }
}

impl std::error::Error for VertexError {}

/// Whether the vertex stage runs shaders of `profile`.
pub fn runs(profile: Profile) -> bool {
    profile.runs() && profile.stage() == Stage::Vertex
}

/// The output registers a shader has: vs_3_0's declared and written `o#`,
/// the fixed registers vs_2_0/vs_2_x write.
pub fn output_slots(shader: &Shader) -> Vec<OutputSlot> {
    outputs(shader).into_iter().map(|(_, s)| s).collect()
}

/// The components of each of [`output_slots`] that some instruction writes
/// (a mask, bit 0 = x), in the same order: a component no instruction
/// writes is one the pixel shader reads Direct3D 9's default in
/// (`core::pixel_inputs::unwritten`). A relative write `o[aL + n]` may
/// reach any `o#`, so it counts as writing every component of each.
pub fn written(shader: &Shader) -> Vec<u8> {
    let p = shader.program();
    let relative = p
        .instructions
        .iter()
        .filter_map(|i| i.dst)
        .any(|d| d.relative.is_some() && d.reg.file == RegFile::Output);
    outputs(shader)
        .into_iter()
        .map(|(row, _)| {
            p.instructions
                .iter()
                .filter_map(|i| i.dst)
                .filter(|d| {
                    (relative && d.reg.file == RegFile::Output)
                        || (d.relative.is_none()
                            && exec::output_row(d.reg.file, d.reg.index) == Some(row))
                })
                .fold(0u8, |m, d| {
                    if d.relative.is_some() {
                        m | 0b1111
                    } else {
                        m | d.mask.0
                    }
                })
        })
        .collect()
}

/// [`output_slots`] with each slot's row in the executor's output block
/// ([`output_row`]).
pub fn outputs(shader: &Shader) -> Vec<(usize, OutputSlot)> {
    let p = shader.program();
    let mut regs: Vec<(RegFile, u32)> = p
        .instructions
        .iter()
        .filter_map(|i| {
            i.dst
                .filter(|d| d.relative.is_none())
                .map(|d| (d.reg.file, d.reg.index))
        })
        .chain(p.inputs.iter().map(|d| (d.reg.file, d.reg.index)))
        .filter(|(f, _)| exec::output_row(*f, 0).is_some())
        .collect();
    regs.sort_by_key(|&(f, i)| exec::output_row(f, i));
    regs.dedup();
    regs.into_iter()
        .map(|(file, index)| {
            let row = exec::output_row(file, index).unwrap_or(0);
            let name = file.info().name;
            let numbered = file.info().numbered;
            let register = if numbered {
                format!("{name}{index}")
            } else {
                name.to_string()
            };
            let fixed = |usage: &str, index| {
                Some(Attribute {
                    usage: usage.to_string(),
                    index,
                })
            };
            let semantic = match file {
                RegFile::Output => p
                    .inputs
                    .iter()
                    .rev()
                    .find(|d| d.reg.file == file && d.reg.index == index)
                    .map(|d| Attribute {
                        usage: d.usage.clone(),
                        index: d.usage_index,
                    }),
                RegFile::PosOut => fixed("position", 0),
                RegFile::AttrOut => fixed("color", index),
                RegFile::TexCoordOut => fixed("texcoord", index),
                RegFile::FogOut => fixed("fog", 0),
                _ => fixed("psize", 0),
            };
            (row, OutputSlot { register, semantic })
        })
        .collect()
}

/// Runs `shader` over `vertices` with `draw`'s constants and samplers.
pub fn run(
    shader: &Shader,
    draw: &VertexDraw,
    vertices: &Vertices,
) -> Result<VertexOutput, VertexError> {
    run_with(shader, draw, vertices, false).map(|(out, _)| out)
}

/// [`run`], also counting the runs of each instruction (by its index in
/// the program) over every vertex: each time its slots are charged, as
/// the cost model counts them (`else` by the lanes of both sides, a `rep`
/// or `loop` again on each further iteration).
pub fn run_counted(
    shader: &Shader,
    draw: &VertexDraw,
    vertices: &Vertices,
) -> Result<(VertexOutput, Vec<u64>), VertexError> {
    run_with(shader, draw, vertices, true)
}

fn run_with(
    shader: &Shader,
    draw: &VertexDraw,
    vertices: &Vertices,
    count: bool,
) -> Result<(VertexOutput, Vec<u64>), VertexError> {
    let bound = check(shader, draw, vertices)?;
    let samplers = bind_samplers(draw)?;
    let state = exec::State::new(shader, draw, samplers);
    let (rows, slots): (Vec<usize>, Vec<OutputSlot>) = outputs(shader).into_iter().unzip();
    let n = if count {
        shader.instructions().len()
    } else {
        0
    };
    let results = (0..vertices.count)
        .into_par_iter()
        .map(|v| {
            let mut runs = vec![0u64; n];
            let (out, executed) =
                state.run_vertex(v, vertex_inputs(&bound, vertices, v), &mut runs)?;
            let values = rows.iter().map(|&r| out[r]).collect::<Vec<_>>();
            Ok((values, executed, runs))
        })
        .collect::<Result<Vec<_>, VertexError>>()?;
    let mut runs = vec![0u64; n];
    let (mut values, mut executed) = (Vec::new(), Vec::new());
    for (v, e, r) in results {
        values.push(v);
        executed.push(e);
        for (total, k) in runs.iter_mut().zip(r) {
            *total += k;
        }
    }
    let out = VertexOutput {
        slots,
        values,
        executed,
    };
    Ok((out, runs))
}

/// Vertex `v`'s input registers v0–v15 from the bindings [`check`] made
/// (zeros where nothing is bound).
pub fn vertex_inputs(bound: &[(usize, usize)], vertices: &Vertices, v: usize) -> [[f32; 4]; 16] {
    let mut inputs = [[0.0f32; 4]; 16];
    for &(reg, attr) in bound {
        inputs[reg] = vertices.attributes[attr].1[v];
    }
    inputs
}

/// The constants a draw's vertices see: the application's with the
/// shader's `def`, `defi` and `defb` over them (c0–c255, i0–i15, b0–b15).
pub fn effective_constants(
    shader: &Shader,
    constants: &Constants,
) -> (Vec<[f32; 4]>, [[i32; 4]; 16], [bool; 16]) {
    let p = shader.program();
    let mut floats = vec![[0.0f32; 4]; VERTEX_CONSTANTS];
    let n = constants.float.len().min(VERTEX_CONSTANTS);
    floats[..n].copy_from_slice(&constants.float[..n]);
    for d in &p.float_defs {
        if let Some(c) = floats.get_mut(d.index as usize) {
            *c = d.value;
        }
    }
    let mut ints = [[0i32; 4]; 16];
    let n = constants.int.len().min(16);
    ints[..n].copy_from_slice(&constants.int[..n]);
    for d in &p.int_defs {
        if let Some(i) = ints.get_mut(d.index as usize) {
            *i = d.value;
        }
    }
    let mut bools = [false; 16];
    let n = constants.bool.len().min(16);
    bools[..n].copy_from_slice(&constants.bool[..n]);
    for d in &p.bool_defs {
        if let Some(b) = bools.get_mut(d.index as usize) {
            *b = d.value;
        }
    }
    (floats, ints, bools)
}

/// Refuses what the vertex stage refuses (a profile it does not run,
/// attributes of the wrong length, too many constants, an input the list
/// does not have) and binds each declared input `v#` to its attribute (by
/// index into `vertices.attributes`).
pub fn check(
    shader: &Shader,
    draw: &VertexDraw,
    vertices: &Vertices,
) -> Result<Vec<(usize, usize)>, VertexError> {
    let profile = shader.program().profile;
    if !runs(profile) {
        return Err(VertexError::NotRun(profile));
    }
    for (attribute, values) in &vertices.attributes {
        if values.len() != vertices.count {
            return Err(VertexError::AttributeLength {
                attribute: attribute.clone(),
                values: values.len(),
                count: vertices.count,
            });
        }
    }
    let c = &draw.constants;
    for (kind, given, max) in [
        ("float", c.float.len(), VERTEX_CONSTANTS),
        ("int", c.int.len(), 16),
        ("bool", c.bool.len(), 16),
    ] {
        if given > max {
            return Err(VertexError::TooManyConstants { kind, given, max });
        }
    }
    bind_inputs(shader, vertices)
}

/// Each declared input `v#` with the attribute it reads (by index into
/// `vertices.attributes`).
fn bind_inputs(shader: &Shader, vertices: &Vertices) -> Result<Vec<(usize, usize)>, VertexError> {
    let mut bound = Vec::new();
    for d in shader
        .program()
        .inputs
        .iter()
        .filter(|d| d.reg.file == RegFile::Input)
    {
        let attribute = Attribute {
            usage: d.usage.clone(),
            index: d.usage_index,
        };
        let Some(k) = vertices
            .attributes
            .iter()
            .position(|(a, _)| *a == attribute)
        else {
            return Err(VertexError::MissingAttribute {
                register: format!("v{}", d.reg.index),
                attribute,
            });
        };
        if (d.reg.index as usize) < 16 {
            bound.push((d.reg.index as usize, k));
        }
    }
    Ok(bound)
}

/// The draw's samplers, checked.
fn bind_samplers<'a>(draw: &VertexDraw<'a>) -> Result<[Option<Sampler<'a>>; 4], VertexError> {
    let mut out: [Option<Sampler>; 4] = Default::default();
    for (index, tex, state) in &draw.samplers {
        let Some(slot) = out.get_mut(*index as usize) else {
            return Err(VertexError::Sampler {
                sampler: *index,
                reason: "vs_3_0 has the vertex samplers s0-s3".into(),
            });
        };
        if slot.is_some() {
            return Err(VertexError::Sampler {
                sampler: *index,
                reason: "bound twice".into(),
            });
        }
        let sampler = Sampler::new(tex, state).map_err(|reason| VertexError::Sampler {
            sampler: *index,
            reason,
        })?;
        *slot = Some(sampler);
    }
    Ok(out)
}

#[cfg(test)]
mod tests;
