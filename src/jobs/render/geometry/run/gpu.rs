//! A draw of geometry on the GPU backend: the primitives assembled here by
//! `core/raster`'s rules (lists, strips rewound, fans around vertex 0, the
//! provoking vertex moved first), points set up as the emulator sets them
//! up, and either the whole draw run on the device in one pass
//! (`one_pass.rs` says when) or each primitive rasterised and shaded by the
//! device (`core::gpu::draw_geometry`), its pixels then taking the same
//! path as the emulator's triangles — `texkill`, the alpha test, the depth
//! test, the output merger — in drawing order.

use super::{Drawn, Pass, Stage};
use crate::core::emu::{self, DrawOutput, PixelInputs};
use crate::core::gpu::{self, GeometryDraw, Gpu, ShadedPrimitive};
use crate::core::ir::Shader;
use crate::core::merge::MergeStats;
use crate::core::raster::clip::{self, VIEW_VOLUME};
use crate::core::raster::fog::{Fog, FogMode};
use crate::core::raster::triangle::Window;
use crate::core::raster::{self, Face, Primitive, Rect, Viewport};
use crate::jobs::backend::Backend;
use crate::jobs::render::geometry::Geometry;
use crate::jobs::render::{DrawFailure, DrawList, DrawStep, Settings, TargetState};
use std::sync::Arc;

/// The vertices and primitives the device draws: the stage's vertices in
/// f32 (exactly the vertex stage's outputs), each point's corners after
/// them, and every primitive's triangles with its provoking vertex first.
struct Setup {
    positions: Vec<[f32; 4]>,
    values: Vec<Vec<[f32; 4]>>,
    primitives: Vec<Vec<[u32; 3]>>,
    /// Each primitive's facing, for two-sided stencil (a point's is front).
    faces: Vec<Face>,
}

/// Assembles `g`'s primitives over `stage`'s vertices.
fn setup(g: &Geometry, stage: &Stage, viewport: &Viewport) -> Result<Setup, String> {
    if !matches!(
        g.primitive,
        Primitive::PointList
            | Primitive::TriangleList
            | Primitive::TriangleStrip
            | Primitive::TriangleFan
    ) {
        return Err(format!(
            "the GPU backend draws points and triangles; {:?} is drawn on the emulator only",
            g.primitive
        ));
    }
    if g.state.fill != super::FillMode::Solid {
        return Err(
            "the GPU backend draws solid fills; fill_mode wireframe and point are drawn on the emulator only"
                .into(),
        );
    }
    let narrow = |v: &[f64; 4]| v.map(|x| x as f32);
    // The stage's values end with each vertex's own point size, which
    // sizes points here and is no input of the pixel shader.
    let inputs = stage.slots.len();
    let mut s = Setup {
        positions: stage.positions.iter().map(narrow).collect(),
        values: stage
            .values
            .iter()
            .map(|v| v[..inputs].iter().map(narrow).collect())
            .collect(),
        primitives: Vec::new(),
        faces: Vec::new(),
    };
    let order: Vec<usize> = match &g.indices {
        Some(ix) => ix.iter().map(|&i| i as usize).collect(),
        None => (0..stage.positions.len()).collect(),
    };
    let planes: Vec<[f64; 4]> = VIEW_VOLUME.iter().chain(&g.clip_planes).copied().collect();
    for prim in raster::assemble(g.primitive, order.len())? {
        let [a, b, c] = prim.corners.map(|i| order[i] as u32);
        if g.primitive == Primitive::PointList {
            let p = stage.positions[a as usize];
            if !stage.transformed && !clip::inside(&planes, &p) {
                // Not drawn; kept in place so that primitives keep their
                // numbers.
                s.primitives.push(Vec::new());
                s.faces.push(Face::Front);
                continue;
            }
            let first = s.positions.len() as u32;
            let at = clip::ClipVertex {
                pos: p,
                values: stage.values[a as usize].clone(),
            };
            let size = super::point_size(g, stage, viewport, &at);
            let corners = [(-1.0, -1.0), (1.0, -1.0), (-1.0, 1.0), (1.0, 1.0)];
            for (k, (dx, dy)) in corners.into_iter().enumerate() {
                s.positions
                    .push(point_corner(p, dx, dy, size, stage.transformed, viewport));
                let values = super::point_values(g, stage, &at.values, k);
                s.values.push(values[..inputs].iter().map(narrow).collect());
            }
            let [tl, tr, bl, br] = [first, first + 1, first + 2, first + 3];
            s.primitives.push(vec![[tl, tr, bl], [tr, br, bl]]);
            s.faces.push(Face::Front);
            continue;
        }
        let provoking = order[prim.provoking] as u32;
        let corners = match provoking {
            p if p == b && p != a => [b, c, a],
            p if p == c && p != a => [c, a, b],
            _ => [a, b, c],
        };
        s.primitives.push(vec![corners]);
        s.faces.push(face(stage, [a, b, c]));
    }
    Ok(s)
}

/// The facing of the triangle of vertices `v` as the emulator's set-up
/// finds it: clockwise on screen is front. On screen (X, Y) = (x/w·W/2 + …,
/// −y/w·H/2 + …), so twice the signed screen area is −(W·H/4)·det/(w₀w₁w₂),
/// det the determinant of the rows (x, y, w): with every w positive the
/// triangle is front where det < 0, and det's sign holds for the part of
/// the triangle in front of the eye whatever the signs of the w. A
/// pre-transformed triangle's corners are on screen already.
fn face(stage: &Stage, v: [u32; 3]) -> Face {
    let [a, b, c] = v.map(|i| stage.positions[i as usize]);
    let area = |a: [f64; 4], b: [f64; 4], c: [f64; 4]| {
        (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    };
    let front = if stage.transformed {
        area(a, b, c) > 0.0
    } else {
        let det = a[0] * (b[1] * c[3] - b[3] * c[1]) - a[1] * (b[0] * c[3] - b[3] * c[0])
            + a[3] * (b[0] * c[1] - b[1] * c[0]);
        det < 0.0
    };
    if front {
        Face::Front
    } else {
        Face::Back
    }
}

/// A corner of the square of a point of side `size` pixels around `p`
/// (`dx`, `dy` = ±1, y down on screen): on screen for a pre-transformed
/// point, else in clip space, where a pixel is 2w/W across and 2w/H down.
fn point_corner(
    p: [f64; 4],
    dx: f64,
    dy: f64,
    size: f64,
    transformed: bool,
    viewport: &Viewport,
) -> [f32; 4] {
    let h = size / 2.0;
    let [x, y, z, w] = p;
    let out = if transformed {
        [x + dx * h, y + dy * h, z, w]
    } else {
        let sx = 2.0 * w / f64::from(viewport.width);
        let sy = 2.0 * w / f64::from(viewport.height);
        [x + dx * h * sx, y - dy * h * sy, z, w]
    };
    out.map(|v| v as f32)
}

/// What a draw on the device needs besides its step and geometry.
pub(super) struct Context<'c, 's> {
    pub viewport: &'c Viewport,
    /// The pixels the draw may write.
    pub clip_rect: Rect,
    pub samplers: &'c [(u32, emu::TextureLevels<'s>, emu::SamplerState)],
    pub settings: &'c Settings,
    /// The target's height.
    pub height: u32,
    /// Fixed-function fog after a ps_2_0/ps_2_x shader.
    pub fog: Option<Fog>,
}

/// Refuses, by name, the fog the GPU backend does not draw: vertex fog
/// (the device does not carry the interpolated fog factor to its pixels)
/// and table fog after a shader that writes `oDepth` (the device's pixels
/// bring back `oDepth`, not the interpolated z table fog reads). Table fog
/// otherwise runs on the CPU from each pixel's rasterised z, as the
/// emulator's does from its own.
pub(super) fn refuse_fog(shader: &Shader, fog: Option<&Fog>) -> Result<(), DrawFailure> {
    let Some(fog) = fog else {
        return Ok(());
    };
    // A ps_1_x shader writes oDepth through its lowering (texdepth).
    let shader = shader.runnable().unwrap_or(shader);
    let odepth = shader.program().instructions.iter().any(|i| {
        i.dst
            .as_ref()
            .is_some_and(|d| d.reg.file == crate::core::isa::RegFile::DepthOut)
    });
    let why = match (fog.mode, odepth) {
        (FogMode::Vertex, _) => "vertex fog (mode \"vertex\") is drawn on the emulator only: the GPU backend does not carry the interpolated fog factor to its pixels",
        (_, _) if fog.w => "table fog from w (depth \"w\") is drawn on the emulator only: the GPU backend applies table fog from each pixel's rasterised z",
        (_, true) => "table fog after a shader that writes oDepth is drawn on the emulator only: the GPU backend's pixels bring back oDepth, not the interpolated z that fog reads",
        _ => return Ok(()),
    };
    Err(DrawFailure::Message(format!("geometry.fog: {why}")))
}

/// Every primitive of `g` drawn on `device` and taken into `pass`.
pub(super) fn shade_all(
    device: &Gpu,
    shader: &Shader,
    d: &DrawStep,
    g: &Geometry,
    stage: &Stage,
    c: &Context,
    pass: &mut Pass,
) -> Result<Drawn, DrawFailure> {
    let (viewport, clip_rect, settings) = (c.viewport, c.clip_rect, c.settings);
    let draw = pixel_draw(d, stage, c.samplers, settings, (pass.width, c.height));
    let (geometry, faces) = geometry_draw(g, stage, &draw, viewport, clip_rect)?;
    let refusal = match c.fog {
        Some(_) => Some("fog runs on the CPU".into()),
        None => super::one_pass::refusal(device, d, g, pass),
    };
    crate::core::phases::mark(&format!(
        "geometry: {}",
        refusal
            .as_deref()
            .map_or("in one pass".into(), |r| format!("per primitive ({r})"))
    ));
    if refusal.is_none() {
        return super::one_pass::draw(device, shader, (d, &geometry, g), settings, pass);
    }
    let primitives = &geometry.primitives;
    let shaded = gpu::draw_geometry(device, shader, &geometry)
        .map_err(|e| DrawFailure::Message(e.to_string()))?;
    let mut drawn = Drawn {
        merged: MergeStats::default(),
        executed: None,
        total: 0,
        gradients: Vec::new(),
        triangles: 0,
        shaded: 0,
    };
    let mut pixels_left = settings.budget.max_pixels;
    for ((prim, &face), s) in primitives.iter().zip(&faces).zip(&shaded) {
        if s.pixels.is_empty() {
            continue;
        }
        pixels_left = pixels_left
            .checked_sub(s.pixels.len() as u64)
            .ok_or_else(|| {
                DrawFailure::Message(format!(
                    "the draw's primitives cover more than {} pixels (raise it with --max-list-pixels)",
                    settings.budget.max_pixels
                ))
            })?;
        drawn.triangles += prim.len() as u64;
        drawn.shaded += s.pixels.len() as u64;
        let (window, mut out) = window(s, pass.width);
        if let (Some(f), Some(Some(colors))) = (&c.fog, out.color.first_mut()) {
            // Table fog from each pixel's rasterised z (`s.depth`: the
            // shader writes no oDepth, `refuse_fog` says).
            for (i, color) in colors.iter_mut().enumerate() {
                if window.inputs.covered[i] {
                    *color = f.blend(*color, f.factor(window.depth[i]));
                }
            }
        }
        pass.take(&window, &out, d.pixel.alpha_test, face)?;
    }
    Ok(drawn)
}

/// The pixel shader's draw for the device: constants, samplers and float
/// rules of step `d` on a `size` target.
fn pixel_draw<'s>(
    d: &DrawStep,
    stage: &Stage,
    samplers: &[(u32, emu::TextureLevels<'s>, emu::SamplerState)],
    settings: &Settings,
    size: (u32, u32),
) -> emu::Draw<'s> {
    let mut draw = emu::Draw::new(size.0, size.1);
    draw.constants = d.constants.clone();
    draw.float_rules = d.pixel.float_rules.unwrap_or(settings.float_rules);
    draw.samplers = samplers.to_vec();
    // The inputs arrive from the device's interpolators; the draw names
    // them so that the emulator's checks of the draw see them supplied.
    draw.inputs = stage
        .slots
        .iter()
        .map(|s| (s.slot, emu::LinearInput::default()))
        .collect();
    draw
}

/// Sets `g` up over `stage` as the device draws it: the draw and each
/// primitive's facing.
fn geometry_draw<'d>(
    g: &Geometry,
    stage: &Stage,
    draw: &'d emu::Draw<'d>,
    viewport: &Viewport,
    clip_rect: Rect,
) -> Result<(GeometryDraw<'d>, Vec<Face>), DrawFailure> {
    let setup = setup(g, stage, viewport).map_err(DrawFailure::Message)?;
    let setup_faces = setup.faces;
    let flat = stage.slots.iter().fold(0u64, |bits, s| {
        (0..4)
            .filter(|&c| s.flat[c] && s.slot < 16)
            .fold(bits, |b, c| b | 1 << (4 * s.slot + c as u32))
    });
    let geometry = GeometryDraw {
        pixel: draw,
        positions: setup.positions,
        transformed: stage.transformed,
        values: setup.values,
        slots: stage.slots.iter().map(|s| s.slot).collect(),
        flat,
        primitives: setup.primitives,
        viewport: *viewport,
        clip: clip_rect,
        // D3DRS_CULLMODE culls triangles; a point's square (clockwise, so
        // front) is never culled, as the emulator's points are not.
        cull: match g.primitive {
            Primitive::PointList => raster::Cull::None,
            _ => g.cull,
        },
        clip_planes: g.clip_planes.iter().map(|p| p.map(|x| x as f32)).collect(),
    };
    Ok((geometry, setup_faces))
}

/// Which pixels each primitive of a draw of geometry covers on the
/// emulator and on a device, for `compare`.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Coverage {
    /// Per primitive (in drawing order), the pixels the emulator's set-up
    /// covers, as indices y·width + x in row order.
    pub emulator: Vec<Vec<u32>>,
    /// Per primitive, the pixels the device covered.
    pub gpu: Vec<Vec<u32>>,
    /// Per primitive, the emulator's screen triangles after clipping and
    /// culling (corners in pixels, centres on integers).
    pub triangles: Vec<Vec<[[f64; 2]; 3]>>,
}

/// The coverage of step `d` (a draw of geometry) on both backends, its
/// samplers bound from `states` (the targets as the step sees them).
pub(crate) fn coverage(
    list: &DrawList,
    d: &DrawStep,
    states: &[TargetState],
    settings: &Settings,
    device: &Arc<Gpu>,
) -> Result<Coverage, DrawFailure> {
    let Some(g) = d.geometry.as_deref() else {
        return Ok(Coverage::default());
    };
    let spec = &list.targets[d.target];
    let (width, height) = (spec.width, spec.height);
    let float_rules = d.pixel.float_rules.unwrap_or(settings.float_rules);
    let viewport = g.viewport.unwrap_or_else(|| Viewport::whole(width, height));
    let clip_rect = super::clip_rect(g, &viewport, width, height);
    let emulated = super::vertex_stage(list, g, d, float_rules, states, &Backend::Emulator)?;
    let order = g
        .indices
        .as_ref()
        .map_or(emulated.positions.len(), Vec::len);
    let count = raster::assemble(g.primitive, order)
        .map_err(DrawFailure::Message)?
        .len();
    let mut c = Coverage {
        emulator: vec![Vec::new(); count],
        gpu: Vec::new(),
        triangles: vec![Vec::new(); count],
    };
    let shapes = super::shapes(g, &emulated, &viewport, clip_rect).map_err(DrawFailure::Message)?;
    for (t, _, p) in shapes {
        c.triangles[p].push(std::array::from_fn(|k| {
            t.corners().get(k).map_or([0.0; 2], |v| [v.x, v.y])
        }));
        let Some(b) = t.bounds(clip_rect) else {
            continue;
        };
        for y in b.top..b.bottom {
            for x in (b.left..b.right).filter(|&x| t.covers(f64::from(x), f64::from(y))) {
                c.emulator[p].push(y * width + x);
            }
        }
    }
    for pixels in &mut c.emulator {
        pixels.sort_unstable();
        pixels.dedup();
    }
    let backend = Backend::Gpu(device.clone());
    let stage = super::vertex_stage(list, g, d, float_rules, states, &backend)?;
    let samplers = crate::jobs::render::bind_samplers(list, d, &d.samplers, states)?;
    let draw = pixel_draw(d, &stage, &samplers, settings, (width, height));
    let shader = &list.shaders[d.shader].loaded.shader;
    let (geometry, _) = geometry_draw(g, &stage, &draw, &viewport, clip_rect)?;
    let shaded = gpu::draw_geometry(device, shader, &geometry)
        .map_err(|e| DrawFailure::Message(e.to_string()))?;
    c.gpu = shaded.into_iter().map(|s| s.pixels).collect();
    c.gpu.resize(count, Vec::new());
    Ok(c)
}

/// A primitive's shaded pixels as the emulator's window of them: the
/// rectangle they span, which pixels are covered, their depths and the
/// shader's outputs.
pub(crate) fn window(s: &ShadedPrimitive, width: u32) -> (Window, DrawOutput) {
    let xs = s.pixels.iter().map(|&i| i % width);
    let ys = s.pixels.iter().map(|&i| i / width);
    let (x0, x1) = (xs.clone().min().unwrap_or(0), xs.max().unwrap_or(0) + 1);
    let (y0, y1) = (ys.clone().min().unwrap_or(0), ys.max().unwrap_or(0) + 1);
    let (w, h) = (x1 - x0, y1 - y0);
    let n = w as usize * h as usize;
    let at = |i: u32| ((i / width - y0) * w + i % width - x0) as usize;
    let mut covered = vec![false; n];
    let mut depth = vec![f64::NAN; n];
    let mut killed = vec![false; n];
    let mut color: Vec<Option<Vec<[f32; 4]>>> = s
        .color
        .iter()
        .map(|c| c.as_ref().map(|_| vec![[0.0; 4]; n]))
        .collect();
    for (k, &i) in s.pixels.iter().enumerate() {
        let j = at(i);
        covered[j] = true;
        depth[j] = f64::from(s.depth[k]);
        killed[j] = s.killed[k];
        for (out, from) in color.iter_mut().zip(&s.color) {
            if let (Some(out), Some(from)) = (out, from) {
                out[j] = from[k];
            }
        }
    }
    let window = Window {
        width: w,
        height: h,
        inputs: PixelInputs {
            origin: (x0, y0),
            covered,
            values: Vec::new(),
        },
        depth,
    };
    let out = DrawOutput {
        width: w,
        height: h,
        color,
        depth: None,
        killed,
        executed: vec![0; n],
        quads_x: w.div_ceil(2),
        quad_executed: Vec::new(),
        quad_divergent: Vec::new(),
        gradients: Vec::new(),
        instructions: Vec::new(),
    };
    (window, out)
}
