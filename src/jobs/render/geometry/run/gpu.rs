//! A draw of geometry on the GPU backend: the primitives assembled here by
//! `core/raster`'s rules (lists, strips rewound, fans around vertex 0, the
//! provoking vertex moved first), points set up as the emulator sets them
//! up, and either the whole draw run on the device in one pass
//! (`one_pass.rs` says when) or each primitive rasterised and shaded by the
//! device (`core::gpu::draw_geometry_recorded`: one device draw whose
//! fragments are recorded and put back in drawing order, or
//! `core::gpu::draw_geometry`: a render pass per primitive), its pixels
//! then taking the same path as the emulator's triangles — `texkill`, the
//! alpha test, the depth test, the output merger — in drawing order.

use super::{Drawn, FillMode, Pass, Stage};
use crate::core::emu::{self, DrawOutput, PixelInputs};
use crate::core::gpu::{self, GeometryDraw, Gpu, GpuError, ShadedPrimitive};
use crate::core::ir::Shader;
use crate::core::raster::clip::{self, GUARD_BAND, VIEW_VOLUME};
use crate::core::raster::fog::{Fog, FogMode};
use crate::core::raster::triangle::Window;
use crate::core::raster::{self, Face, Primitive, Rect, Viewport};
use crate::core::translate::interface::GeometryFog;
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

/// Assembles `g`'s primitives over `stage`'s vertices; with `fog`, each
/// vertex's values end with its fog column (vertex fog's factor or table
/// fog's w in x), which the device interpolates as it does the inputs.
/// A triangle filled as points (D3DFILL_POINT) is clipped and culled here
/// by the emulator's own set-up, and each vertex of what is left becomes a
/// point, as a point list's vertex does; with `points_apart` each such
/// point is a primitive of its own, so that where two of them overlap the
/// CPU merges both fragments in turn, as the emulator does (a primitive's
/// fragments are merged as one window, one per pixel).
fn setup(
    g: &Geometry,
    stage: &Stage,
    viewport: &Viewport,
    fog: bool,
    points_apart: bool,
) -> Result<Setup, String> {
    if g.primitive.is_line() {
        return Err(format!(
            "the GPU backend draws points and triangles; {:?} is drawn on the emulator only",
            g.primitive
        ));
    }
    if g.state.fill == FillMode::Wireframe {
        return Err(
            "the GPU backend draws solid and point fills; fill_mode wireframe (triangles' edges as lines) is drawn on the emulator only"
                .into(),
        );
    }
    let narrow = |v: &[f64; 4]| v.map(|x| x as f32);
    let mut s = Setup {
        positions: stage.positions.iter().map(narrow).collect(),
        values: stage
            .values
            .iter()
            .map(|v| carried(stage, v, fog))
            .collect(),
        primitives: Vec::new(),
        faces: Vec::new(),
    };
    let order: Vec<usize> = match &g.indices {
        Some(ix) => ix.iter().map(|&i| i as usize).collect(),
        None => (0..stage.positions.len()).collect(),
    };
    let planes: Vec<[f64; 4]> = VIEW_VOLUME.iter().chain(&g.clip_planes).copied().collect();
    let guard_band: Vec<[f64; 4]> = GUARD_BAND.iter().chain(&g.clip_planes).copied().collect();
    let emulator = super::Setup {
        g,
        stage,
        viewport,
        limit: viewport.rect(),
    };
    let vertex = |i: u32| clip::ClipVertex {
        pos: stage.positions[i as usize],
        values: stage.values[i as usize].clone(),
    };
    for prim in raster::assemble(g.primitive, order.len())? {
        let [a, b, c] = prim.corners.map(|i| order[i] as u32);
        if g.primitive == Primitive::PointList {
            let p = stage.positions[a as usize];
            // A point outside the view volume is not drawn; it keeps its
            // place so that primitives keep their numbers.
            let drawn = stage.transformed || clip::inside(&planes, &p);
            let points = if drawn {
                s.point(g, stage, viewport, &vertex(a), fog)
            } else {
                Vec::new()
            };
            s.primitives.push(points);
            s.faces.push(Face::Front);
            continue;
        }
        if g.state.fill == FillMode::Point {
            let corners = vec![vertex(a), vertex(b), vertex(c)];
            let polygon = match stage.transformed {
                true => corners,
                false => clip::clip(corners, &guard_band),
            };
            // The emulator's set-up draws nothing of a culled or
            // degenerate polygon.
            let drawn = !emulator.polygon(polygon.clone()).is_empty();
            let mut points = Vec::new();
            for v in polygon.iter().filter(|_| drawn) {
                let square = s.point(g, stage, viewport, v, fog);
                match points_apart {
                    true => {
                        s.primitives.push(square);
                        s.faces.push(Face::Front);
                    }
                    false => points.extend(square),
                }
            }
            if !points_apart {
                s.primitives.push(points);
                s.faces.push(Face::Front);
            }
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

/// A vertex's values as the device takes them: the pixel shader's inputs
/// and, with `fog`, the fog column. The stage's values end with each
/// vertex's own point size, which sizes points here and is no input of
/// the pixel shader, and its fog column.
fn carried(stage: &Stage, v: &[[f64; 4]], fog: bool) -> Vec<[f32; 4]> {
    let inputs = stage.slots.len();
    let fog_column = fog.then(|| &v[inputs + 1]);
    v[..inputs]
        .iter()
        .chain(fog_column)
        .map(|v| v.map(|x| x as f32))
        .collect()
}

impl Setup {
    /// The square of a point at `at` as the emulator sets it up, its four
    /// corners added to the vertices: its two triangles, clockwise (a
    /// front face, as the emulator's are).
    fn point(
        &mut self,
        g: &Geometry,
        stage: &Stage,
        viewport: &Viewport,
        at: &clip::ClipVertex,
        fog: bool,
    ) -> Vec<[u32; 3]> {
        let first = self.positions.len() as u32;
        let size = super::point_size(g, stage, viewport, at);
        let corners = [(-1.0, -1.0), (1.0, -1.0), (-1.0, 1.0), (1.0, 1.0)];
        for (k, (dx, dy)) in corners.into_iter().enumerate() {
            self.positions.push(point_corner(
                at.pos,
                dx,
                dy,
                size,
                stage.transformed,
                viewport,
            ));
            let values = super::point_values(g, stage, &at.values, k);
            self.values.push(carried(stage, &values, fog));
        }
        let [tl, tr, bl, br] = [first, first + 1, first + 2, first + 3];
        vec![[tl, tr, bl], [tr, br, bl]]
    }
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

/// What the device brings back for `fog`: the interpolated fog column
/// for vertex fog and table fog from w (the emulator interpolates the same
/// column with perspective), else the rasterised z, which table fog reads
/// even where the shader writes `oDepth` (the emulator's `fog_pixels`
/// reads its window's z, not `oDepth`).
fn fog_kind(fog: Option<&Fog>) -> Option<GeometryFog> {
    fog.map(|f| match f.mode == FogMode::Vertex || f.w {
        true => GeometryFog::Varying,
        false => GeometryFog::Depth,
    })
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
    let fog = fog_kind(c.fog.as_ref());
    let (geometry, faces) = geometry_draw(g, stage, &draw, (viewport, clip_rect), fog, true)?;
    let refusal = match c.fog {
        Some(_) => Some("fog runs on the CPU".into()),
        // For comparing the two ways on draws that could take one pass.
        None if std::env::var_os("PS30_RECORDS").is_some() => Some("PS30_RECORDS is set".into()),
        None => super::one_pass::refusal(device, d, g, pass),
    };
    let Some(refusal) = refusal else {
        crate::core::phases::mark("geometry: in one pass");
        return super::one_pass::draw(device, shader, (d, &geometry, g), settings, pass);
    };
    let recorded = match records_refusal(device) {
        None => {
            crate::core::phases::mark(&format!(
                "geometry: in one device draw, merged on the CPU ({refusal})"
            ));
            gpu::draw_geometry_recorded(device, shader, &geometry)
        }
        Some(why) => Err(GpuError::Unsupported(why)),
    };
    let shaded = match recorded {
        // A device without what the recorded draw needs, or a triangle
        // whose records outgrow its largest storage buffer: a pass per
        // primitive, which needs neither.
        Err(GpuError::Unsupported(why)) => {
            crate::core::phases::mark(&format!("geometry: per primitive ({refusal}; {why})"));
            gpu::draw_geometry(device, shader, &geometry)
        }
        other => other,
    }
    .map_err(|e| DrawFailure::Message(e.to_string()))?;
    let primitives = &geometry.primitives;
    let mut drawn = Drawn::default();
    let mut pixels_left = settings.budget.max_pixels;
    for ((prim, &face), mut s) in primitives.iter().zip(&faces).zip(shaded) {
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
        if let (Some(f), Some(Some(colors))) = (&c.fog, s.color.first_mut()) {
            // Fog on the CPU, as the emulator's, from each pixel's d as
            // the device brought it back (`fog_kind`).
            for (color, &d) in colors.iter_mut().zip(&s.fog) {
                *color = f.blend(*color, f.factor(f64::from(d)));
            }
        }
        let (window, out) = window(&s, pass.width);
        pass.take(&window, &out, d.pixel.alpha_test, face)?;
    }
    Ok(drawn)
}

/// Why a draw whose merger runs on the CPU cannot be shaded in one device
/// draw with fragment records on `device` (`None` when it can), and so
/// takes a render pass and read-back per primitive.
fn records_refusal(device: &Gpu) -> Option<String> {
    if std::env::var_os("PS30_PER_PRIMITIVE").is_some() {
        return Some("PS30_PER_PRIMITIVE is set".into());
    }
    gpu::records_lack(device).map(str::to_string)
}

/// The pixel shader's draw for the device: constants, samplers and float
/// rules of step `d` on a `size` target.
pub(super) fn pixel_draw<'s>(
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

/// Sets `g` up over `stage` as the device draws it (in `view`: the
/// viewport and the pixels it may write), bringing back `fog`, with a
/// point fill's points as primitives of their own where `points_apart`
/// (`setup`): the draw and each primitive's facing.
fn geometry_draw<'d>(
    g: &Geometry,
    stage: &Stage,
    draw: &'d emu::Draw<'d>,
    view: (&Viewport, Rect),
    fog: Option<GeometryFog>,
    points_apart: bool,
) -> Result<(GeometryDraw<'d>, Vec<Face>), DrawFailure> {
    let (viewport, clip_rect) = view;
    let varying = fog == Some(GeometryFog::Varying);
    let setup = setup(g, stage, viewport, varying, points_apart).map_err(DrawFailure::Message)?;
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
        // front) is never culled, as the emulator's points are not (a
        // triangle filled as points was culled in `setup`).
        cull: match (g.primitive, g.state.fill) {
            (Primitive::PointList, _) | (_, FillMode::Point) => raster::Cull::None,
            _ => g.cull,
        },
        // A point is kept or dropped whole by its centre (`setup`), as on
        // the emulator, which never cuts a point's square by a user plane:
        // the device is given no planes to cut it by.
        clip_planes: match (g.primitive, g.state.fill) {
            (Primitive::PointList, _) | (_, FillMode::Point) => Vec::new(),
            _ => g.clip_planes.iter().map(|p| p.map(|x| x as f32)).collect(),
        },
        fog,
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
    if super::draws_lines(g) {
        // The device shades the pixels the emulator's set-up gives a line
        // (`gpu_lines.rs`): the same coverage by construction.
        c.gpu = c.emulator.clone();
        return Ok(c);
    }
    let backend = Backend::Gpu(device.clone());
    let stage = super::vertex_stage(list, g, d, float_rules, states, &backend)?;
    let samplers = crate::jobs::render::bind_samplers(list, d, &d.samplers, states)?;
    let draw = pixel_draw(d, &stage, &samplers, settings, (width, height));
    let shader = &list.shaders[d.shader].loaded.shader;
    // Coverage is compared per primitive of the draw: a point fill's
    // points stay together.
    let (geometry, _) = geometry_draw(g, &stage, &draw, (&viewport, clip_rect), None, false)?;
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
            positions: None,
        },
        depth,
    };
    let out = DrawOutput::uncounted((w, h), color, None, killed);
    (window, out)
}
