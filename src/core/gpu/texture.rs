//! A sampler's texture on the device, as the emulator sees it: a 2D
//! texture with its levels, a cube map (six array layers in D3DCUBEMAP_FACES
//! order +X, −X, +Y, −Y, +Z, −Z, each face with its own levels, viewed as a
//! 2D array whose face the shader picks) or a volume texture (3D, each
//! level halving all three sides).
//!
//! Levels go up as given — box-filtered, authored in a DDS file, or decoded
//! from DXT blocks by `core/image` — in `Rgba32Float`, so the device reads
//! the very values the emulator reads. Vulkan's layer order and face table
//! are Direct3D's (Vulkan §16.5.4, "Cube Map Face Selection"), and a face's
//! row 0 is its top row in both, so faces are copied without reordering.
//! A declared sampler with nothing bound reads (0, 0, 0, 1): a 1×1 texture
//! (six 1×1 faces, a 1×1×1 volume) of that value.

use super::{Gpu, GpuError};
use crate::core::emu::{Texture, TextureLevels};
use crate::core::isa::SamplerType;

/// A texture uploaded for one sampler and the view dimension it is bound as.
pub(super) struct Uploaded {
    pub texture: wgpu::Texture,
    pub dimension: wgpu::TextureViewDimension,
}

/// One copy into the texture: `texels` at `level`, starting at layer (or
/// slice) `z`, `w × h × d` texels.
struct Write<'a> {
    level: u32,
    z: u32,
    size: (u32, u32, u32),
    texels: &'a [[f32; 4]],
}

/// The view dimension a declaration binds (`dcl_2d`, `dcl_cube`, `dcl_volume`):
/// a cube map as its six faces, a 2D array, which the translation samples
/// face by face (`translate/cube.rs`: Direct3D 9's filtering stops at a
/// face's edge, where a cube view's is seamless).
pub(super) fn view_dimension(ty: SamplerType) -> wgpu::TextureViewDimension {
    match ty {
        SamplerType::Tex2d => wgpu::TextureViewDimension::D2,
        SamplerType::Cube => wgpu::TextureViewDimension::D2Array,
        SamplerType::Volume => wgpu::TextureViewDimension::D3,
    }
}

const UNBOUND: [[f32; 4]; 1] = [[0.0, 0.0, 0.0, 1.0]];

/// The copies of `levels`, with the texture's level-0 size (width, height,
/// layers or depth) and its dimension.
fn writes<'a>(
    levels: TextureLevels<'a>,
) -> (Vec<Write<'a>>, (u32, u32, u32), wgpu::TextureDimension) {
    let flat = |i: usize, t: Texture<'a>, z: u32| Write {
        level: i as u32,
        z,
        size: (t.width, t.height, 1),
        texels: t.texels,
    };
    match levels {
        TextureLevels::Single(_) | TextureLevels::Chain(_) => {
            let views = levels.views();
            let size = (views[0].width, views[0].height, 1);
            let w = views.into_iter().enumerate().map(|(i, t)| flat(i, t, 0));
            (w.collect(), size, wgpu::TextureDimension::D2)
        }
        TextureLevels::Cube(c) => {
            let e = c.edge();
            let w = (0..6).flat_map(|f| {
                let views = c.face(f).views();
                views
                    .into_iter()
                    .enumerate()
                    .map(move |(i, t)| flat(i, t, f as u32))
            });
            (w.collect(), (e, e, 6), wgpu::TextureDimension::D2)
        }
        TextureLevels::Volume(v) => {
            let w = (0..v.len()).filter_map(|i| v.level(i)).enumerate();
            let w: Vec<Write> = w
                .map(|(i, l)| Write {
                    level: i as u32,
                    z: 0,
                    size: (l.width, l.height, l.depth),
                    texels: &l.texels,
                })
                .collect();
            let size = w[0].size;
            (w, size, wgpu::TextureDimension::D3)
        }
    }
}

/// The 1×1 texture of (0, 0, 0, 1) an unbound sampler of type `ty` reads.
fn unbound<'a>(ty: SamplerType) -> (Vec<Write<'a>>, (u32, u32, u32), wgpu::TextureDimension) {
    let one = |z| Write {
        level: 0,
        z,
        size: (1, 1, 1),
        texels: &UNBOUND,
    };
    match ty {
        SamplerType::Tex2d => (vec![one(0)], (1, 1, 1), wgpu::TextureDimension::D2),
        SamplerType::Cube => (
            (0..6).map(one).collect(),
            (1, 1, 6),
            wgpu::TextureDimension::D2,
        ),
        SamplerType::Volume => (vec![one(0)], (1, 1, 1), wgpu::TextureDimension::D3),
    }
}

/// Checks that the device holds a texture of `size` and that every level
/// has the size Vulkan gives it (each side halved, at least 1).
fn check(
    gpu: &Gpu,
    writes: &[Write],
    size: (u32, u32, u32),
    dimension: wgpu::TextureDimension,
    sampler: u32,
) -> Result<(), GpuError> {
    let (w, h, d) = size;
    let (max, sides) = match dimension {
        wgpu::TextureDimension::D3 => (gpu.limits.max_texture_dimension_3d, [w, h, d]),
        _ => (gpu.limits.max_texture_dimension_2d, [w, h, 1]),
    };
    if sides.iter().any(|&n| n > max) {
        return Err(GpuError::Unsupported(format!(
            "s{sampler}: a {w}×{h}{} texture; the device's textures are at most {max} texels a side",
            if dimension == wgpu::TextureDimension::D3 {
                format!("×{d}")
            } else {
                String::new()
            }
        )));
    }
    for wr in writes {
        let i = wr.level;
        let depth = if dimension == wgpu::TextureDimension::D3 {
            (d >> i).max(1)
        } else {
            1
        };
        let want = ((w >> i).max(1), (h >> i).max(1), depth);
        if wr.size != want {
            return Err(GpuError::Unsupported(format!(
                "s{sampler}: mip level {i} is {}×{}×{}, where Vulkan needs {}×{}×{}",
                wr.size.0, wr.size.1, wr.size.2, want.0, want.1, want.2
            )));
        }
    }
    Ok(())
}

/// The large 2D textures of earlier draws, by where their texels lie, their
/// size and a hash of every texel (so that memory freed and reused for
/// other texels of the same size is not taken for them): the passes of one
/// command sample the same image, and a 3840×2160 frame is 133 MB to send.
#[derive(Default)]
pub(crate) struct Cache(std::sync::Mutex<Vec<(Key, wgpu::Texture)>>);

/// What a cached texture was made from.
#[derive(Clone, Copy, PartialEq, Eq)]
struct Key {
    address: usize,
    texels: usize,
    size: (u32, u32),
    hash: u64,
}

/// Textures kept at most (the oldest is dropped first).
const CACHED: usize = 2;

impl Key {
    /// The key of `t` without its hash (see [`Key::hashed`]), if `t` is
    /// large enough to be worth keeping.
    fn place(t: &Texture) -> Option<Key> {
        if t.texels.len() * 16 < PARALLEL_UPLOAD {
            return None;
        }
        Some(Key {
            address: t.texels.as_ptr() as usize,
            texels: t.texels.len(),
            size: (t.width, t.height),
            hash: 0,
        })
    }

    /// This key with the hash of every texel of `t` (on every core: 3.5 ms
    /// for a 3840×2160 frame on a 16-core machine).
    fn hashed(self, t: &Texture) -> Key {
        use rayon::prelude::*;
        use std::hash::{DefaultHasher, Hasher};
        let parts: Vec<u64> = t
            .texels
            .par_chunks(1 << 14)
            .map(|c| {
                let mut h = DefaultHasher::new();
                h.write(bytemuck::cast_slice(c));
                h.finish()
            })
            .collect();
        let mut h = DefaultHasher::new();
        for p in parts {
            h.write_u64(p);
        }
        Key {
            hash: h.finish(),
            ..self
        }
    }

    /// Whether `other` was made from texels at the same place and of the
    /// same size (its hash aside).
    fn same_place(&self, other: &Key) -> bool {
        Key { hash: 0, ..*self } == Key { hash: 0, ..*other }
    }
}

impl Cache {
    /// The texture kept for `t` at `place` ([`Key::place`]); the texels are
    /// hashed only where one was kept at that place.
    fn get(&self, place: &Key, t: &Texture) -> Option<wgpu::Texture> {
        let kept = self.0.lock().ok()?;
        if !kept.iter().any(|(k, _)| k.same_place(place)) {
            return None;
        }
        let key = place.hashed(t);
        kept.iter().find(|(k, _)| *k == key).map(|(_, t)| t.clone())
    }

    fn keep(&self, key: Key, texture: &wgpu::Texture) {
        if let Ok(mut kept) = self.0.lock() {
            if kept.len() == CACHED {
                kept.remove(0);
            }
            kept.push((key, texture.clone()));
        }
    }
}

/// Uploads what sampler `sampler` (declared `ty`) reads: `levels`, or the
/// unbound value; a large 2D texture an earlier draw uploaded is taken
/// from the device's [`Cache`].
pub(super) fn upload(
    gpu: &Gpu,
    levels: Option<TextureLevels>,
    ty: SamplerType,
    sampler: u32,
) -> Result<Uploaded, GpuError> {
    let place = match (&levels, ty) {
        (Some(TextureLevels::Single(t)), SamplerType::Tex2d) => Key::place(t).map(|k| (k, *t)),
        _ => None,
    };
    let kept = place.and_then(|(k, t)| gpu.textures.get(&k, &t));
    crate::core::phases::mark("upload: cache looked up");
    if let Some(texture) = kept {
        return Ok(Uploaded {
            texture,
            dimension: view_dimension(ty),
        });
    }
    let (writes, size, dimension) = match levels {
        Some(l) => writes(l),
        None => unbound(ty),
    };
    check(gpu, &writes, size, dimension, sampler)?;
    let level_count = writes.iter().map(|w| w.level + 1).max().unwrap_or(1);
    let texture = gpu.device.create_texture(&wgpu::TextureDescriptor {
        label: None,
        size: wgpu::Extent3d {
            width: size.0,
            height: size.1,
            depth_or_array_layers: size.2,
        },
        mip_level_count: level_count,
        sample_count: 1,
        dimension,
        format: wgpu::TextureFormat::Rgba32Float,
        usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
        view_formats: &[],
    });
    // A texture to keep is hashed while it is sent.
    let (sent, key) = rayon::join(
        || {
            writes
                .iter()
                .try_for_each(|w| write_texels(gpu, &texture, w.level, w.z, w.size, w.texels))
        },
        || place.map(|(k, t)| k.hashed(&t)),
    );
    sent?;
    if let Some(key) = key {
        gpu.textures.keep(key, &texture);
    }
    crate::core::phases::mark("upload: texture sent");
    Ok(Uploaded {
        texture,
        dimension: view_dimension(ty),
    })
}

/// Copies `texels` (`w × h × d`, row-major, slice after slice) into
/// `level` of `texture` from layer or slice `z`.
pub(super) fn write_texels(
    gpu: &Gpu,
    texture: &wgpu::Texture,
    level: u32,
    z: u32,
    (w, h, d): (u32, u32, u32),
    texels: &[[f32; 4]],
) -> Result<(), GpuError> {
    let width = w as usize;
    if texels.len() * 16 >= PARALLEL_UPLOAD {
        return write_rows(gpu, texture, level, z, (w, h, d), |r, row| {
            row.copy_from_slice(&texels[r * width..(r + 1) * width]);
        });
    }
    // The device's Rgba32Float is little-endian f32, as the host's.
    let bytes: &[u8] = bytemuck::cast_slice(texels);
    gpu.queue.write_texture(
        wgpu::TexelCopyTextureInfo {
            texture,
            mip_level: level,
            origin: wgpu::Origin3d { x: 0, y: 0, z },
            aspect: wgpu::TextureAspect::All,
        },
        bytes,
        wgpu::TexelCopyBufferLayout {
            offset: 0,
            bytes_per_row: Some(16 * w),
            rows_per_image: Some(h),
        },
        wgpu::Extent3d {
            width: w,
            height: h,
            depth_or_array_layers: d,
        },
    );
    Ok(())
}

/// A run of rows of the staging memory, filled by one task.
struct Run<'a>(wgpu::WriteOnly<'a, [u8]>);

// SAFETY: a `WriteOnly<[u8]>` is an exclusive pointer to bytes, as `&mut
// [u8]` is, which may be sent to another thread; wgpu's own `Send` impl
// (`T: Send`) leaves out `?Sized`, so it does not cover a slice.
unsafe impl Send for Run<'_> {}

/// Uploads at least this many bytes go through a staging buffer that every
/// core fills ([`write_rows`]): `write_texture` copies on one thread, which
/// took 40 ms of a 3840×2160 frame's 133 MB on a 16-core machine.
pub(super) const PARALLEL_UPLOAD: usize = 1 << 22;

/// Fills `level` of `texture` from layer or slice `z` (`w × h × d` texels)
/// with the rows `row(r, texels)` writes (r counts rows slice after slice),
/// the rows made in parallel straight into the queue's staging memory, then
/// copied on the device into a buffer and from it into the texture.
///
/// The staging memory is the queue's (`write_buffer_with`) rather than a
/// buffer mapped at creation: wgpu zeroes a buffer mapped at creation on
/// one thread before handing it over, and on a GPU whose host-visible
/// memory lies on the device (NVIDIA's with a resizable BAR) those zeros
/// cross the bus — 133 MB of them for a 3840×2160 frame.
pub(super) fn write_rows(
    gpu: &Gpu,
    texture: &wgpu::Texture,
    level: u32,
    z: u32,
    (w, h, d): (u32, u32, u32),
    row: impl Fn(usize, &mut [[f32; 4]]) + Sync,
) -> Result<(), GpuError> {
    use rayon::prelude::*;
    const ALIGN: usize = wgpu::COPY_BYTES_PER_ROW_ALIGNMENT as usize;
    let row_bytes = 16 * w as usize;
    let pitch = row_bytes.div_ceil(ALIGN) * ALIGN;
    let rows = h as usize * d as usize;
    let size = (pitch * rows.max(1)) as u64;
    let buffer = gpu.device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("ps30 upload"),
        size,
        usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::COPY_SRC,
        mapped_at_creation: false,
    });
    crate::core::phases::mark("upload: texture and buffer made");
    {
        let size = wgpu::BufferSize::new(size)
            .ok_or_else(|| GpuError::Failed("an empty upload".into()))?;
        let mut staging = gpu
            .queue
            .write_buffer_with(&buffer, 0, size)
            .ok_or_else(|| {
                GpuError::Failed(format!("no staging memory for a {size}-byte upload"))
            })?;
        crate::core::phases::mark("upload: staging memory allocated");
        // Disjoint runs of rows, each filled by one task.
        let per = rows.div_ceil(256).max(1);
        let mut runs = Vec::new();
        let mut rest = staging.slice(..);
        let mut first = 0;
        while first < rows {
            let n = per.min(rows - first);
            let (run, tail) = rest.split_at(n * pitch);
            runs.push((first, n, Run(run)));
            rest = tail;
            first += n;
        }
        runs.into_par_iter().for_each(|(first, n, Run(mut run))| {
            let mut texels = vec![[0.0f32; 4]; w as usize];
            for r in 0..n {
                row(first + r, &mut texels);
                run.slice(r * pitch..r * pitch + row_bytes)
                    .copy_from_slice(bytemuck::cast_slice(&texels));
            }
        });
    }
    crate::core::phases::mark("upload: staging filled");
    let mut encoder = gpu.device.create_command_encoder(&Default::default());
    encoder.copy_buffer_to_texture(
        wgpu::TexelCopyBufferInfo {
            buffer: &buffer,
            layout: wgpu::TexelCopyBufferLayout {
                offset: 0,
                bytes_per_row: Some(pitch as u32),
                rows_per_image: Some(h),
            },
        },
        wgpu::TexelCopyTextureInfo {
            texture,
            mip_level: level,
            origin: wgpu::Origin3d { x: 0, y: 0, z },
            aspect: wgpu::TextureAspect::All,
        },
        wgpu::Extent3d {
            width: w,
            height: h,
            depth_or_array_layers: d,
        },
    );
    gpu.queue.submit([encoder.finish()]);
    Ok(())
}
