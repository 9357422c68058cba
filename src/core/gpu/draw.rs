//! One draw on the device: resources from an [`emu::Draw`], one triangle
//! over the target, and the targets read back into the emulator's layout.

use super::{inputs, sampler, texture};
use super::{Gpu, GpuError};
use crate::core::emu::{self, Draw};
use crate::core::image::{unorm8_value, Encoding, TargetFormat};
use crate::core::ir::Shader;
use crate::core::isa::SamplerType;
use crate::core::phases;
use crate::core::translate::{self, interface, Entry};
use rayon::prelude::*;
use std::borrow::Cow;

/// What each `oC#` is rendered into.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TargetKind {
    /// `Rgba32Float`: the shader's f32 output unrounded, as
    /// [`emu::DrawOutput`] holds it.
    Raw,
    /// The D3D9 format: the device stores (and rounds) the value.
    Format(TargetFormat),
}

impl TargetKind {
    fn wgpu(self) -> wgpu::TextureFormat {
        use wgpu::TextureFormat as W;
        match self {
            TargetKind::Raw => W::Rgba32Float,
            TargetKind::Format(f) => match f {
                TargetFormat::A8R8G8B8 => W::Rgba8Unorm,
                TargetFormat::R16F => W::R16Float,
                TargetFormat::G16R16F => W::Rg16Float,
                TargetFormat::Rgba16F => W::Rgba16Float,
                TargetFormat::R32F => W::R32Float,
                TargetFormat::G32R32F => W::Rg32Float,
                TargetFormat::A32B32G32R32F => W::Rgba32Float,
            },
        }
    }

    /// Whether a texel is four little-endian 32-bit floats in the order of
    /// [`GpuOutput`]'s: then [`decode`](TargetKind::decode) is a copy.
    fn four_floats(self) -> bool {
        matches!(
            self,
            TargetKind::Raw | TargetKind::Format(TargetFormat::A32B32G32R32F)
        )
    }

    /// A stored texel as four floats; channels the format does not store
    /// read back as 1, the D3D9 default (as [`TargetFormat::round`]).
    fn decode(self, b: &[u8]) -> [f32; 4] {
        let format = match self {
            TargetKind::Raw => TargetFormat::A32B32G32R32F,
            TargetKind::Format(f) => f,
        };
        std::array::from_fn(|c| {
            if !format.stores(c) {
                return 1.0;
            }
            match format.encoding() {
                Encoding::Unorm8 => unorm8_value(b[c]),
                Encoding::Half => half::f16::from_le_bytes([b[2 * c], b[2 * c + 1]]).to_f32(),
                Encoding::Float => {
                    f32::from_le_bytes([b[4 * c], b[4 * c + 1], b[4 * c + 2], b[4 * c + 3]])
                }
            }
        })
    }
}

/// Per-pixel results of a GPU draw, row-major (`index = y · width + x`),
/// laid out as [`emu::DrawOutput`]'s.
#[derive(Clone, Debug, PartialEq)]
pub struct GpuOutput {
    /// Target width in pixels.
    pub width: u32,
    /// Target height in pixels.
    pub height: u32,
    /// One entry per `oC0..oC3`; `None` if the shader never writes it.
    pub color: Vec<Option<Vec<[f32; 4]>>>,
    /// `oDepth` as the depth target stored it (the device clamps it to [0, 1]).
    pub depth: Option<Vec<f32>>,
    /// Pixels discarded by `texkill` (their colours and depth are zero).
    pub killed: Vec<bool>,
}

impl GpuOutput {
    /// The output as an [`emu::DrawOutput`], for code written against the
    /// emulator (the conformance harness takes any backend that returns
    /// one): colours, depth and killed pixels as drawn; executed counts are
    /// zero and the per-quad statistics empty — a GPU counts nothing.
    pub fn into_draw_output(self) -> emu::DrawOutput {
        emu::DrawOutput::uncounted(
            (self.width, self.height),
            self.color,
            self.depth,
            self.killed,
        )
    }
}

const ROW_ALIGN: u32 = wgpu::COPY_BYTES_PER_ROW_ALIGNMENT;

/// Runs `draw` of `shader` on the device; `targets` chooses the colour
/// targets' format. [`prepare`] and [`Prepared::draw`] in one.
pub fn run(
    gpu: &Gpu,
    shader: &Shader,
    draw: &Draw,
    targets: TargetKind,
) -> Result<GpuOutput, GpuError> {
    prepare(gpu, shader, draw, targets)?.draw()
}

/// [`run`] from a translation made before the device was open
/// ([`translate_ahead`]; made again if it assumed the wrong device).
pub fn run_translated(
    gpu: &Gpu,
    shader: &Shader,
    draw: &Draw,
    targets: TargetKind,
    ahead: Translated,
) -> Result<GpuOutput, GpuError> {
    prepare_from(gpu, shader, draw, targets, Some(ahead))?.draw()
}

/// [`run`], the targets read back `rows` rows at a time
/// ([`Prepared::draw_in_bands`]).
pub fn run_in_bands(
    gpu: &Gpu,
    shader: &Shader,
    draw: &Draw,
    targets: TargetKind,
    rows: u32,
    band: &mut dyn FnMut(u32, GpuOutput) -> bool,
) -> Result<(), GpuError> {
    prepare(gpu, shader, draw, targets)?.draw_in_bands(rows, band)
}

/// [`run_in_bands`] from a translation made before the device was open
/// ([`run_translated`]).
pub fn run_in_bands_translated(
    gpu: &Gpu,
    shader: &Shader,
    draw: &Draw,
    (targets, ahead): (TargetKind, Translated),
    rows: u32,
    band: &mut dyn FnMut(u32, GpuOutput) -> bool,
) -> Result<(), GpuError> {
    prepare_from(gpu, shader, draw, targets, Some(ahead))?.draw_in_bands(rows, band)
}

/// The part of [`prepare`] that needs no device, made while one is still
/// opening ([`translate_ahead`]): the emulator's refusals and the
/// translation specialised to the draw, for a device with or without
/// BORDER addressing (the one thing of the device the translation
/// depends on). For the article's pass 1 on a 3840×2160 frame it is 5 ms
/// that no longer wait for NVIDIA's driver to start (docs/speed.md).
pub struct Translated {
    border: bool,
    /// `Err` where the emulator refuses the draw (nothing translated then).
    made: Result<Result<translate::Translation, GpuError>, GpuError>,
}

/// Translates `draw` of `shader` for a device that has (`border`) or lacks
/// BORDER addressing ([`Gpu::clamp_to_border`]), before the device is there.
pub fn translate_ahead(shader: &Shader, draw: &Draw, border: bool) -> Translated {
    let made = refuse_draw(shader, draw).map(|()| {
        let spec = specialisation_for(border, shader, draw)?;
        let t = translate::translate_specialised(shader, draw.float_rules, Entry::Draw, &spec)
            .map_err(GpuError::Translate);
        phases::mark("draw: translated");
        t
    });
    Translated { border, made }
}

/// A draw made ready on the device: the shader translated and its pipeline
/// compiled, the constants and textures uploaded, the targets allocated.
/// [`Prepared::draw`] draws and reads the targets back, as often as asked:
/// preparing once and drawing many times measures the device's drawing
/// alone, apart from what setting it up costs.
pub struct Prepared<'g> {
    gpu: &'g Gpu,
    size: (u32, u32),
    iface: translate::Interface,
    targets: TargetKind,
    bindings: Bindings,
    pipeline: wgpu::RenderPipeline,
    attachments: Vec<Option<(wgpu::Texture, wgpu::TextureFormat)>>,
    depth: Option<wgpu::Texture>,
    /// The buffers each [`draw`](Prepared::draw) copies the targets into,
    /// made by the first: a 4K target's is 133 MB of host memory the
    /// driver would otherwise map anew for every draw.
    readbacks: std::sync::OnceLock<Vec<(Slot, Readback)>>,
}

/// Makes `draw` of `shader` ready on the device (see [`Prepared`]): the
/// translation specialised to the draw's sampler states.
pub fn prepare<'g>(
    gpu: &'g Gpu,
    shader: &Shader,
    draw: &Draw,
    targets: TargetKind,
) -> Result<Prepared<'g>, GpuError> {
    prepare_from(gpu, shader, draw, targets, None)
}

/// [`prepare`], from `ahead` where it was made for a device like `gpu`.
fn prepare_from<'g>(
    gpu: &'g Gpu,
    shader: &Shader,
    draw: &Draw,
    targets: TargetKind,
    ahead: Option<Translated>,
) -> Result<Prepared<'g>, GpuError> {
    phases::mark("draw: preparing");
    let border = gpu.clamp_to_border();
    let ahead = match ahead {
        Some(t) if t.border == border => t,
        _ => translate_ahead(shader, draw, border),
    };
    // The refusals in the order they always came: the emulator's, the
    // device's size, then the translation's.
    let translation = ahead.made?;
    refuse_size(gpu, draw)?;
    let t = translation?;
    ready(gpu, draw, targets, t.interface, t.module)
}

/// [`prepare`] with `fragment` drawn in place of the translation of
/// `shader`, on the same resources: a shader written by hand for the same
/// computation, measured against the translation (the benchmarks'
/// reference). `fragment` has the translation's interface — the entry
/// point `ps30_draw`, the bindings and locations of
/// [`translate::interface`] for `shader`'s registers.
pub fn prepare_with<'g>(
    gpu: &'g Gpu,
    shader: &Shader,
    draw: &Draw,
    targets: TargetKind,
    fragment: naga::Module,
) -> Result<Prepared<'g>, GpuError> {
    refuse(gpu, shader, draw)?;
    ready(
        gpu,
        draw,
        targets,
        translate::Interface::of(shader),
        fragment,
    )
}

/// The pipeline of `fragment`, the resources of `draw` and the targets.
fn ready<'g>(
    gpu: &'g Gpu,
    draw: &Draw,
    targets: TargetKind,
    iface: translate::Interface,
    fragment: naga::Module,
) -> Result<Prepared<'g>, GpuError> {
    let (w, h) = (draw.target_width, draw.target_height);
    let device = &gpu.device;
    let scopes = ErrorScopes::push(gpu);
    let layout = layout_of(gpu, &iface, input_layers(&iface, draw));
    let color_targets = color_targets(&iface, targets);
    // The driver compiles the pipeline on a thread of its own while this one
    // uploads the textures and inputs: for the article's pass 1 on an NVIDIA
    // H200, 12 ms beside 15 ms (docs/speed.md). Error scopes are per thread.
    let state = PipelineState {
        face: draw.face,
        depth: iface.depth,
        targets: &color_targets,
        layout: &layout,
    };
    let (pipeline, bindings) = std::thread::scope(|s| {
        let compiling = s.spawn(|| {
            let scopes = ErrorScopes::push(gpu);
            let pipeline = render_pipeline(device, fragment, &state);
            phases::mark("draw: pipeline");
            scopes.pop(gpu).and(pipeline)
        });
        let bindings = Bindings::new(gpu, draw, &iface, (&layout, true));
        phases::mark("draw: bound");
        let pipeline = compiling
            .join()
            .unwrap_or_else(|p| std::panic::resume_unwind(p));
        (pipeline, bindings)
    });
    let (pipeline, bindings) = (pipeline?, bindings?);
    let attachments = color_targets
        .iter()
        .map(|c| {
            c.as_ref()
                .map(|c| (target_texture(device, w, h, c.format), c.format))
        })
        .collect();
    let depth = iface
        .depth
        .then(|| target_texture(device, w, h, wgpu::TextureFormat::Depth32Float));
    scopes.pop(gpu)?;
    Ok(Prepared {
        gpu,
        size: (w, h),
        iface,
        targets,
        bindings,
        pipeline,
        attachments,
        depth,
        readbacks: Default::default(),
    })
}

impl Prepared<'_> {
    /// Draws the triangle over the cleared targets and reads them back.
    pub fn draw(&self) -> Result<GpuOutput, GpuError> {
        let (gpu, (w, h)) = (self.gpu, self.size);
        let device = &gpu.device;
        let (scopes, mut encoder) = self.begin();
        let readbacks = self
            .readbacks
            .get_or_init(|| readback_buffers(device, &self.attachments, self.depth.as_ref(), w, h));
        for (_, r) in readbacks {
            r.record(&mut encoder, 0, w, h);
        }
        gpu.queue.submit([encoder.finish()]);
        read_all(gpu, readbacks)?;
        phases::mark("draw: drawn and mapped");
        let out = self.decode(h, readbacks)?;
        for (_, r) in readbacks {
            r.buffer.unmap();
        }
        scopes.pop(gpu)?;
        phases::mark("draw: read back");
        Ok(out)
    }

    /// Draws once and reads the targets back `rows` rows at a time (all at
    /// once where the shader writes depth), top band first, handing each band to `band` (as a `width × rows` output
    /// starting at row `y0`) as soon as it is decoded, so that the caller
    /// works on one band while the next is decoded; `band` returns `false`
    /// to stop.
    ///
    /// The draw is submitted first, then each band's copy into one of two
    /// sets of read-back buffers, used in turn: band k + 2 is copied into
    /// band k's buffers once band k is decoded. The host memory a read-back
    /// buffer lives in costs more to allocate than to fill — about 30 ms
    /// for 133 MB on an NVIDIA H200 (the driver pins it), against a few
    /// milliseconds for the copy — so two band-sized sets replace one per
    /// band, and the first is allocated while the device draws.
    pub fn draw_in_bands(
        &self,
        rows: u32,
        band: &mut dyn FnMut(u32, GpuOutput) -> bool,
    ) -> Result<(), GpuError> {
        let (gpu, (w, h)) = (self.gpu, self.size);
        // WebGPU copies a depth aspect whole, never a band of it.
        let rows = match self.depth {
            Some(_) => h.max(1),
            None => rows.clamp(1, h.max(1)),
        };
        let (scopes, encoder) = self.begin();
        gpu.queue.submit([encoder.finish()]);
        scopes.pop(gpu)?;
        phases::mark("draw: submitted");
        let bands: Vec<(u32, u32)> = (0..h)
            .step_by(rows as usize)
            .map(|y0| (y0, rows.min(h - y0)))
            .collect();
        let Some(&(y, n)) = bands.first() else {
            return Ok(());
        };
        let buffers =
            || readback_buffers(&gpu.device, &self.attachments, self.depth.as_ref(), w, rows);
        let mut sets = vec![buffers()];
        self.copy_band(&sets[0], y, n)?;
        for (k, &(y0, n)) in bands.iter().enumerate() {
            read_all(gpu, &sets[k % 2])?;
            phases::mark("draw: band mapped");
            // The second set is allocated and filled while the first band
            // is decoded.
            if let (0, Some(&(y, m))) = (k, bands.get(1)) {
                sets.push(buffers());
                self.copy_band(&sets[1], y, m)?;
            }
            let set = &sets[k % 2];
            let out = self.decode(n, set)?;
            for (_, r) in set {
                r.buffer.unmap();
            }
            if let Some(&(y, m)) = bands.get(k + 2) {
                self.copy_band(set, y, m)?;
            }
            phases::mark("draw: band read back");
            if !band(y0, out) {
                break;
            }
        }
        Ok(())
    }

    /// Copies rows `y0..y0 + n` of the targets into `set` and submits the
    /// copy; an invalid copy is reported here, before its band is read.
    fn copy_band(&self, set: &[(Slot, Readback)], y0: u32, n: u32) -> Result<(), GpuError> {
        let scopes = ErrorScopes::push(self.gpu);
        let mut encoder = self.gpu.device.create_command_encoder(&Default::default());
        for (_, r) in set {
            r.record(&mut encoder, y0, self.size.0, n);
        }
        self.gpu.queue.submit([encoder.finish()]);
        scopes.pop(self.gpu)
    }

    /// Opens the error scopes and records the draw into a new encoder.
    fn begin(&self) -> (ErrorScopes, wgpu::CommandEncoder) {
        let scopes = ErrorScopes::push(self.gpu);
        let mut encoder = self.gpu.device.create_command_encoder(&Default::default());
        record_pass(
            &mut encoder,
            &self.attachments,
            self.depth.as_ref(),
            &self.pipeline,
            &self.bindings.group,
        );
        (scopes, encoder)
    }

    /// `rows` rows of the targets, decoded straight from the mapped
    /// read-back buffers (a 4K target is 132 MB: no copy first).
    fn decode(&self, rows: u32, readbacks: &[(Slot, Readback)]) -> Result<GpuOutput, GpuError> {
        let views = readbacks
            .iter()
            .map(|(_, r)| r.buffer.get_mapped_range(..))
            .collect::<Result<Vec<_>, _>>()
            .map_err(|e| GpuError::Failed(e.to_string()))?;
        let data: Vec<&[u8]> = views.iter().map(|v| &v[..]).collect();
        Ok(assemble(
            self.size.0,
            rows,
            &self.iface,
            self.targets,
            readbacks,
            &data,
        ))
    }
}

/// The device's validation and out-of-memory errors over a span of calls,
/// and any error it raised outside a scope.
pub(super) struct ErrorScopes {
    // wgpu panics when scopes are popped out of order, and a span left
    // early (`?`) drops them in field order: the inner scope comes first.
    memory: wgpu::ErrorScopeGuard,
    validation: wgpu::ErrorScopeGuard,
}

impl ErrorScopes {
    pub(super) fn push(gpu: &Gpu) -> ErrorScopes {
        let validation = gpu.device.push_error_scope(wgpu::ErrorFilter::Validation);
        let memory = gpu.device.push_error_scope(wgpu::ErrorFilter::OutOfMemory);
        ErrorScopes { memory, validation }
    }

    /// The first error the span raised, if any (innermost scope first).
    pub(super) fn pop(self, gpu: &Gpu) -> Result<(), GpuError> {
        if let Some(e) = pollster::block_on(self.memory.pop()) {
            return Err(GpuError::Failed(e.to_string()));
        }
        if let Some(e) = pollster::block_on(self.validation.pop()) {
            return Err(GpuError::Failed(e.to_string()));
        }
        if let Some(e) = gpu.uncaptured.lock().ok().and_then(|mut e| e.take()) {
            return Err(GpuError::Failed(e));
        }
        Ok(())
    }
}

/// Refuses what the emulator refuses ([`emu::check`]) and targets larger
/// than the device's.
pub(super) fn refuse(gpu: &Gpu, shader: &Shader, draw: &Draw) -> Result<(), GpuError> {
    refuse_draw(shader, draw)?;
    refuse_size(gpu, draw)
}

/// What the emulator refuses ([`emu::check`]).
fn refuse_draw(shader: &Shader, draw: &Draw) -> Result<(), GpuError> {
    let compiled = emu::compile(shader).map_err(GpuError::Draw)?;
    emu::check(&compiled, draw).map_err(GpuError::Draw)
}

/// Targets larger than the device's.
fn refuse_size(gpu: &Gpu, draw: &Draw) -> Result<(), GpuError> {
    let (w, h) = (draw.target_width, draw.target_height);
    let max = gpu.limits.max_texture_dimension_2d;
    if w > max || h > max {
        return Err(GpuError::Unsupported(format!(
            "a {w}×{h} target: the device's textures are at most {max} texels a side"
        )));
    }
    Ok(())
}

/// One colour target per written `oC#` (slot k for `oC`k), then the
/// texkill flag when the shader kills; trailing empty slots dropped.
fn color_targets(
    iface: &interface::Interface,
    targets: TargetKind,
) -> Vec<Option<wgpu::ColorTargetState>> {
    let format = targets.wgpu();
    let mut color_targets: Vec<Option<wgpu::ColorTargetState>> = vec![None; 4];
    for &k in &iface.outputs {
        color_targets[k as usize] = Some(format.into());
    }
    if iface.kills {
        color_targets.push(Some(wgpu::TextureFormat::R32Uint.into()));
    }
    while color_targets.last().is_some_and(|c| c.is_none()) {
        color_targets.pop();
    }
    color_targets
}

/// What a draw's pipeline is made of besides its shaders.
struct PipelineState<'a> {
    face: emu::Face,
    /// The shader writes `oDepth`.
    depth: bool,
    targets: &'a [Option<wgpu::ColorTargetState>],
    layout: &'a wgpu::BindGroupLayout,
}

/// The pipeline: the full-screen triangle and the translated shader.
fn render_pipeline(
    device: &wgpu::Device,
    fragment: naga::Module,
    state: &PipelineState,
) -> Result<wgpu::RenderPipeline, GpuError> {
    let vertex = crate::core::translate::fixed::full_screen_triangle();
    let vs = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("ps30 full-screen triangle"),
        source: wgpu::ShaderSource::Naga(Cow::Owned(vertex)),
    });
    let fs = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("ps30 translated shader"),
        source: wgpu::ShaderSource::Naga(Cow::Owned(fragment)),
    });
    phases::mark("draw: shader module made");
    let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
        label: None,
        bind_group_layouts: &[Some(state.layout)],
        immediate_size: 0,
    });
    Ok(
        device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some("ps30 draw"),
            layout: Some(&layout),
            vertex: wgpu::VertexState {
                module: &vs,
                entry_point: Some("vs"),
                compilation_options: Default::default(),
                buffers: &[],
            },
            // The triangle is counter-clockwise in WebGPU's terms; calling
            // that winding the back face makes its pixels back-facing.
            primitive: wgpu::PrimitiveState {
                front_face: match state.face {
                    emu::Face::Front => wgpu::FrontFace::Ccw,
                    emu::Face::Back => wgpu::FrontFace::Cw,
                },
                ..Default::default()
            },
            depth_stencil: state.depth.then(|| wgpu::DepthStencilState {
                format: wgpu::TextureFormat::Depth32Float,
                depth_write_enabled: Some(true),
                depth_compare: Some(wgpu::CompareFunction::Always),
                stencil: Default::default(),
                bias: Default::default(),
            }),
            multisample: Default::default(),
            fragment: Some(wgpu::FragmentState {
                module: &fs,
                entry_point: Some("ps30_draw"),
                compilation_options: Default::default(),
                targets: state.targets,
            }),
            multiview_mask: None,
            cache: None,
        }),
    )
}

/// The render pass: every target cleared, one triangle drawn.
fn record_pass(
    encoder: &mut wgpu::CommandEncoder,
    attachments: &[Option<(wgpu::Texture, wgpu::TextureFormat)>],
    depth: Option<&wgpu::Texture>,
    pipeline: &wgpu::RenderPipeline,
    group: &wgpu::BindGroup,
) {
    let views: Vec<Option<wgpu::TextureView>> = attachments
        .iter()
        .map(|a| a.as_ref().map(|(t, _)| t.create_view(&Default::default())))
        .collect();
    let depth_view = depth.map(|t| t.create_view(&Default::default()));
    let color_attachments = super::cleared_attachments(&views);
    let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
        label: Some("ps30 draw"),
        color_attachments: &color_attachments,
        depth_stencil_attachment: depth_view.as_ref().map(|view| {
            wgpu::RenderPassDepthStencilAttachment {
                view,
                depth_ops: Some(wgpu::Operations {
                    load: wgpu::LoadOp::Clear(0.0),
                    store: wgpu::StoreOp::Store,
                }),
                stencil_ops: None,
            }
        }),
        ..Default::default()
    });
    pass.set_pipeline(pipeline);
    pass.set_bind_group(0, group, &[]);
    pass.draw(0..3, 0..1);
}

/// A buffer the host can map for every target.
fn readback_buffers(
    device: &wgpu::Device,
    attachments: &[Option<(wgpu::Texture, wgpu::TextureFormat)>],
    depth: Option<&wgpu::Texture>,
    w: u32,
    h: u32,
) -> Vec<(Slot, Readback)> {
    let mut readbacks = Vec::new();
    for (k, a) in attachments.iter().enumerate() {
        if let Some((texture, format)) = a {
            let bytes = format.block_copy_size(None).unwrap_or(16);
            let aspect = wgpu::TextureAspect::All;
            let r = Readback::new(device, texture, w, h, bytes, aspect);
            readbacks.push((Slot::Color(k), r));
        }
    }
    if let Some(d) = depth {
        let aspect = wgpu::TextureAspect::DepthOnly;
        let r = Readback::new(device, d, w, h, 4, aspect);
        readbacks.push((Slot::Depth, r));
    }
    readbacks
}

/// Which target a read-back buffer holds.
#[derive(Clone, Copy)]
enum Slot {
    /// Colour attachment k (k = 4: the texkill flag).
    Color(usize),
    Depth,
}

/// A buffer a target is copied into, and its row pitch.
struct Readback {
    source: wgpu::Texture,
    aspect: wgpu::TextureAspect,
    buffer: wgpu::Buffer,
    pitch: u32,
    texel: u32,
}

pub(super) fn target_texture(
    device: &wgpu::Device,
    w: u32,
    h: u32,
    format: wgpu::TextureFormat,
) -> wgpu::Texture {
    device.create_texture(&wgpu::TextureDescriptor {
        label: None,
        size: wgpu::Extent3d {
            width: w,
            height: h,
            depth_or_array_layers: 1,
        },
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format,
        usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
        view_formats: &[],
    })
}

impl Readback {
    fn new(
        device: &wgpu::Device,
        source: &wgpu::Texture,
        w: u32,
        h: u32,
        texel: u32,
        aspect: wgpu::TextureAspect,
    ) -> Readback {
        let pitch = (w * texel).div_ceil(ROW_ALIGN) * ROW_ALIGN;
        let buffer = device.create_buffer(&wgpu::BufferDescriptor {
            label: None,
            size: pitch as u64 * h as u64,
            usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
            mapped_at_creation: false,
        });
        Readback {
            source: source.clone(),
            aspect,
            buffer,
            pitch,
            texel,
        }
    }

    /// Copies rows `y0..y0 + h` of the target into the buffer.
    fn record(&self, encoder: &mut wgpu::CommandEncoder, y0: u32, w: u32, h: u32) {
        encoder.copy_texture_to_buffer(
            wgpu::TexelCopyTextureInfo {
                texture: &self.source,
                mip_level: 0,
                origin: wgpu::Origin3d { x: 0, y: y0, z: 0 },
                aspect: self.aspect,
            },
            wgpu::TexelCopyBufferInfo {
                buffer: &self.buffer,
                layout: wgpu::TexelCopyBufferLayout {
                    offset: 0,
                    bytes_per_row: Some(self.pitch),
                    rows_per_image: Some(h),
                },
            },
            wgpu::Extent3d {
                width: w,
                height: h,
                depth_or_array_layers: 1,
            },
        );
    }
}

/// Maps every read-back buffer for reading.
fn read_all(gpu: &Gpu, readbacks: &[(Slot, Readback)]) -> Result<(), GpuError> {
    let buffers: Vec<&wgpu::Buffer> = readbacks.iter().map(|(_, r)| &r.buffer).collect();
    map_read(gpu, &buffers)
}

/// Maps every buffer of `buffers` for reading, and waits for them.
pub(super) fn map_read(gpu: &Gpu, buffers: &[&wgpu::Buffer]) -> Result<(), GpuError> {
    let (tx, rx) = std::sync::mpsc::channel();
    for (i, buffer) in buffers.iter().enumerate() {
        let tx = tx.clone();
        buffer.map_async(wgpu::MapMode::Read, .., move |res| {
            let _ = tx.send((i, res));
        });
    }
    gpu.device
        .poll(wgpu::PollType::wait_indefinitely())
        .map_err(|e| GpuError::Failed(e.to_string()))?;
    drop(tx);
    for (i, res) in rx.iter() {
        res.map_err(|e| GpuError::Failed(format!("reading target {i} back: {e}")))?;
    }
    Ok(())
}

/// The read-back bytes as per-pixel values in the emulator's layout.
fn assemble(
    w: u32,
    h: u32,
    iface: &translate::Interface,
    targets: TargetKind,
    readbacks: &[(Slot, Readback)],
    data: &[&[u8]],
) -> GpuOutput {
    let n = w as usize * h as usize;
    let mut out = GpuOutput {
        width: w,
        height: h,
        color: vec![None; 4],
        depth: None,
        killed: vec![false; n],
    };
    for ((slot, r), &bytes) in readbacks.iter().zip(data) {
        match *slot {
            Slot::Color(k) if k < 4 && targets.four_floats() => {
                out.color[k] = Some(four_floats(w, h, r, bytes));
            }
            Slot::Color(k) if k < 4 => {
                out.color[k] = Some(texels(w, h, r, bytes, |b| targets.decode(b)));
            }
            Slot::Color(_) => {
                out.killed = texels(w, h, r, bytes, |b| b.iter().any(|&x| x != 0));
            }
            Slot::Depth => {
                let depth = |b: &[u8]| f32::from_le_bytes([b[0], b[1], b[2], b[3]]);
                out.depth = Some(texels(w, h, r, bytes, depth));
            }
        }
    }
    if iface.kills {
        let killed = std::mem::take(&mut out.killed);
        for (i, _) in killed.iter().enumerate().filter(|(_, &k)| k) {
            for c in out.color.iter_mut().flatten() {
                c[i] = [0.0; 4];
            }
            if let Some(d) = &mut out.depth {
                d[i] = 0.0;
            }
        }
        out.killed = killed;
    }
    out
}

/// Each texel of a read-back target decoded by `decode`, row by row (the
/// rows in parallel, each written in place: a 4K target is 8 million
/// texels, and collecting rows as they come took longer than the draw).
fn texels<T: Send + Copy + Default>(
    w: u32,
    h: u32,
    r: &Readback,
    bytes: &[u8],
    decode: impl Fn(&[u8]) -> T + Sync,
) -> Vec<T> {
    let (pitch, texel) = (r.pitch as usize, r.texel as usize);
    let width = w as usize;
    let row_bytes = width * texel;
    let mut out = vec![T::default(); width * h as usize];
    out.par_chunks_mut(width.max(1))
        .enumerate()
        .for_each(|(y, row)| {
            let src = &bytes[y * pitch..y * pitch + row_bytes];
            for (t, b) in row.iter_mut().zip(src.chunks_exact(texel)) {
                *t = decode(b);
            }
        });
    out
}

/// [`texels`] of a target of four 32-bit floats ([`TargetKind::four_floats`]):
/// each row's bytes copied as they are, the rows in parallel, instead of
/// decoded channel by channel (a 3840×2160 frame is 133 MB: docs/speed.md).
fn four_floats(w: u32, h: u32, r: &Readback, bytes: &[u8]) -> Vec<[f32; 4]> {
    if cfg!(target_endian = "big") {
        return texels(w, h, r, bytes, |b| TargetKind::Raw.decode(b));
    }
    let (pitch, width) = (r.pitch as usize, w as usize);
    let mut out = vec![[0.0f32; 4]; width * h as usize];
    out.par_chunks_mut(width.max(1))
        .enumerate()
        .for_each(|(y, row)| {
            let src = &bytes[y * pitch..][..16 * row.len()];
            bytemuck::cast_slice_mut::<[f32; 4], u8>(row).copy_from_slice(src);
        });
    out
}

/// The bind group's layout: the constants, each declared sampler's texture
/// and sampler, the inputs where they go up as a texture
/// (`per_pixel_inputs`) — made from the interface alone, before anything
/// is uploaded, so the pipeline can be compiled meanwhile.
pub(super) fn bind_group_layout(
    gpu: &Gpu,
    iface: &translate::Interface,
    per_pixel_inputs: bool,
) -> wgpu::BindGroupLayout {
    let layers = match per_pixel_inputs {
        true => iface.inputs.len(),
        false => 0,
    };
    layout_of(gpu, iface, layers)
}

/// The layers of `draw`'s input texture: one per declared `v#`, then, for
/// a draw of given pixels whose shader reads `vPos`, each pixel's place in
/// the render target (`Specialisation::positions_given`).
fn input_layers(iface: &translate::Interface, draw: &Draw) -> usize {
    iface.inputs.len() + usize::from(draw.pixels.is_some() && iface.position)
}

/// [`bind_group_layout`] with an input texture of `layers` layers (none: no
/// input texture).
fn layout_of(gpu: &Gpu, iface: &translate::Interface, layers: usize) -> wgpu::BindGroupLayout {
    let filterable = gpu.float32_filterable();
    let mut layout_entries = vec![entry(
        interface::CONSTANTS_BINDING,
        wgpu::BindingType::Buffer {
            ty: wgpu::BufferBindingType::Uniform,
            has_dynamic_offset: false,
            min_binding_size: None,
        },
    )];
    for s in &iface.samplers {
        let dimension = texture::view_dimension(s.ty);
        layout_entries.push(entry(
            s.texture_binding,
            texture_type(filterable, dimension),
        ));
        layout_entries.push(entry(
            s.sampler_binding,
            wgpu::BindingType::Sampler(if filterable {
                wgpu::SamplerBindingType::Filtering
            } else {
                wgpu::SamplerBindingType::NonFiltering
            }),
        ));
    }
    if layers > 0 {
        let ty = texture_type(false, wgpu::TextureViewDimension::D2Array);
        layout_entries.push(entry(interface::DRAW_INPUTS_BINDING, ty));
    }
    gpu.device
        .create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: None,
            entries: &layout_entries,
        })
}

/// The bind group: constants, textures with their samplers, inputs.
pub(super) struct Bindings {
    pub(super) group: wgpu::BindGroup,
}

impl Bindings {
    /// Uploads what `draw` binds and makes the group of `layout`
    /// ([`bind_group_layout`] of `iface`). `per_pixel_inputs`: the inputs
    /// go up as a texture (`Entry::Draw`); otherwise they arrive from a
    /// vertex stage.
    pub(super) fn new(
        gpu: &Gpu,
        draw: &Draw,
        iface: &translate::Interface,
        (layout, per_pixel_inputs): (&wgpu::BindGroupLayout, bool),
    ) -> Result<Bindings, GpuError> {
        let device = &gpu.device;
        let mut block = constant_block(draw);
        let mut views = Vec::new();
        let mut samplers = Vec::new();
        for s in &iface.samplers {
            let records = &mut block[interface::SAMPLERS_OFFSET as usize..];
            let (view, sampler) = bind_sampler(gpu, draw, s.register, s.ty, records)?;
            views.push((s.texture_binding, view));
            samplers.push((s.sampler_binding, sampler));
        }
        let layers = match per_pixel_inputs {
            true => input_layers(iface, draw),
            false => 0,
        };
        let inputs = match layers {
            0 => None,
            _ => Some(input_texture(gpu, draw, iface, layers as u32)?),
        };
        let buffer = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("ps30 constants"),
            size: block.len() as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        gpu.queue.write_buffer(&buffer, 0, &block);
        let input_view = inputs.as_ref().map(|t| {
            t.create_view(&wgpu::TextureViewDescriptor {
                dimension: Some(wgpu::TextureViewDimension::D2Array),
                ..Default::default()
            })
        });
        let mut entries = vec![wgpu::BindGroupEntry {
            binding: interface::CONSTANTS_BINDING,
            resource: buffer.as_entire_binding(),
        }];
        for (b, v) in &views {
            let resource = wgpu::BindingResource::TextureView(v);
            entries.push(wgpu::BindGroupEntry {
                binding: *b,
                resource,
            });
        }
        for (b, s) in &samplers {
            let resource = wgpu::BindingResource::Sampler(s);
            entries.push(wgpu::BindGroupEntry {
                binding: *b,
                resource,
            });
        }
        if let Some(v) = &input_view {
            entries.push(wgpu::BindGroupEntry {
                binding: interface::DRAW_INPUTS_BINDING,
                resource: wgpu::BindingResource::TextureView(v),
            });
        }
        let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: None,
            layout,
            entries: &entries,
        });
        Ok(Bindings { group })
    }
}

/// A binding the fragment stage sees.
fn entry(binding: u32, ty: wgpu::BindingType) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility: wgpu::ShaderStages::FRAGMENT,
        ty,
        count: None,
    }
}

/// A float texture binding of `view_dimension` (a 2D array: the draw's inputs).
pub(super) fn texture_type(
    filterable: bool,
    view_dimension: wgpu::TextureViewDimension,
) -> wgpu::BindingType {
    wgpu::BindingType::Texture {
        sample_type: wgpu::TextureSampleType::Float { filterable },
        view_dimension,
        multisampled: false,
    }
}

/// The uniform block with the draw's `c#`, `i#` and `b#` at the offsets of
/// [`interface`] (the sampler records are filled by [`bind_sampler`]).
fn constant_block(draw: &Draw) -> Vec<u8> {
    let mut block = vec![0u8; interface::CONSTANTS_SIZE as usize];
    let mut put = |offset: usize, words: [u32; 4]| {
        for (i, w) in words.iter().enumerate() {
            block[offset + 4 * i..offset + 4 * i + 4].copy_from_slice(&w.to_le_bytes());
        }
    };
    for (i, v) in draw.constants.float.iter().enumerate() {
        put(
            interface::FLOATS_OFFSET as usize + 16 * i,
            v.map(f32::to_bits),
        );
    }
    for (i, v) in draw.constants.int.iter().enumerate() {
        put(
            interface::INTS_OFFSET as usize + 16 * i,
            v.map(|x| x as u32),
        );
    }
    for (i, &b) in draw.constants.bool.iter().enumerate() {
        put(
            interface::BOOLS_OFFSET as usize + 16 * i,
            [b as u32, 0, 0, 0],
        );
    }
    block
}

/// The texture bound to sampler `register` and its state. An unbound
/// sampler reads (0, 0, 0, 1) (MS texldl---ps): no levels (a 1×1 texture of
/// that value, `core/gpu/texture.rs`), clamped.
fn bound<'d>(draw: &'d Draw, register: u32) -> (Option<emu::TextureLevels<'d>>, emu::SamplerState) {
    match draw.samplers.iter().find(|b| b.0 == register) {
        Some((_, tex, state)) => (Some(*tex), *state),
        None => (
            None,
            emu::SamplerState {
                address_u: emu::Address::Clamp,
                address_v: emu::Address::Clamp,
                address_w: emu::Address::Clamp,
                ..Default::default()
            },
        ),
    }
}

/// Sampler `register` (declared `ty`): its state mapped for the device,
/// for a texture of its bound levels.
fn mapped(
    border: bool,
    draw: &Draw,
    register: u32,
    ty: SamplerType,
) -> Result<sampler::Mapped, GpuError> {
    let (levels, state) = bound(draw, register);
    let count = levels.map_or(1, |l| l.len()) as u32;
    sampler::map(&state, count, register, ty, border)
}

/// What the translation may assume of the draw (`translate::specialise`):
/// each declared sampler carries only the emulation its state asks for,
/// the float constants are the draw's, and the inputs arrive flushed where
/// the float rules flush them ([`input_texture`] does it on the CPU).
pub(super) fn specialisation(
    gpu: &Gpu,
    shader: &Shader,
    draw: &Draw,
) -> Result<translate::Specialisation, GpuError> {
    specialisation_for(gpu.clamp_to_border(), shader, draw)
}

/// [`specialisation`] for a device that has (`border`) or lacks BORDER
/// addressing.
fn specialisation_for(
    border: bool,
    shader: &Shader,
    draw: &Draw,
) -> Result<translate::Specialisation, GpuError> {
    let mut spec = translate::Specialisation::general();
    for d in &shader.program().samplers {
        spec.set(d.index, mapped(border, draw, d.index, d.ty)?.spec);
    }
    spec.set_constants(
        draw.constants
            .float
            .iter()
            .map(|v| v.map(f32::to_bits))
            .collect(),
    );
    spec.set_inputs_flushed(draw.float_rules.flush_denormals());
    spec.set_positions_given(draw.pixels.is_some());
    Ok(spec)
}

/// Sampler `register`: its texture uploaded, its D3D9 state mapped to a
/// wgpu sampler and view, and what the shader applies itself written into
/// its record of `records` (the constant block's sampler records, s0's
/// first: a pixel and a vertex block place them apart).
pub(super) fn bind_sampler(
    gpu: &Gpu,
    draw: &Draw,
    register: u32,
    ty: SamplerType,
    records: &mut [u8],
) -> Result<(wgpu::TextureView, wgpu::Sampler), GpuError> {
    let (levels, _) = bound(draw, register);
    let mapped = mapped(gpu.clamp_to_border(), draw, register, ty)?;
    if mapped.filtering && !gpu.float32_filterable() {
        return Err(GpuError::Unsupported(format!(
            "s{register} filters linearly and the device cannot filter 32-bit float textures (FLOAT32_FILTERABLE)"
        )));
    }
    records[interface::SAMPLER_STATE_SIZE as usize * register as usize..][..64]
        .copy_from_slice(&mapped.block);
    let up = texture::upload(gpu, levels, ty, register)?;
    let view = up.texture.create_view(&wgpu::TextureViewDescriptor {
        dimension: Some(up.dimension),
        base_mip_level: mapped.base_level,
        mip_level_count: Some(mapped.level_count),
        ..Default::default()
    });
    Ok((view, gpu.device.create_sampler(&mapped.descriptor)))
}

/// The inputs, evaluated per pixel with the emulator's formula (or, for
/// a draw of one primitive's pixels, as [`Draw::pixels`] gives them), one
/// layer per declared `v#` in register order; under the `hardware` rules with
/// denormals flushed, as the emulator reads them (the shader then reads
/// them as they are: [`specialisation`]). `layers` counts a draw of
/// given pixels' layer of positions too ([`input_layers`]).
fn input_texture(
    gpu: &Gpu,
    draw: &Draw,
    iface: &translate::Interface,
    layers: u32,
) -> Result<wgpu::Texture, GpuError> {
    let (w, h) = (draw.target_width, draw.target_height);
    let large = w as usize * h as usize * 16 >= texture::PARALLEL_UPLOAD;
    let texture = gpu.device.create_texture(&wgpu::TextureDescriptor {
        label: Some("ps30 inputs"),
        size: wgpu::Extent3d {
            width: w,
            height: h,
            depth_or_array_layers: layers,
        },
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format: wgpu::TextureFormat::Rgba32Float,
        usage: match large {
            true => {
                wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST | inputs::USAGE
            }
            false => wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
        },
        view_formats: &[],
    });
    let values: Vec<emu::LinearInput> = iface
        .inputs
        .iter()
        .map(|input| {
            draw.inputs
                .iter()
                .find(|(v, _)| *v == input.register)
                .map(|(_, value)| *value)
                .unwrap_or_default()
        })
        .collect();
    if let Some(p) = draw.pixels {
        // A primitive's inputs as the emulator's set-up computed them, at
        // every pixel of its quad grid (`emu::PixelInputs`).
        let grid = emu::PixelInputs::grid_width(w);
        for (layer, input) in iface.inputs.iter().enumerate() {
            let given = p.values.iter().find(|(v, _)| *v == input.register);
            let mut texels = vec![[0.0f32; 4]; w as usize * h as usize];
            for (i, t) in texels.iter_mut().enumerate() {
                let (x, y) = (i % w as usize, i / w as usize);
                let v = given.and_then(|(_, v)| v.get(y * grid + x)).copied();
                *t = v.unwrap_or_default();
                if draw.float_rules.flush_denormals() {
                    *t = t.map(crate::core::float_rules::flush);
                }
            }
            texture::write_texels(gpu, &texture, 0, layer as u32, (w, h, 1), &texels)?;
        }
        if layers as usize > iface.inputs.len() {
            let texels = positions(p, w, h);
            let layer = iface.inputs.len() as u32;
            texture::write_texels(gpu, &texture, 0, layer, (w, h, 1), &texels)?;
        }
        phases::mark("draw: a primitive's inputs uploaded");
        return Ok(texture);
    }
    if large && inputs::fill(gpu, &texture, &values, (w, h))? {
        phases::mark("draw: inputs made on the device");
        return Ok(texture);
    }
    let flush = draw.float_rules.flush_denormals();
    for (layer, &value) in values.iter().enumerate() {
        let row = |y: usize, row: &mut [[f32; 4]]| {
            for (x, t) in row.iter_mut().enumerate() {
                *t = value.at(x as f32, y as f32);
                if flush {
                    *t = t.map(crate::core::float_rules::flush);
                }
            }
        };
        let size = (w, h, 1);
        if large {
            texture::write_rows(gpu, &texture, 0, layer as u32, size, row)?;
        } else {
            let mut texels = vec![[0.0f32; 4]; w as usize * h as usize];
            for (y, r) in texels.chunks_mut(w.max(1) as usize).enumerate() {
                row(y, r);
            }
            texture::write_texels(gpu, &texture, 0, layer as u32, size, &texels)?;
        }
    }
    phases::mark("draw: inputs uploaded");
    Ok(texture)
}

/// The layer of positions of a draw of given pixels (`w × h`): each
/// pixel's `vPos`, `(x, y, 0, 0)`, where its window puts it in the render
/// target ([`emu::PixelInputs::positions`], else `origin + (x, y)`).
fn positions(p: &emu::PixelInputs, w: u32, h: u32) -> Vec<[f32; 4]> {
    let grid = emu::PixelInputs::grid_width(w);
    (0..w as usize * h as usize)
        .map(|i| {
            let (x, y) = (i % w as usize, i / w as usize);
            let at = match &p.positions {
                Some(given) => given.get(y * grid + x).copied().unwrap_or_default(),
                None => (p.origin.0 + x as u32, p.origin.1 + y as u32),
            };
            [at.0 as f32, at.1 as f32, 0.0, 0.0]
        })
        .collect()
}
