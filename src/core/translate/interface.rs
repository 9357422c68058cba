//! The binding layout of a translated shader: what an application (or the
//! GPU backend) binds where. One description, read by the lowering that
//! builds the module, by the header that tells a reader, and by
//! `core/gpu`, which fills the buffers — so the three cannot drift apart.
//!
//! ```text
//! @group(0) @binding(0)        var<uniform> ps30: Ps30Constants
//!   c: array<vec4<f32>, 224>   byte 0      c# at 16·#       (SetPixelShaderConstantF)
//!   i: array<vec4<i32>, 16>    byte 3584   i# at 3584 + 16·# (SetPixelShaderConstantI)
//!   b: array<vec4<u32>, 16>    byte 3840   b# true when b[#].x ≠ 0 (SetPixelShaderConstantB)
//!   s: array<Ps30Sampler, 16>  byte 4096   sampler state the shader applies itself, 64 bytes per s#
//! @group(0) @binding(1 + 2·#)  s#'s texture (texture_2d, texture_cube or texture_3d of f32;
//!                              the GPU backend binds a cube as texture_2d_array, its faces)
//! @group(0) @binding(2 + 2·#)  s#'s sampler
//! @location(#)                 v# in, oC# out; vPos = @builtin(position) − 0.5, vFace = ±1 from
//!                              @builtin(front_facing); oDepth = @builtin(frag_depth)
//! ```
//!
//! `Ps30Sampler` holds what WebGPU samplers cannot express: `lod` (x: added
//! to the level of detail of texld/texldp/texldb — D3DSAMP_MIPMAPLODBIAS;
//! y: added to texldl's; z: the factor texldd's gradients are scaled by,
//! 2^bias), `border` (the border colour the shader adds where it emulates
//! BORDER), `mirror_once` (per axis u, v, w: 1 = D3DTADDRESS_MIRRORONCE,
//! the shader mirrors the coordinate and the sampler clamps to the edge)
//! and `border_mode` (per axis u, v, w: 1 = BORDER emulated with this
//! colour, the sampler set to clamp-to-border with transparent black; w:
//! the filter it was computed for, 1 point, 2 linear). All zero means the
//! plain sampler state does everything.

use crate::core::ir::Shader;
use crate::core::isa::{RegFile, SamplerType};

/// Binding of the constant block.
pub const CONSTANTS_BINDING: u32 = 0;
/// Byte offsets inside the constant block.
pub const FLOATS_OFFSET: u32 = 0;
/// Byte offset of `i0` in the constant block.
pub const INTS_OFFSET: u32 = 224 * 16;
/// Byte offset of `b0` in the constant block.
pub const BOOLS_OFFSET: u32 = INTS_OFFSET + 16 * 16;
/// Byte offset of the first `Ps30Sampler` in the constant block.
pub const SAMPLERS_OFFSET: u32 = BOOLS_OFFSET + 16 * 16;
/// Bytes of one `Ps30Sampler`.
pub const SAMPLER_STATE_SIZE: u32 = 64;
/// Bytes of the whole constant block.
pub const CONSTANTS_SIZE: u32 = SAMPLERS_OFFSET + 16 * SAMPLER_STATE_SIZE;
/// Binding of the per-pixel input texture of the GPU backend's own entry
/// point (not part of the application interface).
pub const DRAW_INPUTS_BINDING: u32 = 40;
/// Location of the GPU backend's texkill flag output (D3D9 has four
/// colour outputs, so location 4 is free).
pub const DRAW_KILLED_LOCATION: u32 = 4;

/// Location of the flags output of the GPU backend's geometry entry point
/// (`ps30_geometry`): bit 0 set for every pixel the primitive covers, bit 1
/// where texkill killed it.
pub const GEOMETRY_FLAGS_LOCATION: u32 = 4;
/// Location of the geometry entry point's depth output: `oDepth` where the
/// shader writes it, else the rasterised depth (`@builtin(position).z`),
/// read back unclamped for the depth test done with the emulator's.
pub const GEOMETRY_DEPTH_LOCATION: u32 = 5;
/// Location of the geometry entry point's fog output, where the draw is
/// fogged ([`GeometryFog`]): the depth or factor fixed-function fog reads
/// at the pixel, for the fog applied on the CPU after read-back.
pub const GEOMETRY_FOG_LOCATION: u32 = 6;

/// What the geometry entry point writes at [`GEOMETRY_FOG_LOCATION`] for
/// a fogged draw: the d of `core::raster::fog::Fog::factor`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GeometryFog {
    /// x of one more input, interpolated with perspective, that the
    /// vertex stage hands on at [`geometry_fog_location`]: vertex fog's
    /// factor, or table fog's w (w interpolated with perspective is the
    /// pixel's own w).
    Varying,
    /// The rasterised z (`@builtin(position).z`), which table fog reads
    /// even where the shader writes `oDepth`.
    Depth,
}

/// The input location of [`GeometryFog::Varying`]: the one after every
/// location [`geometry_locations`] gives.
pub fn geometry_fog_location(inputs: &[Input], flat: u64) -> u32 {
    geometry_locations(inputs, flat)
        .iter()
        .flat_map(|&(_, smooth, flat)| [smooth, flat])
        .flatten()
        .map(|l| l + 1)
        .max()
        .unwrap_or(0)
}

/// Where the geometry entry point (`ps30_geometry`) reads each input:
/// `(slot, smooth, flat)`, the locations its interpolated and its flat
/// components arrive at. `flat` holds four bits per slot (bit `4·slot + c`:
/// component c is flat-shaded, D3DSHADE_FLAT). A slot wholly interpolated
/// or wholly flat arrives at its own location; one with both kinds of
/// components arrives twice, flat at the next location after every slot.
pub fn geometry_locations(inputs: &[Input], flat: u64) -> Vec<(u32, Option<u32>, Option<u32>)> {
    let mut next = inputs.iter().map(|i| i.location + 1).max().unwrap_or(0);
    inputs
        .iter()
        .map(|i| {
            let bits = if i.register < 16 {
                (flat >> (4 * i.register)) & 0xf
            } else {
                0
            };
            match bits {
                0 => (i.register, Some(i.location), None),
                0xf => (i.register, None, Some(i.location)),
                _ => {
                    next += 1;
                    (i.register, Some(i.location), Some(next - 1))
                }
            }
        })
        .collect()
}

/// The texture binding of `s#`.
pub fn texture_binding(sampler: u32) -> u32 {
    1 + 2 * sampler
}

/// The sampler binding of `s#`.
pub fn sampler_binding(sampler: u32) -> u32 {
    2 + 2 * sampler
}

/// A declared input register.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Input {
    /// The input slot (`core/pixel_inputs.rs`): the register number in
    /// ps_3_0 (`v3` → 3); in ps_2_0 and ps_2_x `v0`, `v1` are 0, 1 and `t#`
    /// is 2 + #.
    pub register: u32,
    /// The register's own name where it is not `v` + slot (`t0`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub spelled: Option<String>,
    /// Clamped to [0, 1] where it enters the shader: ps_2_0 and ps_2_x
    /// colours (`core/pixel_inputs.rs`).
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub clamped: bool,
    /// The `dcl` usage (`texcoord`, `color`).
    pub usage: String,
    /// The usage index (`dcl_texcoord3` → 3).
    pub usage_index: u32,
    /// Its `@location`: the register number.
    pub location: u32,
    /// Whether it is interpolated at the centroid (`dcl_centroid`).
    pub centroid: bool,
}

/// A declared sampler.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct Sampler {
    /// The register number (`s2` → 2).
    pub register: u32,
    /// The texture dimension (`2d`, `cube`, `volume`), from `dcl_*`.
    #[serde(serialize_with = "sampler_type_name")]
    pub ty: SamplerType,
    /// Its texture's `@binding` ([`texture_binding`]).
    pub texture_binding: u32,
    /// Its sampler's `@binding` ([`sampler_binding`]).
    pub sampler_binding: u32,
}

fn sampler_type_name<S: serde::Serializer>(ty: &SamplerType, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_str(ty.suffix())
}

/// Everything an application binds, derived from the shader.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Interface {
    /// The shader's profile (its version line).
    #[serde(skip)]
    pub profile: crate::core::profile::Profile,
    /// The `v#` the shader declares, in register order.
    pub inputs: Vec<Input>,
    /// Whether the shader reads `vPos`.
    pub position: bool,
    /// Whether the shader reads `vFace`.
    pub face: bool,
    /// `oC#` the shader writes (each at `@location(#)`).
    pub outputs: Vec<u32>,
    /// Whether the shader writes `oDepth`.
    pub depth: bool,
    /// The `s#` the shader declares, in register order.
    pub samplers: Vec<Sampler>,
    /// `c#`, `i#`, `b#` the shader defines itself: values set by the
    /// application are ignored for them (as in Direct3D).
    pub float_defs: Vec<u32>,
    /// `i#` the shader defines itself (`defi`).
    pub int_defs: Vec<u32>,
    /// `b#` the shader defines itself (`defb`).
    pub bool_defs: Vec<u32>,
    /// `c#`, `i#`, `b#` the shader reads from the application (not
    /// defined by the shader itself).
    pub floats_read: Vec<u32>,
    /// `i#` the shader reads from the application.
    pub ints_read: Vec<u32>,
    /// `b#` the shader reads from the application.
    pub bools_read: Vec<u32>,
    /// Whether the shader uses `texkill` (the pixel is discarded at the end).
    pub kills: bool,
}

impl Interface {
    /// The interface of a validated shader: its declarations, definitions and
    /// the registers its instructions read.
    pub fn of(shader: &Shader) -> Interface {
        let p = shader.program();
        let mut inputs = Vec::new();
        let (mut position, mut face) = (false, false);
        for d in &p.inputs {
            let slot = crate::core::pixel_inputs::slot(p.profile, d.reg.file, d.reg.index);
            match d.reg.file {
                RegFile::Input | RegFile::Texture if slot.is_some() => {
                    let slot = slot.unwrap_or_default();
                    let spelled = crate::core::pixel_inputs::name(p.profile, slot);
                    // ps_2_x declares no usage: a t# is a texcoord, a v# a colour.
                    let usage = match (d.usage.is_empty(), d.reg.file) {
                        (false, _) => d.usage.clone(),
                        (true, RegFile::Texture) => "texcoord".into(),
                        (true, _) => "color".into(),
                    };
                    let usage_index = if d.usage.is_empty() {
                        d.reg.index
                    } else {
                        d.usage_index
                    };
                    inputs.push(Input {
                        register: slot,
                        spelled: (spelled != format!("v{slot}")).then_some(spelled),
                        clamped: crate::core::pixel_inputs::clamped(p.profile) & (1 << slot) != 0,
                        usage,
                        usage_index,
                        location: slot,
                        centroid: d.centroid,
                    })
                }
                RegFile::Position => position = true,
                RegFile::Face => face = true,
                _ => {}
            }
        }
        inputs.sort_by_key(|i| i.register);
        inputs.dedup_by_key(|i| i.register);
        let mut outputs = Vec::new();
        let mut depth = false;
        let mut kills = false;
        for ins in shader.instructions() {
            if ins.op == crate::core::isa::Opcode::TexKill {
                kills = true;
                continue;
            }
            match ins.dst.map(|d| d.reg) {
                Some(r) if r.file == RegFile::ColorOut => outputs.push(r.index),
                Some(r) if r.file == RegFile::DepthOut => depth = true,
                _ => {}
            }
        }
        outputs.sort_unstable();
        outputs.dedup();
        let mut samplers: Vec<Sampler> = p
            .samplers
            .iter()
            .map(|d| Sampler {
                register: d.index,
                ty: d.ty,
                texture_binding: texture_binding(d.index),
                sampler_binding: sampler_binding(d.index),
            })
            .collect();
        samplers.sort_by_key(|s| s.register);
        samplers.dedup_by_key(|s| s.register);
        let defs = |v: Vec<u32>| {
            let mut v = v;
            v.sort_unstable();
            v.dedup();
            v
        };
        let float_defs = defs(p.float_defs.iter().map(|d| d.index).collect());
        let int_defs = defs(p.int_defs.iter().map(|d| d.index).collect());
        let bool_defs = defs(p.bool_defs.iter().map(|d| d.index).collect());
        let read = |file: RegFile, own: &[u32]| {
            let mut v = Vec::new();
            for ins in shader.instructions() {
                for (k, s) in ins.src.iter().enumerate() {
                    if s.reg.file != file {
                        continue;
                    }
                    let rows = ins
                        .op
                        .matrix_shape()
                        .filter(|_| k == 1)
                        .map_or(1, |(n, _)| n);
                    v.extend((s.reg.index..s.reg.index + rows).filter(|r| !own.contains(r)));
                }
            }
            defs(v)
        };
        Interface {
            profile: p.profile,
            inputs,
            position,
            face,
            outputs,
            depth,
            samplers,
            floats_read: read(RegFile::Const, &float_defs),
            ints_read: read(RegFile::ConstInt, &int_defs),
            bools_read: read(RegFile::ConstBool, &bool_defs),
            float_defs,
            int_defs,
            bool_defs,
            kills,
        }
    }
}
