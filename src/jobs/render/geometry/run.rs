//! A draw of geometry, run: the vertex stage, `core/raster`'s set-up, the
//! pixel shader over each triangle's window of pixels, and per pixel, in
//! Direct3D 9's order, `texkill`, the alpha test, the depth test and depth
//! write (D3DRS_ZENABLE, ZFUNC, ZWRITEENABLE; oDepth replaces the
//! interpolated depth where the shader writes it), then the output merger.
//!
//! Primitives reach the target in the order they were drawn, as Direct3D 9
//! guarantees: the colours of consecutive triangles are gathered in one
//! full-target buffer and blended together, and the buffer is merged
//! before a triangle that covers a pixel already in it, so that blending
//! sees every earlier triangle.

mod clipped;
mod gpu;
mod gpu_lines;
mod one_pass;

pub(crate) use gpu::coverage;
pub use gpu::Coverage;

use super::state::{FillMode, StencilState};
use super::{DepthState, Geometry};
use crate::core::emu::vertex::{self, Attribute, VertexDraw};
use crate::core::emu::{self, Compiled, Draw, DrawOutput, EmuError, GradientSite};
use crate::core::ir::Program;
use crate::core::isa::RegFile;
use crate::core::merge::{self, MergeStats, OutputState};
use crate::core::pixel_inputs::unwritten;
use crate::core::raster::clip::{self, ClipVertex, GUARD_BAND, VIEW_VOLUME};
use crate::core::raster::depth::DepthFormat;
use crate::core::raster::fog::{Fog, FogMode};
use crate::core::raster::stencil::{self, StencilOutcome};
use crate::core::raster::{self, Face, Rect, ScreenVertex, Shape, Triangle, Viewport};
use crate::jobs::render::history::{self, Recorder, Verdict};
use crate::jobs::render::{DrawFailure, DrawList, DrawStep, Settings, TargetState};

/// A target's depth-stencil surface: one stored depth per pixel.
#[derive(Clone, Debug, PartialEq)]
pub struct DepthBuffer {
    /// Its format (what every stored value is rounded to).
    pub format: DepthFormat,
    /// Stored depths, row-major.
    pub values: Vec<f64>,
    /// Stored stencil values, row-major (the format's stencil bits; 0 in
    /// a surface without stencil).
    pub stencil: Vec<u8>,
}

/// What a geometry draw did, for its step's report.
#[derive(Default)]
pub(crate) struct Drawn {
    /// What the output merger wrote and what was discarded.
    pub merged: MergeStats,
    /// Executed slots (min, max) over the pixels shaded.
    pub executed: Option<(u64, u64)>,
    /// Executed slots of all pixels, helpers included.
    pub total: u64,
    /// Gradient sites summed over the triangles' draws.
    pub gradients: Vec<GradientSite>,
    /// Triangles that covered a pixel and ran the pixel shader.
    pub triangles: u64,
    /// Pixels a GPU shaded (it counts no executed slots; the list's budget
    /// is charged the cost model's longest path for each).
    pub shaded: u64,
}

/// A pixel-shader input slot and where its components come from: the
/// index of its value in each vertex's values.
struct Slot {
    slot: u32,
    flat: [bool; 4],
}

/// Each input slot of `program` with the semantic it reads: ps_3_0's
/// `dcl_<usage><index> v#`; ps_2_0/ps_2_x's colours v0, v1 (color0, color1)
/// and texture coordinates t# (texcoord#).
fn pixel_semantics(program: &Program) -> Vec<(u32, Attribute)> {
    let mut out: Vec<(u32, Attribute)> = Vec::new();
    for d in &program.inputs {
        let (usage, index) = match d.reg.file {
            RegFile::Input if crate::core::pixel_inputs::clamped(program.profile) != 0 => {
                ("color".to_string(), d.reg.index)
            }
            RegFile::Input => (d.usage.clone(), d.usage_index),
            RegFile::Texture => ("texcoord".to_string(), d.reg.index),
            _ => continue,
        };
        let Some(slot) = crate::core::pixel_inputs::slot(program.profile, d.reg.file, d.reg.index)
        else {
            continue;
        };
        if !out.iter().any(|(s, _)| *s == slot) {
            out.push((slot, Attribute { usage, index }));
        }
    }
    out
}

/// The vertices after the vertex stage: clip-space (or, pre-transformed,
/// screen) positions and each input slot's value per vertex.
struct Stage {
    positions: Vec<[f64; 4]>,
    /// Each vertex's slot values, then two more: its own point size and
    /// its fog factor in x (NaN where it gives none), carried through
    /// clipping with the rest.
    values: Vec<Vec<[f64; 4]>>,
    transformed: bool,
    slots: Vec<Slot>,
    /// Whether each slot reads a texture coordinate (a point sprite
    /// replaces those).
    texcoord: Vec<bool>,
    /// No vertex shader: the fixed-function pipeline transformed the
    /// positions (point scaling applies).
    fixed_function: bool,
    /// Whether the vertices give a fog factor (vertex fog reads it).
    fog_given: bool,
}

impl Stage {
    /// Each pixel-shader input slot with its index among the vertex's
    /// values and its flat-shaded components, as a window's set-up takes
    /// them.
    fn slot_list(&self) -> Vec<(u32, usize, [bool; 4])> {
        self.slots
            .iter()
            .enumerate()
            .map(|(k, s)| (s.slot, k, s.flat))
            .collect()
    }
}

/// `values` with the point-size and fog columns appended.
fn with_size(mut values: Vec<[f64; 4]>, size: Option<f32>, fog: Option<f32>) -> Vec<[f64; 4]> {
    let column = |v: Option<f32>| [v.map_or(f64::NAN, f64::from), 0.0, 0.0, 0.0];
    values.push(column(size));
    values.push(column(fog));
    values
}

fn widen(v: [f32; 4]) -> [f64; 4] {
    v.map(f64::from)
}

fn vertex_stage(
    list: &DrawList,
    g: &Geometry,
    d: &DrawStep,
    float_rules: crate::core::float_rules::FloatRules,
    states: &[TargetState],
    backend: &crate::jobs::backend::Backend,
) -> Result<Stage, DrawFailure> {
    let program = list.shaders[d.shader].loaded.shader.program();
    let wanted = pixel_semantics(program);
    let slots = wanted
        .iter()
        .map(|(slot, _)| Slot {
            slot: *slot,
            flat: if d.pixel.flat {
                super::super::pixel_state::flat_components(program, *slot)
            } else {
                [false; 4]
            },
        })
        .collect();
    let texcoord: Vec<bool> = wanted.iter().map(|(_, a)| a.usage == "texcoord").collect();
    let psize = Attribute {
        usage: "psize".into(),
        index: 0,
    };
    let n = g.vertices.count;
    let find = |usage: &str| {
        g.vertices
            .attributes
            .iter()
            .find(|(a, _)| a.usage == usage && a.index == 0)
            .map(|(_, v)| v)
    };
    let Some(vs) = g.vertex_shader else {
        // Fixed function with identity transforms: attributes by usage.
        let (pos, transformed) = match (find("positiont"), find("position")) {
            (Some(p), _) => (p, true),
            (None, Some(p)) => (p, false),
            (None, None) => return Err(DrawFailure::Message(
                "the vertices have no position0 or positiont0 and no vertex shader computes one"
                    .into(),
            )),
        };
        let attr = |a: &Attribute| {
            g.vertices
                .attributes
                .iter()
                .find(|(b, _)| b == a)
                .map(|(_, v)| v)
        };
        let sizes = attr(&psize);
        // Without a vertex shader vertex fog is the specular alpha.
        let specular = attr(&Attribute {
            usage: "color".into(),
            index: 1,
        });
        let unset =
            |a: &Attribute| [f64::from(unwritten(program.profile, &a.usage, a.index, true)); 4];
        let fog = |v: usize| match fog_from_w(g) {
            // A pre-transformed vertex holds 1/w ("Direct3D takes the
            // reciprocal of the RHW element ... to reproduce true w").
            true if transformed => Some(1.0 / pos[v][3]),
            true => Some(pos[v][3]),
            false => specular.map(|s| s[v][3]),
        };
        let values = (0..n)
            .map(|v| {
                let values = wanted
                    .iter()
                    .map(|(_, a)| attr(a).map_or(unset(a), |vals| widen(vals[v])))
                    .collect();
                with_size(values, sizes.map(|s| s[v][0]), fog(v))
            })
            .collect();
        return Ok(Stage {
            positions: pos.iter().map(|p| widen(*p)).collect(),
            values,
            transformed,
            slots,
            texcoord,
            fixed_function: !transformed,
            fog_given: specular.is_some() || fog_from_w(g),
        });
    };
    let shader = &list.shaders[vs].loaded.shader;
    let draw = VertexDraw {
        constants: g.vertex_constants.clone(),
        samplers: super::super::bind_samplers(list, d, &g.vertex_samplers, states)?,
        float_rules,
        ..VertexDraw::default()
    };
    let out = match settings_gpu(backend)? {
        Some(device) => crate::core::gpu::run_vertices(device, shader, &draw, &g.vertices)
            .map_err(|e| DrawFailure::Message(format!("vertex shader: {e}")))?,
        None => vertex::run(shader, &draw, &g.vertices)
            .map_err(|e| DrawFailure::Message(format!("vertex shader: {e}")))?,
    };
    let column = |a: &Attribute| {
        out.slots
            .iter()
            .position(|s| s.semantic.as_ref() == Some(a))
    };
    let position = column(&Attribute {
        usage: "position".into(),
        index: 0,
    })
    .ok_or_else(|| {
        DrawFailure::Message(
            "the vertex shader writes no position (oPos, or an o# declared dcl_position)".into(),
        )
    })?;
    let columns: Vec<Option<usize>> = wanted.iter().map(|(_, a)| column(a)).collect();
    let defaults = unwritten_values(program, shader, &wanted, &columns);
    let size_column = column(&psize);
    let fog_column = shader_fog_column(g, position, &column);
    Ok(Stage {
        positions: out.values.iter().map(|v| widen(v[position])).collect(),
        values: out
            .values
            .iter()
            .map(|v| {
                let values = columns
                    .iter()
                    .zip(&defaults)
                    .map(|(c, d)| {
                        let given = c.map_or([0.0; 4], |c| widen(v[c]));
                        std::array::from_fn(|k| if d[k].is_nan() { given[k] } else { d[k] })
                    })
                    .collect();
                with_size(
                    values,
                    size_column.map(|c| v[c][0]),
                    fog_column.map(|(c, k)| v[c][k]),
                )
            })
            .collect(),
        transformed: false,
        slots,
        texcoord,
        fixed_function: false,
        fog_given: fog_column.is_some(),
    })
}

/// Per pixel-shader input, each component's value where the vertex shader
/// `vs` never writes it (NaN where it does), by `pixel_inputs::unwritten`;
/// `columns` are the vertex outputs feeding `wanted`.
fn unwritten_values(
    program: &Program,
    vs: &crate::core::ir::Shader,
    wanted: &[(u32, Attribute)],
    columns: &[Option<usize>],
) -> Vec<[f64; 4]> {
    let masks = vertex::written(vs);
    wanted
        .iter()
        .zip(columns)
        .map(|((_, a), c)| {
            let mask = c.map_or(0, |c| masks[c]);
            let value = f64::from(unwritten(program.profile, &a.usage, a.index, false));
            std::array::from_fn(|k| {
                if mask & (1 << k) == 0 {
                    value
                } else {
                    f64::NAN
                }
            })
        })
        .collect()
}

/// The output column and component a vertex shader's fog factor comes
/// from. Vertex fog reads oFog; a vertex shader that writes none but writes
/// the specular colour (oD1) gives its alpha, as the fixed-function
/// pipeline's vertex fog does (vkd3d's fog.shader_test, recorded on native
/// Direct3D 9: `specular = float4(0, 0, 0, 0.3)` fogs by 0.3). Table fog
/// from w reads the position's own w.
fn shader_fog_column(
    g: &Geometry,
    position: usize,
    column: &dyn Fn(&Attribute) -> Option<usize>,
) -> Option<(usize, usize)> {
    if fog_from_w(g) {
        return Some((position, 3));
    }
    let attribute = |usage: &str, index| Attribute {
        usage: usage.into(),
        index,
    };
    column(&attribute("fog", 0))
        .map(|c| (c, 0))
        .or_else(|| column(&attribute("color", 1)).map(|c| (c, 3)))
}

/// Whether the draw's fog is table fog from w, read like vertex fog from a
/// column the vertex stage fills.
fn fog_from_w(g: &Geometry) -> bool {
    g.state
        .fog
        .is_some_and(|f| f.w && f.mode != FogMode::Vertex)
}

/// The primitives of the draw on screen, each with its provoking vertex
/// and the index of the primitive it came from, in drawing order: assembled, clipped (positions in clip space), divided,
/// mapped through the viewport, culled; points as two triangles, lines
/// with the pixels of `limit` they cover.
fn shapes(
    g: &Geometry,
    stage: &Stage,
    viewport: &Viewport,
    limit: Rect,
) -> Result<Vec<(Shape, usize, usize)>, String> {
    let order: Vec<usize> = match &g.indices {
        Some(ix) => ix.iter().map(|&i| i as usize).collect(),
        None => (0..stage.positions.len()).collect(),
    };
    let planes: Vec<[f64; 4]> = VIEW_VOLUME.iter().chain(&g.clip_planes).copied().collect();
    let guard_band: Vec<[f64; 4]> = GUARD_BAND.iter().chain(&g.clip_planes).copied().collect();
    let at = Setup {
        g,
        stage,
        viewport,
        limit,
    };
    let mut out = Vec::new();
    for (index, prim) in raster::assemble(g.primitive, order.len())?
        .into_iter()
        .enumerate()
    {
        let [a, b, c] = prim.corners.map(|i| order[i]);
        let provoking = order[prim.provoking];
        let corner = |i: usize| ClipVertex {
            pos: stage.positions[i],
            values: stage.values[i].clone(),
        };
        if g.primitive == raster::Primitive::PointList {
            let p = stage.positions[a];
            if stage.transformed || clip::inside(&planes, &p) {
                out.extend(
                    at.point(corner(a))
                        .into_iter()
                        .map(|t| (t, provoking, index)),
                );
            }
            continue;
        }
        if g.primitive.is_line() {
            out.extend(at.line(corner(a), corner(b)).map(|l| (l, provoking, index)));
            continue;
        }
        let polygon = if stage.transformed {
            vec![corner(a), corner(b), corner(c)]
        } else {
            clip::clip(vec![corner(a), corner(b), corner(c)], &guard_band)
        };
        for shape in at.polygon(polygon) {
            out.push((shape, provoking, index));
        }
    }
    Ok(out)
}

/// A point's size in pixels: D3DRS_POINTSIZE or the vertex's own
/// (`oPts`/`psize`, the next-to-last value column), scaled where the fixed-function
/// pipeline scales it, and clamped.
fn point_size(g: &Geometry, stage: &Stage, viewport: &Viewport, v: &ClipVertex) -> f64 {
    let own = v
        .values
        .iter()
        .rev()
        .nth(1)
        .map(|s| s[0])
        .filter(|s| !s.is_nan());
    let eye = stage
        .fixed_function
        .then(|| ([v.pos[0], v.pos[1], v.pos[2]], f64::from(viewport.height)));
    g.state.points.size_of(own, eye)
}

/// The values at corner `k` (top-left, top-right, bottom-left,
/// bottom-right) of a point with `values`: a sprite's texture coordinates
/// in place of the vertex's.
fn point_values(g: &Geometry, stage: &Stage, values: &[[f64; 4]], k: usize) -> Vec<[f64; 4]> {
    let mut out = values.to_vec();
    if g.state.points.sprite {
        for (value, _) in out.iter_mut().zip(&stage.texcoord).filter(|(_, t)| **t) {
            *value = raster::points::SPRITE_CORNERS[k];
        }
    }
    out
}

/// What the set-up of one primitive needs.
struct Setup<'a> {
    g: &'a Geometry,
    stage: &'a Stage,
    viewport: &'a Viewport,
    limit: Rect,
}

impl Setup<'_> {
    fn screen(&self, v: ClipVertex) -> ScreenVertex {
        let [x, y, z, rhw] = if self.stage.transformed {
            v.pos
        } else {
            self.viewport.to_screen(v.pos)
        };
        ScreenVertex {
            x,
            y,
            z,
            rhw,
            values: v.values,
        }
    }

    /// A point: the square of its size about it, as two triangles, with a
    /// sprite's texture coordinates at its corners.
    fn point(&self, v: ClipVertex) -> Vec<Shape> {
        let h = point_size(self.g, self.stage, self.viewport, &v) / 2.0;
        let centre = self.screen(v);
        let corner = |k: usize, dx: f64, dy: f64| ScreenVertex {
            x: centre.x + dx,
            y: centre.y + dy,
            values: point_values(self.g, self.stage, &centre.values, k),
            ..centre.clone()
        };
        let (tl, tr, bl, br) = (
            corner(0, -h, -h),
            corner(1, h, -h),
            corner(2, -h, h),
            corner(3, h, h),
        );
        [
            Triangle::new(tl, tr.clone(), bl.clone()),
            Triangle::new(tr, br, bl),
        ]
        .into_iter()
        .flatten()
        .map(Shape::Triangle)
        .collect()
    }

    /// A line, clipped against z and the user planes (x and y are the
    /// viewport's scissor: `core/raster`'s docs say why).
    fn line(&self, a: ClipVertex, b: ClipVertex) -> Option<Shape> {
        let (a, b) = if self.stage.transformed {
            (a, b)
        } else {
            let planes: Vec<[f64; 4]> = VIEW_VOLUME[4..]
                .iter()
                .chain(&self.g.clip_planes)
                .copied()
                .collect();
            clip::clip_segment(a, b, &planes)?
        };
        let (a, b) = (self.screen(a), self.screen(b));
        if ![a.x, a.y, b.x, b.y].iter().all(|v| v.is_finite()) {
            return None;
        }
        let last = self.g.state.last_pixel;
        Some(Shape::Line(raster::Line::new(a, b, last, self.limit)))
    }

    /// A clipped polygon, culled, as the fill mode draws it: triangles of
    /// a fan, its edges as lines, or its vertices as points.
    fn polygon(&self, polygon: Vec<ClipVertex>) -> Vec<Shape> {
        let on_screen: Vec<ScreenVertex> = polygon.iter().map(|v| self.screen(v.clone())).collect();
        if on_screen
            .iter()
            .any(|v| !(v.x.is_finite() && v.y.is_finite()))
        {
            // Only a vertex at the origin of clip space gets here (w = 0
            // and every guard-band plane through it): nothing to draw.
            return Vec::new();
        }
        let tris: Vec<Triangle> = (1..on_screen.len().saturating_sub(1))
            .filter_map(|i| {
                Triangle::new(
                    on_screen[0].clone(),
                    on_screen[i].clone(),
                    on_screen[i + 1].clone(),
                )
            })
            .collect();
        // The polygon's facing is its fan's (all alike).
        if tris.first().is_none_or(|t| self.g.cull.drops(t.face)) {
            return Vec::new();
        }
        let last = self.g.state.last_pixel;
        match self.g.state.fill {
            FillMode::Solid => tris.into_iter().map(Shape::Triangle).collect(),
            FillMode::Wireframe => (0..on_screen.len())
                .map(|i| {
                    let (a, b) = (&on_screen[i], &on_screen[(i + 1) % on_screen.len()]);
                    Shape::Line(raster::Line::new(a.clone(), b.clone(), last, self.limit))
                })
                .collect(),
            FillMode::Point => polygon.into_iter().flat_map(|v| self.point(v)).collect(),
        }
    }
}

/// Colours waiting to be merged: every output's full-target buffer and
/// which pixels hold a colour.
struct Pending {
    colors: Vec<Vec<[f32; 4]>>,
    held: Vec<bool>,
    any: bool,
    /// The outputs the shader wrote: an output it never writes leaves its
    /// target alone ("unwritten oCn → render target not updated", the
    /// ps_3_0 output-register page), as in a full-screen draw.
    wrote: [bool; 4],
}

/// The draw's state while its triangles run.
struct Pass<'t> {
    width: u32,
    /// The draw's targets, oC0 first (`None` where an output is unbound).
    targets: Vec<Option<(&'t mut TargetState, OutputState)>>,
    depth: Option<(DepthBuffer, DepthState)>,
    stencil: Option<StencilState>,
    pending: Pending,
    merged: MergeStats,
    /// The pixels whose history is being recorded, if any.
    watch: Option<&'t mut Recorder>,
}

impl Pass<'_> {
    /// Merges what is pending, in every bound target.
    fn flush(&mut self) -> Result<(), DrawFailure> {
        if !self.pending.any {
            return Ok(());
        }
        let skip: Vec<bool> = self.pending.held.iter().map(|h| !h).collect();
        for (k, t) in self.targets.iter_mut().enumerate() {
            let Some((state, output)) = t else { continue };
            if !self.pending.wrote[k] {
                continue;
            }
            if let Some(w) = self.watch.as_deref_mut() {
                w.before_merge(k, &state.target, &self.pending.colors[k]);
            }
            let stats = merge::merge(&mut state.target, &self.pending.colors[k], &skip, output)
                .map_err(|e| DrawFailure::Message(format!("oC{k}: {e}")))?;
            if let Some(w) = self.watch.as_deref_mut() {
                w.after_merge(k, &state.target);
            }
            if k == 0 {
                self.merged.written += stats.written;
            }
            state.mips = None;
        }
        self.pending.held.fill(false);
        self.pending.any = false;
        Ok(())
    }

    /// The stencil and depth tests at target pixel `t` for a fragment of
    /// depth `z` from a primitive of facing `face`, their writes done:
    /// whether the fragment goes on to the output merger, and what the
    /// stencil stage did (`None` without a stencil test).
    fn depth_stencil(&mut self, t: usize, z: f64, face: Face) -> (bool, Option<StencilOutcome>) {
        let Some((buffer, state)) = &mut self.depth else {
            return (true, None);
        };
        let z = buffer.format.store(z);
        let stored_z = buffer.values[t];
        let depth_passes = || state.func.passes(z, stored_z);
        let (survives, outcome) = match &self.stencil {
            None => (depth_passes(), None),
            Some(s) => {
                let side = match (face, s.ccw) {
                    (Face::Back, Some(ccw)) => ccw,
                    _ => s.cw,
                };
                let o = stencil::run(
                    buffer.stencil[t],
                    |a, b| side.func.passes(a, b),
                    depth_passes,
                    &side.ops,
                    s.reference,
                    s.mask,
                    s.write_mask,
                    buffer.format.stencil_max(),
                );
                buffer.stencil[t] = o.written;
                (o.survives(), Some(o))
            }
        };
        if survives && state.write {
            buffer.values[t] = z;
        }
        (survives, outcome)
    }

    /// Takes one triangle's shaded pixels through the alpha and depth
    /// tests into the pending colours.
    fn take(
        &mut self,
        window: &raster::triangle::Window,
        out: &DrawOutput,
        alpha: Option<super::super::pixel_state::AlphaTest>,
        face: Face,
    ) -> Result<(), DrawFailure> {
        let (ox, oy) = window.inputs.origin;
        let covered = |i: usize| window.inputs.covered[i];
        let width = self.width;
        let index = |i: usize| {
            let (x, y) = (i as u32 % window.width, i as u32 / window.width);
            ((oy + y) * width + ox + x) as usize
        };
        if (0..window.depth.len()).any(|i| covered(i) && self.pending.held[index(i)]) {
            self.flush()?;
        }
        for i in (0..window.depth.len()).filter(|&i| covered(i)) {
            let t = index(i);
            let verdict = self.test(window, out, alpha, (i, t), face);
            if let Some(w) = self.watch.as_deref_mut() {
                w.verdict(t, &verdict);
            }
            if verdict.killed {
                self.merged.killed += 1;
            }
            if !verdict.passed() {
                continue;
            }
            for (k, colors) in out.color.iter().enumerate() {
                if let Some(c) = colors {
                    self.pending.colors[k][t] = c[i];
                    self.pending.wrote[k] = true;
                }
            }
            self.pending.held[t] = true;
            self.pending.any = true;
        }
        Ok(())
    }
}

impl Pass<'_> {
    /// Pixel `i` of the window (`t` of the target), from a primitive of
    /// facing `face`, through `texkill`, the alpha test and the stencil and
    /// depth tests, in Direct3D 9's order, writing its depth and stencil as
    /// they say; the first test that fails ends it.
    fn test(
        &mut self,
        window: &raster::triangle::Window,
        out: &DrawOutput,
        alpha: Option<super::super::pixel_state::AlphaTest>,
        (i, t): (usize, usize),
        face: Face,
    ) -> Verdict {
        let mut verdict = Verdict {
            killed: out.killed[i],
            alpha: None,
            stencil: None,
            depth: None,
        };
        if verdict.killed {
            return verdict;
        }
        let oc0 = out.color.first().and_then(|c| c.as_ref()).map(|c| c[i]);
        if let (Some(a), Some(c)) = (alpha, oc0) {
            verdict.alpha = Some((c[3], a.passes(c[3])));
            if !a.passes(c[3]) {
                return verdict;
            }
        }
        let z = out
            .depth
            .as_ref()
            .map_or(window.depth[i], |d| f64::from(d[i]));
        let Some((buffer, state)) = &self.depth else {
            return verdict;
        };
        let (stored_z, stored, func, write) = (
            buffer.format.store(z),
            buffer.values[t],
            state.func,
            state.write,
        );
        let (survives, stencil) = self.depth_stencil(t, z, face);
        verdict.stencil = stencil;
        // The depth test runs unless the stencil test failed first.
        if stencil.is_none_or(|o| o.passed) {
            verdict.depth = Some(history::DepthTest {
                z: stored_z,
                odepth: out.depth.is_some(),
                stored,
                func,
                passed: func.passes(stored_z, stored),
                written: survives && write,
            });
        }
        verdict
    }
}

/// Runs draw `d` of geometry `g` and merges it into its targets.
pub(crate) fn draw(
    list: &DrawList,
    compiled: &Compiled,
    d: &DrawStep,
    g: &Geometry,
    states: &mut [TargetState],
    (settings, limits): (&Settings, emu::EmuLimits),
    mut watch: Option<&mut Recorder>,
) -> Result<Drawn, DrawFailure> {
    let spec = &list.targets[d.target];
    let (width, height) = (spec.width, spec.height);
    let float_rules = d.pixel.float_rules.unwrap_or(settings.float_rules);
    let stage = vertex_stage(list, g, d, float_rules, states, &settings.backend)?;
    let viewport = g.viewport.unwrap_or_else(|| Viewport::whole(width, height));
    let clip_rect = clip_rect(g, &viewport, width, height);
    let tris = shapes(g, &stage, &viewport, clip_rect).map_err(DrawFailure::Message)?;
    if let Some(w) = watch.as_deref_mut() {
        // The triangles the cull mode dropped, to say why a pixel was missed.
        let all = Geometry {
            cull: raster::Cull::None,
            ..g.clone()
        };
        let culled: Vec<Triangle> = shapes(&all, &stage, &viewport, clip_rect)
            .map_err(DrawFailure::Message)?
            .into_iter()
            .filter_map(|(s, _, _)| match s {
                Shape::Triangle(t) if g.cull.drops(t.face) => Some(t),
                _ => None,
            })
            .collect();
        let clipped = |x, y| clipped::at(g, &stage, &viewport, clip_rect, (x, y));
        w.geometry(tris.len(), &culled, (viewport.rect(), g.scissor), &clipped);
    }
    // The targets this draw writes leave `states` while it runs, so that
    // the samplers may borrow the others (a draw never samples its own).
    let mut outs: Vec<Option<(usize, OutputState)>> = vec![Some((d.target, d.output))];
    outs.extend(d.pixel.outputs.iter().map(|o| {
        o.map(|(t, write)| {
            (
                t,
                OutputState {
                    blend: d.output.blend,
                    write,
                },
            )
        })
    }));
    let mut taken: Vec<Option<(TargetState, OutputState)>> = outs
        .iter()
        .map(|o| o.map(|(t, out)| (take_state(&mut states[t]), out)))
        .collect();
    let depth = depth_buffer(&mut taken[0], g, width, height);
    let result = (|| {
        let depth = depth?;
        let samplers = super::super::bind_samplers(list, d, &d.samplers, states)?;
        let n = width as usize * height as usize;
        let mut pass = Pass {
            width,
            targets: taken
                .iter_mut()
                .map(|t| t.as_mut().map(|(s, o)| (s, *o)))
                .collect(),
            depth,
            stencil: g.state.stencil,
            pending: Pending {
                colors: vec![vec![[0.0; 4]; n]; 4],
                held: vec![false; n],
                any: false,
                wrote: [false; 4],
            },
            merged: MergeStats::default(),
            watch,
        };
        let drawn = match settings_gpu(&settings.backend)? {
            Some(device) => {
                let shader = &list.shaders[d.shader].loaded.shader;
                let fog = fog_state(list, d, &stage)?;
                let context = gpu::Context {
                    viewport: &viewport,
                    clip_rect,
                    samplers: &samplers,
                    settings,
                    height,
                    fog,
                };
                match draws_lines(g) {
                    true => {
                        gpu_lines::shade_lines(device, shader, d, g, &stage, &context, &mut pass)?
                    }
                    false => gpu::shade_all(device, shader, d, g, &stage, &context, &mut pass)?,
                }
            }
            None => shade_all(
                list, compiled, d, &stage, &tris, clip_rect, &samplers, settings, limits, &mut pass,
            )?,
        };
        pass.flush()?;
        let merged = pass.merged;
        let depth = pass.depth.take();
        Ok((drawn, merged, depth))
    })();
    let depth_back = match &result {
        Ok((_, _, depth)) => depth.clone(),
        Err(_) => None,
    };
    for (o, t) in outs.iter().zip(taken) {
        if let (Some((index, _)), Some((state, _))) = (o, t) {
            states[*index] = state;
        }
    }
    if let Some((buffer, _)) = depth_back {
        states[d.target].depth = Some(buffer);
    }
    let (mut drawn, merged, _) = result?;
    drawn.merged = merged;
    Ok(drawn)
}

/// Whether `g` draws lines (line primitives, or wireframe triangles),
/// which the GPU backend shades through the emulator's set-up
/// (`run/gpu_lines.rs`).
fn draws_lines(g: &Geometry) -> bool {
    g.primitive.is_line() || g.state.fill == FillMode::Wireframe
}

/// The pixels a draw may write: its viewport, the scissor rectangle and the
/// `width × height` target together.
fn clip_rect(g: &Geometry, viewport: &Viewport, width: u32, height: u32) -> Rect {
    let rect = viewport.rect().intersect(Rect {
        left: 0,
        top: 0,
        right: width,
        bottom: height,
    });
    match g.scissor {
        Some(s) => rect.intersect(s),
        None => rect,
    }
}

/// The device of a GPU backend (`None` for the emulator).
fn settings_gpu(
    backend: &crate::jobs::backend::Backend,
) -> Result<Option<&std::sync::Arc<crate::core::gpu::Gpu>>, DrawFailure> {
    backend
        .gpu()
        .map_err(|e| DrawFailure::Message(e.to_string()))
}

/// The state of a target, taken out of the list's (an empty target left
/// in its place until it comes back).
fn take_state(state: &mut TargetState) -> TargetState {
    let empty = TargetState {
        target: crate::core::image::RenderTarget::new(1, 1, state.target.format),
        mips: None,
        depth: None,
    };
    std::mem::replace(state, empty)
}

/// The depth buffer the draw tests, made or cleared as its state asks.
fn depth_buffer(
    target: &mut Option<(TargetState, OutputState)>,
    g: &Geometry,
    width: u32,
    height: u32,
) -> Result<Option<(DepthBuffer, DepthState)>, DrawFailure> {
    let (Some(state), Some((t, _))) = (g.depth, target.as_mut()) else {
        return Ok(None);
    };
    let n = width as usize * height as usize;
    let mut buffer = t.depth.take().unwrap_or(DepthBuffer {
        format: state.format,
        values: vec![1.0; n],
        stencil: vec![0; n],
    });
    if buffer.format != state.format {
        return Err(DrawFailure::Message(format!(
            "the target's depth surface is {}; this draw names {}",
            buffer.format.name(),
            state.format.name()
        )));
    }
    if let Some(z) = state.clear {
        buffer.values.fill(state.format.store(z));
    }
    if let Some(v) = g.state.stencil.and_then(|s| s.clear) {
        buffer.stencil.fill(v);
    }
    Ok(Some((buffer, state)))
}

/// Every triangle through the pixel shader, in order, into `pass`.
#[allow(clippy::too_many_arguments)]
fn shade_all(
    list: &DrawList,
    compiled: &Compiled,
    d: &DrawStep,
    stage: &Stage,
    tris: &[(Shape, usize, usize)],
    clip_rect: Rect,
    samplers: &[(u32, emu::TextureLevels<'_>, emu::SamplerState)],
    settings: &Settings,
    limits: emu::EmuLimits,
    pass: &mut Pass,
) -> Result<Drawn, DrawFailure> {
    let mut slots = stage.slot_list();
    let fog = fog_state(list, d, stage)?;
    if fog.is_some_and(|f| f.mode == FogMode::Vertex || f.w) {
        // The fog factor (or table fog's w) rides along as one more input,
        // taken out again before the pixel shader sees them.
        slots.push((FOG_SLOT, stage.slots.len() + 1, [false; 4]));
    }
    let mut drawn = Drawn {
        gradients: compiled.sites.clone(),
        ..Drawn::default()
    };
    let mut pixels_left = settings.budget.max_pixels;
    for (k, (tri, provoking, _)) in tris.iter().enumerate() {
        if clip_rect.is_empty() {
            break;
        }
        // The window's quad grid is paid for before its values are computed.
        let Some(b) = tri.bounds(clip_rect) else {
            continue;
        };
        let side = |lo: u32, hi: u32| emu::PixelInputs::grid_width(hi - (lo & !1)) as u64;
        let grid = side(b.left, b.right) * side(b.top, b.bottom);
        pixels_left = pixels_left.checked_sub(grid).ok_or_else(|| {
            DrawFailure::Message(format!(
                "the draw's triangles cover more than {} pixels with their quads (raise it with --max-list-pixels)",
                settings.budget.max_pixels
            ))
        })?;
        let Some(mut window) = tri.pixels(clip_rect, &slots, &stage.values[*provoking]) else {
            continue;
        };
        let fog_values = match slots.last() {
            Some((FOG_SLOT, _, _)) => window.inputs.values.pop().map(|(_, v)| v),
            _ => None,
        };
        drawn.triangles += 1;
        let mut draw = Draw::new(window.width, window.height);
        draw.limits = limits;
        draw.limits.max_executed_total = limits.max_executed_total.saturating_sub(drawn.total);
        draw.record_lod = true;
        draw.count_instructions = pass
            .watch
            .as_deref()
            .is_some_and(Recorder::counts_instructions);
        draw.constants = d.constants.clone();
        draw.float_rules = d.pixel.float_rules.unwrap_or(settings.float_rules);
        draw.face = tri.face();
        draw.samplers = samplers.to_vec();
        draw.pixels = Some(&window.inputs);
        let threads = settings.threads.unwrap_or(0);
        let mut out = emu::run_with_threads(compiled, &draw, threads).map_err(|e| match e {
            EmuError::TotalExecutedLimit { .. } => DrawFailure::Emu(EmuError::TotalExecutedLimit {
                limit: limits.max_executed_total,
                pixels: u64::from(list.targets[d.target].width)
                    * u64::from(list.targets[d.target].height),
            }),
            e => DrawFailure::Emu(e),
        })?;
        for (i, &e) in out.executed.iter().enumerate() {
            if window.inputs.covered[i] {
                drawn.executed = Some(
                    drawn
                        .executed
                        .map_or((e, e), |(lo, hi)| (lo.min(e), hi.max(e))),
                );
            }
        }
        drawn.total = drawn
            .total
            .saturating_add(out.quad_executed.iter().sum::<u64>());
        crate::jobs::render::costs::add_sites(&mut drawn.gradients, &out.gradients);
        if let Some(w) = pass.watch.as_deref_mut() {
            let program = list.shaders[d.shader].loaded.shader.program();
            w.primitive(program, (k, tri, *provoking), &window, &out);
        }
        if let Some(f) = fog {
            fog_pixels(&mut out, &window, fog_values.as_deref(), &f);
        }
        pass.take(&window, &out, d.pixel.alpha_test, tri.face())?;
    }
    Ok(drawn)
}

/// The input slot number the fog factor borrows inside a window (no pixel
/// shader has one so high).
const FOG_SLOT: u32 = u32::MAX;

/// The draw's fog, if its pixel shader takes fixed-function fog (below
/// ps_3_0), or an error where vertex fog has no factor to read.
fn fog_state(list: &DrawList, d: &DrawStep, stage: &Stage) -> Result<Option<Fog>, DrawFailure> {
    let Some(geometry) = &d.geometry else {
        return Ok(None);
    };
    let Some(fog) = geometry.state.fog else {
        return Ok(None);
    };
    let profile = list.shaders[d.shader].loaded.shader.program().profile;
    if profile == crate::core::profile::Profile::Ps3_0 {
        return Ok(None);
    }
    if fog.mode == FogMode::Vertex && !stage.fog_given {
        return Err(DrawFailure::Message(
            "geometry.fog: vertex fog (mode \"vertex\") reads the vertex shader's oFog (dcl_fog) or else its specular alpha (oD1.w), or without a vertex shader the vertices' color1 alpha, and the draw gives none of them".into(),
        ));
    }
    Ok(Some(fog))
}

/// Fogs oC0 of the window's covered pixels: by the interpolated vertex
/// factor or w (`factors`, over the window's quad grid) or the pixel's z.
fn fog_pixels(
    out: &mut DrawOutput,
    window: &raster::triangle::Window,
    factors: Option<&[[f32; 4]]>,
    fog: &Fog,
) {
    let Some(Some(colors)) = out.color.first_mut() else {
        return;
    };
    let grid = emu::PixelInputs::grid_width(window.width);
    for (i, c) in colors.iter_mut().enumerate() {
        if !window.inputs.covered[i] {
            continue;
        }
        let (x, y) = (i % window.width as usize, i / window.width as usize);
        let d = match factors {
            Some(v) => f64::from(v[y * grid + x][0]),
            None => window.depth[i],
        };
        *c = fog.blend(*c, fog.factor(d));
    }
}
