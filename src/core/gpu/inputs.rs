//! A large draw's inputs made on the device instead of uploaded: each `v#`
//! is the emulator's `base + x·ddx + y·ddy` ([`LinearInput::at`]), which
//! the CPU evaluates as `(base + x·ddx) + y·ddy` in f32. The first term
//! depends on the column alone and the second on the row alone, so the CPU
//! works out one value per column and one per row (w + h instead of w·h)
//! and a compute shader adds the two for every texel. A 3840×2160 frame's
//! inputs are 133 MB a register to fill and send; these vectors are 96 KB.
//!
//! The device's sum is the CPU's only where it is exact to say so: Vulkan
//! rounds an f32 addition correctly, but may flush subnormal operands and
//! results and need not keep the sign of a zero. So the fill is used only
//! when every column and row value is finite, not −0, and either 0 or at
//! least 2⁻¹⁰³ in magnitude: both terms are then multiples of 2⁻¹²⁶ (the
//! spacing of floats at 2⁻¹⁰³), so a sum that is not zero is at least
//! 2⁻¹²⁶ — a normal float, which no flush touches, on the CPU either — and
//! a zero sum is +0 on both (x + (−x) rounds to +0, and no −0 is added).
//! Otherwise the inputs are evaluated on the CPU as before.

use super::{Gpu, GpuError};
use crate::core::emu::LinearInput;

/// Each column's and each row's term of one input, per channel.
struct Terms {
    columns: Vec<[f32; 4]>,
    rows: Vec<[f32; 4]>,
}

/// The smallest magnitude a non-zero term may have (2⁻¹⁰³).
const SMALLEST: f32 = f32::from_bits(24 << 23);

/// Whether `v` keeps the device's sum exact (module comment).
fn exact_term(v: f32) -> bool {
    v.is_finite() && !(v == 0.0 && v.is_sign_negative()) && (v == 0.0 || v.abs() >= SMALLEST)
}

impl Terms {
    /// The terms of `input` over a `w × h` target, or `None` where the
    /// device's sum might differ from the CPU's.
    fn of(input: &LinearInput, w: u32, h: u32) -> Option<Terms> {
        let columns: Vec<[f32; 4]> = (0..w)
            .map(|x| std::array::from_fn(|c| input.base[c] + x as f32 * input.ddx[c]))
            .collect();
        let rows: Vec<[f32; 4]> = (0..h)
            .map(|y| std::array::from_fn(|c| y as f32 * input.ddy[c]))
            .collect();
        let exact = columns
            .iter()
            .chain(&rows)
            .flatten()
            .all(|&v| exact_term(v));
        exact.then_some(Terms { columns, rows })
    }
}

/// The compute pipeline that adds the terms (made once per device).
pub(crate) struct Fill {
    pipeline: wgpu::ComputePipeline,
    layout: wgpu::BindGroupLayout,
}

impl Fill {
    fn new(device: &wgpu::Device) -> Result<Fill, GpuError> {
        let fill = crate::core::translate::fixed::inputs_fill();
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("ps30 inputs"),
            source: wgpu::ShaderSource::Naga(std::borrow::Cow::Owned(fill)),
        });
        let buffer = super::compute_buffer;
        let storage = wgpu::BufferBindingType::Storage { read_only: true };
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: None,
            entries: &[
                buffer(0, wgpu::BufferBindingType::Uniform),
                buffer(1, storage),
                buffer(2, storage),
                wgpu::BindGroupLayoutEntry {
                    binding: 3,
                    visibility: wgpu::ShaderStages::COMPUTE,
                    ty: wgpu::BindingType::StorageTexture {
                        access: wgpu::StorageTextureAccess::WriteOnly,
                        format: wgpu::TextureFormat::Rgba32Float,
                        view_dimension: wgpu::TextureViewDimension::D2Array,
                    },
                    count: None,
                },
            ],
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: None,
            bind_group_layouts: &[Some(&layout)],
            immediate_size: 0,
        });
        let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: Some("ps30 inputs"),
            layout: Some(&pipeline_layout),
            module: &module,
            entry_point: Some("fill"),
            compilation_options: Default::default(),
            cache: None,
        });
        Ok(Fill { pipeline, layout })
    }
}

/// The texture usage an input texture needs for [`fill`].
pub(super) const USAGE: wgpu::TextureUsages = wgpu::TextureUsages::STORAGE_BINDING;

/// Fills `texture` (`w × h`, one layer per input of `inputs`) on the
/// device; returns `false`, having done nothing, where the sums might not
/// be the CPU's (module comment).
pub(super) fn fill(
    gpu: &Gpu,
    texture: &wgpu::Texture,
    inputs: &[LinearInput],
    (w, h): (u32, u32),
) -> Result<bool, GpuError> {
    let mut columns = Vec::with_capacity(w as usize * inputs.len());
    let mut rows = Vec::with_capacity(h as usize * inputs.len());
    for input in inputs {
        match Terms::of(input, w, h) {
            Some(t) => {
                columns.extend(t.columns);
                rows.extend(t.rows);
            }
            None => return Ok(false),
        }
    }
    let limit = gpu.limits.max_storage_buffer_binding_size as usize;
    if columns.len() * 16 > limit || rows.len() * 16 > limit || inputs.is_empty() {
        return Ok(false);
    }
    let fill = match gpu
        .fill
        .get_or_init(|| Fill::new(&gpu.device).map_err(|e| e.to_string()))
    {
        Ok(f) => f,
        Err(e) => return Err(GpuError::Failed(e.clone())),
    };
    let device = &gpu.device;
    let storage = |data: &[[f32; 4]]| {
        let buffer = device.create_buffer(&wgpu::BufferDescriptor {
            label: None,
            size: (data.len() * 16) as u64,
            usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        gpu.queue
            .write_buffer(&buffer, 0, bytemuck::cast_slice(data));
        buffer
    };
    let size = device.create_buffer(&wgpu::BufferDescriptor {
        label: None,
        size: 16,
        usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    });
    let layers = inputs.len() as u32;
    gpu.queue
        .write_buffer(&size, 0, bytemuck::cast_slice(&[w, h, layers, 0]));
    let (columns, rows) = (storage(&columns), storage(&rows));
    let view = texture.create_view(&wgpu::TextureViewDescriptor {
        dimension: Some(wgpu::TextureViewDimension::D2Array),
        ..Default::default()
    });
    let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: None,
        layout: &fill.layout,
        entries: &[
            wgpu::BindGroupEntry {
                binding: 0,
                resource: size.as_entire_binding(),
            },
            wgpu::BindGroupEntry {
                binding: 1,
                resource: columns.as_entire_binding(),
            },
            wgpu::BindGroupEntry {
                binding: 2,
                resource: rows.as_entire_binding(),
            },
            wgpu::BindGroupEntry {
                binding: 3,
                resource: wgpu::BindingResource::TextureView(&view),
            },
        ],
    });
    let mut encoder = device.create_command_encoder(&Default::default());
    {
        let mut pass = encoder.begin_compute_pass(&Default::default());
        pass.set_pipeline(&fill.pipeline);
        pass.set_bind_group(0, &group, &[]);
        pass.dispatch_workgroups(w.div_ceil(16), h.div_ceil(16), layers);
    }
    gpu.queue.submit([encoder.finish()]);
    Ok(true)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn input(base: f32, ddx: f32, ddy: f32) -> LinearInput {
        LinearInput {
            base: [base, 0.5, 0.0, 1.0],
            ddx: [ddx, 0.0, 0.0, 0.0],
            ddy: [ddy, 0.25, 0.0, 0.0],
        }
    }

    #[test]
    fn texel_centres_are_summed_on_the_device() {
        // `tonemap`'s v0 over a 3840×2160 frame.
        let v0 = LinearInput {
            base: [0.5 / 3840.0, 0.5 / 2160.0, 0.0, 0.0],
            ddx: [1.0 / 3840.0, 0.0, 0.0, 0.0],
            ddy: [0.0, 1.0 / 2160.0, 0.0, 0.0],
        };
        let t = Terms::of(&v0, 3840, 2160).expect("exact");
        assert_eq!((t.columns.len(), t.rows.len()), (3840, 2160));
        // Each texel is the column term plus the row term, the CPU's
        // (base + x·ddx) + y·ddy.
        for (x, y) in [(0, 0), (17, 1000), (3839, 2159)] {
            let sum: [f32; 4] = std::array::from_fn(|c| t.columns[x][c] + t.rows[y][c]);
            assert_eq!(sum, v0.at(x as f32, y as f32));
        }
    }

    #[test]
    fn terms_that_a_device_may_flush_or_sign_differently_are_refused() {
        assert!(Terms::of(&input(1.0, 0.5, 0.25), 64, 64).is_some());
        // 1e-40 is subnormal; 2⁻¹⁰⁴ is normal but below the bound.
        assert!(Terms::of(&input(1e-40, 0.0, 0.0), 4, 4).is_none());
        assert!(Terms::of(&input(f32::from_bits(23 << 23), 0.0, 0.0), 4, 4).is_none());
        // 0 · −1 is −0.
        assert!(Terms::of(&input(1.0, 0.5, -1.0), 4, 4).is_none());
        assert!(Terms::of(&input(f32::INFINITY, 0.0, 0.0), 4, 4).is_none());
        assert!(Terms::of(&input(f32::NAN, 0.0, 0.0), 4, 4).is_none());
        // A zero term is fine: 1 − 1 = +0.
        assert!(Terms::of(&input(1.0, -1.0, 0.5), 4, 4).is_some());
    }
}
