//! Draws of geometry: a draw-list draw that carries vertices instead of
//! covering its target whole. The `geometry` field of a draw names the
//! vertices (inline, or a vertex-list file in the format `run --vertices`
//! reads: attributes by D3DDECLUSAGE), optional indices, the primitive
//! type, a vertex shader or none (with its constants and vs_3_0's vertex
//! textures for `texldl`), the viewport, the scissor rectangle, the
//! cull mode, user clip planes, the point size and the depth test; this
//! module reads it into a plain [`Geometry`] and `run.rs` draws it: the
//! vertex stage (`emu::vertex`), then `core/raster` (assembly, clipping,
//! viewport, coverage, interpolation with perspective), the pixel shader
//! on each triangle's pixels (`emu`, [`crate::core::emu::PixelInputs`]),
//! the alpha and depth tests, and the output merger. `docs/draw.md`
//! describes the fields for users.
//!
//! ```json
//! { "draw": "t", "shader": "ps.psh",
//!   "geometry": { "vertices": {"vertices": [{"positiont0": [0, 0, 0.5, 1], "color0": [1, 0, 0, 1]}, …]},
//!                 "primitive": "triangle_strip", "cull": "none",
//!                 "depth": {"format": "D24S8", "func": "LESSEQUAL", "clear": 1} } }
//! ```
//!
//! Without a vertex shader, `position0` is a clip-space position (the
//! fixed-function pipeline with its default transforms, which are
//! identities: D3DTS_WORLD, VIEW and PROJECTION start as identity
//! matrices) and `positiont0` a pre-transformed one (D3DDECLUSAGE_POSITIONT,
//! D3DFVF_XYZRHW: screen x, y, z and 1/w, not clipped); the other
//! attributes reach the pixel shader by usage and index, as the
//! fixed-function pipe passes texture coordinates and colours through.

pub(crate) mod run;
pub(crate) mod state;

use super::floats::{constant4, FileFloat};
use super::pixel_state::CmpFunc;
use crate::core::emu::vertex::Vertices;
use crate::core::emu::Constants;
use crate::core::raster::depth::DepthFormat;
use crate::core::raster::{Cull, Primitive, Rect, Viewport};
use serde::Deserialize;
use std::collections::BTreeMap;
use std::path::Path;

/// The most vertices one draw's geometry may have (inline or from a file),
/// and the most indices.
pub const MAX_VERTICES: usize = 1 << 16;
/// The most indices one draw may have.
pub const MAX_INDICES: usize = 1 << 20;

/// A draw's geometry, resolved: what the pipeline between the stages
/// needs, as plain data (a GPU backend can draw it from this alone).
#[derive(Clone, Debug, PartialEq)]
pub struct Geometry {
    /// The vertices, attributes by usage and index.
    pub vertices: Vertices,
    /// Indices into `vertices`, in drawing order; `None`: the vertices in
    /// order (DrawPrimitive rather than DrawIndexedPrimitive).
    pub indices: Option<Vec<u32>>,
    /// How the vertices (or indices) make primitives.
    pub primitive: Primitive,
    /// The vertex shader (index into [`super::DrawList::shaders`]); `None`:
    /// positions as given (`position0` clip space, `positiont0` screen).
    pub vertex_shader: Option<usize>,
    /// The vertex shader's constants (SetVertexShaderConstantF/I/B).
    pub vertex_constants: Constants,
    /// vs_3_0's vertex textures (`s0`–`s3`, D3DVERTEXTEXTURESAMPLER0–3)
    /// for `texldl`, as the draw's `samplers` give the pixel shader's.
    pub vertex_samplers: Vec<(u32, super::Source, crate::core::emu::SamplerState)>,
    /// The viewport; `None`: the whole target, depth 0 to 1.
    pub viewport: Option<Viewport>,
    /// The scissor rectangle (D3DRS_SCISSORTESTENABLE on); `None`: off.
    pub scissor: Option<Rect>,
    /// D3DRS_CULLMODE.
    pub cull: Cull,
    /// Enabled user clip planes (a, b, c, d) in clip space; a point is
    /// kept where a·x + b·y + c·z + d·w ≥ 0.
    pub clip_planes: Vec<[f64; 4]>,
    /// The depth test; `None`: D3DRS_ZENABLE off.
    pub depth: Option<DepthState>,
    /// Lines, point sizes and sprites, the fill mode and the stencil test
    /// (`state.rs`).
    pub state: state::RasterState,
}

/// The depth buffer a draw tests and writes: the target's depth-stencil
/// surface, made at the first draw that names it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DepthState {
    /// The surface's format; every draw into one target names the same.
    pub format: DepthFormat,
    /// D3DRS_ZFUNC (default LESSEQUAL, Direct3D 9's).
    pub func: CmpFunc,
    /// D3DRS_ZWRITEENABLE (default true).
    pub write: bool,
    /// Clear(D3DCLEAR_ZBUFFER) to this depth before the draw; a surface
    /// never cleared starts at 1.
    pub clear: Option<f64>,
}

/// The `geometry` field as written.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct FileGeometry {
    vertices: serde_json::Value,
    indices: Option<Vec<u32>>,
    primitive: String,
    vertex_shader: Option<String>,
    vertex_constants: Option<BTreeMap<String, Vec<FileFloat>>>,
    /// `vertex_samplers`, read by the draw-list reader (they name its
    /// textures and targets).
    pub(crate) vertex_samplers: Option<BTreeMap<String, super::textures::FileSampler>>,
    viewport: Option<FileViewport>,
    scissor: Option<[u32; 4]>,
    cull: Option<String>,
    clip_planes: Option<Vec<[f64; 4]>>,
    point_size: Option<f64>,
    depth: Option<FileDepth>,
    last_pixel: Option<bool>,
    point_size_min: Option<f64>,
    point_size_max: Option<f64>,
    point_sprite: Option<bool>,
    point_scale: Option<[f64; 3]>,
    fill_mode: Option<String>,
    stencil: Option<state::FileStencil>,
    fog: Option<state::FileFog>,
    /// D3DRS_ANTIALIASEDLINEENABLE: refused when on (`render/multisample.rs`).
    antialiased_lines: Option<bool>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct FileViewport {
    x: u32,
    y: u32,
    width: u32,
    height: u32,
    #[serde(default)]
    min_z: f32,
    #[serde(default = "one")]
    max_z: f32,
}

fn one() -> f32 {
    1.0
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct FileDepth {
    format: String,
    func: Option<String>,
    write: Option<bool>,
    clear: Option<f64>,
}

/// A problem: the field under `geometry` and what is wrong.
type Problem = (String, String);

/// A stencil test needs a depth-stencil format with stencil bits, and its
/// reference and clear value must fit in them.
fn check_stencil(state: &state::RasterState, format: Option<DepthFormat>) -> Result<(), Problem> {
    let Some(s) = &state.stencil else {
        return Ok(());
    };
    let max = format.map_or(0, DepthFormat::stencil_max);
    if max == 0 {
        return Err(problem(
            "stencil",
            "the stencil lives in a depth-stencil surface with stencil bits: give `depth` with format D24S8, D24X4S4 or D15S1 (func ALWAYS and write false leave depth untested)",
        ));
    }
    let name = format.map_or("", DepthFormat::name);
    for (field, v) in [
        ("stencil.ref", Some(s.reference)),
        ("stencil.clear", s.clear),
    ] {
        if let Some(v) = v.filter(|&v| v > max) {
            return Err(problem(
                field,
                format!("{v}: D3DFMT_{name}'s stencil holds 0 to {max}"),
            ));
        }
    }
    Ok(())
}

fn problem(field: &str, message: impl Into<String>) -> Problem {
    (field.to_string(), message.into())
}

/// Reads `g` for a draw into a `width × height` target; vertex-list files
/// are relative to `dir` and read under `max_bytes`. Returns the geometry
/// (its `vertex_shader` unset) and the vertex shader's name, for the
/// caller to load.
pub(crate) fn read(
    g: &FileGeometry,
    dir: &Path,
    max_bytes: u64,
    (width, height): (u32, u32),
) -> Result<(Geometry, Option<String>), Problem> {
    let vertices = vertices(&g.vertices, dir, max_bytes)?;
    if let Some(indices) = &g.indices {
        if indices.len() > MAX_INDICES {
            return Err(problem(
                "indices",
                format!("{} indices, more than {MAX_INDICES}", indices.len()),
            ));
        }
        if let Some((i, &n)) = indices
            .iter()
            .enumerate()
            .find(|(_, &n)| n as usize >= vertices.count)
        {
            return Err(problem(
                &format!("indices[{i}]"),
                format!("{n} is past the last of {} vertices", vertices.count),
            ));
        }
    }
    let primitive = Primitive::from_name(&g.primitive).ok_or_else(|| {
        let names: Vec<&str> = Primitive::ALL.iter().map(|(n, _)| *n).collect();
        problem(
            "primitive",
            format!("`{}` is not one of {}", g.primitive, names.join(", ")),
        )
    })?;
    let cull = match g.cull.as_deref().map(str::to_ascii_lowercase).as_deref() {
        None | Some("ccw") | Some("d3dcull_ccw") => Cull::Ccw,
        Some("cw") | Some("d3dcull_cw") => Cull::Cw,
        Some("none") | Some("d3dcull_none") => Cull::None,
        Some(_) => return Err(problem("cull", "not \"none\", \"cw\" or \"ccw\"")),
    };
    let viewport = g
        .viewport
        .as_ref()
        .map(|v| viewport(v, width, height))
        .transpose()?;
    let scissor = match g.scissor {
        None => None,
        Some([left, top, right, bottom]) if left <= right && top <= bottom => Some(Rect {
            left,
            top,
            right,
            bottom,
        }),
        Some(_) => {
            return Err(problem(
                "scissor",
                "a RECT [left, top, right, bottom] with left ≤ right and top ≤ bottom",
            ))
        }
    };
    let clip_planes = g.clip_planes.clone().unwrap_or_default();
    if clip_planes.len() > 6 {
        return Err(problem(
            "clip_planes",
            format!(
                "{} planes; Direct3D 9 hardware has at most 6",
                clip_planes.len()
            ),
        ));
    }
    if clip_planes.iter().flatten().any(|x| !x.is_finite()) {
        return Err(problem("clip_planes", "every coefficient must be finite"));
    }
    let point_size = g.point_size.unwrap_or(1.0);
    if !(point_size > 0.0 && point_size <= 8192.0) {
        return Err(problem(
            "point_size",
            "a size in pixels, above 0 and at most 8192",
        ));
    }
    let state = state::read(&state::Fields {
        last_pixel: g.last_pixel,
        point_size,
        point_size_min: g.point_size_min,
        point_size_max: g.point_size_max,
        point_sprite: g.point_sprite,
        point_scale: g.point_scale,
        fill_mode: g.fill_mode.as_deref(),
        stencil: g.stencil.as_ref(),
        fog: g.fog.as_ref(),
    })?;
    // D3DRS_ANTIALIASEDLINEENABLE applies to lines and wireframe triangles.
    let lines = primitive.is_line() || state.fill == state::FillMode::Wireframe;
    super::multisample::check_lines(g.antialiased_lines.filter(|_| lines))
        .map_err(|m| problem("antialiased_lines", m))?;
    let depth = g.depth.as_ref().map(depth).transpose()?;
    check_stencil(&state, depth.map(|d| d.format))?;
    let geometry = Geometry {
        vertices,
        indices: g.indices.clone(),
        primitive,
        vertex_shader: None,
        vertex_constants: vertex_constants(g.vertex_constants.as_ref())?,
        vertex_samplers: Vec::new(),
        viewport,
        scissor,
        cull,
        clip_planes,
        depth,
        state,
    };
    Ok((geometry, g.vertex_shader.clone()))
}

/// The vertices: an object in the vertex-list format, or a file of it.
fn vertices(v: &serde_json::Value, dir: &Path, max_bytes: u64) -> Result<Vertices, Problem> {
    let parsed = match v {
        serde_json::Value::String(file) => {
            let path = dir.join(file);
            let bytes = crate::core::input::read_file(&path, "vertex list", max_bytes)
                .map_err(|e| problem("vertices", e))?;
            let text = String::from_utf8(bytes).map_err(|_| problem("vertices", format!("{}: not UTF-8 text", path.display())))?;
            // Vertex buffers named in the file are relative to the file.
            let dir = path.parent().unwrap_or(dir);
            crate::jobs::vertices::parse_in(&text, dir).map_err(|e| problem("vertices", format!("{}: {e}", path.display())))?
        }
        serde_json::Value::Object(_) => crate::jobs::vertices::parse_in(&v.to_string(), dir).map_err(|e| problem("vertices", e))?,
        _ => return Err(problem("vertices", "a vertex-list file name, or the list itself ({\"vertices\": […]} or {\"attributes\": {…}})")),
    };
    if parsed.count > MAX_VERTICES {
        return Err(problem(
            "vertices",
            format!(
                "{} vertices; a draw has at most {MAX_VERTICES}",
                parsed.count
            ),
        ));
    }
    Ok(parsed)
}

fn viewport(v: &FileViewport, width: u32, height: u32) -> Result<Viewport, Problem> {
    // D3DVIEWPORT9: the rectangle must lie within the render target
    // (SetViewport fails otherwise) and MinZ ≤ MaxZ, both in [0, 1].
    let fits = v.width > 0
        && v.height > 0
        && u64::from(v.x) + u64::from(v.width) <= u64::from(width)
        && u64::from(v.y) + u64::from(v.height) <= u64::from(height);
    if !fits {
        return Err(problem(
            "viewport",
            format!("the rectangle must lie within the {width}x{height} target and hold a pixel"),
        ));
    }
    if !(0.0..=1.0).contains(&v.min_z) || !(0.0..=1.0).contains(&v.max_z) || v.min_z > v.max_z {
        return Err(problem("viewport", "0 ≤ min_z ≤ max_z ≤ 1"));
    }
    Ok(Viewport {
        x: v.x,
        y: v.y,
        width: v.width,
        height: v.height,
        min_z: v.min_z,
        max_z: v.max_z,
    })
}

fn vertex_constants(c: Option<&BTreeMap<String, Vec<FileFloat>>>) -> Result<Constants, Problem> {
    let mut out = Constants::default();
    for (name, value) in c.into_iter().flatten() {
        let field = format!("vertex_constants.{name}");
        let index = name
            .strip_prefix('c')
            .and_then(|n| n.parse::<usize>().ok())
            .filter(|&n| n < crate::core::emu::vertex::VERTEX_CONSTANTS)
            .ok_or_else(|| problem(&field, "a register c0 … c255"))?;
        let v = constant4(value).map_err(|m| problem(&field, m))?;
        if out.float.len() <= index {
            out.float.resize(index + 1, [0.0; 4]);
        }
        out.float[index] = v;
    }
    Ok(out)
}

fn depth(d: &FileDepth) -> Result<DepthState, Problem> {
    let format = DepthFormat::from_name(&d.format).ok_or_else(|| {
        let names: Vec<&str> = DepthFormat::ALL.iter().map(|(n, _)| *n).collect();
        problem(
            "depth.format",
            format!("`{}` is not one of {}", d.format, names.join(", ")),
        )
    })?;
    let func = match &d.func {
        None => CmpFunc::LessEqual,
        Some(f) => CmpFunc::from_name(f)
            .ok_or_else(|| problem("depth.func", format!("`{f}` is not a D3DCMPFUNC")))?,
    };
    if let Some(c) = d.clear.filter(|c| !(0.0..=1.0).contains(c)) {
        return Err(problem(
            "depth.clear",
            format!("{c}: a depth clears to a value from 0 to 1"),
        ));
    }
    Ok(DepthState {
        format,
        func,
        write: d.write.unwrap_or(true),
        clear: d.clear,
    })
}
