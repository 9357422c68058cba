//! A draw of geometry whose output merger runs on the CPU (blending, fog,
//! pixel history) in one device draw per batch of triangles instead of one
//! render pass and read-back per primitive: every covered fragment appends
//! its record to a storage buffer (`translate::records`), and the records
//! are put back in drawing order here — sorted by triangle, and within a
//! primitive the last triangle's fragment kept at each pixel, as a
//! primitive drawn into its own cleared attachments keeps it — giving the
//! same [`ShadedPrimitive`]s as [`super::draw_geometry`], word for word.
//!
//! The device rasterises, interpolates and runs the shader with the same
//! pipeline set-up as the per-primitive draw (quads and derivatives its
//! own); only where the fragment's results go differs. Memory is bounded:
//! a triangle covers at most the pixels of its bounding box on screen
//! (widened by a pixel for the device's snapping, cut to the clip
//! rectangle; the whole rectangle where a vertex is behind the eye), and
//! the triangles are drawn in batches whose bounds fit [`BATCH_BYTES`] of
//! records. A fragment past its batch's bound is an error, never lost.

use super::draw::{self, ErrorScopes};
use super::geometry::{self, Fragment, GeometryDraw, Resources, ShadedPrimitive, Stages};
use super::{Gpu, GpuError};
use crate::core::ir::Shader;
use crate::core::phases;
use crate::core::translate::interface;
use crate::core::translate::records::{self, COUNTER_BINDING, HEADER_WORDS, RECORDS_BINDING};
use std::ops::Range;

/// The most bytes of records one batch's buffer holds (one triangle whose
/// bound is larger gets a batch of its own, up to the device's limit on a
/// storage buffer).
const BATCH_BYTES: u64 = 64 << 20;

/// Why this device cannot draw with fragment records (`None` if it can).
pub fn records_lack(gpu: &Gpu) -> Option<&'static str> {
    if !gpu.features.contains(wgpu::Features::PRIMITIVE_INDEX) {
        return Some("the device lacks PRIMITIVE_INDEX, by which each fragment names its triangle");
    }
    if !gpu.fragment_storage {
        return Some("the device cannot write storage buffers from fragment shaders");
    }
    if gpu.limits.max_storage_buffers_per_shader_stage < 2 {
        return Some("the device binds fewer than two storage buffers to a fragment shader");
    }
    None
}

/// Draws `g` of `shader` on the device in batches of triangles, each
/// fragment recorded; returns each primitive's shaded pixels, in drawing
/// order, as [`super::draw_geometry`] does.
pub fn draw_geometry_recorded(
    gpu: &Gpu,
    shader: &Shader,
    g: &GeometryDraw,
) -> Result<Vec<ShadedPrimitive>, GpuError> {
    phases::mark("geometry (records): preparing");
    if let Some(why) = records_lack(gpu) {
        return Err(GpuError::Unsupported(why.into()));
    }
    let triangles: Vec<[u32; 3]> = g.primitives.iter().flatten().copied().collect();
    if g.clip.is_empty() || triangles.is_empty() {
        geometry::check(gpu, shader, g)?;
        return Ok(vec![ShadedPrimitive::default(); g.primitives.len()]);
    }
    let scopes = ErrorScopes::push(gpu);
    let Fragment {
        iface,
        module,
        layout,
        bindings,
    } = geometry::fragment_stage(gpu, shader, g, None, true)?;
    let stride = u64::from(records::stride(iface.outputs.len()));
    let records_layout = records_layout(gpu);
    let mut targets = vec![None; interface::GEOMETRY_FLAGS_LOCATION as usize + 1];
    targets[interface::GEOMETRY_FLAGS_LOCATION as usize] =
        Some(wgpu::TextureFormat::R32Uint.into());
    let stages = Stages {
        fragment: module,
        layouts: &[&layout, &records_layout],
        targets: &targets,
        depth_stencil: None,
    };
    let pipeline = geometry::pipeline(gpu, g, &iface, stages)?;
    let (vertices, indices) = geometry::buffers(gpu, g);
    let (w, h) = (g.pixel.target_width, g.pixel.target_height);
    // The flags' attachment, at its location as in the pipeline's targets.
    let flags = draw::target_texture(&gpu.device, w, h, wgpu::TextureFormat::R32Uint);
    let mut attachments: Vec<Option<wgpu::Texture>> = vec![None; targets.len()];
    attachments[interface::GEOMETRY_FLAGS_LOCATION as usize] = Some(flags);
    scopes.pop(gpu)?;
    phases::mark("geometry (records): pipeline");
    let bounds: Vec<u64> = triangles.iter().map(|&t| bound(g, t)).collect();
    let limit = gpu
        .limits
        .max_storage_buffer_binding_size
        .min(gpu.limits.max_buffer_size);
    let resources = Resources {
        pipeline: &pipeline,
        group: &bindings.group,
        vertices: &vertices,
        indices: &indices,
        attachments: &attachments,
    };
    let batch = Batch {
        resources: &resources,
        layout: &records_layout,
        stride: stride as usize,
    };
    let mut words = Vec::new();
    for range in batches(&bounds, 4 * stride, limit)? {
        let capacity = bounds[range.clone()].iter().sum::<u64>();
        draw_batch(gpu, g, &batch, (range, capacity), &mut words)?;
        phases::mark("geometry (records): batch read back");
    }
    Ok(in_order(g, &iface.outputs, stride as usize, &words))
}

/// The bind-group layout of the counter and the records.
fn records_layout(gpu: &Gpu) -> wgpu::BindGroupLayout {
    gpu.device
        .create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("ps30 fragment records"),
            entries: &[
                super::fragment_storage(COUNTER_BINDING),
                super::fragment_storage(RECORDS_BINDING),
            ],
        })
}

/// The most pixels triangle `t` of `g` can cover: its bounding box on
/// screen, a pixel wider on every side (Direct3D 9's pixel i has its
/// centre at X = i; the device snaps vertices by at most 2⁻⁴ pixel and
/// computes the placement in f32), cut to the clip rectangle; the whole
/// rectangle where a vertex is not finite or not in front of the eye.
fn bound(g: &GeometryDraw, t: [u32; 3]) -> u64 {
    let c = g.clip;
    let whole = u64::from(c.right - c.left) * u64::from(c.bottom - c.top);
    let v = g.viewport;
    let screen = |i: u32| -> Option<[f64; 2]> {
        let [x, y, _, w] = g.positions[i as usize].map(f64::from);
        if !(w > 0.0 && w.is_finite() && x.is_finite() && y.is_finite()) {
            return None;
        }
        Some(match g.transformed {
            true => [x, y],
            false => [
                f64::from(v.x) + (1.0 + x / w) * f64::from(v.width) / 2.0,
                f64::from(v.y) + (1.0 - y / w) * f64::from(v.height) / 2.0,
            ],
        })
    };
    let Some(corners) = t.map(screen).into_iter().collect::<Option<Vec<_>>>() else {
        return whole;
    };
    let span = |axis: usize, lo: u32, hi: u32| -> u64 {
        let min = corners
            .iter()
            .map(|p| p[axis])
            .fold(f64::INFINITY, f64::min);
        let max = corners
            .iter()
            .map(|p| p[axis])
            .fold(f64::NEG_INFINITY, f64::max);
        let first = (min.floor() - 1.0).max(f64::from(lo));
        let end = (max.ceil() + 2.0).min(f64::from(hi));
        (end - first).max(0.0) as u64
    };
    (span(0, c.left, c.right) * span(1, c.top, c.bottom)).min(whole)
}

/// The triangles in consecutive batches whose bounds (`bounds`, in
/// records of `record_bytes`) fit [`BATCH_BYTES`], a triangle over it
/// alone in its batch; an error where one triangle's bound passes
/// `limit`, the device's largest storage buffer.
fn batches(bounds: &[u64], record_bytes: u64, limit: u64) -> Result<Vec<Range<usize>>, GpuError> {
    let mut out = Vec::new();
    let (mut start, mut bytes) = (0, 0u64);
    for (i, &b) in bounds.iter().enumerate() {
        let need = b * record_bytes;
        if need > limit {
            return Err(GpuError::Unsupported(format!(
                "a triangle may cover {b} pixels, more records than the device's largest storage buffer ({limit} bytes) holds"
            )));
        }
        if i > start && bytes + need > BATCH_BYTES {
            out.push(start..i);
            (start, bytes) = (i, 0);
        }
        bytes += need;
    }
    out.push(start..bounds.len());
    Ok(out)
}

/// What every batch of a draw shares.
struct Batch<'b> {
    resources: &'b Resources<'b>,
    layout: &'b wgpu::BindGroupLayout,
    /// Words per record.
    stride: usize,
}

/// Draws the triangles `range` (with room for `capacity` records) and
/// appends their records to `words`, each record's first word made the
/// triangle's index in the whole draw.
fn draw_batch(
    gpu: &Gpu,
    g: &GeometryDraw,
    b: &Batch,
    (range, capacity): (Range<usize>, u64),
    words: &mut Vec<u32>,
) -> Result<(), GpuError> {
    let device = &gpu.device;
    let scopes = ErrorScopes::push(gpu);
    let record_bytes = 4 * b.stride as u64;
    let buffer = |size: u64, usage: wgpu::BufferUsages| {
        device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("ps30 fragment records"),
            size: size.max(4),
            usage,
            mapped_at_creation: false,
        })
    };
    let storage = wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC;
    let counter = buffer(4, storage | wgpu::BufferUsages::COPY_DST);
    let records = buffer(capacity * record_bytes, storage);
    let read = wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST;
    let counter_back = buffer(4, read);
    let records_back = buffer(capacity * record_bytes, read);
    gpu.queue.write_buffer(&counter, 0, &[0; 4]);
    let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: None,
        layout: b.layout,
        entries: &[
            wgpu::BindGroupEntry {
                binding: COUNTER_BINDING,
                resource: counter.as_entire_binding(),
            },
            wgpu::BindGroupEntry {
                binding: RECORDS_BINDING,
                resource: records.as_entire_binding(),
            },
        ],
    });
    let views: Vec<Option<wgpu::TextureView>> = b
        .resources
        .attachments
        .iter()
        .map(|a| a.as_ref().map(|t| t.create_view(&Default::default())))
        .collect();
    let mut encoder = device.create_command_encoder(&Default::default());
    {
        let color_attachments = super::cleared_attachments(&views);
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("ps30 recorded triangles"),
            color_attachments: &color_attachments,
            ..Default::default()
        });
        geometry::bind_pass(&mut pass, g, b.resources);
        pass.set_bind_group(1, &group, &[]);
        pass.draw_indexed(3 * range.start as u32..3 * range.end as u32, 0, 0..1);
    }
    encoder.copy_buffer_to_buffer(&counter, 0, &counter_back, 0, 4);
    encoder.copy_buffer_to_buffer(&records, 0, &records_back, 0, records.size());
    gpu.queue.submit([encoder.finish()]);
    draw::map_read(gpu, &[&counter_back, &records_back])?;
    let count = {
        let view = counter_back
            .get_mapped_range(..)
            .map_err(|e| GpuError::Failed(e.to_string()))?;
        u64::from(u32::from_le_bytes([view[0], view[1], view[2], view[3]]))
    };
    if count > capacity {
        return Err(GpuError::Failed(format!(
            "the device shaded {count} fragments of triangles {range:?}, past their bound of {capacity}"
        )));
    }
    let view = records_back
        .get_mapped_range(..)
        .map_err(|e| GpuError::Failed(e.to_string()))?;
    let bytes = &view[..(count * record_bytes) as usize];
    let first = words.len();
    let in_batch = |r: &[u32]| {
        (r[0] as usize) < range.len() && r[1] < g.pixel.target_width && r[2] < g.pixel.target_height
    };
    if let Some(r) = bytes
        .chunks_exact(record_bytes as usize)
        .map(|r| {
            r.chunks_exact(4)
                .take(3)
                .map(|w| u32::from_le_bytes([w[0], w[1], w[2], w[3]]))
                .collect::<Vec<_>>()
        })
        .find(|r| !in_batch(r))
    {
        return Err(GpuError::Failed(format!(
            "the device recorded a fragment of triangle {} at ({}, {}), outside triangles {range:?} or the target",
            r[0], r[1], r[2]
        )));
    }
    words.extend(
        bytes
            .chunks_exact(4)
            .map(|w| u32::from_le_bytes([w[0], w[1], w[2], w[3]])),
    );
    for record in words[first..].chunks_exact_mut(b.stride) {
        record[0] += range.start as u32;
    }
    drop(view);
    counter_back.unmap();
    records_back.unmap();
    scopes.pop(gpu)?;
    Ok(())
}

/// The records (`words`, `stride` words each, the first the triangle's
/// index in the draw) as each primitive's shaded pixels in row order, the
/// fragment of the primitive's last triangle kept at a pixel two of its
/// triangles cover, as the per-primitive draw's attachments keep it (the
/// GPU backend's set-up makes no such primitive: a point fill's points,
/// whose squares may overlap, are primitives of their own there). `outputs` are the `oC#` the
/// shader writes, in the records' order.
fn in_order(
    g: &GeometryDraw,
    outputs: &[u32],
    stride: usize,
    words: &[u32],
) -> Vec<ShadedPrimitive> {
    let triangles: usize = g.primitives.iter().map(Vec::len).sum();
    // A counting sort of the records by triangle.
    let mut starts = vec![0usize; triangles + 1];
    for r in words.chunks_exact(stride) {
        starts[r[0] as usize + 1] += 1;
    }
    for t in 0..triangles {
        starts[t + 1] += starts[t];
    }
    let mut next = starts.clone();
    let mut sorted = vec![0usize; words.len() / stride];
    for (k, r) in words.chunks_exact(stride).enumerate() {
        sorted[next[r[0] as usize]] = k;
        next[r[0] as usize] += 1;
    }
    let width = g.pixel.target_width;
    let mut out = Vec::with_capacity(g.primitives.len());
    let mut first = 0;
    for prim in &g.primitives {
        let records = &sorted[starts[first]..starts[first + prim.len()]];
        first += prim.len();
        // Stable by pixel: a pixel's records stay in triangle order, and
        // the last of them is kept.
        let pixel = |k: usize| words[k * stride + 2] * width + words[k * stride + 1];
        let mut kept: Vec<usize> = records.to_vec();
        kept.sort_by_key(|&k| pixel(k));
        kept.reverse();
        kept.dedup_by_key(|k| pixel(*k));
        kept.reverse();
        out.push(shaded(g, outputs, stride, words, &kept));
    }
    out
}

/// One primitive's shaded pixels from its records `kept` (one per pixel,
/// in row order).
fn shaded(
    g: &GeometryDraw,
    outputs: &[u32],
    stride: usize,
    words: &[u32],
    kept: &[usize],
) -> ShadedPrimitive {
    let width = g.pixel.target_width;
    let mut s = ShadedPrimitive {
        color: (0..4)
            .map(|k| outputs.contains(&k).then(Vec::new))
            .collect(),
        ..Default::default()
    };
    let header = HEADER_WORDS as usize;
    for &k in kept {
        let r = &words[k * stride..(k + 1) * stride];
        s.pixels.push(r[2] * width + r[1]);
        s.killed.push(r[3] & 2 != 0);
        s.depth.push(f32::from_bits(r[4]));
        if g.fog.is_some() {
            s.fog.push(f32::from_bits(r[5]));
        }
        for (n, &o) in outputs.iter().enumerate() {
            if let Some(c) = &mut s.color[o as usize] {
                let at = header + 4 * n;
                c.push(std::array::from_fn(|i| f32::from_bits(r[at + i])));
            }
        }
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::emu::Draw;
    use crate::core::raster::{Cull, Rect, Viewport};

    #[test]
    fn batches_fill_the_budget_and_a_larger_triangle_goes_alone() {
        // Records of BATCH_BYTES/20 bytes: a bound of 10 is half the
        // budget, so two such triangles fill a batch exactly (≤) and the
        // third starts the next.
        let r = BATCH_BYTES / 20;
        assert_eq!(batches(&[10, 10, 10], r, u64::MAX).unwrap(), [0..2, 2..3]);
        // A bound of 100 is five budgets: alone, between its neighbours.
        assert_eq!(
            batches(&[1, 100, 1], r, u64::MAX).unwrap(),
            [0..1, 1..2, 2..3]
        );
        // Past the device's largest buffer (100·r bytes > 99·r): refused,
        // so that the caller draws per primitive.
        assert!(matches!(
            batches(&[1, 100], r, 99 * r),
            Err(GpuError::Unsupported(_))
        ));
    }

    #[test]
    fn a_triangles_bound_is_its_widened_box_cut_to_the_clip_rectangle() {
        let draw = Draw::new(16, 16);
        let mut g = GeometryDraw {
            pixel: &draw,
            positions: vec![
                [1.0, 1.0, 0.5, 1.0],
                [5.0, 1.0, 0.5, 1.0],
                [1.0, 3.0, 0.5, 1.0],
            ],
            transformed: true,
            values: vec![Vec::new(); 3],
            slots: Vec::new(),
            flat: 0,
            primitives: vec![vec![[0, 1, 2]]],
            viewport: Viewport::whole(16, 16),
            clip: Rect {
                left: 0,
                top: 0,
                right: 16,
                bottom: 16,
            },
            cull: Cull::None,
            clip_planes: Vec::new(),
            fog: None,
        };
        // x from ⌊1⌋ − 1 = 0 to ⌈5⌉ + 2 = 7 (exclusive): 7 columns; y from
        // 0 to ⌈3⌉ + 2 = 5: 5 rows.
        assert_eq!(bound(&g, [0, 1, 2]), 35);
        // Cut by a clip rectangle from (2, 2): columns 2..7, rows 2..5.
        g.clip.left = 2;
        g.clip.top = 2;
        assert_eq!(bound(&g, [0, 1, 2]), 15);
        // In clip space on the whole 16×16 viewport: x/w = −1 is screen
        // X = 0, x/w = 0 is X = 8; y/w = 1 is Y = 0, y/w = 0 is Y = 8.
        // Columns 0 (⌊0⌋ − 1 cut to 0) to ⌈8⌉ + 2 = 10, rows 0 to 10,
        // cut to the rectangle from (2, 2): 8 × 8.
        g.transformed = false;
        g.positions = vec![
            [-2.0, 2.0, 0.5, 2.0],
            [0.0, 2.0, 0.5, 2.0],
            [-2.0, 0.0, 0.5, 2.0],
        ];
        assert_eq!(bound(&g, [0, 1, 2]), 64);
        // A vertex behind the eye: the whole rectangle, 14 × 14.
        g.positions[2][3] = -1.0;
        assert_eq!(bound(&g, [0, 1, 2]), 196);
    }
}
