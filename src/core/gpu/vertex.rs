//! Vertex shaders on the device: the translation's compute entry point
//! (`translate::vertex`) over a vertex list, one invocation per vertex, its
//! output rows read back unrounded — the GPU half of `emu::vertex::run`,
//! returning the same [`VertexOutput`] (without executed counts: a device
//! counts nothing).
//!
//! The inputs go up as 16 `vec4`s per vertex (v0–v15, each declared `v#`
//! from its attribute, zeros elsewhere, as the emulator fills them), the
//! constants as one uniform block in the translation's vertex layout (c0–c255
//! with the shader's `def`s over the application's, so that relative reads
//! see them, then i0–i15 and b0–b15).

use super::{Gpu, GpuError};
use crate::core::emu::vertex::{self, VertexDraw, VertexOutput, Vertices};
use crate::core::ir::Shader;
use crate::core::translate::interface;
use crate::core::translate::vertex as tv;
use std::borrow::Cow;

/// Runs `shader` over `vertices` on `gpu` with `draw`'s constants and
/// vertex textures: what [`vertex::run`] computes, with `executed` empty.
pub fn run_vertices(
    gpu: &Gpu,
    shader: &Shader,
    draw: &VertexDraw,
    vertices: &Vertices,
) -> Result<VertexOutput, GpuError> {
    let bound = vertex::check(shader, draw, vertices).map_err(GpuError::Vertices)?;
    let t = tv::translate_vertex(shader, draw.float_rules).map_err(GpuError::Translate)?;
    let slots: Vec<(usize, vertex::OutputSlot)> = vertex::outputs(shader);
    let count = vertices.count;
    if count == 0 {
        return Ok(VertexOutput {
            slots: slots.into_iter().map(|(_, s)| s).collect(),
            values: Vec::new(),
            executed: Vec::new(),
        });
    }
    let rows = tv::ROWS as usize;
    let out_bytes = (count * rows * 16) as u64;
    let in_bytes = (count * tv::INPUT_ROWS as usize * 16) as u64;
    let max = gpu.limits.max_storage_buffer_binding_size;
    if out_bytes.max(in_bytes) > max {
        return Err(GpuError::Unsupported(format!(
            "{count} vertices: their {out_bytes} bytes of outputs pass the device's storage buffer limit of {max} bytes"
        )));
    }
    let groups = count.div_ceil(tv::WORKGROUP as usize) as u64;
    let most = u64::from(gpu.limits.max_compute_workgroups_per_dimension);
    if groups > most {
        return Err(GpuError::Unsupported(format!(
            "{count} vertices: {groups} workgroups of {}, past the device's {most}",
            tv::WORKGROUP
        )));
    }
    let mut input = Vec::with_capacity(count * tv::INPUT_ROWS as usize);
    for v in 0..count {
        input.extend(vertex::vertex_inputs(&bound, vertices, v));
    }
    let scopes = super::draw::ErrorScopes::push(gpu);
    let mut block = constant_block(shader, draw);
    let textures = textures(gpu, shader, draw, &mut block)?;
    let out = dispatch(gpu, t.module, (&block, &textures), &input, out_bytes)?;
    scopes.pop(gpu)?;
    let values = (0..count)
        .map(|v| {
            slots
                .iter()
                .map(|(row, _)| out[v * rows + row])
                .collect::<Vec<_>>()
        })
        .collect();
    Ok(VertexOutput {
        slots: slots.into_iter().map(|(_, s)| s).collect(),
        values,
        executed: Vec::new(),
    })
}

/// The uniform block's bytes in `translate::vertex`'s layout.
fn constant_block(shader: &Shader, draw: &VertexDraw) -> Vec<u8> {
    let (floats, ints, bools) = vertex::effective_constants(shader, &draw.constants);
    let mut bytes = vec![0u8; tv::CONSTANTS_SIZE as usize];
    let mut put = |at: usize, word: u32| bytes[at..at + 4].copy_from_slice(&word.to_le_bytes());
    for (r, v) in floats.iter().enumerate() {
        for (c, x) in v.iter().enumerate() {
            put(r * 16 + c * 4, x.to_bits());
        }
    }
    for (r, v) in ints.iter().enumerate() {
        for (c, x) in v.iter().enumerate() {
            put(tv::INTS_OFFSET as usize + r * 16 + c * 4, *x as u32);
        }
    }
    for (r, b) in bools.iter().enumerate() {
        put(tv::BOOLS_OFFSET as usize + r * 16, u32::from(*b));
    }
    bytes
}

/// A declared sampler's view and sampler, with its texture and sampler
/// bindings.
struct Bound {
    register: u32,
    view: wgpu::TextureView,
    sampler: wgpu::Sampler,
    dimension: wgpu::TextureViewDimension,
}

/// Every sampler `shader` declares (`texldl`'s vertex textures): uploaded
/// and mapped as a pixel shader's are (`draw::bind_sampler`), each
/// record written into `block`.
fn textures(
    gpu: &Gpu,
    shader: &Shader,
    draw: &VertexDraw,
    block: &mut [u8],
) -> Result<Vec<Bound>, GpuError> {
    let mut pixel = crate::core::emu::Draw::new(1, 1);
    pixel.samplers = draw.samplers.clone();
    pixel.float_rules = draw.float_rules;
    let records = &mut block[tv::SAMPLERS_OFFSET as usize..];
    shader
        .program()
        .samplers
        .iter()
        .map(|d| {
            let (view, sampler) = super::draw::bind_sampler(gpu, &pixel, d.index, d.ty, records)?;
            Ok(Bound {
                register: d.index,
                view,
                sampler,
                dimension: super::texture::view_dimension(d.ty),
            })
        })
        .collect()
}

/// The layout entries of `textures`, seen by the compute stage.
fn texture_entries(gpu: &Gpu, textures: &[Bound]) -> Vec<wgpu::BindGroupLayoutEntry> {
    let filterable = gpu.float32_filterable();
    let entry = |binding, ty| wgpu::BindGroupLayoutEntry {
        binding,
        visibility: wgpu::ShaderStages::COMPUTE,
        ty,
        count: None,
    };
    textures
        .iter()
        .flat_map(|b| {
            let kind = match filterable {
                true => wgpu::SamplerBindingType::Filtering,
                false => wgpu::SamplerBindingType::NonFiltering,
            };
            [
                entry(
                    interface::texture_binding(b.register),
                    super::draw::texture_type(filterable, b.dimension),
                ),
                entry(
                    interface::sampler_binding(b.register),
                    wgpu::BindingType::Sampler(kind),
                ),
            ]
        })
        .collect()
}

/// Compiles `module`, runs it over the inputs and reads the output rows back.
fn dispatch(
    gpu: &Gpu,
    module: naga::Module,
    (constants, textures): (&[u8], &[Bound]),
    input: &[[f32; 4]],
    out_bytes: u64,
) -> Result<Vec<[f32; 4]>, GpuError> {
    use wgpu::util::DeviceExt;
    let device = &gpu.device;
    let shader = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("ps30 vertex shader"),
        source: wgpu::ShaderSource::Naga(Cow::Owned(module)),
    });
    // An explicit layout: a shader that reads no constant (or no input)
    // still binds all three buffers.
    let buffer_entry = super::compute_buffer;
    let mut entries = vec![
        buffer_entry(
            interface::CONSTANTS_BINDING,
            wgpu::BufferBindingType::Uniform,
        ),
        buffer_entry(
            tv::INPUTS_BINDING,
            wgpu::BufferBindingType::Storage { read_only: true },
        ),
        buffer_entry(
            tv::OUTPUTS_BINDING,
            wgpu::BufferBindingType::Storage { read_only: false },
        ),
    ];
    entries.extend(texture_entries(gpu, textures));
    let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some("ps30 vertex bindings"),
        entries: &entries,
    });
    let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
        label: Some("ps30 vertices"),
        bind_group_layouts: &[Some(&layout)],
        immediate_size: 0,
    });
    let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
        label: Some("ps30 vertices"),
        layout: Some(&pipeline_layout),
        module: &shader,
        entry_point: Some(tv::ENTRY),
        compilation_options: Default::default(),
        cache: None,
    });
    let init = |label, contents: &[u8], usage| {
        device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some(label),
            contents,
            usage,
        })
    };
    let uniform = init(
        "ps30 vertex constants",
        constants,
        wgpu::BufferUsages::UNIFORM,
    );
    let inputs = init(
        "ps30 vertex inputs",
        bytemuck::cast_slice(input),
        wgpu::BufferUsages::STORAGE,
    );
    let outputs = device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("ps30 vertex outputs"),
        size: out_bytes,
        usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
        mapped_at_creation: false,
    });
    let readback = device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("ps30 vertex read-back"),
        size: out_bytes,
        usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
        mapped_at_creation: false,
    });
    let mut group_entries = vec![
        bind_entry(interface::CONSTANTS_BINDING, &uniform),
        bind_entry(tv::INPUTS_BINDING, &inputs),
        bind_entry(tv::OUTPUTS_BINDING, &outputs),
    ];
    for b in textures {
        group_entries.push(wgpu::BindGroupEntry {
            binding: interface::texture_binding(b.register),
            resource: wgpu::BindingResource::TextureView(&b.view),
        });
        group_entries.push(wgpu::BindGroupEntry {
            binding: interface::sampler_binding(b.register),
            resource: wgpu::BindingResource::Sampler(&b.sampler),
        });
    }
    let bind = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: None,
        layout: &layout,
        entries: &group_entries,
    });
    let vertices = input.len() as u32 / tv::INPUT_ROWS;
    let mut encoder = device.create_command_encoder(&Default::default());
    {
        let mut pass = encoder.begin_compute_pass(&Default::default());
        pass.set_pipeline(&pipeline);
        pass.set_bind_group(0, &bind, &[]);
        pass.dispatch_workgroups(vertices.div_ceil(tv::WORKGROUP), 1, 1);
    }
    encoder.copy_buffer_to_buffer(&outputs, 0, &readback, 0, out_bytes);
    gpu.queue.submit([encoder.finish()]);
    let (tx, rx) = std::sync::mpsc::channel();
    readback.map_async(wgpu::MapMode::Read, .., move |res| {
        let _ = tx.send(res);
    });
    device
        .poll(wgpu::PollType::wait_indefinitely())
        .map_err(|e| GpuError::Failed(e.to_string()))?;
    rx.recv()
        .map_err(|e| GpuError::Failed(e.to_string()))?
        .map_err(|e| GpuError::Failed(format!("reading the vertex outputs back: {e}")))?;
    let data = readback
        .get_mapped_range(..)
        .map_err(|e| GpuError::Failed(format!("reading the vertex outputs back: {e}")))?;
    let values: Vec<[f32; 4]> = bytemuck::cast_slice(&data).to_vec();
    drop(data);
    readback.unmap();
    Ok(values)
}

fn bind_entry(binding: u32, buffer: &wgpu::Buffer) -> wgpu::BindGroupEntry<'_> {
    wgpu::BindGroupEntry {
        binding,
        resource: buffer.as_entire_binding(),
    }
}
