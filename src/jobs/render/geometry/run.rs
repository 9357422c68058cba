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

use super::{DepthState, Geometry};
use crate::core::emu::vertex::{self, Attribute, VertexDraw};
use crate::core::emu::{self, Compiled, Draw, DrawOutput, EmuError, GradientSite};
use crate::core::ir::Program;
use crate::core::isa::RegFile;
use crate::core::merge::{self, MergeStats, OutputState};
use crate::core::raster::clip::{self, ClipVertex, VIEW_VOLUME};
use crate::core::raster::depth::DepthFormat;
use crate::core::raster::{self, Rect, ScreenVertex, Triangle, Viewport};
use crate::jobs::render::history::{self, Recorder, Verdict};
use crate::jobs::render::{DrawFailure, DrawList, DrawStep, Settings, TargetState};

/// A target's depth-stencil surface: one stored depth per pixel.
#[derive(Clone, Debug, PartialEq)]
pub struct DepthBuffer {
    /// Its format (what every stored value is rounded to).
    pub format: DepthFormat,
    /// Stored depths, row-major.
    pub values: Vec<f64>,
}

/// What a geometry draw did, for its step's report.
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
    values: Vec<Vec<[f64; 4]>>,
    transformed: bool,
    slots: Vec<Slot>,
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
        let values = (0..n)
            .map(|v| {
                wanted
                    .iter()
                    .map(|(_, a)| attr(a).map_or([0.0; 4], |vals| widen(vals[v])))
                    .collect()
            })
            .collect();
        return Ok(Stage {
            positions: pos.iter().map(|p| widen(*p)).collect(),
            values,
            transformed,
            slots,
        });
    };
    let shader = &list.shaders[vs].loaded.shader;
    let draw = VertexDraw {
        constants: g.vertex_constants.clone(),
        samplers: super::super::bind_samplers(list, d, &g.vertex_samplers, states)?,
        float_rules,
        ..VertexDraw::default()
    };
    let out = vertex::run(shader, &draw, &g.vertices)
        .map_err(|e| DrawFailure::Message(format!("vertex shader: {e}")))?;
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
    Ok(Stage {
        positions: out.values.iter().map(|v| widen(v[position])).collect(),
        values: out
            .values
            .iter()
            .map(|v| {
                columns
                    .iter()
                    .map(|c| c.map_or([0.0; 4], |c| widen(v[c])))
                    .collect()
            })
            .collect(),
        transformed: false,
        slots,
    })
}

/// The screen triangles of the draw, each with its provoking vertex, in
/// drawing order: assembled, clipped (positions in clip space), divided,
/// mapped through the viewport, culled.
fn triangles(
    g: &Geometry,
    stage: &Stage,
    viewport: &Viewport,
) -> Result<Vec<(Triangle, usize)>, String> {
    let order: Vec<usize> = match &g.indices {
        Some(ix) => ix.iter().map(|&i| i as usize).collect(),
        None => (0..stage.positions.len()).collect(),
    };
    let planes: Vec<[f64; 4]> = VIEW_VOLUME.iter().chain(&g.clip_planes).copied().collect();
    let screen = |pos: [f64; 4], values: Vec<[f64; 4]>| {
        let [x, y, z, rhw] = if stage.transformed {
            pos
        } else {
            viewport.to_screen(pos)
        };
        ScreenVertex {
            x,
            y,
            z,
            rhw,
            values,
        }
    };
    let mut out = Vec::new();
    for prim in raster::assemble(g.primitive, order.len())? {
        let [a, b, c] = prim.corners.map(|i| order[i]);
        let provoking = order[prim.provoking];
        if g.primitive == raster::Primitive::PointList {
            let p = stage.positions[a];
            if !stage.transformed && !clip::inside(&planes, &p) {
                continue;
            }
            let centre = screen(p, stage.values[a].clone());
            let h = g.point_size / 2.0;
            let corner = |dx: f64, dy: f64| ScreenVertex {
                x: centre.x + dx,
                y: centre.y + dy,
                ..centre.clone()
            };
            let (tl, tr, bl, br) = (corner(-h, -h), corner(h, -h), corner(-h, h), corner(h, h));
            out.extend(Triangle::new(tl, tr.clone(), bl.clone()).map(|t| (t, provoking)));
            out.extend(Triangle::new(tr, br, bl).map(|t| (t, provoking)));
            continue;
        }
        let corners = [a, b, c].map(|i| ClipVertex {
            pos: stage.positions[i],
            values: stage.values[i].clone(),
        });
        let polygon = if stage.transformed {
            corners.to_vec()
        } else {
            clip::clip(corners.to_vec(), &planes)
        };
        let on_screen: Vec<ScreenVertex> = polygon
            .into_iter()
            .map(|v| screen(v.pos, v.values))
            .collect();
        for i in 1..on_screen.len().saturating_sub(1) {
            let t = Triangle::new(
                on_screen[0].clone(),
                on_screen[i].clone(),
                on_screen[i + 1].clone(),
            );
            if let Some(t) = t.filter(|t| !g.cull.drops(t.face)) {
                out.push((t, provoking));
            }
        }
    }
    Ok(out)
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

    /// Takes one triangle's shaded pixels through the alpha and depth
    /// tests into the pending colours.
    fn take(
        &mut self,
        window: &raster::triangle::Window,
        out: &DrawOutput,
        alpha: Option<super::super::pixel_state::AlphaTest>,
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
            let verdict = self.test(window, out, alpha, (i, t));
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
    /// Pixel `i` of the window (`t` of the target) through `texkill`, the
    /// alpha test and the depth test, in Direct3D 9's order, writing its
    /// depth where it passes; the first test that fails ends it.
    fn test(
        &mut self,
        window: &raster::triangle::Window,
        out: &DrawOutput,
        alpha: Option<super::super::pixel_state::AlphaTest>,
        (i, t): (usize, usize),
    ) -> Verdict {
        let mut verdict = Verdict {
            killed: out.killed[i],
            alpha: None,
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
        if let Some((buffer, state)) = &mut self.depth {
            let z = out
                .depth
                .as_ref()
                .map_or(window.depth[i], |d| f64::from(d[i]));
            let z = buffer.format.store(z);
            let stored = buffer.values[t];
            let passed = state.func.passes(z, stored);
            if passed && state.write {
                buffer.values[t] = z;
            }
            verdict.depth = Some(history::DepthTest {
                z,
                odepth: out.depth.is_some(),
                stored,
                func: state.func,
                passed,
                written: passed && state.write,
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
    if !matches!(settings.backend, crate::jobs::backend::Backend::Emulator) {
        return Err(DrawFailure::Message(
            "draws of geometry run on the emulator only (the GPU backend draws full-screen quads)"
                .into(),
        ));
    }
    let spec = &list.targets[d.target];
    let (width, height) = (spec.width, spec.height);
    let float_rules = d.pixel.float_rules.unwrap_or(settings.float_rules);
    let stage = vertex_stage(list, g, d, float_rules, states)?;
    let viewport = g.viewport.unwrap_or_else(|| Viewport::whole(width, height));
    let tris = triangles(g, &stage, &viewport).map_err(DrawFailure::Message)?;
    let mut clip_rect = viewport.rect().intersect(Rect {
        left: 0,
        top: 0,
        right: width,
        bottom: height,
    });
    if let Some(s) = g.scissor {
        clip_rect = clip_rect.intersect(s);
    }
    if let Some(w) = watch.as_deref_mut() {
        // The triangles the cull mode dropped, to say why a pixel was missed.
        let all = Geometry {
            cull: raster::Cull::None,
            ..g.clone()
        };
        let culled: Vec<Triangle> = triangles(&all, &stage, &viewport)
            .map_err(DrawFailure::Message)?
            .into_iter()
            .map(|(t, _)| t)
            .filter(|t| g.cull.drops(t.face))
            .collect();
        w.geometry(&tris, &culled, viewport.rect(), g.scissor);
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
            pending: Pending {
                colors: vec![vec![[0.0; 4]; n]; 4],
                held: vec![false; n],
                any: false,
                wrote: [false; 4],
            },
            merged: MergeStats::default(),
            watch,
        };
        let drawn = shade_all(
            list, compiled, d, &stage, &tris, clip_rect, &samplers, settings, limits, &mut pass,
        )?;
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
    Ok(Some((buffer, state)))
}

/// Every triangle through the pixel shader, in order, into `pass`.
#[allow(clippy::too_many_arguments)]
fn shade_all(
    list: &DrawList,
    compiled: &Compiled,
    d: &DrawStep,
    stage: &Stage,
    tris: &[(Triangle, usize)],
    clip_rect: Rect,
    samplers: &[(u32, emu::TextureLevels<'_>, emu::SamplerState)],
    settings: &Settings,
    limits: emu::EmuLimits,
    pass: &mut Pass,
) -> Result<Drawn, DrawFailure> {
    let slots: Vec<(u32, usize, [bool; 4])> = stage
        .slots
        .iter()
        .enumerate()
        .map(|(k, s)| (s.slot, k, s.flat))
        .collect();
    let mut drawn = Drawn {
        merged: MergeStats::default(),
        executed: None,
        total: 0,
        gradients: compiled.sites.clone(),
        triangles: 0,
    };
    let mut pixels_left = settings.budget.max_pixels;
    for (k, (tri, provoking)) in tris.iter().enumerate() {
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
        let Some(window) = tri.pixels(clip_rect, &slots, &stage.values[*provoking]) else {
            continue;
        };
        drawn.triangles += 1;
        let mut draw = Draw::new(window.width, window.height);
        draw.limits = limits;
        draw.limits.max_executed_total = limits.max_executed_total.saturating_sub(drawn.total);
        draw.record_lod = true;
        draw.constants = d.constants.clone();
        draw.float_rules = d.pixel.float_rules.unwrap_or(settings.float_rules);
        draw.face = tri.face;
        draw.samplers = samplers.to_vec();
        draw.pixels = Some(&window.inputs);
        let threads = settings.threads.unwrap_or(0);
        let out = emu::run_with_threads(compiled, &draw, threads).map_err(|e| match e {
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
        add_sites(&mut drawn.gradients, &out.gradients);
        if let Some(w) = pass.watch.as_deref_mut() {
            let program = list.shaders[d.shader].loaded.shader.program();
            w.primitive(program, (k, tri, *provoking), &window, &out);
        }
        pass.take(&window, &out, d.pixel.alpha_test)?;
    }
    Ok(drawn)
}

/// Adds one triangle's gradient sites to the draw's.
fn add_sites(into: &mut [GradientSite], from: &[GradientSite]) {
    for (g, b) in into.iter_mut().zip(from) {
        g.quads += b.quads;
        g.divergent_quads += b.divergent_quads;
        g.executions += b.executions;
        g.divergent_executions += b.divergent_executions;
        if let Some((lo, hi)) = b.lod {
            g.lod = Some(g.lod.map_or((lo, hi), |(a, c)| (a.min(lo), c.max(hi))));
        }
    }
}
