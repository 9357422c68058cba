//! A draw of geometry on the device: the primitives a draw list's
//! `geometry` assembles, rasterised by the device's own rasteriser through a
//! render pipeline — a vertex stage that places each vertex, clips it
//! against the user planes and hands its values on by `@location`, and the
//! pixel shader's translation (`Entry::Geometry`) as the fragment stage,
//! its inputs interpolated by the device with perspective (or flat).
//!
//! What Direct3D 9 asks of the set-up, and how the pipeline gets it:
//!
//! * **Pixel centres.** Direct3D 9 samples pixel (i, j) at the screen point
//!   (i, j) of its viewport transform X + (1 + x/w)·W/2, Y + (1 − y/w)·H/2
//!   ("Directly Mapping Texels to Pixels (Direct3D 9)": a pixel's edges lie
//!   at half-integers). Vulkan samples it at (i + ½, j + ½) of the same
//!   transform (Vulkan 1.3, "Rasterization": fragment centres at
//!   half-integers; wgpu keeps y down in framebuffer coordinates with +y
//!   up in clip space, as Direct3D does). So every vertex moves half a
//!   pixel right and down: x_f + ½ is x/w + 1/W in normalised coordinates,
//!   y_f + ½ is y/w − 1/H, that is clip x += w/W and y −= w/H (W, H the
//!   viewport's size). The vertex stage adds exactly that, so the device
//!   tests the pixel centre Direct3D 9 tests.
//! * **Pre-transformed positions** (`positiont0`: screen x, y, z and 1/w)
//!   are turned back into clip space against a viewport of the whole
//!   target with depth 0 to 1, w = 1/rhw, and then moved as above.
//! * **Facing and culling**: Direct3D 9's front face is clockwise on screen
//!   (D3DCULL); wgpu's `FrontFace::Cw` is clockwise in framebuffer
//!   coordinates, the same screen.
//! * **Flat shading**: a triangle's provoking vertex comes first in its
//!   index list (the caller rotates it there), which is Vulkan's provoking
//!   vertex for a triangle list, so flat values are the ones D3DSHADE_FLAT
//!   takes.
//! * **User clip planes** are `clip_distances` (the feature
//!   `CLIP_DISTANCES`; without it a draw with planes is refused), each the
//!   plane's dot product with the clip-space position before the
//!   half-pixel move; the view volume is the device's own, 0 ≤ z ≤ w as
//!   in Direct3D 9.
//! * **Points** come as two triangles each, their corners set up by the
//!   caller as the emulator sets them up.
//!
//! Here each primitive is drawn in a render pass of its own and read back,
//! so that the caller can take its pixels through the alpha test, the
//! depth test and the output merger in drawing order, as the emulator does
//! with its own: the device decides coverage, interpolation and the
//! shader's results, the CPU the rest. A draw whose tests the device can
//! run itself goes to [`super::draw_one_pass`] instead, on the same
//! pipeline set-up.

use super::draw::{self, Bindings, ErrorScopes};
use super::{Gpu, GpuError};
use crate::core::emu::Draw;
use crate::core::ir::Shader;
use crate::core::phases;
use crate::core::raster::{Cull, Face, Rect, Viewport};
use crate::core::translate::interface::GeometryFog;
use crate::core::translate::{self, interface, Entry};
use std::borrow::Cow;

/// A draw of geometry as the device takes it: vertices after the vertex
/// stage and primitives after assembly.
#[derive(Clone, Debug)]
pub struct GeometryDraw<'d> {
    /// The pixel shader's draw: target size, constants, samplers, float
    /// rules (its inputs and `pixels` are not read).
    pub pixel: &'d Draw<'d>,
    /// Each vertex's clip-space position, or with `transformed` its screen
    /// (x, y, z, 1/w).
    pub positions: Vec<[f32; 4]>,
    /// Positions are pre-transformed (D3DDECLUSAGE_POSITIONT).
    pub transformed: bool,
    /// Each vertex's value for every pixel-shader input slot of `slots`.
    pub values: Vec<Vec<[f32; 4]>>,
    /// The input slot each value feeds.
    pub slots: Vec<u32>,
    /// Flat-shaded components, bit `4·slot + c`.
    pub flat: u64,
    /// Each primitive's triangles, as vertex indices, the provoking vertex
    /// first.
    pub primitives: Vec<Vec<[u32; 3]>>,
    /// D3DVIEWPORT9.
    pub viewport: Viewport,
    /// The pixels that may be drawn: viewport, scissor and target.
    pub clip: Rect,
    /// D3DRS_CULLMODE.
    pub cull: Cull,
    /// User clip planes in clip space (a, b, c, d).
    pub clip_planes: Vec<[f32; 4]>,
    /// For a fogged draw, what each pixel brings back for the fog
    /// ([`ShadedPrimitive::fog`]); with [`GeometryFog::Varying`] every
    /// vertex's `values` end with one more, its x the fog's d at the
    /// vertex.
    pub fog: Option<GeometryFog>,
}

/// One primitive's pixels as the device shaded them.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ShadedPrimitive {
    /// The target pixels it covers (index y·width + x), in row order.
    pub pixels: Vec<u32>,
    /// Whether texkill killed each.
    pub killed: Vec<bool>,
    /// Each pixel's depth: `oDepth` as written, or the rasterised z.
    pub depth: Vec<f32>,
    /// Each `oC#` the shader writes (`None` otherwise), per pixel.
    pub color: Vec<Option<Vec<[f32; 4]>>>,
    /// For a fogged draw, each pixel's d of the fog (the interpolated
    /// factor or w, or the rasterised z); empty otherwise.
    pub fog: Vec<f32>,
}

/// The most bytes of read-back one submission holds: the primitives are
/// drawn in chunks of at most this much.
const CHUNK_BYTES: u64 = 256 << 20;

/// Draws `g` of `shader` on the device, one primitive at a time; returns
/// each primitive's shaded pixels, in drawing order.
pub fn draw_geometry(
    gpu: &Gpu,
    shader: &Shader,
    g: &GeometryDraw,
) -> Result<Vec<ShadedPrimitive>, GpuError> {
    phases::mark("geometry: preparing");
    let (w, h) = (g.pixel.target_width, g.pixel.target_height);
    if g.clip.is_empty() || g.primitives.is_empty() {
        check(gpu, shader, g)?;
        return Ok(vec![ShadedPrimitive::default(); g.primitives.len()]);
    }
    let scopes = ErrorScopes::push(gpu);
    let Fragment {
        iface,
        module,
        layout,
        bindings,
    } = fragment_stage(gpu, shader, g, None, false)?;
    let formats = attachment_formats(&iface, g.fog.is_some());
    let targets: Vec<Option<wgpu::ColorTargetState>> =
        formats.iter().map(|f| f.map(Into::into)).collect();
    let stages = Stages {
        fragment: module,
        layouts: &[&layout],
        targets: &targets,
        depth_stencil: None,
    };
    let pipeline = pipeline(gpu, g, &iface, stages)?;
    let (vertices, indices) = buffers(gpu, g);
    let attachments: Vec<Option<wgpu::Texture>> = formats
        .iter()
        .map(|f| f.map(|f| draw::target_texture(&gpu.device, w, h, f)))
        .collect();
    scopes.pop(gpu)?;
    phases::mark("geometry: pipeline");
    let per_primitive: u64 = formats
        .iter()
        .flatten()
        .map(|f| u64::from(pitch(w, f)) * u64::from(h))
        .sum();
    let chunk = (CHUNK_BYTES / per_primitive.max(1)).max(1) as usize;
    let mut out = Vec::with_capacity(g.primitives.len());
    let mut first_index = 0u32;
    for (c, prims) in g.primitives.chunks(chunk).enumerate() {
        let resources = Resources {
            pipeline: &pipeline,
            group: &bindings.group,
            vertices: &vertices,
            indices: &indices,
            attachments: &attachments,
        };
        let shaded = draw_chunk(gpu, g, &resources, &formats, prims, first_index)?;
        first_index += prims.iter().map(|p| 3 * p.len() as u32).sum::<u32>();
        out.extend(shaded);
        phases::mark(&format!("geometry: chunk {c} read back"));
    }
    Ok(out)
}

/// What a draw of geometry must have before anything is made: a shader
/// and draw the device can run, and the clip distances its planes need.
pub(super) fn check(gpu: &Gpu, shader: &Shader, g: &GeometryDraw) -> Result<(), GpuError> {
    draw::refuse(gpu, shader, g.pixel)?;
    if !g.clip_planes.is_empty() && !gpu.features.contains(wgpu::Features::CLIP_DISTANCES) {
        return Err(GpuError::Unsupported(
            "user clip planes need the device feature CLIP_DISTANCES, which this device lacks"
                .into(),
        ));
    }
    Ok(())
}

/// The translated pixel shader and its group-0 bindings, uploaded.
pub(super) struct Fragment {
    pub iface: translate::Interface,
    pub module: naga::Module,
    pub layout: wgpu::BindGroupLayout,
    pub bindings: Bindings,
}

/// Checks `g`, translates `shader` as its fragment stage (`tests` and
/// `records` as [`Entry::Geometry`] takes them) and uploads what it binds.
pub(super) fn fragment_stage(
    gpu: &Gpu,
    shader: &Shader,
    g: &GeometryDraw,
    tests: Option<translate::device_tests::DeviceTests>,
    records: bool,
) -> Result<Fragment, GpuError> {
    check(gpu, shader, g)?;
    let draw = g.pixel;
    let mut spec = draw::specialisation(gpu, shader, draw)?;
    // Interpolated inputs arrive as the device made them: the shader
    // flushes them itself where the float rules flush.
    spec.set_inputs_flushed(false);
    let entry = Entry::Geometry {
        flat: g.flat,
        fog: if tests.is_none() { g.fog } else { None },
        tests,
        records,
    };
    let t = translate::translate_specialised(shader, draw.float_rules, entry, &spec)
        .map_err(GpuError::Translate)?;
    let iface = t.interface;
    let layout = draw::bind_group_layout(gpu, &iface, false);
    let bindings = Bindings::new(gpu, draw, &iface, (&layout, false))?;
    Ok(Fragment {
        iface,
        module: t.module,
        layout,
        bindings,
    })
}

/// The pipeline's objects one chunk of primitives is drawn with.
pub(super) struct Resources<'r> {
    pub pipeline: &'r wgpu::RenderPipeline,
    pub group: &'r wgpu::BindGroup,
    pub vertices: &'r wgpu::Buffer,
    pub indices: &'r wgpu::Buffer,
    pub attachments: &'r [Option<wgpu::Texture>],
}

/// The colour attachments by location: `oC#` unrounded, the flags, the
/// depth, and for a fogged draw the fog's d.
fn attachment_formats(iface: &translate::Interface, fog: bool) -> Vec<Option<wgpu::TextureFormat>> {
    let mut formats = vec![None; 6];
    if fog {
        formats.push(Some(wgpu::TextureFormat::R32Float));
    }
    for &k in &iface.outputs {
        formats[k as usize] = Some(wgpu::TextureFormat::Rgba32Float);
    }
    formats[interface::GEOMETRY_FLAGS_LOCATION as usize] = Some(wgpu::TextureFormat::R32Uint);
    formats[interface::GEOMETRY_DEPTH_LOCATION as usize] = Some(wgpu::TextureFormat::R32Float);
    formats
}

/// Bytes per read-back row of a `w`-texel row of `format`.
pub(super) fn pitch(w: u32, format: &wgpu::TextureFormat) -> u32 {
    let texel = format.block_copy_size(None).unwrap_or(16);
    (w * texel).div_ceil(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT) * wgpu::COPY_BYTES_PER_ROW_ALIGNMENT
}

/// The vertex stage: the position placed as the module docs say, the user
/// planes' distances, and each value at its locations.
fn vertex_stage(g: &GeometryDraw, iface: &translate::Interface) -> naga::Module {
    let locations = interface::geometry_locations(&iface.inputs, g.flat);
    let (tw, th) = (g.pixel.target_width as f32, g.pixel.target_height as f32);
    let (vw, vh) = (g.viewport.width as f32, g.viewport.height as f32);
    translate::fixed::geometry_vertex(&translate::fixed::GeometryStage {
        locations: &locations,
        slots: &g.slots,
        screen: g.transformed.then_some((2.0 / tw, 2.0 / th)),
        offset: if g.transformed {
            (1.0 / tw, 1.0 / th)
        } else {
            (1.0 / vw, 1.0 / vh)
        },
        clip_planes: &g.clip_planes,
        fog: (g.fog == Some(GeometryFog::Varying))
            .then(|| interface::geometry_fog_location(&iface.inputs, g.flat)),
    })
}

/// What a geometry pipeline is made of besides its vertex stage.
pub(super) struct Stages<'s> {
    /// The translated pixel shader.
    pub fragment: naga::Module,
    /// The bind-group layouts, group 0 first.
    pub layouts: &'s [&'s wgpu::BindGroupLayout],
    /// The colour targets by location.
    pub targets: &'s [Option<wgpu::ColorTargetState>],
    /// The depth-stencil state, where the device tests.
    pub depth_stencil: Option<wgpu::DepthStencilState>,
}

/// The render pipeline: the vertex stage of [`vertex_stage`] and the
/// translated pixel shader.
pub(super) fn pipeline(
    gpu: &Gpu,
    g: &GeometryDraw,
    iface: &translate::Interface,
    stages: Stages,
) -> Result<wgpu::RenderPipeline, GpuError> {
    let Stages {
        fragment,
        layouts,
        targets,
        depth_stencil,
    } = stages;
    let device = &gpu.device;
    let vertex = vertex_stage(g, iface);
    let vs = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("ps30 geometry vertex stage"),
        source: wgpu::ShaderSource::Naga(Cow::Owned(vertex)),
    });
    let fs = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("ps30 translated shader"),
        source: wgpu::ShaderSource::Naga(Cow::Owned(fragment)),
    });
    let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
        label: None,
        bind_group_layouts: &layouts.iter().map(|l| Some(*l)).collect::<Vec<_>>(),
        immediate_size: 0,
    });
    let values = g.slots.len() as u32 + u32::from(g.fog == Some(GeometryFog::Varying));
    let attributes: Vec<wgpu::VertexAttribute> = (0..=values)
        .map(|k| wgpu::VertexAttribute {
            format: wgpu::VertexFormat::Float32x4,
            offset: 16 * u64::from(k),
            shader_location: k,
        })
        .collect();
    let stride = 16 * (1 + u64::from(values));
    let cull_mode = match (g.cull.drops(Face::Front), g.cull.drops(Face::Back)) {
        (true, _) => Some(wgpu::Face::Front),
        (_, true) => Some(wgpu::Face::Back),
        _ => None,
    };
    Ok(
        device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some("ps30 geometry"),
            layout: Some(&layout),
            vertex: wgpu::VertexState {
                module: &vs,
                entry_point: Some("vs"),
                compilation_options: Default::default(),
                buffers: &[Some(wgpu::VertexBufferLayout {
                    array_stride: stride,
                    step_mode: wgpu::VertexStepMode::Vertex,
                    attributes: &attributes,
                })],
            },
            primitive: wgpu::PrimitiveState {
                topology: wgpu::PrimitiveTopology::TriangleList,
                front_face: wgpu::FrontFace::Cw,
                cull_mode,
                ..Default::default()
            },
            depth_stencil,
            multisample: Default::default(),
            fragment: Some(wgpu::FragmentState {
                module: &fs,
                entry_point: Some("ps30_geometry"),
                compilation_options: Default::default(),
                targets,
            }),
            multiview_mask: None,
            cache: None,
        }),
    )
}

/// The vertex buffer (position then each value, per vertex) and the index
/// buffer (every primitive's triangles in order).
pub(super) fn buffers(gpu: &Gpu, g: &GeometryDraw) -> (wgpu::Buffer, wgpu::Buffer) {
    let mut bytes: Vec<u8> = Vec::new();
    for (p, values) in g.positions.iter().zip(&g.values) {
        for v in std::iter::once(p).chain(values) {
            for x in v {
                bytes.extend_from_slice(&x.to_le_bytes());
            }
        }
    }
    let mut index_bytes: Vec<u8> = Vec::new();
    for t in g.primitives.iter().flatten() {
        for i in t {
            index_bytes.extend_from_slice(&i.to_le_bytes());
        }
    }
    let make = |data: &[u8], usage: wgpu::BufferUsages| {
        let b = gpu.device.create_buffer(&wgpu::BufferDescriptor {
            label: None,
            size: (data.len() as u64).next_multiple_of(4).max(4),
            usage: usage | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let mut padded = data.to_vec();
        padded.resize(padded.len().next_multiple_of(4).max(4), 0);
        gpu.queue.write_buffer(&b, 0, &padded);
        b
    };
    (
        make(&bytes, wgpu::BufferUsages::VERTEX),
        make(&index_bytes, wgpu::BufferUsages::INDEX),
    )
}

/// Draws `prims` (whose first index is `first_index`), each into cleared
/// attachments copied to its own part of the read-back buffers; reads them
/// back and keeps each primitive's covered pixels.
fn draw_chunk(
    gpu: &Gpu,
    g: &GeometryDraw,
    r: &Resources,
    formats: &[Option<wgpu::TextureFormat>],
    prims: &[Vec<[u32; 3]>],
    first_index: u32,
) -> Result<Vec<ShadedPrimitive>, GpuError> {
    let (w, h) = (g.pixel.target_width, g.pixel.target_height);
    let device = &gpu.device;
    let scopes = ErrorScopes::push(gpu);
    let readbacks: Vec<Option<(wgpu::Buffer, u32, u32)>> = formats
        .iter()
        .map(|f| {
            f.map(|f| {
                let pitch = pitch(w, &f);
                let buffer = device.create_buffer(&wgpu::BufferDescriptor {
                    label: None,
                    size: u64::from(pitch) * u64::from(h) * prims.len() as u64,
                    usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
                    mapped_at_creation: false,
                });
                (buffer, pitch, f.block_copy_size(None).unwrap_or(16))
            })
        })
        .collect();
    let views: Vec<Option<wgpu::TextureView>> = r
        .attachments
        .iter()
        .map(|a| a.as_ref().map(|t| t.create_view(&Default::default())))
        .collect();
    let mut encoder = device.create_command_encoder(&Default::default());
    let mut index = first_index;
    for (p, prim) in prims.iter().enumerate() {
        let count = 3 * prim.len() as u32;
        record_primitive(&mut encoder, g, r, &views, index..index + count);
        index += count;
        for (a, rb) in r.attachments.iter().zip(&readbacks) {
            let (Some(texture), Some((buffer, pitch, _))) = (a, rb) else {
                continue;
            };
            encoder.copy_texture_to_buffer(
                texture.as_image_copy(),
                wgpu::TexelCopyBufferInfo {
                    buffer,
                    layout: wgpu::TexelCopyBufferLayout {
                        offset: u64::from(*pitch) * u64::from(h) * p as u64,
                        bytes_per_row: Some(*pitch),
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
    gpu.queue.submit([encoder.finish()]);
    let buffers: Vec<&wgpu::Buffer> = readbacks.iter().flatten().map(|(b, _, _)| b).collect();
    draw::map_read(gpu, &buffers)?;
    let shaded = decode(g, formats, &readbacks, prims.len())?;
    for b in &buffers {
        b.unmap();
    }
    scopes.pop(gpu)?;
    Ok(shaded)
}

/// One primitive's render pass: attachments cleared, its triangles drawn
/// under the viewport and the clip rectangle.
fn record_primitive(
    encoder: &mut wgpu::CommandEncoder,
    g: &GeometryDraw,
    r: &Resources,
    views: &[Option<wgpu::TextureView>],
    indices: std::ops::Range<u32>,
) {
    let color_attachments = super::cleared_attachments(views);
    let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
        label: Some("ps30 primitive"),
        color_attachments: &color_attachments,
        ..Default::default()
    });
    bind_pass(&mut pass, g, r);
    pass.draw_indexed(indices, 0, 0..1);
}

/// Sets the pass's viewport, scissor, pipeline and buffers for `g`.
pub(super) fn bind_pass(pass: &mut wgpu::RenderPass, g: &GeometryDraw, r: &Resources) {
    let v = match g.transformed {
        true => Viewport::whole(g.pixel.target_width, g.pixel.target_height),
        false => g.viewport,
    };
    pass.set_viewport(
        v.x as f32,
        v.y as f32,
        v.width as f32,
        v.height as f32,
        v.min_z,
        v.max_z,
    );
    let c = g.clip;
    pass.set_scissor_rect(c.left, c.top, c.right - c.left, c.bottom - c.top);
    pass.set_pipeline(r.pipeline);
    pass.set_bind_group(0, r.group, &[]);
    pass.set_vertex_buffer(0, r.vertices.slice(..));
    pass.set_index_buffer(r.indices.slice(..), wgpu::IndexFormat::Uint32);
}

/// Each primitive's covered pixels from the mapped read-back buffers.
fn decode(
    g: &GeometryDraw,
    formats: &[Option<wgpu::TextureFormat>],
    readbacks: &[Option<(wgpu::Buffer, u32, u32)>],
    count: usize,
) -> Result<Vec<ShadedPrimitive>, GpuError> {
    let (w, h) = (
        g.pixel.target_width as usize,
        g.pixel.target_height as usize,
    );
    let views = readbacks
        .iter()
        .map(|r| {
            r.as_ref()
                .map(|(b, pitch, texel)| {
                    b.get_mapped_range(..)
                        .map(|v| (v, *pitch as usize, *texel as usize))
                })
                .transpose()
        })
        .collect::<Result<Vec<_>, _>>()
        .map_err(|e| GpuError::Failed(e.to_string()))?;
    let texel = |a: usize, p: usize, x: usize, y: usize| -> &[u8] {
        let (v, pitch, size) = views[a].as_ref().expect("a read-back attachment");
        let at = (p * h + y) * pitch + x * size;
        &v[at..at + size]
    };
    let word = |b: &[u8], i: usize| {
        u32::from_le_bytes([b[4 * i], b[4 * i + 1], b[4 * i + 2], b[4 * i + 3]])
    };
    let flags_at = interface::GEOMETRY_FLAGS_LOCATION as usize;
    let depth_at = interface::GEOMETRY_DEPTH_LOCATION as usize;
    let fog_at = interface::GEOMETRY_FOG_LOCATION as usize;
    let mut out = Vec::with_capacity(count);
    for p in 0..count {
        let mut s = ShadedPrimitive {
            color: (0..4).map(|k| formats[k].map(|_| Vec::new())).collect(),
            ..Default::default()
        };
        for y in 0..h {
            for x in 0..w {
                let flags = word(texel(flags_at, p, x, y), 0);
                if flags & 1 == 0 {
                    continue;
                }
                s.pixels.push((y * w + x) as u32);
                s.killed.push(flags & 2 != 0);
                s.depth
                    .push(f32::from_bits(word(texel(depth_at, p, x, y), 0)));
                if g.fog.is_some() {
                    s.fog.push(f32::from_bits(word(texel(fog_at, p, x, y), 0)));
                }
                for (k, c) in s.color.iter_mut().enumerate() {
                    if let Some(c) = c {
                        let b = texel(k, p, x, y);
                        c.push(std::array::from_fn(|i| f32::from_bits(word(b, i))));
                    }
                }
            }
        }
        out.push(s);
    }
    Ok(out)
}
