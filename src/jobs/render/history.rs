//! One pixel's history through a draw list: "debug this pixel". For a
//! watched pixel of a target, every step that changes the target says
//! what happened there — a clear's colour; for a draw, each primitive
//! whose quads reached the pixel (its corners on screen and the pixel's
//! barycentric weights, whether the pixel was covered or ran as a helper
//! of its 2×2 quad), the pixel shader's inputs as the set-up handed them
//! over (`v#`/`t#`, `vPos`, `vFace`), its outputs (`oC#`, `oDepth`) and
//! executed slots, then in Direct3D 9's order `texkill` (or a full-screen
//! draw's clip plane), the alpha test, the depth test with the incoming
//! and stored depths and whether it wrote, and the blend with its source,
//! destination, factors and result — and why a draw that changed the
//! target did not reach the pixel (outside the viewport, scissored,
//! clipped by the view volume or a user clip plane, culled, outside every
//! primitive); a primitive clipping removed over the pixel is named even
//! where others reached it.
//!
//! The runner ([`super::run_with_history`]) calls a [`Recorder`] at a few
//! places: around each step, after a full-screen draw's shader, after
//! each triangle's shader, at each of a geometry draw's per-pixel tests,
//! and around each merge into a target. Each call looks at the watched
//! pixels only, so a run with no pixel watched (`None`) does no more than
//! test an `Option` per step, triangle and covered pixel.

use super::costs::DrawCosts;
use super::pixel_state::{AlphaTest, CmpFunc, PixelState};
use super::{DrawList, Step, TargetState};
use crate::core::emu::{Draw, DrawOutput, PixelInputs};
use crate::core::image::RenderTarget;
use crate::core::ir::Program;
use crate::core::isa::RegFile;
use crate::core::merge::{OutputState, Terms};
use crate::core::raster::stencil::StencilOutcome;
use crate::core::raster::triangle::{Triangle, Window};
use crate::core::raster::{Face, Rect, Shape};
use serde::Serialize;

/// A pixel to watch: a target of the list and a pixel of it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Pixel {
    /// Index into [`DrawList::targets`].
    pub target: usize,
    /// Column.
    pub x: u32,
    /// Row.
    pub y: u32,
}

/// One pixel's history: every step that changed its target.
#[derive(Clone, Debug, Serialize)]
pub struct History {
    /// The target's name.
    pub target: String,
    /// Column.
    pub x: u32,
    /// Row.
    pub y: u32,
    /// The target's D3D9 format.
    pub format: &'static str,
    /// The steps that clear, reduce or draw into the target, in order.
    pub steps: Vec<StepHistory>,
    /// The pixel's value at the end, as the target stores it.
    pub last: [f32; 4],
}

/// What one step did at the pixel.
#[derive(Clone, Debug, Serialize)]
pub struct StepHistory {
    /// The step's index in the list.
    pub step: usize,
    /// `clear`, `draw` or `mips`.
    pub kind: &'static str,
    /// A draw's pixel shader.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub shader: Option<String>,
    /// The draw's output that reaches this target (0 for oC0, its own
    /// target; 1–3 for oC1–oC3 bound by `outputs`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub output: Option<usize>,
    /// Whether the draw carries geometry (otherwise a full-screen quad).
    pub geometry: bool,
    /// The blend state and write mask of a draw.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub merger: Option<OutputState>,
    /// Each primitive that ran the shader at the pixel, in drawing order.
    pub fragments: Vec<Fragment>,
    /// Why a draw reached the pixel with no primitive, when the set-up
    /// knows (`None` otherwise, and for clears and reductions).
    pub missed: Option<String>,
    /// The draw's primitives that lie over the pixel where clipping (the
    /// view volume or a user clip plane) removed them.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub clipped: Vec<ClippedAt>,
    /// The pixel before the step.
    pub before: [f32; 4],
    /// The pixel after it.
    pub after: [f32; 4],
}

/// The primitive a fragment came from.
#[derive(Clone, Debug, Serialize)]
pub struct PrimitiveAt {
    /// The triangle's or line's index among those that reached the pixel
    /// shader (after assembly, clipping and culling; a point is two
    /// triangles), from 0.
    pub index: usize,
    /// `front` (clockwise on screen) or `back`; a line is `front`.
    pub face: &'static str,
    /// The corners on screen (three for a triangle, clockwise; two for a
    /// line, in drawing order): x, y, z and 1/w.
    pub corners: Vec<[f64; 4]>,
    /// The pixel centre's screen weights of the corners (a line's third
    /// is 0).
    pub weights: [f64; 3],
    /// The vertex flat shading takes colours from.
    pub provoking: usize,
}

/// A primitive that would have covered the pixel, but clipping removed
/// its part over the pixel.
#[derive(Clone, Debug, Serialize)]
pub struct ClippedAt {
    /// `triangle`, `line` or `point`.
    pub kind: &'static str,
    /// Its index among the draw's primitives as assembled (before
    /// clipping and culling), from 0.
    pub primitive: usize,
    /// Its vertices, by their index in the vertex buffer.
    pub vertices: Vec<usize>,
    /// The clip-space (x, y, z, w) of its point over the pixel (a point's
    /// own vertex).
    pub position: [f64; 4],
    /// The planes that point lies beyond: `near plane (z < 0)`, `far plane
    /// (z > w)`, `user clip plane K` (K counts the draw's `clip_planes`),
    /// and for a point, dropped whole by its vertex, the `left`, `right`,
    /// `bottom` and `top` planes.
    pub planes: Vec<String>,
}

/// A register's value.
#[derive(Clone, Debug, Serialize)]
pub struct Named {
    /// `v0`, `t1`, `vPos`, `vFace`, `oC0`, `oDepth`.
    pub register: String,
    /// Its four components (`oDepth` and `vFace` repeat theirs).
    pub value: [f32; 4],
}

/// One run of the pixel shader at the pixel, and what became of it.
#[derive(Clone, Debug, Serialize)]
pub struct Fragment {
    /// The triangle (a draw of geometry); `None` for a full-screen quad.
    pub primitive: Option<PrimitiveAt>,
    /// The pixel ran as a helper: its quad held a covered pixel and it
    /// did not; its values fed the quad's gradients and nothing more.
    pub helper: bool,
    /// Covered pixels of its 2×2 quad (1–4; a full-screen quad's pixels
    /// inside the target).
    pub quad_covered: u32,
    /// The shader's inputs as the set-up interpolated them (ps_2_x's
    /// colours are then clamped to [0, 1] on entry).
    pub inputs: Vec<Named>,
    /// The shader's outputs (none for a helper).
    pub outputs: Vec<Named>,
    /// Executed instruction slots (none for a helper).
    pub executed: Option<u64>,
    /// `texkill` discarded it.
    pub killed: bool,
    /// A full-screen draw's user clip plane that removed it (index).
    pub clip_plane: Option<usize>,
    /// The alpha test (D3DRS_ALPHATESTENABLE), if on and reached.
    pub alpha_test: Option<AlphaVerdict>,
    /// The stencil test (D3DRS_STENCILENABLE), if on and reached: the
    /// value stored before, whether it passed, whether the depth test
    /// then passed, the operation taken and the value written.
    pub stencil: Option<StencilOutcome>,
    /// The depth test (D3DRS_ZENABLE), if on and reached.
    pub depth: Option<DepthVerdict>,
    /// The blend into the target, if the fragment got there.
    pub blend: Option<BlendVerdict>,
    /// Where it ended: `written`, `helper`, `killed`, `clipped`,
    /// `alpha_test`, `stencil_test`, `depth_test`, `no_output` (the shader wrote nothing
    /// to this target's output).
    pub fate: &'static str,
}

/// The alpha test at the pixel.
#[derive(Clone, Debug, Serialize)]
pub struct AlphaVerdict {
    /// oC0's alpha.
    pub alpha: f32,
    /// The alpha as the test compared it: at the target's precision (an
    /// integer on 8-bit and half targets, the float itself on 32-bit ones).
    pub code: f64,
    /// D3DRS_ALPHAFUNC.
    pub func: String,
    /// D3DRS_ALPHAREF.
    pub reference: u8,
    /// Whether the pixel survived.
    pub passed: bool,
}

/// The depth test at the pixel.
#[derive(Clone, Debug, Serialize)]
pub struct DepthVerdict {
    /// The incoming depth as the format stores it.
    pub z: f64,
    /// Where it came from: `interpolated` or `oDepth`.
    pub from: &'static str,
    /// The depth stored before the test.
    pub stored: f64,
    /// D3DRS_ZFUNC.
    pub func: String,
    /// Whether `z FUNC stored` held.
    pub passed: bool,
    /// Whether the depth was written (passed, with D3DRS_ZWRITEENABLE).
    pub written: bool,
}

/// The output merger at the pixel.
#[derive(Clone, Debug, Serialize)]
pub struct BlendVerdict {
    /// The shader's colour.
    pub source: [f32; 4],
    /// The texel before.
    pub dest: [f32; 4],
    /// The blend's terms; `None` with blending off.
    pub terms: Option<Terms>,
    /// The texel after, write mask applied.
    pub result: [f32; 4],
}

/// A geometry draw's verdict on one covered pixel, from `texkill` to the
/// depth test, as its per-pixel loop reached it.
pub(crate) struct Verdict {
    /// `texkill` discarded it.
    pub killed: bool,
    /// oC0's alpha and whether it passed the alpha test (`None`: not tested).
    pub alpha: Option<(f32, bool)>,
    /// The stencil test and its write (`None`: not tested).
    pub stencil: Option<StencilOutcome>,
    /// The depth test (`None`: not tested).
    pub depth: Option<DepthTest>,
}

/// A geometry draw's depth test at one pixel, as its loop computed it
/// (plain data: the loop makes one per covered pixel).
#[derive(Clone, Copy)]
pub(crate) struct DepthTest {
    /// The incoming depth as the format stores it.
    pub z: f64,
    /// It came from `oDepth` (else interpolated).
    pub odepth: bool,
    /// The depth stored before.
    pub stored: f64,
    /// D3DRS_ZFUNC.
    pub func: CmpFunc,
    /// Whether `z FUNC stored` held.
    pub passed: bool,
    /// Whether the depth was written.
    pub written: bool,
}

impl Verdict {
    /// Whether the pixel goes on to the output merger.
    pub fn passed(&self) -> bool {
        !self.killed
            && self.alpha.is_none_or(|(_, p)| p)
            && self.stencil.is_none_or(|s| s.passed)
            && self.depth.is_none_or(|d| d.passed)
    }
}

/// A watched pixel while the list runs.
struct Watch {
    pixel: Pixel,
    width: u32,
    history: History,
    /// The output of the running draw that reaches the pixel's target.
    output: Option<usize>,
    alpha_test: Option<AlphaTest>,
    /// The last fragment waits for a geometry draw's tests.
    testing: bool,
    /// The running triangle's shader wrote the output reaching the target.
    wrote: bool,
    /// The fragment (index in the running step's) waiting for its merge:
    /// a triangle's colours are merged when a later triangle reaches a
    /// pixel they hold, so the next one may already be under test.
    merging: Option<usize>,
}

impl Watch {
    fn index(&self) -> usize {
        self.pixel.y as usize * self.width as usize + self.pixel.x as usize
    }

    fn step(&mut self) -> Option<&mut StepHistory> {
        self.history.steps.last_mut()
    }

    fn fragment(&mut self) -> Option<&mut Fragment> {
        self.history.steps.last_mut()?.fragments.last_mut()
    }

    fn merging(&mut self) -> Option<&mut Fragment> {
        let k = self.merging?;
        self.history.steps.last_mut()?.fragments.get_mut(k)
    }

    fn fragments(&self) -> usize {
        self.history.steps.last().map_or(0, |s| s.fragments.len())
    }
}

/// Records the history of watched pixels while a list runs, and, asked
/// to, what one draw's pixel shader cost ([`Recorder::with_costs`]).
pub struct Recorder {
    watches: Vec<Watch>,
    /// Steps the watched targets saw begun and not yet ended.
    open: bool,
    costs: Option<DrawCosts>,
}

/// vPos and vFace as the set-up gives them, where `program` declares them.
fn position_and_face(program: &Program, x: u32, y: u32, face: f32) -> Vec<Named> {
    let declares = |file: RegFile| program.inputs.iter().any(|d| d.reg.file == file);
    let mut out = Vec::new();
    if declares(RegFile::Position) {
        out.push(Named {
            register: "vPos".into(),
            value: [x as f32, y as f32, 0.0, 0.0],
        });
    }
    if declares(RegFile::Face) {
        out.push(Named {
            register: "vFace".into(),
            value: [face; 4],
        });
    }
    out
}

/// The shader's outputs at pixel `i` of its draw.
fn outputs(out: &DrawOutput, i: usize) -> Vec<Named> {
    let mut v: Vec<Named> = out
        .color
        .iter()
        .enumerate()
        .filter_map(|(k, c)| {
            c.as_ref().map(|c| Named {
                register: format!("oC{k}"),
                value: c[i],
            })
        })
        .collect();
    if let Some(d) = &out.depth {
        v.push(Named {
            register: "oDepth".into(),
            value: [d[i]; 4],
        });
    }
    v
}

fn cmp_name(f: CmpFunc) -> String {
    // The variants are D3DCMP_ names in another case.
    format!("{f:?}").to_uppercase()
}

fn rect_text(r: &Rect) -> String {
    format!("[{}, {}, {}, {}]", r.left, r.top, r.right, r.bottom)
}

fn inside(r: &Rect, x: u32, y: u32) -> bool {
    (r.left..r.right).contains(&x) && (r.top..r.bottom).contains(&y)
}

impl Recorder {
    /// A recorder of `pixels` of `list`'s targets; an error names a pixel
    /// outside its target.
    pub fn new(list: &DrawList, pixels: &[Pixel]) -> Result<Recorder, String> {
        let mut watches = Vec::with_capacity(pixels.len());
        for &p in pixels {
            let t = list
                .targets
                .get(p.target)
                .ok_or_else(|| format!("no target {}", p.target))?;
            if p.x >= t.width || p.y >= t.height {
                return Err(format!(
                    "pixel ({}, {}) is outside `{}`, which is {}×{}",
                    p.x, p.y, t.name, t.width, t.height
                ));
            }
            watches.push(Watch {
                pixel: p,
                width: t.width,
                history: History {
                    target: t.name.clone(),
                    x: p.x,
                    y: p.y,
                    format: t.format.d3d_name(),
                    steps: Vec::new(),
                    last: [0.0; 4],
                },
                output: None,
                alpha_test: None,
                testing: false,
                wrote: false,
                merging: None,
            });
        }
        Ok(Recorder {
            watches,
            open: false,
            costs: None,
        })
    }

    /// Also gathers the costs of draw step `step`'s pixel shader over
    /// every primitive's quads (`ps30 profile --list`).
    pub fn with_costs(mut self, step: usize) -> Recorder {
        self.costs = Some(DrawCosts::new(step));
        self
    }

    /// Whether the step running now is the one whose costs are gathered:
    /// its draws count what ran each instruction
    /// ([`crate::core::emu::Draw::count_instructions`]).
    pub fn counts_instructions(&self) -> bool {
        self.costs.as_ref().is_some_and(|c| c.active)
    }

    /// The costs gathered ([`Recorder::with_costs`]).
    pub fn costs(&self) -> Option<&DrawCosts> {
        self.costs.as_ref()
    }

    /// The histories, one per watched pixel in the order given.
    pub fn histories(self) -> Vec<History> {
        self.watches.into_iter().map(|w| w.history).collect()
    }

    /// Step `index` is about to run over `states`.
    pub(crate) fn begin_step(&mut self, list: &DrawList, index: usize, states: &[TargetState]) {
        if let Some(c) = &mut self.costs {
            c.active = c.step == index;
        }
        let step = &list.steps[index];
        for w in &mut self.watches {
            let t = w.pixel.target;
            let (kind, output, shader, geometry, merger) = match step {
                Step::Clear { target, .. } if *target == t => ("clear", None, None, false, None),
                Step::Mips { target, .. } if *target == t => ("mips", None, None, false, None),
                Step::Draw(d) => {
                    let k = if d.target == t {
                        Some(0)
                    } else {
                        d.pixel
                            .outputs
                            .iter()
                            .position(|o| o.is_some_and(|(u, _)| u == t))
                            .map(|k| k + 1)
                    };
                    let Some(k) = k else { continue };
                    let write = match k {
                        0 => d.output.write,
                        _ => d.pixel.outputs[k - 1].map_or(d.output.write, |(_, w)| w),
                    };
                    let merger = OutputState {
                        blend: d.output.blend,
                        write,
                    };
                    w.alpha_test = d.pixel.alpha_test;
                    let name = list.shaders[d.shader].name.clone();
                    (
                        "draw",
                        Some(k),
                        Some(name),
                        d.geometry.is_some(),
                        Some(merger),
                    )
                }
                _ => continue,
            };
            w.output = output;
            w.testing = false;
            w.merging = None;
            let before = states[t].target.texels[w.index()];
            w.history.steps.push(StepHistory {
                step: index,
                kind,
                shader,
                output,
                geometry,
                merger,
                fragments: Vec::new(),
                missed: None,
                clipped: Vec::new(),
                before,
                after: before,
            });
            self.open = true;
        }
    }

    /// The step begun last has run; `states` are the targets after it.
    pub(crate) fn end_step(&mut self, index: usize, states: &[TargetState]) {
        if let Some(c) = &mut self.costs {
            c.active = false;
        }
        if !self.open {
            return;
        }
        for w in &mut self.watches {
            let value = states[w.pixel.target].target.texels[w.index()];
            w.history.last = value;
            if let Some(s) = w.history.steps.last_mut().filter(|s| s.step == index) {
                s.after = value;
                if !s.fragments.is_empty() {
                    s.missed = None;
                }
            }
            w.output = None;
            w.testing = false;
            w.merging = None;
        }
        self.open = false;
    }

    /// A full-screen draw's shader has run (`out`, before the alpha test
    /// and clip planes mark it): the pixel's inputs, outputs and tests.
    pub(crate) fn full_screen(
        &mut self,
        program: &Program,
        draw: &Draw,
        out: &DrawOutput,
        pixel: &PixelState,
    ) {
        if let Some(c) = self.costs.as_mut().filter(|c| c.active) {
            c.add(None, out);
        }
        for w in self.watches.iter_mut().filter(|w| w.output.is_some()) {
            let (x, y) = (w.pixel.x, w.pixel.y);
            let i = w.index();
            let mut inputs: Vec<Named> = draw
                .inputs
                .iter()
                .map(|(slot, input)| Named {
                    register: crate::core::pixel_inputs::name(program.profile, *slot),
                    value: input.at(x as f32, y as f32),
                })
                .collect();
            inputs.extend(position_and_face(program, x, y, draw.face.value()));
            // The distance as the draw list evaluates it (`PixelState::apply`).
            let clip_plane = pixel
                .clip_planes
                .iter()
                .position(|p| p[0] + x as f32 * p[1] + y as f32 * p[2] < 0.0);
            let killed = out.killed.get(i).copied().unwrap_or(false);
            let oc0 = out.color.first().and_then(|c| c.as_ref()).map(|c| c[i]);
            let alpha = match (killed || clip_plane.is_some(), w.alpha_test, oc0) {
                (false, Some(a), Some(c)) => Some((c[3], a.passes(c[3]))),
                _ => None,
            };
            let written = out
                .color
                .get(w.output.unwrap_or(0))
                .is_some_and(Option::is_some);
            let fate = if killed {
                "killed"
            } else if clip_plane.is_some() {
                "clipped"
            } else if alpha.is_some_and(|(_, p)| !p) {
                "alpha_test"
            } else if !written {
                "no_output"
            } else {
                "written"
            };
            w.merging = (fate == "written").then(|| w.fragments());
            let quad_covered = [(0, 0), (1, 0), (0, 1), (1, 1)]
                .iter()
                .filter(|(dx, dy)| {
                    (x & !1) + dx < draw.target_width && (y & !1) + dy < draw.target_height
                })
                .count() as u32;
            let fragment = Fragment {
                primitive: None,
                helper: false,
                quad_covered,
                inputs,
                outputs: outputs(out, i),
                // A GPU counts nothing.
                executed: out.executed.get(i).copied(),
                killed,
                clip_plane,
                alpha_test: alpha.map(|(a, passed)| alpha_verdict(w.alpha_test, a, passed)),
                stencil: None,
                depth: None,
                blend: None,
                fate,
            };
            if let Some(s) = w.step() {
                s.fragments.push(fragment);
            }
        }
    }

    /// A draw of geometry is set up: its triangles in order, the ones its
    /// cull mode dropped, the rectangles pixels must lie in, and what
    /// clipping removed over a pixel.
    pub(crate) fn geometry(
        &mut self,
        reached: usize,
        culled: &[Triangle],
        (viewport, scissor): (Rect, Option<Rect>),
        clipped: &dyn Fn(u32, u32) -> Vec<ClippedAt>,
    ) {
        for w in self.watches.iter_mut().filter(|w| w.output.is_some()) {
            let (x, y) = (w.pixel.x, w.pixel.y);
            let (fx, fy) = (f64::from(x), f64::from(y));
            let within = inside(&viewport, x, y) && scissor.is_none_or(|s| inside(&s, x, y));
            let lost = if within { clipped(x, y) } else { Vec::new() };
            let missed = if !inside(&viewport, x, y) {
                format!("outside the viewport {}", rect_text(&viewport))
            } else if let Some(s) = scissor.filter(|s| !inside(s, x, y)) {
                format!("scissored (the rectangle is {})", rect_text(&s))
            } else if let Some(c) = lost.first() {
                format!(
                    "clipped: {} {} lies over it beyond the {}",
                    c.kind,
                    c.primitive,
                    c.planes.join(" and the ")
                )
            } else if let Some(t) = culled.iter().find(|t| t.covers(fx, fy)) {
                let face = match t.face {
                    crate::core::raster::Face::Front => "front (clockwise)",
                    crate::core::raster::Face::Back => "back (counter-clockwise)",
                };
                format!("culled: the triangle over it is a {face} face")
            } else {
                format!(
                    "outside every primitive ({} reached the pixel shader)",
                    reached
                )
            };
            if let Some(s) = w.step() {
                s.missed = Some(missed);
                s.clipped = lost;
            }
        }
    }

    /// Triangle `index` has run the shader over its window: the pixel's
    /// fragment, if one of its quads reached the pixel.
    pub(crate) fn primitive(
        &mut self,
        program: &Program,
        (index, shape, provoking): (usize, &Shape, usize),
        window: &Window,
        out: &DrawOutput,
    ) {
        if let Some(c) = self.costs.as_mut().filter(|c| c.active) {
            c.add(Some(&window.inputs.covered), out);
        }
        for w in self.watches.iter_mut().filter(|w| w.output.is_some()) {
            let Some(fragment) =
                fragment_at(program, w.pixel, (index, shape, provoking), window, out)
            else {
                continue;
            };
            w.testing = !fragment.helper;
            w.wrote = w
                .output
                .is_some_and(|k| out.color.get(k).is_some_and(Option::is_some));
            if let Some(s) = w.step() {
                s.fragments.push(fragment);
            }
        }
    }

    /// A geometry draw's tests reached pixel `t` (row-major in the draw's
    /// targets) with `verdict`.
    pub(crate) fn verdict(&mut self, t: usize, verdict: &Verdict) {
        for w in self.watches.iter_mut().filter(|w| w.output.is_some()) {
            if w.index() != t || !w.testing {
                continue;
            }
            w.testing = false;
            let test = w.alpha_test;
            let passed = verdict.passed();
            let wrote = w.wrote;
            let Some(f) = w.fragment() else { continue };
            f.killed = verdict.killed;
            f.alpha_test = verdict.alpha.map(|(a, p)| alpha_verdict(test, a, p));
            f.stencil = verdict.stencil;
            f.depth = verdict.depth.map(|d| DepthVerdict {
                z: d.z,
                from: if d.odepth { "oDepth" } else { "interpolated" },
                stored: d.stored,
                func: cmp_name(d.func),
                passed: d.passed,
                written: d.written,
            });
            f.fate = if verdict.killed {
                "killed"
            } else if verdict.alpha.is_some_and(|(_, p)| !p) {
                "alpha_test"
            } else if verdict.stencil.is_some_and(|s| !s.passed) {
                "stencil_test"
            } else if !passed {
                "depth_test"
            } else if !wrote {
                "no_output"
            } else {
                "written"
            };
            let written = f.fate == "written";
            if written {
                w.merging = Some(w.fragments() - 1);
            }
        }
    }

    /// Output `k`'s colours `colors` (row-major over the target) are about
    /// to be merged into `target`.
    pub(crate) fn before_merge(&mut self, k: usize, target: &RenderTarget, colors: &[[f32; 4]]) {
        for w in self
            .watches
            .iter_mut()
            .filter(|w| w.merging.is_some() && w.output == Some(k))
        {
            let i = w.index();
            let (source, dest) = (colors[i], target.texels[i]);
            let merger = w.step().and_then(|s| s.merger).unwrap_or_default();
            let terms = merger.blend.terms(target.format, source, dest);
            if let Some(f) = w.merging() {
                f.blend = Some(BlendVerdict {
                    source,
                    dest,
                    terms,
                    result: dest,
                });
            }
        }
    }

    /// Output `k` has been merged into `target`.
    pub(crate) fn after_merge(&mut self, k: usize, target: &RenderTarget) {
        for w in self
            .watches
            .iter_mut()
            .filter(|w| w.merging.is_some() && w.output == Some(k))
        {
            let value = target.texels[w.index()];
            if let Some(b) = w.merging().and_then(|f| f.blend.as_mut()) {
                b.result = value;
            }
            w.merging = None;
        }
    }
}

fn alpha_verdict(test: Option<AlphaTest>, alpha: f32, passed: bool) -> AlphaVerdict {
    let test = test.unwrap_or(AlphaTest {
        func: CmpFunc::Always,
        reference: 0,
        precision: super::pixel_state::AlphaPrecision::Fixed(8),
    });
    AlphaVerdict {
        alpha,
        code: f64::from(test.compared(alpha).0),
        func: cmp_name(test.func),
        reference: test.reference,
        passed,
    }
}

/// The fragment a triangle's window holds at `p`, if a quad with a covered
/// pixel holds `p`.
fn fragment_at(
    program: &Program,
    p: Pixel,
    (index, shape, provoking): (usize, &Shape, usize),
    window: &Window,
    out: &DrawOutput,
) -> Option<Fragment> {
    let (ox, oy) = window.inputs.origin;
    let (wx, wy) = (p.x.checked_sub(ox)?, p.y.checked_sub(oy)?);
    let gw = PixelInputs::grid_width(window.width);
    if wx as usize >= gw || wy as usize >= PixelInputs::grid_width(window.height) {
        return None;
    }
    let covered_at = |x: u32, y: u32| {
        x < window.width
            && y < window.height
            && window.inputs.covered[(y * window.width + x) as usize]
    };
    let (qx, qy) = (wx & !1, wy & !1);
    let quad_covered = [(0, 0), (1, 0), (0, 1), (1, 1)]
        .iter()
        .filter(|(dx, dy)| covered_at(qx + dx, qy + dy))
        .count() as u32;
    if quad_covered == 0 {
        return None;
    }
    let covered = covered_at(wx, wy);
    let g = wy as usize * gw + wx as usize;
    let mut inputs: Vec<Named> = window
        .inputs
        .values
        .iter()
        .map(|(slot, values)| Named {
            register: crate::core::pixel_inputs::name(program.profile, *slot),
            value: values[g],
        })
        .collect();
    inputs.extend(position_and_face(program, p.x, p.y, shape.face().value()));
    let i = (wy * window.width + wx) as usize;
    let primitive = PrimitiveAt {
        index,
        face: match shape.face() {
            Face::Front => "front",
            Face::Back => "back",
        },
        corners: shape
            .corners()
            .iter()
            .map(|v| [v.x, v.y, v.z, v.rhw])
            .collect(),
        weights: shape.weights(f64::from(p.x), f64::from(p.y)),
        provoking,
    };
    Some(Fragment {
        primitive: Some(primitive),
        helper: !covered,
        quad_covered,
        inputs,
        outputs: if covered { outputs(out, i) } else { Vec::new() },
        executed: covered.then(|| out.executed[i]),
        killed: false,
        clip_plane: None,
        alpha_test: None,
        stencil: None,
        depth: None,
        blend: None,
        fate: if covered { "written" } else { "helper" },
    })
}
