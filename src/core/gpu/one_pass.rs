//! A whole draw of geometry in one render pass: every primitive of the
//! draw goes to the device in one indexed draw, and the device runs the
//! depth and stencil tests and keeps the primitives in order itself
//! (Vulkan 1.3, "Primitive Order": depth, stencil and colour writes of a
//! draw land in the order its primitives were given), instead of one pass
//! and one read-back per primitive with the tests on the CPU
//! ([`super::draw_geometry`]).
//!
//! The results are those of the per-primitive path exactly, for the draws
//! the caller sends here (the caller decides which: no blending — what is
//! left of the CPU's work is then a function of the last fragment to pass
//! at each pixel):
//!
//! * **The alpha test** runs in the shader before the depth and stencil
//!   tests, as in Direct3D 9: a pixel whose oC0 fails it is discarded, so
//!   that it neither writes nor changes depth or stencil, nor counts as
//!   killed (`translate::device_tests::AlphaDiscard`, the CPU's arithmetic
//!   operation for operation).
//! * **Depth** is compared in the surface's stored form
//!   (`translate::device_tests`): the fragment writes the stored integer
//!   scaled by a power of two into a 32-bit float surface, and the surface
//!   starts as the draw's depth buffer in the same form (drawn in by a
//!   full-target pass, since WebGPU copies into no 32-bit float depth
//!   surface). D3DCMP_* maps one to one onto `CompareFunction`, with the
//!   fragment on the left as in both APIs (D3DRS_ZFUNC "compares the depth
//!   value of a pixel against the depth buffer"; Vulkan 1.3, "Depth Test":
//!   `z_f op z_a`).
//! * **Stencil** is Vulkan's own test, which is Direct3D 9's: reference and
//!   stored value both masked, the reference on the left; the three
//!   operations per facing; the write mask (Vulkan 1.3, "Stencil Test";
//!   `core/raster/stencil.rs` for D3D9). INCRSAT/DECRSAT are
//!   INCREMENT_AND_CLAMP/DECREMENT_AND_CLAMP, INCR/DECR the wrapping ones.
//!   Front faces are clockwise as in the per-primitive path, so the
//!   counter-clockwise side of two-sided stencil is Vulkan's back face.
//! * **Counts**: each pixel the draw covers and each it kills are counted
//!   per triangle in the shader; the pixels that pass every test add 1.0
//!   each into a 32-bit float target blended ONE + ONE (exact below 2²⁴),
//!   which is the per-primitive path's count of pixels written.

use super::draw::ErrorScopes;
use super::geometry::{self, Fragment, GeometryDraw, Resources, Stages};
use super::{Gpu, GpuError};
use crate::core::ir::Shader;
use crate::core::phases;
use crate::core::raster::stencil::StencilOp;
use crate::core::translate::device_tests::{AlphaDiscard, DepthStore, DeviceTests, COUNTS_BINDING};
use crate::core::translate::interface;
use std::borrow::Cow;

/// A comparison function of the depth or stencil test (D3DCMP_*).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Compare {
    /// D3DCMP_NEVER.
    Never,
    /// D3DCMP_LESS.
    Less,
    /// D3DCMP_EQUAL.
    Equal,
    /// D3DCMP_LESSEQUAL.
    LessEqual,
    /// D3DCMP_GREATER.
    Greater,
    /// D3DCMP_NOTEQUAL.
    NotEqual,
    /// D3DCMP_GREATEREQUAL.
    GreaterEqual,
    /// D3DCMP_ALWAYS.
    Always,
}

impl Compare {
    fn device(self) -> wgpu::CompareFunction {
        use wgpu::CompareFunction as C;
        match self {
            Compare::Never => C::Never,
            Compare::Less => C::Less,
            Compare::Equal => C::Equal,
            Compare::LessEqual => C::LessEqual,
            Compare::Greater => C::Greater,
            Compare::NotEqual => C::NotEqual,
            Compare::GreaterEqual => C::GreaterEqual,
            Compare::Always => C::Always,
        }
    }
}

fn operation(op: StencilOp) -> wgpu::StencilOperation {
    use wgpu::StencilOperation as O;
    match op {
        StencilOp::Keep => O::Keep,
        StencilOp::Zero => O::Zero,
        StencilOp::Replace => O::Replace,
        StencilOp::IncrSat => O::IncrementClamp,
        StencilOp::DecrSat => O::DecrementClamp,
        StencilOp::Invert => O::Invert,
        StencilOp::Incr => O::IncrementWrap,
        StencilOp::Decr => O::DecrementWrap,
    }
}

/// One facing's stencil state.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct StencilSide {
    /// D3DRS_STENCILFUNC.
    pub compare: Compare,
    /// D3DRS_STENCILFAIL.
    pub fail: StencilOp,
    /// D3DRS_STENCILZFAIL.
    pub depth_fail: StencilOp,
    /// D3DRS_STENCILPASS.
    pub pass: StencilOp,
}

impl StencilSide {
    fn device(self) -> wgpu::StencilFaceState {
        wgpu::StencilFaceState {
            compare: self.compare.device(),
            fail_op: operation(self.fail),
            depth_fail_op: operation(self.depth_fail),
            pass_op: operation(self.pass),
        }
    }
}

/// The stencil test of a draw.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct StencilTest {
    /// Clockwise triangles and points.
    pub front: StencilSide,
    /// Counter-clockwise triangles (`front` again without two-sided
    /// stencil).
    pub back: StencilSide,
    /// D3DRS_STENCILREF.
    pub reference: u8,
    /// D3DRS_STENCILMASK.
    pub mask: u8,
    /// D3DRS_STENCILWRITEMASK.
    pub write_mask: u8,
    /// The stored values before the draw, row-major.
    pub stored: Vec<u8>,
}

/// The depth-stencil surface of a draw and its tests.
#[derive(Clone, Debug, PartialEq)]
pub struct DepthSurface {
    /// How the surface stores a depth.
    pub store: DepthStore,
    /// D3DRS_ZFUNC.
    pub compare: Compare,
    /// D3DRS_ZWRITEENABLE.
    pub write: bool,
    /// Every pixel's stored depth in the device's form (`k·2⁻ᵇ` for a
    /// b-bit surface storing k, the depth itself for D32F), row-major.
    pub stored: Vec<f32>,
    /// The stencil test, where the draw has one.
    pub stencil: Option<StencilTest>,
}

/// What a draw in one pass left.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct OnePass {
    /// Per target pixel, how many of the draw's pixels passed every test
    /// there.
    pub written: Vec<u32>,
    /// Per `oC#` the shader writes, the colour of the last pixel that
    /// passed, over the whole target.
    pub color: Vec<Option<Vec<[f32; 4]>>>,
    /// The depth surface after the draw, in the device's form.
    pub depth: Option<Vec<f32>>,
    /// The stencil values after the draw.
    pub stencil: Option<Vec<u8>>,
    /// Per triangle, in index order: the pixels it covered and those of
    /// them `texkill` killed.
    pub counts: Vec<[u32; 2]>,
}

/// Why this device cannot draw in one pass (`None` if it can): the
/// features the pass needs.
pub fn one_pass_lacks(gpu: &Gpu, stencil: bool) -> Option<&'static str> {
    let f = gpu.features;
    if !f.contains(wgpu::Features::PRIMITIVE_INDEX) {
        return Some(
            "the device lacks PRIMITIVE_INDEX, by which the pass counts each triangle's pixels",
        );
    }
    if !f.contains(wgpu::Features::FLOAT32_BLENDABLE) {
        return Some(
            "the device lacks FLOAT32_BLENDABLE, by which the pass counts the pixels written",
        );
    }
    if stencil && !f.contains(wgpu::Features::DEPTH32FLOAT_STENCIL8) {
        return Some("the device lacks DEPTH32FLOAT_STENCIL8, the surface that holds depth and stencil exactly");
    }
    None
}

/// The device's depth-stencil format for `surface`.
fn depth_format(surface: &DepthSurface) -> wgpu::TextureFormat {
    match surface.stencil {
        Some(_) => wgpu::TextureFormat::Depth32FloatStencil8,
        None => wgpu::TextureFormat::Depth32Float,
    }
}

/// Draws every primitive of `g` in one render pass, the alpha test
/// `alpha` and the depth and stencil tests of `surface` on the device.
pub fn draw_one_pass(
    gpu: &Gpu,
    shader: &Shader,
    g: &GeometryDraw,
    surface: Option<&DepthSurface>,
    alpha: Option<AlphaDiscard>,
) -> Result<OnePass, GpuError> {
    phases::mark("geometry (one pass): preparing");
    if let Some(why) = one_pass_lacks(gpu, surface.is_some_and(|s| s.stencil.is_some())) {
        return Err(GpuError::Unsupported(why.into()));
    }
    let (w, h) = (g.pixel.target_width, g.pixel.target_height);
    let triangles: usize = g.primitives.iter().map(Vec::len).sum();
    if g.clip.is_empty() || triangles == 0 {
        // Nothing to draw: the surface and targets stay as they are.
        geometry::check(gpu, shader, g)?;
        return Ok(OnePass {
            counts: vec![[0, 0]; triangles],
            ..Default::default()
        });
    }
    let scopes = ErrorScopes::push(gpu);
    let tests = DeviceTests {
        depth: surface.map(|s| s.store),
        alpha,
    };
    let Fragment {
        iface,
        module,
        layout,
        bindings,
    } = geometry::fragment_stage(gpu, shader, g, Some(tests), false)?;
    let counts_layout = gpu
        .device
        .create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: None,
            entries: &[super::fragment_storage(COUNTS_BINDING)],
        });
    let counts = gpu.device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("ps30 counts"),
        size: 8 * triangles.max(1) as u64,
        usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
        mapped_at_creation: false,
    });
    let counts_group = gpu.device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: None,
        layout: &counts_layout,
        entries: &[wgpu::BindGroupEntry {
            binding: COUNTS_BINDING,
            resource: counts.as_entire_binding(),
        }],
    });
    let formats = formats(&iface);
    let targets = targets(&formats);
    let depth_stencil = surface.map(|s| wgpu::DepthStencilState {
        format: depth_format(s),
        depth_write_enabled: Some(s.write),
        depth_compare: Some(s.compare.device()),
        stencil: s
            .stencil
            .as_ref()
            .map_or_else(Default::default, |t| wgpu::StencilState {
                front: t.front.device(),
                back: t.back.device(),
                read_mask: u32::from(t.mask),
                write_mask: u32::from(t.write_mask),
            }),
        bias: Default::default(),
    });
    let stages = Stages {
        fragment: module,
        layouts: &[&layout, &counts_layout],
        targets: &targets,
        depth_stencil,
    };
    let pipeline = geometry::pipeline(gpu, g, &iface, stages)?;
    let (vertices, indices) = geometry::buffers(gpu, g);
    let attachments: Vec<Option<wgpu::Texture>> = formats
        .iter()
        .map(|f| f.map(|f| super::draw::target_texture(&gpu.device, w, h, f)))
        .collect();
    let depth = surface.map(|s| depth_texture(gpu, s, w, h));
    phases::mark("geometry (one pass): pipeline");
    let resources = Resources {
        pipeline: &pipeline,
        group: &bindings.group,
        vertices: &vertices,
        indices: &indices,
        attachments: &attachments,
    };
    let mut encoder = gpu.device.create_command_encoder(&Default::default());
    if let (Some(s), Some(t)) = (surface, &depth) {
        load_surface(gpu, &mut encoder, s, t, (w, h))?;
    }
    record(
        &mut encoder,
        g,
        &resources,
        &counts_group,
        depth.as_ref().zip(surface),
        3 * triangles as u32,
    );
    let reads = Reads::record(
        gpu,
        &mut encoder,
        &attachments,
        depth.as_ref(),
        &counts,
        (w, h),
    );
    gpu.queue.submit([encoder.finish()]);
    let out = reads.take(
        gpu,
        (w, h),
        triangles,
        surface.is_some_and(|s| s.stencil.is_some()),
    )?;
    scopes.pop(gpu)?;
    phases::mark("geometry (one pass): read back");
    Ok(out)
}

/// The colour attachments by location: `oC#` unrounded, and the count of
/// pixels written at location 4.
fn formats(iface: &crate::core::translate::Interface) -> Vec<Option<wgpu::TextureFormat>> {
    let mut formats = vec![None; 5];
    for &k in &iface.outputs {
        formats[k as usize] = Some(wgpu::TextureFormat::Rgba32Float);
    }
    formats[interface::GEOMETRY_FLAGS_LOCATION as usize] = Some(wgpu::TextureFormat::R32Float);
    formats
}

/// The colour targets of `formats`: the count blended ONE + ONE, the
/// colours replaced.
fn targets(formats: &[Option<wgpu::TextureFormat>]) -> Vec<Option<wgpu::ColorTargetState>> {
    let add = wgpu::BlendComponent {
        src_factor: wgpu::BlendFactor::One,
        dst_factor: wgpu::BlendFactor::One,
        operation: wgpu::BlendOperation::Add,
    };
    formats
        .iter()
        .enumerate()
        .map(|(k, f)| {
            f.map(|format| wgpu::ColorTargetState {
                format,
                blend: (k == interface::GEOMETRY_FLAGS_LOCATION as usize).then_some(
                    wgpu::BlendState {
                        color: add,
                        alpha: add,
                    },
                ),
                write_mask: wgpu::ColorWrites::ALL,
            })
        })
        .collect()
}

fn depth_texture(gpu: &Gpu, s: &DepthSurface, w: u32, h: u32) -> wgpu::Texture {
    gpu.device.create_texture(&wgpu::TextureDescriptor {
        label: Some("ps30 depth-stencil"),
        size: wgpu::Extent3d {
            width: w,
            height: h,
            depth_or_array_layers: 1,
        },
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format: depth_format(s),
        usage: wgpu::TextureUsages::RENDER_ATTACHMENT
            | wgpu::TextureUsages::COPY_SRC
            | wgpu::TextureUsages::COPY_DST,
        view_formats: &[],
    })
}

/// Rows of `bytes_per_texel`-byte texels padded to the copy alignment.
fn padded(data: &[u8], (w, h): (u32, u32), bytes_per_texel: u32) -> (Vec<u8>, u32) {
    let row = (w * bytes_per_texel) as usize;
    let pitch = row.next_multiple_of(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT as usize);
    let mut out = vec![0u8; pitch * h as usize];
    for (y, src) in data.chunks(row).enumerate().take(h as usize) {
        out[y * pitch..y * pitch + src.len()].copy_from_slice(src);
    }
    (out, pitch as u32)
}

/// Records what puts `s`'s stored values in `texture`: the stencil values
/// copied, the depths drawn by a full-target pass.
fn load_surface(
    gpu: &Gpu,
    encoder: &mut wgpu::CommandEncoder,
    s: &DepthSurface,
    texture: &wgpu::Texture,
    (w, h): (u32, u32),
) -> Result<(), GpuError> {
    let device = &gpu.device;
    let size = wgpu::Extent3d {
        width: w,
        height: h,
        depth_or_array_layers: 1,
    };
    if let Some(t) = &s.stencil {
        let (bytes, pitch) = padded(&t.stored, (w, h), 1);
        gpu.queue.write_texture(
            wgpu::TexelCopyTextureInfo {
                texture,
                mip_level: 0,
                origin: wgpu::Origin3d::ZERO,
                aspect: wgpu::TextureAspect::StencilOnly,
            },
            &bytes,
            wgpu::TexelCopyBufferLayout {
                offset: 0,
                bytes_per_row: Some(pitch),
                rows_per_image: Some(h),
            },
            size,
        );
    }
    let stored = device.create_texture(&wgpu::TextureDescriptor {
        label: Some("ps30 stored depths"),
        size,
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format: wgpu::TextureFormat::R32Float,
        usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
        view_formats: &[],
    });
    let bytes: Vec<u8> = s.stored.iter().flat_map(|d| d.to_le_bytes()).collect();
    gpu.queue.write_texture(
        stored.as_image_copy(),
        &bytes,
        wgpu::TexelCopyBufferLayout {
            offset: 0,
            bytes_per_row: Some(4 * w),
            rows_per_image: Some(h),
        },
        size,
    );
    let module = crate::core::translate::fixed::depth_load();
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("ps30 depth load"),
        source: wgpu::ShaderSource::Naga(Cow::Owned(module)),
    });
    let pipeline = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some("ps30 depth load"),
        layout: None,
        vertex: wgpu::VertexState {
            module: &module,
            entry_point: Some("vs"),
            compilation_options: Default::default(),
            buffers: &[],
        },
        primitive: Default::default(),
        depth_stencil: Some(wgpu::DepthStencilState {
            format: depth_format(s),
            depth_write_enabled: Some(true),
            depth_compare: Some(wgpu::CompareFunction::Always),
            stencil: Default::default(),
            bias: Default::default(),
        }),
        multisample: Default::default(),
        fragment: Some(wgpu::FragmentState {
            module: &module,
            entry_point: Some("fs"),
            compilation_options: Default::default(),
            targets: &[],
        }),
        multiview_mask: None,
        cache: None,
    });
    let view = stored.create_view(&Default::default());
    let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: None,
        layout: &pipeline.get_bind_group_layout(0),
        entries: &[wgpu::BindGroupEntry {
            binding: 0,
            resource: wgpu::BindingResource::TextureView(&view),
        }],
    });
    let target = texture.create_view(&Default::default());
    let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
        label: Some("ps30 depth load"),
        color_attachments: &[],
        depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
            view: &target,
            depth_ops: Some(wgpu::Operations {
                load: wgpu::LoadOp::Clear(0.0),
                store: wgpu::StoreOp::Store,
            }),
            stencil_ops: s.stencil.as_ref().map(|_| wgpu::Operations {
                load: wgpu::LoadOp::Load,
                store: wgpu::StoreOp::Store,
            }),
        }),
        ..Default::default()
    });
    pass.set_pipeline(&pipeline);
    pass.set_bind_group(0, &group, &[]);
    pass.draw(0..3, 0..1);
    Ok(())
}

/// The draw's one render pass: targets cleared, the surface loaded as
/// [`load_surface`] left it, every triangle in one indexed draw.
fn record(
    encoder: &mut wgpu::CommandEncoder,
    g: &GeometryDraw,
    r: &Resources,
    counts: &wgpu::BindGroup,
    depth: Option<(&wgpu::Texture, &DepthSurface)>,
    index_count: u32,
) {
    let views: Vec<Option<wgpu::TextureView>> = r
        .attachments
        .iter()
        .map(|a| a.as_ref().map(|t| t.create_view(&Default::default())))
        .collect();
    let color_attachments = super::cleared_attachments(&views);
    let depth_view = depth.map(|(t, _)| t.create_view(&Default::default()));
    let load = wgpu::Operations {
        load: wgpu::LoadOp::Load,
        store: wgpu::StoreOp::Store,
    };
    let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
        label: Some("ps30 draw in one pass"),
        color_attachments: &color_attachments,
        depth_stencil_attachment: depth_view.as_ref().zip(depth).map(|(view, (_, s))| {
            wgpu::RenderPassDepthStencilAttachment {
                view,
                depth_ops: Some(load),
                stencil_ops: s.stencil.as_ref().map(|_| wgpu::Operations {
                    load: wgpu::LoadOp::Load,
                    store: wgpu::StoreOp::Store,
                }),
            }
        }),
        ..Default::default()
    });
    geometry::bind_pass(&mut pass, g, r);
    pass.set_bind_group(1, counts, &[]);
    if let Some(t) = depth.and_then(|(_, s)| s.stencil.as_ref()) {
        pass.set_stencil_reference(u32::from(t.reference));
    }
    pass.draw_indexed(0..index_count, 0, 0..1);
}

/// The read-back buffers of one pass and where they come from.
struct Reads {
    /// Per colour location: the buffer and its row pitch.
    colors: Vec<Option<(wgpu::Buffer, u32)>>,
    depth: Option<(wgpu::Buffer, u32)>,
    stencil: Option<(wgpu::Buffer, u32)>,
    counts: wgpu::Buffer,
}

impl Reads {
    /// Records the copies of every attachment, the surface's aspects and
    /// the counters into read-back buffers.
    fn record(
        gpu: &Gpu,
        encoder: &mut wgpu::CommandEncoder,
        attachments: &[Option<wgpu::Texture>],
        depth: Option<&wgpu::Texture>,
        counts: &wgpu::Buffer,
        (w, h): (u32, u32),
    ) -> Reads {
        let readback = |size: u64| {
            gpu.device.create_buffer(&wgpu::BufferDescriptor {
                label: None,
                size,
                usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
                mapped_at_creation: false,
            })
        };
        let mut copy = |texture: &wgpu::Texture, aspect, texel: u32| {
            let pitch = (w * texel).next_multiple_of(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT);
            let buffer = readback(u64::from(pitch) * u64::from(h));
            encoder.copy_texture_to_buffer(
                wgpu::TexelCopyTextureInfo {
                    texture,
                    mip_level: 0,
                    origin: wgpu::Origin3d::ZERO,
                    aspect,
                },
                wgpu::TexelCopyBufferInfo {
                    buffer: &buffer,
                    layout: wgpu::TexelCopyBufferLayout {
                        offset: 0,
                        bytes_per_row: Some(pitch),
                        rows_per_image: Some(h),
                    },
                },
                wgpu::Extent3d {
                    width: w,
                    height: h,
                    depth_or_array_layers: 1,
                },
            );
            (buffer, pitch)
        };
        let colors = attachments
            .iter()
            .map(|a| {
                a.as_ref().map(|t| {
                    let texel = t.format().block_copy_size(None).unwrap_or(16);
                    copy(t, wgpu::TextureAspect::All, texel)
                })
            })
            .collect();
        let depth_read = depth.map(|t| copy(t, wgpu::TextureAspect::DepthOnly, 4));
        let stencil = depth
            .filter(|t| t.format().has_stencil_aspect())
            .map(|t| copy(t, wgpu::TextureAspect::StencilOnly, 1));
        let counts_read = readback(counts.size());
        encoder.copy_buffer_to_buffer(counts, 0, &counts_read, 0, counts.size());
        Reads {
            colors,
            depth: depth_read,
            stencil,
            counts: counts_read,
        }
    }

    /// Maps every buffer and decodes it.
    fn take(
        self,
        gpu: &Gpu,
        (w, h): (u32, u32),
        triangles: usize,
        stencil: bool,
    ) -> Result<OnePass, GpuError> {
        let mut all: Vec<&wgpu::Buffer> = vec![&self.counts];
        all.extend(self.colors.iter().flatten().map(|(b, _)| b));
        all.extend(self.depth.iter().chain(&self.stencil).map(|(b, _)| b));
        super::draw::map_read(gpu, &all)?;
        let failed = |e: wgpu::MapRangeError| GpuError::Failed(e.to_string());
        let read = |(b, pitch): &(wgpu::Buffer, u32), texel: usize| {
            let v = b.get_mapped_range(..).map_err(failed)?;
            Ok::<Vec<Vec<u8>>, GpuError>(
                (0..h as usize)
                    .flat_map(|y| {
                        let row = &v[y * *pitch as usize..][..w as usize * texel];
                        row.chunks(texel).map(<[u8]>::to_vec).collect::<Vec<_>>()
                    })
                    .collect(),
            )
        };
        let word = |b: &[u8], i: usize| {
            u32::from_le_bytes([b[4 * i], b[4 * i + 1], b[4 * i + 2], b[4 * i + 3]])
        };
        let flags_at = interface::GEOMETRY_FLAGS_LOCATION as usize;
        let mut out = OnePass::default();
        for (k, c) in self.colors.iter().enumerate() {
            let Some(c) = c else {
                if k < flags_at {
                    out.color.push(None);
                }
                continue;
            };
            let texels = read(c, if k == flags_at { 4 } else { 16 })?;
            if k == flags_at {
                out.written = texels
                    .iter()
                    .map(|t| f32::from_bits(word(t, 0)) as u32)
                    .collect();
            } else {
                out.color.push(Some(
                    texels
                        .iter()
                        .map(|t| std::array::from_fn(|i| f32::from_bits(word(t, i))))
                        .collect(),
                ));
            }
        }
        if let Some(d) = &self.depth {
            let texels = read(d, 4)?;
            out.depth = Some(texels.iter().map(|t| f32::from_bits(word(t, 0))).collect());
        }
        if let Some(s) = self.stencil.as_ref().filter(|_| stencil) {
            out.stencil = Some(read(s, 1)?.iter().map(|t| t[0]).collect());
        }
        {
            let v = self.counts.get_mapped_range(..).map_err(failed)?;
            out.counts = (0..triangles)
                .map(|t| [word(&v, 2 * t), word(&v, 2 * t + 1)])
                .collect();
        }
        for b in all {
            b.unmap();
        }
        Ok(out)
    }
}
